//! Every output of every subcommand goes through one writer, and each rule
//! holds on every flag: an output that is an input or another output is
//! refused in one line before any work; a symlink is followed and stays a
//! link; a device reached through `/dev` is written through; a file's mode
//! is kept, and one the user may not write is refused; a `.gtkw` the kit did
//! not write is never replaced.

mod common;
use common::{cube, ok, refused};
use std::os::unix::fs::PermissionsExt;
use std::process::Command;

const SCENE: &str = r#"{"volume": {"builtin": "sphere", "dims": [12,12,10]}, "view": {"projection": "parallel", "rotate_deg": [70, 30, 0]}, "image": [24, 24], "hardware": {"pipelines": 2}}"#;

/// A folder with the scene `s.json` and its image `in.png`.
fn setup() -> tempfile::TempDir {
    let d = tempfile::tempdir().unwrap();
    std::fs::write(d.path().join("s.json"), SCENE).unwrap();
    ok(&cube(
        &["render", "--scene", "s.json", "--out", "in.png"],
        d.path(),
    ));
    d
}

/// Each subcommand's run on `s.json` (and `in.png`), and its output flags.
fn commands() -> Vec<(Vec<&'static str>, Vec<&'static str>)> {
    vec![
        (
            vec!["render", "--scene", "s.json", "--compare-reference"],
            vec!["--out", "--json", "--diff", "--base-plane"],
        ),
        (
            vec!["compare", "--scene", "s.json", "--image", "in.png"],
            vec!["--json", "--diff"],
        ),
        (
            vec!["angles", "--scene", "s.json", "--range", "0", "10", "10"],
            vec!["--json"],
        ),
        (
            vec!["gradients", "--scene", "s.json", "--range", "0", "0", "5"],
            vec!["--json", "--plot"],
        ),
        (
            vec!["sim", "--scene", "s.json"],
            vec!["--out", "--json", "--vcd"],
        ),
        (vec!["synth", "--scene", "s.json"], vec!["--json"]),
        (vec!["volume", "--scene", "s.json"], vec!["--out"]),
    ]
}

#[test]
fn an_output_on_an_input_or_on_another_output_is_refused_before_any_work() {
    let d = setup();
    let p = d.path();
    let scene_before = std::fs::read(p.join("s.json")).unwrap();
    let image_before = std::fs::read(p.join("in.png")).unwrap();
    std::os::unix::fs::symlink("s.json", p.join("link.json")).unwrap();
    std::fs::hard_link(p.join("s.json"), p.join("hard.json")).unwrap();
    for (run, flags) in commands() {
        for flag in &flags {
            // The scene itself, a symlink to it, a hard link to it.
            for onto in ["s.json", "link.json", "hard.json", "./sub/../s.json"] {
                let mut args = run.clone();
                args.extend([*flag, onto]);
                refused(&cube(&args, p), "would replace the input --scene");
            }
            if run[0] == "compare" {
                let mut args = run.clone();
                args.extend([*flag, "in.png"]);
                refused(&cube(&args, p), "would replace the input --image");
            }
        }
        // Two outputs on one file.
        for pair in flags.windows(2) {
            let mut args = run.clone();
            args.extend([pair[0], "same.out", pair[1], "same.out"]);
            refused(&cube(&args, p), "give each output its own file");
        }
    }
    // tradeoff: a scene in its output folder under an output's name.
    std::fs::create_dir(p.join("t")).unwrap();
    std::fs::write(p.join("t/tradeoff.json"), SCENE).unwrap();
    refused(
        &cube(&["tradeoff", "--scene", "t/tradeoff.json", "--out", "t"], p),
        "would replace the input --scene",
    );
    // sim: a trace named as its own save file is no trace's name: the
    // format is checked before the save file beside it.
    refused(
        &cube(&["sim", "--scene", "s.json", "--vcd", "x.gtkw"], p),
        "a trace's name ends in .vcd or .fst",
    );
    assert_eq!(std::fs::read(p.join("s.json")).unwrap(), scene_before);
    assert_eq!(std::fs::read(p.join("in.png")).unwrap(), image_before);
    assert!(!p.join("same.out").exists());
}

