//! The shader and classifier (`common::shader`) at Cube-4L's voxels, on
//! hand-built tables, where every output can be worked out by hand, and on
//! tables built from scenes.

use golden_model::common::gradient::quantize_normal;
use golden_model::common::shader::{Sample, Shader};
use golden_model::cube4l::plan::{Control, Face, Plan};
use golden_model::lut::{ColourLut, Lighting, OpacityLut};
use scene::{Mode, Scene};

/// A voxel in the middle of the volume on a valid ray.
fn inside() -> Control {
    Control {
        dx: 0,
        dy: 0,
        sr: false,
        er: false,
        invalid: false,
        edge: false,
        face: Face::None,
    }
}

fn edge() -> Control {
    Control {
        edge: true,
        ..inside()
    }
}

fn invalid() -> Control {
    Control {
        invalid: true,
        ..inside()
    }
}

/// The shader at a voxel with control bits `c`.
fn sample(s: &Shader, v: u32, c: &Control, gradient: impl FnOnce() -> [i32; 3]) -> Sample {
    s.sample(v, c.invalid, c.edge, gradient)
}

fn transparent(s: &Shader, v: u32, c: &Control) -> bool {
    s.transparent(v, c.invalid, c.edge)
}

/// A gradient that must not be asked for.
fn no_gradient() -> [i32; 3] {
    panic!("gradient computed")
}

/// 8-bit voxels and colour. Opacity `v` for `v >= 10`, 0 below (those rows
/// are transparent); colour `[v, 255 - v, 40]`; unlit; threshold 128.
fn shader(mode: Mode) -> Shader {
    let table: Vec<u32> = (0..256).map(|v| if v < 10 { 0 } else { v }).collect();
    let has_opacity = matches!(mode, Mode::Composite | Mode::FirstOpaque | Mode::Xray);
    Shader {
        mode,
        rgba_bits: 8,
        voxel_bits: 8,
        sample_frac: 0,
        gradient_bits: 9,
        colour: mode.uses_colour().then(|| ColourLut {
            shift: 0,
            table: (0..256).map(|v| [v, 255 - v, 40]).collect(),
        }),
        opacity: has_opacity.then(|| OpacityLut {
            shift: 0,
            gm_shift: None,
            row_max: table.clone(),
            table,
        }),
        lighting: None,
        needs_gradient: false,
        threshold: 128,
    }
}

/// As [`shader`], with lighting (so gradients are needed) that is
/// ambient-only `[64, 0]` except at two quantized normals. The light and
/// half-vector registers are both `(2048, 0, -2048)`: normal (15, -4, 0)
/// has dot product 30720 and rnorm(241) = 2111 (32768 / 15.524), so
/// t = 64 849 920 and its cosine index is (t * 1023 + 2^25) >> 26 = 989;
/// normal (0, 0, -9) has dot 18432, rnorm(81) = 3641, index 1023 (clamped).
fn lit_shader(mode: Mode) -> Shader {
    let (mut diffuse, mut specular) = (vec![64; 1024], vec![0; 1024]);
    (diffuse[989], specular[989]) = (128, 40);
    (diffuse[1023], specular[1023]) = (255, 200);
    let d = [2048, 0, -2048];
    assert_eq!(Lighting::cos_index([15, -4, 0], d, 5), (989, true));
    assert_eq!(Lighting::cos_index([0, 0, -9], d, 5), (1023, true));
    Shader {
        lighting: Some(Lighting::from_registers(d, d, diffuse, specular, 5)),
        needs_gradient: true,
        ..shader(mode)
    }
}

fn value(s: &Shader, v: u32, c: &Control, g: [i32; 3]) -> [u32; 4] {
    let out = sample(s, v, c, || g);
    assert!(out.valid);
    out.value
}

#[test]
fn transparency_before_the_gradient() {
    for mode in [Mode::Mip, Mode::Minip] {
        let s = shader(mode);
        for c in [inside(), edge(), invalid()] {
            for v in [0, 5, 200] {
                assert!(!transparent(&s, v, &c), "{mode:?} {v} {c:?}");
            }
        }
    }
    for mode in [Mode::Composite, Mode::FirstOpaque, Mode::Xray] {
        let s = shader(mode);
        // Zero opacity row.
        assert!(transparent(&s, 5, &inside()));
        assert!(transparent(&s, 0, &inside()));
        assert!(!transparent(&s, 10, &inside()));
        assert!(!transparent(&s, 200, &inside()));
        // Invalid rays contribute nothing.
        assert!(transparent(&s, 200, &invalid()));
        // An edge voxel is fine when no gradient is needed.
        assert!(!transparent(&s, 200, &edge()));
    }
    for mode in [Mode::Composite, Mode::FirstOpaque] {
        let s = lit_shader(mode);
        // With gradients, an edge voxel (no valid gradient) is skipped.
        assert!(transparent(&s, 200, &edge()));
        assert!(transparent(&s, 200, &invalid()));
        assert!(transparent(&s, 5, &inside()));
        assert!(!transparent(&s, 200, &inside()));
    }
}

