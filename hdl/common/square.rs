//! The squared gradient component for the gradient magnitude (Cube-4L
//! §3.4), from the 16x16 multipliers rust-hdl offers: a sub-block of
//! [`super::gradient_bin::GradientBin`].

use rust_hdl::prelude::*;

/// `m²` of a magnitude below `2^31`, from 16x16 multipliers. Without
/// `wide` the magnitude has 16 bits and the upper products read 0, for
/// synthesis to remove.
#[derive(LogicBlock)]
pub struct Square {
    pub m: Signal<In, Bits<32>>,
    pub y: Signal<Out, Bits<64>>,
    wide: Constant<Bit>,
    hi: Signal<Local, Bits<16>>,
    lo: Signal<Local, Bits<16>>,
}

impl Square {
    pub fn new(wide: bool) -> Square {
        Square {
            m: Default::default(),
            y: Default::default(),
            wide: Constant::new(wide),
            hi: Default::default(),
            lo: Default::default(),
        }
    }
}

impl Logic for Square {
    #[hdl_gen]
    fn update(&mut self) {
        self.lo.next = self.m.val().get_bits::<16>(0);
        self.hi.next = 0.into();
        if self.wide.val() {
            self.hi.next = self.m.val().get_bits::<16>(16);
        }
        self.y.next = (bit_cast::<64, 32>(self.hi.val() * self.hi.val()) << 32)
            + (bit_cast::<64, 32>(self.hi.val() * self.lo.val()) << 17)
            + bit_cast::<64, 32>(self.lo.val() * self.lo.val());
    }
}
