//! The template weights of each unit's sample (Cube-3 §2-3): the discrete
//! ray's offsets along the major axis, one entry a plane for a parallel
//! view, per ray or scanline for a perspective view. A sub-block of
//! [`super::ray_control::RayControl`].

use super::config::Cube3Config;
use rust_hdl::prelude::*;

/// The template weights of each unit's sample: lane `i`'s ROMs hold weight
/// `k = s·P + i` of ray (scanline) `r` at `r·stride + s`, `stride = G` for
/// a perspective view's per-ray templates, 0 for a parallel view's one.
#[derive(LogicBlock)]
pub struct Templates<const P: usize> {
    pub ray: Signal<In, Bits<16>>,
    pub scanline: Signal<In, Bits<16>>,
    pub segment: Signal<In, Bits<16>>,
    pub wx: [Signal<Out, Bits<16>>; P],
    pub wy: [Signal<Out, Bits<16>>; P],
    stride: Constant<Bits<16>>,
    wx_entry: Signal<Local, Bits<32>>,
    wy_entry: Signal<Local, Bits<32>>,
    wx_rom: [ROM<Bits<16>, 32>; P],
    wy_rom: [ROM<Bits<16>, 32>; P],
}

impl<const P: usize> Templates<P> {
    pub fn new(t: &Cube3Config) -> Templates<P> {
        let segments = t.segments;
        let nk = t.wx.len() / t.wx_rays();
        // Lane i's template ROM: weight k = s·P + i of ray (scanline) r at
        // r·G + s.
        let template = |w: &[u32], lines: usize, i: usize| -> ROM<Bits<16>, 32> {
            (0..lines * segments)
                .map(|a| {
                    let (r, k) = (a / segments, (a % segments) * P + i);
                    let v = if k < nk { w[r * nk + k] } else { 0 };
                    (v as u64).to_bits()
                })
                .into()
        };
        Templates {
            ray: Default::default(),
            scanline: Default::default(),
            segment: Default::default(),
            wx: std::array::from_fn(|_| Default::default()),
            wy: std::array::from_fn(|_| Default::default()),
            stride: Constant::new(((if t.perspective { segments } else { 0 }) as u64).to_bits()),
            wx_entry: Default::default(),
            wy_entry: Default::default(),
            wx_rom: std::array::from_fn(|i| template(&t.wx, t.wx_rays(), i)),
            wy_rom: std::array::from_fn(|i| template(&t.wy, t.wy_scanlines(), i)),
        }
    }
}

impl<const P: usize> Logic for Templates<P> {
    #[hdl_gen]
    fn update(&mut self) {
        self.wx_entry.next =
            self.ray.val() * self.stride.val() + bit_cast::<32, 16>(self.segment.val());
        self.wy_entry.next =
            self.scanline.val() * self.stride.val() + bit_cast::<32, 16>(self.segment.val());
        for i in 0..P {
            self.wx_rom[i].address.next = self.wx_entry.val();
            self.wy_rom[i].address.next = self.wy_entry.val();
            self.wx[i].next = self.wx_rom[i].data.val();
            self.wy[i].next = self.wy_rom[i].data.val();
        }
    }
}
