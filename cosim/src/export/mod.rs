//! Verilog export: the pipeline of each sweep of a scene as rust-hdl emits
//! it, made width-clean (`width_clean.rs`), with the units the scene does not
//! need pruned (`prune.rs`), each module's outputs written once per pass
//! (`write_once.rs`), split into one file per stage with lint waivers
//! (`split.rs`), and a manifest of its parameters and of the units left out.

use golden_model::cube4l::cfb::SkewedMemory;
use golden_model::cube4l::plan::{Plan, Rays, Sweep};
use golden_model::cube4l::shader::Shader as GoldenShader;
use hdl::pipeline::{Pipeline, PipelineConfig};
use rust_hdl::prelude::*;
use scene::{Camera, Scene};

mod cube3;
mod prune;
mod split;
mod width_clean;
mod write_once;

pub use cube3::{
    cube3_config, cube3_left_out, cube3_verilog, write_cube3_export, CUBE3_BUFFER_BITS,
    CUBE3_LINE_BITS,
};

pub use prune::{left_out, names, prune, LeftOut};
pub use split::{
    cube3_stage_file, lint_waivers, split_modules, stage_file, write_stage_files, Layout, Module,
    CUBE3, CUBE3_LINT_WAIVERS, CUBE3_STAGE_FILES, CUBE4L, LINT_WAIVERS, STAGE_FILES,
};
pub use width_clean::width_clean;
pub use write_once::{outputs_written_twice, write_once};

/// rust-hdl's Verilog as the kit writes it: width-clean, without `units`,
/// and with each module's outputs written once per pass.
pub fn clean_verilog(emitted: &str, units: &[LeftOut]) -> Result<String, String> {
    Ok(write_once(&prune(&width_clean(emitted), units)?))
}

/// Delay-line pointer bits of every build: enough for a 256² slice at any p
/// (see `PipelineConfig::history_bits`, which refuses larger needs).
pub const H: usize = 16;
/// Address bits of an on-chip memory module: 2^16 voxels per module.
pub const ON_CHIP_BITS: usize = 16;

/// Where the voxels live.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Memory {
    /// p block-RAM modules inside the CFB, each as deep as its share of the
    /// volume (up to 2^16 voxels), loaded through the load port (or
    /// initialised, for simulation).
    OnChip,
    /// An external RAM on each lane's `ext_addr`/`ext_data` port; the CFB's
    /// own modules are 2-word stubs.
    External,
}

impl Memory {
    /// On chip when every module fits 2^16 voxels.
    pub fn for_volume(dims: [usize; 3], p: usize) -> Memory {
        if dims[0].div_ceil(p) * dims[1] * dims[2] <= 1 << ON_CHIP_BITS {
            Memory::OnChip
        } else {
            Memory::External
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Memory::OnChip => "on-chip",
            Memory::External => "external",
        }
    }
}

/// The Verilog of one sweep's pipeline, with the units the scene does not
/// need left out. `preload` initialises on-chip memory modules (simulation
/// only; hardware loads them through the load port).
pub fn pipeline_verilog(
    config: &PipelineConfig,
    golden: &GoldenShader,
    memory: Memory,
    preload: Option<&SkewedMemory>,
) -> Result<String, String> {
    fn emit<const P: usize>(
        config: &PipelineConfig,
        golden: &GoldenShader,
        preload: Option<&SkewedMemory>,
    ) -> Result<String, String> {
        let mut uut = Pipeline::<P, ON_CHIP_BITS, H>::new(config, golden)?;
        if let Some(mem) = preload {
            uut.cfb.preload(&mem.modules);
        }
        uut.connect_all();
        let units = left_out(config, golden);
        clean_verilog(&generate_verilog(&uut), &units)
    }
    let mut config = config.clone();
    config.cfb.external_memory = memory == Memory::External;
    let preload = preload.filter(|_| memory == Memory::OnChip);
    match config.p {
        1 => emit::<1>(&config, golden, preload),
        2 => emit::<2>(&config, golden, preload),
        4 => emit::<4>(&config, golden, preload),
        8 => emit::<8>(&config, golden, preload),
        p => Err(format!(
            "the RTL is built for 1, 2, 4 or 8 pipelines, not {p}"
        )),
    }
}

