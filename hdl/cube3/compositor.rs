//! The Ray Projection Cone of Cube-3 (§2, Eq. 1; §5, Fig. 12): a folded
//! binary compositing tree with a pipeline register in every node, `P`
//! leaves and an accumulator across a ray's segments, bit for bit as
//! `golden_model::cube3::rpc` (`tree`, `node`, `pixel`).
//!
//! **Segments.** A ray of `K` samples arrives as `ceil(K / P)` segments on
//! consecutive clocks, `P` samples each (leaf `i` takes sample `s·P + i`,
//! the identity beyond the ray's end); `first` and `last` mark the ray's
//! first and last segment, so rays follow each other without a gap.
//!
//! **Tree.** The leaves are registered on entry. The `P - 1` tree nodes
//! (each an [`RpcNode`]) are numbered level by level: nodes `0 .. P/2` take
//! leaves `2j, 2j + 1`; node `j >= P/2` takes nodes `2j - P, 2j - P + 1`; the
//! root is node `P - 2` (the entry register itself when `P = 1`). Node `P -
//! 1` is the accumulator: `acc = op(first ? identity : acc, root)`. The
//! left child is always in front, as in the golden model, whose grouping
//! (and so its rounding) this is.
//!
//! **Pixel.** The segment flags travel beside the values through registers
//! numbered like the nodes. [`latency`]`(P)` clocks after a ray's last
//! segment entered, `done` is high and `pixel_*` holds its base-plane
//! pixel: the accumulator, or the mode's reset value where no sample was
//! valid (`has_sample` low; MinIP's is full scale).
//!
//! Early ray termination is not built: once α is full, `op(acc, x) = acc`,
//! so the hardware keeps compositing without changing a bit, and a ray
//! always takes its `ceil(K / P)` clocks.

use super::rpc_node::RpcNode;
use rust_hdl::prelude::*;
use scene::Mode;

/// Clocks from a ray's last segment at the leaves to its pixel: the entry
/// register, `log2 P` tree levels and the accumulator.
pub fn latency(p: usize) -> usize {
    p.trailing_zeros() as usize + 2
}

/// The Ray Projection Cone with `P` leaves (1, 2, 4 or 8).
#[derive(LogicBlock)]
pub struct Rpc<const P: usize> {
    pub clock: Signal<In, Clock>,
    /// Leaf `i`: channel r (32 bits for the X-ray sum), g, b, a, and whether
    /// the sample takes part (MIP / MinIP).
    pub leaf_r: [Signal<In, Bits<32>>; P],
    pub leaf_g: [Signal<In, Bits<16>>; P],
    pub leaf_b: [Signal<In, Bits<16>>; P],
    pub leaf_a: [Signal<In, Bits<16>>; P],
    pub leaf_valid: [Signal<In, Bit>; P],
    /// The segment is its ray's first / last.
    pub first: Signal<In, Bit>,
    pub last: Signal<In, Bit>,
    /// A ray's pixel is out.
    pub done: Signal<Out, Bit>,
    pub pixel_r: Signal<Out, Bits<32>>,
    pub pixel_g: Signal<Out, Bits<16>>,
    pub pixel_b: Signal<Out, Bits<16>>,
    pub pixel_a: Signal<Out, Bits<16>>,
    /// Some sample of the ray was valid (MIP / MinIP; always for the rest).
    pub has_sample: Signal<Out, Bit>,
    /// The identity's valid bit, and the pixel of a ray without a sample.
    identity_valid: Constant<Bit>,
    reset_r: Constant<Bits<32>>,
    leaf_r_q: [DFF<Bits<32>>; P],
    leaf_g_q: [DFF<Bits<16>>; P],
    leaf_b_q: [DFF<Bits<16>>; P],
    leaf_a_q: [DFF<Bits<16>>; P],
    leaf_valid_q: [DFF<Bit>; P],
    /// `[first, last]` beside the entry register, each node and the root.
    flags_q: DFF<Bits<2>>,
    node_flags_q: [DFF<Bits<2>>; P],
    root_flags: Signal<Local, Bits<2>>,
    nodes: [RpcNode; P],
    root_r: Signal<Local, Bits<32>>,
    root_g: Signal<Local, Bits<16>>,
    root_b: Signal<Local, Bits<16>>,
    root_a: Signal<Local, Bits<16>>,
    root_valid: Signal<Local, Bit>,
}

