//! Today's images, held by hash: every golden model (Cube-4L, Cube-3 and
//! the quantized-voxel path) over a set of small scenes that covers every
//! mode, parallel and perspective views (exactly 45° among them), 8- and
//! 16-bit voxels, each Cube-3 neighbourhood and the quantized path's
//! options. A hash covers the final image (the f64 bits of every channel),
//! the fixed-point base planes where the model has them, and the work
//! counters; a refusal is held by its message (and marked `refused`).
//!
//! Any change to any output fails this test, naming the scenes. A change
//! meant to alter images (a new datapath width, say) regenerates the
//! committed hashes with
//!
//! ```text
//! CUBE_UPDATE_HASHES=1 cargo test -p golden_model --test image_hashes
//! ```
//!
//! and says so, with the error against the reference before and after.
//! Speed-ups must leave this file unchanged.

use golden_model::{cube3, cube4l, quantized};
use scene::volume::Volume;
use scene::Scene;
use std::fmt::Write as _;

const HASHES: &str = "tests/image_hashes.txt";

/// The scene matrix: (name, JSON).
fn scenes() -> Vec<(String, String)> {
    let tf = r#""transfer": {
        "opacity": [[0, 0.0], [50, 0.0], [80, 0.1], [150, 0.4], [255, 0.9]],
        "color": [[0, 0.9, 0.6, 0.5], [120, 0.95, 0.45, 0.35], [255, 1.0, 1.0, 0.95]]}"#;
    let tf_go = r#""transfer": {
        "opacity": [[0, 0.0], [50, 0.0], [80, 0.2], [255, 1.0]],
        "color": [[0, 1, 0.5, 0.2], [255, 0.2, 0.6, 1]],
        "gradient_opacity": [[0, 0.1], [40, 0.6], [120, 1.0]]}"#;
    let tf16 = r#""transfer": {
        "opacity": [[0, 0.0], [20000, 0.0], [40000, 0.3], [65535, 0.8]],
        "color": [[0, 1, 1, 1], [65535, 1, 0.8, 0.6]]}"#;
    let par = |r: [f64; 3]| {
        format!(
            r#""view": {{"projection": "parallel", "rotate_deg": [{}, {}, {}]}}"#,
            r[0], r[1], r[2]
        )
    };
    // A far eye (every model that draws perspective), and a close one,
    // inside the slab of two faces (Cube-4L's several sweeps).
    let persp = r#""view": {"projection": "perspective", "eye": [-16, -8, -16], "target": [9.5, 8.5, 7.5], "fov_deg": 50}"#;
    let close = r#""view": {"projection": "perspective", "eye": [7, 13, -6], "target": [9.5, 8.5, 7.5], "fov_deg": 80}"#;
    let hw = |p: usize, bits: u32| {
        format!(
            r#""hardware": {{"pipelines": {p}, "voxel_bits": {bits}, "frac_bits": 8, "rgba_bits": {}}}"#,
            if bits == 8 { 8 } else { 12 }
        )
    };
    let shading = r#""shading": {"enabled": true, "light_dir": [0.3, -0.5, -0.8], "ambient": 0.2, "diffuse": 0.6, "specular": 0.4, "shininess": 12}"#;
    let scene = |vol: &str, dims: [usize; 3], view: &str, mode: &str, extra: &[&str]| {
        let mut s = format!(
            r#"{{"volume": {{"builtin": "{vol}", "dims": [{}, {}, {}]}}, {view}, "mode": "{mode}", "image": [40, 36]"#,
            dims[0], dims[1], dims[2]
        );
        for e in extra {
            s += ", ";
            s += e;
        }
        s + "}"
    };
    let d = [18, 16, 14];
    let oblique = par([25.0, 35.0, 0.0]);
    let mut out = Vec::new();
    let mut add = |name: String, json: String| out.push((name, json));
    for mode in ["composite", "mip", "minip", "xray", "first_opaque"] {
        for (vname, view) in [
            ("oblique", oblique.clone()),
            ("perspective", persp.into()),
            ("close", close.into()),
        ] {
            add(
                format!("{mode}_{vname}"),
                scene("phantom", d, &view, mode, &[tf, &hw(4, 8), shading]),
            );
        }
    }
    for (vname, r) in [
        ("front", [0.0, 0.0, 0.0]),
        ("exact45", [45.0, 0.0, 0.0]),
        ("tilt70", [70.0, 30.0, 0.0]),
        ("back", [-33.0, 160.0, 7.0]),
        ("side", [10.0, 95.0, 20.0]),
    ] {
        add(
            format!("composite_shaded_{vname}"),
            scene(
                "phantom",
                d,
                &par(r),
                "composite",
                &[tf, &hw(4, 8), shading],
            ),
        );
    }
    add(
        "composite_unshaded".into(),
        scene("phantom", d, &oblique, "composite", &[tf, &hw(4, 8)]),
    );
    add(
        "composite_gradient_opacity".into(),
        scene(
            "phantom",
            d,
            &oblique,
            "composite",
            &[tf_go, &hw(4, 8), shading],
        ),
    );
    for p in [1, 2] {
        add(
            format!("composite_p{p}"),
            scene(
                "phantom",
                d,
                &oblique,
                "composite",
                &[tf, &hw(p, 8), shading],
            ),
        );
    }
    for mode in ["composite", "xray", "mip"] {
        for (vname, view) in [("oblique", oblique.clone()), ("perspective", persp.into())] {
            add(
                format!("{mode}_16bit_{vname}"),
                scene(
                    "sphere",
                    [16, 16, 16],
                    &view,
                    mode,
                    &[tf16, &hw(4, 16), shading],
                ),
            );
        }
    }
    for n in [6, 10, 12, 26] {
        for (vname, r) in [
            ("oblique", [25.0, 35.0, 0.0]),
            ("exact45", [0.0, 45.0, 0.0]),
        ] {
            let c3 = format!(r#""cube3": {{"gradient": {n}}}"#);
            add(
                format!("cube3_n{n}_{vname}"),
                scene(
                    "phantom",
                    d,
                    &par(r),
                    "composite",
                    &[tf, &hw(4, 8), shading, &c3],
                ),
            );
        }
    }
    add(
        "cube3_narrow_widths".into(),
        scene(
            "phantom",
            d,
            &oblique,
            "composite",
            &[
                tf,
                &hw(4, 8),
                shading,
                r#""cube3": {"sample_bits": 8, "gradient_bits": 9}"#,
            ],
        ),
    );
    let q = |extra: &str| format!(r#""quantized": {{{extra}}}"#);
    for (qname, qs) in [
        ("min_empty", q(r#""empty_space": "min""#)),
        ("front_to_back", q(r#""order": "front_to_back""#)),
        ("normals16_sub8", q(r#""normals": 16, "subdivisions": 8"#)),
        ("kernel", q(r#""kernel": [0.8, 4.0], "subdivisions": 4"#)),
    ] {
        for mode in ["composite", "xray"] {
            add(
                format!("quantized_{qname}_{mode}"),
                scene("phantom", d, &oblique, mode, &[tf, &hw(4, 8), shading, &qs]),
            );
        }
    }
    // The eye over the face's middle: increments of both signs.
    let centred = r#""view": {"projection": "perspective", "eye": [9, 8, -20], "target": [9, 8, 7], "fov_deg": 40}"#;
    add(
        "composite_perspective_centred".into(),
        scene(
            "phantom",
            d,
            centred,
            "composite",
            &[tf, &hw(4, 8), shading],
        ),
    );
    // Footprints across the quantized path's bands and blocks: a larger,
    // zoomed image, an opaque volume (occlusion, early termination), and
    // gradients (the blocks' boundary voxels cut).
    let zoomed = |order: &str, opaque: bool, zoom: f64, mode: &str, [w, h]: [u32; 2]| {
        let tf_opaque = r#""transfer": {"opacity": [[0, 0.0], [40, 0.0], [60, 1.0], [255, 1.0]],
            "color": [[0, 1, 0.5, 0.2], [255, 0.2, 0.6, 1]]}"#;
        format!(
            r#"{{"volume": {{"builtin": "phantom", "dims": [30, 26, 22]}},
                "view": {{"projection": "parallel", "rotate_deg": [-20, 130, 15], "zoom": {zoom}}},
                "image": [{w}, {h}], "mode": "{mode}", {}, {}, {shading},
                "quantized": {{"order": "{order}", "subdivisions": 16}}}}"#,
            if opaque { tf_opaque } else { tf_go },
            hw(4, 8)
        )
    };
    for order in ["back_to_front", "front_to_back"] {
        add(
            format!("zoomed_{order}"),
            zoomed(order, false, 2.5, "composite", [150, 140]),
        );
        add(
            format!("zoomed_opaque_{order}"),
            zoomed(order, true, 2.5, "composite", [150, 140]),
        );
        // The volume past every edge of the image.
        add(
            format!("cropped_{order}"),
            zoomed(order, false, 6.0, "composite", [150, 140]),
        );
        add(
            format!("first_opaque_{order}"),
            zoomed(order, true, 2.5, "first_opaque", [150, 140]),
        );
    }
    // Small footprints (whole blocks within a band of 32 rows) past the
    // image's edges, on an image two bands high.
    for order in ["back_to_front", "front_to_back"] {
        for opaque in [false, true] {
            let json = zoomed(order, opaque, 1.8, "composite", [48, 64]);
            add(
                format!("edges_{}_{order}", ["clear", "opaque"][opaque as usize]),
                json,
            );
        }
    }
    out
}

/// Everything a model gives for a scene, hashed: one entry per model.
fn hashes(name: &str, json: &str) -> Vec<(String, String)> {
    let scene = Scene::from_json(json, None).unwrap_or_else(|e| panic!("{name}: {e}"));
    let vol = Volume::from_spec(&scene.volume, scene.hardware.voxel_bits).unwrap();
    let image = |h: &mut crc32fast::Hasher, img: &scene::Image| {
        h.update(&img.width.to_le_bytes());
        h.update(&img.height.to_le_bytes());
        for px in &img.rgb {
            for c in px {
                h.update(&c.to_bits().to_le_bytes());
            }
        }
    };
    let pixels = |h: &mut crc32fast::Hasher, px: &[[u32; 4]]| {
        for p in px {
            for c in p {
                h.update(&c.to_le_bytes());
            }
        }
    };
    let mut out = Vec::new();
    let mut push = |key: String, h: crc32fast::Hasher, refused: bool| {
        let tail = if refused { " refused" } else { "" };
        out.push((key, format!("{:08x}{tail}", h.finalize())));
    };
    // Cube-4L.
    let mut h = crc32fast::Hasher::new();
    let r = cube4l::render_image(&scene, &vol);
    let refused = r.is_err();
    match r {
        Ok((img, frame)) => {
            image(&mut h, &img);
            for b in &frame.bases {
                pixels(&mut h, &b.pixels);
                h.update(format!("{:?}", b.faces).as_bytes());
            }
            h.update(format!("{:?}", frame.stats).as_bytes());
        }
        Err(e) => h.update(format!("refused: {e}").as_bytes()),
    }
    push(format!("{name}/cube4l"), h, refused);
    // Cube-3 with the scene's neighbourhood.
    let mut h = crc32fast::Hasher::new();
    let r = cube3::neighbourhood(&scene, None).and_then(|n| cube3::render_image(&scene, &vol, n));
    let refused = r.is_err();
    match r {
        Ok((img, frame)) => {
            image(&mut h, &img);
            for b in &frame.bases {
                h.update(&b.u0.to_le_bytes());
                h.update(&b.v0.to_le_bytes());
                pixels(&mut h, &b.pixels);
                h.update(format!("{:?}", b.cast).as_bytes());
            }
            h.update(format!("{:?}", frame.stats).as_bytes());
        }
        Err(e) => h.update(format!("refused: {e}").as_bytes()),
    }
    push(format!("{name}/cube3"), h, refused);
    // The quantized path, both methods.
    for method in [quantized::Method::Projection, quantized::Method::Splat] {
        let mut h = crc32fast::Hasher::new();
        let r = quantized::render(&scene, &vol, method);
        let refused = r.is_err();
        match r {
            Ok((img, stats, _)) => {
                image(&mut h, &img);
                h.update(format!("{stats:?}").as_bytes());
            }
            Err(e) => h.update(format!("refused: {e}").as_bytes()),
        }
        push(format!("{name}/{}", method.name()), h, refused);
    }
    out
}

#[test]
fn images_match_the_committed_hashes() {
    let mut now = String::new();
    for (name, json) in scenes() {
        for (key, h) in hashes(&name, &json) {
            writeln!(now, "{key} {h}").unwrap();
        }
    }
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join(HASHES);
    if std::env::var_os("CUBE_UPDATE_HASHES").is_some() {
        std::fs::write(&path, &now).unwrap();
        return;
    }
    let committed = std::fs::read_to_string(&path).unwrap_or_else(|e| {
        panic!(
            "{}: {e}; write it with CUBE_UPDATE_HASHES=1 cargo test -p golden_model --test image_hashes",
            path.display()
        )
    });
    let was: std::collections::BTreeMap<&str, &str> = committed
        .lines()
        .filter_map(|l| l.split_once(' '))
        .collect();
    let mut changed = Vec::new();
    let mut new = Vec::new();
    for line in now.lines() {
        let (key, h) = line.split_once(' ').unwrap();
        match was.get(key) {
            Some(w) if *w == h => {}
            Some(_) => changed.push(key.to_string()),
            None => new.push(key.to_string()),
        }
    }
    assert!(
        changed.is_empty(),
        "{} of {} outputs changed: {}",
        changed.len(),
        was.len(),
        changed.join(", ")
    );
    assert!(
        new.is_empty() && was.len() == now.lines().count(),
        "the committed hashes cover another scene set (not committed: {})",
        new.join(", ")
    );
}

/// Every output is the same on 1 and 3 threads, on scenes tall enough that
/// the software splits their rows differently (Cube-3 sizes its scanline
/// runs by the thread count).
#[test]
fn outputs_do_not_depend_on_the_thread_count() {
    let view = |v: &str| {
        format!(
            r#"{{"volume": {{"builtin": "phantom", "dims": [64, 60, 56]}}, {v}, "mode": "composite", "image": [96, 96],
            "transfer": {{"opacity": [[0, 0.0], [50, 0.0], [80, 0.1], [150, 0.4], [255, 0.9]],
                          "color": [[0, 0.9, 0.6, 0.5], [255, 1.0, 1.0, 0.95]]}}}}"#
        )
    };
    for (name, json) in [
        (
            "oblique",
            view(r#""view": {"projection": "parallel", "rotate_deg": [25, 35, 0]}"#),
        ),
        (
            "perspective",
            view(
                r#""view": {"projection": "perspective", "eye": [-60, -30, -60], "target": [32, 30, 28], "fov_deg": 40}"#,
            ),
        ),
    ] {
        let on = |threads: usize| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap()
                .install(|| hashes(name, &json))
        };
        assert_eq!(on(1), on(3), "{name}");
    }
}
