//! The Cube-4L rendering pipelines (§3, Figs. 4, 6, 18-21): the CFB feeds
//! `P` pipelines, each with the ABC gradient unit (when the configuration shades), a
//! shader, a compositing-buffer history, the bilinear unit and the
//! compositing unit. Pipelines talk only to their nearest neighbours.
//!
//! **Compositing buffer and neighbourhood.** Let R(t, j) be the value lane j
//! composited at beat t, S = n_y*b the beats of a slice and B = b those of a
//! beam. By the skew, cell (x + e_x, y + e_y) of the previous slice, for
//! voxel (x, y, z) of lane k at beat t, was composited by lane
//! k - 1 + e_x + e_y at beat t - S + e_y*B, one beat earlier or later when
//! e_x crosses a partial-beam end (x mod P = 0 with e_x = -1, x mod P = P-1
//! with e_x = +1). Each lane keeps its results once, in a ring of block RAM
//! read once, and beam-length delay lines and registers bring them to each
//! tap's delay ([`super::buffer_rows::BufferRows`], as Fig. 21's SFG reads
//! the compositing FIFO once). The nine taps of the 3x3 region
//! hop to the consuming lane through one register per neighbour link
//! (m = 1 - e_x - e_y links; tap (+1, +1) takes one leftward link), and each
//! tap keeps its previous value for the partial-beam case (the extension
//! units of Figs. 14-15). The signs of the voxel's dx and dy then narrow the
//! 3x3 region to 2x2 (Figs. 19-21). Cells outside the slice, and every cell at
//! the start of a ray (SR), read as the reset value.
//!
//! **Timing.** Shader input at T-1-G (the CFB's output, or the gradient
//! unit's a slice later; G = `GATHER_DELAY`), gather at T, the bilinear unit
//! T..T+L (`bilinear::LATENCY`, pipelined for speed), the shader's sample at
//! T+L (`shader::LATENCY` after its input), the compositor's registers at
//! T+L+1 to T+L+4 (`config::RESULT_AT`), where the result enters the lane's
//! history and, on ER, goes out as a base-plane pixel. The history's ring
//! needs at least one word: (n_y - 1) * b >= L + 9.
//!
//! **Lane.** [`PipeLane`] wires its blocks in this order: the input
//! selection ([`LaneFeed`], which holds the ABC gradient unit), the shader,
//! the taps ([`TapNetwork`] of nine [`super::buffer_tap::BufferTap`]s), the
//! 2x2 selection ([`Select2x2`]), the bilinear unit and the compositor, with
//! the control delay line beside them ([`ControlDelay`], which also makes
//! the pixel output).
//!
//! **Gradient control.** With a gradient unit the lanes' control comes from
//! `late`, a second copy of the CFB's address generator without memory,
//! started S + 1 clocks after the CFB, so the control of the voxel leaving
//! the gradient unit is recomputed rather than stored a slice long.
//!
//! **Registers.** The view is a register file the host writes through the
//! host port before a sweep (`golden_model::cube4l::regs::ViewRegs`; the
//! map is `golden_model::host::Reg`), as are the shader's light and tables:
//! one build renders every view of its configuration. The delay lines are
//! built for the configuration's largest slice and take their lengths from
//! the `Beats` register.
//!
//! Units a configuration does not need are built disabled, with empty
//! tables and one-register delay lines, and drive zero; the export prunes
//! them from the emitted Verilog (`cosim::cube4l::left_out`). The delay
//! lines store only the bits the mode can set
//! (`PipelineConfig::ring_fields`).

use super::cfb::Cfb;
use super::config::PipelineConfig;
use super::pipe_lane::PipeLane;
use crate::common::regs::{Regs, ADDRESS_BITS};
use crate::common::shader::{Shader, ShaderConfig};
use golden_model::cube4l::regs::REGS;
use golden_model::host::{Reg, ShaderTables};
use rust_hdl::prelude::*;

