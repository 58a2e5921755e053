//! `cube` with no subcommand: the kit's first image. It renders the built-in
//! default scene (`scenes/default.json`: the built-in `head`, 96³, parallel
//! view, composite, Phong-shaded) three ways — the float reference, the
//! Cube-4L golden model and the Cube-3 golden model — and writes one
//! labelled overview, `out/default.png`: the three renders, each with its
//! run time and its error against the reference, and each golden model's
//! per-pixel difference from the reference on a stated colour scale. The
//! renders are also written alone (`out/default_reference.png`,
//! `out/default_cube4l.png`, `out/default_cube3.png`), and a summary is
//! printed: one line per method, and which image is the yardstick.
//!
//! The yardstick is the float reference (f64, tri-linear interpolation,
//! 0.25-voxel steps, the scene's exact transfer function and shading): the
//! golden models compute what the hardware computes, in its fixed-point
//! widths, and their distance from the reference is their error.

use crate::common::{render_arch, Rendered};
use crate::methods::Arch;
use crate::output::Files;
use anyhow::{Context, Result};
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use reference::metrics::{compare, ErrorMetrics};
use scene::volume::{Ordered, Volume};
use scene::{Image, Scene};
use std::path::Path;
use std::time::Instant;

/// The built-in default scene: the built-in head, parallel view, composite.
const DEFAULT_SCENE: &str = include_str!("../../scenes/default.json");

/// One render of the default scene.
struct Method {
    /// The name on the overview and in the summary.
    name: &'static str,
    /// What it is, in a few words.
    what: &'static str,
    file: &'static str,
    out: Rendered,
    /// Against the reference (`None` for the reference itself).
    error: Option<ErrorMetrics>,
}

pub fn run() -> Result<()> {
    let scene = Scene::from_json(DEFAULT_SCENE, None).context("built-in default scene")?;
    // Every output is checked before the work, and they land together.
    let out = Path::new("out");
    let mut files = Files::default();
    for f in [
        "default.png",
        "default_reference.png",
        "default_cube4l.png",
        "default_cube3.png",
    ] {
        files.output("the default run's output", &out.join(f))?;
    }
    let t = Instant::now();
    let vol = Volume::from_spec(&scene.volume, scene.hardware.voxel_bits)?;
    let volume_s = t.elapsed().as_secs_f64();
    let step = reference::DEFAULT_STEP;
    let reference = render_arch(&scene, &Ordered::new(&vol), Arch::Reference, step, None)?;
    let mut methods = vec![Method {
        name: "float reference",
        what: "f64, tri-linear, 0.25-voxel steps",
        file: "default_reference.png",
        out: reference,
        error: None,
    }];
    for (arch, name, what, file) in [
        (
            Arch::Cube4l,
            "Cube-4L golden model",
            "ray-slice sweep, fixed point",
            "default_cube4l.png",
        ),
        (
            Arch::Cube3,
            "Cube-3 golden model",
            "sheared tri-linear rays, fixed point",
            "default_cube3.png",
        ),
    ] {
        let out = render_arch(&scene, &Ordered::new(&vol), arch, step, None)?;
        let error = Some(
            compare(&out.image, &methods[0].out.image)
                .context("the built-in scene rendered no foreground pixels")?,
        );
        methods.push(Method {
            name,
            what,
            file,
            out,
            error,
        });
    }

    for m in &methods {
        files.png(&out.join(m.file), &m.out.image)?;
    }
    let (w, h, rgb) = overview(&scene, &methods)?;
    files.png_rgb8(&out.join("default.png"), w, h, rgb)?;
    files.commit()?;

    let d = scene.volume.render_dims();
    let hw = &scene.hardware;
    println!(
        "scene: built-in default, {} {}x{}x{} ({}-bit voxels, built in {:.2} s), {}{}, {}x{} image",
        scene.volume.builtin.as_deref().unwrap_or("?"),
        d[0],
        d[1],
        d[2],
        hw.voxel_bits,
        volume_s,
        format!("{:?}", scene.mode).to_lowercase(),
        if scene.shading.enabled {
            ", shaded"
        } else {
            ""
        },
        scene.image[0],
        scene.image[1]
    );
    for m in &methods {
        match &m.error {
            None => println!("  {:<22} {:>7.3} s   the yardstick", m.name, m.out.seconds),
            Some(e) => println!(
                "  {:<22} {:>7.3} s   rel. Euclidean {:.2} %, PSNR {}, max {:.3}",
                m.name,
                m.out.seconds,
                e.rel_euclid_pct,
                crate::common::psnr_db_text(e.psnr_db, 1),
                e.max_abs
            ),
        }
    }
    println!(
        "the yardstick is the float reference: f64, tri-linear interpolation, {step}-voxel steps,\n\
         the exact transfer function and Phong shading. The golden models compute what the\n\
         hardware computes ({}-bit voxels, {} fractional bits, {}-bit RGBA); their error is their\n\
         distance from it (rel. Euclidean: mean RGB distance / sqrt 3 over the foreground).",
        hw.voxel_bits, hw.frac_bits, hw.rgba_bits
    );
    println!(
        "wrote out/default.png (the overview: renders, times, errors, differences), {}",
        methods
            .iter()
            .map(|m| format!("out/{}", m.file))
            .collect::<Vec<_>>()
            .join(", ")
    );
    Ok(())
}

