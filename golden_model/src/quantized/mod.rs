//! The quantized-voxel software path (Mora, Jessel & Caubet, "Accelerating
//! volume rendering with quantized voxels"): object-order rendering of an
//! orthographic view in which every voxel's projection, or splat, comes
//! from a table chosen by the subdivision its projected centre falls in.
//! It is a fast software path with no hardware twin; it computes in
//! floating point.
//!
//! Stages, each timed on its own:
//!
//! 1. **Per volume** (`grid`, §3.1-3.2): the volume regrouped into `B³`
//!    blocks, each with its voxel grid, its quantized normals (`normals`,
//!    8192 directions by default) and its minimum and maximum.
//! 2. **Per view** (`view`): the template hexagon (`hexagon`) and the
//!    projection classes (`projection`, §2.2) or splat lists (`splat`,
//!    §2.3), the shading table over the normal codes, the block order and
//!    which image bands each block reaches.
//! 3. **Per transfer function** (`classify`): colour and opacity tables by
//!    voxel value, which blocks are empty, and in each other block which
//!    voxels can add anything (a byte of flags per row). Changing the
//!    transfer function reruns only this stage and the rendering; a new
//!    view sets only the per-view opacity terms (256 or 65,536 entries).
//! 4. **Rendering** (`traverse`, §3.3): blocks and voxels back to front
//!    (the paper), or front to back with early ray termination.
//!
//! Opacity: a voxel's projection is covered by the rays that cross its
//! cube, on average `1 / (|d_u| + |d_v| + |d_w|)` voxel lengths of them for
//! the unit view direction `d`, so its opacity is the scene's (per voxel
//! length) corrected to that length. A splat's weight, divided by the
//! kernel's integral, sums to one per voxel length along a ray, and a
//! pixel takes opacity `1 − (1 − α)^weight` from it.
//!
//! Modes: voxel projection draws every mode (composite, first-opaque, MIP,
//! MinIP, X-ray): a pixel is either in a voxel's hexagon or not, so it sees
//! a set of voxels whose extreme, sum or front-most member is well defined.
//! Splatting draws composite and X-ray, which weigh each voxel's share of a
//! pixel; a Gaussian footprint has no edge, so "the largest value under
//! this pixel" or "the first opaque voxel" would depend on an arbitrary
//! cut-off, and those modes are refused.

pub mod classify;
pub mod grid;
pub mod hexagon;
pub mod normals;
pub mod projection;
pub mod splat;
pub mod traverse;
pub mod view;

use scene::volume::Volume;
use scene::{CubeError, Image, Mode, Projection, Result, Scene};
use std::time::Instant;

pub use classify::Classes;
pub use grid::Grid;
pub use view::ViewTables;

/// Which of the paper's two methods.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// Voxel projection by quantized positions (§2.2).
    Projection,
    /// Quantized splatting (§2.3).
    Splat,
}

impl Method {
    pub fn name(self) -> &'static str {
        match self {
            Method::Projection => "quantized-projection",
            Method::Splat => "quantized-splat",
        }
    }
}

/// The scene's parameters for one method.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Params {
    pub method: Method,
    /// Subdivisions per side of the pixel square.
    pub n: usize,
    pub normals: u32,
    pub empty_space: scene::EmptySpace,
    pub order: scene::Traversal,
    pub kernel: splat::Kernel,
}

