//! Cube-3's ray control (§2, §3; §5, Fig. 12): which ray, scanline and
//! segment the 2-DSB streams and the TRILIN units are at, the template
//! weights of each unit's sample, whether the sample lies in the volume,
//! whether the ray is cast on this base plane, and the increments of the
//! ABC units' centre ray.
//!
//! **Counters.** From `start`, the stream counters step through scanlines
//! of `R` rays of `G` segments, one step per `valid` segment (the streams
//! may pause between scanlines); `first` marks a ray's first segment
//! entering the 2-DSB streams. The units work
//! on the ray that entered `trilin_lanes::cell_delay(G) = G + 1` clocks
//! earlier, so their counters are the stream counters through a
//! [`RegisteredLine`] of that length (its block RAM's read ends in a
//! register, not in the tables it addresses).
//!
//! **The view.** Every view-dependent value here is the host's: the
//! stream's rays and segments, the cast rays and the delay lines' lengths
//! are registers (`C3Stream`, `C3Address`, `C3Cast`, `C3Delays`), the
//! templates, bounds and increments tables ([`ViewRom`]s, read in the
//! clock they are addressed, as the ROMs of a design built for one view
//! were). The build holds the largest view of its class
//! ([`Cube3Sizes`]).
//!
//! **Templates.** A parallel view's weights depend only on the plane
//! (`plan::Template::Parallel`): lane `i`'s `wx` table holds `wx(k)` of `k =
//! s·P + i` at address `s`. A perspective view's depend on the ray too (the
//! paper's n² template entries): `wx(u, k)` at address `r·G + s` for stream
//! ray `r`; `wy` likewise by scanline. (The stride, a register, is `G`
//! for a perspective view and 0 for a parallel one.) Whether sample `k` of ray `u`,
//! scanline `v` lies in the volume (`0 <= u·2^W + k·DX(u) <= (n_x - 1)·2^W`,
//! likewise `y`, and `0 <= k + O <= K - 1`) is, for each `k`, an interval
//! of rays and one of scanlines (the positions grow with the ray in either
//! projection): lane `i`'s bounds table holds them, found by the golden
//! model's own test on every ray and scanline of the stream
//! ([`Cube3Config`](super::config::Cube3Config)). The inner box (`1 <=
//! ... <= n - 2`, where a gradient's neighbourhood stays in the volume) has
//! its own bounds table, unused (and removed by synthesis) without
//! gradients.
//!
//! **Cast rays.** A perspective ray steeper than 45° (`|DX| > 2^W`)
//! belongs to another base plane: `unit_cast` is low for it, an interval of
//! rays and one of scanlines. Every parallel ray is cast.
//!
//! **Increments.** The ABC units take the increments `DX(u)`, `DY(v)` of
//! the ray at their centre tap, which came in
//! `abc_unit::centre(T, G) = T + G + 1` clocks before the sample now
//! entering them: the units' counters
//! a further `trilin::LATENCY + G + 1` clocks late (a second delay line)
//! name the centre's ray, and its scanline is one less (the scanlines
//! enter every `T` clocks). Tables by ray and scanline hold the increments;
//! a parallel view's one entry is read at address 0.

use super::config::{Cube3Sizes, SEGMENT_BITS, TEMPLATE_BITS};
use super::increments::Increments;
use super::templates::Templates;
use crate::common::registered_line::RegisteredLine;
use crate::common::regs::{Regs, ADDRESS_BITS};
use crate::common::view_rom::ViewRom;
use golden_model::host::{Reg, ViewTable};
use rust_hdl::prelude::*;

