//! What the `cube` command tests share: running it in a folder, and
//! checking a success or a one-line refusal.

// Each test file is its own crate and uses some of these.
#![allow(dead_code)]

use std::path::Path;
use std::process::{Command, Output, Stdio};

/// Run `cube ARGS` in `dir`, with no input.
pub fn cube(args: &[&str], dir: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_cube"))
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .output()
        .expect("run cube")
}

/// The run succeeded: its standard output.
pub fn ok(o: &Output) -> String {
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    String::from_utf8_lossy(&o.stdout).into()
}

/// The run was refused with exit `code` and one line holding `needle`.
pub fn refused_with(o: &Output, code: i32, needle: &str) {
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(code), "{err}");
    assert_eq!(err.trim_end().lines().count(), 1, "one line: {err}");
    assert!(err.contains(needle), "'{needle}' not in: {err}");
}

/// Refused with exit 1, the code of every bad input.
pub fn refused(o: &Output, needle: &str) {
    refused_with(o, 1, needle)
}