/// The exported design of one sweep.
#[derive(Debug, Clone)]
pub struct SweepDesign {
    pub sweep: Sweep,
    pub config: PipelineConfig,
    pub left_out: Vec<LeftOut>,
    pub verilog: String,
}

/// Every sweep's pipeline for `scene` (volume dimensions `dims`, after any
/// crop) and the memory it was built with.
pub fn export(
    scene: &Scene,
    camera: &Camera,
    dims: [usize; 3],
) -> Result<(Vec<SweepDesign>, Memory), String> {
    let plan = Plan::new(scene, camera).map_err(|e| e.to_string())?;
    let p = scene.hardware.pipelines;
    let memory = Memory::for_volume(dims, p);
    let mut designs = Vec::new();
    for sweep in &plan.sweeps {
        let golden = GoldenShader::new(scene, camera, sweep);
        let config = PipelineConfig::new(sweep, dims, p, &golden)?;
        let verilog = pipeline_verilog(&config, &golden, memory, None)?;
        designs.push(SweepDesign {
            sweep: sweep.clone(),
            left_out: left_out(&config, &golden),
            config,
            verilog,
        });
    }
    Ok((designs, memory))
}

/// The pipelines' buffer memory (compositing-buffer history and gradient
/// slices, not the voxel memory) against the least the scene needs, for the
/// largest sweep's design (sweeps run one after another on one pipeline).
pub fn buffer_memory(designs: &[SweepDesign]) -> serde_json::Value {
    let c = designs
        .iter()
        .map(|d| &d.config)
        .max_by_key(|c| c.buffer_bits())
        .expect("a design per sweep");
    let (bits, min) = (c.buffer_bits(), c.minimum_buffer_bits());
    serde_json::json!({
        "bits": bits,
        "minimum_bits": min,
        "ratio": (bits as f64 / min as f64 * 1000.0).round() / 1000.0,
    })
}

