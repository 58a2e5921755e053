//! The camera: how the final image's pixels map to rays in dataset voxel
//! coordinates, for parallel views (rotations and zoom) and perspective views
//! (eye, target, up, vertical field of view).

use crate::error::{CubeError, Result};
use glam::{DMat3, DVec3};
use serde::Deserialize;

#[derive(Debug, Clone, Copy, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "lowercase")]
pub enum Projection {
    Parallel,
    Perspective,
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ViewSpec {
    pub projection: Projection,
    /// Parallel only: rotations of the volume about the world x, y and z axes,
    /// applied in that order (x first).
    pub rotate_deg: Option<[f64; 3]>,
    /// Perspective only, all in voxel coordinates of the dataset.
    pub eye: Option<[f64; 3]>,
    pub target: Option<[f64; 3]>,
    pub up: Option<[f64; 3]>,
    pub fov_deg: Option<f64>,
    /// Parallel only: magnification; 1 fits the volume's diagonal to the image.
    pub zoom: Option<f64>,
}

pub(crate) fn check_vec(name: &str, v: [f64; 3]) -> Result<DVec3> {
    let d = DVec3::from_array(v);
    if !d.is_finite() {
        return Err(CubeError::View(format!("{name} {v:?} is not finite")));
    }
    Ok(d)
}

/// Largest accepted coordinate of a perspective eye or target, in voxels.
/// It keeps the eye, quantized with up to 15 fractional bits, within the
/// golden model's i64 divider arithmetic and the RTL divider's datapath.
pub const MAX_COORD: f64 = 1e6;

fn check_point(name: &str, v: [f64; 3]) -> Result<DVec3> {
    let d = check_vec(name, v)?;
    if d.abs().max_element() > MAX_COORD {
        return Err(CubeError::View(format!(
            "{name} {v:?} lies beyond ±{MAX_COORD} voxels"
        )));
    }
    Ok(d)
}

pub(crate) fn check_dir(name: &str, v: [f64; 3]) -> Result<DVec3> {
    let d = check_vec(name, v)?;
    // Scale by the largest component first, so that the length neither
    // overflows (components near 1e308) nor underflows (near 1e-300).
    let m = d.abs().max_element();
    if m == 0.0 {
        return Err(CubeError::View(format!("{name} {v:?} has zero length")));
    }
    Ok((d / m).normalize())
}

/// How the final image's pixels map to rays in dataset voxel coordinates
/// (voxel `(u, v, w)` sits at `(u, v, w)`). Both renderers take their rays from
/// here, so their images cover the same region.
#[derive(Debug, Clone)]
pub struct Camera {
    pub projection: Projection,
    /// Camera axes in dataset coordinates: right, up, and forward (into the scene).
    pub right: DVec3,
    pub up: DVec3,
    pub forward: DVec3,
    /// Parallel: image centre. Perspective: eye.
    pub origin: DVec3,
    /// Parallel: voxel units per pixel. Perspective: tan(fov/2) / (height/2).
    pub scale: f64,
    pub width: u32,
    pub height: u32,
    /// Distance from the image centre back to where parallel rays start.
    pub back: f64,
}

impl Camera {
    pub fn new(view: &ViewSpec, dims: [usize; 3], image: [u32; 2]) -> Result<Camera> {
        let centre = DVec3::new(
            (dims[0] - 1) as f64 / 2.0,
            (dims[1] - 1) as f64 / 2.0,
            (dims[2] - 1) as f64 / 2.0,
        );
        let diag = DVec3::new(dims[0] as f64, dims[1] as f64, dims[2] as f64).length();
        let [w, h] = image;
        match view.projection {
            Projection::Parallel => {
                if view.eye.is_some()
                    || view.target.is_some()
                    || view.up.is_some()
                    || view.fov_deg.is_some()
                {
                    return Err(CubeError::View(
                        "parallel views take rotate_deg and zoom, not eye/target/up/fov_deg".into(),
                    ));
                }
                let r = view.rotate_deg.unwrap_or([0.0; 3]);
                let rv = check_vec("rotate_deg", r)?;
                let zoom = view.zoom.unwrap_or(1.0);
                // Symmetric bounds: below 1/1000 the pixel spacing (diag / zoom)
                // runs to infinity for a subnormal zoom, and rays would start at
                // infinity.
                if !(zoom.is_finite() && (1e-3..=1e3).contains(&zoom)) {
                    return Err(CubeError::View(format!(
                        "zoom {zoom} must lie in [0.001, 1000]"
                    )));
                }
                // World = Rz * Ry * Rx * dataset; the camera looks down world -z.
                // Each angle is reduced mod 360 in degrees first: the
                // reduction is exact in f64, where to_radians of a large
                // angle is not (1e17 degrees turned 275.6, not 280). The
                // remainder keeps the sign, so every angle in (-360, 360)
                // is taken as it is and no committed image moves.
                let rad = |deg: f64| (deg % 360.0).to_radians();
                let rot = DMat3::from_rotation_z(rad(rv.z))
                    * DMat3::from_rotation_y(rad(rv.y))
                    * DMat3::from_rotation_x(rad(rv.x));
                let inv = rot.transpose();
                Ok(Camera {
                    projection: Projection::Parallel,
                    right: inv * DVec3::X,
                    up: inv * DVec3::Y,
                    forward: inv * DVec3::NEG_Z,
                    origin: centre,
                    scale: diag / (w.min(h) as f64 * zoom),
                    width: w,
                    height: h,
                    back: diag,
                })
            }
            Projection::Perspective => {
                if view.rotate_deg.is_some() || view.zoom.is_some() {
                    return Err(CubeError::View(
                        "perspective views take eye/target/up/fov_deg, not rotate_deg or zoom"
                            .into(),
                    ));
                }
                let eye = check_point(
                    "eye",
                    view.eye
                        .ok_or_else(|| CubeError::View("perspective view needs 'eye'".into()))?,
                )?;
                let target = check_point("target", view.target.unwrap_or(centre.to_array()))?;
                let up = check_dir("up", view.up.unwrap_or([0.0, 1.0, 0.0]))?;
                let fov = view.fov_deg.unwrap_or(40.0);
                if !(fov.is_finite() && fov > 0.5 && fov < 170.0) {
                    return Err(CubeError::View(format!(
                        "fov_deg {fov} must lie in (0.5, 170)"
                    )));
                }
                let fwd = target - eye;
                if fwd.length().is_nan() || fwd.length() <= 1e-9 {
                    return Err(CubeError::View("eye and target coincide".into()));
                }
                let forward = fwd.normalize();
                let right = forward.cross(up);
                if right.length() < 1e-9 {
                    return Err(CubeError::View(
                        "up is parallel to the viewing direction".into(),
                    ));
                }
                let right = right.normalize();
                let up = right.cross(forward);
                Ok(Camera {
                    projection: Projection::Perspective,
                    right,
                    up,
                    forward,
                    origin: eye,
                    scale: (fov.to_radians() / 2.0).tan() / (h as f64 / 2.0),
                    width: w,
                    height: h,
                    back: 0.0,
                })
            }
        }
    }

