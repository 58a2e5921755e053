//! What both architectures build from: [`lerp`] (linear interpolation),
//! [`over`] (the over operator, fused for the RPC's one-clock loop), the
//! pipelined [`split_mul`] (the exact unorm multiplier, its product and its
//! rounding in clocks of their own; [`split_mul_add`], the shader's, with
//! an addend in the rounding's clock) and [`piped_over`],
//! [`delay_line`] (and [`registered_line`], its output a register, and
//! [`banked_line`], a register at each block RAM), [`ram`] (block RAM as
//! deep as the scene needs) and
//! [`depth_rom`] (a constant table as deep as the build's width needs), the
//! host's [`regs`] and [`table`]s (written between frames), the [`shader`]
//! (classification, with the [`gradient_bin`] of gradient opacity and its
//! [`square`]s, and the [`lighting`] of the [`normal_quantizer`]'s normal),
//! [`lanes`], the lane counts the RTL is built for, [`lane_copy`], a
//! lane's own register of a frame's value, never merged with its
//! neighbours', and [`dsp_product`], a registered product whose register
//! is the multiplier's own on an ECP5. Each architecture's units manifest
//! is made of [`units`], its instance names checked by [`instance`]'s
//! macro.

pub mod banked_line;
pub mod delay_line;
pub mod depth_rom;
pub mod dsp_product;
pub mod gradient_bin;
pub mod instance;
pub mod lane_copy;
pub mod lanes;
pub mod lerp;
pub mod lighting;
pub mod mode_class;
pub mod normal_quantizer;
pub mod over;
pub mod piped_over;
pub mod ram;
pub mod registered_line;
pub mod regs;
pub mod shader;
pub mod split_mul;
pub mod split_mul_add;
pub mod square;
pub mod table;
pub mod units;
pub mod view_rom;

use rust_hdl::prelude::*;

/// A 16-bit constant from a `u32` (the counters' and registers' width).
pub fn bits16(v: u32) -> Bits<16> {
    (v as u64).to_bits()
}

/// The first of a build's datapath widths (voxel, RGBA, weight fraction,
/// normal, in that order) that a scene's differs from, as a refusal naming
/// the scene's field.
pub fn width_refusal(build: [u32; 4], scene: [u32; 4]) -> Option<String> {
    ["voxel_bits", "rgba_bits", "frac_bits", "normal_bits"]
        .into_iter()
        .zip(build.into_iter().zip(scene))
        .find(|(_, (b, s))| b != s)
        .map(|(what, (b, s))| format!("the scene's {what} is {s}, the configuration's {b}"))
}

/// A ROM of 16-bit two's-complement entries (Cube-3's template and group
/// tables).
pub fn rom16<const N: usize>(v: &[i32]) -> ROM<Bits<16>, N> {
    v.iter().map(|&x| ((x as u64) & 0xffff).to_bits()).into()
}
