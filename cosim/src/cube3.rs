//! Cube-3 in the flows: a part is a base plane, its hardware the
//! [`hdl::cube3::Cube3System`] (beam fetch, ray control, TRILIN, ABC units,
//! shaders, RPC), its pixels one per stream ray, in stream order, on the
//! `done` port. The volume is loaded into the memory modules in each base
//! plane's traversal order.
//!
//! The shader's light and tables are host registers and RAM, but the view
//! (templates, bounds, de-fanning groups, the base plane) is still built
//! into each base plane's system: a Cube-3 configuration names the units,
//! and each base plane is a build of its own.

use crate::arch::{Arch, BasePixels, BufferMemory, ClockTerm};
use crate::gtkw::Wave;
use crate::harness::{Group, Record, Stop};
use crate::verilog::{clean_verilog, Layout, LeftOut, ON_CHIP_BITS as A};
use golden_model::cube3::plan::{Neighbourhood, Plan, View};
use golden_model::cube3::shade::Shader;
use golden_model::cube3::{render_view, BasePlane, Frame, Stats};
use golden_model::host::Write;
use hdl::common::lanes::{with_p, ForP};
use hdl::common::mode_class::ModeClass;
use hdl::cube3::{Cube3System, Cube3SystemConfig};
use rust_hdl::prelude::*;
use scene::volume::Volume;
use scene::{Camera, Image, Scene};
use std::path::Path;

/// 2-DSB and delay-line address bits of every Cube-3 build (the ABC
/// units' sample-plane lines are a scanline period long: 13 313 clocks for
/// the engine at p = 4).
pub const B: usize = 16;
pub const H: usize = 16;

/// Cube-3 (Pfister, Wessels and Kaufman): ray-parallel casting.
pub struct Cube3;

/// What a Cube-3 build is made of beyond its views: p, the mode class, the
/// units and the widths.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Cube3Build {
    pub p: usize,
    pub mode: ModeClass,
    pub shading: bool,
    pub gradient_opacity: bool,
    pub perspective: bool,
    pub neighbourhood: Neighbourhood,
    pub voxel_bits: u32,
    pub frac_bits: u32,
    pub rgba_bits: u32,
    /// The voxels live in external RAM (a base plane's module holds more
    /// than 2^16 words).
    pub external_memory: bool,
}

impl Cube3Build {
    /// `{mode}[_shaded][_gm][_perspective]_n{6|12|...}_p{p}`, with the
    /// widths when not 8 bits.
    pub fn name(&self) -> String {
        let mut s = self.mode.name().to_string();
        for (on, w) in [
            (self.shading, "_shaded"),
            (self.gradient_opacity, "_gm"),
            (self.perspective, "_perspective"),
        ] {
            if on {
                s += w;
            }
        }
        s += &format!("_n{}_p{}", self.neighbourhood.count(), self.p);
        for (bits, tag) in [
            (self.voxel_bits, 'v'),
            (self.rgba_bits, 'c'),
            (self.frac_bits, 'f'),
        ] {
            if bits != 8 {
                s += &format!("_{tag}{bits}");
            }
        }
        s
    }
}

/// One base plane: its view, the golden model's shading tables and
/// neighbourhood, and the system's configuration.
#[derive(Debug, Clone)]
pub struct Part {
    pub view: View,
    pub shader: Shader,
    pub neighbourhood: Neighbourhood,
    pub config: Cube3SystemConfig,
}

/// The file (one per stage) of a Cube-3 system's module.
fn stage_file(name: &str) -> &'static str {
    let parts: Vec<&str> = name.split('$').collect();
    match parts.as_slice() {
        ["top"] => "top.v",
        ["top", "fetch", ..] => "beam_fetch.v",
        ["top", "pipeline", "control", ..] => "ray_control.v",
        ["top", "pipeline", "lanes", "units", ..] => "trilin.v",
        ["top", "pipeline", "lanes", ..] => "trilin_lanes.v",
        ["top", "pipeline", "rpc", ..] => "rpc.v",
        ["top", "pipeline", "abc", ..] => "abc_unit.v",
        ["top", "pipeline", "shade", ..] => "shader.v",
        _ => "cube3.v",
    }
}

