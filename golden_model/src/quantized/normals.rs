//! Quantized normals (Mora, Jessel & Caubet, §3.1, after Glassner's normal
//! coding): each voxel's shading normal is mapped once per volume to one
//! of `count` directions, so that shading becomes a table indexed by that
//! number, rebuilt whenever the view or the light changes.
//!
//! The directions are the cells of an octahedral map: the unit sphere is
//! projected onto the octahedron `|x| + |y| + |z| = 1`, the octahedron
//! unfolded onto the square `[-1, 1]²`, and the square cut into
//! `2^ceil(b/2)` × `2^floor(b/2)` cells for `count = 2^b` (8192: 128 × 64).
//! A cell's direction is its centre folded back onto the sphere. Two more
//! codes follow the directions: [`NormalCode::flat`] for a zero gradient
//! (shaded with the ambient term alone, as the reference does) and
//! [`EDGE`] for a voxel on the volume's boundary, which has no full
//! neighbourhood (the kit makes such voxels transparent wherever a scene
//! needs gradients).

use glam::{DVec2, DVec3};

/// Code of a voxel on the volume boundary.
pub const EDGE: u16 = u16::MAX;

/// The octahedral normal code with `count` directions.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct NormalCode {
    cols: u32,
    rows: u32,
}

impl NormalCode {
    /// `count` must be a power of two in 16..=32768 (the scene checks it).
    pub fn new(count: u32) -> NormalCode {
        assert!(
            count.is_power_of_two() && (16..=32768).contains(&count),
            "normal count {count}"
        );
        let b = count.trailing_zeros();
        NormalCode {
            cols: 1 << b.div_ceil(2),
            rows: 1 << (b / 2),
        }
    }

    /// Number of directions.
    pub fn count(&self) -> u32 {
        self.cols * self.rows
    }

    /// The code of a zero gradient: the first after the directions.
    pub fn flat(&self) -> u16 {
        self.count() as u16
    }

    /// The code of unit vector `n`.
    pub fn encode(&self, n: DVec3) -> u16 {
        let s = octahedral(n);
        let cell = |t: f64, k: u32| (((t + 1.0) * 0.5 * k as f64) as u32).min(k - 1);
        (cell(s.y, self.rows) * self.cols + cell(s.x, self.cols)) as u16
    }

    /// The unit direction of code `i` (a direction code, not flat or edge).
    pub fn decode(&self, i: u16) -> DVec3 {
        let (col, row) = (i as u32 % self.cols, i as u32 / self.cols);
        let centre = |c: u32, k: u32| (c as f64 + 0.5) / k as f64 * 2.0 - 1.0;
        unfold(DVec2::new(centre(col, self.cols), centre(row, self.rows)))
    }
}

/// Unit vector to the octahedral square `[-1, 1]²`.
fn octahedral(n: DVec3) -> DVec2 {
    let p = n / (n.x.abs() + n.y.abs() + n.z.abs());
    if p.z >= 0.0 {
        DVec2::new(p.x, p.y)
    } else {
        DVec2::new((1.0 - p.y.abs()) * sign(p.x), (1.0 - p.x.abs()) * sign(p.y))
    }
}

/// The octahedral square back to a unit vector.
fn unfold(s: DVec2) -> DVec3 {
    let z = 1.0 - s.x.abs() - s.y.abs();
    let (x, y) = if z >= 0.0 {
        (s.x, s.y)
    } else {
        ((1.0 - s.y.abs()) * sign(s.x), (1.0 - s.x.abs()) * sign(s.y))
    };
    DVec3::new(x, y, z).normalize()
}

fn sign(x: f64) -> f64 {
    if x >= 0.0 {
        1.0
    } else {
        -1.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_follow_the_count() {
        let c = NormalCode::new(8192);
        assert_eq!((c.cols, c.rows), (128, 64));
        assert_eq!(c.count(), 8192);
        assert_eq!(c.flat(), 8192);
        assert_eq!(NormalCode::new(16).count(), 16);
    }

    /// Worst and mean angle (degrees) between a direction and its code's
    /// direction, over a golden-angle spiral of `k` directions.
    fn errors(count: u32, k: usize) -> (f64, f64) {
        let c = NormalCode::new(count);
        let (mut worst, mut sum) = (0.0f64, 0.0);
        for i in 0..k {
            let z = 1.0 - 2.0 * (i as f64 + 0.5) / k as f64;
            let t = i as f64 * 2.399963229728653;
            let r = (1.0 - z * z).sqrt();
            let n = DVec3::new(r * t.cos(), r * t.sin(), z);
            let a = n
                .dot(c.decode(c.encode(n)))
                .clamp(-1.0, 1.0)
                .acos()
                .to_degrees();
            worst = worst.max(a);
            sum += a;
        }
        (worst, sum / k as f64)
    }

    #[test]
    fn axes_round_trip_and_errors_are_those_of_an_octahedral_map() {
        let c = NormalCode::new(8192);
        for n in [DVec3::X, DVec3::NEG_Y, DVec3::Z, DVec3::NEG_Z] {
            assert!(n.dot(c.decode(c.encode(n))) > 0.999);
        }
        // 8192 cells of 1/64 by 1/32 of the octahedral square: measured
        // over 400 000 random directions, worst 2.87°, mean 1.04° (a
        // square 90 x 90 map: 2.67° and 0.95°).
        let (worst, mean) = errors(8192, 20000);
        assert!(
            worst < 2.9 && (0.95..1.1).contains(&mean),
            "{worst}° {mean}°"
        );
    }

    #[test]
    fn more_codes_give_smaller_errors() {
        let mean = |count| errors(count, 5000).1;
        assert!(mean(256) > 2.0 * mean(2048));
        assert!(mean(2048) > 2.0 * mean(32768));
    }
}
