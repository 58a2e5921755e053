//! Float reference renderer: an image-order ray caster in f64, the VolRen of
//! the Cube-3 paper (§6). Tri-linear interpolation, gradients by central
//! differences of tri-linear samples, a sample step as fine as wanted, and the
//! scene's exact transfer function and Phong shading (no LUTs).
//!
//! It shares no rendering code with the golden model: only the scene (and its
//! camera), the volume and the transfer-function / lighting formulas.
//! Software speed-ups: a min-max block grid lets samples in blocks whose value
//! range is transparent skip interpolation and classification, and rays stop
//! once their opacity exceeds `1 - 1e-4`.

pub mod metrics;
pub mod true3d;

use glam::DVec3;
use rayon::prelude::*;
use scene::lighting::phong;
use scene::transfer::{correct_opacity, TransferFn};
use scene::volume::Volume;
use scene::Image;
use scene::{Camera, Mode, Scene};

/// Default sample step along the ray, in voxel lengths.
pub const DEFAULT_STEP: f64 = 0.25;
const BLOCK: usize = 8;
const OPAQUE: f64 = 1.0 - 1e-4;

struct Caster<'a> {
    vol: &'a Volume,
    scene: &'a Scene,
    cam: &'a Camera,
    tf: TransferFn,
    vmax: f64,
    step: f64,
    light: DVec3,
    /// Colour modes with gradients treat the dataset's outer voxel layer as
    /// transparent, as the Cube-4L CFB marks it invalid (no full neighbourhood).
    inner: bool,
    blocks: BlockGrid,
}

/// Per 8^3 block: whether any sample inside (with a one-voxel apron) can be
/// non-transparent.
struct BlockGrid {
    n: [usize; 3],
    live: Vec<bool>,
}

impl BlockGrid {
    fn new(vol: &Volume, tf: &TransferFn, mode: Mode) -> BlockGrid {
        let n = vol.dims.map(|d| d.div_ceil(BLOCK));
        let mut live = vec![true; n[0] * n[1] * n[2]];
        if matches!(mode, Mode::Mip | Mode::Minip) {
            return BlockGrid { n, live };
        }
        for bz in 0..n[2] {
            for by in 0..n[1] {
                for bx in 0..n[0] {
                    let r = |b: usize, a: usize| {
                        (b * BLOCK).saturating_sub(1)..((b + 1) * BLOCK + 1).min(vol.dims[a])
                    };
                    let (mut lo, mut hi) = (u16::MAX, 0u16);
                    for w in r(bz, 2) {
                        for v in r(by, 1) {
                            for u in r(bx, 0) {
                                let x = vol.get(u, v, w);
                                lo = lo.min(x);
                                hi = hi.max(x);
                            }
                        }
                    }
                    live[bx + n[0] * (by + n[1] * bz)] =
                        max_opacity(tf, lo as f64, hi as f64) > 0.0;
                }
            }
        }
        BlockGrid { n, live }
    }

    fn live_at(&self, p: DVec3) -> bool {
        let b = |a: usize| ((p[a].max(0.0) as usize) / BLOCK).min(self.n[a] - 1);
        self.live[b(0) + self.n[0] * (b(1) + self.n[1] * b(2))]
    }
}

/// Largest opacity the transfer function reaches over `[lo, hi]`: at the ends
/// or at a control point inside (it is piecewise linear).
fn max_opacity(tf: &TransferFn, lo: f64, hi: f64) -> f64 {
    let mut m = tf.opacity(lo).max(tf.opacity(hi));
    let mut x = lo;
    while x <= hi {
        m = m.max(tf.opacity(x));
        x += 1.0;
    }
    m
}

