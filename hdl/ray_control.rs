//! Cube-3's ray control for a parallel view (§2, §3; §5, Fig. 12): which
//! ray, scanline and segment the 2-DSB streams and the TRILIN units are at,
//! the template weights of each unit's sample, and whether the sample lies
//! in the volume.
//!
//! **Counters.** From `start`, the stream counters step through scanlines
//! of `R` rays of `G` segments, one step per `valid` segment (the streams
//! may pause between scanlines); `first` marks a ray's first segment
//! entering the 2-DSB streams. The units work
//! on the ray that entered `trilin_lanes::cell_delay(G) = G + 1` clocks
//! earlier, so their counters are the stream counters through a
//! [`DelayLine`] of that length.
//!
//! **Templates.** A parallel view's weights depend only on the plane
//! (`plan::Template::Parallel`): lane `i`'s weight ROM holds `wx(k)`,
//! `wy(k)` of `k = s·P + i` at address `s`. Whether sample `k` of ray `u`,
//! scanline `v` lies in the volume (`0 <= u + k·dx <= n_x - 1` in fixed
//! point, likewise `y`, and `0 <= k + O <= K - 1`) is, for each `k`, an
//! interval of rays and one of scanlines: lane `i`'s bounds ROM holds them,
//! found by the golden model's own test on every ray and scanline of the
//! stream ([`Cube3Config`](crate::cube3::Cube3Config)). The inner box
//! (`1 <= ... <= n - 2`, where a gradient's neighbourhood stays in the
//! volume) has its own bounds ROM; it is empty, and folded away, for
//! scenes without gradients.

use crate::cube3::Cube3Config;
use crate::delay_line::DelayLine;
use rust_hdl::prelude::*;

/// Address bits of the per-lane ROMs: up to 256 segments a ray.
pub const SEGMENT_BITS: usize = 8;

/// The ray control for `P` lanes (`H`-bit delay-line pointer).
#[derive(LogicBlock)]
pub struct RayControl<const P: usize, const H: usize> {
    pub clock: Signal<In, Clock>,
    /// Restart the counters at the first segment of the first ray.
    pub start: Signal<In, Bit>,
    /// A segment enters the streams this clock (they may pause between
    /// scanlines).
    pub valid: Signal<In, Bit>,
    /// The entering segment starts a ray.
    pub first: Signal<Out, Bit>,
    /// At the units: their segment is valid / a ray's first / a ray's last.
    pub unit_valid: Signal<Out, Bit>,
    pub unit_first: Signal<Out, Bit>,
    pub unit_last: Signal<Out, Bit>,
    /// Each unit's weights and whether its sample is inside (bit `i`).
    pub wx: [Signal<Out, Bits<16>>; P],
    pub wy: [Signal<Out, Bits<16>>; P],
    pub in_volume: Signal<Out, Bits<8>>,
    pub in_inner: Signal<Out, Bits<8>>,
    last_segment: Constant<Bits<16>>,
    last_ray: Constant<Bits<16>>,
    segment: DFF<Bits<16>>,
    ray: DFF<Bits<16>>,
    scanline: DFF<Bits<16>>,
    /// `[valid, segment, ray, scanline]` delayed to the units.
    late: DelayLine<Bits<64>, H>,
    unit_segment: Signal<Local, Bits<16>>,
    unit_ray: Signal<Local, Bits<16>>,
    unit_scanline: Signal<Local, Bits<16>>,
    weights: [ROM<Bits<32>, SEGMENT_BITS>; P],
    bounds: [ROM<Bits<64>, SEGMENT_BITS>; P],
    inner: [ROM<Bits<64>, SEGMENT_BITS>; P],
    /// Lane i's inside and inner bits in place (`lane_bit[i] = 1 << i`).
    lane_in: [Signal<Local, Bits<8>>; 8],
    lane_inner: [Signal<Local, Bits<8>>; 8],
    lane_bit: [Constant<Bits<8>>; 8],
    valid_flag: Constant<Bits<64>>,
}

impl<const P: usize, const H: usize> RayControl<P, H> {
    /// From the pipeline's weights and inside bounds per plane
    /// (`Cube3Config::weights`, `bounds`).
    pub fn new(t: &Cube3Config) -> Result<RayControl<P, H>, String> {
        if P > 8 || t.segments > 1 << SEGMENT_BITS || t.segments + 1 >= 1 << H {
            return Err(format!("rays of {} segments are too long", t.segments));
        }
        let segments = t.segments;
        let weight = |k: usize| {
            t.weights
                .get(k)
                .map_or(0, |[x, y]| *x as u64 | (*y as u64) << 16)
        };
        let bound = |b: &[[u32; 4]], k: usize| {
            let [rl, rh, vl, vh] = b.get(k).copied().unwrap_or([1, 0, 1, 0]);
            rl as u64 | (rh as u64) << 16 | (vl as u64) << 32 | (vh as u64) << 48
        };
        let rom = |b: &[[u32; 4]], i: usize| -> ROM<Bits<64>, SEGMENT_BITS> {
            (0..segments)
                .map(|s| bound(b, s * P + i).to_bits::<64>())
                .into()
        };
        Ok(RayControl {
            clock: Default::default(),
            start: Default::default(),
            valid: Default::default(),
            first: Default::default(),
            unit_valid: Default::default(),
            unit_first: Default::default(),
            unit_last: Default::default(),
            wx: std::array::from_fn(|_| Default::default()),
            wy: std::array::from_fn(|_| Default::default()),
            in_volume: Default::default(),
            in_inner: Default::default(),
            last_segment: Constant::new(((t.segments - 1) as u64).to_bits()),
            last_ray: Constant::new(((t.rays - 1) as u64).to_bits()),
            segment: Default::default(),
            ray: Default::default(),
            scanline: Default::default(),
            late: DelayLine::new(
                crate::trilin_lanes::cell_delay(t.segments),
                &[],
                u64::MAX.to_bits(),
            ),
            unit_segment: Default::default(),
            unit_ray: Default::default(),
            unit_scanline: Default::default(),
            weights: std::array::from_fn(|i| {
                (0..segments)
                    .map(|s| weight(s * P + i).to_bits::<32>())
                    .into()
            }),
            bounds: std::array::from_fn(|i| rom(&t.bounds, i)),
            inner: std::array::from_fn(|i| rom(&t.inner, i)),
            lane_in: Default::default(),
            lane_inner: Default::default(),
            lane_bit: std::array::from_fn(|i| Constant::new((1u64 << i).to_bits())),
            valid_flag: Constant::new((1u64 << 48).to_bits()),
        })
    }
}

