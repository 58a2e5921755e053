//! The gradient half of Cube-3's ABC shading units (§4; §5, Fig. 12): `P`
//! lanes take the TRILIN units' samples, one per lane per clock, and put out
//! each sample's gradient word, bit for bit as
//! `golden_model::cube3::abc::gradient` (6-, 10-, 12- or 26-neighbourhood;
//! the 10's weights and basis correction are the host's registers).
//!
//! **Stream.** Sample planes arrive scanline after scanline, ray after ray
//! (`R` rays of a scanline, a scanline every `T >= R·G` clocks), each ray
//! as `G = ceil(K / P)` segments on consecutive clocks, lane `i` holding
//! sample `s·P + i` of segment `s`. So the sample of ray `u ± 1` is `G`
//! clocks away in the same lane, that of scanline `v ± 1` is `T` clocks
//! away, and sample `k ± 1` is in the
//! neighbouring lane, or, across a segment boundary, in lane `0` one clock
//! later or lane `P - 1` one clock earlier.
//!
//! **Taps.** Each lane keeps its stream in a [`PlaneTaps`] (two sample
//! planes and two rays of memory: the above and current planes while the
//! below one arrives). The centre of the neighbourhood is tap `(1, 1, 1)`,
//! [`centre`]` = T + G + 1` clocks after its sample came in; the lanes'
//! taps are wired to each [`AbcEstimator`] as its `S(i, j, 0)` and `S(i, j, ±1)`, and its
//! gradient word leaves `abc_estimator::LATENCY` clocks later, beside the
//! centre sample (`sample`). The centre
//! ray's increments `DX`, `DY` come in with the centre (the ray control).
//!
//! Where a neighbour lies outside the scanline's rays or the ray's samples
//! the taps hold another ray's samples: the golden model takes no gradient
//! there (its shader leaves such samples transparent, the inner-box rule).

use super::abc_estimator::AbcEstimator;
use super::plane_taps::PlaneTaps;
use crate::common::regs::{Regs, ADDRESS_BITS};
use golden_model::cube3::plan::Neighbourhood;
use golden_model::host::Reg;
use rust_hdl::prelude::*;

/// Clocks from a sample's entry to its neighbourhood's centre tap.
pub fn centre(scanline: usize, segments: usize) -> usize {
    scanline + segments + 1
}

/// `P` lanes of gradient estimation, `H`-bit delay-line pointers.
#[derive(LogicBlock)]
pub struct AbcUnit<const P: usize, const H: usize> {
    pub clock: Signal<In, Clock>,
    /// The host port: the 10's registers.
    pub host_write: Signal<In, Bit>,
    pub host_address: Signal<In, Bits<ADDRESS_BITS>>,
    pub host_data: Signal<In, Bits<64>>,
    /// The sample-plane lines' lengths less one (`PlaneTaps`).
    pub ray_last: Signal<In, Bits<H>>,
    pub line_last: Signal<In, Bits<H>>,
    pub sample: [Signal<In, Bits<32>>; P],
    /// The increments of the ray at the centre tap.
    pub dx_neg: Signal<In, Bit>,
    pub dx_mag: Signal<In, Bits<16>>,
    pub dy_neg: Signal<In, Bit>,
    pub dy_mag: Signal<In, Bits<16>>,
    /// The centre sample leaving with its gradient.
    pub centre: [Signal<Out, Bits<32>>; P],
    pub gx: [Signal<Out, Bits<32>>; P],
    pub gy: [Signal<Out, Bits<32>>; P],
    pub gz: [Signal<Out, Bits<32>>; P],
    lanes: [PlaneTaps<H>; P],
    estimators: [AbcEstimator; P],
    /// The 10: `C3Weights10`, `C3Basis10X/Y/Z`.
    pub(crate) regs10: Regs<4>,
    /// Without it the outputs read 0, as in emitted Verilog that leaves the
    /// unit out (`export::prune`).
    enabled: Constant<Bit>,
}

impl<const P: usize, const H: usize> AbcUnit<P, H> {
    const LAST: usize = P - 1;
    /// `for p in Self::P..Self::P_END` runs once with `p = P`: rust-hdl's
    /// Verilog generator evaluates an array index from loop variables and
    /// literals only.
    const P: usize = P;
    const P_END: usize = P + 1;

