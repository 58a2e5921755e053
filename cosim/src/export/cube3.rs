//! Verilog export of a Cube-3 system (`hdl::cube3_system`): the emitted
//! design made width-clean, the units the scene does not need pruned, one
//! file per stage ([`CUBE3`]) with lint waivers, and a manifest.

use super::{clean_verilog, names, write_dir, write_stage_files, LeftOut, CUBE3, ON_CHIP_BITS};
use golden_model::cube3::plan::Plan;
use golden_model::cube3::shade::Shader;
use hdl::cube3_system::{Cube3System, Cube3SystemConfig};
use rust_hdl::prelude::*;
use scene::{Camera, Mode, Scene};

/// 2-DSB and delay-line address bits of every Cube-3 build (the ABC
/// units' sample-plane lines are a scanline period long: 13 313 clocks for
/// the engine at p = 4).
pub const CUBE3_BUFFER_BITS: usize = 16;
pub const CUBE3_LINE_BITS: usize = 16;

/// The units a Cube-3 system leaves out for its scene.
pub fn cube3_left_out(c: &Cube3SystemConfig) -> Vec<LeftOut> {
    let p = &c.pipeline;
    let mut v = vec![];
    if !p.perspective {
        v.push(LeftOut {
            name: "de-fanning (a parallel view's beams shift as a whole: no group ROMs, one template entry a plane)",
            instances: &["groups", "group_x$*"],
        });
    }
    if p.abc.is_none() {
        v.push(LeftOut {
            name: "abc_gradient_units (no gradient: MIP, MinIP, X-ray, or neither shading nor gradient opacity)",
            instances: &["abc"],
        });
    }
    match &p.shading {
        None => v.push(LeftOut {
            name: "shaders (MIP, MinIP and X-ray take the leaf stage)",
            instances: &["shade$*"],
        }),
        Some(s) => {
            v.push(LeftOut {
                name: "leaf_stage (composite and first-opaque take the shaders; disabled by constants, for synthesis to remove)",
                instances: &[],
            });
            if s.reflectance.is_none() {
                v.push(LeftOut {
                    name: "reflectance_map",
                    instances: &["reflectance"],
                });
            }
            if s.opacity.as_ref().and_then(|o| o.gm_shift).is_none() {
                v.push(LeftOut {
                    name: "gradient_opacity_lut_and_magnitude",
                    instances: &["alpha_gm", "sqrt"],
                });
            }
        }
    }
    if !matches!(p.mode, Mode::Composite | Mode::FirstOpaque) {
        v.push(LeftOut {
            name: "rpc_over_operator_multipliers",
            instances: &["ch_r", "ch_g", "ch_b", "ch_a"],
        });
    }
    if p.opacity.is_none() {
        v.push(LeftOut {
            name: "opacity_table (X-ray only)",
            instances: &["opacity"],
        });
    }
    if p.on_grid {
        v.push(LeftOut {
            name: "trilin_arithmetic (samples on the grid: zero weights, folded by synthesis)",
            instances: &[],
        });
    }
    v
}

/// The Verilog of a Cube-3 system with its unneeded units pruned;
/// `preload` initialises on-chip memory (simulation only).
pub fn cube3_verilog(
    c: &Cube3SystemConfig,
    preload: Option<&[Vec<u16>]>,
) -> Result<String, String> {
    const A: usize = ON_CHIP_BITS;
    const B: usize = CUBE3_BUFFER_BITS;
    const H: usize = CUBE3_LINE_BITS;
    fn emit<const P: usize>(
        c: &Cube3SystemConfig,
        preload: Option<&[Vec<u16>]>,
    ) -> Result<String, String> {
        let mut uut = Cube3System::<P, A, B, H>::new(c)?;
        if let Some(m) = preload.filter(|_| !c.fetch.external) {
            uut.preload(m);
        }
        uut.connect_all();
        clean_verilog(&generate_verilog(&uut), &cube3_left_out(c))
    }
    match c.pipeline.p {
        1 => emit::<1>(c, preload),
        2 => emit::<2>(c, preload),
        4 => emit::<4>(c, preload),
        8 => emit::<8>(c, preload),
        p => Err(format!("hardware.pipelines {p} unsupported (1, 2, 4 or 8)")),
    }
}

