//! What a Cube-4L build is made of (§3): its structural configuration
//! ([`PipelineConfig`]: p, the mode class, which units, the widths and the
//! largest volume), from which the stages size their units and buffers, and
//! the constants the stages share. Everything a view changes (dims, slices,
//! axes, dx and dy or the eye, the order) is a register the host writes
//! (`golden_model::cube4l::regs::ViewRegs`), so one build renders every view
//! of its class. The stages take their configuration from here, never from
//! the pipeline that holds them.

use super::bilinear;
use super::cfb_stages::{ADDRESS_STAGES, READ_STAGES};
use super::compositor;
use crate::common::mode_class::ModeClass;
use crate::common::ram::{bits_for, ON_CHIP_BITS};
use crate::common::shader;
use crate::common::width_refusal;
use golden_model::cube4l::plan::{Rays, Sweep};
use golden_model::cube4l::regs::ViewRegs;
use scene::Mode;
use std::fmt;

/// What a Cube-4L build is made of: the shape of the hardware, not a view.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct PipelineConfig {
    pub p: u32,
    pub mode: ModeClass,
    /// The lighting unit (composite and first-opaque with shading).
    pub shading: bool,
    /// Opacity by gradient magnitude as well as intensity.
    pub gradient_opacity: bool,
    /// The per-voxel divider of perspective views; without it the rays are
    /// parallel (dx and dy registers).
    pub perspective: bool,
    /// The largest volume: `max_dim` voxels along every axis.
    pub max_dim: u32,
    pub voxel_bits: u32,
    pub rgba_bits: u32,
    pub frac_bits: u32,
    /// Bits a component of the lighting's quantized normal; the default
    /// ([`shader::unlit_normal_bits`]) without shading.
    pub normal_bits: u32,
}

/// The widths a configuration's name leaves out.
const DEFAULT_BITS: u32 = 8;

impl PipelineConfig {
    /// The configuration a sweep of a volume of `vol_dims` needs, with the
    /// golden model's shader of that sweep: the volume's largest dimension
    /// sets the buffers and the memory.
    pub fn for_view(
        sweep: &Sweep,
        vol_dims: [usize; 3],
        p: usize,
        shader: &golden_model::common::shader::Shader,
    ) -> PipelineConfig {
        PipelineConfig {
            p: p as u32,
            mode: ModeClass::of(shader.mode),
            shading: shader.lighting.is_some(),
            gradient_opacity: shader
                .opacity
                .as_ref()
                .is_some_and(|o| o.gm_shift.is_some()),
            perspective: matches!(sweep.rays, Rays::Perspective { .. }),
            max_dim: vol_dims.iter().copied().max().unwrap_or(1) as u32,
            voxel_bits: shader.voxel_bits,
            rgba_bits: shader.rgba_bits,
            frac_bits: sweep.frac,
            normal_bits: shader
                .lighting
                .as_ref()
                .map_or_else(shader::unlit_normal_bits, |l| l.normal_bits),
        }
    }

    /// A mask of the bits a coordinate takes in the largest volume: a
    /// voxel's x or y in a slice (below `max_dim`, padding included) or a
    /// base-plane pixel's (below `3 max_dim`: the slice and a border of
    /// at most `max_dim` on either side), with room to spare.
    pub fn coord_mask(&self) -> u32 {
        (4 * self.max_dim).next_power_of_two() - 1
    }

    /// The ABC gradient unit: shading or gradient opacity needs it (and
    /// delays everything a slice).
    pub fn gradient(&self) -> bool {
        self.shading || self.gradient_opacity
    }

    /// The most beats of a beam and of a slice.
    pub fn beam_beats(&self) -> u32 {
        self.max_dim.div_ceil(self.p)
    }
    pub fn slice_beats(&self) -> u32 {
        self.max_dim * self.beam_beats()
    }

