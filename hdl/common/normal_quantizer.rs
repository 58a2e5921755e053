//! The gradient's quantized normal (Cube-4L §3.4; Cube-3's shading units),
//! bit for bit as `golden_model::common::gradient::quantize_normal`: all
//! three components shift right (rounding half up) until the largest fits
//! in `normal_bits - 1` magnitude bits (`hardware.normal_bits`, a build
//! parameter), then saturate to `±(2^(normal_bits - 1) - 1)`. [`LATENCY`]
//! register stages:
//!
//! 1. the shift, from the bit length of `m0 | m1 | m2` (the largest
//!    component's: no magnitude comparator on the path);
//! 2. each component plus the rounding half;
//! 3. the shift right and the saturation.
//!
//! The magnitude ports are [`MAG_BITS`] wide, the widest normal's; the
//! saturated magnitude is masked to the build's width, so synthesis keeps
//! only the bits the build has.

use golden_model::lut::MAX_NORMAL_BITS;
use rust_hdl::prelude::*;

/// Clocks from the gradient to its quantized normal.
pub const LATENCY: usize = 3;

/// Magnitude bits of the widest normal the golden models take.
pub const MAG_BITS: usize = MAX_NORMAL_BITS as usize - 1;

/// Gradient (sign and magnitude per component) in, quantized normal (sign
/// and a `normal_bits - 1`-bit magnitude per component) [`LATENCY`] clocks
/// later.
#[derive(LogicBlock)]
pub struct NormalQuantizer {
    pub clock: Signal<In, Clock>,
    pub neg: [Signal<In, Bit>; 3],
    pub mag: [Signal<In, Bits<32>>; 3],
    pub q_neg: [Signal<Out, Bit>; 3],
    pub q_mag: [Signal<Out, Bits<MAG_BITS>>; 3],
    /// `bit_len[i] = i + 1`.
    bit_len: [Constant<Bits<8>>; 32],
    m: Signal<Local, Bits<32>>,
    bl: Signal<Local, Bits<8>>,
    /// Stage 1: the shift and the components.
    s_q: DFF<Bits<8>>,
    neg_q: [DFF<Bit>; 3],
    mag_q: [DFF<Bits<32>>; 3],
    /// Stage 1: `m` with every bit below its leading one set, and the
    /// rounding halves from it (`2^(s-1)`, and `2^(s-1) - 1` for a negative
    /// component), so that stage 2 holds one adder and no shift.
    smear: Signal<Local, Bits<32>>,
    smear_q: DFF<Bits<32>>,
    half_q: DFF<Bits<32>>,
    half_m1_q: DFF<Bits<32>>,
    one: Constant<Bits<8>>,
    /// Stage 2: the rounded components, the shift.
    s_q2: DFF<Bits<8>>,
    neg_q2: [DFF<Bit>; 3],
    sum_q: [DFF<Bits<32>>; 3],
    /// Stage 2: the bits at and above `2^s` and above `2^(s + mag_bits) - 1`:
    /// a component is non-zero, or saturates, when it has one of them.
    nz_mask_q: DFF<Bits<32>>,
    sat_mask_q: DFF<Bits<32>>,
    /// Stage 3: the rounded components shifted, their low bits.
    q: [Signal<Local, Bits<MAG_BITS>>; 3],
    /// Stage 3: the quantized components.
    out_neg: [DFF<Bit>; 3],
    out_mag: [DFF<Bits<MAG_BITS>>; 3],
    /// The magnitude bits, and the largest magnitude `2^mag_bits - 1` (and
    /// as the magnitude's mask).
    mag_bits: Constant<Bits<8>>,
    limit: Constant<Bits<32>>,
    mask: Constant<Bits<MAG_BITS>>,
}

impl NormalQuantizer {
    /// The quantizer of `normal_bits`-bit normals (3 to
    /// [`MAX_NORMAL_BITS`]).
    pub fn new(normal_bits: u32) -> Self {
        assert!(
            scene::spec::NORMAL_BITS.contains(&normal_bits),
            "{normal_bits}-bit normals"
        );
        let mag_bits = normal_bits as u64 - 1;
        NormalQuantizer {
            clock: Default::default(),
            neg: Default::default(),
            mag: Default::default(),
            q_neg: Default::default(),
            q_mag: Default::default(),
            bit_len: std::array::from_fn(|i| Constant::new((i as u64 + 1).to_bits())),
            m: Default::default(),
            bl: Default::default(),
            s_q: Default::default(),
            neg_q: Default::default(),
            mag_q: Default::default(),
            smear: Default::default(),
            smear_q: Default::default(),
            half_q: Default::default(),
            half_m1_q: Default::default(),
            one: Constant::new(1u64.to_bits()),
            s_q2: Default::default(),
            neg_q2: Default::default(),
            sum_q: Default::default(),
            nz_mask_q: Default::default(),
            sat_mask_q: Default::default(),
            q: Default::default(),
            out_neg: Default::default(),
            out_mag: Default::default(),
            mag_bits: Constant::new(mag_bits.to_bits()),
            limit: Constant::new(((1u64 << mag_bits) - 1).to_bits()),
            mask: Constant::new(((1u64 << mag_bits) - 1).to_bits()),
        }
    }
}

