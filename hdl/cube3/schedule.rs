//! The scanline periods of Cube-3's beam fetch (§5, Fig. 12): which PRP
//! plane is written, which ray segment is read, and the three 2-D skewed
//! buffers' roles. A sub-block of [`super::cfb::BeamFetch`].

use super::config::BeamFetchConfig;
use rust_hdl::prelude::*;

/// The scanline periods: which plane and chunk are written, which ray and
/// segment are read, and the buffers' roles.
#[derive(LogicBlock)]
pub struct Schedule {
    pub clock: Signal<In, Clock>,
    pub start: Signal<In, Bit>,
    pub writing: Signal<Out, Bit>,
    pub plane: Signal<Out, Bits<16>>,
    pub chunk: Signal<Out, Bits<16>>,
    pub period: Signal<Out, Bits<16>>,
    pub write_buffer: Signal<Out, Bits<2>>,
    pub reading: Signal<Out, Bit>,
    pub ray: Signal<Out, Bits<16>>,
    pub segment: Signal<Out, Bits<16>>,
    pub cur_buffer: Signal<Out, Bits<2>>,
    pub next_buffer: Signal<Out, Bits<2>>,
    last_tick: Constant<Bits<16>>,
    last_period: Constant<Bits<16>>,
    last_write_period: Constant<Bits<16>>,
    last_plane: Constant<Bits<16>>,
    last_chunk: Constant<Bits<16>>,
    last_ray: Constant<Bits<16>>,
    last_segment: Constant<Bits<16>>,
    first_read_period: Constant<Bits<16>>,
    active: DFF<Bit>,
    tick: DFF<Bits<16>>,
    period_q: DFF<Bits<16>>,
    plane_q: DFF<Bits<16>>,
    chunk_q: DFF<Bits<16>>,
    ray_q: DFF<Bits<16>>,
    segment_q: DFF<Bits<16>>,
    written: DFF<Bit>,
    read: DFF<Bit>,
    w_q: DFF<Bits<2>>,
    c_q: DFF<Bits<2>>,
    n_q: DFF<Bits<2>>,
}

impl Schedule {
    pub fn new(c: &BeamFetchConfig) -> Schedule {
        let k = |v: usize| Constant::new((v as u64).to_bits());
        Schedule {
            clock: Default::default(),
            start: Default::default(),
            writing: Default::default(),
            plane: Default::default(),
            chunk: Default::default(),
            period: Default::default(),
            write_buffer: Default::default(),
            reading: Default::default(),
            ray: Default::default(),
            segment: Default::default(),
            cur_buffer: Default::default(),
            next_buffer: Default::default(),
            last_tick: k(c.period() - 1),
            last_period: k(c.scanlines + 1),
            last_write_period: k(c.scanlines),
            // A perspective PRP counts its groups as the chunks of one plane.
            last_plane: k(if c.perspective() {
                0
            } else {
                c.planes_written() - 1
            }),
            last_chunk: k(if c.perspective() {
                c.groups.len() - 1
            } else {
                c.rays.div_ceil(c.p) - 1
            }),
            last_ray: k(c.rays - 1),
            last_segment: k(c.segments - 1),
            first_read_period: k(2),
            active: Default::default(),
            tick: Default::default(),
            period_q: Default::default(),
            plane_q: Default::default(),
            chunk_q: Default::default(),
            ray_q: Default::default(),
            segment_q: Default::default(),
            written: Default::default(),
            read: Default::default(),
            w_q: Default::default(),
            c_q: Default::default(),
            n_q: Default::default(),
        }
    }
}

impl Logic for Schedule {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, active, tick, period_q, plane_q, chunk_q, ray_q, segment_q, written, read,
            w_q, c_q, n_q
        );
        self.writing.next = self.active.q.val()
            & !self.written.q.val()
            & (self.period_q.q.val() <= self.last_write_period.val());
        self.reading.next = self.active.q.val()
            & !self.read.q.val()
            & (self.period_q.q.val() >= self.first_read_period.val());
        // Writes: chunk by chunk, plane by plane.
        if self.writing.val() {
            self.chunk_q.d.next = self.chunk_q.q.val() + 1;
            if self.chunk_q.q.val() == self.last_chunk.val() {
                self.chunk_q.d.next = 0.into();
                self.plane_q.d.next = self.plane_q.q.val() + 1;
                if self.plane_q.q.val() == self.last_plane.val() {
                    self.written.d.next = true;
                }
            }
        }
        // Reads: segment by segment, ray by ray.
        if self.reading.val() {
            self.segment_q.d.next = self.segment_q.q.val() + 1;
            if self.segment_q.q.val() == self.last_segment.val() {
                self.segment_q.d.next = 0.into();
                self.ray_q.d.next = self.ray_q.q.val() + 1;
                if self.ray_q.q.val() == self.last_ray.val() {
                    self.read.d.next = true;
                }
            }
        }
        // The period's end: the buffers rotate, the counters restart.
        if self.active.q.val() {
            self.tick.d.next = self.tick.q.val() + 1;
            if self.tick.q.val() == self.last_tick.val() {
                self.tick.d.next = 0.into();
                self.period_q.d.next = self.period_q.q.val() + 1;
                if self.period_q.q.val() == self.last_period.val() {
                    self.active.d.next = false;
                }
                self.chunk_q.d.next = 0.into();
                self.plane_q.d.next = 0.into();
                self.segment_q.d.next = 0.into();
                self.ray_q.d.next = 0.into();
                self.written.d.next = false;
                self.read.d.next = false;
                self.c_q.d.next = self.n_q.q.val();
                self.n_q.d.next = self.w_q.q.val();
                self.w_q.d.next = self.c_q.q.val();
            }
        }
        if self.start.val() {
            self.active.d.next = true;
            self.tick.d.next = 0.into();
            self.period_q.d.next = 0.into();
            self.chunk_q.d.next = 0.into();
            self.plane_q.d.next = 0.into();
            self.segment_q.d.next = 0.into();
            self.ray_q.d.next = 0.into();
            self.written.d.next = false;
            self.read.d.next = false;
            self.w_q.d.next = 0.into();
            self.n_q.d.next = 2.into();
            self.c_q.d.next = 1.into();
        }
        self.plane.next = self.plane_q.q.val();
        self.chunk.next = self.chunk_q.q.val();
        self.period.next = self.period_q.q.val();
        self.write_buffer.next = self.w_q.q.val();
        self.ray.next = self.ray_q.q.val();
        self.segment.next = self.segment_q.q.val();
        self.cur_buffer.next = self.c_q.q.val();
        self.next_buffer.next = self.n_q.q.val();
    }
}
