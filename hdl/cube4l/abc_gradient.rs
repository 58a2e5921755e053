//! ABC gradient estimation of Cube-4L (§3.2, Figs. 8-17): central
//! differences at voxel positions, bit for bit as
//! `golden_model::cube4l::gradient::central_difference`, with only nearest-neighbour
//! links between pipelines.
//!
//! The gradient of slice z needs slice z+1, so the unit emits voxel t one
//! slice later, `S + 1` clocks after the CFB did, when the ahead (A) slice is
//! streaming. The voxel's control is not stored: the pipeline recomputes it
//! with a second copy of the CFB's address generator started `S + 1` clocks
//! late (`Pipeline`'s `late`), and the lane's control ports carry it; only
//! the voxel values wait here. By the skew the six neighbours of voxel
//! (x, y, z) of lane k at beat t are:
//!
//! | neighbour | lane | beat |
//! |---|---|---|
//! | x+1 / x-1 | k+1 / k-1 | t + [x mod P = P-1] / t - [x mod P = 0] |
//! | y+1 / y-1 | k+1 / k-1 | t + B / t - B |
//! | z+1 / z-1 | k+1 / k-1 | t + S (the A slice, live from the CFB) / t - S |
//!
//! Every one is one link away. Each pipeline keeps the behind (B) and
//! current (C) slices once, as a chain of delay lines on its live voxel
//! stream (2S - 1 voxels in all), tapped at every delay a neighbour needs:
//! S - B (y+1, to lane k-1), S - 1 (x+1), S (x-1, to lane k+1), S + 1 (the
//! voxel itself), S + B (y-1) and 2S (z-1). The x neighbours across a partial-beam end
//! come one beat early or late, from a register beside the tap (the
//! extension units of Figs. 14-15). This is the small-buffer variant of Fig.
//! 17: two slices buffered per pipeline and six voxel links (three each way)
//! instead of Fig. 16's four slices and two links. Voxels with a neighbour
//! outside the dataset (`at_edge`) get garbage gradients and are made
//! transparent by the shader, as in the golden model.
//!
//! The lines are built for the configuration's largest slice; their
//! lengths for a view come from the `Beats` register (S and B).

use super::config::PipelineConfig;
use crate::common::banked_line::BankedLine;
use crate::common::lane_copy::LaneCopy;
use rust_hdl::prelude::*;

/// One pipeline's gradient unit (`H`-bit delay-line pointers).
#[derive(LogicBlock)]
pub struct AbcGradient<const H: usize> {
    pub clock: Signal<In, Clock>,
    /// The `Beats` register: S in the low word, B in the high.
    pub beats: Signal<In, Bits<64>>,
    /// The CFB lane's live voxel.
    pub value: Signal<In, Bits<16>>,
    /// The x of the voxel leaving the unit (the late control), for the
    /// partial-beam ends.
    pub x: Signal<In, Bits<16>>,
    /// Neighbour links: from lane k-1 (its x-1, y-1, z-1 taps) ...
    pub from_left_xm: Signal<In, Bits<16>>,
    pub from_left_ym: Signal<In, Bits<16>>,
    pub from_left_zm: Signal<In, Bits<16>>,
    /// ... and from lane k+1 (its x+1, y+1 taps and its live voxel).
    pub from_right_xp: Signal<In, Bits<16>>,
    pub from_right_yp: Signal<In, Bits<16>>,
    pub from_right_zp: Signal<In, Bits<16>>,
    /// What this lane sends: to lane k+1 ...
    pub to_right_xm: Signal<Out, Bits<16>>,
    pub to_right_ym: Signal<Out, Bits<16>>,
    pub to_right_zm: Signal<Out, Bits<16>>,
    /// ... and to lane k-1.
    pub to_left_xp: Signal<Out, Bits<16>>,
    pub to_left_yp: Signal<Out, Bits<16>>,
    pub to_left_zp: Signal<Out, Bits<16>>,
    /// The voxel, S + 1 clocks late, and its gradient (sign and magnitude).
    pub o_value: Signal<Out, Bits<16>>,
    pub gx_neg: Signal<Out, Bit>,
    pub gx_mag: Signal<Out, Bits<16>>,
    pub gy_neg: Signal<Out, Bit>,
    pub gy_mag: Signal<Out, Bits<16>>,
    pub gz_neg: Signal<Out, Bit>,
    pub gz_mag: Signal<Out, Bits<16>>,
    /// The chain: S - B - 1, then a register (S - B) or B more (S - 1),
    /// two registers (S, S + 1), B more (S + B) and S - B more (2S).
    line_a: BankedLine<Bits<16>, H>,
    reg_yp: DFF<Bits<16>>,
    line_b: BankedLine<Bits<16>, H>,
    reg_xm: DFF<Bits<16>>,
    reg_c: DFF<Bits<16>>,
    line_c: BankedLine<Bits<16>, H>,
    line_d: BankedLine<Bits<16>, H>,
    hop_xm: DFF<Bits<16>>,
    hop_ym: DFF<Bits<16>>,
    hop_zm: DFF<Bits<16>>,
    hop_xp: DFF<Bits<16>>,
    hop_yp: DFF<Bits<16>>,
    hop_zp: DFF<Bits<16>>,
    prev_xm: DFF<Bits<16>>,
    prev_xp: DFF<Bits<16>>,
    xm: Signal<Local, Bits<16>>,
    xp: Signal<Local, Bits<16>>,
    p_mask: Constant<Bits<16>>,
    enabled: Constant<Bit>,
    /// The lines' lengths less one: S - B - 2, B - 1 (twice), S - B - 1;
    /// the lane's own registers, one carry chain a clock from its own copy
    /// of `Beats` (S and B to `H` bits) through S - B.
    slice: LaneCopy<Bits<H>>,
    beam: LaneCopy<Bits<H>>,
    slice_less_beam: LaneCopy<Bits<H>>,
    last_a: LaneCopy<Bits<H>>,
    last_b: LaneCopy<Bits<H>>,
    last_d: LaneCopy<Bits<H>>,
}

