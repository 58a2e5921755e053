//! Regression tests for hostile scene input: every case gets one clear line
//! naming the field, never a panic, a hang or a silently wrong scene.

use scene::{Scene, Volume};

const MIN: &str =
    r#"{"volume": {"builtin": "sphere", "dims": [16,16,16]}, "view": {"projection": "parallel"}}"#;

fn err_of(text: &str) -> String {
    let e = Scene::from_json(text, None).unwrap_err().to_string();
    assert!(!e.contains('\n'), "one line: {e}");
    e
}

fn with(key_value: &str) -> String {
    MIN.replace("}}", &format!("}}, {key_value}}}"))
}

#[test]
fn crop_near_usize_max_is_refused_not_wrapped() {
    for (offset, dims) in [
        ("[18446744073709551615, 0, 0]", "[2, 2, 2]"),
        ("[2, 0, 0]", "[18446744073709551615, 2, 2]"),
    ] {
        let s = MIN.replace(
            "[16,16,16]}",
            &format!("[16,16,16], \"crop\": {{\"offset\": {offset}, \"dims\": {dims}}}}}"),
        );
        assert!(err_of(&s).contains("crop"), "{s}");
    }
}

#[test]
fn a_window_whose_width_overflows_is_refused() {
    let s = r#"{"volume": {"raw": "/nonexistent.raw", "type": "i16", "dims": [4,4,4], "window": [-1e308, 1e308]}, "view": {"projection": "parallel"}}"#;
    assert!(err_of(s).contains("window"));
    // And the decoder itself refuses it (it is public).
    let e = scene::volume::from_raw(
        &[0; 128],
        [4, 4, 4],
        scene::RawType::I16,
        Some([-1e308, 1e308]),
        8,
    )
    .unwrap_err();
    assert!(e.contains("window"), "{e}");
}

#[test]
fn extreme_light_directions_normalise_without_overflow_or_underflow() {
    for dir in [
        "[1e200, 1, 1]",
        "[1e308, 1e308, 0]",
        "[1e-200, 1e-200, 1e-200]",
        "[-1e-320, 0, 0]",
    ] {
        let s = with(&format!(
            "\"shading\": {{\"enabled\": true, \"light_dir\": {dir}}}"
        ));
        Scene::from_json(&s, None).unwrap_or_else(|e| panic!("{dir}: {e}"));
    }
    let zero = with("\"shading\": {\"enabled\": true, \"light_dir\": [0, 0, 0]}");
    assert!(err_of(&zero).contains("light_dir"));
    assert!(err_of(&zero).contains("zero length"));
}

#[test]
fn a_subnormal_or_huge_zoom_is_refused_by_name() {
    // A zoom of 1e-320 once made the pixel spacing infinite, and the float
    // reference marched its rays forever.
    let zoomed = |zoom: &str| {
        MIN.replace(
            "\"projection\": \"parallel\"",
            &format!("\"projection\": \"parallel\", \"zoom\": {zoom}"),
        )
    };
    for zoom in ["1e-320", "0.0009", "1000.5", "0"] {
        assert!(err_of(&zoomed(zoom)).contains("zoom"), "{zoom}");
    }
    for zoom in ["0.001", "1000"] {
        Scene::from_json(&zoomed(zoom), None).unwrap_or_else(|e| panic!("{zoom}: {e}"));
    }
}

#[test]
fn a_far_eye_or_target_is_refused_by_name() {
    let persp = |eye: &str, target: &str| {
        MIN.replace(
            "\"projection\": \"parallel\"",
            &format!("\"projection\": \"perspective\", \"eye\": {eye}, \"target\": {target}"),
        )
    };
    let e = err_of(&persp("[1e308, 0, 0]", "[8, 8, 8]"));
    assert!(e.contains("eye") && e.contains("beyond"), "{e}");
    let e = err_of(&persp("[8, 8, -40]", "[8, 8, 1e308]"));
    assert!(e.contains("target") && e.contains("beyond"), "{e}");
    // Within the bound, a distant eye still plans.
    Scene::from_json(&persp("[8, 8, -900000]", "[8, 8, 8]"), None).unwrap();
}

