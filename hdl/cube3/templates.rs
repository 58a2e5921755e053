//! The template weights of each unit's sample (Cube-3 §2-3): the discrete
//! ray's offsets along the major axis, one entry a plane for a parallel
//! view, per ray or scanline for a perspective view. A sub-block of
//! [`super::ray_control::RayControl`].

use super::config::{Cube3Sizes, TEMPLATE_BITS};
use crate::common::regs::ADDRESS_BITS;
use crate::common::view_rom::ViewRom;
use golden_model::host::ViewTable;
use rust_hdl::prelude::*;

/// The template weights of each unit's sample: lane `i`'s tables (the host
/// loads them) hold weight `k = s·P + i` of ray (scanline) `r` at
/// `r·stride + s`, `stride = G` for a perspective view's per-ray
/// templates, 0 for a parallel view's one.
#[derive(LogicBlock)]
pub struct Templates<const P: usize> {
    pub clock: Signal<In, Clock>,
    pub host_write: Signal<In, Bit>,
    pub host_address: Signal<In, Bits<ADDRESS_BITS>>,
    pub host_data: Signal<In, Bits<64>>,
    /// `G` (perspective) or 0 (`RayControl`'s register).
    pub stride: Signal<In, Bits<16>>,
    pub ray: Signal<In, Bits<16>>,
    pub scanline: Signal<In, Bits<16>>,
    pub segment: Signal<In, Bits<16>>,
    pub wx: [Signal<Out, Bits<16>>; P],
    pub wy: [Signal<Out, Bits<16>>; P],
    /// The stride a perspective build takes; a parallel build's is 0, so
    /// synthesis removes the multipliers.
    per_ray: Constant<Bit>,
    row_stride: Signal<Local, Bits<16>>,
    wx_entry: Signal<Local, Bits<32>>,
    wy_entry: Signal<Local, Bits<32>>,
    wx_rom: [ViewRom<16, TEMPLATE_BITS>; P],
    wy_rom: [ViewRom<16, TEMPLATE_BITS>; P],
}

impl<const P: usize> Templates<P> {
    /// For the views of `s`: a segment's entries a lane, or a ray's
    /// (scanline's) in perspective.
    pub fn new(s: &Cube3Sizes) -> Templates<P> {
        let (rays, scanlines) = match s.perspective {
            true => (s.rays(), s.scanlines()),
            false => (1, 1),
        };
        Templates {
            clock: Default::default(),
            host_write: Default::default(),
            host_address: Default::default(),
            host_data: Default::default(),
            stride: Default::default(),
            ray: Default::default(),
            scanline: Default::default(),
            segment: Default::default(),
            wx: std::array::from_fn(|_| Default::default()),
            wy: std::array::from_fn(|_| Default::default()),
            per_ray: Constant::new(s.perspective),
            row_stride: Default::default(),
            wx_entry: Default::default(),
            wy_entry: Default::default(),
            wx_rom: std::array::from_fn(|i| {
                ViewRom::new(ViewTable::Wx(i).base(), rays * s.segments())
            }),
            wy_rom: std::array::from_fn(|i| {
                ViewRom::new(ViewTable::Wy(i).base(), scanlines * s.segments())
            }),
        }
    }
}

impl<const P: usize> Logic for Templates<P> {
    #[hdl_gen]
    fn update(&mut self) {
        self.row_stride.next = 0.into();
        if self.per_ray.val() {
            self.row_stride.next = self.stride.val();
        }
        self.wx_entry.next =
            self.ray.val() * self.row_stride.val() + bit_cast::<32, 16>(self.segment.val());
        self.wy_entry.next =
            self.scanline.val() * self.row_stride.val() + bit_cast::<32, 16>(self.segment.val());
        for i in 0..P {
            self.wx_rom[i].clock.next = self.clock.val();
            self.wx_rom[i].host_write.next = self.host_write.val();
            self.wx_rom[i].host_address.next = self.host_address.val();
            self.wx_rom[i].host_data.next = self.host_data.val();
            self.wy_rom[i].clock.next = self.clock.val();
            self.wy_rom[i].host_write.next = self.host_write.val();
            self.wy_rom[i].host_address.next = self.host_address.val();
            self.wy_rom[i].host_data.next = self.host_data.val();
            self.wx_rom[i].address.next = self.wx_entry.val().get_bits::<TEMPLATE_BITS>(0);
            self.wy_rom[i].address.next = self.wy_entry.val().get_bits::<TEMPLATE_BITS>(0);
            self.wx[i].next = self.wx_rom[i].data.val();
            self.wy[i].next = self.wy_rom[i].data.val();
        }
    }
}
