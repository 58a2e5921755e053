//! The 26-neighbourhood's differences of one Cube-3 ABC unit (§4, Fig. 9,
//! Eq. 4), bit for bit as `golden_model::cube3::abc::gradient`'s `N26`:
//! every lattice neighbour `S(i, j, l)` of the centre weighted by its
//! inverse Manhattan distance, with 1/3 replaced by 1/4 (the paper's way
//! round the division by 3): the integer weights 4, 2 and 1 for distances
//! 1, 2 and 3 total 16 a side, so
//!
//! ```text
//! G_x = (Σ_{j,l} w(1 + |j| + |l|)·(S(1, j, l) - S(-1, j, l)) + 8) >> 4
//! ```
//!
//! (arithmetic shift), likewise `G_y` over `S(i, ±1, l)` and `G_r` over
//! `S(i, j, ±1)`. The taps are [`super::abc_estimator`]'s: `xp, xm, yp,
//! ym` and the current plane's corners `c{3a + b}` = `S(1 - b, 1 - a, 0)`,
//! and the planes `k ± 1` as `kp`, `km`. Clock 0 registers each weight's
//! partial sum, clock 1 their weighted sum and the rounding half, and the
//! shift leaves combinationally from that register: [`LATENCY`] clocks, as
//! the 6's differences wait before its shear. The sums are 32-bit two's
//! complement: 16 weights of samples below 2^26 cannot overflow them.
//! Only 26-neighbourhood builds instantiate it.

use rust_hdl::prelude::*;

/// Clocks from the taps to the differences.
pub const LATENCY: usize = 2;

/// The weighted differences of the 26 neighbours.
#[derive(LogicBlock, Default)]
pub struct AbcSums26 {
    pub clock: Signal<In, Clock>,
    pub xp: Signal<In, Bits<32>>,
    pub xm: Signal<In, Bits<32>>,
    pub yp: Signal<In, Bits<32>>,
    pub ym: Signal<In, Bits<32>>,
    pub c0: Signal<In, Bits<32>>,
    pub c2: Signal<In, Bits<32>>,
    pub c6: Signal<In, Bits<32>>,
    pub c8: Signal<In, Bits<32>>,
    pub kp0: Signal<In, Bits<32>>,
    pub kp1: Signal<In, Bits<32>>,
    pub kp2: Signal<In, Bits<32>>,
    pub kp3: Signal<In, Bits<32>>,
    pub kp4: Signal<In, Bits<32>>,
    pub kp5: Signal<In, Bits<32>>,
    pub kp6: Signal<In, Bits<32>>,
    pub kp7: Signal<In, Bits<32>>,
    pub kp8: Signal<In, Bits<32>>,
    pub km0: Signal<In, Bits<32>>,
    pub km1: Signal<In, Bits<32>>,
    pub km2: Signal<In, Bits<32>>,
    pub km3: Signal<In, Bits<32>>,
    pub km4: Signal<In, Bits<32>>,
    pub km5: Signal<In, Bits<32>>,
    pub km6: Signal<In, Bits<32>>,
    pub km7: Signal<In, Bits<32>>,
    pub km8: Signal<In, Bits<32>>,
    /// The rounded differences of the taps [`LATENCY`] clocks back.
    pub gx: Signal<Out, Bits<32>>,
    pub gy: Signal<Out, Bits<32>>,
    pub gr: Signal<Out, Bits<32>>,
    /// Clock 0: each axis's differences of weight 4, 2 and 1.
    x4: DFF<Bits<32>>,
    x2: DFF<Bits<32>>,
    x1: DFF<Bits<32>>,
    y4: DFF<Bits<32>>,
    y2: DFF<Bits<32>>,
    y1: DFF<Bits<32>>,
    r4: DFF<Bits<32>>,
    r2: DFF<Bits<32>>,
    r1: DFF<Bits<32>>,
    /// Clock 1: the weighted sums plus the rounding half.
    tx: DFF<Bits<32>>,
    ty: DFF<Bits<32>>,
    tr: DFF<Bits<32>>,
}

impl Logic for AbcSums26 {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, x4, x2, x1, y4, y2, y1, r4, r2, r1, tx, ty, tr);
        // x: S(1, j, l) - S(-1, j, l).
        self.x4.d.next = self.xp.val() - self.xm.val();
        self.x2.d.next = (self.c0.val() - self.c2.val())
            + (self.c6.val() - self.c8.val())
            + (self.kp3.val() - self.kp5.val())
            + (self.km3.val() - self.km5.val());
        self.x1.d.next = (self.kp0.val() - self.kp2.val())
            + (self.kp6.val() - self.kp8.val())
            + (self.km0.val() - self.km2.val())
            + (self.km6.val() - self.km8.val());
        // y: S(i, 1, l) - S(i, -1, l).
        self.y4.d.next = self.yp.val() - self.ym.val();
        self.y2.d.next = (self.c0.val() - self.c6.val())
            + (self.c2.val() - self.c8.val())
            + (self.kp1.val() - self.kp7.val())
            + (self.km1.val() - self.km7.val());
        self.y1.d.next = (self.kp0.val() - self.kp6.val())
            + (self.kp2.val() - self.kp8.val())
            + (self.km0.val() - self.km6.val())
            + (self.km2.val() - self.km8.val());
        // The ray: S(i, j, 1) - S(i, j, -1).
        self.r4.d.next = self.kp4.val() - self.km4.val();
        self.r2.d.next = (self.kp1.val() - self.km1.val())
            + (self.kp3.val() - self.km3.val())
            + (self.kp5.val() - self.km5.val())
            + (self.kp7.val() - self.km7.val());
        self.r1.d.next = (self.kp0.val() - self.km0.val())
            + (self.kp2.val() - self.km2.val())
            + (self.kp6.val() - self.km6.val())
            + (self.kp8.val() - self.km8.val());
        self.tx.d.next = (self.x4.q.val() << 2) + (self.x2.q.val() << 1) + self.x1.q.val() + 8;
        self.ty.d.next = (self.y4.q.val() << 2) + (self.y2.q.val() << 1) + self.y1.q.val() + 8;
        self.tr.d.next = (self.r4.q.val() << 2) + (self.r2.q.val() << 1) + self.r1.q.val() + 8;
        // >> 4, arithmetic.
        self.gx.next = self.tx.q.val() >> 4;
        if self.tx.q.val().get_bit(31) {
            self.gx.next = !((!self.tx.q.val()) >> 4);
        }
        self.gy.next = self.ty.q.val() >> 4;
        if self.ty.q.val().get_bit(31) {
            self.gy.next = !((!self.ty.q.val()) >> 4);
        }
        self.gr.next = self.tr.q.val() >> 4;
        if self.tr.q.val().get_bit(31) {
            self.gr.next = !((!self.tr.q.val()) >> 4);
        }
    }
}
