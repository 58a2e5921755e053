//! The voxel stream that feeds a Cube-4L pipeline's shader (§3, Fig. 18,
//! with the ABC gradient unit of §3.2): the CFB lane's beat, or, when the
//! scene needs gradients (shading or gradient opacity), the gradient unit's
//! voxel a slice later with its central-difference gradient, beside the
//! control the late CFB recomputes for it (the lane's control ports then
//! carry the late CFB's, see `Pipeline`). This is the shader input (T-1) of
//! `pipeline`'s timing. Halo slices, streamed for the gradient only, are
//! not beats.
//!
//! Otherwise the gradient unit is built disabled and drives zero
//! (`export::prune` removes it from the emitted Verilog), and the stream is
//! the CFB's.

use super::abc_gradient::AbcGradient;
use super::config::PipelineConfig;
use rust_hdl::prelude::*;

/// Input selection of one lane, with its gradient unit.
#[derive(LogicBlock)]
pub struct LaneFeed<const H: usize> {
    pub clock: Signal<In, Clock>,
    /// The `Beats` register (the gradient unit's line lengths).
    pub beats: Signal<In, Bits<64>>,
    /// The CFB lane's outputs (as `PipeLane`'s ports; the control is the
    /// late CFB's when the configuration has a gradient unit).
    pub beat_valid: Signal<In, Bit>,
    pub value: Signal<In, Bits<16>>,
    pub x: Signal<In, Bits<16>>,
    pub y: Signal<In, Bits<16>>,
    pub pad: Signal<In, Bit>,
    pub invalid: Signal<In, Bit>,
    pub halo: Signal<In, Bit>,
    pub sr: Signal<In, Bit>,
    pub er: Signal<In, Bit>,
    pub base_x: Signal<In, Bits<16>>,
    pub base_y: Signal<In, Bits<16>>,
    pub face: Signal<In, Bits<3>>,
    pub at_edge: Signal<In, Bit>,
    pub dx_neg: Signal<In, Bit>,
    pub dx_mag: Signal<In, Bits<16>>,
    pub dy_neg: Signal<In, Bit>,
    pub dy_mag: Signal<In, Bits<16>>,
    /// ABC gradient links (see `AbcGradient`).
    pub g_from_left_xm: Signal<In, Bits<16>>,
    pub g_from_left_ym: Signal<In, Bits<16>>,
    pub g_from_left_zm: Signal<In, Bits<16>>,
    pub g_from_right_xp: Signal<In, Bits<16>>,
    pub g_from_right_yp: Signal<In, Bits<16>>,
    pub g_from_right_zp: Signal<In, Bits<16>>,
    pub g_to_right_xm: Signal<Out, Bits<16>>,
    pub g_to_right_ym: Signal<Out, Bits<16>>,
    pub g_to_right_zm: Signal<Out, Bits<16>>,
    pub g_to_left_xp: Signal<Out, Bits<16>>,
    pub g_to_left_yp: Signal<Out, Bits<16>>,
    pub g_to_left_zp: Signal<Out, Bits<16>>,
    /// The voxel and its control entering the shader (T-1), and its
    /// gradient as sign and magnitude (zero without the gradient unit).
    pub o_valid: Signal<Out, Bit>,
    pub o_value: Signal<Out, Bits<16>>,
    pub o_x: Signal<Out, Bits<16>>,
    pub o_y: Signal<Out, Bits<16>>,
    pub o_pad: Signal<Out, Bit>,
    pub o_invalid: Signal<Out, Bit>,
    pub o_sr: Signal<Out, Bit>,
    pub o_er: Signal<Out, Bit>,
    pub o_edge: Signal<Out, Bit>,
    pub o_face: Signal<Out, Bits<3>>,
    pub o_base_x: Signal<Out, Bits<16>>,
    pub o_base_y: Signal<Out, Bits<16>>,
    pub o_dx_neg: Signal<Out, Bit>,
    pub o_dx_mag: Signal<Out, Bits<16>>,
    pub o_dy_neg: Signal<Out, Bit>,
    pub o_dy_mag: Signal<Out, Bits<16>>,
    pub gx_neg: Signal<Out, Bit>,
    pub gx_mag: Signal<Out, Bits<16>>,
    pub gy_neg: Signal<Out, Bit>,
    pub gy_mag: Signal<Out, Bits<16>>,
    pub gz_neg: Signal<Out, Bit>,
    pub gz_mag: Signal<Out, Bits<16>>,
    pub(crate) abc: AbcGradient<H>,
    use_gradient: Constant<Bit>,
}

impl<const H: usize> LaneFeed<H> {
    /// Bits of block RAM in the gradient unit.
    pub fn memory_bits(&self) -> usize {
        self.abc.memory_bits()
    }

