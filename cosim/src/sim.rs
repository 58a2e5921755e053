//! A whole scene through an architecture's RTL in simulation, its base
//! planes compared with the golden model's pixel by pixel. Three engines:
//! rust-hdl's own simulator, and Icarus Verilog and Verilator running the
//! Verilog that rust-hdl emits ([`crate::harness`]), so that the emitted
//! Verilog itself is checked against the golden model. Every engine can
//! write a VCD, with a GTKWave save file beside it grouping the signals by
//! stage ([`crate::gtkw`]).

use crate::arch::{Arch, BasePixels, ClockTerm};
use crate::harness::{Engine, Spec};
use scene::volume::Volume;
use scene::{Camera, Scene};
use std::path::Path;
use std::time::Instant;

/// A frame's run, checked against the golden model.
#[derive(Debug, Clone)]
pub struct Outcome<A: Arch> {
    /// The RTL's base planes, one per part.
    pub bases: Vec<A::Base>,
    /// Clocks the RTL took, summed over the parts.
    pub clocks: u64,
    /// One sample per unit per clock, summed over the parts.
    pub ideal_clocks: u64,
    /// Where the clocks go as the RTL's schedule predicts them (summed over
    /// the parts; empty where the architecture predicts none).
    pub clock_terms: Vec<ClockTerm>,
    pub mismatches: usize,
    /// The first few mismatching pixels, described.
    pub first: Vec<String>,
    /// Wall time, the simulator alone, and compiling the Verilog
    /// (Icarus; Verilator when its build was not cached).
    pub seconds: f64,
    pub sim_seconds: f64,
    pub build_seconds: f64,
    /// The units the scene's hardware leaves out.
    pub left_out: Vec<&'static str>,
}

/// Simulate `scene` on `vol` with `engine`; `trace` names a VCD of the
/// first part's run to write, with a `.gtkw` beside it. Errors name what
/// the RTL cannot do or why a scene is too large for the engine.
pub fn simulate<A: Arch>(
    scene: &Scene,
    camera: &Camera,
    vol: &Volume,
    engine: Engine,
    trace: Option<&Path>,
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
    trace: Option<&Path>,
    alter: &dyn Fn(&str) -> String,
) -> Result<Outcome<A>, String> {
    let parts = A::parts(scene, camera, vol.dims)?;
    let ideal: u64 = parts.iter().map(A::ideal_clocks).sum();
    let expected: u64 = parts.iter().map(A::expected_clocks).sum();
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
    if engine != Engine::Verilator {
        if let Some(part) = parts.iter().find(|p| A::external(p)) {
            let words = A::modules(part, vol).first().map_or(0, |m| m.len());
            return Err(format!(
                "{words} voxels per memory module exceed on-chip memory (2^{}); such volumes need the external memory model of --engine verilator",
                crate::verilog::ON_CHIP_BITS
            ));
        }
    }
    let t = Instant::now();
    let mut out = Outcome {
        bases: vec![],
        clocks: 0,
        ideal_clocks: ideal,
        clock_terms: vec![],
        mismatches: 0,
        first: vec![],
        seconds: 0.0,
        sim_seconds: 0.0,
        build_seconds: 0.0,
        left_out: crate::verilog::names(&A::left_out(&parts[0])),
    };
    for (i, part) in parts.iter().enumerate() {
        let trace = if i == 0 { trace } else { None };
        let modules = A::modules(part, vol);
        let started = Instant::now();
        let (records, clocks, built) = match engine {
            Engine::RustHdl => {
                let (r, c) = A::rust_hdl(part, &modules, &A::loads(part), trace)?;
                (r, c, 0.0)
            }
            _ => {
                let external = A::external(part);
                let verilog = alter(&A::verilog(part, (!external).then_some(&modules[..]))?);
                let ports = crate::harness::ports(&verilog)?;
                let loads = A::loads(part);
                let vectors = crate::harness::load_then_start(&ports, &loads);
                let (stop, groups) = A::bus(part);
                let logged = crate::harness::run(
                    engine,
                    &Spec {
                        verilog: &verilog,
                        vectors: &vectors,
                        stop: stop.after(loads.len() as u64),
                        groups: &groups,
                        memory: external.then_some(&modules[..]),
                        trace,
                    },
                )?;
                // Clocks from `start`, as rust-hdl's testbench counts them.
                let n = loads.len() as u64;
                let records = logged
                    .records
                    .into_iter()
                    .map(|mut r| {
                        r.clock -= n;
                        r
                    })
                    .collect();
                (records, logged.clocks - n, logged.build_seconds)
            }
        };
        out.sim_seconds += started.elapsed().as_secs_f64() - built;
        out.build_seconds += built;
        if let Some(path) = trace {
            let top = match engine {
                Engine::RustHdl => "uut",
                Engine::Iverilog => "tb.uut",
                Engine::Verilator => "TOP.top",
            };
            crate::gtkw::write_gtkw(path, top, &A::waves(part, top))
                .map_err(|e| format!("{}: {e}", path.display()))?;
        }
        let terms = A::clock_terms(part);
        let predicted: i64 = terms.iter().map(|t| t.clocks).sum();
        if !terms.is_empty() && predicted != clocks as i64 {
            return Err(format!(
                "{} {i} took {clocks} clocks; its schedule predicts {predicted}",
                A::PART
            ));
        }
        for term in terms {
            match out.clock_terms.iter_mut().find(|t| t.key == term.key) {
                Some(t) => t.clocks += term.clocks,
                None => out.clock_terms.push(term),
            }
        }
        out.clocks += clocks;
        let got = A::decode(part, &records)?;
        let want = A::golden(part, vol);
        for j in 0..want.count() {
            let ((at, g), (_, r)) = (want.at(j), got.at(j));
            if r != g {
                out.mismatches += 1;
                if out.first.len() < 8 {
                    out.first.push(format!(
                        "{} {i} pixel ({}, {}): rtl {r:?}, golden {g:?}",
                        A::PART.replace('_', " "),
                        at[0],
                        at[1]
                    ));
                }
            }
        }
        out.bases.push(got);
    }
    out.seconds = t.elapsed().as_secs_f64();
    Ok(out)
}
