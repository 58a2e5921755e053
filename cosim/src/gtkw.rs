//! GTKWave save files: a VCD from any engine opens with its signals grouped
//! by stage, as the architecture groups them ([`crate::arch::Arch::waves`]).

use std::path::Path;

/// The first line of every save file the kit writes: a GTKWave comment,
/// which tells a file the kit may replace from one the user saved.
pub const MARK: &str = "[*] written by cube";

/// A signal group of a save file: its name and signals.
pub type Wave = (String, Vec<String>);

/// A GTKWave save file beside `vcd` (its extension `.gtkw`) that opens with
/// the design's clock and start (under the scope `top`), then `waves`, one
/// group each.
pub fn write_gtkw(vcd: &Path, top: &str, waves: &[Wave]) -> std::io::Result<()> {
    let mut s = format!(
        "{MARK}: the next run's trace replaces it\n[dumpfile] \"{}\"\n[timestart] 0\n[size] 1400 900\n",
        vcd.display()
    );
    s.push_str(&format!("@28\n{top}.clock\n{top}.start\n"));
    for (name, sigs) in waves {
        s.push_str(&format!("@800200\n-{name}\n@22\n"));
        for sig in sigs {
            s.push_str(sig);
            s.push('\n');
        }
        s.push_str(&format!("@1000200\n-{name}\n"));
    }
    let gtkw = vcd.with_extension("gtkw");
    let tmp = gtkw.with_extension("gtkw.tmp");
    std::fs::write(&tmp, s)?;
    std::fs::rename(tmp, gtkw)
}
