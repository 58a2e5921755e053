//! `hdl::cube4l::cfb` against `golden_model::cube4l::cfb::CfbStream`: the memory is loaded
//! through the load port, the view's registers are set
//! (`golden_model::cube4l::regs::ViewRegs`), then every beat of the sweep
//! is compared lane by lane, cycle by cycle, in rust-hdl simulation. One
//! CFB serves every view of a test: it is built for the largest volume the
//! test uses.

use golden_model::cube4l::cfb::{CfbStream, SkewedMemory};
use golden_model::cube4l::plan::{Plan, Rays};
use golden_model::cube4l::regs::ViewRegs;
use hdl::common::mode_class::ModeClass;
use hdl::cube4l::{
    cfb::{face_code, Cfb},
    cfb_stages::{ADDRESS_STAGES, READ_STAGES},
    counter_lead::LEAD,
    PipelineConfig,
};
use rust_hdl::prelude::*;
use scene::volume::builtin;
use testbenches::{require_tool, run_sim, scene};

const A: usize = 12;

/// The CFB of a build for volumes of up to 16 voxels a side.
fn build(p: usize, perspective: bool, frac_bits: u32) -> PipelineConfig {
    PipelineConfig {
        p: p as u32,
        mode: ModeClass::Over,
        shading: false,
        gradient_opacity: false,
        perspective,
        max_dim: 16,
        voxel_bits: 8,
        rgba_bits: 8,
        frac_bits,
        normal_bits: hdl::common::shader::unlit_normal_bits(),
    }
}

fn views() -> [&'static str; 8] {
    [
        r#"{"projection": "perspective", "eye": [4, 5, -9], "fov_deg": 100}"#,
        r#"{"projection": "perspective", "eye": [30, 4, 3.5], "fov_deg": 70}"#,
        r#"{"projection": "perspective", "eye": [3.3, 4.6, 2.2], "target": [5, 3, 6], "fov_deg": 120}"#,
        r#"{"projection": "parallel"}"#,
        r#"{"projection": "parallel", "rotate_deg": [70, 30, 0]}"#,
        r#"{"projection": "parallel", "rotate_deg": [0, 45, 0]}"#,
        r#"{"projection": "parallel", "rotate_deg": [-20, 135, 10]}"#,
        r#"{"projection": "parallel", "rotate_deg": [90, 0, 0]}"#,
    ]
}

fn run<const P: usize>(dims: [usize; 3], view: &str) {
    let s = scene(&format!(
        r#"{{"volume": {{"builtin": "phantom", "dims": {dims:?}}}, "view": {view}, "image": [16, 16], "hardware": {{"pipelines": {P}}}}}"#
    ));
    let vol = builtin("phantom", dims, 8).unwrap();
    let plan = Plan::new(&s, &s.camera()).unwrap();
    for sweep in &plan.sweeps {
        run_sweep::<P>(
            &vol,
            sweep,
            &format!("p={P} {dims:?} {view} sweep axis {}", sweep.axis()),
        );
    }
}

fn run_sweep<const P: usize>(
    vol: &scene::volume::Volume,
    sweep: &golden_model::cube4l::plan::Sweep,
    label: &str,
) {
    run_sweep_memory::<P>(vol, sweep, label, false)
}

