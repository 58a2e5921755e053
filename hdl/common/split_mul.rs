//! `mul(a, b) = round(a*b / (2^bits - 1))` for unorm words over two
//! registers, bit for bit as `golden_model::fixed::mul_unorm`: the 16x16
//! product alone into a register (the multiplier's clock holds no carry
//! chain; the register is the multiplier's own on an ECP5, [`DspProduct`]), then its rounding half (`t = a*b + 2^(bits-1)`) into a second;
//! `y = (t + (t >> bits)) >> bits` leaves combinationally from that
//! register two clocks after `a` and `b`. The over operator's and the
//! shader's products.

use super::dsp_product::DspProduct;
use rust_hdl::prelude::*;

/// Clocks from `a` and `b` to `y`.
pub const LATENCY: usize = 2;

#[derive(LogicBlock)]
pub struct SplitMulUnorm {
    pub clock: Signal<In, Clock>,
    pub a: Signal<In, Bits<16>>,
    pub b: Signal<In, Bits<16>>,
    /// The product of `a` and `b` of [`LATENCY`] clocks before.
    pub y: Signal<Out, Bits<16>>,
    half: Constant<Bits<32>>,
    shift: Constant<Bits<8>>,
    p: DspProduct,
    t: DFF<Bits<32>>,
    enabled: Constant<Bit>,
}

impl SplitMulUnorm {
    pub fn new(bits: u32) -> SplitMulUnorm {
        Self::enabled(bits, true)
    }

    /// Without `enabled` the product is zero, as in emitted Verilog that
    /// leaves the multiplier out (`export::prune`).
    pub fn enabled(bits: u32, enabled: bool) -> SplitMulUnorm {
        SplitMulUnorm {
            clock: Default::default(),
            a: Default::default(),
            b: Default::default(),
            y: Default::default(),
            half: Constant::new((1u64 << (bits - 1)).to_bits()),
            shift: Constant::new((bits as u64).to_bits()),
            p: DspProduct::new(enabled),
            t: Default::default(),
            enabled: Constant::new(enabled),
        }
    }
}

impl Logic for SplitMulUnorm {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, t);
        self.p.clock.next = self.clock.val();
        self.p.a.next = self.a.val();
        self.p.b.next = self.b.val();
        self.t.d.next = self.p.p.val() + self.half.val();
        self.y.next = bit_cast::<16, 32>(
            (self.t.q.val() + (self.t.q.val() >> self.shift.val())) >> self.shift.val(),
        );
        if !self.enabled.val() {
            self.y.next = 0.into();
        }
    }
}
