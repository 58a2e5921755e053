//! The shared formulas of the `scene` crate against values derived by hand.
//!
//! The golden models and the float reference both read these formulas, so a
//! bug in them would cancel out of every error figure. Every expected value
//! below is a literal worked out by hand (derivation in the comment above it),
//! never a second call of the code under test.

use glam::DVec3;
use scene::lighting::phong;
use scene::transfer::{correct_opacity, piecewise, TransferFn};
use scene::volume::{builtin, from_raw, max_value};
use scene::{Camera, Mode, Projection, RawType, Scene, Shading, ViewSpec, Volume};
use std::path::{Path, PathBuf};

const EPS: f64 = 1e-12;

// sqrt(3), sqrt(48) = 4*sqrt(3), 1/sqrt(6), 2/sqrt(6) = 1/sqrt(1.5).
const SQRT3: f64 = 1.7320508075688772;
const SQRT48: f64 = 6.928203230275509;
const INV_SQRT6: f64 = 0.4082482904638631;
const TWO_INV_SQRT6: f64 = 0.8164965809277261;

fn close(got: f64, want: f64) {
    assert!(
        (got - want).abs() < EPS,
        "got {got:?}, want {want:?} (diff {:e})",
        got - want
    );
}

fn close3(got: DVec3, want: [f64; 3]) {
    let w = DVec3::from_array(want);
    assert!(
        (got - w).abs().max_element() < EPS,
        "got {got:?}, want {w:?}"
    );
}

// ---------------------------------------------------------------- piecewise

#[test]
fn piecewise_at_points_between_and_beyond_the_ends() {
    let p = [(10.0, 0.0), (20.0, 1.0), (40.0, 0.5)];
    // At the points themselves: their y.
    close(piecewise(&p, 10.0), 0.0);
    close(piecewise(&p, 20.0), 1.0);
    close(piecewise(&p, 40.0), 0.5);
    // 13 is 0.3 of the way from 10 to 20: 0 + 0.3 * (1 - 0) = 0.3.
    close(piecewise(&p, 13.0), 0.3);
    // 26 is 0.3 of the way from 20 to 40: 1 + 0.3 * (0.5 - 1) = 0.85.
    close(piecewise(&p, 26.0), 0.85);
    // 35 is 0.75 of the way from 20 to 40: 1 - 0.75 * 0.5 = 0.625.
    close(piecewise(&p, 35.0), 0.625);
    // Before the first point: the first y (0); after the last: the last y (0.5).
    close(piecewise(&p, -5.0), 0.0);
    close(piecewise(&p, 9.999), 0.0);
    close(piecewise(&p, 40.001), 0.5);
    close(piecewise(&p, 1e9), 0.5);
}

#[test]
fn piecewise_vertical_step() {
    // Ramp to 0.4 at x = 50, then a jump to 1 at the same x, flat after.
    let p = [(0.0, 0.0), (50.0, 0.4), (50.0, 1.0), (100.0, 1.0)];
    // 25 is half way from 0 to 50: 0.5 * 0.4 = 0.2.
    close(piecewise(&p, 25.0), 0.2);
    // Just left of the step: on the 0..50 segment, 0.4 * (50 - 1e-9) / 50 ~ 0.4.
    assert!((piecewise(&p, 50.0 - 1e-9) - 0.4).abs() < 1e-9);
    // Exactly at the step: the first segment ending at 50 takes it, so the
    // left value 0.4 (left-continuous convention).
    close(piecewise(&p, 50.0), 0.4);
    // Just right of the step: on the flat (50, 1)..(100, 1) segment -> 1.
    close(piecewise(&p, 50.0 + 1e-9), 1.0);
    close(piecewise(&p, 75.0), 1.0);

    // A step from the first point itself: x <= 0 gives the first y (0); just
    // above 0 the (0, 1)..(10, 1) segment gives 1.
    let q = [(0.0, 0.0), (0.0, 1.0), (10.0, 1.0)];
    close(piecewise(&q, 0.0), 0.0);
    close(piecewise(&q, 0.5), 1.0);
}

#[test]
fn piecewise_single_point_is_constant() {
    let p = [(7.0, 0.6)];
    // One point: its y before, at and after it.
    close(piecewise(&p, -100.0), 0.6);
    close(piecewise(&p, 7.0), 0.6);
    close(piecewise(&p, 300.0), 0.6);
}

// ---------------------------------------------------------------- transfer

fn scene_with_transfer(transfer: &str) -> Scene {
    let text = format!(
        r#"{{"volume": {{"builtin": "ramp", "dims": [4,4,4]}},
            "view": {{"projection": "parallel"}},
            "transfer": {transfer}}}"#
    );
    Scene::from_json(&text, None).unwrap()
}

