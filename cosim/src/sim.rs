//! Scenes through an architecture's RTL in simulation, their base planes
//! compared with the golden model's pixel by pixel. Three engines:
//! rust-hdl's own simulator, and Icarus Verilog and Verilator running the
//! Verilog that rust-hdl emits ([`crate::harness`]), so that the emitted
//! Verilog itself is checked against the golden model.
//!
//! One build renders every frame: the frames' parts (sweeps or base
//! planes) run one after another on one simulation of one design, and
//! before each part the testbench writes, through the host port, the
//! registers and table words that differ from what the hardware holds (a
//! frame's first part writes its view, transfer function and light). Every
//! engine can trace the whole run, every simulation of it one after another,
//! into a VCD or FST limited as asked ([`crate::trace`]), with a GTKWave save
//! file beside it grouping the signals by stage ([`crate::gtkw`]).

use crate::arch::{Arch, BasePixels, ClockTerm};
use crate::harness::{Engine, Run, Spec};
use crate::trace::Request;
use golden_model::host::Write;
use scene::volume::Volume;
use scene::{Camera, Scene};
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// A frame's run, checked against the golden model.
#[derive(Debug, Clone)]
pub struct Outcome<A: Arch> {
    /// The RTL's base planes, one per part.
    pub bases: Vec<A::Base>,
    /// Clocks the RTL took from each part's `start`, summed over the parts.
    pub clocks: u64,
    /// One sample per unit per clock, summed over the parts.
    pub ideal_clocks: u64,
    /// Where the clocks go as the RTL's schedule predicts them (summed over
    /// the parts; empty where the architecture predicts none).
    pub clock_terms: Vec<ClockTerm>,
    /// Clocks of host writes before the parts (one word a clock): the
    /// registers and table words that changed.
    pub reload_clocks: u64,
    pub mismatches: usize,
    /// The first few mismatching pixels, described.
    pub first: Vec<String>,
    /// Wall time, the simulator alone, and compiling the Verilog
    /// (Icarus; Verilator when its build was not cached). For a run of
    /// several frames these are the whole run's.
    pub seconds: f64,
    pub sim_seconds: f64,
    pub build_seconds: f64,
    /// The units the build leaves out.
    pub left_out: Vec<&'static str>,
}

/// Several frames on one build.
#[derive(Clone)]
pub struct Frames<A: Arch> {
    /// The build's configuration.
    pub config: A::Config,
    /// Simulations of the one design: one per run of parts that share the
    /// memory's contents (Cube-3 loads the volume in each base plane's
    /// traversal order).
    pub memory_loads: usize,
    pub frames: Vec<Outcome<A>>,
    /// What the trace holds, when one was asked for.
    pub traced: Option<crate::trace::Written>,
}

/// Simulate `scene` on `vol` with `engine` on the build the scene needs;
/// `trace` asks for a trace of the run, with a `.gtkw` beside it.
/// Errors name what the RTL cannot do or why a scene is too large for the
/// engine.
pub fn simulate<A: Arch>(
    scene: &Scene,
    camera: &Camera,
    vol: &Volume,
    engine: Engine,
    trace: Option<&Request>,
) -> Result<Outcome<A>, String> {
    simulate_altered::<A>(scene, camera, vol, engine, trace, &|v| v.to_string())
}

/// [`simulate`], with the emitted Verilog passed through `alter` before
/// Icarus or Verilator runs it (fault injection).
pub fn simulate_altered<A: Arch>(
    scene: &Scene,
    camera: &Camera,
    vol: &Volume,
    engine: Engine,
    trace: Option<&Request>,
    alter: &dyn Fn(&str) -> String,
) -> Result<Outcome<A>, String> {
    let frames = [(scene.clone(), camera.clone())];
    let mut r = simulate_frames::<A>(&frames, None, vol, engine, trace, alter)?;
    Ok(r.frames.remove(0))
}