    /// The gradient unit's delay lines, in clocks (`abc_gradient`'s
    /// `line_a` to `line_d`; a line of 1 is a register), for S beats per
    /// slice and B per beam: S - B - 1, B, B, S - B.
    pub fn gradient_line_lengths(&self) -> [u32; 4] {
        let (s, b) = (self.slice_beats(), self.beam_beats());
        [s - b - 1, b, b, s - b]
    }

    /// Voxels per skewed memory module, and its address bits.
    pub fn module_words(&self) -> u64 {
        self.beam_beats() as u64 * self.max_dim as u64 * self.max_dim as u64
    }
    pub fn memory_bits(&self) -> u32 {
        bits_for(self.module_words())
    }

    /// The voxels live in external RAM: a module holds more than on-chip
    /// memory's 2^16 words.
    pub fn external_memory(&self) -> bool {
        self.memory_bits() as usize > ON_CHIP_BITS
    }

    /// The datapath widths: voxel, RGBA, weight fraction, normal.
    pub fn widths(&self) -> [u32; 4] {
        [
            self.voxel_bits,
            self.rgba_bits,
            self.frac_bits,
            self.normal_bits,
        ]
    }

    /// The configuration's name: `{mode}[_shaded][_gm][_perspective]_p{p}_{n}`
    /// and, for widths other than 8 bits, `_v{voxel}`, `_c{rgba}`, `_f{frac}`,
    /// and for a normal other than 5 bits `_q{normal}`
    /// (`composite_shaded_p4_256`, `composite_shaded_p4_32_f12_q6`).
    /// [`PipelineConfig::parse`] reads it back.
    pub fn name(&self) -> String {
        let mut s = self.mode.name().to_string();
        for (on, word) in [
            (self.shading, "shaded"),
            (self.gradient_opacity, "gm"),
            (self.perspective, "perspective"),
        ] {
            if on {
                s += "_";
                s += word;
            }
        }
        s += &format!("_p{}_{}", self.p, self.max_dim);
        for (bits, tag) in [
            (self.voxel_bits, 'v'),
            (self.rgba_bits, 'c'),
            (self.frac_bits, 'f'),
        ] {
            if bits != DEFAULT_BITS {
                s += &format!("_{tag}{bits}");
            }
        }
        s + &shader::normal_suffix(self.normal_bits)
    }

    /// The configuration that [`PipelineConfig::name`] names.
    pub fn parse(name: &str) -> Result<PipelineConfig, String> {
        let bad = |why: String| format!("configuration '{name}': {why}");
        let mut words = name.split('_');
        let first = words.next().unwrap_or_default();
        let mode = ModeClass::ALL
            .into_iter()
            .find(|m| m.name() == first)
            .ok_or_else(|| bad(format!("'{first}' is no mode class (composite, mip, xray)")))?;
        let mut c = PipelineConfig {
            p: 0,
            mode,
            shading: false,
            gradient_opacity: false,
            perspective: false,
            max_dim: 0,
            voxel_bits: DEFAULT_BITS,
            rgba_bits: DEFAULT_BITS,
            frac_bits: DEFAULT_BITS,
            normal_bits: shader::unlit_normal_bits(),
        };
        let number = |w: &str, what: &str| {
            w.parse::<u32>()
                .map_err(|_| bad(format!("'{w}' is no {what}")))
        };
        for w in words {
            match w {
                "shaded" => c.shading = true,
                "gm" => c.gradient_opacity = true,
                "perspective" => c.perspective = true,
                _ if c.p == 0 => {
                    let p = w
                        .strip_prefix('p')
                        .ok_or_else(|| bad(format!("'{w}' where p<pipelines> belongs")))?;
                    c.p = number(p, "pipeline count")?;
                }
                _ if c.max_dim == 0 => c.max_dim = number(w, "volume size")?,
                _ => {
                    let (tag, bits) = w.split_at(1.min(w.len()));
                    let bits = number(bits, "width")?;
                    match tag {
                        "v" => c.voxel_bits = bits,
                        "c" => c.rgba_bits = bits,
                        "f" => c.frac_bits = bits,
                        "q" => c.normal_bits = bits,
                        _ => return Err(bad(format!("'{w}' is no width (v, c, f or q and bits)"))),
                    }
                }
            }
        }
        if c.p == 0 || c.max_dim == 0 {
            return Err(bad(
                "it needs p<pipelines> and the largest volume size".into()
            ));
        }
        if c.name() != name {
            return Err(bad(format!("it reads as {}", c.name())));
        }
        c.validate().map_err(bad)?;
        Ok(c)
    }

