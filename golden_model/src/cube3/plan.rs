//! Cube-3 view planning (§2, Fig. 1; §3, Fig. 5, Eq. 3; Fig. 7): the base
//! planes a view needs, the traversal frame of each, the sample offset and
//! the X/Y templates of the discrete rays.
//!
//! **Traversal frame.** The base plane is the face most perpendicular to the
//! view; its axis is the major axis. Traversal coordinates `(x, y, k)` are a
//! cyclic permutation of dataset axes (as Cube-4L's pipeline space), with `k`
//! counted from the face nearest the eye, so every ray steps `k -> k + 1`.
//!
//! **Rays.** The continuous ray of base-plane pixel `(u, v)` starts at the
//! integer base-plane position, offset by `o` along the major axis: it
//! passes through `(u, v, o)` with direction `(dx, dy, 1)`. Its sample `k`
//! sits at `(u + k·dx, v + k·dy, k + o)`, between planes `k` and `k + 1`.
//! Its discrete ray is the 26-connected line `X_k = floor(u + k·dx)` (a 3-D
//! Bresenham line for non-integer end points, Fig. 1), one voxel per plane.
//!
//! **Fixed point.** dx, dy, the offset and every interpolation weight have
//! `W = hardware.frac_bits` fractional bits. Parallel: `DX = round(dx·2^W)`
//! (halves away from zero) for the frame, so `X_k = u + ((k·DX) >> W)` and
//! the template holds one entry per plane (n entries). Perspective: `DX(u) =
//! round((u - e_x) / (o - e_z) · 2^W)` per base-plane column, `X_k(u) = ((u
//! << W) + k·DX(u)) >> W`: n² entries. Rays beyond 45° (`|DX| > 2^W`) belong
//! to another base plane and are not cast here.
//!
//! **Sample offset (§3).** Cast one ray from the image origin (pixel (0, 0);
//! perspective: the eye along the base plane's mean ray), step it by whole
//! sample distances, and take the offset of its first sample after the base
//! plane: `o0 = frac` of the penetration, `O = min(round(o0·2^W), 2^W - 1)`.
//! Eq. 3 admits `O <= 2^W - max(|DX|, |DY|)` (every ray, for perspective);
//! while it does not hold, `O >>= 1` (the iterative reduction). At exactly
//! 45° this reaches `O = 0`.
//!
//! **X/Y weights (Fig. 4).** The sample lies between the sheared edges of
//! the four discrete rays `u, u + 1`: at height `o` ray `u`'s edge is at
//! `E_A = (X_k(u) << W) + O·(X_{k+1}(u) - X_k(u))`, ray `u + 1`'s at `E_B`
//! likewise; the sample's continuous position is `xq = (u << W) + k·DX`.
//! `wx = clamp(round_div((xq - E_A) << W, E_B - E_A), 0, 2^W)` (a template
//! entry; for parallel views `E_B - E_A = 2^W` and `wx = xq - E_A` exactly,
//! in `[0, 2^W)` by Eq. 3). The clamp is counted in `Stats::weight_clamps`.

use crate::common::plan::{dominant_axis, ray_sums};
use crate::fixed::{quantize, round_div};
use glam::{DMat3, DVec3};
use scene::{Camera, CubeError, Projection, Result, Scene};

/// ABC gradient neighbourhood (§4).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Neighbourhood {
    N6,
    N10,
    N12,
    N26,
}

impl Neighbourhood {
    pub fn from_count(n: u32) -> Option<Neighbourhood> {
        match n {
            6 => Some(Neighbourhood::N6),
            10 => Some(Neighbourhood::N10),
            12 => Some(Neighbourhood::N12),
            26 => Some(Neighbourhood::N26),
            _ => None,
        }
    }

    pub fn count(self) -> u32 {
        match self {
            Neighbourhood::N6 => 6,
            Neighbourhood::N10 => 10,
            Neighbourhood::N12 => 12,
            Neighbourhood::N26 => 26,
        }
    }
}