/// With `external`, the voxels come from a RAM model in the testbench that
/// answers each lane's `ext_addr` one clock later; otherwise the memory is
/// loaded through the load port.
fn run_sweep_memory<const P: usize>(
    vol: &scene::volume::Volume,
    sweep: &golden_model::cube4l::plan::Sweep,
    label: &str,
    external: bool,
) {
    let label = label.to_string();
    let mem = SkewedMemory::new(vol, P);
    assert!(
        mem.modules[0].len() <= 1 << A,
        "test volume too large for {A} address bits"
    );
    let beats: Vec<_> = CfbStream::new(&mem, vol.dims, sweep).collect();
    let config = build(
        P,
        matches!(sweep.rays, Rays::Perspective { .. }),
        sweep.frac,
    );
    let words = ViewRegs::new(sweep, vol.dims, P, false, scene::Mode::Composite).words();
    let mut uut = Cfb::<P, A>::new(&config, external);
    let perspective = config.perspective;
    uut.connect_all();
    let mut sim = Simulation::new();
    sim.add_clock(5, |x: &mut Box<Cfb<P, A>>| x.clock.next = !x.clock.val());
    let modules = mem.modules.clone();
    let total = (mem.modules.len() * mem.modules[0].len() + 4 * beats.len() + 64) as u64;
    let label_for_vcd = label.clone();
    sim.add_testbench(move |mut sim: Sim<Cfb<P, A>>| {
        let mut x = sim.init()?;
        // The view's registers (the pipeline's register file drives them).
        x.dims.next = words[0].to_bits();
        x.slices.next = words[1].to_bits();
        x.axes.next = words[2].to_bits();
        x.address_reg.next = words[3].to_bits();
        x.dx.next = words[4].to_bits();
        x.dy.next = words[5].to_bits();
        x.eye_x.next = words[6].to_bits();
        x.eye_y.next = words[7].to_bits();
        x.eye_z.next = words[8].to_bits();
        x.beats.next = words[9].to_bits();
        // Load the skewed memory, one word per clock (the internal memory).
        for (k, module) in modules.iter().enumerate().filter(|_| !external) {
            for (i, &v) in module.iter().enumerate() {
                x.load_enable.next = true;
                x.load_module.next = (k as u64).to_bits();
                x.load_address.next = (i as u64).to_bits();
                x.load_data.next = (v as u64).to_bits();
                wait_clock_cycle!(sim, clock, x);
            }
        }
        x.load_enable.next = false;
        x.start.next = true;
        wait_clock_cycle!(sim, clock, x);
        x.start.next = false;
        let mut next = 0;
        let mut cycles = 0u64;
        // The address of the first beat is presented in the clock after start.
        let mut pending: [usize; P] = std::array::from_fn(|k| x.ext_addr[k].val().to_u32() as usize);
        while next < beats.len() {
            wait_clock_cycle!(sim, clock, x);
            cycles += 1;
            assert!(cycles < 4 * beats.len() as u64 + 16, "{label}: stream stalled at beat {next}");
            if external {
                // The external RAM model: at the edge it returns the word
                // addressed in the clock before; outputs are compared half a
                // clock later, once they have settled.
                for k in 0..P {
                    x.ext_data[k].next = (modules[k].get(pending[k]).copied().unwrap_or(0) as u64).to_bits();
                    pending[k] = x.ext_addr[k].val().to_u32() as usize;
                }
                wait_clock_false!(sim, clock, x);
            }
            if !x.valid.val() {
                continue;
            }
            let beat = &beats[next];
            let shared = [
                ("n_s", x.n_s.val().to_u32(), beat.n_s as u32),
                ("n_beam", x.n_beam.val().to_u32(), beat.n_beam as u32),
                ("n_b", x.n_b.val().to_u32(), beat.n_b as u32),
            ];
            for (name, rtl, golden) in shared {
                assert_eq!(rtl, golden, "{label}: beat {next}, {name}: rtl {rtl} golden {golden}");
            }
            for (k, g) in beat.lanes.iter().enumerate() {
                let c = g.control;
                let (bx, by) = g.pixel.map_or((0, 0), |[a, b]| (a as u32, b as u32));
                let fields = [
                    ("x", x.x[k].val().to_u32(), g.pos[0] as u32),
                    ("y", x.y[k].val().to_u32(), g.pos[1] as u32),
                    ("z", x.z[k].val().to_u32(), g.pos[2] as u32),
                    ("address", x.address[k].val().to_u32(), g.address as u32),
                    ("value", x.value[k].val().to_u32(), g.value as u32),
                    ("pad", x.pad[k].val() as u32, g.pad as u32),
                    ("bs", x.bs.val() as u32, g.bs as u32),
                    ("sr", x.sr[k].val() as u32, c.sr as u32),
                    ("er", x.er[k].val() as u32, c.er as u32),
                    ("invalid", x.invalid[k].val() as u32, c.invalid as u32),
                    ("dx", sign_mag(x.dx_neg[k].val(), x.dx_mag[k].val().to_u32()), c.dx as u32),
                    ("dy", sign_mag(x.dy_neg[k].val(), x.dy_mag[k].val().to_u32()), c.dy as u32),
                    ("at_edge", x.at_edge[k].val() as u32, c.edge as u32),
                    ("face", x.face[k].val().to_u32(), face_code(c.face)),
                    ("base_x", x.base_x[k].val().to_u32(), bx),
                    ("base_y", x.base_y[k].val().to_u32(), by),
                ];
                for (name, rtl, golden) in fields {
                    if rtl != golden {
                        panic!("{label}: first mismatch at beat {next} (cycle {cycles}), lane {k}, {name}: rtl {rtl} golden {golden}");
                    }
                }
            }
            next += 1;
        }
        // One beat per clock with no gaps: counted from the clock after the
        // start pulse is registered (the RAM read latency overlaps it), the
        // last beat is out after as many clocks as there are beats, and the
        // address stages and the read's output register, and for
        // perspective views the counters' lead before the address.
        let lead = if perspective { LEAD as u64 } else { 0 };
        assert_eq!(
            cycles,
            beats.len() as u64 + ADDRESS_STAGES as u64 + READ_STAGES as u64 - 1 + lead,
            "{label}: clocks per sweep"
        );
        sim.done(x)
    });
    run_sim(
        sim,
        Box::new(uut),
        10 * total,
        &format!("cfb {label_for_vcd}"),
    );
}

#[test]
fn cfb_matches_golden_stream() {
    for view in views() {
        run::<1>([6, 5, 4], view);
        run::<2>([7, 6, 5], view);
        run::<4>([10, 8, 6], view);
        run::<8>([12, 9, 8], view);
    }
}

/// Sign and magnitude as the two's-complement bits of an `i32`.
fn sign_mag(neg: bool, mag: u32) -> u32 {
    if neg {
        (mag as i32).wrapping_neg() as u32
    } else {
        mag
    }
}

#[test]
fn cfb_with_external_memory_model() {
    for view in [views()[0], views()[4]] {
        let s = scene(&format!(
            r#"{{"volume": {{"builtin": "phantom", "dims": [10, 8, 6]}}, "view": {view}, "image": [16, 16]}}"#
        ));
        let vol = builtin("phantom", [10, 8, 6], 8).unwrap();
        let plan = Plan::new(&s, &s.camera()).unwrap();
        for sweep in &plan.sweeps {
            run_sweep_memory::<4>(&vol, sweep, &format!("external memory, {view}"), true);
        }
    }
}

#[test]
fn cfb_verilog_passes_yosys() {
    require_tool("yosys");
    let s = scene(
        r#"{"volume": {"builtin": "sphere", "dims": [16,16,16]}, "view": {"projection": "parallel", "rotate_deg": [70, 30, 0]}, "image": [8, 8]}"#,
    );
    let plan = Plan::new(&s, &s.camera()).unwrap();
    let mut uut = Cfb::<4, 10>::new(&build(4, false, plan.sweeps[0].frac), false);
    uut.connect_all();
    yosys_validate("cfb", &generate_verilog(&uut))
        .unwrap_or_else(|e| panic!("yosys rejects the CFB: {e:?}"));
}
