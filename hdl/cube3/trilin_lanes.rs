//! The read side of Cube-3's 2-D skewed buffers and the `P` TRILIN units
//! (§3, Fig. 4; §5, Fig. 12): from the PRPs of scanlines `v` and `v + 1`,
//! streamed ray by ray, each unit gets the eight voxels of its sample and
//! interpolates it ([`Trilin`]), bit for bit as
//! `golden_model::cube3::trilin::plane`.
//!
//! **Streams.** `cur` and `next` are the 2-DSBs of scanlines `v` and `v +
//! 1` read conflict-free a segment per clock: ray after ray (`G` clocks a
//! ray), lane `i` holding plane `s·P + i` of segment `s` (the buffer's skew
//! puts those planes in `P` different modules), 0 beyond plane `K`.
//!
//! **Cells.** Unit `i` interpolates sample `k = s·P + i` of ray `u` when ray
//! `u + 1` is entering: ray `u`'s voxels (A from `cur`, C from `next`) are
//! taken `G + 1` clocks after they came in, ray `u + 1`'s (B, D) one clock
//! after. Plane `k + 1` is the next lane's, or for lane `P - 1` lane 0's of
//! the following clock (the next segment), which is the plane behind the
//! volume and reads 0 when that segment starts another ray (`first`). Each
//! lane and buffer keeps a register, a [`DelayLine`] of `G - 1` clocks and
//! another register.
//!
//! The weights `wx(u, k)`, `wy(v, k)` come from the ray control with the
//! cell (the templates of `plan`); the offset is the view's. The sample of
//! the cell taken at clock `t` leaves at `t + trilin::LATENCY`.

use super::trilin::Trilin;
use crate::common::delay_line::DelayLine;
use rust_hdl::prelude::*;

/// Clocks from a ray's voxels entering to its cells reaching the units.
pub fn cell_delay(segments: usize) -> usize {
    segments + 1
}

/// `P` TRILIN units fed from two 2-DSB streams (`H`-bit pointers).
#[derive(LogicBlock)]
pub struct TrilinLanes<const P: usize, const H: usize> {
    pub clock: Signal<In, Clock>,
    pub cur: [Signal<In, Bits<16>>; P],
    pub next: [Signal<In, Bits<16>>; P],
    /// The entering segment is the first of its ray.
    pub first: Signal<In, Bit>,
    /// The weights of each unit's cell this clock.
    pub wx: [Signal<In, Bits<16>>; P],
    pub wy: [Signal<In, Bits<16>>; P],
    pub sample: [Signal<Out, Bits<32>>; P],
    /// The view's offset `O` and the lines' length less one, `G - 2`
    /// (the pipeline's registers).
    pub offset: Signal<In, Bits<16>>,
    pub line_last: Signal<In, Bits<H>>,
    /// Ray u + 1 (one clock) and ray u (G + 1 clocks) of each stream.
    cur_b: [DFF<Bits<16>>; P],
    cur_line: [DelayLine<Bits<16>, H>; P],
    cur_a: [DFF<Bits<16>>; P],
    next_b: [DFF<Bits<16>>; P],
    next_line: [DelayLine<Bits<16>, H>; P],
    next_a: [DFF<Bits<16>>; P],
    /// Plane k + 1 of lane P - 1: lane 0 one clock later, 0 across rays.
    wrap_cur_b: Signal<Local, Bits<16>>,
    wrap_cur_a: Signal<Local, Bits<16>>,
    wrap_next_b: Signal<Local, Bits<16>>,
    wrap_next_a: Signal<Local, Bits<16>>,
    pub(crate) units: [Trilin; P],
}

impl<const P: usize, const H: usize> TrilinLanes<P, H> {
    const LAST: usize = P - 1;
    /// `for p in Self::P..Self::P_END` runs once with `p = P`: rust-hdl's
    /// Verilog generator evaluates an array index from loop variables and
    /// literals only.
    const P: usize = P;
    const P_END: usize = P + 1;