/// The datapath widths of a Cube-3 frame.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Widths {
    pub voxel_bits: u32,
    /// Fractional bits of weights, templates and the offset (`W`).
    pub weight_bits: u32,
    /// Sample width; `sample_bits - voxel_bits` fractional bits.
    pub sample_bits: u32,
    /// Signed gradient component width.
    pub gradient_bits: u32,
    pub rgba_bits: u32,
}

impl Widths {
    pub fn of(scene: &Scene) -> Widths {
        let hw = scene.hardware;
        Widths {
            voxel_bits: hw.voxel_bits,
            weight_bits: hw.frac_bits,
            sample_bits: scene.cube3.sample_bits(hw.voxel_bits),
            gradient_bits: scene.cube3.gradient_bits(hw.voxel_bits),
            rgba_bits: hw.rgba_bits,
        }
    }

    /// Fractional bits of a sample.
    pub fn sample_frac(&self) -> u32 {
        self.sample_bits - self.voxel_bits
    }
}

/// One axis of the discrete-ray templates: per base-plane column (row) `u`,
/// the fixed-point increment, and per plane the discrete-ray position and the
/// interpolation weight towards ray `u + 1`.
#[derive(Debug, Clone)]
pub enum Template {
    /// n entries: `X_k(u) = u + pos[k]`, one weight per plane.
    Parallel {
        d: i32,
        pos: Vec<i32>,
        weight: Vec<u32>,
    },
    /// n² entries, rays `lo..lo + d.len()`.
    Perspective {
        lo: i32,
        d: Vec<i32>,
        pos: Vec<i32>,
        weight: Vec<u32>,
    },
}

impl Template {
    /// Number of planes `K`: positions hold `K + 1` entries per ray.
    fn planes(&self) -> usize {
        match self {
            Template::Parallel { weight, .. } => weight.len(),
            Template::Perspective { d, weight, .. } => weight.len() / d.len(),
        }
    }

    fn ray(&self, u: i32) -> usize {
        match self {
            Template::Parallel { .. } => 0,
            Template::Perspective { lo, d, .. } => {
                let i = (u - lo) as usize;
                debug_assert!(i < d.len(), "ray {u} outside the template");
                i
            }
        }
    }

    /// Whether the template holds rays `first .. first + n` (a parallel
    /// one holds every ray).
    pub fn covers(&self, first: i32, n: usize) -> bool {
        match self {
            Template::Parallel { .. } => true,
            Template::Perspective { lo, d, .. } => {
                first >= *lo && first + n as i32 <= *lo + d.len() as i32
            }
        }
    }

    /// Fixed-point increment `DX` of ray `u`.
    pub fn d(&self, u: i32) -> i32 {
        match self {
            Template::Parallel { d, .. } => *d,
            Template::Perspective { d, .. } => d[self.ray(u)],
        }
    }

    /// A parallel template's `X_k(u) - u` (its rays shift as a whole on
    /// plane `k`); `None` for a perspective one.
    pub fn shift(&self, k: usize) -> Option<i32> {
        match self {
            Template::Parallel { pos, .. } => Some(pos[k]),
            Template::Perspective { .. } => None,
        }
    }

    /// Discrete-ray position `X_k(u)`, `k` in `0..=K`.
    pub fn pos(&self, u: i32, k: usize) -> i32 {
        match self {
            Template::Parallel { pos, .. } => u + pos[k],
            Template::Perspective { pos, .. } => pos[self.ray(u) * (self.planes() + 1) + k],
        }
    }

    /// Interpolation weight from ray `u` towards ray `u + 1` at sample `k`.
    pub fn weight(&self, u: i32, k: usize) -> u32 {
        match self {
            Template::Parallel { weight, .. } => weight[k],
            Template::Perspective { weight, .. } => weight[self.ray(u) * self.planes() + k],
        }
    }

    /// The `K` weights of ray `u`, sample by sample.
    pub fn weights(&self, u: i32) -> &[u32] {
        match self {
            Template::Parallel { weight, .. } => weight,
            Template::Perspective { weight, .. } => {
                let k = self.planes();
                &weight[self.ray(u) * k..][..k]
            }
        }
    }

