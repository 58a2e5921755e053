//! The Cube-4L rendering pipelines (§3, Figs. 4, 6, 18-21): the CFB feeds
//! `P` pipelines, each with the ABC gradient unit (when the scene shades), a
//! shader, a compositing-buffer history, the bilinear unit and the
//! compositing unit. Pipelines talk only to their nearest neighbours.
//!
//! **Compositing buffer and neighbourhood.** Let R(t, j) be the value lane j
//! composited at beat t, S = n_y*b the beats of a slice and B = b those of a
//! beam. By the skew, cell (x + e_x, y + e_y) of the previous slice, for
//! voxel (x, y, z) of lane k at beat t, was composited by lane
//! k - 1 + e_x + e_y at beat t - S + e_y*B, one beat earlier or later when
//! e_x crosses a partial-beam end (x mod P = 0 with e_x = -1, x mod P = P-1
//! with e_x = +1). Each lane keeps its results in a ring buffer of block RAM
//! (one copy per tap, one read port each). The nine taps of the 3x3 region
//! hop to the consuming lane through one register per neighbour link
//! (m = 1 - e_x - e_y links; tap (+1, +1) takes one leftward link), and each
//! tap keeps its previous value for the partial-beam case (the extension
//! units of Figs. 14-15). The signs of the voxel's dx and dy then narrow the
//! 3x3 region to 2x2 (Figs. 19-21). Cells outside the slice, and every cell at
//! the start of a ray (SR), read as the reset value.
//!
//! **Timing.** Shader input at T-1 (the CFB's output, or the gradient unit's a
//! slice later), shader register at T, gather and bilinear T..T+2, compositor
//! register at T+3, where the result is written to the ring buffer and, on
//! ER, goes out as a base-plane pixel. A tap needs delay > hops + 4, i.e.
//! (n_y - 1) * b >= 9.
//!
//! Units a scene does not need are built disabled, with empty tables and
//! 2-word rings, and drive zero; `export::prune` removes them from the
//! emitted Verilog (see `export::left_out`). The compositing-buffer rings are
//! as deep as the longest tap delay and store only the bits the mode can set
//! (`PipelineConfig::ring_fields`); for parallel views the five taps outside
//! the 2x2 that the constant signs select get 2-word rings
//! (`PipelineConfig::taps_used`).

use crate::abc_gradient::AbcGradient;
use crate::bilinear::Bilinear;
use crate::cfb::{Cfb, CfbConfig};
use crate::compositor::Compositor;
use crate::ram::DepthRam;
use crate::shader::Shader;
use golden_model::cube4l::plan::Sweep;
use rust_hdl::prelude::*;
use scene::Mode;

/// The taps' `(e_x, e_y)` offsets, in the order of the lane's `t0..t8`.
pub const TAPS: [(i32, i32); 9] = [
    (0, 0),
    (-1, 0),
    (1, 0),
    (0, -1),
    (0, 1),
    (-1, -1),
    (1, -1),
    (-1, 1),
    (1, 1),
];

/// Where one tap of the 3x3 neighbourhood comes from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Tap {
    /// Neighbour links the value crosses, each from lane j to lane j+1;
    /// with `left`, one link from lane k+1 to lane k instead.
    pub hops: u32,
    pub left: bool,
    /// Beat delay of the tap stream (its previous value is one beat older).
    pub delay: u32,
}

/// Everything the pipeline is built from.
#[derive(Debug, Clone)]
pub struct PipelineConfig {
    pub cfb: CfbConfig,
    pub p: u32,
    pub taps: [Tap; 9],
    pub frac_bits: u32,
    pub rgba_bits: u32,
    pub order: golden_model::cube4l::plan::Order,
    pub reset: [u32; 4],
    /// Shading needs the ABC gradient unit (and delays everything a slice).
    pub gradient: bool,
    /// Beats per slice and per beam.
    pub slice_beats: u32,
    pub beam_beats: u32,
    pub voxel_bits: u32,
    /// Bit fields `(lowest bit, width)` of a composited word that can be
    /// non-zero, which the compositing-buffer rings store: four `rgba_bits`
    /// channels in 16-bit slots; the intensity for MIP/MinIP; the 32-bit sum
    /// for X-ray.
    pub ring_fields: Vec<(usize, usize)>,
    /// The taps (in `TAPS` order) that the 2x2 selection can pick: all for
    /// perspective views; for parallel views the four that the constant
    /// signs of dx and dy select, fewer when dx or dy is 0. The others get
    /// 2-word rings.
    pub taps_used: [bool; 9],
}