#[test]
fn a_symlinked_output_writes_its_target_and_stays_a_link() {
    let d = setup();
    let p = d.path();
    for (run, flags) in commands() {
        if run[0] == "synth" {
            continue; // its output needs yosys: tests/synth covers the writer there
        }
        let mut args = run.clone();
        // A trace's name carries its format.
        let ext = |flag: &str| if flag == "--vcd" { ".vcd" } else { "" };
        for (i, flag) in flags.iter().enumerate() {
            let link = format!("{}-{i}.link{}", run[0], ext(flag));
            let target = format!("{}-{i}.target{}", run[0], ext(flag));
            std::os::unix::fs::symlink(&target, p.join(&link)).unwrap();
            args.push(flag);
            args.push(Box::leak(link.into_boxed_str()));
        }
        ok(&cube(&args, p));
        for (i, flag) in flags.iter().enumerate() {
            let link = p.join(format!("{}-{i}.link{}", run[0], ext(flag)));
            let meta = std::fs::symlink_metadata(&link).unwrap();
            assert!(meta.file_type().is_symlink(), "{run:?} {flag}");
            let target = p.join(format!("{}-{i}.target{}", run[0], ext(flag)));
            assert!(
                std::fs::metadata(&target).unwrap().len() > 0,
                "{run:?} {flag}"
            );
        }
    }
}

#[test]
fn dev_stdout_into_a_redirected_log_is_written_through() {
    let d = setup();
    let p = d.path();
    let log = std::fs::File::create(p.join("log.txt")).unwrap();
    let o = Command::new(env!("CARGO_BIN_EXE_cube"))
        .args(["render", "--scene", "s.json", "--json", "/dev/stdout"])
        .current_dir(p)
        .stdout(log)
        .status()
        .unwrap();
    assert!(o.success());
    let text = std::fs::read_to_string(p.join("log.txt")).unwrap();
    // The line printed first, then the JSON after it: one file, appended.
    assert!(text.starts_with("cube4l:"), "{text}");
    assert!(text.contains("\"arch\": \"cube4l\""), "{text}");
    assert!(std::fs::symlink_metadata("/dev/stdout")
        .unwrap()
        .file_type()
        .is_symlink());
}

#[test]
fn a_files_mode_is_kept_and_a_file_the_user_may_not_write_is_refused() {
    let d = setup();
    let p = d.path();
    std::fs::write(p.join("kept.json"), "old").unwrap();
    std::fs::set_permissions(p.join("kept.json"), PermissionsExt::from_mode(0o640)).unwrap();
    ok(&cube(
        &["render", "--scene", "s.json", "--json", "kept.json"],
        p,
    ));
    let m = std::fs::metadata(p.join("kept.json")).unwrap();
    assert_eq!(m.permissions().mode() & 0o777, 0o640);
    assert_ne!(std::fs::read_to_string(p.join("kept.json")).unwrap(), "old");
    std::fs::write(p.join("ro.json"), "old").unwrap();
    std::fs::set_permissions(p.join("ro.json"), PermissionsExt::from_mode(0o444)).unwrap();
    let o = cube(&["render", "--scene", "s.json", "--json", "ro.json"], p);
    // SAFETY: geteuid has no preconditions.
    if unsafe { libc::geteuid() } == 0 {
        // As `cp` does for root: written, its mode kept.
        ok(&o);
        let m = std::fs::metadata(p.join("ro.json")).unwrap();
        assert_eq!(m.permissions().mode() & 0o777, 0o444);
    } else {
        refused(&o, "permission denied");
        assert_eq!(std::fs::read_to_string(p.join("ro.json")).unwrap(), "old");
    }
}