impl Logic for NormalQuantizer {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, s_q, s_q2, nz_mask_q, sat_mask_q, smear_q, half_q, half_m1_q);
        // Stage 1: the leading one of the largest component, which is the
        // leading one of the three ORed, sets the shift.
        self.m.next = self.mag[0].val() | self.mag[1].val() | self.mag[2].val();
        self.bl.next = 0.into();
        for i in 0..32 {
            if self.m.val().get_bit(i) {
                self.bl.next = self.bit_len[i].val();
            }
        }
        self.s_q.d.next = 0.into();
        if self.bl.val() > self.mag_bits.val() {
            self.s_q.d.next = self.bl.val() - self.mag_bits.val();
        }
        // With the leading one at bit i, s = i + 1 - mag_bits when positive:
        // 2^(s-1) is the leading one shifted right by mag_bits, and
        // 2^(s-1) - 1 the bits below it, the smear shifted by mag_bits + 1.
        self.smear.next = self.m.val() | (self.m.val() >> 1);
        self.smear.next = self.smear.val() | (self.smear.val() >> 2);
        self.smear.next = self.smear.val() | (self.smear.val() >> 4);
        self.smear.next = self.smear.val() | (self.smear.val() >> 8);
        self.smear.next = self.smear.val() | (self.smear.val() >> 16);
        self.smear_q.d.next = self.smear.val();
        self.half_q.d.next =
            (self.smear.val() ^ (self.smear.val() >> self.one.val())) >> self.mag_bits.val();
        self.half_m1_q.d.next = self.smear.val() >> (self.mag_bits.val() + self.one.val());
        // Stage 2: add the half (a negative component's half rounds
        // towards zero in magnitude); the bits at and above 2^s (a
        // non-zero result) and above 2^(s + mag_bits) - 1 (a saturated one).
        self.s_q2.d.next = self.s_q.q.val();
        self.nz_mask_q.d.next = !(self.smear_q.q.val() >> self.mag_bits.val());
        self.sat_mask_q.d.next = !(self.smear_q.q.val() | self.limit.val());
        // (`bit_cast` takes no loop index in `hdl_gen`.)
        self.q[0].next = bit_cast::<MAG_BITS, 32>(self.sum_q[0].q.val() >> self.s_q2.q.val());
        self.q[1].next = bit_cast::<MAG_BITS, 32>(self.sum_q[1].q.val() >> self.s_q2.q.val());
        self.q[2].next = bit_cast::<MAG_BITS, 32>(self.sum_q[2].q.val() >> self.s_q2.q.val());
        for i in 0..3 {
            self.neg_q[i].clock.next = self.clock.val();
            self.mag_q[i].clock.next = self.clock.val();
            self.neg_q2[i].clock.next = self.clock.val();
            self.sum_q[i].clock.next = self.clock.val();
            self.out_neg[i].clock.next = self.clock.val();
            self.out_mag[i].clock.next = self.clock.val();
            self.neg_q[i].d.next = self.neg[i].val();
            self.mag_q[i].d.next = self.mag[i].val();
            self.neg_q2[i].d.next = self.neg_q[i].q.val();
            self.sum_q[i].d.next = self.mag_q[i].q.val() + self.half_q.q.val();
            if self.neg_q[i].q.val() {
                self.sum_q[i].d.next = self.mag_q[i].q.val() + self.half_m1_q.q.val();
            }
            // Stage 3: shift (`q`, above) and saturate to the limit; the mask (no
            // change to a saturated magnitude) tells synthesis which bits
            // the build has.
            self.out_mag[i].d.next = self.q[i].val() & self.mask.val();
            if (self.sum_q[i].q.val() & self.sat_mask_q.q.val()) != 0 {
                self.out_mag[i].d.next = self.mask.val();
            }
            self.out_neg[i].d.next =
                self.neg_q2[i].q.val() & ((self.sum_q[i].q.val() & self.nz_mask_q.q.val()) != 0);
            self.q_neg[i].next = self.out_neg[i].q.val();
            self.q_mag[i].next = self.out_mag[i].q.val();
        }
    }
}
