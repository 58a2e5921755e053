//! Hostile input to the `cube` command: every case ends in one clear line
//! and exit 1 (vcd-diff: exit 2 for a bad trace), never a panic or a hang,
//! and no user file is ever deleted or replaced by something of another kind.

use std::path::Path;
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

fn cube(args: &[&str], dir: &Path) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_cube"))
        .args(args)
        .current_dir(dir)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("run cube");
    // Nothing may hang: a case that runs past a minute is killed and fails.
    let start = Instant::now();
    while child.try_wait().unwrap().is_none() {
        if start.elapsed() > Duration::from_secs(60) {
            child.kill().unwrap();
            panic!("cube {args:?} hung");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    child.wait_with_output().unwrap()
}

fn one_line_error(o: &Output, needle: &str) {
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(!err.contains("panicked"), "{err}");
    assert_eq!(err.trim_end().lines().count(), 1, "one line: {err}");
    assert!(err.contains(needle), "'{needle}' not in: {err}");
}

const SCENE: &str = r#"{"volume": {"builtin": "sphere", "dims": [12,12,10]}, "view": {"projection": "parallel", "rotate_deg": [70, 30, 0]}, "image": [24, 24], "hardware": {"pipelines": 2}}"#;

fn setup() -> (tempfile::TempDir, String) {
    let d = tempfile::tempdir().unwrap();
    let s = d.path().join("s.json");
    std::fs::write(&s, SCENE).unwrap();
    let s = s.display().to_string();
    (d, s)
}

#[test]
fn usage_errors_are_one_line_and_exit_1() {
    let (d, s) = setup();
    one_line_error(&cube(&["render", "--bogus"], d.path()), "--bogus");
    one_line_error(&cube(&["render"], d.path()), "--scene");
    one_line_error(
        &cube(&["render", "--scene", &s, "--arch", "nope"], d.path()),
        "nope",
    );
    one_line_error(&cube(&["frobnicate"], d.path()), "frobnicate");
    let help = cube(&["render", "--help"], d.path());
    assert_eq!(help.status.code(), Some(0));
    assert!(String::from_utf8_lossy(&help.stdout).contains("--scene"));
}

#[test]
fn negative_numbers_reach_the_range_checks() {
    let (d, s) = setup();
    one_line_error(
        &cube(&["render", "--scene", &s, "--ref-step", "-1"], d.path()),
        "--ref-step -1",
    );
    one_line_error(
        &cube(
            &["angles", "--scene", &s, "--range", "-10", "-20", "5"],
            d.path(),
        ),
        "--range",
    );
    // A range whose step vanishes beside its start ends at once.
    one_line_error(
        &cube(
            &["angles", "--scene", &s, "--range", "1e17", "1e17", "1"],
            d.path(),
        ),
        "--range",
    );
    let o = cube(
        &[
            "angles",
            "--scene",
            &s,
            "--range",
            "-10",
            "-5",
            "5",
            "--ref-step",
            "1",
        ],
        d.path(),
    );
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(text.contains("-10.00") && text.contains("-5.00"), "{text}");
}

#[test]
fn verilog_out_never_deletes_a_users_files() {
    let (d, s) = setup();
    let p = d.path();
    // A directory with a user's notes.
    std::fs::create_dir(p.join("mine")).unwrap();
    std::fs::write(p.join("mine/notes.txt"), "mine").unwrap();
    one_line_error(
        &cube(&["verilog", "--scene", &s, "--out", "mine"], p),
        "which an export does not write",
    );
    assert_eq!(
        std::fs::read_to_string(p.join("mine/notes.txt")).unwrap(),
        "mine"
    );
    // The directory that holds the scene.
    one_line_error(
        &cube(&["verilog", "--scene", &s, "--out", "."], p),
        "would replace the input --scene",
    );
    assert!(p.join("s.json").exists());
    std::fs::write(p.join("notes.txt"), "mine").unwrap();
    // A regular file is not turned into a directory.
    one_line_error(
        &cube(&["verilog", "--scene", &s, "--out", "notes.txt"], p),
        "not a directory",
    );
    assert_eq!(
        std::fs::read_to_string(p.join("notes.txt")).unwrap(),
        "mine"
    );
    // A previous export is replaced.
    for _ in 0..2 {
        let o = cube(&["verilog", "--scene", &s, "--out", "v"], p);
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    }
    assert!(p.join("v/top.v").exists());
    // An export with a user's file added to it is not.
    std::fs::write(p.join("v/mine.v"), "// mine").unwrap();
    one_line_error(
        &cube(&["verilog", "--scene", &s, "--out", "v"], p),
        "mine.v",
    );
    assert!(p.join("v/mine.v").exists());
}

/// `--out` through `..` names the folder it resolves to: an export there is
/// replaced in place, nothing is left beside it, a folder's mode is kept,
/// and a path up from a folder that does not exist is refused before any
/// folder is made.
#[test]
fn verilog_out_through_dot_dot_replaces_in_place() {
    use std::os::unix::fs::PermissionsExt;
    let (d, s) = setup();
    let p = d.path();
    let export = |out: &str| cube(&["verilog", "--scene", &s, "--out", out], p);
    std::fs::create_dir(p.join("v")).unwrap();
    std::fs::set_permissions(p.join("v"), std::fs::Permissions::from_mode(0o700)).unwrap();
    for out in ["v", "v/../v", "./v/../v/"] {
        let o = export(out);
        assert!(
            o.status.success(),
            "{out}: {}",
            String::from_utf8_lossy(&o.stderr)
        );
        assert!(p.join("v/top.v").is_file(), "{out}");
    }
    let mode = std::fs::metadata(p.join("v")).unwrap().permissions().mode() & 0o777;
    assert_eq!(mode, 0o700, "the folder's mode is kept");
    one_line_error(&export("nosuch/../w"), "does not name a directory");
    one_line_error(&export("v/sub/.."), "does not name a directory");
    assert!(!p.join("nosuch").exists() && !p.join("w").exists());
    let left: Vec<_> = std::fs::read_dir(p)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().to_string())
        .filter(|n| n.starts_with(".cube-"))
        .collect();
    assert!(left.is_empty(), "left beside the export: {left:?}");
}

