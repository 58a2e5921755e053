//! One file per stage: an emitted design split into its modules, grouped
//! by the stage each belongs to as the architecture's [`Layout`] says, with
//! the Verilator lint waivers.

use super::modules::split_modules;
use super::prune::LeftOut;

/// How an architecture's emitted design is laid out in files: the stage
/// files in reading order (the top first), the file of each module, and the
/// lint waivers every design of it needs beyond [`lint_waivers`]' own.
#[derive(Debug, Clone, Copy)]
pub struct Layout {
    pub files: &'static [&'static str],
    pub stage_file: fn(&str) -> &'static str,
    pub waivers: &'static str,
}

/// Verilator's configuration for a design with `units` pruned: the
/// waivers every emitted design needs, the architecture's, and those of the
/// pruned units, whose parents still compute the inputs they would have
/// read. Each waiver is narrow (one rule, matched on the signal or file) and
/// explained. (Verilator's configuration lexer stumbles on parentheses and
/// paired apostrophes inside comments, so the comments avoid them.)
pub fn lint_waivers(units: &[LeftOut], layout: &Layout) -> String {
    let mut s = String::from(
        "`verilator_config\n// rust-hdl names every module by its instance path, as in top$cfb$lanes$0, and\n// the kit groups one stage's modules per file, so only top.v can carry its\n// module's name.\n",
    );
    for f in layout.files.iter().filter(|f| **f != "top.v") {
        s.push_str(&format!("lint_off -rule DECLFILENAME -file \"*{f}\"\n"));
    }
    s.push_str("// Memory modules, buffers and delay lines are as deep as the scene needs:\n// they take wide pointers and addresses and use only the low bits.\nlint_off -rule UNUSEDSIGNAL -file \"*\" -match \"*Bits of signal are not used: 'read_address'*\"\nlint_off -rule UNUSEDSIGNAL -file \"*\" -match \"*Bits of signal are not used: 'write_address'*\"\n");
    s.push_str("// The host port carries 64-bit words: a shader table keeps only the bit\n// fields of its entries, and the light and half registers three 16-bit\n// components.\nlint_off -rule UNUSEDSIGNAL -file \"*shader.v\" -match \"*Bits of signal are not used: 'host_data'*\"\nlint_off -rule UNUSEDSIGNAL -file \"*shader.v\" -match \"*Bits of signal are not used: 'write_data'*\"\nlint_off -rule UNUSEDSIGNAL -file \"*shader.v\" -match \"*Bits of signal are not used: 'regs$q$*'*\"\n");
    s.push_str("// The lighting's square tables and reciprocal-norm ROM are as deep as the\n// build's normal width: their addresses are as wide as the widest normal\n// and they decode the low bits.\nlint_off -rule UNUSEDSIGNAL -file \"*shader.v\" -match \"*Bits of signal are not used: 'address'*\"\n");
    s.push_str("// A registered product's port p sits in the unorm multiplier's instance\n// of the same name, which Verilator takes for a declaration it hides.\nlint_off -rule VARHIDDEN -file \"*\" -match \"*hides declaration in upper scope: 'p'*\"\n");
    s.push_str("// A product the build does not read is a constant register that ignores\n// its operands: the lighting's upper products at normals up to 5 bits.\nlint_off -rule UNUSEDSIGNAL -file \"*shader.v\" -match \"*Signal is not used: 'a'\"\nlint_off -rule UNUSEDSIGNAL -file \"*shader.v\" -match \"*Signal is not used: 'b'\"\n");
    s.push_str(layout.waivers);
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
