//! Cube-4L in the flows: a build is a [`PipelineConfig`], its hardware the
//! [`hdl::cube4l::Pipeline`] of CFB and `P` pipelines; a part is a sweep,
//! rendered after the host writes its view registers
//! ([`golden_model::cube4l::regs::ViewRegs`]) and the shader's tables; its
//! pixels are the base plane's cells that leave on ER through each lane's
//! pixel port.

use crate::arch::{Arch, BasePixels, BufferMemory, ClockTerm};
use crate::gtkw::Wave;
use crate::harness::{Group, Record, Stop};
use crate::verilog::{clean_verilog, Layout, LeftOut, ON_CHIP_BITS as A};
use golden_model::common::shader::Shader as GoldenShader;
use golden_model::cube4l::cfb::SkewedMemory;
use golden_model::cube4l::plan::{Face, Plan, Rays, Sweep};
use golden_model::cube4l::regs::ViewRegs;
use golden_model::cube4l::{render_sweep, BasePlane, Frame, Stats};
use golden_model::host::Write;
use hdl::common::lanes::{with_p, ForP};
use hdl::cube4l::config::unpack;
use hdl::cube4l::units;
use hdl::cube4l::{Pipeline, PipelineConfig};
use rust_hdl::prelude::*;
use scene::volume::Volume;
use scene::{Camera, Image, Scene};
use std::path::Path;

/// Delay-line pointer bits of every build: enough for a 256² slice at any p
/// (see `PipelineConfig::history_bits`, which refuses larger needs).
pub const H: usize = 16;

/// Cube-4L (Bitter and Kaufman): ray-slice sweeping.
pub struct Cube4l;

/// One sweep: its plan, the golden model's shader (whose tables the host
/// loads), the build and the view registers the host writes.
#[derive(Debug, Clone)]
pub struct Part {
    pub sweep: Sweep,
    pub golden: GoldenShader,
    pub config: PipelineConfig,
    pub regs: ViewRegs,
}

impl Part {
    /// Beats of the sweep's composited slices: one per clock.
    fn beats(&self) -> u64 {
        let s = &self.sweep;
        ((s.z1 - s.z0 + 1) * s.dims[1] * s.dims[0].div_ceil(self.config.p as usize)) as u64
    }
}

/// The units a build leaves out (hdl's [`units::UNITS`]).
pub fn left_out(config: &PipelineConfig) -> Vec<LeftOut> {
    hdl::common::units::left_out(units::UNITS, config)
}

/// Build the pipeline for `P` lanes and emit its Verilog.
struct Emit<'a>(&'a PipelineConfig, Option<&'a [Vec<u16>]>);

impl ForP for Emit<'_> {
    type Output = Result<String, String>;
    fn run<const P: usize>(self) -> Self::Output {
        let Emit(config, preload) = self;
        let mut uut = Pipeline::<P, A, H>::new(config)?;
        if let Some(m) = preload.filter(|_| !config.external_memory()) {
            uut.preload(m);
        }
        uut.connect_all();
        clean_verilog(&generate_verilog(&uut), &left_out(config))
    }
}

/// Simulate sweeps one after another on one rust-hdl build of `P` lanes.
struct RustHdl<'a>(
    &'a [(&'a Part, Vec<Write>)],
    &'a [Vec<u16>],
    Option<&'a Path>,
);

/// What the rust-hdl testbench collects: per sweep, the records and the
/// clock count.
type Collected = std::sync::Arc<std::sync::Mutex<Vec<(Vec<Record>, u64)>>>;

