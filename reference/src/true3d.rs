//! True3D (Cube-3 paper §6): Cube-3's discrete-ray casting in float. Rays
//! start at integer base-plane positions offset along the major axis, one
//! sample per plane, and the gradient uses the same ABC neighbourhood (6,
//! 10, 12 or 26) over the samples of neighbouring rays. Each sample is the
//! exact tri-linear interpolation of its correct 8-neighbourhood
//! (`Interp::Exact`, True3D) or, to separate the error sources, the sheared
//! tri-linear interpolation of the four discrete rays in float
//! (`Interp::Sheared`: the golden model without quantization).
//!
//! Written from the paper, independently of the golden model: it shares
//! only the scene, camera, transfer function and lighting formulas. The
//! planning rules are the paper's: the base plane is the face most
//! perpendicular to the view; the offset is the penetration of the first
//! sample of the ray from pixel (0, 0) (perspective: from the eye along the
//! base plane's mean ray), halved until Eq. 3 holds; discrete rays are
//! `floor` lines; the perspective eye must lie outside the volume's slab
//! along each major axis in use.

use glam::{DMat3, DVec2, DVec3};
use rayon::prelude::*;
use scene::lighting::phong;
use scene::transfer::{correct_opacity, TransferFn};
use scene::volume::Volume;
use scene::{Camera, CubeError, Image, Mode, Projection, Result, Scene};

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Interp {
    /// Exact tri-linear interpolation at each sample (True3D).
    Exact,
    /// Sheared tri-linear interpolation between discrete rays, in float.
    Sheared,
}

fn major(d: DVec3) -> usize {
    let a = d.abs();
    if a.z >= a.x && a.z >= a.y {
        2
    } else if a.y >= a.x {
        1
    } else {
        0
    }
}

/// How far outside a bound a sample may lie and count as inside: f64's
/// residue, far below any slope a view can have (the fixed-point models
/// resolve 2^-15 of a voxel).
const INSIDE_EPS: f64 = 1e-9;

/// One base plane in float.
struct Plane {
    perm: [usize; 3],
    positive: bool,
    dims: [usize; 3],
    offset: f64,
    /// Perspective eye in traversal space; `None` for parallel.
    eye: Option<DVec3>,
    d: DVec2,
    u: [i32; 2],
    v: [i32; 2],
    spacing: f64,
    view_dir: DVec3,
}

impl Plane {
    fn new(dims: [usize; 3], axis: usize, positive: bool) -> Plane {
        let perm = [(axis + 1) % 3, (axis + 2) % 3, axis];
        Plane {
            perm,
            positive,
            dims: perm.map(|a| dims[a]),
            offset: 0.0,
            eye: None,
            d: DVec2::ZERO,
            u: [0, 0],
            v: [0, 0],
            spacing: 1.0,
            view_dir: DVec3::Z,
        }
    }

    fn m(&self) -> DMat3 {
        let s = if self.positive { 1.0 } else { -1.0 };
        let e = |a: usize| DVec3::from_array(std::array::from_fn(|i| (i == a) as u8 as f64));
        DMat3::from_cols(e(self.perm[0]), e(self.perm[1]), s * e(self.perm[2])).transpose()
    }

    fn point(&self, p: DVec3) -> DVec3 {
        let mut q = self.m() * p;
        if !self.positive {
            q.z += (self.dims[2] - 1) as f64;
        }
        q
    }

    fn dataset(&self, q: DVec3) -> DVec3 {
        let mut q = q;
        if !self.positive {
            q.z -= (self.dims[2] - 1) as f64;
        }
        self.m().transpose() * q
    }

    /// Increments of ray `(u, v)`.
    fn incr(&self, u: i32, v: i32) -> DVec2 {
        match self.eye {
            None => self.d,
            Some(e) => {
                let t = self.offset - e.z;
                DVec2::new((u as f64 - e.x) / t, (v as f64 - e.y) / t)
            }
        }
    }

    /// Continuous position of sample `k` of ray `(u, v)` (traversal).
    fn pos(&self, u: i32, v: i32, k: f64) -> DVec3 {
        let d = self.incr(u, v);
        DVec3::new(u as f64 + k * d.x, v as f64 + k * d.y, k + self.offset)
    }

