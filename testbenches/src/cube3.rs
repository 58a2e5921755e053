//! The Cube-3 pipeline's test cases: parallel views in every mode (exactly
//! 45° among them; composite and first-opaque with the 6- and the
//! 12-neighbourhood, shaded, with gradient opacity and without gradients)
//! and perspective views (close eyes whose rays diverge and pass 45°, a
//! second base plane; MinIP, X-ray, composite with the 12 and first-opaque
//! with the 6), with the golden model's 2-DSB streams and base-plane
//! pixels, and the pixel checker shared by the pipeline's and the whole
//! system's testbenches.

use cosim::harness::{ports, run_stage};
use cosim::Engine;
use golden_model::common::shader::Shader;
use golden_model::cube3::plan::Plan;
use golden_model::cube3::{prp, render_view};
use golden_model::host::Write;
use hdl::cube3::config::Cube3Sizes;
use hdl::cube3::Cube3SystemConfig;
use scene::volume::Volume;

use crate::scene;

/// A case: the configuration, the streams' segments (a scanline every
/// `scanline_clocks`, from the clock after `start`), and per stream ray its
/// golden pixel where it is a base-plane pixel.
pub struct Case {
    pub name: String,
    pub config: Cube3SystemConfig,
    /// The build: sized for the volume's largest side.
    pub sizes: Cube3Sizes,
    /// The volume in the memory modules (`BeamFetchConfig::modules`).
    pub modules: Vec<Vec<u16>>,
    pub cur: Vec<Vec<u32>>,
    pub next: Vec<Vec<u32>>,
    pub want: Vec<Option<([u32; 4], bool)>>,
    /// What the host writes before the stream: the view's registers and
    /// tables, the shaders' registers (their tables are preloaded).
    pub loads: Vec<Write>,
}

pub fn case(name: &str, json: &str, p: usize, scanlines: usize) -> Case {
    case_in_view(name, json, p, scanlines, 0)
}

/// A case on base plane `vi` of the scene's plan.
pub fn case_in_view(name: &str, json: &str, p: usize, scanlines: usize, vi: usize) -> Case {
    let s = scene(json);
    let vol = Volume::from_spec(&s.volume, s.hardware.voxel_bits).unwrap();
    let cam = s.camera();
    let plan = Plan::new(&s, &cam).unwrap();
    let view = &plan.views[vi];
    let shader = Shader::new(&s, &cam, view);
    let n = golden_model::cube3::neighbourhood(&s, None).unwrap();
    let v0 = (view.v[0] + view.v[1]) / 2 - scanlines as i32 / 2;
    let system = Cube3SystemConfig::new(view, &shader, n, p, v0, scanlines).unwrap();
    let config = &system.pipeline;
    assert_eq!(view.on_grid, name.contains("45 degrees"), "{name}");
    assert_eq!(config.abc.is_some(), shader.needs_gradient, "{name}");
    let modules = system.fetch.modules(&vol, view);
    let (base, _) = render_view(&vol, view, &shader, n, p);
    let (nk, g, r) = (view.dims[2], config.segments, config.rays);
    let (mut cur, mut next, mut want) = (vec![], vec![], vec![]);
    let traversal = prp::Traversal::new(&vol, view);
    for vi in 0..config.scanlines {
        let v = config.v0 + vi as i32;
        let pc = prp::fetch(&traversal, view, v, config.u0, r);
        let pn = prp::fetch(&traversal, view, v + 1, config.u0, r);
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
            let inside = u >= view.u[0]
                && u <= view.u[1]
                && ri + 1 < r
                && (v0..v0 + scanlines as i32).contains(&v);
            want.push(inside.then(|| {
                let i = (v - base.v0) as usize * base.width + (u - base.u0) as usize;
                (base.pixels[i], base.cast[i])
            }));
        }
    }
    assert!(want.iter().filter(|w| w.is_some()).count() > 10);
    if config.perspective {
        // Some ray of the stream's pixels is beyond 45° (uncast) and some
        // is cast.
        let cast = want.iter().flatten().filter(|(_, c)| *c).count();
        let uncast = (config.u0..config.u0 + r as i32)
            .any(|u| view.x.d(u).unsigned_abs() > 1 << view.weight_bits);
        assert!(cast > 10 && uncast, "{name}: cast {cast}, uncast {uncast}");
    }
    let mut loads = system.view_writes();
    if let Some(s) = &system.pipeline.shading {
        loads.extend(s.tables().register_writes());
    }
    let sizes = Cube3Sizes {
        n: view.dims.iter().copied().max().unwrap(),
        p,
        perspective: config.perspective,
        gradients: config.abc.is_some(),
        voxel_bits: config.voxel_bits,
    };
    assert_eq!(sizes.refuses(&system), None, "{name}");
    Case {
        name: format!("{name}, p={p}"),
        config: system,
        sizes,
        modules,
        cur,
        next,
        want,
        loads,
    }
}