/// The ray control for `P` lanes (`H`-bit delay-line pointer).
#[derive(LogicBlock)]
pub struct RayControl<const P: usize, const H: usize> {
    pub clock: Signal<In, Clock>,
    /// The host port: the view's registers and tables.
    pub host_write: Signal<In, Bit>,
    pub host_address: Signal<In, Bits<ADDRESS_BITS>>,
    pub host_data: Signal<In, Bits<64>>,
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
    /// The units' ray is cast on this base plane.
    pub unit_cast: Signal<Out, Bit>,
    /// Each unit's weights and whether its sample is inside (bit `i`).
    pub wx: [Signal<Out, Bits<16>>; P],
    pub wy: [Signal<Out, Bits<16>>; P],
    pub in_volume: Signal<Out, Bits<8>>,
    pub in_inner: Signal<Out, Bits<8>>,
    /// The increments of the ABC units' centre ray, sign and magnitude.
    pub dx_neg: Signal<Out, Bit>,
    pub dx_mag: Signal<Out, Bits<16>>,
    pub dy_neg: Signal<Out, Bit>,
    pub dy_mag: Signal<Out, Bits<16>>,
    /// `C3Stream`, `C3Address`, `C3Cast`, `C3Delays`.
    regs: Regs<4>,
    last_segment: Signal<Local, Bits<16>>,
    last_ray: Signal<Local, Bits<16>>,
    segment: DFF<Bits<16>>,
    ray: DFF<Bits<16>>,
    scanline: DFF<Bits<16>>,
    /// `[valid, segment, ray, scanline]` delayed to the units.
    late: RegisteredLine<Bits<64>, H>,
    unit_segment: Signal<Local, Bits<16>>,
    unit_ray: Signal<Local, Bits<16>>,
    unit_scanline: Signal<Local, Bits<16>>,
    templates: Templates<P>,
    /// Cast rays and scanlines `[lo, hi]`, inclusive.
    /// (`x - lo <= hi - lo`, wrapping: one unsigned compare.)
    cast_ray_lo: Signal<Local, Bits<16>>,
    cast_ray_span: Signal<Local, Bits<16>>,
    cast_line_lo: Signal<Local, Bits<16>>,
    cast_line_span: Signal<Local, Bits<16>>,
    per_ray: Constant<Bit>,
    increments: Increments<H>,
    bounds: [ViewRom<64, SEGMENT_BITS>; P],
    inner: [ViewRom<64, SEGMENT_BITS>; P],
    /// Lane i's inside and inner bits in place (`lane_bit[i] = 1 << i`).
    lane_in: [Signal<Local, Bits<8>>; 8],
    lane_inner: [Signal<Local, Bits<8>>; 8],
    lane_bit: [Constant<Bits<8>>; 8],
    valid_flag: Constant<Bits<64>>,
}

