//! The pipelined linear interpolation shared by Cube-4L's bilinear unit
//! (§3.7) and Cube-3's TRILIN unit (§3, Fig. 4): `fixed::lerp_frac`, the
//! product rounded half up, bit for bit, in two clocks and one 16x16
//! multiplier (two for a difference wider than 16 bits).

use rust_hdl::prelude::*;

/// `lerp(a, b, w)` with `w` in `0..=2^frac`, in two clocks. In unsigned
/// form: for `b >= a`, `a + (((b - a) * w + 2^(f-1)) >> f)`; for `b < a`,
/// `a - (((a - b) * w + 2^(f-1) - 1) >> f)` (the arithmetic shift of the
/// golden model). A wide lerp's 32-bit difference goes through two 16x16
/// multipliers, `d*w = (d_hi*w << 16) + d_lo*w`.
#[derive(LogicBlock)]
pub struct Lerp {
    pub clock: Signal<In, Clock>,
    pub a: Signal<In, Bits<32>>,
    pub b: Signal<In, Bits<32>>,
    pub w: Signal<In, Bits<16>>,
    /// The lerp of the inputs two clocks back.
    pub y: Signal<Out, Bits<32>>,
    half: Constant<Bits<64>>,
    shift: Constant<Bits<8>>,
    /// The difference can exceed 16 bits (X-ray's channel 0, TRILIN's
    /// samples beyond 16 bits).
    wide: Constant<Bit>,
    diff: Signal<Local, Bits<32>>,
    prod: Signal<Local, Bits<64>>,
    /// First clock: `b >= a`, `a` and the product.
    up_q: DFF<Bit>,
    a_q: DFF<Bits<32>>,
    prod_q: DFF<Bits<64>>,
    step_up: Signal<Local, Bits<32>>,
    step_down: Signal<Local, Bits<32>>,
    y_q: DFF<Bits<32>>,
}

impl Lerp {
    /// `wide`: the difference can exceed 16 bits (two multipliers).
    pub fn new(frac_bits: u32, wide: bool) -> Lerp {
        Lerp {
            clock: Default::default(),
            a: Default::default(),
            b: Default::default(),
            w: Default::default(),
            y: Default::default(),
            half: Constant::new((1u64 << (frac_bits - 1)).to_bits()),
            shift: Constant::new((frac_bits as u64).to_bits()),
            wide: Constant::new(wide),
            diff: Default::default(),
            prod: Default::default(),
            up_q: Default::default(),
            a_q: Default::default(),
            prod_q: Default::default(),
            step_up: Default::default(),
            step_down: Default::default(),
            y_q: Default::default(),
        }
    }
}

impl Logic for Lerp {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, up_q, a_q, prod_q, y_q);
        if self.b.val() >= self.a.val() {
            self.diff.next = self.b.val() - self.a.val();
        } else {
            self.diff.next = self.a.val() - self.b.val();
        }
        self.prod.next = bit_cast::<64, 32>(self.diff.val().get_bits::<16>(0) * self.w.val());
        if self.wide.val() {
            self.prod.next =
                (bit_cast::<64, 32>(self.diff.val().get_bits::<16>(16) * self.w.val()) << 16)
                    + bit_cast::<64, 32>(self.diff.val().get_bits::<16>(0) * self.w.val());
        }
        self.up_q.d.next = self.b.val() >= self.a.val();
        self.a_q.d.next = self.a.val();
        self.prod_q.d.next = self.prod.val();
        self.step_up.next =
            bit_cast::<32, 64>((self.prod_q.q.val() + self.half.val()) >> self.shift.val());
        self.step_down.next =
            bit_cast::<32, 64>((self.prod_q.q.val() + self.half.val() - 1) >> self.shift.val());
        if self.up_q.q.val() {
            self.y_q.d.next = self.a_q.q.val() + self.step_up.val();
        } else {
            self.y_q.d.next = self.a_q.q.val() - self.step_down.val();
        }
        self.y.next = self.y_q.q.val();
    }
}
