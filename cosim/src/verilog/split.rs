//! One file per stage: an emitted design split into its modules, grouped
//! by the stage each belongs to as the architecture's [`Layout`] says, with
//! the Verilator lint waivers (hdl's [`lint_waivers`]).

use super::modules::split_modules;
use hdl::common::units::{lint_waivers, Layout, LeftOut};

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
            .entry(layout.stage_file(&m.name))
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