impl ForP for RustHdl<'_> {
    type Output = Result<Vec<(Vec<Record>, u64)>, String>;
    fn run<const P: usize>(self) -> Self::Output {
        let RustHdl(runs, modules, trace) = self;
        let mut uut = Pipeline::<P, A, H>::new(&runs[0].0.config)?;
        uut.preload(modules);
        uut.connect_all();
        let runs: Vec<(Vec<Write>, u64)> = runs
            .iter()
            .map(|(part, w)| (w.clone(), part.beats()))
            .collect();
        let clocks: u64 = runs.iter().map(|(w, b)| w.len() as u64 + 2 * b + 200).sum();
        let out: Collected = Default::default();
        let sink = out.clone();
        let mut sim = Simulation::new();
        sim.add_clock(5, |x: &mut Box<Pipeline<P, A, H>>| {
            x.clock.next = !x.clock.val()
        });
        sim.add_testbench(move |mut sim: Sim<Pipeline<P, A, H>>| {
            let mut x = sim.init()?;
            for (loads, beats) in &runs {
                for w in loads {
                    crate::drive_host_port!(x, Some(w));
                    wait_clock_cycle!(sim, clock, x);
                }
                crate::drive_host_port!(x, None::<&Write>);
                x.start.next = true;
                wait_clock_cycle!(sim, clock, x);
                x.start.next = false;
                sink.lock().unwrap().push((vec![], 1));
                let (mut seen, mut t) = (0u64, 0u64);
                while seen < *beats {
                    wait_clock_cycle!(sim, clock, x);
                    t += 1;
                    let mut o = sink.lock().unwrap();
                    let o = o.last_mut().unwrap();
                    for k in 0..P {
                        if x.px_valid[k].val() {
                            let v = [x.px_x[k].val(), x.px_y[k].val()].map(|b| b.to_u64());
                            o.0.push(Record {
                                clock: t,
                                group: k,
                                values: vec![
                                    Some(v[0]),
                                    Some(v[1]),
                                    Some(x.px_face[k].val().to_u64()),
                                    Some(x.res[k].val().to_u64()),
                                ],
                            });
                        }
                    }
                    seen += x.res_beat[0].val() as u64;
                    o.1 = t + 1;
                }
            }
            sim.done(x)
        });
        crate::harness::run_rust_hdl(sim, Box::new(uut), 10 * clocks, trace)?;
        let o = out.lock().unwrap();
        Ok(o.clone())
    }
}

impl BasePixels for BasePlane {
    type Pixel = ([u32; 4], Face);
    fn count(&self) -> usize {
        self.pixels.len()
    }
    fn at(&self, i: usize) -> ([i32; 2], Self::Pixel) {
        let at = [(i % self.width) as i32, (i / self.width) as i32];
        (at, (self.pixels[i], self.faces[i]))
    }
}

/// Put a pixel the RTL put out into `base`, or say why the golden model
/// could never have put it out: an address outside the base plane, or a
/// face code that names no face.
fn place(base: &mut BasePlane, [x, y]: [u64; 2], face: u64, value: [u32; 4]) -> Result<(), String> {
    const FACES: [Face; 6] = [
        Face::None,
        Face::Last,
        Face::XPos,
        Face::XNeg,
        Face::YPos,
        Face::YNeg,
    ];
    let stray = |why: &str| {
        format!(
            "the RTL put out a pixel at ({x}, {y}) with face code {face}: {why} (base plane {} x {})",
            base.width, base.height
        )
    };
    if x >= base.width as u64 || y >= base.height as u64 {
        return Err(stray("outside the base plane"));
    }
    let Some(&f) = FACES.get(face as usize).filter(|&&f| f != Face::None) else {
        return Err(stray("no such face"));
    };
    base.put([x as usize, y as usize], value, f);
    Ok(())
}

impl Arch for Cube4l {
    const NAME: &'static str = "cube4l";
    const TITLE: &'static str = "Cube-4L";
    const PART: &'static str = "sweep";
    const LAYOUT: Layout = units::LAYOUT;
    type Config = PipelineConfig;
    type Part = Part;
    type Base = BasePlane;

    fn needs(scene: &Scene, camera: &Camera, dims: [usize; 3]) -> Result<PipelineConfig, String> {
        let plan = Plan::new(scene, camera).map_err(|e| e.to_string())?;
        let sweep = plan.sweeps.first().ok_or("the view needs no sweep")?;
        let golden = GoldenShader::new(scene, camera, sweep);
        let c = PipelineConfig::for_view(sweep, dims, scene.hardware.pipelines, &golden);
        c.validate()?;
        Ok(c)
    }

    fn config_name(config: &PipelineConfig) -> String {
        config.name()
    }

    fn parse_config(name: &str) -> Result<PipelineConfig, String> {
        PipelineConfig::parse(name)
    }

    fn refuses(build: &PipelineConfig, needed: &PipelineConfig) -> Option<String> {
        build.refuses(needed)
    }

    fn parts(
        scene: &Scene,
        camera: &Camera,
        dims: [usize; 3],
        build: &PipelineConfig,
    ) -> Result<Vec<Part>, String> {
        let needed = Self::needs(scene, camera, dims)?;
        if let Some(why) = build.refuses(&needed) {
            return Err(format!(
                "configuration {build} cannot render the scene: {why}"
            ));
        }
        let plan = Plan::new(scene, camera).map_err(|e| e.to_string())?;
        let p = build.p as usize;
        plan.sweeps
            .into_iter()
            .map(|sweep| {
                let golden = GoldenShader::new(scene, camera, &sweep);
                let regs = ViewRegs::new(&sweep, dims, p, build.gradient(), scene.mode);
                build.check_view(&regs).map_err(|why| {
                    format!("configuration {build} cannot render a sweep of the view: {why}")
                })?;
                Ok(Part {
                    sweep,
                    golden,
                    config: *build,
                    regs,
                })
            })
            .collect()
    }

