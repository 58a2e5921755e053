//! The scene's transfer function in floating point: piecewise-linear maps
//! from intensity to opacity and colour, the optional gradient-opacity
//! factor, and the opacity correction for a sample spacing. Renderers read
//! these; the golden models quantize them into LUTs (`golden_model::lut`).

use crate::spec::Scene;
use glam::DVec3;

/// Piecewise-linear interpolation through sorted `(x, y)` points, constant
/// beyond the ends.
pub fn piecewise(points: &[(f64, f64)], x: f64) -> f64 {
    let first = points[0];
    if x <= first.0 {
        return first.1;
    }
    for w in points.windows(2) {
        let (a, b) = (w[0], w[1]);
        // Here a.0 < x <= b.0 (x passed every earlier point), so a step
        // (a.0 == b.0) never divides by zero: x takes its left value.
        if x <= b.0 {
            return a.1 + (b.1 - a.1) * (x - a.0) / (b.0 - a.0);
        }
    }
    points[points.len() - 1].1
}

/// The scene's transfer function in floating point.
#[derive(Debug, Clone)]
pub struct TransferFn {
    opacity: Vec<(f64, f64)>,
    rgb: [Vec<(f64, f64)>; 3],
    gradient: Option<Vec<(f64, f64)>>,
}

impl TransferFn {
    pub fn new(scene: &Scene) -> TransferFn {
        let t = &scene.transfer;
        let ch = |c: usize| t.color.iter().map(|p| (p[0], p[c + 1])).collect();
        TransferFn {
            opacity: t.opacity.iter().map(|p| (p[0], p[1])).collect(),
            rgb: [ch(0), ch(1), ch(2)],
            gradient: t
                .gradient_opacity
                .as_ref()
                .map(|g| g.iter().map(|p| (p[0], p[1])).collect()),
        }
    }

    /// Opacity per voxel length at intensity `v` (voxel units).
    pub fn opacity(&self, v: f64) -> f64 {
        piecewise(&self.opacity, v)
    }

    pub fn colour(&self, v: f64) -> DVec3 {
        DVec3::new(
            piecewise(&self.rgb[0], v),
            piecewise(&self.rgb[1], v),
            piecewise(&self.rgb[2], v),
        )
    }

    /// Opacity factor for a gradient magnitude (voxel units per voxel); 1 when
    /// the scene has no gradient-opacity map.
    pub fn gradient_factor(&self, g: f64) -> f64 {
        self.gradient.as_ref().map_or(1.0, |p| piecewise(p, g))
    }

    pub fn has_gradient_opacity(&self) -> bool {
        self.gradient.is_some()
    }

    /// Largest gradient magnitude named in the gradient-opacity map.
    pub fn gradient_range(&self) -> f64 {
        self.gradient
            .as_ref()
            .map_or(0.0, |p| p.iter().map(|q| q.0).fold(0.0, f64::max))
    }
}

/// Opacity of a sample `spacing` voxel lengths long, from the per-voxel-length
/// opacity `a`.
pub fn correct_opacity(a: f64, spacing: f64) -> f64 {
    1.0 - (1.0 - a.clamp(0.0, 1.0)).powf(spacing)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn piecewise_matches_points_and_ends() {
        let p = [(0.0, 0.0), (80.0, 0.0), (100.0, 0.75), (255.0, 0.75)];
        assert_eq!(piecewise(&p, -5.0), 0.0);
        assert_eq!(piecewise(&p, 90.0), 0.375);
        assert_eq!(piecewise(&p, 300.0), 0.75);
    }

    #[test]
    fn opacity_correction_is_identity_at_unit_spacing() {
        assert!((correct_opacity(0.3, 1.0) - 0.3).abs() < 1e-15);
        assert!((correct_opacity(0.75, 2.0) - 0.9375).abs() < 1e-12);
        assert_eq!(correct_opacity(1.0, 1.7), 1.0);
    }
}
