//! The Ray Projection Cone (§2, Eq. 1; §5, Fig. 12): a folded binary tree
//! that composites a ray's samples, `p` leaves at a time, with an
//! accumulator across the ray's segments.
//!
//! The tree, exactly as the hardware builds it for `p` leaves (a power of
//! two): segment `s` of a ray holds samples `s·p .. s·p + p - 1` (front to
//! back); leaf `i` takes sample `s·p + i`, and a sample beyond the ray's end
//! is the identity. Level 0 is the leaves; node `i` of level `j + 1` is
//! `op(node 2i, node 2i + 1)` of level `j`, the left child in front. After
//! `log2 p` levels the root is combined into the accumulator, which is in
//! front of it: `acc = op(acc, root)`, starting from the identity. In fixed
//! point the grouping changes the rounding, so `p` is part of the spec.
//!
//! Operators (`M = 2^rgba_bits - 1`, `mul = fixed::mul_unorm`):
//! - Composite and first-opaque (Eq. 1): `C' = sat(C_L + mul(M - α_L, C_R))`,
//!   the same for α. First-opaque leaves have α in {0, M}, so the operator
//!   keeps the front-most opaque sample.
//! - MIP / MinIP: the max / min of the valid children.
//! - X-ray (weighted sum): `C_L + C_R`, no saturation (`rgba_bits +
//!   ceil(log2 K)` bits).
//!
//! Identities: an all-zero leaf (composite, first-opaque, X-ray), an invalid
//! leaf (MIP, MinIP). Early ray termination in software: once the
//! accumulator's α is `M`, `op(acc, x) = acc` for every `x`, so the rest of
//! the ray is skipped without changing a bit.

use crate::common::compositor::{composite, reset_value};
use crate::common::plan::Order;
use crate::common::shader::Sample;
use scene::Mode;

/// A tree value: `[r, g, b, α]` (composite), `[value, 0, 0, 0]` (MIP,
/// MinIP, X-ray); `valid` is false for the MIP/MinIP identity.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Leaf {
    pub value: [u32; 4],
    pub valid: bool,
}

/// The identity of `mode`'s operator.
pub fn identity(mode: Mode) -> Leaf {
    Leaf {
        value: [0; 4],
        valid: !matches!(mode, Mode::Mip | Mode::Minip),
    }
}

/// One tree node: `op(front, back)`, and whether a saturation clipped.
pub fn node(mode: Mode, l: Leaf, r: Leaf, rgba_bits: u32) -> (Leaf, bool) {
    match mode {
        // Cube-4L's compositing unit front to back is the same operator:
        // the left child is the accumulated value, the right one the new.
        Mode::Composite | Mode::FirstOpaque | Mode::Xray => {
            let back = Sample {
                value: r.value,
                valid: true,
            };
            let (value, clipped) = composite(mode, Order::FrontToBack, l.value, &back, rgba_bits);
            (Leaf { value, valid: true }, clipped)
        }
        // Both children may be empty here (Cube-4L's accumulator never is).
        Mode::Mip | Mode::Minip => {
            let pick = |a: u32, b: u32| {
                if mode == Mode::Mip {
                    a.max(b)
                } else {
                    a.min(b)
                }
            };
            let out = match (l.valid, r.valid) {
                (true, true) => Leaf {
                    value: [pick(l.value[0], r.value[0]), 0, 0, 0],
                    valid: true,
                },
                (true, false) => l,
                _ => r,
            };
            (out, false)
        }
    }
}

/// The tree over one segment of `p` leaves (`leaves.len() == p`, a power of
/// two): the root and the number of clipped nodes.
pub fn tree(mode: Mode, leaves: &[Leaf], rgba_bits: u32) -> (Leaf, u64) {
    debug_assert!(leaves.len().is_power_of_two());
    let mut level = leaves.to_vec();
    let clips = fold(mode, &mut level, rgba_bits);
    (level[0], clips)
}

/// [`tree`] in place: level by level, node `i` overwrites `level[i]` (its
/// children `2i` and `2i + 1` are read first, and no later node reads it),
/// leaving the root in `level[0]`. Returns the number of clipped nodes.
pub fn fold(mode: Mode, level: &mut [Leaf], rgba_bits: u32) -> u64 {
    let mut clips = 0;
    let mut n = level.len();
    while n > 1 {
        for i in 0..n / 2 {
            let (v, clipped) = node(mode, level[2 * i], level[2 * i + 1], rgba_bits);
            clips += clipped as u64;
            level[i] = v;
        }
        n /= 2;
    }
    clips
}

