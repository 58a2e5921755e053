//! Run a whole scene through the Cube-3 system (`hdl::cube3_system`) in
//! simulation and compare its base planes with the golden model's
//! (`golden_model::cube3`), pixel by pixel: in rust-hdl, or the Verilog it
//! emits under Icarus or Verilator (through [`crate::stage`]'s testbench,
//! logging only the clocks with a pixel). The volume is preloaded into the
//! memory modules in each base plane's traversal order.
//!
//! Built: parallel and perspective views in every mode (the 6- or the
//! 12-neighbourhood where gradients are used), a system per base plane;
//! the 10 and 26 get one line naming what the RTL does not build.

use crate::gtkw::write_gtkw_cube3;
use crate::sim::Engine;
use crate::stage::{run_stage_logged, start_only, StageEngine};
use golden_model::cube3::plan::View;
use golden_model::cube3::{render, BasePlane, Frame};
use hdl::cube3_system::{Cube3System, Cube3SystemConfig};
use rust_hdl::prelude::*;
use scene::volume::Volume;
use scene::{Camera, Scene};
use std::path::Path;
use std::time::Instant;

/// Memory-module, 2-DSB and delay-line address bits: the export's.
const A: usize = crate::export::ON_CHIP_BITS;
const B: usize = crate::export::CUBE3_BUFFER_BITS;
const H: usize = crate::export::CUBE3_LINE_BITS;

/// Clock limits per engine, as for Cube-4L (`sim::MAX_*_BEATS`).
fn limit(engine: Engine) -> u64 {
    match engine {
        Engine::RustHdl => crate::sim::MAX_SIM_BEATS,
        Engine::Iverilog => crate::sim::MAX_IVERILOG_BEATS,
        Engine::Verilator => crate::sim::MAX_VERILATOR_BEATS,
    }
}

/// Where a frame's clocks go, summed over its base planes: `total =
/// segments + idle + prologue - tail + drain`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct ClockCount {
    /// `n_x·n_y·K / P` of each base plane: one sample per unit per clock.
    pub ideal: u64,
    /// One clock per segment: `R·S·G` for `R` rays (the base plane's
    /// columns and 3 more) of `S` scanlines of `G = ceil(K / P)` segments.
    pub segments: u64,
    /// Clocks a scanline period waits beyond its reads, where writing a
    /// PRP takes longer: `S·(T - R·G)`.
    pub idle: u64,
    /// From `start` to the first segment: two periods of PRPs and 2 clocks.
    pub prologue: u64,
    /// The last period's wait, which the frame does not spend: `T - R·G`.
    pub tail: u64,
    /// The last pixel's way through the pipeline (`pixel_delay`).
    pub drain: u64,
    /// The clocks from `start` to the last pixel.
    pub total: u64,
}

#[derive(Debug, Clone)]
pub struct Cube3Outcome {
    /// The RTL's frame: its base planes under the golden model's plan.
    pub frame: Frame,
    pub clocks: ClockCount,
    pub mismatches: usize,
    /// The first few mismatching pixels, described.
    pub first: Vec<String>,
    pub seconds: f64,
    /// Simulating alone, and compiling the Verilog (Icarus, Verilator).
    pub sim_seconds: f64,
    pub build_seconds: f64,
}

/// One base plane's design and contents.
struct Design {
    config: Cube3SystemConfig,
    modules: Vec<Vec<u16>>,
}

fn design(scene: &Scene, camera: &Camera, vol: &Volume, view: &View) -> Result<Design, String> {
    let config = crate::export::cube3_config(scene, camera, view)?;
    let modules = config.fetch.modules(vol, view);
    Ok(Design { config, modules })
}

fn count(c: &Cube3SystemConfig) -> ClockCount {
    let f = &c.fetch;
    let [nx, ny, nk] = f.dims;
    let rg = (f.rays * f.segments) as u64;
    let (s, t) = (f.scanlines as u64, f.period() as u64);
    let n = ClockCount {
        ideal: ((nx * ny * nk) as u64).div_ceil(f.p as u64),
        segments: rg * s,
        idle: s * (t - rg),
        prologue: c.first_entry() as u64,
        tail: t - rg,
        drain: c.pipeline.pixel_delay() as u64,
        total: c.clocks() as u64,
    };
    assert_eq!(n.total, n.segments + n.idle + n.prologue - n.tail + n.drain);
    n
}