/// The lint waivers every emitted Cube-3 system needs beyond those of
/// every design (`verilog::lint_waivers`).
pub const LINT_WAIVERS: &str = r#"// The beam fetch's write addresses and load address are as wide as its
// largest memory: each module and buffer uses the low bits.
lint_off -rule UNUSEDSIGNAL -file "*beam_fetch.v" -match "*Bits of signal are not used: 'write_address$*"
lint_off -rule UNUSEDSIGNAL -file "*beam_fetch.v" -match "*Bits of signal are not used: 'load_address'*"
// The opacity table, as long as the scene's, takes the low bits of a unit's
// opacity row.
lint_off -rule UNUSEDSIGNAL -file "*cube3.v" -match "*Bits of signal are not used: 'row$*"
// The ray control's delayed word carries segment, ray, scanline and valid
// in 64 bits; the bits above valid are spare.
lint_off -rule UNUSEDSIGNAL -file "*ray_control.v" -match "*Bits of signal are not used: 'late$data_out'*"
// The inside and inner bits have one lane bit per unit of up to 8; with
// fewer units the lane bits above them are unused.
lint_off -rule UNUSEDPARAM -file "*ray_control.v" -match "*Parameter is not used: 'lane_bit$*"
lint_off -rule UNUSEDPARAM -file "*cube3.v" -match "*Parameter is not used: 'lane_bit$*"
lint_off -rule UNUSEDPARAM -file "*cube3.v" -match "*Parameter is not used: 'inner_bit$*"
// One flag word rides beside the units: the leaf stage or the shaders take
// its inside and inner bits, the RPC one clock later its valid, first and
// last bits;
lint_off -rule UNUSEDSIGNAL -file "*cube3.v" -match "*Bits of signal are not used: 'rpc_flags_q$q'*"
// its delay line through the ABC units stores only those bits;
lint_off -rule UNUSEDSIGNAL -file "*cube3.v" -match "*Bits of signal are not used: 'write_data'*"
// and after the accumulator only the last-segment flag is read.
lint_off -rule UNUSEDSIGNAL -file "*rpc.v" -match "*Bits of signal are not used: 'node_flags_q$*$q'*"
// The shaders' value is the sample's integer part, voxel bits wide: the
// top bits of s >> F are zero.
lint_off -rule UNUSEDSIGNAL -file "*cube3.v" -match "*Bits of signal are not used: 'index$*"
// Each lane's sample-plane history offers all 27 taps; the neighbouring
// lanes read their middle ones (plane k), and only the first and the last
// lane's taps of the next and previous segment cross to the other end.
lint_off -rule UNUSEDSIGNAL -file "*abc_unit.v" -match "*Signal is not used: 'lanes$*$t*"
"#;

/// The units a Cube-3 build has.
struct Units {
    perspective: bool,
    gradient: bool,
    /// The shaders (composite and first-opaque), with lighting and
    /// gradient opacity.
    shaders: bool,
    lighting: bool,
    gradient_opacity: bool,
    xray: bool,
}

impl Units {
    fn of_build(b: &Cube3Build) -> Units {
        let shaders = b.mode == ModeClass::Over;
        Units {
            perspective: b.perspective,
            gradient: shaders && (b.shading || b.gradient_opacity),
            shaders,
            lighting: b.shading,
            gradient_opacity: b.gradient_opacity,
            xray: b.mode == ModeClass::Xray,
        }
    }

    fn of_system(c: &Cube3SystemConfig) -> Units {
        let p = &c.pipeline;
        Units {
            perspective: p.perspective,
            gradient: p.abc.is_some(),
            shaders: p.shading.is_some(),
            lighting: p.shading.as_ref().is_some_and(|s| s.lighting.is_some()),
            gradient_opacity: p
                .shading
                .as_ref()
                .is_some_and(|s| s.opacity.as_ref().and_then(|o| o.gm_shift).is_some()),
            xray: p.opacity.is_some(),
        }
    }