impl PipelineConfig {
    pub fn new(
        sweep: &Sweep,
        vol_dims: [usize; 3],
        p: usize,
        shader: &golden_model::cube4l::shader::Shader,
    ) -> Result<PipelineConfig, String> {
        let mut cfb = CfbConfig::from_sweep(sweep, vol_dims, p)?;
        cfb.voxel_bits = shader.voxel_bits;
        let cfb = if shader.needs_gradient {
            cfb.with_halo()
        } else {
            cfb
        };
        let pu = p as u32;
        let b = cfb.dims[0].div_ceil(pu);
        let s = cfb.dims[1] * b;
        if (cfb.dims[1] - 1) * b < 9 {
            return Err(format!(
                "a slice of {} beams of {b} partial beams is too short for the compositing-buffer taps (need (n_y - 1) * b >= 9)",
                cfb.dims[1]
            ));
        }
        let taps = TAPS.map(|(ex, ey)| {
            let m = 1 - ex - ey;
            let delay = (s as i32 - ey * b as i32 - (ex == 1) as i32) as u32;
            if m == -1 && pu > 2 {
                Tap {
                    hops: 1,
                    left: true,
                    delay,
                }
            } else {
                Tap {
                    hops: m.rem_euclid(pu as i32) as u32,
                    left: false,
                    delay,
                }
            }
        });
        Ok(PipelineConfig {
            cfb,
            p: pu,
            taps,
            frac_bits: sweep.frac,
            rgba_bits: shader.rgba_bits,
            order: sweep.order,
            gradient: shader.needs_gradient,
            slice_beats: s,
            beam_beats: b,
            voxel_bits: shader.voxel_bits,
            taps_used: match sweep.rays {
                golden_model::cube4l::plan::Rays::Parallel { dx, dy } => {
                    // Tap (e_x, e_y) serves x - sign(dx), y - sign(dy).
                    let (sx, sy) = (-dx.signum(), -dy.signum());
                    TAPS.map(|(ex, ey)| (ex == 0 || ex == sx) && (ey == 0 || ey == sy))
                }
                golden_model::cube4l::plan::Rays::Perspective { .. } => [true; 9],
            },
            ring_fields: match shader.mode {
                Mode::Mip | Mode::Minip => vec![(0, shader.voxel_bits as usize)],
                Mode::Xray => vec![(0, 32)],
                Mode::Composite | Mode::FirstOpaque => (0..4)
                    .map(|c| (16 * c, shader.rgba_bits as usize))
                    .collect(),
            },
            reset: golden_model::cube4l::compositor::reset_value(shader.mode, shader.voxel_bits),
        })
    }

    /// Address bits of the compositing-buffer tap rings: they hold every
    /// tap's delay, with a margin of 8.
    pub fn tap_bits(&self) -> usize {
        let need = self
            .taps
            .iter()
            .map(|t| t.delay + t.hops + 8)
            .max()
            .unwrap();
        crate::cfb::bits_for(need as u64 + 1) as usize
    }

    /// Smallest ring-buffer address width (`H`) that the build needs: the
    /// tap rings', and the gradient unit's when the scene has one.
    pub fn history_bits(&self) -> usize {
        let abc = if self.gradient {
            AbcGradient::<32>::ring_bits(self.slice_beats, self.beam_beats)
        } else {
            0
        };
        self.tap_bits().max(abc)
    }
}

/// Tap `tap`'s compositing-buffer ring: as deep as the taps' delays (2 words
/// when the tap is never selected), as wide as the composited values can be.
fn tap_ring<const H: usize>(c: &PipelineConfig, tap: usize) -> DepthRam<Bits<64>, H> {
    let mask = c
        .ring_fields
        .iter()
        .fold(0u64, |m, &(lo, w)| m | (((1u128 << w) - 1) as u64) << lo);
    let bits = if c.taps_used[tap] {
        c.tap_bits().min(H)
    } else {
        1
    };
    DepthRam::new(bits).fields(&c.ring_fields, mask.to_bits())
}

fn pack(v: [u32; 4]) -> u64 {
    v[0] as u64 | (v[1] as u64) << 16 | (v[2] as u64) << 32 | (v[3] as u64) << 48
}

