//! Cube-3 in the flows: a part is a base plane, its hardware the
//! [`hdl::cube3::Cube3System`] (beam fetch, ray control, TRILIN, ABC units,
//! shaders, RPC), its pixels one per stream ray, in stream order, on the
//! `done` port. The volume is loaded into the memory modules in each base
//! plane's traversal order.
//!
//! A build is a configuration ([`Cube3Build`]): its units, widths and the
//! largest volume side it serves. The view (templates, bounds, increments,
//! de-fanning groups, the stream's extent) and the shader's tables and
//! light are registers and tables the host writes before each base plane
//! (`Cube3SystemConfig::view_writes`), so one build renders every view of
//! its class. Base planes of another traversal order need the volume
//! reloaded in that order: they run on the same design, one simulation
//! each.

use crate::arch::{Arch, BasePixels, BufferMemory, ClockTerm};
use crate::gtkw::Wave;
use crate::harness::{Group, Record, Stop};
use crate::verilog::{clean_verilog, Layout, LeftOut, ON_CHIP_BITS as A};
use golden_model::common::shader::Shader;
use golden_model::cube3::plan::{Neighbourhood, Plan, View};
use golden_model::cube3::{render_view, BasePlane, Frame, Stats};
use golden_model::host::Write;
use hdl::common::lanes::{with_p, ForP};
use hdl::common::mode_class::ModeClass;
use hdl::common::shader::{normal_bits_refusal, normal_suffix, unlit_normal_bits};
use hdl::common::width_refusal;
use hdl::cube3::config::Cube3Sizes;
use hdl::cube3::units::{self, Units};
use hdl::cube3::{Cube3System, Cube3SystemConfig};
use rust_hdl::prelude::*;
use scene::volume::Volume;
use scene::{Camera, Image, Mode, Scene};
use std::path::Path;

/// 2-DSB and delay-line address bits of every Cube-3 build: a 2-DSB module
/// of a 256-a-side build holds 516 rays of 128 segments (p = 2), and the
/// ABC units' sample-plane lines are a scanline period long (13 314 clocks
/// for the engine at p = 4).
pub const B: usize = 17;
pub const H: usize = 16;

/// Cube-3 (Pfister, Wessels and Kaufman): ray-parallel casting.
pub struct Cube3;

/// What a Cube-3 build is made of beyond its views: p, the mode (the
/// RPC's operator and reset value), the units, the widths and the largest
/// volume side.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Cube3Build {
    pub p: usize,
    pub mode: Mode,
    pub shading: bool,
    pub gradient_opacity: bool,
    pub perspective: bool,
    pub neighbourhood: Neighbourhood,
    pub voxel_bits: u32,
    pub frac_bits: u32,
    pub rgba_bits: u32,
    /// Bits a component of the lighting's quantized normal; the default
    /// without shading.
    pub normal_bits: u32,
    /// The largest volume side served.
    pub n: usize,
}

/// A mode as a scene and a build's name spell it.
fn mode_name(m: Mode) -> &'static str {
    match m {
        Mode::Composite => "composite",
        Mode::FirstOpaque => "first_opaque",
        Mode::Mip => "mip",
        Mode::Minip => "minip",
        Mode::Xray => "xray",
    }
}

impl Cube3Build {
    /// The datapath widths: voxel, RGBA, weight fraction, normal.
    fn widths(&self) -> [u32; 4] {
        [
            self.voxel_bits,
            self.rgba_bits,
            self.frac_bits,
            self.normal_bits,
        ]
    }

    /// `{mode}[_shaded][_gm][_perspective]_n{6|10|12|26}_p{p}_{n}`, with the
    /// widths when not 8 bits (`_v`, `_c`, `_f`) and the normal's when not
    /// 5 (`_q`); the mode exactly (the RPC is built for one).
    pub fn name(&self) -> String {
        let mut s = mode_name(self.mode).to_string();
        for (on, w) in [
            (self.shading, "_shaded"),
            (self.gradient_opacity, "_gm"),
            (self.perspective, "_perspective"),
        ] {
            if on {
                s += w;
            }
        }
        s += &format!("_n{}_p{}_{}", self.neighbourhood.count(), self.p, self.n);
        for (bits, tag) in [
            (self.voxel_bits, 'v'),
            (self.rgba_bits, 'c'),
            (self.frac_bits, 'f'),
        ] {
            if bits != 8 {
                s += &format!("_{tag}{bits}");
            }
        }
        s + &normal_suffix(self.normal_bits)
    }

