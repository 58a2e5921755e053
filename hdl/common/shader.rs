//! Shader and classifier (Cube-4L §3.3-3.4; Cube-3's shading units): the
//! classification LUT indexed by the voxel's top bits, the two-dimensional
//! opacity LUT of gradient opacity, the lighting of the quantized gradient,
//! and the opacity weighting, bit for bit as
//! `golden_model::common::shader::Shader::sample` (Cube-3 feeds it as
//! `golden_model::cube3::shade` does):
//!
//! 1. `alpha = classification[v >> shift].alpha`, or with gradient opacity
//!    `gradient_opacity[(v >> shift) << 4 | bin]` ([`GradientBin`]); 0 on
//!    invalid voxels and, when gradients are used, on voxels at the
//!    dataset's edge (first-opaque's threshold is in the tables);
//! 2. the gradient's quantized normal ([`NormalQuantizer`]) and its
//!    `[diffuse, specular]` ([`Lighting`]);
//! 3. `shaded = sat(mul(colour, diffuse) + specular)`,
//!    `weighted = mul(shaded, alpha)`.
//!
//! Without shading the lighting is `[M, 0]` and `mul(c, M) = c`. MIP and
//! MinIP pass the intensity through with its validity; X-ray takes the
//! classified opacity. The tables are host-loaded block RAM and the light a
//! pair of registers (`golden_model::host`).
//!
//! **Pipeline.** [`LATENCY`] register stages from the input (`T - 1 - G`
//! in the Cube-4L lane) to the sample, none holding more than one
//! multiplier, one table read or one wide carry chain:
//!
//! - E1: the inputs, gated (a transparent voxel's gradient is zero);
//! - E2: the classification read; E1-E4: the quantized normal
//!   ([`normal_quantizer::LATENCY`]) and the magnitude's bin;
//! - E5: the gradient-opacity read; the opacity at E6;
//! - E4-E11: the lighting's `[diffuse, specular]`
//!   ([`lighting::LATENCY`], its tables' words registered);
//! - E12-E13: `sat(mul(c, d) + s)` ([`SplitMulAddUnorm`]: the product,
//!   then its rounding half with `s` above it), registered at E14;
//! - E15-E16: the product with the opacity; E17: the sample.
//!
//! The intensity (MIP, MinIP), the classified colour and the opacity wait
//! in registers beside the units.

use super::gradient_bin::GradientBin;
use super::lighting;
use super::lighting::Lighting;
use super::normal_quantizer::{self, NormalQuantizer};
use super::regs::ADDRESS_BITS;
use super::split_mul::SplitMulUnorm;
use super::split_mul_add::SplitMulAddUnorm;
use super::table::Table;
use golden_model::fixed::max_of;
use golden_model::host::{ShaderTables, Table as HostTable};
use golden_model::lut::lut_bits;
use rust_hdl::prelude::*;
use scene::Mode;

/// Classification LUT index bits (the golden model indexes with at most 12).
pub const LUT_INDEX_BITS: usize = 12;
/// Register stages from the input to the sample: the input, the normal,
/// the lighting, the two products and the sample.
pub const LATENCY: usize = 1 + normal_quantizer::LATENCY + lighting::LATENCY + 6;
// The register arrays below are written for these latencies (`hdl_gen`
// takes only literal loop bounds).
const _: () = assert!(normal_quantizer::LATENCY == 3 && lighting::LATENCY == 7);
const _: () = assert!(super::gradient_bin::LATENCY == normal_quantizer::LATENCY);

