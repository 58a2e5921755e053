//! Verilog export: the pipeline of each sweep of a scene as rust-hdl emits
//! it, split into one file per module, with a manifest of its parameters and
//! of the units the scene leaves out.

use golden_model::cube4l::cfb::SkewedMemory;
use golden_model::cube4l::plan::{Plan, Rays, Sweep};
use golden_model::cube4l::shader::Shader as GoldenShader;
use hdl::pipeline::{Pipeline, PipelineConfig};
use rust_hdl::prelude::*;
use scene::{Camera, Scene};

/// Ring-buffer address bits of every build: enough for a 256² slice at
/// p >= 2 (see `PipelineConfig::history_bits`, which refuses larger needs).
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
        prune(&width_clean(&generate_verilog(&uut)), &units)
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

/// A unit that a scene's hardware leaves out.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LeftOut {
    pub name: &'static str,
    /// Its instance names, under their parents; the emitted Verilog has no
    /// such instance (see [`prune`]). Empty for units that stay in the
    /// Verilog, disabled by constants, for synthesis to remove.
    pub instances: &'static [&'static str],
}

/// The units a sweep's pipeline leaves out.
pub fn left_out(config: &PipelineConfig, golden: &GoldenShader) -> Vec<LeftOut> {
    let mut v = Vec::new();
    if !config.gradient {
        v.push(LeftOut {
            name: "abc_gradient",
            instances: &["abc"],
        });
    }
    if golden.reflectance.is_none() {
        v.push(LeftOut {
            name: "reflectance_map",
            instances: &["reflectance"],
        });
    }
    if golden.colour.is_none() && golden.opacity.is_none() {
        v.push(LeftOut {
            name: "colour_and_opacity_lut",
            instances: &["lut"],
        });
    }
    if golden.opacity.as_ref().and_then(|o| o.gm_shift).is_none() {
        v.push(LeftOut {
            name: "gradient_opacity_lut_and_magnitude",
            instances: &["alpha_gm", "sqrt"],
        });
    }
    if !golden.mode.uses_colour() {
        v.push(LeftOut {
            name: "shading_and_weighting_multipliers",
            instances: &["lit_r", "lit_g", "lit_b", "mul_r", "mul_g", "mul_b"],
        });
    }
    if config.cfb.eye.is_none() {
        v.push(LeftOut {
            name: "sight_ray_divider",
            instances: &["div_x", "div_y"],
        });
        v.push(LeftOut {
            name: "3x3_taps_outside_2x2 (2-word rings)",
            instances: &[],
        });
    }
    v
}

/// The names of `units`, for reports.
pub fn names(units: &[LeftOut]) -> Vec<&'static str> {
    units.iter().map(|u| u.name).collect()
}

/// Ports of a module, from its declarations: (name, is_output).
fn module_ports(text: &str) -> Vec<(String, bool)> {
    text.lines()
        .map(str::trim)
        .filter_map(|l| {
            let output = l.starts_with("output ");
            if !output && !l.starts_with("input ") {
                return None;
            }
            Some((
                l.trim_end_matches(';')
                    .split_whitespace()
                    .last()?
                    .to_string(),
                output,
            ))
        })
        .collect()
}

/// Remove the instances named in `units` from emitted Verilog: their
/// modules and every module below them, and their instantiation in the
/// parent, whose wires for their outputs become constant zero. The rust-hdl
/// description drives zero on those outputs too when the unit is disabled,
/// so simulation and the pruned Verilog agree signal for signal. The inputs
/// the parent computes for the removed instance stay, unread.
pub fn prune(verilog: &str, units: &[LeftOut]) -> Result<String, String> {
    let gone: Vec<&str> = units
        .iter()
        .flat_map(|u| u.instances.iter().copied())
        .collect();
    let mut modules = split_modules(verilog);
    let pruned: Vec<(String, Vec<(String, bool)>)> = modules
        .iter()
        .filter(|m| {
            m.name
                .rsplit_once('$')
                .is_some_and(|(_, leaf)| gone.contains(&leaf))
        })
        .map(|m| (m.name.clone(), module_ports(&m.text)))
        .collect();
    modules.retain(|m| {
        !pruned
            .iter()
            .any(|(p, _)| m.name == *p || m.name.starts_with(&format!("{p}$")))
    });
    for (name, ports) in &pruned {
        let (parent, instance) = name.rsplit_once('$').expect("a sub-module");
        let m = modules
            .iter_mut()
            .find(|m| m.name == parent)
            .ok_or_else(|| format!("prune: no parent module {parent}"))?;
        let head = format!("{name} {instance}(");
        let mut out = String::with_capacity(m.text.len());
        let mut skipping = false;
        let mut found = false;
        for line in m.text.lines() {
            let t = line.trim();
            if t == head {
                skipping = true;
                found = true;
                continue;
            }
            if skipping {
                skipping = t != ");";
                continue;
            }
            let output_wire = ports.iter().any(|(p, out)| {
                *out && t.starts_with("wire ") && t.ends_with(&format!(" {instance}${p};"))
            });
            if output_wire {
                out.push_str(line.trim_end_matches(';'));
                out.push_str(" = 'h0;\n");
            } else {
                out.push_str(line);
                out.push('\n');
            }
        }
        if !found {
            return Err(format!("prune: no instance {instance} in {parent}"));
        }
        m.text = out;
    }
    Ok(modules
        .into_iter()
        .map(|m| m.text)
        .collect::<Vec<_>>()
        .join("\n"))
}