    /// The units left out.
    fn left_out(&self) -> Vec<LeftOut> {
        let mut v = vec![];
        if !self.perspective {
            v.push(LeftOut {
                name: "de-fanning (a parallel view's beams shift as a whole: no group ROMs, one template entry a plane)",
                instances: &["groups", "group_x$*"],
            });
        }
        if !self.gradient {
            v.push(LeftOut {
                name: "abc_gradient_units (no gradient: MIP, MinIP, X-ray, or neither shading nor gradient opacity)",
                instances: &["abc"],
            });
        }
        if self.shaders {
            v.push(LeftOut {
                name: "leaf_stage (composite and first-opaque take the shaders; disabled by constants, for synthesis to remove)",
                instances: &[],
            });
            if !self.lighting {
                v.push(LeftOut {
                    name: "lighting (the normal's dot products, their tables and registers)",
                    instances: &["lighting", "normal"],
                });
            }
            if !self.gradient_opacity {
                v.push(LeftOut {
                    name: "gradient_opacity (the magnitude bin and its table)",
                    instances: &["alpha_gm", "gm_bin"],
                });
            }
        } else {
            v.push(LeftOut {
                name: "shaders (MIP, MinIP and X-ray take the leaf stage)",
                instances: &["shade$*"],
            });
            v.push(LeftOut {
                name: "rpc_over_operator_multipliers",
                instances: &["ch_r", "ch_g", "ch_b", "ch_a"],
            });
        }
        if !self.xray {
            v.push(LeftOut {
                name: "opacity_table (X-ray only)",
                instances: &["opacity"],
            });
        }
        v
    }
}

/// The units a Cube-3 system leaves out.
pub fn left_out(c: &Cube3SystemConfig) -> Vec<LeftOut> {
    Units::of_system(c).left_out()
}

/// The scene's base planes, each with the system that renders it.
fn scene_parts(scene: &Scene, camera: &Camera) -> Result<Vec<Part>, String> {
    let plan = Plan::new(scene, camera).map_err(|e| e.to_string())?;
    let n = golden_model::cube3::neighbourhood(scene, None).map_err(|e| e.to_string())?;
    plan.views
        .into_iter()
        .map(|view| {
            let shader = Shader::new(scene, camera, &view);
            let config = config(scene, &view, &shader, n)?;
            Ok(Part {
                view,
                shader,
                neighbourhood: n,
                config,
            })
        })
        .collect()
}

/// The Verilog of a Cube-3 system with its unneeded units pruned;
/// `preload` initialises on-chip memory (simulation only).
pub fn verilog(c: &Cube3SystemConfig, preload: Option<&[Vec<u16>]>) -> Result<String, String> {
    with_p(c.pipeline.p, Emit(c, preload))?
}

struct Emit<'a>(&'a Cube3SystemConfig, Option<&'a [Vec<u16>]>);

impl ForP for Emit<'_> {
    type Output = Result<String, String>;
    fn run<const P: usize>(self) -> Self::Output {
        let Emit(c, preload) = self;
        let mut uut = Cube3System::<P, A, B, H>::new(c)?;
        if let Some(m) = preload.filter(|_| !c.fetch.external) {
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
    let mut c =
        Cube3SystemConfig::new(view, shader, n, scene.hardware.pipelines, view.v[0], height)?;
    c.fetch.external = c.fetch.module_words() > 1 << A;
    Ok(c)
}

/// Simulate the system for `P` units in rust-hdl.
struct RustHdl<'a>(&'a Part, &'a [Vec<u16>], &'a [Write], Option<&'a Path>);

impl ForP for RustHdl<'_> {
    type Output = Result<(Vec<Record>, u64), String>;
    fn run<const P: usize>(self) -> Self::Output {
        let RustHdl(part, modules, loads, trace) = self;
        let c = &part.config;
        let mut uut = Cube3System::<P, A, B, H>::new(c)?;
        uut.preload(modules);
        uut.connect_all();
        let loads = loads.to_vec();
        let n_loads = loads.len() as u64;
        let (Stop::Pulses { count, limit, .. }, _) = Cube3::bus(part) else {
            unreachable!("a frame stops on its last pixel")
        };
        let out: std::sync::Arc<std::sync::Mutex<(Vec<Record>, u64)>> = Default::default();
        let sink = out.clone();
        let mut sim = Simulation::new();
        sim.add_clock(5, |x: &mut Box<Cube3System<P, A, B, H>>| {
            x.clock.next = !x.clock.val()
        });
        sim.add_testbench(move |mut sim: Sim<Cube3System<P, A, B, H>>| {
            let mut x = sim.init()?;
            for w in &loads {
                crate::drive_host_port!(x, Some(w));
                wait_clock_cycle!(sim, clock, x);
            }
            crate::drive_host_port!(x, None::<&Write>);
            let mut seen = 0;
            let mut t = 0;
            while seen < count && t < limit {
                x.start.next = t == 0;
                wait_clock_cycle!(sim, clock, x);
                if x.done.val() {
                    let px = [
                        x.pixel_r.val().to_u64(),
                        x.pixel_g.val().to_u64(),
                        x.pixel_b.val().to_u64(),
                        x.pixel_a.val().to_u64(),
                        x.has_sample.val() as u64,
                    ];
                    sink.lock().unwrap().0.push(Record {
                        clock: t,
                        group: 0,
                        values: px.map(Some).to_vec(),
                    });
                    seen += 1;
                }
                t += 1;
            }
            sink.lock().unwrap().1 = t;
            sim.done(x)
        });
        crate::harness::run_rust_hdl(sim, Box::new(uut), 10 * (limit + n_loads) + 100, trace)?;
        let o = out.lock().unwrap();
        if o.0.len() as u64 != count {
            return Err(format!(
                "the system put out {} pixels of {count} in {limit} clocks",
                o.0.len()
            ));
        }
        Ok(o.clone())
    }
}

