//! One file per stage: the emitted design split into its modules, grouped
//! by the stage each belongs to, with the Verilator lint waivers.

use super::prune::LeftOut;

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

/// The file (one per stage) that holds module `name`. rust-hdl emits one
/// module per instance, named by its path (`top$lanes$2$shader$lut`), so
/// each stage's file holds that stage's modules of every pipeline.
pub fn stage_file(name: &str) -> &'static str {
    let parts: Vec<&str> = name.split('$').collect();
    match parts.as_slice() {
        ["top"] => "top.v",
        ["top", "cfb" | "late", "lanes", _, div, ..] if div.starts_with("div_") => "divider.v",
        ["top", "cfb" | "late", ..] => "cfb.v",
        ["top", "lanes", _, "feed", "abc", ..] => "abc_gradient.v",
        ["top", "lanes", _, "shader", ..] => "shader.v",
        ["top", "lanes", _, "taps", ..] => "tap_network.v",
        ["top", "lanes", _, "bilinear", ..] => "bilinear.v",
        ["top", "lanes", _, "compositor", ..] => "compositor.v",
        _ => "pipe_lane.v",
    }
}

/// The stage files in the order a tool should read them (top first).
pub const STAGE_FILES: [&str; 9] = [
    "top.v",
    "cfb.v",
    "divider.v",
    "abc_gradient.v",
    "shader.v",
    "pipe_lane.v",
    "tap_network.v",
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
lint_off -rule DECLFILENAME -file "*tap_network.v"
lint_off -rule DECLFILENAME -file "*bilinear.v"
lint_off -rule DECLFILENAME -file "*compositor.v"
// Each CFB lane's dataset z and memory address are observability outputs:
// the CFB testbench compares them with the golden model's stream, and the
// waveforms show them; the pipeline itself needs neither.
lint_off -rule UNUSEDSIGNAL -file "*cfb.v" -match "*Signal is not used: 'lanes$*$z'*"
lint_off -rule UNUSEDSIGNAL -file "*cfb.v" -match "*Signal is not used: 'lanes$*$address'*"
// The late CFB, with a gradient unit, recomputes the control only: its voxel,
// memory port and sweep status are unread.
lint_off -rule UNUSEDSIGNAL -file "*top.v" -match "*Signal is not used: 'late$value$*'*"
lint_off -rule UNUSEDSIGNAL -file "*top.v" -match "*Signal is not used: 'late$ext_addr$*'*"
lint_off -rule UNUSEDSIGNAL -file "*top.v" -match "*Signal is not used: 'late$busy'*"
lint_off -rule UNUSEDSIGNAL -file "*top.v" -match "*Signal is not used: 'late$n_*'*"
lint_off -rule UNUSEDSIGNAL -file "*top.v" -match "*Signal is not used: 'late$bs'*"
// Delay lines and memory modules are as deep as the scene needs: they take
// the pipeline's 16-bit pointers and addresses and use only the low bits,
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
// The shader's r is as wide as Cube-3's RPC leaves (32 bits); a Cube-4L lane
// takes its low 16.
lint_off -rule UNUSEDSIGNAL -file "*pipe_lane.v" -match "*Bits of signal are not used: 'shader$r'*"
"#;

/// How an architecture's emitted design is laid out in files: the stage
/// files in reading order, the file of each module, and the lint waivers
/// every design of it needs.
#[derive(Debug, Clone, Copy)]
pub struct Layout {
    pub files: &'static [&'static str],
    pub stage_file: fn(&str) -> &'static str,
    pub waivers: &'static str,
}

/// Cube-4L's pipelines.
pub const CUBE4L: Layout = Layout {
    files: &STAGE_FILES,
    stage_file,
    waivers: LINT_WAIVERS,
};

/// The file (one per stage) of a Cube-3 system's module.
pub fn cube3_stage_file(name: &str) -> &'static str {
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

/// The Cube-3 stage files, top first.
pub const CUBE3_STAGE_FILES: [&str; 9] = [
    "top.v",
    "beam_fetch.v",
    "ray_control.v",
    "trilin_lanes.v",
    "trilin.v",
    "abc_unit.v",
    "shader.v",
    "cube3.v",
    "rpc.v",
];

/// The Cube-3 system's waivers, each narrow and explained as Cube-4L's.
pub const CUBE3_LINT_WAIVERS: &str = r#"`verilator_config
// rust-hdl names every module by its instance path, as in top$fetch$schedule,
// and the kit groups one stage's modules per file, so only top.v can carry
// its module's name.
lint_off -rule DECLFILENAME -file "*beam_fetch.v"
lint_off -rule DECLFILENAME -file "*ray_control.v"
lint_off -rule DECLFILENAME -file "*trilin_lanes.v"
lint_off -rule DECLFILENAME -file "*trilin.v"
lint_off -rule DECLFILENAME -file "*cube3.v"
lint_off -rule DECLFILENAME -file "*rpc.v"
lint_off -rule DECLFILENAME -file "*abc_unit.v"
lint_off -rule DECLFILENAME -file "*shader.v"
// Memory modules, 2-DSBs and delay lines are as deep as the scene needs:
// they take wide addresses and use only the low bits,
lint_off -rule UNUSEDSIGNAL -file "*" -match "*Bits of signal are not used: 'read_address'*"
lint_off -rule UNUSEDSIGNAL -file "*" -match "*Bits of signal are not used: 'write_address'*"
lint_off -rule UNUSEDSIGNAL -file "*beam_fetch.v" -match "*Bits of signal are not used: 'write_address$*"
lint_off -rule UNUSEDSIGNAL -file "*beam_fetch.v" -match "*Bits of signal are not used: 'load_address'*"
// and the opacity table, as long as the scene's, takes the low bits of a
// unit's opacity row.
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

/// Cube-3 systems.
pub const CUBE3: Layout = Layout {
    files: &CUBE3_STAGE_FILES,
    stage_file: cube3_stage_file,
    waivers: CUBE3_LINT_WAIVERS,
};

/// Verilator waivers for a design with `units` pruned: the inputs its
/// parents still compute for the removed instances are unread.
pub fn lint_waivers(units: &[LeftOut], layout: &Layout) -> String {
    let mut s = layout.waivers.to_string();
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

/// Write one design (emitted Verilog, with `units` left out) into `dir`:
/// the stage files and the lint waivers. Returns the file names written.
pub fn write_stage_files(
    dir: &std::path::Path,
    verilog: &str,
    units: &[LeftOut],
    layout: &Layout,
) -> std::io::Result<Vec<String>> {
    let mut texts: std::collections::BTreeMap<&str, String> = Default::default();
    for m in split_modules(verilog) {
        texts
            .entry((layout.stage_file)(&m.name))
            .or_default()
            .push_str(&m.text);
    }
    let mut names = Vec::new();
    for f in layout.files {
        if let Some(t) = texts.get(f) {
            std::fs::write(dir.join(f), t)?;
            names.push(f.to_string());
        }
    }
    std::fs::write(dir.join("lint.vlt"), lint_waivers(units, layout))?;
    Ok(names)
}
