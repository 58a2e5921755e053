//! The compositing-buffer tap network of a Cube-4L pipeline (§3.5-3.7, with
//! the extension units of Figs. 14-15): the nine cells of the previous
//! slice's 3x3 region around lane k's voxel, aligned at T, from nine
//! [`BufferTap`]s in `TAPS` order.
//!
//! Tap (e_x, e_y) comes over m = 1 - e_x - e_y links from lane k-1 (mod P),
//! and tap (+1, +1) over one link from lane k+1 when P > 2 (`Tap::left`), so
//! the taps carry 1, 2, 0, 2, 0, 3, 1, 1 and 1 link registers; the link
//! ports are the lane's (`tC sJ` out to lane k+1, `tC iJ` in from lane k-1,
//! `t8il` in from lane k+1). At a partial beam's ends the x neighbours come
//! from the taps' previous values: x-1 of a partial beam's first lane is one
//! beat older, and the x+1 taps, whose streams run one beat newer, take
//! their current value only at its last lane.

use super::buffer_rows::BufferRows;
use super::buffer_tap::BufferTap;
use super::config::PipelineConfig;
use rust_hdl::prelude::*;

/// The nine taps of one lane, over its history (`H`-bit delay-line pointers).
#[derive(LogicBlock)]
pub struct TapNetwork<const H: usize> {
    pub clock: Signal<In, Clock>,
    /// The `Beats` register (the history's line lengths).
    pub beats: Signal<In, Bits<64>>,
    /// The voxel's x at T (for the partial-beam ends).
    pub x: Signal<In, Bits<16>>,
    /// The lane's composited value (T + `RESULT_AT`) and its beat flag.
    pub res: Signal<In, Bits<64>>,
    pub res_beat: Signal<In, Bit>,
    /// The lane's link ports (see `PipeLane`).
    pub t0s0: Signal<Out, Bits<64>>,
    pub t0i1: Signal<In, Bits<64>>,
    pub t1s0: Signal<Out, Bits<64>>,
    pub t1s1: Signal<Out, Bits<64>>,
    pub t1i1: Signal<In, Bits<64>>,
    pub t1i2: Signal<In, Bits<64>>,
    pub t3s0: Signal<Out, Bits<64>>,
    pub t3s1: Signal<Out, Bits<64>>,
    pub t3i1: Signal<In, Bits<64>>,
    pub t3i2: Signal<In, Bits<64>>,
    pub t5s0: Signal<Out, Bits<64>>,
    pub t5s1: Signal<Out, Bits<64>>,
    pub t5s2: Signal<Out, Bits<64>>,
    pub t5i1: Signal<In, Bits<64>>,
    pub t5i2: Signal<In, Bits<64>>,
    pub t5i3: Signal<In, Bits<64>>,
    pub t6s0: Signal<Out, Bits<64>>,
    pub t6i1: Signal<In, Bits<64>>,
    pub t7s0: Signal<Out, Bits<64>>,
    pub t7i1: Signal<In, Bits<64>>,
    pub t8s0: Signal<Out, Bits<64>>,
    pub t8i1: Signal<In, Bits<64>>,
    pub t8il: Signal<In, Bits<64>>,
    /// The nine cells at T, in `TAPS` order.
    pub a: [Signal<Out, Bits<64>>; 9],
    rows: BufferRows<H>,
    t0: BufferTap<1>,
    t1: BufferTap<2>,
    t2: BufferTap<0>,
    t3: BufferTap<2>,
    t4: BufferTap<0>,
    t5: BufferTap<3>,
    t6: BufferTap<1>,
    t7: BufferTap<1>,
    t8: BufferTap<1>,
    /// Tap (+1, +1) links from lane k+1.
    left8: Constant<Bit>,
    p_mask: Constant<Bits<16>>,
    first: Signal<Local, Bit>,
    last: Signal<Local, Bit>,
}

impl<const H: usize> TapNetwork<H> {
    /// Bits of block RAM in the lane's history.
    pub fn memory_bits(&self) -> usize {
        self.rows.memory_bits()
    }

    pub fn new(c: &PipelineConfig) -> TapNetwork<H> {
        let taps = c.taps();
        TapNetwork {
            clock: Default::default(),
            beats: Default::default(),
            x: Default::default(),
            res: Default::default(),
            res_beat: Default::default(),
            t0s0: Default::default(),
            t0i1: Default::default(),
            t1s0: Default::default(),
            t1s1: Default::default(),
            t1i1: Default::default(),
            t1i2: Default::default(),
            t3s0: Default::default(),
            t3s1: Default::default(),
            t3i1: Default::default(),
            t3i2: Default::default(),
            t5s0: Default::default(),
            t5s1: Default::default(),
            t5s2: Default::default(),
            t5i1: Default::default(),
            t5i2: Default::default(),
            t5i3: Default::default(),
            t6s0: Default::default(),
            t6i1: Default::default(),
            t7s0: Default::default(),
            t7i1: Default::default(),
            t8s0: Default::default(),
            t8i1: Default::default(),
            t8il: Default::default(),
            a: Default::default(),
            rows: BufferRows::new(c),
            t0: BufferTap::new(&taps[0]),
            t1: BufferTap::new(&taps[1]),
            t2: BufferTap::new(&taps[2]),
            t3: BufferTap::new(&taps[3]),
            t4: BufferTap::new(&taps[4]),
            t5: BufferTap::new(&taps[5]),
            t6: BufferTap::new(&taps[6]),
            t7: BufferTap::new(&taps[7]),
            t8: BufferTap::new(&taps[8]),
            left8: Constant::new(taps[8].left),
            p_mask: Constant::new(((c.p - 1) as u64).to_bits()),
            first: Default::default(),
            last: Default::default(),
        }
    }
}

