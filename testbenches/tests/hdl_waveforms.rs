//! Waveforms of the whole-pipeline simulation: the VCD parses with vcd2fst,
//! and every signal the GTKWave save file names exists in it; the trace
//! limits (scope, depth, clocks) shrink a trace to what they name, FST and
//! VCD of one run are equal under `vcd-diff`, several simulations follow
//! one another in one file, and the save file opens on the trace.

use cosim::trace::{finish, Format, Limits, Request, Written};
use cosim::vcd_diff::{compare, Trace};
use scene::volume::builtin;
use std::collections::HashSet;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;
use testbenches::{assert_trace_opens, scene};

/// Full names (`uut.cfb.n_s`) of every variable in a VCD.
fn vcd_names(path: &std::path::Path) -> HashSet<String> {
    let mut parser = vcd::Parser::new(std::io::BufReader::new(std::fs::File::open(path).unwrap()));
    let header = parser.parse_header().expect("VCD header parses");
    let mut names = HashSet::new();
    fn walk(items: &[vcd::ScopeItem], prefix: &str, names: &mut HashSet<String>) {
        for item in items {
            match item {
                vcd::ScopeItem::Scope(s) => {
                    walk(&s.items, &format!("{prefix}{}.", s.identifier), names)
                }
                vcd::ScopeItem::Var(v) => {
                    names.insert(format!("{prefix}{}", v.reference));
                }
                _ => {}
            }
        }
    }
    walk(&header.items, "", &mut names);
    names
}

fn dir() -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("vcd");
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The whole rust-hdl VCD of a small two-lane MIP scene, simulated once per
/// test binary.
fn full_trace() -> &'static PathBuf {
    static VCD: OnceLock<PathBuf> = OnceLock::new();
    VCD.get_or_init(|| {
        let s = scene(
            r#"{"volume": {"builtin": "phantom", "dims": [10, 10, 8]}, "view": {"projection": "parallel", "rotate_deg": [70, 30, 0]},
                "mode": "mip", "image": [32, 32], "hardware": {"pipelines": 2}}"#,
        );
        let vol = builtin("phantom", [10, 10, 8], 8).unwrap();
        let vcd = dir().join("pipeline_p2.vcd");
        let r = cosim::sim::simulate::<cosim::cube4l::Cube4l>(
            &s,
            &s.camera(),
            &vol,
            cosim::Engine::RustHdl,
            Some(&testbenches::trace_to(&vcd)),
        )
        .unwrap();
        assert_eq!(r.mismatches, 0);
        vcd
    })
}

#[test]
fn pipeline_vcd_parses_and_gtkw_names_its_signals() {
    let vcd = full_trace().clone();
    assert_trace_opens(&vcd);
    let names = vcd_names(&vcd);
    let gtkw = std::fs::read_to_string(vcd.with_extension("gtkw")).unwrap();
    let listed: Vec<&str> = gtkw.lines().filter(|l| l.starts_with("uut.")).collect();
    assert!(
        listed.len() > 20,
        "the save file lists {} signals",
        listed.len()
    );
    for l in listed {
        let name = l.split('[').next().unwrap();
        assert!(
            names.contains(name),
            "{name} is in the .gtkw but not in the VCD"
        );
    }
    assert!(
        gtkw.contains("-CFB lane 1")
            && gtkw.contains("-Compositing lane 0")
            && gtkw.contains("-Pixel out 1")
    );
}

/// `raws` through the trace writer into `name` under `limits`.
fn rewrite(raws: &[PathBuf], name: &str, limits: Limits) -> (PathBuf, Written) {
    let out = dir().join(name);
    let req = Request::new(&out, limits).unwrap();
    let w = finish(raws, "uut", &req, 0).unwrap();
    (out, w)
}

fn size(p: &Path) -> u64 {
    std::fs::metadata(p).unwrap().len()
}

