//! Shader and classifier of Cube-4L (§3.3-3.4): the colour and opacity LUTs
//! indexed by the voxel's top bits, the reflectance map indexed by the
//! quantized gradient, and the opacity weighting, bit for bit as
//! `golden_model::cube4l::shader::Shader::sample`:
//!
//! 1. `alpha = opacity[v >> shift]`, 0 on padding and, when gradients are
//!    used, on voxels at the dataset's edge (first-opaque's threshold is
//!    applied when the table is filled);
//! 2. the gradient is quantized like `golden_model::cube4l::gradient::quantize_normal`:
//!    all three components shift right (rounding half up) until the largest
//!    fits in 4 magnitude bits, then saturate to ±15; the 5-bit two's
//!    complement components index the reflectance map `[diffuse, specular]`;
//! 3. `shaded = sat(mul(colour, diffuse) + specular)`, `weighted = mul(shaded, alpha)`.
//!
//! Without shading the reflectance is `[M, 0]` and `mul(c, M) = c`. MIP and
//! MinIP pass the intensity through with its validity; X-ray takes the
//! classified opacity. One register stage.
//! With `gradient_opacity` the opacity LUT is two-dimensional: the row of the
//! intensity and `min(15, isqrt(gx^2 + gy^2 + gz^2) >> gm_shift)`, with the
//! square root computed digit by digit (no multiplier). The LUT contents are
//! the golden model's own tables.

use super::int_sqrt::IntSqrt;
use super::square::Square;
use super::unorm::MulUnorm;
use golden_model::fixed::max_of;
use golden_model::lut::{ColourLut, OpacityLut, ReflectanceMap, NORMAL_BITS};
use rust_hdl::prelude::*;
use scene::Mode;

/// LUT index bits (the golden model indexes with at most 12).
pub const LUT_INDEX_BITS: usize = 12;
/// Reflectance-map index bits: three 5-bit components.
pub const REFLECTANCE_BITS: usize = 15;

#[derive(LogicBlock)]
pub struct Shader {
    pub clock: Signal<In, Clock>,
    pub value: Signal<In, Bits<16>>,
    pub invalid: Signal<In, Bit>,
    pub at_edge: Signal<In, Bit>,
    pub gx_neg: Signal<In, Bit>,
    pub gx_mag: Signal<In, Bits<32>>,
    pub gy_neg: Signal<In, Bit>,
    pub gy_mag: Signal<In, Bits<32>>,
    pub gz_neg: Signal<In, Bit>,
    pub gz_mag: Signal<In, Bits<32>>,
    /// Registered sample: `[r, g, b, a]`, or the intensity in `r` for
    /// MIP/MinIP (`r` as wide as Cube-3's RPC leaves).
    pub r: Signal<Out, Bits<32>>,
    pub g: Signal<Out, Bits<16>>,
    pub b: Signal<Out, Bits<16>>,
    pub a: Signal<Out, Bits<16>>,
    pub valid: Signal<Out, Bit>,
    /// `[r | g << 16 | b << 32 | alpha << 48]` per LUT entry.
    lut: ROM<Bits<64>, LUT_INDEX_BITS>,
    /// `[diffuse | specular << 16]` per quantized gradient.
    reflectance: ROM<Bits<32>, REFLECTANCE_BITS>,
    /// Opacity by `(intensity row << 4) | gradient-magnitude bin` (empty
    /// without gradient opacity).
    alpha_gm: ROM<Bits<16>, 16>,
    sqrt: IntSqrt,
    sq_x: Square,
    sq_y: Square,
    sq_z: Square,
    gm_bin: Signal<Local, Bits<32>>,
    row: Signal<Local, Bits<LUT_INDEX_BITS>>,
    gm_on: Constant<Bit>,
    gm_shift: Constant<Bits<8>>,
    scalar: Constant<Bit>,
    xray: Constant<Bit>,
    shaded: Constant<Bit>,
    edge_transparent: Constant<Bit>,
    shift: Constant<Bits<8>>,
    m_max: Constant<Bits<16>>,
    mul_r: MulUnorm,
    mul_g: MulUnorm,
    mul_b: MulUnorm,
    lit_r: MulUnorm,
    lit_g: MulUnorm,
    lit_b: MulUnorm,
    alpha: Signal<Local, Bits<16>>,
    m: Signal<Local, Bits<32>>,
    /// `bit_len[i] = i + 1`.
    bit_len: [Constant<Bits<8>>; 32],
    bl: Signal<Local, Bits<8>>,
    s: Signal<Local, Bits<8>>,
    half: Signal<Local, Bits<32>>,
    qx: Signal<Local, Bits<32>>,
    qy: Signal<Local, Bits<32>>,
    qz: Signal<Local, Bits<32>>,
    ix: Signal<Local, Bits<5>>,
    iy: Signal<Local, Bits<5>>,
    iz: Signal<Local, Bits<5>>,
    diffuse: Signal<Local, Bits<16>>,
    specular: Signal<Local, Bits<16>>,
    sum_r: Signal<Local, Bits<32>>,
    sum_g: Signal<Local, Bits<32>>,
    sum_b: Signal<Local, Bits<32>>,
    r_q: DFF<Bits<16>>,
    g_q: DFF<Bits<16>>,
    b_q: DFF<Bits<16>>,
    a_q: DFF<Bits<16>>,
    valid_q: DFF<Bit>,
    /// Without it the outputs read 0, as in emitted Verilog that leaves the
    /// shader out (`export::prune`).
    enabled: Constant<Bit>,
}

