//! Compositing (Cube-4L §3.5-3.7, Figs. 3 and 18-21): the bilinear unit that
//! reads the one-slice compositing buffer where the voxel's sight ray meets
//! the previous slice, and the compositing unit for every projection mode.
//!
//! The ray through voxel `(x, y)` meets the previous slice at `(x - dx, y - dy)`,
//! inside the 3x3 region around the voxel because |dx|, |dy| <= 1. The signs
//! of dx and dy narrow it to 2x2: neighbour `x - sign(dx)` with weight `|dx|`.
//! Cells outside the slice read as the reset value (nothing accumulated).

use super::plan::Order;
use super::shader::Sample;
use crate::fixed::{lerp_frac, max_of, mul_unorm, sat_u};
use scene::Mode;

/// Value of an empty compositing-buffer cell (the SR reset value).
pub fn reset_value(mode: Mode, voxel_bits: u32) -> [u32; 4] {
    match mode {
        Mode::Minip => [max_of(voxel_bits), 0, 0, 0],
        _ => [0; 4],
    }
}

/// The bilinear unit: accumulated value where the sight ray of cell `(x, y)`
/// meets the previous slice `prev` (`nx * ny` cells, x fastest).
/// Each channel: `top = lerp(c[y][x], c[y][x'], |dx|)`,
/// `bottom = lerp(c[y'][x], c[y'][x'], |dx|)`, `lerp(top, bottom, |dy|)` with
/// `x' = x - sign(dx)`, `y' = y - sign(dy)` and `lerp` = `fixed::lerp_frac`.
#[allow(clippy::too_many_arguments)]
pub fn gather(
    prev: &[[u32; 4]],
    nx: usize,
    ny: usize,
    x: usize,
    y: usize,
    dx: i32,
    dy: i32,
    frac: u32,
    reset: [u32; 4],
) -> [u32; 4] {
    let cell = |cx: isize, cy: isize| -> [u32; 4] {
        if cx < 0 || cy < 0 || cx >= nx as isize || cy >= ny as isize {
            reset
        } else {
            prev[cx as usize + nx * cy as usize]
        }
    };
    let (x, y) = (x as isize, y as isize);
    let (x2, y2) = (x - dx.signum() as isize, y - dy.signum() as isize);
    let (wx, wy) = (dx.unsigned_abs(), dy.unsigned_abs());
    let (c00, c10, c01, c11) = (cell(x, y), cell(x2, y), cell(x, y2), cell(x2, y2));
    std::array::from_fn(|i| {
        let top = lerp_frac(c00[i], c10[i], wx, frac);
        let bottom = lerp_frac(c01[i], c11[i], wx, frac);
        lerp_frac(top, bottom, wy, frac)
    })
}

/// The compositing unit. Returns the new cell value and whether a
/// saturation clipped a channel.
///
/// - Composite and first-opaque, front to back:
///   `C = sat(C_acc + mul(M - A_acc, C_new))`, likewise A.
/// - Back to front: `C = sat(C_new + mul(M - A_new, C_acc))`, likewise A.
/// - MIP / MinIP: max / min of the gathered value and a valid voxel.
/// - X-ray: gathered sum plus the voxel's opacity (no saturation; the sum
///   needs `rgba_bits + ceil(log2(depth))` bits).
pub fn composite(
    mode: Mode,
    order: Order,
    acc: [u32; 4],
    new: &Sample,
    rgba_bits: u32,
) -> ([u32; 4], bool) {
    let m = max_of(rgba_bits);
    match mode {
        Mode::Composite | Mode::FirstOpaque => {
            let (front, back) = match order {
                Order::FrontToBack => (acc, new.value),
                Order::BackToFront => (new.value, acc),
            };
            let mut clipped = false;
            let out = std::array::from_fn(|i| {
                let s = front[i] as u64 + mul_unorm(m - front[3], back[i], rgba_bits) as u64;
                clipped |= s > m as u64;
                sat_u(s, m)
            });
            (out, clipped)
        }
        Mode::Mip if new.valid => ([acc[0].max(new.value[0]), 0, 0, 0], false),
        Mode::Minip if new.valid => ([acc[0].min(new.value[0]), 0, 0, 0], false),
        Mode::Mip | Mode::Minip => (acc, false),
        Mode::Xray => ([acc[0] + new.value[0], 0, 0, 0], false),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn s(v: [u32; 4]) -> Sample {
        Sample {
            value: v,
            valid: true,
        }
    }

    #[test]
    fn gather_at_zero_and_unit_increments() {
        let prev: Vec<[u32; 4]> = (0..9).map(|i| [i * 10, 0, 0, 0]).collect();
        assert_eq!(gather(&prev, 3, 3, 1, 1, 0, 0, 8, [0; 4])[0], 40);
        assert_eq!(gather(&prev, 3, 3, 1, 1, 256, 0, 8, [0; 4])[0], 30);
        assert_eq!(gather(&prev, 3, 3, 1, 1, -256, -256, 8, [0; 4])[0], 80);
        assert_eq!(gather(&prev, 3, 3, 1, 1, 128, 0, 8, [0; 4])[0], 35);
        assert_eq!(gather(&prev, 3, 3, 0, 0, 256, 256, 8, [7; 4])[0], 7);
    }

    #[test]
    fn opaque_front_hides_everything_behind() {
        let front = [200, 100, 50, 255];
        let (c, _) = composite(
            Mode::Composite,
            Order::FrontToBack,
            front,
            &s([9, 9, 9, 200]),
            8,
        );
        assert_eq!(c, front);
        let (c, _) = composite(
            Mode::Composite,
            Order::BackToFront,
            [9, 9, 9, 200],
            &s(front),
            8,
        );
        assert_eq!(c, front);
    }

    #[test]
    fn transparent_voxel_leaves_the_buffer() {
        for acc in [[0, 0, 0, 0], [17, 30, 2, 31], [255, 255, 255, 255]] {
            for order in [Order::FrontToBack, Order::BackToFront] {
                assert_eq!(composite(Mode::Composite, order, acc, &s([0; 4]), 8).0, acc);
            }
        }
    }

    #[test]
    fn mip_ignores_invalid_voxels() {
        let bad = Sample {
            value: [900, 0, 0, 0],
            valid: false,
        };
        assert_eq!(
            composite(Mode::Mip, Order::FrontToBack, [5, 0, 0, 0], &bad, 8).0[0],
            5
        );
        assert_eq!(
            composite(
                Mode::Mip,
                Order::FrontToBack,
                [5, 0, 0, 0],
                &s([900, 0, 0, 0]),
                8
            )
            .0[0],
            900
        );
    }
}
