//! The lighting of a quantized normal (Cube-4L §3.4's reflectance; Cube-3's
//! shading units), bit for bit as `golden_model::lut::Lighting`: the
//! cosines between `-q` and the light and half vectors from two dot
//! products and a reciprocal norm, each indexing a host-loaded table.
//! [`LATENCY`] register stages, none with more than one multiplier or two
//! carry chains in series (stage 5 three with normals wider than 5 bits):
//!
//! 1. the products of `q`'s magnitudes and the registers' (held in
//!    registers of their own: they change only with a host write; the
//!    products' registers the multipliers' own, [`DspProduct`]), their
//!    signs, and `|q|²` from three square tables (LUT logic, no
//!    multiplier);
//! 2. the products in two's complement, the first two summed and the third
//!    registered beside them, and `rnorm(|q|²)` from a constant ROM; a
//!    negative product `-p = !p + 1` goes into the sums as `!p`, and the
//!    `+ 1`s, the count of the negative ones, into the third's register
//!    (the same sums mod 2^32, one carry chain before each register where a
//!    negation was a chain of its own);
//! 3. the dot products `q · light`, `q · half` (the last sum), each made
//!    positive and saturated to `normal_bits + 11` bits, its tests
//!    reductions of the sum's bits, not compares after it;
//! 4. `t = dot · rnorm`, one 16x16 multiplier each for the dot product's
//!    low 16 bits, and one for its bits above them (not built up to 5
//!    bits), each product in its multiplier's register;
//! 5. the cosine index `min(1023, (t · 1023 + 2^25) >> 26)`, `t` the sum
//!    of the two products (one carry chain more above 5 bits): the sum's
//!    bits up to 2^36, and beside it the saturation as a compare of `t`
//!    with a constant ([`saturates_from`]), not of the shifted sum;
//! 6. the diffuse and specular tables' registered reads;
//! 7. their words registered (the specular term 0 where the light's dot
//!    product is not positive).
//!
//! The normal's width (`hardware.normal_bits`, 3 to 8) is a build
//! parameter: the square tables hold `2^(normal_bits - 1)` words and the
//! reciprocal-norm ROM [`rnorm_words`] (1 024 at 5 bits, one block RAM; 4
//! 096 at 6), behind ports as wide as the widest normal's; the saturation
//! and the masks tell synthesis which bits a build has.
//!
//! The light and half vectors are registers, the tables depend only on the
//! lighting coefficients: a new view or light is six register words.

use super::depth_rom::DepthRom;
use super::dsp_product::DspProduct;
use super::normal_quantizer::MAG_BITS;
use super::regs::{Regs, ADDRESS_BITS};
use super::table::Table;
use golden_model::host::{Reg, Table as HostTable};
use golden_model::lut::{rnorm, rnorm_words, COS_BITS, DIR_FRAC, MAX_NORMAL_BITS, RNORM_FRAC};
use rust_hdl::prelude::*;

/// Clocks from the quantized normal to the terms.
pub const LATENCY: usize = 7;

/// Stage 5's `(t << 10) - t` is `t · (2^COS_BITS - 1)`.
const _: () = assert!(COS_BITS == 10);

/// The least `t` whose cosine index `(t · last + half) >> shift` exceeds
/// `last`: `ceil(((last + 1) << shift - half) / last)`.
pub fn saturates_from() -> u64 {
    let last = (1u64 << COS_BITS) - 1;
    let shift = DIR_FRAC + RNORM_FRAC;
    (((last + 1) << shift) - (1u64 << (shift - 1))).div_ceil(last)
}

/// `|q|²` bits of the widest normal: `3 · 127² < 2^16`.
const N2_BITS: usize = 16;
const _: () = assert!(rnorm_words(MAX_NORMAL_BITS) as usize <= 1 << N2_BITS);

