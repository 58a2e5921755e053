//! `hdl::cube3::abc_gradient::AbcUnit` against `golden_model::cube3::abc::gradient`,
//! clock by clock, for the 6-, 10-, 12- and 26-neighbourhood (the 10 on
//! parallel views, its registers written through the host port as the
//! stream starts): the golden model's sample planes of real views (oblique
//! parallel on a non-cubic volume, a close perspective eye, 16-bit voxels
//! with saturating gradient words, a view at exactly 45°) stream in as the
//! TRILIN units deliver them, p = 1, 2, 4 and 8 lanes, in rust-hdl
//! simulation and as emitted Verilog under Icarus and Verilator.
//! Every sample whose whole neighbourhood lies in the streamed planes is
//! compared (the golden model takes no gradient elsewhere).

use cosim::harness::{ports, run_stage};
use cosim::Engine;
use golden_model::cube3::abc::{gradient, Planes, RayCoeffs};
use golden_model::cube3::plan::{Neighbourhood, Plan};
use golden_model::cube3::regs::basis10_writes;
use golden_model::cube3::{prp, trilin};
use golden_model::host::Write;
use hdl::cube3::abc_estimator::LATENCY;
use hdl::cube3::abc_gradient::{centre, AbcUnit};
use hdl::cube3::plane_taps::line_lengths;
use rust_hdl::prelude::*;
use scene::volume::Volume;
use testbenches::{for_each_p, require_tool, run_clocks, scene, Edge};

const H: usize = 10;

/// One clock of the stream: the lanes' samples, the increments of the ray
/// at the centre tap, and the gradient words due `LATENCY - 1` clocks after
/// the centre (per lane, where the golden model has one).
#[derive(Clone, Default)]
struct Clock {
    samples: Vec<u32>,
    dx: i32,
    dy: i32,
    want: Vec<Option<[i32; 3]>>,
}

struct Case {
    name: String,
    n: Neighbourhood,
    weight_bits: u32,
    sample_bits: u32,
    gradient_bits: u32,
    rays: usize,
    segments: usize,
    clocks: Vec<Clock>,
    compared: usize,
    /// Host writes on the first clocks (the 10's registers).
    writes: Vec<Write>,
}

fn case(name: &str, json: &str, p: usize, n: Neighbourhood, lines: i32) -> Case {
    let s = scene(json);
    let vol = Volume::from_spec(&s.volume, s.hardware.voxel_bits).unwrap();
    let plan = Plan::new(&s, &s.camera()).unwrap();
    let view = &plan.views[0];
    let vb = s.hardware.voxel_bits;
    let (sb, gb) = (s.cube3.sample_bits(vb), s.cube3.gradient_bits(vb));
    let (w, f) = (view.weight_bits, sb - vb);
    let (pu0, prays) = (view.u[0] - 1, (view.u[1] - view.u[0] + 4) as usize);
    let nk = view.dims[2];
    let g = nk.div_ceil(p);
    // Sample planes v0 - 1 ..= v0 + lines: the gradients of v0 .. v0 + lines.
    let v0 = (view.v[0] + view.v[1]) / 2 - lines / 2;
    let traversal = prp::Traversal::new(&vol, view);
    let planes: Vec<trilin::SamplePlane> = (v0 - 1..=v0 + lines)
        .map(|v| {
            let cur = prp::fetch(&traversal, view, v, pu0, prays);
            let next = prp::fetch(&traversal, view, v + 1, pu0, prays);
            trilin::plane(view, v, &cur, &next, f)
        })
        .collect();
    let rays = planes[0].rays;
    let mut clocks = Vec::new();
    let mut compared = 0;
    for (pi, plane) in planes.iter().enumerate() {
        for r in 0..rays {
            let u = plane.u0 + r as i32;
            for seg in 0..g {
                let mut c = Clock {
                    samples: (0..p)
                        .map(|i| {
                            let k = seg * p + i;
                            if k < nk {
                                plane.at(u, k)
                            } else {
                                0
                            }
                        })
                        .collect(),
                    ..Clock::default()
                };
                // The whole neighbourhood inside the streamed planes, and a
                // ray that this base plane casts.
                let inside = pi >= 1 && pi + 1 < planes.len() && r >= 1 && r + 1 < rays;
                let cast = inside && view.casts(u, plane.v);
                if cast {
                    (c.dx, c.dy) = (view.x.d(u), view.y.d(plane.v));
                }
                let coeffs = RayCoeffs::new(c.dx, c.dy, w);
                c.want = (0..p)
                    .map(|i| {
                        let k = seg * p + i;
                        (cast && k >= 1 && k + 1 < nk).then(|| {
                            compared += 1;
                            let window = Planes {
                                above: &planes[pi - 1],
                                current: plane,
                                below: &planes[pi + 1],
                            };
                            gradient(n, &window, u, k, &coeffs, w, gb).0
                        })
                    })
                    .collect();
                clocks.push(c);
            }
        }
    }
    let writes = match n {
        Neighbourhood::N10 => {
            let c = RayCoeffs::new(view.x.d(0), view.y.d(0), w);
            basis10_writes(c.t, &c.c10)
        }
        _ => vec![],
    };
    Case {
        name: format!("{name}, p={p}, {}-neighbourhood", n.count()),
        writes,
        n,
        weight_bits: w,
        sample_bits: sb,
        gradient_bits: gb,
        rays,
        segments: g,
        clocks,
        compared,
    }
}

