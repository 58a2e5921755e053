//! Volumes: raw files (little-endian, x fastest) and the built-in synthetic
//! volumes. Voxels are unsigned integers of the scene's `voxel_bits`.

use crate::error::{CubeError, Result};
use glam::DVec3;
use rayon::prelude::*;
use serde::Deserialize;
use std::ops::Deref;
use std::path::PathBuf;
use std::sync::{Arc, Mutex};
use std::time::Instant;

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct VolumeSpec {
    pub builtin: Option<String>,
    pub raw: Option<PathBuf>,
    pub dims: [usize; 3],
    #[serde(rename = "type")]
    pub kind: Option<RawType>,
    pub window: Option<[f64; 2]>,
    /// Optional sub-box of the loaded volume; the scene then renders it alone.
    #[serde(default, deserialize_with = "crate::spec::optional_object")]
    pub crop: Option<Crop>,
    /// The built-in sphere's shell: the width in voxels of its
    /// volume-sampling ramp (default [`SPHERE_SHELL`]).
    pub shell: Option<f64>,
}

/// The built-in sphere's default shell: a one-voxel box filter.
pub const SPHERE_SHELL: f64 = 1.0;

/// The widest shell a scene may ask for, in voxels.
pub const MAX_SHELL: f64 = 16.0;

#[derive(Debug, Clone, Copy, Deserialize, PartialEq, Eq)]
#[serde(deny_unknown_fields)]
pub struct Crop {
    pub offset: [usize; 3],
    pub dims: [usize; 3],
}

impl VolumeSpec {
    /// Dims of the volume the scene renders (after any crop).
    pub fn render_dims(&self) -> [usize; 3] {
        self.crop.map_or(self.dims, |c| c.dims)
    }
}

#[derive(Debug, Clone, Copy, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "lowercase")]
pub enum RawType {
    U8,
    U16,
    I16,
}

impl RawType {
    pub fn bytes(self) -> usize {
        match self {
            RawType::U8 => 1,
            RawType::U16 | RawType::I16 => 2,
        }
    }
}

/// Largest value of an unsigned `bits`-wide voxel, `2^bits - 1`.
pub fn max_value(bits: u32) -> u32 {
    ((1u64 << bits) - 1) as u32
}

#[derive(Debug, Clone)]
pub struct Volume {
    pub dims: [usize; 3],
    pub bits: u32,
    /// `dims[0] * dims[1] * dims[2]` voxels, x fastest.
    pub data: Vec<u16>,
}

/// Voxels in a renderer's traversal order: the volume's own where that is
/// their order, else a copy ([`Volume::permuted`]).
#[derive(Debug, Clone)]
pub enum InOrder<'a> {
    Own(&'a [u16]),
    Copy(Arc<Vec<u16>>),
}

impl Deref for InOrder<'_> {
    type Target = [u16];
    fn deref(&self) -> &[u16] {
        match self {
            InOrder::Own(d) => d,
            InOrder::Copy(d) => d,
        }
    }
}

/// What a renderer reads: a volume, and its voxels in a traversal order. A
/// [`Volume`] makes the copy at every call; an [`Ordered`] keeps it for the
/// frames after.
pub trait Voxels: Sync {
    fn volume(&self) -> &Volume;

    /// The voxels with dataset axis `perm[0]` fastest, then `perm[1]`, then
    /// `perm[2]` (a renderer's traversal order, so that its rows are
    /// contiguous).
    fn in_order(&self, perm: [usize; 3]) -> InOrder<'_>;
}

impl Voxels for Volume {
    fn volume(&self) -> &Volume {
        self
    }

    fn in_order(&self, perm: [usize; 3]) -> InOrder<'_> {
        match perm {
            [0, 1, 2] => InOrder::Own(&self.data),
            _ => InOrder::Copy(Arc::new(self.permuted(perm))),
        }
    }
}

/// A volume and the copies of its voxels in the traversal orders renderers
/// have asked for, kept for the frames after: a view that keeps its major
/// axis pays for its copy in its first frame only, as a peer's per-volume
/// preparation. The golden models ask for the two cyclic orders other than
/// the volume's own at most, so at most two copies are kept. The volume is
/// borrowed while the copies live: it cannot change under them.
#[derive(Debug)]
pub struct Ordered<'a> {
    volume: &'a Volume,
    kept: Mutex<Kept>,
}

#[derive(Debug, Default)]
struct Kept {
    copies: Vec<([usize; 3], Arc<Vec<u16>>)>,
    seconds: f64,
}

impl<'a> Ordered<'a> {
    pub fn new(volume: &'a Volume) -> Ordered<'a> {
        Ordered {
            volume,
            kept: Mutex::default(),
        }
    }

    /// The seconds spent making copies so far (`None`: none was made).
    pub fn copy_seconds(&self) -> Option<f64> {
        let k = self.kept.lock().expect("no copy panics");
        (!k.copies.is_empty()).then_some(k.seconds)
    }
}

impl Voxels for Ordered<'_> {
    fn volume(&self) -> &Volume {
        self.volume
    }

    fn in_order(&self, perm: [usize; 3]) -> InOrder<'_> {
        if perm == [0, 1, 2] {
            return InOrder::Own(&self.volume.data);
        }
        let kept = |k: &Kept| k.copies.iter().find(|c| c.0 == perm).map(|c| c.1.clone());
        if let Some(c) = kept(&self.kept.lock().expect("no copy panics")) {
            return InOrder::Copy(c);
        }
        // Copied without the lock: the copy runs on the pool, whose threads
        // may ask for another order meanwhile.
        let t = Instant::now();
        let copy = Arc::new(self.volume.permuted(perm));
        let mut k = self.kept.lock().expect("no copy panics");
        k.seconds += t.elapsed().as_secs_f64();
        match kept(&k) {
            Some(c) => InOrder::Copy(c),
            None => {
                k.copies.push((perm, copy.clone()));
                InOrder::Copy(copy)
            }
        }
    }
}

