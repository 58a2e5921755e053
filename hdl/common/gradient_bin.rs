//! The gradient-magnitude bin of the two-dimensional opacity LUT (Cube-4L
//! §3.4, gradient opacity; Cube-3's shading units), bit for bit as
//! `golden_model::lut::OpacityLut::lookup`'s `min(15, isqrt(n) >> s)` for
//! `n = gx² + gy² + gz²` and the host's shift `s`, without a square root:
//! `isqrt(n) >> s >= k` exactly when `n >> 2s >= k²`, so the bin counts the
//! `k` in 1..=15 with `n >> 2s >= k²`. Three register stages: the squares,
//! their sum, the bin.

use super::regs::{Regs, ADDRESS_BITS};
use super::square::Square;
use golden_model::host::Reg;
use rust_hdl::prelude::*;

/// Clocks from the gradient to its bin.
pub const LATENCY: usize = 3;

#[derive(LogicBlock)]
pub struct GradientBin {
    pub clock: Signal<In, Clock>,
    pub host_write: Signal<In, Bit>,
    pub host_address: Signal<In, Bits<ADDRESS_BITS>>,
    pub host_data: Signal<In, Bits<64>>,
    /// Gradient magnitudes (below `2^31`).
    pub mag: [Signal<In, Bits<32>>; 3],
    /// The bin, [`LATENCY`] clocks later.
    pub bin: Signal<Out, Bits<4>>,
    /// The shift `s` (`Reg::GmShift`).
    regs: Regs<1>,
    sq: [Square; 3],
    sq_q: [DFF<Bits<64>>; 3],
    n_q: DFF<Bits<64>>,
    m: Signal<Local, Bits<64>>,
    /// `k²` for k = 1..=15.
    k2: [Constant<Bits<64>>; 15],
    count: Signal<Local, Bits<4>>,
    bin_q: DFF<Bits<4>>,
}

impl GradientBin {
    /// `wide`: magnitudes beyond 16 bits (Cube-3's gradients).
    pub fn new(wide: bool) -> GradientBin {
        GradientBin {
            clock: Default::default(),
            host_write: Default::default(),
            host_address: Default::default(),
            host_data: Default::default(),
            mag: Default::default(),
            bin: Default::default(),
            regs: Regs::new([Reg::GmShift.address()]),
            sq: std::array::from_fn(|_| Square::new(wide)),
            sq_q: Default::default(),
            n_q: Default::default(),
            m: Default::default(),
            k2: std::array::from_fn(|k| Constant::new((((k + 1) * (k + 1)) as u64).to_bits())),
            count: Default::default(),
            bin_q: Default::default(),
        }
    }
}

impl Logic for GradientBin {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, n_q, bin_q);
        self.regs.clock.next = self.clock.val();
        self.regs.host_write.next = self.host_write.val();
        self.regs.host_address.next = self.host_address.val();
        self.regs.host_data.next = self.host_data.val();
        // Stage 1: the squares; stage 2: their sum.
        for i in 0..3 {
            self.sq[i].m.next = self.mag[i].val();
            self.sq_q[i].clock.next = self.clock.val();
            self.sq_q[i].d.next = self.sq[i].y.val();
        }
        self.n_q.d.next = self.sq_q[0].q.val() + self.sq_q[1].q.val() + self.sq_q[2].q.val();
        // Stage 3: n >> 2s against the squares of 1..=15.
        self.m.next = self.n_q.q.val() >> (self.regs.q[0].val().get_bits::<8>(0) << 1);
        self.count.next = 0.into();
        for k in 0..15 {
            if self.m.val() >= self.k2[k].val() {
                self.count.next = self.count.val() + 1;
            }
        }
        self.bin_q.d.next = self.count.val();
        self.bin.next = self.bin_q.q.val();
    }
}