impl<const H: usize> AbcGradient<H> {
    /// The unit of `c`'s lanes. Without a gradient (a configuration that
    /// neither shades nor has gradient opacity) the lines are registers.
    pub fn new(c: &PipelineConfig) -> AbcGradient<H> {
        let enabled = c.gradient();
        let voxel_bits = c.voxel_bits;
        let [a_len, b_len, c_len, d_len] = c.gradient_line_lengths();
        let line = |length: u32| {
            BankedLine::new(
                if enabled { length as usize } else { 1 },
                &[(0, voxel_bits as usize)],
                ((1u64 << voxel_bits) - 1).to_bits(),
            )
        };
        AbcGradient {
            clock: Default::default(),
            beats: Default::default(),
            value: Default::default(),
            x: Default::default(),
            from_left_xm: Default::default(),
            from_left_ym: Default::default(),
            from_left_zm: Default::default(),
            from_right_xp: Default::default(),
            from_right_yp: Default::default(),
            from_right_zp: Default::default(),
            to_right_xm: Default::default(),
            to_right_ym: Default::default(),
            to_right_zm: Default::default(),
            to_left_xp: Default::default(),
            to_left_yp: Default::default(),
            to_left_zp: Default::default(),
            o_value: Default::default(),
            gx_neg: Default::default(),
            gx_mag: Default::default(),
            gy_neg: Default::default(),
            gy_mag: Default::default(),
            gz_neg: Default::default(),
            gz_mag: Default::default(),
            line_a: line(a_len),
            reg_yp: Default::default(),
            line_b: line(b_len),
            reg_xm: Default::default(),
            reg_c: Default::default(),
            line_c: line(c_len),
            line_d: line(d_len),
            hop_xm: Default::default(),
            hop_ym: Default::default(),
            hop_zm: Default::default(),
            hop_xp: Default::default(),
            hop_yp: Default::default(),
            hop_zp: Default::default(),
            prev_xm: Default::default(),
            prev_xp: Default::default(),
            xm: Default::default(),
            xp: Default::default(),
            p_mask: Constant::new(((c.p - 1) as u64).to_bits()),
            enabled: Constant::new(enabled),
            slice: Default::default(),
            beam: Default::default(),
            slice_less_beam: Default::default(),
            last_a: Default::default(),
            last_b: Default::default(),
            last_d: Default::default(),
        }
    }

    /// Bits of block RAM in the chain.
    pub fn memory_bits(&self) -> usize {
        [&self.line_a, &self.line_b, &self.line_c, &self.line_d]
            .iter()
            .map(|l| l.memory_bits())
            .sum()
    }
}

