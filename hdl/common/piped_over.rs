//! The over operator over a register (Cube-4L §3.5's compositing unit):
//! `sat(front + mul(M - front_alpha, back))` for one channel, bit for bit as
//! [`super::over::Over`], with the subtract and the multiplier in the clock
//! of the inputs ([`PipedMulUnorm`]) and the rounding, the sum and the
//! saturation combinational from the register one clock later.

use super::piped_mul::PipedMulUnorm;
use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct PipedOver {
    pub clock: Signal<In, Clock>,
    pub front: Signal<In, Bits<16>>,
    pub back: Signal<In, Bits<16>>,
    pub front_alpha: Signal<In, Bits<16>>,
    /// The previous clock's inputs composited.
    pub result: Signal<Out, Bits<16>>,
    m: Constant<Bits<16>>,
    mul: PipedMulUnorm,
    front_q: DFF<Bits<16>>,
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
            mul: PipedMulUnorm::enabled(rgba_bits, true),
            front_q: Default::default(),
            sum: Default::default(),
        }
    }
}

impl Logic for PipedOver {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, front_q);
        self.mul.clock.next = self.clock.val();
        self.mul.a.next = self.m.val() - self.front_alpha.val();
        self.mul.b.next = self.back.val();
        self.front_q.d.next = self.front.val();
        self.sum.next =
            bit_cast::<32, 16>(self.front_q.q.val()) + bit_cast::<32, 16>(self.mul.y.val());
        self.result.next = bit_cast::<16, 32>(self.sum.val());
        if self.sum.val() > bit_cast::<32, 16>(self.m.val()) {
            self.result.next = self.m.val();
        }
    }
}
