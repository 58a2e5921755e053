//! The scene's transfer function in floating point: piecewise-linear maps
//! from intensity to opacity and colour, the optional gradient-opacity
//! factor, and the opacity correction for a sample spacing. Renderers read
//! these; the golden models quantize them into LUTs (`golden_model::lut`).

use crate::spec::Scene;
use glam::DVec3;

/// Piecewise-linear interpolation through sorted `(x, y)` points, constant
/// beyond the ends.
///
/// The points' `x` are non-decreasing (the scene validates them so): equal
/// `x` make a step, whose left value is taken at the step itself. The
/// segment is found by binary search, `O(log n)` a lookup (a scene may hold
/// a hundred thousand points, looked up for every sample): the first point
/// at or beyond `x`, and the one before it, as a linear scan from the left
/// would find them, so the results are the same to the bit.
pub fn piecewise(points: &[(f64, f64)], x: f64) -> f64 {
    let first = points[0];
    if x <= first.0 {
        return first.1;
    }
    // Every point before `j` lies below x, every one from `j` on at or
    // beyond it; `j >= 1` as x passed the first point, but for a NaN x
    // (no point below it, j = 0), which takes the last value.
    let j = points.partition_point(|p| p.0 < x);
    if j == 0 || j == points.len() {
        return points[points.len() - 1].1;
    }
    let (a, b) = (points[j - 1], points[j]);
    // Here a.0 < x <= b.0, so a step (a.0 == b.0) never divides by zero:
    // x takes its left value.
    a.1 + (b.1 - a.1) * (x - a.0) / (b.0 - a.0)
}

/// The linear scan [`piecewise`] replaced, kept to test it against.
#[cfg(test)]
fn piecewise_scan(points: &[(f64, f64)], x: f64) -> f64 {
    let first = points[0];
    if x <= first.0 {
        return first.1;
    }
    for w in points.windows(2) {
        let (a, b) = (w[0], w[1]);
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

    /// The binary search gives the linear scan's values to the bit: at and
    /// around every control point, beyond the ends, on steps (two and three
    /// points at one x, a step at either end), one point, NaN and infinities.
    #[test]
    fn piecewise_search_matches_the_scan_to_the_bit() {
        let tables: Vec<Vec<(f64, f64)>> = vec![
            vec![(0.0, 0.0), (80.0, 0.0), (100.0, 0.75), (255.0, 0.75)],
            vec![(7.0, 0.6)],
            vec![(3.0, 0.1), (3.0, 0.9)],
            vec![(0.0, 0.0), (50.0, 0.4), (50.0, 1.0), (100.0, 1.0)],
            vec![
                (0.0, 0.2),
                (0.0, 0.5),
                (10.0, 0.5),
                (10.0, 0.7),
                (10.0, 0.1),
            ],
            vec![
                (1.0, 0.3),
                (2.0, 0.6),
                (2.0, 0.2),
                (2.0, 0.8),
                (4.5, 0.0),
                (255.0, 1.0),
                (255.0, 0.0),
            ],
            // Many points, irregular, with repeats.
            (0..1000)
                .map(|i| {
                    (
                        ((i * 37) % 1000 / 3) as f64 * 0.77,
                        ((i * 7919) % 101) as f64 / 100.0,
                    )
                })
                .collect(),
        ];
        for mut t in tables {
            t.sort_by(|a, b| a.0.total_cmp(&b.0));
            let mut xs = vec![
                f64::NAN,
                f64::INFINITY,
                f64::NEG_INFINITY,
                -1e300,
                1e300,
                -0.0,
                0.0,
            ];
            for p in &t {
                for d in [0.0, 1e-9, -1e-9, 0.5, -0.5, 0.125] {
                    xs.push(p.0 + d);
                }
                xs.push(p.0.next_up());
                xs.push(p.0.next_down());
            }
            for x in xs {
                let (a, b) = (piecewise(&t, x), piecewise_scan(&t, x));
                assert_eq!(a.to_bits(), b.to_bits(), "x {x} in {t:?}: {a} against {b}");
            }
        }
    }

    /// A step takes its left value at the step, its right value just past;
    /// a control point gives its own value (to rounding: `a + (b - a)`).
    #[test]
    fn piecewise_steps_and_control_points() {
        let p = [(0.0, 0.0), (50.0, 0.4), (50.0, 1.0), (100.0, 1.0)];
        assert_eq!(piecewise(&p, 50.0), 0.4);
        assert_eq!(piecewise(&p, 50.0f64.next_up()), 1.0);
        assert_eq!(piecewise(&p, 0.0), 0.0);
        assert_eq!(piecewise(&p, 100.0), 1.0);
        // Three points at one x: the first's value at x, the last's beyond.
        let q = [
            (0.0, 0.0),
            (10.0, 0.2),
            (10.0, 0.5),
            (10.0, 0.9),
            (20.0, 0.9),
        ];
        assert_eq!(piecewise(&q, 10.0), 0.2);
        assert_eq!(piecewise(&q, 10.0f64.next_up()), 0.9);
        assert!((piecewise(&q, 5.0) - 0.1).abs() < 1e-15);
        // A step at the first x: the first value there and below.
        let r = [(0.0, 0.3), (0.0, 0.6), (8.0, 1.0)];
        assert_eq!(piecewise(&r, 0.0), 0.3);
        assert_eq!(piecewise(&r, -1.0), 0.3);
        assert!((piecewise(&r, 4.0) - 0.8).abs() < 1e-15);
        // At the last x: the value of the first point there.
        let s = [(0.0, 0.0), (8.0, 0.5), (8.0, 0.25)];
        assert_eq!(piecewise(&s, 8.0), 0.5);
        assert_eq!(piecewise(&s, 9.0), 0.25);
        // Every control point of a long table.
        let long: Vec<(f64, f64)> = (0..150_000)
            .map(|i| {
                (
                    255.0 * i as f64 / 149_999.0,
                    ((i * 7919) % 1000) as f64 / 1000.0,
                )
            })
            .collect();
        for (i, &(x, y)) in long.iter().enumerate().step_by(997) {
            assert!((piecewise(&long, x) - y).abs() < 1e-15, "point {i}");
        }
    }

    #[test]
    fn opacity_correction_is_identity_at_unit_spacing() {
        assert!((correct_opacity(0.3, 1.0) - 0.3).abs() < 1e-15);
        assert!((correct_opacity(0.75, 2.0) - 0.9375).abs() < 1e-12);
        assert_eq!(correct_opacity(1.0, 1.7), 1.0);
    }
}
