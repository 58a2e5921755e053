//! `hdl::cube3::cfb::BeamFetch` against `golden_model::cube3::prp::fetch`:
//! the volume in the skewed memory modules, the PRPs of consecutive
//! scanlines fetched as beams through the Fast Bus into three rotating
//! 2-DSBs, and the `cur` and `next` streams read from them must be the
//! golden model's PRPs of scanlines `v` and `v + 1`, segment by segment, for
//! p = 1, 2, 4 and 8 on oblique parallel views of non-cubic volumes (the
//! shear) and close perspective eyes (de-fanning: rays that diverge by more
//! than a voxel a plane, some beyond 45°), in rust-hdl simulation and under
//! Icarus.

use cosim::drive_host_port;
use cosim::harness::{load_then_start, ports, run_stage};
use cosim::Engine;
use golden_model::cube3::plan::Plan;
use golden_model::cube3::prp;
use golden_model::host::Write;
use hdl::cube3::config::Cube3Sizes;
use hdl::cube3::{cfb::BeamFetch, BeamFetchConfig};
use rust_hdl::prelude::*;
use scene::volume::Volume;
use testbenches::{for_each_p, require_tool, run_clocks, scene, Edge};

const A: usize = 13;
const B: usize = 10;

pub struct Case {
    name: String,
    config: BeamFetchConfig,
    /// The build, sized for the volume's largest side, and the view's
    /// words the host writes before `start`.
    sizes: Cube3Sizes,
    loads: Vec<Write>,
    modules: Vec<Vec<u16>>,
    /// Per segment of the stream: `cur` and `next`, `None` for planes beyond
    /// `K` (never read by a sample).
    want: Vec<[Vec<Option<u32>>; 2]>,
}

fn case(name: &str, json: &str, p: usize, scanlines: usize) -> Case {
    let s = scene(json);
    let vol = Volume::from_spec(&s.volume, s.hardware.voxel_bits).unwrap();
    let plan = Plan::new(&s, &s.camera()).unwrap();
    let view = &plan.views[plan.views.len() - 1];
    let (u0, rays) = (view.u[0] - 1, (view.u[1] - view.u[0] + 4) as usize);
    let v0 = (view.v[0] + view.v[1]) / 2 - scanlines as i32 / 2;
    let config = BeamFetchConfig::new(view, p, u0, rays, v0, scanlines).unwrap();
    let modules = config.modules(&vol, view);
    let nk = view.dims[2];
    if name.contains("perspective") {
        // De-fanning: neighbouring rays more than a voxel apart on some
        // plane, and some ray beyond 45° (not cast on this base plane).
        let apart = (u0..u0 + rays as i32 - 1)
            .any(|u| (0..nk).any(|k| view.x.pos(u + 1, k) - view.x.pos(u, k) > 1));
        assert!(apart, "{name}: no diverging rays");
        assert!(
            (u0..u0 + rays as i32).any(|u| view.x.d(u).unsigned_abs() > 1 << view.weight_bits),
            "{name}: every ray within 45°"
        );
        assert_eq!(
            plan.views.len(),
            1 + name.contains("second") as usize,
            "{name}"
        );
        // Each group's voxels in the volume lie in distinct memory modules,
        // and some group (p > 1) spans P voxels or more: lanes take modules
        // in any order, not only a window of P consecutive voxels.
        let nx = view.dims[0] as i32;
        for g in &config.groups {
            let mut modules: Vec<i32> = (g.x.iter())
                .filter(|&&x| g.plane < nk && (0..nx).contains(&x))
                .map(|x| x.rem_euclid(p as i32))
                .collect();
            let n = modules.len();
            modules.sort();
            modules.dedup();
            assert_eq!(modules.len(), n, "{name}: group {g:?} shares a module");
        }
        assert!(
            p == 1 || (config.groups.iter()).any(|g| g.x[g.x.len() - 1] - g.x[0] >= p as i32),
            "{name}: every group within {p} consecutive voxels"
        );
    }
    let mut want = Vec::new();
    let traversal = prp::Traversal::new(&vol, view);
    for vi in 0..scanlines {
        let v = v0 + vi as i32;
        let pc = prp::fetch(&traversal, view, v, u0, rays);
        let pn = prp::fetch(&traversal, view, v + 1, u0, rays);
        for r in 0..rays {
            let u = u0 + r as i32;
            for seg in 0..config.segments {
                let lane = |b: &prp::Prp| {
                    (0..p)
                        .map(|i| seg * p + i)
                        .map(|k| (k <= nk).then(|| b.at(u, k)))
                        .collect()
                };
                want.push([lane(&pc), lane(&pn)]);
            }
        }
    }
    let sizes = Cube3Sizes {
        n: view.dims.iter().copied().max().unwrap(),
        p,
        perspective: config.perspective(),
        gradients: false,
        voxel_bits: s.hardware.voxel_bits,
    };
    Case {
        name: format!("{name}, p={p}"),
        loads: config.view_writes(view.offset),
        sizes,
        config,
        modules,
        want,
    }
}

