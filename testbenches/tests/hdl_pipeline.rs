//! The whole rust-hdl Cube-4L pipeline (CFB, shader, compositing-buffer ring
//! buffers with nearest-neighbour taps, bilinear unit, compositor) against
//! the golden model: every lane's composited value every cycle, every
//! base-plane pixel and its address, and the clocks per sweep.

use cosim::drive_host_port;
use golden_model::common::shader::Shader as GoldenShader;
use golden_model::cube4l::cfb::SkewedMemory;
use golden_model::cube4l::plan::{Face, Plan};
use golden_model::cube4l::regs::ViewRegs;
use hdl::cube4l::{config::unpack, Pipeline, PipelineConfig};
use rust_hdl::prelude::*;
use scene::volume::builtin;
use testbenches::{require_tool, run_sim, scene, stream_results};

const A: usize = 13;
const H: usize = 12;

/// Simulate one scene's first sweep; returns (clocks from start to the last
/// result, ideal clocks n_x*n_y*n_z/P rounded up per beam).
fn run<const P: usize>(dims: [usize; 3], view: &str, mode: &str, vol_name: &str) -> (u64, u64) {
    run_shaded::<P>(dims, view, mode, vol_name, false)
}

fn run_shaded<const P: usize>(
    dims: [usize; 3],
    view: &str,
    mode: &str,
    vol_name: &str,
    shading: bool,
) -> (u64, u64) {
    run_tf::<P>(dims, view, mode, vol_name, shading, "", None)
}

/// One scene through every sweep; `gradient_opacity` is spliced into the
/// transfer function. With `reset_at`, each sweep is first started and
/// reset that many clocks later, then rendered from a fresh `start`.
fn run_tf<const P: usize>(
    dims: [usize; 3],
    view: &str,
    mode: &str,
    vol_name: &str,
    shading: bool,
    gradient_opacity: &str,
    reset_at: Option<u64>,
) -> (u64, u64) {
    let tf = format!(
        r#""transfer": {{"opacity": [[0, 0], [40, 0.02], [120, 0.3], [200, 0.9], [255, 1.0]], "color": [[0, 0.2, 0.4, 1.0], [128, 1.0, 0.5, 0.1], [255, 1.0, 1.0, 1.0]]{gradient_opacity}}}"#
    );
    let s = scene(&format!(
        r#"{{"volume": {{"builtin": "{vol_name}", "dims": {dims:?}}}, "view": {view}, "mode": "{mode}", {tf},
            "shading": {{"enabled": {shading}, "light_dir": [0.3, 0.5, 1.0], "specular": 0.4}}, "image": [16, 16], "hardware": {{"pipelines": {P}}}}}"#
    ));
    let vol = builtin(vol_name, dims, 8).unwrap();
    let cam = s.camera();
    let plan = Plan::new(&s, &cam).unwrap();
    let mut total = (0, 0);
    for sweep in &plan.sweeps {
        let label = format!(
            "p={P} {dims:?} {mode} {view} sweep axis {} z {}..={}",
            sweep.axis(),
            sweep.z0,
            sweep.z1
        );
        let (c, i) = run_sweep::<P>(&s, &cam, &vol, sweep, label, reset_at);
        total = (total.0 + c, total.1 + i);
    }
    total
}