/// What a shader is built from: the golden model's tables, Cube-4L's or
/// Cube-3's, and the units its scene needs.
pub struct Tables<'a> {
    pub mode: Mode,
    pub rgba_bits: u32,
    pub colour: Option<&'a ColourLut>,
    pub opacity: Option<&'a OpacityLut>,
    pub reflectance: Option<&'a ReflectanceMap>,
    /// Gradients are used: the edge rule applies.
    pub needs_gradient: bool,
    pub threshold: u32,
    /// Right shift of the gradient magnitude before the opacity LUT's own
    /// (Cube-3: the sample's fractional bits).
    pub magnitude_shift: u32,
    /// Gradient magnitudes may exceed 16 bits.
    pub wide: bool,
}

impl Shader {
    /// Build from the golden model's shader of the same sweep.
    pub fn new(golden: &golden_model::cube4l::shader::Shader) -> Result<Shader, String> {
        Shader::build(&Tables {
            mode: golden.mode,
            rgba_bits: golden.rgba_bits,
            colour: golden.colour.as_ref(),
            opacity: golden.opacity.as_ref(),
            reflectance: golden.reflectance.as_ref(),
            needs_gradient: golden.needs_gradient,
            threshold: golden.threshold,
            magnitude_shift: 0,
            wide: false,
        })
    }

    /// Cube-3's shading for the samples of `golden` (`cube3::shade`): the
    /// value is the sample's integer part `s >> F`, the gradient the ABC
    /// unit's word (at most 31 bits), its magnitude shifted by `F` more.
    pub fn for_cube3(golden: &golden_model::cube3::shade::Shader) -> Result<Shader, String> {
        let w = golden.widths;
        if w.gradient_bits > 31 {
            return Err(format!(
                "cube3.gradient_bits {} unsupported by the shader (at most 31)",
                w.gradient_bits
            ));
        }
        Shader::build(&Tables {
            mode: golden.mode,
            rgba_bits: w.rgba_bits,
            colour: golden.colour.as_ref(),
            opacity: golden.opacity.as_ref(),
            reflectance: golden.reflectance.as_ref(),
            needs_gradient: golden.needs_gradient,
            threshold: golden.threshold,
            magnitude_shift: w.sample_frac(),
            wide: w.gradient_bits > 17,
        })
    }

