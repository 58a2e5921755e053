//! The Cube-4L rendering pipelines (§3, Figs. 4, 6, 18-21) for parallel
//! views of scenes without gradients: the CFB feeds `P` pipelines, each with a
//! shader, a compositing-buffer history, the bilinear unit and the compositing
//! unit. Pipelines talk only to their nearest neighbours.
//!
//! **Compositing buffer and neighbourhood.** Let R(t, j) be the value lane j
//! composited at beat t, S = n_y*b the beats of a slice and B = b those of a
//! beam. By the skew, the cells of the previous slice around voxel (x, y, z)
//! of lane k at beat t are:
//!
//! | cell | lane | beat |
//! |---|---|---|
//! | (x, y) | k-1 | t - S |
//! | (x-1, y) / (x+1, y) | k-2 / k | t - S - [x mod P = 0] / t - S + [x mod P = P-1] |
//! | (x, y-1) / (x, y+1) | k-2 / k | t - S - B / t - S + B |
//! | diagonals | k-3, k-1, k+1 | combinations of the above |
//!
//! Parallel views have constant signs of dx and dy, so only the 2x2 cells they
//! select are fetched (the 3x3 network is needed only with the perspective
//! divider). Each lane keeps its results in a ring buffer of block RAM (one
//! copy per tap, one read port each). A tap read at lane j hops to lane k
//! through one register per neighbour link, so it is read that many clocks
//! early. Each tap also keeps its previous value for the partial-beam
//! boundary cases (the extension units of Figs. 14-15). Cells outside the
//! slice, and every cell at the start of a ray (SR), read as the reset value.
//!
//! **Timing.** CFB output at T-1, shader register at T, gather and bilinear
//! T..T+2, compositor register at T+3, where the result is written to the
//! ring buffer and, on ER, goes out as a base-plane pixel. A tap needs
//! D > hops + 4, i.e. (n_y - 1) * b >= 9.

use crate::abc_gradient::AbcGradient;
use crate::bilinear::Bilinear;
use crate::cfb::{Cfb, CfbConfig};
use crate::compositor::Compositor;
use crate::shader::Shader;
use golden_model::plan::Sweep;
use golden_model::scene::Mode;
use rust_hdl::prelude::*;

/// Where one tap of the 2x2 neighbourhood comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Tap {
    /// Neighbour links the value crosses, each from lane j to lane j+1;
    /// with `left`, one link from lane k+1 to lane k instead.
    pub hops: u32,
    pub left: bool,
    /// Beat delay of the tap stream.
    pub delay: u32,
}

/// Everything the pipeline is built from.
#[derive(Debug, Clone)]
pub struct PipelineConfig {
    pub cfb: CfbConfig,
    pub p: u32,
    pub taps: [Tap; 4],
    /// The x neighbour is x-1 (dx >= 0) or x+1; likewise y.
    pub sx_pos: bool,
    pub sy_pos: bool,
    pub frac_bits: u32,
    pub rgba_bits: u32,
    pub order: golden_model::plan::Order,
    pub reset: [u32; 4],
    /// Shading needs the ABC gradient unit (and delays everything a slice).
    pub gradient: bool,
    /// Beats per slice and per beam.
    pub slice_beats: u32,
    pub beam_beats: u32,
}

impl PipelineConfig {
    pub fn new(
        sweep: &Sweep,
        vol_dims: [usize; 3],
        p: usize,
        shader: &golden_model::shader::Shader,
    ) -> Result<PipelineConfig, String> {
        let cfb = CfbConfig::from_sweep(sweep, vol_dims, p)?;
        let pu = p as u32;
        let b = cfb.dims[0].div_ceil(pu);
        let s = cfb.dims[1] * b;
        if (cfb.dims[1] - 1) * b < 9 {
            return Err(format!(
                "a slice of {} beams of {b} partial beams is too short for the compositing-buffer taps (need (n_y - 1) * b >= 9)",
                cfb.dims[1]
            ));
        }
        let sx_pos = cfb.dx >= 0;
        let sy_pos = cfb.dy >= 0;
        let tap = |m: i32, delay: u32| {
            let hops = m.rem_euclid(pu as i32) as u32;
            if m == -1 && pu > 2 {
                Tap {
                    hops: 1,
                    left: true,
                    delay,
                }
            } else {
                Tap {
                    hops,
                    left: false,
                    delay,
                }
            }
        };
        let bb = b;
        let taps = [
            tap(1, s),
            if sx_pos { tap(2, s) } else { tap(0, s - 1) },
            if sy_pos {
                tap(2, s + bb)
            } else {
                tap(0, s - bb)
            },
            match (sx_pos, sy_pos) {
                (true, true) => tap(3, s + bb),
                (true, false) => tap(1, s - bb),
                (false, true) => tap(1, s + bb - 1),
                (false, false) => tap(-1, s - bb - 1),
            },
        ];
        Ok(PipelineConfig {
            cfb,
            p: pu,
            taps,
            sx_pos,
            sy_pos,
            frac_bits: sweep.frac,
            rgba_bits: shader.rgba_bits,
            order: sweep.order,
            gradient: shader.needs_gradient,
            slice_beats: s,
            beam_beats: b,
            reset: golden_model::compositor::reset_value(shader.mode, shader.voxel_bits),
        })
    }