    /// Whether every weight is 0 and every step is in {0, ±1} with the
    /// offset 0: samples sit on the grid.
    fn on_grid(&self, w: u32) -> bool {
        match self {
            Template::Parallel { d, .. } => *d == 0 || d.unsigned_abs() == 1 << w,
            Template::Perspective { .. } => false,
        }
    }
}

/// Continuous fixed-point position `(u << W) + k·DX` of sample `k` of ray `u`.
pub fn sample_pos(u: i32, k: usize, d: i32, w: u32) -> i64 {
    ((u as i64) << w) + k as i64 * d as i64
}

/// Build a template for rays `lo..=hi` with increments `d(u)` over `K` planes.
fn build_template(
    lo: i32,
    hi: i32,
    planes: usize,
    offset: u32,
    w: u32,
    d: impl Fn(i32) -> i32,
    parallel: bool,
) -> (Template, u64) {
    let pos_of = |u: i32, k: usize| (sample_pos(u, k, d(u), w) >> w) as i32;
    let mut clamps = 0;
    let mut weight_of = |u: i32, k: usize| {
        let edge = |r: i32| {
            let (a, b) = (pos_of(r, k), pos_of(r, k + 1));
            ((a as i64) << w) + offset as i64 * (b - a) as i64
        };
        let (ea, eb) = (edge(u), edge(u + 1));
        let xq = sample_pos(u, k, d(u), w);
        let raw = round_div((xq - ea) << w, eb - ea);
        let c = raw.clamp(0, 1 << w);
        clamps += (c != raw) as u64;
        c as u32
    };
    if parallel {
        let pos = (0..=planes).map(|k| pos_of(0, k)).collect();
        let weight = (0..planes).map(|k| weight_of(0, k)).collect();
        (
            Template::Parallel {
                d: d(0),
                pos,
                weight,
            },
            clamps,
        )
    } else {
        let mut pos = Vec::new();
        let mut weight = Vec::new();
        for u in lo..=hi {
            pos.extend((0..=planes).map(|k| pos_of(u, k)));
            // The last ray has no right neighbour in the template; its
            // weights are never read (it is only ever a neighbour).
            weight.extend((0..planes).map(|k| if u < hi { weight_of(u, k) } else { 0 }));
        }
        (
            Template::Perspective {
                lo,
                d: (lo..=hi).map(&d).collect(),
                pos,
                weight,
            },
            clamps,
        )
    }
}

/// One base-plane projection.
#[derive(Debug, Clone)]
pub struct View {
    /// Traversal axis `i` is dataset axis `perm[i]`; `perm[2]` is the major axis.
    pub perm: [usize; 3],
    /// Whether rays travel towards +major in dataset space.
    pub positive: bool,
    /// Traversal dims `[nx, ny, K]`.
    pub dims: [usize; 3],
    /// Sample offset `O` along the major axis, `W` fractional bits.
    pub offset: u32,
    pub x: Template,
    pub y: Template,
    /// Base-plane pixels cast: `u` in `u_lo..=u_hi`, `v` in `v_lo..=v_hi`.
    pub u: [i32; 2],
    pub v: [i32; 2],
    /// Samples sit on voxels: TRILIN is left out.
    pub on_grid: bool,
    /// Sample spacing along the mean ray, in voxel lengths.
    pub spacing: f64,
    /// Mean viewing direction (eye to volume) in dataset space.
    pub view_dir: DVec3,
    pub weight_clamps: u64,
    pub weight_bits: u32,
}

impl View {
    /// Matrix taking dataset vectors to traversal vectors.
    pub fn to_traversal(&self) -> DMat3 {
        let row = |a: usize, s: f64| {
            DVec3::from_array(std::array::from_fn(|i| s * (i == a) as u8 as f64))
        };
        let s = if self.positive { 1.0 } else { -1.0 };
        DMat3::from_cols(
            row(self.perm[0], 1.0),
            row(self.perm[1], 1.0),
            row(self.perm[2], s),
        )
        .transpose()
    }

