//! The lighting of a quantized normal (Cube-4L §3.4's reflectance; Cube-3's
//! shading units), bit for bit as `golden_model::lut::Lighting`: the
//! cosines between `-q` and the light and half vectors from two dot
//! products and a reciprocal norm, each indexing a host-loaded table.
//! Three register stages, then the tables' registered reads:
//!
//! 1. the dot products `q · light`, `q · half` (sign-magnitude products of
//!    4-bit components and 12-bit registers), and `rnorm(|q|²)` from a
//!    constant ROM;
//! 2. `t = min(dot, 2^16 - 1) · rnorm`, one 16x16 multiplier each;
//! 3. the cosine index `min(1023, (t · 1023 + 2^25) >> 26)` addressing the
//!    diffuse and specular tables, whose words come out one clock later
//!    (the specular term 0 where the light's dot product is not positive).
//!
//! The light and half vectors are registers, the tables depend only on the
//! lighting coefficients: a new view or light is six register words.

use super::regs::{Regs, ADDRESS_BITS};
use super::table::Table;
use golden_model::host::{Reg, Table as HostTable};
use golden_model::lut::{rnorm, COS_BITS, DIR_FRAC, RNORM_FRAC};
use rust_hdl::prelude::*;

/// Clocks from the quantized normal to the terms.
pub const LATENCY: usize = 3;

/// The lighting unit of one shader, with `rgba_bits` table words.
#[derive(LogicBlock)]
pub struct Lighting {
    pub clock: Signal<In, Clock>,
    pub host_write: Signal<In, Bit>,
    pub host_address: Signal<In, Bits<ADDRESS_BITS>>,
    pub host_data: Signal<In, Bits<64>>,
    /// The quantized normal, sign and magnitude per component.
    pub q_neg: [Signal<In, Bit>; 3],
    pub q_mag: [Signal<In, Bits<4>>; 3],
    /// `[diffuse, specular]`, [`LATENCY`] clocks later.
    pub diffuse: Signal<Out, Bits<16>>,
    pub specular: Signal<Out, Bits<16>>,
    /// The light (`q[0]`) and half (`q[1]`) vectors.
    regs: Regs<2>,
    rnorm: ROM<Bits<16>, 10>,
    diffuse_table: Table<16, COS_BITS_U>,
    specular_table: Table<16, COS_BITS_U>,
    /// Stage 1: the registers' magnitudes, the products and sums.
    m_l: [Signal<Local, Bits<16>>; 3],
    m_h: [Signal<Local, Bits<16>>; 3],
    qm: [Signal<Local, Bits<16>>; 3],
    p_l: [Signal<Local, Bits<32>>; 3],
    p_h: [Signal<Local, Bits<32>>; 3],
    sum_l: Signal<Local, Bits<32>>,
    sum_h: Signal<Local, Bits<32>>,
    n2: Signal<Local, Bits<16>>,
    dot_l: DFF<Bits<32>>,
    dot_h: DFF<Bits<32>>,
    rn: DFF<Bits<16>>,
    /// Stage 2.
    d16_l: Signal<Local, Bits<16>>,
    d16_h: Signal<Local, Bits<16>>,
    t_l: DFF<Bits<32>>,
    t_h: DFF<Bits<32>>,
    lit_2: DFF<Bit>,
    /// Stage 3.
    i_l: Signal<Local, Bits<64>>,
    i_h: Signal<Local, Bits<64>>,
    lit_3: DFF<Bit>,
    half_ulp: Constant<Bits<64>>,
    shift: Constant<Bits<8>>,
    last: Constant<Bits<64>>,
}

/// [`COS_BITS`] as a const generic.
const COS_BITS_U: usize = COS_BITS as usize;

