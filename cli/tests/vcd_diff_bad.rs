//! `cube vcd-diff` on traces its parser (`wellen`) panicked on, and on a
//! bus named as the clock (issue 70, 4): each is refused with exit 2 and
//! one line naming the file and, for the text, its line; none prints a
//! panic.

mod common;
use common::cube;
use std::path::Path;

/// A header with a 1-bit `clock` (`!`) and an 8-bit `ctl` (`#`), then
/// `body` on line 12.
fn vcd(body: &str) -> String {
    format!(
        "$timescale 1ns $end\n$scope module uut $end\n$var wire 1 ! clock $end\n$var wire 8 # ctl $end\n$upscope $end\n$enddefinitions $end\n#0\n0!\nb0 #\n#5\n1!\n{body}\n#10\n0!\nb11 #\n#15\n1!\n"
    )
}

/// `cube vcd-diff ARGS` in `dir` was refused with exit 2 and one line
/// holding each of `needles`, with no panic.
fn refused(dir: &Path, args: &[&str], needles: &[&str]) {
    let mut all = vec!["vcd-diff"];
    all.extend_from_slice(args);
    let o = cube(&all, dir);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{args:?}: {err}");
    assert!(!err.contains("panicked"), "{args:?}: {err}");
    assert_eq!(
        err.trim_end().lines().count(),
        1,
        "{args:?}: one line: {err}"
    );
    for n in needles {
        assert!(err.contains(n), "{args:?}: '{n}' not in: {err}");
    }
    assert!(
        o.stdout.is_empty(),
        "{args:?}: {}",
        String::from_utf8_lossy(&o.stdout)
    );
}

#[test]
fn values_wellen_panicked_on_are_refused_with_their_line() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    std::fs::write(p.join("good.vcd"), vcd("b1 #")).unwrap();
    let o = cube(&["vcd-diff", "good.vcd", "good.vcd"], p);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    for (name, body, needle) in [
        (
            "wide.vcd",
            "b111111111 #",
            "9 bits, wider than the 8-bit `ctl`",
        ),
        ("b12.vcd", "b12 #", "`2` is not a bit"),
        ("b1q.vcd", "b1q #", "`q` is not a bit"),
        ("short.vcd", "bh #", "does not extend"),
        ("empty.vcd", "b #", "an empty value"),
        ("clock.vcd", "b1q !", "`q` is not a bit"),
        ("undeclared.vcd", "1%", "no $var declares"),
        ("noid.vcd", "1", "with no signal id"),
        // wellen warned on stdout and dropped what followed a step back:
        // traces that differ there read as equal.
        ("back.vcd", "#3", "time 3 comes after time 5"),
        ("badtime.vcd", "#x", "`#x` is not a time"),
    ] {
        std::fs::write(p.join(name), vcd(body)).unwrap();
        refused(p, &[name, "good.vcd"], &[name, "line 12:", needle]);
        // As B too.
        refused(p, &["good.vcd", name], &[name, "line 12:", needle]);
    }
}

#[test]
fn headers_wellen_panicked_on_are_refused_with_their_line() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    std::fs::write(p.join("good.vcd"), vcd("b1 #")).unwrap();
    let up = "$upscope $end\n";
    for (name, text, line, needle) in [
        (
            "upscope.vcd",
            vcd("").replace(up, &up.repeat(3)),
            6,
            "an $upscope with no $scope open",
        ),
        (
            "upscope_var.vcd",
            vcd("").replace(up, &format!("{up}{up}$var wire 1 $ q $end\n")),
            6,
            "an $upscope with no $scope open",
        ),
        (
            "scope.vcd",
            vcd("").replace("module uut", ""),
            2,
            "a $scope with no type",
        ),
        (
            "date.vcd",
            format!("$date a $end\n$date b $end\n{}", vcd("")),
            2,
            "a second $date",
        ),
        (
            "timescale.vcd",
            format!("$timescale 1ps $end\n{}", vcd("")),
            2,
            "a second $timescale",
        ),
        (
            "huge.vcd",
            vcd("").replace("wire 8 #", "wire 4294967295 #"),
            4,
            "4294967295 bits wide",
        ),
    ] {
        std::fs::write(p.join(name), text).unwrap();
        refused(
            p,
            &[name, "good.vcd"],
            &[name, &format!("line {line}:"), needle],
        );
    }
}