impl<const P: usize> Rpc<P> {
    /// Level-1 nodes, and the accumulator's index.
    const HALF: usize = P / 2;
    const ACC: usize = P - 1;
    /// `for p in Self::P..Self::P_END` runs once with `p = P`: rust-hdl's
    /// Verilog generator evaluates an array index from loop variables and
    /// literals only, so the indices below name `P` through `p`.
    const P: usize = P;
    const P_END: usize = P + 1;

    pub fn new(mode: Mode, rgba_bits: u32, voxel_bits: u32) -> Rpc<P> {
        if let Err(e) = crate::common::lanes::built(P) {
            panic!("the RPC's leaves: {e}");
        }
        let reset = golden_model::common::compositor::reset_value(mode, voxel_bits)[0];
        Rpc {
            clock: Default::default(),
            leaf_r: std::array::from_fn(|_| Default::default()),
            leaf_g: std::array::from_fn(|_| Default::default()),
            leaf_b: std::array::from_fn(|_| Default::default()),
            leaf_a: std::array::from_fn(|_| Default::default()),
            leaf_valid: std::array::from_fn(|_| Default::default()),
            first: Default::default(),
            last: Default::default(),
            done: Default::default(),
            pixel_r: Default::default(),
            pixel_g: Default::default(),
            pixel_b: Default::default(),
            pixel_a: Default::default(),
            has_sample: Default::default(),
            identity_valid: Constant::new(!matches!(mode, Mode::Mip | Mode::Minip)),
            reset_r: Constant::new((reset as u64).to_bits()),
            leaf_r_q: std::array::from_fn(|_| Default::default()),
            leaf_g_q: std::array::from_fn(|_| Default::default()),
            leaf_b_q: std::array::from_fn(|_| Default::default()),
            leaf_a_q: std::array::from_fn(|_| Default::default()),
            leaf_valid_q: std::array::from_fn(|_| Default::default()),
            flags_q: Default::default(),
            node_flags_q: std::array::from_fn(|_| Default::default()),
            root_flags: Default::default(),
            nodes: std::array::from_fn(|_| RpcNode::new(mode, rgba_bits)),
            root_r: Default::default(),
            root_g: Default::default(),
            root_b: Default::default(),
            root_a: Default::default(),
            root_valid: Default::default(),
        }
    }
}

