//! `cube sim`: run the scene through the pipeline in simulation (rust-hdl, or
//! the emitted Verilog under Icarus or Verilator), warp its base plane, and
//! compare it with the golden model bit for bit; fails unless every pixel
//! matches.

use crate::common::load;
use crate::output::{self, write_json, write_png};
use anyhow::{bail, Context, Result};
use clap::ValueEnum;
use serde_json::json;
use std::path::PathBuf;

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

/// The architecture simulated.
#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
enum SimArch {
    Cube4l,
    /// Cube-3: parallel and perspective views in every mode (the 6 or the
    /// 12 gradient neighbourhood).
    Cube3,
}

#[derive(clap::Args)]
pub struct SimArgs {
    #[arg(long)]
    scene: PathBuf,
    #[arg(long, value_enum, default_value = "cube4l")]
    arch: SimArch,
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
}

pub fn run(args: SimArgs) -> Result<()> {
    let SimArgs {
        scene: scene_path,
        arch,
        engine,
        vcd,
        out,
        json: json_path,
    } = args;
    let engine = match engine {
        Engine::RustHdl => cosim::sim::Engine::RustHdl,
        Engine::Iverilog => cosim::sim::Engine::Iverilog,
        Engine::Verilator => cosim::sim::Engine::Verilator,
    };
    let name = engine.name();
    let (scene, vol) = load(&scene_path)?;
    let cam = scene.camera()?;
    for path in [&out, &json_path].into_iter().flatten() {
        output::check_target(path)?;
    }
    if arch == SimArch::Cube3 {
        return run_cube3(&scene_path, engine, vcd, out, json_path);
    }
    let vcd_tmp = vcd_temp(&vcd)?;
    let simulated = cosim::sim::simulate_with(&scene, &cam, &vol, engine, vcd_tmp.as_deref())
        .map_err(|e| anyhow::anyhow!("sim: {e}"))
        .and_then(|r| keep_vcd(&vcd_tmp, &vcd).map(|()| r));
    drop_vcd_temp(&vcd_tmp);
    let r = simulated?;
    let cps = if r.sim_seconds > 0.0 {
        r.cycles as f64 / r.sim_seconds
    } else {
        0.0
    };
    println!(
        "{name}: {} clocks (ideal {}, {:+} fill), {:.2} s in all ({:.2} s simulating, {:.0} clocks/s; {:.1} s building); {} base-plane pixels differ from the golden model",
        r.cycles,
        r.ideal_cycles,
        r.cycles as i64 - r.ideal_cycles as i64,
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

/// `cube sim --arch cube3`: the Cube-3 system against the Cube-3 golden
/// model, with the frame's clocks explained.
fn run_cube3(
    scene_path: &std::path::Path,
    engine: cosim::sim::Engine,
    vcd: Option<PathBuf>,
    out: Option<PathBuf>,
    json_path: Option<PathBuf>,
) -> Result<()> {
    let name = engine.name();
    let (scene, vol) = load(scene_path)?;
    let cam = scene.camera()?;
    for path in [&out, &json_path].into_iter().flatten() {
        output::check_target(path)?;
    }
    let vcd_tmp = vcd_temp(&vcd)?;
    let simulated = cosim::cube3_sim::simulate(&scene, &cam, &vol, engine, vcd_tmp.as_deref())
        .map_err(|e| anyhow::anyhow!("sim: {e}"))
        .and_then(|r| keep_vcd(&vcd_tmp, &vcd).map(|()| r));
    drop_vcd_temp(&vcd_tmp);
    let r = simulated?;
    let c = r.clocks;
    let cps = c.total as f64 / r.sim_seconds.max(1e-9);
    println!(
        "{name} (cube3): {} clocks, ideal n_x*n_y*n_z/p = {} ({:.2}x), {:.2} s in all ({:.2} s simulating, {:.0} clocks/s; {:.1} s building); {} base-plane pixels differ from the golden model",
        c.total,
        c.ideal,
        c.total as f64 / c.ideal as f64,
        r.seconds,
        r.sim_seconds,
        cps,
        r.build_seconds,
        r.mismatches
    );
    println!(
        "clocks: {} segments (R*S*G) + {} waiting for PRP writes + {} prologue - {} last wait + {} drain",
        c.segments, c.idle, c.prologue, c.tail, c.drain
    );
    for m in &r.first {
        println!("  {m}");
    }
    if let Some(o) = out {
        let img = golden_model::cube3::warp(&r.frame, &cam, scene.mode);
        write_png(&o, &img)?;
    }
    if let Some(j) = json_path {
        write_json(
            &j,
            &json!({
                "engine": name,
                "arch": "cube3",
                "scene": scene_path.display().to_string(),
                "cycles": c.total,
                "ideal_cycles": c.ideal,
                "clocks": {
                    "segments": c.segments,
                    "idle": c.idle,
                    "prologue": c.prologue,
                    "tail": c.tail,
                    "drain": c.drain,
                },
                "mismatches": r.mismatches,
                "seconds": r.seconds,
                "sim_seconds": r.sim_seconds,
                "build_seconds": r.build_seconds,
                "cycles_per_second": cps,
                "pipelines": scene.hardware.pipelines,
                "base_planes": r.frame.bases.len(),
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

/// The temporary path the simulation traces to, beside `--vcd` (checked
/// first: a VCD is written whole, never over a special file).
fn vcd_temp(vcd: &Option<PathBuf>) -> Result<Option<PathBuf>> {
    let Some(v) = vcd else { return Ok(None) };
    if let output::Target::Special = output::check_target(v)? {
        bail!(
            "--vcd {}: not a regular file (a VCD is written whole, with its .gtkw beside it)",
            v.display()
        );
    }
    if let Some(dir) = v.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
    }
    Ok(Some(v.with_extension("vcd.tmp")))
}

/// Move a finished trace and its `.gtkw` into place.
fn keep_vcd(tmp: &Option<PathBuf>, vcd: &Option<PathBuf>) -> Result<()> {
    if let (Some(tmp), Some(v)) = (tmp, vcd) {
        let text = std::fs::read_to_string(tmp.with_extension("gtkw"))?
            .replace(&tmp.display().to_string(), &v.display().to_string());
        output::write_text(&v.with_extension("gtkw"), &text)?;
        std::fs::rename(tmp, v).with_context(|| format!("renaming to {}", v.display()))?;
    }
    Ok(())
}

/// Whatever happened, no temporary trace is left behind.
fn drop_vcd_temp(tmp: &Option<PathBuf>) {
    if let Some(tmp) = tmp {
        let _ = std::fs::remove_file(tmp);
        let _ = std::fs::remove_file(tmp.with_extension("gtkw"));
    }
}