/// Built-in volumes: name and one-line description.
pub const BUILTINS: &[(&str, &str)] = &[
    ("sphere", "volume-sampled (anti-aliased) solid sphere, radius 0.4 of the smallest side, analytic normals known; its shell a ramp of 'shell' voxels (default 1)"),
    ("phantom", "head-like phantom: skull shell, brain, ventricles and a dense lesion"),
    ("head", "anatomical head facing +z, top at +y: skin, skull with orbits, nasal aperture, cheekbones, jaw and teeth, brain and ventricles, neck and spine; every boundary a straight ramp about 4 voxels wide, so it renders without terraces"),
    ("checkerboard", "alternating empty and full-scale cubes, 8 per side"),
    ("ramp", "intensity rising linearly along x from 0 to full scale"),
    ("impulse", "one full-scale voxel at the centre, the rest empty"),
    ("empty", "all voxels zero"),
];

impl Volume {
    pub fn index(&self, u: usize, v: usize, w: usize) -> usize {
        u + self.dims[0] * (v + self.dims[1] * w)
    }

    pub fn get(&self, u: usize, v: usize, w: usize) -> u16 {
        self.data[self.index(u, v, w)]
    }

    pub fn max_value(&self) -> u32 {
        max_value(self.bits)
    }

    /// A copy of the voxels in the order of [`Voxels::in_order`]. The inner
    /// loop runs along the dataset's shorter stride
    /// of the first two: a stride of whole slices would map every read of a
    /// row to one cache set.
    pub fn permuted(&self, perm: [usize; 3]) -> Vec<u16> {
        let stride = [1, self.dims[0], self.dims[0] * self.dims[1]];
        let [nx, ny, _] = perm.map(|a| self.dims[a]);
        let [sx, sy, sz] = perm.map(|a| stride[a]);
        let mut out = vec![0; self.data.len()];
        if sz == 1 {
            // The output's planes are the dataset's fastest axis: a plane
            // at a time would use one voxel of every cache line it reads.
            // PLANES planes at once read whole runs of that axis.
            const PLANES: usize = 32;
            let nz = self.dims[perm[2]];
            out.par_chunks_mut(nx * ny * PLANES)
                .enumerate()
                .for_each(|(g, planes)| {
                    let z0 = g * PLANES;
                    let k = PLANES.min(nz - z0);
                    for y in 0..ny {
                        for x in 0..nx {
                            let run = &self.data[z0 + y * sy + x * sx..][..k];
                            for (dz, &d) in run.iter().enumerate() {
                                planes[dz * nx * ny + y * nx + x] = d;
                            }
                        }
                    }
                });
            return out;
        }
        out.par_chunks_mut(nx * ny)
            .enumerate()
            .for_each(|(z, plane)| {
                let slice = &self.data[z * sz..];
                if sx <= sy {
                    for (y, row) in plane.chunks_exact_mut(nx).enumerate() {
                        for (x, d) in row.iter_mut().enumerate() {
                            *d = slice[y * sy + x * sx];
                        }
                    }
                } else {
                    // In tiles, so that neither the reads nor the writes
                    // stride through more cache lines than a tile's side.
                    const TILE: usize = 32;
                    for x0 in (0..nx).step_by(TILE) {
                        for y0 in (0..ny).step_by(TILE) {
                            for x in x0..(x0 + TILE).min(nx) {
                                for y in y0..(y0 + TILE).min(ny) {
                                    plane[y * nx + x] = slice[y * sy + x * sx];
                                }
                            }
                        }
                    }
                }
            });
        out
    }

    /// Load the volume a scene describes (cropped when the scene says so).
    pub fn from_spec(spec: &VolumeSpec, bits: u32) -> Result<Volume> {
        let vol = Self::load_whole(spec, bits)?;
        Ok(match spec.crop {
            Some(c) => vol.crop(c.offset, c.dims),
            None => vol,
        })
    }

    /// The sub-box at `offset` of size `dims` (which must lie inside).
    pub fn crop(&self, offset: [usize; 3], dims: [usize; 3]) -> Volume {
        let mut data = Vec::with_capacity(dims.iter().product());
        for w in 0..dims[2] {
            for v in 0..dims[1] {
                for u in 0..dims[0] {
                    data.push(self.get(u + offset[0], v + offset[1], w + offset[2]));
                }
            }
        }
        Volume {
            dims,
            bits: self.bits,
            data,
        }
    }

    fn load_whole(spec: &VolumeSpec, bits: u32) -> Result<Volume> {
        match (&spec.builtin, &spec.raw) {
            (Some(name), None) if name == "sphere" => {
                Ok(sphere(spec.dims, bits, spec.shell.unwrap_or(SPHERE_SHELL)))
            }
            (Some(name), None) => builtin(name, spec.dims, bits),
            (None, Some(path)) => {
                let kind = spec
                    .kind
                    .ok_or_else(|| CubeError::Volume("raw volume needs 'type'".into()))?;
                let bytes = read_raw(path, spec.dims, kind)?;
                from_raw(&bytes, spec.dims, kind, spec.window, bits)
                    .map_err(|e| CubeError::Volume(format!("{}: {e}", path.display())))
            }
            _ => Err(CubeError::Volume(
                "volume needs exactly one of 'builtin' and 'raw'".into(),
            )),
        }
    }
}