/// The base-plane pixel of a finished ray: the accumulator, or the reset
/// value where no sample was valid (MinIP: full scale, as Cube-4L).
pub fn pixel(mode: Mode, acc: Leaf, voxel_bits: u32) -> [u32; 4] {
    if acc.valid {
        acc.value
    } else {
        reset_value(mode, voxel_bits)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn leaf(v: [u32; 4]) -> Leaf {
        Leaf {
            value: v,
            valid: true,
        }
    }

    #[test]
    fn tree_counts_every_clipped_node() {
        // Full colour at zero opacity: every node's sum passes 255.
        let leaves = [leaf([255, 255, 255, 0]); 4];
        let (root, clips) = tree(Mode::Composite, &leaves, 8);
        assert_eq!(root.value, [255, 255, 255, 0]);
        assert_eq!(clips, 3);
        let quiet = [leaf([10, 10, 10, 0]); 4];
        assert_eq!(tree(Mode::Composite, &quiet, 8), (leaf([40, 40, 40, 0]), 0));
    }

    #[test]
    fn over_by_hand() {
        // Front α = 0.5 (128/255): C' = 100 + round(127·80/255) = 100 + 40.
        let (c, clip) = node(
            Mode::Composite,
            leaf([100, 0, 0, 128]),
            leaf([80, 0, 0, 255]),
            8,
        );
        assert_eq!(c.value, [140, 0, 0, 255]);
        assert!(!clip);
        // Identity on either side.
        let x = leaf([9, 8, 7, 200]);
        assert_eq!(node(Mode::Composite, identity(Mode::Composite), x, 8).0, x);
        assert_eq!(node(Mode::Composite, x, identity(Mode::Composite), 8).0, x);
    }

    #[test]
    fn over_equals_the_compositing_unit_front_to_back() {
        // The same operator as the compositing unit (`common::compositor`,
        // Cube-4L's), front to back.
        for (a, b) in [
            ([10, 20, 30, 40], [250, 1, 2, 250]),
            ([255, 255, 0, 255], [3, 3, 3, 3]),
            ([0, 0, 0, 0], [77, 0, 5, 90]),
        ] {
            let s = Sample {
                value: b,
                valid: true,
            };
            let want = composite(Mode::Composite, Order::FrontToBack, a, &s, 8);
            let (got, clip) = node(Mode::Composite, leaf(a), leaf(b), 8);
            assert_eq!((got.value, clip), want);
        }
    }

    #[test]
    fn tree_shape_is_pairwise_front_first() {
        // Four leaves, each α = 1/2 of a channel: ((0 over 1) over (2 over 3)).
        let l = [
            leaf([128, 0, 0, 128]),
            leaf([0, 128, 0, 128]),
            leaf([0, 0, 128, 128]),
            leaf([128, 128, 128, 128]),
        ];
        let (a, _) = node(Mode::Composite, l[0], l[1], 8);
        let (b, _) = node(Mode::Composite, l[2], l[3], 8);
        let (want, _) = node(Mode::Composite, a, b, 8);
        assert_eq!(tree(Mode::Composite, &l, 8).0, want);
        // By hand: a = [128, 0 + round(127·128/255), 0, 128 + 64] =
        // [128, 64, 0, 192], b = [64, 64, 192, 192], root = a +
        // round(63·b/255) = [144, 80, 47, 239].
        assert_eq!(a.value, [128, 64, 0, 192]);
        assert_eq!(want.value, [144, 80, 47, 239]);
    }

    #[test]
    fn mip_minip_ignore_invalid_and_xray_sums() {
        let none = identity(Mode::Mip);
        let l = [none, leaf([7, 0, 0, 0]), leaf([3, 0, 0, 0]), none];
        assert_eq!(tree(Mode::Mip, &l, 8).0.value[0], 7);
        assert_eq!(tree(Mode::Minip, &l, 8).0.value[0], 3);
        assert!(!tree(Mode::Mip, &[none; 4], 8).0.valid);
        assert_eq!(
            pixel(Mode::Minip, identity(Mode::Minip), 12),
            [4095, 0, 0, 0]
        );
        let x = [leaf([255, 0, 0, 0]); 8];
        assert_eq!(tree(Mode::Xray, &x, 8).0.value[0], 8 * 255);
    }

    #[test]
    fn near_transparent_accumulation_through_the_tree_by_p() {
        // 256 samples of α = 1/255 (colour premultiplied, also 1/255).
        // Exact: 1 - (254/255)^256 = 0.6339, i.e. 161.6 of 255.
        // p = 1 is a plain front-to-back chain: mul(255 - α, 1) rounds to 1
        // only while 255 - α >= 128, so α stalls at 128 (0.502). A tree
        // first sums leaves pairwise (1 over 1 = 2, exact while α is
        // small), and its roots stay above the rounding floor much longer:
        // 160, 163 and 162 for p = 2, 4 and 8, within 1.5 % of exact.
        let want = [(1usize, 128), (2, 160), (4, 163), (8, 162)];
        for (p, a) in want {
            let mut acc = identity(Mode::Composite);
            for _ in 0..256 / p {
                let (root, _) = tree(Mode::Composite, &vec![leaf([1, 1, 1, 1]); p], 8);
                acc = node(Mode::Composite, acc, root, 8).0;
            }
            assert_eq!(acc.value, [a; 4], "p = {p}");
        }
    }

    #[test]
    fn opaque_leaf_hides_everything_behind_at_any_p() {
        // α = 1 in front: the rest of the ray cannot change a bit (the
        // software's early ray termination relies on it).
        let front = leaf([200, 100, 50, 255]);
        for p in [1usize, 2, 4, 8] {
            let mut l = vec![leaf([9, 9, 9, 200]); p];
            l[0] = front;
            assert_eq!(tree(Mode::Composite, &l, 8).0, front);
            let (acc, _) = node(Mode::Composite, front, tree(Mode::Composite, &l, 8).0, 8);
            assert_eq!(acc, front);
        }
    }
}
