//! The Cube-3 golden model (Pfister, Wessels & Kaufman, "Sheared
//! interpolation and gradient estimation for real-time volume rendering"):
//! template rays cast from a base plane (§2), their Projection Ray Planes
//! fetched as beams and sheared or de-fanned into 2-D skewed buffers (`prp`),
//! sheared tri-linear interpolation (`trilin`, §3), ABC gradients over the
//! above, current and below sample planes (`abc`, §4), shading and
//! classification by the kit's shader (`common::shader`, fed as `shade`
//! says), and the Ray Projection Cone (`rpc`, §5).
//! The base planes are warped to the image by the kit's warp.
//!
//! Dataflow for one base plane, scanline by scanline as the hardware does:
//! PRP `v + 1` is fetched while planes `v` and `v + 1` are interpolated, so
//! three 2-D buffers rotate; the sample plane of `v` is shaded once the
//! planes of `v - 1` and `v + 1` exist. Scanlines are independent given the
//! volume, so the software runs chunks of them on all cores (the result
//! does not depend on the split).
//!
//! Software shortcuts that cannot change a bit: samples whose opacity row is
//! zero skip the gradient, and a ray whose accumulated α is full stops
//! (`rpc`); where samples sit on the grid the interpolation is skipped
//! (`trilin`).

pub mod abc;
pub mod plan;
pub mod prp;
pub mod regs;
pub mod rpc;
pub mod shade;
pub mod surface;
pub mod trilin;

use crate::common::shader::Shader;
use abc::{gradient, Planes, RayCoeffs};
use plan::{sample_pos, Neighbourhood, Plan, View, Widths};
use rayon::prelude::*;
use rpc::{fold, identity, node, pixel};
use scene::volume::Voxels;
use scene::{Camera, CubeError, Image, Mode, Result, Scene};
use trilin::SamplePlane;

/// The base-plane image of one view: pixel `(u, v)` for `u` in
/// `u0..u0 + width`; `cast` is false where no ray was cast.
#[derive(Debug, Clone)]
pub struct BasePlane {
    pub u0: i32,
    pub v0: i32,
    pub width: usize,
    pub height: usize,
    pub pixels: Vec<[u32; 4]>,
    pub cast: Vec<bool>,
}

/// Work counters of a frame.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Stats {
    pub rays: u64,
    /// Samples taken (interpolated or on the grid).
    pub samples: u64,
    /// Samples through the TRILIN unit (0 when the samples sit on the grid).
    pub interpolated: u64,
    /// Samples through gradient and shading.
    pub shaded: u64,
    /// Samples skipped by early ray termination.
    pub terminated: u64,
    pub gradient_saturations: u64,
    pub composite_saturations: u64,
    /// Template weights clamped to [0, 1] (perspective frusta).
    pub weight_clamps: u64,
}

impl std::ops::Add for Stats {
    type Output = Stats;
    fn add(self, o: Stats) -> Stats {
        Stats {
            rays: self.rays + o.rays,
            samples: self.samples + o.samples,
            interpolated: self.interpolated + o.interpolated,
            shaded: self.shaded + o.shaded,
            terminated: self.terminated + o.terminated,
            gradient_saturations: self.gradient_saturations + o.gradient_saturations,
            composite_saturations: self.composite_saturations + o.composite_saturations,
            weight_clamps: self.weight_clamps + o.weight_clamps,
        }
    }
}

/// A whole Cube-3 frame.
#[derive(Debug, Clone)]
pub struct Frame {
    pub plan: Plan,
    pub bases: Vec<BasePlane>,
    pub stats: Stats,
    pub widths: Widths,
    pub neighbourhood: Neighbourhood,
    pub pipelines: usize,
}

/// The scene's gradient neighbourhood, or `n` when given.
pub fn neighbourhood(scene: &Scene, n: Option<u32>) -> Result<Neighbourhood> {
    let c = n.unwrap_or(scene.cube3.gradient);
    Neighbourhood::from_count(c).ok_or_else(|| {
        CubeError::Hardware(format!("cube3.gradient {c} unsupported (6, 10, 12 or 26)"))
    })
}