impl Caster<'_> {
    fn value(&self, p: DVec3) -> f64 {
        let d = self.vol.dims;
        let c = |a: usize| p[a].clamp(0.0, (d[a] - 1) as f64);
        let (x, y, z) = (c(0), c(1), c(2));
        let (x0, y0, z0) = (x.floor() as usize, y.floor() as usize, z.floor() as usize);
        let (x1, y1, z1) = (
            (x0 + 1).min(d[0] - 1),
            (y0 + 1).min(d[1] - 1),
            (z0 + 1).min(d[2] - 1),
        );
        let (fx, fy, fz) = (x - x0 as f64, y - y0 as f64, z - z0 as f64);
        let g = |u, v, w| self.vol.get(u, v, w) as f64;
        let l = |a: f64, b: f64, t: f64| a + (b - a) * t;
        l(
            l(
                l(g(x0, y0, z0), g(x1, y0, z0), fx),
                l(g(x0, y1, z0), g(x1, y1, z0), fx),
                fy,
            ),
            l(
                l(g(x0, y0, z1), g(x1, y0, z1), fx),
                l(g(x0, y1, z1), g(x1, y1, z1), fx),
                fy,
            ),
            fz,
        )
    }

    /// Gradient in voxel units per voxel, by central differences of samples.
    fn gradient(&self, p: DVec3) -> DVec3 {
        let d = |e: DVec3| (self.value(p + e) - self.value(p - e)) / 2.0;
        DVec3::new(d(DVec3::X), d(DVec3::Y), d(DVec3::Z))
    }

    fn inside_domain(&self, p: DVec3) -> bool {
        !self.inner || (0..3).all(|a| p[a] >= 1.0 && p[a] <= (self.vol.dims[a] - 2) as f64)
    }

    /// Opacity per voxel length and shaded colour at `p`.
    fn classify(&self, p: DVec3, v: f64) -> (f64, Option<DVec3>) {
        if !self.inside_domain(p) {
            return (0.0, None);
        }
        let a0 = self.tf.opacity(v);
        if a0 <= 0.0 {
            return (0.0, None);
        }
        let needs_grad = self.scene.shading.enabled || self.tf.has_gradient_opacity();
        let g = if needs_grad {
            self.gradient(p)
        } else {
            DVec3::ZERO
        };
        let a = a0 * self.tf.gradient_factor(g.length());
        if a <= 0.0 {
            return (0.0, None);
        }
        let colour = self.tf.colour(v);
        let shaded = if self.scene.shading.enabled {
            let (diff, spec) = if g.length() < 1e-12 {
                (self.scene.shading.ambient, 0.0)
            } else {
                phong(
                    &self.scene.shading,
                    -g.normalize(),
                    self.light,
                    self.cam.to_viewer(p),
                )
            };
            (colour * diff + DVec3::splat(spec)).min(DVec3::ONE)
        } else {
            colour
        };
        (a, Some(shaded))
    }

    fn pixel(&self, i: u32, j: u32) -> [f64; 3] {
        let (o, d) = self.cam.ray(i, j);
        let n = self.vol.dims;
        let hi = DVec3::new((n[0] - 1) as f64, (n[1] - 1) as f64, (n[2] - 1) as f64);
        let Some((t0, t1)) = box_span(o, d, hi) else {
            return [0.0; 3];
        };
        let mode = self.scene.mode;
        let major = d.abs().max_element();
        let depth = n[d.abs().to_array().iter().position(|&c| c == major).unwrap()] as f64;
        let (mut acc, mut alpha, mut extreme, mut xray) = (DVec3::ZERO, 0.0, None::<f64>, 0.0);
        let mut t = t0;
        while t <= t1 + 1e-9 {
            let p = o + d * t;
            if !self.blocks.live_at(p) {
                t += self.step;
                continue;
            }
            let v = self.value(p);
            match mode {
                Mode::Mip => extreme = Some(extreme.map_or(v, |e| e.max(v))),
                Mode::Minip => extreme = Some(extreme.map_or(v, |e| e.min(v))),
                Mode::Xray => {
                    if self.inside_domain(p) {
                        xray += self.tf.opacity(v) * self.step * major / depth;
                    }
                }
                Mode::Composite => {
                    let (a, c) = self.classify(p, v);
                    if let Some(c) = c {
                        let a = correct_opacity(a, self.step);
                        acc += (1.0 - alpha) * a * c;
                        alpha += (1.0 - alpha) * a;
                        if alpha > OPAQUE {
                            break;
                        }
                    }
                }
                Mode::FirstOpaque => {
                    let (a, c) = self.classify(p, v);
                    if let Some(c) = c {
                        if a >= self.scene.transfer.opaque_threshold {
                            acc = c;
                            break;
                        }
                    }
                }
            }
            t += self.step;
        }
        match mode {
            Mode::Composite | Mode::FirstOpaque => acc.to_array(),
            Mode::Mip | Mode::Minip => [extreme.unwrap_or(0.0) / self.vmax; 3],
            Mode::Xray => [xray.min(1.0); 3],
        }
    }
}

/// Render `scene` with sample step `step` (voxel lengths).
pub fn render(scene: &Scene, cam: &Camera, vol: &Volume, step: f64) -> Image {
    assert!(
        step > 0.0 && step.is_finite(),
        "reference step must be positive"
    );
    let tf = TransferFn::new(scene);
    let light = cam
        .camera_to_dataset(DVec3::from_array(scene.shading.light_dir))
        .normalize_or_zero();
    let c = Caster {
        vol,
        scene,
        cam,
        blocks: BlockGrid::new(vol, &tf, scene.mode),
        tf,
        vmax: vol.max_value() as f64,
        step,
        light,
        inner: scene.mode.uses_colour()
            && (scene.shading.enabled || scene.transfer.gradient_opacity.is_some()),
    };
    let mut img = Image::black(cam.width, cam.height);
    img.rgb
        .par_chunks_mut(cam.width as usize)
        .enumerate()
        .for_each(|(j, row)| {
            for (i, px) in row.iter_mut().enumerate() {
                *px = c.pixel(i as u32, j as u32);
            }
        });
    img
}

/// Where the ray `o + t·d` (`t >= 0`) is inside the box `[0, hi]`:
/// `(t_in, t_out)`, or `None` if it misses.
pub(crate) fn box_span(o: DVec3, d: DVec3, hi: DVec3) -> Option<(f64, f64)> {
    let (mut t0, mut t1) = (0.0f64, f64::INFINITY);
    for a in 0..3 {
        if d[a].abs() < 1e-300 {
            if o[a] < 0.0 || o[a] > hi[a] {
                return None;
            }
            continue;
        }
        let (mut n0, mut n1) = (-o[a] / d[a], (hi[a] - o[a]) / d[a]);
        if n0 > n1 {
            std::mem::swap(&mut n0, &mut n1);
        }
        t0 = t0.max(n0);
        t1 = t1.min(n1);
    }
    (t0 <= t1).then_some((t0, t1))
}