fn run_sweep<const P: usize>(
    s: &scene::Scene,
    cam: &scene::Camera,
    vol: &scene::volume::Volume,
    sweep: &golden_model::cube4l::plan::Sweep,
    label: String,
    reset_at: Option<u64>,
) -> (u64, u64) {
    let golden = GoldenShader::new(s, cam, sweep);
    let mode = golden.mode;
    let (base, results) = stream_results(vol, sweep, &golden, P);
    let config = PipelineConfig::for_view(sweep, vol.dims, P, &golden);
    config.validate().unwrap();
    let mut uut = Pipeline::<P, A, H>::new(&config).unwrap();
    assert_eq!(
        uut.buffer_bits(),
        config.buffer_bits(),
        "{label}: buffer memory as built and as the manifest counts it"
    );
    let mem = SkewedMemory::new(vol, P);
    assert!(mem.modules[0].len() <= 1 << A);
    uut.preload(&mem.modules);
    // Tables preloaded as a bitstream would hold them; the shader's and
    // the view's registers written through the host port before `start`.
    let tables = golden.tables();
    uut.preload_tables(&tables);
    let view = ViewRegs::new(sweep, vol.dims, P, config.gradient(), s.mode);
    config
        .check_view(&view)
        .unwrap_or_else(|why| panic!("{label}: {why}"));
    let loads = [tables.register_writes(), view.writes()].concat();
    uut.connect_all();
    let expected_pixels = base.faces.iter().filter(|f| **f != Face::None).count();
    let beats = results.len();
    let mut sim = Simulation::new();
    sim.add_clock(5, |x: &mut Box<Pipeline<P, A, H>>| {
        x.clock.next = !x.clock.val()
    });
    let ideal = beats as u64;
    let (tx, rx) = std::sync::mpsc::channel();
    let label_for_vcd = label.clone();
    sim.add_testbench(move |mut sim: Sim<Pipeline<P, A, H>>| {
        let mut x = sim.init()?;
        for w in &loads {
            drive_host_port!(x, Some(w));
            wait_clock_cycle!(sim, clock, x);
        }
        drive_host_port!(x, None::<&golden_model::host::Write>);
        if let Some(at) = reset_at {
            // A sweep reset in flight: the generator stops and the pixel
            // bus stays quiet, however long the host waits.
            x.start.next = true;
            wait_clock_cycle!(sim, clock, x);
            x.start.next = false;
            for _ in 0..at {
                wait_clock_cycle!(sim, clock, x);
            }
            x.reset.next = true;
            wait_clock_cycle!(sim, clock, x);
            x.reset.next = false;
            for t in 0..3 * hdl::cube4l::config::fill_clocks(&config) + 64 {
                wait_clock_cycle!(sim, clock, x);
                assert!(!x.busy.val(), "{label}: busy {t} clocks after the reset");
                for k in 0..P {
                    assert!(
                        !x.res_beat[k].val() && !x.px_valid[k].val(),
                        "{label}: lane {k} strobes {t} clocks after the reset"
                    );
                }
            }
        }
        x.start.next = true;
        wait_clock_cycle!(sim, clock, x);
        x.start.next = false;
        let (mut beat, mut cycles, mut pixels) = (0usize, 0u64, 0usize);
        while beat < beats {
            wait_clock_cycle!(sim, clock, x);
            cycles += 1;
            assert!(cycles < 2 * beats as u64 + 64, "{label}: no result for beat {beat}");
            if !x.res_beat[0].val() {
                continue;
            }
            for (k, want) in results[beat].iter().enumerate() {
                assert_eq!(x.res_valid[k].val(), want.is_some(), "{label}: beat {beat} lane {k}: padding");
                let Some(want) = want else { continue };
                let got = unpack(mode, x.res[k].val().to_u64());
                if got != *want {
                    panic!("{label}: first mismatch at cycle {cycles}, beat {beat}, lane {k}, res: rtl {got:?} golden {want:?}");
                }
                if x.px_valid[k].val() {
                    let (px, py) = (x.px_x[k].val().to_u32() as usize, x.px_y[k].val().to_u32() as usize);
                    let i = px + base.width * py;
                    assert!(px < base.width && py < base.height && base.faces[i] != Face::None, "{label}: beat {beat} lane {k}: pixel address ({px}, {py}) is no ER cell");
                    assert_eq!(base.pixels[i], *want, "{label}: pixel ({px}, {py}) differs from the base plane");
                    pixels += 1;
                }
            }
            beat += 1;
        }
        assert_eq!(pixels, expected_pixels, "{label}: ER pixels out");
        tx.send(cycles + 1).unwrap();
        sim.done(x)
    });
    run_sim(
        sim,
        Box::new(uut),
        10 * (3 * beats as u64 + 200 + reset_at.map_or(0, |at| at + 400)),
        &format!("pipeline {label_for_vcd}"),
    );
    (rx.recv().unwrap(), ideal)
}

const VIEWS: [&str; 5] = [
    r#"{"projection": "parallel"}"#,
    r#"{"projection": "parallel", "rotate_deg": [70, 30, 0]}"#,
    r#"{"projection": "parallel", "rotate_deg": [0, 45, 0]}"#,
    r#"{"projection": "parallel", "rotate_deg": [-20, 135, 10]}"#,
    r#"{"projection": "parallel", "rotate_deg": [200, 30, 0]}"#,
];