    /// What the stages can build: p of 1, 2, 4 or 8, volumes of 2 to 4095
    /// voxels a side whose slices leave the compositing buffer a word,
    /// shading only where colour is composited, the configuration's widths.
    pub fn validate(&self) -> Result<(), String> {
        crate::common::lanes::built(self.p as usize)?;
        if !(2..=4095).contains(&self.max_dim) {
            return Err(format!(
                "volumes of {} voxels a side: the RTL CFB counts positions in 12 bits",
                self.max_dim
            ));
        }
        if (self.max_dim - 1) * self.beam_beats() < RESULT_AT + 5 {
            return Err(format!(
                "volumes of at most {} voxels a side are too small for the compositing-buffer taps at p = {}",
                self.max_dim, self.p
            ));
        }
        if self.mode != ModeClass::Over && (self.shading || self.gradient_opacity) {
            return Err(format!(
                "{} composite no colour: no shading or gradient opacity",
                self.mode.modes()
            ));
        }
        // The scene's own limits (`scene::Scene::validate`).
        if ![8, 12, 16].contains(&self.voxel_bits) {
            return Err(format!("{}-bit voxels: 8, 12 or 16", self.voxel_bits));
        }
        if !(4..=15).contains(&self.rgba_bits) {
            return Err(format!("{}-bit RGBA channels: 4 to 15", self.rgba_bits));
        }
        if !(2..=15).contains(&self.frac_bits) {
            return Err(format!("{} fractional bits: 2 to 15", self.frac_bits));
        }
        match shader::normal_bits_refusal(self.normal_bits, self.shading) {
            Some(why) => Err(why),
            None => Ok(()),
        }
    }

    /// Why this build cannot render what `needed` describes (a scene's own
    /// configuration), or `None`: every feature must match, and the volume
    /// must fit.
    pub fn refuses(&self, needed: &PipelineConfig) -> Option<String> {
        let yes_no = |b: bool| if b { "has" } else { "has no" };
        let unit = |what: &str, build: bool, scene: bool| {
            (build != scene).then(|| {
                format!(
                    "the scene {} {what}, the configuration {}",
                    if scene { "needs" } else { "has no" },
                    yes_no(build)
                )
            })
        };
        if self.mode != needed.mode {
            return Some(format!(
                "the scene's mode needs the {} hardware ({}); this configuration renders {}",
                needed.mode.name(),
                needed.mode.modes(),
                self.mode.modes()
            ));
        }
        if self.p != needed.p {
            return Some(format!(
                "the scene asks for {} pipelines, the configuration has {}",
                needed.p, self.p
            ));
        }
        unit("shading", self.shading, needed.shading)
            .or_else(|| {
                unit(
                    "gradient opacity",
                    self.gradient_opacity,
                    needed.gradient_opacity,
                )
            })
            .or_else(|| {
                (self.perspective != needed.perspective).then(|| {
                    format!(
                        "the scene's view is {}, the configuration's rays are {}",
                        if needed.perspective {
                            "perspective"
                        } else {
                            "parallel"
                        },
                        if self.perspective {
                            "perspective"
                        } else {
                            "parallel"
                        }
                    )
                })
            })
            .or_else(|| width_refusal(self.widths(), needed.widths()))
            .or_else(|| {
                (needed.max_dim > self.max_dim).then(|| {
                    format!(
                        "the volume is {} voxels along an axis, the configuration holds at most {}",
                        needed.max_dim, self.max_dim
                    )
                })
            })
    }