#[test]
fn mip_and_minip_pass_the_intensity() {
    for mode in [Mode::Mip, Mode::Minip] {
        let s = shader(mode);
        let out = sample(&s, 77, &inside(), no_gradient);
        assert_eq!(
            out,
            Sample {
                value: [77, 0, 0, 0],
                valid: true
            }
        );
        // Low intensities are not classified away.
        assert_eq!(sample(&s, 3, &inside(), no_gradient).value, [3, 0, 0, 0]);
        let out = sample(&s, 77, &invalid(), no_gradient);
        assert!(!out.valid);
        assert_eq!(out.value, [77, 0, 0, 0]);
        // 16-bit intensities go through whole.
        let s = Shader {
            voxel_bits: 16,
            ..shader(mode)
        };
        assert_eq!(
            sample(&s, 65535, &edge(), no_gradient).value,
            [65535, 0, 0, 0]
        );
    }
}

#[test]
fn xray_passes_the_opacity() {
    let s = shader(Mode::Xray);
    assert_eq!(value(&s, 100, &inside(), [0; 3]), [100, 0, 0, 0]);
    assert_eq!(value(&s, 255, &edge(), [0; 3]), [255, 0, 0, 0]);
    assert_eq!(value(&s, 5, &inside(), [0; 3]), [0; 4]);
    assert_eq!(value(&s, 100, &invalid(), [0; 3]), [0; 4]);
}

#[test]
fn composite_weights_colour_by_opacity() {
    let s = shader(Mode::Composite);
    // alpha 100, colour (100, 155, 40), unlit: round(c * 100 / 255) =
    // 39.2 -> 39, 60.8 -> 61, 15.7 -> 16.
    assert_eq!(
        sample(&s, 100, &inside(), no_gradient),
        Sample {
            value: [39, 61, 16, 100],
            valid: true
        }
    );
    // alpha 128 passes as is (no threshold outside first-opaque):
    // 128 * 128 / 255 = 64.25, 127 * 128 / 255 = 63.75, 40 * 128 / 255 = 20.1.
    assert_eq!(value(&s, 128, &inside(), [0; 3]), [64, 64, 20, 128]);
    // Full opacity leaves the colour.
    assert_eq!(value(&s, 255, &inside(), [0; 3]), [255, 0, 40, 255]);
    // Transparent and invalid voxels.
    assert_eq!(value(&s, 9, &inside(), [0; 3]), [0; 4]);
    assert_eq!(value(&s, 200, &invalid(), [0; 3]), [0; 4]);
    // No gradient needed: edge voxels shade as usual.
    assert_eq!(value(&s, 255, &edge(), [0; 3]), [255, 0, 40, 255]);
}

#[test]
fn composite_with_lighting() {
    let s = lit_shader(Mode::Composite);
    assert_eq!(quantize_normal([30, -8, 0], 5), [15, -4, 0]);
    // v = 200: alpha 200, colour (200, 55, 40), [d, s] = [128, 40]:
    // shaded = round(c * 128 / 255) + 40 = 100 + 40, 28 + 40, 20 + 40;
    // weighted = round(shaded * 200 / 255) = 109.8 -> 110, 53.3 -> 53,
    // 47.1 -> 47.
    assert_eq!(value(&s, 200, &inside(), [30, -8, 0]), [110, 53, 47, 200]);
    // [d, s] = [255, 200] at full opacity: 255 + 200 saturates to 255,
    // 0 + 200, 40 + 200.
    assert_eq!(value(&s, 255, &inside(), [0, 0, -9]), [255, 200, 240, 255]);
    // Ambient only, [64, 0]: round(200 * 64 / 255) = 50.2 -> 50, then
    // round(50 * 200 / 255) = 39.2 -> 39; 55 -> 13.8 -> 14 -> 11;
    // 40 -> 10.04 -> 10 -> 7.8 -> 8.
    assert_eq!(value(&s, 200, &inside(), [1, 2, 3]), [39, 11, 8, 200]);
    // Transparent voxels and edge voxels are not shaded (no gradient asked).
    assert_eq!(value(&s, 5, &inside(), [0; 3]), [0; 4]);
    assert_eq!(sample(&s, 200, &edge(), no_gradient).value, [0; 4]);
    assert_eq!(sample(&s, 200, &invalid(), no_gradient).value, [0; 4]);
}

