//! The over operator over a register (Cube-4L §3.5's compositing unit):
//! `sat(front + mul(M - front_alpha, back))` for one channel, bit for bit as
//! [`super::over::Over`], in [`LATENCY`] clocks: the subtract
//! `M - front_alpha` into a register beside `back`'s, so that the
//! multiplier's operands come straight from flip-flops; the product and its
//! rounding half, a clock each ([`SplitMulUnorm`]); then the rounding, the
//! sum and the saturation combinational from its register.

use super::split_mul::{self, SplitMulUnorm};
use rust_hdl::prelude::*;

/// Clocks from the inputs to `result`.
pub const LATENCY: usize = 1 + split_mul::LATENCY;

#[derive(LogicBlock)]
pub struct PipedOver {
    pub clock: Signal<In, Clock>,
    pub front: Signal<In, Bits<16>>,
    pub back: Signal<In, Bits<16>>,
    pub front_alpha: Signal<In, Bits<16>>,
    /// The inputs of [`LATENCY`] clocks before, composited.
    pub result: Signal<Out, Bits<16>>,
    m: Constant<Bits<16>>,
    mul: SplitMulUnorm,
    weight_q: DFF<Bits<16>>,
    back_q: DFF<Bits<16>>,
    front_q: DFF<Bits<16>>,
    front_qq: DFF<Bits<16>>,
    front_qqq: DFF<Bits<16>>,
    sum: Signal<Local, Bits<32>>,
}

impl PipedOver {
    pub fn new(rgba_bits: u32) -> PipedOver {
        PipedOver {
            clock: Default::default(),
            front: Default::default(),
            back: Default::default(),
            front_alpha: Default::default(),
            result: Default::default(),
            m: Constant::new(((1u64 << rgba_bits) - 1).to_bits()),
            mul: SplitMulUnorm::new(rgba_bits),
            weight_q: Default::default(),
            back_q: Default::default(),
            front_q: Default::default(),
            front_qq: Default::default(),
            front_qqq: Default::default(),
            sum: Default::default(),
        }
    }
}

impl Logic for PipedOver {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, weight_q, back_q, front_q, front_qq, front_qqq);
        self.weight_q.d.next = self.m.val() - self.front_alpha.val();
        self.back_q.d.next = self.back.val();
        self.front_q.d.next = self.front.val();
        self.mul.clock.next = self.clock.val();
        self.mul.a.next = self.weight_q.q.val();
        self.mul.b.next = self.back_q.q.val();
        self.front_qq.d.next = self.front_q.q.val();
        self.front_qqq.d.next = self.front_qq.q.val();
        self.sum.next =
            bit_cast::<32, 16>(self.front_qqq.q.val()) + bit_cast::<32, 16>(self.mul.y.val());
        self.result.next = bit_cast::<16, 32>(self.sum.val());
        if self.sum.val() > bit_cast::<32, 16>(self.m.val()) {
            self.result.next = self.m.val();
        }
    }
}