    /// Smallest ring-buffer address width that holds every tap's delay.
    pub fn history_bits(&self) -> usize {
        let need = self
            .taps
            .iter()
            .map(|t| t.delay + t.hops + 8)
            .max()
            .unwrap();
        (32 - need.leading_zeros()) as usize
    }
}

fn pack(v: [u32; 4]) -> u64 {
    v[0] as u64 | (v[1] as u64) << 16 | (v[2] as u64) << 32 | (v[3] as u64) << 48
}

/// One pipeline after the CFB.
#[derive(LogicBlock)]
pub struct PipeLane<const H: usize> {
    pub clock: Signal<In, Clock>,
    /// Free-running cycle counter shared by all lanes (ring-buffer time).
    pub now: Signal<In, Bits<H>>,
    /// The CFB lane's outputs.
    pub beat_valid: Signal<In, Bit>,
    pub value: Signal<In, Bits<16>>,
    pub x: Signal<In, Bits<16>>,
    pub y: Signal<In, Bits<16>>,
    pub pad: Signal<In, Bit>,
    pub sr: Signal<In, Bit>,
    pub er: Signal<In, Bit>,
    pub base_x: Signal<In, Bits<16>>,
    pub base_y: Signal<In, Bits<16>>,
    pub face: Signal<In, Bits<3>>,
    pub at_edge: Signal<In, Bit>,
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
    /// Ring-buffer reads (hop 0) and forwarding registers, to the neighbours.
    pub ram0: Signal<Out, Bits<64>>,
    pub ram1: Signal<Out, Bits<64>>,
    pub ram2: Signal<Out, Bits<64>>,
    pub ram3: Signal<Out, Bits<64>>,
    pub fwd0a: Signal<Out, Bits<64>>,
    pub fwd1a: Signal<Out, Bits<64>>,
    pub fwd1b: Signal<Out, Bits<64>>,
    pub fwd2a: Signal<Out, Bits<64>>,
    pub fwd2b: Signal<Out, Bits<64>>,
    pub fwd3a: Signal<Out, Bits<64>>,
    pub fwd3b: Signal<Out, Bits<64>>,
    /// From the neighbour: `in_c_s` feeds hop s+1 of tap c.
    pub in0a: Signal<In, Bits<64>>,
    pub in1a: Signal<In, Bits<64>>,
    pub in1b: Signal<In, Bits<64>>,
    pub in2a: Signal<In, Bits<64>>,
    pub in2b: Signal<In, Bits<64>>,
    pub in3a: Signal<In, Bits<64>>,
    pub in3b: Signal<In, Bits<64>>,
    pub in3c: Signal<In, Bits<64>>,
    /// From the right neighbour (lane k+1), for the leftward tap.
    pub in3l: Signal<In, Bits<64>>,
    /// The composited value of this lane's voxel (T+3): `res_beat` marks a
    /// beat, `res_valid` one that is not padding.
    pub res_beat: Signal<Out, Bit>,
    pub res_valid: Signal<Out, Bit>,
    pub res: Signal<Out, Bits<64>>,
    /// Base-plane pixel output on ER.
    pub px_valid: Signal<Out, Bit>,
    pub px_x: Signal<Out, Bits<16>>,
    pub px_y: Signal<Out, Bits<16>>,
    /// The face the pixel left through (`golden_model::plan::Face` as a number).
    pub px_face: Signal<Out, Bits<3>>,
    abc: AbcGradient<H>,
    use_gradient: Constant<Bit>,
    // The voxel and its control entering the shader: the CFB's, or the
    // gradient unit's a slice later.
    st_valid: Signal<Local, Bit>,
    st_value: Signal<Local, Bits<16>>,
    st_x: Signal<Local, Bits<16>>,
    st_y: Signal<Local, Bits<16>>,
    st_pad: Signal<Local, Bit>,
    st_sr: Signal<Local, Bit>,
    st_er: Signal<Local, Bit>,
    st_edge: Signal<Local, Bit>,
    st_face: Signal<Local, Bits<3>>,
    st_bx: Signal<Local, Bits<16>>,
    st_by: Signal<Local, Bits<16>>,
    shader: Shader,
    ring0: RAM<Bits<64>, H>,
    ring1: RAM<Bits<64>, H>,
    ring2: RAM<Bits<64>, H>,
    ring3: RAM<Bits<64>, H>,
    f0a: DFF<Bits<64>>,
    f1a: DFF<Bits<64>>,
    f1b: DFF<Bits<64>>,
    f2a: DFF<Bits<64>>,
    f2b: DFF<Bits<64>>,
    f3a: DFF<Bits<64>>,
    f3b: DFF<Bits<64>>,
    f3c: DFF<Bits<64>>,
    f3l: DFF<Bits<64>>,
    prev1: DFF<Bits<64>>,
    prev3: DFF<Bits<64>>,
    t0: Signal<Local, Bits<64>>,
    t1: Signal<Local, Bits<64>>,
    t2: Signal<Local, Bits<64>>,
    t3: Signal<Local, Bits<64>>,
    c00: Signal<Local, Bits<64>>,
    c10: Signal<Local, Bits<64>>,
    c01: Signal<Local, Bits<64>>,
    c11: Signal<Local, Bits<64>>,
    x_out: Signal<Local, Bit>,
    y_out: Signal<Local, Bit>,
    use_prev: Signal<Local, Bit>,
    bilinear: Bilinear,
    compositor: Compositor,
    // Control delayed from the CFB (T-1) to T, and on to T+3.
    v_q: [DFF<Bit>; 4],
    er_q: [DFF<Bit>; 4],
    pad_q: [DFF<Bit>; 4],
    bx_q: [DFF<Bits<16>>; 4],
    by_q: [DFF<Bits<16>>; 4],
    face_q: [DFF<Bits<3>>; 4],
    x_q: DFF<Bits<16>>,
    y_q: DFF<Bits<16>>,
    sr_q: DFF<Bit>,
    // The shader's sample delayed from T to T+2.
    s_r: [DFF<Bits<16>>; 2],
    s_g: [DFF<Bits<16>>; 2],
    s_b: [DFF<Bits<16>>; 2],
    s_a: [DFF<Bits<16>>; 2],
    s_v: [DFF<Bit>; 2],
    hops0: Constant<Bits<2>>,
    hops1: Constant<Bits<2>>,
    hops2: Constant<Bits<2>>,
    hops3: Constant<Bits<2>>,
    left3: Constant<Bit>,
    off0: Constant<Bits<H>>,
    off1: Constant<Bits<H>>,
    off2: Constant<Bits<H>>,
    off3: Constant<Bits<H>>,
    sx_pos: Constant<Bit>,
    sy_pos: Constant<Bit>,
    p_mask: Constant<Bits<16>>,
    nx_last: Constant<Bits<16>>,
    ny_last: Constant<Bits<16>>,
    reset: Constant<Bits<64>>,
    wx: Constant<Bits<16>>,
    wy: Constant<Bits<16>>,
}