    /// Traversal coordinates of a dataset point.
    pub fn point(&self, p: DVec3) -> DVec3 {
        let mut q = self.to_traversal() * p;
        if !self.positive {
            q.z += (self.dims[2] - 1) as f64;
        }
        q
    }

    /// Dataset index `[x, y, z]` of traversal voxel `(x, y, k)`, or `None`
    /// outside the volume.
    pub fn voxel(&self, x: i32, y: i32, k: usize) -> Option<[usize; 3]> {
        let [nx, ny, nk] = self.dims;
        if x < 0 || y < 0 || x as usize >= nx || y as usize >= ny || k >= nk {
            return None;
        }
        let mut d = [0; 3];
        d[self.perm[0]] = x as usize;
        d[self.perm[1]] = y as usize;
        d[self.perm[2]] = if self.positive { k } else { nk - 1 - k };
        Some(d)
    }

    /// Base-plane size `[w, h]`.
    pub fn base_dims(&self) -> [usize; 2] {
        [
            (self.u[1] - self.u[0] + 1) as usize,
            (self.v[1] - self.v[0] + 1) as usize,
        ]
    }

    /// Rays `(dx, dy)` of pixel `(u, v)` are within 45°: cast on this plane.
    pub fn casts(&self, u: i32, v: i32) -> bool {
        let one = 1u32 << self.weight_bits;
        self.x.d(u).unsigned_abs() <= one && self.y.d(v).unsigned_abs() <= one
    }
}

/// The base planes of one view.
#[derive(Debug, Clone)]
pub struct Plan {
    pub views: Vec<View>,
    /// Perspective: view index for each `(axis, positive)`.
    slots: [[Option<usize>; 2]; 3],
}

impl Plan {
    pub fn new(scene: &Scene, camera: &Camera) -> Result<Plan> {
        let dims = scene.volume.render_dims();
        let w = scene.hardware.frac_bits;
        let mut views = Vec::new();
        let mut slots = [[None; 2]; 3];
        match camera.projection {
            Projection::Parallel => {
                let d = camera.forward;
                let axis = dominant_axis(d);
                let (o, _) = camera.ray(0, 0);
                views.push(View::parallel(dims, axis, d, o, w));
                slots[axis][(d[axis] > 0.0) as usize] = Some(0);
            }
            Projection::Perspective => {
                let sums = ray_sums(camera, dims);
                for (a, pair) in sums.iter().enumerate() {
                    for (pos, sum) in pair.iter().enumerate() {
                        if *sum == DVec3::ZERO {
                            continue;
                        }
                        let v = View::perspective(dims, a, pos == 1, camera.origin, *sum, w)?;
                        slots[a][pos] = Some(views.len());
                        views.push(v);
                    }
                }
                if views.is_empty() {
                    return Err(CubeError::View("no pixel's ray meets the volume".into()));
                }
            }
        }
        Ok(Plan { views, slots })
    }

    /// The view that renders a ray with direction `d` (dataset space).
    pub fn view_for(&self, d: DVec3) -> Option<usize> {
        if self.views.len() == 1 {
            return Some(0);
        }
        let a = dominant_axis(d);
        self.slots[a][(d[a] > 0.0) as usize]
    }
}

fn empty_view(dims: [usize; 3], axis: usize, positive: bool, w: u32) -> View {
    let perm = [(axis + 1) % 3, (axis + 2) % 3, axis];
    View {
        perm,
        positive,
        dims: [dims[perm[0]], dims[perm[1]], dims[perm[2]]],
        offset: 0,
        x: Template::Parallel {
            d: 0,
            pos: vec![],
            weight: vec![],
        },
        y: Template::Parallel {
            d: 0,
            pos: vec![],
            weight: vec![],
        },
        u: [0, 0],
        v: [0, 0],
        on_grid: false,
        spacing: 1.0,
        view_dir: DVec3::Z,
        weight_clamps: 0,
        weight_bits: w,
    }
}