/// What the check before the parser leaves to it, and the parser panics
/// on, is caught: still one line and exit 2.
#[test]
fn a_panic_the_check_lets_through_is_caught() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    std::fs::write(p.join("good.vcd"), vcd("b1 #")).unwrap();
    let text = vcd("").replace("$var wire 8", "$attrbegin misc 07 \"\" 5 $end\n$var wire 8");
    std::fs::write(p.join("attr.vcd"), text).unwrap();
    refused(
        p,
        &["attr.vcd", "good.vcd"],
        &["attr.vcd", "the trace reader failed"],
    );
}

#[test]
fn a_bus_is_refused_as_the_clock() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    // The traces differ in `ctl`, but a 4-bit clock counted no cycle:
    // "traces equal".
    let a = "$timescale 1ns $end\n$scope module uut $end\n$var wire 1 ! clock $end\n$var wire 4 \" ctl $end\n$upscope $end\n$enddefinitions $end\n#0\n0!\nb0 \"\n#5\n1!\nb1 \"\n#10\n0!\nb0 \"\n#15\n1!\nb11 \"\n";
    std::fs::write(p.join("a.vcd"), a).unwrap();
    std::fs::write(p.join("b.vcd"), a.replace("b11 \"", "b1111 \"")).unwrap();
    refused(
        p,
        &["--clock", "ctl", "a.vcd", "b.vcd"],
        &["a.vcd", "`ctl` is 4 bits wide", "1-bit"],
    );
    refused(
        p,
        &["--clock", "uut.ctl", "a.vcd", "b.vcd"],
        &["`uut.ctl` is 4 bits wide"],
    );
    // On the 1-bit clock they differ.
    let o = cube(&["vcd-diff", "a.vcd", "b.vcd"], p);
    assert_eq!(
        o.status.code(),
        Some(1),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
}

/// Issue 70 re-probe: traces that differ only in a real or a string value,
/// or in a bus's bit range, said "traces equal" (exit 0); they now differ
/// (exit 1). A 0-bit wire, one name under two ids in a scope, and a real
/// that is NaN or overflows are refused (exit 2) naming the file and line.
#[test]
fn reals_strings_ranges_and_names_count() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    let with = |var: &str, first: &str, second: &str| {
        format!(
            "$timescale 1ns $end\n$scope module uut $end\n$var wire 1 ! clock $end\n{var}\n$upscope $end\n$enddefinitions $end\n#0\n0!\n{first}\n#5\n1!\n#10\n0!\n{second}\n#15\n1!\n"
        )
    };
    let real = "$var real 64 \" data $end";
    let string = "$var string 1 \" data $end";
    for (a, b, what) in [
        (
            with(real, "r1.5 \"", "r2.5 \""),
            with(real, "r1.5 \"", "r3.5 \""),
            "reals",
        ),
        (
            with(string, "sHello \"", "sx \""),
            with(string, "sWorld \"", "sx \""),
            "strings",
        ),
        (
            with("$var wire 4 \" data [3:0] $end", "b0 \"", "b1 \""),
            with("$var wire 4 \" data [7:4] $end", "b0 \"", "b1 \""),
            "ranges",
        ),
    ] {
        std::fs::write(p.join("a.vcd"), a).unwrap();
        std::fs::write(p.join("b.vcd"), b).unwrap();
        let o = cube(&["vcd-diff", "a.vcd", "b.vcd"], p);
        let out = String::from_utf8_lossy(&o.stdout);
        assert_eq!(o.status.code(), Some(1), "{what}: {out}");
        assert!(
            out.contains("uut.data") && !out.contains("traces equal"),
            "{what}: {out}"
        );
    }
    std::fs::write(p.join("good.vcd"), with(real, "r1.5 \"", "r2.5 \"")).unwrap();
    for (name, text, line, needle) in [
        (
            "nan.vcd",
            with(real, "rNaN \"", "r2.5 \""),
            "line 9:",
            "not a finite number",
        ),
        (
            "huge.vcd",
            with(real, "r1e400 \"", "r2.5 \""),
            "line 9:",
            "not a finite number",
        ),
        (
            "zero.vcd",
            with("$var wire 0 \" data $end", "b0000 \"", "b0 \""),
            "line 4:",
            "declared 0 bits wide",
        ),
        (
            "twice.vcd",
            with(
                "$var wire 4 \" data $end\n$var wire 4 # data $end",
                "b0 \"\nb1 #",
                "b1 \"",
            ),
            "line 5:",
            "declared again, under another id (first on line 4)",
        ),
    ] {
        std::fs::write(p.join(name), text).unwrap();
        refused(p, &[name, "good.vcd"], &[name, line, needle]);
    }
}