/// An export's own files are replaced only as it wrote them: a top.v edited
/// since, a top.v that is now a directory, or a directory whose only file is
/// a manifest.json of the user's is refused, and stays as it was.
#[test]
fn verilog_out_never_replaces_an_edited_export() {
    let (d, s) = setup();
    let p = d.path();
    let export = |out: &str| cube(&["verilog", "--scene", &s, "--out", out], p);
    let o = export("v");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let m: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(p.join("v/manifest.json")).unwrap()).unwrap();
    let top = std::fs::read(p.join("v/top.v")).unwrap();
    assert_eq!(
        m["files_crc32"]["top.v"].as_str().unwrap(),
        format!("{:08x}", crc32fast::hash(&top)),
        "the manifest records top.v's CRC-32"
    );
    let edited = [top.as_slice(), b"// my fix\n"].concat();
    std::fs::write(p.join("v/top.v"), &edited).unwrap();
    one_line_error(&export("v"), "top.v is not the file the export");
    assert_eq!(std::fs::read(p.join("v/top.v")).unwrap(), edited);
    // Put back as written, it is the export's again.
    std::fs::write(p.join("v/top.v"), &top).unwrap();
    assert!(export("v").status.success());
    // A directory where the export writes a file.
    std::fs::remove_file(p.join("v/top.v")).unwrap();
    std::fs::create_dir(p.join("v/top.v")).unwrap();
    one_line_error(
        &export("v"),
        "top.v, a directory where an export writes a file",
    );
    assert!(p.join("v/top.v").is_dir());
    // A user's manifest.json, alone in its directory.
    std::fs::create_dir(p.join("w")).unwrap();
    std::fs::write(p.join("w/manifest.json"), "{\"mine\": 1}").unwrap();
    one_line_error(&export("w"), "holds no manifest.json with the record");
    assert_eq!(
        std::fs::read_to_string(p.join("w/manifest.json")).unwrap(),
        "{\"mine\": 1}"
    );
}

#[test]
fn special_files_are_written_through_never_replaced() {
    let (d, s) = setup();
    let p = d.path();
    let o = cube(&["render", "--scene", &s, "--json", "/dev/null"], p);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    use std::os::unix::fs::FileTypeExt;
    assert!(std::fs::metadata("/dev/null")
        .unwrap()
        .file_type()
        .is_char_device());
    // A FIFO with no reader is an error, not a hang; it stays a FIFO.
    let fifo = p.join("pipe");
    assert!(Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .unwrap()
        .success());
    one_line_error(
        &cube(&["render", "--scene", &s, "--json", "pipe"], p),
        "FIFO",
    );
    assert!(std::fs::metadata(&fifo).unwrap().file_type().is_fifo());
    // A FIFO with a reader receives the JSON.
    let reader = std::thread::spawn({
        let fifo = fifo.clone();
        move || std::fs::read_to_string(fifo).unwrap()
    });
    std::thread::sleep(Duration::from_millis(200));
    let o = cube(&["render", "--scene", &s, "--json", "pipe"], p);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(reader.join().unwrap().contains("\"arch\""));
    // A directory is refused.
    std::fs::create_dir(p.join("dir")).unwrap();
    one_line_error(
        &cube(&["render", "--scene", &s, "--out", "dir"], p),
        "directory",
    );
}

