//! One stage of the Cube-4L sight-ray divider (§3.1): one quotient bit of
//! the two restoring divisions `num_x / den` and `num_y / den`, which share
//! their denominator, registered. Stage `k` of [`super::divider::Divider`]
//! decides bit `16 - k`: where the remainder is at least `den << (16 - k)`
//! (the shift within 64 bits, as the combinational divider it replaces
//! wrote it) the remainder drops by it and the bit is set. The remainders,
//! quotients, denominator and the voxel's flags move on together, a voxel a
//! clock.

use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct DivStage {
    pub clock: Signal<In, Clock>,
    pub rem_x: Signal<In, Bits<64>>,
    pub rem_y: Signal<In, Bits<64>>,
    pub den: Signal<In, Bits<64>>,
    pub q_x: Signal<In, Bits<32>>,
    pub q_y: Signal<In, Bits<32>>,
    /// The voxel's signs and range flags, carried along (`Divider`'s `F_*`).
    pub flags: Signal<In, Bits<7>>,
    /// The same, one clock later, with this stage's bit decided.
    pub rem_x_out: Signal<Out, Bits<64>>,
    pub rem_y_out: Signal<Out, Bits<64>>,
    pub den_out: Signal<Out, Bits<64>>,
    pub q_x_out: Signal<Out, Bits<32>>,
    pub q_y_out: Signal<Out, Bits<32>>,
    pub flags_out: Signal<Out, Bits<7>>,
    shift: Constant<Bits<8>>,
    q_bit: Constant<Bits<32>>,
    shifted: Signal<Local, Bits<64>>,
    rx: DFF<Bits<64>>,
    ry: DFF<Bits<64>>,
    den_q: DFF<Bits<64>>,
    qx: DFF<Bits<32>>,
    qy: DFF<Bits<32>>,
    f: DFF<Bits<7>>,
}

impl DivStage {
    /// The stage that decides quotient bit `bit` (0 to 16).
    pub fn new(bit: u32) -> DivStage {
        assert!(bit <= 16, "the sight-ray quotient has 17 bits");
        DivStage {
            clock: Default::default(),
            rem_x: Default::default(),
            rem_y: Default::default(),
            den: Default::default(),
            q_x: Default::default(),
            q_y: Default::default(),
            flags: Default::default(),
            rem_x_out: Default::default(),
            rem_y_out: Default::default(),
            den_out: Default::default(),
            q_x_out: Default::default(),
            q_y_out: Default::default(),
            flags_out: Default::default(),
            shift: Constant::new((bit as u64).to_bits()),
            q_bit: Constant::new((1u64 << bit).to_bits()),
            shifted: Default::default(),
            rx: Default::default(),
            ry: Default::default(),
            den_q: Default::default(),
            qx: Default::default(),
            qy: Default::default(),
            f: Default::default(),
        }
    }
}

impl Logic for DivStage {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, rx, ry, den_q, qx, qy, f);
        self.shifted.next = self.den.val() << self.shift.val();
        self.rx.d.next = self.rem_x.val();
        self.qx.d.next = self.q_x.val();
        if self.rem_x.val() >= self.shifted.val() {
            self.rx.d.next = self.rem_x.val() - self.shifted.val();
            self.qx.d.next = self.q_x.val() | self.q_bit.val();
        }
        self.ry.d.next = self.rem_y.val();
        self.qy.d.next = self.q_y.val();
        if self.rem_y.val() >= self.shifted.val() {
            self.ry.d.next = self.rem_y.val() - self.shifted.val();
            self.qy.d.next = self.q_y.val() | self.q_bit.val();
        }
        self.den_q.d.next = self.den.val();
        self.f.d.next = self.flags.val();
        self.rem_x_out.next = self.rx.q.val();
        self.rem_y_out.next = self.ry.q.val();
        self.den_out.next = self.den_q.q.val();
        self.q_x_out.next = self.qx.q.val();
        self.q_y_out.next = self.qy.q.val();
        self.flags_out.next = self.f.q.val();
    }
}
