//! `hdl::cube3::Cube3`, the Cube-3 pipeline from the 2-D skewed buffers to
//! the base plane, against the golden model's base plane
//! (`golden_model::cube3::render_view`), pixel by pixel and on the clock
//! `Cube3Config::pixel_delay` predicts: MIP, MinIP and X-ray on parallel
//! views of non-cubic volumes, p = 1, 2, 4 and 8, in rust-hdl simulation and
//! as emitted Verilog under Icarus and Verilator. The 2-DSB streams are the
//! golden model's PRPs (`prp::fetch`), as the beam fetch would fill them.

use cosim::stage::{ports, run_stage, StageEngine};
use golden_model::cube3::plan::{Neighbourhood, Plan};
use golden_model::cube3::shade::Shader;
use golden_model::cube3::{prp, render_view};
use hdl::cube3::{Cube3, Cube3Config};
use rust_hdl::prelude::*;
use scene::volume::Volume;
use testbenches::{require_tool, run_sim, scene};

const H: usize = 8;

/// A case: the configuration, the streams of every clock (from the clock
/// after `start`), and per stream ray its golden pixel where it is a
/// base-plane pixel.
struct Case {
    name: String,
    config: Cube3Config,
    cur: Vec<Vec<u32>>,
    next: Vec<Vec<u32>>,
    want: Vec<Option<([u32; 4], bool)>>,
}

fn case(name: &str, json: &str, p: usize, scanlines: usize) -> Case {
    let s = scene(json);
    let vol = Volume::from_spec(&s.volume, s.hardware.voxel_bits).unwrap();
    let cam = s.camera().unwrap();
    let plan = Plan::new(&s, &cam).unwrap();
    let view = &plan.views[0];
    let shader = Shader::new(&s, &cam, view);
    let v0 = (view.v[0] + view.v[1]) / 2 - scanlines as i32 / 2;
    let config = Cube3Config::new(view, &shader, p, v0, scanlines).unwrap();
    assert_eq!(config.on_grid, name.contains("45 degrees"), "{name}");
    let (base, _) = render_view(&vol, view, &shader, Neighbourhood::N12, p);
    let (nk, g, r) = (view.dims[2], config.segments, config.rays);
    let (mut cur, mut next, mut want) = (vec![], vec![], vec![]);
    for vi in 0..scanlines {
        let v = v0 + vi as i32;
        let pc = prp::fetch(&vol, view, v, config.u0, r);
        let pn = prp::fetch(&vol, view, v + 1, config.u0, r);
        for ri in 0..r {
            let u = config.u0 + ri as i32;
            for seg in 0..g {
                let lane = |b: &prp::Prp| {
                    (0..p)
                        .map(|i| seg * p + i)
                        .map(|k| if k <= nk { b.at(u, k) } else { 0 })
                        .collect()
                };
                cur.push(lane(&pc));
                next.push(lane(&pn));
            }
            let inside = u >= view.u[0] && u <= view.u[1] && ri + 1 < r;
            want.push(inside.then(|| {
                let i = (v - base.v0) as usize * base.width + (u - base.u0) as usize;
                (base.pixels[i], base.cast[i])
            }));
        }
    }
    assert!(want.iter().filter(|w| w.is_some()).count() > 10);
    Case {
        name: format!("{name}, p={p}"),
        config,
        cur,
        next,
        want,
    }
}

fn scene_json(volume: &str, dims: [usize; 3], rotate: [f64; 3], mode: &str) -> String {
    format!(
        r#"{{"volume": {{"builtin": "{volume}", "dims": {dims:?}}}, "view": {{"projection": "parallel", "rotate_deg": {rotate:?}}},
            "mode": "{mode}", "image": [16, 16]}}"#
    )
}

