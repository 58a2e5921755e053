//! `cube angles`: error and run time of the golden model against the
//! reference while a parallel view turns about the vertical axis (the Cube-3
//! §6 experiment), one row per angle.

use crate::common::{check_step, error_json, load, render_arch, Arch};
use crate::output::write_json;
use anyhow::{bail, Result};
use reference::metrics::compare;
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
}

pub fn run(args: AnglesArgs) -> Result<()> {
    let AnglesArgs {
        scene: scene_path,
        range,
        ref_step,
        json: json_path,
    } = args;
    check_step(ref_step)?;
    let [from, to, step] = [range[0], range[1], range[2]];
    // Angles are from + i * step, so each is exact to one rounding and the
    // sweep ends even where from + step == from in floating point.
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
    let (mut scene, vol) = load(&scene_path)?;
    let base = scene.view.rotate_deg.unwrap_or([0.0; 3]);
    if scene.view.projection != scene::Projection::Parallel {
        bail!("angles turns a parallel view; the scene is perspective");
    }
    let mut rows = Vec::new();
    println!(
        "{:>7} {:>10} {:>10} {:>10} {:>9} {:>7}",
        "angle", "cube4l s", "ref s", "rel.eucl%", "PSNR dB", "sweep"
    );
    for i in 0..=(steps + 1e-9).floor() as u32 {
        let a = from + i as f64 * step;
        scene.view.rotate_deg = Some([base[0], a, base[2]]);
        let g = render_arch(&scene, &vol, Arch::Cube4l, ref_step, None)?;
        let r = render_arch(&scene, &vol, Arch::Reference, ref_step, None)?;
        let m = compare(&g.image, &r.image);
        let cam = scene.camera()?;
        let plan = golden_model::cube4l::plan::Plan::new(&scene, &cam)?;
        let axis = ["u", "v", "w"][plan.sweeps[0].axis()];
        println!(
            "{a:>7.2} {:>10.3} {:>10.3} {:>10.3} {:>9.2} {:>7}",
            g.seconds, r.seconds, m.rel_euclid_pct, m.psnr_db, axis
        );
        rows.push(json!({"angle": a, "cube4l_seconds": g.seconds, "reference_seconds": r.seconds, "major_axis": axis, "error": error_json(&m)}));
    }
    let worst = rows
        .iter()
        .map(|r| r["error"]["rel_euclid_pct"].as_f64().unwrap())
        .fold(0.0, f64::max);
    println!("largest rel. Euclidean error: {worst:.3} %");
    if let Some(j) = json_path {
        write_json(
            &j,
            &json!({"scene": scene_path.display().to_string(), "rows": rows, "max_rel_euclid_pct": worst}),
        )?;
    }
    Ok(())
}
