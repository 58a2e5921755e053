//! View planning (Cube-4L §3.1, Fig. 7): which sweeps a view needs, and for
//! each the pipeline coordinate system, the compositing order and the sight
//! ray increments dx = S_x/S_z, dy = S_y/S_z of every voxel.
//!
//! Pipeline space is a cyclic permutation of dataset space with z along the
//! major axis, so it stays right handed. Every sweep walks z upwards. A view
//! point below the swept slab composites front to back, one above it back to
//! front (§3.5). Parallel views need one sweep. A perspective view gets one
//! sweep per (major axis, direction) that some pixel's ray has; each covers
//! the slices on the ray's side of the eye.

use super::caveat::Caveat;
use crate::common::plan::{dominant_axis, ray_sums, Order};
use crate::common::shader::ShadedPlane;
use crate::fixed::{quantize, round_div};
use glam::{DMat3, DVec3};
use scene::{Camera, Projection, Scene};
use scene::{CubeError, Result};

/// Sight-ray increments of a sweep.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Rays {
    /// One `(dx, dy)` for the frame, fixed point with `frac_bits`: frame registers.
    Parallel { dx: i32, dy: i32 },
    /// Eye in pipeline coordinates, fixed point with `frac_bits`; dx and dy come
    /// from the per-voxel divider.
    Perspective { eye: [i64; 3] },
}

/// The face of the swept box through which a compositing-buffer cell's ray
/// leaves: where its pixel goes out on ER.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[repr(u8)]
pub enum Face {
    None = 0,
    Last = 1,
    XPos = 2,
    XNeg = 3,
    YPos = 4,
    YNeg = 5,
}

/// Per-voxel control produced by the CFB.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Control {
    /// Sight-ray increments, fixed point; clamped to [-1, 1] on invalid voxels.
    pub dx: i32,
    pub dy: i32,
    /// Start of ray: the compositing buffer input is reset.
    pub sr: bool,
    /// End of ray: the cell's pixel goes out to the base plane.
    pub er: bool,
    /// The sight ray is beyond 45 degrees (or the voxel lies in the eye's plane).
    pub invalid: bool,
    /// A direct neighbour lies outside the dataset, so the gradient is invalid.
    pub edge: bool,
    pub face: Face,
}

#[derive(Debug, Clone)]
pub struct Sweep {
    /// Pipeline axis `i` is dataset axis `perm[i]`; `perm[2]` is the major axis.
    pub perm: [usize; 3],
    /// Pipeline-space dims `[nx, ny, nz]` of the whole dataset.
    pub dims: [usize; 3],
    /// Slices swept, inclusive.
    pub z0: usize,
    pub z1: usize,
    pub order: Order,
    pub rays: Rays,
    pub frac: u32,
    /// Sample spacing of the sweep's central ray, in voxel lengths.
    pub spacing: f64,
    /// Mean viewing direction (eye to volume) in dataset space.
    pub view_dir: DVec3,
}

impl Sweep {
    fn new(axis: usize, dims: [usize; 3], frac: u32) -> Sweep {
        let perm = [(axis + 1) % 3, (axis + 2) % 3, axis];
        Sweep {
            perm,
            dims: [dims[perm[0]], dims[perm[1]], dims[perm[2]]],
            z0: 0,
            z1: dims[axis] - 1,
            order: Order::FrontToBack,
            rays: Rays::Parallel { dx: 0, dy: 0 },
            frac,
            spacing: 1.0,
            view_dir: DVec3::Z,
        }
    }

    pub fn axis(&self) -> usize {
        self.perm[2]
    }

    /// Matrix taking dataset vectors to pipeline vectors.
    pub fn to_pipeline(&self) -> DMat3 {
        let row = |a: usize| DVec3::from_array(std::array::from_fn(|i| (i == a) as u8 as f64));
        DMat3::from_cols(row(self.perm[0]), row(self.perm[1]), row(self.perm[2])).transpose()
    }

    pub fn to_dataset(&self) -> DMat3 {
        self.to_pipeline().transpose()
    }

