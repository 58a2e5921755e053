//! `cube` with no subcommand: render the built-in default scene (a head-like
//! phantom, parallel view, composite) with the golden model and the float
//! reference, write both images and their difference to `out/`, and print
//! the run times and the error.

use crate::common::{render_arch, Arch};
use crate::output::write_png;
use anyhow::{Context, Result};
use reference::metrics::{compare, difference};
use scene::volume::Volume;
use scene::Scene;
use std::path::Path;

/// The built-in default scene: a head-like phantom, parallel view, composite.
const DEFAULT_SCENE: &str = include_str!("../../scenes/default.json");

pub fn run() -> Result<()> {
    let scene = Scene::from_json(DEFAULT_SCENE, None).context("built-in default scene")?;
    let vol = Volume::from_spec(&scene.volume, scene.hardware.voxel_bits)?;
    let g = render_arch(&scene, &vol, Arch::Cube4l, reference::DEFAULT_STEP, None)?;
    let r = render_arch(&scene, &vol, Arch::Reference, reference::DEFAULT_STEP, None)?;
    let m = compare(&g.image, &r.image);
    let out = Path::new("out");
    write_png(&out.join("default_cube4l.png"), &g.image)?;
    write_png(&out.join("default_reference.png"), &r.image)?;
    write_png(
        &out.join("default_diff.png"),
        &difference(&g.image, &r.image, 8.0),
    )?;
    let d = scene.volume.render_dims();
    println!(
        "scene: built-in default ({} {}x{}x{}, {:?})",
        scene.volume.builtin.as_deref().unwrap_or("?"),
        d[0],
        d[1],
        d[2],
        scene.mode
    );
    println!(
        "cube4l golden model: {:.3} s ({:.1} M voxels/s)",
        g.seconds,
        g.extra["voxels_per_second"].as_f64().unwrap_or(0.0) / 1e6
    );
    println!(
        "float reference:     {:.3} s (step {} voxel)",
        r.seconds,
        reference::DEFAULT_STEP
    );
    println!(
        "error vs reference:  rel. Euclidean {:.3} %, RMSE {:.5}, PSNR {:.2} dB, max {:.4}",
        m.rel_euclid_pct, m.rmse, m.psnr_db, m.max_abs
    );
    println!("wrote out/default_cube4l.png, out/default_reference.png, out/default_diff.png (difference x8)");
    Ok(())
}