/// Whether `out` may be replaced by an export: it does not exist, or it is
/// a directory holding only what an export writes (stage files,
/// `lint.vlt`, `manifest.json`, `sweep<i>/` or `base_plane<i>/` of the
/// same). Anything else is a user's, and is never deleted.
fn replaceable(out: &std::path::Path) -> Result<(), String> {
    fn check(dir: &std::path::Path, top: bool) -> Result<(), String> {
        let entries = std::fs::read_dir(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
        for entry in entries {
            let entry = entry.map_err(|e| format!("{}: {e}", dir.display()))?;
            let name = entry.file_name().to_string_lossy().to_string();
            let kind = entry
                .file_type()
                .map_err(|e| format!("{}: {e}", dir.display()))?;
            let ours = if kind.is_dir() {
                top && ["sweep", "base_plane"].iter().any(|p| {
                    name.strip_prefix(p)
                        .is_some_and(|i| !i.is_empty() && i.bytes().all(|b| b.is_ascii_digit()))
                }) && check(&entry.path(), false).is_ok()
            } else {
                kind.is_file()
                    && (STAGE_FILES.contains(&name.as_str())
                        || CUBE3_STAGE_FILES.contains(&name.as_str())
                        || name == "lint.vlt"
                        || (top && name == "manifest.json"))
            };
            if !ours {
                return Err(format!(
                    "{} holds {name}, which an export does not write; choose a new or empty directory",
                    dir.display()
                ));
            }
        }
        Ok(())
    }
    match std::fs::symlink_metadata(out) {
        Err(_) => Ok(()),
        Ok(m) if m.is_dir() => check(out, true),
        Ok(_) => Err(format!(
            "{} exists and is not a directory; an export writes a directory",
            out.display()
        )),
    }
}

/// Export `scene` (named `name` in the manifest) into `out`: the stage files
/// of each sweep's pipeline (in `out` for one sweep, in `out/sweep<i>` for
/// several), `lint.vlt`, and `manifest.json`. The directory is built beside
/// `out` and renamed over it, so it is written whole or not at all. Returns
/// the manifest.
pub fn write_export(
    name: &str,
    scene: &Scene,
    camera: &Camera,
    dims: [usize; 3],
    out: &std::path::Path,
) -> Result<serde_json::Value, String> {
    replaceable(out)?;
    let (designs, memory) = export(scene, camera, dims)?;
    write_dir(out, |tmp| {
        let io = |e: std::io::Error| format!("{}: {e}", out.display());
        let mut sweeps = Vec::new();
        for (i, d) in designs.iter().enumerate() {
            let sub = if designs.len() == 1 {
                ".".to_string()
            } else {
                format!("sweep{i}")
            };
            let dir = tmp.join(&sub);
            std::fs::create_dir_all(&dir).map_err(io)?;
            let files = write_stage_files(&dir, &d.verilog, &d.left_out, &CUBE4L).map_err(io)?;
            let s = &d.sweep;
            let rays = match s.rays {
                Rays::Parallel { dx, dy } => serde_json::json!({"parallel": {"dx": dx, "dy": dy}}),
                Rays::Perspective { eye } => serde_json::json!({"perspective": {"eye": eye}}),
            };
            sweeps.push(serde_json::json!({
                "dir": sub,
                "files": files,
                "axes": s.perm,
                "dims": s.dims,
                "slices": [s.z0, s.z1],
                "order": format!("{:?}", s.order),
                "rays": rays,
                "history_bits_needed": d.config.history_bits(),
            }));
        }
        let hw = scene.hardware;
        let p = hw.pipelines;
        let config = &designs[0].config;
        let manifest = serde_json::json!({
            "scene": name,
            "generator": format!("cube {} with rust-hdl 0.46", env!("CARGO_PKG_VERSION")),
            "top": "top",
            "parameters": {
                "pipelines": p,
                "volume_dims": dims,
                "voxel_bits": hw.voxel_bits,
                "frac_bits": hw.frac_bits,
                "rgba_bits": hw.rgba_bits,
                "mode": format!("{:?}", scene.mode),
                "memory": {
                    "kind": memory.name(),
                    "voxels_per_module": dims[0].div_ceil(p) * dims[1] * dims[2],
                    "module_address_bits": if memory == Memory::OnChip { config.cfb.memory_bits } else { 32 },
                },
                "buffer_memory": buffer_memory(&designs),
            },
            "units_left_out": names(&designs[0].left_out),
            "sweeps": sweeps,
            "lint": "verilator --lint-only -Wall lint.vlt <files>",
        });
        Ok(manifest)
    })
}

/// Build the export directory `out` through `fill` (given a fresh directory
/// beside `out`, it writes the files and returns the manifest, which goes to
/// `manifest.json`), then rename it over `out`: written whole or not at
/// all. `out` must be replaceable (see [`replaceable`]).
pub(crate) fn write_dir(
    out: &std::path::Path,
    fill: impl FnOnce(&std::path::Path) -> Result<serde_json::Value, String>,
) -> Result<serde_json::Value, String> {
    replaceable(out)?;
    let parent = match out.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => std::path::PathBuf::from("."),
    };
    let leaf = out
        .file_name()
        .ok_or_else(|| format!("{} is not a directory path", out.display()))?
        .to_string_lossy()
        .to_string();
    let io = |e: std::io::Error| format!("{}: {e}", out.display());
    std::fs::create_dir_all(&parent).map_err(io)?;
    let tmp = parent.join(format!(".{leaf}.tmp{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&tmp);
    let result = (|| {
        std::fs::create_dir_all(&tmp).map_err(io)?;
        let manifest = fill(&tmp)?;
        let text = serde_json::to_string_pretty(&manifest).map_err(|e| e.to_string())? + "\n";
        std::fs::write(tmp.join("manifest.json"), text).map_err(io)?;
        let old = parent.join(format!(".{leaf}.old{}", std::process::id()));
        if out.exists() {
            std::fs::rename(out, &old).map_err(io)?;
        }
        std::fs::rename(&tmp, out).map_err(io)?;
        let _ = std::fs::remove_dir_all(&old);
        Ok(manifest)
    })();
    if result.is_err() {
        let _ = std::fs::remove_dir_all(&tmp);
    }
    result
}