    /// The configuration a name spells ([`Cube3Build::name`]).
    pub fn parse(name: &str) -> Result<Cube3Build, String> {
        let bad = |why: &str| format!("configuration '{name}': {why}");
        let mut words: Vec<&str> = name.split('_').collect();
        let mode = match words.first().copied() {
            Some("first") if words.get(1) == Some(&"opaque") => {
                words.remove(0);
                Mode::FirstOpaque
            }
            Some("composite") => Mode::Composite,
            Some("mip") => Mode::Mip,
            Some("minip") => Mode::Minip,
            Some("xray") => Mode::Xray,
            _ => {
                return Err(bad(
                    "the mode is composite, first_opaque, mip, minip or xray",
                ))
            }
        };
        let mut b = Cube3Build {
            p: 0,
            mode,
            shading: false,
            gradient_opacity: false,
            perspective: false,
            neighbourhood: Neighbourhood::N12,
            voxel_bits: 8,
            frac_bits: 8,
            rgba_bits: 8,
            normal_bits: unlit_normal_bits(),
            n: 0,
        };
        let mut rest = words[1..].iter().peekable();
        for (flag, word) in [
            (&mut b.shading, "shaded"),
            (&mut b.gradient_opacity, "gm"),
            (&mut b.perspective, "perspective"),
        ] {
            *flag = rest.next_if(|w| **w == word).is_some();
        }
        let number = |w: Option<&&str>, tag: &str, what: &str| {
            w.and_then(|w| w.strip_prefix(tag))
                .and_then(|n| n.parse::<usize>().ok())
                .ok_or_else(|| bad(&format!("expected {what} ({tag}<number>)")))
        };
        b.neighbourhood = match number(rest.next(), "n", "the gradient neighbourhood")? {
            6 => Neighbourhood::N6,
            10 => Neighbourhood::N10,
            12 => Neighbourhood::N12,
            26 => Neighbourhood::N26,
            k => {
                return Err(bad(&format!(
                    "the {k}-neighbourhood is not built (6, 10, 12 or 26)"
                )))
            }
        };
        b.p = number(rest.next(), "p", "the pipelines")?;
        b.n = number(rest.next(), "", "the largest volume side")?;
        for w in rest {
            let bits = |tag| number(Some(w), tag, "a width").map(|v| v as u32);
            match w.chars().next() {
                Some('v') => b.voxel_bits = bits("v")?,
                Some('c') => b.rgba_bits = bits("c")?,
                Some('f') => b.frac_bits = bits("f")?,
                Some('q') => b.normal_bits = bits("q")?,
                _ => return Err(bad(&format!("unknown field '{w}'"))),
            }
        }
        if b.name() != name {
            return Err(bad(&format!("it reads as {}", b.name())));
        }
        match normal_bits_refusal(b.normal_bits, b.shading) {
            Some(why) => Err(bad(&why)),
            None => Ok(b),
        }
    }

    /// The units the build has.
    fn units(&self) -> Units {
        let shaders = ModeClass::of(self.mode) == ModeClass::Over;
        Units {
            perspective: self.perspective,
            gradient: shaders && (self.shading || self.gradient_opacity),
            shaders,
            lighting: self.shading,
            gradient_opacity: self.gradient_opacity,
            xray: self.mode == Mode::Xray,
            n26: self.neighbourhood == Neighbourhood::N26,
            n10: self.neighbourhood == Neighbourhood::N10,
        }
    }

    /// What the build's memories and tables are sized for.
    pub fn sizes(&self) -> Cube3Sizes {
        Cube3Sizes {
            n: self.n,
            p: self.p,
            perspective: self.perspective,
            gradients: self.units().gradient,
            voxel_bits: self.voxel_bits,
        }
    }

