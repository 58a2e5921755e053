//! GTKWave save files: a trace from any engine opens with its signals
//! grouped by stage, as the architecture groups them
//! ([`crate::arch::Arch::waves`]), at the first `start` with [`OPEN_CLOCKS`]
//! clocks in view (the whole trace when it holds no start), counters and
//! addresses in decimal and data in hex.
//!
//! The save file names its trace by absolute path and names itself beside
//! it (`[savefile]`): GTKWave opens the trace from any working folder, and
//! when the two files move together it finds the trace beside the save file.

use crate::trace::{Request, Written, CLOCK_TIME};
use std::path::{Path, PathBuf};

/// The first line of every save file the kit writes: a GTKWave comment,
/// which tells a file the kit may replace from one the user saved.
pub const MARK: &str = "[*] written by cube";

/// A signal group of a save file: its name and signals.
pub use hdl::common::units::Wave;

/// Pixels of GTKWave's wave pane at the save file's window size (1400
/// wide, less the signal list), which the zoom fills.
const PANE_PIXELS: f64 = 1100.0;

/// Clocks in view when the save file opens at the first start: the start,
/// the first beats through the stages' registers, and a clock before it.
pub const OPEN_CLOCKS: u64 = 48;

/// GTKWave's trace flags: binary for one bit, hex or decimal for vectors
/// (right-justified).
const BINARY: &str = "@28";
const HEX: &str = "@22";
const DECIMAL: &str = "@24";

/// Whether a signal (its name below its scope, with a bit range or not)
/// counts or addresses: shown in decimal.
pub fn is_count(leaf: &str) -> bool {
    let base = leaf.split('[').next().unwrap_or(leaf);
    const COUNTS: &[&str] = &[
        "x", "y", "z", "face", "chunk", "period", "plane", "ray", "segment", "n_s", "n_beam",
        "n_b", "px_x", "px_y", "px_face",
    ];
    COUNTS.contains(&base)
        || ["addr", "count", "pointer", "index"]
            .iter()
            .any(|w| base.contains(w))
}

/// An absolute form of `path` (its folder made absolute; the file itself
/// need not exist yet).
fn absolute(path: &Path) -> PathBuf {
    let dir = path.parent().filter(|d| !d.as_os_str().is_empty());
    let dir = dir.map_or_else(|| Path::new(".").to_path_buf(), Path::to_path_buf);
    let dir = std::fs::canonicalize(&dir)
        .or_else(|_| std::path::absolute(&dir))
        .unwrap_or(dir);
    dir.join(path.file_name().unwrap_or_default())
}

/// The save file's text for a trace at `trace` (its final place) that
/// spans `written.clocks`, with the design's clock and start (under the
/// scope `top`), then `waves`, one group each.
pub fn render(trace: &Path, written: &Written, top: &str, waves: &[Wave]) -> String {
    let dump = absolute(trace);
    let save = dump.with_extension("gtkw");
    let (first, end) = match written.first_start {
        Some(s) => {
            let at = s.saturating_sub(1).max(written.clocks.0);
            (at, (at + OPEN_CLOCKS).min(written.clocks.1))
        }
        None => written.clocks,
    };
    let span = (end.saturating_sub(first).max(1)).saturating_mul(CLOCK_TIME) as f64;
    // GTKWave shows 2^-zoom time units a pixel.
    let zoom = (PANE_PIXELS / span).log2().floor();
    let mut s = format!(
        "{MARK}: the next run's trace replaces it\n[dumpfile] \"{}\"\n[savefile] \"{}\"\n[timestart] {}\n[size] 1400 900\n*{zoom:.6} -1{}\n",
        dump.display(),
        save.display(),
        first.saturating_mul(CLOCK_TIME),
        " -1".repeat(26)
    );
    s.push_str(&format!("{BINARY}\n{top}.clock\n{top}.start\n"));
    for (name, sigs) in waves {
        s.push_str(&format!("@800200\n-{name}\n"));
        let mut flag = "";
        for sig in sigs {
            let leaf = sig.rsplit('.').next().unwrap_or(sig);
            let want = if !leaf.contains('[') {
                BINARY
            } else if is_count(leaf) {
                DECIMAL
            } else {
                HEX
            };
            if want != flag {
                s.push_str(want);
                s.push('\n');
                flag = want;
            }
            s.push_str(sig);
            s.push('\n');
        }
        s.push_str(&format!("@1000200\n-{name}\n"));
    }
    s
}

/// Write the save file for the trace `req` asked for, beside `req.path`
/// (its extension `.gtkw`), naming the trace at `req.lands_at` when the
/// caller moves it there.
pub fn write_gtkw(
    req: &Request,
    written: &Written,
    top: &str,
    waves: &[Wave],
) -> std::io::Result<()> {
    let shown = req.lands_at.as_deref().unwrap_or(&req.path);
    let text = render(shown, written, top, waves);
    let gtkw = req.path.with_extension("gtkw");
    let tmp = gtkw.with_extension("gtkw.tmp");
    std::fs::write(&tmp, text)?;
    std::fs::rename(tmp, gtkw)
}
