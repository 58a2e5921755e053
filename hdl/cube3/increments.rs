//! The gradient increments of the ABC units' centre ray (Cube-3 §4): the
//! `dx`, `dy` of a parallel view, or a perspective view's per ray and per
//! scanline. A sub-block of [`super::ray_control::RayControl`].

use super::config::{Cube3Config, TEMPLATE_BITS};
use crate::common::delay_line::DelayLine;
use rust_hdl::prelude::*;

/// The increments of the ABC units' centre ray: the units' ray and
/// scanline through a delay line to the centre (perspective), then ROMs by
/// ray and scanline (sign in bit 16); a parallel view's one entry at
/// address 0 (the mask clears the address).
#[derive(LogicBlock)]
pub struct Increments<const H: usize> {
    pub clock: Signal<In, Clock>,
    pub ray: Signal<In, Bits<16>>,
    pub scanline: Signal<In, Bits<16>>,
    pub dx_neg: Signal<Out, Bit>,
    pub dx_mag: Signal<Out, Bits<16>>,
    pub dy_neg: Signal<Out, Bit>,
    pub dy_mag: Signal<Out, Bits<16>>,
    centre_line: DelayLine<Bits<32>, H>,
    centre_last: Constant<Bits<H>>,
    mask: Constant<Bits<16>>,
    dx_address: Signal<Local, Bits<16>>,
    dy_address: Signal<Local, Bits<16>>,
    dx_rom: ROM<Bits<17>, TEMPLATE_BITS>,
    dy_rom: ROM<Bits<17>, TEMPLATE_BITS>,
}

impl<const H: usize> Increments<H> {
    pub fn new(t: &Cube3Config, centre_delay: usize) -> Increments<H> {
        let rom = |d: &[i32]| -> ROM<Bits<17>, TEMPLATE_BITS> {
            d.iter()
                .map(|&d| ((d.unsigned_abs() as u64) | ((d < 0) as u64) << 16).to_bits())
                .into()
        };
        let (dx, dy) = t
            .abc
            .as_ref()
            .map_or((vec![0], vec![0]), |a| (a.dx.clone(), a.dy.clone()));
        Increments {
            clock: Default::default(),
            ray: Default::default(),
            scanline: Default::default(),
            dx_neg: Default::default(),
            dx_mag: Default::default(),
            dy_neg: Default::default(),
            dy_mag: Default::default(),
            centre_line: DelayLine::new(
                if t.perspective { centre_delay } else { 1 },
                &[],
                u32::MAX.to_bits(),
            ),
            centre_last: Constant::new(
                ((if t.perspective { centre_delay } else { 1 } - 1) as u64).to_bits(),
            ),
            mask: Constant::new((if t.perspective { 0xffffu64 } else { 0 }).to_bits()),
            dx_address: Default::default(),
            dy_address: Default::default(),
            dx_rom: rom(&dx),
            dy_rom: rom(&dy),
        }
    }
}

impl<const H: usize> Logic for Increments<H> {
    #[hdl_gen]
    fn update(&mut self) {
        self.centre_line.clock.next = self.clock.val();
        self.centre_line.last.next = self.centre_last.val();
        self.centre_line.write_enable.next = true;
        self.centre_line.data_in.next =
            bit_cast::<32, 16>(self.ray.val()) | (bit_cast::<32, 16>(self.scanline.val()) << 16);
        // The centre's scanline is one before the delayed one.
        self.dx_address.next = self.centre_line.data_out.val().get_bits::<16>(0) & self.mask.val();
        self.dy_address.next =
            (self.centre_line.data_out.val().get_bits::<16>(16) - 1) & self.mask.val();
        self.dx_rom.address.next = self.dx_address.val();
        self.dy_rom.address.next = self.dy_address.val();
        self.dx_neg.next = self.dx_rom.data.val().get_bit(16);
        self.dx_mag.next = self.dx_rom.data.val().get_bits::<16>(0);
        self.dy_neg.next = self.dy_rom.data.val().get_bit(16);
        self.dy_mag.next = self.dy_rom.data.val().get_bits::<16>(0);
    }
}