    /// The voxels live in external RAM (a module holds more than 2^16
    /// words).
    pub fn external_memory(&self) -> bool {
        self.sizes().external()
    }
}

/// One base plane: its view, the golden model's shading tables and
/// neighbourhood, the system's configuration for this view, and what the
/// build is sized for.
#[derive(Debug, Clone)]
pub struct Part {
    pub view: View,
    pub shader: Shader,
    pub neighbourhood: Neighbourhood,
    pub config: Cube3SystemConfig,
    pub sizes: Cube3Sizes,
}

/// The units a Cube-3 system leaves out.
pub fn left_out(c: &Cube3SystemConfig) -> Vec<LeftOut> {
    hdl::common::units::left_out(units::UNITS, &Units::of_system(c))
}

/// The scene's base planes, each with the system that renders it, for a
/// build sized for volumes of `n` a side (the scene's own largest side
/// without one).
fn scene_parts(scene: &Scene, camera: &Camera, n: Option<usize>) -> Result<Vec<Part>, String> {
    let plan = Plan::new(scene, camera).map_err(|e| e.to_string())?;
    let nb = golden_model::cube3::neighbourhood(scene, None).map_err(|e| e.to_string())?;
    plan.views
        .into_iter()
        .map(|view| {
            let shader = Shader::new(scene, camera, &view);
            let config = config(scene, &view, &shader, nb)?;
            let sizes = Cube3Sizes {
                n: n.unwrap_or_else(|| view.dims.iter().copied().max().unwrap_or(1)),
                p: config.pipeline.p,
                perspective: config.pipeline.perspective,
                gradients: config.pipeline.abc.is_some(),
                voxel_bits: config.pipeline.voxel_bits,
            };
            Ok(Part {
                view,
                shader,
                neighbourhood: nb,
                config,
                sizes,
            })
        })
        .collect()
}

/// The Verilog of the build that renders `part`, its unneeded units pruned;
/// `preload` initialises on-chip memory (simulation only).
pub fn verilog(part: &Part, preload: Option<&[Vec<u16>]>) -> Result<String, String> {
    with_p(part.config.pipeline.p, Emit(part, preload))?
}

struct Emit<'a>(&'a Part, Option<&'a [Vec<u16>]>);

impl ForP for Emit<'_> {
    type Output = Result<String, String>;
    fn run<const P: usize>(self) -> Self::Output {
        let Emit(part, preload) = self;
        let c = &part.config;
        let mut uut = Cube3System::<P, A, B, H>::new(&c.pipeline, &part.sizes)?;
        if let Some(m) = preload.filter(|_| !part.sizes.external()) {
            uut.preload(m);
        }
        uut.connect_all();
        clean_verilog(&generate_verilog(&uut), &left_out(c))
    }
}

/// The system of one of the scene's base planes: the whole base plane, its
/// memory external beyond 2^16 voxels a module.
pub fn config(
    scene: &Scene,
    view: &View,
    shader: &Shader,
    n: Neighbourhood,
) -> Result<Cube3SystemConfig, String> {
    let height = (view.v[1] - view.v[0] + 1) as usize;
    Cube3SystemConfig::new(view, shader, n, scene.hardware.pipelines, view.v[0], height)
}

/// Simulate a run of base planes on one build for `P` units in rust-hdl:
/// before each, the host's writes, then `start`, then its pixels.
struct RustHdl<'a>(
    &'a [(&'a Part, Vec<Write>)],
    &'a [Vec<u16>],
    Option<&'a Path>,
);

/// What the rust-hdl testbench collects: per base plane, the records and
/// the clock count.
type Collected = std::sync::Arc<std::sync::Mutex<Vec<(Vec<Record>, u64)>>>;

