//! The integer square root of the gradient magnitude (Cube-4L §3.4, the
//! gradient-opacity index; Cube-3's shading reuses it): a sub-block of
//! [`super::shader::Shader`].

use rust_hdl::prelude::*;

/// `floor(sqrt(n))` of an `n` below `2^62`, digit by digit (shifts,
/// compares and subtracts; no multiplier), combinational. The leading
/// digits of a smaller `n` are no-ops, which synthesis folds away.
#[derive(LogicBlock)]
pub struct IntSqrt {
    pub n: Signal<In, Bits<64>>,
    pub root: Signal<Out, Bits<32>>,
    op: Signal<Local, Bits<64>>,
    res: Signal<Local, Bits<64>>,
    trial: Signal<Local, Bits<64>>,
    enabled: Constant<Bit>,
}

impl IntSqrt {
    /// Without `enabled` (no gradient opacity) the root is zero, as in the
    /// emitted Verilog, which leaves the unit out (`export::prune`).
    pub fn new(enabled: bool) -> IntSqrt {
        IntSqrt {
            n: Default::default(),
            root: Default::default(),
            op: Default::default(),
            res: Default::default(),
            trial: Default::default(),
            enabled: Constant::new(enabled),
        }
    }
}

impl Logic for IntSqrt {
    #[hdl_gen]
    fn update(&mut self) {
        self.op.next = self.n.val();
        self.res.next = 0.into();
        for i in 0..31 {
            self.trial.next = self.res.val() + (bit_cast::<64, 1>(1.into()) << (60 - 2 * i));
            if self.op.val() >= self.trial.val() {
                self.op.next = self.op.val() - self.trial.val();
                self.res.next =
                    (self.res.val() >> 1) + (bit_cast::<64, 1>(1.into()) << (60 - 2 * i));
            } else {
                self.res.next = self.res.val() >> 1;
            }
        }
        self.root.next = bit_cast::<32, 64>(self.res.val());
        if !self.enabled.val() {
            self.root.next = 0.into();
        }
    }
}
