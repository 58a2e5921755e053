//! The pipelined linear interpolation shared by Cube-4L's bilinear unit
//! (§3.7) and Cube-3's TRILIN unit (§3, Fig. 4): `fixed::lerp_frac`, the
//! product rounded half up, bit for bit, with one 16x16 multiplier (two for
//! a difference wider than 16 bits), in two clocks (the compare, difference
//! and product; the rounded sum) or, built [`Lerp::split`], in three (the
//! compare and difference in a clock of their own, for speed: Cube-4L's
//! bilinear unit). The rounded sum is one carry chain: `a` enters it
//! shifted up with the rounding half below it, `(a << f) | 2^(f-1)`, an OR
//! in the product's clock. A one-multiplier lerp's product register is the
//! multiplier's own ([`DspProduct`]); a wide lerp sums its two products
//! before its register, in the fabric.

use super::dsp_product::DspProduct;
use rust_hdl::prelude::*;

/// Clocks from the inputs to the lerp, built with [`Lerp::new`].
pub const LATENCY: usize = 2;
/// ... and built with [`Lerp::split`].
pub const SPLIT_LATENCY: usize = 3;

/// `lerp(a, b, w)` with `w` in `0..=2^frac`, in [`LATENCY`] or
/// [`SPLIT_LATENCY`] clocks. The golden model's
/// `a + (((b - a) * w + 2^(f-1)) >> f)` (arithmetic shift) is
/// `((a << f) + 2^(f-1) + (b - a) * w) >> f`, since `a` is whole; in
/// unsigned form, with `p = |b - a| * w`, `(A + p) >> f` for `b >= a` and
/// `(A - p) >> f` for `b < a`, where `A = (a << f) | 2^(f-1)` (neither
/// goes below zero: the result lies between `a` and `b`). A wide lerp's
/// 32-bit difference goes through two 16x16 multipliers,
/// `d*w = (d_hi*w << 16) + d_lo*w`.
#[derive(LogicBlock)]
pub struct Lerp {
    pub clock: Signal<In, Clock>,
    pub a: Signal<In, Bits<32>>,
    pub b: Signal<In, Bits<32>>,
    pub w: Signal<In, Bits<16>>,
    /// The lerp of the inputs [`LATENCY`] (split: [`SPLIT_LATENCY`])
    /// clocks back.
    pub y: Signal<Out, Bits<32>>,
    half: Constant<Bits<64>>,
    shift: Constant<Bits<8>>,
    /// The difference can exceed 16 bits (X-ray's channel 0, TRILIN's
    /// samples beyond 16 bits).
    wide: Constant<Bit>,
    /// Split: the first clock's `b >= a`, `a`, `|b - a|` and `w`.
    split: Constant<Bit>,
    up_q: DFF<Bit>,
    a_q: DFF<Bits<32>>,
    diff_q: DFF<Bits<32>>,
    w_q: DFF<Bits<16>>,
    /// The inputs' order and difference.
    up_c: Signal<Local, Bit>,
    diff_c: Signal<Local, Bits<32>>,
    /// The product's operands: the inputs', or the split's registers.
    up: Signal<Local, Bit>,
    a_in: Signal<Local, Bits<32>>,
    diff: Signal<Local, Bits<32>>,
    w_in: Signal<Local, Bits<16>>,
    /// The product's clock: a narrow lerp's product into the multiplier's
    /// own register, a wide one's two products summed into `prod_q`.
    narrow: DspProduct,
    prod: Signal<Local, Bits<64>>,
    up_q2: DFF<Bit>,
    /// `(a << f) | 2^(f-1)`.
    a_q2: DFF<Bits<64>>,
    prod_q: DFF<Bits<64>>,
    /// The registered product, the narrow or the wide one.
    prod_r: Signal<Local, Bits<64>>,
    /// The last clock's sum, `f` bits above the result.
    sum: Signal<Local, Bits<64>>,
    y_q: DFF<Bits<32>>,
}