impl ForP for RustHdl<'_> {
    type Output = Result<Vec<(Vec<Record>, u64)>, String>;
    fn run<const P: usize>(self) -> Self::Output {
        let RustHdl(runs, modules, trace) = self;
        let first = runs.first().ok_or("no base plane to simulate")?.0;
        let mut uut = Cube3System::<P, A, B, H>::new(&first.config.pipeline, &first.sizes)?;
        uut.preload(modules);
        uut.connect_all();
        // Per base plane: its writes, and its pixels and clock limit.
        let runs: Vec<(Vec<Write>, u64, u64)> = runs
            .iter()
            .map(|(part, w)| {
                let (Stop::Pulses { count, limit, .. }, _) = Cube3::bus(part) else {
                    unreachable!("a frame stops on its last pixel")
                };
                (w.clone(), count, limit)
            })
            .collect();
        let clocks: u64 = runs.iter().map(|(w, _, l)| w.len() as u64 + l + 2).sum();
        let expected: Vec<(u64, u64)> = runs.iter().map(|r| (r.1, r.2)).collect();
        let out: Collected = Default::default();
        let sink = out.clone();
        let mut sim = Simulation::new();
        sim.add_clock(5, |x: &mut Box<Cube3System<P, A, B, H>>| {
            x.clock.next = !x.clock.val()
        });
        sim.add_testbench(move |mut sim: Sim<Cube3System<P, A, B, H>>| {
            let mut x = sim.init()?;
            for (loads, count, limit) in &runs {
                for w in loads {
                    crate::drive_host_port!(x, Some(w));
                    wait_clock_cycle!(sim, clock, x);
                }
                crate::drive_host_port!(x, None::<&Write>);
                sink.lock().unwrap().push((vec![], 0));
                let (mut seen, mut t) = (0, 0);
                while seen < *count && t < *limit {
                    x.start.next = t == 0;
                    wait_clock_cycle!(sim, clock, x);
                    let mut o = sink.lock().unwrap();
                    let o = o.last_mut().unwrap();
                    if x.done.val() {
                        let px = [
                            x.pixel_r.val().to_u64(),
                            x.pixel_g.val().to_u64(),
                            x.pixel_b.val().to_u64(),
                            x.pixel_a.val().to_u64(),
                            x.has_sample.val() as u64,
                        ];
                        o.0.push(Record {
                            clock: t,
                            group: 0,
                            values: px.map(Some).to_vec(),
                        });
                        seen += 1;
                    }
                    t += 1;
                    o.1 = t;
                }
            }
            sim.done(x)
        });
        crate::harness::run_rust_hdl(sim, Box::new(uut), 10 * clocks + 100, trace)?;
        let o = out.lock().unwrap();
        for ((rec, _), (count, limit)) in o.iter().zip(&expected) {
            if rec.len() as u64 != *count {
                return Err(format!(
                    "the system put out {} pixels of {count} in {limit} clocks",
                    rec.len()
                ));
            }
        }
        Ok(o.clone())
    }
}

impl Arch for Cube3 {
    type Config = Cube3Build;
    const NAME: &'static str = "cube3";
    const TITLE: &'static str = "Cube-3";
    const PART: &'static str = "base_plane";
    const LAYOUT: Layout = units::LAYOUT;
    type Part = Part;
    type Base = BasePlane;

    fn needs(scene: &Scene, camera: &Camera, dims: [usize; 3]) -> Result<Cube3Build, String> {
        let parts = scene_parts(scene, camera, None)?;
        let first = parts.first().ok_or("the view needs no base plane")?;
        let hw = scene.hardware;
        Ok(Cube3Build {
            p: hw.pipelines,
            mode: scene.mode,
            shading: first.shader.lighting.is_some(),
            gradient_opacity: first
                .shader
                .opacity
                .as_ref()
                .is_some_and(|o| o.gm_shift.is_some()),
            perspective: first.config.pipeline.perspective,
            neighbourhood: first.neighbourhood,
            voxel_bits: hw.voxel_bits,
            frac_bits: hw.frac_bits,
            rgba_bits: hw.rgba_bits,
            normal_bits: first
                .shader
                .lighting
                .as_ref()
                .map_or_else(unlit_normal_bits, |l| l.normal_bits),
            n: dims.iter().copied().max().unwrap_or(1),
        })
    }

