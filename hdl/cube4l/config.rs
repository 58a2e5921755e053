//! What a Cube-4L pipeline is built from (§3): the CFB's sweep parameters
//! ([`CfbConfig`]), and the pipeline's ([`PipelineConfig`]): the
//! compositing-buffer taps and their delays, the buffers' lengths and
//! widths, and the constants the stages share. The stages take their
//! configuration from here, never from the pipeline that holds them.

use super::abc_gradient;
use super::bilinear;
use crate::common::ram::bits_for;
use crate::common::shader;
use golden_model::cube4l::plan::{Rays, Sweep};
use scene::Mode;

/// Sweep parameters the CFB is built for.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct CfbConfig {
    /// Pipeline-space dims `[nx, ny, nz]` and the swept slices.
    pub dims: [u32; 3],
    pub z0: u32,
    pub z1: u32,
    /// Slices streamed: `z0..=z1`, plus, for a gradient unit, the halo slices
    /// z0 - 1 and z1 + 1 inside the dataset (streamed but not composited).
    pub stream_z0: u32,
    pub stream_z1: u32,
    /// Pipeline axis (0 = x, 1 = y, 2 = z) that holds dataset u, v and w.
    pub u_from: u32,
    pub v_from: u32,
    pub w_from: u32,
    /// Dataset partial beams per u beam (`ceil(n_u / P)`) and dataset n_v.
    pub b_u: u32,
    pub n_v: u32,
    /// Parallel views: the frame registers (fixed point with `frac` bits).
    pub dx: i32,
    pub dy: i32,
    /// Perspective views: the eye in pipeline space, fixed point.
    pub eye: Option<[i64; 3]>,
    pub frac: u32,
    /// Voxels come from an external RAM through `ext_addr`/`ext_data`.
    pub external_memory: bool,
    /// Address bits of an on-chip memory module: it holds
    /// `ceil(n_u / P) * n_v * n_w` voxels.
    pub memory_bits: u32,
    /// Bits stored per voxel (the scene's voxel bits; 16 by default).
    pub voxel_bits: u32,
}

impl CfbConfig {
    /// The configuration for one sweep over a dataset of `vol_dims`.
    pub fn from_sweep(sweep: &Sweep, vol_dims: [usize; 3], p: usize) -> Result<CfbConfig, String> {
        let (dx, dy, eye) = match sweep.rays {
            Rays::Parallel { dx, dy } => (dx, dy, None),
            Rays::Perspective { eye } => (0, 0, Some(eye)),
        };
        if eye.is_some_and(|e| e.iter().any(|c| c.abs() >= 1 << 40)) {
            return Err("the eye is too far away for the RTL divider's 64-bit datapath".into());
        }
        if vol_dims.iter().any(|&n| n > 4095) {
            return Err(format!(
                "dims {vol_dims:?}: the RTL CFB counts positions in 12 bits"
            ));
        }
        let from = |axis: usize| sweep.perm.iter().position(|&a| a == axis).unwrap() as u32;
        Ok(CfbConfig {
            dims: sweep.dims.map(|n| n as u32),
            z0: sweep.z0 as u32,
            z1: sweep.z1 as u32,
            stream_z0: sweep.z0 as u32,
            stream_z1: sweep.z1 as u32,
            u_from: from(0),
            v_from: from(1),
            w_from: from(2),
            b_u: vol_dims[0].div_ceil(p) as u32,
            n_v: vol_dims[1] as u32,
            dx,
            dy,
            eye,
            frac: sweep.frac,
            external_memory: false,
            memory_bits: bits_for((vol_dims[0].div_ceil(p) * vol_dims[1] * vol_dims[2]) as u64),
            voxel_bits: 16,
        })
    }

    /// Stream one halo slice beyond each end of the sweep that lies inside
    /// the dataset, for the gradient unit's B and A slices.
    pub fn with_halo(mut self) -> CfbConfig {
        self.stream_z0 = self.z0.saturating_sub(1);
        self.stream_z1 = (self.z1 + 1).min(self.dims[2] - 1);
        self
    }
}

/// Clocks from a beat's gather (T: the taps, the 2x2 selection) to its
/// composited result.
pub const RESULT_AT: u32 = bilinear::LATENCY as u32 + 1;

/// Clocks the gather waits beyond the one after the shader's input, so
/// that the shader's sample (`shader::LATENCY` clocks after its input) meets
/// the bilinear unit's output at the compositor: the shader's input is at
/// `T - 1 - GATHER_DELAY`.
pub const GATHER_DELAY: usize = shader::LATENCY - 1 - bilinear::LATENCY;
// The shader's sample must not come before the bilinear unit's output (it
// would need registers of its own, which the control delay does not build).
const _: () = assert!(shader::LATENCY > bilinear::LATENCY);

/// Clocks of a sweep beyond one beat per clock: the start register, the
/// block-RAM read, the shader's input register, the gather's delay and the
/// bilinear unit's latency (the compositor register ends the last beat's
/// own clock), and with a gradient unit one more (its output register).
pub fn fill_clocks(gradient: bool) -> u64 {
    3 + GATHER_DELAY as u64 + bilinear::LATENCY as u64 + gradient as u64
}

/// Clocks for one frame of an n³ volume at `p` pipelines: one voxel per
/// pipeline per clock over n slices of n beams of ceil(n/p) partial beams,
/// plus one slice for the gradient unit and the pipeline's fill.
pub fn frame_clocks(n: u64, p: u64, gradient: bool) -> u64 {
    let slice = n * n.div_ceil(p);
    n * slice + if gradient { slice } else { 0 } + fill_clocks(gradient)
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
                Rays::Parallel { dx, dy } => {
                    // Tap (e_x, e_y) serves x - sign(dx), y - sign(dy).
                    let (sx, sy) = (-dx.signum(), -dy.signum());
                    TAPS.map(|(ex, ey)| (ex == 0 || ex == sx) && (ey == 0 || ey == sy))
                }
                Rays::Perspective { .. } => [true; 9],
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

    /// The clocks tap `tap`'s value waits after the lane's result (`E` in
    /// `buffer_rows`).
    pub fn tap_wait(&self, tap: usize) -> u32 {
        let t = &self.taps[tap];
        t.delay - t.hops - RESULT_AT
    }

    /// Clocks from the result to row `e_y`'s first register (`R(e_y)`).
    pub fn row_wait(&self, ey: i32) -> u32 {
        (self.slice_beats as i32 - ey * self.beam_beats as i32) as u32 - RESULT_AT - 4
    }

    /// The history's ring and two beam lines, in clocks: row y-1's line is
    /// a register (length 1) when no tap the 2x2 can select reads that row.
    pub fn history_lines(&self) -> [u32; 3] {
        let below = if self.reads_row_below() {
            self.beam_beats
        } else {
            1
        };
        [self.row_wait(1), self.beam_beats, below]
    }

    /// Every delay line of a lane, in clocks, with its word bits.
    fn lines(&self) -> Vec<(u32, u64)> {
        let mut v: Vec<(u32, u64)> = self
            .history_lines()
            .iter()
            .map(|&l| (l, self.word_bits()))
            .collect();
        if self.gradient {
            v.extend(
                abc_gradient::line_lengths(self.slice_beats, self.beam_beats)
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
        bits_for(longest as u64 + 1) as usize
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
pub fn pack(v: [u32; 4]) -> u64 {
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