#[test]
fn transfer_fn_from_scene_opacity_colour_gradient() {
    let s = scene_with_transfer(
        r#"{"opacity": [[0, 0], [100, 0], [200, 0.8]],
            "color": [[0, 1, 0, 0], [100, 0, 1, 0], [255, 0, 0, 1]],
            "gradient_opacity": [[0, 0.1], [20, 1], [30, 1]]}"#,
    );
    // opaque_threshold not given: default 0.5.
    close(s.transfer.opaque_threshold, 0.5);
    let t = TransferFn::new(&s);

    // Opacity: 0 up to 100; 130 is 0.3 of the way 100 -> 200: 0.3 * 0.8 = 0.24.
    close(t.opacity(50.0), 0.0);
    close(t.opacity(100.0), 0.0);
    close(t.opacity(130.0), 0.24);
    // 175 is 0.75 of the way: 0.75 * 0.8 = 0.6; beyond 200 it stays 0.8.
    close(t.opacity(175.0), 0.6);
    close(t.opacity(200.0), 0.8);
    close(t.opacity(255.0), 0.8);

    // Colour: 30 is 0.3 of the way from red (0) to green (100):
    // r = 1 - 0.3 = 0.7, g = 0.3, b = 0.
    close3(t.colour(30.0), [0.7, 0.3, 0.0]);
    // 177.5 is (177.5 - 100) / 155 = 0.5 of the way green -> blue: (0, 0.5, 0.5).
    close3(t.colour(177.5), [0.0, 0.5, 0.5]);
    // At the points and beyond the ends.
    close3(t.colour(0.0), [1.0, 0.0, 0.0]);
    close3(t.colour(100.0), [0.0, 1.0, 0.0]);
    close3(t.colour(255.0), [0.0, 0.0, 1.0]);

    // Gradient factor: 5 is 0.25 of the way 0 -> 20: 0.1 + 0.25 * 0.9 = 0.325.
    assert!(t.has_gradient_opacity());
    close(t.gradient_factor(5.0), 0.325);
    close(t.gradient_factor(0.0), 0.1);
    close(t.gradient_factor(25.0), 1.0);
    close(t.gradient_factor(1000.0), 1.0);
    // gradient_range: the largest magnitude named, 30.
    close(t.gradient_range(), 30.0);
}

#[test]
fn transfer_fn_without_gradient_opacity() {
    let s = scene_with_transfer(
        r#"{"opacity": [[0, 0.5]], "color": [[0, 0.2, 0.4, 0.6]], "opaque_threshold": 0.9}"#,
    );
    close(s.transfer.opaque_threshold, 0.9);
    let t = TransferFn::new(&s);
    // No gradient map: factor 1 everywhere, range 0.
    assert!(!t.has_gradient_opacity());
    close(t.gradient_factor(0.0), 1.0);
    close(t.gradient_factor(123.0), 1.0);
    close(t.gradient_range(), 0.0);
    // Single points: constant.
    close(t.opacity(0.0), 0.5);
    close(t.opacity(255.0), 0.5);
    close3(t.colour(77.0), [0.2, 0.4, 0.6]);
}

#[test]
fn default_transfer_is_the_bone_ramp() {
    let s = Scene::from_json(
        r#"{"volume": {"builtin": "sphere", "dims": [16,16,16]}, "view": {"projection": "parallel"}}"#,
        None,
    )
    .unwrap();
    let t = TransferFn::new(&s);
    // Default opacity: 0 up to 80, ramp to 0.75 at 100, flat to 255.
    close(t.opacity(80.0), 0.0);
    // 90 is half way 80 -> 100: 0.375; 95 is 0.75 of the way: 0.5625.
    close(t.opacity(90.0), 0.375);
    close(t.opacity(95.0), 0.5625);
    close(t.opacity(100.0), 0.75);
    close(t.opacity(255.0), 0.75);
    // Default colour: white everywhere.
    close3(t.colour(0.0), [1.0, 1.0, 1.0]);
    close3(t.colour(128.0), [1.0, 1.0, 1.0]);
    assert!(!t.has_gradient_opacity());
}

// ---------------------------------------------------------- correct_opacity

#[test]
fn opacity_correction_by_hand() {
    // 1 - (1 - 0.5)^2 = 1 - 0.25 = 0.75.
    close(correct_opacity(0.5, 2.0), 0.75);
    // 1 - 0.5^0.5 = 1 - 0.70710678118654752 = 0.29289321881345248.
    close(correct_opacity(0.5, 0.5), 0.2928932188134524);
    // 1 - 0.8^3 = 1 - 0.512 = 0.488.
    close(correct_opacity(0.2, 3.0), 0.488);
    // Spacing 1 is the identity: 1 - (1 - a) = a.
    close(correct_opacity(0.3, 1.0), 0.3);
    close(correct_opacity(0.37, 1.0), 0.37);
    close(correct_opacity(0.0, 1.0), 0.0);
    close(correct_opacity(1.0, 1.0), 1.0);
    // Spacing 0: 1 - (1 - a)^0 = 0.
    close(correct_opacity(0.6, 0.0), 0.0);
    // a clamped to [0, 1]: 1.5 -> 1 gives 1 - 0^s = 1; -0.2 -> 0 gives 1 - 1^s = 0.
    close(correct_opacity(1.5, 2.0), 1.0);
    close(correct_opacity(1.5, 0.5), 1.0);
    close(correct_opacity(-0.2, 2.0), 0.0);
    close(correct_opacity(-0.2, 0.5), 0.0);
}

