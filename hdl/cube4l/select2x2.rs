//! The 2x2 selection of a Cube-4L pipeline's bilinear unit (§3.7, Figs.
//! 19-21): of the previous slice's 3x3 region around the voxel, the cells
//! its sight ray can meet, by the signs of dx and dy, split into the
//! bilinear unit's channels. Combinational, at T.
//!
//! The neighbours are x - sign(dx) and y - sign(dy), as in
//! `golden_model::cube4l::compositor::gather`; with dx = 0 (dy = 0) the
//! x (y) neighbour is the voxel's own cell, whose weight is 0. A neighbour
//! outside the slice, and every cell at the start of a ray (SR), reads as
//! the reset value (the intensity's maximum for MinIP, else 0): whether the
//! neighbour lies outside comes registered from the control delay
//! (`x_out`, `y_out`), and MinIP from the `Order` register.
//!
//! Each bilinear channel is selected by its own copy of the flags
//! (`ControlDelay::sel_t`), so one register drives only the multiplexers
//! of its channel's 16-bit slot (X-ray: channel 0's 32 bits). The flags'
//! bits (literals below: `hdl_gen` emits a named constant as an undeclared
//! Verilog identifier): 0 SR, 1 dx negative, 2 dx non-zero, 3 dy negative,
//! 4 dy non-zero, 5 the x neighbour outside the slice, 6 the y neighbour.

use super::config::PipelineConfig;
use crate::common::mode_class::ModeClass;
use golden_model::fixed::max_of;
use rust_hdl::prelude::*;

/// The 2x2 selection for one lane.
#[derive(LogicBlock)]
pub struct Select2x2 {
    /// The nine cells at T, in `TAPS` order.
    pub a: [Signal<In, Bits<64>>; 9],
    /// The voxel at T, each channel's copy: SR, the signs of dx and dy,
    /// whether they are non-zero, and whether its x and y neighbours lie
    /// outside the slice (bits 0 to 6, in that order).
    pub sel: [Signal<In, Bits<7>>; 4],
    /// The cells `cXY[channel]`, X/Y = 1 the neighbour by the sign of dx/dy,
    /// as `Bilinear` takes them.
    pub c00: [Signal<Out, Bits<32>>; 4],
    pub c10: [Signal<Out, Bits<32>>; 4],
    pub c01: [Signal<Out, Bits<32>>; 4],
    pub c11: [Signal<Out, Bits<32>>; 4],
    /// The `Order` register.
    pub order: Signal<In, Bits<64>>,
    reset: Signal<Local, Bits<64>>,
    /// MinIP's reset value: the largest intensity.
    vmax: Constant<Bits<64>>,
    /// Channel masks of the packed word: X-ray keeps a 32-bit sum in channel
    /// 0 and nothing else.
    r_mask: Constant<Bits<64>>,
    gba_mask: Constant<Bits<64>>,
    /// Each channel's packed words, of which it keeps its slot.
    w00: [Signal<Local, Bits<64>>; 4],
    w10: [Signal<Local, Bits<64>>; 4],
    w01: [Signal<Local, Bits<64>>; 4],
    w11: [Signal<Local, Bits<64>>; 4],
}

impl Select2x2 {
    pub fn new(c: &PipelineConfig) -> Select2x2 {
        let xray = c.mode == ModeClass::Xray;
        Select2x2 {
            a: Default::default(),
            sel: Default::default(),
            c00: Default::default(),
            c10: Default::default(),
            c01: Default::default(),
            c11: Default::default(),
            order: Default::default(),
            reset: Default::default(),
            vmax: Constant::new((max_of(c.voxel_bits) as u64).to_bits()),
            r_mask: Constant::new((if xray { 0xffff_ffffu64 } else { 0xffff }).to_bits()),
            gba_mask: Constant::new((if xray { 0u64 } else { 0xffff }).to_bits()),
            w00: Default::default(),
            w10: Default::default(),
            w01: Default::default(),
            w11: Default::default(),
        }
    }
}

