//! `mul(a, b) = round(a*b / (2^bits - 1))` for unorm words over a register,
//! bit for bit as `golden_model::fixed::mul_unorm`: the 16x16 product and its
//! rounding half are registered (`t = a*b + 2^(bits-1)`), and
//! `y = (t + (t >> bits)) >> bits` leaves combinationally from the register
//! one clock after `a` and `b`, so the multiplier has a clock to itself.

use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct PipedMulUnorm {
    pub clock: Signal<In, Clock>,
    pub a: Signal<In, Bits<16>>,
    pub b: Signal<In, Bits<16>>,
    /// The product of the previous clock's `a` and `b`.
    pub y: Signal<Out, Bits<16>>,
    half: Constant<Bits<32>>,
    shift: Constant<Bits<8>>,
    t: DFF<Bits<32>>,
    enabled: Constant<Bit>,
}

impl PipedMulUnorm {
    /// Without `enabled` the product is zero, as in emitted Verilog that
    /// leaves the multiplier out (`export::prune`).
    pub fn enabled(bits: u32, enabled: bool) -> PipedMulUnorm {
        PipedMulUnorm {
            clock: Default::default(),
            a: Default::default(),
            b: Default::default(),
            y: Default::default(),
            half: Constant::new((1u64 << (bits - 1)).to_bits()),
            shift: Constant::new((bits as u64).to_bits()),
            t: Default::default(),
            enabled: Constant::new(enabled),
        }
    }
}

impl Logic for PipedMulUnorm {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, t);
        self.t.d.next = self.a.val() * self.b.val() + self.half.val();
        self.y.next = bit_cast::<16, 32>(
            (self.t.q.val() + (self.t.q.val() >> self.shift.val())) >> self.shift.val(),
        );
        if !self.enabled.val() {
            self.y.next = 0.into();
        }
    }
}
