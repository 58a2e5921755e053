//! The lighting formula: Phong with a directional light and a white
//! specular term, as every renderer of the kit applies it.

use crate::spec::Shading;
use glam::DVec3;

/// Phong lighting terms for unit normal `n`, unit light `l` and unit viewer
/// direction `v`: the multiplier of the surface colour (ambient + diffuse) and
/// the additive white specular term, each clamped to [0, 1].
pub fn phong(s: &Shading, n: DVec3, l: DVec3, v: DVec3) -> (f64, f64) {
    let diff = (s.ambient + s.diffuse * n.dot(l).max(0.0)).min(1.0);
    let h = (l + v).normalize_or_zero();
    let spec = if n.dot(l) > 0.0 {
        (s.specular * n.dot(h).max(0.0).powf(s.shininess)).min(1.0)
    } else {
        0.0
    };
    (diff, spec)
}