/// The Cube-3 system of one of the scene's base planes,
/// the whole base plane, its memory external beyond 2^16 voxels a module.
pub fn cube3_config(
    scene: &Scene,
    camera: &Camera,
    view: &golden_model::cube3::plan::View,
) -> Result<Cube3SystemConfig, String> {
    let shader = Shader::new(scene, camera, view);
    let height = (view.v[1] - view.v[0] + 1) as usize;
    let n = golden_model::cube3::neighbourhood(scene, None).map_err(|e| e.to_string())?;
    let mut c = Cube3SystemConfig::new(
        view,
        &shader,
        n,
        scene.hardware.pipelines,
        view.v[0],
        height,
    )?;
    c.fetch.external = c.fetch.module_words() > 1 << ON_CHIP_BITS;
    Ok(c)
}

/// Export the scene's Cube-3 systems into `out` (written whole or not at
/// all): the stage files and `lint.vlt` of each base plane (in
/// `base_plane{i}` when a perspective view needs several) and
/// `manifest.json`, whose `parameters` are the first base plane's but for
/// `frame_clocks`, the frame's.
pub fn write_cube3_export(
    name: &str,
    scene: &Scene,
    camera: &Camera,
    dims: [usize; 3],
    out: &std::path::Path,
) -> Result<serde_json::Value, String> {
    let plan = Plan::new(scene, camera).map_err(|e| e.to_string())?;
    let configs: Vec<Cube3SystemConfig> = plan
        .views
        .iter()
        .map(|v| cube3_config(scene, camera, v))
        .collect::<Result<_, _>>()?;
    let verilog: Vec<String> = configs
        .iter()
        .map(|c| cube3_verilog(c, None))
        .collect::<Result<_, _>>()?;
    let c = &configs[0];
    let units = cube3_left_out(c);
    write_dir(out, |tmp| {
        let io = |e: std::io::Error| format!("{}: {e}", out.display());
        let mut bases = Vec::new();
        for (i, (c, v)) in configs.iter().zip(&verilog).enumerate() {
            // One system per base plane: the templates and the memory's
            // traversal order are the view's.
            let sub = if configs.len() == 1 {
                ".".to_string()
            } else {
                format!("base_plane{i}")
            };
            let dir = tmp.join(&sub);
            std::fs::create_dir_all(&dir).map_err(io)?;
            let files = write_stage_files(&dir, v, &cube3_left_out(c), &CUBE3).map_err(io)?;
            let view = &plan.views[i];
            let axis = ["u", "v", "w"][view.perm[2]];
            bases.push(serde_json::json!({
                "dir": sub,
                "files": files,
                "axis": axis,
                "towards_positive": view.positive,
                "projection": if c.pipeline.perspective { "perspective" } else { "parallel" },
                "traversal_dims": c.fetch.dims,
                "offset": c.pipeline.offset,
                "rays": c.fetch.rays,
                "scanlines": c.fetch.scanlines,
                "period_clocks": c.fetch.period(),
                "clocks": c.clocks(),
            }));
        }
        let (f, p) = (&c.fetch, &c.pipeline);
        let hw = scene.hardware;
        Ok(serde_json::json!({
            "scene": name,
            "architecture": "cube3",
            "generator": format!("cube {} with rust-hdl 0.46", env!("CARGO_PKG_VERSION")),
            "top": "top",
            "parameters": {
                "pipelines": p.p,
                "volume_dims": dims,
                "traversal_dims": f.dims,
                "voxel_bits": hw.voxel_bits,
                "frac_bits": hw.frac_bits,
                "sample_bits": p.voxel_bits + p.sample_frac,
                "rgba_bits": hw.rgba_bits,
                "mode": format!("{:?}", scene.mode),
                "offset": p.offset,
                "rays": f.rays,
                "scanlines": f.scanlines,
                "segments_per_ray": f.segments,
                "period_clocks": f.period(),
                "frame_clocks": configs.iter().map(|c| c.clocks()).sum::<usize>(),
                "memory": {
                    "kind": if f.external { "external" } else { "on-chip" },
                    "voxels_per_module": f.module_words(),
                    "module_address_bits": if f.external { 32 } else { ON_CHIP_BITS },
                },
                "buffers": {
                    "two_d_skewed_buffers": 3,
                    "words_per_buffer_module": f.rays * f.segments,
                },
            },
            "units_left_out": names(&units),
            "base_planes": bases,
            "lint": "verilator --lint-only -Wall lint.vlt <files>",
        }))
    })
}