/// Per-pixel RGB distance from the reference over `sqrt(3)`, in [0, 1]:
/// the quantity whose mean over the foreground is the relative Euclidean
/// error.
fn distance(img: &Image, reference: &Image) -> Vec<f64> {
    img.rgb
        .iter()
        .zip(&reference.rgb)
        .map(|(a, b)| {
            let d: f64 = (0..3).map(|i| (a[i] - b[i]).powi(2)).sum();
            (d / 3.0).sqrt()
        })
        .collect()
}

/// The full scale of the difference panels: the smallest round value at
/// or above the 99th percentile of the panels' non-zero distances (a few
/// outliers saturate rather than flatten the rest).
fn full_scale(maps: &[Vec<f64>]) -> f64 {
    let mut all: Vec<f64> = maps
        .iter()
        .flatten()
        .copied()
        .filter(|&e| e > 0.0)
        .collect();
    if all.is_empty() {
        return 0.05;
    }
    all.sort_by(f64::total_cmp);
    let p99 = all[(all.len() - 1) * 99 / 100];
    [0.02, 0.05, 0.1, 0.2, 0.5]
        .into_iter()
        .find(|&s| s >= p99)
        .unwrap_or(1.0)
}

/// The colour of `t` in [0, 1] on a perceptually ordered map from black
/// (no difference) through purple and orange to pale yellow (matplotlib's
/// "inferno", sampled at nine points).
fn inferno(t: f64) -> [u8; 3] {
    const MAP: [[f64; 3]; 9] = [
        [0.0, 0.0, 4.0],
        [31.0, 12.0, 72.0],
        [85.0, 15.0, 109.0],
        [136.0, 34.0, 106.0],
        [186.0, 54.0, 85.0],
        [227.0, 89.0, 51.0],
        [249.0, 140.0, 10.0],
        [249.0, 201.0, 50.0],
        [252.0, 255.0, 164.0],
    ];
    let x = t.clamp(0.0, 1.0) * 8.0;
    let i = (x.floor() as usize).min(7);
    let f = x - i as f64;
    std::array::from_fn(|c| (MAP[i][c] + (MAP[i + 1][c] - MAP[i][c]) * f).round() as u8)
}

const MARGIN: i32 = 20;
const GAP: i32 = 20;
const TITLE_H: i32 = 62;
const HEAD_H: i32 = 44;
const CAPTION_H: i32 = 46;
const BAR_H: i32 = 56;

