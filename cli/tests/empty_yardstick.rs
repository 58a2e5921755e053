//! No error figure against an empty yardstick: when neither image has a
//! foreground pixel (a transparent transfer function, a view that misses
//! the volume), every subcommand that reports an error says `n/a`, and
//! those that exist only for that figure refuse in one line.

mod common;
use common::{cube, ok, refused};
use std::path::Path;

/// Every voxel transparent.
const CLEAR: &str = r#"{"volume": {"builtin": "sphere", "dims": [12,12,10]}, "view": {"projection": "parallel", "rotate_deg": [70, 30, 0]}, "image": [24, 24], "hardware": {"pipelines": 2}, "transfer": {"opacity": [[0, 0], [255, 0]], "color": [[0, 1, 1, 1], [255, 1, 1, 1]]}}"#;

fn json(path: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(path).unwrap()).unwrap()
}

fn not_available(error: &serde_json::Value) {
    for k in ["rel_euclid_pct", "psnr_db", "rmse", "max_abs"] {
        assert_eq!(error[k], "n/a", "{k}: {error}");
    }
    assert_eq!(error["foreground_pixels"], 0);
}

#[test]
fn an_empty_yardstick_gives_no_figure() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    std::fs::write(p.join("clear.json"), CLEAR).unwrap();
    let s = "clear.json";
    for arch in ["cube4l", "cube3", "quantized-projection"] {
        let out = ok(&cube(
            &[
                "render",
                "--scene",
                s,
                "--arch",
                arch,
                "--compare-reference",
                "--json",
                "r.json",
                "--out",
                "r.png",
            ],
            p,
        ));
        assert!(out.contains("error n/a"), "{arch}: {out}");
        assert!(!out.contains("0.000 %"), "{arch}: {out}");
        not_available(&json(&p.join("r.json"))["error"]);
    }
    let out = ok(&cube(
        &[
            "compare", "--scene", s, "--image", "r.png", "--json", "c.json",
        ],
        p,
    ));
    assert!(out.contains("error n/a"), "{out}");
    not_available(&json(&p.join("c.json"))["error"]);
    let out = ok(&cube(
        &[
            "angles", "--scene", s, "--range", "0", "10", "10", "--json", "a.json",
        ],
        p,
    ));
    assert!(out.contains("largest rel. Euclidean error: n/a"), "{out}");
    let a = json(&p.join("a.json"));
    assert_eq!(a["max_rel_euclid_pct"], "n/a");
    for row in a["rows"].as_array().unwrap() {
        not_available(&row["error"]);
    }
    refused(
        &cube(&["tradeoff", "--scene", s, "--out", "t"], p),
        "no foreground pixels",
    );
    assert!(!p.join("t/tradeoff.json").exists());
}

#[test]
fn gradients_with_no_crossing_refuse() {
    let d = tempfile::tempdir().unwrap();
    let p = d.path();
    std::fs::write(
        p.join("tiny.json"),
        r#"{"volume": {"builtin": "sphere", "dims": [2,2,2]}, "view": {"projection": "parallel"}, "image": [16,16]}"#,
    )
    .unwrap();
    refused(
        &cube(
            &[
                "gradients",
                "--scene",
                "tiny.json",
                "--range",
                "0",
                "0",
                "5",
                "--json",
                "g.json",
            ],
            p,
        ),
        "no threshold crossing",
    );
    assert!(!p.join("g.json").exists());
}
