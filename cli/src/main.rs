//! `cube`: render scenes with the Cube-4L golden model and the float
//! reference, and report run time and error.

mod output;

use anyhow::{bail, Context, Result};
use clap::{Parser, Subcommand, ValueEnum};
use output::{write_json, write_png};
use reference::metrics::{compare, difference, ErrorMetrics};
use scene::volume::{Volume, BUILTINS};
use scene::Image;
use scene::Scene;
use serde_json::{json, Value};
use std::path::{Path, PathBuf};
use std::time::Instant;

/// The built-in default scene: a head-like phantom, parallel view, composite.
const DEFAULT_SCENE: &str = include_str!("../../scenes/default.json");

#[derive(Parser)]
#[command(
    name = "cube",
    version,
    about = "Cube-4L volume-rendering kit: golden model, float reference, error and run time"
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
enum Arch {
    Cube4l,
    Reference,
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
enum Engine {
    /// rust-hdl's own simulator.
    RustHdl,
    /// Icarus Verilog running the Verilog rust-hdl emits.
    Iverilog,
    /// Verilator running the Verilog rust-hdl emits (built once per design,
    /// cached); the engine for full frames.
    Verilator,
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
enum SynthTarget {
    Ice40,
    Xilinx,
    Generic,
}

#[derive(Subcommand)]
enum Command {
    /// Render a scene.
    Render {
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
        #[arg(long, default_value_t = reference::DEFAULT_STEP)]
        ref_step: f64,
        /// Cube-4L only: write the base plane of the first sweep (PNG).
        #[arg(long)]
        base_plane: Option<PathBuf>,
    },
    /// Error and run time of the golden model against the reference while the
    /// view turns about the vertical axis (the Cube-3 §6 experiment).
    Angles {
        #[arg(long)]
        scene: PathBuf,
        /// First, last and step angle in degrees (rotate_deg[1]).
        #[arg(long, num_args = 3, default_values_t = [0.0, 90.0, 5.0])]
        range: Vec<f64>,
        #[arg(long, default_value_t = reference::DEFAULT_STEP)]
        ref_step: f64,
        #[arg(long)]
        json: Option<PathBuf>,
    },
    /// Run the scene through the pipeline in simulation (rust-hdl, or the
    /// emitted Verilog under Icarus or Verilator), warp its base plane, and
    /// compare it with the golden model bit for bit (exit 0 only if every
    /// pixel matches).
    Sim {
        #[arg(long)]
        scene: PathBuf,
        #[arg(long, value_enum, default_value = "rust-hdl")]
        engine: Engine,
        /// Write the simulation's VCD (and a GTKWave .gtkw beside it).
        #[arg(long)]
        vcd: Option<PathBuf>,
        /// The warped image of the RTL's base plane (PNG).
        #[arg(long)]
        out: Option<PathBuf>,
        #[arg(long)]
        json: Option<PathBuf>,
    },
    /// Write the scene's pruned pipeline as Verilog: one file per stage, a
    /// top, Verilator lint waivers and a manifest of parameters and left-out
    /// units.
    Verilog {
        #[arg(long)]
        scene: PathBuf,
        #[arg(long)]
        out: PathBuf,
    },
    /// Synthesize the scene's pipeline with yosys and report cells, LUTs,
    /// flip-flops, block RAMs and DSPs; on iCE40, a design that fits an UP5K
    /// is placed and routed with nextpnr-ice40 for fmax, and the frame rate
    /// is projected for 256³ and 512³ volumes.
    Synth {
        #[arg(long)]
        scene: PathBuf,
        #[arg(long, value_enum, default_value = "ice40")]
        target: SynthTarget,
        #[arg(long)]
        json: Option<PathBuf>,
        /// Skip placement and routing.
        #[arg(long)]
        no_pnr: bool,
    },
    /// Compare two VCD traces of the same design (e.g. rust-hdl against
    /// Verilator) signal by signal and cycle by cycle. Exit 0 when equal, 1
    /// when they differ, 2 on a bad file.
    VcdDiff {
        a: PathBuf,
        b: PathBuf,
        /// Compare only signals whose name below the top matches this glob
        /// (e.g. 'lanes$0.*' or '*.res').
        #[arg(long)]
        signals: Option<String>,
        /// How many first mismatches to print.
        #[arg(long, default_value_t = 10)]
        show: usize,
    },
    /// List the built-in volumes.
    Scenes,
}

fn main() {
    let cli = Cli::parse();
    if let Some(Command::VcdDiff {
        a,
        b,
        signals,
        show,
    }) = &cli.command
    {
        std::process::exit(vcd_diff_cmd(a, b, signals.as_deref(), *show));
    }
    let r = match cli.command {
        None => default_run(),
        Some(Command::Verilog { scene, out }) => verilog_cmd(&scene, &out),
        Some(Command::VcdDiff { .. }) => unreachable!("handled above"),
        Some(Command::Synth {
            scene,
            target,
            json,
            no_pnr,
        }) => synth_cmd(&scene, target, json, !no_pnr),
        Some(Command::Scenes) => {
            for (name, what) in BUILTINS {
                println!("{name:<13} {what}");
            }
            Ok(())
        }
        Some(Command::Render {
            scene,
            arch,
            out,
            json,
            compare_reference,
            diff,
            ref_step,
            base_plane,
        }) => render_cmd(
            &scene,
            arch,
            out,
            json,
            compare_reference || diff.is_some(),
            diff,
            ref_step,
            base_plane,
        ),
        Some(Command::Sim {
            scene,
            engine,
            vcd,
            out,
            json,
        }) => sim_cmd(&scene, engine, vcd, out, json),
        Some(Command::Angles {
            scene,
            range,
            ref_step,
            json,
        }) => angles_cmd(&scene, &range, ref_step, json),
    };
    if let Err(e) = r {
        eprintln!("cube: {e:#}");
        std::process::exit(1);
    }
}

fn check_step(step: f64) -> Result<()> {
    if !(0.01..=4.0).contains(&step) {
        bail!("--ref-step {step} must lie in [0.01, 4]");
    }
    Ok(())
}

fn load(scene_path: &Path) -> Result<(Scene, Volume)> {
    let scene = Scene::load(scene_path)?;
    let vol = Volume::from_spec(&scene.volume, scene.hardware.voxel_bits)?;
    Ok((scene, vol))
}

struct Rendered {
    image: Image,
    seconds: f64,
    extra: Value,
}

fn render_arch(scene: &Scene, vol: &Volume, arch: Arch, ref_step: f64) -> Result<Rendered> {
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

fn error_json(m: &ErrorMetrics) -> Value {
    json!({
        "rel_euclid_pct": m.rel_euclid_pct,
        "rmse": m.rmse,
        "psnr_db": if m.psnr_db.is_finite() { json!(m.psnr_db) } else { json!(null) },
        "max_abs": m.max_abs,
        "foreground_pixels": m.foreground_pixels,
    })
}

fn arch_name(a: Arch) -> &'static str {
    match a {
        Arch::Cube4l => "cube4l",
        Arch::Reference => "reference",
    }
}

#[allow(clippy::too_many_arguments)]
fn render_cmd(
    scene_path: &Path,
    arch: Arch,
    out: Option<PathBuf>,
    json_path: Option<PathBuf>,
    with_ref: bool,
    diff: Option<PathBuf>,
    ref_step: f64,
    base_plane: Option<PathBuf>,
) -> Result<()> {
    check_step(ref_step)?;
    if base_plane.is_some() && arch != Arch::Cube4l {
        bail!("--base-plane needs --arch cube4l");
    }
    let (scene, vol) = load(scene_path)?;
    let r = render_arch(&scene, &vol, arch, ref_step)?;
    println!("{}: {:.3} s", arch_name(arch), r.seconds);
    let mut report = json!({
        "arch": arch_name(arch),
        "scene": scene_path.display().to_string(),
        "seconds": r.seconds,
        "image": [r.image.width, r.image.height],
        "details": r.extra,
    });
    if with_ref {
        let rr = render_arch(&scene, &vol, Arch::Reference, ref_step)?;
        let m = compare(&r.image, &rr.image);
        println!(
            "reference: {:.3} s; error: rel. Euclidean {:.3} %, RMSE {:.5}, PSNR {:.2} dB, max {:.4}",
            rr.seconds, m.rel_euclid_pct, m.rmse, m.psnr_db, m.max_abs
        );
        report["error"] = error_json(&m);
        report["reference_seconds"] = json!(rr.seconds);
        if let Some(d) = diff {
            write_png(&d, &difference(&r.image, &rr.image, 8.0))?;
        }
    }
    if let Some(p) = base_plane {
        let (frame_img, _) = base_plane_image(&scene, &vol)?;
        write_png(&p, &frame_img)?;
    }
    if let Some(o) = out {
        write_png(&o, &r.image)?;
    }
    if let Some(j) = json_path {
        write_json(&j, &report)?;
    }
    Ok(())
}

/// The first sweep's base plane as an image (scaled to the display range).
fn base_plane_image(scene: &Scene, vol: &Volume) -> Result<(Image, usize)> {
    let cam = scene.camera()?;
    let frame = golden_model::cube4l::render(scene, &cam, vol)?;
    let b = &frame.bases[0];
    let depth = frame.plan.sweeps[0].dims[2];
    let hw = scene.hardware;
    let mut img = Image::black(b.width as u32, b.height as u32);
    for (o, p) in img.rgb.iter_mut().zip(&b.pixels) {
        *o = golden_model::warp::to_rgb(
            scene.mode,
            p.map(|c| c as f64),
            hw.rgba_bits,
            hw.voxel_bits,
            depth,
        );
    }
    Ok((img, frame.bases.len()))
}

fn synth_cmd(
    scene_path: &Path,
    target: SynthTarget,
    json_path: Option<PathBuf>,
    pnr: bool,
) -> Result<()> {
    use cosim::synth::{frame_clocks, synthesize, Target};
    let target = match target {
        SynthTarget::Ice40 => Target::Ice40,
        SynthTarget::Xilinx => Target::Xilinx,
        SynthTarget::Generic => Target::Generic,
    };
    let scene = Scene::load(scene_path)?;
    let cam = scene.camera()?;
    let dir = std::env::temp_dir().join(format!("cube-synth-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let name = scene_path
        .file_name()
        .map(|n| n.to_string_lossy().to_string())
        .unwrap_or_default();
    let result = (|| {
        let m = cosim::export::write_export(&name, &scene, &cam, scene.volume.render_dims(), &dir)
            .map_err(|e| anyhow::anyhow!("synth: {e}"))?;
        let sweep = &m["sweeps"][0];
        let files: Vec<String> = sweep["files"]
            .as_array()
            .context("manifest files")?
            .iter()
            .filter_map(|f| f.as_str().map(String::from))
            .collect();
        let sub = dir.join(sweep["dir"].as_str().unwrap_or("."));
        let r = synthesize(&sub, &files, target, pnr).map_err(|e| anyhow::anyhow!("synth: {e}"))?;
        Ok::<_, anyhow::Error>((m, r))
    })();
    let _ = std::fs::remove_dir_all(&dir);
    let (m, r) = result?;
    let p = scene.hardware.pipelines as u64;
    let gradient = !m["units_left_out"]
        .as_array()
        .is_some_and(|a| a.iter().any(|u| u == "abc_gradient"));
    println!(
        "{}: {} cells, {} LUTs, {} flip-flops, {} block RAMs, {} DSPs ({:.1} s)",
        target.name(),
        r.cells,
        r.luts,
        r.flip_flops,
        r.block_rams,
        r.dsps,
        r.synth_seconds
    );
    let sweeps = m["sweeps"].as_array().map_or(1, |s| s.len());
    if sweeps > 1 {
        println!("(sweep 0 of {sweeps}; every sweep's pipeline has the same structure, with its own constants)");
    }
    let mut projection = serde_json::Map::new();
    match (r.fits_up5k, r.fmax_mhz) {
        (Some(false), _) => println!(
            "does not fit an iCE40 UP5K ({} LUTs, {} BRAMs, {} DSPs available): no place and route",
            cosim::synth::UP5K.0,
            cosim::synth::UP5K.1,
            cosim::synth::UP5K.2
        ),
        (_, Some(f)) => {
            println!("nextpnr-ice40 (UP5K): fmax {f:.2} MHz");
            for n in [256u64, 512] {
                let clocks = frame_clocks(n, p, gradient);
                let fps = f * 1e6 / clocks as f64;
                println!("  {n}³ at p = {p}: {clocks} clocks per frame, {fps:.2} frames/s");
                projection.insert(
                    format!("{n}"),
                    json!({"clocks_per_frame": clocks, "frames_per_second": fps}),
                );
            }
        }
        _ => {}
    }
    if let Some(j) = json_path {
        write_json(
            &j,
            &json!({
                "scene": name,
                "target": target.name(),
                "pipelines": p,
                "cells": r.cells,
                "luts": r.luts,
                "flip_flops": r.flip_flops,
                "block_rams": r.block_rams,
                "dsps": r.dsps,
                "cell_types": r.cell_types,
                "synth_seconds": r.synth_seconds,
                "fits_up5k": r.fits_up5k,
                "fmax_mhz": r.fmax_mhz,
                "pnr_seconds": r.pnr_seconds,
                "projected": projection,
                "units_left_out": m["units_left_out"],
                "parameters": m["parameters"],
            }),
        )?;
    }
    Ok(())
}

/// `cube vcd-diff`: 0 equal, 1 different, 2 bad input.
fn vcd_diff_cmd(a: &Path, b: &Path, signals: Option<&str>, show: usize) -> i32 {
    use cosim::vcd_diff::{compare, show as hex, Trace};
    let loaded = Trace::load(a).and_then(|ta| Ok((ta, Trace::load(b)?)));
    let c = match loaded.and_then(|(ta, tb)| compare(&ta, &tb, signals)) {
        Ok(c) => c,
        Err(e) => {
            eprintln!("error: vcd-diff: {e}");
            return 2;
        }
    };
    println!(
        "{} signals compared over {} cycles ({} in A only, {} in B only)",
        c.compared,
        c.cycles_a.min(c.cycles_b),
        c.only_a.len(),
        c.only_b.len()
    );
    if c.cycles_a != c.cycles_b {
        println!(
            "lengths differ: A has {} cycles, B has {}",
            c.cycles_a, c.cycles_b
        );
    }
    for m in c.mismatches.iter().take(show) {
        println!(
            "cycle {}: {}: A {} B {}",
            m.cycle,
            m.signal,
            hex(&m.a),
            hex(&m.b)
        );
    }
    if c.equal() {
        println!("traces equal");
        0
    } else {
        println!("{} signals differ", c.mismatches.len());
        1
    }
}

fn verilog_cmd(scene_path: &Path, out: &Path) -> Result<()> {
    let scene = Scene::load(scene_path)?;
    let cam = scene.camera()?;
    let name = scene_path
        .file_name()
        .map(|n| n.to_string_lossy().to_string())
        .unwrap_or_default();
    let m = cosim::export::write_export(&name, &scene, &cam, scene.volume.render_dims(), out)
        .map_err(|e| anyhow::anyhow!("verilog: {e}"))?;
    let sweeps = m["sweeps"].as_array().map_or(0, |s| s.len());
    println!(
        "wrote {} ({} sweep{}, {} memory); units left out: {}",
        out.display(),
        sweeps,
        if sweeps == 1 { "" } else { "s" },
        m["parameters"]["memory"]["kind"].as_str().unwrap_or("?"),
        m["units_left_out"]
            .as_array()
            .map(|a| a
                .iter()
                .filter_map(|v| v.as_str())
                .collect::<Vec<_>>()
                .join(", "))
            .unwrap_or_default()
    );
    Ok(())
}

fn sim_cmd(
    scene_path: &Path,
    engine: Engine,
    vcd: Option<PathBuf>,
    out: Option<PathBuf>,
    json_path: Option<PathBuf>,
) -> Result<()> {
    let engine = match engine {
        Engine::RustHdl => cosim::sim::Engine::RustHdl,
        Engine::Iverilog => cosim::sim::Engine::Iverilog,
        Engine::Verilator => cosim::sim::Engine::Verilator,
    };
    let name = engine.name();
    let (scene, vol) = load(scene_path)?;
    let cam = scene.camera()?;
    let vcd_tmp = vcd.as_ref().map(|v| v.with_extension("vcd.tmp"));
    let r = cosim::sim::simulate_with(&scene, &cam, &vol, engine, vcd_tmp.as_deref())
        .map_err(|e| anyhow::anyhow!("sim: {e}"))?;
    if let (Some(tmp), Some(v)) = (&vcd_tmp, &vcd) {
        std::fs::rename(tmp, v).with_context(|| format!("renaming to {}", v.display()))?;
        let gtkw_tmp = tmp.with_extension("gtkw");
        let gtkw = v.with_extension("gtkw");
        let text = std::fs::read_to_string(&gtkw_tmp)?
            .replace(&tmp.display().to_string(), &v.display().to_string());
        std::fs::remove_file(&gtkw_tmp)?;
        output::write_text(&gtkw, &text)?;
    }
    let cps = r.cycles as f64 / r.sim_seconds;
    println!(
        "{name}: {} clocks (ideal {}, +{} fill), {:.2} s in all ({:.2} s simulating, {:.0} clocks/s; {:.1} s building); {} base-plane pixels differ from the golden model",
        r.cycles,
        r.ideal_cycles,
        r.cycles - r.ideal_cycles,
        r.seconds,
        r.sim_seconds,
        cps,
        r.build_seconds,
        r.mismatches
    );
    println!(
        "units left out: {}",
        if r.left_out.is_empty() {
            "none".to_string()
        } else {
            r.left_out.join(", ")
        }
    );
    for m in &r.first {
        println!(
            "  sweep {} pixel ({}, {}): rtl {:?} {:?}, golden {:?} {:?}",
            m.sweep, m.x, m.y, m.rtl.0, m.rtl.1, m.golden.0, m.golden.1
        );
    }
    if let Some(o) = out {
        let hw = scene.hardware;
        let img = golden_model::warp::warp(&r.frame, &cam, scene.mode, hw.rgba_bits, hw.voxel_bits);
        write_png(&o, &img)?;
    }
    if let Some(j) = json_path {
        write_json(
            &j,
            &json!({
                "engine": name,
                "scene": scene_path.display().to_string(),
                "cycles": r.cycles,
                "ideal_cycles": r.ideal_cycles,
                "mismatches": r.mismatches,
                "seconds": r.seconds,
                "sim_seconds": r.sim_seconds,
                "build_seconds": r.build_seconds,
                "cycles_per_second": cps,
                "pipelines": scene.hardware.pipelines,
                "units_left_out": r.left_out,
            }),
        )?;
    }
    if r.mismatches > 0 {
        bail!(
            "{} base-plane pixels differ from the golden model",
            r.mismatches
        );
    }
    Ok(())
}

fn default_run() -> Result<()> {
    let scene = Scene::from_json(DEFAULT_SCENE, None).context("built-in default scene")?;
    let vol = Volume::from_spec(&scene.volume, scene.hardware.voxel_bits)?;
    let g = render_arch(&scene, &vol, Arch::Cube4l, reference::DEFAULT_STEP)?;
    let r = render_arch(&scene, &vol, Arch::Reference, reference::DEFAULT_STEP)?;
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

fn angles_cmd(
    scene_path: &Path,
    range: &[f64],
    ref_step: f64,
    json_path: Option<PathBuf>,
) -> Result<()> {
    check_step(ref_step)?;
    let [from, to, step] = [range[0], range[1], range[2]];
    if !(from.is_finite()
        && to.is_finite()
        && step.is_finite()
        && step > 0.0
        && to >= from
        && (to - from) / step <= 3600.0)
    {
        bail!(
            "--range FROM TO STEP needs finite values, STEP > 0, TO >= FROM and at most 3600 steps"
        );
    }
    let (mut scene, vol) = load(scene_path)?;
    let base = scene.view.rotate_deg.unwrap_or([0.0; 3]);
    if scene.view.projection != scene::Projection::Parallel {
        bail!("angles turns a parallel view; the scene is perspective");
    }
    let mut rows = Vec::new();
    println!(
        "{:>7} {:>10} {:>10} {:>10} {:>9} {:>7}",
        "angle", "cube4l s", "ref s", "rel.eucl%", "PSNR dB", "sweep"
    );
    let mut a = from;
    while a <= to + 1e-9 {
        scene.view.rotate_deg = Some([base[0], a, base[2]]);
        let g = render_arch(&scene, &vol, Arch::Cube4l, ref_step)?;
        let r = render_arch(&scene, &vol, Arch::Reference, ref_step)?;
        let m = compare(&g.image, &r.image);
        let cam = scene.camera()?;
        let plan = golden_model::cube4l::plan::Plan::new(&scene, &cam)?;
        let axis = ["u", "v", "w"][plan.sweeps[0].axis()];
        println!(
            "{a:>7.2} {:>10.3} {:>10.3} {:>10.3} {:>9.2} {:>7}",
            g.seconds, r.seconds, m.rel_euclid_pct, m.psnr_db, axis
        );
        rows.push(json!({"angle": a, "cube4l_seconds": g.seconds, "reference_seconds": r.seconds, "major_axis": axis, "error": error_json(&m)}));
        a += step;
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