// ------------------------------------------------------------------- phong

fn shading(ambient: f64, diffuse: f64, specular: f64, shininess: f64) -> Shading {
    Shading {
        enabled: true,
        light_dir: [0.0, 0.0, 1.0],
        ambient,
        diffuse,
        specular,
        shininess,
    }
}

#[test]
fn phong_normal_along_light_and_viewer() {
    let s = shading(0.2, 0.6, 0.3, 10.0);
    let z = DVec3::Z;
    // n = l = v: n.l = 1, h = z, n.h = 1:
    // diffuse = 0.2 + 0.6 * 1 = 0.8, specular = 0.3 * 1^10 = 0.3.
    let (d, sp) = phong(&s, z, z, z);
    close(d, 0.8);
    close(sp, 0.3);
}

#[test]
fn phong_clamps_to_one() {
    // ambient + diffuse = 0.5 + 0.8 = 1.3 -> clamped to 1;
    // specular 1 * 1^n = 1 (at the top of the range, not above).
    let s = shading(0.5, 0.8, 1.0, 7.0);
    let (d, sp) = phong(&s, DVec3::Z, DVec3::Z, DVec3::Z);
    close(d, 1.0);
    close(sp, 1.0);
    // A specular coefficient above 1 (not valid in a scene, but the struct is
    // public): 1.5 * 1 -> clamped to 1.
    let s = shading(0.5, 0.8, 1.5, 7.0);
    let (_, sp) = phong(&s, DVec3::Z, DVec3::Z, DVec3::Z);
    close(sp, 1.0);
}

#[test]
fn phong_sixty_degrees_and_half_vector() {
    // n = z, light 60 degrees off the normal in the xz plane:
    // l = (sin 60, 0, cos 60) = (sqrt3/2, 0, 1/2), v = z.
    let n = DVec3::Z;
    let l = DVec3::new(SQRT3 / 2.0, 0.0, 0.5);
    let v = DVec3::Z;
    // l + v = (sqrt3/2, 0, 3/2), length sqrt(3/4 + 9/4) = sqrt3,
    // h = (1/2, 0, sqrt3/2): 30 degrees off n, n.h = cos 30 = sqrt3/2.
    // Shininess 2: diffuse = 0.2 + 0.6 * 0.5 = 0.5;
    // specular = 0.3 * (sqrt3/2)^2 = 0.3 * 3/4 = 0.225.
    let (d, sp) = phong(&shading(0.2, 0.6, 0.3, 2.0), n, l, v);
    close(d, 0.5);
    close(sp, 0.225);
    // Shininess 10: (sqrt3/2)^10 = (3/4)^5 = 243/1024 = 0.2373046875;
    // specular = 0.3 * 0.2373046875 = 0.0711914062.
    let (d, sp) = phong(&shading(0.2, 0.6, 0.3, 10.0), n, l, v);
    close(d, 0.5);
    close(sp, 0.07119140625);
}

#[test]
fn phong_mirror_direction_gives_full_specular() {
    // n = z, l = (1,0,1)/sqrt2, v = (-1,0,1)/sqrt2: l + v = (0,0,sqrt2), h = z,
    // n.h = 1 -> specular = 0.3 * 1^10 = 0.3.
    // n.l = 1/sqrt2 -> diffuse = 0.2 + 0.6/sqrt2 = 0.2 + 0.42426406871192852
    // = 0.62426406871192852.
    let r = std::f64::consts::FRAC_1_SQRT_2;
    let (d, sp) = phong(
        &shading(0.2, 0.6, 0.3, 10.0),
        DVec3::Z,
        DVec3::new(r, 0.0, r),
        DVec3::new(-r, 0.0, r),
    );
    close(d, 0.6242640687119285);
    close(sp, 0.3);
}

#[test]
fn phong_light_behind_the_surface() {
    let s = shading(0.2, 0.6, 0.3, 10.0);
    // Light straight behind: n.l = -1 -> max(0) = 0: diffuse = ambient 0.2;
    // n.l <= 0 -> specular 0.
    let (d, sp) = phong(&s, DVec3::Z, DVec3::NEG_Z, DVec3::Z);
    close(d, 0.2);
    close(sp, 0.0);
    // Light 120 degrees off the normal: l = (sqrt3/2, 0, -1/2), n.l = -1/2.
    // h = normalize(l + v) = (sqrt3/2, 0, 1/2) has n.h = 1/2 > 0, yet the
    // light is behind the surface, so specular 0 and diffuse = ambient 0.2.
    let (d, sp) = phong(&s, DVec3::Z, DVec3::new(SQRT3 / 2.0, 0.0, -0.5), DVec3::Z);
    close(d, 0.2);
    close(sp, 0.0);
    // Grazing light (90 degrees): n.l = 0 -> diffuse 0.2, specular 0.
    let (d, sp) = phong(&s, DVec3::Z, DVec3::X, DVec3::Z);
    close(d, 0.2);
    close(sp, 0.0);
}