impl<const H: usize> PipeLane<H> {
    fn new(c: &PipelineConfig, shader: Shader, mode: Mode) -> PipeLane<H> {
        let mask = (1u64 << H) - 1;
        // Read address = now + hops + 1 - delay (mod 2^H).
        let off = |t: &Tap| ((t.hops as u64 + 1).wrapping_sub(t.delay as u64)) & mask;
        PipeLane {
            clock: Default::default(),
            now: Default::default(),
            beat_valid: Default::default(),
            value: Default::default(),
            x: Default::default(),
            y: Default::default(),
            pad: Default::default(),
            sr: Default::default(),
            er: Default::default(),
            base_x: Default::default(),
            base_y: Default::default(),
            face: Default::default(),
            at_edge: Default::default(),
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
            ram0: Default::default(),
            ram1: Default::default(),
            ram2: Default::default(),
            ram3: Default::default(),
            fwd0a: Default::default(),
            fwd1a: Default::default(),
            fwd1b: Default::default(),
            fwd2a: Default::default(),
            fwd2b: Default::default(),
            fwd3a: Default::default(),
            fwd3b: Default::default(),
            in0a: Default::default(),
            in1a: Default::default(),
            in1b: Default::default(),
            in2a: Default::default(),
            in2b: Default::default(),
            in3a: Default::default(),
            in3b: Default::default(),
            in3c: Default::default(),
            in3l: Default::default(),
            res_beat: Default::default(),
            res_valid: Default::default(),
            res: Default::default(),
            px_valid: Default::default(),
            px_x: Default::default(),
            px_y: Default::default(),
            px_face: Default::default(),
            abc: AbcGradient::new(c.slice_beats, c.beam_beats, c.p),
            use_gradient: Constant::new(c.gradient),
            st_valid: Default::default(),
            st_value: Default::default(),
            st_x: Default::default(),
            st_y: Default::default(),
            st_pad: Default::default(),
            st_sr: Default::default(),
            st_er: Default::default(),
            st_edge: Default::default(),
            st_face: Default::default(),
            st_bx: Default::default(),
            st_by: Default::default(),
            shader,
            ring0: Default::default(),
            ring1: Default::default(),
            ring2: Default::default(),
            ring3: Default::default(),
            f0a: Default::default(),
            f1a: Default::default(),
            f1b: Default::default(),
            f2a: Default::default(),
            f2b: Default::default(),
            f3a: Default::default(),
            f3b: Default::default(),
            f3c: Default::default(),
            f3l: Default::default(),
            prev1: Default::default(),
            prev3: Default::default(),
            t0: Default::default(),
            t1: Default::default(),
            t2: Default::default(),
            t3: Default::default(),
            c00: Default::default(),
            c10: Default::default(),
            c01: Default::default(),
            c11: Default::default(),
            x_out: Default::default(),
            y_out: Default::default(),
            use_prev: Default::default(),
            bilinear: Bilinear::new(c.frac_bits),
            compositor: Compositor::new(mode, c.order, c.rgba_bits),
            v_q: Default::default(),
            er_q: Default::default(),
            pad_q: Default::default(),
            bx_q: Default::default(),
            by_q: Default::default(),
            face_q: Default::default(),
            x_q: Default::default(),
            y_q: Default::default(),
            sr_q: Default::default(),
            s_r: Default::default(),
            s_g: Default::default(),
            s_b: Default::default(),
            s_a: Default::default(),
            s_v: Default::default(),
            hops0: Constant::new((c.taps[0].hops as u64).to_bits()),
            hops1: Constant::new((c.taps[1].hops as u64).to_bits()),
            hops2: Constant::new((c.taps[2].hops as u64).to_bits()),
            hops3: Constant::new((c.taps[3].hops as u64).to_bits()),
            left3: Constant::new(c.taps[3].left),
            off0: Constant::new(off(&c.taps[0]).to_bits()),
            off1: Constant::new(off(&c.taps[1]).to_bits()),
            off2: Constant::new(off(&c.taps[2]).to_bits()),
            off3: Constant::new(off(&c.taps[3]).to_bits()),
            sx_pos: Constant::new(c.sx_pos),
            sy_pos: Constant::new(c.sy_pos),
            p_mask: Constant::new(((c.p - 1) as u64).to_bits()),
            nx_last: Constant::new(((c.cfb.dims[0] - 1) as u64).to_bits()),
            ny_last: Constant::new(((c.cfb.dims[1] - 1) as u64).to_bits()),
            reset: Constant::new(pack(c.reset).to_bits()),
            wx: Constant::new((c.cfb.dx.unsigned_abs() as u64).to_bits()),
            wy: Constant::new((c.cfb.dy.unsigned_abs() as u64).to_bits()),
        }
    }
}