const OBLIQUE: &str = r#"{"volume": {"builtin": "phantom", "dims": [12, 11, 9]}, "view": {"projection": "parallel", "rotate_deg": [20, 35, 0]},
    "mode": "composite", "image": [16, 16]}"#;
const PERSPECTIVE: &str = r#"{"volume": {"builtin": "sphere", "dims": [12, 12, 10]}, "view": {"projection": "perspective", "eye": [5.5, 5.5, -5], "fov_deg": 60},
    "mode": "composite", "image": [16, 16]}"#;
const FULL_SCALE: &str = r#"{"volume": {"builtin": "checkerboard", "dims": [10, 10, 10]}, "view": {"projection": "parallel", "rotate_deg": [-15, 25, 0]},
    "mode": "composite", "image": [16, 16], "hardware": {"voxel_bits": 16}, "cube3": {"sample_bits": 24, "gradient_bits": 25}}"#;
/// Rays at exactly 45° in x: `|DX| = 2^W`, the steepest a base plane takes.
const FORTY_FIVE: &str = r#"{"volume": {"builtin": "sphere", "dims": [12, 12, 10]}, "view": {"projection": "parallel", "rotate_deg": [0, 45, 0]},
    "mode": "composite", "image": [16, 16]}"#;
const DEEP: &str = r#"{"volume": {"builtin": "phantom", "dims": [10, 9, 17]}, "view": {"projection": "parallel", "rotate_deg": [10, -20, 0]},
    "mode": "composite", "image": [16, 16]}"#;

/// Every neighbourhood, and those built for perspective views (the 10's
/// basis correction is one set, a parallel view's).
const ALL: [Neighbourhood; 4] = [
    Neighbourhood::N6,
    Neighbourhood::N10,
    Neighbourhood::N12,
    Neighbourhood::N26,
];
const PERSPECTIVE_BUILT: [Neighbourhood; 3] =
    [Neighbourhood::N6, Neighbourhood::N12, Neighbourhood::N26];

fn cases(p: usize) -> Vec<Case> {
    match p {
        1 => [Neighbourhood::N10, Neighbourhood::N12, Neighbourhood::N26]
            .iter()
            .map(|&n| case("oblique", OBLIQUE, 1, n, 2))
            .collect(),
        2 => PERSPECTIVE_BUILT
            .iter()
            .map(|&n| case("close perspective eye", PERSPECTIVE, 2, n, 2))
            .chain(
                ALL.iter()
                    .map(|&n| case("16-bit voxels", FULL_SCALE, 2, n, 2)),
            )
            .collect(),
        4 => ALL
            .iter()
            .flat_map(|&n| {
                [
                    case("oblique, non-cubic", OBLIQUE, 4, n, 3),
                    case("45 degrees", FORTY_FIVE, 4, n, 2),
                ]
            })
            .collect(),
        _ => [Neighbourhood::N6, Neighbourhood::N10, Neighbourhood::N26]
            .iter()
            .map(|&n| case("17 deep", DEEP, 8, n, 2))
            .collect(),
    }
}

/// The host write of clock `t`, if any.
fn host_write(c: &Case, t: usize) -> Option<&Write> {
    c.writes.get(t)
}

