//! Fixed-point primitives of the Cube-4L datapath.
//!
//! Every rounding, truncation and saturation in the golden model goes through a
//! function here, so the hardware stages can copy them one for one. The
//! arithmetic is hand-written rather than taken from a fixed-point crate
//! because it must equal the RTL bit for bit, including the exact rounding
//! rule of each step.

/// Largest value of an unsigned `bits`-wide word, `2^bits - 1`.
#[inline]
pub fn max_of(bits: u32) -> u32 {
    ((1u64 << bits) - 1) as u32
}

/// `round(a * b / (2^bits - 1))` for `a, b <= 2^bits - 1`, the product of two
/// unorm fractions (where `2^bits - 1` stands for 1.0).
///
/// Hardware form: `t = a*b + 2^(bits-1); (t + (t >> bits)) >> bits`, one
/// multiplier and two adders; exact for every pair of `bits`-wide operands
/// (checked exhaustively for 8 and 12 bits in the tests).
#[inline]
pub fn mul_unorm(a: u32, b: u32, bits: u32) -> u32 {
    let t = a as u64 * b as u64 + (1u64 << (bits - 1));
    ((t + (t >> bits)) >> bits) as u32
}

/// Saturate an unsigned value to `max`.
#[inline]
pub fn sat_u(v: u64, max: u32) -> u32 {
    v.min(max as u64) as u32
}

/// [`lerp_frac`] in i32, where every `(b - a)·w` fits 31 bits: the same
/// result, in a form the compiler puts in vector lanes.
#[inline(always)]
pub fn lerp_i32(a: i32, b: i32, w: i32, frac: u32) -> i32 {
    a + (((b - a) * w + (1 << (frac - 1))) >> frac)
}

/// Linear interpolation from `a` towards `b` by `w / 2^frac` (`0 <= w <= 2^frac`):
/// `a + ((b - a) * w + 2^(frac-1)) >> frac`, an arithmetic shift, so the product
/// is rounded half up. The result always lies between `a` and `b`.
pub fn lerp_frac(a: u32, b: u32, w: u32, frac: u32) -> u32 {
    let d = b as i64 - a as i64;
    let p = (d * w as i64 + (1i64 << (frac - 1))) >> frac;
    (a as i64 + p) as u32
}

/// `round(n / d)`, halves away from zero, for the per-voxel sight-ray divider.
/// `d` must not be zero.
pub fn round_div(n: i64, d: i64) -> i64 {
    let (n, d) = if d < 0 { (-n, -d) } else { (n, d) };
    if n >= 0 {
        (n + d / 2) / d
    } else {
        -((-n + d / 2) / d)
    }
}

/// Quantize a real number to a signed fixed-point integer with `frac` fractional
/// bits, rounding halves away from zero (`f64::round`).
pub fn quantize(v: f64, frac: u32) -> i64 {
    (v * (1u64 << frac) as f64).round() as i64
}

/// Quantize a fraction in `[0, 1]` (clamped) to a unorm word of `bits` bits.
pub fn quantize_unorm(v: f64, bits: u32) -> u32 {
    (v.clamp(0.0, 1.0) * max_of(bits) as f64).round() as u32
}

/// Arithmetic right shift by `s` rounding half up, then saturation to the signed
/// range `[-lim, lim]`: the normalisation step of the gradient quantizer.
#[inline]
pub fn round_shift_sat(v: i32, s: u32, lim: i32) -> i32 {
    let r = if s == 0 { v } else { (v + (1 << (s - 1))) >> s };
    r.clamp(-lim, lim)
}

/// Number of bits needed to hold `v` (0 for 0): the leading-one detector.
#[inline]
pub fn bit_len(v: u64) -> u32 {
    64 - v.leading_zeros()
}