    /// For a scanline every `scanline` clocks and rays of `segments` at
    /// most, with the gradients of neighbourhood `n`.
    pub fn new(
        scanline: usize,
        segments: usize,
        n: Neighbourhood,
        weight_bits: u32,
        sample_bits: u32,
        gradient_bits: u32,
    ) -> Result<AbcUnit<P, H>, String> {
        AbcUnit::build(
            scanline,
            segments,
            n,
            weight_bits,
            sample_bits,
            gradient_bits,
            true,
        )
    }

    /// The unit of a scene that takes no gradient: outputs 0, shortest
    /// lines.
    pub fn left_out(segments: usize) -> Result<AbcUnit<P, H>, String> {
        let g = segments.max(3);
        AbcUnit::build(2 * g + 3, g, Neighbourhood::N6, 8, 8, 9, false)
    }

    fn build(
        scanline: usize,
        segments: usize,
        n: Neighbourhood,
        weight_bits: u32,
        sample_bits: u32,
        gradient_bits: u32,
        enabled: bool,
    ) -> Result<AbcUnit<P, H>, String> {
        let mut lanes = Vec::with_capacity(P);
        let mut estimators = Vec::with_capacity(P);
        for _ in 0..P {
            lanes.push(PlaneTaps::new(scanline, segments)?);
            estimators.push(AbcEstimator::new(
                n,
                weight_bits,
                gradient_bits,
                sample_bits > 16,
            )?);
        }
        Ok(AbcUnit {
            clock: Default::default(),
            host_write: Default::default(),
            host_address: Default::default(),
            host_data: Default::default(),
            ray_last: Default::default(),
            line_last: Default::default(),
            sample: std::array::from_fn(|_| Default::default()),
            dx_neg: Default::default(),
            dx_mag: Default::default(),
            dy_neg: Default::default(),
            dy_mag: Default::default(),
            centre: std::array::from_fn(|_| Default::default()),
            gx: std::array::from_fn(|_| Default::default()),
            gy: std::array::from_fn(|_| Default::default()),
            gz: std::array::from_fn(|_| Default::default()),
            lanes: lanes.try_into().ok().expect("P lanes"),
            estimators: estimators.try_into().ok().expect("P estimators"),
            regs10: Regs::new(
                [
                    Reg::C3Weights10,
                    Reg::C3Basis10X,
                    Reg::C3Basis10Y,
                    Reg::C3Basis10Z,
                ]
                .map(Reg::address),
            ),
            enabled: Constant::new(enabled),
        })
    }

    /// Bits of block RAM in the sample-plane lines.
    pub fn memory_bits(&self) -> usize {
        self.lanes.iter().map(|l| l.memory_bits()).sum()
    }
}