impl<const P: usize, const H: usize> Logic for RayControl<P, H> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, segment, ray, scanline);
        self.late.clock.next = self.clock.val();
        self.late.write_enable.next = true;
        // The stream counters: segment, ray, scanline of the entering
        // segment, stepped by each valid one.
        if self.valid.val() {
            self.segment.d.next = self.segment.q.val() + 1;
            if self.segment.q.val() == self.last_segment.val() {
                self.segment.d.next = 0.into();
                self.ray.d.next = self.ray.q.val() + 1;
                if self.ray.q.val() == self.last_ray.val() {
                    self.ray.d.next = 0.into();
                    self.scanline.d.next = self.scanline.q.val() + 1;
                }
            }
        }
        if self.start.val() {
            self.segment.d.next = 0.into();
            self.ray.d.next = 0.into();
            self.scanline.d.next = 0.into();
        }
        self.first.next = self.valid.val() & !self.segment.q.val().any();
        self.late.data_in.next = bit_cast::<64, 16>(self.segment.q.val())
            | (bit_cast::<64, 16>(self.ray.q.val()) << 16)
            | (bit_cast::<64, 16>(self.scanline.q.val()) << 32);
        if self.valid.val() {
            self.late.data_in.next = bit_cast::<64, 16>(self.segment.q.val())
                | (bit_cast::<64, 16>(self.ray.q.val()) << 16)
                | (bit_cast::<64, 16>(self.scanline.q.val()) << 32)
                | self.valid_flag.val();
        }
        // At the units.
        self.unit_segment.next = self.late.data_out.val().get_bits::<16>(0);
        self.unit_ray.next = self.late.data_out.val().get_bits::<16>(16);
        self.unit_scanline.next = self.late.data_out.val().get_bits::<16>(32);
        self.unit_valid.next = self.late.data_out.val().get_bit(48);
        self.unit_first.next =
            self.late.data_out.val().get_bit(48) & !self.unit_segment.val().any();
        self.unit_last.next = self.late.data_out.val().get_bit(48)
            & (self.unit_segment.val() == self.last_segment.val());
        for i in 0..8 {
            self.lane_in[i].next = 0.into();
            self.lane_inner[i].next = 0.into();
        }
        for i in 0..P {
            self.weights[i].address.next = self.unit_segment.val().get_bits::<SEGMENT_BITS>(0);
            self.bounds[i].address.next = self.unit_segment.val().get_bits::<SEGMENT_BITS>(0);
            self.wx[i].next = self.weights[i].data.val().get_bits::<16>(0);
            self.wy[i].next = self.weights[i].data.val().get_bits::<16>(16);
            if (self.unit_ray.val() >= self.bounds[i].data.val().get_bits::<16>(0))
                & (self.unit_ray.val() <= self.bounds[i].data.val().get_bits::<16>(16))
                & (self.unit_scanline.val() >= self.bounds[i].data.val().get_bits::<16>(32))
                & (self.unit_scanline.val() <= self.bounds[i].data.val().get_bits::<16>(48))
            {
                self.lane_in[i].next = self.lane_bit[i].val();
            }
            self.inner[i].address.next = self.unit_segment.val().get_bits::<SEGMENT_BITS>(0);
            if (self.unit_ray.val() >= self.inner[i].data.val().get_bits::<16>(0))
                & (self.unit_ray.val() <= self.inner[i].data.val().get_bits::<16>(16))
                & (self.unit_scanline.val() >= self.inner[i].data.val().get_bits::<16>(32))
                & (self.unit_scanline.val() <= self.inner[i].data.val().get_bits::<16>(48))
            {
                self.lane_inner[i].next = self.lane_bit[i].val();
            }
        }
        self.in_volume.next = self.lane_in[0].val()
            | self.lane_in[1].val()
            | self.lane_in[2].val()
            | self.lane_in[3].val()
            | self.lane_in[4].val()
            | self.lane_in[5].val()
            | self.lane_in[6].val()
            | self.lane_in[7].val();
        self.in_inner.next = self.lane_inner[0].val()
            | self.lane_inner[1].val()
            | self.lane_inner[2].val()
            | self.lane_inner[3].val()
            | self.lane_inner[4].val()
            | self.lane_inner[5].val()
            | self.lane_inner[6].val()
            | self.lane_inner[7].val();
    }
}
