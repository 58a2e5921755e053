//! The view registers of a Cube-4L sweep (`host::Reg::Dims ..=
//! host::Reg::Order`): what the planner computes for one sweep, as the words
//! the host writes before it starts, so that one build renders any view of
//! its class. The hardware derives what it needs from them (the last
//! indices, the delay lines' lengths, the late control's start).

use super::plan::{Rays, Sweep};
use crate::common::plan::Order;
use crate::host::{Reg, Write};
use crate::regmap::pack;
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
        let [nx, ny, nz] = self.dims.map(|n| n as i64);
        let [u, v, w] = self.axes.map(|a| a as i64);
        let eye = |r: Reg, i: usize| pack(r, &[("neg_eye", self.neg_eye[i])]);
        [
            pack(Reg::Dims, &[("nx", nx), ("ny", ny), ("nz", nz)]),
            pack(
                Reg::Slices,
                &[
                    ("z0", self.z0 as i64),
                    ("z1", self.z1 as i64),
                    ("stream_z0", self.stream_z0 as i64),
                    ("stream_z1", self.stream_z1 as i64),
                ],
            ),
            pack(Reg::Axes, &[("u", u), ("v", v), ("w", w)]),
            pack(
                Reg::Address,
                &[("b_u", self.b_u as i64), ("slab", self.slab as i64)],
            ),
            pack(Reg::Dx, &[("dx", self.dx as i64)]),
            pack(Reg::Dy, &[("dy", self.dy as i64)]),
            eye(Reg::EyeX, 0),
            eye(Reg::EyeY, 1),
            eye(Reg::EyeZ, 2),
            pack(
                Reg::Beats,
                &[
                    ("slice", self.slice_beats as i64),
                    ("beam", self.beam_beats as i64),
                ],
            ),
            pack(
                Reg::Order,
                &[
                    ("front_to_back", self.front_to_back as i64),
                    ("minip", self.minip as i64),
                ],
            ),
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

#[cfg(test)]
mod tests {
    use super::*;

    /// A perspective sweep's words, worked by hand.
    #[test]
    fn the_words_pack_by_hand() {
        let r = ViewRegs {
            dims: [10, 20, 30],
            z0: 1,
            z1: 28,
            stream_z0: 0,
            stream_z1: 29,
            axes: [2, 0, 1],
            b_u: 3,
            slab: 0x1_0002,
            dx: -2,
            dy: 5,
            neg_eye: [-1, 1 << 40, 7],
            slice_beats: 60,
            beam_beats: 3,
            front_to_back: false,
            minip: true,
        };
        assert_eq!(
            r.words(),
            [
                0x001e_0014_000a,
                0x001d_0000_001c_0001,
                0b01_00_10,
                0x1_0002_0003,
                0xffff_ffff_ffff_fffe,
                5,
                u64::MAX,
                1 << 40,
                7,
                0x3_0000_003c,
                0b10,
            ]
        );
    }
}