#[test]
fn parse_errors_name_the_field() {
    let e = err_of(&with("\"mode\": 3"));
    assert!(e.starts_with("scene: mode:"), "{e}");
    let e = err_of(&MIN.replace("[16,16,16]", "[16,16,16,4]"));
    assert!(e.contains("volume.dims") && e.contains("too many"), "{e}");
    let e = err_of(&MIN.replace("[16,16,16]", "[16,16]"));
    assert!(e.contains("volume.dims") && e.contains("length"), "{e}");
    let e = err_of(&with("\"hardware\": {\"pipelines\": -1}"));
    assert!(e.contains("hardware.pipelines"), "{e}");
    let e = err_of(&format!("{MIN} x"));
    assert!(e.contains("after the scene object"), "{e}");
}

#[test]
fn gradient_opacity_beyond_any_gradient_is_refused() {
    let s = with(
        r#""transfer": {"opacity": [[0, 0.5]], "color": [[0, 1, 1, 1]], "gradient_opacity": [[0, 1], [1e10, 1]]}"#,
    );
    assert!(err_of(&s).contains("transfer.gradient_opacity"));
}

#[test]
fn too_many_voxels_are_refused_before_anything_is_allocated() {
    let s = MIN.replace("[16,16,16]", "[4096,4096,4096]");
    assert!(err_of(&s).contains("exceed"));
}

fn load(s: &Scene) -> scene::Result<Volume> {
    Volume::from_spec(&s.volume, s.hardware.voxel_bits)
}

fn raw_scene(path: &str) -> Scene {
    let s = format!(
        r#"{{"volume": {{"raw": "{path}", "type": "u8", "dims": [16,16,16]}}, "view": {{"projection": "parallel"}}}}"#
    );
    Scene::from_json(&s, None).unwrap()
}