fn scene_json(volume: &str, dims: [usize; 3], rotate: [f64; 3], mode: &str) -> String {
    scene_with(volume, dims, rotate, mode, "")
}

/// A scene with `more` JSON members.
fn scene_with(volume: &str, dims: [usize; 3], rotate: [f64; 3], mode: &str, more: &str) -> String {
    let view = format!(r#"{{"projection": "parallel", "rotate_deg": {rotate:?}}}"#);
    scene_json_view(volume, dims, &view, mode, more)
}

/// A perspective scene: the eye at `eye`, a 60° field of view.
fn perspective(volume: &str, dims: [usize; 3], eye: [f64; 3], mode: &str, more: &str) -> String {
    let view = format!(r#"{{"projection": "perspective", "eye": {eye:?}, "fov_deg": 60}}"#);
    scene_json_view(volume, dims, &view, mode, more)
}

fn scene_json_view(volume: &str, dims: [usize; 3], view: &str, mode: &str, more: &str) -> String {
    format!(
        r#"{{"volume": {{"builtin": "{volume}", "dims": {dims:?}}}, "view": {view},
            "mode": "{mode}", "image": [16, 16]{more}}}"#
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
        case(
            "composite, shaded, the 12-neighbourhood, phantom 11x10x17",
            &scene_with(
                "phantom",
                [11, 10, 17],
                [20.0, -30.0, 0.0],
                "composite",
                r#", "transfer": {"opacity": [[0, 0.0], [60, 0.0], [120, 0.6], [255, 0.9]],
                             "color": [[0, 1.0, 0.5, 0.2], [255, 0.3, 0.6, 1.0]]}"#,
            ),
            p,
            2,
        ),
        case(
            "first-opaque, unshaded, gradient opacity, the 6-neighbourhood, sphere 10x11x17",
            &scene_with(
                "sphere",
                [10, 11, 17],
                [-25.0, 15.0, 0.0],
                "first_opaque",
                r#", "cube3": {"gradient": 6}, "shading": {"enabled": false},
                "transfer": {"opacity": [[0, 0.0], [40, 0.0], [200, 1.0], [255, 1.0]],
                             "color": [[0, 1.0, 1.0, 1.0], [255, 0.8, 0.4, 0.2]],
                             "gradient_opacity": [[0, 0.2], [30, 1.0]], "opaque_threshold": 0.5}"#,
            ),
            p,
            2,
        ),
        case(
            "perspective MinIP, close eye, phantom 12x10x9",
            &perspective("phantom", [12, 10, 9], [5.5, 4.5, -3.0], "minip", ""),
            p,
            2,
        ),
        case(
            "perspective X-ray, close eye, ramp 10x11x9",
            &perspective("ramp", [10, 11, 9], [4.0, 6.0, -3.5], "xray", ""),
            p,
            2,
        ),
        case_in_view(
            "perspective composite, shaded, the 12-neighbourhood, second base plane, sphere 9x11x17",
            &scene_json_view(
                "sphere",
                [9, 11, 17],
                r#"{"projection": "perspective", "eye": [-14, -6, -14], "target": [4, 5, 4.5], "fov_deg": 70}"#,
                "composite",
                "",
            ),
            p,
            2,
            1,
        ),
        case(
            "perspective first-opaque, gradient opacity, the 6-neighbourhood, sphere 11x10x17",
            &perspective(
                "sphere",
                [11, 10, 17],
                [5.0, 4.5, -3.0],
                "first_opaque",
                r#", "cube3": {"gradient": 6}, "shading": {"enabled": false},
                "transfer": {"opacity": [[0, 0.0], [40, 0.0], [200, 1.0], [255, 1.0]],
                             "color": [[0, 1.0, 1.0, 1.0], [255, 0.8, 0.4, 0.2]],
                             "gradient_opacity": [[0, 0.2], [30, 1.0]], "opaque_threshold": 0.5}"#,
            ),
            p,
            2,
        ),
        case(
            "composite, unshaded: no gradient, ramp 10x9x9",
            &scene_with(
                "ramp",
                [10, 9, 9],
                [10.0, 30.0, 0.0],
                "composite",
                r#", "shading": {"enabled": false}"#,
            ),
            p,
            2,
        ),
    ]
}

