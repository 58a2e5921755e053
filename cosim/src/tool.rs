//! Running the external tools (Icarus, Verilator, yosys, nextpnr): a
//! missing tool names the set-up command, a failing one shows its errors and
//! the end of its log.

use std::process::{Command, Output};

/// Run `cmd` (the tool `what`) to completion; its output when it succeeds.
pub fn run(cmd: &mut Command, what: &str) -> Result<Output, String> {
    let out = cmd
        .output()
        .map_err(|e| format!("cannot run {what} ({e}): run scripts/test, which installs it"))?;
    if !out.status.success() {
        let err = String::from_utf8_lossy(&out.stderr);
        let log = String::from_utf8_lossy(&out.stdout);
        let tail: Vec<&str> = log.lines().rev().take(15).collect();
        return Err(format!(
            "{what} failed: {err}{}",
            tail.into_iter().rev().collect::<Vec<_>>().join("\n")
        ));
    }
    Ok(out)
}
