//! What a Cube-4L frame produces: the base plane of each sweep (pixels
//! output on ER at their base-plane addresses, with their face), the sweep's
//! work counters, and the frame that the warp turns into the final image.

use super::plan::{Face, Plan, Sweep};

/// The base-plane image of one sweep: pixels output on ER at their base-plane
/// addresses, with the face each came out of (`Face::None` where none did).
#[derive(Debug, Clone)]
pub struct BasePlane {
    pub width: usize,
    pub height: usize,
    pub pixels: Vec<[u32; 4]>,
    pub faces: Vec<Face>,
}

impl BasePlane {
    /// An empty base plane for `sweep`: no pixel has come out yet.
    pub fn new(sweep: &Sweep) -> BasePlane {
        let [width, height] = sweep.base_dims();
        BasePlane {
            width,
            height,
            pixels: vec![[0; 4]; width * height],
            faces: vec![Face::None; width * height],
        }
    }

    /// Record the pixel that left through `face` at base-plane address `[x, y]`.
    pub fn put(&mut self, [x, y]: [usize; 2], value: [u32; 4], face: Face) {
        self.pixels[x + self.width * y] = value;
        self.faces[x + self.width * y] = face;
    }
}

/// Work counters of a sweep.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Stats {
    pub voxels: u64,
    /// Voxels that went through gradient and shading.
    pub shaded: u64,
    /// Front-to-back cells already opaque: voxel skipped.
    pub terminated: u64,
    /// Compositing results clipped by saturation.
    pub saturations: u64,
    pub pixels_out: u64,
}

impl std::ops::Add for Stats {
    type Output = Stats;
    fn add(self, o: Stats) -> Stats {
        Stats {
            voxels: self.voxels + o.voxels,
            shaded: self.shaded + o.shaded,
            terminated: self.terminated + o.terminated,
            saturations: self.saturations + o.saturations,
            pixels_out: self.pixels_out + o.pixels_out,
        }
    }
}

/// A whole Cube-4L frame: the plan, and one base plane per sweep.
#[derive(Debug, Clone)]
pub struct Frame {
    pub plan: Plan,
    pub bases: Vec<BasePlane>,
    pub stats: Stats,
}
