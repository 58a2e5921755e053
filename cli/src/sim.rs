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

#[derive(clap::Args)]
pub struct SimArgs {
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
}

pub fn run(args: SimArgs) -> Result<()> {
    let SimArgs {
        scene: scene_path,
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
