//! Bilinear interpolation datapath of the Cube-4L bilinear unit (§3.7, the
//! second two stages of Figs. 20-21): given the 2x2 compositing-buffer cells
//! that the signs of dx and dy selected, and the weights |dx| and |dy|, it
//! computes per channel, bit for bit as `golden_model::cube4l::compositor::gather`,
//!
//! ```text
//! top    = lerp(c00, c10, |dx|)     bottom = lerp(c01, c11, |dx|)    (stage 1)
//! result = lerp(top, bottom, |dy|)                                    (stage 2)
//! lerp(a, b, w) = a + (((b - a) * w + 2^(f-1)) >> f)   (arithmetic shift)
//! ```
//!
//! One voxel per clock with [`LATENCY`] clocks of latency, pipelined for
//! speed: the cells and weights are registered on entry, and each lerp takes
//! `lerp::SPLIT_LATENCY` clocks: its compare and difference, its product, and
//! the rounded sum (one carry chain), one a clock. Every channel is 32 bits wide
//! so that channel 0 can carry the X-ray sum (`rgba_bits + log2(depth)`
//! bits); for X-ray the difference is split into 16-bit halves for two
//! 16x16 multipliers. Every other channel, and channel 0 in the other
//! modes, holds values of at most 16 bits, whose difference has no upper
//! half: those lerps are built with one multiplier (three per channel, the
//! datapath's count).

use crate::common::lane_copy::LaneCopy;
use crate::common::lerp::{self, Lerp};
use rust_hdl::prelude::*;

/// Clocks from the cells to the result.
pub const LATENCY: usize = 1 + 2 * lerp::SPLIT_LATENCY;
// The y lerp's weight waits in `wy_q`, written for 3-clock lerps.
const _: () = assert!(lerp::SPLIT_LATENCY == 3);

/// One channel: the cells registered, two x lerps, the y lerp.
#[derive(LogicBlock)]
struct WideChannel {
    pub clock: Signal<In, Clock>,
    pub c00: Signal<In, Bits<32>>,
    pub c10: Signal<In, Bits<32>>,
    pub c01: Signal<In, Bits<32>>,
    pub c11: Signal<In, Bits<32>>,
    /// The weights, already registered (`Bilinear` lines them up).
    pub wx: Signal<In, Bits<16>>,
    pub wy: Signal<In, Bits<16>>,
    pub y: Signal<Out, Bits<32>>,
    top: Lerp,
    bottom: Lerp,
    vertical: Lerp,
    cells_q: [DFF<Bits<32>>; 4],
}

impl WideChannel {
    fn new(frac_bits: u32, wide: bool) -> WideChannel {
        WideChannel {
            clock: Default::default(),
            c00: Default::default(),
            c10: Default::default(),
            c01: Default::default(),
            c11: Default::default(),
            wx: Default::default(),
            wy: Default::default(),
            y: Default::default(),
            top: Lerp::split(frac_bits, wide),
            bottom: Lerp::split(frac_bits, wide),
            vertical: Lerp::split(frac_bits, wide),
            cells_q: Default::default(),
        }
    }
}

impl Logic for WideChannel {
    #[hdl_gen]
    fn update(&mut self) {
        for i in 0..4 {
            self.cells_q[i].clock.next = self.clock.val();
        }
        self.top.clock.next = self.clock.val();
        self.bottom.clock.next = self.clock.val();
        self.vertical.clock.next = self.clock.val();
        self.cells_q[0].d.next = self.c00.val();
        self.cells_q[1].d.next = self.c10.val();
        self.cells_q[2].d.next = self.c01.val();
        self.cells_q[3].d.next = self.c11.val();
        self.top.a.next = self.cells_q[0].q.val();
        self.top.b.next = self.cells_q[1].q.val();
        self.top.w.next = self.wx.val();
        self.bottom.a.next = self.cells_q[2].q.val();
        self.bottom.b.next = self.cells_q[3].q.val();
        self.bottom.w.next = self.wx.val();
        self.vertical.a.next = self.top.y.val();
        self.vertical.b.next = self.bottom.y.val();
        self.vertical.w.next = self.wy.val();
        self.y.next = self.vertical.y.val();
    }
}

/// The bilinear datapath for RGBA (or an X-ray sum in channel 0): cells
/// `cXY[channel]` where X/Y = 1 names the neighbour chosen by the sign of
/// dx/dy; [`LATENCY`] clocks of latency.
#[derive(LogicBlock)]
pub struct Bilinear {
    pub clock: Signal<In, Clock>,
    pub c00: [Signal<In, Bits<32>>; 4],
    pub c10: [Signal<In, Bits<32>>; 4],
    pub c01: [Signal<In, Bits<32>>; 4],
    pub c11: [Signal<In, Bits<32>>; 4],
    /// |dx| and |dy| with `frac_bits` fractional bits (1.0 = 2^frac_bits).
    pub wx: Signal<In, Bits<16>>,
    pub wy: Signal<In, Bits<16>>,
    pub out: [Signal<Out, Bits<32>>; 4],
    /// wx for the x lerps (one clock), wy for the y lerp (four), the last
    /// register each channel's own: equal registers would be merged into one
    /// driving every channel's multipliers across the lane (the shaded 256³
    /// build's critical path, 5.1 ns of routing).
    wx_q: [LaneCopy<Bits<16>>; 4],
    wy_q: [DFF<Bits<16>>; 3],
    wy_last: [LaneCopy<Bits<16>>; 4],
    ch: [WideChannel; 4],
}

impl Bilinear {
    /// `wide`: channel 0 carries X-ray's 32-bit sum.
    pub fn new(frac_bits: u32, wide: bool) -> Bilinear {
        Bilinear {
            clock: Default::default(),
            c00: Default::default(),
            c10: Default::default(),
            c01: Default::default(),
            c11: Default::default(),
            wx: Default::default(),
            wy: Default::default(),
            out: Default::default(),
            wx_q: Default::default(),
            wy_q: Default::default(),
            wy_last: Default::default(),
            ch: std::array::from_fn(|i| WideChannel::new(frac_bits, wide && i == 0)),
        }
    }
}

impl Logic for Bilinear {
    #[hdl_gen]
    fn update(&mut self) {
        for i in 0..3 {
            self.wy_q[i].clock.next = self.clock.val();
        }
        self.wy_q[0].d.next = self.wy.val();
        self.wy_q[1].d.next = self.wy_q[0].q.val();
        self.wy_q[2].d.next = self.wy_q[1].q.val();
        for i in 0..4 {
            self.wx_q[i].clock.next = self.clock.val();
            self.wx_q[i].d.next = self.wx.val();
            self.wy_last[i].clock.next = self.clock.val();
            self.wy_last[i].d.next = self.wy_q[2].q.val();
            self.ch[i].clock.next = self.clock.val();
            self.ch[i].c00.next = self.c00[i].val();
            self.ch[i].c10.next = self.c10[i].val();
            self.ch[i].c01.next = self.c01[i].val();
            self.ch[i].c11.next = self.c11[i].val();
            self.ch[i].wx.next = self.wx_q[i].q.val();
            self.ch[i].wy.next = self.wy_last[i].q.val();
            self.out[i].next = self.ch[i].y.val();
        }
    }
}