impl Arch for Cube3 {
    type Config = Cube3Build;
    const NAME: &'static str = "cube3";
    const TITLE: &'static str = "Cube-3";
    const PART: &'static str = "base_plane";
    const LAYOUT: Layout = Layout {
        files: &[
            "top.v",
            "beam_fetch.v",
            "ray_control.v",
            "trilin_lanes.v",
            "trilin.v",
            "abc_unit.v",
            "shader.v",
            "cube3.v",
            "rpc.v",
        ],
        stage_file,
        waivers: LINT_WAIVERS,
    };
    type Part = Part;
    type Base = BasePlane;

    fn needs(scene: &Scene, camera: &Camera, _dims: [usize; 3]) -> Result<Cube3Build, String> {
        let parts = scene_parts(scene, camera)?;
        let first = parts.first().ok_or("the view needs no base plane")?;
        let hw = scene.hardware;
        Ok(Cube3Build {
            p: hw.pipelines,
            mode: ModeClass::of(scene.mode),
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
            external_memory: parts.iter().any(|p| p.config.fetch.external),
        })
    }

    fn config_name(config: &Cube3Build) -> String {
        config.name()
    }

    fn parse_config(name: &str) -> Result<Cube3Build, String> {
        Err(format!(
            "configuration '{name}': a Cube-3 build is made for its scene's base planes (their templates, bounds and groups are built in); give --scene"
        ))
    }