#[derive(LogicBlock)]
pub struct Shader {
    pub clock: Signal<In, Clock>,
    pub host_write: Signal<In, Bit>,
    pub host_address: Signal<In, Bits<ADDRESS_BITS>>,
    pub host_data: Signal<In, Bits<64>>,
    pub value: Signal<In, Bits<16>>,
    pub invalid: Signal<In, Bit>,
    pub at_edge: Signal<In, Bit>,
    pub gx_neg: Signal<In, Bit>,
    pub gx_mag: Signal<In, Bits<32>>,
    pub gy_neg: Signal<In, Bit>,
    pub gy_mag: Signal<In, Bits<32>>,
    pub gz_neg: Signal<In, Bit>,
    pub gz_mag: Signal<In, Bits<32>>,
    /// The sample, [`LATENCY`] clocks after the input: `[r, g, b, a]`, or
    /// the intensity in `r` for MIP/MinIP (`r` as wide as Cube-3's RPC
    /// leaves).
    pub r: Signal<Out, Bits<32>>,
    pub g: Signal<Out, Bits<16>>,
    pub b: Signal<Out, Bits<16>>,
    pub a: Signal<Out, Bits<16>>,
    pub valid: Signal<Out, Bit>,
    /// `[r | g << 16 | b << 32 | alpha << 48]` per entry.
    pub(crate) lut: Table<64, LUT_INDEX_BITS>,
    /// Opacity by `(row << 4) | bin` (gradient opacity only).
    pub(crate) alpha_gm: Table<16, 16>,
    pub(crate) gm_bin: GradientBin,
    pub(crate) normal: NormalQuantizer,
    pub(crate) lighting: Lighting,
    gm_on: Constant<Bit>,
    scalar: Constant<Bit>,
    xray: Constant<Bit>,
    shaded: Constant<Bit>,
    edge_transparent: Constant<Bit>,
    shift: Constant<Bits<8>>,
    m_max: Constant<Bits<16>>,
    row: Signal<Local, Bits<LUT_INDEX_BITS>>,
    /// The voxel is transparent whatever its gradient; the gradient the
    /// units take.
    gate: Signal<Local, Bit>,
    mag: [Signal<Local, Bits<32>>; 3],
    /// The gated gradient (E1).
    neg_in: [DFF<Bit>; 3],
    mag_in: [DFF<Bits<32>>; 3],
    /// The intensity row, E1 to the gradient-opacity read (E4).
    row_q: [DFF<Bits<LUT_INDEX_BITS>>; 4],
    /// The classification word, E3 to the shading (E11).
    lut_q: [DFF<Bits<64>>; 9],
    /// The gating flag, E1 to the opacity (E5).
    gate_q: [DFF<Bit>; 5],
    alpha: Signal<Local, Bits<16>>,
    /// The opacity, E6 to E16.
    alpha_q: [DFF<Bits<16>>; 11],
    /// The intensity (E1 to E16) and the validity (E1 to E17).
    value_q: [DFF<Bits<16>>; 16],
    valid_q: [DFF<Bit>; 17],
    diffuse: Signal<Local, Bits<16>>,
    specular: Signal<Local, Bits<16>>,
    pub(crate) lit_r: SplitMulAddUnorm,
    pub(crate) lit_g: SplitMulAddUnorm,
    pub(crate) lit_b: SplitMulAddUnorm,
    shaded_q: [DFF<Bits<16>>; 3],
    pub(crate) mul_r: SplitMulUnorm,
    pub(crate) mul_g: SplitMulUnorm,
    pub(crate) mul_b: SplitMulUnorm,
    r_q: DFF<Bits<16>>,
    g_q: DFF<Bits<16>>,
    b_q: DFF<Bits<16>>,
    a_q: DFF<Bits<16>>,
    /// Without it the outputs read 0, as in emitted Verilog that leaves the
    /// shader out (`export::prune`).
    enabled: Constant<Bit>,
}

/// What a shader is built from: the mode class and the units its scene
/// needs (the tables' contents come from the host).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ShaderConfig {
    pub mode: Mode,
    pub voxel_bits: u32,
    pub rgba_bits: u32,
    /// The lighting unit: shading.
    pub lighting: bool,
    /// The gradient-opacity LUT and the magnitude's bin.
    pub gradient_opacity: bool,
    /// Gradients are used: the edge rule applies.
    pub needs_gradient: bool,
    /// Gradient magnitudes may exceed 16 bits (Cube-3).
    pub wide: bool,
    /// Bits a component of the lighting's quantized normal
    /// (`hardware.normal_bits`; the default where nothing is lit).
    pub normal_bits: u32,
}

/// The normal width of a build that lights nothing: the scene default.
pub fn unlit_normal_bits() -> u32 {
    scene::Hardware::default().normal_bits
}

/// A configuration name's `_q{bits}`: empty at the unlit default.
pub fn normal_suffix(normal_bits: u32) -> String {
    match normal_bits == unlit_normal_bits() {
        true => String::new(),
        false => format!("_q{normal_bits}"),
    }
}

/// Why a build cannot have `normal_bits`-bit normals, or `None`: a width
/// the scene takes, and only a lit build has a normal.
pub fn normal_bits_refusal(normal_bits: u32, shading: bool) -> Option<String> {
    let range = scene::spec::NORMAL_BITS;
    if !range.contains(&normal_bits) {
        return Some(format!(
            "{normal_bits}-bit normals: {} to {}",
            range.start(),
            range.end()
        ));
    }
    (!shading && normal_bits != unlit_normal_bits()).then(|| {
        format!("{normal_bits}-bit normals without shading: only the lighting has a normal")
    })
}