impl Lighting {
    pub fn new(rgba_bits: u32) -> Lighting {
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
            rnorm: (0..1024u32).map(|n2| (rnorm(n2) as u64).to_bits()).into(),
            diffuse_table: Table::new(HostTable::Diffuse.base(), words, &word),
            specular_table: Table::new(HostTable::Specular.base(), words, &word),
            m_l: Default::default(),
            m_h: Default::default(),
            qm: Default::default(),
            p_l: Default::default(),
            p_h: Default::default(),
            sum_l: Default::default(),
            sum_h: Default::default(),
            n2: Default::default(),
            dot_l: Default::default(),
            dot_h: Default::default(),
            rn: Default::default(),
            d16_l: Default::default(),
            d16_h: Default::default(),
            t_l: Default::default(),
            t_h: Default::default(),
            lit_2: Default::default(),
            i_l: Default::default(),
            i_h: Default::default(),
            lit_3: Default::default(),
            half_ulp: Constant::new((1u64 << (DIR_FRAC + RNORM_FRAC - 1)).to_bits()),
            shift: Constant::new(((DIR_FRAC + RNORM_FRAC) as u64).to_bits()),
            last: Constant::new(((1u64 << COS_BITS) - 1).to_bits()),
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
        dff_setup!(self, clock, dot_l, dot_h, rn, t_l, t_h, lit_2, lit_3);
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
        // Stage 1: the dot products in two's complement, and 1 / |q|.
        self.sum_l.next = 0.into();
        self.sum_h.next = 0.into();
        self.n2.next = 0.into();
        // Unrolled: hdl_gen takes no loop index inside a cast.
        self.qm[0].next = bit_cast::<16, 4>(self.q_mag[0].val());
        self.m_l[0].next = self.regs.q[0].val().get_bits::<16>(0);
        if self.regs.q[0].val().get_bit(15) {
            self.m_l[0].next = 0 - self.regs.q[0].val().get_bits::<16>(0);
        }
        self.m_h[0].next = self.regs.q[1].val().get_bits::<16>(0);
        if self.regs.q[1].val().get_bit(15) {
            self.m_h[0].next = 0 - self.regs.q[1].val().get_bits::<16>(0);
        }
        self.p_l[0].next = self.qm[0].val() * self.m_l[0].val();
        if self.q_neg[0].val() ^ self.regs.q[0].val().get_bit(15) {
            self.p_l[0].next = 0 - (self.qm[0].val() * self.m_l[0].val());
        }
        self.sum_l.next = self.sum_l.val() + self.p_l[0].val();
        self.p_h[0].next = self.qm[0].val() * self.m_h[0].val();
        if self.q_neg[0].val() ^ self.regs.q[1].val().get_bit(15) {
            self.p_h[0].next = 0 - (self.qm[0].val() * self.m_h[0].val());
        }
        self.sum_h.next = self.sum_h.val() + self.p_h[0].val();
        self.n2.next = self.n2.val() + bit_cast::<16, 32>(self.qm[0].val() * self.qm[0].val());
        self.qm[1].next = bit_cast::<16, 4>(self.q_mag[1].val());
        self.m_l[1].next = self.regs.q[0].val().get_bits::<16>(16);
        if self.regs.q[0].val().get_bit(31) {
            self.m_l[1].next = 0 - self.regs.q[0].val().get_bits::<16>(16);
        }
        self.m_h[1].next = self.regs.q[1].val().get_bits::<16>(16);
        if self.regs.q[1].val().get_bit(31) {
            self.m_h[1].next = 0 - self.regs.q[1].val().get_bits::<16>(16);
        }
        self.p_l[1].next = self.qm[1].val() * self.m_l[1].val();
        if self.q_neg[1].val() ^ self.regs.q[0].val().get_bit(31) {
            self.p_l[1].next = 0 - (self.qm[1].val() * self.m_l[1].val());
        }
        self.sum_l.next = self.sum_l.val() + self.p_l[1].val();
        self.p_h[1].next = self.qm[1].val() * self.m_h[1].val();
        if self.q_neg[1].val() ^ self.regs.q[1].val().get_bit(31) {
            self.p_h[1].next = 0 - (self.qm[1].val() * self.m_h[1].val());
        }
        self.sum_h.next = self.sum_h.val() + self.p_h[1].val();
        self.n2.next = self.n2.val() + bit_cast::<16, 32>(self.qm[1].val() * self.qm[1].val());
        self.qm[2].next = bit_cast::<16, 4>(self.q_mag[2].val());
        self.m_l[2].next = self.regs.q[0].val().get_bits::<16>(32);
        if self.regs.q[0].val().get_bit(47) {
            self.m_l[2].next = 0 - self.regs.q[0].val().get_bits::<16>(32);
        }
        self.m_h[2].next = self.regs.q[1].val().get_bits::<16>(32);
        if self.regs.q[1].val().get_bit(47) {
            self.m_h[2].next = 0 - self.regs.q[1].val().get_bits::<16>(32);
        }
        self.p_l[2].next = self.qm[2].val() * self.m_l[2].val();
        if self.q_neg[2].val() ^ self.regs.q[0].val().get_bit(47) {
            self.p_l[2].next = 0 - (self.qm[2].val() * self.m_l[2].val());
        }
        self.sum_l.next = self.sum_l.val() + self.p_l[2].val();
        self.p_h[2].next = self.qm[2].val() * self.m_h[2].val();
        if self.q_neg[2].val() ^ self.regs.q[1].val().get_bit(47) {
            self.p_h[2].next = 0 - (self.qm[2].val() * self.m_h[2].val());
        }
        self.sum_h.next = self.sum_h.val() + self.p_h[2].val();
        self.n2.next = self.n2.val() + bit_cast::<16, 32>(self.qm[2].val() * self.qm[2].val());
        self.dot_l.d.next = self.sum_l.val();
        self.dot_h.d.next = self.sum_h.val();
        self.rnorm.address.next = bit_cast::<10, 16>(self.n2.val());
        self.rn.d.next = self.rnorm.data.val();
        // Stage 2: a positive dot product, saturated to 16 bits, times 1 / |q|.
        self.d16_l.next = self.dot_l.q.val().get_bits::<16>(0);
        if self.dot_l.q.val().get_bit(31) | (self.dot_l.q.val() == 0) {
            self.d16_l.next = 0.into();
        } else if self.dot_l.q.val() > 0xffff {
            self.d16_l.next = 0xffff.into();
        }
        self.d16_h.next = self.dot_h.q.val().get_bits::<16>(0);
        if self.dot_h.q.val().get_bit(31) | (self.dot_h.q.val() == 0) {
            self.d16_h.next = 0.into();
        } else if self.dot_h.q.val() > 0xffff {
            self.d16_h.next = 0xffff.into();
        }
        self.t_l.d.next = self.d16_l.val() * self.rn.q.val();
        self.t_h.d.next = self.d16_h.val() * self.rn.q.val();
        self.lit_2.d.next = !self.dot_l.q.val().get_bit(31) & (self.dot_l.q.val() != 0);
        // Stage 3: the cosine to the nearest table entry; the tables' reads.
        self.i_l.next = ((bit_cast::<64, 32>(self.t_l.q.val()) << 10)
            - bit_cast::<64, 32>(self.t_l.q.val())
            + self.half_ulp.val())
            >> self.shift.val();
        if self.i_l.val() > self.last.val() {
            self.i_l.next = self.last.val();
        }
        self.i_h.next = ((bit_cast::<64, 32>(self.t_h.q.val()) << 10)
            - bit_cast::<64, 32>(self.t_h.q.val())
            + self.half_ulp.val())
            >> self.shift.val();
        if self.i_h.val() > self.last.val() {
            self.i_h.next = self.last.val();
        }
        self.diffuse_table.address.next = bit_cast::<COS_BITS_U, 64>(self.i_l.val());
        self.specular_table.address.next = bit_cast::<COS_BITS_U, 64>(self.i_h.val());
        self.lit_3.d.next = self.lit_2.q.val();
        self.diffuse.next = self.diffuse_table.data.val();
        self.specular.next = 0.into();
        if self.lit_3.q.val() {
            self.specular.next = self.specular_table.data.val();
        }
    }
}
