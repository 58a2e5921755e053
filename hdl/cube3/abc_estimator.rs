//! The gradient estimator of one Cube-3 ABC unit (§4, Figs. 8, 9 and 11),
//! bit for bit as `golden_model::cube3::abc::gradient` for the 6-, 12- and
//! 26-neighbourhood, in [`LATENCY`] clocks. [`super::abc_gradient`] brings it
//! the samples around the centre `S(0, 0, 0)` of the above, current and
//! below sample planes (`S(i, j, l)`: ray `u + i`, scanline `v + j`, plane
//! `k + l`):
//!
//! - `xp, xm, yp, ym` = `S(±1, 0, 0)`, `S(0, ±1, 0)`: `G_x`, `G_y` are their
//!   differences (both neighbourhoods);
//! - `kp{3a + b}`, `km{3a + b}` = `S(1 - b, 1 - a, ±1)`: the planes `k ± 1`;
//! - `c0, c2, c6, c8` = `S(±1, ±1, 0)`, the current plane's corners
//!   (numbered as `kp`): the 26 only.
//!
//! **6** (Fig. 8): `G_r = S(0, 0, 1) - S(0, 0, -1)`, along the ray, then the
//! shear `g_z = G_r - ((DX·G_x + DY·G_y + 2^(W-1)) >> W)` (arithmetic
//! shift): a [`SignedProduct`] of the difference and the 16-bit increment
//! each (two 16-bit multipliers where samples are wider than 16 bits),
//! registered, then the sum. **12** (Fig. 11): `g_z` is
//! the difference of two bilinear interpolations ([`Lerp`]s with weights
//! `|DX|`, `|DY|`): on plane `k + 1` of the rays `(0 | -s_x, 0 | -s_y)` and
//! on plane `k - 1` of `(0 | s_x, 0 | s_y)`, the signs selecting the taps.
//! **26** (Fig. 9): the 6's shear on the weighted differences of all 26
//! neighbours ([`AbcSums26`], two clocks, as the 6's differences wait).
//! **10** (Fig. 10, parallel views): lerped neighbours and the host's basis
//! correction ([`AbcBasis10`], in place of the shear).
//!
//! Every component is saturated to `±(2^(gradient_bits-1) - 1)` in the last
//! clock and leaves as a 32-bit two's-complement word. The neighbourhood is
//! a build parameter: the 6's and 12's multipliers or lerps are built with
//! their outputs unused where the other is chosen, for synthesis to remove;
//! the 26's sums only in a 26 build (the export leaves them out of the
//! others).

use super::abc_basis10::{self, AbcBasis10};
use super::abc_sums26::{self, AbcSums26};
use super::signed_product::SignedProduct;
use crate::common::lerp::{self, Lerp};
use golden_model::cube3::plan::Neighbourhood;
use rust_hdl::prelude::*;

/// Clocks from the neighbourhood to the gradient word: the 12's two lerps
/// in series, each split ([`lerp::SPLIT_LATENCY`]), and the saturation.
pub const LATENCY: usize = 2 * lerp::SPLIT_LATENCY + 1;
// The 26's differences take the 6's place in `gx_q[2]`; the 10's gradient,
// two registers on, the shear's place in the last clock. The register
// arrays below are written for these latencies (`hdl_gen` takes only
// literal indices).
const _: () = assert!(abc_sums26::LATENCY == 2 && abc_basis10::LATENCY + 2 == LAST);
const _: () = assert!(LATENCY == 7);
const LAST: usize = LATENCY - 1;

/// `clamp(v, -lim, lim)` of a 64-bit two's-complement word, as 32 bits.
#[derive(LogicBlock)]
struct Saturate {
    pub v: Signal<In, Bits<64>>,
    pub y: Signal<Out, Bits<32>>,
    lim: Constant<Bits<64>>,
    /// `lim` and `-lim` as 32-bit words.
    high: Constant<Bits<32>>,
    low: Constant<Bits<32>>,
    mag: Signal<Local, Bits<64>>,
}

impl Saturate {
    fn new(gradient_bits: u32) -> Saturate {
        let lim = (1u64 << (gradient_bits - 1)) - 1;
        Saturate {
            v: Default::default(),
            y: Default::default(),
            lim: Constant::new(lim.to_bits()),
            high: Constant::new(lim.to_bits()),
            low: Constant::new(((lim as u32).wrapping_neg() as u64).to_bits()),
            mag: Default::default(),
        }
    }
}