/// A lane's packed result word as `[r, g, b, a]`: four 16-bit channels, or
/// for X-ray a 32-bit sum in channel 0.
pub fn unpack(mode: Mode, word: u64) -> [u32; 4] {
    if mode == Mode::Xray {
        [word as u32, 0, 0, 0]
    } else {
        std::array::from_fn(|c| ((word >> (16 * c)) & 0xffff) as u32)
    }
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
    /// Compositing-buffer taps: `tC s0` is tap C's ring-buffer read, `tC sJ`
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
    /// The composited value of this lane's voxel (T+3): `res_beat` marks a
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
    abc: AbcGradient<H>,
    use_gradient: Constant<Bit>,
    // The voxel and its control entering the shader: the CFB's, or the
    // gradient unit's a slice later.
    st_valid: Signal<Local, Bit>,
    st_value: Signal<Local, Bits<16>>,
    st_x: Signal<Local, Bits<16>>,
    st_y: Signal<Local, Bits<16>>,
    st_pad: Signal<Local, Bit>,
    st_invalid: Signal<Local, Bit>,
    st_sr: Signal<Local, Bit>,
    st_er: Signal<Local, Bit>,
    st_edge: Signal<Local, Bit>,
    st_face: Signal<Local, Bits<3>>,
    st_bx: Signal<Local, Bits<16>>,
    st_by: Signal<Local, Bits<16>>,
    st_dxn: Signal<Local, Bit>,
    st_dxm: Signal<Local, Bits<16>>,
    st_dyn: Signal<Local, Bit>,
    st_dym: Signal<Local, Bits<16>>,
    shader: Shader,
    ring0: DepthRam<Bits<64>, H>,
    f0_1: DFF<Bits<64>>,
    s0: Signal<Local, Bits<64>>,
    a0: Signal<Local, Bits<64>>,
    prev0: DFF<Bits<64>>,
    hops0: Constant<Bits<2>>,
    off0: Constant<Bits<H>>,
    ring1: DepthRam<Bits<64>, H>,
    f1_1: DFF<Bits<64>>,
    f1_2: DFF<Bits<64>>,
    s1: Signal<Local, Bits<64>>,
    a1: Signal<Local, Bits<64>>,
    prev1: DFF<Bits<64>>,
    hops1: Constant<Bits<2>>,
    off1: Constant<Bits<H>>,
    ring2: DepthRam<Bits<64>, H>,
    s2: Signal<Local, Bits<64>>,
    a2: Signal<Local, Bits<64>>,
    prev2: DFF<Bits<64>>,
    off2: Constant<Bits<H>>,
    ring3: DepthRam<Bits<64>, H>,
    f3_1: DFF<Bits<64>>,
    f3_2: DFF<Bits<64>>,
    s3: Signal<Local, Bits<64>>,
    a3: Signal<Local, Bits<64>>,
    prev3: DFF<Bits<64>>,
    hops3: Constant<Bits<2>>,
    off3: Constant<Bits<H>>,
    ring4: DepthRam<Bits<64>, H>,
    s4: Signal<Local, Bits<64>>,
    a4: Signal<Local, Bits<64>>,
    prev4: DFF<Bits<64>>,
    off4: Constant<Bits<H>>,
    ring5: DepthRam<Bits<64>, H>,
    f5_1: DFF<Bits<64>>,
    f5_2: DFF<Bits<64>>,
    f5_3: DFF<Bits<64>>,
    s5: Signal<Local, Bits<64>>,
    a5: Signal<Local, Bits<64>>,
    prev5: DFF<Bits<64>>,
    hops5: Constant<Bits<2>>,
    off5: Constant<Bits<H>>,
    ring6: DepthRam<Bits<64>, H>,
    f6_1: DFF<Bits<64>>,
    s6: Signal<Local, Bits<64>>,
    a6: Signal<Local, Bits<64>>,
    prev6: DFF<Bits<64>>,
    hops6: Constant<Bits<2>>,
    off6: Constant<Bits<H>>,
    ring7: DepthRam<Bits<64>, H>,
    f7_1: DFF<Bits<64>>,
    s7: Signal<Local, Bits<64>>,
    a7: Signal<Local, Bits<64>>,
    prev7: DFF<Bits<64>>,
    hops7: Constant<Bits<2>>,
    off7: Constant<Bits<H>>,
    ring8: DepthRam<Bits<64>, H>,
    f8_1: DFF<Bits<64>>,
    s8: Signal<Local, Bits<64>>,
    a8: Signal<Local, Bits<64>>,
    prev8: DFF<Bits<64>>,
    hops8: Constant<Bits<2>>,
    off8: Constant<Bits<H>>,
    f8l: DFF<Bits<64>>,
    left8: Constant<Bit>,
    first: Signal<Local, Bit>,
    last: Signal<Local, Bit>,
    c00: Signal<Local, Bits<64>>,
    c10: Signal<Local, Bits<64>>,
    c01: Signal<Local, Bits<64>>,
    c11: Signal<Local, Bits<64>>,
    x_out: Signal<Local, Bit>,
    y_out: Signal<Local, Bit>,
    bilinear: Bilinear,
    compositor: Compositor,
    // Control delayed from the shader input (T-1) to T, and on to T+3.
    v_q: [DFF<Bit>; 4],
    er_q: [DFF<Bit>; 4],
    pad_q: [DFF<Bit>; 4],
    bx_q: [DFF<Bits<16>>; 4],
    by_q: [DFF<Bits<16>>; 4],
    face_q: [DFF<Bits<3>>; 4],
    x_q: DFF<Bits<16>>,
    y_q: DFF<Bits<16>>,
    sr_q: DFF<Bit>,
    dxn_q: DFF<Bit>,
    dxm_q: DFF<Bits<16>>,
    dyn_q: DFF<Bit>,
    dym_q: DFF<Bits<16>>,
    // The shader's sample delayed from T to T+2.
    s_r: [DFF<Bits<16>>; 2],
    s_g: [DFF<Bits<16>>; 2],
    s_b: [DFF<Bits<16>>; 2],
    s_a: [DFF<Bits<16>>; 2],
    s_v: [DFF<Bit>; 2],
    p_mask: Constant<Bits<16>>,
    nx_last: Constant<Bits<16>>,
    ny_last: Constant<Bits<16>>,
    reset: Constant<Bits<64>>,
    /// Channel masks of the packed word: X-ray keeps a 32-bit sum in channel
    /// 0 and nothing else.
    r_mask: Constant<Bits<64>>,
    gba_mask: Constant<Bits<64>>,
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
            res_beat: Default::default(),
            res_valid: Default::default(),
            res: Default::default(),
            px_valid: Default::default(),
            px_x: Default::default(),
            px_y: Default::default(),
            px_face: Default::default(),
            abc: AbcGradient::new(c.slice_beats, c.beam_beats, c.p, c.voxel_bits, c.gradient),
            use_gradient: Constant::new(c.gradient),
            st_valid: Default::default(),
            st_value: Default::default(),
            st_x: Default::default(),
            st_y: Default::default(),
            st_pad: Default::default(),
            st_invalid: Default::default(),
            st_sr: Default::default(),
            st_er: Default::default(),
            st_edge: Default::default(),
            st_face: Default::default(),
            st_bx: Default::default(),
            st_by: Default::default(),
            st_dxn: Default::default(),
            st_dxm: Default::default(),
            st_dyn: Default::default(),
            st_dym: Default::default(),
            shader,
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
            ring0: tap_ring(c, 0),
            f0_1: Default::default(),
            s0: Default::default(),
            a0: Default::default(),
            prev0: Default::default(),
            hops0: Constant::new((c.taps[0].hops as u64).to_bits()),
            off0: Constant::new(off(&c.taps[0]).to_bits()),
            ring1: tap_ring(c, 1),
            f1_1: Default::default(),
            f1_2: Default::default(),
            s1: Default::default(),
            a1: Default::default(),
            prev1: Default::default(),
            hops1: Constant::new((c.taps[1].hops as u64).to_bits()),
            off1: Constant::new(off(&c.taps[1]).to_bits()),
            ring2: tap_ring(c, 2),
            s2: Default::default(),
            a2: Default::default(),
            prev2: Default::default(),
            off2: Constant::new(off(&c.taps[2]).to_bits()),
            ring3: tap_ring(c, 3),
            f3_1: Default::default(),
            f3_2: Default::default(),
            s3: Default::default(),
            a3: Default::default(),
            prev3: Default::default(),
            hops3: Constant::new((c.taps[3].hops as u64).to_bits()),
            off3: Constant::new(off(&c.taps[3]).to_bits()),
            ring4: tap_ring(c, 4),
            s4: Default::default(),
            a4: Default::default(),
            prev4: Default::default(),
            off4: Constant::new(off(&c.taps[4]).to_bits()),
            ring5: tap_ring(c, 5),
            f5_1: Default::default(),
            f5_2: Default::default(),
            f5_3: Default::default(),
            s5: Default::default(),
            a5: Default::default(),
            prev5: Default::default(),
            hops5: Constant::new((c.taps[5].hops as u64).to_bits()),
            off5: Constant::new(off(&c.taps[5]).to_bits()),
            ring6: tap_ring(c, 6),
            f6_1: Default::default(),
            s6: Default::default(),
            a6: Default::default(),
            prev6: Default::default(),
            hops6: Constant::new((c.taps[6].hops as u64).to_bits()),
            off6: Constant::new(off(&c.taps[6]).to_bits()),
            ring7: tap_ring(c, 7),
            f7_1: Default::default(),
            s7: Default::default(),
            a7: Default::default(),
            prev7: Default::default(),
            hops7: Constant::new((c.taps[7].hops as u64).to_bits()),
            off7: Constant::new(off(&c.taps[7]).to_bits()),
            ring8: tap_ring(c, 8),
            f8_1: Default::default(),
            s8: Default::default(),
            a8: Default::default(),
            prev8: Default::default(),
            hops8: Constant::new((c.taps[8].hops as u64).to_bits()),
            off8: Constant::new(off(&c.taps[8]).to_bits()),
            f8l: Default::default(),
            left8: Constant::new(c.taps[8].left),
            first: Default::default(),
            last: Default::default(),
            c00: Default::default(),
            c10: Default::default(),
            c01: Default::default(),
            c11: Default::default(),
            x_out: Default::default(),
            y_out: Default::default(),
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
            dxn_q: Default::default(),
            dxm_q: Default::default(),
            dyn_q: Default::default(),
            dym_q: Default::default(),
            s_r: Default::default(),
            s_g: Default::default(),
            s_b: Default::default(),
            s_a: Default::default(),
            s_v: Default::default(),
            p_mask: Constant::new(((c.p - 1) as u64).to_bits()),
            nx_last: Constant::new(((c.cfb.dims[0] - 1) as u64).to_bits()),
            ny_last: Constant::new(((c.cfb.dims[1] - 1) as u64).to_bits()),
            reset: Constant::new(pack(c.reset).to_bits()),
            r_mask: Constant::new(
                (if mode == Mode::Xray {
                    0xffff_ffffu64
                } else {
                    0xffff
                })
                .to_bits(),
            ),
            gba_mask: Constant::new((if mode == Mode::Xray { 0u64 } else { 0xffff }).to_bits()),
        }
    }
}

