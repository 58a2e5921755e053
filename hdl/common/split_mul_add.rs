//! `y = sat(mul(a, b) + c)` for unorm words over two registers, bit for
//! bit as `golden_model::fixed::mul_unorm` followed by an add saturated to
//! `2^bits - 1`: the shader's lit colour, `sat(mul(colour, diffuse) +
//! specular)` (Cube-4L §3.4's shading; Cube-3's shading units).
//!
//! The add goes into the multiplier's rounding clock rather than a clock
//! of its own after the rounding. With `t = a·b + 2^(bits-1)`,
//! `mul(a, b) = (t + (t >> bits)) >> bits`, and since `c·2^bits` has no
//! bits below `bits`, `mul(a, b) + c = (t_c + (t >> bits)) >> bits` where
//! `t_c = a·b + (c << bits | 2^(bits-1))` (an OR, not an add: `c` lies
//! above the rounding half). So:
//!
//! 1. the 16x16 product in a register ([`DspProduct`], the multiplier's
//!    own on an ECP5), `c` beside it;
//! 2. `t` and `t_c`, one carry chain each, side by side;
//! 3. `u = t_c + (t >> bits)` leaves combinationally with `y = u >> bits`,
//!    saturated where `u`'s bits from `2·bits` up are not all zero (a
//!    reduction, not a compare): one carry chain from the registers to the
//!    caller's.

use super::dsp_product::DspProduct;
use rust_hdl::prelude::*;

/// Clocks from `a`, `b` and `c` to `y`.
pub const LATENCY: usize = 2;

#[derive(LogicBlock)]
pub struct SplitMulAddUnorm {
    pub clock: Signal<In, Clock>,
    pub a: Signal<In, Bits<16>>,
    pub b: Signal<In, Bits<16>>,
    /// The addend, at most `2^bits - 1`.
    pub c: Signal<In, Bits<16>>,
    /// `sat(mul(a, b) + c)` of [`LATENCY`] clocks before.
    pub y: Signal<Out, Bits<16>>,
    half: Constant<Bits<48>>,
    shift: Constant<Bits<8>>,
    shift2: Constant<Bits<8>>,
    /// `2^bits - 1`, the saturation.
    max: Constant<Bits<16>>,
    p: DspProduct,
    c_q: DFF<Bits<16>>,
    t: DFF<Bits<48>>,
    t_c: DFF<Bits<48>>,
    u: Signal<Local, Bits<48>>,
}

impl SplitMulAddUnorm {
    /// Without `enabled` the product is zero and `y = c`, as in emitted
    /// Verilog that leaves the multiplier out (`export::prune`).
    pub fn enabled(bits: u32, enabled: bool) -> SplitMulAddUnorm {
        assert!((1..=16).contains(&bits), "{bits}-bit unorm words");
        SplitMulAddUnorm {
            clock: Default::default(),
            a: Default::default(),
            b: Default::default(),
            c: Default::default(),
            y: Default::default(),
            half: Constant::new((1u64 << (bits - 1)).to_bits()),
            shift: Constant::new((bits as u64).to_bits()),
            shift2: Constant::new((2 * bits as u64).to_bits()),
            max: Constant::new(((1u64 << bits) - 1).to_bits()),
            p: DspProduct::new(enabled),
            c_q: Default::default(),
            t: Default::default(),
            t_c: Default::default(),
            u: Default::default(),
        }
    }
}

impl Logic for SplitMulAddUnorm {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, c_q, t, t_c);
        self.p.clock.next = self.clock.val();
        self.p.a.next = self.a.val();
        self.p.b.next = self.b.val();
        self.c_q.d.next = self.c.val();
        self.t.d.next = bit_cast::<48, 32>(self.p.p.val()) + self.half.val();
        self.t_c.d.next = bit_cast::<48, 32>(self.p.p.val())
            + ((bit_cast::<48, 16>(self.c_q.q.val()) << self.shift.val()) | self.half.val());
        self.u.next = self.t_c.q.val() + (self.t.q.val() >> self.shift.val());
        self.y.next = bit_cast::<16, 48>(self.u.val() >> self.shift.val());
        if (self.u.val() >> self.shift2.val()) != 0 {
            self.y.next = self.max.val();
        }
    }
}
