//! Cubic Frame Buffer of Cube-4L (§3.1, Figs. 5, 6, 7 and 13):
//! `P` skewed memory modules, the address generator with its counters N_b,
//! N_B and N_s, the pipeline-to-dataset transform for the sweep's major axis,
//! the control bits SR, ER, BS, invalid and edge, the frame registers dx and
//! dy, and the base-plane pixel address. Each beat it reads one voxel per
//! pipeline and emits it with its control `ADDRESS_STAGES + READ_STAGES`
//! clocks after the counters issue it (the address pipeline: the skew and
//! transform, the three stride products, their sum, each registered; then
//! the block RAM's registered read, a register beside it and a relay
//! register beside the lane, so that the memory's clock-to-out reaches no
//! logic and no route across the part), exactly as
//! `golden_model::cube4l::cfb::CfbStream`.
//!
//! Lane `k` holds `x = N_b*P + ((k - N_B - N_s) mod P)` of beam `N_B` in slice
//! `N_s`. Dataset voxel `(u, v, w)` is at address `u div P + v*b + w*b*n_v`
//! of module `(u + v + w) mod P`. Lanes past the end of a beam whose length
//! is not a multiple of `P` are padding: invalid, value 0, no pixel.
//!
//! The memory is loaded through the `load_*` port (one write per clock into
//! module `load_module`) and maps to block RAM (`A` address bits per module).
//! For volumes beyond on-chip memory
//! ([`PipelineConfig::external_memory`]), each lane presents its read
//! address on `ext_addr` and takes the voxel from `ext_data` one clock
//! later, as a synchronous external RAM answers, into the same register.
//!
//! The view is the host's registers (`golden_model::cube4l::regs`): the
//! dims, the slices streamed, the axes, the memory's address layout, the
//! beats of a beam, and dx and dy (parallel views) or the eye (perspective). Perspective views add
//! the per-voxel divider: `S = P - V` in fixed point, then
//! `dx = round(S_x * 2^f / S_z)` with halves away from zero. `|dx| > 1` or
//! `S_z = 0` sets *invalid*, and such voxels carry the golden model's
//! saturated direction, `sign(S_x) * sign(S_z)`.

use super::cfb_lane::CfbLane;
use super::config::PipelineConfig;
use super::counter_lead::CounterLead;
use golden_model::cube4l::plan::Face;
use rust_hdl::prelude::*;