/// Simulate `frames` (scene and camera each) on `vol`, one after another on
/// one build: `build`, or the configuration the first frame needs. Every
/// frame must be one the build renders (the error names why not).
pub fn simulate_frames<A: Arch>(
    frames: &[(Scene, Camera)],
    build: Option<&A::Config>,
    vol: &Volume,
    engine: Engine,
    trace: Option<&Request>,
    alter: &dyn Fn(&str) -> String,
) -> Result<Frames<A>, String> {
    let (first, _) = frames.first().ok_or("no frame to simulate")?;
    let config = match build {
        Some(c) => c.clone(),
        None => A::needs(first, &frames[0].1, vol.dims)?,
    };
    let mut parts = Vec::new();
    for (i, (scene, camera)) in frames.iter().enumerate() {
        let needed = A::needs(scene, camera, vol.dims)?;
        if let Some(why) = A::refuses(&config, &needed) {
            return Err(format!(
                "frame {} needs configuration {}, not {}: {why}",
                i + 1,
                A::config_name(&needed),
                A::config_name(&config)
            ));
        }
        for part in A::parts(scene, camera, vol.dims, &config)? {
            parts.push((i, part));
        }
    }
    let expected: u64 = parts.iter().map(|(_, p)| A::expected_clocks(p)).sum();
    let limit = A::clock_limit(engine);
    if expected > limit {
        return Err(format!(
            "{expected} clocks are too many for {} simulation (limit {limit}){}",
            engine.name(),
            if engine == Engine::Verilator {
                ""
            } else {
                "; use a smaller volume, or the Verilog engine for full frames: --engine verilator"
            }
        ));
    }
    let external = A::external(&config);
    if engine != Engine::Verilator && external {
        let words = A::modules(&parts[0].1, vol).first().map_or(0, |m| m.len());
        return Err(format!(
            "{words} voxels per memory module exceed on-chip memory (2^{}); such volumes need the external memory model of --engine verilator",
            crate::verilog::ON_CHIP_BITS
        ));
    }
    let t = Instant::now();
    // Consecutive parts on one build run in one simulation; before each
    // part the host writes what differs from the build's registers and
    // tables (all of it on a fresh build).
    let mut groups: Vec<std::ops::Range<usize>> = Vec::new();
    for i in 0..parts.len() {
        match groups.last_mut() {
            Some(g) if A::same_build(&parts[g.start].1, &parts[i].1) => g.end = i + 1,
            _ => groups.push(i..i + 1),
        }
    }
    let loads: Vec<Vec<Write>> = groups
        .iter()
        .flat_map(|g| incremental_loads(parts[g.clone()].iter().map(|(_, p)| A::loads(p))))
        .collect();
    let mut results = Vec::new();
    let (mut sim_seconds, mut build_seconds) = (0.0, 0.0);
    // Each simulation traces to a scratch file (a VCD, or under Icarus the
    // format asked for); `trace::finish` joins them.
    let scratch = trace.map(|_| Scratch::new()).transpose()?;
    let ext = match (engine, trace.map(|t| t.format)) {
        (Engine::Iverilog, Some(crate::trace::Format::Fst)) => "fst",
        _ => "vcd",
    };
    let raws: Vec<PathBuf> = match &scratch {
        Some(s) => (0..groups.len())
            .map(|n| s.0.join(format!("part{n}.{ext}")))
            .collect(),
        None => vec![],
    };
    // Verilator dumps only the clocks asked for; its clock count restarts
    // with each simulation, so only a run of one simulation is cut there
    // (the limits apply again as the trace is written).
    let clocks = trace
        .and_then(|t| t.limits.clocks)
        .filter(|_| groups.len() == 1);
    for (n, g) in groups.iter().enumerate() {
        let raw = raws.get(n).map(|p| p.as_path());
        let modules = A::modules(&parts[g.start].1, vol);
        let started = Instant::now();
        match engine {
            Engine::RustHdl => {
                let runs: Vec<(&A::Part, Vec<Write>)> = parts[g.clone()]
                    .iter()
                    .zip(&loads[g.clone()])
                    .map(|((_, p), w)| (p, w.clone()))
                    .collect();
                results.extend(A::rust_hdl(&runs, &modules, raw)?);
                sim_seconds += started.elapsed().as_secs_f64();
            }
            _ => {
                let (r, sim, build) = run_verilog::<A>(
                    &parts[g.clone()],
                    &loads[g.clone()],
                    &modules,
                    engine,
                    raw.map(|p| (p, clocks)),
                    alter,
                    external,
                )?;
                results.extend(r);
                sim_seconds += sim;
                build_seconds += build;
            }
        }
    }
    let memory_loads = groups.len();
    let traced = match trace {
        Some(req) => {
            let top = match engine {
                Engine::RustHdl => "uut",
                Engine::Iverilog => "tb.uut",
                Engine::Verilator => "TOP.top",
            };
            let run_clocks = results.iter().map(|(_, c)| c).sum::<u64>()
                + loads.iter().map(|w| w.len() as u64).sum::<u64>();
            let bar = crate::tool::spinner("writing the trace");
            let written = crate::trace::finish(&raws, top, req, run_clocks);
            bar.finish_and_clear();
            let written = written?;
            crate::gtkw::write_gtkw(req, &written, top, &A::waves(&parts[0].1, top))
                .map_err(|e| format!("{}: {e}", req.path.display()))?;
            Some(written)
        }
        None => None,
    };
    drop(scratch);
    let left_out = crate::verilog::names(&A::left_out(&config));
    let mut out: Vec<Outcome<A>> = frames
        .iter()
        .map(|_| Outcome {
            bases: vec![],
            clocks: 0,
            ideal_clocks: 0,
            clock_terms: vec![],
            reload_clocks: 0,
            mismatches: 0,
            first: vec![],
            seconds: 0.0,
            sim_seconds,
            build_seconds,
            left_out: left_out.clone(),
        })
        .collect();
    for (((frame, part), (records, clocks)), writes) in parts.iter().zip(results).zip(&loads) {
        let o = &mut out[*frame];
        let i = o.bases.len();
        let terms = A::clock_terms(part);
        let predicted: i64 = terms.iter().map(|t| t.clocks).sum();
        if !terms.is_empty() && predicted != clocks as i64 {
            return Err(format!(
                "{} {i}{} took {clocks} clocks; its schedule predicts {predicted}",
                A::PART,
                frame_label(frames.len(), *frame)
            ));
        }
        for term in terms {
            match o.clock_terms.iter_mut().find(|t| t.key == term.key) {
                Some(t) => t.clocks += term.clocks,
                None => o.clock_terms.push(term),
            }
        }
        o.clocks += clocks;
        o.ideal_clocks += A::ideal_clocks(part);
        o.reload_clocks += writes.len() as u64;
        let got = A::decode(part, &records)
            .map_err(|e| format!("{} {i}{}: {e}", A::PART, frame_label(frames.len(), *frame)))?;
        let want = A::golden(part, vol);
        for k in 0..want.count() {
            let ((at, g), (_, r)) = (want.at(k), got.at(k));
            if r != g {
                o.mismatches += 1;
                if o.first.len() < 8 {
                    o.first.push(format!(
                        "{} {i}{} pixel ({}, {}): rtl {r:?}, golden {g:?}",
                        A::PART.replace('_', " "),
                        frame_label(frames.len(), *frame),
                        at[0],
                        at[1]
                    ));
                }
            }
        }
        o.bases.push(got);
    }
    let seconds = t.elapsed().as_secs_f64();
    for o in &mut out {
        o.seconds = seconds;
    }
    Ok(Frames {
        config,
        memory_loads,
        frames: out,
        traced,
    })
}

