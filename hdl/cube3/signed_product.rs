//! A signed product of Cube-3's ABC gradient estimators (§4): `d·g` for a
//! 32-bit two's-complement difference `g` and a factor `d` in sign and
//! magnitude (an increment, for the 6's and 26's shear; a basis
//! coefficient, for the 10), as a 64-bit two's-complement word. One 16x16
//! multiplier takes the low half of `|g|`; a second, the high half, only
//! where samples are wider than 16 bits (`wide`), so that a difference of
//! up to 25 significant bits fits.

use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct SignedProduct {
    pub g: Signal<In, Bits<32>>,
    pub d_neg: Signal<In, Bit>,
    pub d_mag: Signal<In, Bits<16>>,
    pub y: Signal<Out, Bits<64>>,
    wide: Constant<Bit>,
    mag: Signal<Local, Bits<32>>,
    prod: Signal<Local, Bits<64>>,
}

impl SignedProduct {
    /// `wide`: differences beyond 16 bits (samples of more than 16 bits).
    pub fn new(wide: bool) -> SignedProduct {
        SignedProduct {
            g: Default::default(),
            d_neg: Default::default(),
            d_mag: Default::default(),
            y: Default::default(),
            wide: Constant::new(wide),
            mag: Default::default(),
            prod: Default::default(),
        }
    }
}

impl Logic for SignedProduct {
    #[hdl_gen]
    fn update(&mut self) {
        self.mag.next = self.g.val();
        if self.g.val().get_bit(31) {
            self.mag.next = !self.g.val() + 1;
        }
        self.prod.next = bit_cast::<64, 32>(self.mag.val().get_bits::<16>(0) * self.d_mag.val());
        if self.wide.val() {
            self.prod.next =
                (bit_cast::<64, 32>(self.mag.val().get_bits::<16>(16) * self.d_mag.val()) << 16)
                    + bit_cast::<64, 32>(self.mag.val().get_bits::<16>(0) * self.d_mag.val());
        }
        self.y.next = self.prod.val();
        if self.g.val().get_bit(31) ^ self.d_neg.val() {
            self.y.next = !self.prod.val() + 1;
        }
    }
}
