//! The over operator of front-to-back compositing (Cube-4L §3.5; Cube-3's
//! Eq. 1 in the RPC nodes): `C = sat(C_front + mul(M - A_front, C_back))`
//! for one channel, combinational, bit for bit as the golden model's
//! `cube4l::compositor::composite`. `mul(a, b) = round(a*b / M)`, `M =
//! 2^rgba_bits - 1`, is `unorm::MulUnorm`: one 16x16 multiplier.

use super::unorm::MulUnorm;
use rust_hdl::prelude::*;

/// `sat(front + mul(m - front_alpha, back))` for one channel, combinational.
#[derive(LogicBlock)]
pub struct Over {
    pub front: Signal<In, Bits<16>>,
    pub back: Signal<In, Bits<16>>,
    pub front_alpha: Signal<In, Bits<16>>,
    pub result: Signal<Out, Bits<16>>,
    m: Constant<Bits<16>>,
    mul: MulUnorm,
    sum: Signal<Local, Bits<32>>,
}

impl Over {
    pub fn new(rgba_bits: u32) -> Over {
        Over::enabled(rgba_bits, true)
    }

    /// Without `enabled` the multiplier is disabled (`MulUnorm::enabled`),
    /// for a scene whose mode has no over operator.
    pub fn enabled(rgba_bits: u32, enabled: bool) -> Over {
        Over {
            m: Constant::new(((1u64 << rgba_bits) - 1).to_bits()),
            mul: MulUnorm::enabled(rgba_bits, enabled),
            front: Default::default(),
            back: Default::default(),
            front_alpha: Default::default(),
            result: Default::default(),
            sum: Default::default(),
        }
    }
}

impl Logic for Over {
    #[hdl_gen]
    fn update(&mut self) {
        self.mul.a.next = self.m.val() - self.front_alpha.val();
        self.mul.b.next = self.back.val();
        self.sum.next = bit_cast::<32, 16>(self.front.val()) + bit_cast::<32, 16>(self.mul.y.val());
        self.result.next = bit_cast::<16, 32>(self.sum.val());
        if self.sum.val() > bit_cast::<32, 16>(self.m.val()) {
            self.result.next = self.m.val();
        }
    }
}
