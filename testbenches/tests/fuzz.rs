//! Fuzzing the parsers with proptest: valid scene JSON and VCD text, mutated
//! in field values, types, lengths, extremes and truncations. Whatever comes
//! in, parsing ends in a scene (which then plans and, when small, renders)
//! or in one clear line; it never panics or hangs.
//!
//! The suite runs a bounded number of cases (`PROPTEST_CASES`, default 64
//! per property) from a fixed seed, so that every run tries the same cases;
//! `scripts/fuzz` runs a longer session from a fresh seed
//! (`PROPTEST_RNG_SEED`). A case that takes longer than `CASE_LIMIT` fails
//! with its scene text instead of hanging the suite.

use proptest::prelude::*;
use proptest::test_runner::RngSeed;
use scene::{Scene, Volume};
use serde_json::{json, Value};
use std::io::Write;
use std::sync::mpsc;
use std::time::Duration;

/// The suite's bounded number of cases, or `PROPTEST_CASES`; its fixed
/// seed, or `PROPTEST_RNG_SEED`.
fn config() -> ProptestConfig {
    let env = |name: &str| std::env::var(name).ok().and_then(|c| c.parse().ok());
    ProptestConfig {
        cases: env("PROPTEST_CASES").unwrap_or(64) as u32,
        rng_seed: RngSeed::Fixed(env("PROPTEST_RNG_SEED").unwrap_or(0xc0be3)),
        failure_persistence: None,
        ..ProptestConfig::default()
    }
}

/// The longest one case may take (a debug build renders an 8³ scene in
/// milliseconds).
const CASE_LIMIT: Duration = Duration::from_secs(20);

/// Run `exercise` on `text` in a thread of its own. If it does not finish
/// within `CASE_LIMIT`, end the whole test binary naming the text: shrinking
/// a hang would only start more threads that never end.
fn exercise_within_limit(text: String) {
    let (done, finished) = mpsc::channel();
    let worker = {
        let text = text.clone();
        std::thread::spawn(move || {
            exercise(&text);
            let _ = done.send(());
        })
    };
    match finished.recv_timeout(CASE_LIMIT) {
        Ok(()) => worker.join().unwrap(),
        // The worker panicked: re-raise its panic here.
        Err(mpsc::RecvTimeoutError::Disconnected) => {
            std::panic::resume_unwind(worker.join().unwrap_err())
        }
        Err(mpsc::RecvTimeoutError::Timeout) => {
            // Straight to stderr: the harness captures eprintln! and would
            // lose it with the process.
            let _ = writeln!(
                std::io::stderr(),
                "fuzz: no result after {CASE_LIMIT:?}, a hang on: {text}"
            );
            std::process::exit(1)
        }
    }
}

/// A valid scene with every section present, small enough to render.
fn base_scene() -> Value {
    json!({
        "volume": {"builtin": "sphere", "dims": [8, 8, 8]},
        "view": {"projection": "parallel", "rotate_deg": [70, 30, 0], "zoom": 1},
        "mode": "composite",
        "transfer": {"opacity": [[0, 0.0], [80, 0.0], [100, 0.75], [255, 0.75]],
                     "color": [[0, 1.0, 1.0, 1.0], [255, 1.0, 0.5, 0.2]],
                     "gradient_opacity": [[0, 0.5], [40, 1.0]],
                     "opaque_threshold": 0.5},
        "shading": {"enabled": true, "light_dir": [0.3, 0.3, 1.0], "ambient": 0.2,
                    "diffuse": 0.6, "specular": 0.3, "shininess": 10},
        "image": [16, 16],
        "hardware": {"pipelines": 2, "voxel_bits": 8, "frac_bits": 8, "rgba_bits": 8}
    })
}

fn perspective_scene() -> Value {
    let mut s = base_scene();
    s["view"] = json!({"projection": "perspective", "eye": [3.5, 3.5, -12], "target": [3.5, 3.5, 3.5],
                       "up": [0, 1, 0], "fov_deg": 40});
    s
}

/// Every path to a leaf (or an array) of `v`.
fn paths(v: &Value, prefix: &mut Vec<Value>, out: &mut Vec<Vec<Value>>) {
    out.push(prefix.clone());
    match v {
        Value::Object(m) => {
            for (k, c) in m {
                prefix.push(Value::String(k.clone()));
                paths(c, prefix, out);
                prefix.pop();
            }
        }
        Value::Array(a) => {
            for (i, c) in a.iter().enumerate() {
                prefix.push(json!(i));
                paths(c, prefix, out);
                prefix.pop();
            }
        }
        _ => {}
    }
}