/// The CFB of `P` pipelines with `A`-bit module addresses.
#[derive(LogicBlock)]
pub struct Cfb<const P: usize, const A: usize> {
    pub clock: Signal<In, Clock>,
    /// The view registers (see `CfbLane`), and `Beats`.
    pub dims: Signal<In, Bits<64>>,
    pub slices: Signal<In, Bits<64>>,
    pub axes: Signal<In, Bits<64>>,
    pub address_reg: Signal<In, Bits<64>>,
    pub dx: Signal<In, Bits<64>>,
    pub dy: Signal<In, Bits<64>>,
    pub eye_x: Signal<In, Bits<64>>,
    pub eye_y: Signal<In, Bits<64>>,
    pub eye_z: Signal<In, Bits<64>>,
    pub beats: Signal<In, Bits<64>>,
    /// Pulse to start a sweep; `busy` stays high until its last beat is issued.
    pub start: Signal<In, Bit>,
    /// Synchronous reset: the address generator stops (the counters' next
    /// `start` restarts them).
    pub reset: Signal<In, Bit>,
    pub busy: Signal<Out, Bit>,
    pub load_enable: Signal<In, Bit>,
    pub load_module: Signal<In, Bits<8>>,
    pub load_address: Signal<In, Bits<A>>,
    pub load_data: Signal<In, Bits<16>>,
    /// The beat on the lanes is valid (`ADDRESS_STAGES + READ_STAGES`
    /// clocks after it was issued).
    pub valid: Signal<Out, Bit>,
    pub n_s: Signal<Out, Bits<16>>,
    pub n_beam: Signal<Out, Bits<16>>,
    pub n_b: Signal<Out, Bits<16>>,
    /// Start of beam: the first partial beam of a full beam.
    pub bs: Signal<Out, Bit>,
    /// The lanes' outputs the pipelines use, per lane (a parent may only
    /// read its children's ports).
    pub value: [Signal<Out, Bits<16>>; P],
    pub x: [Signal<Out, Bits<16>>; P],
    pub y: [Signal<Out, Bits<16>>; P],
    /// The voxel's slice and memory address: observability outputs, for
    /// the CFB's testbench and the waveforms; the pipelines read neither.
    pub z: [Signal<Out, Bits<16>>; P],
    pub address: [Signal<Out, Bits<32>>; P],
    pub pad: [Signal<Out, Bit>; P],
    pub sr: [Signal<Out, Bit>; P],
    pub er: [Signal<Out, Bit>; P],
    pub base_x: [Signal<Out, Bits<16>>; P],
    pub base_y: [Signal<Out, Bits<16>>; P],
    pub face: [Signal<Out, Bits<3>>; P],
    pub at_edge: [Signal<Out, Bit>; P],
    pub invalid: [Signal<Out, Bit>; P],
    pub halo: [Signal<Out, Bit>; P],
    /// Per lane: the external memory port (see `CfbLane`).
    pub ext_addr: [Signal<Out, Bits<32>>; P],
    pub ext_data: [Signal<In, Bits<16>>; P],
    pub dx_neg: [Signal<Out, Bit>; P],
    pub dx_mag: [Signal<Out, Bits<16>>; P],
    pub dy_neg: [Signal<Out, Bit>; P],
    pub dy_mag: [Signal<Out, Bits<16>>; P],
    pub(crate) lanes: [CfbLane<A>; P],
    running: DFF<Bit>,
    ns_c: DFF<Bits<16>>,
    nbeam_c: DFF<Bits<16>>,
    nb_c: DFF<Bits<16>>,
    /// Perspective views: the counters' lead before the address pipeline,
    /// while each lane's divider takes them as issued.
    pub(crate) lead: CounterLead,
    perspective: Constant<Bit>,
    /// The counters as the address pipeline takes them: as issued, or
    /// (perspective) from the lead.
    e_run: Signal<Local, Bit>,
    e_ns: Signal<Local, Bits<16>>,
    e_nbeam: Signal<Local, Bits<16>>,
    e_nb: Signal<Local, Bits<16>>,
    /// The counters and `running` through the lanes' address pipeline
    /// (`ADDRESS_STAGES`, three clocks: `_d1` to `_d3`), then the RAM
    /// read's clocks (`_d4`, `_d5`) and its last register's (`_q`).
    run_d1: DFF<Bit>,
    run_d2: DFF<Bit>,
    run_d3: DFF<Bit>,
    ns_d1: DFF<Bits<16>>,
    ns_d2: DFF<Bits<16>>,
    ns_d3: DFF<Bits<16>>,
    nbeam_d1: DFF<Bits<16>>,
    nbeam_d2: DFF<Bits<16>>,
    nbeam_d3: DFF<Bits<16>>,
    nb_d1: DFF<Bits<16>>,
    nb_d2: DFF<Bits<16>>,
    nb_d3: DFF<Bits<16>>,
    run_d4: DFF<Bit>,
    ns_d4: DFF<Bits<16>>,
    nbeam_d4: DFF<Bits<16>>,
    nb_d4: DFF<Bits<16>>,
    run_d5: DFF<Bit>,
    ns_d5: DFF<Bits<16>>,
    nbeam_d5: DFF<Bits<16>>,
    nb_d5: DFF<Bits<16>>,
    valid_q: DFF<Bit>,
    ns_q: DFF<Bits<16>>,
    nbeam_q: DFF<Bits<16>>,
    nb_q: DFF<Bits<16>>,
    z0: Signal<Local, Bits<16>>,
    z1: Signal<Local, Bits<16>>,
    /// The view's `n_y - 1` and `B - 1`.
    ny_m1: Signal<Local, Bits<16>>,
    b_m1: Signal<Local, Bits<16>>,
    /// The inner counts' spans, registered from the view registers for the
    /// wraps' reloads, and each counter's steps left before it wraps: the
    /// wrap tests a counter's own register against zero, not an up-counter
    /// against a view register shared (and merged by synthesis) across lanes.
    ny_last: DFF<Bits<16>>,
    b_last: DFF<Bits<16>>,
    nb_left: DFF<Bits<16>>,
    nbeam_left: DFF<Bits<16>>,
    ns_left: DFF<Bits<16>>,
    /// Each counter's wrap as a register of its own, `left == 0`, set
    /// beside the count (`left == 1` as it steps, the span's `== 0` as it
    /// reloads): the three counters' enables are an AND of flip-flops, no
    /// 16-bit zero test lies before them (the perspective build's critical
    /// path ran from `nb_left` through those tests to the slice counter).
    nb_end: DFF<Bit>,
    nbeam_end: DFF<Bit>,
    ns_end: DFF<Bit>,
    ny_last_zero: DFF<Bit>,
    b_last_zero: DFF<Bit>,
}

