//! `cube render`: render a scene with the Cube-4L golden model or the float
//! reference, optionally compare it with the reference, and write the image,
//! a difference image, the first sweep's base plane and a JSON report.

use crate::common::{check_step, error_json, error_line, load, render_arch, render_repeat};
use crate::methods::Arch;
use crate::output::Files;
use anyhow::{bail, Result};
use reference::metrics::{compare, difference};
use scene::volume::{Ordered, Volume};
use scene::Image;
use scene::Scene;
use serde_json::json;
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct RenderArgs {
    #[arg(long)]
    scene: PathBuf,
    #[arg(long, value_enum, default_value = "cube4l")]
    arch: Arch,
    /// Final image (PNG).
    #[arg(long)]
    out: Option<PathBuf>,
    /// Run time, image size and (with a reference) error as JSON.
    #[arg(long)]
    json: Option<PathBuf>,
    /// Also render the float reference and report the error against it.
    #[arg(long)]
    compare_reference: bool,
    /// Difference image against the reference (implies --compare-reference).
    #[arg(long)]
    diff: Option<PathBuf>,
    /// Reference sample step along the ray, in voxel lengths.
    #[arg(long, default_value_t = reference::DEFAULT_STEP, allow_negative_numbers = true)]
    ref_step: f64,
    /// Cube-3 and True3D: ABC gradient neighbourhood (6, 10, 12 or 26);
    /// default: the scene's `cube3.gradient`, else 12.
    #[arg(long)]
    gradient: Option<u32>,
    /// Cube-4L only: write the base plane of the first sweep (PNG).
    #[arg(long)]
    base_plane: Option<PathBuf>,
    /// Render K times and report the median of each time (1..=1000).
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=1000))]
    repeat: u32,
}

pub fn run(args: RenderArgs) -> Result<()> {
    let RenderArgs {
        scene: scene_path,
        arch,
        out,
        json: json_path,
        compare_reference,
        diff,
        ref_step,
        base_plane,
        gradient,
        repeat,
    } = args;
    if gradient.is_some() && !arch.takes_gradient() {
        bail!("--gradient needs --arch cube3, true3d or sheared-float");
    }
    let with_ref = compare_reference || diff.is_some();
    check_step(ref_step)?;
    if base_plane.is_some() && arch != Arch::Cube4l {
        bail!("--base-plane needs --arch cube4l");
    }
    let (scene, vol) = load(&scene_path)?;
    let mut files = Files::default();
    files.scene("--scene", &scene_path, &scene)?;
    for (flag, path) in [
        ("--out", &out),
        ("--json", &json_path),
        ("--diff", &diff),
        ("--base-plane", &base_plane),
    ] {
        if let Some(p) = path {
            files.output(flag, p)?;
        }
    }
    let r = render_repeat(&scene, &vol, arch, ref_step, gradient, repeat as usize)?;
    println!("{}: {:.3} s", arch.name(), r.seconds);
    if matches!(arch, Arch::QuantizedProjection | Arch::QuantizedSplat) {
        let d = &r.extra;
        let ms = |k: &str| d[k].as_f64().unwrap_or(0.0) * 1e3;
        println!(
            "  per volume {:.1} ms; per frame {:.2} ms (view {:.2}, render {:.2}); after a transfer-function change {:.2} ms (classify {:.2})",
            ms("volume_prep_seconds"),
            ms("frame_seconds"),
            ms("view_prep_seconds"),
            ms("render_seconds"),
            ms("tf_change_seconds"),
            ms("classify_seconds")
        );
        let pct =
            |k: &str| 100.0 * d[k].as_f64().unwrap_or(0.0) / d["voxels"].as_f64().unwrap_or(1.0);
        println!(
            "  voxels inspected {} ({:.1} %), treated {} ({:.1} %), skipped hidden {}; {} classes, {} table entries",
            d["voxels_inspected"],
            pct("voxels_inspected"),
            d["voxels_treated"],
            pct("voxels_treated"),
            d["voxels_occluded"],
            d["classes"],
            d["table_entries"]
        );
    }
    let mut report = json!({
        "arch": arch.name(),
        "scene": scene_path.display().to_string(),
        "seconds": r.seconds,
        "image": [r.image.width, r.image.height],
        "details": r.extra,
    });
    if with_ref {
        let rr = render_arch(&scene, &Ordered::new(&vol), Arch::Reference, ref_step, None)?;
        let m = compare(&r.image, &rr.image);
        println!("reference: {:.3} s; {}", rr.seconds, error_line(&m));
        report["error"] = error_json(&m);
        report["reference_seconds"] = json!(rr.seconds);
        if let Some(d) = diff {
            files.png(&d, &difference(&r.image, &rr.image, 8.0))?;
        }
    }
    if let Some(p) = base_plane {
        let (frame_img, _) = base_plane_image(&scene, &vol)?;
        files.png(&p, &frame_img)?;
    }
    if let Some(o) = out {
        files.png(&o, &r.image)?;
    }
    if let Some(j) = json_path {
        files.json(&j, &report)?;
    }
    // Every output lands now, or none does.
    files.commit()
}

/// The first sweep's base plane as an image (scaled to the display range).
fn base_plane_image(scene: &Scene, vol: &Volume) -> Result<(Image, usize)> {
    let cam = scene.camera();
    let frame = golden_model::cube4l::render(scene, &cam, vol)?;
    let b = &frame.bases[0];
    let depth = frame.plan.sweeps[0].dims[2];
    let hw = scene.hardware;
    let mut img = Image::black(b.width as u32, b.height as u32);
    for (o, p) in img.rgb.iter_mut().zip(&b.pixels) {
        *o = golden_model::common::warp::to_rgb(
            scene.mode,
            p.map(|c| c as f64),
            hw.rgba_bits,
            hw.voxel_bits,
            depth,
        );
    }
    Ok((img, frame.bases.len()))
}