/// A scratch folder for the engines' own traces, removed when dropped.
struct Scratch(PathBuf);

impl Scratch {
    fn new() -> Result<Scratch, String> {
        static N: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
        let n = N.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        let dir = std::env::temp_dir().join(format!("cube-trace-{}-{n}", std::process::id()));
        std::fs::create_dir_all(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
        Ok(Scratch(dir))
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// ` of frame N` when a run has several frames.
fn frame_label(frames: usize, frame: usize) -> String {
    if frames > 1 {
        format!(" of frame {}", frame + 1)
    } else {
        String::new()
    }
}

/// Per part, the writes that change what the hardware holds: the host
/// skips a register or table word that already has its value.
pub fn incremental_loads(parts: impl IntoIterator<Item = Vec<Write>>) -> Vec<Vec<Write>> {
    let mut held: HashMap<u32, u64> = HashMap::new();
    parts
        .into_iter()
        .map(|writes| {
            writes
                .into_iter()
                .filter(|w| held.insert(w.address, w.data) != Some(w.data))
                .collect()
        })
        .collect()
}

/// Run the parts of one build on its Verilog: one harness invocation,
/// each part a run of its own; per part the records and the clocks, both
/// from its `start`, then the simulator's and the build's seconds.
#[allow(clippy::type_complexity)]
fn run_verilog<A: Arch>(
    parts: &[(usize, A::Part)],
    loads: &[Vec<Write>],
    modules: &[Vec<u16>],
    engine: Engine,
    trace: Option<(&Path, Option<(u64, u64)>)>,
    alter: &dyn Fn(&str) -> String,
    external: bool,
) -> Result<(Vec<(Vec<crate::harness::Record>, u64)>, f64, f64), String> {
    let verilog = alter(&A::verilog(&parts[0].1, (!external).then_some(modules))?);
    let ports = crate::harness::ports(&verilog)?;
    let mut groups = None;
    let runs: Vec<Run> = parts
        .iter()
        .zip(loads)
        .map(|((_, part), w)| {
            let (stop, g) = A::bus(part);
            groups.get_or_insert(g);
            Run {
                vectors: crate::harness::load_then_start(&ports, w),
                stop: stop.after(w.len() as u64),
            }
        })
        .collect();
    let logged = crate::harness::run(
        engine,
        &Spec {
            verilog: &verilog,
            runs: &runs,
            groups: &groups.unwrap_or_default(),
            memory: external.then_some(modules),
            trace: trace.map(|t| t.0),
            trace_clocks: trace.and_then(|t| t.1),
        },
    )?;
    // Split the records by run, with clocks from each run's `start`.
    let mut by_run: Vec<(Vec<crate::harness::Record>, u64)> = logged
        .clocks
        .iter()
        .zip(loads)
        .map(|(&clocks, w)| (vec![], clocks - w.len() as u64))
        .collect();
    let starts: Vec<u64> = logged
        .clocks
        .iter()
        .scan(0u64, |s, &c| {
            let b = *s;
            *s += c;
            Some(b)
        })
        .collect();
    for mut r in logged.records {
        let k = starts.partition_point(|&s| s <= r.clock) - 1;
        r.clock -= starts[k] + loads[k].len() as u64;
        by_run[k].0.push(r);
    }
    Ok((by_run, logged.run_seconds, logged.build_seconds))
}