impl Params {
    /// The scene's `quantized` section for `method`; refuses what the
    /// method cannot draw.
    pub fn of(scene: &Scene, method: Method) -> Result<Params> {
        if scene.view.projection != Projection::Parallel {
            return Err(CubeError::View(format!(
                "{} renders orthographic views only (its projection tables hold for every voxel only when all rays are parallel); the scene is perspective",
                method.name()
            )));
        }
        if method == Method::Splat && !matches!(scene.mode, Mode::Composite | Mode::Xray) {
            return Err(CubeError::Scene(format!(
                "mode {:?} unsupported by quantized-splat (composite or xray: a Gaussian splat has no edge to decide which voxels lie under a pixel); quantized-projection draws every mode",
                scene.mode
            )));
        }
        let q = &scene.quantized;
        Ok(Params {
            method,
            n: q.subdivisions.unwrap_or(match method {
                Method::Projection => 64,
                Method::Splat => 32,
            }) as usize,
            normals: q.normals,
            empty_space: q.empty_space,
            order: q.order,
            kernel: splat::Kernel {
                b: q.kernel[0],
                r: q.kernel[1],
            },
        })
    }
}

/// Seconds spent in each stage.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Times {
    /// The grid (per volume).
    pub volume: f64,
    /// The view tables and the classification's per-view terms (per frame).
    pub view: f64,
    /// The classification (per transfer function).
    pub classify: f64,
    pub render: f64,
}

/// Work counters of a frame (Table 3 of the paper, and more).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Stats {
    pub voxels: u64,
    pub blocks: u64,
    /// Blocks the transfer function leaves non-empty.
    pub blocks_live: u64,
    /// Voxels looked at: those of non-empty blocks within reach of the image.
    pub inspected: u64,
    /// Voxels projected or splatted (non-transparent, not hidden).
    pub treated: u64,
    /// Front to back: voxels of blocks skipped because every pixel they
    /// reach was already opaque.
    pub occluded: u64,
    /// Projection classes, or splat subdivisions.
    pub classes: u64,
    /// Table entries (pixel offsets) over all classes or subdivisions.
    pub entries: u64,
}

/// Render `scene` with `method`: the image, the counters and the time of
/// each stage.
pub fn render(scene: &Scene, vol: &Volume, method: Method) -> Result<(Image, Stats, Times)> {
    let params = Params::of(scene, method)?;
    let t = Instant::now();
    let grid = Grid::new(vol, params.normals);
    let volume = t.elapsed().as_secs_f64();
    let t = Instant::now();
    let mut classes = Classes::new(scene, &grid, &params);
    let classify = t.elapsed().as_secs_f64();
    let (img, stats, mut times, _) = frame(scene, &grid, &mut classes, &params)?;
    times.volume = volume;
    times.classify = classify;
    Ok((img, stats, times))
}

/// One frame at the scene's view, from a grid and a classification built
/// before: the view tables with the classification's per-view terms, and
/// the rendering (the volume and classification times are 0). The view
/// tables are returned for [`reclassify`].
pub fn frame(
    scene: &Scene,
    grid: &Grid,
    classes: &mut Classes,
    params: &Params,
) -> Result<(Image, Stats, Times, ViewTables)> {
    let camera = scene.camera();
    let t = Instant::now();
    let view = ViewTables::new(scene, &camera, grid, params);
    classes.view(grid, &view);
    let view_s = t.elapsed().as_secs_f64();
    let t = Instant::now();
    let (img, stats) = traverse::render(scene.mode, grid, &view, classes, params);
    let times = Times {
        view: view_s,
        render: t.elapsed().as_secs_f64(),
        ..Times::default()
    };
    Ok((img, stats, times, view))
}

/// A new transfer function at the same view: classification and
/// rendering. Classification reads the blocks' minima and maxima and the
/// voxels of the blocks left live, never the rest of the volume.
pub fn reclassify(
    scene: &Scene,
    grid: &Grid,
    view: &ViewTables,
    params: &Params,
) -> (Image, Stats, Times) {
    let t = Instant::now();
    let mut classes = Classes::new(scene, grid, params);
    classes.view(grid, view);
    let classify = t.elapsed().as_secs_f64();
    let t = Instant::now();
    let (img, stats) = traverse::render(scene.mode, grid, view, &classes, params);
    let times = Times {
        classify,
        render: t.elapsed().as_secs_f64(),
        ..Times::default()
    };
    (img, stats, times)
}