// ------------------------------------------------------------------ camera

fn parallel(rotate: [f64; 3], zoom: Option<f64>) -> ViewSpec {
    ViewSpec {
        projection: Projection::Parallel,
        rotate_deg: Some(rotate),
        eye: None,
        target: None,
        up: None,
        fov_deg: None,
        zoom,
    }
}

fn perspective(eye: [f64; 3], fov: Option<f64>) -> ViewSpec {
    ViewSpec {
        projection: Projection::Perspective,
        rotate_deg: None,
        eye: Some(eye),
        target: None,
        up: None,
        fov_deg: fov,
        zoom: None,
    }
}

#[test]
fn parallel_camera_unrotated() {
    let c = Camera::new(&parallel([0.0; 3], None), [4, 4, 4], [2, 2]).unwrap();
    // Centre of voxels 0..3 on each axis: 1.5.
    close3(c.origin, [1.5, 1.5, 1.5]);
    // No rotation: camera axes are the dataset axes, looking down -z.
    close3(c.forward, [0.0, 0.0, -1.0]);
    close3(c.right, [1.0, 0.0, 0.0]);
    close3(c.up, [0.0, 1.0, 0.0]);
    // diag = |(4,4,4)| = sqrt48 = 4 sqrt3; scale = diag / (min(2,2) * 1) = 2 sqrt3.
    close(c.scale, 2.0 * SQRT3);
    close(c.back, SQRT48);
    // Pixel (0,0): sx = 0 + 0.5 - 1 = -0.5, sy = 1 - 0.5 = +0.5.
    // origin = centre + right * (-0.5 * 2sqrt3) + up * (0.5 * 2sqrt3) - forward * 4sqrt3
    //        = (1.5 - sqrt3, 1.5 + sqrt3, 1.5 + 4 sqrt3); direction = forward.
    let (o, d) = c.ray(0, 0);
    close3(o, [1.5 - SQRT3, 1.5 + SQRT3, 1.5 + 4.0 * SQRT3]);
    close3(d, [0.0, 0.0, -1.0]);
    // Pixel (1,1): sx = +0.5, sy = -0.5 -> (1.5 + sqrt3, 1.5 - sqrt3, 1.5 + 4 sqrt3).
    let (o, _) = c.ray(1, 1);
    close3(o, [1.5 + SQRT3, 1.5 - SQRT3, 1.5 + 4.0 * SQRT3]);
    // Parallel: the viewer is -forward = +z wherever the point is.
    close3(c.to_viewer(DVec3::new(9.0, -3.0, 2.0)), [0.0, 0.0, 1.0]);
    // Camera space = dataset space here: (1,2,3) -> x*right + y*up - z*forward = (1,2,3).
    close3(
        c.camera_to_dataset(DVec3::new(1.0, 2.0, 3.0)),
        [1.0, 2.0, 3.0],
    );
}

#[test]
fn parallel_camera_zoom_and_wide_image() {
    // Zoom 2: scale = sqrt48 / (2 * 2) = sqrt3.
    let c = Camera::new(&parallel([0.0; 3], Some(2.0)), [4, 4, 4], [2, 2]).unwrap();
    close(c.scale, SQRT3);
    // Image 4 x 2: min side 2, scale = sqrt48 / 2 = 2 sqrt3.
    let c = Camera::new(&parallel([0.0; 3], None), [4, 4, 4], [4, 2]).unwrap();
    close(c.scale, 2.0 * SQRT3);
    // Pixel (3,0): sx = 3.5 - 2 = 1.5, sy = 1 - 0.5 = 0.5:
    // x = 1.5 + 1.5 * 2sqrt3 = 1.5 + 3sqrt3, y = 1.5 + sqrt3, z = 1.5 + 4sqrt3.
    let (o, _) = c.ray(3, 0);
    close3(o, [1.5 + 3.0 * SQRT3, 1.5 + SQRT3, 1.5 + 4.0 * SQRT3]);
    // Non-cubic dims [4, 6, 2]: centre (1.5, 2.5, 0.5);
    // diag = sqrt(16 + 36 + 4) = sqrt56, scale = sqrt56 / 2 = sqrt14 = 3.7416573867739413.
    let c = Camera::new(&parallel([0.0; 3], None), [4, 6, 2], [2, 2]).unwrap();
    close3(c.origin, [1.5, 2.5, 0.5]);
    close(c.scale, 3.7416573867739413);
}

