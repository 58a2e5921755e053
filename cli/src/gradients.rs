//! `cube gradients`: the Cube-3 paper's Fig. 15. The built-in volume-sampled
//! sphere turns about the vertical axis; at each angle, every cast ray's
//! threshold crossing (interpolated between samples, or the first sample
//! past it) gives one gradient per ABC neighbourhood (6, 10, 12, 26), and
//! the mean angle between the estimated normal (the negated gradient) and
//! the sphere's analytic normal is reported per neighbourhood, with the
//! basis correction and without it (the 12 needs none), with a plot.

use crate::common::{angle_sweep, load};
use crate::output::Files;
use crate::plot::{angle_plot, Curve, PLOT_H, PLOT_W};
use anyhow::{bail, Context, Result};
use golden_model::cube3::surface::{crossings, At, ALL};
use plotters::style::colors::{BLUE, GREEN, MAGENTA, RED};
use serde_json::json;
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct GradientsArgs {
    /// A scene with the built-in sphere (its analytic normals are known).
    #[arg(long)]
    scene: PathBuf,
    /// First, last and step angle in degrees (rotate_deg[1]).
    #[arg(long, num_args = 3, default_values_t = [0.0, 90.0, 5.0], allow_negative_numbers = true)]
    range: Vec<f64>,
    /// Threshold in voxel units; default half of full scale.
    #[arg(long)]
    threshold: Option<u32>,
    /// Where a ray's crossing is taken: `interpolated` between the samples
    /// on either side of the threshold (as §6.2 measures, at the surface),
    /// or the `first` sample past it.
    #[arg(long, value_enum, default_value_t = CrossingAt::Interpolated)]
    crossing: CrossingAt,
    #[arg(long)]
    json: Option<PathBuf>,
    /// The curves (PNG), with the paper's 3° for the 12.
    #[arg(long)]
    plot: Option<PathBuf>,
}

#[derive(Clone, Copy, clap::ValueEnum)]
enum CrossingAt {
    Interpolated,
    First,
}

/// The neighbourhoods whose basis correction can be left out (the 12 has
/// none), by index in `ALL`.
const CORRECTED: [usize; 3] = [0, 1, 3];

/// The paper's Fig. 15: the 12's error, "flat at about 3°".
const PAPER_12_DEG: f64 = 3.0;

