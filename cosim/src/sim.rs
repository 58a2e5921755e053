//! Run a whole scene through the pipeline in simulation and compare its base
//! planes with the golden model's, pixel by pixel. Three engines: rust-hdl's
//! own simulator, and Icarus Verilog and Verilator running the Verilog that
//! rust-hdl emits, so that the emitted Verilog itself is checked against the
//! golden model. rust-hdl and Verilator can write a VCD with a GTKWave save
//! file grouping the signals by stage.

use crate::export::{pipeline_verilog, Memory, H, ON_CHIP_BITS as A};
use crate::gtkw::write_gtkw;
use crate::iverilog::run_icarus;
use crate::pixel_log::place;
use golden_model::cube4l::cfb::SkewedMemory;
use golden_model::cube4l::plan::{Face, Plan};
use golden_model::cube4l::shader::Shader as GoldenShader;
use golden_model::cube4l::{render_sweep, BasePlane, Frame, Stats};
use hdl::pipeline::{unpack, Pipeline, PipelineConfig};
use rust_hdl::prelude::*;
use scene::volume::Volume;
use scene::{Camera, Scene};
use std::path::Path;
use std::time::Instant;

/// Clocks above which rust-hdl simulation is refused. With p = 4 the whole
/// pipeline simulates at about 4-5·10^2 clocks/s (measured with `cube sim` on
/// `scenes/sim_*.json`), so this bounds a run to two or three minutes.
pub const MAX_SIM_BEATS: u64 = 1 << 16;

/// One base-plane pixel where RTL and golden model differ.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Mismatch {
    pub sweep: usize,
    pub x: usize,
    pub y: usize,
    pub rtl: ([u32; 4], Face),
    pub golden: ([u32; 4], Face),
}

#[derive(Debug, Clone)]
pub struct SimOutcome {
    /// The RTL's frame: its base planes under the golden model's plan.
    pub frame: Frame,
    pub cycles: u64,
    /// One beat per clock: n_x * n_y * slices * ceil(n_x / p) / (n_x / p).
    pub ideal_cycles: u64,
    pub mismatches: usize,
    /// The first few mismatching pixels.
    pub first: Vec<Mismatch>,
    pub seconds: f64,
    /// Time inside the simulator alone (for Verilator, without its build).
    pub sim_seconds: f64,
    /// Verilator's build time (0 when every sweep's build was cached).
    pub build_seconds: f64,
    /// Units this scene's hardware leaves out (see `export::left_out`).
    pub left_out: Vec<&'static str>,
}

/// The simulator that runs the pipeline.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Engine {
    RustHdl,
    /// Icarus Verilog on the emitted Verilog.
    Iverilog,
    /// Verilator on the emitted Verilog, with a generated C++ harness.
    Verilator,
}

impl Engine {
    pub fn name(self) -> &'static str {
        match self {
            Engine::RustHdl => "rust-hdl",
            Engine::Iverilog => "iverilog",
            Engine::Verilator => "verilator",
        }
    }
}

/// Clocks above which Verilator simulation is refused: about 2.7·10^8, some
/// minutes at its measured speed on the full pipeline.
pub const MAX_VERILATOR_BEATS: u64 = 1 << 28;

/// Clocks above which Icarus simulation is refused: it runs the emitted
/// pipeline at about 10^2 clocks/s (p = 4, compilation included, measured on
/// `scenes/sim_*.json`), so this bounds a run to about five minutes.
pub const MAX_IVERILOG_BEATS: u64 = 1 << 15;

/// Simulate `scene` on `vol` with rust-hdl; `vcd` names a VCD to write (with a
/// `.gtkw` beside it). Errors name what the RTL cannot do yet or why a scene
/// is too large for rust-hdl simulation.
pub fn simulate(
    scene: &Scene,
    camera: &Camera,
    vol: &Volume,
    vcd: Option<&Path>,
) -> Result<SimOutcome, String> {
    simulate_with(scene, camera, vol, Engine::RustHdl, vcd)
}