impl Logic for Saturate {
    #[hdl_gen]
    fn update(&mut self) {
        self.mag.next = self.v.val();
        if self.v.val().get_bit(63) {
            self.mag.next = !self.v.val() + 1;
        }
        self.y.next = self.v.val().get_bits::<32>(0);
        if self.mag.val() > self.lim.val() {
            self.y.next = self.high.val();
            if self.v.val().get_bit(63) {
                self.y.next = self.low.val();
            }
        }
    }
}

/// One lane's gradient estimator.
#[derive(LogicBlock)]
pub struct AbcEstimator {
    pub clock: Signal<In, Clock>,
    pub xp: Signal<In, Bits<32>>,
    pub xm: Signal<In, Bits<32>>,
    pub yp: Signal<In, Bits<32>>,
    pub ym: Signal<In, Bits<32>>,
    pub kp0: Signal<In, Bits<32>>,
    pub kp1: Signal<In, Bits<32>>,
    pub kp2: Signal<In, Bits<32>>,
    pub kp3: Signal<In, Bits<32>>,
    pub kp4: Signal<In, Bits<32>>,
    pub kp5: Signal<In, Bits<32>>,
    pub kp6: Signal<In, Bits<32>>,
    pub kp7: Signal<In, Bits<32>>,
    pub kp8: Signal<In, Bits<32>>,
    pub km0: Signal<In, Bits<32>>,
    pub km1: Signal<In, Bits<32>>,
    pub km2: Signal<In, Bits<32>>,
    pub km3: Signal<In, Bits<32>>,
    pub km4: Signal<In, Bits<32>>,
    pub km5: Signal<In, Bits<32>>,
    pub km6: Signal<In, Bits<32>>,
    pub km7: Signal<In, Bits<32>>,
    pub km8: Signal<In, Bits<32>>,
    pub c0: Signal<In, Bits<32>>,
    pub c2: Signal<In, Bits<32>>,
    pub c6: Signal<In, Bits<32>>,
    pub c8: Signal<In, Bits<32>>,
    /// The 10's weights and basis correction (the host's registers).
    pub weights10: Signal<In, Bits<64>>,
    pub basis10_x: Signal<In, Bits<64>>,
    pub basis10_y: Signal<In, Bits<64>>,
    pub basis10_z: Signal<In, Bits<64>>,
    /// The centre ray's increments, `W` fractional bits.
    pub dx_neg: Signal<In, Bit>,
    pub dx_mag: Signal<In, Bits<16>>,
    pub dy_neg: Signal<In, Bit>,
    pub dy_mag: Signal<In, Bits<16>>,
    /// The centre `S(0, 0, 0)`, and the same leaving with its gradient.
    pub centre: Signal<In, Bits<32>>,
    pub sample: Signal<Out, Bits<32>>,
    /// `2∇` in traversal axes, sample units, saturated.
    pub gx: Signal<Out, Bits<32>>,
    pub gy: Signal<Out, Bits<32>>,
    pub gz: Signal<Out, Bits<32>>,
    n12: Constant<Bit>,
    n26: Constant<Bit>,
    n10: Constant<Bit>,
    half: Constant<Bits<64>>,
    shift: Constant<Bits<8>>,
    sign_ext: Constant<Bits<64>>,
    /// The 26: its differences, in place of the 6's from clock 2 on.
    pub(crate) sums26: AbcSums26,
    /// The 10: its gradient, two registers on, in place of the 6's in the
    /// last clock.
    pub(crate) basis10: AbcBasis10,
    b10x_q: [DFF<Bits<64>>; 2],
    b10y_q: [DFF<Bits<64>>; 2],
    b10z_q: [DFF<Bits<64>>; 2],
    /// The differences, G_x, G_y and G_r to the last clock (the 6).
    gx_q: [DFF<Bits<32>>; 6],
    gy_q: [DFF<Bits<32>>; 6],
    gr_q: [DFF<Bits<32>>; 6],
    /// The increments: |DY| for the 12's second lerps (three clocks), both
    /// for the 6's shear (five).
    dx_neg_q: [DFF<Bit>; 5],
    dx_mag_q: [DFF<Bits<16>>; 5],
    dy_neg_q: [DFF<Bit>; 5],
    dy_mag_q: [DFF<Bits<16>>; 5],
    /// The 6: the shear's products, registered.
    px: SignedProduct,
    py: SignedProduct,
    px_q: DFF<Bits<64>>,
    py_q: DFF<Bits<64>>,
    shear_sum: Signal<Local, Bits<64>>,
    shear: Signal<Local, Bits<64>>,
    /// The 12: the selected taps and the bilinear interpolations.
    sx_pos: Signal<Local, Bit>,
    sx_neg: Signal<Local, Bit>,
    sy_pos: Signal<Local, Bit>,
    sy_neg: Signal<Local, Bit>,
    front_row: [Signal<Local, Bits<32>>; 3],
    back_row: [Signal<Local, Bits<32>>; 3],
    front_x: Signal<Local, Bits<32>>,
    front_xy: Signal<Local, Bits<32>>,
    back_x: Signal<Local, Bits<32>>,
    back_xy: Signal<Local, Bits<32>>,
    front_top: Lerp,
    front_bottom: Lerp,
    front_y: Lerp,
    back_top: Lerp,
    back_bottom: Lerp,
    back_y: Lerp,
    gr_wide: Signal<Local, Bits<64>>,
    gz_wide: Signal<Local, Bits<64>>,
    sat_x: Saturate,
    sat_y: Saturate,
    sat_z: Saturate,
    gx_out: DFF<Bits<32>>,
    gy_out: DFF<Bits<32>>,
    gz_out: DFF<Bits<32>>,
    centre_q: [DFF<Bits<32>>; LATENCY],
}

