//! The emitted Verilog under Verilator: bit for bit against the golden model
//! (the full 256x256x110 engine frame included), and its VCD equal to the
//! rust-hdl simulation's, cycle for cycle on every common signal. A fault
//! injected into a copy of the Verilog is caught by both comparisons.

use cosim::arch::Arch;
use cosim::cube4l::Cube4l;
use cosim::sim::{simulate, simulate_altered};
use cosim::vcd_diff::{compare, Trace};
use cosim::Engine;
use scene::volume::{builtin, Volume};
use scene::Scene;
use std::path::PathBuf;
use std::sync::OnceLock;
use testbenches::{assert_trace_opens, require_tool, scene, trace_to};

/// The trace-comparison scene: the sphere, p = 2, shaded composite at an
/// oblique view (one sweep).
const SPHERE_P2: &str = r#"{"volume": {"builtin": "sphere", "dims": [12, 12, 10]},
    "view": {"projection": "parallel", "rotate_deg": [-20, 135, 10]},
    "mode": "composite", "image": [32, 32], "hardware": {"pipelines": 2}}"#;

fn vcd_dir() -> PathBuf {
    let d = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("vcd");
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn sphere() -> (Scene, Volume) {
    let s = scene(SPHERE_P2);
    let vol = builtin("sphere", s.volume.dims, 8).unwrap();
    (s, vol)
}

/// The rust-hdl VCD of the sphere scene, simulated once per test binary.
fn rust_hdl_vcd() -> &'static PathBuf {
    static VCD: OnceLock<PathBuf> = OnceLock::new();
    VCD.get_or_init(|| {
        let (s, vol) = sphere();
        let vcd = vcd_dir().join("sphere_p2_rust_hdl.vcd");
        let r = simulate::<Cube4l>(
            &s,
            &s.camera(),
            &vol,
            Engine::RustHdl,
            Some(&trace_to(&vcd)),
        )
        .unwrap();
        assert_eq!(r.mismatches, 0, "rust-hdl: {:?}", r.first);
        vcd
    })
}

#[test]
fn verilator_trace_equals_rust_hdl_trace() {
    require_tool("verilator");
    let (s, vol) = sphere();
    // Verilator's trace as FST, compared with rust-hdl's VCD.
    let vcd = vcd_dir().join("sphere_p2_verilator.fst");
    let r = simulate::<Cube4l>(
        &s,
        &s.camera(),
        &vol,
        Engine::Verilator,
        Some(&trace_to(&vcd)),
    )
    .unwrap();
    assert_eq!(r.mismatches, 0, "verilator: {:?}", r.first);
    assert_trace_opens(&vcd);
    let (a, b) = (
        Trace::load(rust_hdl_vcd()).unwrap(),
        Trace::load(&vcd).unwrap(),
    );
    let c = compare(&a, &b, None).unwrap();
    // Every rust-hdl signal has its namesake in Verilator's trace (which
    // also holds the parents' copies of child ports), but for those inside
    // the units the scene leaves out of the Verilog: here the divider, the
    // gradient-opacity table and the gradient-magnitude bin.
    let gone = |n: &str| {
        n.split('.')
            .any(|part| ["div", "lead", "alpha_gm", "gm_bin"].contains(&part))
    };
    assert!(!c.only_a.is_empty());
    assert!(
        c.only_a.iter().all(|n| gone(n)),
        "rust-hdl signals missing in Verilator's trace: {:?}",
        c.only_a.iter().filter(|n| !gone(n)).collect::<Vec<_>>()
    );
    assert!(c.compared > 2000, "only {} signals compared", c.compared);
    // Both traces hold the host's table and register writes, then the
    // sweep's clocks from `start`.
    let loads = Cube4l::loads(&testbenches::emitted_sweep(&s, &vol).part).len() as u64;
    assert!(loads > 256, "{loads} host writes");
    assert_eq!(
        (c.cycles_a, c.cycles_b),
        (loads + r.clocks, loads + r.clocks)
    );
    assert!(
        c.equal(),
        "first differences: {:?}",
        &c.mismatches[..c.mismatches.len().min(5)]
    );
    // The save file beside the trace names only signals that are in it
    // (read from GTKWave's own conversion of the FST).
    let gtkw = std::fs::read_to_string(vcd.with_extension("gtkw")).unwrap();
    let names: Vec<&str> = gtkw.lines().filter(|l| l.starts_with("TOP.top.")).collect();
    assert!(names.len() > 20);
    let text = std::fs::read_to_string(vcd.with_extension("fst.vcd")).unwrap();
    for n in names {
        let leaf = n.rsplit('.').next().unwrap().split('[').next().unwrap();
        assert!(text.contains(&format!(" {leaf} ")), "{n} is not in the VCD");
    }
}

