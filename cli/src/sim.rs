//! `cube sim`: run scenes through an architecture's RTL in simulation
//! (rust-hdl, or the emitted Verilog under Icarus or Verilator), warp their
//! base planes, and compare them with the golden model bit for bit; fails
//! unless every pixel matches. Several `--scene`s are consecutive frames on
//! one build (one simulation of one design): between frames the testbench
//! writes the next view's registers and the table words that changed.

use crate::common::load;
use crate::methods::HwArch;
use crate::output;
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
    /// The scene; give it several times for consecutive frames on one
    /// build (they must share the volume).
    #[arg(long, required = true)]
    scene: Vec<PathBuf>,
    /// The build, by name (`cube verilog`); by default the configuration
    /// the first scene needs.
    #[arg(long)]
    config: Option<String>,
    #[arg(long, value_enum, default_value = "cube4l")]
    arch: HwArch,
    #[arg(long, value_enum, default_value = "rust-hdl")]
    engine: Engine,
    /// Trace the simulation: VCD or FST by the name's extension, every
    /// simulation of the run one after another, with a GTKWave .gtkw beside
    /// it.
    #[arg(long, visible_alias = "vcd")]
    trace: Option<PathBuf>,
    /// Trace only signals whose dotted name below the design's top matches
    /// this glob (e.g. 'lanes$0.*' for one lane, '*shader*'); give it
    /// several times for several.
    #[arg(long, requires = "trace")]
    trace_scope: Vec<String>,
    /// Trace only signals at most this many modules below the top (0: the
    /// top's own).
    #[arg(long, requires = "trace")]
    trace_depth: Option<usize>,
    /// Trace only clocks FIRST..END of the run (END excluded, counted from
    /// the run's first clock, host writes included).
    #[arg(long, requires = "trace", value_name = "FIRST..END")]
    trace_clocks: Option<String>,
    /// The warped image of the RTL's base planes (PNG; with several frames,
    /// frame i goes to `<stem>-<i>.png`).
    #[arg(long)]
    out: Option<PathBuf>,
    #[arg(long)]
    json: Option<PathBuf>,
}

/// Threads a simulation starts with `RUST_MIN_STACK` stacks: rust-hdl's
/// testbench thread and the progress spinner's, with room for two more.
const SIM_THREADS: u64 = 4;

/// Refuse a simulation whose threads would not fit the address-space
/// limit, before any starts (a thread whose signal stack cannot be mapped
/// aborts the process).
fn check_sim_threads() -> Result<()> {
    let stack = std::env::var("RUST_MIN_STACK")
        .ok()
        .and_then(|v| v.trim().parse::<u64>().ok())
        .unwrap_or(2 << 20);
    if let Err((need, limit)) = crate::budget::threads_fit(SIM_THREADS, stack, 256 << 20) {
        bail!(
            "sim: cannot start the simulation's threads ({SIM_THREADS} of RUST_MIN_STACK={stack} bytes of stack): with what the run maps they take {} MiB of address space, over the limit of {} MiB (ulimit -v); allow more memory, or set RAYON_NUM_THREADS or RUST_MIN_STACK lower",
            need >> 20,
            limit >> 20
        );
    }
    Ok(())
}

