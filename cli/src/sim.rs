//! `cube sim`: run the scene through an architecture's RTL in simulation
//! (rust-hdl, or the emitted Verilog under Icarus or Verilator), warp its
//! base planes, and compare them with the golden model bit for bit; fails
//! unless every pixel matches.

use crate::common::{load, HwArch};
use crate::output::{self, write_json, write_png};
use anyhow::{bail, Context, Result};
use clap::ValueEnum;
use cosim::arch::Arch;
use cosim::archs::ForArch;
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
    #[arg(long, value_enum, default_value = "cube4l")]
    arch: HwArch,
    #[arg(long, value_enum, default_value = "rust-hdl")]
    engine: Engine,
    /// Write the simulation's VCD (and a GTKWave .gtkw beside it).
    #[arg(long)]
    vcd: Option<PathBuf>,
    /// The warped image of the RTL's base planes (PNG).
    #[arg(long)]
    out: Option<PathBuf>,
    #[arg(long)]
    json: Option<PathBuf>,
}

pub fn run(args: SimArgs) -> Result<()> {
    let engine = match args.engine {
        Engine::RustHdl => cosim::Engine::RustHdl,
        Engine::Iverilog => cosim::Engine::Iverilog,
        Engine::Verilator => cosim::Engine::Verilator,
    };
    args.arch.arch().with(Sim {
        args: &args,
        engine,
    })
}

struct Sim<'a> {
    args: &'a SimArgs,
    engine: cosim::Engine,
}

impl ForArch for Sim<'_> {
    type Output = Result<()>;
    fn run<A: Arch>(self) -> Result<()> {
        let Sim { args, engine } = self;
        let name = engine.name();
        let (scene, vol) = load(&args.scene)?;
        let cam = scene.camera()?;
        for path in [&args.out, &args.json].into_iter().flatten() {
            output::check_target(path)?;
        }
        let vcd_tmp = vcd_temp(&args.vcd)?;
        let simulated = cosim::sim::simulate::<A>(&scene, &cam, &vol, engine, vcd_tmp.as_deref())
            .map_err(|e| anyhow::anyhow!("sim: {e}"))
            .and_then(|r| keep_vcd(&vcd_tmp, &args.vcd).map(|()| r));
        drop_vcd_temp(&vcd_tmp);
        let r = simulated?;
        let cps = if r.sim_seconds > 0.0 {
            r.clocks as f64 / r.sim_seconds
        } else {
            0.0
        };
        println!(
            "{name} ({}): {} clocks, ideal n_x*n_y*n_z/p = {} ({:.2}x), {:.2} s in all ({:.2} s simulating, {:.0} clocks/s; {:.1} s building); {} base-plane pixels differ from the golden model",
            A::NAME,
            r.clocks,
            r.ideal_clocks,
            r.clocks as f64 / r.ideal_clocks as f64,
            r.seconds,
            r.sim_seconds,
            cps,
            r.build_seconds,
            r.mismatches
        );
        if !r.clock_terms.is_empty() {
            let mut line = String::new();
            for (i, t) in r.clock_terms.iter().enumerate() {
                let sign = match (i, t.clocks < 0) {
                    (0, _) => "",
                    (_, true) => " - ",
                    (_, false) => " + ",
                };
                line += &format!("{sign}{} {}", t.clocks.unsigned_abs(), t.what);
            }
            println!("clocks: {line}");
        }
        println!(
            "units left out: {}",
            if r.left_out.is_empty() {
                "none".to_string()
            } else {
                r.left_out.join(", ")
            }
        );
        for m in &r.first {
            println!("  {m}");
        }
        let parts = r.bases.len();
        if let Some(o) = &args.out {
            let img = A::image(&scene, &cam, r.bases).map_err(|e| anyhow::anyhow!("sim: {e}"))?;
            write_png(o, &img)?;
        }
        if let Some(j) = &args.json {
            let terms: serde_json::Map<String, serde_json::Value> = r
                .clock_terms
                .iter()
                .map(|t| (t.key.to_string(), json!(t.clocks)))
                .collect();
            write_json(
                j,
                &json!({
                    "engine": name,
                    "arch": A::NAME,
                    "scene": args.scene.display().to_string(),
                    "cycles": r.clocks,
                    "ideal_cycles": r.ideal_clocks,
                    "clocks": terms,
                    "mismatches": r.mismatches,
                    "seconds": r.seconds,
                    "sim_seconds": r.sim_seconds,
                    "build_seconds": r.build_seconds,
                    "cycles_per_second": cps,
                    "pipelines": scene.hardware.pipelines,
                    format!("{}s", A::PART): parts,
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