    /// The ray through the centre of pixel `(i, j)` (row 0 at the top):
    /// origin and unit direction, in dataset coordinates.
    pub fn ray(&self, i: u32, j: u32) -> (DVec3, DVec3) {
        let sx = i as f64 + 0.5 - self.width as f64 / 2.0;
        let sy = self.height as f64 / 2.0 - (j as f64 + 0.5);
        match self.projection {
            Projection::Parallel => {
                let o = self.origin + self.right * (sx * self.scale) + self.up * (sy * self.scale)
                    - self.forward * self.back;
                (o, self.forward)
            }
            Projection::Perspective => {
                let d = self.forward + self.right * (sx * self.scale) + self.up * (sy * self.scale);
                (self.origin, d.normalize())
            }
        }
    }

    /// Direction from a point towards the viewer (for specular highlights).
    pub fn to_viewer(&self, p: DVec3) -> DVec3 {
        match self.projection {
            Projection::Parallel => -self.forward,
            Projection::Perspective => (self.origin - p).normalize_or_zero(),
        }
    }

    /// A camera-space vector (x right, y up, z towards the viewer) in dataset coordinates.
    pub fn camera_to_dataset(&self, v: DVec3) -> DVec3 {
        self.right * v.x + self.up * v.y - self.forward * v.z
    }
}
