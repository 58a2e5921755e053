//! The compositing unit of both architectures (Cube-4L §3.5-3.7, Figs. 18-21;
//! Cube-3 §2, Eq. 1, whose Ray Projection Cone nodes are this operator front
//! to back): over for composite and first-opaque in either order, max/min
//! for MIP/MinIP and the sum for X-ray, and the value of an empty cell.

use super::plan::Order;
use super::shader::Sample;
use crate::fixed::{max_of, mul_unorm, sat_u};
use scene::Mode;

/// Value of an empty compositing-buffer cell (the SR reset value).
pub fn reset_value(mode: Mode, voxel_bits: u32) -> [u32; 4] {
    match mode {
        Mode::Minip => [max_of(voxel_bits), 0, 0, 0],
        _ => [0; 4],
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