    fn left_out(config: &PipelineConfig) -> Vec<LeftOut> {
        left_out(config)
    }

    fn external(config: &PipelineConfig) -> bool {
        config.external_memory()
    }

    fn modules(part: &Part, vol: &Volume) -> Vec<Vec<u16>> {
        SkewedMemory::new(vol, part.config.p as usize).modules
    }

    fn verilog(part: &Part, preload: Option<&[Vec<u16>]>) -> Result<String, String> {
        with_p(part.config.p as usize, Emit(&part.config, preload))?
    }

    fn design(config: &PipelineConfig) -> Result<String, String> {
        with_p(config.p as usize, Emit(config, None))?
    }

    fn same_build(a: &Part, b: &Part) -> bool {
        a.config == b.config
    }

    fn bus(part: &Part) -> (Stop, Vec<Group>) {
        let beats = part.beats();
        let stop = Stop::Pulses {
            output: units::BEAT.into(),
            count: beats,
            limit: 2 * beats + 1000,
        };
        let groups = (0..part.config.p)
            .map(|k| Group {
                when: Some(format!("{}${k}", units::PIXEL_VALID)),
                fields: units::PIXEL.map(|f| format!("{f}${k}")).to_vec(),
            })
            .collect();
        (stop, groups)
    }

    fn loads(part: &Part) -> Vec<Write> {
        let t = part.golden.tables();
        [t.table_writes(), t.register_writes(), part.regs.writes()].concat()
    }

    fn rust_hdl(
        runs: &[(&Part, Vec<Write>)],
        modules: &[Vec<u16>],
        trace: Option<&Path>,
    ) -> Result<Vec<(Vec<Record>, u64)>, String> {
        let p = runs.first().ok_or("no sweep to simulate")?.0.config.p as usize;
        with_p(p, RustHdl(runs, modules, trace))?
    }

    fn decode(part: &Part, records: &[Record]) -> Result<BasePlane, String> {
        let mut base = BasePlane::new(&part.sweep);
        for r in records {
            let v: Vec<u64> = r
                .values
                .iter()
                .map(|v| {
                    v.ok_or_else(|| {
                        format!(
                            "the RTL put out an undefined (X or Z) pixel at clock {} on lane {}",
                            r.clock, r.group
                        )
                    })
                })
                .collect::<Result<_, _>>()?;
            place(
                &mut base,
                [v[0], v[1]],
                v[2],
                unpack(part.golden.mode, v[3]),
            )
            .map_err(|e| format!("clock {}: {e}", r.clock))?;
        }
        Ok(base)
    }

    fn golden(part: &Part, vol: &Volume) -> BasePlane {
        render_sweep(vol, &part.sweep, &part.golden).0
    }

    fn image(scene: &Scene, camera: &Camera, bases: Vec<BasePlane>) -> Result<Image, String> {
        let plan = Plan::new(scene, camera).map_err(|e| e.to_string())?;
        let frame = Frame {
            plan,
            bases,
            stats: Stats::default(),
        };
        let hw = scene.hardware;
        Ok(golden_model::cube4l::warp::warp(
            &frame,
            camera,
            scene.mode,
            hw.rgba_bits,
            hw.voxel_bits,
        ))
    }

    fn ideal_clocks(part: &Part) -> u64 {
        part.beats()
    }

    fn clock_terms(part: &Part) -> Vec<ClockTerm> {
        let (c, r) = (&part.config, &part.regs);
        let slice = r.slice_beats as i64;
        let mut v = vec![ClockTerm {
            key: "beats",
            what: "beats (one voxel per pipeline per clock)",
            clocks: part.beats() as i64,
        }];
        if c.gradient() {
            v.push(ClockTerm {
                key: "gradient_slice",
                what: "gradient unit's slice",
                clocks: slice,
            });
        }
        if c.gradient() && r.stream_z0 < r.z0 {
            // A sweep that starts inside the volume streams the slice before
            // its first as the gradient's halo.
            v.push(ClockTerm {
                key: "halo_slice",
                what: "leading halo slice",
                clocks: slice,
            });
        }
        let lead = if c.perspective {
            hdl::cube4l::counter_lead::LEAD as i64
        } else {
            0
        };
        if lead > 0 {
            v.push(ClockTerm {
                key: "divider_lead",
                what: "sight-ray divider's lead",
                clocks: lead,
            });
        }
        v.push(ClockTerm {
            key: "fill",
            what: "fill",
            clocks: hdl::cube4l::config::fill_clocks(c) as i64 - lead,
        });
        v
    }

