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
    Reference,
}

pub fn check_step(step: f64) -> Result<()> {
    if !(0.01..=4.0).contains(&step) {
        bail!("--ref-step {step} must lie in [0.01, 4]");
    }
    Ok(())
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

pub fn render_arch(scene: &Scene, vol: &Volume, arch: Arch, ref_step: f64) -> Result<Rendered> {
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