#[test]
fn parallel_camera_rotated_90_about_y() {
    // Ry(90) = [[0,0,1],[0,1,0],[-1,0,0]], its transpose [[0,0,-1],[0,1,0],[1,0,0]].
    // forward = R^T (0,0,-1) = (1,0,0); right = R^T (1,0,0) = (0,0,1);
    // up = R^T (0,1,0) = (0,1,0).
    // Check: R (1,0,0) = (0,0,-1), world -z, where the camera looks.
    let c = Camera::new(&parallel([0.0, 90.0, 0.0], None), [4, 4, 4], [2, 2]).unwrap();
    close3(c.forward, [1.0, 0.0, 0.0]);
    close3(c.right, [0.0, 0.0, 1.0]);
    close3(c.up, [0.0, 1.0, 0.0]);
    // Rays start back along -forward: pixel (0,0) at
    // centre + right * (-sqrt3) + up * sqrt3 - forward * 4sqrt3
    // = (1.5 - 4sqrt3, 1.5 + sqrt3, 1.5 - sqrt3).
    let (o, d) = c.ray(0, 0);
    close3(o, [1.5 - 4.0 * SQRT3, 1.5 + SQRT3, 1.5 - SQRT3]);
    close3(d, [1.0, 0.0, 0.0]);
    // Viewer: -forward = (-1, 0, 0).
    close3(c.to_viewer(DVec3::ZERO), [-1.0, 0.0, 0.0]);
    // Camera (1,2,3): 1*(0,0,1) + 2*(0,1,0) - 3*(1,0,0) = (-3, 2, 1).
    close3(
        c.camera_to_dataset(DVec3::new(1.0, 2.0, 3.0)),
        [-3.0, 2.0, 1.0],
    );
}

#[test]
fn parallel_camera_rotated_90_about_x() {
    // Rx(90) = [[1,0,0],[0,0,-1],[0,1,0]], transpose [[1,0,0],[0,0,1],[0,-1,0]].
    // forward = R^T (0,0,-1) = (0,-1,0); right = (1,0,0); up = R^T (0,1,0) = (0,0,-1).
    let c = Camera::new(&parallel([90.0, 0.0, 0.0], None), [4, 4, 4], [2, 2]).unwrap();
    close3(c.forward, [0.0, -1.0, 0.0]);
    close3(c.right, [1.0, 0.0, 0.0]);
    close3(c.up, [0.0, 0.0, -1.0]);
}

#[test]
fn parallel_camera_rotation_order_is_x_then_z() {
    // rotate_deg [90, 0, 90]: world = Rz(90) Rx(90) dataset.
    // Rz(90) = [[0,-1,0],[1,0,0],[0,0,1]], Rz^T = [[0,1,0],[-1,0,0],[0,0,1]];
    // Rx^T = [[1,0,0],[0,0,1],[0,-1,0]].
    // forward = Rx^T Rz^T (0,0,-1) = Rx^T (0,0,-1) = (0,-1,0);
    // right   = Rx^T Rz^T (1,0,0) = Rx^T (0,-1,0) = (0,0,1);
    // up      = Rx^T Rz^T (0,1,0) = Rx^T (1,0,0) = (1,0,0).
    // (The other order, Rx Rz, would give forward (-1,0,0).)
    let c = Camera::new(&parallel([90.0, 0.0, 90.0], None), [4, 4, 4], [2, 2]).unwrap();
    close3(c.forward, [0.0, -1.0, 0.0]);
    close3(c.right, [0.0, 0.0, 1.0]);
    close3(c.up, [1.0, 0.0, 0.0]);
}

#[test]
fn perspective_camera_by_hand() {
    // Eye (1.5,1.5,-10), target the centre (1.5,1.5,1.5), up default +y, fov 90.
    let c = Camera::new(
        &perspective([1.5, 1.5, -10.0], Some(90.0)),
        [4, 4, 4],
        [2, 2],
    )
    .unwrap();
    // forward = normalize((0,0,11.5)) = (0,0,1);
    // right = forward x up = (0,0,1) x (0,1,0) = (0*0 - 1*1, 1*0 - 0*0, 0) = (-1,0,0);
    // up = right x forward = (-1,0,0) x (0,0,1) = (0, 1, 0).
    close3(c.forward, [0.0, 0.0, 1.0]);
    close3(c.right, [-1.0, 0.0, 0.0]);
    close3(c.up, [0.0, 1.0, 0.0]);
    close3(c.origin, [1.5, 1.5, -10.0]);
    // scale = tan(45 deg) / (2 / 2) = 1.
    close(c.scale, 1.0);
    // Pixel (1,1): sx = 0.5, sy = -0.5:
    // d = (0,0,1) + (-1,0,0) * 0.5 + (0,1,0) * (-0.5) = (-0.5, -0.5, 1),
    // |d| = sqrt(1.5); d / |d| = (-1/sqrt6, -1/sqrt6, 2/sqrt6).
    let (o, d) = c.ray(1, 1);
    close3(o, [1.5, 1.5, -10.0]);
    close3(d, [-INV_SQRT6, -INV_SQRT6, TWO_INV_SQRT6]);
    // Pixel (0,0): sx = -0.5, sy = 0.5: (0.5, 0.5, 1) / sqrt1.5.
    let (_, d) = c.ray(0, 0);
    close3(d, [INV_SQRT6, INV_SQRT6, TWO_INV_SQRT6]);
    // to_viewer: normalize(eye - p). p = (1.5,1.5,0): (0,0,-10)/10 = (0,0,-1).
    close3(c.to_viewer(DVec3::new(1.5, 1.5, 0.0)), [0.0, 0.0, -1.0]);
    // p = (4.5, 1.5, -6): eye - p = (-3, 0, -4), length 5 -> (-0.6, 0, -0.8).
    close3(c.to_viewer(DVec3::new(4.5, 1.5, -6.0)), [-0.6, 0.0, -0.8]);
    // camera_to_dataset: x -> right = (-1,0,0); z (towards viewer) -> -forward = (0,0,-1);
    // (1,2,3) -> (-1,0,0) + 2(0,1,0) - 3(0,0,1) = (-1, 2, -3).
    close3(c.camera_to_dataset(DVec3::X), [-1.0, 0.0, 0.0]);
    close3(c.camera_to_dataset(DVec3::Z), [0.0, 0.0, -1.0]);
    close3(
        c.camera_to_dataset(DVec3::new(1.0, 2.0, 3.0)),
        [-1.0, 2.0, -3.0],
    );
}

