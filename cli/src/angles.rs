//! `cube angles`: error and run time of an architecture against a yardstick
//! (the reference unless `--against` names another) while a parallel view
//! turns about the vertical axis (the Cube-3 §6 experiment, Fig. 14), one
//! row per angle. For `--arch cube3` and `sheared-float` each row also
//! gives the error against True3D (same rays and neighbourhood, exact
//! tri-linear samples in float).

use crate::common::{angle_sweep, check_step, error_json, load, na_or, render_arch};
use crate::methods::Arch;
use crate::output::Files;
use crate::plot::{angle_plot, Curve, PLOT_H, PLOT_W};
use anyhow::{bail, Result};
use plotters::style::colors::{BLUE, RED};
use reference::metrics::compare;
use scene::volume::Ordered;
use serde_json::json;
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct AnglesArgs {
    #[arg(long)]
    scene: PathBuf,
    /// First, last and step angle in degrees (rotate_deg[1]).
    #[arg(long, num_args = 3, default_values_t = [0.0, 90.0, 5.0], allow_negative_numbers = true)]
    range: Vec<f64>,
    #[arg(long, default_value_t = reference::DEFAULT_STEP, allow_negative_numbers = true)]
    ref_step: f64,
    #[arg(long)]
    json: Option<PathBuf>,
    /// The error curves (PNG): foreground and all-pixel readings, against
    /// the yardstick and (cube3, sheared-float) True3D, with the paper's
    /// bounds when the yardstick is the reference.
    #[arg(long)]
    plot: Option<PathBuf>,
    /// Architecture to compare with the reference.
    #[arg(long, value_enum, default_value = "cube4l")]
    arch: Arch,
    /// Cube-3 and True3D: gradient neighbourhood (default: the scene's).
    #[arg(long)]
    gradient: Option<u32>,
    /// The yardstick: the float reference, or another architecture (for
    /// example `sheared-float`, to measure the fixed-point model's
    /// quantization alone).
    #[arg(long, value_enum, default_value = "reference")]
    against: Arch,
}

