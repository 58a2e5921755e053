//! Cube-3 from the volume memory to the base plane (§5, Fig. 12): the
//! [`BeamFetch`] (CFB, Fast Bus, 2-DSBs) feeding the [`Cube3`] pipeline
//! (ray control, TRILIN, ABC units or leaf stage, RPC), for one base plane
//! of a parallel or perspective view in every mode.
//!
//! After `start` the system fetches the PRPs of `S + 1` stream scanlines
//! and puts out one `done` pixel per stream ray (`R` per scanline, in
//! order), the last one [`Cube3SystemConfig::clocks`]` - 1` clocks later.
//! The stream's scanlines are a fetch period apart, which the ABC units'
//! sample-plane lines are built for.

use super::cfb::BeamFetch;
use super::config::{Cube3Config, Cube3Sizes};
use super::pipeline::Cube3;
use crate::common::regs::ADDRESS_BITS;
use golden_model::host::ShaderTables;
use rust_hdl::prelude::*;

/// Cube-3 with `P` units: `A`-bit memory, `B`-bit 2-DSB and `H`-bit
/// delay-line addresses.
#[derive(LogicBlock)]
pub struct Cube3System<const P: usize, const A: usize, const B: usize, const H: usize> {
    pub clock: Signal<In, Clock>,
    /// The host port: registers and tables, written between frames
    /// (`golden_model::host`).
    pub host_write: Signal<In, Bit>,
    pub host_address: Signal<In, Bits<ADDRESS_BITS>>,
    pub host_data: Signal<In, Bits<64>>,
    pub start: Signal<In, Bit>,
    pub done: Signal<Out, Bit>,
    pub pixel_r: Signal<Out, Bits<32>>,
    pub pixel_g: Signal<Out, Bits<16>>,
    pub pixel_b: Signal<Out, Bits<16>>,
    pub pixel_a: Signal<Out, Bits<16>>,
    pub has_sample: Signal<Out, Bit>,
    /// The external memory's ports (`BeamFetchConfig::external`).
    pub ext_addr: [Signal<Out, Bits<32>>; P],
    pub ext_data: [Signal<In, Bits<16>>; P],
    /// Loading on-chip memory (`BeamFetch::load_*`).
    pub load_enable: Signal<In, Bit>,
    pub load_module: Signal<In, Bits<8>>,
    pub load_address: Signal<In, Bits<32>>,
    pub load_data: Signal<In, Bits<16>>,
    pub(crate) fetch: BeamFetch<P, A, B>,
    pub(crate) pipeline: Cube3<P, H>,
}

impl<const P: usize, const A: usize, const B: usize, const H: usize> Cube3System<P, A, B, H> {
    /// The units of `c` (not its view) for the views of `s`.
    pub fn new(c: &Cube3Config, s: &Cube3Sizes) -> Result<Cube3System<P, A, B, H>, String> {
        Ok(Cube3System {
            clock: Default::default(),
            host_write: Default::default(),
            host_address: Default::default(),
            host_data: Default::default(),
            start: Default::default(),
            done: Default::default(),
            pixel_r: Default::default(),
            pixel_g: Default::default(),
            pixel_b: Default::default(),
            pixel_a: Default::default(),
            has_sample: Default::default(),
            ext_addr: std::array::from_fn(|_| Default::default()),
            ext_data: std::array::from_fn(|_| Default::default()),
            load_enable: Default::default(),
            load_module: Default::default(),
            load_address: Default::default(),
            load_data: Default::default(),
            fetch: BeamFetch::new(s)?,
            pipeline: Cube3::new(c, s)?,
        })
    }

    /// Load the volume (`BeamFetchConfig::modules`).
    pub fn preload(&mut self, modules: &[Vec<u16>]) {
        self.fetch.preload(modules);
    }

    /// Give the shaders' tables the contents the host would load.
    pub fn preload_tables(&mut self, tables: &ShaderTables) {
        self.pipeline.preload_tables(tables);
    }
}

impl<const P: usize, const A: usize, const B: usize, const H: usize> Logic
    for Cube3System<P, A, B, H>
{
    #[hdl_gen]
    fn update(&mut self) {
        self.fetch.clock.next = self.clock.val();
        self.pipeline.clock.next = self.clock.val();
        self.fetch.start.next = self.start.val();
        self.fetch.host_write.next = self.host_write.val();
        self.fetch.host_address.next = self.host_address.val();
        self.fetch.host_data.next = self.host_data.val();
        self.fetch.load_enable.next = self.load_enable.val();
        self.fetch.load_module.next = self.load_module.val();
        self.fetch.load_address.next = self.load_address.val();
        self.fetch.load_data.next = self.load_data.val();
        self.pipeline.start.next = self.start.val();
        self.pipeline.host_write.next = self.host_write.val();
        self.pipeline.host_address.next = self.host_address.val();
        self.pipeline.host_data.next = self.host_data.val();
        self.pipeline.valid.next = self.fetch.valid.val();
        for i in 0..P {
            self.pipeline.cur[i].next = self.fetch.cur[i].val();
            self.pipeline.next[i].next = self.fetch.next[i].val();
            self.ext_addr[i].next = self.fetch.ext_addr[i].val();
            self.fetch.ext_data[i].next = self.ext_data[i].val();
        }
        self.done.next = self.pipeline.done.val();
        self.pixel_r.next = self.pipeline.pixel_r.val();
        self.pixel_g.next = self.pipeline.pixel_g.val();
        self.pixel_b.next = self.pipeline.pixel_b.val();
        self.pixel_a.next = self.pipeline.pixel_a.val();
        self.has_sample.next = self.pipeline.has_sample.val();
    }
}
