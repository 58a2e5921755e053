//! One flow for every architecture: what the kit needs to know of an
//! architecture to export it, simulate it on any engine, check it against
//! its golden model, trace it and synthesize it. [`crate::cube4l::Cube4l`]
//! and [`crate::cube3::Cube3`] implement [`Arch`]; the flows
//! ([`crate::export`], [`crate::sim`] and the `cube` subcommands) are
//! written once over it, and [`crate::archs::ArchName`] picks one at run
//! time. A third architecture is a third implementation and a variant of
//! `ArchName`, not a copy of a flow.

use crate::gtkw::Wave;
use crate::harness::{Engine, Group, Record, Stop};
use crate::verilog::{Layout, LeftOut};
use golden_model::host::Write;
use scene::volume::Volume;
use scene::{Camera, Image, Scene};
use std::path::Path;

/// A base plane's pixels as the checker compares them.
pub trait BasePixels {
    /// Everything the golden model fixes of a pixel: its colour, and its
    /// face (Cube-4L) or whether a ray was cast (Cube-3).
    type Pixel: PartialEq + std::fmt::Debug;
    /// The number of pixels.
    fn count(&self) -> usize;
    /// Pixel `i`: its base-plane coordinates and value.
    fn at(&self, i: usize) -> ([i32; 2], Self::Pixel);
}

/// A term of a part's clocks: its key in reports, what it counts, and its
/// clocks (negative for clocks the frame does not spend).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ClockTerm {
    pub key: &'static str,
    pub what: &'static str,
    pub clocks: i64,
}

