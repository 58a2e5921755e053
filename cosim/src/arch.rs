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

/// An architecture, as the flows see it. A frame runs in *parts* the
/// hardware renders one after another with one build: Cube-4L's sweeps,
/// Cube-3's base planes.
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

    /// One part: its plan, the hardware's configuration and the golden
    /// model's tables.
    type Part: Send + Sync;
    /// A part's base plane, from the golden model or the RTL.
    type Base: BasePixels + Clone + Send;

    /// The scene's parts, for a volume of `dims` (after any crop).
    fn parts(scene: &Scene, camera: &Camera, dims: [usize; 3]) -> Result<Vec<Self::Part>, String>;
    /// The units the part's hardware leaves out.
    fn left_out(part: &Self::Part) -> Vec<LeftOut>;
    /// Whether the voxels live in external memory.
    fn external(part: &Self::Part) -> bool;
    /// The memory modules' contents for the part, module by module.
    fn modules(part: &Self::Part, vol: &Volume) -> Vec<Vec<u16>>;
    /// The part's Verilog as the kit exports it; `preload` initialises
    /// on-chip voxel memory (simulation only: hardware loads it through the
    /// load port). The tables start empty: the host writes them.
    fn verilog(part: &Self::Part, preload: Option<&[Vec<u16>]>) -> Result<String, String>;
    /// What the host writes through the host port before the part starts:
    /// its tables, then its registers (`golden_model::host`). Every engine
    /// gets the same writes, so traces line up cycle for cycle.
    fn loads(part: &Self::Part) -> Vec<Write>;
    /// The pixel bus: what a frame's run logs, and the pulses that end it.
    fn bus(part: &Self::Part) -> (Stop, Vec<Group>);
    /// Run the part in rust-hdl's simulator (memory preloaded, then the
    /// host's `loads` one a clock, then `start`), logging
    /// [`Arch::bus`] as the Verilog harness does; the records and the clock
    /// count from `start`.
    fn rust_hdl(
        part: &Self::Part,
        modules: &[Vec<u16>],
        loads: &[Write],
        trace: Option<&Path>,
    ) -> Result<(Vec<Record>, u64), String>;
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
    /// The buffer memory the part's hardware builds (not the voxel memory),
    /// in bits, against the least the scene needs, and what it is.
    fn buffer_memory(parts: &[Self::Part]) -> BufferMemory;
    /// Clocks of a frame of an `n`³ volume on the parts' hardware, where
    /// the architecture can project them.
    fn projected_clocks(n: u64, parts: &[Self::Part]) -> Option<u64>;
    /// The signal groups of a trace of the part, under `top` (the design's
    /// scope: `uut` in rust-hdl, `TOP.top` in Verilator, `tb.uut` in Icarus).
    fn waves(part: &Self::Part, top: &str) -> Vec<Wave>;
    /// The manifest's entry for one part.
    fn manifest_part(part: &Self::Part) -> serde_json::Value;
    /// The manifest's `parameters`.
    fn manifest_parameters(
        scene: &Scene,
        dims: [usize; 3],
        parts: &[Self::Part],
    ) -> serde_json::Value;
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