#[test]
fn a_save_file_the_kit_did_not_write_is_never_replaced() {
    let d = setup();
    let p = d.path();
    std::fs::write(p.join("notes.gtkw"), "[*] my own view\n").unwrap();
    refused(
        &cube(&["sim", "--scene", "s.json", "--vcd", "notes.vcd"], p),
        "was not written by cube",
    );
    assert_eq!(
        std::fs::read_to_string(p.join("notes.gtkw")).unwrap(),
        "[*] my own view\n"
    );
    assert!(!p.join("notes.vcd").exists());
    // The kit's own save file is replaced by the next run.
    ok(&cube(&["sim", "--scene", "s.json", "--vcd", "t.vcd"], p));
    ok(&cube(&["sim", "--scene", "s.json", "--vcd", "t.vcd"], p));
    let gtkw = std::fs::read_to_string(p.join("t.gtkw")).unwrap();
    assert!(gtkw.starts_with("[*] written by cube"), "{gtkw}");
}

/// An export replaces its `--out` folder as a whole: an input inside it
/// (by path, through a link, or as a hard link) is refused before any work,
/// and the input is left as it was.
#[test]
fn an_export_never_replaces_its_own_input() {
    let d = setup();
    let p = d.path();
    std::fs::create_dir(p.join("exp")).unwrap();
    std::fs::copy(p.join("s.json"), p.join("exp/manifest.json")).unwrap();
    let scene = std::fs::read(p.join("s.json")).unwrap();
    refused(
        &cube(
            &["verilog", "--scene", "exp/manifest.json", "--out", "exp"],
            p,
        ),
        "would replace the input --scene exp/manifest.json",
    );
    assert_eq!(std::fs::read(p.join("exp/manifest.json")).unwrap(), scene);
    // A hard link in the folder to a scene elsewhere.
    std::fs::create_dir(p.join("exp2")).unwrap();
    std::fs::hard_link(p.join("s.json"), p.join("exp2/top.v")).unwrap();
    refused(
        &cube(&["verilog", "--scene", "s.json", "--out", "exp2"], p),
        "would replace the input --scene s.json",
    );
    assert_eq!(std::fs::read(p.join("s.json")).unwrap(), scene);
    // The folder named through a link to it.
    std::os::unix::fs::symlink("exp", p.join("via")).unwrap();
    refused(
        &cube(
            &["verilog", "--scene", "exp/manifest.json", "--out", "via"],
            p,
        ),
        "would replace the input",
    );
}

/// `stage-vectors` replaces only the files it wrote (each begins with its
/// mark), and writes both or neither.
#[test]
fn stage_vectors_never_replace_a_users_file() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    let args = ["stage-vectors", "--clocks", "20", "--out", "sv"];
    std::fs::create_dir(p.join("sv")).unwrap();
    std::fs::write(p.join("sv/compositor.v"), "module mine; endmodule\n").unwrap();
    refused(&cube(&args, p), "was not written by cube");
    assert_eq!(
        std::fs::read_to_string(p.join("sv/compositor.v")).unwrap(),
        "module mine; endmodule\n"
    );
    assert!(!p.join("sv/compositor.json").exists());
    std::fs::remove_file(p.join("sv/compositor.v")).unwrap();
    std::fs::write(p.join("sv/compositor.json"), "{\"mine\": 1}\n").unwrap();
    refused(&cube(&args, p), "was not written by cube");
    assert!(!p.join("sv/compositor.v").exists());
    std::fs::remove_file(p.join("sv/compositor.json")).unwrap();
    // The kit's own pair is replaced by the next run.
    ok(&cube(&args, p));
    ok(&cube(&args, p));
    let v = std::fs::read_to_string(p.join("sv/compositor.v")).unwrap();
    assert!(v.starts_with("// written by cube stage-vectors"), "{v}");
    let j: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(p.join("sv/compositor.json")).unwrap())
            .unwrap();
    assert!(j["about"].as_str().unwrap().starts_with("written by cube"));
    assert_eq!(leftovers(p), Vec::<String>::new());
}

/// Files a run left that it did not mean to: its temporary files, at any
/// depth.
fn leftovers(dir: &std::path::Path) -> Vec<String> {
    let mut found = Vec::new();
    let mut todo = vec![dir.to_path_buf()];
    while let Some(d) = todo.pop() {
        for e in std::fs::read_dir(&d).unwrap().flatten() {
            let name = e.file_name().to_string_lossy().to_string();
            if e.file_type().unwrap().is_dir() {
                todo.push(e.path());
            }
            if name.starts_with(".cube-") {
                found.push(e.path().display().to_string());
            }
        }
    }
    found
}

