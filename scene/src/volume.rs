//! Volumes: raw files (little-endian, x fastest) and the built-in synthetic
//! volumes. Voxels are unsigned integers of the scene's `voxel_bits`.

use crate::error::{CubeError, Result};
use glam::DVec3;
use serde::Deserialize;
use std::path::PathBuf;

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
    pub crop: Option<Crop>,
}

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

/// Built-in volumes: name and one-line description.
pub const BUILTINS: &[(&str, &str)] = &[
    ("sphere", "volume-sampled (anti-aliased) solid sphere, radius 0.4 of the smallest side, analytic normals known"),
    ("phantom", "head-like phantom: skull shell, brain, ventricles and a dense lesion"),
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
    let raw: Vec<f64> = match kind {
        RawType::U8 => bytes.iter().map(|&b| b as f64).collect(),
        RawType::U16 => bytes
            .chunks_exact(2)
            .map(|c| u16::from_le_bytes([c[0], c[1]]) as f64)
            .collect(),
        RawType::I16 => bytes
            .chunks_exact(2)
            .map(|c| i16::from_le_bytes([c[0], c[1]]) as f64)
            .collect(),
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
            raw.iter()
                .map(|&r| (((r - lo) / width).clamp(0.0, 1.0) * vmax as f64).round() as u16)
                .collect()
        }
        None => {
            if let Some(pos) = raw.iter().position(|&r| r < 0.0 || r > vmax as f64) {
                return Err(format!(
                    "voxel {pos} has value {} outside [0, {vmax}] for voxel_bits {bits}; give a 'window' to map it",
                    raw[pos]
                ));
            }
            raw.iter().map(|&r| r as u16).collect()
        }
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

fn fill(dims: [usize; 3], bits: u32, f: impl Fn(DVec3) -> f64) -> Volume {
    let vmax = max_value(bits) as f64;
    let mut data = Vec::with_capacity(dims.iter().product());
    for w in 0..dims[2] {
        for v in 0..dims[1] {
            for u in 0..dims[0] {
                let x = f(DVec3::new(u as f64, v as f64, w as f64));
                data.push((x.clamp(0.0, 1.0) * vmax).round() as u16);
            }
        }
    }
    Volume { dims, bits, data }
}

/// Coverage of a voxel-sized box filter by a solid of signed distance `d`
/// (negative inside): the volume-sampling ramp of one voxel width.
fn coverage(d: f64) -> f64 {
    (0.5 - d).clamp(0.0, 1.0)
}

fn ellipsoid(p: DVec3, c: DVec3, r: DVec3) -> f64 {
    // Approximate signed distance, in voxels, scaled by the smallest radius.
    let q = (p - c) / r;
    (q.length() - 1.0) * r.min_element()
}

pub fn builtin(name: &str, dims: [usize; 3], bits: u32) -> Result<Volume> {
    let n = DVec3::new(dims[0] as f64, dims[1] as f64, dims[2] as f64);
    let c = (n - 1.0) / 2.0;
    let vol = match name {
        "sphere" => {
            let (c, r) = sphere_geometry(dims);
            fill(dims, bits, |p| coverage((p - c).length() - r))
        }
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
}