impl<const P: usize, const A: usize> Cfb<P, A> {
    /// The CFB of `c`; `external`: its voxels come from external RAM (or
    /// from none, for the late CFB).
    pub fn new(c: &PipelineConfig, external: bool) -> Cfb<P, A> {
        assert!(P.is_power_of_two(), "P must be a power of two");
        Cfb {
            clock: Default::default(),
            dims: Default::default(),
            slices: Default::default(),
            axes: Default::default(),
            address_reg: Default::default(),
            dx: Default::default(),
            dy: Default::default(),
            eye_x: Default::default(),
            eye_y: Default::default(),
            eye_z: Default::default(),
            beats: Default::default(),
            start: Default::default(),
            reset: Default::default(),
            busy: Default::default(),
            load_enable: Default::default(),
            load_module: Default::default(),
            load_address: Default::default(),
            load_data: Default::default(),
            valid: Default::default(),
            n_s: Default::default(),
            n_beam: Default::default(),
            n_b: Default::default(),
            bs: Default::default(),
            value: std::array::from_fn(|_| Default::default()),
            x: std::array::from_fn(|_| Default::default()),
            y: std::array::from_fn(|_| Default::default()),
            z: std::array::from_fn(|_| Default::default()),
            address: std::array::from_fn(|_| Default::default()),
            pad: std::array::from_fn(|_| Default::default()),
            sr: std::array::from_fn(|_| Default::default()),
            er: std::array::from_fn(|_| Default::default()),
            base_x: std::array::from_fn(|_| Default::default()),
            base_y: std::array::from_fn(|_| Default::default()),
            face: std::array::from_fn(|_| Default::default()),
            at_edge: std::array::from_fn(|_| Default::default()),
            invalid: std::array::from_fn(|_| Default::default()),
            halo: std::array::from_fn(|_| Default::default()),
            ext_addr: std::array::from_fn(|_| Default::default()),
            ext_data: std::array::from_fn(|_| Default::default()),
            dx_neg: std::array::from_fn(|_| Default::default()),
            dx_mag: std::array::from_fn(|_| Default::default()),
            dy_neg: std::array::from_fn(|_| Default::default()),
            dy_mag: std::array::from_fn(|_| Default::default()),
            lanes: std::array::from_fn(|k| CfbLane::new(k as u32, c, external)),
            running: Default::default(),
            ns_c: Default::default(),
            nbeam_c: Default::default(),
            nb_c: Default::default(),
            lead: CounterLead::new(c.perspective),
            perspective: Constant::new(c.perspective),
            e_run: Default::default(),
            e_ns: Default::default(),
            e_nbeam: Default::default(),
            e_nb: Default::default(),
            run_d1: Default::default(),
            run_d2: Default::default(),
            run_d3: Default::default(),
            ns_d1: Default::default(),
            ns_d2: Default::default(),
            ns_d3: Default::default(),
            nbeam_d1: Default::default(),
            nbeam_d2: Default::default(),
            nbeam_d3: Default::default(),
            nb_d1: Default::default(),
            nb_d2: Default::default(),
            nb_d3: Default::default(),
            run_d4: Default::default(),
            ns_d4: Default::default(),
            nbeam_d4: Default::default(),
            nb_d4: Default::default(),
            run_d5: Default::default(),
            ns_d5: Default::default(),
            nbeam_d5: Default::default(),
            nb_d5: Default::default(),
            valid_q: Default::default(),
            ns_q: Default::default(),
            nbeam_q: Default::default(),
            nb_q: Default::default(),
            z0: Default::default(),
            z1: Default::default(),
            ny_m1: Default::default(),
            b_m1: Default::default(),
            ny_last: Default::default(),
            b_last: Default::default(),
            nb_left: Default::default(),
            nbeam_left: Default::default(),
            ns_left: Default::default(),
            nb_end: Default::default(),
            nbeam_end: Default::default(),
            ns_end: Default::default(),
            ny_last_zero: Default::default(),
            b_last_zero: Default::default(),
        }
    }
}