fn at<'a>(v: &'a mut Value, path: &[Value]) -> &'a mut Value {
    path.iter().fold(v, |v, k| match k {
        Value::String(s) => &mut v[s.as_str()],
        Value::Number(n) => &mut v[n.as_u64().unwrap() as usize],
        _ => unreachable!(),
    })
}

/// Replacement values: extremes, wrong types, wrong lengths.
fn odd_value() -> impl Strategy<Value = Value> {
    prop_oneof![
        Just(json!(0)),
        Just(json!(-1)),
        Just(json!(1e308)),
        Just(json!(-1e308)),
        Just(json!(1e-320)),
        Just(json!(u64::MAX)),
        Just(json!(i64::MIN)),
        Just(json!(4097)),
        Just(json!(65536)),
        Just(json!(0.5)),
        Just(json!(null)),
        Just(json!(true)),
        Just(json!("")),
        Just(json!("mip")),
        Just(json!("perspective")),
        Just(json!([])),
        Just(json!([1])),
        Just(json!([1, 2, 3, 4])),
        Just(json!([[0, 0]])),
        Just(json!({})),
        any::<f64>().prop_map(|f| json!(f)),
        any::<i64>().prop_map(|i| json!(i)),
        (-3.0f64..300.0).prop_map(|f| json!(f)),
    ]
}

/// Parse; if the scene is accepted, it must plan, and render when small.
fn exercise(text: &str) {
    let Ok(scene) = Scene::from_json(text, None) else {
        let e = Scene::from_json(text, None).unwrap_err().to_string();
        assert!(!e.contains('\n'), "one line: {e}");
        return;
    };
    let cam = scene.camera();
    let _ = golden_model::cube4l::plan::Plan::new(&scene, &cam);
    let dims = scene.volume.render_dims();
    let [w, h] = scene.image;
    if dims.iter().product::<usize>() <= 16 * 16 * 16 && w * h <= 64 * 64 {
        let vol = Volume::from_spec(&scene.volume, scene.hardware.voxel_bits).unwrap();
        if let Ok((img, _)) = golden_model::cube4l::render_image(&scene, &vol) {
            assert!(img.rgb.iter().flatten().all(|c| c.is_finite()));
        }
        let r = reference::render(&scene, &cam, &vol, 1.0);
        assert!(r.rgb.iter().flatten().all(|c| c.is_finite()));
    }
}

fn mutate(mut v: Value, pick: usize, new: Value) -> String {
    let mut all = Vec::new();
    paths(&v, &mut Vec::new(), &mut all);
    let path = &all[pick % all.len()];
    *at(&mut v, path) = new;
    v.to_string()
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn mutated_scene_values_never_panic(pick in any::<usize>(), new in odd_value(), persp in any::<bool>()) {
        let base = if persp { perspective_scene() } else { base_scene() };
        exercise_within_limit(mutate(base, pick, new));
    }

    #[test]
    fn two_mutations_never_panic(p1 in any::<usize>(), n1 in odd_value(), p2 in any::<usize>(), n2 in odd_value()) {
        let once: Value = serde_json::from_str(&mutate(base_scene(), p1, n1)).unwrap();
        exercise_within_limit(mutate(once, p2, n2));
    }

    #[test]
    fn truncated_or_spliced_scene_text_never_panics(cut in any::<usize>(), junk in "[\\[\\]{}\",:0-9a-z.eE+-]{0,8}") {
        let text = base_scene().to_string();
        let cut = cut % (text.len() + 1);
        exercise_within_limit(format!("{}{junk}{}", &text[..cut], &text[cut..(cut + junk.len()).min(text.len())]));
        exercise_within_limit(text[..cut].to_string());
    }
}

/// Every struct-valued field of the scene (read through `scene::spec`'s
/// `object`), as a path from the top and as the error names it; the scene
/// itself is the empty path.
const OBJECTS: &[(&[&str], &str)] = &[
    (&[], ""),
    (&["volume"], "volume"),
    (&["view"], "view"),
    (&["transfer"], "transfer"),
    (&["shading"], "shading"),
    (&["hardware"], "hardware"),
    (&["cube3"], "cube3"),
    (&["quantized"], "quantized"),
    (&["volume", "crop"], "volume.crop"),
];