/// The whole Cube-4L pipeline: CFB and `P` pipelines (`A`-bit memory
/// modules, `H`-bit delay-line pointers).
#[derive(LogicBlock)]
pub struct Pipeline<const P: usize, const A: usize, const H: usize> {
    pub clock: Signal<In, Clock>,
    /// Start a sweep; the CFB's load port fills the voxel memory.
    pub start: Signal<In, Bit>,
    /// Synchronous reset: the sweep stops, and the pixel bus is quiet for
    /// the [`super::config::fill_clocks`] clocks the beats in flight take
    /// to drain. The registers and tables keep what the host wrote.
    pub reset: Signal<In, Bit>,
    pub load_enable: Signal<In, Bit>,
    pub load_module: Signal<In, Bits<8>>,
    pub load_address: Signal<In, Bits<A>>,
    pub load_data: Signal<In, Bits<16>>,
    /// The host port: registers and tables, written between sweeps
    /// (`golden_model::host`).
    pub host_write: Signal<In, Bit>,
    pub host_address: Signal<In, Bits<ADDRESS_BITS>>,
    pub host_data: Signal<In, Bits<64>>,
    /// Sweep status from the CFB's address generator: running, and the
    /// slice (N_s), beam (N_B) and partial beam (N_b) being read, with BS.
    pub busy: Signal<Out, Bit>,
    pub n_s: Signal<Out, Bits<16>>,
    pub n_beam: Signal<Out, Bits<16>>,
    pub n_b: Signal<Out, Bits<16>>,
    pub bs: Signal<Out, Bit>,
    /// Per pipeline, the external voxel memory port of a CFB built with
    /// `external_memory` (see `cfb::CfbLane`).
    pub ext_addr: [Signal<Out, Bits<32>>; P],
    pub ext_data: [Signal<In, Bits<16>>; P],
    /// The pixel bus: per pipeline, a base-plane pixel on ER (§3, Fig. 4),
    /// and each lane's composited value with its beat and padding flags.
    pub px_valid: [Signal<Out, Bit>; P],
    pub px_x: [Signal<Out, Bits<16>>; P],
    pub px_y: [Signal<Out, Bits<16>>; P],
    pub px_face: [Signal<Out, Bits<3>>; P],
    pub res_beat: [Signal<Out, Bit>; P],
    pub res_valid: [Signal<Out, Bit>; P],
    pub res: [Signal<Out, Bits<64>>; P],
    /// The view registers (`golden_model::cube4l::regs::REGS`).
    pub(crate) view: Regs<11>,
    pub(crate) cfb: Cfb<P, A>,
    pub(crate) lanes: [PipeLane<H>; P],
    /// With a gradient unit: the CFB's address generator again, without
    /// memory, started S + 1 clocks after it (`late_wait` counts down), so
    /// that the control of the voxel leaving the gradient unit is recomputed
    /// rather than stored.
    pub(crate) late: Cfb<P, A>,
    late_wait: DFF<Bits<32>>,
    /// `late_wait == 1`, registered from the count's next value: the late
    /// CFB's start is a flip-flop, no 32-bit compare lies before its
    /// counters' loads (the shaded build's critical path once).
    late_go: DFF<Bit>,
    gradient: Constant<Bit>,
    /// Clocks left of the drain after a reset.
    flush: DFF<Bits<8>>,
    flush_clocks: Constant<Bits<8>>,
    quiet: Signal<Local, Bit>,
}

impl<const P: usize, const A: usize, const H: usize> Pipeline<P, A, H> {
    /// Build the pipeline of configuration `config`.
    pub fn new(config: &PipelineConfig) -> Result<Pipeline<P, A, H>, String> {
        config.validate()?;
        if config.p as usize != P {
            return Err(format!(
                "configuration for {} pipelines, built with {P}",
                config.p
            ));
        }
        if config.history_bits() > H {
            return Err(format!(
                "the buffers need {}-bit delay-line pointers, built with {H}",
                config.history_bits()
            ));
        }
        if !config.external_memory() && config.memory_bits() as usize > A {
            return Err(format!(
                "{}-bit memory modules needed, built with {A}: use external memory",
                config.memory_bits()
            ));
        }
        let shading = ShaderConfig {
            mode: config.mode.mode(),
            voxel_bits: config.voxel_bits,
            rgba_bits: config.rgba_bits,
            lighting: config.shading,
            gradient_opacity: config.gradient_opacity,
            needs_gradient: config.gradient(),
            wide: false,
            normal_bits: config.normal_bits,
        };
        let mut lanes = Vec::with_capacity(P);
        for _ in 0..P {
            lanes.push(PipeLane::new(config, Shader::new(&shading)));
        }
        let lanes = lanes
            .into_boxed_slice()
            .try_into()
            .unwrap_or_else(|_| unreachable!());
        let cfb = Box::new(Cfb::new(config, config.external_memory()));
        let late = Box::new(Cfb::new(config, true));
        Ok(Self::with_lanes(config, lanes, cfb, late))
    }

    /// Give the CFB's memory modules initial contents (block-RAM
    /// initialisation), `modules[k][i]` being word `i` of module `k`.
    pub fn preload(&mut self, modules: &[Vec<u16>]) {
        self.cfb.preload(modules);
    }