/// The base-plane pixels `(clock, [r, g, b, a], has_sample)` in stream
/// order, into a base plane shaped as the golden model's.
fn place(c: &Cube3SystemConfig, want: &BasePlane, pixels: &[([u64; 4], bool)]) -> BasePlane {
    let mut base = BasePlane {
        pixels: vec![[0; 4]; want.pixels.len()],
        cast: vec![false; want.cast.len()],
        ..want.clone()
    };
    let r = c.fetch.rays;
    for (n, (px, has)) in pixels.iter().enumerate() {
        let (u, v) = (c.fetch.u0 + (n % r) as i32, c.fetch.v0 + (n / r) as i32);
        let (x, y) = (u - base.u0, v - base.v0);
        if n % r + 1 < r
            && x >= 0
            && (x as usize) < base.width
            && y >= 0
            && (y as usize) < base.height
        {
            let i = y as usize * base.width + x as usize;
            base.pixels[i] = px.map(|v| v as u32);
            base.cast[i] = *has;
        }
    }
    base
}

/// Simulate `scene` with `engine`; `vcd` names a VCD of the first base
/// plane's run to write, with a `.gtkw` beside it.
pub fn simulate(
    scene: &Scene,
    camera: &Camera,
    vol: &Volume,
    engine: Engine,
    vcd: Option<&Path>,
) -> Result<Cube3Outcome, String> {
    simulate_altered(scene, camera, vol, engine, vcd, &|v| v.to_string())
}

/// [`simulate`], with the emitted Verilog passed through `alter` before
/// Icarus or Verilator runs it (fault injection).
pub fn simulate_altered(
    scene: &Scene,
    camera: &Camera,
    vol: &Volume,
    engine: Engine,
    vcd: Option<&Path>,
    alter: &dyn Fn(&str) -> String,
) -> Result<Cube3Outcome, String> {
    let n = golden_model::cube3::neighbourhood(scene, None).map_err(|e| e.to_string())?;
    let golden = render(scene, camera, vol, n).map_err(|e| e.to_string())?;
    let designs: Vec<Design> = golden
        .plan
        .views
        .iter()
        .map(|v| design(scene, camera, vol, v))
        .collect::<Result<_, _>>()?;
    let mut clocks = ClockCount::default();
    for d in &designs {
        let c = count(&d.config);
        clocks.ideal += c.ideal;
        clocks.segments += c.segments;
        clocks.idle += c.idle;
        clocks.prologue += c.prologue;
        clocks.tail += c.tail;
        clocks.drain += c.drain;
        clocks.total += c.total;
    }
    if clocks.total > limit(engine) {
        return Err(format!(
            "{} clocks are too many for {} simulation (limit {})",
            clocks.total,
            engine.name(),
            limit(engine)
        ));
    }
    let t = Instant::now();
    let (mut bases, mut mismatches, mut first) = (vec![], 0, vec![]);
    let (mut sim_seconds, mut build_seconds) = (0.0, 0.0);
    for (vi, (d, want)) in designs.iter().zip(&golden.bases).enumerate() {
        let started = Instant::now();
        let vcd = if vi == 0 { vcd } else { None };
        if d.config.fetch.external && engine != Engine::Verilator {
            return Err(format!(
                "{} voxels per memory module exceed on-chip memory (2^{}); such volumes need the external memory model of --engine verilator",
                d.config.fetch.module_words(),
                crate::export::ON_CHIP_BITS
            ));
        }
        let p = d.config.pipeline.p;
        let mut built = 0.0;
        let pixels = match (engine, p) {
            (Engine::RustHdl, 1) => run::<1>(d, vcd)?,
            (Engine::RustHdl, 2) => run::<2>(d, vcd)?,
            (Engine::RustHdl, 4) => run::<4>(d, vcd)?,
            (Engine::RustHdl, 8) => run::<8>(d, vcd)?,
            (Engine::Iverilog, _) => {
                run_verilog(d, StageEngine::Iverilog, vcd, "tb.uut", alter, &mut built)?
            }
            (Engine::Verilator, _) => {
                run_verilog(d, StageEngine::Verilator, vcd, "TOP.top", alter, &mut built)?
            }
            _ => return Err(format!("hardware.pipelines {p} unsupported (1, 2, 4 or 8)")),
        };
        sim_seconds += started.elapsed().as_secs_f64() - built;
        build_seconds += built;
        let base = place(&d.config, want, &pixels);
        for i in 0..want.pixels.len() {
            let (r, g) = (
                (base.pixels[i], base.cast[i]),
                (want.pixels[i], want.cast[i]),
            );
            if r != g {
                mismatches += 1;
                if first.len() < 8 {
                    first.push(format!(
                        "base plane {vi} pixel ({}, {}): rtl {:?}, golden {:?}",
                        want.u0 + (i % want.width) as i32,
                        want.v0 + (i / want.width) as i32,
                        r,
                        g
                    ));
                }
            }
        }
        bases.push(base);
    }
    Ok(Cube3Outcome {
        frame: Frame { bases, ..golden },
        clocks,
        mismatches,
        first,
        seconds: t.elapsed().as_secs_f64(),
        sim_seconds,
        build_seconds,
    })
}

