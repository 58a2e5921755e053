//! The gradient increments of the ABC units' centre ray (Cube-3 §4): the
//! `dx`, `dy` of a parallel view, or a perspective view's per ray and per
//! scanline. A sub-block of [`super::ray_control::RayControl`].

use super::config::{Cube3Sizes, TEMPLATE_BITS};
use crate::common::delay_line::DelayLine;
use crate::common::regs::ADDRESS_BITS;
use crate::common::view_rom::ViewRom;
use golden_model::host::ViewTable;
use rust_hdl::prelude::*;

/// The increments of the ABC units' centre ray: the units' ray and
/// scanline through a delay line to a clock before the centre
/// (perspective), then tables by ray and scanline (sign in bit 16) the
/// host loads, read into a register; a parallel view's one entry at
/// address 0 (the mask clears the address).
#[derive(LogicBlock)]
pub struct Increments<const H: usize> {
    pub clock: Signal<In, Clock>,
    pub host_write: Signal<In, Bit>,
    pub host_address: Signal<In, Bits<ADDRESS_BITS>>,
    pub host_data: Signal<In, Bits<64>>,
    /// The centre line's length less one (`RayControl`'s register): a clock
    /// short of the centre, for the tables' registered read.
    pub centre_last: Signal<In, Bits<H>>,
    pub ray: Signal<In, Bits<16>>,
    pub scanline: Signal<In, Bits<16>>,
    pub dx_neg: Signal<Out, Bit>,
    pub dx_mag: Signal<Out, Bits<16>>,
    pub dy_neg: Signal<Out, Bit>,
    pub dy_mag: Signal<Out, Bits<16>>,
    centre_line: DelayLine<Bits<32>, H>,
    mask: Constant<Bits<16>>,
    dx_address: Signal<Local, Bits<16>>,
    dy_address: Signal<Local, Bits<16>>,
    dx_rom: ViewRom<17, TEMPLATE_BITS>,
    dy_rom: ViewRom<17, TEMPLATE_BITS>,
    dx_q: DFF<Bits<17>>,
    dy_q: DFF<Bits<17>>,
}

impl<const H: usize> Increments<H> {
    /// For the views of `s`, the centre at most `centre_delay` clocks
    /// behind the units.
    pub fn new(s: &Cube3Sizes, centre_delay: usize) -> Increments<H> {
        let (rays, scanlines, delay) = match s.perspective {
            true => (s.rays(), s.scanlines(), centre_delay),
            false => (1, 1, 1),
        };
        Increments {
            clock: Default::default(),
            host_write: Default::default(),
            host_address: Default::default(),
            host_data: Default::default(),
            centre_last: Default::default(),
            ray: Default::default(),
            scanline: Default::default(),
            dx_neg: Default::default(),
            dx_mag: Default::default(),
            dy_neg: Default::default(),
            dy_mag: Default::default(),
            centre_line: DelayLine::new(delay, &[], u32::MAX.to_bits()),
            mask: Constant::new((if s.perspective { 0xffffu64 } else { 0 }).to_bits()),
            dx_address: Default::default(),
            dy_address: Default::default(),
            dx_rom: ViewRom::new(ViewTable::Dx.base(), rays),
            dy_rom: ViewRom::new(ViewTable::Dy.base(), scanlines),
            dx_q: Default::default(),
            dy_q: Default::default(),
        }
    }
}

impl<const H: usize> Logic for Increments<H> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, dx_q, dy_q);
        self.centre_line.clock.next = self.clock.val();
        self.centre_line.last.next = self.centre_last.val();
        self.dx_rom.clock.next = self.clock.val();
        self.dx_rom.host_write.next = self.host_write.val();
        self.dx_rom.host_address.next = self.host_address.val();
        self.dx_rom.host_data.next = self.host_data.val();
        self.dy_rom.clock.next = self.clock.val();
        self.dy_rom.host_write.next = self.host_write.val();
        self.dy_rom.host_address.next = self.host_address.val();
        self.dy_rom.host_data.next = self.host_data.val();
        self.centre_line.write_enable.next = true;
        self.centre_line.data_in.next =
            bit_cast::<32, 16>(self.ray.val()) | (bit_cast::<32, 16>(self.scanline.val()) << 16);
        // The centre's scanline is one before the delayed one.
        self.dx_address.next = self.centre_line.data_out.val().get_bits::<16>(0) & self.mask.val();
        self.dy_address.next =
            (self.centre_line.data_out.val().get_bits::<16>(16) - 1) & self.mask.val();
        self.dx_rom.address.next = self.dx_address.val();
        self.dy_rom.address.next = self.dy_address.val();
        // Registered: the increments reach the ABC units' multipliers from
        // flip-flops, not through the line and the tables.
        self.dx_q.d.next = self.dx_rom.data.val();
        self.dy_q.d.next = self.dy_rom.data.val();
        self.dx_neg.next = self.dx_q.q.val().get_bit(16);
        self.dx_mag.next = self.dx_q.q.val().get_bits::<16>(0);
        self.dy_neg.next = self.dy_q.q.val().get_bit(16);
        self.dy_mag.next = self.dy_q.q.val().get_bits::<16>(0);
    }
}
