//! ABC gradient estimation (Cube-4L §3.2, Fig. 8): central differences at
//! voxel positions from the ahead, current and behind slices, in pipeline
//! space. Voxels with a neighbour outside the dataset are flagged by the CFB
//! (`Control::edge`) and never reach here.

use crate::fixed::{bit_len, isqrt, round_shift_sat};
use crate::lut::NORMAL_BITS;

/// `(v(x+1) - v(x-1), v(y+1) - v(y-1), v(z+1) - v(z-1))`: signed, one bit
/// wider than the voxels, not halved.
pub fn central_difference(at: impl Fn(isize, isize, isize) -> u16) -> [i32; 3] {
    [
        at(1, 0, 0) as i32 - at(-1, 0, 0) as i32,
        at(0, 1, 0) as i32 - at(0, -1, 0) as i32,
        at(0, 0, 1) as i32 - at(0, 0, -1) as i32,
    ]
}

/// Integer gradient magnitude `floor(sqrt(gx^2 + gy^2 + gz^2))` for the
/// classifier's gradient-magnitude index.
pub fn magnitude(g: [i32; 3]) -> u64 {
    isqrt(g.iter().map(|&c| (c as i64 * c as i64) as u64).sum())
}

/// Quantize a gradient to the reflectance-map index components: shift all
/// three right (rounding half up) until the largest fits in `NORMAL_BITS - 1`
/// magnitude bits, then saturate to `±(2^(NORMAL_BITS-1) - 1)`.
pub fn quantize_normal(g: [i32; 3]) -> [i32; 3] {
    let m = g.iter().map(|c| c.unsigned_abs()).max().unwrap() as u64;
    let s = bit_len(m).saturating_sub(NORMAL_BITS - 1);
    let lim = (1 << (NORMAL_BITS - 1)) - 1;
    g.map(|c| round_shift_sat(c, s, lim))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normal_quantization_keeps_direction() {
        assert_eq!(quantize_normal([0, 0, 0]), [0, 0, 0]);
        assert_eq!(quantize_normal([3, -2, 1]), [3, -2, 1]);
        assert_eq!(quantize_normal([510, 0, -255]), [15, 0, -8]);
        assert_eq!(quantize_normal([-131070, 65535, 0]), [-15, 8, 0]);
    }

    #[test]
    fn central_difference_of_a_ramp() {
        let g = central_difference(|dx, dy, dz| (100 + 3 * dx + 5 * dy - 7 * dz) as u16);
        assert_eq!(g, [6, 10, -14]);
        assert_eq!(magnitude([3, 4, 0]), 5);
    }
}