proptest! {
    #![proptest_config(config())]

    /// serde's derived structs also take a sequence, filling the fields in
    /// order: every object of the format, given as an array of anything,
    /// is refused in one line naming the field.
    #[test]
    fn an_array_for_an_object_is_refused_naming_the_field(
        pick in any::<usize>(),
        items in prop::collection::vec(odd_value(), 0..8),
        persp in any::<bool>(),
    ) {
        let (path, field) = OBJECTS[pick % OBJECTS.len()];
        let mut scene = if persp { perspective_scene() } else { base_scene() };
        *path.iter().fold(&mut scene, |v, k| &mut v[*k]) = Value::Array(items);
        let text = scene.to_string();
        let (tx, rx) = mpsc::channel();
        let worker = {
            let text = text.clone();
            std::thread::spawn(move || {
                let _ = tx.send(Scene::from_json(&text, None).map(|_| ()).map_err(|e| e.to_string()));
            })
        };
        let r = rx.recv_timeout(CASE_LIMIT);
        prop_assert!(worker.join().is_ok(), "a panic on: {text}");
        let e = match r {
            Ok(Err(e)) => e,
            Ok(Ok(())) => return Err(TestCaseError::fail(format!("accepted: {text}"))),
            Err(_) => return Err(TestCaseError::fail(format!("no result: {text}"))),
        };
        prop_assert!(!e.contains('\n'), "one line: {e}");
        let named = if field.is_empty() {
            "expected an object, found an array".to_string()
        } else {
            format!("{field}: expected an object, found an array")
        };
        prop_assert!(e.contains(&named), "'{named}' not in: {e} ({text})");
    }
}

/// A small valid VCD with a clock, a vector and a scope below the top.
const VCD: &str = "$timescale 1ns $end\n$scope module uut $end\n$var wire 1 ! clock $end\n$var wire 4 \" count $end\n$scope module sub $end\n$var wire 1 # q $end\n$upscope $end\n$upscope $end\n$enddefinitions $end\n#0\n0!\nb0 \"\n0#\n#5\n1!\nb1 \"\n#10\n0!\n#15\n1!\nb10 \"\n1#\n#20\n0!\n";

fn trace_of(text: &str) -> Result<cosim::vcd_diff::Trace, cosim::vcd_diff::BadTrace> {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("t.vcd");
    std::fs::write(&path, text).unwrap();
    cosim::vcd_diff::Trace::load(&path)
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn mutated_vcd_text_never_panics(cut in any::<usize>(), at in any::<usize>(), junk in "[$#!\"01bxzZX \\n a-z]{0,12}") {
        let good = trace_of(VCD).unwrap();
        let cut = cut % (VCD.len() + 1);
        let at = at % (cut + 1);
        let text = format!("{}{junk}{}", &VCD[..at], &VCD[cut..]);
        if let Ok(t) = trace_of(&text) {
            let c = cosim::vcd_diff::compare(&good, &t, None);
            if let Ok(c) = c {
                let _ = c.equal();
            }
        } else {
            let e = trace_of(&text).unwrap_err().to_string();
            prop_assert!(!e.contains('\n'), "one line: {e}");
            prop_assert!(!e.contains("the trace reader failed"), "left to the safety net: {e}: {text:?}");
        }
    }
}

/// What `wellen` 0.25 panicked on (issue 70, 4): a value wider than its
/// variable, a digit that is not a bit, more `$upscope`s than scopes. Each
/// is refused in one line naming the file and the line.
#[test]
fn the_inputs_wellen_panicked_on_are_refused_naming_the_line() {
    let head = "$timescale 1ns $end\n$scope module uut $end\n$var wire 1 ! clock $end\n$var wire 8 # ctl $end\n$upscope $end\n$enddefinitions $end\n#0\n0!\nb0 #\n#5\n1!\n";
    for (text, line, needle) in [
        (
            format!("{head}b111111111 #\n"),
            12,
            "wider than the 8-bit `ctl`",
        ),
        (format!("{head}b12 #\n"), 12, "`2` is not a bit"),
        (format!("{head}b1q #\n"), 12, "`q` is not a bit"),
        (
            head.replace(
                "$upscope $end\n",
                "$upscope $end\n$upscope $end\n$upscope $end\n",
            ),
            6,
            "an $upscope with no $scope open",
        ),
    ] {
        let e = trace_of(&text).unwrap_err().to_string();
        assert!(!e.contains('\n'), "one line: {e}");
        assert!(
            e.contains("t.vcd: ") && e.contains(&format!("line {line}: ")),
            "{e}"
        );
        assert!(e.contains(needle), "'{needle}' not in: {e}");
    }
}

/// [`VCD`] with `extra` inserted as line `at` (counted from 0, wrapped).
fn with_line(at: usize, extra: &str) -> (String, usize) {
    let mut lines: Vec<&str> = VCD.lines().collect();
    let at = at % (lines.len() + 1);
    lines.insert(at, extra);
    (lines.join("\n") + "\n", at + 1)
}