fn cases(p: usize) -> Vec<Case> {
    vec![
        case(
            "MIP, phantom 14x11x9",
            &scene_json("phantom", [14, 11, 9], [20.0, 35.0, 0.0], "mip"),
            p,
            3,
        ),
        case(
            "MinIP, ramp 10x12x11",
            &scene_json("ramp", [10, 12, 11], [-25.0, 10.0, 5.0], "minip"),
            p,
            2,
        ),
        case(
            "MIP at exactly 45 degrees, phantom 12x12x10",
            &scene_json("phantom", [12, 12, 10], [0.0, 45.0, 0.0], "mip"),
            p,
            2,
        ),
        case(
            "X-ray, phantom 12x10x10",
            &scene_json("phantom", [12, 10, 10], [15.0, -30.0, 0.0], "xray"),
            p,
            2,
        ),
    ]
}

fn pipeline<const P: usize>(c: &Case) -> Cube3<P, H> {
    let mut uut = Cube3::<P, H>::new(&c.config).unwrap();
    uut.connect_all();
    uut
}

/// Clocks to run: `start`, the streams, and the last pixel's delay.
fn clocks(c: &Case) -> usize {
    1 + c.cur.len() + c.config.pixel_delay() + 2
}

/// Check the pixels in stream order, and that the first comes on the
/// predicted clock; returns the mismatches.
struct Pixels<'a> {
    case: &'a Case,
    seen: usize,
    errors: Vec<String>,
}

impl Pixels<'_> {
    fn clock(&mut self, engine: &str, t: usize, done: bool, px: [u64; 4], has: bool) {
        if !done {
            return;
        }
        let c = self.case;
        if self.seen == 0 {
            // Ray 0's last segment enters at clock g (start at clock 0).
            let expect = c.config.segments + c.config.pixel_delay();
            if t != expect {
                self.errors.push(format!(
                    "{}: {engine}: the first pixel came at clock {t}, not {expect}",
                    c.name
                ));
            }
        }
        match c.want.get(self.seen) {
            Some(Some((w, cast))) if px != w.map(u64::from) || has != *cast => {
                self.errors.push(format!(
                    "{}: {engine}: first mismatch at clock {t}, ray {} of the stream: rtl {px:?} has_sample {has}, golden {w:?} cast {cast}",
                    c.name, self.seen
                ))
            }
            None => self
                .errors
                .push(format!("{}: {engine}: a pixel beyond the stream at clock {t}", c.name)),
            _ => {}
        }
        self.seen += 1;
    }

    fn finish(mut self) -> Vec<String> {
        if self.seen != self.case.want.len() {
            self.errors.push(format!(
                "{}: {} pixels out of {}",
                self.case.name,
                self.seen,
                self.case.want.len()
            ));
        }
        self.errors
    }
}

/// Clock `t`'s `start`, `valid` and streams: start at clock 0, the
/// segments from clock 1.
fn stream(c: &Case, t: usize) -> (bool, bool, &[u32], &[u32]) {
    let empty: &[u32] = &[0; 8][..c.config.p];
    match t
        .checked_sub(1)
        .and_then(|s| c.cur.get(s).zip(c.next.get(s)))
    {
        Some((a, b)) => (false, true, a, b),
        None => (t == 0, false, empty, empty),
    }
}

fn rust_hdl_run<const P: usize>() {
    for c in cases(P) {
        let uut = pipeline::<P>(&c);
        let n = clocks(&c);
        let case = std::sync::Arc::new(c);
        let tb = case.clone();
        let mut sim = Simulation::new();
        sim.add_clock(5, |x: &mut Box<Cube3<P, H>>| x.clock.next = !x.clock.val());
        sim.add_testbench(move |mut sim: Sim<Cube3<P, H>>| {
            let mut x = sim.init()?;
            let mut pixels = Pixels {
                case: &tb,
                seen: 0,
                errors: vec![],
            };
            for t in 0..n {
                let (start, valid, cur, next) = stream(&tb, t);
                x.start.next = start;
                x.valid.next = valid;
                for i in 0..P {
                    x.cur[i].next = (cur[i] as u64).to_bits();
                    x.next[i].next = (next[i] as u64).to_bits();
                }
                wait_clock_cycle!(sim, clock, x);
                let px = [
                    x.pixel_r.val().to_u64(),
                    x.pixel_g.val().to_u64(),
                    x.pixel_b.val().to_u64(),
                    x.pixel_a.val().to_u64(),
                ];
                pixels.clock("rust-hdl", t, x.done.val(), px, x.has_sample.val());
            }
            let errors = pixels.finish();
            assert!(errors.is_empty(), "{}", errors[0]);
            sim.done(x)
        });
        run_sim(
            sim,
            Box::new(uut),
            10 * n as u64 + 100,
            &format!("cube3 {}", case.name),
        );
    }
}