    /// Dataset coordinates of pipeline position `(x, y, z)`.
    pub fn dataset(&self, x: usize, y: usize, z: usize) -> [usize; 3] {
        let mut d = [0; 3];
        d[self.perm[0]] = x;
        d[self.perm[1]] = y;
        d[self.perm[2]] = z;
        d
    }

    /// Depth of the base-plane border on each side: `z1 - z0`.
    pub fn border(&self) -> usize {
        self.z1 - self.z0
    }

    /// Base-plane size `[w, h]`: the last slice with the side faces unfolded around it.
    pub fn base_dims(&self) -> [usize; 2] {
        let b = 2 * self.border();
        [self.dims[0] + b, self.dims[1] + b]
    }

    /// Sight-ray increments of the voxel at pipeline `(x, y, z)`; `None` when
    /// the ray is beyond 45 degrees or parallel to the slices.
    pub fn increments(&self, x: usize, y: usize, z: usize) -> Option<(i32, i32)> {
        let one = 1i64 << self.frac;
        let (dx, dy) = match self.rays {
            Rays::Parallel { dx, dy } => (dx as i64, dy as i64),
            Rays::Perspective { eye } => {
                // The per-voxel divider: S = P - V in fixed point, then
                // dx = round(S_x * 2^frac / S_z), halves away from zero.
                let sx = ((x as i64) << self.frac) - eye[0];
                let sy = ((y as i64) << self.frac) - eye[1];
                let sz = ((z as i64) << self.frac) - eye[2];
                if sz == 0 {
                    return None;
                }
                (
                    round_div(sx << self.frac, sz),
                    round_div(sy << self.frac, sz),
                )
            }
        };
        (dx.abs() <= one && dy.abs() <= one).then_some((dx as i32, dy as i32))
    }

    /// The CFB's control bits for the voxel at pipeline `(x, y, z)` (inside the dataset).
    pub fn control(&self, x: usize, y: usize, z: usize) -> Control {
        let [nx, ny, nz] = self.dims;
        let one = 1i32 << self.frac;
        let inc = self.increments(x, y, z);
        let (dx, dy) = match (inc, self.rays) {
            (Some(d), _) => d,
            (None, Rays::Parallel { .. }) => {
                unreachable!("parallel increments are range checked at planning")
            }
            (None, Rays::Perspective { eye }) => {
                // Saturate the direction of an invalid voxel to the 3x3 region
                // so its cell still gathers from its neighbours.
                let s = |p: usize, e: i64| (((p as i64) << self.frac) - e).signum() as i32 * one;
                let sz = (((z as i64) << self.frac) - eye[2]).signum() as i32;
                (s(x, eye[0]) * sz, s(y, eye[1]) * sz)
            }
        };
        let invalid = inc.is_none();
        let edge = x == 0 || y == 0 || z == 0 || x == nx - 1 || y == ny - 1 || z == nz - 1;
        let face = if invalid {
            Face::None
        } else if z == self.z1 {
            Face::Last
        } else if x == nx - 1 && dx > 0 {
            Face::XPos
        } else if x == 0 && dx < 0 {
            Face::XNeg
        } else if y == ny - 1 && dy > 0 {
            Face::YPos
        } else if y == 0 && dy < 0 {
            Face::YNeg
        } else {
            Face::None
        };
        Control {
            dx,
            dy,
            sr: z == self.z0,
            er: face != Face::None,
            invalid,
            edge,
            face,
        }
    }

    /// Base-plane address of the cell at pipeline `(x, y, z)` leaving through `face`:
    /// the last slice sits in the middle, each side face is unfolded outwards
    /// with slice `z` at distance `z1 - z` from the fold.
    pub fn base_address(&self, x: usize, y: usize, z: usize, face: Face) -> Option<[usize; 2]> {
        let b = self.border() as i64;
        let depth = (self.z1 - z) as i64;
        let (x, y) = (x as i64, y as i64);
        let (ex, ey) = match face {
            Face::None => return None,
            Face::Last => (0, 0),
            Face::XPos => (1, 0),
            Face::XNeg => (-1, 0),
            Face::YPos => (0, 1),
            Face::YNeg => (0, -1),
        };
        let (bx, by) = (b + x + depth * ex, b + y + depth * ey);
        Some([bx as usize, by as usize])
    }
}

