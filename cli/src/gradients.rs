//! `cube gradients`: the Cube-3 paper's Fig. 15. The built-in volume-sampled
//! sphere turns about the vertical axis; at each angle, every cast ray's
//! first sample at or above the threshold gives one gradient per ABC
//! neighbourhood (6, 10, 12, 26), and the mean angle between the estimated
//! normal (the negated gradient) and the sphere's analytic normal is
//! reported per neighbourhood, with a plot.

use crate::common::{angle_sweep, load};
use crate::output::{write_json, write_png_rgb8, Files};
use anyhow::{bail, Context, Result};
use golden_model::cube3::surface::{crossings, ALL};
use plotters::prelude::*;
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
    #[arg(long)]
    json: Option<PathBuf>,
    /// The four curves (PNG).
    #[arg(long)]
    plot: Option<PathBuf>,
}

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
    println!(
        "{:>7} {:>8} {:>8} {:>8} {:>8} {:>9}",
        "angle", "6", "10", "12", "26", "crossings"
    );
    let mut rows = Vec::new();
    let mut curves = vec![Vec::new(); 4];
    for &a in &angles {
        let scene = base_scene.with(|s| s.view.rotate_deg = Some([base[0], a, base[2]]))?;
        let cam = scene.camera();
        let xs = crossings(&scene, &cam, &vol, threshold)?;
        let mut sum = [0.0f64; 4];
        let mut count = [0u64; 4];
        for c in &xs {
            let n = (c.position - centre).normalize_or_zero();
            for (j, g) in c.gradients.iter().enumerate() {
                if g.length() > 0.0 && n.length() > 0.0 {
                    sum[j] += (-g.normalize()).dot(n).clamp(-1.0, 1.0).acos().to_degrees();
                    count[j] += 1;
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
        let mean: [f64; 4] = std::array::from_fn(|j| sum[j] / count[j] as f64);
        println!(
            "{a:>7.2} {:>8.3} {:>8.3} {:>8.3} {:>8.3} {:>9}",
            mean[0],
            mean[1],
            mean[2],
            mean[3],
            xs.len()
        );
        for j in 0..4 {
            curves[j].push((a, mean[j]));
        }
        rows.push(json!({
            "angle": a,
            "crossings": xs.len(),
            "mean_error_deg": {"6": mean[0], "10": mean[1], "12": mean[2], "26": mean[3]},
        }));
    }
    if let Some(p) = &args.plot {
        let png = plot(&curves, angles[0], angles[angles.len() - 1]).context("drawing the plot")?;
        write_png_rgb8(p, PLOT_W, PLOT_H, png)?;
    }
    if let Some(j) = &args.json {
        write_json(
            j,
            &json!({
                "scene": args.scene.display().to_string(),
                "threshold": threshold,
                "neighbourhoods": ALL.map(|n| n.count()),
                "rows": rows,
            }),
        )?;
    }
    Ok(())
}

const PLOT_W: u32 = 800;
const PLOT_H: u32 = 500;

/// Draw the four curves (mean error in degrees against angle).
fn plot(curves: &[Vec<(f64, f64)>], from: f64, to: f64) -> Result<Vec<u8>> {
    // Text needs a font that every machine has: DejaVu Sans, embedded.
    plotters::style::register_font("sans-serif", FontStyle::Normal, dejavu::sans::regular())
        .map_err(|_| anyhow::anyhow!("registering the embedded font"))?;
    let mut buf = vec![0u8; (PLOT_W * PLOT_H * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buf, (PLOT_W, PLOT_H)).into_drawing_area();
        root.fill(&WHITE)?;
        let top = curves.iter().flatten().map(|p| p.1).fold(1.0, f64::max) * 1.1;
        let mut chart = ChartBuilder::on(&root)
            .caption(
                "ABC gradient error against the analytic sphere normal",
                ("sans-serif", 20),
            )
            .margin(15)
            .x_label_area_size(40)
            .y_label_area_size(55)
            .build_cartesian_2d(from..to.max(from + 1.0), 0.0..top)?;
        chart
            .configure_mesh()
            .x_desc("rotation about the vertical axis (degrees)")
            .y_desc("mean angular error (degrees)")
            .draw()?;
        let colours = [RED, BLUE, GREEN, MAGENTA];
        for (j, c) in curves.iter().enumerate() {
            let colour = colours[j];
            chart
                .draw_series(LineSeries::new(c.iter().copied(), colour.stroke_width(2)))?
                .label(format!("{}-neighbourhood", ALL[j].count()))
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(2))
                });
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .draw()?;
        root.present()?;
    }
    Ok(buf)
}
