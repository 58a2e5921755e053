//! The rays each clock of Cube-3's beam fetch reads (§2, Fig. 3): a
//! parallel view's chunk of consecutive rays, or a perspective view's
//! de-fanning group from tables the host loads. A sub-block of
//! [`super::cfb::BeamFetch`].
//!
//! The group tables hold a word a group of every plane (thousands of
//! words), so they are block RAM: their read is registered, addressed by
//! the schedule's next chunk so that the word answers this clock's chunk.

use super::config::{Cube3Sizes, GROUP_BITS, PLANE_BITS};
use crate::common::ram::bits_for;
use crate::common::regs::ADDRESS_BITS;
use crate::common::table::Table;
use crate::common::view_rom::ViewRom;
use golden_model::host::ViewTable;
use rust_hdl::prelude::*;

/// This clock's group of rays, at most `P`: a parallel chunk from the
/// schedule's counters (`P` rays from `chunk·P`, `x` from the plane's
/// template), or a perspective group from the host-loaded tables (the
/// schedule's chunk counts groups): its plane, first ray and each lane's `x` and whether it
/// holds a ray.
#[derive(LogicBlock)]
pub struct Groups<const P: usize> {
    pub clock: Signal<In, Clock>,
    /// The host port (the tables' writes).
    pub host_write: Signal<In, Bit>,
    pub host_address: Signal<In, Bits<ADDRESS_BITS>>,
    pub host_data: Signal<In, Bits<64>>,
    /// The stream's first ray (`BeamFetch`'s register).
    pub u0: Signal<In, Bits<16>>,
    pub chunk: Signal<In, Bits<24>>,
    /// The next clock's chunk (the group tables' read address).
    pub chunk_next: Signal<In, Bits<24>>,
    pub plane_count: Signal<In, Bits<16>>,
    pub plane: Signal<Out, Bits<16>>,
    pub first_ray: Signal<Out, Bits<16>>,
    pub x: [Signal<Out, Bits<16>>; P],
    pub holds: [Signal<Out, Bit>; P],
    perspective: Constant<Bit>,
    /// Parallel: `pos_x` by plane, and the chunk's first ray and `x`.
    pos_x: ViewRom<16, PLANE_BITS>,
    chunk_ray: Signal<Local, Bits<16>>,
    x0: Signal<Local, Bits<16>>,
    /// Perspective: each group's `[plane, first ray]` and its lanes' `x`
    /// (bit 16: the lane holds a ray).
    pub(crate) groups: Table<32, GROUP_BITS>,
    pub(crate) group_x: [Table<17, GROUP_BITS>; P],
    index: [Constant<Bits<16>>; P],
    shift: Constant<Bits<16>>,
}

impl<const P: usize> Groups<P> {
    /// For the views of `s`: a parallel build's `pos_x` table of a plane
    /// a word, a perspective build's group tables.
    pub fn new(s: &Cube3Sizes) -> Groups<P> {
        let k = |v: i64| Constant::new(((v as u64) & 0xffff).to_bits());
        let (planes, groups) = match s.perspective {
            true => (2, 1 << bits_for(s.groups() as u64)),
            false => (s.planes(), 2),
        };
        Groups {
            clock: Default::default(),
            host_write: Default::default(),
            host_address: Default::default(),
            host_data: Default::default(),
            u0: Default::default(),
            chunk: Default::default(),
            chunk_next: Default::default(),
            plane_count: Default::default(),
            plane: Default::default(),
            first_ray: Default::default(),
            x: std::array::from_fn(|_| Default::default()),
            holds: std::array::from_fn(|_| Default::default()),
            perspective: Constant::new(s.perspective),
            pos_x: ViewRom::new(ViewTable::PosX.base(), planes),
            chunk_ray: Default::default(),
            x0: Default::default(),
            groups: Table::new(ViewTable::Groups.base(), groups, &[(0, 32)]),
            group_x: std::array::from_fn(|j| {
                Table::new(ViewTable::GroupX(j).base(), groups, &[(0, 17)])
            }),
            index: std::array::from_fn(|j| k(j as i64)),
            shift: k(P.trailing_zeros() as i64),
        }
    }
}

impl<const P: usize> Logic for Groups<P> {
    #[hdl_gen]
    fn update(&mut self) {
        self.pos_x.clock.next = self.clock.val();
        self.pos_x.host_write.next = self.host_write.val();
        self.pos_x.host_address.next = self.host_address.val();
        self.pos_x.host_data.next = self.host_data.val();
        self.groups.clock.next = self.clock.val();
        self.groups.host_write.next = self.host_write.val();
        self.groups.host_address.next = self.host_address.val();
        self.groups.host_data.next = self.host_data.val();
        self.pos_x.address.next = self.plane_count.val().get_bits::<PLANE_BITS>(0);
        self.groups.address.next = self.chunk_next.val().get_bits::<GROUP_BITS>(0);
        self.chunk_ray.next = self.chunk.val().get_bits::<16>(0) << self.shift.val();
        self.x0.next = self.u0.val() + self.pos_x.data.val() + self.chunk_ray.val();
        self.plane.next = self.plane_count.val();
        self.first_ray.next = self.chunk_ray.val();
        if self.perspective.val() {
            self.plane.next = self.groups.data.val().get_bits::<16>(0);
            self.first_ray.next = self.groups.data.val().get_bits::<16>(16);
        }
        for j in 0..P {
            self.group_x[j].clock.next = self.clock.val();
            self.group_x[j].host_write.next = self.host_write.val();
            self.group_x[j].host_address.next = self.host_address.val();
            self.group_x[j].host_data.next = self.host_data.val();
            self.group_x[j].address.next = self.chunk_next.val().get_bits::<GROUP_BITS>(0);
            self.x[j].next = self.x0.val() + self.index[j].val();
            self.holds[j].next = true;
            if self.perspective.val() {
                self.x[j].next = self.group_x[j].data.val().get_bits::<16>(0);
                self.holds[j].next = self.group_x[j].data.val().get_bit(16);
            }
        }
    }
}