    /// Whether the build can render one sweep with these registers: its
    /// slices fit the buffers, and leave the compositing buffer's ring a
    /// word.
    pub fn check_view(&self, v: &ViewRegs) -> Result<(), String> {
        if v.dims.iter().any(|&d| d > self.max_dim) {
            return Err(format!(
                "a sweep of {:?} voxels does not fit a configuration of at most {} a side",
                v.dims, self.max_dim
            ));
        }
        if (v.dims[1] - 1) * v.beam_beats < RESULT_AT + 5 {
            return Err(format!(
                "a slice of {} beams of {} partial beams is too short for the compositing-buffer taps (need (n_y - 1) * b >= {})",
                v.dims[1],
                v.beam_beats,
                RESULT_AT + 5
            ));
        }
        Ok(())
    }
}

impl fmt::Display for PipelineConfig {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        f.write_str(&self.name())
    }
}

/// Clocks from a beat's gather (T: the taps, the 2x2 selection) to its
/// composited result.
pub const RESULT_AT: u32 = (bilinear::LATENCY + compositor::LATENCY) as u32;

/// Clocks the gather waits beyond the one after the shader's input, so
/// that the shader's sample (`shader::LATENCY` clocks after its input) meets
/// the bilinear unit's output at the compositor: the shader's input is at
/// `T - 1 - GATHER_DELAY`.
pub const GATHER_DELAY: usize = shader::LATENCY - 1 - bilinear::LATENCY;
// The shader's sample must not come before the bilinear unit's output (it
// would need registers of its own, which the control delay does not build).
const _: () = assert!(shader::LATENCY > bilinear::LATENCY);

/// Clocks of a sweep beyond one beat per clock: the start register, the
/// CFB's address stages, the block-RAM read and its output register, the
/// shader's input register, the gather's delay, the bilinear unit's latency
/// and the compositor's first stage (its last register ends the last beat's
/// own clock); with a gradient unit one more (its output register), and
/// with the perspective divider the counters' lead before the address
/// stages ([`super::counter_lead::LEAD`]).
pub fn fill_clocks(c: &PipelineConfig) -> u64 {
    2 + ADDRESS_STAGES as u64
        + READ_STAGES as u64
        + GATHER_DELAY as u64
        + bilinear::LATENCY as u64
        + (compositor::LATENCY - 1) as u64
        + c.gradient() as u64
        + if c.perspective {
            super::counter_lead::LEAD as u64
        } else {
            0
        }
}

/// Clocks for one frame of an n³ volume on `c`: one voxel per pipeline per
/// clock over n slices of n beams of ceil(n/p) partial beams, plus one
/// slice for the gradient unit and the pipeline's fill.
pub fn frame_clocks(n: u64, c: &PipelineConfig) -> u64 {
    let slice = n * n.div_ceil(c.p as u64);
    n * slice + if c.gradient() { slice } else { 0 } + fill_clocks(c)
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

/// Where one tap of the 3x3 neighbourhood comes from: the lanes it crosses.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Tap {
    /// Neighbour links the value crosses, each from lane j to lane j+1;
    /// with `left`, one link from lane k+1 to lane k instead.
    pub hops: u32,
    pub left: bool,
}

/// Clocks between the history's row `e_y` and tap `(e_x, e_y)`'s read, for
/// a tap over `hops` links: the candidate `BufferRows` picks. It does not
/// depend on the view: the tap waits `S - e_y B - [e_x = 1]` beats, the
/// row `S - e_y B - RESULT_AT - 4`.
pub fn tap_offset((ex, _): (i32, i32), hops: u32) -> u32 {
    4 - (ex == 1) as u32 - hops
}

impl PipelineConfig {
    /// The nine taps in `TAPS` order, by the lane count alone.
    pub fn taps(&self) -> [Tap; 9] {
        let p = self.p as i32;
        TAPS.map(|(ex, ey)| {
            let m = 1 - ex - ey;
            if m == -1 && p > 2 {
                Tap {
                    hops: 1,
                    left: true,
                }
            } else {
                Tap {
                    hops: m.rem_euclid(p) as u32,
                    left: false,
                }
            }
        })
    }

