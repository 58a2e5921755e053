//! The Cube-3 pipeline's test cases: parallel views in MIP, MinIP and
//! X-ray (exactly 45° among them) with the golden model's 2-DSB streams and
//! base-plane pixels, and the pixel checker shared by the pipeline's and the
//! whole system's testbenches.

use cosim::stage::{ports, run_stage, StageEngine};
use golden_model::cube3::plan::{Neighbourhood, Plan};
use golden_model::cube3::shade::Shader;
use golden_model::cube3::{prp, render_view};
use hdl::cube3_system::Cube3SystemConfig;
use scene::volume::Volume;

use crate::scene;

/// A case: the configuration, the streams of every clock (from the clock
/// after `start`), and per stream ray its golden pixel where it is a
/// base-plane pixel.
pub struct Case {
    pub name: String,
    pub config: Cube3SystemConfig,
    /// The volume in the memory modules (`BeamFetchConfig::modules`).
    pub modules: Vec<Vec<u16>>,
    pub cur: Vec<Vec<u32>>,
    pub next: Vec<Vec<u32>>,
    pub want: Vec<Option<([u32; 4], bool)>>,
}

pub fn case(name: &str, json: &str, p: usize, scanlines: usize) -> Case {
    let s = scene(json);
    let vol = Volume::from_spec(&s.volume, s.hardware.voxel_bits).unwrap();
    let cam = s.camera().unwrap();
    let plan = Plan::new(&s, &cam).unwrap();
    let view = &plan.views[0];
    let shader = Shader::new(&s, &cam, view);
    let v0 = (view.v[0] + view.v[1]) / 2 - scanlines as i32 / 2;
    let system = Cube3SystemConfig::new(view, &shader, p, v0, scanlines).unwrap();
    let config = &system.pipeline;
    assert_eq!(config.on_grid, name.contains("45 degrees"), "{name}");
    let modules = system.fetch.modules(&vol, view);
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
        config: system,
        modules,
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

pub fn cases(p: usize) -> Vec<Case> {
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

/// Check the pixels in stream order, and that the first comes on the
/// predicted clock; returns the mismatches.
pub struct Pixels<'a> {
    case: &'a Case,
    /// The clock the first pixel must come on.
    first: usize,
    seen: usize,
    errors: Vec<String>,
}

impl Pixels<'_> {
    pub fn new(case: &Case, first: usize) -> Pixels<'_> {
        Pixels {
            case,
            first,
            seen: 0,
            errors: vec![],
        }
    }

    pub fn clock(&mut self, engine: &str, t: usize, done: bool, px: [u64; 4], has: bool) {
        if !done {
            return;
        }
        let c = self.case;
        if self.seen == 0 {
            let expect = self.first;
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

    pub fn finish(mut self) -> Vec<String> {
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

/// Run a design's Verilog on `vectors` and check the pixels on its `done`,
/// `pixel_*` and `has_sample` outputs, the first due on clock `first`;
/// the mismatches.
pub fn verilog_pixels(
    engine: StageEngine,
    c: &Case,
    verilog: &str,
    vectors: &[Vec<u64>],
    first: usize,
) -> Vec<String> {
    let outs = run_stage(engine, verilog, vectors).unwrap();
    let names: Vec<String> = ports(verilog)
        .unwrap()
        .into_iter()
        .filter(|p| !p.input)
        .map(|p| p.name)
        .collect();
    let mut pixels = Pixels::new(c, first);
    for (t, o) in outs.iter().enumerate() {
        let get = |n: &str| o[names.iter().position(|x| x == n).unwrap()].unwrap_or(u64::MAX);
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