impl<const P: usize, const H: usize> Logic for AbcUnit<P, H> {
    #[hdl_gen]
    fn update(&mut self) {
        self.regs10.clock.next = self.clock.val();
        self.regs10.host_write.next = self.host_write.val();
        self.regs10.host_address.next = self.host_address.val();
        self.regs10.host_data.next = self.host_data.val();
        for i in 0..P {
            self.estimators[i].weights10.next = self.regs10.q[0].val();
            self.estimators[i].basis10_x.next = self.regs10.q[1].val();
            self.estimators[i].basis10_y.next = self.regs10.q[2].val();
            self.estimators[i].basis10_z.next = self.regs10.q[3].val();
            self.lanes[i].clock.next = self.clock.val();
            self.lanes[i].ray_last.next = self.ray_last.val();
            self.lanes[i].line_last.next = self.line_last.val();
            self.estimators[i].clock.next = self.clock.val();
            self.lanes[i].sample.next = self.sample[i].val();
            // The lane's own taps: S(±1, 0, 0) at (1, 0 | 2, 1), S(0, ±1, 0)
            // at (0 | 2, 1, 1).
            self.estimators[i].xp.next = self.lanes[i].t101.val();
            self.estimators[i].xm.next = self.lanes[i].t121.val();
            self.estimators[i].yp.next = self.lanes[i].t011.val();
            self.estimators[i].ym.next = self.lanes[i].t211.val();
            // The current plane's corners S(±1, ±1, 0) (the 26).
            self.estimators[i].c0.next = self.lanes[i].t001.val();
            self.estimators[i].c2.next = self.lanes[i].t021.val();
            self.estimators[i].c6.next = self.lanes[i].t201.val();
            self.estimators[i].c8.next = self.lanes[i].t221.val();
            self.estimators[i].dx_neg.next = self.dx_neg.val();
            self.estimators[i].dx_mag.next = self.dx_mag.val();
            self.estimators[i].dy_neg.next = self.dy_neg.val();
            self.estimators[i].dy_mag.next = self.dy_mag.val();
            self.estimators[i].centre.next = self.lanes[i].t111.val();
            self.centre[i].next = 0.into();
            self.gx[i].next = 0.into();
            self.gy[i].next = 0.into();
            self.gz[i].next = 0.into();
            if self.enabled.val() {
                self.centre[i].next = self.estimators[i].sample.val();
                self.gx[i].next = self.estimators[i].gx.val();
                self.gy[i].next = self.estimators[i].gy.val();
                self.gz[i].next = self.estimators[i].gz.val();
            }
        }
        // Plane k + 1: the next lane, and lane 0 one clock later for the last.
        for i in 0..Self::LAST {
            self.estimators[i].kp0.next = self.lanes[i + 1].t001.val();
            self.estimators[i].kp1.next = self.lanes[i + 1].t011.val();
            self.estimators[i].kp2.next = self.lanes[i + 1].t021.val();
            self.estimators[i].kp3.next = self.lanes[i + 1].t101.val();
            self.estimators[i].kp4.next = self.lanes[i + 1].t111.val();
            self.estimators[i].kp5.next = self.lanes[i + 1].t121.val();
            self.estimators[i].kp6.next = self.lanes[i + 1].t201.val();
            self.estimators[i].kp7.next = self.lanes[i + 1].t211.val();
            self.estimators[i].kp8.next = self.lanes[i + 1].t221.val();
        }
        // Plane k - 1: the previous lane, and lane P - 1 one clock earlier
        // for the first.
        for i in 1..P {
            self.estimators[i].km0.next = self.lanes[i - 1].t001.val();
            self.estimators[i].km1.next = self.lanes[i - 1].t011.val();
            self.estimators[i].km2.next = self.lanes[i - 1].t021.val();
            self.estimators[i].km3.next = self.lanes[i - 1].t101.val();
            self.estimators[i].km4.next = self.lanes[i - 1].t111.val();
            self.estimators[i].km5.next = self.lanes[i - 1].t121.val();
            self.estimators[i].km6.next = self.lanes[i - 1].t201.val();
            self.estimators[i].km7.next = self.lanes[i - 1].t211.val();
            self.estimators[i].km8.next = self.lanes[i - 1].t221.val();
        }
        for p in Self::P..Self::P_END {
            self.estimators[p - 1].kp0.next = self.lanes[0].t000.val();
            self.estimators[p - 1].kp1.next = self.lanes[0].t010.val();
            self.estimators[p - 1].kp2.next = self.lanes[0].t020.val();
            self.estimators[p - 1].kp3.next = self.lanes[0].t100.val();
            self.estimators[p - 1].kp4.next = self.lanes[0].t110.val();
            self.estimators[p - 1].kp5.next = self.lanes[0].t120.val();
            self.estimators[p - 1].kp6.next = self.lanes[0].t200.val();
            self.estimators[p - 1].kp7.next = self.lanes[0].t210.val();
            self.estimators[p - 1].kp8.next = self.lanes[0].t220.val();
            self.estimators[0].km0.next = self.lanes[p - 1].t002.val();
            self.estimators[0].km1.next = self.lanes[p - 1].t012.val();
            self.estimators[0].km2.next = self.lanes[p - 1].t022.val();
            self.estimators[0].km3.next = self.lanes[p - 1].t102.val();
            self.estimators[0].km4.next = self.lanes[p - 1].t112.val();
            self.estimators[0].km5.next = self.lanes[p - 1].t122.val();
            self.estimators[0].km6.next = self.lanes[p - 1].t202.val();
            self.estimators[0].km7.next = self.lanes[p - 1].t212.val();
            self.estimators[0].km8.next = self.lanes[p - 1].t222.val();
        }
    }
}
