//! The over operator of front-to-back compositing (Cube-3's Eq. 1 in the
//! RPC nodes, the same operator as Cube-4L §3.5): `C = sat(C_front +
//! mul(M - A_front, C_back))` for one channel, combinational, bit for bit
//! as the golden model's `common::compositor::composite`, with `M =
//! 2^k - 1` (`k = rgba_bits`) and `mul = fixed::mul_unorm`.
//!
//! The RPC's accumulator runs this operator in a one-clock loop, so it is
//! written to put one multiplier and one carry chain between the
//! accumulator's register and itself (hand-rolled: the rounding must stay
//! the golden model's exactly):
//!
//! - Operands are unorm words (`≤ M`): they are masked to `k` bits, so the
//!   synthesis tool sizes the datapath for `k`, not for the 16-bit ports.
//! - `M - A = !A & M` for `A ≤ M`: no subtractor.
//! - `mul_unorm(a, b) = (t + (t >> k)) >> k` with `t = a·b + 2^(k-1)` is
//!   `⌊t·(2^k + 1) / 2^(2k)⌋` (adding `t`'s fraction below `2^k` to the
//!   integer `t + ⌊t / 2^k⌋` cannot carry past a multiple of `2^k`), and
//!   `b·(2^k + 1)` is `b` written twice, `{b, b}`.
//! - So `C_front + mul(a, b) = ({C_front, 0} + K + a·{b, b}) >> 2k` with
//!   `K = 2^(k-1)·(2^k + 1) < 2^(2k)`: one product and one addition, where
//!   `{C_front, 0} + K` is a concatenation. The saturation is the sum's
//!   bits above `3k`.
//! - For `k > 8`, `{b, b}` does not fit the 16-bit multiplier port: the
//!   product is `(a·b << k) + a·b` there, one adder more.

use rust_hdl::prelude::*;

/// `sat(front + mul(m - front_alpha, back))` for one channel, combinational.
#[derive(LogicBlock)]
pub struct Over {
    pub front: Signal<In, Bits<16>>,
    pub back: Signal<In, Bits<16>>,
    pub front_alpha: Signal<In, Bits<16>>,
    pub result: Signal<Out, Bits<16>>,
    m: Constant<Bits<16>>,
    /// `k`, `2k` and `3k`.
    k: Constant<Bits<8>>,
    k2: Constant<Bits<8>>,
    k3: Constant<Bits<8>>,
    /// `K = 2^(k-1)·(2^k + 1)`.
    half: Constant<Bits<64>>,
    /// `k > 8`: `{b, b}` is wider than the multiplier's port.
    wide: Constant<Bit>,
    enabled: Constant<Bit>,
    /// `M - A_front`, and the back value, masked to `k` bits.
    a: Signal<Local, Bits<16>>,
    b: Signal<Local, Bits<16>>,
    front_m: Signal<Local, Bits<16>>,
    /// `{b, b}`, and `a·{b, b}` (`k <= 8`) or `a·b` (`k > 8`).
    bb: Signal<Local, Bits<16>>,
    ab: Signal<Local, Bits<32>>,
    /// `a·b·(2^k + 1)`.
    product: Signal<Local, Bits<64>>,
    sum: Signal<Local, Bits<64>>,
}

impl Over {
    /// Without `enabled` the product is zero, for a scene whose mode has no
    /// over operator (the export then leaves the multiplier out).
    pub fn enabled(rgba_bits: u32, enabled: bool) -> Over {
        let k = rgba_bits as u64;
        Over {
            m: Constant::new(((1u64 << k) - 1).to_bits()),
            k: Constant::new(k.to_bits()),
            k2: Constant::new((2 * k).to_bits()),
            k3: Constant::new((3 * k).to_bits()),
            half: Constant::new(((1u64 << (k - 1)) * ((1u64 << k) + 1)).to_bits()),
            wide: Constant::new(k > 8),
            enabled: Constant::new(enabled),
            front: Default::default(),
            back: Default::default(),
            front_alpha: Default::default(),
            result: Default::default(),
            a: Default::default(),
            b: Default::default(),
            front_m: Default::default(),
            bb: Default::default(),
            ab: Default::default(),
            product: Default::default(),
            sum: Default::default(),
        }
    }
}