pub fn run(args: SimArgs) -> Result<()> {
    check_sim_threads()?;
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
        let err = |e: String| anyhow::anyhow!("sim: {e}");
        let mut frames = Vec::new();
        let mut vol = None;
        for path in &args.scene {
            let (scene, v) = load(path)?;
            match &vol {
                None => vol = Some(v),
                Some(first) if first.dims == v.dims && first.data == v.data => {}
                Some(_) => bail!(
                    "sim: {} has another volume than {}: the frames of one run share the volume in the build's memory",
                    path.display(),
                    args.scene[0].display()
                ),
            }
            let cam = scene.camera();
            frames.push((scene, cam));
        }
        let vol = vol.expect("a scene");
        let build = args
            .config
            .as_deref()
            .map(A::parse_config)
            .transpose()
            .map_err(err)?;
        let outs = frame_paths(&args.out, frames.len());
        let mut files = output::Files::default();
        for (path, (scene, _)) in args.scene.iter().zip(&frames) {
            files.scene("--scene", path, scene)?;
        }
        for path in &outs {
            files.output("--out", path)?;
        }
        if let Some(j) = &args.json {
            files.output("--json", j)?;
        }
        if let Some(v) = &args.trace {
            files.output("--trace", v)?;
            // The format before the save file: a name that is no trace's is
            // the problem, not what lies beside it.
            cosim::trace::Format::of(v).map_err(|e| anyhow::anyhow!("--trace: {e}"))?;
            files.companion("--trace's save file", &v.with_extension("gtkw"))?;
        }
        // The trace is written to temporary files of the set, which land
        // with the images and the JSON (or are removed with them).
        let request = trace_request(args, &mut files)?;
        let run = cosim::sim::simulate_frames::<A>(
            &frames,
            build.as_ref(),
            &vol,
            engine,
            request.as_ref(),
            &|v| v.to_string(),
        )
        .map_err(err)?;
        if let Some(t) = &run.traced {
            println!(
                "trace: {} of {} signals, clocks {}..{} ({} simulation{}), {} bytes",
                t.signals,
                t.of,
                t.clocks.0,
                t.clocks.1,
                t.parts,
                if t.parts == 1 {
                    ""
                } else {
                    "s one after another"
                },
                t.bytes
            );
        }
        let several = frames.len() > 1;
        if several {
            println!(
                "{} frames on one build of {} configuration {} (the volume loaded {} time{})",
                frames.len(),
                A::TITLE,
                A::config_name(&run.config),
                run.memory_loads,
                if run.memory_loads == 1 { "" } else { "s" }
            );
        }
        // Clocks simulated: every frame's parts and the host's writes.
        let simulated: u64 = run.frames.iter().map(|r| r.clocks + r.reload_clocks).sum();
        let (seconds, sim_seconds, build_seconds) =
            run.frames.first().map_or((0.0, 0.0, 0.0), |r| {
                (r.seconds, r.sim_seconds, r.build_seconds)
            });
        let cps = if sim_seconds > 0.0 {
            simulated as f64 / sim_seconds
        } else {
            0.0
        };
        let mut reports = Vec::new();
        let mut mismatches = 0;
        for (i, (r, (scene, cam))) in run.frames.into_iter().zip(&frames).enumerate() {
            let label = if several {
                format!("frame {} ({}) ", i + 1, args.scene[i].display())
            } else {
                String::new()
            };
            println!(
                "{label}{name} ({}): {} clocks, ideal n_x*n_y*n_z/p = {} ({:.2}x), after {} clocks of host writes; {} base-plane pixels differ from the golden model",
                A::NAME,
                r.clocks,
                r.ideal_clocks,
                r.clocks as f64 / r.ideal_clocks as f64,
                r.reload_clocks,
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
            if i == 0 {
                println!(
                    "units left out: {}",
                    if r.left_out.is_empty() {
                        "none".to_string()
                    } else {
                        r.left_out.join(", ")
                    }
                );
            }
            for m in &r.first {
                println!("  {m}");
            }
            let terms: serde_json::Map<String, serde_json::Value> = r
                .clock_terms
                .iter()
                .map(|t| (t.key.to_string(), json!(t.clocks)))
                .collect();
            reports.push(json!({
                "scene": args.scene[i].display().to_string(),
                "cycles": r.clocks,
                "ideal_cycles": r.ideal_clocks,
                "clocks": terms,
                "reload_clocks": r.reload_clocks,
                "mismatches": r.mismatches,
                format!("{}s", A::PART): r.bases.len(),
            }));
            mismatches += r.mismatches;
            if let Some(o) = outs.get(i) {
                let img = A::image(scene, cam, r.bases).map_err(err)?;
                files.png(o, &img)?;
            }
            if i + 1 == frames.len() {
                if let Some(j) = &args.json {
                    let mut doc = json!({
                        "engine": name,
                        "arch": A::NAME,
                        "configuration": A::config_name(&run.config),
                        "memory_loads": run.memory_loads,
                        "seconds": seconds,
                        "sim_seconds": sim_seconds,
                        "build_seconds": build_seconds,
                        "cycles_per_second": cps,
                        "pipelines": scene.hardware.pipelines,
                        "units_left_out": r.left_out,
                    });
                    if several {
                        doc["frames"] = json!(reports);
                    } else if let (Some(d), serde_json::Value::Object(f)) =
                        (doc.as_object_mut(), reports.remove(0))
                    {
                        d.extend(f);
                    }
                    files.json(j, &doc)?;
                }
            }
        }
        println!(
            "{seconds:.2} s in all ({sim_seconds:.2} s simulating {simulated} clocks, {cps:.0} clocks/s; {build_seconds:.1} s building)"
        );
        // The outputs land even when pixels differ: they show how.
        files.commit()?;
        if mismatches > 0 {
            bail!("{mismatches} base-plane pixels differ from the golden model");
        }
        Ok(())
    }
}

/// Where each frame's image goes: `--out` for one frame, `<stem>-<i>.png`
/// beside it for several.
fn frame_paths(out: &Option<PathBuf>, frames: usize) -> Vec<PathBuf> {
    let Some(o) = out else { return vec![] };
    if frames == 1 {
        return vec![o.clone()];
    }
    let stem = o
        .file_stem()
        .map(|s| s.to_string_lossy().to_string())
        .unwrap_or_default();
    (1..=frames)
        .map(|i| o.with_file_name(format!("{stem}-{i}.png")))
        .collect()
}

/// The trace `--trace` asks for, written to a temporary path beside it
/// (a trace is written whole, never through a special file).
fn trace_request(
    args: &SimArgs,
    files: &mut output::Files,
) -> Result<Option<cosim::trace::Request>> {
    let Some(v) = &args.trace else {
        return Ok(None);
    };
    let scopes = args
        .trace_scope
        .iter()
        .map(|p| glob::Pattern::new(p).with_context(|| format!("--trace-scope {p}")))
        .collect::<Result<Vec<_>>>()?;
    let clocks = args
        .trace_clocks
        .as_deref()
        .map(|r| {
            let parsed = r
                .split_once("..")
                .and_then(|(a, b)| Some((a.trim().parse().ok()?, b.trim().parse().ok()?)));
            parsed
                .with_context(|| format!("--trace-clocks {r}: expected FIRST..END, e.g. 100..400"))
        })
        .transpose()?;
    let limits = cosim::trace::Limits {
        scopes,
        depth: args.trace_depth,
        clocks,
    };
    let mut req =
        cosim::trace::Request::new(v, limits).map_err(|e| anyhow::anyhow!("--trace: {e}"))?;
    let ext = if req.format == cosim::trace::Format::Fst {
        "fst"
    } else {
        "vcd"
    };
    let tmp = files
        .temp_for(v, ext)
        .with_context(|| "--trace: a trace is written whole, with its .gtkw beside it")?;
    files.temp_at(&tmp.with_extension("gtkw"), &v.with_extension("gtkw"))?;
    req.path = tmp;
    req.lands_at = Some(v.clone());
    Ok(Some(req))
}
