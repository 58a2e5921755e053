//! Quantized splatting (Mora, Jessel & Caubet, §2.3, Fig. 3, Eqs. 6-11).
//!
//! Every splat whose centre falls in the same subdivision of the pixel
//! square is drawn as the splat centred on that subdivision's centre. Each
//! subdivision holds a list of pixel offsets and a list of kernel weights,
//! rebuilt when the view changes; a pixel then costs two addressings and
//! one addition, no footprint evaluation.
//!
//! The kernel is the Gaussian `f(x) = b·e^(−r·x²)` (Eq. 6) of the distance
//! `x` between the voxel's projected centre and the pixel's centre,
//! measured in voxel lengths, cut off at `RADIUS` voxel lengths
//! (`f(RADIUS) = b·e^(−8)` for r = 2). Position quantization moves a centre
//! by at most `1 / (n·√2)` pixels, `s / (n·√2)` voxel lengths at `s` voxel
//! lengths per pixel, and `|f'| <= b·√(2r) / √e` (Eqs. 8, 9), so each
//! pixel's weight is off by at most `b·√r·s / (n·√e)` (Eq. 11; the paper's
//! bound is the case s = 1: 0.012 for b = 0.446, r = 2, n = 32).

/// Kernel cut-off, in voxel lengths.
pub const RADIUS: f64 = 2.0;

/// The Gaussian kernel of Eq. 6.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Kernel {
    pub b: f64,
    pub r: f64,
}

impl Kernel {
    /// `f(x)` for `x` in voxel lengths (no cut-off).
    pub fn at(&self, x: f64) -> f64 {
        self.b * (-self.r * x * x).exp()
    }

    /// The integral of `f` over the image plane, in square voxel lengths:
    /// `b·π / r`. A splat's weight divided by it gives, summed over the
    /// voxels a ray passes, one per voxel length of ray.
    pub fn integral(&self) -> f64 {
        self.b * std::f64::consts::PI / self.r
    }

    /// Eq. 11 at `s` voxel lengths per pixel and `n` subdivisions.
    pub fn error_bound(&self, n: usize, s: f64) -> f64 {
        self.b * self.r.sqrt() * s / (n as f64 * std::f64::consts::E.sqrt())
    }
}

/// Per-view splat table: for subdivision `i`, pixel offsets
/// `offsets[start[i]..start[i + 1]]` and their kernel weights.
#[derive(Debug, Clone)]
pub struct SplatTable {
    pub n: usize,
    pub start: Vec<u32>,
    pub offsets: Vec<[i32; 2]>,
    pub weights: Vec<f32>,
}

impl SplatTable {
    /// `s`: voxel lengths per pixel.
    pub fn new(kernel: Kernel, n: usize, s: f64) -> SplatTable {
        assert!((1..=256).contains(&n));
        let reach = (RADIUS / s).ceil() as i32 + 1;
        let mut start = Vec::with_capacity(n * n + 1);
        let mut offsets = Vec::new();
        let mut weights = Vec::new();
        for sy in 0..n {
            for sx in 0..n {
                start.push(offsets.len() as u32);
                let cx = (sx as f64 + 0.5) / n as f64;
                let cy = (sy as f64 + 0.5) / n as f64;
                for oy in -reach..=reach + 1 {
                    for ox in -reach..=reach + 1 {
                        let (dx, dy) = (ox as f64 - cx, oy as f64 - cy);
                        let x = (dx * dx + dy * dy).sqrt() * s;
                        if x <= RADIUS {
                            offsets.push([ox, oy]);
                            weights.push(kernel.at(x) as f32);
                        }
                    }
                }
            }
        }
        start.push(offsets.len() as u32);
        SplatTable {
            n,
            start,
            offsets,
            weights,
        }
    }

    /// The subdivision index of position `(fx, fy)` in the square.
    pub fn cell(&self, fx: f64, fy: f64) -> usize {
        let c = |t: f64| ((t * self.n as f64) as usize).min(self.n - 1);
        c(fy) * self.n + c(fx)
    }

    /// Smallest and largest offset of any listed pixel: `[min, max]`.
    pub fn extent(&self) -> [[i32; 2]; 2] {
        let mut e = [[i32::MAX; 2], [i32::MIN; 2]];
        for o in &self.offsets {
            for a in 0..2 {
                e[0][a] = e[0][a].min(o[a]);
                e[1][a] = e[1][a].max(o[a]);
            }
        }
        e
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paper_bound_at_n_32() {
        let k = Kernel { b: 0.446, r: 2.0 };
        // 0.446 * sqrt(2) / (32 * sqrt(e)) = 0.0119551
        assert!((k.error_bound(32, 1.0) - 0.0119551).abs() < 1e-7);
        // b·π/r = 0.446 * π / 2
        assert!((k.integral() - 0.700575).abs() < 1e-6);
    }

    #[test]
    fn table_weights_are_the_kernel_at_the_subdivision_centre() {
        let k = Kernel { b: 0.446, r: 2.0 };
        let t = SplatTable::new(k, 4, 1.0);
        // Subdivision (0, 0) is centred at (0.125, 0.125); offset (0, 0)
        // lies 0.125·√2 away: f = 0.446·e^(−2·0.03125) = 0.419...
        let i = t.offsets[..t.start[1] as usize]
            .iter()
            .position(|&o| o == [0, 0])
            .unwrap();
        assert!((t.weights[i] as f64 - 0.446 * (-0.0625f64).exp()).abs() < 1e-7);
        // Every listed pixel is within the cut-off of its centre.
        assert!(t.start.windows(2).all(|w| w[1] > w[0]));
    }
}