#[test]
fn views_cover_both_orders_and_every_sign() {
    use golden_model::common::plan::Order;
    use golden_model::cube4l::plan::Rays;
    let (mut orders, mut dx, mut dy) = (Vec::new(), Vec::new(), Vec::new());
    for view in VIEWS {
        let s = scene(&format!(
            r#"{{"volume": {{"builtin": "sphere", "dims": [8, 8, 8]}}, "view": {view}, "image": [8, 8]}}"#
        ));
        let sweep = &Plan::new(&s, &s.camera()).unwrap().sweeps[0];
        let Rays::Parallel { dx: x, dy: y } = sweep.rays else {
            unreachable!()
        };
        orders.push(sweep.order);
        dx.push(x);
        dy.push(y);
    }
    assert!(
        orders.contains(&Order::FrontToBack) && orders.contains(&Order::BackToFront),
        "{orders:?}"
    );
    assert!(
        dx.iter().any(|&v| v > 0) && dx.iter().any(|&v| v < 0),
        "{dx:?}"
    );
    assert!(
        dy.iter().any(|&v| v > 0) && dy.iter().any(|&v| v < 0),
        "{dy:?}"
    );
    assert!(
        dx.iter().any(|&v| v.abs() == 256),
        "exactly 45 degrees: {dx:?}"
    );
}

#[test]
fn pipeline_larger_non_cubic_volume() {
    run_shaded::<4>([32, 24, 16], VIEWS[1], "composite", "phantom", true);
}

#[test]
fn pipeline_mip_every_view_and_p() {
    for view in VIEWS {
        run::<1>([8, 8, 8], view, "mip", "phantom");
        run::<2>([10, 8, 9], view, "mip", "phantom");
        run::<4>([10, 12, 9], view, "mip", "phantom");
    }
}

#[test]
fn pipeline_composite_and_other_modes() {
    for view in PERSPECTIVE.iter().take(1).chain(VIEWS.iter()) {
        run::<2>([10, 10, 9], view, "xray", "phantom");
    }
    for view in VIEWS {
        run::<4>([12, 12, 12], view, "composite", "phantom");
        run::<2>([9, 10, 8], view, "first_opaque", "sphere");
        run::<4>([8, 10, 9], view, "minip", "checkerboard");
    }
}

#[test]
fn pipeline_shaded_composite_with_abc_gradients() {
    for view in VIEWS {
        run_shaded::<4>([12, 12, 12], view, "composite", "phantom", true);
        run_shaded::<2>([10, 9, 8], view, "composite", "sphere", true);
        run_shaded::<1>([8, 8, 8], view, "first_opaque", "sphere", true);
    }
}

#[test]
fn pipeline_gradient_magnitude_opacity() {
    let gm = r#", "gradient_opacity": [[0, 0.1], [10, 0.4], [40, 1.0]]"#;
    for view in [VIEWS[1], VIEWS[3], PERSPECTIVE[0]] {
        run_tf::<4>([12, 12, 12], view, "composite", "phantom", true, gm, None);
        run_tf::<2>([10, 12, 9], view, "composite", "phantom", false, gm, None);
        run_tf::<2>([10, 12, 9], view, "first_opaque", "sphere", false, gm, None);
    }
}

#[test]
fn pipeline_reset_mid_sweep_then_renders() {
    // Reset while the first slice streams (the late generator of the
    // gradient unit not yet started), and a slice later (both running).
    for at in [5, 80] {
        run_tf::<2>(
            [10, 9, 8],
            VIEWS[1],
            "composite",
            "phantom",
            true,
            "",
            Some(at),
        );
    }
    run_tf::<4>(
        [12, 12, 12],
        PERSPECTIVE[0],
        "mip",
        "phantom",
        false,
        "",
        Some(30),
    );
}

#[test]
fn pipeline_shaded_clock_count_adds_one_slice() {
    // The gradient needs the slice ahead: one slice (n_y * n_x / p beats) and
    // one clock more fill than without shading.
    let (cycles, ideal) = run_shaded::<4>([16, 16, 16], VIEWS[1], "composite", "phantom", true);
    let (plain, _) = run::<4>([16, 16, 16], VIEWS[1], "composite", "phantom");
    assert_eq!(cycles - plain, 16 * 16 / 4 + 1);
    assert!(cycles > ideal);
}