/// A sweep is the shader's base plane: it shades voxels (no fractional
/// bits) with central differences one bit wider than they are.
impl ShadedPlane for Sweep {
    fn spacing(&self) -> f64 {
        self.spacing
    }

    fn view_dir(&self) -> DVec3 {
        self.view_dir
    }

    fn gradient_to_dataset(&self) -> DMat3 {
        self.to_dataset()
    }

    fn sample_frac(_: &Scene) -> u32 {
        0
    }

    fn gradient_bits(scene: &Scene) -> u32 {
        scene.hardware.voxel_bits + 1
    }
}

/// The sweeps one view needs.
#[derive(Debug, Clone)]
pub struct Plan {
    pub sweeps: Vec<Sweep>,
    /// Perspective: sweep index for each `(axis, positive direction)`.
    slots: [[Option<usize>; 2]; 3],
    /// A perspective view with a known large error (the eye next to an
    /// edge or inside the volume), to be reported with the image.
    pub caveat: Option<Caveat>,
}

impl Plan {
    pub fn new(scene: &Scene, camera: &Camera) -> Result<Plan> {
        let dims = scene.volume.render_dims();
        let frac = scene.hardware.frac_bits;
        let mut slots = [[None; 2]; 3];
        let mut sweeps = Vec::new();
        match camera.projection {
            Projection::Parallel => {
                let d = camera.forward;
                let axis = dominant_axis(d);
                let mut s = Sweep::new(axis, dims, frac);
                let p = s.to_pipeline() * d;
                let one = 1i64 << frac;
                let dx = quantize(p.x / p.z, frac).clamp(-one, one) as i32;
                let dy = quantize(p.y / p.z, frac).clamp(-one, one) as i32;
                s.rays = Rays::Parallel { dx, dy };
                s.order = if p.z > 0.0 {
                    Order::FrontToBack
                } else {
                    Order::BackToFront
                };
                s.spacing = (1.0 + (p.x / p.z).powi(2) + (p.y / p.z).powi(2)).sqrt();
                s.view_dir = d;
                slots[axis][(p.z > 0.0) as usize] = Some(0);
                sweeps.push(s);
            }
            Projection::Perspective => {
                let eye = camera.origin;
                let sums = ray_sums(camera, dims);
                for (a, pair) in sums.iter().enumerate() {
                    for (pos, sum) in pair.iter().enumerate() {
                        if *sum == DVec3::ZERO {
                            continue;
                        }
                        let mut s = Sweep::new(a, dims, frac);
                        let n = dims[a];
                        let e = eye[a];
                        if pos == 1 {
                            s.z0 = if e < 0.0 {
                                0
                            } else {
                                (e.floor() as usize + 1).min(n)
                            };
                            s.z1 = n - 1;
                            s.order = Order::FrontToBack;
                        } else {
                            // The exit slice (nearest the eye) must lie at
                            // least half a voxel from it, so that one of the
                            // 2x2 cells around every exiting ray is within 45
                            // degrees (valid); nearer voxels are beyond 45
                            // degrees but for at most one next to the eye.
                            let last = (e - 0.5).floor();
                            if last < 0.0 {
                                continue;
                            }
                            s.z0 = 0;
                            s.z1 = (last as usize).min(n - 1);
                            s.order = Order::BackToFront;
                        }
                        if s.z0 > s.z1 || s.z0 >= n {
                            continue;
                        }
                        let pe = s.to_pipeline() * eye;
                        s.rays = Rays::Perspective {
                            eye: [
                                quantize(pe.x, frac),
                                quantize(pe.y, frac),
                                quantize(pe.z, frac),
                            ],
                        };
                        let m = s.to_pipeline() * sum.normalize();
                        s.spacing = (1.0 + (m.x / m.z).powi(2) + (m.y / m.z).powi(2)).sqrt();
                        s.view_dir = sum.normalize();
                        slots[a][pos] = Some(sweeps.len());
                        sweeps.push(s);
                    }
                }
                if sweeps.is_empty() {
                    return Err(CubeError::View("no pixel's ray meets the volume".into()));
                }
            }
        }
        let caveat = match camera.projection {
            Projection::Parallel => None,
            Projection::Perspective => Caveat::of(camera.origin, dims, sweeps.len()),
        };
        Ok(Plan {
            sweeps,
            slots,
            caveat,
        })
    }