    fn buffer_memory(config: &PipelineConfig, _parts: &[Part]) -> BufferMemory {
        BufferMemory {
            what: "compositing-buffer history and gradient slices",
            bits: config.buffer_bits(),
            minimum_bits: config.minimum_buffer_bits(),
        }
    }

    fn projected_clocks(n: u64, config: &PipelineConfig) -> Option<u64> {
        Some(hdl::cube4l::config::frame_clocks(n, config))
    }

    fn waves(part: &Part, top: &str) -> Vec<Wave> {
        units::waves(part.config.p, top)
    }

    fn manifest_part(part: &Part) -> serde_json::Value {
        let s = &part.sweep;
        let rays = match s.rays {
            Rays::Parallel { dx, dy } => serde_json::json!({"parallel": {"dx": dx, "dy": dy}}),
            Rays::Perspective { eye } => serde_json::json!({"perspective": {"eye": eye}}),
        };
        serde_json::json!({
            "axes": s.perm,
            "dims": s.dims,
            "slices": [s.z0, s.z1],
            "order": format!("{:?}", s.order),
            "rays": rays,
            "register_writes": part.regs.writes().len(),
        })
    }

    fn manifest_parameters(config: &PipelineConfig) -> serde_json::Value {
        let buffer = Self::buffer_memory(config, &[]);
        serde_json::json!({
            "configuration": config.name(),
            "pipelines": config.p,
            "modes": config.mode.modes(),
            "shading": config.shading,
            "gradient_opacity": config.gradient_opacity,
            "rays": if config.perspective { "perspective" } else { "parallel" },
            "largest_volume": config.max_dim,
            "voxel_bits": config.voxel_bits,
            "frac_bits": config.frac_bits,
            "rgba_bits": config.rgba_bits,
            "memory": {
                "kind": if config.external_memory() { "external" } else { "on-chip" },
                "voxels_per_module": config.module_words(),
                "module_address_bits": if config.external_memory() { 32 } else { config.memory_bits() },
            },
            "delay_line_pointer_bits": config.history_bits(),
            "buffer_memory": {
                "bits": buffer.bits,
                "minimum_bits": buffer.minimum_bits,
                "ratio": buffer.ratio(),
            },
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn part() -> Part {
        let s = scene::Scene::from_json(
            r#"{"volume": {"builtin": "sphere", "dims": [12, 12, 10]}, "view": {"projection": "parallel", "rotate_deg": [20, 30, 0]}, "mode": "mip", "image": [8, 8]}"#,
            None,
        )
        .unwrap();
        let cam = s.camera();
        let build = Cube4l::needs(&s, &cam, s.volume.dims).unwrap();
        Cube4l::parts(&s, &cam, s.volume.dims, &build)
            .unwrap()
            .remove(0)
    }

    fn pixel(clock: u64, values: [Option<u64>; 4]) -> Record {
        Record {
            clock,
            group: 0,
            values: values.to_vec(),
        }
    }

    #[test]
    fn stray_and_undefined_pixels_are_reported_not_panicked_on() {
        let p = part();
        let base = Cube4l::decode(&p, &[pixel(3, [Some(1), Some(1), Some(2), Some(5)])]).unwrap();
        assert_eq!(
            (base.pixels[1 + base.width], base.faces[1 + base.width]),
            ([5, 0, 0, 0], Face::XPos)
        );
        let w = base.width as u64;
        for (values, why) in [
            ([Some(0), Some(0), Some(7), Some(0)], "no such face"),
            ([Some(0), Some(0), Some(0), Some(0)], "no such face"),
            (
                [Some(w), Some(0), Some(1), Some(5)],
                "outside the base plane",
            ),
            (
                [Some(u64::MAX), Some(0), Some(1), Some(0)],
                "outside the base plane",
            ),
            ([Some(0), Some(0), Some(1), None], "undefined (X or Z)"),
        ] {
            let e = Cube4l::decode(&p, &[pixel(9, values)]).unwrap_err();
            assert!(e.contains(why) && e.contains("clock 9"), "{e}");
        }
    }
}
