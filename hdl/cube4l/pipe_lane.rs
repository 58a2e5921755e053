//! One Cube-4L pipeline after the CFB (§3, Figs. 4 and 18-21): the input
//! selection with the ABC gradient unit, the shader, the compositing-buffer
//! taps, the 2x2 selection, the bilinear unit and the compositor, with the
//! control beside them. [`super::pipeline::Pipeline`] holds `P` of them,
//! joined by nearest-neighbour links.

use super::bilinear::Bilinear;
use super::compositor::Compositor;
use super::config::PipelineConfig;
use super::control_delay::ControlDelay;
use super::lane_feed::LaneFeed;
use super::select2x2::Select2x2;
use super::tap_network::TapNetwork;
use crate::common::mode_class::ModeClass;
use crate::common::regs::ADDRESS_BITS;
use crate::common::shader::Shader;
use golden_model::host::ShaderTables;
use rust_hdl::prelude::*;

/// One pipeline after the CFB: input selection ([`LaneFeed`], with the ABC
/// gradient unit), shader, the compositing-buffer taps ([`TapNetwork`]),
/// the 2x2 selection ([`Select2x2`]), bilinear unit and compositor, with
/// the control beside them ([`ControlDelay`]).
#[derive(LogicBlock)]
pub struct PipeLane<const H: usize> {
    pub clock: Signal<In, Clock>,
    /// The host port (the shader's tables and registers).
    pub host_write: Signal<In, Bit>,
    pub host_address: Signal<In, Bits<ADDRESS_BITS>>,
    pub host_data: Signal<In, Bits<64>>,
    /// The view registers the lane reads: `Dims`, `Beats` and `Order`.
    pub dims: Signal<In, Bits<64>>,
    pub beats: Signal<In, Bits<64>>,
    pub order: Signal<In, Bits<64>>,
    /// The CFB lane's outputs: the live voxel, and its control, or with a
    /// gradient unit the late CFB's control for the voxel a slice back.
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
    /// Compositing-buffer taps: `tC s0` is tap C's value from the history, `tC sJ`
    /// its value after J links (passed on), `tC iJ` the input of its J-th
    /// link register (from lane k-1), `t8il` tap 8's leftward link (from k+1).
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
    /// The composited value of this lane's voxel (T + `RESULT_AT`): `res_beat` marks a
    /// beat, `res_valid` one that is not padding.
    pub res_beat: Signal<Out, Bit>,
    pub res_valid: Signal<Out, Bit>,
    pub res: Signal<Out, Bits<64>>,
    /// Base-plane pixel output on ER.
    pub px_valid: Signal<Out, Bit>,
    pub px_x: Signal<Out, Bits<16>>,
    pub px_y: Signal<Out, Bits<16>>,
    /// The face the pixel left through (`golden_model::cube4l::plan::Face` as a number).
    pub px_face: Signal<Out, Bits<3>>,
    pub(crate) feed: LaneFeed<H>,
    pub(crate) shader: Shader,
    pub(crate) ctl: ControlDelay,
    /// The bits a slice or base-plane coordinate of the build's largest
    /// volume can have ([`PipelineConfig::coord_mask`]).
    coord_mask: Constant<Bits<16>>,
    pub(crate) taps: TapNetwork<H>,
    pub(crate) cells: Select2x2,
    pub(crate) bilinear: Bilinear,
    pub(crate) compositor: Compositor,
}

impl<const H: usize> PipeLane<H> {
    /// Give the shader's tables the contents the host would load.
    pub fn preload_tables(&mut self, tables: &ShaderTables) {
        self.shader.preload(tables);
    }

    /// Bits of block RAM in the lane's buffers, as built.
    pub fn buffer_bits(&self) -> u64 {
        (self.taps.memory_bits() + self.feed.memory_bits()) as u64
    }

    pub fn new(c: &PipelineConfig, shader: Shader) -> PipeLane<H> {
        PipeLane {
            dims: Default::default(),
            beats: Default::default(),
            order: Default::default(),
            clock: Default::default(),
            host_write: Default::default(),
            host_address: Default::default(),
            host_data: Default::default(),
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
            res_beat: Default::default(),
            res_valid: Default::default(),
            res: Default::default(),
            px_valid: Default::default(),
            px_x: Default::default(),
            px_y: Default::default(),
            px_face: Default::default(),
            feed: LaneFeed::new(c),
            shader,
            ctl: Default::default(),
            coord_mask: Constant::new((c.coord_mask() as u64).to_bits()),
            taps: TapNetwork::new(c),
            cells: Select2x2::new(c),
            bilinear: Bilinear::new(c.frac_bits, c.mode == ModeClass::Xray),
            compositor: Compositor::new(c.mode, c.rgba_bits),
        }
    }
}