impl<const H: usize> Logic for PipeLane<H> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, x_q, y_q, sr_q, dxn_q, dxm_q, dyn_q, dym_q, f0_1, prev0, f1_1, f1_2,
            prev1, prev2, f3_1, f3_2, prev3, prev4, f5_1, f5_2, f5_3, prev5, f6_1, prev6, f7_1,
            prev7, f8_1, prev8, f8l
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
        // ABC gradient unit: fed by the CFB, linked to the neighbours.
        self.abc.clock.next = self.clock.val();
        self.abc.now.next = self.now.val();
        self.abc.valid.next = self.beat_valid.val() & !self.halo.val();
        self.abc.value.next = self.value.val();
        self.abc.x.next = self.x.val();
        self.abc.y.next = self.y.val();
        self.abc.pad.next = self.pad.val();
        self.abc.invalid.next = self.invalid.val();
        self.abc.sr.next = self.sr.val();
        self.abc.er.next = self.er.val();
        self.abc.at_edge.next = self.at_edge.val();
        self.abc.face.next = self.face.val();
        self.abc.base_x.next = self.base_x.val();
        self.abc.base_y.next = self.base_y.val();
        self.abc.dx_neg.next = self.dx_neg.val();
        self.abc.dx_mag.next = self.dx_mag.val();
        self.abc.dy_neg.next = self.dy_neg.val();
        self.abc.dy_mag.next = self.dy_mag.val();
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
            self.st_invalid.next = self.abc.o_invalid.val();
            self.st_sr.next = self.abc.o_sr.val();
            self.st_er.next = self.abc.o_er.val();
            self.st_edge.next = self.abc.o_edge.val();
            self.st_face.next = self.abc.o_face.val();
            self.st_bx.next = self.abc.o_base_x.val();
            self.st_by.next = self.abc.o_base_y.val();
            self.st_dxn.next = self.abc.o_dx_neg.val();
            self.st_dxm.next = self.abc.o_dx_mag.val();
            self.st_dyn.next = self.abc.o_dy_neg.val();
            self.st_dym.next = self.abc.o_dy_mag.val();
        } else {
            self.st_valid.next = self.beat_valid.val();
            self.st_value.next = self.value.val();
            self.st_x.next = self.x.val();
            self.st_y.next = self.y.val();
            self.st_pad.next = self.pad.val();
            self.st_invalid.next = self.invalid.val();
            self.st_sr.next = self.sr.val();
            self.st_er.next = self.er.val();
            self.st_edge.next = self.at_edge.val();
            self.st_face.next = self.face.val();
            self.st_bx.next = self.base_x.val();
            self.st_by.next = self.base_y.val();
            self.st_dxn.next = self.dx_neg.val();
            self.st_dxm.next = self.dx_mag.val();
            self.st_dyn.next = self.dy_neg.val();
            self.st_dym.next = self.dy_mag.val();
        }
        // Shader (input at T-1, registered sample at T).
        self.shader.value.next = self.st_value.val();
        self.shader.invalid.next = self.st_invalid.val();
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
        self.dxn_q.d.next = self.st_dxn.val();
        self.dxm_q.d.next = self.st_dxm.val();
        self.dyn_q.d.next = self.st_dyn.val();
        self.dym_q.d.next = self.st_dym.val();
        // Partial-beam ends: x-1 of a partial beam's first lane is one beat
        // older, x+1 of its last lane one beat newer.
        self.first.next = (self.x_q.q.val() & self.p_mask.val()) == 0;
        self.last.next = (self.x_q.q.val() & self.p_mask.val()) == self.p_mask.val();
        // The nine taps, aligned at T.
        self.ring0.read_clock.next = self.clock.val();
        self.ring0.write_clock.next = self.clock.val();
        self.ring0.read_address.next = self.now.val() + self.off0.val();
        self.t0s0.next = self.ring0.read_data.val();
        self.f0_1.d.next = self.t0i1.val();
        self.s0.next = self.ring0.read_data.val();
        if self.hops0.val() == 1 {
            self.s0.next = self.f0_1.q.val();
        }
        self.prev0.d.next = self.s0.val();
        self.a0.next = self.s0.val();
        self.ring1.read_clock.next = self.clock.val();
        self.ring1.write_clock.next = self.clock.val();
        self.ring1.read_address.next = self.now.val() + self.off1.val();
        self.t1s0.next = self.ring1.read_data.val();
        self.f1_1.d.next = self.t1i1.val();
        self.f1_2.d.next = self.t1i2.val();
        self.t1s1.next = self.f1_1.q.val();
        self.s1.next = self.ring1.read_data.val();
        if self.hops1.val() == 1 {
            self.s1.next = self.f1_1.q.val();
        }
        if self.hops1.val() == 2 {
            self.s1.next = self.f1_2.q.val();
        }
        self.prev1.d.next = self.s1.val();
        self.a1.next = self.s1.val();
        if self.first.val() {
            self.a1.next = self.prev1.q.val();
        }
        self.ring2.read_clock.next = self.clock.val();
        self.ring2.write_clock.next = self.clock.val();
        self.ring2.read_address.next = self.now.val() + self.off2.val();
        self.s2.next = self.ring2.read_data.val();
        self.prev2.d.next = self.s2.val();
        self.a2.next = self.prev2.q.val();
        if self.last.val() {
            self.a2.next = self.s2.val();
        }
        self.ring3.read_clock.next = self.clock.val();
        self.ring3.write_clock.next = self.clock.val();
        self.ring3.read_address.next = self.now.val() + self.off3.val();
        self.t3s0.next = self.ring3.read_data.val();
        self.f3_1.d.next = self.t3i1.val();
        self.f3_2.d.next = self.t3i2.val();
        self.t3s1.next = self.f3_1.q.val();
        self.s3.next = self.ring3.read_data.val();
        if self.hops3.val() == 1 {
            self.s3.next = self.f3_1.q.val();
        }
        if self.hops3.val() == 2 {
            self.s3.next = self.f3_2.q.val();
        }
        self.prev3.d.next = self.s3.val();
        self.a3.next = self.s3.val();
        self.ring4.read_clock.next = self.clock.val();
        self.ring4.write_clock.next = self.clock.val();
        self.ring4.read_address.next = self.now.val() + self.off4.val();
        self.s4.next = self.ring4.read_data.val();
        self.prev4.d.next = self.s4.val();
        self.a4.next = self.s4.val();
        self.ring5.read_clock.next = self.clock.val();
        self.ring5.write_clock.next = self.clock.val();
        self.ring5.read_address.next = self.now.val() + self.off5.val();
        self.t5s0.next = self.ring5.read_data.val();
        self.f5_1.d.next = self.t5i1.val();
        self.f5_2.d.next = self.t5i2.val();
        self.f5_3.d.next = self.t5i3.val();
        self.t5s1.next = self.f5_1.q.val();
        self.t5s2.next = self.f5_2.q.val();
        self.s5.next = self.ring5.read_data.val();
        if self.hops5.val() == 1 {
            self.s5.next = self.f5_1.q.val();
        }
        if self.hops5.val() == 2 {
            self.s5.next = self.f5_2.q.val();
        }
        if self.hops5.val() == 3 {
            self.s5.next = self.f5_3.q.val();
        }
        self.prev5.d.next = self.s5.val();
        self.a5.next = self.s5.val();
        if self.first.val() {
            self.a5.next = self.prev5.q.val();
        }
        self.ring6.read_clock.next = self.clock.val();
        self.ring6.write_clock.next = self.clock.val();
        self.ring6.read_address.next = self.now.val() + self.off6.val();
        self.t6s0.next = self.ring6.read_data.val();
        self.f6_1.d.next = self.t6i1.val();
        self.s6.next = self.ring6.read_data.val();
        if self.hops6.val() == 1 {
            self.s6.next = self.f6_1.q.val();
        }
        self.prev6.d.next = self.s6.val();
        self.a6.next = self.prev6.q.val();
        if self.last.val() {
            self.a6.next = self.s6.val();
        }
        self.ring7.read_clock.next = self.clock.val();
        self.ring7.write_clock.next = self.clock.val();
        self.ring7.read_address.next = self.now.val() + self.off7.val();
        self.t7s0.next = self.ring7.read_data.val();
        self.f7_1.d.next = self.t7i1.val();
        self.s7.next = self.ring7.read_data.val();
        if self.hops7.val() == 1 {
            self.s7.next = self.f7_1.q.val();
        }
        self.prev7.d.next = self.s7.val();
        self.a7.next = self.s7.val();
        if self.first.val() {
            self.a7.next = self.prev7.q.val();
        }
        self.ring8.read_clock.next = self.clock.val();
        self.ring8.write_clock.next = self.clock.val();
        self.ring8.read_address.next = self.now.val() + self.off8.val();
        self.t8s0.next = self.ring8.read_data.val();
        self.f8_1.d.next = self.t8i1.val();
        self.s8.next = self.ring8.read_data.val();
        if self.hops8.val() == 1 {
            self.s8.next = self.f8_1.q.val();
        }
        self.f8l.d.next = self.t8il.val();
        if self.left8.val() {
            self.s8.next = self.f8l.q.val();
        }
        self.prev8.d.next = self.s8.val();
        self.a8.next = self.prev8.q.val();
        if self.last.val() {
            self.a8.next = self.s8.val();
        }
        // The signs of dx and dy narrow the 3x3 region to 2x2: the
        // neighbours are x - sign(dx) and y - sign(dy).
        self.c00.next = self.a0.val();
        self.c10.next = self.a0.val();
        self.c01.next = self.a0.val();
        self.c11.next = self.a0.val();
        self.x_out.next = false;
        self.y_out.next = false;
        if self.dxm_q.q.val() != 0 {
            if self.dxn_q.q.val() {
                self.c10.next = self.a2.val();
                self.x_out.next = self.x_q.q.val() == self.nx_last.val();
            } else {
                self.c10.next = self.a1.val();
                self.x_out.next = self.x_q.q.val() == 0;
            }
        }
        if self.dym_q.q.val() != 0 {
            if self.dyn_q.q.val() {
                self.c01.next = self.a4.val();
                self.y_out.next = self.y_q.q.val() == self.ny_last.val();
            } else {
                self.c01.next = self.a3.val();
                self.y_out.next = self.y_q.q.val() == 0;
            }
        }
        self.c11.next = self.c01.val();
        if self.dxm_q.q.val() != 0 {
            self.c11.next = self.c10.val();
            if self.dym_q.q.val() != 0 {
                if self.dxn_q.q.val() {
                    if self.dyn_q.q.val() {
                        self.c11.next = self.a8.val();
                    } else {
                        self.c11.next = self.a6.val();
                    }
                } else if self.dyn_q.q.val() {
                    self.c11.next = self.a7.val();
                } else {
                    self.c11.next = self.a5.val();
                }
            }
        }
        // Cells outside the slice, and the start of a ray, read as reset.
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
        self.bilinear.c00[0].next = bit_cast::<32, 64>(self.c00.val() & self.r_mask.val());
        self.bilinear.c00[1].next =
            bit_cast::<32, 64>((self.c00.val() >> 16) & self.gba_mask.val());
        self.bilinear.c00[2].next =
            bit_cast::<32, 64>((self.c00.val() >> 32) & self.gba_mask.val());
        self.bilinear.c00[3].next =
            bit_cast::<32, 64>((self.c00.val() >> 48) & self.gba_mask.val());
        self.bilinear.c10[0].next = bit_cast::<32, 64>(self.c10.val() & self.r_mask.val());
        self.bilinear.c10[1].next =
            bit_cast::<32, 64>((self.c10.val() >> 16) & self.gba_mask.val());
        self.bilinear.c10[2].next =
            bit_cast::<32, 64>((self.c10.val() >> 32) & self.gba_mask.val());
        self.bilinear.c10[3].next =
            bit_cast::<32, 64>((self.c10.val() >> 48) & self.gba_mask.val());
        self.bilinear.c01[0].next = bit_cast::<32, 64>(self.c01.val() & self.r_mask.val());
        self.bilinear.c01[1].next =
            bit_cast::<32, 64>((self.c01.val() >> 16) & self.gba_mask.val());
        self.bilinear.c01[2].next =
            bit_cast::<32, 64>((self.c01.val() >> 32) & self.gba_mask.val());
        self.bilinear.c01[3].next =
            bit_cast::<32, 64>((self.c01.val() >> 48) & self.gba_mask.val());
        self.bilinear.c11[0].next = bit_cast::<32, 64>(self.c11.val() & self.r_mask.val());
        self.bilinear.c11[1].next =
            bit_cast::<32, 64>((self.c11.val() >> 16) & self.gba_mask.val());
        self.bilinear.c11[2].next =
            bit_cast::<32, 64>((self.c11.val() >> 32) & self.gba_mask.val());
        self.bilinear.c11[3].next =
            bit_cast::<32, 64>((self.c11.val() >> 48) & self.gba_mask.val());
        self.bilinear.wx.next = self.dxm_q.q.val();
        self.bilinear.wy.next = self.dym_q.q.val();
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
        self.compositor.acc_r.next = self.bilinear.out[0].val();
        self.compositor.acc_g.next = bit_cast::<16, 32>(self.bilinear.out[1].val());
        self.compositor.acc_b.next = bit_cast::<16, 32>(self.bilinear.out[2].val());
        self.compositor.acc_a.next = bit_cast::<16, 32>(self.bilinear.out[3].val());
        self.compositor.new_r.next = bit_cast::<32, 16>(self.s_r[1].q.val());
        self.compositor.new_g.next = self.s_g[1].q.val();
        self.compositor.new_b.next = self.s_b[1].q.val();
        self.compositor.new_a.next = self.s_a[1].q.val();
        self.compositor.new_valid.next = self.s_v[1].q.val();
        self.res.next = bit_cast::<64, 32>(self.compositor.out_r.val())
            | (bit_cast::<64, 16>(self.compositor.out_g.val()) << 16)
            | (bit_cast::<64, 16>(self.compositor.out_b.val()) << 32)
            | (bit_cast::<64, 16>(self.compositor.out_a.val()) << 48);
        // Write the result into the ring buffers at its beat's time.
        self.ring0.write_address.next = self.now.val() - 3;
        self.ring0.write_data.next = self.res.val();
        self.ring0.write_enable.next = self.v_q[3].q.val();
        self.ring1.write_address.next = self.now.val() - 3;
        self.ring1.write_data.next = self.res.val();
        self.ring1.write_enable.next = self.v_q[3].q.val();
        self.ring2.write_address.next = self.now.val() - 3;
        self.ring2.write_data.next = self.res.val();
        self.ring2.write_enable.next = self.v_q[3].q.val();
        self.ring3.write_address.next = self.now.val() - 3;
        self.ring3.write_data.next = self.res.val();
        self.ring3.write_enable.next = self.v_q[3].q.val();
        self.ring4.write_address.next = self.now.val() - 3;
        self.ring4.write_data.next = self.res.val();
        self.ring4.write_enable.next = self.v_q[3].q.val();
        self.ring5.write_address.next = self.now.val() - 3;
        self.ring5.write_data.next = self.res.val();
        self.ring5.write_enable.next = self.v_q[3].q.val();
        self.ring6.write_address.next = self.now.val() - 3;
        self.ring6.write_data.next = self.res.val();
        self.ring6.write_enable.next = self.v_q[3].q.val();
        self.ring7.write_address.next = self.now.val() - 3;
        self.ring7.write_data.next = self.res.val();
        self.ring7.write_enable.next = self.v_q[3].q.val();
        self.ring8.write_address.next = self.now.val() - 3;
        self.ring8.write_data.next = self.res.val();
        self.ring8.write_enable.next = self.v_q[3].q.val();
        self.res_beat.next = self.v_q[3].q.val();
        self.res_valid.next = self.v_q[3].q.val() & !self.pad_q[3].q.val();
        // Pixel out on ER.
        self.px_valid.next = self.v_q[3].q.val() & self.er_q[3].q.val() & !self.pad_q[3].q.val();
        self.px_x.next = self.bx_q[3].q.val();
        self.px_y.next = self.by_q[3].q.val();
        self.px_face.next = self.face_q[3].q.val();
    }
}

