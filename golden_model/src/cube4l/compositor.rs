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
use crate::fixed::{lerp_frac, lerp_i32, max_of, mul_unorm, sat_u};
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
    let (wx, wy) = (dx.unsigned_abs(), dy.unsigned_abs());
    let (c00, c10, c01, c11) = if x > 0 && y > 0 && x + 1 < nx && y + 1 < ny {
        // Inside the slice's border: all four cells are in it.
        let i = x + nx * y;
        let ix = (i as isize - dx.signum() as isize) as usize;
        let iy = (i as isize - dy.signum() as isize * nx as isize) as usize;
        let ixy = (ix as isize - dy.signum() as isize * nx as isize) as usize;
        (prev[i], prev[ix], prev[iy], prev[ixy])
    } else {
        let cell = |cx: isize, cy: isize| -> [u32; 4] {
            if cx < 0 || cy < 0 || cx >= nx as isize || cy >= ny as isize {
                reset
            } else {
                prev[cx as usize + nx * cy as usize]
            }
        };
        let (x, y) = (x as isize, y as isize);
        let (x2, y2) = (x - dx.signum() as isize, y - dy.signum() as isize);
        (cell(x, y), cell(x2, y), cell(x, y2), cell(x2, y2))
    };
    let any = (0..4).fold(0, |a, i| a | c00[i] | c10[i] | c01[i] | c11[i]);
    if frac <= 16 && any < 1 << (30 - frac) {
        // Every product of a difference and a weight fits 31 bits: the same
        // lerps in i32, four channels at once.
        let lerp = |a: [u32; 4], b: [u32; 4], w: u32| -> [u32; 4] {
            std::array::from_fn(|i| lerp_i32(a[i] as i32, b[i] as i32, w as i32, frac) as u32)
        };
        return lerp(lerp(c00, c10, wx), lerp(c01, c11, wx), wy);
    }
    std::array::from_fn(|i| {
        let top = lerp_frac(c00[i], c10[i], wx, frac);
        let bottom = lerp_frac(c01[i], c11[i], wx, frac);
        lerp_frac(top, bottom, wy, frac)
    })
}

/// [`gather`] for cells `lo..hi` of row `y` at once, one `(dx, dy)` for
/// the whole row (a parallel view), inside the slice's border (`1 <= lo`,
/// `hi <= nx - 1`, `0 < y < ny - 1`): the same lerps, channel by channel,
/// in vector lanes where every product fits 31 bits (as [`gather`]'s own
/// shortcut), else one cell at a time.
#[allow(clippy::too_many_arguments)]
pub fn gather_row(
    prev: &[[u32; 4]],
    nx: usize,
    y: usize,
    (lo, hi): (usize, usize),
    dx: i32,
    dy: i32,
    frac: u32,
    out: &mut [[u32; 4]],
) {
    let n = hi - lo;
    let at = |offset: isize| {
        let i = (y * nx + lo) as isize + offset;
        &prev[i as usize..i as usize + n]
    };
    let (sx, sy) = (dx.signum() as isize, dy.signum() as isize * nx as isize);
    let cells = [at(0), at(-sx), at(-sy), at(-sx - sy)];
    let (wx, wy) = (dx.unsigned_abs(), dy.unsigned_abs());
    let any = cells
        .iter()
        .fold(0, |a, c| a | c.as_flattened().iter().fold(0, |o, &v| o | v));
    if frac <= 16 && any < 1 << (30 - frac) {
        let flat = cells.map(|c| c.as_flattened());
        return row_i32(out.as_flattened_mut(), flat, [wx, wy, frac]);
    }
    for (k, o) in out.iter_mut().enumerate() {
        *o = std::array::from_fn(|i| {
            let top = lerp_frac(cells[0][k][i], cells[1][k][i], wx, frac);
            let bottom = lerp_frac(cells[2][k][i], cells[3][k][i], wx, frac);
            lerp_frac(top, bottom, wy, frac)
        });
    }
}

/// [`gather_row`]'s lerps in i32 over the row's channels.
fn row_i32(out: &mut [u32], c: [&[u32]; 4], w: [u32; 3]) {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        // SAFETY: the CPU has AVX2, checked just above.
        return unsafe { row_i32_avx2(out, c, w) };
    }
    row_i32_lanes(out, c, w)
}

/// [`row_i32_lanes`] compiled for AVX2's eight 32-bit lanes (a vector
/// multiply of 32-bit words, which the x86-64 baseline lacks).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn row_i32_avx2(out: &mut [u32], c: [&[u32]; 4], w: [u32; 3]) {
    row_i32_lanes(out, c, w)
}

