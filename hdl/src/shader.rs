//! Shader and classifier of Cube-4L (§3.3-3.4) for scenes without gradients
//! (shading off, no gradient-magnitude opacity): the colour and opacity LUTs,
//! indexed by the voxel's top bits, and the opacity weighting
//! `weighted = mul(colour, alpha)`, bit for bit as
//! `golden_model::shader::Shader::sample` with an unlit reflectance
//! (`mul(c, M) = c` exactly). MIP and MinIP pass the intensity through with
//! its validity. One register stage.
//!
//! The LUT contents are the golden model's own tables, so hardware and model
//! cannot disagree on them; first-opaque's threshold is applied when the
//! opacity table is filled. The gradient-driven units (reflectance map,
//! gradient-magnitude index) are not built yet.

use crate::unorm::MulUnorm;
use golden_model::fixed::max_of;
use golden_model::scene::Mode;
use rust_hdl::prelude::*;

/// LUT index bits (the golden model indexes with at most 12).
pub const LUT_INDEX_BITS: usize = 12;

#[derive(LogicBlock)]
pub struct Shader {
    pub clock: Signal<In, Clock>,
    pub value: Signal<In, Bits<16>>,
    pub invalid: Signal<In, Bit>,
    /// Registered sample: `[r, g, b, a]`, or the intensity in `r` for MIP/MinIP.
    pub r: Signal<Out, Bits<16>>,
    pub g: Signal<Out, Bits<16>>,
    pub b: Signal<Out, Bits<16>>,
    pub a: Signal<Out, Bits<16>>,
    pub valid: Signal<Out, Bit>,
    /// `[r | g << 16 | b << 32 | alpha << 48]` per LUT entry.
    lut: ROM<Bits<64>, LUT_INDEX_BITS>,
    scalar: Constant<Bit>,
    shift: Constant<Bits<8>>,
    mul_r: MulUnorm,
    mul_g: MulUnorm,
    mul_b: MulUnorm,
    alpha: Signal<Local, Bits<16>>,
    r_q: DFF<Bits<16>>,
    g_q: DFF<Bits<16>>,
    b_q: DFF<Bits<16>>,
    a_q: DFF<Bits<16>>,
    valid_q: DFF<Bit>,
}

impl Shader {
    /// Build from the golden model's shader of the same sweep; `Err` for the
    /// parts not built in hardware yet.
    pub fn new(golden: &golden_model::shader::Shader) -> Result<Shader, String> {
        if golden.needs_gradient {
            return Err("scenes with shading or gradient opacity need the ABC gradient and reflectance units, which the RTL does not have yet".into());
        }
        if golden.mode == Mode::Xray {
            return Err("X-ray sums are wider than the RTL bilinear unit's 16-bit channels".into());
        }
        let scalar = matches!(golden.mode, Mode::Mip | Mode::Minip);
        let m = max_of(golden.rgba_bits);
        let (entries, shift): (Vec<u64>, u32) = match (&golden.colour, &golden.opacity) {
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
            _ => (Vec::new(), 0),
        };
        let rom: ROM<Bits<64>, LUT_INDEX_BITS> = entries.into_iter().map(|e| e.to_bits()).into();
        Ok(Shader {
            clock: Default::default(),
            value: Default::default(),
            invalid: Default::default(),
            r: Default::default(),
            g: Default::default(),
            b: Default::default(),
            a: Default::default(),
            valid: Default::default(),
            lut: rom,
            scalar: Constant::new(scalar),
            shift: Constant::new((shift as u64).to_bits()),
            mul_r: MulUnorm::new(golden.rgba_bits),
            mul_g: MulUnorm::new(golden.rgba_bits),
            mul_b: MulUnorm::new(golden.rgba_bits),
            alpha: Default::default(),
            r_q: Default::default(),
            g_q: Default::default(),
            b_q: Default::default(),
            a_q: Default::default(),
            valid_q: Default::default(),
        })
    }
}

impl Logic for Shader {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, r_q, g_q, b_q, a_q, valid_q);
        self.lut.address.next =
            bit_cast::<LUT_INDEX_BITS, 16>(self.value.val() >> self.shift.val());
        self.alpha.next = bit_cast::<16, 64>(self.lut.data.val() >> 48);
        if self.invalid.val() {
            self.alpha.next = 0.into();
        }
        self.mul_r.a.next = bit_cast::<16, 64>(self.lut.data.val());
        self.mul_g.a.next = bit_cast::<16, 64>(self.lut.data.val() >> 16);
        self.mul_b.a.next = bit_cast::<16, 64>(self.lut.data.val() >> 32);
        self.mul_r.b.next = self.alpha.val();
        self.mul_g.b.next = self.alpha.val();
        self.mul_b.b.next = self.alpha.val();
        if self.scalar.val() {
            self.r_q.d.next = self.value.val();
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
        self.r.next = self.r_q.q.val();
        self.g.next = self.g_q.q.val();
        self.b.next = self.b_q.q.val();
        self.a.next = self.a_q.q.val();
        self.valid.next = self.valid_q.q.val();
    }
}