/// The whole Cube-4L pipeline: CFB and `P` pipelines (`A`-bit memory
/// modules, `H`-bit ring buffers).
#[derive(LogicBlock)]
pub struct Pipeline<const P: usize, const A: usize, const H: usize> {
    pub clock: Signal<In, Clock>,
    /// Start a sweep; the CFB's load port fills the voxel memory.
    pub start: Signal<In, Bit>,
    pub load_enable: Signal<In, Bit>,
    pub load_module: Signal<In, Bits<8>>,
    pub load_address: Signal<In, Bits<A>>,
    pub load_data: Signal<In, Bits<16>>,
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
    pub cfb: Cfb<P, A>,
    pub lanes: [PipeLane<H>; P],
    now: DFF<Bits<H>>,
}

impl<const P: usize, const A: usize, const H: usize> Pipeline<P, A, H> {
    /// Build the pipeline for one sweep; `golden` is the golden model's
    /// shader of that sweep, whose LUTs the hardware copies.
    pub fn new(
        config: &PipelineConfig,
        golden: &golden_model::cube4l::shader::Shader,
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
        if !config.cfb.external_memory && config.cfb.memory_bits as usize > A {
            return Err(format!(
                "{}-bit memory modules needed, built with {A}: use external memory",
                config.cfb.memory_bits
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
        self.busy.next = self.cfb.busy.val();
        self.n_s.next = self.cfb.n_s.val();
        self.n_beam.next = self.cfb.n_beam.val();
        self.n_b.next = self.cfb.n_b.val();
        self.bs.next = self.cfb.bs.val();
        for k in 0..P {
            self.lanes[k].clock.next = self.clock.val();
            self.lanes[k].now.next = self.now.q.val();
            self.lanes[k].beat_valid.next = self.cfb.valid.val();
            self.cfb.ext_data[k].next = self.ext_data[k].val();
            self.ext_addr[k].next = self.cfb.ext_addr[k].val();
            self.px_valid[k].next = self.lanes[k].px_valid.val();
            self.px_x[k].next = self.lanes[k].px_x.val();
            self.px_y[k].next = self.lanes[k].px_y.val();
            self.px_face[k].next = self.lanes[k].px_face.val();
            self.res_beat[k].next = self.lanes[k].res_beat.val();
            self.res_valid[k].next = self.lanes[k].res_valid.val();
            self.res[k].next = self.lanes[k].res.val();
            self.lanes[k].value.next = self.cfb.value[k].val();
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