    fn casts(&self, u: i32, v: i32) -> bool {
        let d = self.incr(u, v);
        d.x.abs() <= 1.0 + 1e-12 && d.y.abs() <= 1.0 + 1e-12
    }

    fn ranges(&mut self) -> Option<()> {
        let [nx, ny, nk] = self.dims.map(|n| n as f64);
        let kk = self.dims[2] as i32;
        let hit = |a: f64, b: f64, n: f64| a.max(b) >= -1.0 && a.min(b) <= n;
        let xs = |u: i32| {
            let d = self.incr(u, 0).x;
            d.abs() <= 1.0 + 1e-12 && hit(u as f64, u as f64 + (nk - 1.0) * d, nx)
        };
        let ys = |v: i32| {
            let d = self.incr(0, v).y;
            d.abs() <= 1.0 + 1e-12 && hit(v as f64, v as f64 + (nk - 1.0) * d, ny)
        };
        let range = |f: &dyn Fn(i32) -> bool, n: usize| {
            let c = -(kk + 2)..=(n as i32 + kk + 1);
            Some([c.clone().find(|&u| f(u))?, c.rev().find(|&u| f(u))?])
        };
        let (u, v) = (range(&xs, self.dims[0])?, range(&ys, self.dims[1])?);
        self.u = u;
        self.v = v;
        Some(())
    }
}

fn first_offset(o: DVec3, d: DVec3) -> f64 {
    let t = (-o.z / d.z).ceil();
    (o.z + t * d.z).max(0.0)
}

fn reduce(mut o: f64, max_d: f64) -> f64 {
    while o > 1.0 - max_d + 1e-12 {
        o /= 2.0;
        if o < 1e-9 {
            return 0.0;
        }
    }
    o
}

/// Whether True3D renders this view: the refusal its render would give,
/// without rendering (its ray planes only).
pub fn check(scene: &Scene, cam: &Camera) -> Result<()> {
    plan(scene, cam).map(|_| ())
}

fn plan(scene: &Scene, cam: &Camera) -> Result<Vec<Plane>> {
    let dims = scene.volume.render_dims();
    let mut planes = Vec::new();
    match cam.projection {
        Projection::Parallel => {
            let d = cam.forward;
            let a = major(d);
            let mut p = Plane::new(dims, a, d[a] > 0.0);
            let q = p.m() * d;
            p.d = DVec2::new(q.x / q.z, q.y / q.z);
            let (o, _) = cam.ray(0, 0);
            p.offset = reduce(first_offset(p.point(o), q), p.d.x.abs().max(p.d.y.abs()));
            p.ranges();
            p.spacing = (1.0 + p.d.length_squared()).sqrt();
            p.view_dir = d;
            planes.push(p);
        }
        Projection::Perspective => {
            let hi = DVec3::from_array(dims.map(|n| (n - 1) as f64));
            let mut sums = [[DVec3::ZERO; 2]; 3];
            for j in 0..cam.height {
                for i in 0..cam.width {
                    let (o, d) = cam.ray(i, j);
                    if crate::box_span(o, d, hi).is_some() {
                        let a = major(d);
                        sums[a][(d[a] > 0.0) as usize] += d;
                    }
                }
            }
            for (a, pair) in sums.iter().enumerate() {
                for (pos, sum) in pair.iter().enumerate() {
                    if *sum == DVec3::ZERO {
                        continue;
                    }
                    let mut p = Plane::new(dims, a, pos == 1);
                    let e = p.point(cam.origin);
                    if e.z >= -0.5 {
                        return Err(CubeError::View(
                            "true3d casts rays from a face: the eye must lie outside the volume's slab along each major axis in use".into(),
                        ));
                    }
                    p.eye = Some(e);
                    let mean = p.m() * sum.normalize();
                    p.offset = first_offset(e, mean);
                    loop {
                        if p.ranges().is_none() {
                            return Err(CubeError::View("true3d: no ray meets the volume".into()));
                        }
                        let mx = (p.u[0]..=p.u[1])
                            .map(|u| p.incr(u, 0).x.abs())
                            .chain((p.v[0]..=p.v[1]).map(|v| p.incr(0, v).y.abs()))
                            .fold(0.0, f64::max);
                        let r = reduce(p.offset, mx);
                        if r == p.offset {
                            break;
                        }
                        p.offset = r;
                    }
                    p.spacing =
                        (1.0 + (mean.x / mean.z).powi(2) + (mean.y / mean.z).powi(2)).sqrt();
                    p.view_dir = sum.normalize();
                    planes.push(p);
                }
            }
        }
    }
    Ok(planes)
}