impl Logic for Over {
    #[hdl_gen]
    fn update(&mut self) {
        self.a.next = !self.front_alpha.val() & self.m.val();
        self.b.next = self.back.val() & self.m.val();
        self.front_m.next = self.front.val() & self.m.val();
        self.bb.next = (self.b.val() << self.k.val()) | self.b.val();
        if self.wide.val() {
            self.ab.next = self.a.val() * self.b.val();
            self.product.next = (bit_cast::<64, 32>(self.ab.val()) << self.k.val())
                + bit_cast::<64, 32>(self.ab.val());
        } else {
            self.ab.next = self.a.val() * self.bb.val();
            self.product.next = bit_cast::<64, 32>(self.ab.val());
        }
        if !self.enabled.val() {
            self.product.next = 0.into();
        }
        self.sum.next = (bit_cast::<64, 16>(self.front_m.val()) << self.k2.val())
            + self.half.val()
            + self.product.val();
        self.result.next = bit_cast::<16, 64>(self.sum.val() >> self.k2.val());
        if (self.sum.val() >> self.k3.val()).any() {
            self.result.next = self.m.val();
        }
    }
}

#[cfg(test)]
mod tests {
    use golden_model::fixed::{mul_unorm, sat_u};

    /// The widget's arithmetic, step for step, in `u64`.
    fn over(front: u64, alpha: u64, back: u64, k: u32) -> u64 {
        let m = (1u64 << k) - 1;
        let (a, b) = (!alpha & m, back & m);
        let product = a * b * ((1 << k) + 1);
        let sum = ((front & m) << (2 * k)) + (1u64 << (k - 1)) * ((1 << k) + 1) + product;
        if sum >> (3 * k) != 0 {
            m
        } else {
            sum >> (2 * k)
        }
    }

    fn golden(front: u32, alpha: u32, back: u32, k: u32) -> u64 {
        let m = (1u32 << k) - 1;
        sat_u(front as u64 + mul_unorm(m - alpha, back, k) as u64, m) as u64
    }

    #[test]
    fn the_fused_form_is_the_golden_over_for_every_8_bit_operand() {
        for alpha in 0..=255 {
            for back in 0..=255 {
                for front in [0, 1, 2, 127, 128, 200, 253, 254, 255] {
                    assert_eq!(
                        over(front as u64, alpha as u64, back as u64, 8),
                        golden(front, alpha, back, 8),
                        "front {front} alpha {alpha} back {back}"
                    );
                }
            }
        }
    }

    #[test]
    fn the_fused_form_is_the_golden_over_at_every_width() {
        let mut x = 0x9e37_79b9_7f4a_7c15u64;
        for k in 4..=15 {
            let m = (1u32 << k) - 1;
            for _ in 0..20_000 {
                x ^= x << 13;
                x ^= x >> 7;
                x ^= x << 17;
                let v = [x as u32 & m, (x >> 20) as u32 & m, (x >> 40) as u32 & m];
                let ends = [0, 1, m - 1, m];
                let pick = |i: usize| {
                    if (x >> (60 + i)) & 1 == 1 {
                        ends[(x >> (50 + 2 * i)) as usize & 3]
                    } else {
                        v[i]
                    }
                };
                let (front, alpha, back) = (pick(0), pick(1), pick(2));
                assert_eq!(
                    over(front as u64, alpha as u64, back as u64, k),
                    golden(front, alpha, back, k),
                    "k {k} front {front} alpha {alpha} back {back}"
                );
            }
        }
    }
}
