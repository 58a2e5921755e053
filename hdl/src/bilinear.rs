//! Bilinear interpolation datapath of the Cube-4L bilinear unit (§3.7, the
//! second two stages of Figs. 20-21): given the 2x2 compositing-buffer cells
//! that the signs of dx and dy selected, and the weights |dx| and |dy|, it
//! computes per channel, bit for bit as `golden_model::compositor::gather`,
//!
//! ```text
//! top    = lerp(c00, c10, |dx|)     bottom = lerp(c01, c11, |dx|)    (stage 1)
//! result = lerp(top, bottom, |dy|)                                    (stage 2)
//! lerp(a, b, w) = a + (((b - a) * w + 2^(f-1)) >> f)   (arithmetic shift)
//! ```
//!
//! Two register stages, one voxel per clock. Channels are 16 bits wide
//! (RGBA, or MIP/MinIP intensities); the X-ray sum, wider than the 16x16
//! multiplier, is not handled here yet.

use rust_hdl::prelude::*;

/// `lerp(a, b, w)` with `w` in `0..=2^frac`, combinational, one multiplier.
/// Unsigned form of the arithmetic shift: for `b >= a`,
/// `a + (((b - a) * w + 2^(f-1)) >> f)`; for `b < a`,
/// `a - (((a - b) * w + 2^(f-1) - 1) >> f)`.
#[derive(LogicBlock)]
struct Lerp {
    pub a: Signal<In, Bits<16>>,
    pub b: Signal<In, Bits<16>>,
    pub w: Signal<In, Bits<16>>,
    pub y: Signal<Out, Bits<16>>,
    half: Constant<Bits<32>>,
    shift: Constant<Bits<8>>,
    diff: Signal<Local, Bits<16>>,
    step_up: Signal<Local, Bits<32>>,
    step_down: Signal<Local, Bits<32>>,
}

impl Lerp {
    fn new(frac_bits: u32) -> Lerp {
        Lerp {
            a: Default::default(),
            b: Default::default(),
            w: Default::default(),
            y: Default::default(),
            half: Constant::new((1u64 << (frac_bits - 1)).to_bits()),
            shift: Constant::new((frac_bits as u64).to_bits()),
            diff: Default::default(),
            step_up: Default::default(),
            step_down: Default::default(),
        }
    }
}

impl Logic for Lerp {
    #[hdl_gen]
    fn update(&mut self) {
        if self.b.val() >= self.a.val() {
            self.diff.next = self.b.val() - self.a.val();
        } else {
            self.diff.next = self.a.val() - self.b.val();
        }
        self.step_up.next = (self.diff.val() * self.w.val() + self.half.val()) >> self.shift.val();
        self.step_down.next =
            (self.diff.val() * self.w.val() + self.half.val() - 1) >> self.shift.val();
        if self.b.val() >= self.a.val() {
            self.y.next = self.a.val() + bit_cast::<16, 32>(self.step_up.val());
        } else {
            self.y.next = self.a.val() - bit_cast::<16, 32>(self.step_down.val());
        }
    }
}

/// One channel: two x lerps, a register, the y lerp, a register.
#[derive(LogicBlock)]
struct Channel {
    pub clock: Signal<In, Clock>,
    pub c00: Signal<In, Bits<16>>,
    pub c10: Signal<In, Bits<16>>,
    pub c01: Signal<In, Bits<16>>,
    pub c11: Signal<In, Bits<16>>,
    pub wx: Signal<In, Bits<16>>,
    /// |dy|, already delayed to stage 2 by the caller.
    pub wy: Signal<In, Bits<16>>,
    pub y: Signal<Out, Bits<16>>,
    top: Lerp,
    bottom: Lerp,
    vertical: Lerp,
    top_q: DFF<Bits<16>>,
    bottom_q: DFF<Bits<16>>,
    out_q: DFF<Bits<16>>,
}

impl Channel {
    fn new(frac_bits: u32) -> Channel {
        Channel {
            clock: Default::default(),
            c00: Default::default(),
            c10: Default::default(),
            c01: Default::default(),
            c11: Default::default(),
            wx: Default::default(),
            wy: Default::default(),
            y: Default::default(),
            top: Lerp::new(frac_bits),
            bottom: Lerp::new(frac_bits),
            vertical: Lerp::new(frac_bits),
            top_q: Default::default(),
            bottom_q: Default::default(),
            out_q: Default::default(),
        }
    }
}

impl Logic for Channel {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, top_q, bottom_q, out_q);
        self.top.a.next = self.c00.val();
        self.top.b.next = self.c10.val();
        self.top.w.next = self.wx.val();
        self.bottom.a.next = self.c01.val();
        self.bottom.b.next = self.c11.val();
        self.bottom.w.next = self.wx.val();
        self.top_q.d.next = self.top.y.val();
        self.bottom_q.d.next = self.bottom.y.val();
        self.vertical.a.next = self.top_q.q.val();
        self.vertical.b.next = self.bottom_q.q.val();
        self.vertical.w.next = self.wy.val();
        self.out_q.d.next = self.vertical.y.val();
        self.y.next = self.out_q.q.val();
    }
}

/// The bilinear datapath for RGBA: cells `cXY_{r,g,b,a}` where X/Y = 1
/// names the neighbour chosen by the sign of dx/dy; two clocks of latency.
#[derive(LogicBlock)]
pub struct Bilinear {
    pub clock: Signal<In, Clock>,
    pub c00: [Signal<In, Bits<16>>; 4],
    pub c10: [Signal<In, Bits<16>>; 4],
    pub c01: [Signal<In, Bits<16>>; 4],
    pub c11: [Signal<In, Bits<16>>; 4],
    /// |dx| and |dy| with `frac_bits` fractional bits (1.0 = 2^frac_bits).
    pub wx: Signal<In, Bits<16>>,
    pub wy: Signal<In, Bits<16>>,
    pub out: [Signal<Out, Bits<16>>; 4],
    wy_q: DFF<Bits<16>>,
    ch: [Channel; 4],
}

impl Bilinear {
    pub fn new(frac_bits: u32) -> Bilinear {
        Bilinear {
            clock: Default::default(),
            c00: Default::default(),
            c10: Default::default(),
            c01: Default::default(),
            c11: Default::default(),
            wx: Default::default(),
            wy: Default::default(),
            out: Default::default(),
            wy_q: Default::default(),
            ch: std::array::from_fn(|_| Channel::new(frac_bits)),
        }
    }
}

impl Logic for Bilinear {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, wy_q);
        self.wy_q.d.next = self.wy.val();
        for i in 0..4 {
            self.ch[i].clock.next = self.clock.val();
            self.ch[i].c00.next = self.c00[i].val();
            self.ch[i].c10.next = self.c10[i].val();
            self.ch[i].c01.next = self.c01[i].val();
            self.ch[i].c11.next = self.c11[i].val();
            self.ch[i].wx.next = self.wx.val();
            self.ch[i].wy.next = self.wy_q.q.val();
            self.out[i].next = self.ch[i].y.val();
        }
    }
}