    fn config_name(config: &Cube3Build) -> String {
        config.name()
    }

    fn parse_config(name: &str) -> Result<Cube3Build, String> {
        Cube3Build::parse(name)
    }

    fn refuses(build: &Cube3Build, needed: &Cube3Build) -> Option<String> {
        if needed.n > build.n {
            return Some(format!(
                "a volume side of {}, beyond the configuration's {}",
                needed.n, build.n
            ));
        }
        let width = width_refusal(build.widths(), needed.widths())
            .map(|w| w + "; ")
            .unwrap_or_default();
        (*build
            != Cube3Build {
                n: build.n,
                ..needed.clone()
            })
        .then(|| {
            format!(
                "{width}the scene needs {}, the configuration is {}",
                needed.name(),
                build.name()
            )
        })
    }

    fn parts(
        scene: &Scene,
        camera: &Camera,
        dims: [usize; 3],
        build: &Cube3Build,
    ) -> Result<Vec<Part>, String> {
        let needed = Self::needs(scene, camera, dims)?;
        if let Some(why) = Self::refuses(build, &needed) {
            return Err(format!(
                "configuration {} cannot render the scene: {why}",
                build.name()
            ));
        }
        let parts = scene_parts(scene, camera, Some(build.n))?;
        for (i, p) in parts.iter().enumerate() {
            if let Some(why) = p.sizes.refuses(&p.config) {
                return Err(format!(
                    "configuration {} cannot render base plane {i} of the scene: {why}",
                    build.name()
                ));
            }
        }
        Ok(parts)
    }

    fn left_out(config: &Cube3Build) -> Vec<LeftOut> {
        hdl::common::units::left_out(units::UNITS, &config.units())
    }

    fn external(config: &Cube3Build) -> bool {
        config.external_memory()
    }

    fn modules(part: &Part, vol: &Volume) -> Vec<Vec<u16>> {
        part.config.fetch.modules(vol, &part.view)
    }

    fn verilog(part: &Part, preload: Option<&[Vec<u16>]>) -> Result<String, String> {
        verilog(part, preload)
    }

    fn design(config: &Cube3Build) -> Result<String, String> {
        Err(format!(
            "configuration {}: a Cube-3 build takes its tables' shapes from a scene of its class; give --scene too",
            config.name()
        ))
    }

    /// One simulation runs the base planes of one traversal order (the
    /// memory holds the volume in that order).
    fn same_build(a: &Part, b: &Part) -> bool {
        a.sizes == b.sizes && a.view.perm == b.view.perm && a.view.positive == b.view.positive
    }

    fn bus(part: &Part) -> (Stop, Vec<Group>) {
        let p = &part.config.pipeline;
        let stop = Stop::Pulses {
            output: units::PIXEL_VALID.into(),
            count: (p.rays * p.scanlines) as u64,
            limit: part.config.clocks() as u64 + 1000,
        };
        let groups = vec![Group {
            when: Some(units::PIXEL_VALID.into()),
            fields: units::PIXEL.map(String::from).to_vec(),
        }];
        (stop, groups)
    }

    fn loads(part: &Part) -> Vec<Write> {
        let mut w = part.config.view_writes();
        if let Some(s) = &part.config.pipeline.shading {
            let t = s.tables();
            w.extend(t.table_writes());
            w.extend(t.register_writes());
        }
        w
    }

    fn rust_hdl(
        runs: &[(&Part, Vec<Write>)],
        modules: &[Vec<u16>],
        trace: Option<&Path>,
    ) -> Result<Vec<(Vec<Record>, u64)>, String> {
        let p = runs
            .first()
            .ok_or("no base plane to simulate")?
            .0
            .config
            .pipeline
            .p;
        with_p(p, RustHdl(runs, modules, trace))?
    }