/// A run's outputs land together or not at all: an output that cannot be
/// made is refused before any work, and one that fails as it is written
/// (`/dev/full`) leaves none of the others, no temporary file and no folder
/// the run made.
#[test]
fn a_failed_run_leaves_no_output_behind() {
    let d = setup();
    let p = d.path();
    std::fs::write(p.join("afile"), "x").unwrap();
    refused(
        &cube(
            &[
                "render",
                "--scene",
                "s.json",
                "--out",
                "good.png",
                "--json",
                "afile/new.json",
            ],
            p,
        ),
        "is not a directory",
    );
    assert!(!p.join("good.png").exists());
    let o = cube(
        &[
            "render",
            "--scene",
            "s.json",
            "--out",
            "new/deep/good.png",
            "--json",
            "/dev/full",
        ],
        p,
    );
    refused(&o, "/dev/full");
    assert!(!p.join("new").exists(), "the folders made are removed");
    assert_eq!(leftovers(p), Vec::<String>::new());
    // sim's JSON is checked before the simulation, not after it.
    refused(
        &cube(
            &[
                "sim",
                "--scene",
                "s.json",
                "--out",
                "f.png",
                "--json",
                "afile/x.json",
            ],
            p,
        ),
        "is not a directory",
    );
    assert!(!p.join("f.png").exists());
    // The default run, with one of its outputs a directory.
    std::fs::create_dir_all(p.join("out/default.png")).unwrap();
    refused(&cube(&[], p), "is a directory");
    let mut names: Vec<String> = std::fs::read_dir(p.join("out"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().to_string())
        .collect();
    names.sort();
    assert_eq!(names, ["default.png"]);
}

/// A legal 255-byte name has room for the run's temporary file beside it;
/// a path that ends in `/`, `.` or `..` is not a file name.
#[test]
fn any_legal_name_is_taken_and_a_folder_path_is_not_a_file() {
    let d = setup();
    let p = d.path();
    let long = format!("{}.png", "a".repeat(251));
    ok(&cube(&["render", "--scene", "s.json", "--out", &long], p));
    assert!(p.join(&long).is_file());
    for bad in ["x.png/", "sub/.", "sub/.."] {
        refused(
            &cube(&["render", "--scene", "s.json", "--out", bad], p),
            "not a file name",
        );
    }
    assert!(!p.join("x.png").exists());
    // One byte more than a name may have: refused before the render, for a
    // file and for an export's directory.
    let over = format!("{}.png", "a".repeat(252));
    refused(
        &cube(&["render", "--scene", "s.json", "--out", &over], p),
        "a name in it is 256 bytes, longer than the 255 a file name may have",
    );
    refused(
        &cube(
            &[
                "verilog",
                "--config",
                "mip_p4_64",
                "--out",
                &format!("sub/{over}"),
            ],
            p,
        ),
        "a name in it is 256 bytes",
    );
    assert!(!p.join("sub").exists());
    assert_eq!(leftovers(p), Vec::<String>::new());
}

/// `tradeoff --out DIR` replaces its five files only where a tradeoff run
/// wrote them (its tradeoff.json begins with the mark): a user's
/// `tradeoff.md` there is never lost.
#[test]
fn tradeoff_never_replaces_a_users_file_in_its_folder() {
    let d = setup();
    let p = d.path();
    std::fs::create_dir(p.join("tr")).unwrap();
    std::fs::write(p.join("tr/tradeoff.md"), "my notes\n").unwrap();
    refused(
        &cube(&["tradeoff", "--scene", "s.json", "--out", "tr"], p),
        "no cube tradeoff run wrote it",
    );
    assert_eq!(
        std::fs::read_to_string(p.join("tr/tradeoff.md")).unwrap(),
        "my notes\n"
    );
}