#[cfg(unix)]
#[test]
fn special_files_are_refused_without_blocking_or_reading() {
    // /dev/zero would be read forever; a FIFO with no writer would block.
    let e = load(&raw_scene("/dev/zero")).unwrap_err().to_string();
    assert!(e.contains("not a regular file"), "{e}");
    let dir = std::env::temp_dir().join(format!("cube-fifo-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let fifo = dir.join("volume.raw");
    let made = std::process::Command::new("mkfifo").arg(&fifo).status();
    assert!(
        made.is_ok_and(|s| s.success()),
        "mkfifo (coreutils) is needed"
    );
    let e = load(&raw_scene(fifo.to_str().unwrap()))
        .unwrap_err()
        .to_string();
    std::fs::remove_dir_all(&dir).unwrap();
    assert!(e.contains("not a regular file"), "{e}");
}

#[test]
fn a_raw_file_of_the_wrong_size_is_refused_before_it_is_read() {
    let dir = std::env::temp_dir().join(format!("cube-size-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let f = dir.join("v.raw");
    std::fs::write(&f, vec![0u8; 100]).unwrap();
    let e = load(&raw_scene(f.to_str().unwrap()))
        .unwrap_err()
        .to_string();
    std::fs::remove_dir_all(&dir).unwrap();
    assert!(e.contains("100 bytes") && e.contains("4096"), "{e}");
}

/// serde's derived structs also take a sequence: `"hardware": [1,8,8,8,5]`
/// rendered at 1 pipeline, and a volume given as an array was read in field
/// order. Every object of the format refuses an array, naming the field.
#[test]
fn arrays_are_refused_where_the_format_is_an_object() {
    let view = r#""view": {"projection": "parallel"}"#;
    let vol = r#""volume": {"builtin": "sphere", "dims": [16,16,16]}"#;
    for (text, field) in [
        (with(r#""hardware": [1,8,8,8,5]"#), "hardware"),
        (
            with(r#""transfer": [[[0,0]],[[0,1,1,1]],null,0.5]"#),
            "transfer",
        ),
        (with(r#""shading": [true]"#), "shading"),
        (with(r#""cube3": [12]"#), "cube3"),
        (with(r#""quantized": [32]"#), "quantized"),
        (
            format!(r#"{{"volume": [null,"vol.raw",[16,16,16],"u8",null,null,null], {view}}}"#),
            "volume",
        ),
        (
            format!(r#"{{{vol}, "view": ["parallel", [0,0,0], null, null, null, null, 1]}}"#),
            "view",
        ),
        (
            MIN.replace("[16,16,16]}", r#"[16,16,16], "crop": [[0,0,0],[8,8,8]]}"#),
            "volume.crop",
        ),
    ] {
        let e = err_of(&text);
        assert!(
            e.contains(&format!("{field}: expected an object, found an array")),
            "{text}: {e}"
        );
    }
    let e = err_of(r#"[{"builtin": "sphere", "dims": [16,16,16]}, {"projection": "parallel"}]"#);
    assert!(e.contains("expected an object, found an array"), "{e}");
    // Objects, and a null crop, still read as before.
    let s = Scene::from_json(
        &with(r#""hardware": {"pipelines": 1}, "quantized": {"kernel": [0.4, 2]}"#),
        None,
    )
    .unwrap();
    assert_eq!(s.hardware.pipelines, 1);
    let s = MIN.replace("[16,16,16]}", r#"[16,16,16], "crop": null}"#);
    assert!(Scene::from_json(&s, None).unwrap().volume.crop.is_none());
    let s = MIN.replace(
        "[16,16,16]}",
        r#"[16,16,16], "crop": {"offset": [0,0,0], "dims": [8,8,8]}}"#,
    );
    assert!(Scene::from_json(&s, None).unwrap().volume.crop.is_some());
}

/// `rotate_deg` is reduced mod 360 in degrees, exactly, before it becomes
/// radians: 1e17° once rendered at 275.6°, not at 1e17 mod 360 = 280°.
#[test]
fn huge_angles_are_reduced_exactly() {
    let cam = |r: &str| {
        Scene::from_json(
            &MIN.replace("parallel\"", &format!("parallel\", \"rotate_deg\": {r}")),
            None,
        )
        .unwrap()
        .camera()
    };
    for (big, small) in [
        ("[0, 1e17, 0]", "[0, 280, 0]"),
        ("[1e17, 0, 0]", "[280, 0, 0]"),
        ("[0, 0, -1e17]", "[0, 0, -280]"),
        ("[720.5, -360, 1080]", "[0.5, 0, 0]"),
    ] {
        let (a, b) = (cam(big), cam(small));
        for (u, v) in [(a.right, b.right), (a.up, b.up), (a.forward, b.forward)] {
            assert_eq!(u, v, "{big} against {small}");
        }
    }
}

/// A splat kernel whose `b` underflows in f32 gave NaN weights (1e-100: a
/// black image and a NaN error) or subnormal ones (X-ray, 1e-44: 79.8 %
/// against 16.0 %): refused, naming the field and the usable range.
#[test]
fn a_kernel_that_f32_cannot_hold_is_refused() {
    for b in ["1e-100", "1e-44", "1e-38", "1e-31", "0", "-1", "11"] {
        let e = err_of(&with(&format!(r#""quantized": {{"kernel": [{b}, 0.1]}}"#)));
        assert!(
            e.contains("quantized.kernel") && e.contains("[1e-30, 10]"),
            "{b}: {e}"
        );
    }
    for b in ["1e-30", "0.446", "10"] {
        let s = with(&format!(r#""quantized": {{"kernel": [{b}, 0.1]}}"#));
        if let Err(e) = Scene::from_json(&s, None) {
            panic!("{b}: {e}");
        }
    }
}
