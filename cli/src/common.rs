//! Helpers shared by several subcommands: checking the reference step,
//! loading a scene and its volume, rendering with either architecture and
//! reporting the error against the reference.

use anyhow::{bail, Result};
use clap::ValueEnum;
use reference::metrics::ErrorMetrics;
use scene::volume::Volume;
use scene::Image;
use scene::Scene;
use serde_json::{json, Value};
use std::path::Path;
use std::time::Instant;

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Arch {
    Cube4l,
    /// The Cube-3 golden model (Sheared3D of the paper's §6).
    Cube3,
    /// Cube-3's discrete rays with exact tri-linear samples, in float.
    True3d,
    /// Cube-3's sheared tri-linear interpolation in float: the golden model
    /// without quantization (separates interpolation from quantization).
    ShearedFloat,
    Reference,
}

impl Arch {
    pub fn name(self) -> &'static str {
        match self {
            Arch::Cube4l => "cube4l",
            Arch::Cube3 => "cube3",
            Arch::True3d => "true3d",
            Arch::ShearedFloat => "sheared-float",
            Arch::Reference => "reference",
        }
    }
}

pub fn check_step(step: f64) -> Result<()> {
    if !(0.01..=4.0).contains(&step) {
        bail!("--ref-step {step} must lie in [0.01, 4]");
    }
    Ok(())
}

/// The angles of `--range FROM TO STEP`: `FROM + i·STEP` up to `TO`, so
/// each is exact to one rounding and the sweep ends even where
/// `FROM + STEP == FROM` in floating point.
pub fn angle_sweep(range: &[f64]) -> Result<Vec<f64>> {
    let [from, to, step] = [range[0], range[1], range[2]];
    let steps = (to - from) / step;
    let ok = from.abs() <= 1e6
        && to.abs() <= 1e6
        && step.is_finite()
        && step > 0.0
        && (0.0..=3600.0).contains(&steps);
    if !ok {
        bail!(
            "--range FROM TO STEP needs FROM and TO within ±1e6 degrees, STEP > 0, TO >= FROM and at most 3600 steps"
        );
    }
    Ok((0..=(steps + 1e-9).floor() as u32)
        .map(|i| from + i as f64 * step)
        .collect())
}

pub fn load(scene_path: &Path) -> Result<(Scene, Volume)> {
    let scene = Scene::load(scene_path)?;
    let vol = Volume::from_spec(&scene.volume, scene.hardware.voxel_bits)?;
    Ok((scene, vol))
}

/// The scene file's name (without its directory), as the exported designs
/// are named.
pub fn scene_name(scene_path: &Path) -> String {
    scene_path
        .file_name()
        .map(|n| n.to_string_lossy().to_string())
        .unwrap_or_default()
}

pub struct Rendered {
    pub image: Image,
    pub seconds: f64,
    pub extra: Value,
}

/// Render with `arch`; `gradient` overrides the scene's Cube-3 neighbourhood
/// (Cube-3 and True3D).
pub fn render_arch(
    scene: &Scene,
    vol: &Volume,
    arch: Arch,
    ref_step: f64,
    gradient: Option<u32>,
) -> Result<Rendered> {
    let t = Instant::now();
    match arch {
        Arch::Cube4l => {
            let (image, frame) = golden_model::cube4l::render_image(scene, vol)?;
            let seconds = t.elapsed().as_secs_f64();
            let s = frame.stats;
            Ok(Rendered {
                image,
                seconds,
                extra: json!({
                    "sweeps": frame.plan.sweeps.len(),
                    "voxels": s.voxels,
                    "voxels_shaded": s.shaded,
                    "voxels_terminated": s.terminated,
                    "saturations": s.saturations,
                    "voxels_per_second": s.voxels as f64 / seconds,
                }),
            })
        }
        Arch::Cube3 => {
            let n = golden_model::cube3::neighbourhood(scene, gradient)?;
            let (image, frame) = golden_model::cube3::render_image(scene, vol, n)?;
            let seconds = t.elapsed().as_secs_f64();
            let s = frame.stats;
            let v = &frame.plan.views[0];
            Ok(Rendered {
                image,
                seconds,
                extra: json!({
                    "gradient": n.count(),
                    "base_planes": frame.plan.views.len(),
                    "offset": v.offset,
                    "weight_bits": frame.widths.weight_bits,
                    "sample_bits": frame.widths.sample_bits,
                    "gradient_bits": frame.widths.gradient_bits,
                    "pipelines": frame.pipelines,
                    "trilin_left_out": frame.plan.views.iter().all(|v| v.on_grid),
                    "rays": s.rays,
                    "samples": s.samples,
                    "samples_interpolated": s.interpolated,
                    "samples_shaded": s.shaded,
                    "samples_terminated": s.terminated,
                    "gradient_saturations": s.gradient_saturations,
                    "composite_saturations": s.composite_saturations,
                    "weight_clamps": s.weight_clamps,
                    "samples_per_second": s.samples as f64 / seconds,
                }),
            })
        }
        Arch::True3d | Arch::ShearedFloat => {
            let cam = scene.camera()?;
            let n = gradient.unwrap_or(scene.cube3.gradient);
            let interp = if arch == Arch::True3d {
                reference::true3d::Interp::Exact
            } else {
                reference::true3d::Interp::Sheared
            };
            let image = reference::true3d::render(scene, &cam, vol, n, interp)?;
            Ok(Rendered {
                image,
                seconds: t.elapsed().as_secs_f64(),
                extra: json!({ "gradient": n }),
            })
        }
        Arch::Reference => {
            let cam = scene.camera()?;
            let image = reference::render(scene, &cam, vol, ref_step);
            Ok(Rendered {
                image,
                seconds: t.elapsed().as_secs_f64(),
                extra: json!({ "step": ref_step }),
            })
        }
    }
}

pub fn error_json(m: &ErrorMetrics) -> Value {
    json!({
        "rel_euclid_pct": m.rel_euclid_pct,
        "rmse": m.rmse,
        "psnr_db": if m.psnr_db.is_finite() { json!(m.psnr_db) } else { json!(null) },
        "max_abs": m.max_abs,
        "foreground_pixels": m.foreground_pixels,
    })
}