/// Simulate with either engine (a VCD only with rust-hdl).
pub fn simulate_with(
    scene: &Scene,
    camera: &Camera,
    vol: &Volume,
    engine: Engine,
    vcd: Option<&Path>,
) -> Result<SimOutcome, String> {
    let plan = Plan::new(scene, camera).map_err(|e| e.to_string())?;
    let p = scene.hardware.pipelines;
    let per_module = vol.dims[0].div_ceil(p) * vol.dims[1] * vol.dims[2];
    let memory = Memory::for_volume(vol.dims, p);
    if memory == Memory::External && engine != Engine::Verilator {
        return Err(format!(
            "{per_module} voxels per memory module exceed on-chip memory (2^{A}); \
             such volumes need the external memory model of --engine verilator"
        ));
    }
    let beats: u64 = plan
        .sweeps
        .iter()
        .map(|s| ((s.z1 - s.z0 + 1) * s.dims[1] * s.dims[0].div_ceil(p)) as u64)
        .sum();
    match engine {
        Engine::RustHdl if beats > MAX_SIM_BEATS => {
            return Err(format!(
                "{beats} clocks are too many for rust-hdl simulation (limit {MAX_SIM_BEATS}); use a smaller volume, \
                 or the Verilog engine for full frames: --engine verilator"
            ))
        }
        Engine::Iverilog if beats > MAX_IVERILOG_BEATS => {
            return Err(format!(
                "{beats} clocks are too many for Icarus simulation (limit {MAX_IVERILOG_BEATS}); use --engine verilator"
            ))
        }
        Engine::Verilator if beats > MAX_VERILATOR_BEATS => {
            return Err(format!("{beats} clocks are too many for Verilator simulation (limit {MAX_VERILATOR_BEATS})"))
        }
        _ => {}
    }
    let t = Instant::now();
    let mut bases = Vec::new();
    let (mut cycles, mut ideal, mut mismatches, mut first) = (0, 0, 0, Vec::new());
    let mut left_out = Vec::new();
    let (mut sim_seconds, mut build_seconds) = (0.0, 0.0);
    for (si, sweep) in plan.sweeps.iter().enumerate() {
        let golden = GoldenShader::new(scene, camera, sweep);
        let config = PipelineConfig::new(sweep, vol.dims, p, &golden)?;
        left_out = crate::export::names(&crate::export::left_out(&config, &golden));
        let mem = SkewedMemory::new(vol, p);
        let vcd = if si == 0 { vcd } else { None };
        let started = Instant::now();
        let mut built = 0.0;
        let (base, c) = match (engine, p) {
            (Engine::RustHdl, 1) => run::<1>(&config, &golden, &mem, sweep, vcd)?,
            (Engine::RustHdl, 2) => run::<2>(&config, &golden, &mem, sweep, vcd)?,
            (Engine::RustHdl, 4) => run::<4>(&config, &golden, &mem, sweep, vcd)?,
            (Engine::RustHdl, 8) => run::<8>(&config, &golden, &mem, sweep, vcd)?,
            (Engine::Iverilog, _) => {
                let verilog = pipeline_verilog(&config, &golden, memory, Some(&mem))?;
                let r = run_icarus(&verilog, p, sweep, golden.mode, vcd)?;
                if let Some(path) = vcd {
                    write_gtkw(path, p, "tb.uut")
                        .map_err(|e| format!("{}: {e}", path.display()))?;
                }
                r
            }
            (Engine::Verilator, _) => {
                let verilog = pipeline_verilog(&config, &golden, memory, Some(&mem))?;
                let external = (memory == Memory::External).then_some(&mem);
                let r = crate::verilator::run(&verilog, p, sweep, golden.mode, external, vcd)?;
                if let Some(path) = vcd {
                    write_gtkw(path, p, "TOP.top")
                        .map_err(|e| format!("{}: {e}", path.display()))?;
                }
                built = r.build_seconds;
                sim_seconds += r.run_seconds;
                (r.base, r.cycles)
            }
            _ => {
                return Err(format!(
                    "the RTL is built for 1, 2, 4 or 8 pipelines, not {p}"
                ))
            }
        };
        if engine != Engine::Verilator {
            sim_seconds += started.elapsed().as_secs_f64();
        }
        build_seconds += built;
        let (want, _) = render_sweep(vol, sweep, &golden);
        for i in 0..want.pixels.len() {
            let (r, g) = (
                (base.pixels[i], base.faces[i]),
                (want.pixels[i], want.faces[i]),
            );
            if r != g {
                mismatches += 1;
                if first.len() < 8 {
                    first.push(Mismatch {
                        sweep: si,
                        x: i % want.width,
                        y: i / want.width,
                        rtl: r,
                        golden: g,
                    });
                }
            }
        }
        cycles += c;
        ideal += ((sweep.z1 - sweep.z0 + 1) * sweep.dims[1] * sweep.dims[0].div_ceil(p)) as u64;
        bases.push(base);
    }
    Ok(SimOutcome {
        frame: Frame {
            plan,
            bases,
            stats: Stats::default(),
        },
        cycles,
        ideal_cycles: ideal,
        mismatches,
        first,
        seconds: t.elapsed().as_secs_f64(),
        sim_seconds,
        build_seconds,
        left_out,
    })
}