    /// Give every lane's shader tables the contents the host would load
    /// (block-RAM initialisation, for simulation).
    pub fn preload_tables(&mut self, tables: &ShaderTables) {
        for lane in self.lanes.iter_mut() {
            lane.preload_tables(tables);
        }
    }

    /// Bits of block RAM in the pipelines' buffers, as built (not the CFB's
    /// voxel memory): `PipelineConfig::buffer_bits` counts them ahead.
    pub fn buffer_bits(&self) -> u64 {
        self.lanes.iter().map(|l| l.buffer_bits()).sum()
    }

    /// The pipeline around `lanes` and the two CFBs. rust-hdl's signals are
    /// large (a p = 4 pipeline takes half a megabyte) and testbenches build
    /// pipelines on 2 MB test-thread stacks, so the parts stay boxed until
    /// they move into place, and this function, kept out of line, writes the pipeline
    /// straight into the caller's result rather than through temporaries in
    /// `new`'s frame.
    #[inline(never)]
    #[allow(clippy::boxed_local)] // the boxes keep the parts off the stack
    fn with_lanes(
        config: &PipelineConfig,
        lanes: Box<[PipeLane<H>; P]>,
        cfb: Box<Cfb<P, A>>,
        late: Box<Cfb<P, A>>,
    ) -> Self {
        Pipeline {
            clock: Default::default(),
            start: Default::default(),
            reset: Default::default(),
            load_enable: Default::default(),
            load_module: Default::default(),
            load_address: Default::default(),
            load_data: Default::default(),
            host_write: Default::default(),
            host_address: Default::default(),
            host_data: Default::default(),
            busy: Default::default(),
            n_s: Default::default(),
            n_beam: Default::default(),
            n_b: Default::default(),
            bs: Default::default(),
            ext_addr: std::array::from_fn(|_| Default::default()),
            ext_data: std::array::from_fn(|_| Default::default()),
            px_valid: std::array::from_fn(|_| Default::default()),
            px_x: std::array::from_fn(|_| Default::default()),
            px_y: std::array::from_fn(|_| Default::default()),
            px_face: std::array::from_fn(|_| Default::default()),
            res_beat: std::array::from_fn(|_| Default::default()),
            res_valid: std::array::from_fn(|_| Default::default()),
            res: std::array::from_fn(|_| Default::default()),
            view: Regs::new(REGS.map(Reg::address)),
            cfb: *cfb,
            lanes: *lanes,
            late: *late,
            late_wait: Default::default(),
            late_go: Default::default(),
            gradient: Constant::new(config.gradient()),
            flush: Default::default(),
            flush_clocks: Constant::new(super::config::fill_clocks(config).to_bits()),
            quiet: Default::default(),
        }
    }
}

