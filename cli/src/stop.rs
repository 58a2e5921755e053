//! A run stopped by SIGTERM, SIGINT or SIGHUP stops the tools it started
//! and removes its temporary work (a synthesis directory, a half-written
//! output) before it exits with 128 + the signal.
//!
//! [`watch`] blocks the three signals in the main thread before any other
//! thread exists, so every thread inherits the mask and one watcher thread
//! receives them with `sigwait`: the clean-up runs as ordinary code, not in
//! a signal handler. The tools themselves start with the mask cleared
//! (`std::process::Command` resets it in the child).

use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// Paths to remove if the run is stopped.
static TEMPORARY: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// Remove `path` (a file or a directory tree) if the run is stopped.
pub fn remove_on_stop(path: &Path) {
    TEMPORARY
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .push(path.to_path_buf());
}

fn signals() -> libc::sigset_t {
    // SAFETY: sigset_t is plain data, initialised by sigemptyset.
    unsafe {
        let mut set: libc::sigset_t = std::mem::zeroed();
        libc::sigemptyset(&mut set);
        for s in [libc::SIGTERM, libc::SIGINT, libc::SIGHUP] {
            libc::sigaddset(&mut set, s);
        }
        set
    }
}

/// The working folders this process made under the temporary directory:
/// the simulation harnesses' (`cube-harness-PID-N`) and the traces'
/// (`cube-trace-PID-N`), which cosim makes and removes itself when a run
/// ends, but not when the run is stopped.
fn own_work() -> Vec<PathBuf> {
    let tag = format!("-{}-", std::process::id());
    let Ok(entries) = std::fs::read_dir(std::env::temp_dir()) else {
        return Vec::new();
    };
    entries
        .flatten()
        .filter(|e| {
            let name = e.file_name().to_string_lossy().to_string();
            name.starts_with("cube-") && name.contains(&tag)
        })
        .map(|e| e.path())
        .collect()
}

/// Stop the tools the run started and remove its temporary work: on a
/// stop signal, and on a run that cannot go on (a thread that cannot
/// start).
pub fn clean_up() {
    cosim::tool::stop_running();
    let paths = TEMPORARY.lock().unwrap_or_else(|e| e.into_inner()).clone();
    for p in paths.iter().rev().chain(&own_work()) {
        let _ = std::fs::remove_dir_all(p).or_else(|_| std::fs::remove_file(p));
    }
}

/// Start watching for the stop signals. Call first in `main`.
pub fn watch() {
    let set = signals();
    // SAFETY: a valid signal set; no other thread exists yet.
    unsafe {
        libc::pthread_sigmask(libc::SIG_BLOCK, &set, std::ptr::null_mut());
    }
    // Its own stack, not RUST_MIN_STACK's (rust-hdl's 32 MiB, or whatever
    // the environment says).
    let watcher = std::thread::Builder::new().stack_size(1 << 20);
    let started = watcher.spawn(move || {
        let mut sig = 0;
        // SAFETY: waits on the set blocked above.
        if unsafe { libc::sigwait(&set, &mut sig) } != 0 {
            return;
        }
        clean_up();
        eprintln!("cube: stopped by signal {sig}; temporary work removed");
        std::process::exit(128 + sig);
    });
    if let Err(e) = started {
        eprintln!(
            "cube: {}",
            crate::message::one_line(&format!(
                "cannot start the signal watcher thread: {e}; allow more memory (ulimit -v)"
            ))
        );
        std::process::exit(1);
    }
}