/// Read a raw volume file, checking first (with `stat`, which never blocks)
/// that it is a regular file of exactly the size `dims` and `kind` need: a
/// FIFO, a device or a directory is refused before it is opened, and a file
/// of the wrong size before it is read.
fn read_raw(path: &std::path::Path, dims: [usize; 3], kind: RawType) -> Result<Vec<u8>> {
    let io = |err| CubeError::Io {
        path: path.display().to_string(),
        err,
    };
    let meta = std::fs::metadata(path).map_err(io)?;
    let err = |msg: String| CubeError::Volume(format!("raw {}: {msg}", path.display()));
    if !meta.is_file() {
        return Err(err("not a regular file".into()));
    }
    let want = dims.iter().product::<usize>() * kind.bytes();
    if meta.len() != want as u64 {
        return Err(err(format!(
            "file has {} bytes but dims {dims:?} x {kind:?} need {want}",
            meta.len()
        )));
    }
    std::fs::read(path).map_err(io)
}

/// Decode little-endian raw bytes. With `window = [lo, hi]` a raw value `r`
/// becomes `round(clamp((r - lo) / (hi - lo), 0, 1) * (2^bits - 1))`; without a
/// window raw values are taken as they are and must fit in `bits`.
pub fn from_raw(
    bytes: &[u8],
    dims: [usize; 3],
    kind: RawType,
    window: Option<[f64; 2]>,
    bits: u32,
) -> std::result::Result<Volume, String> {
    let n: usize = dims.iter().product();
    let want = n * kind.bytes();
    if bytes.len() != want {
        return Err(format!(
            "file has {} bytes but dims {dims:?} x {kind:?} need {want}",
            bytes.len()
        ));
    }
    // Raw values one at a time, with no copy of the volume wider than the
    // result (a 512³ volume of f64 would take 1 GiB).
    let raw = |i: usize| -> f64 {
        match kind {
            RawType::U8 => bytes[i] as f64,
            RawType::U16 => u16::from_le_bytes([bytes[2 * i], bytes[2 * i + 1]]) as f64,
            RawType::I16 => i16::from_le_bytes([bytes[2 * i], bytes[2 * i + 1]]) as f64,
        }
    };
    let vmax = max_value(bits);
    let data = match window {
        Some([lo, hi]) => {
            // The scene refuses windows whose width overflows; check here
            // too, since this is public.
            let width = hi - lo;
            if !(width.is_finite() && width > 0.0) {
                return Err(format!("window [{lo}, {hi}] must be finite with hi > lo"));
            }
            (0..n)
                .map(|i| (((raw(i) - lo) / width).clamp(0.0, 1.0) * vmax as f64).round() as u16)
                .collect()
        }
        None => (0..n)
            .map(|i| match raw(i) {
                r if (0.0..=vmax as f64).contains(&r) => Ok(r as u16),
                r => Err(format!(
                    "voxel {i} has value {r} outside [0, {vmax}] for voxel_bits {bits}; give a 'window' to map it"
                )),
            })
            .collect::<std::result::Result<_, _>>()?,
    };
    Ok(Volume { dims, bits, data })
}

/// Radius and centre of the built-in sphere.
pub fn sphere_geometry(dims: [usize; 3]) -> (DVec3, f64) {
    let c = DVec3::new(
        (dims[0] - 1) as f64 / 2.0,
        (dims[1] - 1) as f64 / 2.0,
        (dims[2] - 1) as f64 / 2.0,
    );
    (c, 0.4 * *dims.iter().min().unwrap() as f64)
}

/// Sample `f` (full scale 1) at every voxel. Large volumes are filled by
/// slabs of slices on every core; each voxel's value depends on its position
/// alone, so the result does not depend on the number of threads.
fn fill(dims: [usize; 3], bits: u32, f: impl Fn(DVec3) -> f64 + Sync) -> Volume {
    let vmax = max_value(bits) as f64;
    let slice = dims[0] * dims[1];
    let mut data = vec![0u16; slice * dims[2]];
    let fill_slices = |w0: usize, out: &mut [u16]| {
        for (k, px) in out.iter_mut().enumerate() {
            let (u, v, w) = (k % dims[0], (k / dims[0]) % dims[1], w0 + k / slice);
            let x = f(DVec3::new(u as f64, v as f64, w as f64));
            *px = (x.clamp(0.0, 1.0) * vmax).round() as u16;
        }
    };
    data.par_chunks_mut(slice)
        .enumerate()
        .for_each(|(w, out)| fill_slices(w, out));
    Volume { dims, bits, data }
}

/// Coverage of a voxel-sized box filter by a solid of signed distance `d`
/// (negative inside): the volume-sampling ramp of one voxel width.
fn coverage(d: f64) -> f64 {
    (0.5 - d).clamp(0.0, 1.0)
}

/// The built-in sphere ([`sphere_geometry`]), its surface a linear ramp
/// `shell` voxels wide centred on the radius.
fn sphere(dims: [usize; 3], bits: u32, shell: f64) -> Volume {
    let (c, r) = sphere_geometry(dims);
    fill(dims, bits, |p| coverage(((p - c).length() - r) / shell))
}

fn ellipsoid(p: DVec3, c: DVec3, r: DVec3) -> f64 {
    // Approximate signed distance, in voxels, scaled by the smallest radius.
    let q = (p - c) / r;
    (q.length() - 1.0) * r.min_element()
}