impl Logic for Select2x2 {
    #[hdl_gen]
    fn update(&mut self) {
        self.reset.next = 0.into();
        if self.order.val().get_bit(1) {
            self.reset.next = self.vmax.val();
        }
        for ch in 0..4 {
            // The packed words: the voxel's own cell, then its neighbours.
            self.w00[ch].next = self.a[0].val();
            self.w10[ch].next = self.a[0].val();
            self.w01[ch].next = self.a[0].val();
            if self.sel[ch].val().get_bit(2) {
                if self.sel[ch].val().get_bit(1) {
                    self.w10[ch].next = self.a[2].val();
                } else {
                    self.w10[ch].next = self.a[1].val();
                }
            }
            if self.sel[ch].val().get_bit(4) {
                if self.sel[ch].val().get_bit(3) {
                    self.w01[ch].next = self.a[4].val();
                } else {
                    self.w01[ch].next = self.a[3].val();
                }
            }
            self.w11[ch].next = self.w01[ch].val();
            if self.sel[ch].val().get_bit(2) {
                self.w11[ch].next = self.w10[ch].val();
                if self.sel[ch].val().get_bit(4) {
                    if self.sel[ch].val().get_bit(1) {
                        if self.sel[ch].val().get_bit(3) {
                            self.w11[ch].next = self.a[8].val();
                        } else {
                            self.w11[ch].next = self.a[6].val();
                        }
                    } else if self.sel[ch].val().get_bit(3) {
                        self.w11[ch].next = self.a[7].val();
                    } else {
                        self.w11[ch].next = self.a[5].val();
                    }
                }
            }
            // Cells outside the slice, and the start of a ray, read as reset.
            if self.sel[ch].val().get_bit(5) {
                self.w10[ch].next = self.reset.val();
                self.w11[ch].next = self.reset.val();
            }
            if self.sel[ch].val().get_bit(6) {
                self.w01[ch].next = self.reset.val();
                self.w11[ch].next = self.reset.val();
            }
            if self.sel[ch].val().get_bit(0) {
                self.w00[ch].next = self.reset.val();
                self.w10[ch].next = self.reset.val();
                self.w01[ch].next = self.reset.val();
                self.w11[ch].next = self.reset.val();
            }
        }
        // Channels: 16-bit slots, or the X-ray sum in channel 0.
        self.c00[0].next = bit_cast::<32, 64>(self.w00[0].val() & self.r_mask.val());
        self.c00[1].next = bit_cast::<32, 64>((self.w00[1].val() >> 16) & self.gba_mask.val());
        self.c00[2].next = bit_cast::<32, 64>((self.w00[2].val() >> 32) & self.gba_mask.val());
        self.c00[3].next = bit_cast::<32, 64>((self.w00[3].val() >> 48) & self.gba_mask.val());
        self.c10[0].next = bit_cast::<32, 64>(self.w10[0].val() & self.r_mask.val());
        self.c10[1].next = bit_cast::<32, 64>((self.w10[1].val() >> 16) & self.gba_mask.val());
        self.c10[2].next = bit_cast::<32, 64>((self.w10[2].val() >> 32) & self.gba_mask.val());
        self.c10[3].next = bit_cast::<32, 64>((self.w10[3].val() >> 48) & self.gba_mask.val());
        self.c01[0].next = bit_cast::<32, 64>(self.w01[0].val() & self.r_mask.val());
        self.c01[1].next = bit_cast::<32, 64>((self.w01[1].val() >> 16) & self.gba_mask.val());
        self.c01[2].next = bit_cast::<32, 64>((self.w01[2].val() >> 32) & self.gba_mask.val());
        self.c01[3].next = bit_cast::<32, 64>((self.w01[3].val() >> 48) & self.gba_mask.val());
        self.c11[0].next = bit_cast::<32, 64>(self.w11[0].val() & self.r_mask.val());
        self.c11[1].next = bit_cast::<32, 64>((self.w11[1].val() >> 16) & self.gba_mask.val());
        self.c11[2].next = bit_cast::<32, 64>((self.w11[2].val() >> 32) & self.gba_mask.val());
        self.c11[3].next = bit_cast::<32, 64>((self.w11[3].val() >> 48) & self.gba_mask.val());
    }
}