/// The lighting unit of one shader, with `rgba_bits` table words and
/// `normal_bits`-bit normals.
#[derive(LogicBlock)]
pub struct Lighting {
    pub clock: Signal<In, Clock>,
    pub host_write: Signal<In, Bit>,
    pub host_address: Signal<In, Bits<ADDRESS_BITS>>,
    pub host_data: Signal<In, Bits<64>>,
    /// The quantized normal, sign and magnitude per component.
    pub q_neg: [Signal<In, Bit>; 3],
    pub q_mag: [Signal<In, Bits<MAG_BITS>>; 3],
    /// `[diffuse, specular]`, [`LATENCY`] clocks later.
    pub diffuse: Signal<Out, Bits<16>>,
    pub specular: Signal<Out, Bits<16>>,
    /// The light (`q[0]`) and half (`q[1]`) vectors.
    regs: Regs<2>,
    rnorm: DepthRom<Bits<16>, N2_BITS>,
    /// `m²` of each magnitude.
    square: [DepthRom<Bits<16>, MAG_BITS>; 3],
    diffuse_table: Table<16, COS_BITS_U>,
    specular_table: Table<16, COS_BITS_U>,
    /// The light's and half vector's magnitudes, registered.
    m_l: [Signal<Local, Bits<16>>; 3],
    m_h: [Signal<Local, Bits<16>>; 3],
    ml_q: [DFF<Bits<16>>; 3],
    mh_q: [DFF<Bits<16>>; 3],
    /// Stage 1: the products' magnitudes and signs.
    qm: [Signal<Local, Bits<16>>; 3],
    p_l: [DspProduct; 3],
    p_h: [DspProduct; 3],
    sl_q: [DFF<Bit>; 3],
    sh_q: [DFF<Bit>; 3],
    /// Stage 2: the products, a negative one complemented, and the count
    /// of the complemented ones (the `+ 1`s of their negations).
    t_pl: [Signal<Local, Bits<32>>; 3],
    t_ph: [Signal<Local, Bits<32>>; 3],
    c_l: Signal<Local, Bits<32>>,
    c_h: Signal<Local, Bits<32>>,
    n2: Signal<Local, Bits<16>>,
    n2_q: DFF<Bits<16>>,
    /// Stage 2: the first two products' sum, and the third.
    pair_l: DFF<Bits<32>>,
    pair_h: DFF<Bits<32>>,
    third_l: DFF<Bits<32>>,
    third_h: DFF<Bits<32>>,
    rn: DFF<Bits<16>>,
    /// Stage 3: the dot products.
    dot_l: Signal<Local, Bits<32>>,
    dot_h: Signal<Local, Bits<32>>,
    /// Stage 3: the saturated dot products, the saturation `2^(normal_bits
    /// + DIR_FRAC) - 1` (also their mask).
    d_l: DFF<Bits<32>>,
    d_h: DFF<Bits<32>>,
    rn_3: DFF<Bits<16>>,
    lit_3: DFF<Bit>,
    saturation: Constant<Bits<32>>,
    /// The dot products can exceed 16 bits (normals wider than 5 bits):
    /// without it the upper products and their sum are not built (yosys
    /// would find the saturated dot product's upper bits zero only after
    /// it had mapped their products to multipliers).
    wide_dot: Constant<Bit>,
    /// Stage 4: the products of the low 16 bits and of the bits above.
    t_l: DspProduct,
    t_h: DspProduct,
    u_l: DspProduct,
    u_h: DspProduct,
    lit_4: DFF<Bit>,
    /// Stage 5.
    tt_l: Signal<Local, Bits<64>>,
    tt_h: Signal<Local, Bits<64>>,
    i_l: Signal<Local, Bits<COS_BITS_U>>,
    i_h: Signal<Local, Bits<COS_BITS_U>>,
    idx_l: DFF<Bits<COS_BITS_U>>,
    idx_h: DFF<Bits<COS_BITS_U>>,
    lit_5: DFF<Bit>,
    /// Stages 6 and 7.
    lit_6: DFF<Bit>,
    diffuse_q: DFF<Bits<16>>,
    specular_q: DFF<Bits<16>>,
    half_ulp: Constant<Bits<64>>,
    shift: Constant<Bits<8>>,
    last: Constant<Bits<COS_BITS_U>>,
    /// [`saturates_from`].
    sat_t: Constant<Bits<64>>,
}

/// [`COS_BITS`] as a const generic.
const COS_BITS_U: usize = COS_BITS as usize;