/// Verilator waivers for a design with `units` pruned: the inputs its
/// parents still compute for the removed instances are unread.
pub fn lint_waivers(units: &[LeftOut]) -> String {
    let mut s = LINT_WAIVERS.to_string();
    let instances: Vec<&str> = units
        .iter()
        .flat_map(|u| u.instances.iter().copied())
        .collect();
    if !instances.is_empty() {
        s.push_str("// Units this scene leaves out are gone, but their parents still compute\n// the inputs they would have read.\n");
        for i in instances {
            s.push_str(&format!(
                "lint_off -rule UNUSEDSIGNAL -file \"*\" -match \"*Signal is not used: '{i}$*\"\n"
            ));
        }
    }
    s
}

/// One Verilog module of an emitted design.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Module {
    pub name: String,
    pub text: String,
}

/// Split emitted Verilog into its modules, in order (the top first).
pub fn split_modules(verilog: &str) -> Vec<Module> {
    let mut out = Vec::new();
    let mut current: Option<Module> = None;
    for line in verilog.lines() {
        if current.is_none() {
            if let Some(rest) = line.strip_prefix("module ") {
                let name = rest
                    .split(|c: char| c == '(' || c.is_whitespace())
                    .next()
                    .unwrap_or_default()
                    .to_string();
                current = Some(Module {
                    name,
                    text: String::new(),
                });
            } else {
                continue;
            }
        }
        let m = current.as_mut().expect("inside a module");
        m.text.push_str(line);
        m.text.push('\n');
        if line.starts_with("endmodule") {
            out.extend(current.take());
        }
    }
    out
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

/// Rewrite two of rust-hdl's emission habits that make every expression
/// width-mismatched for `verilator -Wall`, keeping rust-hdl's semantics:
/// - `bit_cast::<N, M>(e)` is emitted as the mask `((e) & N'h…)`, which
///   leaves the expression at the wider width; it becomes the
///   SystemVerilog size cast `N'(e)`, which truncates or zero-extends to N
///   bits exactly as `bit_cast` does in rust-hdl's simulation;
/// - every Rust integer literal is emitted as `32'h…`; it becomes the
///   unsized `'h…`, which is the same 32-bit unsigned value but which lint
///   lets take the width of its context.
///
/// Both forms are checked against the golden model by co-simulation.
pub fn width_clean(verilog: &str) -> String {
    unsize_literals(&size_casts(verilog))
}

fn size_casts(v: &str) -> String {
    let b = v.as_bytes();
    let mut out = String::with_capacity(v.len());
    // Positions of open parentheses not yet closed, in `out`.
    let mut open: Vec<usize> = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let c = b[i];
        if c == b'(' {
            open.push(out.len());
            out.push('(');
            i += 1;
            continue;
        }
        if c == b')' {
            let inner_open = open.pop();
            out.push(')');
            i += 1;
            // After `(e)`: ` & N'h<mask>)` closing an outer `(` right before it?
            if let (Some(start), Some((bits, len))) = (inner_open, cast_mask(&v[i..])) {
                if start > 0
                    && out.as_bytes()[start - 1] == b'('
                    && open.last() == Some(&(start - 1))
                {
                    open.pop();
                    let e = out[start + 1..out.len() - 1].to_string();
                    out.truncate(start - 1);
                    out.push_str(&format!("{bits}'({e})"));
                    i += len;
                }
            }
            continue;
        }
        let ch = v[i..].chars().next().expect("inside the text");
        out.push(ch);
        i += ch.len_utf8();
    }
    out
}