#[test]
fn perspective_camera_scale_and_wide_image() {
    // fov 60, height 2: scale = tan(30 deg) / 1 = 1/sqrt3 = 0.5773502691896258.
    let c = Camera::new(
        &perspective([1.5, 1.5, -10.0], Some(60.0)),
        [4, 4, 4],
        [2, 2],
    )
    .unwrap();
    close(c.scale, 0.5773502691896258);
    // Default fov 40, height 256: tan(20 deg) / 128 = 0.36397023426620234 / 128
    // = 0.002843517455204706.
    let c = Camera::new(&perspective([1.5, 1.5, -10.0], None), [4, 4, 4], [256, 256]).unwrap();
    close(c.scale, 0.002843517455204706);
    // fov 90, image 4 x 2: scale = 1 / (2/2) = 1; pixel (3,1): sx = 1.5, sy = -0.5:
    // d = (0,0,1) + (-1.5,0,0) + (0,-0.5,0) = (-1.5,-0.5,1), |d| = sqrt3.5:
    // (-0.8017837257372732, -0.2672612419124244, 0.5345224838248488).
    let c = Camera::new(
        &perspective([1.5, 1.5, -10.0], Some(90.0)),
        [4, 4, 4],
        [4, 2],
    )
    .unwrap();
    close(c.scale, 1.0);
    let (_, d) = c.ray(3, 1);
    close3(
        d,
        [-0.8017837257372732, -0.2672612419124244, 0.5345224838248488],
    );
}

// ------------------------------------------------------------ spec defaults

#[test]
fn scene_defaults() {
    let s = Scene::from_json(
        r#"{"volume": {"builtin": "sphere", "dims": [16,16,16]}, "view": {"projection": "parallel"}}"#,
        None,
    )
    .unwrap();
    assert_eq!(s.mode, Mode::Composite);
    assert_eq!(s.image, [256, 256]);
    assert_eq!(s.hardware.pipelines, 4);
    assert_eq!(s.hardware.voxel_bits, 8);
    assert_eq!(s.hardware.frac_bits, 8);
    assert_eq!(s.hardware.rgba_bits, 8);
    // The bone ramp.
    assert_eq!(
        s.transfer.opacity,
        vec![[0.0, 0.0], [80.0, 0.0], [100.0, 0.75], [255.0, 0.75]]
    );
    assert_eq!(
        s.transfer.color,
        vec![[0.0, 1.0, 1.0, 1.0], [255.0, 1.0, 1.0, 1.0]]
    );
    assert!(s.transfer.gradient_opacity.is_none());
    assert_eq!(s.transfer.opaque_threshold, 0.5);
    // Shading defaults.
    assert!(s.shading.enabled);
    // [0.3, 0.3, 1] as validated: a unit vector, divided by
    // sqrt(1.18) = 1.0862780491200215.
    let l = s.shading.light_dir;
    for (got, want) in l
        .iter()
        .zip([0.276172385369497, 0.276172385369497, 0.9205746178983233])
    {
        assert!((got - want).abs() < 1e-15, "{l:?}");
    }
    assert_eq!(s.shading.ambient, 0.2);
    assert_eq!(s.shading.diffuse, 0.6);
    assert_eq!(s.shading.specular, 0.3);
    assert_eq!(s.shading.shininess, 10.0);
    // Default camera: zoom 1, diag = 16 sqrt3, scale = 16 sqrt3 / 256 = sqrt3 / 16
    // = 0.10825317547305482; centre (7.5, 7.5, 7.5).
    let c = s.camera();
    close(c.scale, 0.10825317547305482);
    close3(c.origin, [7.5, 7.5, 7.5]);
    // Hardware given in part: the rest defaults.
    let s = Scene::from_json(
        r#"{"volume": {"builtin": "sphere", "dims": [16,16,16]}, "view": {"projection": "parallel"},
            "hardware": {"voxel_bits": 12}, "image": [64, 32]}"#,
        None,
    )
    .unwrap();
    assert_eq!(s.hardware.voxel_bits, 12);
    assert_eq!(s.hardware.pipelines, 4);
    assert_eq!(s.hardware.frac_bits, 8);
    assert_eq!(s.hardware.rgba_bits, 8);
    assert_eq!(s.image, [64, 32]);
}

