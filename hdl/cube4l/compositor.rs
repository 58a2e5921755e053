//! Compositing unit of the Cube-4L pipeline (§3.5, the C_k circles of Fig.
//! 18): one voxel per clock, [`LATENCY`] register stages. It combines the bilinear
//! unit's accumulated RGBA with the shaded voxel, bit for bit as
//! `golden_model::common::compositor::composite`:
//!
//! - over (composite, first-opaque): `C = sat(C_front + mul(M - A_front, C_back))`
//!   per channel, where front/back are acc/new front to back and new/acc back
//!   to front;
//! - MIP / MinIP: the larger / smaller of the accumulated value and a valid voxel;
//! - X-ray: the accumulated sum plus the voxel's opacity.
//!
//! The mode class is built in (the logic of the other classes is
//! constant-folded away by synthesis); the order, and MIP or MinIP, come
//! from the `Order` register, bits 0 and 1. The over operator is
//! [`PipedOver`], one 16x16 multiplier per channel with a clock to itself:
//! stage 1 the operands' selection and the weight `M - A_front` (the scalar
//! modes' result), stage 2 the product, stage 3 its rounding half, stage 4
//! the rounding, sum and saturation.

use crate::common::mode_class::ModeClass;
use crate::common::piped_over::{self, PipedOver};
use rust_hdl::prelude::*;

/// Clocks from the operands to the composited value.
pub const LATENCY: usize = 1 + piped_over::LATENCY;

/// The compositing unit. Channels are `[r, g, b, a]`; the scalar modes use
/// channel r only and carry 0 in the others. Channel r is 32 bits wide for
/// the X-ray sum (`rgba_bits + log2(depth)` bits) and 16-bit MIP values.
#[derive(LogicBlock)]
pub struct Compositor {
    pub clock: Signal<In, Clock>,
    pub acc_r: Signal<In, Bits<32>>,
    pub acc_g: Signal<In, Bits<16>>,
    pub acc_b: Signal<In, Bits<16>>,
    pub acc_a: Signal<In, Bits<16>>,
    pub new_r: Signal<In, Bits<32>>,
    pub new_g: Signal<In, Bits<16>>,
    pub new_b: Signal<In, Bits<16>>,
    pub new_a: Signal<In, Bits<16>>,
    /// MIP/MinIP: the voxel takes part.
    pub new_valid: Signal<In, Bit>,
    pub out_r: Signal<Out, Bits<32>>,
    pub out_g: Signal<Out, Bits<16>>,
    pub out_b: Signal<Out, Bits<16>>,
    pub out_a: Signal<Out, Bits<16>>,
    /// The `Order` register: front to back (bit 0), MinIP (bit 1).
    pub order: Signal<In, Bits<64>>,
    over: Constant<Bit>,
    scalar: Constant<Bit>,
    ch_r: PipedOver,
    ch_g: PipedOver,
    ch_b: PipedOver,
    ch_a: PipedOver,
    /// Stage 1: the scalar modes' result, and its stages 2 and 3.
    scalar_q: DFF<Bits<32>>,
    scalar_qq: DFF<Bits<32>>,
    scalar_qqq: DFF<Bits<32>>,
    reg_r: DFF<Bits<32>>,
    reg_g: DFF<Bits<16>>,
    reg_b: DFF<Bits<16>>,
    reg_a: DFF<Bits<16>>,
}

impl Compositor {
    pub fn new(mode: ModeClass, rgba_bits: u32) -> Compositor {
        Compositor {
            clock: Default::default(),
            acc_r: Default::default(),
            acc_g: Default::default(),
            acc_b: Default::default(),
            acc_a: Default::default(),
            new_r: Default::default(),
            new_g: Default::default(),
            new_b: Default::default(),
            new_a: Default::default(),
            new_valid: Default::default(),
            out_r: Default::default(),
            out_g: Default::default(),
            out_b: Default::default(),
            out_a: Default::default(),
            order: Default::default(),
            over: Constant::new(mode == ModeClass::Over),
            scalar: Constant::new(mode == ModeClass::Scalar),
            ch_r: PipedOver::new(rgba_bits),
            ch_g: PipedOver::new(rgba_bits),
            ch_b: PipedOver::new(rgba_bits),
            ch_a: PipedOver::new(rgba_bits),
            scalar_q: Default::default(),
            scalar_qq: Default::default(),
            scalar_qqq: Default::default(),
            reg_r: Default::default(),
            reg_g: Default::default(),
            reg_b: Default::default(),
            reg_a: Default::default(),
        }
    }
}