/// ` & N'h<2^N - 1>)` at the start of `s`: (N, its length).
fn cast_mask(s: &str) -> Option<(usize, usize)> {
    let rest = s.strip_prefix(" & ")?;
    let tick = rest.find('\'')?;
    let bits: usize = rest[..tick].parse().ok()?;
    let digits = rest[tick + 1..].strip_prefix('h')?;
    let end = digits.find(')')?;
    let mask = &digits[..end];
    let want = format!("{:x}", ones(bits));
    (bits > 0 && mask == want).then_some((bits, 3 + tick + 2 + end + 1))
}

/// 2^bits - 1 (bits up to 128).
fn ones(bits: usize) -> u128 {
    if bits >= 128 {
        u128::MAX
    } else {
        (1u128 << bits) - 1
    }
}

fn unsize_literals(v: &str) -> String {
    let mut out = String::with_capacity(v.len());
    let mut rest = v;
    while let Some(k) = rest.find("32'h") {
        let before = rest[..k].chars().last();
        out.push_str(&rest[..k]);
        if before.is_some_and(|c| c.is_ascii_alphanumeric() || c == '_' || c == '$') {
            out.push_str("32'h");
        } else {
            out.push_str("'h");
        }
        rest = &rest[k + 4..];
    }
    out.push_str(rest);
    out
}

/// The file (one per stage) that holds module `name`. rust-hdl emits one
/// module per instance, named by its path (`top$lanes$2$shader$lut`), so
/// each stage's file holds that stage's modules of every pipeline.
pub fn stage_file(name: &str) -> &'static str {
    let parts: Vec<&str> = name.split('$').collect();
    match parts.as_slice() {
        ["top"] => "top.v",
        ["top", "cfb", "lanes", _, div, ..] if div.starts_with("div_") => "divider.v",
        ["top", "cfb", ..] => "cfb.v",
        ["top", "lanes", _, "abc", ..] => "abc_gradient.v",
        ["top", "lanes", _, "shader", ..] => "shader.v",
        ["top", "lanes", _, "bilinear", ..] => "bilinear.v",
        ["top", "lanes", _, "compositor", ..] => "compositor.v",
        _ => "pipe_lane.v",
    }
}

/// The stage files in the order a tool should read them (top first).
pub const STAGE_FILES: [&str; 8] = [
    "top.v",
    "cfb.v",
    "divider.v",
    "abc_gradient.v",
    "shader.v",
    "pipe_lane.v",
    "bilinear.v",
    "compositor.v",
];

/// Verilator configuration with the lint waivers every emitted design
/// needs; each is narrow (one rule, matched on the signal or file) and
/// explained. (Verilator's configuration lexer stumbles on parentheses and
/// paired apostrophes inside comments, so the comments avoid them.)
pub const LINT_WAIVERS: &str = r#"`verilator_config
// rust-hdl names every module by its instance path, as in top$cfb$lanes$0, and
// the kit groups one stage's modules per file, so only top.v can carry its
// module's name.
lint_off -rule DECLFILENAME -file "*cfb.v"
lint_off -rule DECLFILENAME -file "*divider.v"
lint_off -rule DECLFILENAME -file "*abc_gradient.v"
lint_off -rule DECLFILENAME -file "*shader.v"
lint_off -rule DECLFILENAME -file "*pipe_lane.v"
lint_off -rule DECLFILENAME -file "*bilinear.v"
lint_off -rule DECLFILENAME -file "*compositor.v"
// Each CFB lane's dataset z and memory address are observability outputs:
// the CFB testbench compares them with the golden model's stream, and the
// waveforms show them; the pipeline itself needs neither.
lint_off -rule UNUSEDSIGNAL -file "*cfb.v" -match "*Signal is not used: 'lanes$*$z'*"
lint_off -rule UNUSEDSIGNAL -file "*cfb.v" -match "*Signal is not used: 'lanes$*$address'*"
// Ring buffers and memory modules are as deep as the scene needs: they take
// the pipeline's 16-bit addresses and use only the low address bits,
lint_off -rule UNUSEDSIGNAL -file "*" -match "*Bits of signal are not used: 'read_address'*"
lint_off -rule UNUSEDSIGNAL -file "*" -match "*Bits of signal are not used: 'write_address'*"
// and store only the bits the scene can set: the voxel bits of a voxel, and
// four channels of RGBA bits in the 16-bit slots of a composited word.
lint_off -rule UNUSEDSIGNAL -file "*" -match "*Bits of signal are not used: 'write_data'*"
// The bilinear unit's four channels share one 32-bit datapath, which X-ray
// needs for its sum in channel 0; channels 1-3 carry 16-bit values.
lint_off -rule UNUSEDSIGNAL -file "*pipe_lane.v" -match "*bilinear$out$*"
// Perspective only. rust-hdl emits the logic of a module as one always block,
// so Verilator sees the block, the divider it feeds and the block again as a
// loop, though the divider inputs come from registers and the rust-hdl
// logic-loop check passes. This only costs Verilator some speed.
lint_off -rule UNOPTFLAT -file "*cfb.v" -match "*div_*"
"#;