impl<const P: usize> Logic for Rpc<P> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, flags_q);
        for i in 0..P {
            self.leaf_r_q[i].clock.next = self.clock.val();
            self.leaf_g_q[i].clock.next = self.clock.val();
            self.leaf_b_q[i].clock.next = self.clock.val();
            self.leaf_a_q[i].clock.next = self.clock.val();
            self.leaf_valid_q[i].clock.next = self.clock.val();
            self.node_flags_q[i].clock.next = self.clock.val();
            self.nodes[i].clock.next = self.clock.val();
            self.leaf_r_q[i].d.next = self.leaf_r[i].val();
            self.leaf_g_q[i].d.next = self.leaf_g[i].val();
            self.leaf_b_q[i].d.next = self.leaf_b[i].val();
            self.leaf_a_q[i].d.next = self.leaf_a[i].val();
            self.leaf_valid_q[i].d.next = self.leaf_valid[i].val();
        }
        self.flags_q.d.next = bit_cast::<2, 1>(self.first.val().into())
            | (bit_cast::<2, 1>(self.last.val().into()) << 1);
        // The root: the entry register for one leaf; each level below
        // overwrites it, so the last node assigned (P - 2) wins.
        self.root_r.next = self.leaf_r_q[0].q.val();
        self.root_g.next = self.leaf_g_q[0].q.val();
        self.root_b.next = self.leaf_b_q[0].q.val();
        self.root_a.next = self.leaf_a_q[0].q.val();
        self.root_valid.next = self.leaf_valid_q[0].q.val();
        self.root_flags.next = self.flags_q.q.val();
        // Level 1: leaves 2j (front) and 2j + 1.
        for j in 0..Self::HALF {
            self.nodes[j].front_r.next = self.leaf_r_q[2 * j].q.val();
            self.nodes[j].front_g.next = self.leaf_g_q[2 * j].q.val();
            self.nodes[j].front_b.next = self.leaf_b_q[2 * j].q.val();
            self.nodes[j].front_a.next = self.leaf_a_q[2 * j].q.val();
            self.nodes[j].front_valid.next = self.leaf_valid_q[2 * j].q.val();
            self.nodes[j].back_r.next = self.leaf_r_q[2 * j + 1].q.val();
            self.nodes[j].back_g.next = self.leaf_g_q[2 * j + 1].q.val();
            self.nodes[j].back_b.next = self.leaf_b_q[2 * j + 1].q.val();
            self.nodes[j].back_a.next = self.leaf_a_q[2 * j + 1].q.val();
            self.nodes[j].back_valid.next = self.leaf_valid_q[2 * j + 1].q.val();
            self.node_flags_q[j].d.next = self.flags_q.q.val();
            self.root_r.next = self.nodes[j].out_r.val();
            self.root_g.next = self.nodes[j].out_g.val();
            self.root_b.next = self.nodes[j].out_b.val();
            self.root_a.next = self.nodes[j].out_a.val();
            self.root_valid.next = self.nodes[j].out_valid.val();
            self.root_flags.next = self.node_flags_q[j].q.val();
        }
        for p in Self::P..Self::P_END {
            // Upper levels: nodes 2j - P (front) and 2j - P + 1.
            for j in Self::HALF..Self::ACC {
                self.nodes[j].front_r.next = self.nodes[2 * j - p].out_r.val();
                self.nodes[j].front_g.next = self.nodes[2 * j - p].out_g.val();
                self.nodes[j].front_b.next = self.nodes[2 * j - p].out_b.val();
                self.nodes[j].front_a.next = self.nodes[2 * j - p].out_a.val();
                self.nodes[j].front_valid.next = self.nodes[2 * j - p].out_valid.val();
                self.nodes[j].back_r.next = self.nodes[2 * j - p + 1].out_r.val();
                self.nodes[j].back_g.next = self.nodes[2 * j - p + 1].out_g.val();
                self.nodes[j].back_b.next = self.nodes[2 * j - p + 1].out_b.val();
                self.nodes[j].back_a.next = self.nodes[2 * j - p + 1].out_a.val();
                self.nodes[j].back_valid.next = self.nodes[2 * j - p + 1].out_valid.val();
                self.node_flags_q[j].d.next = self.node_flags_q[2 * j - p].q.val();
                self.root_r.next = self.nodes[j].out_r.val();
                self.root_g.next = self.nodes[j].out_g.val();
                self.root_b.next = self.nodes[j].out_b.val();
                self.root_a.next = self.nodes[j].out_a.val();
                self.root_valid.next = self.nodes[j].out_valid.val();
                self.root_flags.next = self.node_flags_q[j].q.val();
            }
            // The accumulator, node P - 1: in front of the root, restarted from
            // the identity at a ray's first segment.
            self.nodes[p - 1].front_r.next = self.nodes[p - 1].out_r.val();
            self.nodes[p - 1].front_g.next = self.nodes[p - 1].out_g.val();
            self.nodes[p - 1].front_b.next = self.nodes[p - 1].out_b.val();
            self.nodes[p - 1].front_a.next = self.nodes[p - 1].out_a.val();
            self.nodes[p - 1].front_valid.next = self.nodes[p - 1].out_valid.val();
            if self.root_flags.val().get_bit(0) {
                self.nodes[p - 1].front_r.next = 0.into();
                self.nodes[p - 1].front_g.next = 0.into();
                self.nodes[p - 1].front_b.next = 0.into();
                self.nodes[p - 1].front_a.next = 0.into();
                self.nodes[p - 1].front_valid.next = self.identity_valid.val();
            }
            self.nodes[p - 1].back_r.next = self.root_r.val();
            self.nodes[p - 1].back_g.next = self.root_g.val();
            self.nodes[p - 1].back_b.next = self.root_b.val();
            self.nodes[p - 1].back_a.next = self.root_a.val();
            self.nodes[p - 1].back_valid.next = self.root_valid.val();
            self.node_flags_q[p - 1].d.next = self.root_flags.val();
            // The pixel.
            self.done.next = self.node_flags_q[p - 1].q.val().get_bit(1);
            self.has_sample.next = self.nodes[p - 1].out_valid.val();
            self.pixel_r.next = self.nodes[p - 1].out_r.val();
            self.pixel_g.next = self.nodes[p - 1].out_g.val();
            self.pixel_b.next = self.nodes[p - 1].out_b.val();
            self.pixel_a.next = self.nodes[p - 1].out_a.val();
            if !self.nodes[p - 1].out_valid.val() {
                self.pixel_r.next = self.reset_r.val();
            }
        }
    }
}