impl Lighting {
    pub fn new(rgba_bits: u32, normal_bits: u32) -> Lighting {
        assert!(
            scene::spec::NORMAL_BITS.contains(&normal_bits),
            "{normal_bits}-bit normals"
        );
        let word = [(0, rgba_bits as usize)];
        let words = 1 << COS_BITS;
        Lighting {
            clock: Default::default(),
            host_write: Default::default(),
            host_address: Default::default(),
            host_data: Default::default(),
            q_neg: Default::default(),
            q_mag: Default::default(),
            diffuse: Default::default(),
            specular: Default::default(),
            regs: Regs::new([Reg::Light.address(), Reg::Half.address()]),
            rnorm: DepthRom::new(
                (0..rnorm_words(normal_bits))
                    .map(|n2| (rnorm(n2) as u64).to_bits())
                    .collect(),
            ),
            square: std::array::from_fn(|_| {
                DepthRom::new(
                    (0..1u64 << (normal_bits - 1))
                        .map(|m| (m * m).to_bits())
                        .collect(),
                )
            }),
            diffuse_table: Table::new(HostTable::Diffuse.base(), words, &word),
            specular_table: Table::new(HostTable::Specular.base(), words, &word),
            m_l: Default::default(),
            m_h: Default::default(),
            ml_q: Default::default(),
            mh_q: Default::default(),
            sl_q: Default::default(),
            sh_q: Default::default(),
            t_pl: Default::default(),
            t_ph: Default::default(),
            c_l: Default::default(),
            c_h: Default::default(),
            qm: Default::default(),
            p_l: Default::default(),
            p_h: Default::default(),
            n2: Default::default(),
            n2_q: Default::default(),
            pair_l: Default::default(),
            pair_h: Default::default(),
            third_l: Default::default(),
            third_h: Default::default(),
            dot_l: Default::default(),
            dot_h: Default::default(),
            rn: Default::default(),
            d_l: Default::default(),
            d_h: Default::default(),
            rn_3: Default::default(),
            lit_3: Default::default(),
            saturation: Constant::new(((1u64 << (normal_bits + DIR_FRAC)) - 1).to_bits()),
            wide_dot: Constant::new(normal_bits + DIR_FRAC > 16),
            t_l: Default::default(),
            t_h: Default::default(),
            u_l: DspProduct::new(normal_bits + DIR_FRAC > 16),
            u_h: DspProduct::new(normal_bits + DIR_FRAC > 16),
            lit_4: Default::default(),
            tt_l: Default::default(),
            tt_h: Default::default(),
            i_l: Default::default(),
            i_h: Default::default(),
            idx_l: Default::default(),
            idx_h: Default::default(),
            lit_5: Default::default(),
            lit_6: Default::default(),
            diffuse_q: Default::default(),
            specular_q: Default::default(),
            half_ulp: Constant::new((1u64 << (DIR_FRAC + RNORM_FRAC - 1)).to_bits()),
            shift: Constant::new(((DIR_FRAC + RNORM_FRAC) as u64).to_bits()),
            last: Constant::new(((1u64 << COS_BITS) - 1).to_bits()),
            sat_t: Constant::new(saturates_from().to_bits()),
        }
    }

    /// Bits of the tables.
    pub fn memory_bits(&self) -> usize {
        self.diffuse_table.memory_bits() + self.specular_table.memory_bits()
    }

    /// Start with the tables' contents (simulation).
    pub fn preload(&mut self, diffuse: &[u32], specular: &[u32]) {
        self.diffuse_table
            .preload(diffuse.iter().map(|&d| d as u64));
        self.specular_table
            .preload(specular.iter().map(|&s| s as u64));
    }
}

