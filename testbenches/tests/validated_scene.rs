//! A scene is validated once, and every renderer reads what was validated:
//! a light direction at the edge of the floating-point range renders as
//! its unit vector, in every renderer of the kit, instead of overflowing to
//! an ambient-only image.

use golden_model::quantized::Method;
use reference::true3d::Interp;
use scene::{Image, Scene, Volume};

fn scene(light: &str) -> Scene {
    Scene::from_json(
        &format!(
            r#"{{"volume": {{"builtin": "sphere", "dims": [16, 16, 16]}},
            "view": {{"projection": "parallel", "rotate_deg": [20, 30, 0]}},
            "shading": {{"enabled": true, "light_dir": {light}, "specular": 0.4}},
            "image": [24, 24]}}"#
        ),
        None,
    )
    .unwrap_or_else(|e| panic!("{light}: {e}"))
}

/// Every renderer's image of the scene.
fn images(s: &Scene) -> Vec<(&'static str, Image)> {
    let vol = Volume::from_spec(&s.volume, s.hardware.voxel_bits).unwrap();
    let cam = s.camera();
    let n = golden_model::cube3::neighbourhood(s, None).unwrap();
    vec![
        (
            "cube4l",
            golden_model::cube4l::render_image(s, &vol).unwrap().0,
        ),
        (
            "cube3",
            golden_model::cube3::render_image(s, &vol, n).unwrap().0,
        ),
        (
            "quantized",
            golden_model::quantized::render(s, &vol, Method::Projection)
                .unwrap()
                .0,
        ),
        ("reference", reference::render(s, &cam, &vol, 0.5)),
        (
            "true3d",
            reference::true3d::render(s, &cam, &vol, 12, Interp::Exact).unwrap(),
        ),
    ]
}

#[test]
fn extreme_light_directions_render_as_their_unit_vectors() {
    for (extreme, unit) in [
        ("[0, 0, 1e200]", "[0, 0, 1]"),
        ("[0, 0, 1e-200]", "[0, 0, 1]"),
        ("[1e-320, 0, 0]", "[1, 0, 0]"),
        ("[-1e308, 0, 0]", "[-1, 0, 0]"),
    ] {
        let (a, b) = (scene(extreme), scene(unit));
        assert_eq!(a.shading.light_dir, b.shading.light_dir, "{extreme}");
        for ((name, x), (_, y)) in images(&a).into_iter().zip(images(&b)) {
            assert_eq!(x.rgb, y.rgb, "{name}: light {extreme} against {unit}");
        }
    }
}

#[test]
fn a_light_of_mixed_extreme_components_is_not_ambient_only() {
    // [3e200, -1e250, 2e300] once overflowed to a NaN light: ambient only.
    let s = scene("[3e200, -1e250, 2e300]");
    let l = s.shading.light_dir;
    let len = (l[0] * l[0] + l[1] * l[1] + l[2] * l[2]).sqrt();
    assert!((len - 1.0).abs() < 1e-15, "{l:?}");
    let lit = images(&scene("[0, 0, 1]"));
    let unlit = images(
        &scene("[0, 0, 1]")
            .with(|s| s.shading.diffuse = 0.0)
            .unwrap(),
    );
    for ((name, x), ((_, y), (_, z))) in images(&s).into_iter().zip(lit.iter().zip(&unlit)) {
        assert!(
            x.rgb.iter().all(|p| p.iter().all(|c| c.is_finite())),
            "{name}"
        );
        // The light is [1.5e-100, -5e-51, 1]: as lit as [0, 0, 1], not dark.
        assert_ne!(x.rgb, z.rgb, "{name}: ambient only");
        let diff = x
            .rgb
            .iter()
            .zip(&y.rgb)
            .map(|(p, q)| (0..3).map(|c| (p[c] - q[c]).abs()).fold(0.0, f64::max))
            .fold(0.0, f64::max);
        assert!(diff < 1e-9, "{name}: {diff}");
    }
}
