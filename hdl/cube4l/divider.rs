//! The sight-ray divider of the Cube-4L CFB (§3.1): `q = floor(num / den)`
//! for the magnitudes of `S_x * 2^f + S_z / 2` and `S_z`, combinational
//! restoring division over 17 quotient bits. `overflow` flags a quotient of
//! 2^17 or more (far beyond the 45-degree limit of 2^f). Only perspective
//! views instantiate it.

use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct Divider {
    pub num: Signal<In, Bits<64>>,
    pub den: Signal<In, Bits<64>>,
    pub q: Signal<Out, Bits<32>>,
    pub overflow: Signal<Out, Bit>,
    rem: Signal<Local, Bits<64>>,
    quo: Signal<Local, Bits<32>>,
    enabled: Constant<Bit>,
}

impl Divider {
    /// Without `enabled` (parallel views) the outputs are zero, as in the
    /// emitted Verilog, which leaves the divider out (`export::prune`).
    pub fn new(enabled: bool) -> Divider {
        Divider {
            num: Default::default(),
            den: Default::default(),
            q: Default::default(),
            overflow: Default::default(),
            rem: Default::default(),
            quo: Default::default(),
            enabled: Constant::new(enabled),
        }
    }
}

impl Logic for Divider {
    #[hdl_gen]
    fn update(&mut self) {
        self.rem.next = self.num.val();
        self.quo.next = 0.into();
        // 17 quotient bits: 2^f <= 2^15 always fits (literals, not constants:
        // the Verilog generator copies the expressions as written).
        self.overflow.next = self.num.val() >= (self.den.val() << 17);
        for i in 0..17 {
            if self.rem.val() >= (self.den.val() << (16 - i)) {
                self.rem.next = self.rem.val() - (self.den.val() << (16 - i));
                self.quo.next = self.quo.val() | (bit_cast::<32, 1>(1.into()) << (16 - i));
            }
        }
        self.q.next = self.quo.val();
        if !self.enabled.val() {
            self.q.next = 0.into();
            self.overflow.next = false;
        }
    }
}