/// Signed-distance primitives and blends for the built-in head, in the
/// head's own units (1 = half the volume's smallest side). The distances are
/// the usual cheap approximations: exact enough to place a smooth ramp.
mod sdf {
    use glam::{DVec2, DVec3};

    /// Ellipsoid of centre `c` and radii `r` (first-order distance estimate).
    pub fn ellipsoid(p: DVec3, c: DVec3, r: DVec3) -> f64 {
        let q = p - c;
        let k1 = (q / (r * r)).length();
        if k1 == 0.0 {
            return -r.min_element();
        }
        let k0 = (q / r).length();
        k0 * (k0 - 1.0) / k1
    }

    /// Signed distance (first order) to the parabola `z = front - k x²` in
    /// the plane `q = (x, z)`: positive in front of it.
    pub fn parabola(q: DVec2, front: f64, k: f64) -> f64 {
        (q.y - front + k * q.x * q.x) / (1.0 + 4.0 * k * k * q.x * q.x).sqrt()
    }

    /// Segment `a`–`b` swept by a sphere whose radius runs from `ra` to `rb`.
    pub fn cone(p: DVec3, a: DVec3, b: DVec3, ra: f64, rb: f64) -> f64 {
        let (pa, ba) = (p - a, b - a);
        let h = (pa.dot(ba) / ba.dot(ba)).clamp(0.0, 1.0);
        (pa - ba * h).length() - (ra + (rb - ra) * h)
    }

    /// Rectangle of half sizes `h` about the origin (2-D signed distance).
    pub fn rect(q: DVec2, h: DVec2) -> f64 {
        let e = q.abs() - h;
        e.max(DVec2::ZERO).length() + e.max_element().min(0.0)
    }

    /// Smooth union over a blend width `k`.
    pub fn smin(a: f64, b: f64, k: f64) -> f64 {
        let h = (k - (a - b).abs()).max(0.0) / k;
        a.min(b) - h * h * k * 0.25
    }

    /// Smooth intersection over a blend width `k`.
    pub fn smax(a: f64, b: f64, k: f64) -> f64 {
        -smin(-a, -b, k)
    }
}

/// Tissue values of the built-in head, as fractions of full scale: soft
/// tissue (skin, muscle, eyes), cerebrospinal fluid, brain, bone and teeth.
pub const HEAD_SOFT: f64 = 0.32;
pub const HEAD_CSF: f64 = 0.12;
pub const HEAD_BRAIN: f64 = 0.44;
pub const HEAD_BONE: f64 = 0.88;
pub const HEAD_TEETH: f64 = 1.0;

