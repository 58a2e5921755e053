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

use super::config::PipelineConfig;
use crate::common::mode_class::ModeClass;
use golden_model::fixed::max_of;
use rust_hdl::prelude::*;

/// The 2x2 selection for one lane.
#[derive(LogicBlock)]
pub struct Select2x2 {
    /// The nine cells at T, in `TAPS` order.
    pub a: [Signal<In, Bits<64>>; 9],
    /// The voxel at T: SR, dx and dy as sign and magnitude, and whether its
    /// x and y neighbours lie outside the slice.
    pub sr: Signal<In, Bit>,
    pub dx_neg: Signal<In, Bit>,
    pub dx_mag: Signal<In, Bits<16>>,
    pub dy_neg: Signal<In, Bit>,
    pub dy_mag: Signal<In, Bits<16>>,
    pub x_out: Signal<In, Bit>,
    pub y_out: Signal<In, Bit>,
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
    w00: Signal<Local, Bits<64>>,
    w10: Signal<Local, Bits<64>>,
    w01: Signal<Local, Bits<64>>,
    w11: Signal<Local, Bits<64>>,
}

impl Select2x2 {
    pub fn new(c: &PipelineConfig) -> Select2x2 {
        let xray = c.mode == ModeClass::Xray;
        Select2x2 {
            a: Default::default(),
            sr: Default::default(),
            dx_neg: Default::default(),
            dx_mag: Default::default(),
            dy_neg: Default::default(),
            dy_mag: Default::default(),
            x_out: Default::default(),
            y_out: Default::default(),
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
        // The packed words: the voxel's own cell, then its neighbours.
        self.w00.next = self.a[0].val();
        self.w10.next = self.a[0].val();
        self.w01.next = self.a[0].val();
        self.w11.next = self.a[0].val();
        if self.dx_mag.val() != 0 {
            if self.dx_neg.val() {
                self.w10.next = self.a[2].val();
            } else {
                self.w10.next = self.a[1].val();
            }
        }
        if self.dy_mag.val() != 0 {
            if self.dy_neg.val() {
                self.w01.next = self.a[4].val();
            } else {
                self.w01.next = self.a[3].val();
            }
        }
        self.w11.next = self.w01.val();
        if self.dx_mag.val() != 0 {
            self.w11.next = self.w10.val();
            if self.dy_mag.val() != 0 {
                if self.dx_neg.val() {
                    if self.dy_neg.val() {
                        self.w11.next = self.a[8].val();
                    } else {
                        self.w11.next = self.a[6].val();
                    }
                } else if self.dy_neg.val() {
                    self.w11.next = self.a[7].val();
                } else {
                    self.w11.next = self.a[5].val();
                }
            }
        }
        // Cells outside the slice, and the start of a ray, read as reset.
        if self.x_out.val() {
            self.w10.next = self.reset.val();
            self.w11.next = self.reset.val();
        }
        if self.y_out.val() {
            self.w01.next = self.reset.val();
            self.w11.next = self.reset.val();
        }
        if self.sr.val() {
            self.w00.next = self.reset.val();
            self.w10.next = self.reset.val();
            self.w01.next = self.reset.val();
            self.w11.next = self.reset.val();
        }
        // Channels: 16-bit slots, or the X-ray sum in channel 0.
        self.c00[0].next = bit_cast::<32, 64>(self.w00.val() & self.r_mask.val());
        self.c00[1].next = bit_cast::<32, 64>((self.w00.val() >> 16) & self.gba_mask.val());
        self.c00[2].next = bit_cast::<32, 64>((self.w00.val() >> 32) & self.gba_mask.val());
        self.c00[3].next = bit_cast::<32, 64>((self.w00.val() >> 48) & self.gba_mask.val());
        self.c10[0].next = bit_cast::<32, 64>(self.w10.val() & self.r_mask.val());
        self.c10[1].next = bit_cast::<32, 64>((self.w10.val() >> 16) & self.gba_mask.val());
        self.c10[2].next = bit_cast::<32, 64>((self.w10.val() >> 32) & self.gba_mask.val());
        self.c10[3].next = bit_cast::<32, 64>((self.w10.val() >> 48) & self.gba_mask.val());
        self.c01[0].next = bit_cast::<32, 64>(self.w01.val() & self.r_mask.val());
        self.c01[1].next = bit_cast::<32, 64>((self.w01.val() >> 16) & self.gba_mask.val());
        self.c01[2].next = bit_cast::<32, 64>((self.w01.val() >> 32) & self.gba_mask.val());
        self.c01[3].next = bit_cast::<32, 64>((self.w01.val() >> 48) & self.gba_mask.val());
        self.c11[0].next = bit_cast::<32, 64>(self.w11.val() & self.r_mask.val());
        self.c11[1].next = bit_cast::<32, 64>((self.w11.val() >> 16) & self.gba_mask.val());
        self.c11[2].next = bit_cast::<32, 64>((self.w11.val() >> 32) & self.gba_mask.val());
        self.c11[3].next = bit_cast::<32, 64>((self.w11.val() >> 48) & self.gba_mask.val());
    }
}