impl<const H: usize> Logic for TapNetwork<H> {
    #[hdl_gen]
    fn update(&mut self) {
        // The lane's history, read once.
        self.rows.clock.next = self.clock.val();
        self.rows.beats.next = self.beats.val();
        self.rows.res.next = self.res.val();
        self.rows.res_beat.next = self.res_beat.val();
        // Partial-beam ends.
        self.first.next = (self.x.val() & self.p_mask.val()) == 0;
        self.last.next = (self.x.val() & self.p_mask.val()) == self.p_mask.val();
        // Tap (0, 0): one link.
        self.t0.clock.next = self.clock.val();
        self.t0.read.next = self.rows.tap[0].val();
        self.t0.use_prev.next = false;
        self.t0.link_in[0].next = self.t0i1.val();
        self.t0s0.next = self.t0.pass[0].val();
        self.a[0].next = self.t0.a.val();
        // Tap (-1, 0): two links.
        self.t1.clock.next = self.clock.val();
        self.t1.read.next = self.rows.tap[1].val();
        self.t1.use_prev.next = self.first.val();
        self.t1.link_in[0].next = self.t1i1.val();
        self.t1.link_in[1].next = self.t1i2.val();
        self.t1s0.next = self.t1.pass[0].val();
        self.t1s1.next = self.t1.pass[1].val();
        self.a[1].next = self.t1.a.val();
        // Tap (+1, 0): the lane's own history, no link.
        self.t2.clock.next = self.clock.val();
        self.t2.read.next = self.rows.tap[2].val();
        self.t2.use_prev.next = !self.last.val();
        self.a[2].next = self.t2.a.val();
        // Tap (0, -1): two links.
        self.t3.clock.next = self.clock.val();
        self.t3.read.next = self.rows.tap[3].val();
        self.t3.use_prev.next = false;
        self.t3.link_in[0].next = self.t3i1.val();
        self.t3.link_in[1].next = self.t3i2.val();
        self.t3s0.next = self.t3.pass[0].val();
        self.t3s1.next = self.t3.pass[1].val();
        self.a[3].next = self.t3.a.val();
        // Tap (0, +1): the lane's own history, no link.
        self.t4.clock.next = self.clock.val();
        self.t4.read.next = self.rows.tap[4].val();
        self.t4.use_prev.next = false;
        self.a[4].next = self.t4.a.val();
        // Tap (-1, -1): three links.
        self.t5.clock.next = self.clock.val();
        self.t5.read.next = self.rows.tap[5].val();
        self.t5.use_prev.next = self.first.val();
        self.t5.link_in[0].next = self.t5i1.val();
        self.t5.link_in[1].next = self.t5i2.val();
        self.t5.link_in[2].next = self.t5i3.val();
        self.t5s0.next = self.t5.pass[0].val();
        self.t5s1.next = self.t5.pass[1].val();
        self.t5s2.next = self.t5.pass[2].val();
        self.a[5].next = self.t5.a.val();
        // Tap (+1, -1): one link.
        self.t6.clock.next = self.clock.val();
        self.t6.read.next = self.rows.tap[6].val();
        self.t6.use_prev.next = !self.last.val();
        self.t6.link_in[0].next = self.t6i1.val();
        self.t6s0.next = self.t6.pass[0].val();
        self.a[6].next = self.t6.a.val();
        // Tap (-1, +1): one link.
        self.t7.clock.next = self.clock.val();
        self.t7.read.next = self.rows.tap[7].val();
        self.t7.use_prev.next = self.first.val();
        self.t7.link_in[0].next = self.t7i1.val();
        self.t7s0.next = self.t7.pass[0].val();
        self.a[7].next = self.t7.a.val();
        // Tap (+1, +1): one link, from lane k+1 when P > 2.
        self.t8.clock.next = self.clock.val();
        self.t8.read.next = self.rows.tap[8].val();
        self.t8.use_prev.next = !self.last.val();
        // Assigned once, not as a default and an override (see `BufferTap`).
        if self.left8.val() {
            self.t8.link_in[0].next = self.t8il.val();
        } else {
            self.t8.link_in[0].next = self.t8i1.val();
        }
        self.t8s0.next = self.t8.pass[0].val();
        self.a[8].next = self.t8.a.val();
    }
}