#[test]
fn fst_and_vcd_of_one_run_are_equal_and_gtkwave_reads_both() {
    let full = full_trace().clone();
    let (fst, w) = rewrite(std::slice::from_ref(&full), "whole.fst", Limits::default());
    assert_eq!((w.signals, w.parts), (w.of, 1));
    assert_trace_opens(&fst);
    assert!(
        size(&fst) * 5 < size(&full),
        "FST {} bytes against VCD {}",
        size(&fst),
        size(&full)
    );
    let c = compare(
        &Trace::load(&full).unwrap(),
        &Trace::load(&fst).unwrap(),
        None,
    )
    .unwrap();
    assert!(c.compared > 1000 && c.only_a.is_empty() && c.only_b.is_empty());
    assert!(c.equal(), "{:?}", c.mismatches.first());
    // The extension is the format; any other is refused, not mislabelled.
    assert_eq!(Format::of(Path::new("a/b.fst")), Ok(Format::Fst));
    assert_eq!(Format::of(Path::new("b.vcd")), Ok(Format::Vcd));
    for bad in ["b.txt", "b", "b.fst.gz", "b.VCD"] {
        let e = Request::new(Path::new(bad), Limits::default()).unwrap_err();
        assert!(e.contains(".vcd or .fst"), "{bad}: {e}");
    }
}

#[test]
fn trace_limits_keep_only_what_they_name() {
    let full = full_trace().clone();
    let raws = std::slice::from_ref(&full);
    let all = Trace::load(&full).unwrap();
    // One lane of the two by scope: its signals and the top's clock and
    // start only.
    let lane = Limits {
        scopes: vec![glob::Pattern::new("lanes$1.*").unwrap()],
        ..Limits::default()
    };
    let (one, w) = rewrite(raws, "lane1.vcd", lane);
    assert_trace_opens(&one);
    assert!(w.signals > 20 && w.signals * 2 < w.of, "{w:?}");
    assert!(size(&one) * 2 < size(&full));
    let c = compare(&all, &Trace::load(&one).unwrap(), None).unwrap();
    assert!(c.only_b.is_empty());
    assert!(c.equal(), "{:?}", c.mismatches.first());
    let names = vcd_names(&one);
    assert!(names
        .iter()
        .all(|n| n.starts_with("uut.lanes$1.") || n == "uut.clock" || n == "uut.start"));
    // By depth: the top's own signals, then one level more.
    let (d0, w0) = rewrite(
        raws,
        "depth0.vcd",
        Limits {
            depth: Some(0),
            ..Limits::default()
        },
    );
    let (_, w1) = rewrite(
        raws,
        "depth1.vcd",
        Limits {
            depth: Some(1),
            ..Limits::default()
        },
    );
    assert!(vcd_names(&d0).iter().all(|n| n.matches('.').count() == 1));
    assert!(0 < w0.signals && w0.signals < w1.signals && w1.signals < w.of);
    // By clocks: 100..200 holds 100 rising edges, every value from the
    // range's first clock on as in the whole trace.
    let (part, wc) = rewrite(
        raws,
        "clocks.fst",
        Limits {
            clocks: Some((100, 200)),
            ..Limits::default()
        },
    );
    assert_eq!(wc.clocks, (100, 200));
    let p = Trace::load(&part).unwrap();
    assert_eq!(p.cycles, 100);
    assert!(size(&part) < size(&rewrite(raws, "whole2.fst", Limits::default()).0));
    // A limit that keeps nothing is an error naming the limits.
    let none = Limits {
        scopes: vec![glob::Pattern::new("no_such_unit*").unwrap()],
        depth: Some(5),
        ..Limits::default()
    };
    let e = finish(
        raws,
        "uut",
        &Request::new(&dir().join("none.vcd"), none).unwrap(),
        0,
    )
    .unwrap_err();
    assert!(e.contains("keep no signal"), "{e}");
    assert!(Request::new(
        Path::new("x.vcd"),
        Limits {
            clocks: Some((5, 5)),
            ..Limits::default()
        }
    )
    .is_err());
}

#[test]
fn several_simulations_follow_one_another_in_one_trace() {
    let full = full_trace().clone();
    let one = Trace::load(&full).unwrap();
    let (two, w) = rewrite(
        &[full.clone(), full.clone()],
        "twice.fst",
        Limits::default(),
    );
    assert_eq!(w.parts, 2);
    let t = Trace::load(&two).unwrap();
    assert!(
        t.cycles >= 2 * one.cycles,
        "{} cycles, one run {}",
        t.cycles,
        one.cycles
    );
    // The first run's clocks are the whole trace's.
    let c = compare(&one, &t, None).unwrap();
    assert!(c.mismatches.is_empty(), "{:?}", c.mismatches.first());
}

