//! The rays each clock of Cube-3's beam fetch reads (§2, Fig. 3): a
//! parallel view's chunk of consecutive rays, or a perspective view's
//! de-fanning group from ROMs. A sub-block of [`super::cfb::BeamFetch`].

use super::config::{BeamFetchConfig, GROUP_BITS, PLANE_BITS};
use crate::common::rom16;
use rust_hdl::prelude::*;

/// This clock's group of rays, at most `P`: a parallel chunk from the
/// schedule's counters (`P` rays from `chunk·P`, `x` from the plane's
/// template), or a perspective group from the ROMs (the schedule's chunk
/// counts groups): its plane, first ray and each lane's `x` and whether it
/// holds a ray.
#[derive(LogicBlock)]
pub struct Groups<const P: usize> {
    pub chunk: Signal<In, Bits<16>>,
    pub plane_count: Signal<In, Bits<16>>,
    pub plane: Signal<Out, Bits<16>>,
    pub first_ray: Signal<Out, Bits<16>>,
    pub x: [Signal<Out, Bits<16>>; P],
    pub holds: [Signal<Out, Bit>; P],
    perspective: Constant<Bit>,
    /// Parallel: `pos_x` by plane, and the chunk's first ray and `x`.
    pos_x: ROM<Bits<16>, PLANE_BITS>,
    chunk_ray: Signal<Local, Bits<16>>,
    x0: Signal<Local, Bits<16>>,
    /// Perspective: each group's `[plane, first ray]` and its lanes' `x`
    /// (bit 16: the lane holds a ray).
    groups: ROM<Bits<32>, GROUP_BITS>,
    group_x: [ROM<Bits<17>, GROUP_BITS>; P],
    index: [Constant<Bits<16>>; P],
    shift: Constant<Bits<16>>,
    u0: Constant<Bits<16>>,
}

impl<const P: usize> Groups<P> {
    pub fn new(c: &BeamFetchConfig) -> Groups<P> {
        let k = |v: i64| Constant::new(((v as u64) & 0xffff).to_bits());
        let group_x = |j: usize| -> ROM<Bits<17>, GROUP_BITS> {
            c.groups
                .iter()
                .map(|g| {
                    g.x.get(j)
                        .map_or(0, |&x| (x as u64 & 0xffff) | 1 << 16)
                        .to_bits()
                })
                .into()
        };
        Groups {
            chunk: Default::default(),
            plane_count: Default::default(),
            plane: Default::default(),
            first_ray: Default::default(),
            x: std::array::from_fn(|_| Default::default()),
            holds: std::array::from_fn(|_| Default::default()),
            perspective: Constant::new(c.perspective()),
            pos_x: rom16(&c.pos_x),
            chunk_ray: Default::default(),
            x0: Default::default(),
            groups: c
                .groups
                .iter()
                .map(|g| (g.plane as u64 | (g.ray as u64) << 16).to_bits())
                .into(),
            group_x: std::array::from_fn(group_x),
            index: std::array::from_fn(|j| k(j as i64)),
            shift: k(P.trailing_zeros() as i64),
            u0: k(c.u0 as i64),
        }
    }
}

impl<const P: usize> Logic for Groups<P> {
    #[hdl_gen]
    fn update(&mut self) {
        self.pos_x.address.next = self.plane_count.val().get_bits::<PLANE_BITS>(0);
        self.groups.address.next = self.chunk.val();
        self.chunk_ray.next = self.chunk.val() << self.shift.val();
        self.x0.next = self.u0.val() + self.pos_x.data.val() + self.chunk_ray.val();
        self.plane.next = self.plane_count.val();
        self.first_ray.next = self.chunk_ray.val();
        if self.perspective.val() {
            self.plane.next = self.groups.data.val().get_bits::<16>(0);
            self.first_ray.next = self.groups.data.val().get_bits::<16>(16);
        }
        for j in 0..P {
            self.group_x[j].address.next = self.chunk.val();
            self.x[j].next = self.x0.val() + self.index[j].val();
            self.holds[j].next = true;
            if self.perspective.val() {
                self.x[j].next = self.group_x[j].data.val().get_bits::<16>(0);
                self.holds[j].next = self.group_x[j].data.val().get_bit(16);
            }
        }
    }
}