impl<const H: usize> Logic for PipeLane<H> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, f0a, f1a, f1b, f2a, f2b, f3a, f3b, f3c, f3l, prev1, prev3, x_q, y_q, sr_q
        );
        for i in 0..4 {
            self.v_q[i].clock.next = self.clock.val();
            self.er_q[i].clock.next = self.clock.val();
            self.pad_q[i].clock.next = self.clock.val();
            self.bx_q[i].clock.next = self.clock.val();
            self.by_q[i].clock.next = self.clock.val();
            self.face_q[i].clock.next = self.clock.val();
        }
        for i in 0..2 {
            self.s_r[i].clock.next = self.clock.val();
            self.s_g[i].clock.next = self.clock.val();
            self.s_b[i].clock.next = self.clock.val();
            self.s_a[i].clock.next = self.clock.val();
            self.s_v[i].clock.next = self.clock.val();
        }
        self.shader.clock.next = self.clock.val();
        self.bilinear.clock.next = self.clock.val();
        self.compositor.clock.next = self.clock.val();
        self.ring0.read_clock.next = self.clock.val();
        self.ring0.write_clock.next = self.clock.val();
        self.ring1.read_clock.next = self.clock.val();
        self.ring1.write_clock.next = self.clock.val();
        self.ring2.read_clock.next = self.clock.val();
        self.ring2.write_clock.next = self.clock.val();
        self.ring3.read_clock.next = self.clock.val();
        self.ring3.write_clock.next = self.clock.val();
        // ABC gradient unit: fed by the CFB, linked to the neighbours.
        self.abc.clock.next = self.clock.val();
        self.abc.now.next = self.now.val();
        self.abc.valid.next = self.beat_valid.val();
        self.abc.value.next = self.value.val();
        self.abc.x.next = self.x.val();
        self.abc.y.next = self.y.val();
        self.abc.pad.next = self.pad.val();
        self.abc.sr.next = self.sr.val();
        self.abc.er.next = self.er.val();
        self.abc.at_edge.next = self.at_edge.val();
        self.abc.face.next = self.face.val();
        self.abc.base_x.next = self.base_x.val();
        self.abc.base_y.next = self.base_y.val();
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
        if self.use_gradient.val() {
            self.st_valid.next = self.abc.o_valid.val();
            self.st_value.next = self.abc.o_value.val();
            self.st_x.next = self.abc.o_x.val();
            self.st_y.next = self.abc.o_y.val();
            self.st_pad.next = self.abc.o_pad.val();
            self.st_sr.next = self.abc.o_sr.val();
            self.st_er.next = self.abc.o_er.val();
            self.st_edge.next = self.abc.o_edge.val();
            self.st_face.next = self.abc.o_face.val();
            self.st_bx.next = self.abc.o_base_x.val();
            self.st_by.next = self.abc.o_base_y.val();
        } else {
            self.st_valid.next = self.beat_valid.val();
            self.st_value.next = self.value.val();
            self.st_x.next = self.x.val();
            self.st_y.next = self.y.val();
            self.st_pad.next = self.pad.val();
            self.st_sr.next = self.sr.val();
            self.st_er.next = self.er.val();
            self.st_edge.next = self.at_edge.val();
            self.st_face.next = self.face.val();
            self.st_bx.next = self.base_x.val();
            self.st_by.next = self.base_y.val();
        }
        // Shader (input at T-1, registered sample at T).
        self.shader.value.next = self.st_value.val();
        self.shader.invalid.next = self.st_pad.val();
        self.shader.at_edge.next = self.st_edge.val();
        self.shader.gx_neg.next = self.abc.gx_neg.val();
        self.shader.gx_mag.next = self.abc.gx_mag.val();
        self.shader.gy_neg.next = self.abc.gy_neg.val();
        self.shader.gy_mag.next = self.abc.gy_mag.val();
        self.shader.gz_neg.next = self.abc.gz_neg.val();
        self.shader.gz_mag.next = self.abc.gz_mag.val();
        // Control pipeline.
        self.v_q[0].d.next = self.st_valid.val();
        self.er_q[0].d.next = self.st_er.val();
        self.pad_q[0].d.next = self.st_pad.val();
        self.bx_q[0].d.next = self.st_bx.val();
        self.by_q[0].d.next = self.st_by.val();
        self.face_q[0].d.next = self.st_face.val();
        for i in 1..4 {
            self.v_q[i].d.next = self.v_q[i - 1].q.val();
            self.er_q[i].d.next = self.er_q[i - 1].q.val();
            self.pad_q[i].d.next = self.pad_q[i - 1].q.val();
            self.bx_q[i].d.next = self.bx_q[i - 1].q.val();
            self.by_q[i].d.next = self.by_q[i - 1].q.val();
            self.face_q[i].d.next = self.face_q[i - 1].q.val();
        }
        self.x_q.d.next = self.st_x.val();
        self.y_q.d.next = self.st_y.val();
        self.sr_q.d.next = self.st_sr.val();
        // Ring-buffer reads and the forwarding registers.
        self.ring0.read_address.next = self.now.val() + self.off0.val();
        self.ring1.read_address.next = self.now.val() + self.off1.val();
        self.ring2.read_address.next = self.now.val() + self.off2.val();
        self.ring3.read_address.next = self.now.val() + self.off3.val();
        self.ram0.next = self.ring0.read_data.val();
        self.ram1.next = self.ring1.read_data.val();
        self.ram2.next = self.ring2.read_data.val();
        self.ram3.next = self.ring3.read_data.val();
        self.f0a.d.next = self.in0a.val();
        self.f1a.d.next = self.in1a.val();
        self.f1b.d.next = self.in1b.val();
        self.f2a.d.next = self.in2a.val();
        self.f2b.d.next = self.in2b.val();
        self.f3a.d.next = self.in3a.val();
        self.f3b.d.next = self.in3b.val();
        self.f3c.d.next = self.in3c.val();
        self.f3l.d.next = self.in3l.val();
        self.fwd0a.next = self.f0a.q.val();
        self.fwd1a.next = self.f1a.q.val();
        self.fwd1b.next = self.f1b.q.val();
        self.fwd2a.next = self.f2a.q.val();
        self.fwd2b.next = self.f2b.q.val();
        self.fwd3a.next = self.f3a.q.val();
        self.fwd3b.next = self.f3b.q.val();
        // The tap streams at this lane, after their hops.
        self.t0.next = self.ring0.read_data.val();
        if self.hops0.val() == 1 {
            self.t0.next = self.f0a.q.val();
        }
        self.t1.next = self.ring1.read_data.val();
        if self.hops1.val() == 1 {
            self.t1.next = self.f1a.q.val();
        }
        if self.hops1.val() == 2 {
            self.t1.next = self.f1b.q.val();
        }
        self.t2.next = self.ring2.read_data.val();
        if self.hops2.val() == 1 {
            self.t2.next = self.f2a.q.val();
        }
        if self.hops2.val() == 2 {
            self.t2.next = self.f2b.q.val();
        }
        self.t3.next = self.ring3.read_data.val();
        if self.hops3.val() == 1 {
            self.t3.next = self.f3a.q.val();
        }
        if self.hops3.val() == 2 {
            self.t3.next = self.f3b.q.val();
        }
        if self.hops3.val() == 3 {
            self.t3.next = self.f3c.q.val();
        }
        if self.left3.val() {
            self.t3.next = self.f3l.q.val();
        }
        self.prev1.d.next = self.t1.val();
        self.prev3.d.next = self.t3.val();
        // Partial-beam boundaries: x-1 of a beam's first lane lies one beat
        // further back, x+1 of its last lane one beat nearer.
        if self.sx_pos.val() {
            self.use_prev.next = (self.x_q.q.val() & self.p_mask.val()) == 0;
        } else {
            self.use_prev.next = (self.x_q.q.val() & self.p_mask.val()) != self.p_mask.val();
        }
        self.c00.next = self.t0.val();
        self.c10.next = self.t1.val();
        self.c11.next = self.t3.val();
        if self.use_prev.val() {
            self.c10.next = self.prev1.q.val();
            self.c11.next = self.prev3.q.val();
        }
        self.c01.next = self.t2.val();
        // Cells outside the slice, and the start of a ray, read as reset.
        if self.sx_pos.val() {
            self.x_out.next = self.x_q.q.val() == 0;
        } else {
            self.x_out.next = self.x_q.q.val() == self.nx_last.val();
        }
        if self.sy_pos.val() {
            self.y_out.next = self.y_q.q.val() == 0;
        } else {
            self.y_out.next = self.y_q.q.val() == self.ny_last.val();
        }
        if self.x_out.val() {
            self.c10.next = self.reset.val();
            self.c11.next = self.reset.val();
        }
        if self.y_out.val() {
            self.c01.next = self.reset.val();
            self.c11.next = self.reset.val();
        }
        if self.sr_q.q.val() {
            self.c00.next = self.reset.val();
            self.c10.next = self.reset.val();
            self.c01.next = self.reset.val();
            self.c11.next = self.reset.val();
        }
        // Bilinear unit (T..T+2).
        self.bilinear.c00[0].next = bit_cast::<16, 64>(self.c00.val());
        self.bilinear.c00[1].next = bit_cast::<16, 64>(self.c00.val() >> 16);
        self.bilinear.c00[2].next = bit_cast::<16, 64>(self.c00.val() >> 32);
        self.bilinear.c00[3].next = bit_cast::<16, 64>(self.c00.val() >> 48);
        self.bilinear.c10[0].next = bit_cast::<16, 64>(self.c10.val());
        self.bilinear.c10[1].next = bit_cast::<16, 64>(self.c10.val() >> 16);
        self.bilinear.c10[2].next = bit_cast::<16, 64>(self.c10.val() >> 32);
        self.bilinear.c10[3].next = bit_cast::<16, 64>(self.c10.val() >> 48);
        self.bilinear.c01[0].next = bit_cast::<16, 64>(self.c01.val());
        self.bilinear.c01[1].next = bit_cast::<16, 64>(self.c01.val() >> 16);
        self.bilinear.c01[2].next = bit_cast::<16, 64>(self.c01.val() >> 32);
        self.bilinear.c01[3].next = bit_cast::<16, 64>(self.c01.val() >> 48);
        self.bilinear.c11[0].next = bit_cast::<16, 64>(self.c11.val());
        self.bilinear.c11[1].next = bit_cast::<16, 64>(self.c11.val() >> 16);
        self.bilinear.c11[2].next = bit_cast::<16, 64>(self.c11.val() >> 32);
        self.bilinear.c11[3].next = bit_cast::<16, 64>(self.c11.val() >> 48);
        self.bilinear.wx.next = self.wx.val();
        self.bilinear.wy.next = self.wy.val();
        // The sample waits for the bilinear unit (T -> T+2).
        self.s_r[0].d.next = self.shader.r.val();
        self.s_g[0].d.next = self.shader.g.val();
        self.s_b[0].d.next = self.shader.b.val();
        self.s_a[0].d.next = self.shader.a.val();
        self.s_v[0].d.next = self.shader.valid.val();
        self.s_r[1].d.next = self.s_r[0].q.val();
        self.s_g[1].d.next = self.s_g[0].q.val();
        self.s_b[1].d.next = self.s_b[0].q.val();
        self.s_a[1].d.next = self.s_a[0].q.val();
        self.s_v[1].d.next = self.s_v[0].q.val();
        // Compositing unit (T+2 -> T+3).
        self.compositor.acc_r.next = bit_cast::<32, 16>(self.bilinear.out[0].val());
        self.compositor.acc_g.next = self.bilinear.out[1].val();
        self.compositor.acc_b.next = self.bilinear.out[2].val();
        self.compositor.acc_a.next = self.bilinear.out[3].val();
        self.compositor.new_r.next = bit_cast::<32, 16>(self.s_r[1].q.val());
        self.compositor.new_g.next = self.s_g[1].q.val();
        self.compositor.new_b.next = self.s_b[1].q.val();
        self.compositor.new_a.next = self.s_a[1].q.val();
        self.compositor.new_valid.next = self.s_v[1].q.val();
        self.res.next = bit_cast::<64, 32>(self.compositor.out_r.val())
            | (bit_cast::<64, 16>(self.compositor.out_g.val()) << 16)
            | (bit_cast::<64, 16>(self.compositor.out_b.val()) << 32)
            | (bit_cast::<64, 16>(self.compositor.out_a.val()) << 48);
        self.res_beat.next = self.v_q[3].q.val();
        self.res_valid.next = self.v_q[3].q.val() & !self.pad_q[3].q.val();
        // Write the result into the ring buffer at its beat's time.
        self.ring0.write_address.next = self.now.val() - 3;
        self.ring1.write_address.next = self.now.val() - 3;
        self.ring2.write_address.next = self.now.val() - 3;
        self.ring3.write_address.next = self.now.val() - 3;
        self.ring0.write_data.next = self.res.val();
        self.ring1.write_data.next = self.res.val();
        self.ring2.write_data.next = self.res.val();
        self.ring3.write_data.next = self.res.val();
        self.ring0.write_enable.next = self.v_q[3].q.val();
        self.ring1.write_enable.next = self.v_q[3].q.val();
        self.ring2.write_enable.next = self.v_q[3].q.val();
        self.ring3.write_enable.next = self.v_q[3].q.val();
        // Pixel out on ER.
        self.px_valid.next = self.v_q[3].q.val() & self.er_q[3].q.val() & !self.pad_q[3].q.val();
        self.px_x.next = self.bx_q[3].q.val();
        self.px_y.next = self.by_q[3].q.val();
        self.px_face.next = self.face_q[3].q.val();
    }
}