    /// The sweep that renders a ray with direction `d` (dataset space).
    pub fn sweep_for(&self, d: DVec3) -> Option<usize> {
        if self.sweeps.len() == 1 {
            return Some(0);
        }
        let a = dominant_axis(d);
        self.slots[a][(d[a] > 0.0) as usize]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scene(view: &str) -> Scene {
        let t = format!(
            r#"{{"volume": {{"builtin": "sphere", "dims": [16,12,10]}}, "view": {view}, "image": [32,32]}}"#
        );
        Scene::from_json(&t, None).unwrap()
    }

    fn plan(view: &str) -> Plan {
        let s = scene(view);
        Plan::new(&s, &s.camera()).unwrap()
    }

    #[test]
    fn the_farthest_accepted_eye_plans_without_overflow() {
        // Eye and target are bounded to ±1e6 voxels; at 15 fractional bits
        // the divider's S << frac must still fit i64 (tests run with
        // overflow checks). A 1x1 image's one ray passes the target.
        for eye in ["[8, 6, -1000000]", "[1000000, -1000000, 1000000]"] {
            let t = format!(
                r#"{{"volume": {{"builtin": "sphere", "dims": [16,12,10]}}, "view": {{"projection": "perspective", "eye": {eye}, "fov_deg": 1}},
                    "image": [1, 1], "hardware": {{"frac_bits": 15}}}}"#
            );
            let s = Scene::from_json(&t, None).unwrap();
            let p = Plan::new(&s, &s.camera()).unwrap();
            for sw in &p.sweeps {
                let [nx, ny, _] = sw.dims;
                for (x, y, z) in [(0, 0, sw.z0), (nx - 1, ny - 1, sw.z1)] {
                    let _ = sw.control(x, y, z);
                }
            }
        }
    }

    #[test]
    fn head_on_view_sweeps_z_back_to_front() {
        // The camera looks down -z: the eye is above the volume in w.
        let p = plan(r#"{"projection": "parallel"}"#);
        assert_eq!(p.sweeps.len(), 1);
        let s = &p.sweeps[0];
        assert_eq!(s.axis(), 2);
        assert_eq!(s.order, Order::BackToFront);
        assert_eq!(s.rays, Rays::Parallel { dx: 0, dy: 0 });
    }

    #[test]
    fn exactly_45_degrees_gives_unit_increment() {
        let p = plan(r#"{"projection": "parallel", "rotate_deg": [0, 45, 0]}"#);
        let Rays::Parallel { dx, dy } = p.sweeps[0].rays else {
            panic!()
        };
        assert_eq!((dx.abs(), dy), (256, 0));
        let p = plan(r#"{"projection": "parallel", "rotate_deg": [0, 45.01, 0]}"#);
        let q = plan(r#"{"projection": "parallel", "rotate_deg": [0, 44.99, 0]}"#);
        assert_ne!(
            p.sweeps[0].axis(),
            q.sweeps[0].axis(),
            "the base plane switches at 45 degrees"
        );
    }

    #[test]
    fn pipeline_matrix_matches_permutation() {
        for axis in 0..3 {
            let s = Sweep::new(axis, [5, 6, 7], 8);
            let m = s.to_pipeline();
            let d = DVec3::new(1.0, 2.0, 3.0);
            let p = m * d;
            for i in 0..3 {
                assert_eq!(p[i], d[s.perm[i]]);
            }
            assert_eq!(s.to_dataset() * p, d);
        }
    }

    #[test]
    fn perspective_close_eye_needs_several_sweeps() {
        let p = plan(r#"{"projection": "perspective", "eye": [7.5, 5.5, -3], "fov_deg": 120}"#);
        assert!(p.sweeps.len() > 1, "{} sweeps", p.sweeps.len());
        for s in &p.sweeps {
            let Rays::Perspective { .. } = s.rays else {
                panic!()
            };
        }
    }
}