/// The view's scanlines in ascending runs, `[first, last]`: each run
/// fetches three PRPs and interpolates two sample planes beyond its own (for
/// the gradients), so runs are as long as four per thread allow, and at
/// least 8 scanlines. The result does not depend on the split.
pub fn chunks(view: &View) -> Vec<[i32; 2]> {
    let lines = (view.v[1] - view.v[0] + 1).max(1) as usize;
    let run = lines.div_ceil(4 * rayon::current_num_threads()).max(8);
    (view.v[0]..=view.v[1])
        .step_by(run)
        .map(|va| [va, (va + run as i32 - 1).min(view.v[1])])
        .collect()
}

/// Render one base plane.
pub fn render_view(
    vol: &dyn Voxels,
    view: &View,
    shader: &Shader,
    n: Neighbourhood,
    p: usize,
) -> (BasePlane, Stats) {
    let [w, h] = view.base_dims();
    let (u0, v0) = (view.u[0], view.v[0]);
    let vol = &prp::Traversal::new(vol, view);
    let identity = &shade::identity_table(shader);
    let rows: Vec<(Vec<[u32; 4]>, Vec<bool>, Stats)> = chunks(view)
        .into_par_iter()
        .map(|[va, vb]| render_rows(vol, view, (shader, identity), n, p, va, vb))
        .collect();
    let mut base = BasePlane {
        u0,
        v0,
        width: w,
        height: h,
        pixels: Vec::with_capacity(w * h),
        cast: Vec::with_capacity(w * h),
    };
    // TRILIN's samples in one pass down the base plane: every scanline's
    // plane, and with gradients the planes above the first and below the
    // last (independent of how the software splits the scanlines).
    let planes = h as u64 + 2 * shader.needs_gradient as u64;
    let rays = (view.u[1] - view.u[0] + 3) as u64;
    let mut stats = Stats {
        weight_clamps: view.weight_clamps,
        interpolated: if view.on_grid {
            0
        } else {
            planes * rays * view.dims[2] as u64
        },
        ..Stats::default()
    };
    for (px, cast, s) in rows {
        base.pixels.extend(px);
        base.cast.extend(cast);
        stats = stats + s;
    }
    (base, stats)
}

/// Walk scanlines `va..=vb`, calling `visit(v, planes)` with the above,
/// current and below sample planes of each (above and below are zero when
/// `gradients` is false). PRPs `va - 1 ..= vb + 2` are fetched, sample planes
/// `va - 1 ..= vb + 1` interpolated, in a window of three.
pub fn scanlines(
    vol: &prp::Traversal,
    view: &View,
    sample_frac: u32,
    gradients: bool,
    [va, vb]: [i32; 2],
    mut visit: impl FnMut(i32, &Planes),
) {
    let (pu0, prays) = (view.u[0] - 1, (view.u[1] - view.u[0] + 4) as usize);
    let fetch = |v: i32| prp::fetch(vol, view, v, pu0, prays);
    let nk = view.dims[2];
    let zero = |v: i32| SamplePlane::zero(v, pu0, prays - 1, nk);
    let interp =
        |v: i32, cur: &prp::Prp, next: &prp::Prp| trilin::plane(view, v, cur, next, sample_frac);
    let mut cur = fetch(va - 1);
    let mut next = fetch(va);
    let mut above = if gradients {
        interp(va - 1, &cur, &next)
    } else {
        zero(va - 1)
    };
    cur = next;
    next = fetch(va + 1);
    let mut current = interp(va, &cur, &next);
    for v in va..=vb {
        let below = if gradients || v < vb {
            cur = next;
            next = fetch(v + 2);
            interp(v + 1, &cur, &next)
        } else {
            zero(v + 1)
        };
        visit(
            v,
            &Planes {
                above: &above,
                current: &current,
                below: &below,
            },
        );
        above = current;
        current = below;
    }
}