    /// For rays of up to `segments` clocks (at least 2: more planes than
    /// units).
    pub fn new(
        segments: usize,
        weight_bits: u32,
        voxel_bits: u32,
        sample_frac: u32,
    ) -> Result<TrilinLanes<P, H>, String> {
        if segments < 2 || segments >= 1 << H {
            return Err(format!(
                "the 2-DSB streams need rays of 2 to 2^{H} clocks, not {segments}: more planes than TRILIN units"
            ));
        }
        let line = || DelayLine::new(segments - 1, &[], 0xffffu64.to_bits());
        Ok(TrilinLanes {
            clock: Default::default(),
            cur: std::array::from_fn(|_| Default::default()),
            next: std::array::from_fn(|_| Default::default()),
            first: Default::default(),
            wx: std::array::from_fn(|_| Default::default()),
            wy: std::array::from_fn(|_| Default::default()),
            sample: std::array::from_fn(|_| Default::default()),
            offset: Default::default(),
            line_last: Default::default(),
            cur_b: std::array::from_fn(|_| Default::default()),
            cur_line: std::array::from_fn(|_| line()),
            cur_a: std::array::from_fn(|_| Default::default()),
            next_b: std::array::from_fn(|_| Default::default()),
            next_line: std::array::from_fn(|_| line()),
            next_a: std::array::from_fn(|_| Default::default()),
            wrap_cur_b: Default::default(),
            wrap_cur_a: Default::default(),
            wrap_next_b: Default::default(),
            wrap_next_a: Default::default(),
            units: std::array::from_fn(|_| Trilin::new(weight_bits, voxel_bits, sample_frac)),
        })
    }
}

impl<const P: usize, const H: usize> Logic for TrilinLanes<P, H> {
    #[hdl_gen]
    fn update(&mut self) {
        // The streams' delays: B one clock, the line, A G + 1 clocks.
        for i in 0..P {
            self.cur_b[i].clock.next = self.clock.val();
            self.cur_a[i].clock.next = self.clock.val();
            self.next_b[i].clock.next = self.clock.val();
            self.next_a[i].clock.next = self.clock.val();
            self.cur_line[i].clock.next = self.clock.val();
            self.next_line[i].clock.next = self.clock.val();
            self.units[i].clock.next = self.clock.val();
            self.cur_line[i].last.next = self.line_last.val();
            self.next_line[i].last.next = self.line_last.val();
            self.cur_line[i].write_enable.next = true;
            self.next_line[i].write_enable.next = true;
            self.cur_b[i].d.next = self.cur[i].val();
            self.cur_line[i].data_in.next = self.cur_b[i].q.val();
            self.cur_a[i].d.next = self.cur_line[i].data_out.val();
            self.next_b[i].d.next = self.next[i].val();
            self.next_line[i].data_in.next = self.next_b[i].q.val();
            self.next_a[i].d.next = self.next_line[i].data_out.val();
            // Plane k of rays A, B, C, D; the weights.
            self.units[i].a0.next = self.cur_a[i].q.val();
            self.units[i].b0.next = self.cur_b[i].q.val();
            self.units[i].c0.next = self.next_a[i].q.val();
            self.units[i].d0.next = self.next_b[i].q.val();
            self.units[i].offset.next = self.offset.val();
            self.units[i].wx.next = self.wx[i].val();
            self.units[i].wy.next = self.wy[i].val();
            self.sample[i].next = self.units[i].sample.val();
        }
        // Plane k + 1: the next lane's ...
        for i in 0..Self::LAST {
            self.units[i].a1.next = self.cur_a[i + 1].q.val();
            self.units[i].b1.next = self.cur_b[i + 1].q.val();
            self.units[i].c1.next = self.next_a[i + 1].q.val();
            self.units[i].d1.next = self.next_b[i + 1].q.val();
        }
        // ... and for the last lane, lane 0 of the next segment: the line's
        // output for rays A and C, the entering voxel for B and D.
        self.wrap_cur_a.next = self.cur_line[0].data_out.val();
        self.wrap_cur_b.next = self.cur[0].val();
        self.wrap_next_a.next = self.next_line[0].data_out.val();
        self.wrap_next_b.next = self.next[0].val();
        if self.first.val() {
            self.wrap_cur_a.next = 0.into();
            self.wrap_cur_b.next = 0.into();
            self.wrap_next_a.next = 0.into();
            self.wrap_next_b.next = 0.into();
        }
        for p in Self::P..Self::P_END {
            self.units[p - 1].a1.next = self.wrap_cur_a.val();
            self.units[p - 1].b1.next = self.wrap_cur_b.val();
            self.units[p - 1].c1.next = self.wrap_next_a.val();
            self.units[p - 1].d1.next = self.wrap_next_b.val();
        }
    }
}