impl Lerp {
    /// `wide`: the difference can exceed 16 bits (two multipliers); two
    /// clocks.
    pub fn new(frac_bits: u32, wide: bool) -> Lerp {
        Lerp::build(frac_bits, wide, false)
    }

    /// As [`Lerp::new`], in three clocks.
    pub fn split(frac_bits: u32, wide: bool) -> Lerp {
        Lerp::build(frac_bits, wide, true)
    }

    fn build(frac_bits: u32, wide: bool, split: bool) -> Lerp {
        Lerp {
            clock: Default::default(),
            a: Default::default(),
            b: Default::default(),
            w: Default::default(),
            y: Default::default(),
            half: Constant::new((1u64 << (frac_bits - 1)).to_bits()),
            shift: Constant::new((frac_bits as u64).to_bits()),
            wide: Constant::new(wide),
            split: Constant::new(split),
            up_q: Default::default(),
            a_q: Default::default(),
            diff_q: Default::default(),
            w_q: Default::default(),
            up_c: Default::default(),
            diff_c: Default::default(),
            up: Default::default(),
            a_in: Default::default(),
            diff: Default::default(),
            w_in: Default::default(),
            narrow: DspProduct::new(!wide),
            prod: Default::default(),
            up_q2: Default::default(),
            a_q2: Default::default(),
            prod_q: Default::default(),
            prod_r: Default::default(),
            sum: Default::default(),
            y_q: Default::default(),
        }
    }
}

impl Logic for Lerp {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, up_q, a_q, diff_q, w_q, up_q2, a_q2, prod_q, y_q);
        // The order of the ends and their difference, in a clock of their
        // own when split.
        self.up_c.next = self.b.val() >= self.a.val();
        self.diff_c.next = self.b.val() - self.a.val();
        if !self.up_c.val() {
            self.diff_c.next = self.a.val() - self.b.val();
        }
        self.up_q.d.next = self.up_c.val();
        self.a_q.d.next = self.a.val();
        self.diff_q.d.next = self.diff_c.val();
        self.w_q.d.next = self.w.val();
        self.up.next = self.up_c.val();
        self.a_in.next = self.a.val();
        self.diff.next = self.diff_c.val();
        self.w_in.next = self.w.val();
        if self.split.val() {
            self.up.next = self.up_q.q.val();
            self.a_in.next = self.a_q.q.val();
            self.diff.next = self.diff_q.q.val();
            self.w_in.next = self.w_q.q.val();
        }
        // The product.
        self.narrow.clock.next = self.clock.val();
        self.narrow.a.next = self.diff.val().get_bits::<16>(0);
        self.narrow.b.next = self.w_in.val();
        self.prod.next = 0.into();
        if self.wide.val() {
            self.prod.next =
                (bit_cast::<64, 32>(self.diff.val().get_bits::<16>(16) * self.w_in.val()) << 16)
                    + bit_cast::<64, 32>(self.diff.val().get_bits::<16>(0) * self.w_in.val());
        }
        self.up_q2.d.next = self.up.val();
        self.a_q2.d.next =
            (bit_cast::<64, 32>(self.a_in.val()) << self.shift.val()) | self.half.val();
        self.prod_q.d.next = self.prod.val();
        // The last clock: the product onto `a` and the rounding half, one
        // carry chain, and the shift.
        self.prod_r.next = bit_cast::<64, 32>(self.narrow.p.val());
        if self.wide.val() {
            self.prod_r.next = self.prod_q.q.val();
        }
        self.sum.next = self.a_q2.q.val() - self.prod_r.val();
        if self.up_q2.q.val() {
            self.sum.next = self.a_q2.q.val() + self.prod_r.val();
        }
        self.y_q.d.next = bit_cast::<32, 64>(self.sum.val() >> self.shift.val());
        self.y.next = self.y_q.q.val();
    }
}