#[test]
fn cube3_pipeline_matches_golden_base_plane_in_rust_hdl() {
    rust_hdl_run::<1>();
    rust_hdl_run::<2>();
    rust_hdl_run::<4>();
    rust_hdl_run::<8>();
}

/// Run a case's Verilog; its mismatches.
fn verilog_case<const P: usize>(engine: StageEngine, c: &Case, verilog: &str) -> Vec<String> {
    let ports = ports(verilog).unwrap();
    let vectors: Vec<Vec<u64>> = (0..clocks(c))
        .map(|t| {
            let (start, valid, cur, next) = stream(c, t);
            ports
                .iter()
                .filter(|p| p.input)
                .map(|p| match p.name.split_once('$') {
                    Some(("cur", i)) => cur[i.parse::<usize>().unwrap()] as u64,
                    Some((_, i)) => next[i.parse::<usize>().unwrap()] as u64,
                    None if p.name == "start" => start as u64,
                    None => valid as u64,
                })
                .collect()
        })
        .collect();
    let outs = run_stage(engine, verilog, &vectors).unwrap();
    let names: Vec<&str> = ports
        .iter()
        .filter(|p| !p.input)
        .map(|p| p.name.as_str())
        .collect();
    let mut pixels = Pixels {
        case: c,
        seen: 0,
        errors: vec![],
    };
    for (t, o) in outs.iter().enumerate() {
        let get = |n: &str| o[names.iter().position(|x| *x == n).unwrap()].unwrap_or(u64::MAX);
        let px = ["pixel_r", "pixel_g", "pixel_b", "pixel_a"].map(get);
        pixels.clock(
            &format!("{engine:?}"),
            t,
            get("done") == 1,
            px,
            get("has_sample") == 1,
        );
    }
    pixels.finish()
}

fn check<const P: usize>(engine: StageEngine) {
    for c in cases(P) {
        let errors = verilog_case::<P>(engine, &c, &generate_verilog(&pipeline::<P>(&c)));
        assert!(errors.is_empty(), "{}", errors[0]);
    }
}

#[test]
fn cube3_verilog_matches_golden_base_plane_under_icarus() {
    require_tool("iverilog");
    check::<2>(StageEngine::Iverilog);
    check::<4>(StageEngine::Iverilog);
}

#[test]
fn cube3_verilog_matches_golden_base_plane_under_verilator() {
    require_tool("verilator");
    check::<4>(StageEngine::Verilator);
}

#[test]
fn a_fault_in_the_cube3_verilog_is_caught() {
    require_tool("iverilog");
    let c = cases(2).remove(0);
    let verilog = generate_verilog(&pipeline::<2>(&c));
    // Unit 0's leaf stage takes the inside bits of the previous clock's
    // cell.
    let site = "(flags_q$6$q & lane_bit$0)";
    assert!(verilog.contains(site), "the fault site exists");
    let faulty = verilog.replace(site, "(flags_q$5$q & lane_bit$0)");
    let errors = verilog_case::<2>(StageEngine::Iverilog, &c, &faulty);
    assert!(
        !errors.is_empty(),
        "the faulty Cube-3 pipeline went unnoticed"
    );
}
