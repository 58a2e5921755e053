//! The scanline periods of Cube-3's beam fetch (§5, Fig. 12): which PRP
//! plane is written, which ray segment is read, and the three 2-D skewed
//! buffers' roles. A sub-block of [`super::cfb::BeamFetch`].

use crate::common::regs::{Regs, ADDRESS_BITS};
use golden_model::host::Reg;
use rust_hdl::prelude::*;

/// The scanline periods: which plane and chunk are written, which ray and
/// segment are read, and the buffers' roles.
#[derive(LogicBlock)]
pub struct Schedule {
    pub clock: Signal<In, Clock>,
    pub start: Signal<In, Bit>,
    pub writing: Signal<Out, Bit>,
    pub plane: Signal<Out, Bits<16>>,
    /// The chunk (parallel) or group (perspective: up to 2^18) written.
    pub chunk: Signal<Out, Bits<24>>,
    /// The chunk of the next clock (the counter's input), so that the group
    /// tables' registered read answers `chunk` in its own clock.
    pub chunk_next: Signal<Out, Bits<24>>,
    pub period: Signal<Out, Bits<16>>,
    /// The period of the next clock (the counter's input).
    pub period_next: Signal<Out, Bits<16>>,
    pub write_buffer: Signal<Out, Bits<2>>,
    pub reading: Signal<Out, Bit>,
    pub ray: Signal<Out, Bits<16>>,
    /// `ray·G + segment`, counted: the reads' 2-DSB address, from a
    /// register (the segments of a period are read in that order).
    pub read_address: Signal<Out, Bits<32>>,
    pub cur_buffer: Signal<Out, Bits<2>>,
    pub next_buffer: Signal<Out, Bits<2>>,
    /// The host port: the view's counts (`C3Stream`, `C3Schedule`), in the
    /// schedule's own copy of the registers.
    pub host_write: Signal<In, Bit>,
    pub host_address: Signal<In, Bits<ADDRESS_BITS>>,
    pub host_data: Signal<In, Bits<64>>,
    regs: Regs<2>,
    /// The counts less one: the period's clocks, the scanlines written (the
    /// stream's `S`, then one more period of reads), the planes and chunks
    /// of a PRP, the rays and segments read.
    last_tick: Signal<Local, Bits<24>>,
    last_write_period: Signal<Local, Bits<16>>,
    last_plane: Signal<Local, Bits<16>>,
    last_chunk: Signal<Local, Bits<24>>,
    last_ray: Signal<Local, Bits<16>>,
    last_segment: Signal<Local, Bits<16>>,
    last_period: Signal<Local, Bits<16>>,
    first_read_period: Constant<Bits<16>>,
    active: DFF<Bit>,
    tick: DFF<Bits<24>>,
    period_q: DFF<Bits<16>>,
    plane_q: DFF<Bits<16>>,
    chunk_q: DFF<Bits<24>>,
    ray_q: DFF<Bits<16>>,
    segment_q: DFF<Bits<16>>,
    address_q: DFF<Bits<32>>,
    written: DFF<Bit>,
    read: DFF<Bit>,
    w_q: DFF<Bits<2>>,
    c_q: DFF<Bits<2>>,
    n_q: DFF<Bits<2>>,
}

impl Default for Schedule {
    fn default() -> Schedule {
        Schedule {
            clock: Default::default(),
            start: Default::default(),
            writing: Default::default(),
            plane: Default::default(),
            chunk: Default::default(),
            chunk_next: Default::default(),
            period: Default::default(),
            period_next: Default::default(),
            write_buffer: Default::default(),
            reading: Default::default(),
            ray: Default::default(),
            read_address: Default::default(),
            cur_buffer: Default::default(),
            next_buffer: Default::default(),
            host_write: Default::default(),
            host_address: Default::default(),
            host_data: Default::default(),
            regs: Regs::new([Reg::C3Stream, Reg::C3Schedule].map(Reg::address)),
            last_tick: Default::default(),
            last_write_period: Default::default(),
            last_plane: Default::default(),
            last_chunk: Default::default(),
            last_ray: Default::default(),
            last_segment: Default::default(),
            last_period: Default::default(),
            first_read_period: Constant::new(2.into()),
            active: Default::default(),
            tick: Default::default(),
            period_q: Default::default(),
            plane_q: Default::default(),
            chunk_q: Default::default(),
            ray_q: Default::default(),
            segment_q: Default::default(),
            address_q: Default::default(),
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
            self, clock, active, tick, period_q, plane_q, chunk_q, ray_q, segment_q, address_q,
            written, read, w_q, c_q, n_q
        );
        self.regs.clock.next = self.clock.val();
        self.regs.host_write.next = self.host_write.val();
        self.regs.host_address.next = self.host_address.val();
        self.regs.host_data.next = self.host_data.val();
        self.last_ray.next = self.regs.q[0].val().get_bits::<16>(0) - 1;
        self.last_write_period.next = self.regs.q[0].val().get_bits::<16>(16);
        self.last_segment.next = self.regs.q[0].val().get_bits::<16>(32) - 1;
        self.last_tick.next = self.regs.q[1].val().get_bits::<24>(0);
        self.last_chunk.next = self.regs.q[1].val().get_bits::<24>(24);
        self.last_plane.next = self.regs.q[1].val().get_bits::<16>(48);
        self.last_period.next = self.last_write_period.val() + 1;
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
            self.address_q.d.next = self.address_q.q.val() + 1;
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
                self.address_q.d.next = 0.into();
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
            self.address_q.d.next = 0.into();
            self.written.d.next = false;
            self.read.d.next = false;
            self.w_q.d.next = 0.into();
            self.n_q.d.next = 2.into();
            self.c_q.d.next = 1.into();
        }
        self.plane.next = self.plane_q.q.val();
        self.chunk.next = self.chunk_q.q.val();
        self.chunk_next.next = self.chunk_q.d.val();
        self.period.next = self.period_q.q.val();
        self.period_next.next = self.period_q.d.val();
        self.write_buffer.next = self.w_q.q.val();
        self.ray.next = self.ray_q.q.val();
        self.read_address.next = self.address_q.q.val();
        self.cur_buffer.next = self.c_q.q.val();
        self.next_buffer.next = self.n_q.q.val();
    }
}