/// An architecture, as the flows see it. A build is a *configuration*:
/// what the hardware is made of (p, the mode class, which units, the
/// widths, the largest volume), never a view. A frame runs in *parts* the
/// build renders one after another, each after the host has written its
/// registers and tables: Cube-4L's sweeps, Cube-3's base planes. Frames
/// follow each other on the same build.
pub trait Arch: 'static {
    /// The `--arch` value and the manifest's `architecture`.
    const NAME: &'static str;
    /// The paper's name, for reports.
    const TITLE: &'static str;
    /// What a part is called: export directories are `<PART><i>`, the
    /// manifest lists them under `<PART>s`.
    const PART: &'static str;
    /// The export's stage files and lint waivers.
    const LAYOUT: Layout;

    /// A build's configuration.
    type Config: Clone + PartialEq + std::fmt::Debug + Send + Sync;
    /// One part: its plan, the build's configuration, the golden model's
    /// tables and the registers the host writes.
    type Part: Send + Sync;
    /// A part's base plane, from the golden model or the RTL.
    type Base: BasePixels + Clone + Send;

    /// The configuration a scene needs, for a volume of `dims` (after any
    /// crop): the smallest build that renders it.
    fn needs(scene: &Scene, camera: &Camera, dims: [usize; 3]) -> Result<Self::Config, String>;
    /// A configuration's name (`composite_shaded_p4_256`), which
    /// [`Arch::parse_config`] reads back.
    fn config_name(config: &Self::Config) -> String;
    fn parse_config(name: &str) -> Result<Self::Config, String>;
    /// Why build `build` cannot render what `needed` describes, or `None`.
    fn refuses(build: &Self::Config, needed: &Self::Config) -> Option<String>;
    /// The scene's parts on build `build`, for a volume of `dims`; an error
    /// names a view the build cannot render.
    fn parts(
        scene: &Scene,
        camera: &Camera,
        dims: [usize; 3],
        build: &Self::Config,
    ) -> Result<Vec<Self::Part>, String>;
    /// The units the build leaves out.
    fn left_out(config: &Self::Config) -> Vec<LeftOut>;
    /// Whether the build's voxels live in external memory.
    fn external(config: &Self::Config) -> bool;
    /// The memory modules' contents for the part, module by module.
    fn modules(part: &Self::Part, vol: &Volume) -> Vec<Vec<u16>>;
    /// The Verilog that renders the part, as the kit exports it (the same
    /// for every part of a build whose views are all registers); `preload`
    /// initialises on-chip voxel memory (simulation only: hardware loads it
    /// through the load port). The tables start empty: the host writes
    /// them.
    fn verilog(part: &Self::Part, preload: Option<&[Vec<u16>]>) -> Result<String, String>;
    /// The build's Verilog without a scene, or why the architecture needs
    /// one.
    fn design(config: &Self::Config) -> Result<String, String>;
    /// Whether two parts run on one build, one after the other (every
    /// part of a build whose views are all registers does).
    fn same_build(a: &Self::Part, b: &Self::Part) -> bool;
    /// What the host writes through the host port before the part starts:
    /// its tables, then its registers (`golden_model::host`). Every engine
    /// gets the same writes, so traces line up cycle for cycle.
    fn loads(part: &Self::Part) -> Vec<Write>;
    /// The pixel bus: what a frame's run logs, and the pulses that end it.
    fn bus(part: &Self::Part) -> (Stop, Vec<Group>);
    /// Run the parts one after another on one rust-hdl build (memory
    /// preloaded; before each part the host's writes, one a clock, then
    /// `start`), logging [`Arch::bus`] as the Verilog harness does; per
    /// part the records and the clock count, both from its `start`.
    fn rust_hdl(
        runs: &[(&Self::Part, Vec<Write>)],
        modules: &[Vec<u16>],
        trace: Option<&Path>,
    ) -> Result<Vec<(Vec<Record>, u64)>, String>;
    /// The base plane of the logged pixels, or why the golden model could
    /// never have put one of them out.
    fn decode(part: &Self::Part, records: &[Record]) -> Result<Self::Base, String>;
    /// The golden model's base plane.
    fn golden(part: &Self::Part, vol: &Volume) -> Self::Base;
    /// The final image of a frame's base planes.
    fn image(scene: &Scene, camera: &Camera, bases: Vec<Self::Base>) -> Result<Image, String>;
    /// One sample per unit per clock: the part's ideal clocks.
    fn ideal_clocks(part: &Self::Part) -> u64;
    /// Where the part's clocks go, as the RTL's schedule predicts them:
    /// terms that add up to its clocks (empty where there is no prediction).
    fn clock_terms(part: &Self::Part) -> Vec<ClockTerm>;
    /// The part's clocks as its schedule predicts them, or its ideal
    /// clocks where there is no prediction.
    fn expected_clocks(part: &Self::Part) -> u64 {
        match Self::clock_terms(part) {
            t if t.is_empty() => Self::ideal_clocks(part),
            t => t.iter().map(|t| t.clocks).sum::<i64>() as u64,
        }
    }
    /// The clocks above which each engine's run is refused.
    fn clock_limit(engine: Engine) -> u64 {
        match engine {
            Engine::RustHdl => 1 << 16,
            Engine::Iverilog => 1 << 15,
            Engine::Verilator => 1 << 28,
        }
    }
    /// The buffer memory the build holds (not the voxel memory), in bits,
    /// against the least its largest volume needs, and what it is.
    fn buffer_memory(config: &Self::Config, parts: &[Self::Part]) -> BufferMemory;
    /// Clocks of a frame of an `n`³ volume on the build, where the
    /// architecture can project them.
    fn projected_clocks(n: u64, config: &Self::Config) -> Option<u64>;
    /// The signal groups of a trace of the build, under `top` (the design's
    /// scope: `uut` in rust-hdl, `TOP.top` in Verilator, `tb.uut` in Icarus).
    fn waves(part: &Self::Part, top: &str) -> Vec<Wave>;
    /// The manifest's entry for one part of a scene.
    fn manifest_part(part: &Self::Part) -> serde_json::Value;
    /// The manifest's `parameters` of a build.
    fn manifest_parameters(config: &Self::Config) -> serde_json::Value;
}

/// A design's buffer memory: bits as built and the least the scene needs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BufferMemory {
    pub what: &'static str,
    pub bits: u64,
    pub minimum_bits: u64,
}

impl BufferMemory {
    /// Built over needed, to three decimals.
    pub fn ratio(&self) -> f64 {
        (self.bits as f64 / self.minimum_bits.max(1) as f64 * 1000.0).round() / 1000.0
    }
}
