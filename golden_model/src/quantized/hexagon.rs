//! The template hexagon of a projected voxel (Mora, Jessel & Caubet, §2.2,
//! Fig. 1): under an orthographic view every voxel, taken as a unit cube,
//! projects to a translated copy of one convex hexagon `T` (a rectangle or
//! parallelogram when the view runs along a volume axis). `T` is symmetric
//! about its centre, so the area of effect of a pixel, the set of voxel
//! centres whose hexagon covers it, is `T` centred on the pixel (Eq. 2).
//!
//! Coordinates are image pixels: x to the right, y down, pixel `(i, j)`
//! centred at `(i, j)`.

use glam::DVec2;

/// One edge of `T` as a half-plane: a point `q` (relative to the hexagon's
/// centre) is inside when `a·q.x + b·q.y + c >= 0`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HalfPlane {
    pub a: f64,
    pub b: f64,
    pub c: f64,
}

impl HalfPlane {
    pub fn eval(&self, q: DVec2) -> f64 {
        self.a * q.x + self.b * q.y + self.c
    }
}

/// The template hexagon: its vertices (counter-clockwise in x-right, y-down
/// coordinates, i.e. clockwise on screen) and one half-plane per edge.
#[derive(Debug, Clone)]
pub struct Hexagon {
    pub vertices: Vec<DVec2>,
    pub edges: Vec<HalfPlane>,
}

impl Hexagon {
    /// The projection of a unit cube whose axis steps project to `steps`
    /// (pixel offsets of one voxel step along u, v and w).
    pub fn of_steps(steps: [DVec2; 3]) -> Hexagon {
        // A step along the view direction projects to a rounding residue
        // (cos 90° = 6e-17): zero it, so that the cube's corners pair up
        // exactly and the hull is the rectangle it should be.
        let big = steps
            .iter()
            .fold(0.0f64, |m, s| m.max(s.abs().max_element()));
        let steps = steps.map(|s| s * (s.abs().max_element() > 1e-9 * big) as u8 as f64);
        let mut corners = Vec::with_capacity(8);
        for s in 0..8 {
            let sign = |bit: usize| if s >> bit & 1 == 1 { 0.5 } else { -0.5 };
            corners.push(steps[0] * sign(0) + steps[1] * sign(1) + steps[2] * sign(2));
        }
        let vertices = convex_hull(corners);
        let k = vertices.len();
        let edges = (0..k)
            .map(|i| {
                let (p, q) = (vertices[i], vertices[(i + 1) % k]);
                let d = q - p;
                // Left normal of p -> q; the hull winds so that the inside
                // (the centre, at the origin) is on the left: c > 0.
                let (a, b) = (-d.y, d.x);
                HalfPlane {
                    a,
                    b,
                    c: -(a * p.x + b * p.y),
                }
            })
            .collect();
        Hexagon { vertices, edges }
    }

    /// Whether `q` (relative to the centre) lies in the hexagon, edges
    /// included.
    pub fn contains(&self, q: DVec2) -> bool {
        self.edges.iter().all(|e| e.eval(q) >= 0.0)
    }

    /// Half the hexagon's width and height: the largest |x| and |y| of a
    /// vertex.
    pub fn half_extent(&self) -> DVec2 {
        self.vertices
            .iter()
            .fold(DVec2::ZERO, |m, v| m.max(v.abs()))
    }

    /// Area in square pixels.
    pub fn area(&self) -> f64 {
        let k = self.vertices.len();
        (0..k)
            .map(|i| self.vertices[i].perp_dot(self.vertices[(i + 1) % k]))
            .sum::<f64>()
            / 2.0
    }
}

/// Convex hull (Andrew's monotone chain), collinear and repeated points
/// dropped, wound with positive `perp_dot` (the inside on the left).
fn convex_hull(mut pts: Vec<DVec2>) -> Vec<DVec2> {
    pts.sort_by(|p, q| p.x.total_cmp(&q.x).then(p.y.total_cmp(&q.y)));
    pts.dedup();
    let eps = 1e-12 * pts.iter().fold(1.0f64, |m, p| m.max(p.abs().max_element()));
    if pts.len() < 3 {
        return pts;
    }
    let turn = |o: DVec2, a: DVec2, b: DVec2| (a - o).perp_dot(b - o);
    let mut hull: Vec<DVec2> = Vec::with_capacity(2 * pts.len());
    for pass in 0..2 {
        let start = hull.len();
        let order: Vec<DVec2> = if pass == 0 {
            pts.clone()
        } else {
            pts.iter().rev().copied().collect()
        };
        for p in order {
            while hull.len() >= start + 2
                && turn(hull[hull.len() - 2], hull[hull.len() - 1], p) <= eps
            {
                hull.pop();
            }
            hull.push(p);
        }
        hull.pop();
    }
    hull
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn axis_view_gives_the_unit_square() {
        // Looking down w: u and v map to x and y, w to nothing.
        let h = Hexagon::of_steps([DVec2::X, DVec2::Y, DVec2::ZERO]);
        assert_eq!(h.vertices.len(), 4);
        assert!((h.area() - 1.0).abs() < 1e-12);
        assert!(h.contains(DVec2::new(0.5, -0.5)));
        assert!(!h.contains(DVec2::new(0.51, 0.0)));
    }

    #[test]
    fn oblique_view_gives_a_hexagon_of_the_projected_area() {
        // The projected area of a unit cube is |d_u| + |d_v| + |d_w| for
        // the unit view direction d; with an orthonormal image basis
        // (right, down) the steps are the rows of the rotation.
        let d = glam::DVec3::new(1.0, 2.0, 2.0) / 3.0;
        let right = glam::DVec3::new(2.0, -2.0, 1.0) / 3.0;
        let down = d.cross(right);
        let steps = [0, 1, 2].map(|a| DVec2::new(right[a], down[a]));
        let h = Hexagon::of_steps(steps);
        assert_eq!(h.vertices.len(), 6);
        assert!((h.area() - 5.0 / 3.0).abs() < 1e-12, "{}", h.area());
        for e in &h.edges {
            assert!(e.c > 0.0, "centre inside every edge");
        }
        // Just inside and just outside each vertex, and each edge's middle.
        let k = h.vertices.len();
        for i in 0..k {
            let (p, q) = (h.vertices[i], h.vertices[(i + 1) % k]);
            for m in [p, (p + q) / 2.0] {
                assert!(h.contains(m * 0.999), "{m} inside");
                assert!(!h.contains(m * 1.001), "{m} outside");
            }
        }
    }
}
