//! ABC gradient estimation (Cube-4L §3.2, Fig. 8): central differences at
//! voxel positions from the ahead, current and behind slices, in pipeline
//! space. Voxels with a neighbour outside the dataset are flagged by the CFB
//! (`Control::edge`) and never reach here.

/// `(v(x+1) - v(x-1), v(y+1) - v(y-1), v(z+1) - v(z-1))`: signed, one bit
/// wider than the voxels, not halved.
#[inline]
pub fn central_difference(at: impl Fn(isize, isize, isize) -> u16) -> [i32; 3] {
    [
        at(1, 0, 0) as i32 - at(-1, 0, 0) as i32,
        at(0, 1, 0) as i32 - at(0, -1, 0) as i32,
        at(0, 0, 1) as i32 - at(0, 0, -1) as i32,
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::common::gradient::magnitude;

    #[test]
    fn central_difference_of_a_ramp() {
        let g = central_difference(|dx, dy, dz| (100 + 3 * dx + 5 * dy - 7 * dz) as u16);
        assert_eq!(g, [6, 10, -14]);
        assert_eq!(magnitude([3, 4, 0]), 5);
    }

    #[test]
    fn central_difference_reads_each_axis_both_ways() {
        // Only the six direct neighbours are read, each with its own value.
        let g = central_difference(|dx, dy, dz| match (dx, dy, dz) {
            (1, 0, 0) => 1000,
            (-1, 0, 0) => 3,
            (0, 1, 0) => 7,
            (0, -1, 0) => 60,
            (0, 0, 1) => 65535,
            (0, 0, -1) => 0,
            other => panic!("read {other:?}"),
        });
        assert_eq!(g, [997, -53, 65535]);
    }
}