/// Verilator dumps only the clocks asked for: the trace of clocks
/// 2400..2500 holds 100 rising edges, each equal to the same clock of the
/// whole trace, in a file a fraction of its size.
#[test]
fn verilator_traces_only_the_clocks_asked_for() {
    require_tool("verilator");
    let (s, vol) = sphere();
    let whole = vcd_dir().join("sphere_p2_verilator_whole.fst");
    let part = vcd_dir().join("sphere_p2_verilator_2400_2500.fst");
    simulate::<Cube4l>(
        &s,
        &s.camera(),
        &vol,
        Engine::Verilator,
        Some(&trace_to(&whole)),
    )
    .unwrap();
    let limits = cosim::trace::Limits {
        clocks: Some((2400, 2500)),
        ..Default::default()
    };
    let req = cosim::trace::Request::new(&part, limits).unwrap();
    let r = simulate::<Cube4l>(&s, &s.camera(), &vol, Engine::Verilator, Some(&req)).unwrap();
    assert_eq!(r.mismatches, 0);
    assert_trace_opens(&part);
    let (w, p) = (Trace::load(&whole).unwrap(), Trace::load(&part).unwrap());
    assert_eq!(p.cycles, 100);
    let size = |f: &PathBuf| std::fs::metadata(f).unwrap().len();
    assert!(
        size(&part) * 5 < size(&whole),
        "{} against {}",
        size(&part),
        size(&whole)
    );
    let c = cosim::vcd_diff::compare_from(&w, 2400, &p, None).unwrap();
    assert!(c.compared > 2000, "{} signals compared", c.compared);
    assert!(c.mismatches.is_empty(), "{:?}", c.mismatches.first());
}

#[test]
fn a_swapped_neighbour_link_is_caught_by_pixels_and_by_the_trace() {
    require_tool("verilator");
    let (s, vol) = sphere();
    let verilog = testbenches::emitted_sweep(&s, &vol).verilog;
    // Lane 1 takes its own x-gradient link instead of lane 0's.
    let link = "lanes$1$g_from_left_xm = lanes$0$g_to_right_xm;";
    assert!(verilog.contains(link), "fault site not found");
    let broken = verilog.replace(link, "lanes$1$g_from_left_xm = lanes$1$g_to_right_xm;");
    let vcd = vcd_dir().join("sphere_p2_verilator_fault.vcd");
    let cam = s.camera();
    let r = simulate_altered::<Cube4l>(
        &s,
        &cam,
        &vol,
        Engine::Verilator,
        Some(&trace_to(&vcd)),
        &|_| broken.clone(),
    )
    .unwrap();
    assert!(r.mismatches > 0, "the pixel comparison missed the fault");
    let c = compare(
        &Trace::load(rust_hdl_vcd()).unwrap(),
        &Trace::load(&vcd).unwrap(),
        None,
    )
    .unwrap();
    assert!(!c.equal(), "the trace comparison missed the fault");
    // The first differing cycle names the faulty link (with the gradient
    // unit's input it drives, in the same cycle).
    let first = c.mismatches[0].cycle;
    let at_first: Vec<&str> = c
        .mismatches
        .iter()
        .take_while(|m| m.cycle == first)
        .map(|m| m.signal.as_str())
        .collect();
    assert!(
        at_first.contains(&"lanes$1.g_from_left_xm"),
        "cycle {first}: {at_first:?}"
    );
}

#[test]
fn engine_frame_matches_under_verilator() {
    require_tool("verilator");
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../scenes/engine.json");
    let s = Scene::load(&path).unwrap();
    let vol = Volume::from_spec(&s.volume, 8).unwrap_or_else(|e| {
        panic!(
            "{e}\nThe engine data set is missing: run scripts/fetch-engine (scripts/setup does it)."
        )
    });
    assert_eq!(vol.dims, [256, 256, 110]);
    let r = simulate::<Cube4l>(&s, &s.camera(), &vol, Engine::Verilator, None).unwrap();
    assert_eq!(r.mismatches, 0, "first differences {:?}", r.first);
    // The view sweeps 256 slices of 256 beams of 110 voxels, padded to 112
    // for p = 4: one beat per clock is 256 * 256 * 28 clocks. Shading adds
    // one slice (the ABC gradient's delay) and 28 clocks of fill (start,
    // the CFB's three address stages, block-RAM read, its bank and relay
    // registers, shader input, nine gather clocks, seven bilinear stages,
    // the compositor's first three and the gradient unit's output register).
    assert_eq!(r.ideal_clocks, 256 * 256 * 28);
    assert_eq!(r.clocks, r.ideal_clocks + 256 * 28 + 28);
}