/// Scanlines `va..=vb` of a base plane: pixels, cast flags and counters
/// (`shading`: the shader and its `shade::identity_table`).
fn render_rows(
    vol: &prp::Traversal,
    view: &View,
    shading: (&Shader, &[bool]),
    n: Neighbourhood,
    p: usize,
    va: i32,
    vb: i32,
) -> (Vec<[u32; 4]>, Vec<bool>, Stats) {
    let mut stats = Stats::default();
    let mut pixels = Vec::new();
    let mut cast = Vec::new();
    let shader = shading.0;
    let f = shader.sample_frac;
    scanlines(
        vol,
        view,
        f,
        shader.needs_gradient,
        [va, vb],
        |v, window| {
            // A ray's estimator constants, kept while its increments repeat
            // (every ray of a parallel view).
            let mut coeffs: Option<RayCoeffs> = None;
            for u in view.u[0]..=view.u[1] {
                if !view.casts(u, v) {
                    cast.push(false);
                    pixels.push([0; 4]);
                    continue;
                }
                stats.rays += 1;
                if shader.needs_gradient {
                    let (dx, dy, w) = (view.x.d(u), view.y.d(v), view.weight_bits);
                    if coeffs.is_none_or(|c| (c.dx, c.dy) != (dx, dy)) {
                        coeffs = Some(RayCoeffs::new(dx, dy, w));
                    }
                }
                let (px, any, s) = cast_ray(view, shading, n, p, window, coeffs.as_ref(), u, v);
                // A MIP/MinIP ray without a sample inside the volume has
                // no value: the warp leaves it out, as it does uncast rays.
                cast.push(any);
                pixels.push(px);
                stats = stats + s;
            }
        },
    );
    (pixels, cast, stats)
}

/// One ray through the RPC: its base-plane pixel, whether it holds a value
/// (MIP/MinIP: some sample was inside the volume) and counters.
#[allow(clippy::too_many_arguments)]
fn cast_ray(
    view: &View,
    (shader, zero): (&Shader, &[bool]),
    n: Neighbourhood,
    p: usize,
    planes: &Planes,
    coeffs: Option<&RayCoeffs>,
    u: i32,
    v: i32,
) -> ([u32; 4], bool, Stats) {
    let w = view.weight_bits;
    let [nx, ny, nk] = view.dims;
    let (dx, dy) = (view.x.d(u), view.y.d(v));
    let mode = shader.mode;
    let f = shader.sample_frac;
    let rgba = shader.rgba_bits;
    let m = crate::fixed::max_of(rgba);
    let within = |q: i64, lo: i64, hi: i64| q >= lo << w && q <= hi << w;
    let mut st = Stats::default();
    let id = identity(mode);
    let mut acc = id;
    let mut leaves = vec![id; p];
    let ray = planes.current.ray(u);
    for seg in 0..nk.div_ceil(p) {
        if matches!(mode, Mode::Composite | Mode::FirstOpaque) && acc.value[3] == m {
            st.terminated += (nk - seg * p) as u64;
            break;
        }
        // A segment of zero leaves leaves the accumulator as it is, with no
        // clipped node: its samples are counted and skipped.
        let samples = &ray[seg * p..((seg + 1) * p).min(nk)];
        if samples.iter().all(|&s| zero[(s >> f) as usize]) {
            st.samples += samples.len() as u64;
            continue;
        }
        for (i, leaf) in leaves.iter_mut().enumerate() {
            let k = seg * p + i;
            if k >= nk {
                *leaf = id;
                continue;
            }
            st.samples += 1;
            let xq = sample_pos(u, k, dx, w);
            let yq = sample_pos(v, k, dy, w);
            let zq = ((k as i64) << w) + view.offset as i64;
            let (nx, ny, nk) = (nx as i64, ny as i64, nk as i64);
            let inside = within(xq, 0, nx - 1) && within(yq, 0, ny - 1) && within(zq, 0, nk - 1);
            let inner = within(xq, 1, nx - 2) && within(yq, 1, ny - 2) && within(zq, 1, nk - 2);
            let s = planes.current.at(u, k);
            let mut shaded = false;
            *leaf = shade::leaf(shader, s, inside, inner, || {
                shaded = true;
                let (g, sat) = gradient(
                    n,
                    planes,
                    u,
                    k,
                    coeffs.expect("the ray's estimator constants, with gradients"),
                    w,
                    shader.gradient_bits,
                );
                st.gradient_saturations += sat as u64;
                g
            });
            st.shaded += shaded as u64;
        }
        // A segment of identities leaves the accumulator as it is, with no
        // clipped node (`op(x, id) = op(id, x) = x`).
        if leaves.iter().any(|l| *l != id) {
            let c1 = fold(mode, &mut leaves, rgba);
            let (a, c2) = node(mode, acc, leaves[0], rgba);
            acc = a;
            st.composite_saturations += c1 + c2 as u64;
        }
    }
    (pixel(mode, acc, shader.voxel_bits), acc.valid, st)
}