/// Integer square root, rounded down (the gradient-magnitude unit).
pub fn isqrt(v: u64) -> u64 {
    if v < 2 {
        return v;
    }
    let mut x = (v as f64).sqrt() as u64;
    while x * x > v {
        x -= 1;
    }
    while (x + 1) * (x + 1) <= v {
        x += 1;
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn exact_mul(a: u32, b: u32, bits: u32) -> u32 {
        let m = max_of(bits) as u64;
        ((2 * a as u64 * b as u64 + m) / (2 * m)) as u32
    }

    #[test]
    fn mul_unorm_exact_8_bits() {
        for a in 0..=255 {
            for b in 0..=255 {
                assert_eq!(mul_unorm(a, b, 8), exact_mul(a, b, 8), "{a}*{b}");
            }
        }
    }

    #[test]
    fn mul_unorm_exact_12_bits() {
        for a in 0..=4095 {
            for b in 0..=4095 {
                assert_eq!(mul_unorm(a, b, 12), exact_mul(a, b, 12), "{a}*{b}");
            }
        }
    }

    proptest! {
        #[test]
        fn mul_unorm_matches_exact(bits in 4u32..=16, a in 0u32..65536, b in 0u32..65536) {
            let m = max_of(bits);
            let (a, b) = (a % (m + 1), b % (m + 1));
            prop_assert_eq!(mul_unorm(a, b, bits), exact_mul(a, b, bits));
        }

        #[test]
        fn lerp_stays_between(a in 0u32..65536, b in 0u32..65536, w in 0u32..=256) {
            let r = lerp_frac(a, b, w, 8);
            prop_assert!(r >= a.min(b) && r <= a.max(b));
        }

        #[test]
        fn round_div_is_nearest(n in -1_000_000i64..1_000_000, d in 1i64..5000, neg in any::<bool>()) {
            let d = if neg { -d } else { d };
            let q = round_div(n, d);
            let exact = n as f64 / d as f64;
            prop_assert!((q as f64 - exact).abs() <= 0.5 + 1e-9);
        }

        #[test]
        fn isqrt_floor(v in 0u64..(1u64 << 40)) {
            let r = isqrt(v);
            prop_assert!(r * r <= v && (r + 1) * (r + 1) > v);
        }
    }

    #[test]
    fn lerp_end_points() {
        assert_eq!(lerp_frac(10, 200, 0, 8), 10);
        assert_eq!(lerp_frac(10, 200, 256, 8), 200);
        assert_eq!(lerp_frac(200, 10, 256, 8), 10);
        assert_eq!(lerp_frac(0, 255, 128, 8), 128);
    }

    #[test]
    fn round_shift_saturates() {
        assert_eq!(round_shift_sat(31, 1, 15), 15);
        assert_eq!(round_shift_sat(-31, 1, 15), -15);
        assert_eq!(round_shift_sat(5, 0, 15), 5);
        assert_eq!(round_shift_sat(-3, 1, 15), -1);
    }

    #[test]
    fn max_of_word_widths() {
        assert_eq!(max_of(1), 1);
        assert_eq!(max_of(8), 255);
        assert_eq!(max_of(12), 4095);
        assert_eq!(max_of(32), u32::MAX);
    }

    #[test]
    fn sat_u_clamps_at_max() {
        assert_eq!(sat_u(0, 255), 0);
        assert_eq!(sat_u(254, 255), 254);
        assert_eq!(sat_u(255, 255), 255);
        assert_eq!(sat_u(256, 255), 255);
        assert_eq!(sat_u(u64::MAX, 4095), 4095);
    }

    /// `round(n / d)` for `d > 0`, halves up, by exact integer arithmetic.
    fn round_half_up(n: i128, d: i128) -> i128 {
        (2 * n + d).div_euclid(2 * d)
    }

    #[test]
    fn lerp_frac_is_exact_rational_rounding() {
        // lerp = round_half_up((a * (2^f - w) + b * w) / 2^f), every pair of
        // 6-bit ends and every weight, for 2 to 8 fractional bits.
        for frac in 2..=8u32 {
            let one = 1i128 << frac;
            for a in 0..64u32 {
                for b in 0..64u32 {
                    for w in 0..=(1u32 << frac) {
                        let num = a as i128 * (one - w as i128) + b as i128 * w as i128;
                        let want = round_half_up(num, one) as u32;
                        assert_eq!(lerp_frac(a, b, w, frac), want, "{a} {b} {w} {frac}");
                    }
                }
            }
        }
        // Wide ends: 15-bit values, 15 fractional bits (the widest the
        // scene accepts), at a few weights.
        for (a, b, w) in [(0, 32767, 1), (32767, 0, 16384), (12345, 23456, 32767)] {
            let num = a as i128 * ((1 << 15) - w as i128) + b as i128 * w as i128;
            assert_eq!(lerp_frac(a, b, w, 15) as i128, round_half_up(num, 1 << 15));
        }
    }

    #[test]
    fn round_div_halves_away_from_zero() {
        // Halves, every sign combination.
        assert_eq!(round_div(5, 2), 3);
        assert_eq!(round_div(-5, 2), -3);
        assert_eq!(round_div(5, -2), -3);
        assert_eq!(round_div(-5, -2), 3);
        assert_eq!(round_div(1, 2), 1);
        assert_eq!(round_div(-1, 2), -1);
        assert_eq!(round_div(-1, -2), 1);
        // Not halves: nearest.
        assert_eq!(round_div(7, 3), 2);
        assert_eq!(round_div(-7, 3), -2);
        assert_eq!(round_div(8, -3), -3);
        assert_eq!(round_div(-8, -3), 3);
        assert_eq!(round_div(1, 3), 0);
        assert_eq!(round_div(-1, 3), 0);
        assert_eq!(round_div(0, -7), 0);
        assert_eq!(round_div(12, 4), 3);
        assert_eq!(round_div(-12, 4), -3);
        // Against exact rounding over a range of both signs.
        for n in -300i64..=300 {
            for d in (-17i64..=17).filter(|&d| d != 0) {
                let (an, ad) = (n.unsigned_abs() as i128, d.unsigned_abs() as i128);
                let mag = (2 * an + ad) / (2 * ad);
                let want = if (n < 0) != (d < 0) { -mag } else { mag };
                assert_eq!(round_div(n, d) as i128, want, "{n}/{d}");
            }
        }
    }

    #[test]
    fn quantize_rounds_halves_away_from_zero() {
        assert_eq!(quantize(0.0, 8), 0);
        assert_eq!(quantize(1.0, 8), 256);
        assert_eq!(quantize(-0.5, 8), -128);
        assert_eq!(quantize(0.75, 2), 3);
        assert_eq!(quantize(0.625, 2), 3); // 2.5 -> 3
        assert_eq!(quantize(-0.625, 2), -3); // -2.5 -> -3
        assert_eq!(quantize(0.3, 4), 5); // 4.8
        assert_eq!(quantize(12.34, 0), 12);
    }

    #[test]
    fn quantize_unorm_rounds_and_clamps() {
        assert_eq!(quantize_unorm(0.0, 8), 0);
        assert_eq!(quantize_unorm(1.0, 8), 255);
        assert_eq!(quantize_unorm(0.5, 8), 128); // 127.5 -> 128
        assert_eq!(quantize_unorm(0.25, 8), 64); // 63.75
        assert_eq!(quantize_unorm(0.2, 12), 819);
        assert_eq!(quantize_unorm(0.001, 8), 0); // 0.255
        assert_eq!(quantize_unorm(-0.25, 8), 0);
        assert_eq!(quantize_unorm(1.5, 8), 255);
        assert_eq!(quantize_unorm(f64::INFINITY, 4), 15);
        for k in 0..=4095u32 {
            assert_eq!(quantize_unorm(k as f64 / 4095.0, 12), k);
        }
    }

    #[test]
    fn bit_len_is_the_leading_one() {
        assert_eq!(bit_len(0), 0);
        assert_eq!(bit_len(1), 1);
        assert_eq!(bit_len(2), 2);
        assert_eq!(bit_len(15), 4);
        assert_eq!(bit_len(16), 5);
        assert_eq!(bit_len(u64::MAX), 64);
    }

    fn exact_isqrt(v: u64) -> u64 {
        // Bisection in u128: independent of the f64 estimate.
        let (mut lo, mut hi) = (0u128, 1u128 << 33);
        while hi - lo > 1 {
            let mid = (lo + hi) / 2;
            if mid * mid <= v as u128 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        lo as u64
    }

    #[test]
    fn isqrt_small_values_exhaustive() {
        let mut r = 0u64;
        for v in 0..=200_000u64 {
            if (r + 1) * (r + 1) <= v {
                r += 1;
            }
            assert_eq!(isqrt(v), r, "isqrt({v})");
        }
    }

    #[test]
    fn isqrt_around_large_squares() {
        // Beyond 2^53 the f64 estimate of sqrt(k^2 - 1) rounds up to k, so
        // the correction loop must bring it down.
        for k in [
            (1u64 << 26) + 1,
            (1 << 27) + 3,
            (1 << 30) + 1,
            (1 << 31) - 1,
            (1 << 31) + 12345,
            3_037_000_499,
        ] {
            for v in [k * k - 2, k * k - 1, k * k, k * k + 1, k * k + 2 * k] {
                assert_eq!(isqrt(v), exact_isqrt(v), "isqrt({v})");
            }
        }
        assert_eq!(isqrt(((1u64 << 30) + 1) * ((1 << 30) + 1) - 1), 1 << 30);
    }

    proptest! {
        /// Why isqrt's second correction loop never runs: the correctly
        /// rounded f64 estimate is never below the floor (docs/mutants.md).
        #[test]
        fn isqrt_estimate_never_below_floor(k in 1u64..(1 << 32) - 1, w in any::<u64>()) {
            for v in [k * k - 1, k * k, k * k + 2 * k, w] {
                prop_assert!((v as f64).sqrt() as u64 >= exact_isqrt(v), "{}", v);
            }
        }
    }
}