/// The built-in head at point `q`, as a fraction of full scale. Head units:
/// the volume's centre at 0 and 1 = half its smallest side; x to the head's
/// left, y up, z out of the face. Every tissue is a solid given by an
/// (approximate) signed distance `d`, laid over the tissues before it with
/// weight `clamp(1/2 - d/w, 0, 1)`: a linear ramp `w` wide centred on the
/// surface, which tri-linear interpolation reproduces exactly where the
/// surface is flat. Layers are about `w` thick or more where they meet, so
/// that each surface's ramp stays straight for a voxel or two either side.
fn head_value(q: DVec3, w: f64) -> f64 {
    use sdf::{cone, ellipsoid, parabola, rect, smax, smin};
    let v3 = DVec3::new;
    let v2 = glam::DVec2::new;
    let cover = |d: f64| (0.5 - d / w).clamp(0.0, 1.0);
    let h = 0.5 * w;
    // Paired features are modelled on the +x side and mirrored.
    let m = v3(q.x.abs(), q.y, q.z);
    // Whether `p` lies within the box `lo..hi` grown by `reach` and the
    // ramp. Each part is evaluated only near the box that holds it, grown
    // by how far the part can reach (padding and blends): elsewhere it
    // changes nothing, and is skipped.
    let near = |p: DVec3, lo: DVec3, hi: DVec3, reach: f64| {
        p.cmpge(lo - (h + reach)).all() && p.cmple(hi + (h + reach)).all()
    };
    if !near(q, v3(-0.70, -0.88, -0.96), v3(0.70, 0.96, 0.96), 0.0) {
        return 0.0;
    }
    let far = f64::INFINITY;

    // The skull's outer surface (before its openings): the vault, the
    // mid-face narrowing to the upper teeth, brow ridges, cheekbones with
    // their arches, the nasal bones and the ridge that holds the upper teeth.
    let vault_c = v3(0.0, 0.22, -0.10);
    let vault_r = v3(0.56, 0.60, 0.74);
    let vault = ellipsoid(q, vault_c, vault_r);
    // The dental arch: a parabola in the horizontal plane (positive in
    // front of it), and its distance.
    let arch = parabola(v2(q.x, q.z), 0.60, 6.0);
    let face = if near(m, v3(0.0, -0.42, -0.12), v3(0.56, 0.23, 0.70), 0.36) {
        let mid = ellipsoid(
            v3(q.x * (1.0 + 0.8 * (-0.1 - q.y).max(0.0)), q.y, q.z),
            v3(0.0, -0.16, 0.26),
            v3(0.40, 0.26, 0.38),
        );
        let brow = cone(m, v3(0.36, 0.17, 0.49), v3(0.06, 0.19, 0.61), 0.04, 0.04);
        let cheek = smin(
            ellipsoid(m, v3(0.38, -0.06, 0.36), v3(0.10, 0.08, 0.10)),
            cone(
                m,
                v3(0.44, -0.06, 0.28),
                v3(0.52, -0.04, -0.08),
                0.035,
                0.03,
            ),
            0.06,
        );
        let nasal = cone(q, v3(0.0, 0.11, 0.63), v3(0.0, -0.02, 0.66), 0.025, 0.025);
        let ridge = smax(
            rect(v2(arch + 0.02, q.y + 0.33), v2(0.05, 0.07)),
            0.0 - q.z,
            0.06,
        );
        [mid, brow, cheek, ridge]
            .into_iter()
            .reduce(|a, b| smin(a, b, 0.08))
            .unwrap()
            .min(smin(mid, nasal, 0.04))
    } else {
        far
    };
    // The mandible: a U-shaped bar under the lower teeth whose lower border
    // falls from the angles to the chin, the rami up to the joints in front
    // of the ears, and the chin.
    let mandible = if near(m, v3(0.0, -0.78, -0.17), v3(0.48, -0.05, 0.70), 0.36) {
        let jaw = parabola(v2(q.x, q.z), 0.62, 5.2);
        let along = ((q.z + 0.02) / 0.64).clamp(0.0, 1.0);
        let body = smax(
            rect(
                v2(jaw + 0.035, q.y + 0.57 + 0.07 * along),
                v2(0.035, 0.07 + 0.05 * along),
            ),
            -0.06 - q.z,
            0.06,
        );
        let ramus = smin(
            cone(
                m,
                v3(0.35, -0.60, -0.03),
                v3(0.43, -0.10, -0.12),
                0.055,
                0.045,
            ),
            cone(
                m,
                v3(0.34, -0.50, 0.08),
                v3(0.39, -0.16, 0.10),
                0.035,
                0.025,
            ),
            0.10,
        );
        let chin = ellipsoid(q, v3(0.0, -0.70, 0.58), v3(0.10, 0.06, 0.05));
        smin(smin(body, ramus, 0.10), chin, 0.06)
    } else {
        far
    };

    // Skin: scalp over the vault, thinner soft tissue over the face and
    // jaw, the cheeks, nose, lips, ears, eyelids and the neck; the eyes set
    // back under the brows.
    let eye_c = v3(0.25, 0.03, 0.50);
    let eye = (m - eye_c).length() - 0.11;
    let mut skin = smin(
        vault - 0.09,
        smin(
            smin(face, mandible, 0.14),
            ellipsoid(m, v3(0.28, -0.26, 0.40), v3(0.17, 0.16, 0.15)),
            0.14,
        ) - 0.06,
        0.16,
    );
    if near(m, v3(0.0, -0.52, 0.39), v3(0.39, 0.13, 0.93), 0.15) {
        let nose = smin(
            cone(q, v3(0.0, 0.10, 0.70), v3(0.0, -0.22, 0.86), 0.03, 0.065),
            ellipsoid(m, v3(0.06, -0.24, 0.78), v3(0.05, 0.04, 0.045)),
            0.05,
        );
        // The lips follow the dental arch.
        let bent = v3(q.x, q.y, q.z + 2.5 * q.x * q.x);
        let lips = smin(
            ellipsoid(bent, v3(0.0, -0.39, 0.69), v3(0.13, 0.04, 0.05)),
            ellipsoid(bent, v3(0.0, -0.48, 0.67), v3(0.11, 0.04, 0.05)),
            0.03,
        );
        skin = smin(smin(skin, nose, 0.08), lips, 0.06);
        let socket = ellipsoid(m, eye_c + v3(0.0, 0.0, 0.17), v3(0.14, 0.10, 0.07));
        skin = smax(skin, -socket, 0.06).min(eye - 0.015);
    }
    if near(m, v3(0.56, -0.21, -0.24), v3(0.66, 0.09, -0.04), 0.10) {
        let ear = ellipsoid(m, v3(0.61, -0.06, -0.14), v3(0.05, 0.15, 0.10));
        skin = smin(skin, ear, 0.06);
    }
    if q.y < 0.1 {
        // Cut flat, as a bust, a little above the volume's bottom.
        let neck = smax(
            cone(q, v3(0.0, -0.35, -0.12), v3(0.0, -1.3, -0.16), 0.27, 0.29),
            -0.86 - q.y,
            0.06,
        );
        skin = smin(skin, neck, 0.12);
    }
    let mut v = HEAD_SOFT * cover(skin);
    if v == 0.0 {
        return 0.0;
    }

    // The cranial cavity (the vault's inside above the skull base), filled
    // with fluid; the brain inside it, with its lateral and third
    // ventricles. The orbits and their walls keep out of it; each orbit is
    // a cone narrowing backwards and inwards, wider than tall.
    let orbit = cone(
        v3(m.x, eye_c.y + (m.y - eye_c.y) * 1.12, m.z),
        eye_c + v3(0.0, 0.0, 0.12),
        v3(0.14, 0.0, 0.14),
        0.145,
        0.03,
    );
    let orbit_wall = orbit - 0.05;
    let floor_y = {
        let t = ((q.z + 0.25) / 0.5).clamp(0.0, 1.0);
        -0.30 + 0.44 * t * t * (3.0 - 2.0 * t)
    };
    let vault_in = ellipsoid(q, vault_c, vault_r - 0.09);
    let cavity = smax(smax(vault_in, floor_y - q.y, 0.08), -orbit_wall, 0.04);
    if cavity < h {
        v += (HEAD_CSF - v) * cover(cavity);
        let brain = smin(
            ellipsoid(q, vault_c, vault_r - 0.115),
            ellipsoid(m, v3(0.15, -0.14, -0.46), v3(0.17, 0.12, 0.17)),
            0.10,
        );
        v += (HEAD_BRAIN - v) * cover(smax(brain, cavity + 0.025, 0.04));
        if near(m, v3(0.0, 0.06, -0.38), v3(0.13, 0.31, 0.22), 0.05) {
            let bend = (q.z + 0.1) * (q.z + 0.1);
            let ventricle = smin(
                ellipsoid(
                    m,
                    v3(0.07 + 0.12 * bend, 0.24 - 0.3 * bend, -0.08),
                    v3(0.045, 0.07, 0.30),
                ),
                ellipsoid(q, v3(0.0, 0.12, -0.06), v3(0.02, 0.06, 0.10)),
                0.04,
            );
            v += (HEAD_CSF - v) * cover(ventricle);
        }
    }

    // Bone: the vault's shell down to the skull base, the base as a plate,
    // the face and the orbits' walls (soft tissue below the base), the jaw
    // and the cervical spine; then the openings: the orbits and the nasal
    // aperture with the nasal cavity behind it.
    let base = smax((q.y - floor_y + 0.04).abs() - 0.045, vault, 0.03);
    let shell = smax(smax(vault, -vault_in, 0.03), floor_y - 0.08 - q.y, 0.05);
    let walls = smax(orbit_wall, smin(vault, face, 0.1), 0.03);
    let mut bone = smax(smin(shell.min(base), face, 0.10).min(walls), -cavity, 0.03);
    bone = smin(bone, mandible, 0.03);
    if near(q, v3(-0.10, -0.85, -0.41), v3(0.10, -0.37, -0.09), 0.05) {
        for k in 0..4 {
            let y = -0.42 - 0.12 * k as f64;
            let vertebra = smin(
                ellipsoid(q, v3(0.0, y, -0.18), v3(0.10, 0.042, 0.085)),
                cone(q, v3(0.0, y, -0.24), v3(0.0, y - 0.03, -0.38), 0.035, 0.025),
                0.04,
            );
            bone = bone.min(vertebra);
        }
    }
    let mut nasal_cavity = far;
    if near(m, v3(0.0, -0.32, 0.0), v3(0.40, 0.16, 0.77), 0.05) {
        nasal_cavity = ellipsoid(q, v3(0.0, -0.12, 0.38), v3(0.07, 0.13, 0.26));
        let aperture = ellipsoid(q, v3(0.0, -0.18, 0.62), v3(0.085, 0.125, 0.14));
        bone = smax(smax(bone, -orbit, 0.03), -aperture.min(nasal_cavity), 0.03);
    }
    v += (HEAD_BONE - v) * cover(bone);
    // Air in the nasal cavity, closed off by the skin.
    v -= v * cover(nasal_cavity.max(skin + 0.06));

    // Teeth: an upper and a lower row along the dental arch.
    if near(m, v3(0.0, -0.54, 0.08), v3(0.33, -0.38, 0.64), 0.05) {
        let teeth = smax(
            rect(v2(arch, q.y + 0.42), v2(0.03, 0.04))
                .min(rect(v2(arch, q.y + 0.50), v2(0.03, 0.035))),
            0.08 - q.z,
            0.04,
        );
        v += (HEAD_TEETH - v) * cover(teeth);
    }
    v
}