impl<const H: usize> Logic for PipeLane<H> {
    #[hdl_gen]
    fn update(&mut self) {
        // Input selection (T-1): the CFB's beat, or the gradient unit's.
        self.feed.clock.next = self.clock.val();
        self.feed.beats.next = self.beats.val();
        self.feed.beat_valid.next = self.beat_valid.val();
        self.feed.value.next = self.value.val();
        self.feed.x.next = self.x.val();
        self.feed.y.next = self.y.val();
        self.feed.pad.next = self.pad.val();
        self.feed.invalid.next = self.invalid.val();
        self.feed.halo.next = self.halo.val();
        self.feed.sr.next = self.sr.val();
        self.feed.er.next = self.er.val();
        self.feed.base_x.next = self.base_x.val();
        self.feed.base_y.next = self.base_y.val();
        self.feed.face.next = self.face.val();
        self.feed.at_edge.next = self.at_edge.val();
        self.feed.dx_neg.next = self.dx_neg.val();
        self.feed.dx_mag.next = self.dx_mag.val();
        self.feed.dy_neg.next = self.dy_neg.val();
        self.feed.dy_mag.next = self.dy_mag.val();
        self.feed.g_from_left_xm.next = self.g_from_left_xm.val();
        self.feed.g_from_left_ym.next = self.g_from_left_ym.val();
        self.feed.g_from_left_zm.next = self.g_from_left_zm.val();
        self.feed.g_from_right_xp.next = self.g_from_right_xp.val();
        self.feed.g_from_right_yp.next = self.g_from_right_yp.val();
        self.feed.g_from_right_zp.next = self.g_from_right_zp.val();
        self.g_to_right_xm.next = self.feed.g_to_right_xm.val();
        self.g_to_right_ym.next = self.feed.g_to_right_ym.val();
        self.g_to_right_zm.next = self.feed.g_to_right_zm.val();
        self.g_to_left_xp.next = self.feed.g_to_left_xp.val();
        self.g_to_left_yp.next = self.feed.g_to_left_yp.val();
        self.g_to_left_zp.next = self.feed.g_to_left_zp.val();
        // Shader (input at T-1-GATHER_DELAY, the sample at T+L).
        self.shader.clock.next = self.clock.val();
        self.shader.host_write.next = self.host_write.val();
        self.shader.host_address.next = self.host_address.val();
        self.shader.host_data.next = self.host_data.val();
        self.shader.value.next = self.feed.o_value.val();
        self.shader.invalid.next = self.feed.o_invalid.val();
        self.shader.at_edge.next = self.feed.o_edge.val();
        self.shader.gx_neg.next = self.feed.gx_neg.val();
        self.shader.gx_mag.next = bit_cast::<32, 16>(self.feed.gx_mag.val());
        self.shader.gy_neg.next = self.feed.gy_neg.val();
        self.shader.gy_mag.next = bit_cast::<32, 16>(self.feed.gy_mag.val());
        self.shader.gz_neg.next = self.feed.gz_neg.val();
        self.shader.gz_mag.next = bit_cast::<32, 16>(self.feed.gz_mag.val());
        // Control beside the voxel, to the gather (T) and the result.
        self.ctl.clock.next = self.clock.val();
        self.ctl.valid.next = self.feed.o_valid.val();
        self.ctl.er.next = self.feed.o_er.val();
        self.ctl.pad.next = self.feed.o_pad.val();
        self.ctl.coord_mask.next = self.coord_mask.val();
        self.ctl.base_x.next = self.feed.o_base_x.val();
        self.ctl.base_y.next = self.feed.o_base_y.val();
        self.ctl.face.next = self.feed.o_face.val();
        self.ctl.x.next = self.feed.o_x.val();
        self.ctl.y.next = self.feed.o_y.val();
        self.ctl.sr.next = self.feed.o_sr.val();
        self.ctl.dx_neg.next = self.feed.o_dx_neg.val();
        self.ctl.dx_mag.next = self.feed.o_dx_mag.val();
        self.ctl.dy_neg.next = self.feed.o_dy_neg.val();
        self.ctl.dy_mag.next = self.feed.o_dy_mag.val();
        self.ctl.dims.next = self.dims.val();
        // The compositing-buffer taps (T).
        self.taps.clock.next = self.clock.val();
        self.taps.beats.next = self.beats.val();
        self.taps.x.next = self.ctl.x_t.val();
        self.t0s0.next = self.taps.t0s0.val();
        self.taps.t0i1.next = self.t0i1.val();
        self.t1s0.next = self.taps.t1s0.val();
        self.t1s1.next = self.taps.t1s1.val();
        self.taps.t1i1.next = self.t1i1.val();
        self.taps.t1i2.next = self.t1i2.val();
        self.t3s0.next = self.taps.t3s0.val();
        self.t3s1.next = self.taps.t3s1.val();
        self.taps.t3i1.next = self.t3i1.val();
        self.taps.t3i2.next = self.t3i2.val();
        self.t5s0.next = self.taps.t5s0.val();
        self.t5s1.next = self.taps.t5s1.val();
        self.t5s2.next = self.taps.t5s2.val();
        self.taps.t5i1.next = self.t5i1.val();
        self.taps.t5i2.next = self.t5i2.val();
        self.taps.t5i3.next = self.t5i3.val();
        self.t6s0.next = self.taps.t6s0.val();
        self.taps.t6i1.next = self.t6i1.val();
        self.t7s0.next = self.taps.t7s0.val();
        self.taps.t7i1.next = self.t7i1.val();
        self.t8s0.next = self.taps.t8s0.val();
        self.taps.t8i1.next = self.t8i1.val();
        self.taps.t8il.next = self.t8il.val();
        // The 2x2 selection by the signs of dx and dy (T).
        for c in 0..9 {
            self.cells.a[c].next = self.taps.a[c].val();
        }
        self.cells.order.next = self.order.val();
        for ch in 0..4 {
            self.cells.sel[ch].next = self.ctl.sel_t[ch].val();
        }
        // Bilinear unit (T..T+L).
        self.bilinear.clock.next = self.clock.val();
        for i in 0..4 {
            self.bilinear.c00[i].next = self.cells.c00[i].val();
            self.bilinear.c10[i].next = self.cells.c10[i].val();
            self.bilinear.c01[i].next = self.cells.c01[i].val();
            self.bilinear.c11[i].next = self.cells.c11[i].val();
        }
        self.bilinear.wx.next = self.ctl.dx_mag_t.val();
        self.bilinear.wy.next = self.ctl.dy_mag_t.val();
        // Compositing unit (T+L -> the result).
        self.compositor.clock.next = self.clock.val();
        self.compositor.order.next = self.order.val();
        self.compositor.acc_r.next = self.bilinear.out[0].val();
        self.compositor.acc_g.next = bit_cast::<16, 32>(self.bilinear.out[1].val());
        self.compositor.acc_b.next = bit_cast::<16, 32>(self.bilinear.out[2].val());
        self.compositor.acc_a.next = bit_cast::<16, 32>(self.bilinear.out[3].val());
        // The shader's sample arrives at T+L (`ControlDelay`).
        self.compositor.new_r.next = self.shader.r.val();
        self.compositor.new_g.next = self.shader.g.val();
        self.compositor.new_b.next = self.shader.b.val();
        self.compositor.new_a.next = self.shader.a.val();
        self.compositor.new_valid.next = self.shader.valid.val();
        self.res.next = bit_cast::<64, 32>(self.compositor.out_r.val())
            | (bit_cast::<64, 16>(self.compositor.out_g.val()) << 16)
            | (bit_cast::<64, 16>(self.compositor.out_b.val()) << 32)
            | (bit_cast::<64, 16>(self.compositor.out_a.val()) << 48);
        // The result: into the history, and out with the pixel on ER.
        self.taps.res.next = self.res.val();
        self.taps.res_beat.next = self.ctl.res_beat.val();
        self.res_beat.next = self.ctl.res_beat.val();
        self.res_valid.next = self.ctl.res_valid.val();
        self.px_valid.next = self.ctl.px_valid.val();
        self.px_x.next = self.ctl.px_x.val();
        self.px_y.next = self.ctl.px_y.val();
        self.px_face.next = self.ctl.px_face.val();
    }
}
