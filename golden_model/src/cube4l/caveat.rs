//! Where a perspective ray-slice sweep (Cube-4L §3.5) is known to lie far
//! from the float reference, so that a user is told rather than handed a
//! silently wrong image.
//!
//! Each sweep covers the rays within 45° of its axis, and a sight ray is
//! followed through the previous slice's bilinearly interpolated buffer. Next
//! to an edge of the volume two or three sweeps meet, every ray there runs
//! near 45° in both, and the cells around its exit point are magnified next
//! to the eye. Against the float reference (phantom, sphere and head, 32³
//! and 64³, a 64² image, fov 60°; docs/accuracy.md#perspective):
//!
//! | eye | rel. Euclidean error |
//! |---|---|
//! | in front of a face, more than 16 voxels from an edge | 2.6–11 % |
//! | outside, within 1 voxel of an edge or corner | 8–44 % |
//! | 1–4 voxels from one | 8–33 % |
//! | 4–8 voxels from one | 11–20 % |
//! | 8–16 voxels from one | 9.8–15 % |
//! | inside the volume | 0.4–58 % (50 % at a corner) |
//!
//! The ranges are wide: the same distance gives 8–14 % beside the edges
//! nearest the target's face and 38–44 % beside the far corner. Beyond 16
//! voxels from an edge the error is that of any other view.

use glam::DVec3;
use std::fmt;

/// Below this distance (in voxels) from an edge of the volume a view is
/// flagged.
pub const EDGE_VOXELS: f64 = 16.0;

/// A view the sweep renders with a known large error.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Caveat {
    /// The eye lies inside the volume's box.
    pub inside: bool,
    /// Distance from the eye to the nearest edge of the volume's box, in voxels.
    pub edge_voxels: f64,
    /// The measured range of the error for such views, in percent
    /// (relative Euclidean distance to the float reference).
    pub expected_error_percent: [f64; 2],
}

impl Caveat {
    /// The caveat for a perspective eye over a volume of `dims` voxels that
    /// takes `sweeps` sweeps, or `None` where the view is an ordinary one.
    pub fn of(eye: DVec3, dims: [usize; 3], sweeps: usize) -> Option<Caveat> {
        let hi = DVec3::from_array(dims.map(|n| (n - 1) as f64));
        let inside = (0..3).all(|i| eye[i] >= 0.0 && eye[i] <= hi[i]);
        let edge_voxels = edge_distance(eye, hi);
        let expected_error_percent = if inside {
            [0.4, 58.0]
        } else if sweeps < 2 || edge_voxels >= EDGE_VOXELS {
            return None;
        } else if edge_voxels < 1.0 {
            [8.0, 44.0]
        } else if edge_voxels < 4.0 {
            [8.0, 33.0]
        } else if edge_voxels < 8.0 {
            [11.0, 20.0]
        } else {
            [9.8, 15.0]
        };
        Some(Caveat {
            inside,
            edge_voxels,
            expected_error_percent,
        })
    }
}

/// Distance from `p` to the nearest of the twelve edges of the box `0..=hi`.
fn edge_distance(p: DVec3, hi: DVec3) -> f64 {
    let mut best = f64::INFINITY;
    for a in 0..3 {
        let (b, c) = ((a + 1) % 3, (a + 2) % 3);
        let along = (-p[a]).max(p[a] - hi[a]).max(0.0);
        for cb in [0.0, hi[b]] {
            for cc in [0.0, hi[c]] {
                let d = DVec3::new(along, p[b] - cb, p[c] - cc).length();
                best = best.min(d);
            }
        }
    }
    best
}

impl fmt::Display for Caveat {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let [lo, hi] = self.expected_error_percent;
        let place = if self.inside {
            format!(
                "the eye is inside the volume ({:.1} voxels from an edge)",
                self.edge_voxels
            )
        } else {
            format!(
                "the eye is {:.1} voxels from an edge of the volume, where sweeps meet near 45°",
                self.edge_voxels
            )
        };
        write!(
            f,
            "{place}: Cube-4L's perspective sweep is measured {lo}–{hi} % from the reference \
             for such views (2.6–11 % in front of a face, further out; docs/accuracy.md, Cube-4L)"
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn edge_distance_by_hand() {
        let hi = DVec3::splat(31.0);
        // Beyond the corner (31, 31, 31) along the diagonal: 2 voxels out
        // in each axis.
        let p = DVec3::splat(33.0);
        assert!((edge_distance(p, hi) - 12f64.sqrt()).abs() < 1e-12);
        // In front of the z = 0 face's centre: the face's edges are 15.5 away
        // in one axis and 4 in z.
        let p = DVec3::new(15.5, 15.5, -4.0);
        assert!((edge_distance(p, hi) - (15.5f64 * 15.5 + 16.0).sqrt()).abs() < 1e-12);
        // The centre of the box.
        let p = DVec3::splat(15.5);
        assert!((edge_distance(p, hi) - (2.0 * 15.5f64 * 15.5).sqrt()).abs() < 1e-12);
    }

    #[test]
    fn only_views_near_an_edge_or_inside_are_flagged() {
        let dims = [32, 32, 32];
        assert_eq!(Caveat::of(DVec3::new(15.5, 15.5, -20.0), dims, 1), None);
        assert_eq!(Caveat::of(DVec3::splat(60.0), dims, 3), None);
        // One sweep: no sweeps meet, whatever the distance.
        assert_eq!(Caveat::of(DVec3::new(33.0, 15.5, 33.0), dims, 1), None);
        let c = Caveat::of(DVec3::splat(33.0), dims, 3).unwrap();
        assert!(!c.inside);
        assert_eq!(c.expected_error_percent, [8.0, 33.0]);
        // 11.3 voxels beyond an edge: still flagged.
        let c = Caveat::of(DVec3::new(39.0, 39.0, 15.5), dims, 2).unwrap();
        assert_eq!(c.expected_error_percent, [9.8, 15.0]);
        let c = Caveat::of(DVec3::splat(31.0), dims, 6).unwrap();
        assert!(c.inside && c.edge_voxels == 0.0);
        assert!(c.to_string().contains("inside the volume"));
    }
}
