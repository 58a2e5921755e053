//! `mul(a, b) = round(a*b / (2^bits - 1))` for unorm words, combinational:
//! `t = a*b + 2^(bits-1); (t + (t >> bits)) >> bits` with one 16x16
//! multiplier, bit for bit as `golden_model::fixed::mul_unorm`.

use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct MulUnorm {
    pub a: Signal<In, Bits<16>>,
    pub b: Signal<In, Bits<16>>,
    pub y: Signal<Out, Bits<16>>,
    half: Constant<Bits<32>>,
    shift: Constant<Bits<8>>,
    t: Signal<Local, Bits<32>>,
    enabled: Constant<Bit>,
}

impl MulUnorm {
    pub fn new(bits: u32) -> MulUnorm {
        MulUnorm::enabled(bits, true)
    }

    /// Without `enabled` the product is zero, as in emitted Verilog that
    /// leaves the multiplier out (`export::prune`).
    pub fn enabled(bits: u32, enabled: bool) -> MulUnorm {
        MulUnorm {
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

impl Logic for MulUnorm {
    #[hdl_gen]
    fn update(&mut self) {
        self.t.next = self.a.val() * self.b.val() + self.half.val();
        self.y.next = bit_cast::<16, 32>(
            (self.t.val() + (self.t.val() >> self.shift.val())) >> self.shift.val(),
        );
        if !self.enabled.val() {
            self.y.next = 0.into();
        }
    }
}