/// §3: the offset of the first sample after the base plane of a ray from
/// `o` (traversal) along `d` (traversal, `d.z > 0`) stepped by whole sample
/// distances, as `W`-bit fraction below 1.
fn first_offset(o: DVec3, d: DVec3, w: u32) -> u32 {
    let t = (-o.z / d.z).ceil();
    let z = (o.z + t * d.z).max(0.0);
    quantize(z, w).clamp(0, (1 << w) - 1) as u32
}

/// Eq. 3 and the iterative reduction: halve `offset` until
/// `offset <= 2^W - max_d`.
pub fn reduce_offset(mut offset: u32, max_d: u32, w: u32) -> u32 {
    let limit = (1u32 << w).saturating_sub(max_d);
    while offset > limit {
        offset >>= 1;
    }
    offset
}

/// Rays `u` whose samples meet `[-1, n]` over planes `0..K`, from the
/// candidates `-(K + 2)..=n + K + 1` (within 45° a ray moves at most one per
/// plane), given each ray's increment.
fn ray_range(n: usize, planes: usize, w: u32, d: impl Fn(i32) -> i32) -> Option<[i32; 2]> {
    let (n, kk) = (n as i64, planes as i64);
    let meets = |u: i32| {
        let one = 1i64 << w;
        if d(u).unsigned_abs() > one as u32 {
            return false;
        }
        let a = sample_pos(u, 0, d(u), w);
        let b = sample_pos(u, planes - 1, d(u), w);
        a.max(b) >= -one && a.min(b) <= n * one
    };
    let c = (-(kk + 2) as i32)..=((n + kk + 1) as i32);
    let lo = c.clone().find(|&u| meets(u))?;
    let hi = c.rev().find(|&u| meets(u))?;
    Some([lo, hi])
}

impl View {
    fn parallel(dims: [usize; 3], axis: usize, dir: DVec3, origin: DVec3, w: u32) -> View {
        let mut v = empty_view(dims, axis, dir[axis] > 0.0, w);
        let q = v.to_traversal() * dir;
        let one = 1i64 << w;
        let dx = quantize(q.x / q.z, w).clamp(-one, one) as i32;
        let dy = quantize(q.y / q.z, w).clamp(-one, one) as i32;
        let max_d = dx.unsigned_abs().max(dy.unsigned_abs());
        v.offset = reduce_offset(first_offset(v.point(origin), q, w), max_d, w);
        v.finish(|_| dx, |_| dy, true);
        v.spacing = (1.0 + (q.x / q.z).powi(2) + (q.y / q.z).powi(2)).sqrt();
        v.view_dir = dir;
        v
    }

    fn perspective(
        dims: [usize; 3],
        axis: usize,
        positive: bool,
        eye: DVec3,
        sum: DVec3,
        w: u32,
    ) -> Result<View> {
        let mut v = empty_view(dims, axis, positive, w);
        let e = v.point(eye);
        if e.z >= -0.5 {
            let side = if positive { "below" } else { "above" };
            return Err(CubeError::View(format!(
                "cube3 casts rays from a face: the eye must lie at least half a voxel {side} the volume along axis {} for the rays that face receives (it is inside the slab)",
                ["u", "v", "w"][axis]
            )));
        }
        let one = 1i64 << w;
        let [nx, ny, nk] = v.dims;
        let ez = e.z;
        let incr = move |p: i32, e: f64, o: u32| {
            let t = (o as f64 / one as f64) - ez;
            quantize((p as f64 - e) / t, w).clamp(-2 * one, 2 * one) as i32
        };
        let mean = v.to_traversal() * sum.normalize();
        let mut offset = first_offset(e, mean, w);
        // Eq. 3 over every cast ray; the increments depend on the offset.
        loop {
            let dx = |u: i32| incr(u, e.x, offset);
            let dy = |u: i32| incr(u, e.y, offset);
            let rx = ray_range(nx, nk, w, dx);
            let ry = ray_range(ny, nk, w, dy);
            let (Some(rx), Some(ry)) = (rx, ry) else {
                return Err(CubeError::View(
                    "cube3: no ray of a perspective base plane meets the volume".into(),
                ));
            };
            let max_d = (rx[0]..=rx[1])
                .map(|u| dx(u).unsigned_abs())
                .chain((ry[0]..=ry[1]).map(|u| dy(u).unsigned_abs()))
                .max()
                .unwrap();
            let r = reduce_offset(offset, max_d, w);
            if r == offset {
                break;
            }
            offset = r;
        }
        v.offset = offset;
        let (ex, ey) = (e.x, e.y);
        v.finish(
            move |u| incr(u, ex, offset),
            move |u| incr(u, ey, offset),
            false,
        );
        v.spacing = (1.0 + (mean.x / mean.z).powi(2) + (mean.y / mean.z).powi(2)).sqrt();
        v.view_dir = sum.normalize();
        Ok(v)
    }