#[test]
fn the_save_file_opens_on_the_trace_from_its_own_folder() {
    let written = Written {
        signals: 3,
        of: 3,
        parts: 1,
        bytes: 1,
        clocks: (0, 3609),
        first_start: None,
    };
    let waves = vec![(
        "Lane".to_string(),
        vec![
            "uut.lanes$0.x[15:0]".to_string(),
            "uut.lanes$0.value[15:0]".to_string(),
            "uut.lanes$0.address[31:0]".to_string(),
            "uut.lanes$0.valid".to_string(),
        ],
    )];
    let g = cosim::gtkw::render(Path::new("rel/t.fst"), &written, "uut", &waves);
    let here = std::fs::canonicalize(".").unwrap();
    let line = |key: &str| {
        g.lines()
            .find(|l| l.starts_with(key))
            .unwrap_or_else(|| panic!("no {key} in {g}"))
            .to_string()
    };
    // Absolute paths of the trace and of the save file beside it: GTKWave
    // opens the trace from any folder, and beside the save file when both
    // move.
    assert_eq!(
        line("[dumpfile]"),
        format!("[dumpfile] \"{}\"", here.join("rel/t.fst").display())
    );
    assert_eq!(
        line("[savefile]"),
        format!("[savefile] \"{}\"", here.join("rel/t.gtkw").display())
    );
    // Zoomed to fit: 36 090 time units in the 1100-pixel pane is 2^5.04
    // units a pixel, so zoom -6 (2^6 a pixel) shows it all.
    assert!(line("*").starts_with("*-6.000000 "), "{}", line("*"));
    // Counters and addresses in decimal (@24), data in hex (@22), one bit
    // in binary (@28).
    let after = |sig: &str| {
        let lines: Vec<&str> = g.lines().collect();
        let i = lines.iter().position(|l| *l == sig).unwrap();
        lines[..i]
            .iter()
            .rev()
            .find(|l| l.starts_with('@'))
            .unwrap()
            .to_string()
    };
    assert_eq!(after("uut.lanes$0.x[15:0]"), "@24");
    assert_eq!(after("uut.lanes$0.value[15:0]"), "@22");
    assert_eq!(after("uut.lanes$0.address[31:0]"), "@24");
    assert_eq!(after("uut.lanes$0.valid"), "@28");
    // With a start in the trace it opens a clock before it, 48 clocks in
    // view: 480 units in 1100 pixels is 2^-1.2 units a pixel, zoom 1.
    let started = Written {
        first_start: Some(1000),
        ..written
    };
    let g = cosim::gtkw::render(Path::new("rel/t.fst"), &started, "uut", &waves);
    let line = |key: &str| g.lines().find(|l| l.starts_with(key)).unwrap().to_string();
    assert_eq!(line("[timestart]"), "[timestart] 9990");
    assert!(line("*").starts_with("*1.000000 "), "{}", line("*"));
}

/// A traced simulation's save file opens at its first start: the host's
/// writes come first, so the start lies past clock 0.
#[test]
fn a_traced_run_opens_at_its_first_start() {
    let d = tempfile::tempdir().unwrap();
    let trace = d.path().join("t.vcd");
    let s = scene(
        r#"{"volume": {"builtin": "sphere", "dims": [8, 8, 8]}, "view": {"projection": "parallel"},
            "image": [8, 8], "hardware": {"pipelines": 2}}"#,
    );
    let vol = scene::volume::Volume::from_spec(&s.volume, s.hardware.voxel_bits).unwrap();
    let req = Request::new(&trace, Limits::default()).unwrap();
    let frames = [(s.clone(), s.camera())];
    let run = cosim::sim::simulate_frames::<cosim::cube4l::Cube4l>(
        &frames,
        None,
        &vol,
        cosim::harness::Engine::RustHdl,
        Some(&req),
        &|v| v.to_string(),
    )
    .unwrap();
    let start = run
        .traced
        .unwrap()
        .first_start
        .expect("a start in the trace");
    assert!(start > 10, "the first start at clock {start}");
    let g = std::fs::read_to_string(trace.with_extension("gtkw")).unwrap();
    assert!(
        g.contains(&format!("[timestart] {}\n", (start - 1) * 10)),
        "{g}"
    );
}