#[test]
fn max_value_is_two_to_the_bits_minus_one() {
    // 2^8 - 1 = 255, 2^12 - 1 = 4095, 2^16 - 1 = 65535.
    assert_eq!(max_value(8), 255);
    assert_eq!(max_value(12), 4095);
    assert_eq!(max_value(16), 65535);
    let v = builtin("empty", [2, 2, 2], 12).unwrap();
    assert_eq!(v.max_value(), 4095);
}

// ------------------------------------------------------------- raw volumes

/// A fresh folder under the system temp dir, removed on drop.
struct TempDir(PathBuf);

impl TempDir {
    fn new(tag: &str) -> TempDir {
        let nanos = std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .unwrap()
            .as_nanos();
        let p = std::env::temp_dir().join(format!(
            "cube-scene-formulas-{tag}-{}-{nanos}",
            std::process::id()
        ));
        std::fs::create_dir_all(&p).unwrap();
        TempDir(p)
    }

    fn path(&self) -> &Path {
        &self.0
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// Raw little-endian i16 values, encoded by hand:
/// -1000 = 65536 - 1000 = 64536 = 0xFC18; -100 = 65436 = 0xFF9C; 0; 100 = 0x0064;
/// 200 = 0x00C8; 333 = 0x014D; 400 = 0x0190; 32767 = 0x7FFF.
const I16_BYTES: [u8; 16] = [
    0x18, 0xFC, 0x9C, 0xFF, 0x00, 0x00, 0x64, 0x00, 0xC8, 0x00, 0x4D, 0x01, 0x90, 0x01, 0xFF, 0x7F,
];

fn json_path(p: &Path) -> String {
    // The path as a JSON string (escape backslashes for Windows paths).
    p.display().to_string().replace('\\', "\\\\")
}

#[test]
fn raw_i16_window_via_scene() {
    let dir = TempDir::new("i16");
    let raw = dir.path().join("vol.raw");
    std::fs::write(&raw, I16_BYTES).unwrap();
    for (bits, want) in [
        // window [-100, 400], hi - lo = 500; (r - lo)/500 clamped, times 2^bits - 1:
        // -1000 -> below lo -> 0; -100 -> 0; 0 -> 100/500 = 0.2; 100 -> 0.4;
        // 200 -> 0.6; 333 -> 433/500 = 0.866; 400 -> 1; 32767 -> above hi -> 1.
        // bits 8: 0.2*255 = 51, 0.4*255 = 102, 0.6*255 = 153,
        // 0.866*255 = 220.83 -> 221, 255.
        (8u32, [0u16, 0, 51, 102, 153, 221, 255, 255]),
        // bits 12: 0.2*4095 = 819, 0.4*4095 = 1638, 0.6*4095 = 2457,
        // 0.866*4095 = 3546.27 -> 3546, 4095.
        (12, [0, 0, 819, 1638, 2457, 3546, 4095, 4095]),
    ] {
        let text = format!(
            r#"{{"volume": {{"raw": "{}", "type": "i16", "dims": [2,2,2], "window": [-100, 400]}},
                "view": {{"projection": "parallel"}},
                "hardware": {{"voxel_bits": {bits}}}}}"#,
            json_path(&raw)
        );
        let s = Scene::from_json(&text, None).unwrap();
        assert_eq!(s.volume.kind, Some(RawType::I16));
        let v = Volume::from_spec(&s.volume, s.hardware.voxel_bits).unwrap();
        assert_eq!(v.dims, [2, 2, 2]);
        assert_eq!(v.bits, bits);
        assert_eq!(v.data, want.to_vec(), "bits {bits}");
        // x fastest: (u,v,w) = (1,0,1) is index 1 + 2*(0 + 2*1) = 5 -> raw 333.
        assert_eq!(v.get(1, 0, 1), want[5]);
        // (0,1,0) is index 0 + 2*(1 + 0) = 2 -> raw 0.
        assert_eq!(v.get(0, 1, 0), want[2]);
    }
}