/// Check the pixels in stream order, and that the first comes on the
/// predicted clock; returns the mismatches.
pub struct Pixels {
    name: String,
    want: Vec<Option<([u32; 4], bool)>>,
    /// The clock the first pixel must come on.
    first: usize,
    seen: usize,
    errors: Vec<String>,
}

impl Pixels {
    pub fn new(case: &Case, first: usize) -> Pixels {
        Pixels {
            name: case.name.clone(),
            want: case.want.clone(),
            first,
            seen: 0,
            errors: vec![],
        }
    }

    fn clock(&mut self, engine: &str, t: usize, done: bool, px: [u64; 4], has: bool) {
        if !done {
            return;
        }
        if self.seen == 0 && t != self.first {
            self.errors.push(format!(
                "{}: {engine}: the first pixel came at clock {t}, not {}",
                self.name, self.first
            ));
        }
        match self.want.get(self.seen) {
            Some(Some((w, cast))) if px != w.map(u64::from) || has != *cast => {
                self.errors.push(format!(
                    "{}: {engine}: first mismatch at clock {t}, ray {} of the stream: rtl {px:?} has_sample {has}, golden {w:?} cast {cast}",
                    self.name, self.seen
                ))
            }
            None => self
                .errors
                .push(format!("{}: {engine}: a pixel beyond the stream at clock {t}", self.name)),
            _ => {}
        }
        self.seen += 1;
    }

    /// Check the pixel port `o` after clock `t`.
    pub fn read(&mut self, engine: &str, t: usize, o: PixelPort) {
        self.clock(engine, t, o.done, o.px, o.has_sample);
    }

    pub fn finish(&mut self) -> Vec<String> {
        if self.seen != self.want.len() {
            self.errors.push(format!(
                "{}: {} pixels out of {}",
                self.name,
                self.seen,
                self.want.len()
            ));
        }
        std::mem::take(&mut self.errors)
    }
}

/// The pixel port of a Cube-3 pipeline or system after a clock.
pub struct PixelPort {
    pub done: bool,
    pub px: [u64; 4],
    pub has_sample: bool,
}

/// Read the pixel port of `$x` (a `Cube3` or `Cube3System` in rust-hdl).
#[macro_export]
macro_rules! pixel_port {
    ($x:expr) => {
        $crate::cube3::PixelPort {
            done: $x.done.val(),
            px: [
                $x.pixel_r.val().to_u64(),
                $x.pixel_g.val().to_u64(),
                $x.pixel_b.val().to_u64(),
                $x.pixel_a.val().to_u64(),
            ],
            has_sample: $x.has_sample.val(),
        }
    };
}

/// Run a design's Verilog on `vectors` and check the pixels on its `done`,
/// `pixel_*` and `has_sample` outputs, the first due on clock `first`;
/// the mismatches.
pub fn verilog_pixels(
    engine: Engine,
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
        let port = PixelPort {
            done: get("done") == 1,
            px: ["pixel_r", "pixel_g", "pixel_b", "pixel_a"].map(get),
            has_sample: get("has_sample") == 1,
        };
        pixels.read(&format!("{engine:?}"), t, port);
    }
    pixels.finish()
}

/// The Verilog of `uut`, a Cube-3 pipeline or system built from `c`, as
/// `cube verilog` emits it: the units `c` leaves out pruned.
pub fn emitted_verilog(c: &Case, uut: &impl rust_hdl::prelude::Block) -> String {
    cosim::verilog::clean_verilog(
        &rust_hdl::prelude::generate_verilog(uut),
        &cosim::cube3::left_out(&c.config),
    )
    .unwrap()
}
