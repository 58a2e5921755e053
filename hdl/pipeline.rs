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
//! with e_x = +1). Each lane keeps its results once, in a ring of block RAM
//! read once, and beam-length delay lines and registers bring them to each
//! tap's delay ([`crate::buffer_rows::BufferRows`], as Fig. 21's SFG reads
//! the compositing FIFO once). The nine taps of the 3x3 region
//! hop to the consuming lane through one register per neighbour link
//! (m = 1 - e_x - e_y links; tap (+1, +1) takes one leftward link), and each
//! tap keeps its previous value for the partial-beam case (the extension
//! units of Figs. 14-15). The signs of the voxel's dx and dy then narrow the
//! 3x3 region to 2x2 (Figs. 19-21). Cells outside the slice, and every cell at
//! the start of a ray (SR), read as the reset value.
//!
//! **Timing.** Shader input at T-1 (the CFB's output, or the gradient unit's a
//! slice later), shader register at T, gather at T, the bilinear unit
//! T..T+L (`bilinear::LATENCY`, pipelined for speed), compositor register at
//! T+L+1 ([`RESULT_AT`]), where the result enters the lane's history and, on
//! ER, goes out as a base-plane pixel. The history's ring needs at least
//! one word: (n_y - 1) * b >= L + 6.
//!
//! **Lane.** [`PipeLane`] wires its blocks in this order: the input
//! selection ([`LaneFeed`], which holds the ABC gradient unit), the shader,
//! the taps ([`TapNetwork`] of nine [`crate::buffer_tap::BufferTap`]s), the
//! 2x2 selection ([`Select2x2`]), the bilinear unit and the compositor, with
//! the control delay line beside them ([`ControlDelay`], which also makes
//! the pixel output).
//!
//! **Gradient control.** With a gradient unit the lanes' control comes from
//! `late`, a second copy of the CFB's address generator without memory,
//! started S + 1 clocks after the CFB, so the control of the voxel leaving
//! the gradient unit is recomputed rather than stored a slice long.
//!
//! Units a scene does not need are built disabled, with empty tables and
//! one-register delay lines, and drive zero; `export::prune` removes them
//! from the emitted Verilog (see `export::left_out`). The delay lines are
//! exactly as long as their delays and store only the bits the mode can set
//! (`PipelineConfig::ring_fields`); when no tap the 2x2 selection can pick
//! looks at row y - 1 (parallel views, `PipelineConfig::taps_used`), that
//! row's beam-length line is a register.

use crate::bilinear::Bilinear;
use crate::cfb::{Cfb, CfbConfig};
use crate::compositor::Compositor;
use crate::control_delay::ControlDelay;
use crate::lane_feed::LaneFeed;
use crate::select2x2::Select2x2;
use crate::shader::Shader;
use crate::tap_network::TapNetwork;
use golden_model::cube4l::plan::Sweep;
use rust_hdl::prelude::*;
use scene::Mode;

/// Clocks from a beat's shader register (T) to its composited result.
pub const RESULT_AT: u32 = crate::bilinear::LATENCY as u32 + 1;