impl<const P: usize, const A: usize> Logic for Cfb<P, A> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            running,
            ns_c,
            nbeam_c,
            nb_c,
            valid_q,
            ns_q,
            nbeam_q,
            nb_q,
            run_d1,
            run_d2,
            run_d3,
            run_d4,
            ns_d1,
            ns_d2,
            ns_d3,
            ns_d4,
            nbeam_d1,
            nbeam_d2,
            nbeam_d3,
            nbeam_d4,
            nb_d1,
            nb_d2,
            nb_d3,
            nb_d4,
            run_d5,
            ns_d5,
            nbeam_d5,
            nb_d5,
            ny_last,
            b_last,
            nb_left,
            nbeam_left,
            ns_left,
            nb_end,
            nbeam_end,
            ns_end,
            ny_last_zero,
            b_last_zero
        );
        self.lead.clock.next = self.clock.val();
        self.lead.reset.next = self.reset.val();
        self.lead.running.next = self.running.q.val();
        self.lead.n_s.next = self.ns_c.q.val();
        self.lead.n_beam.next = self.nbeam_c.q.val();
        self.lead.n_b.next = self.nb_c.q.val();
        self.e_run.next = self.running.q.val();
        self.e_ns.next = self.ns_c.q.val();
        self.e_nbeam.next = self.nbeam_c.q.val();
        self.e_nb.next = self.nb_c.q.val();
        if self.perspective.val() {
            self.e_run.next = self.lead.running_out.val();
            self.e_ns.next = self.lead.n_s_out.val();
            self.e_nbeam.next = self.lead.n_beam_out.val();
            self.e_nb.next = self.lead.n_b_out.val();
        }
        self.run_d1.d.next = self.e_run.val();
        self.ns_d1.d.next = self.e_ns.val();
        self.nbeam_d1.d.next = self.e_nbeam.val();
        self.nb_d1.d.next = self.e_nb.val();
        self.run_d2.d.next = self.run_d1.q.val();
        self.ns_d2.d.next = self.ns_d1.q.val();
        self.nbeam_d2.d.next = self.nbeam_d1.q.val();
        self.nb_d2.d.next = self.nb_d1.q.val();
        self.run_d3.d.next = self.run_d2.q.val();
        self.ns_d3.d.next = self.ns_d2.q.val();
        self.nbeam_d3.d.next = self.nbeam_d2.q.val();
        self.nb_d3.d.next = self.nb_d2.q.val();
        self.run_d4.d.next = self.run_d3.q.val();
        self.ns_d4.d.next = self.ns_d3.q.val();
        self.nbeam_d4.d.next = self.nbeam_d3.q.val();
        self.nb_d4.d.next = self.nb_d3.q.val();
        self.run_d5.d.next = self.run_d4.q.val();
        self.ns_d5.d.next = self.ns_d4.q.val();
        self.nbeam_d5.d.next = self.nbeam_d4.q.val();
        self.nb_d5.d.next = self.nb_d4.q.val();
        // The slices streamed, the last beam, the last partial beam.
        self.z0.next = self.slices.val().get_bits::<16>(32);
        self.z1.next = self.slices.val().get_bits::<16>(48);
        self.ny_m1.next = self.dims.val().get_bits::<16>(16) - 1;
        self.b_m1.next = self.beats.val().get_bits::<16>(32) - 1;
        self.ny_last.d.next = self.ny_m1.val();
        self.b_last.d.next = self.b_m1.val();
        self.ny_last_zero.d.next = self.ny_m1.val() == 0;
        self.b_last_zero.d.next = self.b_m1.val() == 0;
        for k in 0..P {
            self.lanes[k].clock.next = self.clock.val();
            self.lanes[k].dims.next = self.dims.val();
            self.lanes[k].slices.next = self.slices.val();
            self.lanes[k].axes.next = self.axes.val();
            self.lanes[k].address_reg.next = self.address_reg.val();
            self.lanes[k].dx.next = self.dx.val();
            self.lanes[k].dy.next = self.dy.val();
            self.lanes[k].eye_x.next = self.eye_x.val();
            self.lanes[k].eye_y.next = self.eye_y.val();
            self.lanes[k].eye_z.next = self.eye_z.val();
            self.lanes[k].d_n_s.next = self.ns_c.q.val();
            self.lanes[k].d_n_beam.next = self.nbeam_c.q.val();
            self.lanes[k].d_n_b.next = self.nb_c.q.val();
            self.lanes[k].a_n_s.next = self.e_ns.val();
            self.lanes[k].a_n_beam.next = self.e_nbeam.val();
            self.lanes[k].a_n_b.next = self.e_nb.val();
            self.lanes[k].c_n_s.next = self.ns_d4.q.val();
            self.lanes[k].c_n_beam.next = self.nbeam_d4.q.val();
            self.lanes[k].c_n_b.next = self.nb_d4.q.val();
            self.lanes[k].n_s.next = self.ns_d5.q.val();
            self.lanes[k].n_beam.next = self.nbeam_d5.q.val();
            self.lanes[k].load_enable.next = self.load_enable.val();
            self.lanes[k].load_module.next = self.load_module.val();
            self.lanes[k].load_address.next = self.load_address.val();
            self.lanes[k].load_data.next = self.load_data.val();
            self.value[k].next = self.lanes[k].value.val();
            self.x[k].next = self.lanes[k].x.val();
            self.z[k].next = self.lanes[k].z.val();
            self.address[k].next = self.lanes[k].address.val();
            self.y[k].next = self.lanes[k].y.val();
            self.pad[k].next = self.lanes[k].pad.val();
            self.sr[k].next = self.lanes[k].sr.val();
            self.er[k].next = self.lanes[k].er.val();
            self.base_x[k].next = self.lanes[k].base_x.val();
            self.base_y[k].next = self.lanes[k].base_y.val();
            self.face[k].next = self.lanes[k].face.val();
            self.at_edge[k].next = self.lanes[k].at_edge.val();
            self.invalid[k].next = self.lanes[k].invalid.val();
            self.halo[k].next = self.lanes[k].halo.val();
            self.ext_addr[k].next = self.lanes[k].ext_addr.val();
            self.lanes[k].ext_data.next = self.ext_data[k].val();
            self.dx_neg[k].next = self.lanes[k].dx_neg.val();
            self.dx_mag[k].next = self.lanes[k].dx_mag.val();
            self.dy_neg[k].next = self.lanes[k].dy_neg.val();
            self.dy_mag[k].next = self.lanes[k].dy_mag.val();
        }
        // The address generator: N_b fastest, then N_B, then N_s.
        if self.start.val() & !self.running.q.val() {
            self.running.d.next = true;
            self.ns_c.d.next = self.z0.val();
            self.nbeam_c.d.next = 0.into();
            self.nb_c.d.next = 0.into();
            // The view is valid from this clock; its registered spans from
            // the next, in time for the first wrap.
            self.nb_left.d.next = self.b_m1.val();
            self.nbeam_left.d.next = self.ny_m1.val();
            self.ns_left.d.next = self.z1.val() - self.z0.val();
            self.nb_end.d.next = self.b_m1.val() == 0;
            self.nbeam_end.d.next = self.ny_m1.val() == 0;
            self.ns_end.d.next = self.z1.val() == self.z0.val();
        }
        if self.running.q.val() {
            if !self.nb_end.q.val() {
                self.nb_c.d.next = self.nb_c.q.val() + 1;
                self.nb_left.d.next = self.nb_left.q.val() - 1;
                self.nb_end.d.next = self.nb_left.q.val() == 1;
            } else {
                self.nb_c.d.next = 0.into();
                self.nb_left.d.next = self.b_last.q.val();
                self.nb_end.d.next = self.b_last_zero.q.val();
                if !self.nbeam_end.q.val() {
                    self.nbeam_c.d.next = self.nbeam_c.q.val() + 1;
                    self.nbeam_left.d.next = self.nbeam_left.q.val() - 1;
                    self.nbeam_end.d.next = self.nbeam_left.q.val() == 1;
                } else {
                    self.nbeam_c.d.next = 0.into();
                    self.nbeam_left.d.next = self.ny_last.q.val();
                    self.nbeam_end.d.next = self.ny_last_zero.q.val();
                    if !self.ns_end.q.val() {
                        self.ns_c.d.next = self.ns_c.q.val() + 1;
                        self.ns_left.d.next = self.ns_left.q.val() - 1;
                        self.ns_end.d.next = self.ns_left.q.val() == 1;
                    } else {
                        self.running.d.next = false;
                    }
                }
            }
        }
        if self.reset.val() {
            self.running.d.next = false;
        }
        self.valid_q.d.next = self.run_d5.q.val();
        self.ns_q.d.next = self.ns_d5.q.val();
        self.nbeam_q.d.next = self.nbeam_d5.q.val();
        self.nb_q.d.next = self.nb_d5.q.val();
        self.busy.next = self.running.q.val();
        if self.perspective.val() {
            self.busy.next = self.lead.busy.val();
        }
        self.valid.next = self.valid_q.q.val();
        self.n_s.next = self.ns_q.q.val();
        self.n_beam.next = self.nbeam_q.q.val();
        self.n_b.next = self.nb_q.q.val();
        self.bs.next = self.nb_q.q.val() == 0;
    }
}

impl<const P: usize, const A: usize> Cfb<P, A> {
    /// Give the memory modules initial contents (block-RAM initialisation),
    /// `modules[k][i]` being word `i` of module `k`.
    pub fn preload(&mut self, modules: &[Vec<u16>]) {
        for (lane, words) in self.lanes.iter_mut().zip(modules) {
            lane.preload(words);
        }
    }
}

/// `Face` as the number on the lanes' `face` output.
pub fn face_code(f: Face) -> u32 {
    f as u8 as u32
}