#[test]
fn the_45_degree_case_has_rays_at_45_degrees() {
    let s = scene(FORTY_FIVE);
    let plan = Plan::new(&s, &s.camera()).unwrap();
    let view = &plan.views[0];
    assert_eq!(view.x.d(0).unsigned_abs(), 1 << view.weight_bits);
}

fn unit<const P: usize>(c: &Case) -> AbcUnit<P, H> {
    // Built for longer scanlines and rays than the case's: the lines'
    // lengths are the view's, at run time.
    let mut uut = AbcUnit::<P, H>::new(
        c.rays * c.segments + 20,
        c.segments + 2,
        c.n,
        c.weight_bits,
        c.sample_bits,
        c.gradient_bits,
    )
    .unwrap();
    uut.connect_all();
    uut
}

/// The sample-plane lines' lengths less one, within a scanline and from
/// one to the next (`plane_taps::line_lengths`).
fn line_lasts(c: &Case) -> [usize; 2] {
    let l = line_lengths(c.rays * c.segments, c.segments).unwrap();
    [l[0] - 1, l[2] - 1]
}

/// Clocks to run, the clock whose inputs hold the centre of input clock
/// `t` (`t + centre`), and the clock whose outputs are its gradient.
fn timing(c: &Case) -> (usize, usize) {
    let d = centre(c.rays * c.segments, c.segments);
    (c.clocks.len() + d + LATENCY, d)
}

/// The inputs of clock `t`: the samples entering, and the increments of
/// the centre's ray.
fn inputs(c: &Case, t: usize, d: usize) -> (Vec<u32>, i32, i32) {
    let samples = c.clocks.get(t).map(|k| k.samples.clone());
    let (dx, dy) = t
        .checked_sub(d)
        .and_then(|s| c.clocks.get(s))
        .map_or((0, 0), |k| (k.dx, k.dy));
    (
        samples.unwrap_or_else(|| vec![0; c.clocks[0].samples.len()]),
        dx,
        dy,
    )
}

/// The gradient words due after the edge of clock `t`.
fn due(c: &Case, t: usize, d: usize) -> Option<&Vec<Option<[i32; 3]>>> {
    (t + 1)
        .checked_sub(d + LATENCY)
        .and_then(|s| c.clocks.get(s))
        .map(|k| &k.want)
}

fn compare(c: &Case, engine: &str, t: usize, lane: usize, got: [i32; 3], want: [i32; 3]) {
    assert_eq!(
        got, want,
        "{}: {engine}: first mismatch at clock {t}, lane {lane}: rtl {got:?} golden {want:?}",
        c.name
    );
}

fn rust_hdl_run<const P: usize>() {
    for c in cases(P) {
        assert!(c.compared > 50, "{}: only {} gradients", c.name, c.compared);
        let uut = unit::<P>(&c);
        let (clocks, d) = timing(&c);
        let name = format!("abc {}", c.name);
        run_clocks(uut, clocks, &name, move |e, x| match e {
            Edge::Before(t) => {
                let (samples, dx, dy) = inputs(&c, t, d);
                for (i, s) in samples.iter().enumerate() {
                    x.sample[i].next = (*s as u64).to_bits();
                }
                x.dx_neg.next = dx < 0;
                x.dx_mag.next = (dx.unsigned_abs() as u64).to_bits();
                x.dy_neg.next = dy < 0;
                x.dy_mag.next = (dy.unsigned_abs() as u64).to_bits();
                let [ray_last, line_last] = line_lasts(&c);
                x.ray_last.next = (ray_last as u64).to_bits();
                x.line_last.next = (line_last as u64).to_bits();
                let w = host_write(&c, t);
                x.host_write.next = w.is_some();
                x.host_address.next = (w.map_or(0, |w| w.address) as u64).to_bits();
                x.host_data.next = w.map_or(0, |w| w.data).to_bits();
            }
            Edge::After(t) => {
                for (i, w) in due(&c, t, d).into_iter().flatten().enumerate() {
                    if let Some(w) = w {
                        let got = [&x.gx[i], &x.gy[i], &x.gz[i]].map(|s| s.val().to_u32() as i32);
                        compare(&c, "rust-hdl", t, i, got, *w);
                        // The centre sample leaves with its gradient.
                        let s = c.clocks[t + 1 - d - LATENCY].samples[i];
                        let centre = x.centre[i].val().to_u32();
                        assert_eq!(
                            centre, s,
                            "{}: rust-hdl: clock {t}, lane {i}: centre sample {centre}, not {s}",
                            c.name
                        );
                    }
                }
            }
            Edge::End => {}
        });
    }
}