impl<const P: usize, const A: usize, const H: usize> Logic for Pipeline<P, A, H> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, late_wait, late_go, flush);
        // The view registers, to both CFBs and every lane.
        self.view.clock.next = self.clock.val();
        self.view.host_write.next = self.host_write.val();
        self.view.host_address.next = self.host_address.val();
        self.view.host_data.next = self.host_data.val();
        self.cfb.dims.next = self.view.q[0].val();
        self.cfb.slices.next = self.view.q[1].val();
        self.cfb.axes.next = self.view.q[2].val();
        self.cfb.address_reg.next = self.view.q[3].val();
        self.cfb.dx.next = self.view.q[4].val();
        self.cfb.dy.next = self.view.q[5].val();
        self.cfb.eye_x.next = self.view.q[6].val();
        self.cfb.eye_y.next = self.view.q[7].val();
        self.cfb.eye_z.next = self.view.q[8].val();
        self.cfb.beats.next = self.view.q[9].val();
        self.late.dims.next = self.view.q[0].val();
        self.late.slices.next = self.view.q[1].val();
        self.late.axes.next = self.view.q[2].val();
        self.late.address_reg.next = self.view.q[3].val();
        self.late.dx.next = self.view.q[4].val();
        self.late.dy.next = self.view.q[5].val();
        self.late.eye_x.next = self.view.q[6].val();
        self.late.eye_y.next = self.view.q[7].val();
        self.late.eye_z.next = self.view.q[8].val();
        self.late.beats.next = self.view.q[9].val();
        self.cfb.clock.next = self.clock.val();
        self.cfb.start.next = self.start.val();
        self.cfb.reset.next = self.reset.val();
        self.late.reset.next = self.reset.val();
        // After a reset, the beats in flight drain with the pixel bus quiet.
        self.flush.d.next = self.flush.q.val();
        if self.reset.val() {
            self.flush.d.next = self.flush_clocks.val();
        } else if self.flush.q.val() != 0 {
            self.flush.d.next = self.flush.q.val() - 1;
        }
        self.quiet.next = self.reset.val() | (self.flush.q.val() != 0);
        self.cfb.load_enable.next = self.load_enable.val();
        self.cfb.load_module.next = self.load_module.val();
        self.cfb.load_address.next = self.load_address.val();
        self.cfb.load_data.next = self.load_data.val();
        self.busy.next = self.cfb.busy.val();
        self.n_s.next = self.cfb.n_s.val();
        self.n_beam.next = self.cfb.n_beam.val();
        self.n_b.next = self.cfb.n_b.val();
        self.bs.next = self.cfb.bs.val();
        // The late CFB starts S + 1 clocks after the CFB took its start.
        self.late_wait.d.next = self.late_wait.q.val();
        if self.start.val() & !self.cfb.busy.val() {
            self.late_wait.d.next = self.view.q[9].val().get_bits::<32>(0) + 1;
        } else if self.late_wait.q.val() != 0 {
            self.late_wait.d.next = self.late_wait.q.val() - 1;
        }
        if self.reset.val() {
            self.late_wait.d.next = 0.into();
        }
        self.late.clock.next = self.clock.val();
        self.late_go.d.next = self.late_wait.d.val() == 1;
        self.late.start.next = self.late_go.q.val();
        self.late.load_enable.next = false;
        self.late.load_module.next = 0.into();
        self.late.load_address.next = 0.into();
        self.late.load_data.next = 0.into();
        for k in 0..P {
            self.late.ext_data[k].next = 0.into();
            self.lanes[k].clock.next = self.clock.val();
            self.lanes[k].host_write.next = self.host_write.val();
            self.lanes[k].host_address.next = self.host_address.val();
            self.lanes[k].host_data.next = self.host_data.val();
            self.lanes[k].dims.next = self.view.q[0].val();
            self.lanes[k].beats.next = self.view.q[9].val();
            self.lanes[k].order.next = self.view.q[10].val();
            self.cfb.ext_data[k].next = self.ext_data[k].val();
            self.ext_addr[k].next = self.cfb.ext_addr[k].val();
            self.px_valid[k].next = self.lanes[k].px_valid.val() & !self.quiet.val();
            self.px_x[k].next = self.lanes[k].px_x.val();
            self.px_y[k].next = self.lanes[k].px_y.val();
            self.px_face[k].next = self.lanes[k].px_face.val();
            self.res_beat[k].next = self.lanes[k].res_beat.val() & !self.quiet.val();
            self.res_valid[k].next = self.lanes[k].res_valid.val() & !self.quiet.val();
            self.res[k].next = self.lanes[k].res.val();
            self.lanes[k].value.next = self.cfb.value[k].val();
        }
        // The lanes' control: the CFB's, or the late CFB's with a gradient unit.
        if self.gradient.val() {
            for k in 0..P {
                self.lanes[k].beat_valid.next = self.late.valid.val();
                self.lanes[k].x.next = self.late.x[k].val();
                self.lanes[k].y.next = self.late.y[k].val();
                self.lanes[k].pad.next = self.late.pad[k].val();
                self.lanes[k].invalid.next = self.late.invalid[k].val();
                self.lanes[k].halo.next = self.late.halo[k].val();
                self.lanes[k].sr.next = self.late.sr[k].val();
                self.lanes[k].er.next = self.late.er[k].val();
                self.lanes[k].base_x.next = self.late.base_x[k].val();
                self.lanes[k].base_y.next = self.late.base_y[k].val();
                self.lanes[k].face.next = self.late.face[k].val();
                self.lanes[k].at_edge.next = self.late.at_edge[k].val();
                self.lanes[k].dx_neg.next = self.late.dx_neg[k].val();
                self.lanes[k].dx_mag.next = self.late.dx_mag[k].val();
                self.lanes[k].dy_neg.next = self.late.dy_neg[k].val();
                self.lanes[k].dy_mag.next = self.late.dy_mag[k].val();
            }
        } else {
            for k in 0..P {
                self.lanes[k].beat_valid.next = self.cfb.valid.val();
                self.lanes[k].x.next = self.cfb.x[k].val();
                self.lanes[k].y.next = self.cfb.y[k].val();
                self.lanes[k].pad.next = self.cfb.pad[k].val();
                self.lanes[k].invalid.next = self.cfb.invalid[k].val();
                self.lanes[k].halo.next = self.cfb.halo[k].val();
                self.lanes[k].sr.next = self.cfb.sr[k].val();
                self.lanes[k].er.next = self.cfb.er[k].val();
                self.lanes[k].base_x.next = self.cfb.base_x[k].val();
                self.lanes[k].base_y.next = self.cfb.base_y[k].val();
                self.lanes[k].face.next = self.cfb.face[k].val();
                self.lanes[k].at_edge.next = self.cfb.at_edge[k].val();
                self.lanes[k].dx_neg.next = self.cfb.dx_neg[k].val();
                self.lanes[k].dx_mag.next = self.cfb.dx_mag[k].val();
                self.lanes[k].dy_neg.next = self.cfb.dy_neg[k].val();
                self.lanes[k].dy_mag.next = self.cfb.dy_mag[k].val();
            }
        }
        // Nearest-neighbour links: lane k-1 feeds lane k (lane P-1 feeds 0).
        for k in 1..P {
            self.lanes[k].t0i1.next = self.lanes[k - 1].t0s0.val();
            self.lanes[k].t1i1.next = self.lanes[k - 1].t1s0.val();
            self.lanes[k].t1i2.next = self.lanes[k - 1].t1s1.val();
            self.lanes[k].t3i1.next = self.lanes[k - 1].t3s0.val();
            self.lanes[k].t3i2.next = self.lanes[k - 1].t3s1.val();
            self.lanes[k].t5i1.next = self.lanes[k - 1].t5s0.val();
            self.lanes[k].t5i2.next = self.lanes[k - 1].t5s1.val();
            self.lanes[k].t5i3.next = self.lanes[k - 1].t5s2.val();
            self.lanes[k].t6i1.next = self.lanes[k - 1].t6s0.val();
            self.lanes[k].t7i1.next = self.lanes[k - 1].t7s0.val();
            self.lanes[k].t8i1.next = self.lanes[k - 1].t8s0.val();
        }
        for k in (P - 1)..P {
            self.lanes[0].t0i1.next = self.lanes[k].t0s0.val();
            self.lanes[0].t1i1.next = self.lanes[k].t1s0.val();
            self.lanes[0].t1i2.next = self.lanes[k].t1s1.val();
            self.lanes[0].t3i1.next = self.lanes[k].t3s0.val();
            self.lanes[0].t3i2.next = self.lanes[k].t3s1.val();
            self.lanes[0].t5i1.next = self.lanes[k].t5s0.val();
            self.lanes[0].t5i2.next = self.lanes[k].t5s1.val();
            self.lanes[0].t5i3.next = self.lanes[k].t5s2.val();
            self.lanes[0].t6i1.next = self.lanes[k].t6s0.val();
            self.lanes[0].t7i1.next = self.lanes[k].t7s0.val();
            self.lanes[0].t8i1.next = self.lanes[k].t8s0.val();
        }
        // The leftward link of tap (x+1, y+1): lane k+1 feeds lane k.
        for k in 0..(P - 1) {
            self.lanes[k].t8il.next = self.lanes[k + 1].t8s0.val();
        }
        for k in (P - 1)..P {
            self.lanes[k].t8il.next = self.lanes[0].t8s0.val();
        }
        // ABC gradient links, both ways.
        for k in 1..P {
            self.lanes[k].g_from_left_xm.next = self.lanes[k - 1].g_to_right_xm.val();
            self.lanes[k].g_from_left_ym.next = self.lanes[k - 1].g_to_right_ym.val();
            self.lanes[k].g_from_left_zm.next = self.lanes[k - 1].g_to_right_zm.val();
        }
        for k in (P - 1)..P {
            self.lanes[0].g_from_left_xm.next = self.lanes[k].g_to_right_xm.val();
            self.lanes[0].g_from_left_ym.next = self.lanes[k].g_to_right_ym.val();
            self.lanes[0].g_from_left_zm.next = self.lanes[k].g_to_right_zm.val();
        }
        for k in 0..(P - 1) {
            self.lanes[k].g_from_right_xp.next = self.lanes[k + 1].g_to_left_xp.val();
            self.lanes[k].g_from_right_yp.next = self.lanes[k + 1].g_to_left_yp.val();
            self.lanes[k].g_from_right_zp.next = self.lanes[k + 1].g_to_left_zp.val();
        }
        for k in (P - 1)..P {
            self.lanes[k].g_from_right_xp.next = self.lanes[0].g_to_left_xp.val();
            self.lanes[k].g_from_right_yp.next = self.lanes[0].g_to_left_yp.val();
            self.lanes[k].g_from_right_zp.next = self.lanes[0].g_to_left_zp.val();
        }
    }
}