    pub fn new(c: &PipelineConfig) -> LaneFeed<H> {
        LaneFeed {
            clock: Default::default(),
            beats: Default::default(),
            beat_valid: Default::default(),
            value: Default::default(),
            x: Default::default(),
            y: Default::default(),
            pad: Default::default(),
            invalid: Default::default(),
            halo: Default::default(),
            sr: Default::default(),
            er: Default::default(),
            base_x: Default::default(),
            base_y: Default::default(),
            face: Default::default(),
            at_edge: Default::default(),
            dx_neg: Default::default(),
            dx_mag: Default::default(),
            dy_neg: Default::default(),
            dy_mag: Default::default(),
            g_from_left_xm: Default::default(),
            g_from_left_ym: Default::default(),
            g_from_left_zm: Default::default(),
            g_from_right_xp: Default::default(),
            g_from_right_yp: Default::default(),
            g_from_right_zp: Default::default(),
            g_to_right_xm: Default::default(),
            g_to_right_ym: Default::default(),
            g_to_right_zm: Default::default(),
            g_to_left_xp: Default::default(),
            g_to_left_yp: Default::default(),
            g_to_left_zp: Default::default(),
            o_valid: Default::default(),
            o_value: Default::default(),
            o_x: Default::default(),
            o_y: Default::default(),
            o_pad: Default::default(),
            o_invalid: Default::default(),
            o_sr: Default::default(),
            o_er: Default::default(),
            o_edge: Default::default(),
            o_face: Default::default(),
            o_base_x: Default::default(),
            o_base_y: Default::default(),
            o_dx_neg: Default::default(),
            o_dx_mag: Default::default(),
            o_dy_neg: Default::default(),
            o_dy_mag: Default::default(),
            gx_neg: Default::default(),
            gx_mag: Default::default(),
            gy_neg: Default::default(),
            gy_mag: Default::default(),
            gz_neg: Default::default(),
            gz_mag: Default::default(),
            abc: AbcGradient::new(c),
            use_gradient: Constant::new(c.gradient()),
        }
    }
}

impl<const H: usize> Logic for LaneFeed<H> {
    #[hdl_gen]
    fn update(&mut self) {
        // ABC gradient unit: fed by the CFB, linked to the neighbours.
        self.abc.clock.next = self.clock.val();
        self.abc.beats.next = self.beats.val();
        self.abc.value.next = self.value.val();
        self.abc.x.next = self.x.val();
        self.abc.from_left_xm.next = self.g_from_left_xm.val();
        self.abc.from_left_ym.next = self.g_from_left_ym.val();
        self.abc.from_left_zm.next = self.g_from_left_zm.val();
        self.abc.from_right_xp.next = self.g_from_right_xp.val();
        self.abc.from_right_yp.next = self.g_from_right_yp.val();
        self.abc.from_right_zp.next = self.g_from_right_zp.val();
        self.g_to_right_xm.next = self.abc.to_right_xm.val();
        self.g_to_right_ym.next = self.abc.to_right_ym.val();
        self.g_to_right_zm.next = self.abc.to_right_zm.val();
        self.g_to_left_xp.next = self.abc.to_left_xp.val();
        self.g_to_left_yp.next = self.abc.to_left_yp.val();
        self.g_to_left_zp.next = self.abc.to_left_zp.val();
        self.gx_neg.next = self.abc.gx_neg.val();
        self.gx_mag.next = self.abc.gx_mag.val();
        self.gy_neg.next = self.abc.gy_neg.val();
        self.gy_mag.next = self.abc.gy_mag.val();
        self.gz_neg.next = self.abc.gz_neg.val();
        self.gz_mag.next = self.abc.gz_mag.val();
        // The voxel: the gradient unit's, or the CFB's; its control as it
        // comes.
        if self.use_gradient.val() {
            self.o_value.next = self.abc.o_value.val();
        } else {
            self.o_value.next = self.value.val();
        }
        self.o_valid.next = self.beat_valid.val() & !self.halo.val();
        self.o_x.next = self.x.val();
        self.o_y.next = self.y.val();
        self.o_pad.next = self.pad.val();
        self.o_invalid.next = self.invalid.val();
        self.o_sr.next = self.sr.val();
        self.o_er.next = self.er.val();
        self.o_edge.next = self.at_edge.val();
        self.o_face.next = self.face.val();
        self.o_base_x.next = self.base_x.val();
        self.o_base_y.next = self.base_y.val();
        self.o_dx_neg.next = self.dx_neg.val();
        self.o_dx_mag.next = self.dx_mag.val();
        self.o_dy_neg.next = self.dy_neg.val();
        self.o_dy_mag.next = self.dy_mag.val();
    }
}