impl ShaderConfig {
    /// The configuration of the golden model's tables.
    pub fn of(t: &ShaderTables, voxel_bits: u32, needs_gradient: bool, wide: bool) -> Self {
        ShaderConfig {
            mode: t.mode,
            voxel_bits,
            rgba_bits: t.rgba_bits,
            lighting: t.lighting.is_some(),
            gradient_opacity: t.gm_shift().is_some(),
            needs_gradient,
            wide,
            normal_bits: t.lighting.map_or_else(unlit_normal_bits, |l| l.normal_bits),
        }
    }
}

impl Shader {
    pub fn new(c: &ShaderConfig) -> Shader {
        assert_eq!(
            golden_model::lut::GM_BITS,
            4,
            "the RTL opacity LUT takes a 4-bit gradient-magnitude bin"
        );
        let lb = lut_bits(c.voxel_bits);
        let rb = c.rgba_bits as usize;
        // Colour in three 16-bit slots and the opacity in the fourth; X-ray
        // keeps only its opacity.
        let channels: &[(usize, usize)] = if c.mode.uses_colour() {
            &[(0, rb), (16, rb), (32, rb), (48, rb)]
        } else {
            &[(48, rb)]
        };
        let classified = matches!(c.mode, Mode::Composite | Mode::FirstOpaque | Mode::Xray);
        let words = if classified { 1 << lb } else { 2 };
        let gm_words = if c.gradient_opacity { 1 << (lb + 4) } else { 2 };
        let colour = c.mode.uses_colour();
        Shader {
            clock: Default::default(),
            host_write: Default::default(),
            host_address: Default::default(),
            host_data: Default::default(),
            value: Default::default(),
            invalid: Default::default(),
            at_edge: Default::default(),
            gx_neg: Default::default(),
            gx_mag: Default::default(),
            gy_neg: Default::default(),
            gy_mag: Default::default(),
            gz_neg: Default::default(),
            gz_mag: Default::default(),
            r: Default::default(),
            g: Default::default(),
            b: Default::default(),
            a: Default::default(),
            valid: Default::default(),
            lut: Table::new(HostTable::Classification.base(), words, channels),
            alpha_gm: Table::new(HostTable::GradientOpacity.base(), gm_words, &[(0, rb)]),
            gm_bin: GradientBin::new(c.wide),
            normal: NormalQuantizer::new(c.normal_bits),
            lighting: Lighting::new(c.rgba_bits, c.normal_bits),
            gm_on: Constant::new(c.gradient_opacity),
            scalar: Constant::new(matches!(c.mode, Mode::Mip | Mode::Minip)),
            xray: Constant::new(c.mode == Mode::Xray),
            shaded: Constant::new(c.lighting),
            edge_transparent: Constant::new(c.needs_gradient),
            shift: Constant::new(((c.voxel_bits - lb) as u64).to_bits()),
            m_max: Constant::new((max_of(c.rgba_bits) as u64).to_bits()),
            row: Default::default(),
            gate: Default::default(),
            mag: Default::default(),
            neg_in: Default::default(),
            mag_in: Default::default(),
            row_q: Default::default(),
            lut_q: Default::default(),
            gate_q: Default::default(),
            alpha: Default::default(),
            alpha_q: Default::default(),
            value_q: Default::default(),
            valid_q: Default::default(),
            diffuse: Default::default(),
            specular: Default::default(),
            lit_r: SplitMulAddUnorm::enabled(c.rgba_bits, colour),
            lit_g: SplitMulAddUnorm::enabled(c.rgba_bits, colour),
            lit_b: SplitMulAddUnorm::enabled(c.rgba_bits, colour),
            shaded_q: Default::default(),
            mul_r: SplitMulUnorm::enabled(c.rgba_bits, colour),
            mul_g: SplitMulUnorm::enabled(c.rgba_bits, colour),
            mul_b: SplitMulUnorm::enabled(c.rgba_bits, colour),
            r_q: Default::default(),
            g_q: Default::default(),
            b_q: Default::default(),
            a_q: Default::default(),
            enabled: Constant::new(true),
        }
    }

    /// The shader of a scene that shades nothing: no tables, outputs 0.
    pub fn left_out() -> Shader {
        let mut s = Shader::new(&ShaderConfig {
            mode: Mode::Mip,
            voxel_bits: 8,
            rgba_bits: 8,
            lighting: false,
            gradient_opacity: false,
            needs_gradient: false,
            wide: false,
            normal_bits: unlit_normal_bits(),
        });
        s.enabled = Constant::new(false);
        s
    }