fn cases(p: usize) -> Vec<Case> {
    let json = |vol: &str, dims: &str, rot: &str| {
        format!(
            r#"{{"volume": {{"builtin": "{vol}", "dims": {dims}}}, "view": {{"projection": "parallel", "rotate_deg": {rot}}},
                "mode": "mip", "image": [16, 16]}}"#
        )
    };
    vec![
        case(
            "phantom 14x11x9",
            &json("phantom", "[14, 11, 9]", "[20, 35, 0]"),
            p,
            3,
        ),
        case(
            "ramp 10x12x11, negative increments",
            &json("ramp", "[10, 12, 11]", "[-25, -10, 5]"),
            p,
            2,
        ),
        case(
            "perspective, close eye, phantom 12x10x9",
            r#"{"volume": {"builtin": "phantom", "dims": [12, 10, 9]}, "view": {"projection": "perspective", "eye": [5.5, 4.5, -3], "fov_deg": 60},
                "mode": "mip", "image": [16, 16]}"#,
            p,
            3,
        ),
        case(
            "perspective, off-axis eye, second base plane, ramp 9x11x10",
            r#"{"volume": {"builtin": "ramp", "dims": [9, 11, 10]}, "view": {"projection": "perspective", "eye": [-14, -6, -14], "target": [4, 5, 4.5], "fov_deg": 70},
                "mode": "mip", "image": [16, 16]}"#,
            p,
            2,
        ),
    ]
}

fn fetch<const P: usize>(c: &Case) -> BeamFetch<P, A, B> {
    let mut uut = BeamFetch::<P, A, B>::new(&c.sizes).unwrap();
    uut.preload(&c.modules);
    uut.connect_all();
    uut
}

/// Checks the segments in order as they come out: the segments seen.
#[derive(Default)]
struct Segments(usize);

impl Segments {
    fn clock(&mut self, c: &Case, engine: &str, t: usize, valid: bool, got: [Vec<u32>; 2]) {
        if !valid {
            return;
        }
        let want = c.want.get(self.0).unwrap_or_else(|| {
            panic!(
                "{}: {engine}: a segment beyond the stream at clock {t}",
                c.name
            )
        });
        for (b, name) in ["cur", "next"].iter().enumerate() {
            for (i, w) in want[b].iter().enumerate() {
                if let Some(w) = w {
                    assert_eq!(
                        got[b][i], *w,
                        "{}: {engine}: first mismatch at clock {t}, segment {} of the stream, {name}[{i}]: rtl {} golden {w}",
                        c.name, self.0, got[b][i]
                    );
                }
            }
        }
        self.0 += 1;
    }

    fn finish(&self, c: &Case) {
        assert_eq!(self.0, c.want.len(), "{}: segments", c.name);
    }
}

fn rust_hdl_run<const P: usize>() {
    for c in cases(P) {
        let uut = fetch::<P>(&c);
        let l = c.loads.len();
        let clocks = l + c.config.clocks() + 4;
        let name = format!("beam fetch {}", c.name);
        let mut segments = Segments::default();
        run_clocks(uut, clocks, &name, move |e, x| match e {
            Edge::Before(t) if t < l => drive_host_port!(x, Some(&c.loads[t])),
            Edge::Before(t) => {
                drive_host_port!(x, None::<&Write>);
                x.start.next = t == l;
            }
            Edge::After(t) if t > l => {
                let got = [
                    (0..P).map(|i| x.cur[i].val().to_u32()).collect(),
                    (0..P).map(|i| x.next[i].val().to_u32()).collect(),
                ];
                segments.clock(&c, "rust-hdl", t - l, x.valid.val(), got);
            }
            Edge::After(_) => {}
            Edge::End => segments.finish(&c),
        });
    }
}

#[test]
fn beam_fetch_matches_golden_prps_in_rust_hdl() {
    for_each_p!(rust_hdl_run);
}

#[test]
fn beam_fetch_verilog_matches_golden_prps_under_icarus() {
    require_tool("iverilog");
    for c in cases(4) {
        let verilog = generate_verilog(&fetch::<4>(&c));
        let ports = ports(&verilog).unwrap();
        // The view's words, `start`, then nothing to the end.
        let mut vectors = load_then_start(&ports, &c.loads);
        let idle = vectors.pop().expect("an idle vector");
        vectors.extend(std::iter::repeat_n(idle, c.config.clocks() + 3));
        let outs = run_stage(Engine::Iverilog, &verilog, &vectors).unwrap();
        let names: Vec<&str> = ports
            .iter()
            .filter(|p| !p.input)
            .map(|p| p.name.as_str())
            .collect();
        let mut segments = Segments::default();
        for (t, o) in outs.iter().enumerate() {
            let get = |n: String| {
                o[names.iter().position(|x| *x == n).unwrap()].map_or(u32::MAX, |v| v as u32)
            };
            let got = [
                (0..4).map(|i| get(format!("cur${i}"))).collect(),
                (0..4).map(|i| get(format!("next${i}"))).collect(),
            ];
            if let Some(t) = t.checked_sub(c.loads.len()).filter(|&t| t > 0) {
                segments.clock(&c, "Icarus", t, get("valid".into()) == 1, got);
            }
        }
        segments.finish(&c);
    }
}