/// Clocks of a sweep beyond one beat per clock: the start register, the
/// block-RAM read, the shader register and the bilinear unit's latency (the
/// compositor register ends the last beat's own clock), and with a gradient
/// unit one more (its output register).
pub fn fill_clocks(gradient: bool) -> u64 {
    3 + crate::bilinear::LATENCY as u64 + gradient as u64
}

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
    /// signs of dx and dy select, fewer when dx or dy is 0. The history
    /// builds only the rows they need.
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
        if (cfb.dims[1] - 1) * b < RESULT_AT + 5 {
            return Err(format!(
                "a slice of {} beams of {b} partial beams is too short for the compositing-buffer taps (need (n_y - 1) * b >= {})",
                cfb.dims[1],
                RESULT_AT + 5
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

    /// Stored bits of a composited word (`ring_fields`).
    pub fn word_bits(&self) -> u64 {
        self.ring_fields.iter().map(|f| f.1 as u64).sum()
    }

    /// Whether a tap the 2x2 selection can pick reads row y - 1.
    pub fn reads_row_below(&self) -> bool {
        (0..9).any(|t| self.taps_used[t] && TAPS[t].1 == -1)
    }

    /// Every delay line of a lane, in clocks, with its word bits.
    fn lines(&self) -> Vec<(u32, u64)> {
        let mut v: Vec<(u32, u64)> = crate::buffer_rows::line_lengths(self)
            .iter()
            .map(|&l| (l, self.word_bits()))
            .collect();
        if self.gradient {
            v.extend(
                crate::abc_gradient::line_lengths(self.slice_beats, self.beam_beats)
                    .iter()
                    .map(|&l| (l, self.voxel_bits as u64)),
            );
        }
        v
    }

    /// Delay-line pointer bits (`H`) the build needs for its longest line,
    /// the compositing-buffer ring or the gradient unit's.
    pub fn history_bits(&self) -> usize {
        let longest = self.lines().iter().map(|l| l.0).max().unwrap_or(1);
        crate::cfb::bits_for(longest as u64 + 1) as usize
    }

    /// Bits of block RAM the pipelines' buffers hold (not the CFB's
    /// voxel memory), as built: per lane the compositing-buffer history and
    /// the gradient unit's B and C slices (a line of 1 is a register).
    pub fn buffer_bits(&self) -> u64 {
        let lane: u64 = self
            .lines()
            .iter()
            .filter(|l| l.0 > 1)
            .map(|&(l, bits)| l as u64 * bits)
            .sum();
        self.p as u64 * lane
    }

    /// The least the scene's buffers can hold (Tables 1 and 2 of the paper):
    /// one slice of composited words, and with gradients two slices of
    /// voxels, for the pipeline-space slice `n_x * n_y`.
    pub fn minimum_buffer_bits(&self) -> u64 {
        let slice = self.cfb.dims[0] as u64 * self.cfb.dims[1] as u64;
        slice * self.word_bits()
            + if self.gradient {
                2 * slice * self.voxel_bits as u64
            } else {
                0
            }
    }
}

/// A lane's packed result word from `[r, g, b, a]` (see [`unpack`]).
pub(crate) fn pack(v: [u32; 4]) -> u64 {
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

/// One pipeline after the CFB: input selection ([`LaneFeed`], with the ABC
/// gradient unit), shader, the compositing-buffer taps ([`TapNetwork`]),
/// the 2x2 selection ([`Select2x2`]), bilinear unit and compositor, with
/// the control beside them ([`ControlDelay`]).
#[derive(LogicBlock)]
pub struct PipeLane<const H: usize> {
    pub clock: Signal<In, Clock>,
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
    feed: LaneFeed<H>,
    shader: Shader,
    ctl: ControlDelay,
    taps: TapNetwork<H>,
    cells: Select2x2,
    bilinear: Bilinear,
    compositor: Compositor,
}

impl<const H: usize> PipeLane<H> {
    /// Bits of block RAM in the lane's buffers, as built.
    pub fn buffer_bits(&self) -> u64 {
        (self.taps.memory_bits() + self.feed.memory_bits()) as u64
    }

    fn new(c: &PipelineConfig, shader: Shader, mode: Mode) -> PipeLane<H> {
        PipeLane {
            clock: Default::default(),
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
            taps: TapNetwork::new(c),
            cells: Select2x2::new(c, mode),
            bilinear: Bilinear::new(c.frac_bits, mode == Mode::Xray),
            compositor: Compositor::new(mode, c.order, c.rgba_bits),
        }
    }
}

impl<const H: usize> Logic for PipeLane<H> {
    #[hdl_gen]
    fn update(&mut self) {
        // Input selection (T-1): the CFB's beat, or the gradient unit's.
        self.feed.clock.next = self.clock.val();
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
        // Shader (input at T-1, registered sample at T).
        self.shader.clock.next = self.clock.val();
        self.shader.value.next = self.feed.o_value.val();
        self.shader.invalid.next = self.feed.o_invalid.val();
        self.shader.at_edge.next = self.feed.o_edge.val();
        self.shader.gx_neg.next = self.feed.gx_neg.val();
        self.shader.gx_mag.next = bit_cast::<32, 16>(self.feed.gx_mag.val());
        self.shader.gy_neg.next = self.feed.gy_neg.val();
        self.shader.gy_mag.next = bit_cast::<32, 16>(self.feed.gy_mag.val());
        self.shader.gz_neg.next = self.feed.gz_neg.val();
        self.shader.gz_mag.next = bit_cast::<32, 16>(self.feed.gz_mag.val());
        // Control beside the voxel (T-1 to T and the result), the sample T
        // to T+L.
        self.ctl.clock.next = self.clock.val();
        self.ctl.valid.next = self.feed.o_valid.val();
        self.ctl.er.next = self.feed.o_er.val();
        self.ctl.pad.next = self.feed.o_pad.val();
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
        self.ctl.r.next = bit_cast::<16, 32>(self.shader.r.val());
        self.ctl.g.next = self.shader.g.val();
        self.ctl.b.next = self.shader.b.val();
        self.ctl.a.next = self.shader.a.val();
        self.ctl.sample_valid.next = self.shader.valid.val();
        // The compositing-buffer taps (T).
        self.taps.clock.next = self.clock.val();
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
        self.cells.x.next = self.ctl.x_t.val();
        self.cells.y.next = self.ctl.y_t.val();
        self.cells.sr.next = self.ctl.sr_t.val();
        self.cells.dx_neg.next = self.ctl.dx_neg_t.val();
        self.cells.dx_mag.next = self.ctl.dx_mag_t.val();
        self.cells.dy_neg.next = self.ctl.dy_neg_t.val();
        self.cells.dy_mag.next = self.ctl.dy_mag_t.val();
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
        self.compositor.acc_r.next = self.bilinear.out[0].val();
        self.compositor.acc_g.next = bit_cast::<16, 32>(self.bilinear.out[1].val());
        self.compositor.acc_b.next = bit_cast::<16, 32>(self.bilinear.out[2].val());
        self.compositor.acc_a.next = bit_cast::<16, 32>(self.bilinear.out[3].val());
        self.compositor.new_r.next = bit_cast::<32, 16>(self.ctl.new_r.val());
        self.compositor.new_g.next = self.ctl.new_g.val();
        self.compositor.new_b.next = self.ctl.new_b.val();
        self.compositor.new_a.next = self.ctl.new_a.val();
        self.compositor.new_valid.next = self.ctl.new_valid.val();
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

/// The whole Cube-4L pipeline: CFB and `P` pipelines (`A`-bit memory
/// modules, `H`-bit delay-line pointers).
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
    /// With a gradient unit: the CFB's address generator again, without
    /// memory, started S + 1 clocks after it (`late_wait` counts down), so
    /// that the control of the voxel leaving the gradient unit is recomputed
    /// rather than stored.
    late: Cfb<P, A>,
    late_wait: DFF<Bits<32>>,
    late_delay: Constant<Bits<32>>,
    gradient: Constant<Bit>,
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
                "the buffers need {}-bit delay-line pointers, built with {H}",
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
        let lanes = lanes
            .into_boxed_slice()
            .try_into()
            .unwrap_or_else(|_| unreachable!());
        let cfb = Box::new(Cfb::new(&config.cfb));
        let late = Box::new(Cfb::new(&CfbConfig {
            external_memory: true,
            ..config.cfb
        }));
        Ok(Self::with_lanes(config, lanes, cfb, late))
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
            cfb: *cfb,
            lanes: *lanes,
            late: *late,
            late_wait: Default::default(),
            late_delay: Constant::new(((config.slice_beats + 1) as u64).to_bits()),
            gradient: Constant::new(config.gradient),
        }
    }
}

impl<const P: usize, const A: usize, const H: usize> Logic for Pipeline<P, A, H> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, late_wait);
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
        // The late CFB starts S + 1 clocks after the CFB took its start.
        self.late_wait.d.next = self.late_wait.q.val();
        if self.start.val() & !self.cfb.busy.val() {
            self.late_wait.d.next = self.late_delay.val();
        } else if self.late_wait.q.val() != 0 {
            self.late_wait.d.next = self.late_wait.q.val() - 1;
        }
        self.late.clock.next = self.clock.val();
        self.late.start.next = self.late_wait.q.val() == 1;
        self.late.load_enable.next = false;
        self.late.load_module.next = 0.into();
        self.late.load_address.next = 0.into();
        self.late.load_data.next = 0.into();
        for k in 0..P {
            self.late.ext_data[k].next = 0.into();
            self.lanes[k].clock.next = self.clock.val();
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