/// The built-in head of `dims`: centred, scaled to the smallest side (it
/// keeps its proportions in a box of any shape), every boundary ramped over
/// 0.04 of the smallest side, at least 1 voxel and at most 4 (reached at
/// 100 voxels a side).
fn head(dims: [usize; 3], bits: u32) -> Volume {
    let n = DVec3::new(dims[0] as f64, dims[1] as f64, dims[2] as f64);
    let c = (n - 1.0) / 2.0;
    // Voxels per head unit; the head spans about ±0.92 units.
    let s = 0.5 * n.min_element();
    // The ramp, in head units: 4 voxels, wide enough that tri-linear
    // samples and central-difference gradients within 2 voxels of a surface
    // lie on the straight ramp (no terraces); narrower in small volumes, so
    // that the features survive.
    let ramp = (0.08 * s).clamp(1.0, 4.0) / s;
    fill(dims, bits, |p| head_value((p - c) / s, ramp))
}

pub fn builtin(name: &str, dims: [usize; 3], bits: u32) -> Result<Volume> {
    let n = DVec3::new(dims[0] as f64, dims[1] as f64, dims[2] as f64);
    let c = (n - 1.0) / 2.0;
    let vol = match name {
        "sphere" => sphere(dims, bits, SPHERE_SHELL),
        "phantom" => {
            let h = n * 0.5;
            let skull_out = h * DVec3::new(0.82, 0.92, 0.85);
            let skull_in = skull_out - DVec3::splat(0.06 * h.min_element());
            let brain = skull_in - DVec3::splat(0.02 * h.min_element());
            fill(dims, bits, |p| {
                let skull =
                    coverage(ellipsoid(p, c, skull_out)) - coverage(ellipsoid(p, c, skull_in));
                let tissue = coverage(ellipsoid(p, c, brain));
                let vl = coverage(ellipsoid(
                    p,
                    c + h * DVec3::new(-0.18, 0.1, 0.0),
                    h * DVec3::new(0.1, 0.25, 0.15),
                ));
                let vr = coverage(ellipsoid(
                    p,
                    c + h * DVec3::new(0.18, 0.1, 0.0),
                    h * DVec3::new(0.1, 0.25, 0.15),
                ));
                let lesion = coverage(ellipsoid(p, c + h * DVec3::new(0.25, -0.35, 0.2), h * 0.08));
                0.95 * skull + 0.3 * tissue - 0.2 * (vl + vr) + 0.45 * lesion
            })
        }
        "head" => head(dims, bits),
        "checkerboard" => {
            let cell = (dims.iter().min().unwrap() / 8).max(1);
            fill(dims, bits, |p| {
                let s = (p.x as usize / cell) + (p.y as usize / cell) + (p.z as usize / cell);
                (s % 2) as f64
            })
        }
        "ramp" => fill(dims, bits, |p| p.x / (n.x - 1.0)),
        "impulse" => {
            let ci = DVec3::new(
                (dims[0] / 2) as f64,
                (dims[1] / 2) as f64,
                (dims[2] / 2) as f64,
            );
            fill(dims, bits, |p| if p == ci { 1.0 } else { 0.0 })
        }
        "empty" => fill(dims, bits, |_| 0.0),
        other => {
            return Err(CubeError::Volume(format!(
                "unknown builtin volume '{other}'"
            )))
        }
    };
    Ok(vol)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn permuted_puts_each_axis_where_asked() {
        // Voxel (u, v, w) holds 100u + 10v + w; both copy loops (x the
        // dataset's shorter or longer stride), the second in several tiles
        // where the sides exceed one.
        for dims in [[2, 3, 4], [37, 33, 3], [70, 5, 6]] {
            let value = |[u, v, w]: [usize; 3]| 100 * u + 10 * v + w;
            let data = (0..dims[0] * dims[1] * dims[2])
                .map(|i| {
                    let (u, v) = (i % dims[0], i / dims[0] % dims[1]);
                    value([u, v, i / (dims[0] * dims[1])]) as u16
                })
                .collect();
            let vol = Volume {
                dims,
                bits: 16,
                data,
            };
            for perm in [
                [0, 1, 2],
                [1, 2, 0],
                [2, 0, 1],
                [1, 0, 2],
                [2, 1, 0],
                [0, 2, 1],
            ] {
                let out = vol.permuted(perm);
                let n = perm.map(|a| dims[a]);
                for (i, &got) in out.iter().enumerate() {
                    let p = [i % n[0], i / n[0] % n[1], i / (n[0] * n[1])];
                    let mut d = [0; 3];
                    for (axis, &a) in perm.iter().enumerate() {
                        d[a] = p[axis];
                    }
                    assert_eq!(got as usize, value(d), "{dims:?} {perm:?} {p:?}");
                }
            }
        }
    }

    #[test]
    fn ordered_keeps_each_copy_and_lends_the_own_order() {
        let dims = [5, 4, 3];
        let vol = Volume {
            dims,
            bits: 16,
            data: (0..60).collect(),
        };
        let ordered = Ordered::new(&vol);
        let own = ordered.in_order([0, 1, 2]);
        assert!(matches!(own, InOrder::Own(d) if std::ptr::eq(d, vol.data.as_slice())));
        assert_eq!(ordered.copy_seconds(), None);
        for perm in [[1, 2, 0], [2, 0, 1]] {
            let (InOrder::Copy(a), InOrder::Copy(b)) =
                (ordered.in_order(perm), ordered.in_order(perm))
            else {
                panic!("{perm:?} is a copy");
            };
            assert!(Arc::ptr_eq(&a, &b), "{perm:?} copied twice");
            assert_eq!(*a, vol.permuted(perm), "{perm:?}");
            assert_eq!(*vol.in_order(perm), vol.permuted(perm)[..], "{perm:?}");
        }
        assert_eq!(ordered.kept.lock().unwrap().copies.len(), 2);
        assert!(ordered.copy_seconds().is_some_and(|s| s > 0.0));
    }

    #[test]
    fn raw_size_mismatch_is_an_error() {
        let e = from_raw(&[0u8; 10], [2, 2, 2], RawType::U8, None, 8).unwrap_err();
        assert!(e.contains("need 8"), "{e}");
    }

    #[test]
    fn raw_u16_little_endian_and_window() {
        let bytes = [0x00, 0x01, 0xff, 0x0f];
        let v = from_raw(&bytes, [2, 1, 1], RawType::U16, None, 12).unwrap();
        assert_eq!(v.data, vec![256, 4095]);
        let e = from_raw(&[0xff, 0xff], [1, 1, 1], RawType::U16, None, 12).unwrap_err();
        assert!(e.contains("window"));
        let hu: Vec<u8> = [-1000i16, 0, 1000, 3000]
            .iter()
            .flat_map(|v| v.to_le_bytes())
            .collect();
        let v = from_raw(&hu, [4, 1, 1], RawType::I16, Some([-1000.0, 2000.0]), 12).unwrap();
        assert_eq!(v.data, vec![0, 1365, 2730, 4095]);
    }

    #[test]
    fn crop_takes_the_sub_box() {
        let r = builtin("ramp", [8, 3, 2], 8).unwrap();
        let c = r.crop([2, 1, 1], [3, 2, 1]);
        assert_eq!(c.dims, [3, 2, 1]);
        assert_eq!(
            c.data,
            vec![
                r.get(2, 1, 1),
                r.get(3, 1, 1),
                r.get(4, 1, 1),
                r.get(2, 2, 1),
                r.get(3, 2, 1),
                r.get(4, 2, 1)
            ]
        );
    }

    #[test]
    fn large_volumes_fill_every_voxel_in_place() {
        // Over 2^16 voxels, so filled by slabs on several threads.
        let dims = [70, 48, 41];
        let c = builtin("checkerboard", dims, 8).unwrap();
        let cell = 41 / 8;
        for w in 0..dims[2] {
            for v in 0..dims[1] {
                for u in 0..dims[0] {
                    let want = if (u / cell + v / cell + w / cell) % 2 == 1 {
                        255
                    } else {
                        0
                    };
                    assert_eq!(c.get(u, v, w), want, "({u}, {v}, {w})");
                }
            }
        }
        let i = builtin("impulse", dims, 8).unwrap();
        assert_eq!(i.data.iter().filter(|&&v| v == 255).count(), 1);
        assert_eq!(i.get(35, 24, 20), 255);
    }

    /// The head at a head-unit point `q` of a `n`³ volume (nearest voxel).
    fn head_at(h: &Volume, q: [f64; 3]) -> f64 {
        let n = h.dims[0] as f64;
        let p = q.map(|x| ((n - 1.0) / 2.0 + x * n / 2.0).round() as usize);
        h.get(p[0], p[1], p[2]) as f64 / h.max_value() as f64
    }

    #[test]
    fn head_works_at_any_size_and_is_deterministic() {
        for dims in [[2, 2, 2], [8, 8, 8], [3, 17, 5], [40, 24, 33]] {
            for bits in [8, 12, 16] {
                let a = builtin("head", dims, bits).unwrap();
                assert_eq!(a.data.len(), dims.iter().product::<usize>());
                assert!(a.data.iter().all(|&v| v as u32 <= max_value(bits)));
                assert_eq!(a.data, builtin("head", dims, bits).unwrap().data);
            }
        }
        // Something of the head shows even at 8³.
        assert!(builtin("head", [8, 8, 8], 8)
            .unwrap()
            .data
            .iter()
            .any(|&v| v > 0));
    }

    #[test]
    fn head_has_its_tissues_in_place_and_is_symmetric() {
        let n = 96;
        let h = builtin("head", [n, n, n], 8).unwrap();
        let near = |v: f64, want: f64| (v - want).abs() <= 1.5 / 255.0;
        assert_eq!(head_at(&h, [0.95, 0.95, 0.95]), 0.0, "corner: air");
        assert!(near(head_at(&h, [0.0, 0.3, -0.3]), HEAD_BRAIN), "brain");
        // The skull is thin: its core reaches most of the bone value.
        assert!(head_at(&h, [0.0, 0.78, -0.10]) > 0.8, "skull top");
        assert!(near(head_at(&h, [0.25, 0.03, 0.50]), HEAD_SOFT), "eye");
        assert_eq!(head_at(&h, [0.0, -0.12, 0.38]), 0.0, "nasal cavity");
        assert!(head_at(&h, [0.0, -0.42, 0.60]) > 0.85, "front teeth");
        assert!(
            near(head_at(&h, [0.07, 0.24, -0.08]), HEAD_CSF),
            "ventricle"
        );
        // Mirror-symmetric about the mid-sagittal plane.
        for w in 0..n {
            for v in 0..n {
                for u in 0..n / 2 {
                    assert_eq!(h.get(u, v, w), h.get(n - 1 - u, v, w));
                }
            }
        }
    }

    #[test]
    fn head_boundaries_are_ramps_not_steps() {
        // At 96³ every boundary rises over about 4 voxels: no neighbouring
        // voxels differ by more than 100/255 along any axis (a one-voxel
        // edge from air to bone would be 224).
        let n = 96;
        let h = builtin("head", [n, n, n], 8).unwrap();
        let mut steepest = 0;
        for w in 1..n {
            for v in 1..n {
                for u in 1..n {
                    let x = h.get(u, v, w) as i32;
                    for y in [h.get(u - 1, v, w), h.get(u, v - 1, w), h.get(u, v, w - 1)] {
                        steepest = steepest.max((x - y as i32).abs());
                    }
                }
            }
        }
        assert!(steepest <= 100, "steepest step {steepest}");
    }

    #[test]
    fn builtins_have_expected_extremes() {
        let s = builtin("sphere", [32, 32, 32], 8).unwrap();
        assert_eq!(s.get(16, 16, 16), 255);
        assert_eq!(s.get(0, 0, 0), 0);
        let i = builtin("impulse", [9, 8, 7], 16).unwrap();
        assert_eq!(i.data.iter().filter(|&&v| v == 65535).count(), 1);
        assert_eq!(i.get(4, 4, 3), 65535);
        assert!(builtin("empty", [4, 4, 4], 8)
            .unwrap()
            .data
            .iter()
            .all(|&v| v == 0));
        let r = builtin("ramp", [5, 2, 2], 8).unwrap();
        assert_eq!(&r.data[0..5], &[0, 64, 128, 191, 255]);
    }

    #[test]
    fn the_spheres_shell_is_a_ramp_of_its_width() {
        // Along +x from the centre of a 32-cube (c = 15.5, r = 12.8), the
        // value at distance d from the surface is 1/2 - d/shell, clamped:
        // u = 28 lies 12.5 out, d = -0.3.
        for (shell, want) in [(1.0, 0.8), (2.0, 0.65), (4.0, 0.575)] {
            let s = sphere([32, 32, 32], 16, shell);
            let got = s.get(28, 15, 15) as f64 / 65535.0;
            let d = (DVec3::new(28.0, 15.0, 15.0) - DVec3::splat(15.5)).length() - 12.8;
            assert!((got - (0.5 - d / shell)).abs() < 1e-4, "{shell}: {got}");
            assert!((want - got).abs() < 0.03, "{shell}: {got}");
        }
        assert_eq!(
            sphere([32, 32, 32], 8, SPHERE_SHELL).data,
            builtin("sphere", [32, 32, 32], 8).unwrap().data
        );
    }
}