/// Render every base plane of the view (`vol`: a
/// [`scene::volume::Volume`], or an [`scene::volume::Ordered`] that keeps its
/// traversal-order copies for the next frame).
pub fn render(scene: &Scene, camera: &Camera, vol: &dyn Voxels, n: Neighbourhood) -> Result<Frame> {
    let plan = Plan::new(scene, camera)?;
    let p = scene.hardware.pipelines;
    let mut bases = Vec::new();
    let mut stats = Stats::default();
    for view in &plan.views {
        let shader = Shader::new(scene, camera, view);
        let (b, s) = render_view(vol, view, &shader, n, p);
        bases.push(b);
        stats = stats + s;
    }
    Ok(Frame {
        plan,
        bases,
        stats,
        widths: Widths::of(scene),
        neighbourhood: n,
        pipelines: p,
    })
}

/// Render a scene with the Cube-3 golden model to the final image.
pub fn render_image(scene: &Scene, vol: &dyn Voxels, n: Neighbourhood) -> Result<(Image, Frame)> {
    let camera = scene.camera();
    let frame = render(scene, &camera, vol, n)?;
    let img = warp(&frame, &camera, scene.mode);
    Ok((img, frame))
}

/// Warp the base planes to the image: each pixel's ray meets its base
/// plane's start plane (`k = O`) at continuous `(x, y)`, where the cast
/// pixels are resampled bilinearly (`common::warp::bilinear`).
pub fn warp(frame: &Frame, camera: &Camera, mode: Mode) -> Image {
    let wd = frame.widths;
    let dims = {
        let v = &frame.plan.views[0];
        let mut d = [0usize; 3];
        for i in 0..3 {
            d[v.perm[i]] = v.dims[i];
        }
        d
    };
    let hi = glam::DVec3::from_array(dims.map(|n| (n - 1) as f64));
    crate::common::warp::warp_with(camera, |o, d| {
        crate::common::plan::slab(o, d, glam::DVec3::ZERO, hi)?;
        let vi = frame.plan.view_for(d)?;
        let (view, base) = (&frame.plan.views[vi], &frame.bases[vi]);
        let (po, pd) = (view.point(o), view.to_traversal() * d);
        if pd.z <= 0.0 {
            return None;
        }
        let z = view.offset as f64 / (1u64 << view.weight_bits) as f64;
        let q = po + pd * ((z - po.z) / pd.z);
        let at = glam::DVec2::new(q.x - base.u0 as f64, q.y - base.v0 as f64);
        let v = crate::common::warp::bilinear(base.width, base.height, at, |i| {
            base.cast[i].then(|| base.pixels[i])
        })?;
        Some(crate::common::warp::to_rgb(
            mode,
            v,
            wd.rgba_bits,
            wd.voxel_bits,
            view.dims[2],
        ))
    })
}