    /// The shader of a scene that shades nothing: no tables, outputs 0.
    pub fn left_out() -> Shader {
        let mut s = Shader::build(&Tables {
            mode: Mode::Mip,
            rgba_bits: 8,
            colour: None,
            opacity: None,
            reflectance: None,
            needs_gradient: false,
            threshold: 0,
            magnitude_shift: 0,
            wide: false,
        })
        .expect("an empty shader");
        s.enabled = Constant::new(false);
        s
    }

    fn build(golden: &Tables) -> Result<Shader, String> {
        assert_eq!(
            NORMAL_BITS, 5,
            "the RTL normal quantizer is built for 5-bit components"
        );
        assert_eq!(
            golden_model::lut::GM_BITS,
            4,
            "the RTL opacity LUT takes a 4-bit gradient-magnitude bin"
        );
        let scalar = matches!(golden.mode, Mode::Mip | Mode::Minip);
        let m = max_of(golden.rgba_bits);
        let (entries, shift): (Vec<u64>, u32) = match (golden.colour, golden.opacity) {
            (Some(c), Some(o)) => (
                c.table
                    .iter()
                    .zip(&o.table)
                    .map(|(rgb, &a)| {
                        let a = match golden.mode {
                            Mode::FirstOpaque => {
                                if a >= golden.threshold {
                                    m
                                } else {
                                    0
                                }
                            }
                            _ => a,
                        };
                        rgb[0] as u64
                            | (rgb[1] as u64) << 16
                            | (rgb[2] as u64) << 32
                            | (a as u64) << 48
                    })
                    .collect(),
                c.shift,
            ),
            (None, Some(o)) => (o.table.iter().map(|&a| (a as u64) << 48).collect(), o.shift),
            _ => (Vec::new(), 0),
        };
        let lut: ROM<Bits<64>, LUT_INDEX_BITS> = entries.into_iter().map(|e| e.to_bits()).into();
        let gm_shift = golden
            .opacity
            .and_then(|o| o.gm_shift)
            .map(|s| s + golden.magnitude_shift);
        let alpha_gm: ROM<Bits<16>, 16> = match (golden.opacity, gm_shift) {
            (Some(o), Some(_)) => o
                .table
                .iter()
                .map(|&a| {
                    let a = match golden.mode {
                        Mode::FirstOpaque => {
                            if a >= golden.threshold {
                                m
                            } else {
                                0
                            }
                        }
                        _ => a,
                    };
                    (a as u64).to_bits()
                })
                .into(),
            _ => Vec::<Bits<16>>::new().into_iter().into(),
        };
        let reflectance: ROM<Bits<32>, REFLECTANCE_BITS> = match golden.reflectance {
            Some(r) => r
                .table
                .iter()
                .map(|[d, s]| (*d as u64 | (*s as u64) << 16).to_bits())
                .into(),
            None => Vec::<Bits<32>>::new().into_iter().into(),
        };
        // The colour path (shading and opacity weighting) serves composite and
        // first-opaque only.
        let colour = golden.mode.uses_colour();
        Ok(Shader {
            clock: Default::default(),
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
            lut,
            reflectance,
            alpha_gm,
            sqrt: IntSqrt::new(gm_shift.is_some()),
            sq_x: Square::new(golden.wide),
            sq_y: Square::new(golden.wide),
            sq_z: Square::new(golden.wide),
            gm_bin: Default::default(),
            row: Default::default(),
            gm_on: Constant::new(gm_shift.is_some()),
            gm_shift: Constant::new((gm_shift.unwrap_or(0) as u64).to_bits()),
            scalar: Constant::new(scalar),
            xray: Constant::new(golden.mode == Mode::Xray),
            shaded: Constant::new(golden.reflectance.is_some()),
            edge_transparent: Constant::new(golden.needs_gradient),
            shift: Constant::new((shift as u64).to_bits()),
            m_max: Constant::new((m as u64).to_bits()),
            mul_r: MulUnorm::enabled(golden.rgba_bits, colour),
            mul_g: MulUnorm::enabled(golden.rgba_bits, colour),
            mul_b: MulUnorm::enabled(golden.rgba_bits, colour),
            lit_r: MulUnorm::enabled(golden.rgba_bits, colour),
            lit_g: MulUnorm::enabled(golden.rgba_bits, colour),
            lit_b: MulUnorm::enabled(golden.rgba_bits, colour),
            alpha: Default::default(),
            m: Default::default(),
            bit_len: std::array::from_fn(|i| Constant::new((i as u64 + 1).to_bits())),
            bl: Default::default(),
            s: Default::default(),
            half: Default::default(),
            qx: Default::default(),
            qy: Default::default(),
            qz: Default::default(),
            ix: Default::default(),
            iy: Default::default(),
            iz: Default::default(),
            diffuse: Default::default(),
            specular: Default::default(),
            sum_r: Default::default(),
            sum_g: Default::default(),
            sum_b: Default::default(),
            r_q: Default::default(),
            g_q: Default::default(),
            b_q: Default::default(),
            a_q: Default::default(),
            valid_q: Default::default(),
            enabled: Constant::new(true),
        })
    }
}