    fn decode(part: &Part, records: &[Record]) -> Result<BasePlane, String> {
        let c = &part.config;
        let want = Self::golden_shape(part);
        let mut base = BasePlane {
            pixels: vec![[0; 4]; want.width * want.height],
            cast: vec![false; want.width * want.height],
            ..want
        };
        let r = c.fetch.rays;
        for (n, rec) in records.iter().enumerate() {
            let v: Vec<u64> = rec
                .values
                .iter()
                .zip(units::PIXEL)
                .map(|(v, name)| v.ok_or_else(|| format!("clock {}: {name} is unknown", rec.clock)))
                .collect::<Result<_, _>>()?;
            let (u, vv) = (c.fetch.u0 + (n % r) as i32, c.fetch.v0 + (n / r) as i32);
            let (x, y) = (u - base.u0, vv - base.v0);
            if n % r + 1 < r
                && x >= 0
                && (x as usize) < base.width
                && y >= 0
                && (y as usize) < base.height
            {
                let i = y as usize * base.width + x as usize;
                base.pixels[i] = [v[0], v[1], v[2], v[3]].map(|v| v as u32);
                base.cast[i] = v[4] == 1;
            }
        }
        Ok(base)
    }

    fn golden(part: &Part, vol: &Volume) -> BasePlane {
        let p = part.config.pipeline.p;
        render_view(vol, &part.view, &part.shader, part.neighbourhood, p).0
    }

    fn image(scene: &Scene, camera: &Camera, bases: Vec<BasePlane>) -> Result<Image, String> {
        let plan = Plan::new(scene, camera).map_err(|e| e.to_string())?;
        let n = golden_model::cube3::neighbourhood(scene, None).map_err(|e| e.to_string())?;
        let frame = Frame {
            plan,
            bases,
            stats: Stats::default(),
            widths: golden_model::cube3::plan::Widths::of(scene),
            neighbourhood: n,
            pipelines: scene.hardware.pipelines,
        };
        Ok(golden_model::cube3::warp(&frame, camera, scene.mode))
    }

    fn ideal_clocks(part: &Part) -> u64 {
        let [nx, ny, nk] = part.config.fetch.dims;
        ((nx * ny * nk) as u64).div_ceil(part.config.fetch.p as u64)
    }

    fn clock_terms(part: &Part) -> Vec<ClockTerm> {
        let c = &part.config;
        let f = &c.fetch;
        let rg = (f.rays * f.segments) as i64;
        let (s, t) = (f.scanlines as i64, f.period() as i64);
        let term = |key, what, clocks| ClockTerm { key, what, clocks };
        assert_eq!(
            (f.rays, f.scanlines),
            (c.pipeline.rays, c.pipeline.scanlines)
        );
        let (inside, crossing) = c.pipeline.segments_inside();
        let (inside, crossing) = (inside as i64, crossing as i64);
        let terms = vec![
            term("segments", "segments with a sample in the volume", inside),
            term(
                "segments_outside",
                "segments wholly outside, on rays that cross the volume",
                crossing - inside,
            ),
            term(
                "rays_outside",
                "segments of rays that miss the volume",
                rg * s - crossing,
            ),
            term("idle", "waiting for PRP writes", s * (t - rg)),
            term("prologue", "prologue", c.first_entry() as i64),
            term("tail", "last wait", -(t - rg)),
            term("drain", "drain", c.pipeline.pixel_delay() as i64),
        ];
        assert_eq!(
            terms.iter().map(|t| t.clocks).sum::<i64>(),
            c.clocks() as i64,
            "the clock terms add up to the system's clocks"
        );
        terms
    }

    fn buffer_memory(config: &Cube3Build, _parts: &[Part]) -> BufferMemory {
        // The build's 2-DSBs hold the longest PRP of its class: `R` rays of
        // `G·P` words of voxel bits, where the least is `n` planes a ray.
        let s = config.sizes();
        BufferMemory {
            what: "three 2-D skewed buffers",
            bits: (3 * s.p * s.rays() * s.segments()) as u64 * config.voxel_bits as u64,
            minimum_bits: (3 * s.rays() * s.n) as u64 * config.voxel_bits as u64,
        }
    }

    fn projected_clocks(_n: u64, _config: &Cube3Build) -> Option<u64> {
        None
    }

