//! One node of Cube-3's Ray Projection Cone (§2, Eq. 1; §5, Fig. 12):
//! `op(front, back)` and its pipeline register, bit for bit as
//! `golden_model::cube3::rpc::node`.
//!
//! - Composite and first-opaque: [`Over`] on each channel with the front
//!   alpha.
//! - X-ray: `front + back` in channel r (32 bits: `rgba_bits + log2 K`).
//! - MIP / MinIP: the larger / smaller of the valid children; either child
//!   may be empty (invalid), and the node is empty only when both are.
//!
//! The node holds only the scene's mode's operator: the comparators and
//! adder of the other modes are constant-folded, and the over multipliers
//! are built disabled outside composite and first-opaque, for the export to
//! leave out.

use crate::common::over::Over;
use rust_hdl::prelude::*;
use scene::Mode;

#[derive(LogicBlock)]
pub struct RpcNode {
    pub clock: Signal<In, Clock>,
    pub front_r: Signal<In, Bits<32>>,
    pub front_g: Signal<In, Bits<16>>,
    pub front_b: Signal<In, Bits<16>>,
    pub front_a: Signal<In, Bits<16>>,
    pub front_valid: Signal<In, Bit>,
    pub back_r: Signal<In, Bits<32>>,
    pub back_g: Signal<In, Bits<16>>,
    pub back_b: Signal<In, Bits<16>>,
    pub back_a: Signal<In, Bits<16>>,
    pub back_valid: Signal<In, Bit>,
    /// `op(front, back)` of the previous clock.
    pub out_r: Signal<Out, Bits<32>>,
    pub out_g: Signal<Out, Bits<16>>,
    pub out_b: Signal<Out, Bits<16>>,
    pub out_a: Signal<Out, Bits<16>>,
    pub out_valid: Signal<Out, Bit>,
    over: Constant<Bit>,
    mip: Constant<Bit>,
    minip: Constant<Bit>,
    /// MIP / MinIP: the node takes the back child.
    take_back: Signal<Local, Bit>,
    pub(crate) ch_r: Over,
    pub(crate) ch_g: Over,
    pub(crate) ch_b: Over,
    pub(crate) ch_a: Over,
    reg_r: DFF<Bits<32>>,
    reg_g: DFF<Bits<16>>,
    reg_b: DFF<Bits<16>>,
    reg_a: DFF<Bits<16>>,
    reg_valid: DFF<Bit>,
}

impl RpcNode {
    pub fn new(mode: Mode, rgba_bits: u32) -> RpcNode {
        let over = matches!(mode, Mode::Composite | Mode::FirstOpaque);
        RpcNode {
            clock: Default::default(),
            front_r: Default::default(),
            front_g: Default::default(),
            front_b: Default::default(),
            front_a: Default::default(),
            front_valid: Default::default(),
            back_r: Default::default(),
            back_g: Default::default(),
            back_b: Default::default(),
            back_a: Default::default(),
            back_valid: Default::default(),
            out_r: Default::default(),
            out_g: Default::default(),
            out_b: Default::default(),
            out_a: Default::default(),
            out_valid: Default::default(),
            over: Constant::new(over),
            mip: Constant::new(mode == Mode::Mip),
            minip: Constant::new(mode == Mode::Minip),
            take_back: Default::default(),
            ch_r: Over::enabled(rgba_bits, over),
            ch_g: Over::enabled(rgba_bits, over),
            ch_b: Over::enabled(rgba_bits, over),
            ch_a: Over::enabled(rgba_bits, over),
            reg_r: Default::default(),
            reg_g: Default::default(),
            reg_b: Default::default(),
            reg_a: Default::default(),
            reg_valid: Default::default(),
        }
    }
}

impl Logic for RpcNode {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, reg_r, reg_g, reg_b, reg_a, reg_valid);
        self.ch_r.front.next = bit_cast::<16, 32>(self.front_r.val());
        self.ch_r.back.next = bit_cast::<16, 32>(self.back_r.val());
        self.ch_g.front.next = self.front_g.val();
        self.ch_g.back.next = self.back_g.val();
        self.ch_b.front.next = self.front_b.val();
        self.ch_b.back.next = self.back_b.val();
        self.ch_a.front.next = self.front_a.val();
        self.ch_a.back.next = self.back_a.val();
        self.ch_r.front_alpha.next = self.front_a.val();
        self.ch_g.front_alpha.next = self.front_a.val();
        self.ch_b.front_alpha.next = self.front_a.val();
        self.ch_a.front_alpha.next = self.front_a.val();
        // MIP / MinIP: the back child wins when the front is empty, or when
        // both are valid and the back wins the comparison.
        self.take_back.next = !self.front_valid.val();
        if self.mip.val() & self.back_valid.val() & (self.back_r.val() > self.front_r.val()) {
            self.take_back.next = true;
        }
        if self.minip.val() & self.back_valid.val() & (self.back_r.val() < self.front_r.val()) {
            self.take_back.next = true;
        }
        self.reg_g.d.next = 0.into();
        self.reg_b.d.next = 0.into();
        self.reg_a.d.next = 0.into();
        self.reg_valid.d.next = true;
        if self.over.val() {
            self.reg_r.d.next = bit_cast::<32, 16>(self.ch_r.result.val());
            self.reg_g.d.next = self.ch_g.result.val();
            self.reg_b.d.next = self.ch_b.result.val();
            self.reg_a.d.next = self.ch_a.result.val();
        } else if self.mip.val() | self.minip.val() {
            self.reg_r.d.next = self.front_r.val();
            self.reg_valid.d.next = self.front_valid.val() | self.back_valid.val();
            if self.take_back.val() {
                self.reg_r.d.next = self.back_r.val();
            }
        } else {
            self.reg_r.d.next = self.front_r.val() + self.back_r.val();
        }
        self.out_r.next = self.reg_r.q.val();
        self.out_g.next = self.reg_g.q.val();
        self.out_b.next = self.reg_b.q.val();
        self.out_a.next = self.reg_a.q.val();
        self.out_valid.next = self.reg_valid.q.val();
    }
}
