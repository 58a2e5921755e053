//! Run a whole scene through the pipeline in simulation and compare its base
//! planes with the golden model's, pixel by pixel. Three engines: rust-hdl's
//! own simulator, and Icarus Verilog and Verilator running the Verilog that
//! rust-hdl emits, so that the emitted Verilog itself is checked against the
//! golden model. rust-hdl and Verilator can write a VCD with a GTKWave save
//! file grouping the signals by stage.

use crate::export::{pipeline_verilog, Memory, H, ON_CHIP_BITS as A};
use crate::pipeline::{unpack, Pipeline, PipelineConfig};
use golden_model::cfb::SkewedMemory;
use golden_model::cube4l::{render_sweep, BasePlane, Frame, Stats};
use golden_model::plan::{Face, Plan};
use golden_model::scene::{Camera, Scene};
use golden_model::shader::Shader as GoldenShader;
use golden_model::volume::Volume;
use rust_hdl::prelude::*;
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

fn face_of(code: u32) -> Face {
    [
        Face::None,
        Face::Last,
        Face::XPos,
        Face::XNeg,
        Face::YPos,
        Face::YNeg,
    ][code as usize]
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
        Engine::Iverilog if vcd.is_some() => {
            return Err("--vcd is written by the rust-hdl and verilator engines".into())
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
                run_icarus(&verilog, p, sweep, golden.mode)?
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

type Collected = std::sync::Arc<std::sync::Mutex<(BasePlane, u64)>>;

fn run<const P: usize>(
    config: &PipelineConfig,
    golden: &GoldenShader,
    mem: &SkewedMemory,
    sweep: &golden_model::plan::Sweep,
    vcd: Option<&Path>,
) -> Result<(BasePlane, u64), String> {
    let mut uut = Pipeline::<P, A, H>::new(config, golden)?;
    uut.cfb.preload(&mem.modules);
    uut.connect_all();
    let beats = ((sweep.z1 - sweep.z0 + 1) * sweep.dims[1] * sweep.dims[0].div_ceil(P)) as u64;
    let mode = golden.mode;
    let out: Collected = std::sync::Arc::new(std::sync::Mutex::new((BasePlane::new(sweep), 0)));
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
                    let addr = [
                        lane.px_x.val().to_u32() as usize,
                        lane.px_y.val().to_u32() as usize,
                    ];
                    o.0.put(addr, v, face_of(lane.px_face.val().to_u32()));
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
    Ok((o.0.clone(), o.1))
}

/// Simulate emitted pipeline Verilog (from [`pipeline_verilog`] with on-chip
/// memory preloaded, possibly altered)
/// under Icarus for one sweep; returns the base plane of the pixels it put
/// out and its clock count.
pub fn run_icarus(
    verilog: &str,
    p: usize,
    sweep: &golden_model::plan::Sweep,
    mode: golden_model::scene::Mode,
) -> Result<(BasePlane, u64), String> {
    let beats = ((sweep.z1 - sweep.z0 + 1) * sweep.dims[1] * sweep.dims[0].div_ceil(p)) as u64;
    static RUNS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let run = RUNS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let dir = std::env::temp_dir().join(format!("cube-iverilog-{}-{run}", std::process::id()));
    std::fs::create_dir_all(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let result = (|| {
        std::fs::write(dir.join("top.v"), verilog).map_err(|e| e.to_string())?;
        std::fs::write(dir.join("tb.v"), testbench_verilog(p, beats)).map_err(|e| e.to_string())?;
        crate::tool::run(
            std::process::Command::new("iverilog")
                .args(["-g2012", "-o", "sim.vvp", "top.v", "tb.v"])
                .current_dir(&dir),
            "Icarus Verilog (iverilog)",
        )?;
        crate::tool::run(
            std::process::Command::new("vvp")
                .args(["-n", "sim.vvp"])
                .current_dir(&dir),
            "Icarus Verilog (vvp)",
        )?;
        let log = std::fs::read_to_string(dir.join("pixels.txt")).map_err(|e| e.to_string())?;
        let (base, cycles) = parse_pixel_log(&log, sweep, mode)?;
        // Counted like the rust-hdl engine: from the clock that registers start.
        Ok((base, cycles + 1))
    })();
    let _ = std::fs::remove_dir_all(&dir);
    result
}

/// Parse a Verilog engine's pixel log: `x y face res` per pixel on the bus,
/// then `cycles N` (or `timeout`).
pub fn parse_pixel_log(
    log: &str,
    sweep: &golden_model::plan::Sweep,
    mode: golden_model::scene::Mode,
) -> Result<(BasePlane, u64), String> {
    let mut base = BasePlane::new(sweep);
    let mut cycles = None;
    for line in log.lines() {
        let f: Vec<&str> = line.split_whitespace().collect();
        match f.as_slice() {
            ["cycles", c] => cycles = c.parse::<u64>().ok(),
            ["timeout"] => return Err("the Verilog pipeline did not finish the sweep".into()),
            [x, y, face, res] => {
                let n = |s: &str| {
                    s.parse::<u64>()
                        .map_err(|e| format!("pixel log '{line}': {e}"))
                };
                base.put(
                    [n(x)? as usize, n(y)? as usize],
                    unpack(mode, n(res)?),
                    face_of(n(face)? as u32),
                );
            }
            _ => return Err(format!("unexpected line in the pixel log: '{line}'")),
        }
    }
    Ok((base, cycles.ok_or("the pixel log has no clock count")?))
}

/// A Verilog testbench for the emitted `top`: clock, one start pulse, and a
/// log line `x y face res` for every pixel on the bus until `beats` beats
/// have come out; then `cycles N` (or `timeout`).
fn testbench_verilog(p: usize, beats: u64) -> String {
    let mut v =
        String::from("`timescale 1ns/1ps\nmodule tb;\n  reg clock = 0;\n  reg start = 0;\n");
    let mut ports = String::from(
        ".clock(clock), .start(start), .load_enable(1'b0), .load_module(8'd0), .load_address({A}'d0), .load_data(16'd0)",
    )
    .replace("{A}", &A.to_string());
    let mut log = String::new();
    for k in 0..p {
        v.push_str(&format!(
            "  wire px_valid${k};\n  wire [15:0] px_x${k};\n  wire [15:0] px_y${k};\n  wire [2:0] px_face${k};\n  wire res_beat${k};\n  wire res_valid${k};\n  wire [63:0] res${k};\n"
        ));
        ports.push_str(&format!(", .ext_data${k}(16'd0)"));
        for n in [
            "px_valid",
            "px_x",
            "px_y",
            "px_face",
            "res_beat",
            "res_valid",
            "res",
        ] {
            ports.push_str(&format!(", .{n}${k}({n}${k})"));
        }
        log.push_str(&format!(
            "      if (px_valid${k}) $fdisplay(f, \"%0d %0d %0d %0d\", px_x${k}, px_y${k}, px_face${k}, res${k});\n"
        ));
    }
    v.push_str(&format!(
        "  top uut({ports});\n  always #5 clock = ~clock;\n"
    ));
    v.push_str(&format!(
        "  integer f;\n  integer beats = 0;\n  integer cycles = 0;\n  initial begin\n    f = $fopen(\"pixels.txt\", \"w\");\n    @(negedge clock) start = 1;\n    @(negedge clock) start = 0;\n    while (beats < {beats}) begin\n      @(posedge clock);\n      #1;\n      cycles = cycles + 1;\n      if (res_beat$0) beats = beats + 1;\n{log}      if (cycles > {limit}) begin\n        $fdisplay(f, \"timeout\");\n        beats = {beats};\n      end\n    end\n    $fdisplay(f, \"cycles %0d\", cycles);\n    $fclose(f);\n    $finish;\n  end\nendmodule\n",
        limit = 2 * beats + 1000
    ));
    v
}

/// A GTKWave save file beside `vcd` that opens with the signals grouped by
/// stage: CFB counters, then per pipeline its CFB lane, compositing-buffer
/// taps, and pixel output. `top` is the design's scope in the VCD (`uut` for
/// rust-hdl, `TOP.top` for Verilator).
pub fn write_gtkw(vcd: &Path, p: usize, top: &str) -> std::io::Result<()> {
    let mut s = format!(
        "[dumpfile] \"{}\"\n[timestart] 0\n[size] 1400 900\n",
        vcd.display()
    );
    let group = |s: &mut String, name: &str, sigs: Vec<String>| {
        s.push_str(&format!("@800200\n-{name}\n@22\n"));
        for sig in sigs {
            s.push_str(&sig);
            s.push('\n');
        }
        s.push_str(&format!("@1000200\n-{name}\n"));
    };
    let under = |prefix: &str, names: &[&str]| {
        names
            .iter()
            .map(|n| format!("{prefix}.{n}"))
            .collect::<Vec<_>>()
    };
    s.push_str(&format!("@28\n{top}.clock\n{top}.start\n"));
    group(
        &mut s,
        "CFB",
        under(
            &format!("{top}.cfb"),
            &["valid", "n_s[15:0]", "n_beam[15:0]", "n_b[15:0]", "bs"],
        ),
    );
    for k in 0..p {
        let cfb_lane = [
            "x[15:0]",
            "y[15:0]",
            "z[15:0]",
            "value[15:0]",
            "address[31:0]",
            "pad",
            "halo",
            "sr",
            "er",
            "at_edge",
            "invalid",
            "face[2:0]",
            "dx_neg",
            "dx_mag[15:0]",
            "dy_neg",
            "dy_mag[15:0]",
        ];
        group(
            &mut s,
            &format!("CFB lane {k}"),
            under(&format!("{top}.cfb.lanes${k}"), &cfb_lane),
        );
        let lane = format!("{top}.lanes${k}");
        let abc = [
            "o_valid",
            "o_value[15:0]",
            "gx_neg",
            "gx_mag[15:0]",
            "gy_neg",
            "gy_mag[15:0]",
            "gz_neg",
            "gz_mag[15:0]",
        ];
        group(
            &mut s,
            &format!("ABC gradient {k}"),
            under(&format!("{lane}.abc"), &abc),
        );
        let shader = ["valid", "r[15:0]", "g[15:0]", "b[15:0]", "a[15:0]"];
        group(
            &mut s,
            &format!("Shader {k}"),
            under(&format!("{lane}.shader"), &shader),
        );
        let mut taps: Vec<String> = (0..9).map(|c| format!("{lane}.a{c}[63:0]")).collect();
        taps.extend(under(&lane, &["res_valid", "res[63:0]"]));
        group(&mut s, &format!("Compositing lane {k}"), taps);
        group(
            &mut s,
            &format!("Pixel out {k}"),
            under(
                &lane,
                &["px_valid", "px_x[15:0]", "px_y[15:0]", "px_face[2:0]"],
            ),
        );
    }
    let gtkw = vcd.with_extension("gtkw");
    let tmp = gtkw.with_extension("gtkw.tmp");
    std::fs::write(&tmp, s)?;
    std::fs::rename(tmp, gtkw)
}