impl AbcEstimator {
    /// Neighbourhood `n`; `wide`: samples of more than 16 bits.
    pub fn new(
        n: Neighbourhood,
        weight_bits: u32,
        gradient_bits: u32,
        wide: bool,
    ) -> Result<AbcEstimator, String> {
        let lerp = || Lerp::split(weight_bits, wide);
        Ok(AbcEstimator {
            clock: Default::default(),
            xp: Default::default(),
            xm: Default::default(),
            yp: Default::default(),
            ym: Default::default(),
            kp0: Default::default(),
            kp1: Default::default(),
            kp2: Default::default(),
            kp3: Default::default(),
            kp4: Default::default(),
            kp5: Default::default(),
            kp6: Default::default(),
            kp7: Default::default(),
            kp8: Default::default(),
            km0: Default::default(),
            km1: Default::default(),
            km2: Default::default(),
            km3: Default::default(),
            km4: Default::default(),
            km5: Default::default(),
            km6: Default::default(),
            km7: Default::default(),
            km8: Default::default(),
            c0: Default::default(),
            c2: Default::default(),
            c6: Default::default(),
            c8: Default::default(),
            weights10: Default::default(),
            basis10_x: Default::default(),
            basis10_y: Default::default(),
            basis10_z: Default::default(),
            dx_neg: Default::default(),
            dx_mag: Default::default(),
            dy_neg: Default::default(),
            dy_mag: Default::default(),
            centre: Default::default(),
            sample: Default::default(),
            gx: Default::default(),
            gy: Default::default(),
            gz: Default::default(),
            n12: Constant::new(n == Neighbourhood::N12),
            n26: Constant::new(n == Neighbourhood::N26),
            n10: Constant::new(n == Neighbourhood::N10),
            sums26: Default::default(),
            basis10: AbcBasis10::new(weight_bits, wide),
            b10x_q: Default::default(),
            b10y_q: Default::default(),
            b10z_q: Default::default(),
            half: Constant::new((1u64 << (weight_bits - 1)).to_bits()),
            shift: Constant::new((weight_bits as u64).to_bits()),
            sign_ext: Constant::new((u64::MAX << 32).to_bits()),
            gx_q: Default::default(),
            gy_q: Default::default(),
            gr_q: Default::default(),
            dx_neg_q: Default::default(),
            dx_mag_q: Default::default(),
            dy_neg_q: Default::default(),
            dy_mag_q: Default::default(),
            px: SignedProduct::new(wide),
            py: SignedProduct::new(wide),
            px_q: Default::default(),
            py_q: Default::default(),
            shear_sum: Default::default(),
            shear: Default::default(),
            sx_pos: Default::default(),
            sx_neg: Default::default(),
            sy_pos: Default::default(),
            sy_neg: Default::default(),
            front_row: Default::default(),
            back_row: Default::default(),
            front_x: Default::default(),
            front_xy: Default::default(),
            back_x: Default::default(),
            back_xy: Default::default(),
            front_top: lerp(),
            front_bottom: lerp(),
            front_y: lerp(),
            back_top: lerp(),
            back_bottom: lerp(),
            back_y: lerp(),
            gr_wide: Default::default(),
            gz_wide: Default::default(),
            sat_x: Saturate::new(gradient_bits),
            sat_y: Saturate::new(gradient_bits),
            sat_z: Saturate::new(gradient_bits),
            gx_out: Default::default(),
            gy_out: Default::default(),
            gz_out: Default::default(),
            centre_q: Default::default(),
        })
    }
}