/// What the testbench collects: the base plane, the clock count, and the
/// first pixel the golden model could never have output.
type Collected = std::sync::Arc<std::sync::Mutex<(BasePlane, u64, Option<String>)>>;

fn run<const P: usize>(
    config: &PipelineConfig,
    golden: &GoldenShader,
    mem: &SkewedMemory,
    sweep: &golden_model::cube4l::plan::Sweep,
    vcd: Option<&Path>,
) -> Result<(BasePlane, u64), String> {
    let mut uut = Pipeline::<P, A, H>::new(config, golden)?;
    uut.cfb.preload(&mem.modules);
    uut.connect_all();
    let beats = ((sweep.z1 - sweep.z0 + 1) * sweep.dims[1] * sweep.dims[0].div_ceil(P)) as u64;
    let mode = golden.mode;
    let out: Collected =
        std::sync::Arc::new(std::sync::Mutex::new((BasePlane::new(sweep), 0, None)));
    let sink = out.clone();
    let mut sim = Simulation::new();
    sim.add_clock(5, |x: &mut Box<Pipeline<P, A, H>>| {
        x.clock.next = !x.clock.val()
    });
    sim.add_testbench(move |mut sim: Sim<Pipeline<P, A, H>>| {
        let mut x = sim.init()?;
        x.start.next = true;
        wait_clock_cycle!(sim, clock, x);
        x.start.next = false;
        let (mut seen, mut cycles) = (0u64, 1u64);
        while seen < beats {
            wait_clock_cycle!(sim, clock, x);
            cycles += 1;
            if !x.lanes[0].res_beat.val() {
                continue;
            }
            seen += 1;
            let mut o = sink.lock().unwrap();
            for lane in x.lanes.iter() {
                if lane.px_valid.val() {
                    let v = unpack(mode, lane.res.val().to_u64());
                    let addr = [lane.px_x.val().to_u64(), lane.px_y.val().to_u64()];
                    let face = lane.px_face.val().to_u64();
                    if let Err(e) = place(&mut o.0, addr, face, v) {
                        // Keep the first stray pixel, with its clock.
                        o.2.get_or_insert(format!("clock {cycles}: {e}"));
                    }
                }
            }
            o.1 = cycles;
        }
        sim.done(x)
    });
    let limit = 10 * (2 * beats + 200);
    match vcd {
        Some(path) => {
            let f = std::fs::File::create(path).map_err(|e| format!("{}: {e}", path.display()))?;
            sim.run_traced(Box::new(uut), limit, f)
                .map_err(|e| format!("simulation: {e:?}"))?;
            write_gtkw(path, P, "uut").map_err(|e| format!("{}: {e}", path.display()))?;
        }
        None => sim
            .run(Box::new(uut), limit)
            .map_err(|e| format!("simulation: {e:?}"))?,
    }
    let o = out.lock().unwrap();
    match &o.2 {
        Some(stray) => Err(stray.clone()),
        None => Ok((o.0.clone(), o.1)),
    }
}