type Pixels = Vec<([u64; 4], bool)>;

fn run<const P: usize>(d: &Design, vcd: Option<&Path>) -> Result<Pixels, String> {
    let mut uut = Cube3System::<P, A, B, H>::new(&d.config)?;
    uut.preload(&d.modules);
    uut.connect_all();
    let clocks = d.config.clocks();
    let out = std::sync::Arc::new(std::sync::Mutex::new(Vec::new()));
    let sink = out.clone();
    let mut sim = Simulation::new();
    sim.add_clock(5, |x: &mut Box<Cube3System<P, A, B, H>>| {
        x.clock.next = !x.clock.val()
    });
    sim.add_testbench(move |mut sim: Sim<Cube3System<P, A, B, H>>| {
        let mut x = sim.init()?;
        for t in 0..clocks {
            x.start.next = t == 0;
            wait_clock_cycle!(sim, clock, x);
            if x.done.val() {
                let px = [
                    x.pixel_r.val().to_u64(),
                    x.pixel_g.val().to_u64(),
                    x.pixel_b.val().to_u64(),
                    x.pixel_a.val().to_u64(),
                ];
                sink.lock().unwrap().push((px, x.has_sample.val()));
            }
        }
        sim.done(x)
    });
    let limit = 10 * clocks as u64 + 100;
    match vcd {
        Some(path) => {
            let f = std::fs::File::create(path).map_err(|e| format!("{}: {e}", path.display()))?;
            sim.run_traced(Box::new(uut), limit, f)
                .map_err(|e| format!("simulation: {e:?}"))?;
            write_gtkw_cube3(path, &d.config.pipeline, "uut")
                .map_err(|e| format!("{}: {e}", path.display()))?;
        }
        None => sim
            .run(Box::new(uut), limit)
            .map_err(|e| format!("simulation: {e:?}"))?,
    }
    let pixels = out.lock().unwrap().clone();
    Ok(pixels)
}

/// Run the emitted Verilog; `vcd` gets the trace and a `.gtkw` for the
/// design's scope `top`.
fn run_verilog(
    d: &Design,
    engine: StageEngine,
    vcd: Option<&Path>,
    top: &str,
    alter: &dyn Fn(&str) -> String,
    build_seconds: &mut f64,
) -> Result<Pixels, String> {
    let v = alter(&crate::export::cube3_verilog(&d.config, Some(&d.modules))?);
    let ports = crate::stage::ports(&v)?;
    let names: Vec<&str> = ports
        .iter()
        .filter(|p| !p.input)
        .map(|p| p.name.as_str())
        .collect();
    // `start` on the first clock; the external memory's data come from the
    // harness.
    let vectors = vec![start_only(&ports, 0), start_only(&ports, 1)];
    let logged = run_stage_logged(
        engine,
        &v,
        &vectors,
        d.config.clocks(),
        Some("done"),
        vcd,
        d.config.fetch.external.then_some(&d.modules[..]),
    )?;
    if let Some(path) = vcd {
        write_gtkw_cube3(path, &d.config.pipeline, top)
            .map_err(|e| format!("{}: {e}", path.display()))?;
    }
    *build_seconds = logged.build_seconds;
    logged
        .logged
        .iter()
        .map(|(t, o)| {
            let get = |n: &str| {
                o[names.iter().position(|x| *x == n).expect("a system output")]
                    .ok_or_else(|| format!("clock {t}: {n} is unknown"))
            };
            Ok((
                [
                    get("pixel_r")?,
                    get("pixel_g")?,
                    get("pixel_b")?,
                    get("pixel_a")?,
                ],
                get("has_sample")? == 1,
            ))
        })
        .collect()
}