    /// Start with the tables' contents and registers' values the host
    /// would write (simulation: a block RAM's initialisation).
    pub fn preload(&mut self, t: &ShaderTables) {
        self.lut.preload(t.classification());
        self.alpha_gm.preload(t.gradient_opacity());
        if let Some(l) = t.lighting {
            self.lighting.preload(&l.diffuse, &l.specular);
        }
    }

    /// Bits of the tables.
    pub fn memory_bits(&self) -> usize {
        self.lut.memory_bits() + self.alpha_gm.memory_bits() + self.lighting.memory_bits()
    }
}

impl Logic for Shader {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, r_q, g_q, b_q, a_q);
        // The host port reaches every table and register.
        self.lut.clock.next = self.clock.val();
        self.lut.host_write.next = self.host_write.val();
        self.lut.host_address.next = self.host_address.val();
        self.lut.host_data.next = self.host_data.val();
        self.alpha_gm.clock.next = self.clock.val();
        self.alpha_gm.host_write.next = self.host_write.val();
        self.alpha_gm.host_address.next = self.host_address.val();
        self.alpha_gm.host_data.next = self.host_data.val();
        self.gm_bin.clock.next = self.clock.val();
        self.gm_bin.host_write.next = self.host_write.val();
        self.gm_bin.host_address.next = self.host_address.val();
        self.gm_bin.host_data.next = self.host_data.val();
        self.lighting.clock.next = self.clock.val();
        self.lighting.host_write.next = self.host_write.val();
        self.lighting.host_address.next = self.host_address.val();
        self.lighting.host_data.next = self.host_data.val();
        self.normal.clock.next = self.clock.val();
        self.lit_r.clock.next = self.clock.val();
        self.lit_g.clock.next = self.clock.val();
        self.lit_b.clock.next = self.clock.val();
        self.mul_r.clock.next = self.clock.val();
        self.mul_g.clock.next = self.clock.val();
        self.mul_b.clock.next = self.clock.val();
        // E1: the inputs. A transparent voxel's value and gradient (the
        // edge's, whose neighbours lie outside the dataset) are garbage the
        // golden model never reads: the units take zero instead, so no
        // unknown bit travels on.
        self.gate.next = self.invalid.val() | (self.edge_transparent.val() & self.at_edge.val());
        self.row.next = bit_cast::<LUT_INDEX_BITS, 16>(self.value.val() >> self.shift.val());
        self.mag[0].next = self.gx_mag.val();
        self.mag[1].next = self.gy_mag.val();
        self.mag[2].next = self.gz_mag.val();
        if self.gate.val() {
            self.row.next = 0.into();
            self.mag[0].next = 0.into();
            self.mag[1].next = 0.into();
            self.mag[2].next = 0.into();
        }
        for i in 0..3 {
            self.neg_in[i].clock.next = self.clock.val();
            self.mag_in[i].clock.next = self.clock.val();
            self.mag_in[i].d.next = self.mag[i].val();
        }
        self.neg_in[0].d.next = self.gx_neg.val() & !self.gate.val();
        self.neg_in[1].d.next = self.gy_neg.val() & !self.gate.val();
        self.neg_in[2].d.next = self.gz_neg.val() & !self.gate.val();
        // E2: the classification read; E4: the normal and the bin.
        self.lut.address.next = self.row_q[0].q.val();
        for i in 0..3 {
            self.normal.neg[i].next = self.neg_in[i].q.val();
            self.normal.mag[i].next = self.mag_in[i].q.val();
            self.gm_bin.mag[i].next = self.mag_in[i].q.val();
            self.lighting.q_neg[i].next = self.normal.q_neg[i].val();
            self.lighting.q_mag[i].next = self.normal.q_mag[i].val();
        }
        // The pipelines beside the units.
        for i in 0..4 {
            self.row_q[i].clock.next = self.clock.val();
        }
        self.row_q[0].d.next = self.row.val();
        for i in 1..4 {
            self.row_q[i].d.next = self.row_q[i - 1].q.val();
        }
        for i in 0..9 {
            self.lut_q[i].clock.next = self.clock.val();
        }
        for i in 0..11 {
            self.alpha_q[i].clock.next = self.clock.val();
        }
        self.lut_q[0].d.next = self.lut.data.val();
        for i in 1..9 {
            self.lut_q[i].d.next = self.lut_q[i - 1].q.val();
        }
        for i in 0..5 {
            self.gate_q[i].clock.next = self.clock.val();
        }
        self.gate_q[0].d.next = self.gate.val();
        for i in 1..5 {
            self.gate_q[i].d.next = self.gate_q[i - 1].q.val();
        }
        for i in 0..16 {
            self.value_q[i].clock.next = self.clock.val();
        }
        for i in 0..17 {
            self.valid_q[i].clock.next = self.clock.val();
        }
        self.value_q[0].d.next = self.value.val();
        self.valid_q[0].d.next = !self.invalid.val() | self.xray.val();
        for i in 1..16 {
            self.value_q[i].d.next = self.value_q[i - 1].q.val();
        }
        for i in 1..17 {
            self.valid_q[i].d.next = self.valid_q[i - 1].q.val();
        }
        // E5: the gradient-opacity read.
        self.alpha_gm.address.next = (bit_cast::<16, LUT_INDEX_BITS>(self.row_q[3].q.val()) << 4)
            | bit_cast::<16, 4>(self.gm_bin.bin.val());
        // E6: the opacity.
        self.alpha.next = bit_cast::<16, 64>(self.lut_q[2].q.val() >> 48);
        if self.gm_on.val() {
            self.alpha.next = self.alpha_gm.data.val();
        }
        if self.gate_q[4].q.val() {
            self.alpha.next = 0.into();
        }
        self.alpha_q[0].d.next = self.alpha.val();
        for i in 1..11 {
            self.alpha_q[i].d.next = self.alpha_q[i - 1].q.val();
        }
        // E12-E13: sat(mul(c, diffuse) + specular), registered at E14.
        self.diffuse.next = self.m_max.val();
        self.specular.next = 0.into();
        if self.shaded.val() {
            self.diffuse.next = self.lighting.diffuse.val();
            self.specular.next = self.lighting.specular.val();
        }
        self.lit_r.a.next = bit_cast::<16, 64>(self.lut_q[8].q.val());
        self.lit_g.a.next = bit_cast::<16, 64>(self.lut_q[8].q.val() >> 16);
        self.lit_b.a.next = bit_cast::<16, 64>(self.lut_q[8].q.val() >> 32);
        self.lit_r.b.next = self.diffuse.val();
        self.lit_g.b.next = self.diffuse.val();
        self.lit_b.b.next = self.diffuse.val();
        self.lit_r.c.next = self.specular.val();
        self.lit_g.c.next = self.specular.val();
        self.lit_b.c.next = self.specular.val();
        for i in 0..3 {
            self.shaded_q[i].clock.next = self.clock.val();
        }
        self.shaded_q[0].d.next = self.lit_r.y.val();
        self.shaded_q[1].d.next = self.lit_g.y.val();
        self.shaded_q[2].d.next = self.lit_b.y.val();
        // E15-E16: mul(shaded, alpha); E17: the sample, or the scalar modes'.
        self.mul_r.a.next = self.shaded_q[0].q.val();
        self.mul_g.a.next = self.shaded_q[1].q.val();
        self.mul_b.a.next = self.shaded_q[2].q.val();
        self.mul_r.b.next = self.alpha_q[8].q.val();
        self.mul_g.b.next = self.alpha_q[8].q.val();
        self.mul_b.b.next = self.alpha_q[8].q.val();
        if self.scalar.val() {
            self.r_q.d.next = self.value_q[15].q.val();
            self.g_q.d.next = 0.into();
            self.b_q.d.next = 0.into();
            self.a_q.d.next = 0.into();
        } else if self.xray.val() {
            self.r_q.d.next = self.alpha_q[10].q.val();
            self.g_q.d.next = 0.into();
            self.b_q.d.next = 0.into();
            self.a_q.d.next = 0.into();
        } else {
            self.r_q.d.next = self.mul_r.y.val();
            self.g_q.d.next = self.mul_g.y.val();
            self.b_q.d.next = self.mul_b.y.val();
            self.a_q.d.next = self.alpha_q[10].q.val();
        }
        self.r.next = 0.into();
        self.g.next = 0.into();
        self.b.next = 0.into();
        self.a.next = 0.into();
        self.valid.next = false;
        if self.enabled.val() {
            self.r.next = bit_cast::<32, 16>(self.r_q.q.val());
            self.g.next = self.g_q.q.val();
            self.b.next = self.b_q.q.val();
            self.a.next = self.a_q.q.val();
            self.valid.next = self.valid_q[16].q.val();
        }
    }
}