#[test]
fn raw_u8_window_relative_to_the_scene_file() {
    let dir = TempDir::new("u8");
    // u8 values, window [10, 60] (hi - lo = 50):
    // 0 -> 0; 10 -> 0; 20 -> 0.2*255 = 51; 30 -> 0.4 -> 102; 40 -> 0.6 -> 153;
    // 50 -> 0.8 -> 204; 60 -> 1 -> 255; 255 -> clamped -> 255.
    std::fs::write(
        dir.path().join("vol.raw"),
        [0u8, 10, 20, 30, 40, 50, 60, 255],
    )
    .unwrap();
    let scene_path = dir.path().join("scene.json");
    std::fs::write(
        &scene_path,
        r#"{"volume": {"raw": "vol.raw", "type": "u8", "dims": [2,2,2], "window": [10, 60]},
            "view": {"projection": "parallel"}}"#,
    )
    .unwrap();
    let s = Scene::load(&scene_path).unwrap();
    // The relative raw path is resolved against the scene file's folder.
    assert_eq!(
        s.volume.raw.as_deref(),
        Some(dir.path().join("vol.raw").as_path())
    );
    let v = Volume::from_spec(&s.volume, s.hardware.voxel_bits).unwrap();
    assert_eq!(v.data, vec![0, 0, 51, 102, 153, 204, 255, 255]);
}

#[test]
fn raw_without_window_takes_values_as_they_are() {
    // u16 little endian: [0x2C, 0x01] = 0x012C = 300; [0xFF, 0x0F] = 0x0FFF = 4095.
    let v = from_raw(&[0x2C, 0x01, 0xFF, 0x0F], [2, 1, 1], RawType::U16, None, 12).unwrap();
    assert_eq!(v.data, vec![300, 4095]);
    // 300 does not fit in 8 bits (max 255) without a window.
    assert!(from_raw(&[0x2C, 0x01], [1, 1, 1], RawType::U16, None, 8).is_err());
    // i16 window straight through from_raw, 16 bits: window [0, 3], hi - lo = 3:
    // raw 1 -> 1/3 * 65535 = 21845; raw 2 -> 2/3 * 65535 = 43690; raw -1 -> 0; 3 -> 65535.
    let b: Vec<u8> = vec![0x01, 0x00, 0x02, 0x00, 0xFF, 0xFF, 0x03, 0x00];
    let v = from_raw(&b, [4, 1, 1], RawType::I16, Some([0.0, 3.0]), 16).unwrap();
    assert_eq!(v.data, vec![21845, 43690, 0, 65535]);
}

// ------------------------------------------------------------------- crops

#[test]
fn crop_of_builtin_ramp_via_scene() {
    // ramp, dims [6,3,2], 8 bits: value round(x / 5 * 255) = 0, 51, 102, 153, 204, 255.
    let s = Scene::from_json(
        r#"{"volume": {"builtin": "ramp", "dims": [6,3,2],
                       "crop": {"offset": [2,1,0], "dims": [3,2,2]}},
            "view": {"projection": "parallel"}}"#,
        None,
    )
    .unwrap();
    assert_eq!(s.volume.render_dims(), [3, 2, 2]);
    let whole = builtin("ramp", [6, 3, 2], 8).unwrap();
    assert_eq!(&whole.data[0..6], &[0, 51, 102, 153, 204, 255]);
    let v = Volume::from_spec(&s.volume, 8).unwrap();
    assert_eq!(v.dims, [3, 2, 2]);
    // x = 2, 3, 4 on each of the 2 x 2 rows: 102, 153, 204.
    assert_eq!(
        v.data,
        vec![102, 153, 204, 102, 153, 204, 102, 153, 204, 102, 153, 204]
    );
    // The camera sees the crop: centre ((3-1)/2, (2-1)/2, (2-1)/2) = (1, 0.5, 0.5).
    close3(s.camera().origin, [1.0, 0.5, 0.5]);
}

#[test]
fn crop_of_raw_volume() {
    let dir = TempDir::new("crop");
    let raw = dir.path().join("idx.raw");
    // dims [3,3,2], each voxel holds its own index u + 3*(v + 3*w), 0..17.
    std::fs::write(&raw, (0u8..18).collect::<Vec<u8>>()).unwrap();
    // A crop side must be >= 2: the 2 x 2 x 2 box at offset [1,1,0].
    let text = format!(
        r#"{{"volume": {{"raw": "{}", "type": "u8", "dims": [3,3,2],
                         "crop": {{"offset": [1,1,0], "dims": [2,2,2]}}}},
            "view": {{"projection": "parallel"}}}}"#,
        json_path(&raw)
    );
    let s = Scene::from_json(&text, None).unwrap();
    let v = Volume::from_spec(&s.volume, 8).unwrap();
    assert_eq!(v.dims, [2, 2, 2]);
    // u in {1,2}, v in {1,2}, w in {0,1}, index u + 3*(v + 3w), x fastest:
    // w=0 v=1: 1+3 = 4, 5;  w=0 v=2: 1+6 = 7, 8;
    // w=1 v=1: 1+12 = 13, 14;  w=1 v=2: 1+15 = 16, 17.
    assert_eq!(v.data, vec![4, 5, 7, 8, 13, 14, 16, 17]);
    // Crop (1,0,1) is whole (2,1,1): 2 + 3*(1 + 3) = 14.
    assert_eq!(v.get(1, 0, 1), 14);
    // A crop side of 1 is rejected by the scene.
    let bad = text.replace(r#""dims": [2,2,2]"#, r#""dims": [2,1,2]"#);
    assert!(Scene::from_json(&bad, None).is_err());
}