struct Caster<'a> {
    vol: &'a Volume,
    scene: &'a Scene,
    tf: TransferFn,
    light: DVec3,
    interp: Interp,
    n: u32,
}

impl Caster<'_> {
    fn voxel(&self, pl: &Plane, x: i64, y: i64, k: i64) -> f64 {
        let [nx, ny, nk] = pl.dims.map(|n| n as i64);
        if x < 0 || y < 0 || k < 0 || x >= nx || y >= ny || k >= nk {
            return 0.0;
        }
        let q = pl.dataset(DVec3::new(x as f64, y as f64, k as f64)).round();
        self.vol.get(q.x as usize, q.y as usize, q.z as usize) as f64
    }

    /// Sample of ray `(u, v)` on plane `k` (`k` may lie one beyond either end).
    fn sample(&self, pl: &Plane, u: i32, v: i32, k: i64) -> f64 {
        let lerp = |a: f64, b: f64, t: f64| a + (b - a) * t;
        match self.interp {
            Interp::Exact => {
                let p = pl.pos(u, v, k as f64);
                let (x0, y0, z0) = (p.x.floor(), p.y.floor(), p.z.floor());
                let (fx, fy, fz) = (p.x - x0, p.y - y0, p.z - z0);
                let g = |i: f64, j: f64, l: f64| {
                    self.voxel(pl, (x0 + i) as i64, (y0 + j) as i64, (z0 + l) as i64)
                };
                let plane = |l: f64| {
                    lerp(
                        lerp(g(0., 0., l), g(1., 0., l), fx),
                        lerp(g(0., 1., l), g(1., 1., l), fx),
                        fy,
                    )
                };
                lerp(plane(0.0), plane(1.0), fz)
            }
            Interp::Sheared => {
                // Discrete ray positions floor(u + k·dx) on planes k, k + 1;
                // edges at height o; weights relative to the sheared edges.
                let kf = k as f64;
                let o = pl.offset;
                // A parallel view's rays are translates of ray (0, 0): its
                // floor plus the integer (u, v). Flooring u + k·dx instead
                // rounds differently per u when dx is a hair below an
                // integer (f64's sin 45° < cos 45° gives dx = 1 - 2^-53),
                // which put neighbour rays two voxels apart.
                let dpos = |u: i32, v: i32, kk: f64| match pl.eye {
                    None => (
                        u as f64 + (kk * pl.d.x).floor(),
                        v as f64 + (kk * pl.d.y).floor(),
                    ),
                    Some(_) => {
                        let p = pl.pos(u, v, kk);
                        (p.x.floor(), p.y.floor())
                    }
                };
                let edge = |u: i32, v: i32| {
                    let (a, b) = (dpos(u, v, kf), dpos(u, v, kf + 1.0));
                    (a.0 + o * (b.0 - a.0), a.1 + o * (b.1 - a.1))
                };
                let p = pl.pos(u, v, kf);
                let (ea, eb, ec) = (edge(u, v), edge(u + 1, v), edge(u, v + 1));
                let wx = ((p.x - ea.0) / (eb.0 - ea.0)).clamp(0.0, 1.0);
                let wy = ((p.y - ea.1) / (ec.1 - ea.1)).clamp(0.0, 1.0);
                // Discrete ray (uu, vv): voxels (X_k(uu), Y_k(vv), k) and k + 1.
                let ray = |uu: i32, vv: i32| {
                    let (f, b) = (dpos(uu, vv, kf), dpos(uu, vv, kf + 1.0));
                    lerp(
                        self.voxel(pl, f.0 as i64, f.1 as i64, k),
                        self.voxel(pl, b.0 as i64, b.1 as i64, k + 1),
                        o,
                    )
                };
                lerp(
                    lerp(ray(u, v), ray(u + 1, v), wx),
                    lerp(ray(u, v + 1), ray(u + 1, v + 1), wx),
                    wy,
                )
            }
        }
    }

    /// `2∇` in traversal axes by the paper's neighbourhood, in float.
    fn gradient(&self, pl: &Plane, u: i32, v: i32, k: i64) -> DVec3 {
        let s = |i: i32, j: i32, l: i64| self.sample(pl, u + i, v + j, k + l);
        let d = pl.incr(u, v);
        let lerp = |a: f64, b: f64, t: f64| a + (b - a) * t;
        let shear = |g: DVec3| DVec3::new(g.x, g.y, g.z - d.x * g.x - d.y * g.y);
        match self.n {
            6 => shear(DVec3::new(
                s(1, 0, 0) - s(-1, 0, 0),
                s(0, 1, 0) - s(0, -1, 0),
                s(0, 0, 1) - s(0, 0, -1),
            )),
            26 => {
                let w = |m: i32| [1.0, 0.5, 0.25][(m - 1) as usize];
                let mut g = DVec3::ZERO;
                for a in -1..=1i32 {
                    for b in -1..=1i32 {
                        let wt = w(1 + a.abs() + b.abs());
                        g.x += wt * (s(1, a, b as i64) - s(-1, a, b as i64));
                        g.y += wt * (s(a, 1, b as i64) - s(a, -1, b as i64));
                        g.z += wt * (s(a, b, 1) - s(a, b, -1));
                    }
                }
                shear(g / 4.0)
            }
            10 => {
                let r = DVec3::new(d.x, d.y, 1.0);
                let (tx, ty) = (d.x / r.length_squared(), d.y / r.length_squared());
                let (sx, sy) = (d.x.signum() as i64, d.y.signum() as i64);
                let gx = lerp(s(1, 0, 0), s(1, 0, -sx), tx.abs())
                    - lerp(s(-1, 0, 0), s(-1, 0, sx), tx.abs());
                let gy = lerp(s(0, 1, 0), s(0, 1, -sy), ty.abs())
                    - lerp(s(0, -1, 0), s(0, -1, sy), ty.abs());
                let gr = s(0, 0, 1) - s(0, 0, -1);
                let b = DMat3::from_cols(DVec3::X - tx * r, DVec3::Y - ty * r, r).transpose();
                b.inverse() * DVec3::new(gx, gy, gr)
            }
            _ => {
                let (sx, sy) = (d.x.signum() as i32, d.y.signum() as i32);
                let bil = |l: i64, ex: i32, ey: i32| {
                    lerp(
                        lerp(s(0, 0, l), s(ex, 0, l), d.x.abs()),
                        lerp(s(0, ey, l), s(ex, ey, l), d.x.abs()),
                        d.y.abs(),
                    )
                };
                DVec3::new(
                    s(1, 0, 0) - s(-1, 0, 0),
                    s(0, 1, 0) - s(0, -1, 0),
                    bil(1, -sx, -sy) - bil(-1, sx, sy),
                )
            }
        }
    }

    /// The ray's base-plane value; `None` for a MIP/MinIP ray without a
    /// sample inside the volume (the warp leaves it out).
    fn ray(&self, pl: &Plane, u: i32, v: i32) -> Option<[f64; 4]> {
        let [nx, ny, nk] = pl.dims.map(|n| n as f64);
        let mode = self.scene.mode;
        let needs_grad =
            mode.uses_colour() && (self.scene.shading.enabled || self.tf.has_gradient_opacity());
        let spacing = if mode == Mode::Composite {
            pl.spacing
        } else {
            1.0
        };
        let (mut acc, mut alpha, mut ext, mut sum) = (DVec3::ZERO, 0.0, None::<f64>, 0.0);
        let to_ds = pl.m().transpose();
        for k in 0..pl.dims[2] as i64 {
            let p = pl.pos(u, v, k as f64);
            // Positions carry f64 residue (cos 90° is 6e-17, so a ray on a
            // face runs a hair outside it): within INSIDE_EPS is inside, as
            // the fixed-point models, whose slopes round to 0, have it.
            let inside = |lo: f64, hx: f64, hy: f64, hz: f64| {
                let e = INSIDE_EPS;
                p.x >= lo - e
                    && p.y >= lo - e
                    && p.z >= lo - e
                    && p.x <= hx + e
                    && p.y <= hy + e
                    && p.z <= hz + e
            };
            if !inside(0.0, nx - 1.0, ny - 1.0, nk - 1.0) {
                continue;
            }
            let s = self.sample(pl, u, v, k);
            match mode {
                Mode::Mip => ext = Some(ext.map_or(s, |e| e.max(s))),
                Mode::Minip => ext = Some(ext.map_or(s, |e| e.min(s))),
                Mode::Xray => sum += self.tf.opacity(s),
                Mode::Composite | Mode::FirstOpaque => {
                    if needs_grad && !inside(1.0, nx - 2.0, ny - 2.0, nk - 2.0) {
                        continue;
                    }
                    let a0 = self.tf.opacity(s);
                    if a0 <= 0.0 {
                        continue;
                    }
                    let g = if needs_grad {
                        to_ds * self.gradient(pl, u, v, k) / 2.0
                    } else {
                        DVec3::ZERO
                    };
                    let a = correct_opacity(a0 * self.tf.gradient_factor(g.length()), spacing);
                    if a <= 0.0 {
                        continue;
                    }
                    let c = self.tf.colour(s);
                    let c = if self.scene.shading.enabled {
                        let (df, sp) = if g.length() < 1e-12 {
                            (self.scene.shading.ambient, 0.0)
                        } else {
                            phong(
                                &self.scene.shading,
                                -g.normalize(),
                                self.light,
                                -pl.view_dir,
                            )
                        };
                        (c * df + DVec3::splat(sp)).min(DVec3::ONE)
                    } else {
                        c
                    };
                    if mode == Mode::FirstOpaque {
                        if a >= self.scene.transfer.opaque_threshold {
                            return Some([c.x, c.y, c.z, 1.0]);
                        }
                        continue;
                    }
                    acc += (1.0 - alpha) * a * c;
                    alpha += (1.0 - alpha) * a;
                }
            }
        }
        let vmax = self.vol.max_value() as f64;
        Some(match mode {
            Mode::Composite | Mode::FirstOpaque => [acc.x, acc.y, acc.z, alpha],
            Mode::Mip | Mode::Minip => [ext? / vmax, 0.0, 0.0, 0.0],
            Mode::Xray => [(sum / nk).min(1.0), 0.0, 0.0, 0.0],
        })
    }
}