impl Logic for Shader {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, r_q, g_q, b_q, a_q, valid_q);
        self.row.next = bit_cast::<LUT_INDEX_BITS, 16>(self.value.val() >> self.shift.val());
        self.lut.address.next = self.row.val();
        self.alpha.next = bit_cast::<16, 64>(self.lut.data.val() >> 48);
        // Gradient magnitude and the two-dimensional opacity LUT.
        self.sq_x.m.next = self.gx_mag.val();
        self.sq_y.m.next = self.gy_mag.val();
        self.sq_z.m.next = self.gz_mag.val();
        self.sqrt.n.next = self.sq_x.y.val() + self.sq_y.y.val() + self.sq_z.y.val();
        self.gm_bin.next = self.sqrt.root.val() >> self.gm_shift.val();
        if self.gm_bin.val() > 15 {
            self.gm_bin.next = 15.into();
        }
        self.alpha_gm.address.next = (bit_cast::<16, LUT_INDEX_BITS>(self.row.val()) << 4)
            | bit_cast::<16, 32>(self.gm_bin.val());
        if self.gm_on.val() {
            self.alpha.next = self.alpha_gm.data.val();
        }
        if self.invalid.val() | (self.edge_transparent.val() & self.at_edge.val()) {
            self.alpha.next = 0.into();
        }
        // Normal quantizer: leading one of the largest component.
        self.m.next = self.gx_mag.val();
        if self.gy_mag.val() > self.m.val() {
            self.m.next = self.gy_mag.val();
        }
        if self.gz_mag.val() > self.m.val() {
            self.m.next = self.gz_mag.val();
        }
        self.bl.next = 0.into();
        for i in 0..32 {
            if self.m.val().get_bit(i) {
                self.bl.next = self.bit_len[i].val();
            }
        }
        self.s.next = 0.into();
        if self.bl.val() > 4 {
            self.s.next = self.bl.val() - 4;
        }
        self.half.next = 0.into();
        if self.s.val() > 0 {
            self.half.next = (bit_cast::<32, 16>(1.into()) << self.s.val()) >> 1;
        }
        self.qx.next = (self.gx_mag.val() + self.half.val()) >> self.s.val();
        if self.gx_neg.val() & (self.s.val() > 0) {
            self.qx.next = (self.gx_mag.val() + self.half.val() - 1) >> self.s.val();
        }
        self.qy.next = (self.gy_mag.val() + self.half.val()) >> self.s.val();
        if self.gy_neg.val() & (self.s.val() > 0) {
            self.qy.next = (self.gy_mag.val() + self.half.val() - 1) >> self.s.val();
        }
        self.qz.next = (self.gz_mag.val() + self.half.val()) >> self.s.val();
        if self.gz_neg.val() & (self.s.val() > 0) {
            self.qz.next = (self.gz_mag.val() + self.half.val() - 1) >> self.s.val();
        }
        if self.qx.val() > 15 {
            self.qx.next = 15.into();
        }
        if self.qy.val() > 15 {
            self.qy.next = 15.into();
        }
        if self.qz.val() > 15 {
            self.qz.next = 15.into();
        }
        // Five-bit two's complement components.
        self.ix.next = bit_cast::<5, 32>(self.qx.val());
        if self.gx_neg.val() {
            self.ix.next = bit_cast::<5, 32>(32 - self.qx.val());
        }
        self.iy.next = bit_cast::<5, 32>(self.qy.val());
        if self.gy_neg.val() {
            self.iy.next = bit_cast::<5, 32>(32 - self.qy.val());
        }
        self.iz.next = bit_cast::<5, 32>(self.qz.val());
        if self.gz_neg.val() {
            self.iz.next = bit_cast::<5, 32>(32 - self.qz.val());
        }
        self.reflectance.address.next = bit_cast::<REFLECTANCE_BITS, 5>(self.ix.val())
            | (bit_cast::<REFLECTANCE_BITS, 5>(self.iy.val()) << 5)
            | (bit_cast::<REFLECTANCE_BITS, 5>(self.iz.val()) << 10);
        self.diffuse.next = self.m_max.val();
        self.specular.next = 0.into();
        if self.shaded.val() {
            self.diffuse.next = bit_cast::<16, 32>(self.reflectance.data.val());
            self.specular.next = bit_cast::<16, 32>(self.reflectance.data.val() >> 16);
        }
        // shaded = sat(mul(c, diffuse) + specular)
        self.lit_r.a.next = bit_cast::<16, 64>(self.lut.data.val());
        self.lit_g.a.next = bit_cast::<16, 64>(self.lut.data.val() >> 16);
        self.lit_b.a.next = bit_cast::<16, 64>(self.lut.data.val() >> 32);
        self.lit_r.b.next = self.diffuse.val();
        self.lit_g.b.next = self.diffuse.val();
        self.lit_b.b.next = self.diffuse.val();
        self.sum_r.next =
            bit_cast::<32, 16>(self.lit_r.y.val()) + bit_cast::<32, 16>(self.specular.val());
        self.sum_g.next =
            bit_cast::<32, 16>(self.lit_g.y.val()) + bit_cast::<32, 16>(self.specular.val());
        self.sum_b.next =
            bit_cast::<32, 16>(self.lit_b.y.val()) + bit_cast::<32, 16>(self.specular.val());
        self.mul_r.a.next = bit_cast::<16, 32>(self.sum_r.val());
        if self.sum_r.val() > bit_cast::<32, 16>(self.m_max.val()) {
            self.mul_r.a.next = self.m_max.val();
        }
        self.mul_g.a.next = bit_cast::<16, 32>(self.sum_g.val());
        if self.sum_g.val() > bit_cast::<32, 16>(self.m_max.val()) {
            self.mul_g.a.next = self.m_max.val();
        }
        self.mul_b.a.next = bit_cast::<16, 32>(self.sum_b.val());
        if self.sum_b.val() > bit_cast::<32, 16>(self.m_max.val()) {
            self.mul_b.a.next = self.m_max.val();
        }
        self.mul_r.b.next = self.alpha.val();
        self.mul_g.b.next = self.alpha.val();
        self.mul_b.b.next = self.alpha.val();
        if self.scalar.val() {
            self.r_q.d.next = self.value.val();
            self.g_q.d.next = 0.into();
            self.b_q.d.next = 0.into();
            self.a_q.d.next = 0.into();
        } else if self.xray.val() {
            self.r_q.d.next = self.alpha.val();
            self.g_q.d.next = 0.into();
            self.b_q.d.next = 0.into();
            self.a_q.d.next = 0.into();
        } else {
            self.r_q.d.next = self.mul_r.y.val();
            self.g_q.d.next = self.mul_g.y.val();
            self.b_q.d.next = self.mul_b.y.val();
            self.a_q.d.next = self.alpha.val();
        }
        self.valid_q.d.next = !self.invalid.val();
        if self.xray.val() {
            self.valid_q.d.next = true;
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
            self.valid.next = self.valid_q.q.val();
        }
    }
}
