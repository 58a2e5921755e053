//! The gradient helpers of both architectures' shading (Cube-4L §3.3-3.4;
//! Cube-3 §4): the integer magnitude that indexes the opacity LUT's
//! gradient dimension, and the quantized normal the lighting is looked up by.

use crate::fixed::{bit_len, isqrt, round_shift_sat};
use crate::lut::normal_limit;

/// Integer gradient magnitude `floor(sqrt(gx^2 + gy^2 + gz^2))` for the
/// classifier's gradient-magnitude index.
pub fn magnitude(g: [i32; 3]) -> u64 {
    isqrt(g.iter().map(|&c| (c as i64 * c as i64) as u64).sum())
}

/// Quantize a gradient to the lighting's normal of `bits`-bit signed
/// components (`hardware.normal_bits`): shift all three right (rounding half
/// up) until the largest fits in `bits - 1` magnitude bits, then saturate to
/// `±(2^(bits-1) - 1)`.
#[inline]
pub fn quantize_normal(g: [i32; 3], bits: u32) -> [i32; 3] {
    let m = g.iter().map(|c| c.unsigned_abs()).max().unwrap() as u64;
    let s = bit_len(m).saturating_sub(bits - 1);
    g.map(|c| round_shift_sat(c, s, normal_limit(bits)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lut::MAX_NORMAL_BITS;

    #[test]
    fn normal_quantization_keeps_direction() {
        assert_eq!(quantize_normal([0, 0, 0], 5), [0, 0, 0]);
        assert_eq!(quantize_normal([3, -2, 1], 5), [3, -2, 1]);
        assert_eq!(quantize_normal([510, 0, -255], 5), [15, 0, -8]);
        assert_eq!(quantize_normal([-131070, 65535, 0], 5), [-15, 8, 0]);
    }

    #[test]
    fn magnitude_is_floor_of_length() {
        assert_eq!(magnitude([0, 0, 0]), 0);
        assert_eq!(magnitude([-1, 0, 0]), 1);
        assert_eq!(magnitude([1, 1, 1]), 1); // sqrt(3)
        assert_eq!(magnitude([2, -2, 1]), 3);
        assert_eq!(magnitude([0, 5, -12]), 13);
        // sqrt(27) = 5.196.
        assert_eq!(magnitude([3, 3, 3]), 5);
        // The largest 16-bit difference on every axis: sqrt(3) * 65535.
        assert_eq!(magnitude([65535, -65535, 65535]), 113_509);
    }

    /// The quantizer by its definition: the smallest shift `s` that brings the
    /// largest component below `2^(bits - 1)`, then `floor(c / 2^s + 1/2)`
    /// per component, clamped to `±(2^(bits - 1) - 1)` (±15 at 5 bits).
    fn quantize_by_definition(g: [i32; 3], bits: u32) -> [i32; 3] {
        let m = g.iter().map(|c| c.unsigned_abs()).max().unwrap();
        let mut s = 0;
        while (m >> s) >= 1 << (bits - 1) {
            s += 1;
        }
        let lim = (1i64 << (bits - 1)) - 1;
        g.map(|c| {
            let r = (2 * c as i64 + (1i64 << s)).div_euclid(2i64 << s);
            r.clamp(-lim, lim) as i32
        })
    }

    #[test]
    fn normal_quantizer_small_gradients_exhaustive() {
        for x in -40..=40 {
            for y in -40..=40 {
                for z in [-40, -17, -16, -15, -9, -1, 0, 1, 8, 15, 16, 33] {
                    let g = [x, y, z];
                    for bits in 3..=MAX_NORMAL_BITS {
                        assert_eq!(
                            quantize_normal(g, bits),
                            quantize_by_definition(g, bits),
                            "{g:?} at {bits} bits"
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn normal_quantizer_hand_values() {
        // Largest 15 fits 4 magnitude bits: no shift.
        assert_eq!(quantize_normal([15, -15, 7], 5), [15, -15, 7]);
        // 16 needs one shift: 16/2 = 8, -3/2 = -1.5 -> -1 (half up), 5/2 -> 3.
        assert_eq!(quantize_normal([16, -3, 5], 5), [8, -1, 3]);
        // -16 also needs one shift.
        assert_eq!(quantize_normal([-16, 0, 1], 5), [-8, 0, 1]);
        // 31 -> 15.5 -> 16, saturated to 15; -31 -> -15.5 -> -15.
        assert_eq!(quantize_normal([31, -31, 0], 5), [15, -15, 0]);
        // Four shifts: 255/16 = 15.94 -> 16 -> 15; 40/16 = 2.5 -> 3.
        assert_eq!(quantize_normal([255, 40, -40], 5), [15, 3, -2]);
        // At 6 bits the largest fits 5 magnitude bits: 31 stays, 255 -> 31.9
        // -> 32, saturated to 31; 40/8 = 5.
        assert_eq!(quantize_normal([31, -31, 0], 6), [31, -31, 0]);
        assert_eq!(quantize_normal([255, 40, -40], 6), [31, 5, -5]);
    }

    proptest::proptest! {
        #[test]
        fn normal_quantizer_matches_definition(
            x in -131_070i32..=131_070,
            y in -131_070i32..=131_070,
            z in -131_070i32..=131_070,
        ) {
            let g = [x, y, z];
            for bits in 3..=MAX_NORMAL_BITS {
                proptest::prop_assert_eq!(quantize_normal(g, bits), quantize_by_definition(g, bits));
            }
            let len = ((x as f64).powi(2) + (y as f64).powi(2) + (z as f64).powi(2)).sqrt();
            let m = magnitude(g);
            proptest::prop_assert!((m as f64) <= len && len < (m + 1) as f64);
        }
    }
}