    fn waves(part: &Part, top: &str) -> Vec<Wave> {
        units::waves(&part.config.pipeline, top)
    }

    fn manifest_part(part: &Part) -> serde_json::Value {
        let (c, view) = (&part.config, &part.view);
        let axis = ["u", "v", "w"][view.perm[2]];
        serde_json::json!({
            "axis": axis,
            "towards_positive": view.positive,
            "projection": if c.pipeline.perspective { "perspective" } else { "parallel" },
            "traversal_dims": c.fetch.dims,
            "offset": c.pipeline.offset,
            "rays": c.fetch.rays,
            "scanlines": c.fetch.scanlines,
            "period_clocks": c.fetch.period(),
            "clocks": c.clocks(),
            "segments_per_ray": c.fetch.segments,
            "voxels_per_module": c.fetch.module_words(),
            "words_per_buffer_module": c.fetch.rays * c.fetch.segments,
        })
    }

    fn manifest_parameters(config: &Cube3Build) -> serde_json::Value {
        serde_json::json!({
            "configuration": config.name(),
            "pipelines": config.p,
            "mode": mode_name(config.mode),
            "shading": config.shading,
            "gradient_opacity": config.gradient_opacity,
            "rays": if config.perspective { "perspective" } else { "parallel" },
            "neighbourhood": config.neighbourhood.count(),
            "voxel_bits": config.voxel_bits,
            "frac_bits": config.frac_bits,
            "rgba_bits": config.rgba_bits,
            "largest_volume_side": config.n,
            "memory": if config.external_memory() { "external" } else { "on-chip" },
        })
    }
}

impl BasePixels for BasePlane {
    type Pixel = ([u32; 4], bool);
    fn count(&self) -> usize {
        self.pixels.len()
    }
    fn at(&self, i: usize) -> ([i32; 2], Self::Pixel) {
        let at = [
            self.u0 + (i % self.width) as i32,
            self.v0 + (i / self.width) as i32,
        ];
        (at, (self.pixels[i], self.cast[i]))
    }
}

impl Cube3 {
    /// The golden base plane's shape (origin and size), without its pixels.
    fn golden_shape(part: &Part) -> BasePlane {
        let v = &part.view;
        let [width, height] = v.base_dims();
        BasePlane {
            u0: v.u[0],
            v0: v.v[0],
            width,
            height,
            pixels: vec![],
            cast: vec![],
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn configuration_names_read_back() {
        for name in [
            "composite_shaded_n12_p4_32",
            "composite_shaded_n26_p4_32",
            "composite_shaded_n10_p2_16",
            "first_opaque_gm_perspective_n6_p2_20",
            "minip_n12_p8_256_v16_c12",
            "xray_n12_p2_256",
            "composite_shaded_n12_p4_32_f12_q6",
        ] {
            assert_eq!(Cube3Build::parse(name).map(|b| b.name()), Ok(name.into()));
        }
        let knee = Cube3Build::parse("composite_shaded_n12_p4_32_f12_q6").unwrap();
        assert_eq!((knee.frac_bits, knee.normal_bits), (12, 6));
        let b = Cube3Build::parse("first_opaque_gm_perspective_n6_p2_20").unwrap();
        assert_eq!(
            (b.mode, b.gradient_opacity, b.perspective, b.p, b.n),
            (Mode::FirstOpaque, true, true, 2, 20)
        );
        for (bad, why) in [
            ("mip_n12_p4", "the largest volume side"),
            ("mip_n8_p4_32", "8-neighbourhood"),
            ("glow_n12_p4_32", "the mode is"),
            ("mip_n12_p4_32_x3", "unknown field 'x3'"),
            ("mip_n12_p4_32_q6", "6-bit normals without shading"),
            ("composite_shaded_n12_p4_32_q9", "9-bit normals"),
            ("composite_shaded_n12_p4_32_q5", "it reads as"),
            ("mip_shaded_n12_p4_32_v8", "it reads as"),
        ] {
            let e = Cube3Build::parse(bad).unwrap_err();
            assert!(e.contains(why), "{bad}: {e}");
        }
    }
}