/// Render `scene` with True3D (or float Sheared3D) and neighbourhood `n`.
pub fn render(scene: &Scene, cam: &Camera, vol: &Volume, n: u32, interp: Interp) -> Result<Image> {
    if ![6, 10, 12, 26].contains(&n) {
        return Err(CubeError::Hardware(format!(
            "gradient {n} unsupported (6, 10, 12 or 26)"
        )));
    }
    let planes = plan(scene, cam)?;
    let c = Caster {
        vol,
        scene,
        tf: TransferFn::new(scene),
        light: cam
            .camera_to_dataset(DVec3::from_array(scene.shading.light_dir))
            .normalize_or_zero(),
        interp,
        n,
    };
    let bases: Vec<Vec<Option<[f64; 4]>>> = planes
        .iter()
        .map(|pl| {
            (pl.v[0]..=pl.v[1])
                .into_par_iter()
                .flat_map_iter(|v| {
                    let c = &c;
                    (pl.u[0]..=pl.u[1]).map(move |u| {
                        if pl.casts(u, v) {
                            c.ray(pl, u, v)
                        } else {
                            None
                        }
                    })
                })
                .collect()
        })
        .collect();
    let dims = scene.volume.render_dims();
    let hi = DVec3::from_array(dims.map(|n| (n - 1) as f64));
    let mut img = Image::black(cam.width, cam.height);
    let mode = scene.mode;
    img.rgb
        .par_chunks_mut(cam.width as usize)
        .enumerate()
        .for_each(|(j, row)| {
            for (i, px) in row.iter_mut().enumerate() {
                let (o, d) = cam.ray(i as u32, j as u32);
                if crate::box_span(o, d, hi).is_none() {
                    continue;
                }
                let pi = if planes.len() == 1 {
                    0
                } else {
                    let a = major(d);
                    match planes
                        .iter()
                        .position(|p| p.perm[2] == a && p.positive == (d[a] > 0.0))
                    {
                        Some(i) => i,
                        None => continue,
                    }
                };
                let pl = &planes[pi];
                let (po, pd) = (pl.point(o), pl.m() * d);
                if pd.z <= 0.0 {
                    continue;
                }
                let q = po + pd * ((pl.offset - po.z) / pd.z);
                let w = (pl.u[1] - pl.u[0] + 1) as i64;
                let h = (pl.v[1] - pl.v[0] + 1) as i64;
                let (x, y) = (q.x - pl.u[0] as f64, q.y - pl.v[0] as f64);
                let (x0, y0) = (x.floor(), y.floor());
                let (fx, fy) = (x - x0, y - y0);
                let mut acc = [0.0; 4];
                let mut ws = 0.0;
                for (ox, oy, wt) in [
                    (0, 0, (1.0 - fx) * (1.0 - fy)),
                    (1, 0, fx * (1.0 - fy)),
                    (0, 1, (1.0 - fx) * fy),
                    (1, 1, fx * fy),
                ] {
                    let (cx, cy) = (x0 as i64 + ox, y0 as i64 + oy);
                    if wt <= 0.0 || cx < 0 || cy < 0 || cx >= w || cy >= h {
                        continue;
                    }
                    if let Some(v) = bases[pi][(cx + w * cy) as usize] {
                        for (a, b) in acc.iter_mut().zip(v) {
                            *a += wt * b;
                        }
                        ws += wt;
                    }
                }
                if ws > 1e-9 {
                    let v = acc.map(|a| a / ws);
                    *px = match mode {
                        Mode::Composite | Mode::FirstOpaque => [v[0], v[1], v[2]],
                        _ => [v[0]; 3],
                    }
                    .map(|c| c.clamp(0.0, 1.0));
                }
            }
        });
    Ok(img)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// At exactly 45° about the vertical axis (no tilt) the §3 offset is 0
    /// and the slope 1, so sheared and exact tri-linear samples are the
    /// same voxels (§6.1's "zero error for 45°"), though f64 gives the
    /// slope as 1 - 2^-53; and likewise at 90° and 135°.
    #[test]
    fn sheared_equals_exact_where_the_offset_is_zero_and_the_slope_whole() {
        for turn in [45, 90, 135] {
            let text = format!(
                r#"{{"volume": {{"builtin": "phantom", "dims": [40, 40, 40]}},
                "view": {{"projection": "parallel", "rotate_deg": [0, {turn}, 0]}},
                "transfer": {{"opacity": [[0, 0.0], [80, 0.0], [100, 0.2], [255, 0.2]],
                "color": [[0, 1.0, 1.0, 1.0], [255, 1.0, 1.0, 1.0]]}},
                "shading": {{"enabled": true}}, "image": [96, 96]}}"#
            );
            let scene = Scene::from_json(&text, None).unwrap();
            let vol = Volume::from_spec(&scene.volume, scene.hardware.voxel_bits).unwrap();
            let cam = scene.camera();
            let exact = render(&scene, &cam, &vol, 12, Interp::Exact).unwrap();
            let sheared = render(&scene, &cam, &vol, 12, Interp::Sheared).unwrap();
            assert!(exact.rgb.iter().any(|c| c[0] > 0.1), "{turn}°: empty");
            // The same voxels; at 90° the weight of one is 1 - 2^-53
            // rather than 1.
            let diff = exact
                .rgb
                .iter()
                .zip(&sheared.rgb)
                .flat_map(|(a, b)| (0..3).map(move |i| (a[i] - b[i]).abs()))
                .fold(0.0, f64::max);
            assert!(diff < 1e-9, "{turn}°: {diff}");
        }
    }
}