#[test]
fn first_opaque_thresholds_the_opacity() {
    let s = shader(Mode::FirstOpaque);
    // Below the threshold: nothing.
    assert_eq!(value(&s, 100, &inside(), [0; 3]), [0; 4]);
    assert_eq!(value(&s, 127, &inside(), [0; 3]), [0; 4]);
    // At and above it: fully opaque, unweighted colour.
    assert_eq!(value(&s, 128, &inside(), [0; 3]), [128, 127, 40, 255]);
    assert_eq!(value(&s, 200, &inside(), [0; 3]), [200, 55, 40, 255]);
    // With lighting: shaded colour at full opacity.
    let s = lit_shader(Mode::FirstOpaque);
    assert_eq!(value(&s, 200, &inside(), [30, -8, 0]), [140, 68, 60, 255]);
    assert_eq!(value(&s, 100, &inside(), [30, -8, 0]), [0; 4]);
}

#[test]
fn gradient_magnitude_indexes_the_opacity() {
    // Opacity rows of 16 gradient bins, index gm >> 2: entry (v, g) = 16 g
    // for v >= 10 (so bin 0 is transparent).
    let mut table = Vec::new();
    for v in 0..256u32 {
        table.extend((0..16u32).map(|g| if v < 10 { 0 } else { 16 * g }));
    }
    let row_max = (0..256).map(|v| if v < 10 { 0 } else { 240 }).collect();
    let s = Shader {
        opacity: Some(OpacityLut {
            shift: 0,
            gm_shift: Some(2),
            table,
            row_max,
        }),
        needs_gradient: true,
        ..shader(Mode::Composite)
    };
    // |(3, 4, 0)| = 5 -> bin 1 -> alpha 16: colour (255, 0, 40) ->
    // round(255 * 16 / 255) = 16, 0, round(40 * 16 / 255) = 2.5 -> 3.
    assert_eq!(value(&s, 255, &inside(), [3, 4, 0]), [16, 0, 3, 16]);
    // |(30, -8, 0)| = 31 -> bin 7 -> alpha 112.
    assert_eq!(value(&s, 255, &inside(), [30, -8, 0]), [112, 0, 18, 112]);
    // A flat neighbourhood: bin 0, alpha 0.
    assert_eq!(value(&s, 255, &inside(), [0, 0, 0]), [0; 4]);
}

fn scene(extra: &str) -> Scene {
    let text = format!(
        r#"{{"volume": {{"builtin": "sphere", "dims": [8, 8, 8]}},
            "view": {{"projection": "parallel", "rotate_deg": [30, 20, 0]}},
            "image": [8, 8] {extra}}}"#
    );
    Scene::from_json(&text, None).unwrap()
}

fn shader_of(scene: &Scene) -> (Shader, f64) {
    let camera = scene.camera();
    let plan = Plan::new(scene, &camera).unwrap();
    let sweep = &plan.sweeps[0];
    (Shader::new(scene, &camera, sweep), sweep.spacing)
}

#[test]
fn shader_units_follow_the_scene() {
    let (s, spacing) = shader_of(&scene(""));
    assert!(spacing > 1.05, "an oblique view: {spacing}");
    assert!(s.needs_gradient && s.lighting.is_some());
    assert_eq!(s.threshold, 128);
    let op = s.opacity.as_ref().unwrap();
    assert_eq!(op.gm_shift, None);
    // Default opacity 0.75 from intensity 100 on, corrected for the spacing.
    let want = 1.0 - 0.25f64.powf(spacing);
    assert_eq!(op.table[200], (want * 255.0).round() as u32);
    assert!(op.table[200] > 191);
    assert_eq!(op.table[50], 0);
    assert_eq!(s.colour.as_ref().unwrap().table[200], [255, 255, 255]);

    let (s, _) = shader_of(&scene(r#", "shading": {"enabled": false}"#));
    assert!(!s.needs_gradient && s.lighting.is_none());

    // First-opaque: opacities are not corrected for the spacing.
    let (s, _) = shader_of(&scene(
        r#", "mode": "first_opaque", "transfer": {"opacity": [[0, 0], [100, 0.75]],
            "color": [[0, 1, 1, 1]], "opaque_threshold": 0.25}"#,
    ));
    assert_eq!(s.threshold, 64);
    assert_eq!(s.opacity.as_ref().unwrap().table[200], 191);

    let (s, _) = shader_of(&scene(r#", "mode": "xray""#));
    assert!(!s.needs_gradient && s.colour.is_none() && s.lighting.is_none());
    assert_eq!(s.opacity.as_ref().unwrap().table[200], 191);

    for mode in ["mip", "minip"] {
        let (s, _) = shader_of(&scene(&format!(r#", "mode": "{mode}""#)));
        assert!(s.opacity.is_none() && s.colour.is_none() && !s.needs_gradient);
    }

    // Gradient opacity adds the gradient unit even without shading.
    let (s, _) = shader_of(&scene(
        r#", "shading": {"enabled": false}, "transfer": {"opacity": [[0, 1]],
            "color": [[0, 1, 1, 1]], "gradient_opacity": [[0, 0], [50, 1]]}"#,
    ));
    assert!(s.needs_gradient && s.lighting.is_none());
    assert_eq!(s.opacity.as_ref().unwrap().gm_shift, Some(4)); // 200: 8 bits
}
