//! Classification of the quantized-voxel path (Mora, Jessel & Caubet,
//! §3.1-3.2): colour and opacity tables indexed by voxel value, and which
//! blocks of the two-level grid the transfer function leaves empty. It
//! reads the block minima and maxima, never the voxels, so a new transfer
//! function costs a pass over the value range and the blocks.
//!
//! Per value, `term` holds what a voxel adds, already shaped for the mode,
//! the method and the view:
//!
//! | mode | projection | splat (per unit of kernel weight) |
//! |---|---|---|
//! | composite | `1 − (1 − α)^chord` | `−ln(1 − α) / I` |
//! | first-opaque | `α` (compared with the threshold) | — |
//! | X-ray | `α · chord · m` | `α · m / I` |
//! | MIP, MinIP | `v / vmax` | — |
//!
//! with `chord` the mean length of ray in a voxel (`view::Geometry::chord`),
//! `I` the kernel's integral and `m = |d_major| / depth`, the reference's
//! scale that turns a sum along the ray into the mean per slice of the
//! major axis. With gradient opacity the factor of the voxel's stored
//! gradient magnitude multiplies `α` first, so composite and first-opaque
//! shape `α` per voxel (`Classes::shape`).

use super::grid::{Grid, B, B3, GMAG_LEVELS};
use super::view::ViewTables;
use super::{Method, Params};
use rayon::prelude::*;
use scene::transfer::TransferFn;
use scene::{EmptySpace, Mode, Scene};

// A row of a block is one byte of flags.
const _: () = assert!(B == 8);

/// Largest opacity a splat may take before `−ln(1 − α)` (an opaque
/// voxel's infinite optical depth) is formed.
const ALPHA_CAP: f64 = 1.0 - 1e-7;

#[derive(Debug, Clone)]
pub struct Classes {
    pub mode: Mode,
    pub method: Method,
    /// Per value: what a voxel adds (see the module doc).
    pub term: Vec<f32>,
    /// Per value: the opacity per voxel length before shaping (gradient
    /// opacity only).
    pub alpha: Vec<f32>,
    pub colour: Vec<[f32; 3]>,
    /// Per stored gradient-magnitude level: the gradient-opacity factor,
    /// when the scene has one and the mode uses it.
    pub gradient: Option<Vec<f32>>,
    /// Per block: whether it can add anything.
    pub live: Vec<bool>,
    /// Per row of `B` voxels of a live block (`b·B² + k·B + j`): bit `i`
    /// set when voxel `i` can add anything. The renderer visits set bits
    /// only; a row of zero is skipped whole.
    pub rows: Vec<u8>,
    /// Voxels on the volume's boundary are transparent (the scene needs
    /// gradients, and they have no full neighbourhood).
    pub inner: bool,
    pub shaded: bool,
    /// First-opaque: the opacity at which a voxel counts as opaque.
    pub threshold: f32,
    /// The view's mean chord through a voxel (set by [`Classes::view`]).
    pub chord: f64,
    pub integral: f64,
    /// Per value: the transfer function's opacity per voxel length.
    opacity: Vec<f64>,
    /// X-ray: `m` of the module doc, for the view.
    scale: f64,
}