/// Write one design (emitted Verilog, with `units` left out) into `dir`:
/// the stage files and the lint waivers. Returns the file names written.
pub fn write_stage_files(
    dir: &std::path::Path,
    verilog: &str,
    units: &[LeftOut],
) -> std::io::Result<Vec<String>> {
    let mut texts: std::collections::BTreeMap<&str, String> = Default::default();
    for m in split_modules(verilog) {
        texts
            .entry(stage_file(&m.name))
            .or_default()
            .push_str(&m.text);
    }
    let mut names = Vec::new();
    for f in STAGE_FILES {
        if let Some(t) = texts.get(f) {
            std::fs::write(dir.join(f), t)?;
            names.push(f.to_string());
        }
    }
    std::fs::write(dir.join("lint.vlt"), lint_waivers(units))?;
    Ok(names)
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
    let (designs, memory) = export(scene, camera, dims)?;
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
        let mut sweeps = Vec::new();
        for (i, d) in designs.iter().enumerate() {
            let sub = if designs.len() == 1 {
                ".".to_string()
            } else {
                format!("sweep{i}")
            };
            let dir = tmp.join(&sub);
            std::fs::create_dir_all(&dir).map_err(io)?;
            let files = write_stage_files(&dir, &d.verilog, &d.left_out).map_err(io)?;
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
                "tap_ring_address_bits": config.tap_bits(),
                "gradient_ring_address_bits": if config.gradient {
                    hdl::abc_gradient::AbcGradient::<H>::ring_bits(config.slice_beats, config.beam_beats)
                } else {
                    0
                },
            },
            "units_left_out": names(&designs[0].left_out),
            "sweeps": sweeps,
            "lint": "verilator --lint-only -Wall lint.vlt <files>",
        });
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn casts_become_size_casts_and_literals_unsized() {
        let v = "  y = ((a + ((b) & 16'hffff)) & 32'hffffffff) + 32'h3 - 132'h1 + x32'h2;\n  z = ((c) & 16'hfff);\n";
        assert_eq!(
            width_clean(v),
            "  y = 32'(a + 16'(b)) + 'h3 - 132'h1 + x32'h2;\n  z = ((c) & 16'hfff);\n",
            "a mask that is not 2^N - 1 stays a mask"
        );
    }

    const TOY: &str = "\n\nmodule top(clock,q);\n    input wire  clock;\n    output reg  [3:0] q;\n    reg  u$a;\n    wire  [3:0] u$y;\n    top$u u(\n        .a(u$a),\n        .y(u$y)\n    );\n    always @(*) begin\n        u$a = clock;\n        q = u$y;\n    end\nendmodule // top\n\n\nmodule top$u(a,y);\n    input wire  a;\n    output reg  [3:0] y;\n    top$u$v v(\n    );\nendmodule // top$u\n\n\nmodule top$u$v();\nendmodule // top$u$v\n";

    #[test]
    fn split_keeps_every_module_in_order() {
        let names: Vec<String> = split_modules(TOY).into_iter().map(|m| m.name).collect();
        assert_eq!(names, ["top", "top$u", "top$u$v"]);
    }

    #[test]
    fn prune_removes_the_unit_and_zeroes_its_outputs() {
        let unit = LeftOut {
            name: "u",
            instances: &["u"],
        };
        let v = prune(TOY, &[unit]).unwrap();
        assert_eq!(split_modules(&v).len(), 1, "{v}");
        assert!(v.contains("wire  [3:0] u$y = 'h0;"), "{v}");
        assert!(!v.contains("top$u u("), "{v}");
        assert!(
            v.contains("u$a = clock;"),
            "the parent's input wiring stays"
        );
        let missing = LeftOut {
            name: "w",
            instances: &["w"],
        };
        assert_eq!(
            prune(TOY, &[missing]).unwrap(),
            split_modules(TOY)
                .into_iter()
                .map(|m| m.text)
                .collect::<Vec<_>>()
                .join("\n")
        );
    }
}