pub fn run(args: AnglesArgs) -> Result<()> {
    let AnglesArgs {
        scene: scene_path,
        range,
        ref_step,
        json: json_path,
        plot,
        arch,
        gradient,
        against,
    } = args;
    if arch == against {
        bail!("--arch {} would compare {0} with itself", arch.name());
    }
    if gradient.is_some() && !arch.takes_gradient() {
        bail!("--gradient needs --arch cube3, true3d or sheared-float");
    }
    check_step(ref_step)?;
    let angles = angle_sweep(&range)?;
    let (base_scene, vol) = load(&scene_path)?;
    // Every angle's renders share the traversal-order copies.
    let vol = Ordered::new(&vol);
    let mut files = Files::default();
    files.scene("--scene", &scene_path, &base_scene)?;
    if let Some(j) = &json_path {
        files.output("--json", j)?;
    }
    if let Some(p) = &plot {
        files.output("--plot", p)?;
    }
    let scene = &base_scene;
    let base = scene.view.rotate_deg.unwrap_or([0.0; 3]);
    if scene.view.projection != scene::Projection::Parallel {
        bail!("angles turns a parallel view; the scene is perspective");
    }
    let mut rows = Vec::new();
    let with_true3d = matches!(arch, Arch::Cube3 | Arch::ShearedFloat);
    println!(
        "error of {} against {}: the mean Euclidean RGB distance over the foreground pixels, relative to sqrt 3 (Cube-3 §6); the JSON rows hold the other readings",
        arch.name(),
        if against == Arch::Reference {
            format!("the reference (rays at {ref_step}-voxel steps, tri-linear)")
        } else {
            against.name().to_string()
        }
    );
    println!(
        "{:>7} {:>10} {:>10} {:>10} {:>9} {:>7} {:>12}",
        "angle",
        format!("{} s", arch.name()),
        "ref s",
        "rel.eucl%",
        "PSNR dB",
        "major",
        if with_true3d { "vs true3d %" } else { "" }
    );
    let yardstick_gradient = gradient.filter(|_| against.takes_gradient());
    for &a in &angles {
        let scene = base_scene.with(|s| s.view.rotate_deg = Some([base[0], a, base[2]]))?;
        let g = render_arch(&scene, &vol, arch, ref_step, gradient)?;
        let r = render_arch(&scene, &vol, against, ref_step, yardstick_gradient)?;
        let m = compare(&g.image, &r.image);
        let cam = scene.camera();
        let plan = golden_model::cube4l::plan::Plan::new(&scene, &cam)?;
        let axis = ["u", "v", "w"][plan.sweeps[0].axis()];
        let mut row = json!({"angle": a, "seconds": g.seconds, "reference_seconds": r.seconds, "major_axis": axis, "error": error_json(&m), "details": g.extra});
        let mut t3 = String::new();
        if with_true3d {
            let t = render_arch(&scene, &vol, Arch::True3d, ref_step, gradient)?;
            let mt = compare(&g.image, &t.image);
            t3 = na_or(mt.map(|m| m.rel_euclid_pct), 3);
            row["error_vs_true3d"] = error_json(&mt);
            row["true3d_seconds"] = json!(t.seconds);
            if against == Arch::Reference {
                let mr = compare(&t.image, &r.image);
                row["true3d_error"] = error_json(&mr);
            }
        }
        println!(
            "{a:>7.2} {:>10.3} {:>10.3} {:>10} {:>9} {:>7} {:>12}",
            g.seconds,
            r.seconds,
            na_or(m.map(|m| m.rel_euclid_pct), 3),
            m.map_or("n/a".into(), |m| crate::common::psnr_text(m.psnr_db, 2)),
            axis,
            t3
        );
        rows.push(row);
    }
    // The largest error over the angles that have one.
    let worst = rows
        .iter()
        .filter_map(|r| r["error"]["rel_euclid_pct"].as_f64())
        .reduce(f64::max);
    println!(
        "largest rel. Euclidean error: {}",
        worst.map_or("n/a".into(), |w| format!("{w:.3} %"))
    );
    if let Some(p) = &plot {
        let png = plot_rows(&rows, arch, against, &angles)?;
        files.png_rgb8(p, PLOT_W, PLOT_H, png)?;
    }
    if let Some(j) = json_path {
        let worst = worst.map_or(json!("n/a"), |w| json!(w));
        files.json(
            &j,
            &json!({"scene": scene_path.display().to_string(), "arch": arch.name(), "against": against.name(), "rows": rows, "max_rel_euclid_pct": worst}),
        )?;
    }
    files.commit()
}

/// The rows' errors as curves: thick for the foreground reading, thin for
/// all pixels; red against the yardstick, blue against True3D. The paper's
/// bounds (§6: < 1.3 % against VolRen, < 0.3 % against True3D) are drawn
/// when the yardstick is the reference and True3D is measured.
fn plot_rows(
    rows: &[serde_json::Value],
    arch: Arch,
    against: Arch,
    angles: &[f64],
) -> Result<Vec<u8>> {
    let curve = |key: &str, reading: &str| -> Vec<(f64, f64)> {
        rows.iter()
            .filter_map(|r| Some((r["angle"].as_f64()?, r[key][reading].as_f64()?)))
            .collect()
    };
    let mut curves = Vec::new();
    let mut levels = Vec::new();
    for (key, name, colour) in [
        ("error", against.name(), RED),
        ("error_vs_true3d", "true3d", BLUE),
    ] {
        for (reading, what, width) in [
            ("rel_euclid_pct", "foreground", 2),
            ("rel_euclid_all_pct", "all pixels", 1),
        ] {
            let points = curve(key, reading);
            if !points.is_empty() {
                curves.push(Curve {
                    label: format!("against {name}, {what}"),
                    colour,
                    width,
                    points,
                });
            }
        }
    }
    if against == Arch::Reference && rows.iter().any(|r| !r["error_vs_true3d"].is_null()) {
        levels.push(("paper: < 1.3 % against VolRen".to_string(), 1.3));
        levels.push(("paper: < 0.3 % against True3D".to_string(), 0.3));
    }
    angle_plot(
        &format!("{}: relative Euclidean RGB error (Cube-3 §6)", arch.name()),
        "error (% of sqrt 3)",
        &curves,
        &levels,
        angles[0],
        angles[angles.len() - 1],
    )
}