    /// Base-plane ranges and templates; rays one beyond each end are kept as
    /// neighbours (gradients), and one more for the TRILIN's `u + 1`.
    fn finish(&mut self, dx: impl Fn(i32) -> i32, dy: impl Fn(i32) -> i32, parallel: bool) {
        let w = self.weight_bits;
        let [nx, ny, nk] = self.dims;
        self.u = ray_range(nx, nk, w, &dx).expect("a parallel ray meets the volume");
        self.v = ray_range(ny, nk, w, &dy).expect("a parallel ray meets the volume");
        let (tx, cx) = build_template(
            self.u[0] - 1,
            self.u[1] + 2,
            nk,
            self.offset,
            w,
            dx,
            parallel,
        );
        let (ty, cy) = build_template(
            self.v[0] - 1,
            self.v[1] + 2,
            nk,
            self.offset,
            w,
            dy,
            parallel,
        );
        self.on_grid = self.offset == 0 && tx.on_grid(w) && ty.on_grid(w);
        self.x = tx;
        self.y = ty;
        self.weight_clamps = cx + cy;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scene(view: &str, frac: u32) -> Scene {
        let t = format!(
            r#"{{"volume": {{"builtin": "sphere", "dims": [16,12,10]}}, "view": {view}, "image": [32,32], "hardware": {{"frac_bits": {frac}}}}}"#
        );
        Scene::from_json(&t, None).unwrap()
    }

    fn plan(view: &str) -> Plan {
        let s = scene(view, 8);
        Plan::new(&s, &s.camera()).unwrap()
    }

    #[test]
    fn eq3_reduction_by_hand() {
        // dx = 0.25 (64/256): the offset may be at most 1 - 0.25 = 192/256.
        assert_eq!(reduce_offset(200, 64, 8), 100);
        assert_eq!(reduce_offset(192, 64, 8), 192);
        // 45 degrees: only 0 is admissible.
        assert_eq!(reduce_offset(255, 256, 8), 0);
        assert_eq!(reduce_offset(0, 256, 8), 0);
    }

    #[test]
    fn parallel_template_is_a_floor_bresenham_line() {
        // dx = 0.375 at W = 3 fractional bits: DX = 3, X_k = floor(3k/8).
        let (t, clamps) = build_template(0, 3, 6, 0, 3, |_| 3, true);
        assert_eq!(clamps, 0);
        let want_pos = [0, 0, 0, 1, 1, 1, 2];
        // Offset 0: the weight is the fraction of k·dx: 0, 3, 6, 1, 4, 7.
        let want_w = [0, 3, 6, 1, 4, 7];
        for (k, p) in want_pos.iter().enumerate() {
            assert_eq!(t.pos(5, k), 5 + p, "pos k={k}");
        }
        for (k, w) in want_w.iter().enumerate() {
            assert_eq!(t.weight(5, k), *w, "weight k={k}");
        }
    }

    #[test]
    fn sheared_weight_subtracts_the_offset_on_a_step() {
        // DX = 3/8, offset O = 4/8 (<= 1 - 3/8). Plane 2 -> 3 steps (6/8 + 3/8
        // >= 1): the edges at height 1/2 are sheared by 1/2, so the weight is
        // 6 - 4 = 2. Plane 1 -> 2 does not step: weight 3.
        let (t, _) = build_template(0, 3, 6, 4, 3, |_| 3, true);
        assert_eq!(t.weight(0, 2), 2);
        assert_eq!(t.weight(0, 1), 3);
        // Negative dx: DX = -3, X_k = floor(-3k/8) = 0, -1, -1, -2; a step
        // of -1 adds the offset: plane 0 -> 1 steps, weight 0 + 4.
        let (t, _) = build_template(0, 3, 6, 4, 3, |_| -3, true);
        assert_eq!(
            [t.pos(0, 0), t.pos(0, 1), t.pos(0, 2), t.pos(0, 3)],
            [0, -1, -1, -2]
        );
        assert_eq!(t.weight(0, 0), 4);
        // Plane 1: fraction of -3/8 is 5/8, no step to plane 2 (X = -1): 5.
        assert_eq!(t.weight(0, 1), 5);
    }

    #[test]
    fn exactly_45_degrees_has_offset_zero_and_samples_on_the_grid() {
        let p = plan(r#"{"projection": "parallel", "rotate_deg": [0, 45, 0]}"#);
        let v = &p.views[0];
        assert_eq!(v.offset, 0);
        assert_eq!(v.x.d(0).unsigned_abs(), 256);
        assert!(v.on_grid);
        let q = plan(r#"{"projection": "parallel", "rotate_deg": [0, 30, 0]}"#);
        assert!(!q.views[0].on_grid);
        // Head on: dx = dy = 0; the offset is then the only weight.
        let h = plan(r#"{"projection": "parallel"}"#);
        assert_eq!(h.views[0].on_grid, h.views[0].offset == 0);
    }

    #[test]
    fn the_base_plane_switches_at_45_degrees() {
        let a = plan(r#"{"projection": "parallel", "rotate_deg": [0, 44.99, 0]}"#);
        let b = plan(r#"{"projection": "parallel", "rotate_deg": [0, 45.01, 0]}"#);
        assert_ne!(a.views[0].perm[2], b.views[0].perm[2]);
    }

    #[test]
    fn traversal_maps_voxels_and_points_alike() {
        // The default camera looks down -w: rays travel towards -w, and
        // k = 0 is the slice w = n - 1.
        let p = plan(r#"{"projection": "parallel", "rotate_deg": [10, 0, 0]}"#);
        let v = &p.views[0];
        assert!(!v.positive);
        assert_eq!(v.voxel(0, 0, 0).unwrap()[2], 9);
        let [nx, ny, nk] = v.dims;
        for (x, y, k) in [(0, 0, 0), (nx - 1, 2, 3), (4, ny - 1, nk - 1)] {
            let d = v.voxel(x as i32, y as i32, k).unwrap();
            let q = v.point(DVec3::new(d[0] as f64, d[1] as f64, d[2] as f64));
            assert_eq!(q, DVec3::new(x as f64, y as f64, k as f64));
        }
        assert_eq!(v.voxel(-1, 0, 0), None);
    }

    #[test]
    fn perspective_corner_eye_needs_three_base_planes() {
        let p = plan(r#"{"projection": "perspective", "eye": [-12, -12, -12], "fov_deg": 100}"#);
        assert_eq!(p.views.len(), 3, "one base plane per major axis");
        for v in &p.views {
            assert!(v.positive);
            assert!(matches!(v.x, Template::Perspective { .. }));
        }
    }

    #[test]
    fn perspective_eye_inside_the_slab_is_refused() {
        let s = scene(
            r#"{"projection": "perspective", "eye": [7.5, 5.5, -3], "fov_deg": 150}"#,
            8,
        );
        let e = Plan::new(&s, &s.camera()).unwrap_err().to_string();
        assert!(e.contains("eye must lie"), "{e}");
    }

    #[test]
    fn eye_within_half_a_voxel_of_the_face_is_refused() {
        // 0.3 voxels below the z = 0 face, looking along +z: inside the
        // half-voxel margin the rule asks for.
        let s = scene(
            r#"{"projection": "perspective", "eye": [7.5, 5.5, -0.3], "target": [7.5, 5.5, 9], "fov_deg": 20}"#,
            8,
        );
        let e = Plan::new(&s, &s.camera()).unwrap_err().to_string();
        assert!(e.contains("half a voxel"), "{e}");
        let s = scene(
            r#"{"projection": "perspective", "eye": [7.5, 5.5, -0.7], "target": [7.5, 5.5, 9], "fov_deg": 20}"#,
            8,
        );
        assert!(Plan::new(&s, &s.camera()).is_ok());
    }

    #[test]
    fn neighbourhood_counts_round_trip() {
        for n in [6, 10, 12, 26] {
            assert_eq!(Neighbourhood::from_count(n).unwrap().count(), n);
        }
        assert_eq!(Neighbourhood::from_count(8), None);
    }

    #[test]
    fn perspective_template_covers_exactly_its_rays() {
        // Rays -2..=5 (8 of them): increments spread from -1 to +1.
        let (t, _) = build_template(-2, 5, 4, 0, 8, |u| (u - 2) * 64, false);
        assert!(t.covers(-2, 8));
        assert!(t.covers(0, 6));
        assert!(t.covers(5, 1));
        assert!(!t.covers(-3, 1));
        assert!(!t.covers(-2, 9));
        assert!(!t.covers(5, 2));
        assert!(!t.covers(6, 1));
        let (par, _) = build_template(0, 3, 4, 0, 8, |_| 64, true);
        assert!(par.covers(-100, 1000));
    }

    #[test]
    fn first_offset_stays_below_one() {
        // The first whole step from z = -1.0005 ends at z = 0.9995, which
        // rounds to 2^W at W = 8: the offset keeps to 2^W - 1.
        assert_eq!(
            first_offset(DVec3::new(0.0, 0.0, -1.0005), DVec3::Z, 8),
            255
        );
        // From z = -0.25 along z: a quarter voxel in, 64/256.
        assert_eq!(first_offset(DVec3::new(3.0, 1.0, -1.25), DVec3::Z, 8), 192);
    }

    #[test]
    fn casts_within_45_degrees_on_both_axes() {
        let mut v = empty_view([8, 8, 8], 2, true, 8);
        let par = |d: i32| Template::Parallel {
            d,
            pos: vec![],
            weight: vec![],
        };
        for (dx, dy, casts) in [
            (256, -256, true),
            (0, 0, true),
            (257, 0, false),
            (0, -257, false),
            (-300, 300, false),
        ] {
            v.x = par(dx);
            v.y = par(dy);
            assert_eq!(v.casts(0, 0), casts, "dx {dx} dy {dy}");
        }
    }

    #[test]
    fn clamped_weights_are_counted_by_the_view() {
        // An offset past Eq. 3's bound (255/256 against increments near
        // -1): the edges run ahead of the samples and weights leave [0, 1].
        let d = |u: i32| (u - 256).clamp(-256, 256);
        let (t, clamps) = build_template(-1, 6, 6, 255, 8, d, false);
        assert!(clamps > 0);
        for u in -1..6 {
            for k in 0..6 {
                assert!(t.weight(u, k) <= 256);
            }
        }
        // The last ray's weights are never read, so never computed or
        // counted: one ray fewer or more in the template counts fewer or
        // more clamps.
        for k in 0..6 {
            assert_eq!(t.weight(6, k), 0);
        }
        let (_, with_5) = build_template(-1, 5, 6, 255, 8, d, false);
        let (_, with_6_of_7) = build_template(-1, 7, 6, 255, 8, d, false);
        assert!(with_5 < clamps && clamps < with_6_of_7);
        let mut v = empty_view([6, 6, 6], 2, true, 8);
        v.offset = 255;
        let e = |u: i32| (2 * u - 256).clamp(-256, 256);
        v.finish(d, e, false);
        let (_, cx) = build_template(v.u[0] - 1, v.u[1] + 2, 6, 255, 8, d, false);
        let (_, cy) = build_template(v.v[0] - 1, v.v[1] + 2, 6, 255, 8, e, false);
        assert!(cx > 0 && cy > 0 && cx != cy);
        assert_eq!(v.weight_clamps, cx + cy);
    }
}