impl Logic for AbcEstimator {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, px_q, py_q, gx_out, gy_out, gz_out);
        for i in 0..LATENCY {
            self.centre_q[i].clock.next = self.clock.val();
        }
        self.centre_q[0].d.next = self.centre.val();
        for i in 1..LATENCY {
            self.centre_q[i].d.next = self.centre_q[i - 1].q.val();
        }
        // The last register (a loop: rust-hdl's Verilog generator takes an
        // array index from loop variables and literals only).
        for i in LAST..LATENCY {
            self.sample.next = self.centre_q[i].q.val();
        }
        for i in 0..6 {
            self.gx_q[i].clock.next = self.clock.val();
            self.gy_q[i].clock.next = self.clock.val();
            self.gr_q[i].clock.next = self.clock.val();
        }
        for i in 0..2 {
            self.b10x_q[i].clock.next = self.clock.val();
            self.b10y_q[i].clock.next = self.clock.val();
            self.b10z_q[i].clock.next = self.clock.val();
        }
        for i in 0..5 {
            self.dx_neg_q[i].clock.next = self.clock.val();
            self.dx_mag_q[i].clock.next = self.clock.val();
            self.dy_neg_q[i].clock.next = self.clock.val();
            self.dy_mag_q[i].clock.next = self.clock.val();
        }
        self.front_top.clock.next = self.clock.val();
        self.front_bottom.clock.next = self.clock.val();
        self.front_y.clock.next = self.clock.val();
        self.back_top.clock.next = self.clock.val();
        self.back_bottom.clock.next = self.clock.val();
        self.back_y.clock.next = self.clock.val();
        // Clock 0: the differences, and the increments into their delays.
        self.gx_q[0].d.next = self.xp.val() - self.xm.val();
        self.gy_q[0].d.next = self.yp.val() - self.ym.val();
        self.gr_q[0].d.next = self.kp4.val() - self.km4.val();
        for i in 1..6 {
            self.gx_q[i].d.next = self.gx_q[i - 1].q.val();
            self.gy_q[i].d.next = self.gy_q[i - 1].q.val();
            self.gr_q[i].d.next = self.gr_q[i - 1].q.val();
        }
        // The 26, clocks 0-1: its differences replace the 6's at clock 2.
        self.sums26.clock.next = self.clock.val();
        self.sums26.xp.next = self.xp.val();
        self.sums26.xm.next = self.xm.val();
        self.sums26.yp.next = self.yp.val();
        self.sums26.ym.next = self.ym.val();
        self.sums26.c0.next = self.c0.val();
        self.sums26.c2.next = self.c2.val();
        self.sums26.c6.next = self.c6.val();
        self.sums26.c8.next = self.c8.val();
        self.sums26.kp0.next = self.kp0.val();
        self.sums26.kp1.next = self.kp1.val();
        self.sums26.kp2.next = self.kp2.val();
        self.sums26.kp3.next = self.kp3.val();
        self.sums26.kp4.next = self.kp4.val();
        self.sums26.kp5.next = self.kp5.val();
        self.sums26.kp6.next = self.kp6.val();
        self.sums26.kp7.next = self.kp7.val();
        self.sums26.kp8.next = self.kp8.val();
        self.sums26.km0.next = self.km0.val();
        self.sums26.km1.next = self.km1.val();
        self.sums26.km2.next = self.km2.val();
        self.sums26.km3.next = self.km3.val();
        self.sums26.km4.next = self.km4.val();
        self.sums26.km5.next = self.km5.val();
        self.sums26.km6.next = self.km6.val();
        self.sums26.km7.next = self.km7.val();
        self.sums26.km8.next = self.km8.val();
        // The 10, clocks 0-4, then two registers.
        self.basis10.clock.next = self.clock.val();
        self.basis10.xp.next = self.xp.val();
        self.basis10.xm.next = self.xm.val();
        self.basis10.yp.next = self.yp.val();
        self.basis10.ym.next = self.ym.val();
        self.basis10.kp1.next = self.kp1.val();
        self.basis10.kp3.next = self.kp3.val();
        self.basis10.kp4.next = self.kp4.val();
        self.basis10.kp5.next = self.kp5.val();
        self.basis10.kp7.next = self.kp7.val();
        self.basis10.km1.next = self.km1.val();
        self.basis10.km3.next = self.km3.val();
        self.basis10.km4.next = self.km4.val();
        self.basis10.km5.next = self.km5.val();
        self.basis10.km7.next = self.km7.val();
        self.basis10.dx_neg.next = self.dx_neg.val();
        self.basis10.dx_mag.next = self.dx_mag.val();
        self.basis10.dy_neg.next = self.dy_neg.val();
        self.basis10.dy_mag.next = self.dy_mag.val();
        self.basis10.weights.next = self.weights10.val();
        self.basis10.basis_x.next = self.basis10_x.val();
        self.basis10.basis_y.next = self.basis10_y.val();
        self.basis10.basis_z.next = self.basis10_z.val();
        if self.n26.val() {
            self.gx_q[2].d.next = self.sums26.gx.val();
            self.gy_q[2].d.next = self.sums26.gy.val();
            self.gr_q[2].d.next = self.sums26.gr.val();
        }
        self.dx_neg_q[0].d.next = self.dx_neg.val();
        self.dx_mag_q[0].d.next = self.dx_mag.val();
        self.dy_neg_q[0].d.next = self.dy_neg.val();
        self.dy_mag_q[0].d.next = self.dy_mag.val();
        for i in 1..5 {
            self.dx_neg_q[i].d.next = self.dx_neg_q[i - 1].q.val();
            self.dx_mag_q[i].d.next = self.dx_mag_q[i - 1].q.val();
            self.dy_neg_q[i].d.next = self.dy_neg_q[i - 1].q.val();
            self.dy_mag_q[i].d.next = self.dy_mag_q[i - 1].q.val();
        }
        // The 6, clock 5: the shear's products; clock 6: their rounded sum.
        self.px.g.next = self.gx_q[4].q.val();
        self.px.d_neg.next = self.dx_neg_q[4].q.val();
        self.px.d_mag.next = self.dx_mag_q[4].q.val();
        self.py.g.next = self.gy_q[4].q.val();
        self.py.d_neg.next = self.dy_neg_q[4].q.val();
        self.py.d_mag.next = self.dy_mag_q[4].q.val();
        self.px_q.d.next = self.px.y.val();
        self.py_q.d.next = self.py.y.val();
        self.shear_sum.next = self.px_q.q.val() + self.py_q.q.val() + self.half.val();
        self.shear.next = self.shear_sum.val() >> self.shift.val();
        if self.shear_sum.val().get_bit(63) {
            self.shear.next = !((!self.shear_sum.val()) >> self.shift.val());
        }
        // The 12, clock 0: the signs select plane k+1's taps at ray u - s_x,
        // scanline v - s_y, and plane k-1's at u + s_x, v + s_y.
        self.sx_pos.next = !self.dx_neg.val() & self.dx_mag.val().any();
        self.sx_neg.next = self.dx_neg.val() & self.dx_mag.val().any();
        self.sy_pos.next = !self.dy_neg.val() & self.dy_mag.val().any();
        self.sy_neg.next = self.dy_neg.val() & self.dy_mag.val().any();
        self.front_row[0].next = self.kp3.val();
        self.back_row[0].next = self.km3.val();
        if self.sy_pos.val() {
            self.front_row[0].next = self.kp6.val();
            self.back_row[0].next = self.km0.val();
        }
        if self.sy_neg.val() {
            self.front_row[0].next = self.kp0.val();
            self.back_row[0].next = self.km6.val();
        }
        self.front_row[1].next = self.kp4.val();
        self.back_row[1].next = self.km4.val();
        if self.sy_pos.val() {
            self.front_row[1].next = self.kp7.val();
            self.back_row[1].next = self.km1.val();
        }
        if self.sy_neg.val() {
            self.front_row[1].next = self.kp1.val();
            self.back_row[1].next = self.km7.val();
        }
        self.front_row[2].next = self.kp5.val();
        self.back_row[2].next = self.km5.val();
        if self.sy_pos.val() {
            self.front_row[2].next = self.kp8.val();
            self.back_row[2].next = self.km2.val();
        }
        if self.sy_neg.val() {
            self.front_row[2].next = self.kp2.val();
            self.back_row[2].next = self.km8.val();
        }
        self.front_x.next = self.kp4.val();
        self.front_xy.next = self.front_row[1].val();
        self.back_x.next = self.km4.val();
        self.back_xy.next = self.back_row[1].val();
        if self.sx_pos.val() {
            self.front_x.next = self.kp5.val();
            self.front_xy.next = self.front_row[2].val();
            self.back_x.next = self.km3.val();
            self.back_xy.next = self.back_row[0].val();
        }
        if self.sx_neg.val() {
            self.front_x.next = self.kp3.val();
            self.front_xy.next = self.front_row[0].val();
            self.back_x.next = self.km5.val();
            self.back_xy.next = self.back_row[2].val();
        }
        // Clocks 0-6: the two bilinear interpolations, each lerp split.
        self.front_top.a.next = self.kp4.val();
        self.front_top.b.next = self.front_x.val();
        self.front_top.w.next = self.dx_mag.val();
        self.front_bottom.a.next = self.front_row[1].val();
        self.front_bottom.b.next = self.front_xy.val();
        self.front_bottom.w.next = self.dx_mag.val();
        self.front_y.a.next = self.front_top.y.val();
        self.front_y.b.next = self.front_bottom.y.val();
        self.front_y.w.next = self.dy_mag_q[2].q.val();
        self.back_top.a.next = self.km4.val();
        self.back_top.b.next = self.back_x.val();
        self.back_top.w.next = self.dx_mag.val();
        self.back_bottom.a.next = self.back_row[1].val();
        self.back_bottom.b.next = self.back_xy.val();
        self.back_bottom.w.next = self.dx_mag.val();
        self.back_y.a.next = self.back_top.y.val();
        self.back_y.b.next = self.back_bottom.y.val();
        self.back_y.w.next = self.dy_mag_q[2].q.val();
        // Clock 6: g_z of the chosen neighbourhood, sign-extended to 64 bits.
        self.gr_wide.next = bit_cast::<64, 32>(self.gr_q[5].q.val());
        if self.gr_q[5].q.val().get_bit(31) {
            self.gr_wide.next = bit_cast::<64, 32>(self.gr_q[5].q.val()) | self.sign_ext.val();
        }
        self.gz_wide.next = self.gr_wide.val() - self.shear.val();
        if self.n12.val() {
            self.gz_wide.next =
                bit_cast::<64, 32>(self.front_y.y.val()) - bit_cast::<64, 32>(self.back_y.y.val());
        }
        self.sat_x.v.next = bit_cast::<64, 32>(self.gx_q[5].q.val());
        if self.gx_q[5].q.val().get_bit(31) {
            self.sat_x.v.next = bit_cast::<64, 32>(self.gx_q[5].q.val()) | self.sign_ext.val();
        }
        self.sat_y.v.next = bit_cast::<64, 32>(self.gy_q[5].q.val());
        if self.gy_q[5].q.val().get_bit(31) {
            self.sat_y.v.next = bit_cast::<64, 32>(self.gy_q[5].q.val()) | self.sign_ext.val();
        }
        self.sat_z.v.next = self.gz_wide.val();
        self.b10x_q[0].d.next = self.basis10.gx.val();
        self.b10y_q[0].d.next = self.basis10.gy.val();
        self.b10z_q[0].d.next = self.basis10.gz.val();
        self.b10x_q[1].d.next = self.b10x_q[0].q.val();
        self.b10y_q[1].d.next = self.b10y_q[0].q.val();
        self.b10z_q[1].d.next = self.b10z_q[0].q.val();
        if self.n10.val() {
            self.sat_x.v.next = self.b10x_q[1].q.val();
            self.sat_y.v.next = self.b10y_q[1].q.val();
            self.sat_z.v.next = self.b10z_q[1].q.val();
        }
        self.gx_out.d.next = self.sat_x.y.val();
        self.gy_out.d.next = self.sat_y.y.val();
        self.gz_out.d.next = self.sat_z.y.val();
        self.gx.next = self.gx_out.q.val();
        self.gy.next = self.gy_out.q.val();
        self.gz.next = self.gz_out.q.val();
    }
}