pub fn run(args: GradientsArgs) -> Result<()> {
    let angles = angle_sweep(&args.range)?;
    let (base_scene, vol) = load(&args.scene)?;
    let mut files = Files::default();
    files.scene("--scene", &args.scene, &base_scene)?;
    for (flag, path) in [("--json", &args.json), ("--plot", &args.plot)] {
        if let Some(p) = path {
            files.output(flag, p)?;
        }
    }
    let scene = &base_scene;
    if scene.volume.builtin.as_deref() != Some("sphere") {
        bail!("volume: gradients needs the built-in sphere (its analytic normals)");
    }
    if scene.view.projection != scene::Projection::Parallel {
        bail!("view.projection: gradients turns a parallel view");
    }
    let full = golden_model::fixed::max_of(scene.hardware.voxel_bits);
    let threshold = args.threshold.unwrap_or(full.div_ceil(2));
    if threshold == 0 || threshold > full {
        bail!("--threshold {threshold} must lie in 1..={full}");
    }
    // The sphere is built over the whole volume: a crop moves its centre
    // into the cropped frame, by the crop's offset.
    let (centre, _) = scene::volume::sphere_geometry(scene.volume.dims);
    let offset = scene.volume.crop.map_or([0; 3], |c| c.offset);
    let centre = centre - glam::DVec3::from_array(offset.map(|o| o as f64));
    let base = scene.view.rotate_deg.unwrap_or([0.0; 3]);
    let at = match args.crossing {
        CrossingAt::Interpolated => At::Interpolated,
        CrossingAt::First => At::FirstSample,
    };
    println!(
        "mean angle to the analytic normal, degrees; crossings {}; u: without the basis correction",
        match at {
            At::Interpolated => "interpolated at the threshold",
            At::FirstSample => "at the first sample past the threshold",
        }
    );
    println!(
        "{:>7} {:>7} {:>7} {:>7} {:>7} {:>7} {:>7} {:>7} {:>9}",
        "angle", "6", "10", "12", "26", "6u", "10u", "26u", "crossings"
    );
    let mut rows = Vec::new();
    let mut curves = vec![Vec::new(); 4 + CORRECTED.len()];
    for &a in &angles {
        let scene = base_scene.with(|s| s.view.rotate_deg = Some([base[0], a, base[2]]))?;
        let cam = scene.camera();
        let xs = crossings(&scene, &cam, &vol, threshold, at)?;
        // Per curve: the four corrected, then the uncorrected 6, 10, 26.
        let mut sum = [0.0f64; 7];
        let mut count = [0u64; 7];
        for c in &xs {
            let n = (c.position - centre).normalize_or_zero();
            let estimates = (0..4)
                .map(|j| c.gradients[j])
                .chain(CORRECTED.map(|j| c.uncorrected[j]));
            for (i, g) in estimates.enumerate() {
                if g.length() > 0.0 && n.length() > 0.0 {
                    sum[i] += (-g.normalize()).dot(n).clamp(-1.0, 1.0).acos().to_degrees();
                    count[i] += 1;
                }
            }
        }
        // A mean over no crossings is undefined: the command exists for
        // this figure, so it refuses rather than report one.
        if let Some(j) = (0..4).find(|&j| count[j] == 0) {
            bail!(
                "gradients: at {a}° the {}-neighbourhood has no threshold crossing with a gradient ({} crossings): no mean error to report; a larger sphere or another --threshold gives some",
                ALL[j].count(),
                xs.len()
            );
        }
        let mean: [f64; 7] = std::array::from_fn(|i| sum[i] / count[i].max(1) as f64);
        println!(
            "{a:>7.2} {:>7.3} {:>7.3} {:>7.3} {:>7.3} {:>7.3} {:>7.3} {:>7.3} {:>9}",
            mean[0],
            mean[1],
            mean[2],
            mean[3],
            mean[4],
            mean[5],
            mean[6],
            xs.len()
        );
        for (curve, m) in curves.iter_mut().zip(mean) {
            curve.push((a, m));
        }
        rows.push(json!({
            "angle": a,
            "crossings": xs.len(),
            "mean_error_deg": {"6": mean[0], "10": mean[1], "12": mean[2], "26": mean[3]},
            "uncorrected_mean_error_deg": {"6": mean[4], "10": mean[5], "26": mean[6]},
        }));
    }
    if let Some(p) = &args.plot {
        let png = plot(&curves, angles[0], angles[angles.len() - 1]).context("drawing the plot")?;
        files.png_rgb8(p, PLOT_W, PLOT_H, png)?;
    }
    if let Some(j) = &args.json {
        files.json(
            j,
            &json!({
                "scene": args.scene.display().to_string(),
                "threshold": threshold,
                "crossing": match at {
                    At::Interpolated => "interpolated",
                    At::FirstSample => "first sample",
                },
                "neighbourhoods": ALL.map(|n| n.count()),
                "paper_12_deg": PAPER_12_DEG,
                "rows": rows,
            }),
        )?;
    }
    files.commit()
}

/// The curves (mean error in degrees against angle): the corrected ones
/// thick, the uncorrected thin in their neighbourhood's colour, and the
/// paper's level for the 12.
fn plot(curves: &[Vec<(f64, f64)>], from: f64, to: f64) -> Result<Vec<u8>> {
    let colours = [RED, BLUE, GREEN, MAGENTA];
    let curves: Vec<Curve> = curves
        .iter()
        .enumerate()
        .map(|(i, c)| {
            let (j, corrected) = if i < 4 {
                (i, true)
            } else {
                (CORRECTED[i - 4], false)
            };
            Curve {
                label: format!(
                    "{}-neighbourhood{}",
                    ALL[j].count(),
                    if corrected { "" } else { ", uncorrected" }
                ),
                colour: colours[j],
                width: if corrected { 2 } else { 1 },
                points: c.clone(),
            }
        })
        .collect();
    angle_plot(
        "ABC gradient error against the analytic sphere normal",
        "mean angular error (degrees)",
        &curves,
        &[("paper: the 12, about 3°".into(), PAPER_12_DEG)],
        from,
        to,
    )
}