/// The whole Cube-4L pipeline: CFB and `P` pipelines (`A`-bit memory
/// modules, `H`-bit compositing-buffer ring buffers).
#[derive(LogicBlock)]
pub struct Pipeline<const P: usize, const A: usize, const H: usize> {
    pub clock: Signal<In, Clock>,
    /// Start a sweep; the CFB's load port fills the voxel memory.
    pub start: Signal<In, Bit>,
    pub load_enable: Signal<In, Bit>,
    pub load_module: Signal<In, Bits<8>>,
    pub load_address: Signal<In, Bits<A>>,
    pub load_data: Signal<In, Bits<16>>,
    pub cfb: Cfb<P, A>,
    pub lanes: [PipeLane<H>; P],
    now: DFF<Bits<H>>,
}

impl<const P: usize, const A: usize, const H: usize> Pipeline<P, A, H> {
    /// Build the pipeline for one sweep; `golden` is the golden model's
    /// shader of that sweep, whose LUTs the hardware copies.
    pub fn new(
        config: &PipelineConfig,
        golden: &golden_model::shader::Shader,
    ) -> Result<Pipeline<P, A, H>, String> {
        if config.p as usize != P {
            return Err(format!(
                "configuration for {} pipelines, built with {P}",
                config.p
            ));
        }
        if config.history_bits() > H {
            return Err(format!(
                "the taps need {}-bit ring buffers, built with {H}",
                config.history_bits()
            ));
        }
        let mut lanes = Vec::with_capacity(P);
        for _ in 0..P {
            lanes.push(PipeLane::new(config, Shader::new(golden)?, golden.mode));
        }
        Ok(Pipeline {
            clock: Default::default(),
            start: Default::default(),
            load_enable: Default::default(),
            load_module: Default::default(),
            load_address: Default::default(),
            load_data: Default::default(),
            cfb: Cfb::new(&config.cfb),
            lanes: lanes.try_into().unwrap_or_else(|_| unreachable!()),
            now: Default::default(),
        })
    }
}