#[test]
fn abc_unit_matches_golden_model_in_rust_hdl() {
    for_each_p!(rust_hdl_run);
}

/// Run a case's Verilog; the number of gradient words that differ (the
/// first one panics unless `count`).
fn verilog_case<const P: usize>(engine: Engine, c: &Case, verilog: &str, count: bool) -> usize {
    let ports = ports(verilog).unwrap();
    let (clocks, d) = timing(c);
    let vectors: Vec<Vec<u64>> = (0..clocks)
        .map(|t| {
            let (samples, dx, dy) = inputs(c, t, d);
            let w = host_write(c, t);
            ports
                .iter()
                .filter(|p| p.input)
                .map(|p| match p.name.split_once('$') {
                    Some((_, i)) => samples[i.parse::<usize>().unwrap()] as u64,
                    None => match p.name.as_str() {
                        "dx_neg" => (dx < 0) as u64,
                        "dx_mag" => dx.unsigned_abs() as u64,
                        "dy_neg" => (dy < 0) as u64,
                        "dy_mag" => dy.unsigned_abs() as u64,
                        "ray_last" => line_lasts(c)[0] as u64,
                        "line_last" => line_lasts(c)[1] as u64,
                        "host_write" => w.is_some() as u64,
                        "host_address" => w.map_or(0, |w| w.address) as u64,
                        "host_data" => w.map_or(0, |w| w.data),
                        other => panic!("unexpected input port {other}"),
                    },
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
    let mut wrong = 0;
    for (t, o) in outs.iter().enumerate() {
        let Some(want) = due(c, t, d) else { continue };
        for (i, w) in want.iter().enumerate() {
            let Some(w) = w else { continue };
            let get = |f: &str| {
                let at = names.iter().position(|n| *n == format!("{f}${i}")).unwrap();
                o[at].map_or(i32::MIN, |v| v as u32 as i32)
            };
            let got = [get("gx"), get("gy"), get("gz")];
            if got != *w {
                if !count {
                    compare(c, &format!("{engine:?}"), t, i, got, *w);
                }
                wrong += 1;
            }
        }
    }
    wrong
}

fn verilog_of<const P: usize>(c: &Case) -> String {
    generate_verilog(&unit::<P>(c))
}

#[test]
fn abc_unit_verilog_matches_golden_model_under_icarus() {
    require_tool("iverilog");
    for c in cases(1) {
        verilog_case::<1>(Engine::Iverilog, &c, &verilog_of::<1>(&c), false);
    }
    for c in cases(2) {
        verilog_case::<2>(Engine::Iverilog, &c, &verilog_of::<2>(&c), false);
    }
    for c in cases(4) {
        verilog_case::<4>(Engine::Iverilog, &c, &verilog_of::<4>(&c), false);
    }
}

#[test]
fn abc_unit_verilog_matches_golden_model_under_verilator() {
    require_tool("verilator");
    for c in cases(4) {
        verilog_case::<4>(Engine::Verilator, &c, &verilog_of::<4>(&c), false);
    }
    // The 26 and the 10 at p = 1, and the 26 in perspective at p = 2.
    for c in cases(1)
        .iter()
        .filter(|c| matches!(c.n, Neighbourhood::N26 | Neighbourhood::N10))
    {
        verilog_case::<1>(Engine::Verilator, c, &verilog_of::<1>(c), false);
    }
    for c in cases(2)
        .iter()
        .filter(|c| c.n == Neighbourhood::N26 && c.name.contains("perspective"))
    {
        verilog_case::<2>(Engine::Verilator, c, &verilog_of::<2>(c), false);
    }
}

#[test]
fn a_fault_in_the_abc_verilog_is_caught() {
    require_tool("iverilog");
    let c = case("oblique", OBLIQUE, 4, Neighbourhood::N6, 3);
    let verilog = verilog_of::<4>(&c);
    // Lane 2's G_y takes the plane above twice: its y difference is lost.
    let site = "estimators$2$yp = lanes$2$t011;";
    assert!(verilog.contains(site), "the fault site exists");
    let faulty = verilog.replacen(site, "estimators$2$yp = lanes$2$t211;", 1);
    let wrong = verilog_case::<4>(Engine::Iverilog, &c, &faulty, true);
    assert!(wrong > 0, "the faulty ABC unit went unnoticed");
}