    /// Bit fields `(lowest bit, width)` of a composited word that can be
    /// non-zero, which the compositing-buffer rings store: four `rgba_bits`
    /// channels in 16-bit slots; the intensity for MIP/MinIP; the 32-bit sum
    /// for X-ray.
    pub fn ring_fields(&self) -> Vec<(usize, usize)> {
        match self.mode {
            ModeClass::Scalar => vec![(0, self.voxel_bits as usize)],
            ModeClass::Xray => vec![(0, 32)],
            ModeClass::Over => (0..4).map(|c| (16 * c, self.rgba_bits as usize)).collect(),
        }
    }

    /// Stored bits of a composited word ([`PipelineConfig::ring_fields`]).
    pub fn word_bits(&self) -> u64 {
        self.ring_fields().iter().map(|f| f.1 as u64).sum()
    }

    /// The history's ring and two beam lines, at their longest (a slice of
    /// `max_dim` beams of the most partial beams): the ring holds
    /// `S - B - RESULT_AT - 4` words of a view, the lines `B`.
    pub fn history_lines(&self) -> [u32; 3] {
        let (s, b) = (self.slice_beats(), self.beam_beats());
        [s - b - RESULT_AT - 4, b, b]
    }

    /// Every delay line of a lane at its longest, with its word bits.
    fn lines(&self) -> Vec<(u32, u64)> {
        let mut v: Vec<(u32, u64)> = self
            .history_lines()
            .iter()
            .map(|&l| (l, self.word_bits()))
            .collect();
        if self.gradient() {
            v.extend(
                self.gradient_line_lengths()
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
    /// the gradient unit's B and C slices (a line of L keeps L - 2 words and
    /// two registers after them; a line of 3 or less is registers alone).
    pub fn buffer_bits(&self) -> u64 {
        let lane: u64 = self
            .lines()
            .iter()
            .filter(|l| l.0 > 3)
            .map(|&(l, bits)| (l as u64 - 2) * bits)
            .sum();
        self.p as u64 * lane
    }

    /// The least the largest volume's buffers can hold (Tables 1 and 2 of
    /// the paper): one slice of composited words, and with gradients two
    /// slices of voxels, for the pipeline-space slice `n_x * n_y`.
    pub fn minimum_buffer_bits(&self) -> u64 {
        let slice = self.max_dim as u64 * self.max_dim as u64;
        slice * self.word_bits()
            + if self.gradient() {
                2 * slice * self.voxel_bits as u64
            } else {
                0
            }
    }
}

/// A lane's result word as `[r, g, b, a]`: four 16-bit channels, or
/// for X-ray a 32-bit sum in channel 0.
pub fn unpack(mode: Mode, word: u64) -> [u32; 4] {
    if mode == Mode::Xray {
        [word as u32, 0, 0, 0]
    } else {
        std::array::from_fn(|c| ((word >> (16 * c)) & 0xffff) as u32)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn configuration_names_read_back() {
        for name in [
            "composite_shaded_p4_256",
            "composite_perspective_p2_32",
            "mip_p4_64",
            "composite_shaded_gm_p2_16_v12_c10_f6",
            "composite_shaded_p4_32_f12_q6",
        ] {
            assert_eq!(
                PipelineConfig::parse(name).map(|c| c.name()),
                Ok(name.into())
            );
        }
        let knee = PipelineConfig::parse("composite_shaded_p4_32_f12_q6").unwrap();
        assert_eq!((knee.frac_bits, knee.normal_bits), (12, 6));
        for (bad, why) in [
            ("mip_p4_32_q6", "6-bit normals without shading"),
            ("composite_shaded_p4_32_q9", "9-bit normals"),
            ("composite_shaded_p4_32_q5", "it reads as"),
            ("composite_shaded_p4_32_x5", "is no width"),
        ] {
            let e = PipelineConfig::parse(bad).unwrap_err();
            assert!(e.contains(why), "{bad}: {e}");
        }
    }
}
