//! The TRILIN unit of Cube-3 (§3, Fig. 4; §5, Fig. 12): sheared tri-linear
//! interpolation, one sample per clock, bit for bit as
//! `golden_model::cube3::trilin::interpolate`.
//!
//! A sample of ray `(u, v)` between planes `k` and `k + 1` takes the eight
//! voxels of the discrete rays `A = (u, v)`, `B = (u + 1, v)`, `C = (u, v +
//! 1)` and `D = (u + 1, v + 1)` on both planes, as the 2-D skewed buffers of
//! scanlines `v` and `v + 1` deliver them. The golden model's steps, each a
//! [`Lerp`] of two clocks (`W` fractional bits, product rounded half up):
//!
//! 1. `widen`: every voxel `<< F`, `F = sample_bits - voxel_bits` (wiring);
//! 2. four lerps along the major axis with the offset `O`: `a, b, c, d`;
//! 3. two lerps in X with the template weight `wx`: `top`, `bottom`;
//! 4. one lerp in Y with `wy`: the sample.
//!
//! The voxels and weights are registered on entry, so the sample of the
//! inputs at clock `t` leaves at `t + LATENCY`. Each lerp lies between its
//! ends, so every value fits `sample_bits` (at most 24); the differences
//! need the two-multiplier lerp only when `sample_bits > 16`. The weights and
//! offset are the view's, loaded at run time, so the unit is built for
//! every view of its class, on the grid (`View::on_grid`) or not.

use crate::common::lerp::Lerp;
use rust_hdl::prelude::*;

/// Clocks from the voxels to the sample: the entry registers and three
/// lerps of two clocks.
pub const LATENCY: usize = 7;

/// The sheared tri-linear interpolation unit.
#[derive(LogicBlock)]
pub struct Trilin {
    pub clock: Signal<In, Clock>,
    /// Rays A, B, C, D on plane `k` (`a0`, ...) and `k + 1` (`a1`, ...);
    /// one signal each, so that a parent's array of units can drive them.
    pub a0: Signal<In, Bits<16>>,
    pub a1: Signal<In, Bits<16>>,
    pub b0: Signal<In, Bits<16>>,
    pub b1: Signal<In, Bits<16>>,
    pub c0: Signal<In, Bits<16>>,
    pub c1: Signal<In, Bits<16>>,
    pub d0: Signal<In, Bits<16>>,
    pub d1: Signal<In, Bits<16>>,
    /// The offset `O` and the template weights, `W` fractional bits.
    pub offset: Signal<In, Bits<16>>,
    pub wx: Signal<In, Bits<16>>,
    pub wy: Signal<In, Bits<16>>,
    /// The sample, `sample_bits - voxel_bits` fractional bits.
    pub sample: Signal<Out, Bits<32>>,
    widen: Constant<Bits<8>>,
    front_q: [DFF<Bits<32>>; 4],
    back_q: [DFF<Bits<32>>; 4],
    offset_q: DFF<Bits<16>>,
    /// wx for the X lerps (three clocks), wy for the Y lerp (five).
    wx_q: [DFF<Bits<16>>; 3],
    wy_q: [DFF<Bits<16>>; 5],
    z: [Lerp; 4],
    top: Lerp,
    bottom: Lerp,
    vertical: Lerp,
}

impl Trilin {
    /// `sample_frac = sample_bits - voxel_bits`.
    pub fn new(weight_bits: u32, voxel_bits: u32, sample_frac: u32) -> Trilin {
        let wide = voxel_bits + sample_frac > 16;
        let lerp = || Lerp::new(weight_bits, wide);
        Trilin {
            clock: Default::default(),
            a0: Default::default(),
            a1: Default::default(),
            b0: Default::default(),
            b1: Default::default(),
            c0: Default::default(),
            c1: Default::default(),
            d0: Default::default(),
            d1: Default::default(),
            offset: Default::default(),
            wx: Default::default(),
            wy: Default::default(),
            sample: Default::default(),
            widen: Constant::new((sample_frac as u64).to_bits()),
            front_q: Default::default(),
            back_q: Default::default(),
            offset_q: Default::default(),
            wx_q: Default::default(),
            wy_q: Default::default(),
            z: std::array::from_fn(|_| lerp()),
            top: lerp(),
            bottom: lerp(),
            vertical: lerp(),
        }
    }
}

impl Logic for Trilin {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, offset_q);
        for i in 0..3 {
            self.wx_q[i].clock.next = self.clock.val();
        }
        for i in 0..5 {
            self.wy_q[i].clock.next = self.clock.val();
        }
        for i in 0..4 {
            self.front_q[i].clock.next = self.clock.val();
            self.back_q[i].clock.next = self.clock.val();
            self.z[i].clock.next = self.clock.val();
        }
        self.top.clock.next = self.clock.val();
        self.bottom.clock.next = self.clock.val();
        self.vertical.clock.next = self.clock.val();
        // Entry registers, the voxels widened.
        // (hdl_gen does not substitute a loop index inside bit_cast.)
        self.front_q[0].d.next = bit_cast::<32, 16>(self.a0.val()) << self.widen.val();
        self.back_q[0].d.next = bit_cast::<32, 16>(self.a1.val()) << self.widen.val();
        self.front_q[1].d.next = bit_cast::<32, 16>(self.b0.val()) << self.widen.val();
        self.back_q[1].d.next = bit_cast::<32, 16>(self.b1.val()) << self.widen.val();
        self.front_q[2].d.next = bit_cast::<32, 16>(self.c0.val()) << self.widen.val();
        self.back_q[2].d.next = bit_cast::<32, 16>(self.c1.val()) << self.widen.val();
        self.front_q[3].d.next = bit_cast::<32, 16>(self.d0.val()) << self.widen.val();
        self.back_q[3].d.next = bit_cast::<32, 16>(self.d1.val()) << self.widen.val();
        self.offset_q.d.next = self.offset.val();
        self.wx_q[0].d.next = self.wx.val();
        self.wx_q[1].d.next = self.wx_q[0].q.val();
        self.wx_q[2].d.next = self.wx_q[1].q.val();
        self.wy_q[0].d.next = self.wy.val();
        for i in 1..5 {
            self.wy_q[i].d.next = self.wy_q[i - 1].q.val();
        }
        // Along the major axis: a, b, c, d.
        for i in 0..4 {
            self.z[i].a.next = self.front_q[i].q.val();
            self.z[i].b.next = self.back_q[i].q.val();
            self.z[i].w.next = self.offset_q.q.val();
        }
        // In X, then in Y.
        self.top.a.next = self.z[0].y.val();
        self.top.b.next = self.z[1].y.val();
        self.top.w.next = self.wx_q[2].q.val();
        self.bottom.a.next = self.z[2].y.val();
        self.bottom.b.next = self.z[3].y.val();
        self.bottom.w.next = self.wx_q[2].q.val();
        self.vertical.a.next = self.top.y.val();
        self.vertical.b.next = self.bottom.y.val();
        self.vertical.w.next = self.wy_q[4].q.val();
        self.sample.next = self.vertical.y.val();
    }
}