const PERSPECTIVE: [&str; 3] = [
    r#"{"projection": "perspective", "eye": [5, 6, -10], "fov_deg": 90}"#,
    r#"{"projection": "perspective", "eye": [30, 4, 5.5], "fov_deg": 70}"#,
    r#"{"projection": "perspective", "eye": [5.3, 6.6, 4.2], "target": [6, 5, 11], "fov_deg": 120}"#,
];

#[test]
fn pipeline_perspective_every_sweep() {
    for view in PERSPECTIVE {
        run::<4>([12, 12, 12], view, "mip", "phantom");
        run_shaded::<2>([10, 12, 11], view, "composite", "phantom", true);
        run::<1>([9, 10, 11], view, "first_opaque", "sphere");
    }
}

#[test]
fn pipeline_clock_count_is_ideal_plus_fill() {
    let (cycles, ideal) = run::<4>([16, 16, 16], VIEWS[1], "composite", "phantom");
    // One beat per clock plus 27 clocks of fill: the start register, the
    // CFB's three address stages, the block-RAM read, its bank register and
    // its relay register, the shader's input register, nine clocks of gather delay
    // (the shader's 17 stages less the bilinear unit's 7, less the input
    // register), the bilinear unit's seven stages and the compositor's first
    // three (its fourth register ends the last beat's own clock).
    assert_eq!(
        cycles,
        ideal + 27,
        "clocks per sweep vs the ideal n_x*n_y*n_z/p"
    );
}

#[test]
fn pipeline_verilog_passes_yosys() {
    require_tool("yosys");
    let s = scene(
        r#"{"volume": {"builtin": "sphere", "dims": [16,16,16]}, "view": {"projection": "parallel", "rotate_deg": [70, 30, 0]}, "mode": "mip", "image": [8, 8]}"#,
    );
    let cam = s.camera();
    let plan = Plan::new(&s, &cam).unwrap();
    let golden = GoldenShader::new(&s, &cam, &plan.sweeps[0]);
    let config = PipelineConfig::for_view(&plan.sweeps[0], [16, 16, 16], 2, &golden);
    let mut uut = Pipeline::<2, 11, 10>::new(&config).unwrap();
    uut.connect_all();
    yosys_validate("pipeline", &generate_verilog(&uut))
        .unwrap_or_else(|e| panic!("yosys rejects the pipeline: {e:?}"));
}

/// Wider voxels and channels than the 8-bit default: the memory words and
/// compositing rings are narrowed to the scene's bits, so every precision
/// must still match the golden model bit for bit.
#[test]
fn pipeline_wider_voxels_and_channels() {
    let cases = [
        ("composite", 12, 12, 2, true),
        ("first_opaque", 12, 15, 2, false),
        ("mip", 16, 15, 4, false),
        ("minip", 12, 8, 2, false),
        ("xray", 16, 12, 2, false),
    ];
    for (mode, voxel_bits, rgba_bits, p, shading) in cases {
        let top = (1u32 << voxel_bits) - 1;
        let s = scene(&format!(
            r#"{{"volume": {{"builtin": "sphere", "dims": [10, 10, 8]}}, "view": {{"projection": "parallel", "rotate_deg": [25, 40, 0]}},
                "mode": "{mode}", "transfer": {{"opacity": [[0, 0.0], [{q}, 0.2], [{top}, 0.9]], "color": [[0, 0.2, 0.4, 1.0], [{top}, 1.0, 0.9, 0.5]]}},
                "shading": {{"enabled": {shading}}}, "image": [16, 16],
                "hardware": {{"pipelines": {p}, "voxel_bits": {voxel_bits}, "rgba_bits": {rgba_bits}}}}}"#,
            q = top / 4
        ));
        let vol = builtin("sphere", s.volume.dims, voxel_bits).unwrap();
        let r = cosim::sim::simulate::<cosim::cube4l::Cube4l>(
            &s,
            &s.camera(),
            &vol,
            cosim::Engine::RustHdl,
            None,
        )
        .unwrap();
        assert_eq!(
            r.mismatches, 0,
            "{mode} voxel_bits={voxel_bits} rgba_bits={rgba_bits} p={p}: first differences {:?}",
            r.first
        );
    }
}
