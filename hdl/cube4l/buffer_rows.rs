//! The compositing-buffer history of one Cube-4L lane (§3.5-3.7, as Fig.
//! 21's SFG builds it): the lane's composited values, read once from one
//! ring and brought to every tap's delay by beam-length delay lines and
//! registers, instead of one ring copy with its own read port per tap.
//!
//! Tap (e_x, e_y), crossing h links, needs the lane's result from
//! E = S - e_y*B - [e_x = 1] - h - r clocks back (`pipeline`'s tap delay,
//! less its links and the r = `RESULT_AT` clocks from a beat's shader
//! register to its result). Row e_y's taps lie within 4 clocks of
//! R(e_y) = S - e_y*B - r - 4:
//! the ring delays the result R(+1), one beam-length line more gives R(0),
//! another R(-1), and four registers per row give the rest. Which register
//! a tap takes does not depend on the view; the lines' lengths do, and
//! come from the `Beats` register (S and B) at run time. Each line is read
//! through a register at each of its block RAMs ([`BankedLine`]): no block
//! RAM's read data crosses the part to the next line or the taps' selection
//! before a flip-flop.
//!
//! Memory: S - B - r - 4 words for the ring and 2B for the lines at the
//! configuration's largest slice, where each tap used to keep its own ring
//! of the next power of two above S + B.

use super::config::{tap_offset, PipelineConfig, RESULT_AT, TAPS};
use crate::common::banked_line::BankedLine;
use crate::common::lane_copy::LaneCopy;
use rust_hdl::prelude::*;

/// One lane's compositing-buffer history (`H`-bit delay-line pointers).
#[derive(LogicBlock)]
pub struct BufferRows<const H: usize> {
    pub clock: Signal<In, Clock>,
    /// The `Beats` register: S in the low word, B in the high.
    pub beats: Signal<In, Bits<64>>,
    /// The lane's composited value (T + `RESULT_AT`) and its beat flag.
    pub res: Signal<In, Bits<64>>,
    pub res_beat: Signal<In, Bit>,
    /// Each tap's value (in `TAPS` order) as its ring read used to give it.
    pub tap: [Signal<Out, Bits<64>>; 9],
    ring: BankedLine<Bits<64>, H>,
    beam0: BankedLine<Bits<64>, H>,
    beam1: BankedLine<Bits<64>, H>,
    /// Row r's register i is `stage[4 r + i]` (rows +1, 0, -1).
    stage: [DFF<Bits<64>>; 12],
    /// Candidate `5 r + i`: row r's value i clocks after R(e_y).
    cand: [Signal<Local, Bits<64>>; 15],
    /// One-hot: the candidate each tap takes.
    pick: [Constant<Bits<15>>; 9],
    sel: [Signal<Local, Bits<64>>; 9],
    /// The lines' lengths less one, from `Beats`: S - B - r - 5 and B - 1;
    /// the lane's own registers, one carry chain a clock from its own copy
    /// of `Beats` (S and B to `H` bits) through S - B.
    slice: LaneCopy<Bits<H>>,
    beam: LaneCopy<Bits<H>>,
    slice_less_beam: LaneCopy<Bits<H>>,
    ring_last: LaneCopy<Bits<H>>,
    beam_last: LaneCopy<Bits<H>>,
    ring_less: Constant<Bits<H>>,
}

impl<const H: usize> BufferRows<H> {
    pub fn new(c: &PipelineConfig) -> BufferRows<H> {
        let mask = c
            .ring_fields()
            .iter()
            .fold(0u64, |m, &(lo, w)| m | (((1u128 << w) - 1) as u64) << lo)
            .to_bits();
        let fields = c.ring_fields();
        let line = |length: u32| BankedLine::new(length as usize, &fields, mask);
        let [ring, beam0, beam1] = c.history_lines();
        let taps = c.taps();
        BufferRows {
            clock: Default::default(),
            beats: Default::default(),
            res: Default::default(),
            res_beat: Default::default(),
            tap: Default::default(),
            ring: line(ring),
            beam0: line(beam0),
            beam1: line(beam1),
            stage: Default::default(),
            cand: Default::default(),
            pick: std::array::from_fn(|t| {
                let row = (1 - TAPS[t].1) as u64;
                let i = tap_offset(TAPS[t], taps[t].hops) as u64;
                Constant::new((1u64 << (5 * row + i)).to_bits())
            }),
            sel: Default::default(),
            slice: Default::default(),
            beam: Default::default(),
            slice_less_beam: Default::default(),
            ring_last: Default::default(),
            beam_last: Default::default(),
            ring_less: Constant::new(((RESULT_AT + 5) as u64).to_bits()),
        }
    }

    /// Bits of block RAM: the ring and the lines.
    pub fn memory_bits(&self) -> usize {
        self.ring.memory_bits() + self.beam0.memory_bits() + self.beam1.memory_bits()
    }
}

impl<const H: usize> Logic for BufferRows<H> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            slice,
            beam,
            slice_less_beam,
            ring_last,
            beam_last
        );
        // The lines' lengths for the view, three clocks behind `Beats`
        // (which holds still through a sweep; the ring takes the sweep's
        // first result many clocks later).
        self.slice.d.next = self.beats.val().get_bits::<H>(0);
        self.beam.d.next = self.beats.val().get_bits::<H>(32);
        self.slice_less_beam.d.next = self.slice.q.val() - self.beam.q.val();
        self.ring_last.d.next = self.slice_less_beam.q.val() - self.ring_less.val();
        self.beam_last.d.next = self.beam.q.val() - 1;
        self.ring.last.next = self.ring_last.q.val();
        self.beam0.last.next = self.beam_last.q.val();
        self.beam1.last.next = self.beam_last.q.val();
        self.ring.clock.next = self.clock.val();
        self.beam0.clock.next = self.clock.val();
        self.beam1.clock.next = self.clock.val();
        for i in 0..12 {
            self.stage[i].clock.next = self.clock.val();
        }
        // Written at its beat, read once; the lines copy every clock.
        self.ring.data_in.next = self.res.val();
        self.ring.write_enable.next = self.res_beat.val();
        self.beam0.data_in.next = self.ring.data_out.val();
        self.beam0.write_enable.next = true;
        self.beam1.data_in.next = self.beam0.data_out.val();
        self.beam1.write_enable.next = true;
        self.cand[0].next = self.ring.data_out.val();
        self.cand[5].next = self.beam0.data_out.val();
        self.cand[10].next = self.beam1.data_out.val();
        for r in 0..3 {
            self.stage[4 * r].d.next = self.cand[5 * r].val();
            for i in 1..4 {
                self.stage[4 * r + i].d.next = self.stage[4 * r + i - 1].q.val();
            }
            for i in 0..4 {
                self.cand[5 * r + i + 1].next = self.stage[4 * r + i].q.val();
            }
        }
        // Each tap's candidate, chosen when the design is built.
        for t in 0..9 {
            self.sel[t].next = self.cand[0].val();
            for k in 1..15 {
                if self.pick[t].val().get_bit(k) {
                    self.sel[t].next = self.cand[k].val();
                }
            }
            self.tap[t].next = self.sel[t].val();
        }
    }
}