impl<const P: usize, const H: usize> RayControl<P, H> {
    /// For the views of `s`.
    pub fn new(s: &Cube3Sizes) -> Result<RayControl<P, H>, String> {
        let segments = s.segments();
        let centre_delay = super::trilin::LATENCY + segments + 1;
        if P > 8 || segments > 1 << SEGMENT_BITS || centre_delay >= 1 << H {
            return Err(format!("rays of {segments} segments are too long"));
        }
        if s.perspective && s.scanlines() * segments > 1 << TEMPLATE_BITS {
            return Err(format!(
                "{} rays and {} scanlines of {segments} segments: the templates hold at most 2^{TEMPLATE_BITS} weights a unit",
                s.rays(),
                s.scanlines()
            ));
        }
        Ok(RayControl {
            clock: Default::default(),
            host_write: Default::default(),
            host_address: Default::default(),
            host_data: Default::default(),
            start: Default::default(),
            valid: Default::default(),
            first: Default::default(),
            unit_valid: Default::default(),
            unit_first: Default::default(),
            unit_last: Default::default(),
            unit_cast: Default::default(),
            wx: std::array::from_fn(|_| Default::default()),
            wy: std::array::from_fn(|_| Default::default()),
            in_volume: Default::default(),
            in_inner: Default::default(),
            dx_neg: Default::default(),
            dx_mag: Default::default(),
            dy_neg: Default::default(),
            dy_mag: Default::default(),
            regs: Regs::new(
                [Reg::C3Stream, Reg::C3Address, Reg::C3Cast, Reg::C3Delays].map(Reg::address),
            ),
            last_segment: Default::default(),
            last_ray: Default::default(),
            segment: Default::default(),
            ray: Default::default(),
            scanline: Default::default(),
            late: RegisteredLine::new(
                super::trilin_lanes::cell_delay(segments),
                &[],
                u64::MAX.to_bits(),
            ),
            unit_segment: Default::default(),
            unit_ray: Default::default(),
            unit_scanline: Default::default(),
            templates: Templates::new(s),
            cast_ray_lo: Default::default(),
            cast_ray_span: Default::default(),
            cast_line_lo: Default::default(),
            cast_line_span: Default::default(),
            per_ray: Constant::new(s.perspective),
            increments: Increments::new(s, centre_delay),
            bounds: std::array::from_fn(|i| ViewRom::new(ViewTable::Bounds(i).base(), segments)),
            inner: std::array::from_fn(|i| ViewRom::new(ViewTable::Inner(i).base(), segments)),
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
        // The view's registers.
        self.regs.clock.next = self.clock.val();
        self.regs.host_write.next = self.host_write.val();
        self.regs.host_address.next = self.host_address.val();
        self.regs.host_data.next = self.host_data.val();
        self.last_ray.next = self.regs.q[0].val().get_bits::<16>(0) - 1;
        self.last_segment.next = self.regs.q[0].val().get_bits::<16>(32) - 1;
        self.cast_ray_lo.next = self.regs.q[2].val().get_bits::<16>(0);
        self.cast_ray_span.next = self.regs.q[2].val().get_bits::<16>(16);
        self.cast_line_lo.next = self.regs.q[2].val().get_bits::<16>(32);
        self.cast_line_span.next = self.regs.q[2].val().get_bits::<16>(48);
        self.late.clock.next = self.clock.val();
        self.late.last.next = self.regs.q[3].val().get_bits::<H>(0);
        self.late.write_enable.next = true;
        self.increments.clock.next = self.clock.val();
        self.increments.host_write.next = self.host_write.val();
        self.increments.host_address.next = self.host_address.val();
        self.increments.host_data.next = self.host_data.val();
        self.increments.centre_last.next = self.regs.q[3].val().get_bits::<H>(32);
        self.templates.clock.next = self.clock.val();
        self.templates.host_write.next = self.host_write.val();
        self.templates.host_address.next = self.host_address.val();
        self.templates.host_data.next = self.host_data.val();
        self.templates.stride.next = self.regs.q[1].val().get_bits::<16>(48);
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
        self.unit_cast.next = !self.per_ray.val()
            | (((self.unit_ray.val() - self.cast_ray_lo.val()) <= self.cast_ray_span.val())
                & ((self.unit_scanline.val() - self.cast_line_lo.val())
                    <= self.cast_line_span.val()));
        self.increments.ray.next = self.unit_ray.val();
        self.increments.scanline.next = self.unit_scanline.val();
        self.dx_neg.next = self.increments.dx_neg.val();
        self.dx_mag.next = self.increments.dx_mag.val();
        self.dy_neg.next = self.increments.dy_neg.val();
        self.dy_mag.next = self.increments.dy_mag.val();
        self.templates.ray.next = self.unit_ray.val();
        self.templates.scanline.next = self.unit_scanline.val();
        self.templates.segment.next = self.unit_segment.val();
        for i in 0..8 {
            self.lane_in[i].next = 0.into();
            self.lane_inner[i].next = 0.into();
        }
        for i in 0..P {
            self.bounds[i].clock.next = self.clock.val();
            self.bounds[i].host_write.next = self.host_write.val();
            self.bounds[i].host_address.next = self.host_address.val();
            self.bounds[i].host_data.next = self.host_data.val();
            self.inner[i].clock.next = self.clock.val();
            self.inner[i].host_write.next = self.host_write.val();
            self.inner[i].host_address.next = self.host_address.val();
            self.inner[i].host_data.next = self.host_data.val();
            self.bounds[i].address.next = self.unit_segment.val().get_bits::<SEGMENT_BITS>(0);
            self.wx[i].next = self.templates.wx[i].val();
            self.wy[i].next = self.templates.wy[i].val();
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