impl Logic for Compositor {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, scalar_q, scalar_qq, scalar_qqq, reg_r, reg_g, reg_b, reg_a);
        self.ch_r.clock.next = self.clock.val();
        self.ch_g.clock.next = self.clock.val();
        self.ch_b.clock.next = self.clock.val();
        self.ch_a.clock.next = self.clock.val();
        // Front and back operands of the over operator.
        if self.order.val().get_bit(0) {
            self.ch_r.front.next = bit_cast::<16, 32>(self.acc_r.val());
            self.ch_g.front.next = self.acc_g.val();
            self.ch_b.front.next = self.acc_b.val();
            self.ch_a.front.next = self.acc_a.val();
            self.ch_r.back.next = bit_cast::<16, 32>(self.new_r.val());
            self.ch_g.back.next = self.new_g.val();
            self.ch_b.back.next = self.new_b.val();
            self.ch_a.back.next = self.new_a.val();
            self.ch_r.front_alpha.next = self.acc_a.val();
            self.ch_g.front_alpha.next = self.acc_a.val();
            self.ch_b.front_alpha.next = self.acc_a.val();
            self.ch_a.front_alpha.next = self.acc_a.val();
        } else {
            self.ch_r.front.next = bit_cast::<16, 32>(self.new_r.val());
            self.ch_g.front.next = self.new_g.val();
            self.ch_b.front.next = self.new_b.val();
            self.ch_a.front.next = self.new_a.val();
            self.ch_r.back.next = bit_cast::<16, 32>(self.acc_r.val());
            self.ch_g.back.next = self.acc_g.val();
            self.ch_b.back.next = self.acc_b.val();
            self.ch_a.back.next = self.acc_a.val();
            self.ch_r.front_alpha.next = self.new_a.val();
            self.ch_g.front_alpha.next = self.new_a.val();
            self.ch_b.front_alpha.next = self.new_a.val();
            self.ch_a.front_alpha.next = self.new_a.val();
        }
        // Stage 1, scalar modes (channel r only): MIP, MinIP, the X-ray sum.
        if self.scalar.val() {
            self.scalar_q.d.next = self.acc_r.val();
            if self.order.val().get_bit(1) {
                if self.new_valid.val() & (self.new_r.val() < self.acc_r.val()) {
                    self.scalar_q.d.next = self.new_r.val();
                }
            } else if self.new_valid.val() & (self.new_r.val() > self.acc_r.val()) {
                self.scalar_q.d.next = self.new_r.val();
            }
        } else {
            self.scalar_q.d.next = self.acc_r.val() + self.new_r.val();
        }
        // Stages 2 to 4.
        self.scalar_qq.d.next = self.scalar_q.q.val();
        self.scalar_qqq.d.next = self.scalar_qq.q.val();
        self.reg_r.d.next = self.scalar_qqq.q.val();
        self.reg_g.d.next = 0.into();
        self.reg_b.d.next = 0.into();
        self.reg_a.d.next = 0.into();
        if self.over.val() {
            self.reg_r.d.next = bit_cast::<32, 16>(self.ch_r.result.val());
            self.reg_g.d.next = self.ch_g.result.val();
            self.reg_b.d.next = self.ch_b.result.val();
            self.reg_a.d.next = self.ch_a.result.val();
        }
        self.out_r.next = self.reg_r.q.val();
        self.out_g.next = self.reg_g.q.val();
        self.out_b.next = self.reg_b.q.val();
        self.out_a.next = self.reg_a.q.val();
    }
}
