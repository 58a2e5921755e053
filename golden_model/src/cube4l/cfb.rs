//! Cubic Frame Buffer (Cube-4L §3.1, Figs. 5 and 13): skewed memory and the
//! cycle-by-cycle voxel stream with its control bits.
//!
//! Voxel `(u, v, w)` lives in module `k = (u + v + w) mod p` at address
//! `i = u div p + v*b + w*b*n_v` with `b = ceil(n_u / p)`. When rendering,
//! pipeline `k` reads only module `k`. At cycle `(N_s, N_B, N_b)` (slice,
//! beam, partial beam, all in pipeline space) pipeline `k` holds the voxel
//! `x = N_b*p + ((k - N_B - N_s) mod p)` of that beam. A pipeline-space x size
//! that is not a multiple of `p` is padded: lanes past the end carry an
//! invalid, padding voxel and never output a pixel.

use super::plan::{Control, Sweep};
use scene::volume::Volume;

/// The volume distributed over `p` memory modules.
#[derive(Debug, Clone)]
pub struct SkewedMemory {
    pub p: usize,
    /// Partial beams per dataset beam along u: `ceil(n_u / p)`.
    pub b: usize,
    pub modules: Vec<Vec<u16>>,
}

/// Memory module and address of dataset voxel `(u, v, w)`.
pub fn skew(u: usize, v: usize, w: usize, p: usize, b: usize, n_v: usize) -> (usize, usize) {
    ((u + v + w) % p, u / p + v * b + w * b * n_v)
}

impl SkewedMemory {
    pub fn new(vol: &Volume, p: usize) -> SkewedMemory {
        let [nu, nv, nw] = vol.dims;
        let b = nu.div_ceil(p);
        let mut modules = vec![vec![0u16; b * nv * nw]; p];
        for w in 0..nw {
            for v in 0..nv {
                for u in 0..nu {
                    let (k, i) = skew(u, v, w, p, b, nv);
                    modules[k][i] = vol.get(u, v, w);
                }
            }
        }
        SkewedMemory { p, b, modules }
    }
}

/// One pipeline's voxel in one clock cycle.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Lane {
    /// Pipeline-space position; `x` may be past the end on a padding lane.
    pub pos: [usize; 3],
    /// Memory address read by this pipeline (its module is the lane number).
    pub address: usize,
    pub value: u16,
    /// Start of beam: first partial beam of a full beam.
    pub bs: bool,
    /// Padding lane past the end of a beam whose length is not a multiple of p.
    pub pad: bool,
    pub control: Control,
    /// Base-plane address of the pixel output on ER.
    pub pixel: Option<[usize; 2]>,
}

/// One clock cycle of the CFB: `p` lanes.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Beat {
    pub cycle: u64,
    /// Slice, beam and partial-beam counters N_s, N_B, N_b.
    pub n_s: usize,
    pub n_beam: usize,
    pub n_b: usize,
    pub lanes: Vec<Lane>,
}

/// The CFB stream of one sweep, in the exact order the hardware emits it:
/// slices z0..=z1, beams along y, partial beams along x, `p` lanes each.
pub struct CfbStream<'a> {
    mem: &'a SkewedMemory,
    vol_dims: [usize; 3],
    sweep: &'a Sweep,
    b: usize,
    next: (usize, usize, usize),
    cycle: u64,
}

impl<'a> CfbStream<'a> {
    pub fn new(mem: &'a SkewedMemory, vol_dims: [usize; 3], sweep: &'a Sweep) -> CfbStream<'a> {
        CfbStream {
            mem,
            vol_dims,
            sweep,
            b: sweep.dims[0].div_ceil(mem.p),
            next: (sweep.z0, 0, 0),
            cycle: 0,
        }
    }

    /// Clock cycles of the whole sweep: slices x beams x partial beams.
    pub fn cycles(&self) -> u64 {
        ((self.sweep.z1 - self.sweep.z0 + 1) * self.sweep.dims[1] * self.b) as u64
    }
}

impl Iterator for CfbStream<'_> {
    type Item = Beat;

    fn next(&mut self) -> Option<Beat> {
        let (z, y, nb) = self.next;
        if z > self.sweep.z1 {
            return None;
        }
        let p = self.mem.p;
        let [nx, _, _] = self.sweep.dims;
        let lanes = (0..p)
            .map(|k| {
                let x = nb * p + (k + p - (y + z) % p) % p;
                let pad = x >= nx;
                let (address, value, control, pixel) = if pad {
                    let c = Control {
                        dx: 0,
                        dy: 0,
                        sr: z == self.sweep.z0,
                        er: false,
                        invalid: true,
                        edge: true,
                        face: super::plan::Face::None,
                    };
                    (0, 0, c, None)
                } else {
                    let [u, v, w] = self.sweep.dataset(x, y, z);
                    let (module, address) = skew(u, v, w, p, self.mem.b, self.vol_dims[1]);
                    debug_assert_eq!(module, k);
                    let c = self.sweep.control(x, y, z);
                    let px = self.sweep.base_address(x, y, z, c.face);
                    (address, self.mem.modules[k][address], c, px)
                };
                Lane {
                    pos: [x, y, z],
                    address,
                    value,
                    bs: nb == 0,
                    pad,
                    control,
                    pixel,
                }
            })
            .collect();
        let beat = Beat {
            cycle: self.cycle,
            n_s: z,
            n_beam: y,
            n_b: nb,
            lanes,
        };
        self.cycle += 1;
        self.next = if nb + 1 < self.b {
            (z, y, nb + 1)
        } else if y + 1 < self.sweep.dims[1] {
            (z, y + 1, 0)
        } else {
            (z + 1, 0, 0)
        };
        Some(beat)
    }
}