impl Logic for Lighting {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, n2_q, pair_l, pair_h, third_l, third_h, rn, d_l, d_h, rn_3, lit_3, lit_4,
            idx_l, idx_h, lit_5, lit_6, diffuse_q, specular_q
        );
        self.regs.clock.next = self.clock.val();
        self.regs.host_write.next = self.host_write.val();
        self.regs.host_address.next = self.host_address.val();
        self.regs.host_data.next = self.host_data.val();
        self.diffuse_table.clock.next = self.clock.val();
        self.diffuse_table.host_write.next = self.host_write.val();
        self.diffuse_table.host_address.next = self.host_address.val();
        self.diffuse_table.host_data.next = self.host_data.val();
        self.specular_table.clock.next = self.clock.val();
        self.specular_table.host_write.next = self.host_write.val();
        self.specular_table.host_address.next = self.host_address.val();
        self.specular_table.host_data.next = self.host_data.val();
        // Unrolled: hdl_gen takes no loop index inside a cast. Assigned
        // before they are read, so the block has no combinational loop.
        self.qm[0].next = bit_cast::<16, MAG_BITS>(self.q_mag[0].val());
        self.qm[1].next = bit_cast::<16, MAG_BITS>(self.q_mag[1].val());
        self.qm[2].next = bit_cast::<16, MAG_BITS>(self.q_mag[2].val());
        self.m_l[0].next = self.regs.q[0].val().get_bits::<16>(0);
        if self.regs.q[0].val().get_bit(15) {
            self.m_l[0].next = 0 - self.regs.q[0].val().get_bits::<16>(0);
        }
        self.m_l[1].next = self.regs.q[0].val().get_bits::<16>(16);
        if self.regs.q[0].val().get_bit(31) {
            self.m_l[1].next = 0 - self.regs.q[0].val().get_bits::<16>(16);
        }
        self.m_l[2].next = self.regs.q[0].val().get_bits::<16>(32);
        if self.regs.q[0].val().get_bit(47) {
            self.m_l[2].next = 0 - self.regs.q[0].val().get_bits::<16>(32);
        }
        self.m_h[0].next = self.regs.q[1].val().get_bits::<16>(0);
        if self.regs.q[1].val().get_bit(15) {
            self.m_h[0].next = 0 - self.regs.q[1].val().get_bits::<16>(0);
        }
        self.m_h[1].next = self.regs.q[1].val().get_bits::<16>(16);
        if self.regs.q[1].val().get_bit(31) {
            self.m_h[1].next = 0 - self.regs.q[1].val().get_bits::<16>(16);
        }
        self.m_h[2].next = self.regs.q[1].val().get_bits::<16>(32);
        if self.regs.q[1].val().get_bit(47) {
            self.m_h[2].next = 0 - self.regs.q[1].val().get_bits::<16>(32);
        }
        // The light's and half vector's magnitudes, registered: they change
        // only with a host write, and the multipliers then take them from a
        // register rather than through the negation.
        for i in 0..3 {
            self.ml_q[i].clock.next = self.clock.val();
            self.mh_q[i].clock.next = self.clock.val();
            self.sl_q[i].clock.next = self.clock.val();
            self.sh_q[i].clock.next = self.clock.val();
            self.p_l[i].clock.next = self.clock.val();
            self.p_h[i].clock.next = self.clock.val();
            self.p_l[i].a.next = self.qm[i].val();
            self.p_h[i].a.next = self.qm[i].val();
            self.square[i].address.next = self.q_mag[i].val();
            self.ml_q[i].d.next = self.m_l[i].val();
            self.mh_q[i].d.next = self.m_h[i].val();
            self.p_l[i].b.next = self.ml_q[i].q.val();
            self.p_h[i].b.next = self.mh_q[i].q.val();
        }
        // Stage 1: the products' magnitudes and signs, and |q|².
        self.sl_q[0].d.next = self.q_neg[0].val() ^ self.regs.q[0].val().get_bit(15);
        self.sl_q[1].d.next = self.q_neg[1].val() ^ self.regs.q[0].val().get_bit(31);
        self.sl_q[2].d.next = self.q_neg[2].val() ^ self.regs.q[0].val().get_bit(47);
        self.sh_q[0].d.next = self.q_neg[0].val() ^ self.regs.q[1].val().get_bit(15);
        self.sh_q[1].d.next = self.q_neg[1].val() ^ self.regs.q[1].val().get_bit(31);
        self.sh_q[2].d.next = self.q_neg[2].val() ^ self.regs.q[1].val().get_bit(47);
        self.n2.next =
            self.square[0].data.val() + self.square[1].data.val() + self.square[2].data.val();
        self.n2_q.d.next = self.n2.val();
        // Stage 2: the products in two's complement, the first two summed,
        // and 1 / |q|.
        // `-p = !p + 1`: a negative product goes into the sums as `!p`,
        // and the signs' count into the third product's register.
        for i in 0..3 {
            self.t_pl[i].next = self.p_l[i].p.val();
            if self.sl_q[i].q.val() {
                self.t_pl[i].next = !self.p_l[i].p.val();
            }
            self.t_ph[i].next = self.p_h[i].p.val();
            if self.sh_q[i].q.val() {
                self.t_ph[i].next = !self.p_h[i].p.val();
            }
        }
        self.c_l.next = bit_cast::<32, 1>(self.sl_q[0].q.val().into())
            + bit_cast::<32, 1>(self.sl_q[1].q.val().into())
            + bit_cast::<32, 1>(self.sl_q[2].q.val().into());
        self.c_h.next = bit_cast::<32, 1>(self.sh_q[0].q.val().into())
            + bit_cast::<32, 1>(self.sh_q[1].q.val().into())
            + bit_cast::<32, 1>(self.sh_q[2].q.val().into());
        self.pair_l.d.next = self.t_pl[0].val() + self.t_pl[1].val();
        self.pair_h.d.next = self.t_ph[0].val() + self.t_ph[1].val();
        self.third_l.d.next = self.t_pl[2].val() + self.c_l.val();
        self.third_h.d.next = self.t_ph[2].val() + self.c_h.val();
        self.rnorm.address.next = self.n2_q.q.val();
        self.rn.d.next = self.rnorm.data.val();
        // Stage 3: the dot products, positive ones saturated (and masked:
        // no change to a saturated value) to normal_bits + DIR_FRAC bits. A
        // positive sum exceeds the saturation when it has a bit above the
        // mask: a reduction, not a compare.
        self.dot_l.next = self.pair_l.q.val() + self.third_l.q.val();
        self.dot_h.next = self.pair_h.q.val() + self.third_h.q.val();
        self.d_l.d.next = self.dot_l.val() & self.saturation.val();
        if self.dot_l.val().get_bit(31) | (self.dot_l.val() == 0) {
            self.d_l.d.next = 0.into();
        } else if (self.dot_l.val() & !self.saturation.val()) != 0 {
            self.d_l.d.next = self.saturation.val();
        }
        self.d_h.d.next = self.dot_h.val() & self.saturation.val();
        if self.dot_h.val().get_bit(31) | (self.dot_h.val() == 0) {
            self.d_h.d.next = 0.into();
        } else if (self.dot_h.val() & !self.saturation.val()) != 0 {
            self.d_h.d.next = self.saturation.val();
        }
        self.rn_3.d.next = self.rn.q.val();
        self.lit_3.d.next = !self.dot_l.val().get_bit(31) & (self.dot_l.val() != 0);
        // Stage 4: times 1 / |q|, the dot product's low 16 bits and the
        // bits above them (zero up to 5-bit normals) apart.
        self.t_l.clock.next = self.clock.val();
        self.t_h.clock.next = self.clock.val();
        self.u_l.clock.next = self.clock.val();
        self.u_h.clock.next = self.clock.val();
        self.t_l.a.next = self.d_l.q.val().get_bits::<16>(0);
        self.t_h.a.next = self.d_h.q.val().get_bits::<16>(0);
        self.u_l.a.next = self.d_l.q.val().get_bits::<16>(16);
        self.u_h.a.next = self.d_h.q.val().get_bits::<16>(16);
        self.t_l.b.next = self.rn_3.q.val();
        self.t_h.b.next = self.rn_3.q.val();
        self.u_l.b.next = self.rn_3.q.val();
        self.u_h.b.next = self.rn_3.q.val();
        self.lit_4.d.next = self.lit_3.q.val();
        // Stage 5: the cosine to the nearest table entry; only the index's
        // 10 bits of the sum are used, so synthesis builds its chains no
        // wider than 2^36.
        self.tt_l.next = bit_cast::<64, 32>(self.t_l.p.val());
        self.tt_h.next = bit_cast::<64, 32>(self.t_h.p.val());
        if self.wide_dot.val() {
            self.tt_l.next =
                bit_cast::<64, 32>(self.t_l.p.val()) + (bit_cast::<64, 32>(self.u_l.p.val()) << 16);
            self.tt_h.next =
                bit_cast::<64, 32>(self.t_h.p.val()) + (bit_cast::<64, 32>(self.u_h.p.val()) << 16);
        }
        self.i_l.next = bit_cast::<COS_BITS_U, 64>(
            ((self.tt_l.val() << 10) - self.tt_l.val() + self.half_ulp.val()) >> self.shift.val(),
        );
        self.i_h.next = bit_cast::<COS_BITS_U, 64>(
            ((self.tt_h.val() << 10) - self.tt_h.val() + self.half_ulp.val()) >> self.shift.val(),
        );
        self.idx_l.d.next = self.i_l.val();
        if self.tt_l.val() >= self.sat_t.val() {
            self.idx_l.d.next = self.last.val();
        }
        self.idx_h.d.next = self.i_h.val();
        if self.tt_h.val() >= self.sat_t.val() {
            self.idx_h.d.next = self.last.val();
        }
        self.lit_5.d.next = self.lit_4.q.val();
        // Stage 6: the tables' reads.
        self.diffuse_table.address.next = self.idx_l.q.val();
        self.specular_table.address.next = self.idx_h.q.val();
        self.lit_6.d.next = self.lit_5.q.val();
        // Stage 7: their words.
        self.diffuse_q.d.next = self.diffuse_table.data.val();
        self.specular_q.d.next = 0.into();
        if self.lit_6.q.val() {
            self.specular_q.d.next = self.specular_table.data.val();
        }
        self.diffuse.next = self.diffuse_q.q.val();
        self.specular.next = self.specular_q.q.val();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn saturation_starts_where_the_index_passes_1023() {
        // By hand: (1024 * 2^26 - 2^25) / 1023 = 68 685 922 304 / 1023
        // = 67 141 664.03..., and 67 141 664 * 1023 = 68 685 922 272.
        assert_eq!(saturates_from(), 67_141_665);
        let index = |t: u64| (t * 1023 + (1 << 25)) >> 26;
        assert_eq!(index(saturates_from() - 1), 1023);
        assert_eq!(index(saturates_from()), 1024);
    }
}