impl Classes {
    /// Classify for the scene's transfer function: everything but the
    /// per-view terms, which [`Classes::view`] sets.
    pub fn new(scene: &Scene, grid: &Grid, params: &Params) -> Classes {
        let tf = TransferFn::new(scene);
        let vmax = ((1u64 << scene.hardware.voxel_bits) - 1) as usize;
        let mode = scene.mode;
        let opacity: Vec<f64> = (0..=vmax).map(|v| tf.opacity(v as f64)).collect();
        let uses_gradient = tf.has_gradient_opacity() && mode.uses_colour();
        let mut classes = Classes {
            mode,
            method: params.method,
            term: Vec::new(),
            alpha: opacity.iter().map(|&a| a as f32).collect(),
            colour: (0..=vmax)
                .map(|v| tf.colour(v as f64).to_array().map(|c| c as f32))
                .collect(),
            gradient: uses_gradient.then(|| {
                (0..GMAG_LEVELS)
                    .map(|g| tf.gradient_factor(grid.gmag_of(g as u8)) as f32)
                    .collect()
            }),
            live: Vec::new(),
            rows: Vec::new(),
            inner: mode.uses_colour() && (scene.shading.enabled || tf.has_gradient_opacity()),
            shaded: scene.shading.enabled,
            threshold: scene.transfer.opaque_threshold as f32,
            chord: f64::NAN,
            integral: params.kernel.integral(),
            opacity,
            scale: f64::NAN,
        };
        let alpha = &classes.opacity;
        // Which values can add anything: any opacity (first-opaque: enough
        // opacity); MIP any value above zero; MinIP every value.
        let threshold = scene.transfer.opaque_threshold;
        let adds: Vec<bool> = (0..=vmax)
            .map(|v| match mode {
                Mode::Composite | Mode::Xray => alpha[v] > 0.0,
                Mode::FirstOpaque => alpha[v] >= threshold,
                Mode::Mip => v > 0,
                Mode::Minip => true,
            })
            .collect();
        let mut prefix = vec![0u32; vmax + 2];
        for v in 0..=vmax {
            prefix[v + 1] = prefix[v] + adds[v] as u32;
        }
        let any = |lo: usize, hi: usize| prefix[hi + 1] > prefix[lo];
        classes.live = (0..grid.min.len())
            .map(|b| {
                let lo = grid.min[b] as usize;
                let hi = match params.empty_space {
                    EmptySpace::MinMax => grid.max[b] as usize,
                    EmptySpace::Min => vmax,
                };
                any(lo, hi)
            })
            .collect();
        classes.rows = vec![0u8; grid.min.len() * B * B];
        classes
            .rows
            .par_chunks_mut(B * B)
            .enumerate()
            .filter(|(b, _)| classes.live[*b])
            .for_each(|(b, rows)| {
                let e = grid.extent(b);
                let vals = &grid.voxels[b * B3..(b + 1) * B3];
                for k in 0..e[2] {
                    for j in 0..e[1] {
                        let row = &vals[(k * B + j) * B..][..e[0]];
                        rows[k * B + j] = row
                            .iter()
                            .enumerate()
                            .fold(0, |m, (i, v)| m | (adds[v.value as usize] as u8) << i);
                    }
                }
            });
        classes
    }

    /// Set the per-view terms: the opacity corrected to the view's chord
    /// and X-ray's scale to the mean per slice of the major axis.
    pub fn view(&mut self, grid: &Grid, view: &ViewTables) {
        self.chord = view.geom.chord();
        let f = view.geom.forward.abs();
        let axis = if f.x >= f.y && f.x >= f.z {
            0
        } else if f.y >= f.z {
            1
        } else {
            2
        };
        self.scale = f[axis] / grid.dims[axis] as f64;
        let vmax = (self.opacity.len() - 1) as f64;
        self.term = (0..self.opacity.len())
            .map(|v| self.term_of(v, vmax))
            .collect();
    }

    fn term_of(&self, v: usize, vmax: f64) -> f32 {
        let (a, m) = (self.opacity[v], self.scale);
        match self.mode {
            Mode::Composite | Mode::FirstOpaque => self.shape(a) as f32,
            Mode::Xray => match self.method {
                Method::Projection => (a * self.chord * m) as f32,
                Method::Splat => (a * m / self.integral) as f32,
            },
            Mode::Mip | Mode::Minip => (v as f64 / vmax) as f32,
        }
    }

    /// Composite and first-opaque: the term of opacity `a` (per voxel
    /// length, gradient factor applied).
    pub fn shape(&self, a: f64) -> f64 {
        match (self.mode, self.method) {
            (Mode::FirstOpaque, _) => a,
            (_, Method::Projection) => scene::transfer::correct_opacity(a, self.chord),
            (_, Method::Splat) => -(1.0 - a.min(ALPHA_CAP)).ln() / self.integral,
        }
    }
}
