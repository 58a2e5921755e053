//! The view registers of a Cube-4L sweep (`host::Reg::Dims ..=
//! host::Reg::Order`): what the planner computes for one sweep, as the words
//! the host writes before it starts, so that one build renders any view of
//! its class. The hardware derives what it needs from them (the last
//! indices, the delay lines' lengths, the late control's start).

use super::plan::{Rays, Sweep};
use crate::common::plan::Order;
use crate::host::{pack16, Reg, Write};
use scene::Mode;

/// The view registers, in the order of [`ViewRegs::words`].
pub const REGS: [Reg; 11] = [
    Reg::Dims,
    Reg::Slices,
    Reg::Axes,
    Reg::Address,
    Reg::Dx,
    Reg::Dy,
    Reg::EyeX,
    Reg::EyeY,
    Reg::EyeZ,
    Reg::Beats,
    Reg::Order,
];

/// One sweep's registers.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ViewRegs {
    /// Pipeline-space dims `[nx, ny, nz]`.
    pub dims: [u32; 3],
    /// The slices composited, `z0 ..= z1`, and the slices streamed (one
    /// halo slice more at each end that lies in the dataset when the
    /// gradient unit is built).
    pub z0: u32,
    pub z1: u32,
    pub stream_z0: u32,
    pub stream_z1: u32,
    /// The pipeline axes (0 = x, 1 = y, 2 = z) that hold dataset u, v, w.
    pub axes: [u32; 3],
    /// The skewed memory's address: partial beams per u beam
    /// (`ceil(n_u / P)`) and per w slab (`ceil(n_u / P) * n_v`).
    pub b_u: u32,
    pub slab: u32,
    /// Parallel views: the frame registers dx and dy (fixed point, the
    /// sweep's fractional bits).
    pub dx: i32,
    pub dy: i32,
    /// Perspective views: the eye in pipeline space, negated (fixed point).
    pub neg_eye: [i64; 3],
    /// Beats (clocks) of a slice and of a beam: `n_y · ceil(n_x / P)` and
    /// `ceil(n_x / P)`.
    pub slice_beats: u32,
    pub beam_beats: u32,
    pub front_to_back: bool,
    /// MinIP rather than MIP (the scalar modes' class).
    pub minip: bool,
}

impl ViewRegs {
    /// The registers of `sweep` over a dataset of `vol_dims` with `p`
    /// pipelines; `gradient`: the gradient unit is built (halo slices).
    pub fn new(
        sweep: &Sweep,
        vol_dims: [usize; 3],
        p: usize,
        gradient: bool,
        mode: Mode,
    ) -> ViewRegs {
        let (dx, dy, eye) = match sweep.rays {
            Rays::Parallel { dx, dy } => (dx, dy, [0; 3]),
            Rays::Perspective { eye } => (0, 0, eye),
        };
        let from = |axis: usize| sweep.perm.iter().position(|&a| a == axis).unwrap() as u32;
        let (z0, z1) = (sweep.z0 as u32, sweep.z1 as u32);
        let (stream_z0, stream_z1) = match gradient {
            true => (z0.saturating_sub(1), (z1 + 1).min(sweep.dims[2] as u32 - 1)),
            false => (z0, z1),
        };
        let b_u = vol_dims[0].div_ceil(p) as u32;
        let beam = sweep.dims[0].div_ceil(p) as u32;
        ViewRegs {
            dims: sweep.dims.map(|n| n as u32),
            z0,
            z1,
            stream_z0,
            stream_z1,
            axes: [from(0), from(1), from(2)],
            b_u,
            slab: b_u * vol_dims[1] as u32,
            dx,
            dy,
            neg_eye: eye.map(|e| e.wrapping_neg()),
            slice_beats: sweep.dims[1] as u32 * beam,
            beam_beats: beam,
            front_to_back: sweep.order == Order::FrontToBack,
            minip: mode == Mode::Minip,
        }
    }

    /// The registers' words, in [`REGS`] order.
    pub fn words(&self) -> [u64; 11] {
        let d = self.dims.map(|n| n as u64);
        [
            pack16(&[d[0], d[1], d[2]]),
            pack16(&[self.z0, self.z1, self.stream_z0, self.stream_z1].map(|z| z as u64)),
            self.axes
                .iter()
                .enumerate()
                .fold(0, |a, (i, &x)| a | (x as u64) << (2 * i)),
            self.b_u as u64 | (self.slab as u64) << 16,
            self.dx as i64 as u64,
            self.dy as i64 as u64,
            self.neg_eye[0] as u64,
            self.neg_eye[1] as u64,
            self.neg_eye[2] as u64,
            self.slice_beats as u64 | (self.beam_beats as u64) << 32,
            self.front_to_back as u64 | (self.minip as u64) << 1,
        ]
    }

    /// The words the host writes.
    pub fn writes(&self) -> Vec<Write> {
        REGS.iter()
            .zip(self.words())
            .map(|(r, data)| Write {
                address: r.address(),
                data,
            })
            .collect()
    }
}
