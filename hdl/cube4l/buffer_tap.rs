//! One tap of a Cube-4L pipeline's compositing buffer (§3.5-3.7, with the
//! extension units of Figs. 14-15): the cell of the previous slice's 3x3
//! region at offset `(e_x, e_y)` from the voxel, as it reaches the consuming
//! lane at T.
//!
//! The tap takes the lane's composited value from `delay - hops` beats back,
//! from the lane's [`super::buffer_rows::BufferRows`] (see `pipeline`). That
//! value reaches lane k over
//! `hops` neighbour links, one register each; the tap carries `M` link
//! registers, as many as any `P` needs, takes the value after `hops` of them,
//! and passes the values after 0..M-1 links on to lane k+1. Its previous
//! value, one beat older, stands in for the cell at a partial beam's end
//! (`use_prev`, decided by the `tap_network`).

use super::config::Tap;
use rust_hdl::prelude::*;

/// A compositing-buffer tap with `M` link registers.
#[derive(LogicBlock)]
pub struct BufferTap<const M: usize> {
    pub clock: Signal<In, Clock>,
    /// The lane's history at this tap's delay (`BufferRows::tap`).
    pub read: Signal<In, Bits<64>>,
    /// Take the previous value instead of the current one (partial-beam end).
    pub use_prev: Signal<In, Bit>,
    /// Link register j's input: lane k-1's value after j links (the lane's
    /// port `tC i{j+1}` for tap C).
    pub link_in: [Signal<In, Bits<64>>; M],
    /// The value after j links, passed on to lane k+1 (port `tC s{j}`): the
    /// history's value for j = 0, link register j-1's output beyond.
    pub pass: [Signal<Out, Bits<64>>; M],
    /// The tap's cell at T.
    pub a: Signal<Out, Bits<64>>,
    links: [DFF<Bits<64>>; M],
    /// `take[j]`: the value crosses j + 1 links (none set: no link).
    take: [Constant<Bit>; M],
    stream: Signal<Local, Bits<64>>,
    prev: DFF<Bits<64>>,
}

impl<const M: usize> BufferTap<M> {
    /// The tap that `route` describes. Which neighbour feeds the links
    /// (`route.left`) is the network's wiring.
    pub fn new(route: &Tap) -> Self {
        assert!(
            route.hops as usize <= M,
            "a tap with {M} link registers cannot cross {} links",
            route.hops
        );
        BufferTap {
            clock: Default::default(),
            read: Default::default(),
            use_prev: Default::default(),
            link_in: std::array::from_fn(|_| Default::default()),
            pass: std::array::from_fn(|_| Default::default()),
            a: Default::default(),
            links: std::array::from_fn(|_| Default::default()),
            take: std::array::from_fn(|j| Constant::new(route.hops as usize == j + 1)),
            stream: Default::default(),
            prev: Default::default(),
        }
    }
}

impl<const M: usize> Logic for BufferTap<M> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, prev);
        for j in 0..M {
            self.links[j].clock.next = self.clock.val();
            self.links[j].d.next = self.link_in[j].val();
        }
        // (`0..M.min(1)`: j = 0 only, and only for a tap with links.)
        for j in 0..M.min(1) {
            self.pass[j].next = self.read.val();
        }
        for j in 1..M {
            self.pass[j].next = self.links[j - 1].q.val();
        }
        self.stream.next = self.read.val();
        for j in 0..M {
            if self.take[j].val() {
                self.stream.next = self.links[j].q.val();
            }
        }
        self.prev.d.next = self.stream.val();
        // An output is assigned once: a default overridden in the same block
        // glitches, and two modules whose glitches wake each other never
        // settle under Icarus.
        if self.use_prev.val() {
            self.a.next = self.prev.q.val();
        } else {
            self.a.next = self.stream.val();
        }
    }
}