impl<const H: usize> Logic for AbcGradient<H> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            reg_yp,
            reg_xm,
            reg_c,
            hop_xm,
            hop_ym,
            hop_zm,
            hop_xp,
            hop_yp,
            hop_zp,
            prev_xm,
            prev_xp,
            slice,
            beam,
            slice_less_beam,
            last_a,
            last_b,
            last_d
        );
        // The lines' lengths for the view, three clocks behind `Beats`
        // (which holds still through a sweep; the lines carry no sample
        // of the sweep before its first beat, many clocks later).
        self.slice.d.next = self.beats.val().get_bits::<H>(0);
        self.beam.d.next = self.beats.val().get_bits::<H>(32);
        self.slice_less_beam.d.next = self.slice.q.val() - self.beam.q.val();
        self.last_d.d.next = self.slice_less_beam.q.val() - 1;
        self.last_a.d.next = self.slice_less_beam.q.val() - 2;
        self.last_b.d.next = self.beam.q.val() - 1;
        self.line_a.last.next = self.last_a.q.val();
        self.line_b.last.next = self.last_b.q.val();
        self.line_c.last.next = self.last_b.q.val();
        self.line_d.last.next = self.last_d.q.val();
        self.line_a.clock.next = self.clock.val();
        self.line_b.clock.next = self.clock.val();
        self.line_c.clock.next = self.clock.val();
        self.line_d.clock.next = self.clock.val();
        // The B and C slices: every CFB clock enters the chain.
        self.line_a.data_in.next = self.value.val();
        self.line_a.write_enable.next = true;
        self.reg_yp.d.next = self.line_a.data_out.val();
        self.line_b.data_in.next = self.line_a.data_out.val();
        self.line_b.write_enable.next = true;
        self.reg_xm.d.next = self.line_b.data_out.val();
        self.reg_c.d.next = self.reg_xm.q.val();
        self.line_c.data_in.next = self.reg_xm.q.val();
        self.line_c.write_enable.next = true;
        self.line_d.data_in.next = self.line_c.data_out.val();
        self.line_d.write_enable.next = true;
        // Taps, lined up S + 1 clocks after the CFB once across their link.
        self.to_left_yp.next = self.reg_yp.q.val();
        self.to_left_xp.next = self.line_b.data_out.val();
        self.to_right_xm.next = self.reg_xm.q.val();
        self.to_right_ym.next = self.line_c.data_out.val();
        self.to_right_zm.next = self.line_d.data_out.val();
        self.to_left_zp.next = self.value.val();
        // One register per link.
        self.hop_xm.d.next = self.from_left_xm.val();
        self.hop_ym.d.next = self.from_left_ym.val();
        self.hop_zm.d.next = self.from_left_zm.val();
        self.hop_xp.d.next = self.from_right_xp.val();
        self.hop_yp.d.next = self.from_right_yp.val();
        self.hop_zp.d.next = self.from_right_zp.val();
        self.prev_xm.d.next = self.hop_xm.q.val();
        self.prev_xp.d.next = self.hop_xp.q.val();
        // Partial-beam ends: x-1 of a partial beam's first voxel is one beat
        // older, x+1 of its last voxel one beat newer.
        self.xm.next = self.hop_xm.q.val();
        if (self.x.val() & self.p_mask.val()) == 0 {
            self.xm.next = self.prev_xm.q.val();
        }
        self.xp.next = self.prev_xp.q.val();
        if (self.x.val() & self.p_mask.val()) == self.p_mask.val() {
            self.xp.next = self.hop_xp.q.val();
        }
        // Central differences as sign and magnitude.
        self.gx_neg.next = self.xp.val() < self.xm.val();
        self.gx_mag.next = self.xp.val() - self.xm.val();
        if self.xp.val() < self.xm.val() {
            self.gx_mag.next = self.xm.val() - self.xp.val();
        }
        self.gy_neg.next = self.hop_yp.q.val() < self.hop_ym.q.val();
        self.gy_mag.next = self.hop_yp.q.val() - self.hop_ym.q.val();
        if self.hop_yp.q.val() < self.hop_ym.q.val() {
            self.gy_mag.next = self.hop_ym.q.val() - self.hop_yp.q.val();
        }
        self.gz_neg.next = self.hop_zp.q.val() < self.hop_zm.q.val();
        self.gz_mag.next = self.hop_zp.q.val() - self.hop_zm.q.val();
        if self.hop_zp.q.val() < self.hop_zm.q.val() {
            self.gz_mag.next = self.hop_zm.q.val() - self.hop_zp.q.val();
        }
        self.o_value.next = self.reg_c.q.val();
        // Left out of the configuration's hardware (see `export::prune`): every
        // output is zero, as in the emitted Verilog, which has no unit.
        if !self.enabled.val() {
            self.to_right_xm.next = 0.into();
            self.to_right_ym.next = 0.into();
            self.to_right_zm.next = 0.into();
            self.to_left_xp.next = 0.into();
            self.to_left_yp.next = 0.into();
            self.to_left_zp.next = 0.into();
            self.o_value.next = 0.into();
            self.gx_mag.next = 0.into();
            self.gy_mag.next = 0.into();
            self.gz_mag.next = 0.into();
            self.gx_neg.next = false;
            self.gy_neg.next = false;
            self.gz_neg.next = false;
        }
    }
}