/// The overview: the three renders in the top row, with their run times and
/// errors; under each golden model, its distance from the reference; in
/// the bottom left, how to read the figure. Returns width, height and RGB.
fn overview(scene: &Scene, methods: &[Method]) -> Result<(u32, u32, Vec<u8>)> {
    plotters::style::register_font("sans-serif", FontStyle::Normal, dejavu::sans::regular())
        .map_err(|_| anyhow::anyhow!("registering the embedded font"))?;
    plotters::style::register_font("sans-serif", FontStyle::Bold, dejavu::sans::bold())
        .map_err(|_| anyhow::anyhow!("registering the embedded font"))?;
    let [pw, ph] = scene.image.map(|v| v as i32);
    let cols = methods.len() as i32;
    let width = (2 * MARGIN + cols * pw + (cols - 1) * GAP) as u32;
    let row1 = MARGIN + TITLE_H + HEAD_H;
    let row2 = row1 + ph + CAPTION_H + HEAD_H;
    let height = (row2 + ph + BAR_H + MARGIN) as u32;
    let col = |i: i32| MARGIN + i * (pw + GAP);

    let reference = &methods[0].out.image;
    let maps: Vec<Vec<f64>> = methods[1..]
        .iter()
        .map(|m| distance(&m.out.image, reference))
        .collect();
    let scale = full_scale(&maps);

    let mut buf = vec![255u8; (width * height * 3) as usize];
    let mut blit = |x0: i32, y0: i32, w: i32, rgb: &[[u8; 3]]| {
        for (k, px) in rgb.iter().enumerate() {
            let (x, y) = (x0 + k as i32 % w, y0 + k as i32 / w);
            let o = ((y as u32 * width + x as u32) * 3) as usize;
            buf[o..o + 3].copy_from_slice(px);
        }
    };
    for (i, m) in methods.iter().enumerate() {
        let rgb: Vec<[u8; 3]> = m
            .out
            .image
            .to_rgb8()
            .chunks_exact(3)
            .map(|c| [c[0], c[1], c[2]])
            .collect();
        blit(col(i as i32), row1, pw, &rgb);
    }
    for (i, map) in maps.iter().enumerate() {
        let rgb: Vec<[u8; 3]> = map.iter().map(|&e| inferno(e / scale)).collect();
        blit(col(i as i32 + 1), row2, pw, &rgb);
    }
    // The colour bar, under the difference panels.
    let (bar_x0, bar_x1) = (col(1), col(cols - 1) + pw);
    let bar_y = row2 + ph + 10;
    let bar: Vec<[u8; 3]> = (0..12)
        .flat_map(|_| {
            (bar_x0..bar_x1).map(|x| inferno((x - bar_x0) as f64 / (bar_x1 - bar_x0 - 1) as f64))
        })
        .collect();
    blit(bar_x0, bar_y, bar_x1 - bar_x0, &bar);

    {
        let root = BitMapBackend::with_buffer(&mut buf, (width, height)).into_drawing_area();
        let font = |size: i32, bold: bool, colour: &'static RGBColor, pos: Pos| {
            let style = if bold {
                FontStyle::Bold
            } else {
                FontStyle::Normal
            };
            TextStyle::from(("sans-serif", size, style).into_font())
                .color(colour)
                .pos(pos)
        };
        const INK: RGBColor = RGBColor(20, 20, 20);
        const GREY: RGBColor = RGBColor(90, 90, 90);
        let (ink, grey) = (&INK, &GREY);
        let left = Pos::new(HPos::Left, VPos::Top);
        let centre = Pos::new(HPos::Center, VPos::Top);
        let text = |s: &str, x: i32, y: i32, style: &TextStyle| -> Result<()> {
            root.draw(&Text::new(s.to_string(), (x, y), style.clone()))?;
            Ok(())
        };
        let d = scene.volume.render_dims();
        text(
            "The default scene, three ways: golden models against the float reference",
            MARGIN,
            MARGIN,
            &font(20, true, ink, left),
        )?;
        text(
            &format!(
                "scenes/default.json · built-in {} {}×{}×{}, {}-bit · parallel view · {}{} · {}×{} pixels · wall-clock times",
                scene.volume.builtin.as_deref().unwrap_or("?"),
                d[0],
                d[1],
                d[2],
                scene.hardware.voxel_bits,
                format!("{:?}", scene.mode).to_lowercase(),
                if scene.shading.enabled { ", shaded" } else { "" },
                pw,
                ph
            ),
            MARGIN,
            MARGIN + 30,
            &font(14, false, grey, left),
        )?;
        for (i, m) in methods.iter().enumerate() {
            let x = col(i as i32) + pw / 2;
            text(m.name, x, row1 - HEAD_H, &font(17, true, ink, centre))?;
            text(
                m.what,
                x,
                row1 - HEAD_H + 22,
                &font(14, false, grey, centre),
            )?;
            let (line1, line2) = match &m.error {
                None => (
                    format!("{:.2} s", m.out.seconds),
                    "the yardstick".to_string(),
                ),
                Some(e) => (
                    format!("{:.2} s    error {:.2} %", m.out.seconds, e.rel_euclid_pct),
                    format!("PSNR {}", crate::common::psnr_db_text(e.psnr_db, 1)),
                ),
            };
            text(&line1, x, row1 + ph + 6, &font(16, true, ink, centre))?;
            text(&line2, x, row1 + ph + 26, &font(14, false, grey, centre))?;
        }
        for (i, m) in methods[1..].iter().enumerate() {
            let x = col(i as i32 + 1) + pw / 2;
            let short = m.name.trim_end_matches(" golden model");
            text(
                &format!("|{short} − reference|"),
                x,
                row2 - HEAD_H + 14,
                &font(17, true, ink, centre),
            )?;
        }
        // The colour bar's ticks and legend.
        let tick_y = bar_y + 12;
        for k in 0..=4 {
            let x = bar_x0 + ((bar_x1 - bar_x0 - 1) as f64 * k as f64 / 4.0).round() as i32;
            root.draw(&PathElement::new(
                vec![(x, tick_y), (x, tick_y + 4)],
                ink.stroke_width(1),
            ))?;
            let (label, pos) = match k {
                0 => ("0".to_string(), Pos::new(HPos::Left, VPos::Top)),
                2 => (format!("{}", scale / 2.0), centre),
                4 => (format!("≥ {scale}"), Pos::new(HPos::Right, VPos::Top)),
                _ => continue,
            };
            text(&label, x, tick_y + 6, &font(14, false, ink, pos))?;
        }
        text(
            "per-pixel RGB distance from the reference / √3",
            (bar_x0 + bar_x1) / 2,
            tick_y + 24,
            &font(14, false, grey, centre),
        )?;
        // How to read it.
        let x = col(0);
        let mut y = row2 - HEAD_H + 14;
        text("How to read this", x, y, &font(17, true, ink, left))?;
        y += 30;
        let hw = &scene.hardware;
        let fixed = format!("hardware computes: {}-bit voxels,", hw.voxel_bits);
        let rgba = format!("{}-bit RGBA, bit for bit.", hw.rgba_bits);
        // Cube-4L resamples its compositing buffer every slice unless the
        // view is axis-aligned or at 45°, where its rays step whole voxels.
        let on_grid = scene
            .view
            .rotate_deg
            .is_some_and(|r| r.iter().all(|a| a.rem_euclid(45.0) == 0.0));
        let lines = [
            "The float reference is the",
            "yardstick: f64, tri-linear, a",
            "sample every 0.25 voxel, the",
            "exact transfer function and",
            "shading.",
            "",
            "The golden models compute what the",
            fixed.as_str(),
            rgba.as_str(),
            "",
            "error: mean distance over the",
            "pixels either image covers",
            "(Cube-3 §6). Cube-4L is sharpest",
            if on_grid {
                "at 0° and 45°, as here; other"
            } else {
                "at 0° and 45°; other angles"
            },
            if on_grid {
                "angles blur it (cube angles)."
            } else {
                "blur it (cube angles)."
            },
        ];
        for line in lines {
            text(line, x, y, &font(15, false, ink, left))?;
            y += 19;
        }
        root.present()?;
    }
    Ok((width, height, buf))
}