/// The body of [`row_i32`]; `w` is `[|dx|, |dy|, frac]`.
#[inline(always)]
fn row_i32_lanes(out: &mut [u32], c: [&[u32]; 4], w: [u32; 3]) {
    let [wx, wy, frac] = w;
    let n = out.len();
    let lerp = |a: i32, b: i32, w: i32| lerp_i32(a, b, w, frac);
    // Exact lengths, so that the loop has no bounds checks.
    let [a, b, c, d] = c.map(|s| &s[..n]);
    for k in 0..n {
        let top = lerp(a[k] as i32, b[k] as i32, wx as i32);
        let bottom = lerp(c[k] as i32, d[k] as i32, wx as i32);
        out[k] = lerp(top, bottom, wy as i32) as u32;
    }
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
#[inline]
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
    fn a_row_gathers_as_its_cells_do() {
        let (nx, ny) = (13, 5);
        let mut x = 0x2545_f491_4f6c_dd1du64;
        let mut next = |bits: u32| {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            (x >> 11) as u32 & ((1u64 << bits) - 1) as u32
        };
        // 8-bit colours (the vector lanes), and X-ray sums past 2^22 (one
        // cell at a time).
        for bits in [8, 16, 26] {
            for frac in [4, 8, 12] {
                let prev: Vec<[u32; 4]> = (0..nx * ny)
                    .map(|_| std::array::from_fn(|_| next(bits)))
                    .collect();
                let one = 1i32 << frac;
                for (dx, dy) in [(0, 0), (one, -one), (-(one / 3), one / 2), (5, -7)] {
                    for y in 1..ny - 1 {
                        let mut row = vec![[0; 4]; nx - 2];
                        gather_row(&prev, nx, y, (1, nx - 1), dx, dy, frac, &mut row);
                        for (k, got) in row.iter().enumerate() {
                            let want = gather(&prev, nx, ny, k + 1, y, dx, dy, frac, [0; 4]);
                            assert_eq!(
                                *got,
                                want,
                                "bits {bits} frac {frac} d ({dx}, {dy}) at ({}, {y})",
                                k + 1
                            );
                        }
                    }
                }
            }
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

    #[test]
    fn reset_values_per_mode() {
        assert_eq!(reset_value(Mode::Minip, 8), [255, 0, 0, 0]);
        assert_eq!(reset_value(Mode::Minip, 12), [4095, 0, 0, 0]);
        assert_eq!(reset_value(Mode::Minip, 16), [65535, 0, 0, 0]);
        for mode in [Mode::Composite, Mode::FirstOpaque, Mode::Mip, Mode::Xray] {
            for bits in [8, 12, 16] {
                assert_eq!(reset_value(mode, bits), [0; 4], "{mode:?}");
            }
        }
    }

    /// `round_half_up((a * (2^f - w) + b * w) / 2^f)`, exactly.
    fn lerp_exact(a: u32, b: u32, w: u32, frac: u32) -> u32 {
        let one = 1i128 << frac;
        let num = a as i128 * (one - w as i128) + b as i128 * w as i128;
        (2 * num + one).div_euclid(2 * one) as u32
    }

    /// The bilinear unit by its definition: the ray leaves `(x, y)` towards
    /// `(x - dx, y - dy)`; the 2x2 cells around that point, cells outside the
    /// slice reading `reset`.
    #[allow(clippy::too_many_arguments)]
    fn gather_by_definition(
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
        let at = |cx: i64, cy: i64| {
            if (0..nx as i64).contains(&cx) && (0..ny as i64).contains(&cy) {
                prev[cy as usize * nx + cx as usize]
            } else {
                reset
            }
        };
        let step = |d: i32| match d {
            d if d > 0 => 1,
            d if d < 0 => -1,
            _ => 0,
        };
        let (x, y) = (x as i64, y as i64);
        let (xn, yn) = (x - step(dx), y - step(dy));
        let (wx, wy) = (dx.unsigned_abs(), dy.unsigned_abs());
        std::array::from_fn(|i| {
            let top = lerp_exact(at(x, y)[i], at(xn, y)[i], wx, frac);
            let bottom = lerp_exact(at(x, yn)[i], at(xn, yn)[i], wx, frac);
            lerp_exact(top, bottom, wy, frac)
        })
    }

    #[test]
    fn gather_matches_definition_everywhere() {
        // A 4x3 slice with distinct values per cell and channel, every cell
        // (edges and corners included), increments of both signs.
        let (nx, ny) = (4, 3);
        let prev: Vec<[u32; 4]> = (0..12u32)
            .map(|i| [i * 21 + 3, 255 - i * 17, (i * 97) % 256, i * 5])
            .collect();
        let reset = [9, 250, 7, 131];
        let ds = [-256, -255, -200, -128, -1, 0, 1, 77, 128, 129, 256];
        for y in 0..ny {
            for x in 0..nx {
                for &dx in &ds {
                    for &dy in &ds {
                        assert_eq!(
                            gather(&prev, nx, ny, x, y, dx, dy, 8, reset),
                            gather_by_definition(&prev, nx, ny, x, y, dx, dy, 8, reset),
                            "({x}, {y}) d ({dx}, {dy})"
                        );
                    }
                }
            }
        }
        // Wide X-ray sums (past the i32 shortcut): the i64 lerps.
        let wide: Vec<[u32; 4]> = prev.iter().map(|c| c.map(|v| v << 20)).collect();
        for y in 0..ny {
            for x in 0..nx {
                for &d in &ds {
                    assert_eq!(
                        gather(&wide, nx, ny, x, y, d, -d, 8, reset),
                        gather_by_definition(&wide, nx, ny, x, y, d, -d, 8, reset),
                        "wide ({x}, {y}) d {d}"
                    );
                }
            }
        }
        // Other fractional widths: 2 and 12 bits.
        for (frac, d) in [(2u32, 3i32), (12, -2900)] {
            for y in 0..ny {
                for x in 0..nx {
                    assert_eq!(
                        gather(&prev, nx, ny, x, y, d, -d, frac, reset),
                        gather_by_definition(&prev, nx, ny, x, y, d, -d, frac, reset)
                    );
                }
            }
        }
    }

    #[test]
    fn gather_edges_by_hand() {
        // prev[x + 3y] = 10 * (x + 3y), reset 7.
        let prev: Vec<[u32; 4]> = (0..9).map(|i| [i * 10, 0, 0, 0]).collect();
        let g = |x, y, dx, dy| gather(&prev, 3, 3, x, y, dx, dy, 8, [7, 0, 0, 0])[0];
        // Row 0 and column 0 are inside the slice.
        assert_eq!(g(1, 0, 0, 0), 10);
        assert_eq!(g(0, 1, 0, 0), 30);
        assert_eq!(g(0, 0, 0, 0), 0);
        assert_eq!(g(2, 2, 0, 0), 80);
        // Row -1 is outside: lerp(10, 7, 1/2) = 8.5 -> 9 (half up).
        assert_eq!(g(1, 0, 0, 128), 9);
        assert_eq!(g(1, 0, 0, 256), 7);
        // Row 3 and column 3 are outside.
        assert_eq!(g(1, 2, 0, -256), 7);
        assert_eq!(g(2, 1, -256, 0), 7);
        // lerp(70, 7, 1/2) = 38.5 -> 39.
        assert_eq!(g(1, 2, 0, -128), 39);
        // Corner outside on both axes: top = lerp(80, 7, 1/4) = 61.75 -> 62,
        // bottom = 7, lerp(62, 7, 3/4) = 20.75 -> 21.
        assert_eq!(g(2, 2, -64, -192), 21);
    }

    #[test]
    fn front_to_back_by_hand() {
        // C = C_acc + round((255 - A_acc) * C_new / 255).
        // 255 - 128 = 127: 127 * 200 / 255 = 99.6 -> 100, 127 * 100 / 255 =
        // 49.8 -> 50, 127 * 50 / 255 = 24.9 -> 25.
        let (c, clip) = composite(
            Mode::Composite,
            Order::FrontToBack,
            [100, 50, 0, 128],
            &s([200, 100, 50, 200]),
            8,
        );
        assert_eq!(c, [200, 100, 25, 228]);
        assert!(!clip);
        // First-opaque composites the same way.
        let (c, _) = composite(
            Mode::FirstOpaque,
            Order::FrontToBack,
            [100, 50, 0, 128],
            &s([200, 100, 50, 200]),
            8,
        );
        assert_eq!(c, [200, 100, 25, 228]);
        // Empty buffer: the voxel itself.
        let (c, _) = composite(
            Mode::Composite,
            Order::FrontToBack,
            [0; 4],
            &s([10, 20, 30, 40]),
            8,
        );
        assert_eq!(c, [10, 20, 30, 40]);
    }

    #[test]
    fn back_to_front_by_hand() {
        // C = C_new + round((255 - A_new) * C_acc / 255).
        // 255 - 64 = 191: 191 * 100 / 255 = 74.9 -> 75, 191 * 50 / 255 =
        // 37.45 -> 37, 191 * 128 / 255 = 95.9 -> 96.
        let (c, clip) = composite(
            Mode::Composite,
            Order::BackToFront,
            [100, 50, 0, 128],
            &s([60, 30, 10, 64]),
            8,
        );
        assert_eq!(c, [135, 67, 10, 160]);
        assert!(!clip);
        // 12-bit words: 4095 - 1000 = 3095; 3095 * 2000 / 4095 = 1511.6 -> 1512.
        let (c, _) = composite(
            Mode::FirstOpaque,
            Order::BackToFront,
            [2000, 0, 4095, 2000],
            &s([500, 1000, 0, 1000]),
            12,
        );
        assert_eq!(c, [500 + 1512, 1000, 3095, 1000 + 1512]);
    }

    #[test]
    fn saturation_is_flagged() {
        // A colour above its opacity (not premultiplied) overflows:
        // 200 + (255 - 100) * 255 / 255 = 355 -> 255.
        let (c, clip) = composite(
            Mode::Composite,
            Order::FrontToBack,
            [200, 0, 100, 100],
            &s([255, 255, 0, 255]),
            8,
        );
        assert_eq!(c, [255, 155, 100, 255]);
        assert!(clip);
        let (c, clip) = composite(
            Mode::Composite,
            Order::BackToFront,
            [255, 0, 0, 255],
            &s([200, 0, 0, 100]),
            8,
        );
        // 200 + 155 = 355 -> 255; the alpha reaches 100 + 155 = 255 exactly.
        assert_eq!(c, [255, 0, 0, 255]);
        assert!(clip);
        // Exactly full is not a saturation.
        let (c, clip) = composite(
            Mode::Composite,
            Order::FrontToBack,
            [255; 4],
            &s([255; 4]),
            8,
        );
        assert_eq!(c, [255; 4]);
        assert!(!clip);
        let (c, clip) = composite(
            Mode::Composite,
            Order::FrontToBack,
            [100, 100, 100, 100],
            &s([255; 4]),
            8,
        );
        assert_eq!(c, [255; 4]);
        assert!(!clip);
        // Below full: no flag either way.
        for order in [Order::FrontToBack, Order::BackToFront] {
            let (_, clip) = composite(Mode::Composite, order, [17, 30, 2, 31], &s([0; 4]), 8);
            assert!(!clip);
        }
    }

    #[test]
    fn minip_keeps_the_smallest_valid_voxel() {
        let acc = reset_value(Mode::Minip, 8);
        let (c, clip) = composite(Mode::Minip, Order::FrontToBack, acc, &s([90, 0, 0, 0]), 8);
        assert_eq!(c, [90, 0, 0, 0]);
        assert!(!clip);
        let (c, _) = composite(Mode::Minip, Order::BackToFront, c, &s([120, 0, 0, 0]), 8);
        assert_eq!(c, [90, 0, 0, 0]);
        let (c, _) = composite(Mode::Minip, Order::BackToFront, c, &s([3, 0, 0, 0]), 8);
        assert_eq!(c, [3, 0, 0, 0]);
        let bad = Sample {
            value: [1, 0, 0, 0],
            valid: false,
        };
        assert_eq!(
            composite(Mode::Minip, Order::FrontToBack, [90, 0, 0, 0], &bad, 8),
            ([90, 0, 0, 0], false)
        );
        let bad = Sample {
            value: [200, 0, 0, 0],
            valid: false,
        };
        assert_eq!(
            composite(Mode::Minip, Order::FrontToBack, [255, 0, 0, 0], &bad, 8),
            ([255, 0, 0, 0], false)
        );
    }

    #[test]
    fn mip_keeps_the_largest_valid_voxel() {
        let (c, clip) = composite(Mode::Mip, Order::BackToFront, [0; 4], &s([40, 0, 0, 0]), 8);
        assert_eq!((c, clip), ([40, 0, 0, 0], false));
        let (c, _) = composite(Mode::Mip, Order::FrontToBack, c, &s([12, 0, 0, 0]), 8);
        assert_eq!(c, [40, 0, 0, 0]);
    }

    #[test]
    fn xray_sums_opacities_without_saturating() {
        let (c, clip) = composite(
            Mode::Xray,
            Order::FrontToBack,
            [100, 0, 0, 0],
            &s([50, 0, 0, 0]),
            8,
        );
        assert_eq!((c, clip), ([150, 0, 0, 0], false));
        // Past M: the sum is wider than rgba_bits.
        let (c, clip) = composite(
            Mode::Xray,
            Order::BackToFront,
            [250, 0, 0, 0],
            &s([255, 0, 0, 0]),
            8,
        );
        assert_eq!((c, clip), ([505, 0, 0, 0], false));
        let mut acc = reset_value(Mode::Xray, 8);
        for _ in 0..20 {
            acc = composite(Mode::Xray, Order::FrontToBack, acc, &s([7, 0, 0, 0]), 8).0;
        }
        assert_eq!(acc, [140, 0, 0, 0]);
    }
}