    fn refuses(build: &Cube3Build, needed: &Cube3Build) -> Option<String> {
        (build != needed).then(|| {
            format!(
                "the scene needs {}, the configuration is {}",
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
        scene_parts(scene, camera)
    }

    fn left_out(config: &Cube3Build) -> Vec<LeftOut> {
        Units::of_build(config).left_out()
    }

    fn external(config: &Cube3Build) -> bool {
        config.external_memory
    }

    fn modules(part: &Part, vol: &Volume) -> Vec<Vec<u16>> {
        part.config.fetch.modules(vol, &part.view)
    }

    fn verilog(part: &Part, preload: Option<&[Vec<u16>]>) -> Result<String, String> {
        verilog(&part.config, preload)
    }

    fn design(config: &Cube3Build) -> Result<String, String> {
        Self::parse_config(&config.name()).map(|_| String::new())
    }

    fn same_build(_a: &Part, _b: &Part) -> bool {
        false
    }

    fn bus(part: &Part) -> (Stop, Vec<Group>) {
        let p = &part.config.pipeline;
        let stop = Stop::Pulses {
            output: "done".into(),
            count: (p.rays * p.scanlines) as u64,
            limit: part.config.clocks() as u64 + 1000,
        };
        let fields = ["pixel_r", "pixel_g", "pixel_b", "pixel_a", "has_sample"];
        let groups = vec![Group {
            when: Some("done".into()),
            fields: fields.map(String::from).to_vec(),
        }];
        (stop, groups)
    }

    fn loads(part: &Part) -> Vec<Write> {
        let Some(s) = &part.config.pipeline.shading else {
            return vec![];
        };
        let t = s.tables();
        [t.table_writes(), t.register_writes()].concat()
    }

    fn rust_hdl(
        runs: &[(&Part, Vec<Write>)],
        modules: &[Vec<u16>],
        trace: Option<&Path>,
    ) -> Result<Vec<(Vec<Record>, u64)>, String> {
        // Each base plane is a build of its own (`same_build`).
        runs.iter()
            .map(|(part, loads)| {
                with_p(part.config.pipeline.p, RustHdl(part, modules, loads, trace))?
            })
            .collect()
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
                .zip(["pixel_r", "pixel_g", "pixel_b", "pixel_a", "has_sample"])
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
        let terms = vec![
            term("segments", "segments (R*S*G)", rg * s),
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

    fn buffer_memory(_config: &Cube3Build, parts: &[Part]) -> BufferMemory {
        // Base planes run one after another on one system: the largest
        // one's 2-DSBs are what is built. Each holds a PRP of `R` rays,
        // `G·P` 16-bit words a ray, where the least is `K` planes of voxel
        // bits.
        let c = parts
            .iter()
            .map(|d| &d.config)
            .max_by_key(|c| c.fetch.rays * c.fetch.segments)
            .expect("a part per base plane");
        let f = &c.fetch;
        BufferMemory {
            what: "three 2-D skewed buffers",
            bits: (3 * f.p * f.rays * f.segments * 16) as u64,
            minimum_bits: (3 * f.rays * f.dims[2]) as u64 * c.pipeline.voxel_bits as u64,
        }
    }

    fn projected_clocks(_n: u64, _config: &Cube3Build) -> Option<u64> {
        None
    }

    fn waves(part: &Part, top: &str) -> Vec<Wave> {
        let c = &part.config.pipeline;
        let p = c.p;
        let under = |prefix: &str, names: &[&str]| -> Vec<String> {
            names.iter().map(|n| format!("{prefix}.{n}")).collect()
        };
        let sch = format!("{top}.fetch.schedule");
        let mut w: Vec<Wave> = vec![(
            "Beam fetch".into(),
            under(
                &sch,
                &[
                    "writing",
                    "period[15:0]",
                    "plane[15:0]",
                    "chunk[15:0]",
                    "reading",
                    "ray[15:0]",
                    "segment[15:0]",
                ],
            ),
        )];
        let mut streams = vec![format!("{top}.fetch.valid")];
        for i in 0..p {
            streams.push(format!("{top}.fetch.cur${i}[15:0]"));
            streams.push(format!("{top}.fetch.next${i}[15:0]"));
        }
        w.push(("2-DSB streams".into(), streams));
        let pipe = format!("{top}.pipeline");
        w.push((
            "Ray control".into(),
            under(
                &format!("{pipe}.control"),
                &[
                    "first",
                    "unit_valid",
                    "unit_first",
                    "unit_last",
                    "in_volume[7:0]",
                ],
            ),
        ));
        for i in 0..p {
            let mut sigs = vec![
                format!("{pipe}.lanes.wx${i}[15:0]"),
                format!("{pipe}.lanes.wy${i}[15:0]"),
                format!("{pipe}.lanes.sample${i}[31:0]"),
            ];
            if c.shading.is_none() {
                sigs.push(format!("{pipe}.leaf_q${i}.q[31:0]"));
                sigs.push(format!("{pipe}.leaf_valid_q${i}.q"));
            }
            w.push((format!("TRILIN {i}"), sigs));
            if c.shading.is_some() {
                let mut sigs = vec![];
                if c.abc.is_some() {
                    for g in ["centre", "gx", "gy", "gz"] {
                        sigs.push(format!("{pipe}.abc.{g}${i}[31:0]"));
                    }
                }
                for o in ["r[31:0]", "g[15:0]", "b[15:0]", "a[15:0]", "valid"] {
                    sigs.push(format!("{pipe}.shade${i}.{o}"));
                }
                w.push((format!("ABC unit {i}"), sigs));
            }
        }
        w.push((
            "RPC".into(),
            under(
                &format!("{pipe}.rpc"),
                &[
                    "first",
                    "last",
                    "done",
                    "pixel_r[31:0]",
                    "pixel_a[15:0]",
                    "has_sample",
                ],
            ),
        ));
        w
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
            "modes": config.mode.modes(),
            "shading": config.shading,
            "gradient_opacity": config.gradient_opacity,
            "rays": if config.perspective { "perspective" } else { "parallel" },
            "neighbourhood": config.neighbourhood.count(),
            "voxel_bits": config.voxel_bits,
            "frac_bits": config.frac_bits,
            "rgba_bits": config.rgba_bits,
            "memory": if config.external_memory { "external" } else { "on-chip" },
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