#[test]
fn a_failed_run_leaves_no_temporary_files() {
    let (d, _) = setup();
    let p = d.path();
    // 16 pipelines: a valid scene the RTL is not built for, so sim fails.
    let s16 = p.join("s16.json");
    std::fs::write(&s16, SCENE.replace("\"pipelines\": 2", "\"pipelines\": 16")).unwrap();
    let s16 = s16.display().to_string();
    let o = cube(&["sim", "--scene", &s16, "--vcd", "w/t.vcd"], p);
    assert_eq!(o.status.code(), Some(1));
    // Nothing is left, not even the folder the run made for the trace.
    assert!(!p.join("w").exists());
    // A directory as the VCD is refused before anything is simulated.
    std::fs::create_dir(p.join("vcd_dir")).unwrap();
    let s2 = p.join("s.json").display().to_string();
    one_line_error(
        &cube(&["sim", "--scene", &s2, "--vcd", "vcd_dir"], p),
        "directory",
    );
    assert_eq!(std::fs::read_dir(p.join("vcd_dir")).unwrap().count(), 0);
    let stray: Vec<_> = std::fs::read_dir(p)
        .unwrap()
        .filter_map(|e| e.ok())
        .filter(|e| e.file_name().to_string_lossy().contains(".tmp"))
        .collect();
    assert!(stray.is_empty(), "{stray:?}");
    // synth refuses a directory for --json before it runs yosys.
    std::fs::create_dir(p.join("j")).unwrap();
    let t = Instant::now();
    one_line_error(
        &cube(&["synth", "--scene", &s16, "--json", "j"], p),
        "directory",
    );
    assert!(t.elapsed() < Duration::from_secs(20));
}

#[test]
fn vcd_diff_counts_cycles_on_a_named_clock() {
    let d = tempfile::tempdir().unwrap();
    let vcd = "$scope module top $end\n$var wire 1 ! clk $end\n$var wire 1 \" q $end\n$upscope $end\n$enddefinitions $end\n#0\n0!\n0\"\n#5\n1!\n1\"\n#10\n0!\n#15\n1!\n";
    std::fs::write(d.path().join("a.vcd"), vcd).unwrap();
    let o = cube(&["vcd-diff", "a.vcd", "a.vcd"], d.path());
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stderr).contains("--clock"));
    let o = cube(&["vcd-diff", "a.vcd", "a.vcd", "--clock", "clk"], d.path());
    let text = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(0), "{text}");
    assert!(text.contains("over 2 cycles"), "{text}");
}

#[test]
fn bad_trace_requests_are_one_line_naming_the_flag() {
    let (d, s) = setup();
    let p = d.path();
    // A save file of the user's beside a name that is no trace's: the name
    // is what is wrong.
    std::fs::write(p.join("u.gtkw"), "mine").unwrap();
    for (flags, needle) in [
        (
            vec!["--trace", "t.txt"],
            "--trace: t.txt: a trace's name ends in .vcd or .fst",
        ),
        (vec!["--trace", "t"], "ends in .vcd or .fst"),
        (
            vec!["--trace", "u.txt"],
            "--trace: u.txt: a trace's name ends in .vcd or .fst",
        ),
        (
            vec!["--trace", "t.vcd", "--trace-clocks", "5..2"],
            "trace clocks 5..2: an empty range",
        ),
        (
            vec!["--trace", "t.vcd", "--trace-clocks", "abc"],
            "--trace-clocks abc: expected FIRST..END",
        ),
        (
            vec![
                "--trace",
                "t.fst",
                "--trace-clocks",
                "0..99999999999999999999",
            ],
            "--trace-clocks 0..99999999999999999999",
        ),
        (
            vec!["--trace", "t.vcd", "--trace-scope", "["],
            "--trace-scope [",
        ),
        (vec!["--trace-depth", "2"], "--trace"),
    ] {
        let mut args = vec!["sim", "--scene", &s];
        args.extend(flags);
        one_line_error(&cube(&args, p), needle);
    }
    let left: Vec<_> = std::fs::read_dir(p)
        .unwrap()
        .filter_map(|e| e.ok())
        .map(|e| e.file_name().to_string_lossy().to_string())
        .filter(|n| n != "s.json" && n != "u.gtkw")
        .collect();
    assert!(left.is_empty(), "{left:?}");
}