/// The line after `#5` in [`VCD`], counted from 0: in the value changes.
fn after_first_edge() -> usize {
    VCD.lines().position(|l| l == "#5").unwrap() + 1
}

/// Odd lines for [`VCD`]: values for its ids (`!` the clock, `"` the 4-bit
/// count, `#` a 1-bit `q`, `%` none) of any width and digits, reals,
/// scope commands, stray words.
fn odd_vcd_line() -> impl Strategy<Value = String> {
    prop_oneof![
        "b[01xzXZ]{1,12} [!\"#%]",
        "b[01]{0,3}[0-9a-zA-Z.]{1,2} [!\"#]",
        "b0b[01]{1,6} [!\"#]",
        "[01xzhuwl2q-][!\"#%]?",
        "r[0-9.ea-z-]{0,5} [!\"#]",
        "s[a-z]{0,4} [!\"#]",
        "b[01]{0,4}",
        Just("$upscope $end".to_string()),
        Just("$scope module m $end".to_string()),
        Just("$scope $end".to_string()),
        Just("$date x $end".to_string()),
        Just("$timescale 1ps $end".to_string()),
        Just("$var wire 4294967295 % big $end".to_string()),
        Just("$var real 64 % f $end".to_string()),
        Just("$comment b12 \" $end".to_string()),
        "#[0-9]{1,3}",
    ]
}

/// A trace is read, then compared, or refused in one line.
fn read_or_refused(text: &str) -> Result<(), TestCaseError> {
    match trace_of(text) {
        Ok(t) => {
            let good = trace_of(VCD).unwrap();
            if let Ok(c) = cosim::vcd_diff::compare(&good, &t, None) {
                let _ = c.equal();
            }
        }
        Err(e) => {
            let e = e.to_string();
            prop_assert!(!e.contains('\n'), "one line: {e}");
            // The check before the parser finds what it would panic on:
            // the caught panic is a safety net only.
            prop_assert!(
                !e.contains("the trace reader failed"),
                "left to the safety net: {e}: {text:?}"
            );
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn odd_vcd_lines_never_panic(at in any::<usize>(), odd in prop::collection::vec(odd_vcd_line(), 1..4)) {
        let (mut text, _) = with_line(at, &odd[0]);
        for (i, o) in odd.iter().enumerate().skip(1) {
            let mut lines: Vec<String> = text.lines().map(String::from).collect();
            let k = (at / (i + 1)) % (lines.len() + 1);
            lines.insert(k, o.clone());
            text = lines.join("\n") + "\n";
        }
        read_or_refused(&text)?;
    }

    #[test]
    fn values_wider_than_their_variable_are_refused(bits in "[01xz]{5,40}") {
        let (text, line) = with_line(after_first_edge(), &format!("b{bits} \""));
        let e = trace_of(&text).unwrap_err().to_string();
        prop_assert!(e.contains(&format!("line {line}: ")), "{e}");
        prop_assert!(e.contains("wider than the 4-bit `count`"), "{e}");
    }

    #[test]
    fn digits_that_are_not_bits_are_refused(
        before in "[01]{0,2}",
        bad in "[2-9a-gijkmnopqrstvyA-GIJKMNOPQRSTVY.+]",
        id in "[!\"#]",
    ) {
        let (text, line) = with_line(after_first_edge(), &format!("b{before}{bad} {id}"));
        let e = trace_of(&text).unwrap_err().to_string();
        prop_assert!(e.contains(&format!("line {line}: ")), "{e}");
        prop_assert!(e.contains(&format!("`{bad}` is not a bit")), "{e}");
    }

    #[test]
    fn more_upscopes_than_scopes_are_refused(n in 1usize..5, at in any::<usize>()) {
        // After the last `$upscope`, or anywhere before `$enddefinitions`
        // once the scopes are closed: one more than open.
        let lines: Vec<&str> = VCD.lines().collect();
        let last = lines.iter().rposition(|l| *l == "$upscope $end").unwrap();
        let end = lines.iter().position(|l| l.starts_with("$enddefinitions")).unwrap();
        let at = last + 1 + at % (end - last);
        let mut out: Vec<&str> = lines[..at].to_vec();
        out.extend(std::iter::repeat_n("$upscope $end", n));
        out.extend(&lines[at..]);
        let e = trace_of(&(out.join("\n") + "\n")).unwrap_err().to_string();
        prop_assert!(e.contains(&format!("line {}: an $upscope with no $scope open", at + 1)), "{e}");
        read_or_refused(&(out.join("\n") + "\n"))?;
    }
}