impl<const P: usize, const A: usize, const H: usize> Logic for Pipeline<P, A, H> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, now);
        self.now.d.next = self.now.q.val() + 1;
        self.cfb.clock.next = self.clock.val();
        self.cfb.start.next = self.start.val();
        self.cfb.load_enable.next = self.load_enable.val();
        self.cfb.load_module.next = self.load_module.val();
        self.cfb.load_address.next = self.load_address.val();
        self.cfb.load_data.next = self.load_data.val();
        for k in 0..P {
            self.lanes[k].clock.next = self.clock.val();
            self.lanes[k].now.next = self.now.q.val();
            self.lanes[k].beat_valid.next = self.cfb.valid.val();
            self.lanes[k].value.next = self.cfb.value[k].val();
            self.lanes[k].x.next = self.cfb.x[k].val();
            self.lanes[k].y.next = self.cfb.y[k].val();
            self.lanes[k].pad.next = self.cfb.pad[k].val();
            self.lanes[k].sr.next = self.cfb.sr[k].val();
            self.lanes[k].er.next = self.cfb.er[k].val();
            self.lanes[k].base_x.next = self.cfb.base_x[k].val();
            self.lanes[k].base_y.next = self.cfb.base_y[k].val();
            self.lanes[k].face.next = self.cfb.face[k].val();
            self.lanes[k].at_edge.next = self.cfb.at_edge[k].val();
        }
        // Nearest-neighbour links: lane k-1 feeds lane k (lane P-1 feeds 0).
        for k in 1..P {
            self.lanes[k].in0a.next = self.lanes[k - 1].ram0.val();
            self.lanes[k].in1a.next = self.lanes[k - 1].ram1.val();
            self.lanes[k].in1b.next = self.lanes[k - 1].fwd1a.val();
            self.lanes[k].in2a.next = self.lanes[k - 1].ram2.val();
            self.lanes[k].in2b.next = self.lanes[k - 1].fwd2a.val();
            self.lanes[k].in3a.next = self.lanes[k - 1].ram3.val();
            self.lanes[k].in3b.next = self.lanes[k - 1].fwd3a.val();
            self.lanes[k].in3c.next = self.lanes[k - 1].fwd3b.val();
        }
        for k in (P - 1)..P {
            self.lanes[0].in0a.next = self.lanes[k].ram0.val();
            self.lanes[0].in1a.next = self.lanes[k].ram1.val();
            self.lanes[0].in1b.next = self.lanes[k].fwd1a.val();
            self.lanes[0].in2a.next = self.lanes[k].ram2.val();
            self.lanes[0].in2b.next = self.lanes[k].fwd2a.val();
            self.lanes[0].in3a.next = self.lanes[k].ram3.val();
            self.lanes[0].in3b.next = self.lanes[k].fwd3a.val();
            self.lanes[0].in3c.next = self.lanes[k].fwd3b.val();
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
        // The leftward link: lane k+1 feeds lane k (lane 0 feeds P-1).
        for k in 0..(P - 1) {
            self.lanes[k].in3l.next = self.lanes[k + 1].ram3.val();
        }
        for k in (P - 1)..P {
            self.lanes[k].in3l.next = self.lanes[0].ram3.val();
        }
    }
}
