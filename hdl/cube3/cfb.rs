//! Cube-3's beam fetch into the 2-D skewed buffers (§2, Figs. 2 and 3; §5,
//! Fig. 12): the CFB delivers the PRP of each scanline as beams, the Fast
//! Bus shears (parallel) or de-fans (perspective) them so that each
//! discrete ray becomes a row, and three 2-DSBs in turn take a PRP while
//! the other two are read as the `cur` and `next` streams of
//! [`super::trilin_lanes`].
//!
//! **CFB.** `P` memory modules (on chip, or an external RAM through the
//! `ext_*` ports) hold the volume in the view's traversal
//! order `(x, y, k)`, skewed as Cube-4L's CFB: voxel `(x, y, k)` in module
//! `(x + y + k) mod P` at address `x div P + y·b + k·b·n_y`, `b = ceil(n_x /
//! P)`, so any `P` voxels of a beam within `P` consecutive `x` lie in `P`
//! different modules. (Cube-4L's CFB reads beams along the dataset's first
//! axis in sweep order; the host loads this memory in the traversal order
//! of the base plane instead.)
//!
//! **Beams.** Scanline `v`'s PRP is beam `k` = the voxels `(X_k(u), Y_k(v),
//! k)` for the stream's rays `u` (the templates). Each clock reads a group
//! of up to `P` consecutive rays of one beam, through `P` lanes: lane `j`
//! reads ray `r + j` at `x_j = X_k(u_0 + r + j)`, from module `(x_j + y +
//! k) mod P`; voxels outside the volume read 0. Planes `0 .. K_w` are
//! written (`K_w = min(K + 1, G·P)`; plane `K`, behind the volume, is 0).
//!
//! - *Parallel* (a shear): `X_k(u) = u + pos_x[k]`, so every group is a
//!   chunk of `P` rays whose `x_j = x_0 + j` are consecutive:
//!   `K_w·ceil(R / P)` clocks a PRP, from counters and one table entry a
//!   plane.
//! - *Perspective* (de-fanning, Fig. 3): the rays diverge from the eye, so
//!   `X_k` grows by one or more from ray to ray and voxels between them are
//!   not fetched. A group is the next rays (up to `P`) while those whose
//!   voxel lies in the volume have distinct `x mod P`, so that they read
//!   distinct modules (the others read none): conflict-free, and up to `P`
//!   rays a clock where they lie more than a voxel apart. The host lists
//!   the groups of every plane ([`Group`]) and loads them into tables, one
//!   entry a clock, with `Y_k(v)` by scanline and plane. A PRP takes as
//!   many clocks as groups.
//!
//! **Fast Bus.** Ray `r` of plane `k` goes to 2-DSB module `(r + k) mod P`
//! at address `r·G + k div P`, so a ray's `P` planes of a segment lie in `P`
//! modules at one address. The write side is five stages, each ending in
//! registers, so no multiplier or crossbar lies between a block RAM and
//! another: (0) the group (its tables read a clock ahead, or the parallel
//! chunk's counters) is registered while `pos_y` is read; (1) the beam's
//! row; (2) each lane's memory module and address `x div P + y·b +
//! k·b·n_y`, and its ray's 2-DSB module and address; (3) memory module `m`
//! takes the address of the lane whose voxel it holds; (4) with the word,
//! 2-DSB module `d` takes the word of the lane whose ray it stores: a voxel
//! may travel from any module to any other (a `P`-way crossbar each way). In a parallel
//! view both are rotations, by `(x_0 + y + k) mod P` and `(r + k) mod P`;
//! between consecutive beams the first changes by `pos_x[k+1] - pos_x[k] +
//! pos_y[k+1] - pos_y[k] + 1`, the shift of the paper's Fast Bus. A
//! perspective view's lanes land in modules in any order, hence the
//! crossbar.
//!
//! **Reads.** Segment `s` of ray `r` reads address `r·G + s` of every module
//! of the `cur` and `next` buffers (a counter: the segments are read in
//! that order); lane `i` takes module `(r + i) mod P`.
//!
//! **Schedule.** Scanline periods of `T` clocks: in period `j` the buffer
//! `j mod 3` takes scanline `v_0 + j` (for `j <= S`) while, from period 2,
//! scanlines `v_0 + j - 2` (`cur`) and `v_0 + j - 1` (`next`) are read, `R·G`
//! segments on consecutive clocks, `valid` high. `T` is the longer of the
//! writes (the groups, and the row's and the memory's reads:
//! [`WRITE_LATENCY`](super::config::WRITE_LATENCY)) and the reads (`R·G`
//! and the read latency): [`BeamFetchConfig::period`].

use super::config::{Cube3Sizes, GROUP_BITS, PLANE_BITS};
use super::groups::Groups;
use super::schedule::Schedule;
use crate::common::ram::{bits_for, DepthRam};
use crate::common::regs::{Regs, ADDRESS_BITS};
use crate::common::table::Table;
use golden_model::host::{Reg, ViewTable};
use rust_hdl::prelude::*;

/// The beam fetch for `P` lanes: `A`-bit memory and `B`-bit 2-DSB
/// addresses.
#[derive(LogicBlock)]
pub struct BeamFetch<const P: usize, const A: usize, const B: usize> {
    pub clock: Signal<In, Clock>,
    /// The host port: the view's registers and tables.
    pub host_write: Signal<In, Bit>,
    pub host_address: Signal<In, Bits<ADDRESS_BITS>>,
    pub host_data: Signal<In, Bits<64>>,
    pub start: Signal<In, Bit>,
    /// A segment of `cur` and `next` is out this clock.
    pub valid: Signal<Out, Bit>,
    pub cur: [Signal<Out, Bits<16>>; P],
    pub next: [Signal<Out, Bits<16>>; P],
    /// External memory (`BeamFetchConfig::external`): each module's read
    /// address, and its word one clock later, as a synchronous RAM answers.
    pub ext_addr: [Signal<Out, Bits<32>>; P],
    pub ext_data: [Signal<In, Bits<16>>; P],
    /// Loading on-chip memory: one word per clock into module
    /// `load_module` (the host's order of `BeamFetchConfig::modules`).
    pub load_enable: Signal<In, Bit>,
    pub load_module: Signal<In, Bits<8>>,
    pub load_address: Signal<In, Bits<32>>,
    pub load_data: Signal<In, Bits<16>>,
    external: Constant<Bit>,
    /// The on-chip modules (two words each with external memory).
    memory: [DepthRam<Bits<16>, A>; P],
    word: [Signal<Local, Bits<16>>; P],
    buffer0: [DepthRam<Bits<16>, B>; P],
    buffer1: [DepthRam<Bits<16>, B>; P],
    buffer2: [DepthRam<Bits<16>, B>; P],
    /// This clock's group of rays.
    group: Groups<P>,
    /// `Y_k(v) - v` by plane (parallel), or by scanline and plane at
    /// `j·(K + 1) + k` (perspective: `row_stride = K + 1`); block RAM in a
    /// perspective build, read a clock after the group.
    pos_y: Table<16, GROUP_BITS>,
    /// `C3Stream`, `C3Dims`, `C3Address`, `C3Origin`.
    regs: Regs<4>,
    /// `K + 1` in a perspective build; a parallel build's is 0, so
    /// synthesis removes its multiplier.
    row_stride: Signal<Local, Bits<16>>,
    perspective: Constant<Bit>,
    row_entry: Signal<Local, Bits<32>>,
    /// `period·row_stride`, registered from the schedule's next period.
    row_base_r: DFF<Bits<32>>,
    pub(crate) schedule: Schedule,
    /// The group, registered beside `pos_y`'s read: its plane, first ray,
    /// each lane's `x` and whether it holds a ray, with the schedule's
    /// period, write flag and buffer.
    plane_r: DFF<Bits<16>>,
    first_ray_r: DFF<Bits<16>>,
    x_r: [DFF<Bits<16>>; P],
    holds_r: [DFF<Bit>; P],
    period_r: DFF<Bits<16>>,
    writing_r: DFF<Bit>,
    buffer_r: DFF<Bits<2>>,
    /// Write stage 1, with `pos_y`: the beam's row, the plane and
    /// `plane·plane_words`, and per lane its ray, `x` and whether it holds
    /// a ray; the write flag and buffer beside them.
    s1_row: DFF<Bits<16>>,
    s1_plane: DFF<Bits<16>>,
    s1_plane_segment: Signal<Local, Bits<16>>,
    s1_plane_offset: DFF<Bits<32>>,
    s1_ray: [DFF<Bits<16>>; P],
    s1_x: [DFF<Bits<16>>; P],
    s1_holds: [DFF<Bit>; P],
    s1_writing: DFF<Bit>,
    s1_buffer: DFF<Bits<2>>,
    /// Write stage 2, per lane: whether its voxel lies in the volume, its
    /// memory module and address, its 2-DSB module and address, and whether
    /// its ray is in the stream; computed, then registered.
    lane_inside: [Signal<Local, Bit>; P],
    lane_module: [Signal<Local, Bits<16>>; P],
    lane_column: [Signal<Local, Bits<16>>; P],
    lane_address: [Signal<Local, Bits<32>>; P],
    lane_dsb: [Signal<Local, Bits<16>>; P],
    lane_write_address: [Signal<Local, Bits<32>>; P],
    s2_inside: [DFF<Bit>; P],
    s2_module: [DFF<Bits<16>>; P],
    s2_address: [DFF<Bits<32>>; P],
    s2_holds: [DFF<Bit>; P],
    s2_dsb: [DFF<Bits<16>>; P],
    s2_write_address: [DFF<Bits<32>>; P],
    s2_in_stream: [DFF<Bit>; P],
    s2_writing: DFF<Bit>,
    s2_buffer: DFF<Bits<2>>,
    /// Write stage 3, per memory module: the address it reads (the lanes'
    /// crossbar), and whether it reads.
    address: [Signal<Local, Bits<32>>; P],
    reads: [Signal<Local, Bit>; P],
    /// Write stage 4, with the memory's data: stage 2's lane fields a
    /// clock later.
    holds_q: [DFF<Bit>; P],
    inside_q: [DFF<Bit>; P],
    module_q: [DFF<Bits<16>>; P],
    dsb_q: [DFF<Bits<16>>; P],
    write_address_q: [DFF<Bits<32>>; P],
    in_stream_q: [DFF<Bit>; P],
    write_q: DFF<Bit>,
    buffer_q: DFF<Bits<2>>,
    value: [Signal<Local, Bits<16>>; P],
    /// Per 2-DSB module: the lane's word and address, and whether one is
    /// written.
    dsb_data: [Signal<Local, Bits<16>>; P],
    dsb_write: [Signal<Local, Bit>; P],
    write_address: [Signal<Local, Bits<32>>; P],
    read_address: Signal<Local, Bits<32>>,
    /// The read side, one clock later: each module's `cur` and `next`
    /// words, chosen among the buffers and registered, so that a 2-DSB's
    /// depth cascade ends in a register...
    read_q: DFF<Bit>,
    lane_q: DFF<Bits<16>>,
    cur_q: DFF<Bits<2>>,
    next_q: DFF<Bits<2>>,
    cur_m: [DFF<Bits<16>>; P],
    next_m: [DFF<Bits<16>>; P],
    /// ... and a clock later the rotation to the lanes.
    read_q2: DFF<Bit>,
    lane_q2: DFF<Bits<16>>,
    index: [Constant<Bits<16>>; P],
    module_id: [Constant<Bits<8>>; P],
    buffer_id: [Constant<Bits<2>>; 3],
    one: Constant<Bits<16>>,
    mask: Constant<Bits<16>>,
    shift: Constant<Bits<16>>,
    n_x: Signal<Local, Bits<16>>,
    n_y: Signal<Local, Bits<16>>,
    n_k: Signal<Local, Bits<16>>,
    row_words: Signal<Local, Bits<16>>,
    plane_words: Signal<Local, Bits<16>>,
    v0: Signal<Local, Bits<16>>,
    rays: Signal<Local, Bits<16>>,
    segments: Signal<Local, Bits<16>>,
}

impl<const P: usize, const A: usize, const B: usize> BeamFetch<P, A, B> {
    /// For the views of `s`.
    pub fn new(s: &Cube3Sizes) -> Result<BeamFetch<P, A, B>, String> {
        crate::common::lanes::built(s.p)?;
        if s.p != P {
            return Err(format!(
                "sizes for {} pipelines given to a beam fetch of {P}",
                s.p
            ));
        }
        let n = s.n;
        let buffer_words = s.rays() * s.segments();
        if s.segments() * n >= 1 << 16
            || (!s.external() && s.module_words() > 1 << A)
            || buffer_words > 1 << B
        {
            return Err(format!(
                "volumes of {n} a side need more memory than this build's {A}-bit modules and {B}-bit buffers"
            ));
        }
        if s.planes() > 1 << PLANE_BITS {
            return Err(format!(
                "{} planes: the templates hold at most {}",
                s.planes(),
                1 << PLANE_BITS
            ));
        }
        let rows = if s.perspective {
            (s.scanlines() + 1) * s.planes()
        } else {
            s.planes()
        };
        if s.groups() > 1 << GROUP_BITS || rows > 1 << GROUP_BITS {
            return Err(format!(
                "{} groups of rays and {rows} rows: the perspective templates hold at most 2^{GROUP_BITS}",
                s.groups()
            ));
        }
        let k = |v: i64| Constant::new(((v as u64) & 0xffff).to_bits());
        let words = if s.external() { 2 } else { s.module_words() };
        let ram = || DepthRam::with_words(words);
        // A 2-DSB word holds one voxel: its `voxel_bits`, not the 16-bit
        // datapath word (half the block RAM for 8-bit voxels).
        let voxel = ((1u64 << s.voxel_bits) - 1).to_bits();
        let buffer =
            || DepthRam::with_words(buffer_words).fields(&[(0, s.voxel_bits as usize)], voxel);
        Ok(BeamFetch {
            clock: Default::default(),
            host_write: Default::default(),
            host_address: Default::default(),
            host_data: Default::default(),
            start: Default::default(),
            valid: Default::default(),
            cur: std::array::from_fn(|_| Default::default()),
            next: std::array::from_fn(|_| Default::default()),
            ext_addr: std::array::from_fn(|_| Default::default()),
            ext_data: std::array::from_fn(|_| Default::default()),
            load_enable: Default::default(),
            load_module: Default::default(),
            load_address: Default::default(),
            load_data: Default::default(),
            external: Constant::new(s.external()),
            memory: std::array::from_fn(|_| ram()),
            word: std::array::from_fn(|_| Default::default()),
            buffer0: std::array::from_fn(|_| buffer()),
            buffer1: std::array::from_fn(|_| buffer()),
            buffer2: std::array::from_fn(|_| buffer()),
            group: Groups::new(s),
            pos_y: Table::new(
                ViewTable::PosY.base(),
                1 << bits_for(rows as u64),
                &[(0, 16)],
            ),
            regs: Regs::new(
                [Reg::C3Stream, Reg::C3Dims, Reg::C3Address, Reg::C3Origin].map(Reg::address),
            ),
            row_entry: Default::default(),
            row_stride: Default::default(),
            perspective: Constant::new(s.perspective),
            row_base_r: Default::default(),
            schedule: Schedule::default(),
            plane_r: Default::default(),
            first_ray_r: Default::default(),
            x_r: std::array::from_fn(|_| Default::default()),
            holds_r: std::array::from_fn(|_| Default::default()),
            period_r: Default::default(),
            writing_r: Default::default(),
            buffer_r: Default::default(),
            s1_row: Default::default(),
            s1_plane: Default::default(),
            s1_plane_segment: Default::default(),
            s1_plane_offset: Default::default(),
            s1_writing: Default::default(),
            s1_buffer: Default::default(),
            s2_writing: Default::default(),
            s2_buffer: Default::default(),
            write_q: Default::default(),
            buffer_q: Default::default(),
            s1_ray: std::array::from_fn(|_| Default::default()),
            s1_x: std::array::from_fn(|_| Default::default()),
            s1_holds: std::array::from_fn(|_| Default::default()),
            lane_inside: std::array::from_fn(|_| Default::default()),
            lane_module: std::array::from_fn(|_| Default::default()),
            lane_column: std::array::from_fn(|_| Default::default()),
            lane_address: std::array::from_fn(|_| Default::default()),
            lane_dsb: std::array::from_fn(|_| Default::default()),
            lane_write_address: std::array::from_fn(|_| Default::default()),
            s2_inside: std::array::from_fn(|_| Default::default()),
            s2_module: std::array::from_fn(|_| Default::default()),
            s2_address: std::array::from_fn(|_| Default::default()),
            s2_holds: std::array::from_fn(|_| Default::default()),
            s2_dsb: std::array::from_fn(|_| Default::default()),
            s2_write_address: std::array::from_fn(|_| Default::default()),
            s2_in_stream: std::array::from_fn(|_| Default::default()),
            address: std::array::from_fn(|_| Default::default()),
            reads: std::array::from_fn(|_| Default::default()),
            holds_q: std::array::from_fn(|_| Default::default()),
            inside_q: std::array::from_fn(|_| Default::default()),
            module_q: std::array::from_fn(|_| Default::default()),
            dsb_q: std::array::from_fn(|_| Default::default()),
            write_address_q: std::array::from_fn(|_| Default::default()),
            in_stream_q: std::array::from_fn(|_| Default::default()),
            value: std::array::from_fn(|_| Default::default()),
            dsb_data: std::array::from_fn(|_| Default::default()),
            dsb_write: std::array::from_fn(|_| Default::default()),
            write_address: std::array::from_fn(|_| Default::default()),
            read_address: Default::default(),
            read_q: Default::default(),
            lane_q: Default::default(),
            cur_q: Default::default(),
            next_q: Default::default(),
            cur_m: std::array::from_fn(|_| Default::default()),
            next_m: std::array::from_fn(|_| Default::default()),
            read_q2: Default::default(),
            lane_q2: Default::default(),
            index: std::array::from_fn(|m| k(m as i64)),
            module_id: std::array::from_fn(|m| Constant::new((m as u64).to_bits())),
            buffer_id: std::array::from_fn(|b| Constant::new((b as u64).to_bits())),
            one: k(1),
            mask: k(P as i64 - 1),
            shift: k(P.trailing_zeros() as i64),
            n_x: Default::default(),
            n_y: Default::default(),
            n_k: Default::default(),
            row_words: Default::default(),
            plane_words: Default::default(),
            v0: Default::default(),
            rays: Default::default(),
            segments: Default::default(),
        })
    }

    /// Load the memory modules (`BeamFetchConfig::modules`).
    pub fn preload(&mut self, modules: &[Vec<u16>]) {
        for (m, words) in self.memory.iter_mut().zip(modules) {
            m.preload(words.iter().map(|&w| (w as u64).to_bits()));
        }
    }
}

impl<const P: usize, const A: usize, const B: usize> Logic for BeamFetch<P, A, B> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            plane_r,
            first_ray_r,
            period_r,
            writing_r,
            buffer_r,
            row_base_r,
            s1_row,
            s1_plane,
            s1_plane_offset,
            s1_writing,
            s1_buffer,
            s2_writing,
            s2_buffer,
            write_q,
            buffer_q,
            read_q,
            lane_q,
            cur_q,
            next_q,
            read_q2,
            lane_q2
        );
        // The view's registers.
        self.regs.clock.next = self.clock.val();
        self.regs.host_write.next = self.host_write.val();
        self.regs.host_address.next = self.host_address.val();
        self.regs.host_data.next = self.host_data.val();
        self.rays.next = self.regs.q[0].val().get_bits::<16>(0);
        self.segments.next = self.regs.q[0].val().get_bits::<16>(32);
        self.n_x.next = self.regs.q[1].val().get_bits::<16>(0);
        self.n_y.next = self.regs.q[1].val().get_bits::<16>(16);
        self.n_k.next = self.regs.q[1].val().get_bits::<16>(32);
        self.row_words.next = self.regs.q[2].val().get_bits::<16>(0);
        self.plane_words.next = self.regs.q[2].val().get_bits::<16>(16);
        self.row_stride.next = 0.into();
        if self.perspective.val() {
            self.row_stride.next = self.regs.q[2].val().get_bits::<16>(32);
        }
        self.v0.next = self.regs.q[3].val().get_bits::<16>(16);
        self.pos_y.clock.next = self.clock.val();
        self.pos_y.host_write.next = self.host_write.val();
        self.pos_y.host_address.next = self.host_address.val();
        self.pos_y.host_data.next = self.host_data.val();
        self.group.clock.next = self.clock.val();
        self.group.host_write.next = self.host_write.val();
        self.group.host_address.next = self.host_address.val();
        self.group.host_data.next = self.host_data.val();
        self.group.u0.next = self.regs.q[3].val().get_bits::<16>(0);
        self.schedule.clock.next = self.clock.val();
        self.schedule.start.next = self.start.val();
        self.schedule.host_write.next = self.host_write.val();
        self.schedule.host_address.next = self.host_address.val();
        self.schedule.host_data.next = self.host_data.val();
        // Write stage 0: this clock's group of rays, and its row's entry
        // (`period·row_stride` registered from the next period).
        self.group.chunk.next = self.schedule.chunk.val();
        self.group.chunk_next.next = self.schedule.chunk_next.val();
        self.group.plane_count.next = self.schedule.plane.val();
        self.row_base_r.d.next = self.schedule.period_next.val() * self.row_stride.val();
        self.row_entry.next = self.row_base_r.q.val() + bit_cast::<32, 16>(self.group.plane.val());
        self.pos_y.address.next = self.row_entry.val().get_bits::<GROUP_BITS>(0);
        self.plane_r.d.next = self.group.plane.val();
        self.first_ray_r.d.next = self.group.first_ray.val();
        self.period_r.d.next = self.schedule.period.val();
        self.writing_r.d.next = self.schedule.writing.val();
        self.buffer_r.d.next = self.schedule.write_buffer.val();
        // Stage 1, with the row's `pos_y`: the beam's row.
        self.s1_row.d.next = self.v0.val() + self.period_r.q.val() + self.pos_y.data.val();
        self.s1_plane.d.next = self.plane_r.q.val();
        self.s1_plane_offset.d.next = self.plane_r.q.val() * self.plane_words.val();
        self.s1_plane_segment.next = self.s1_plane.q.val() >> self.shift.val();
        self.s1_writing.d.next = self.writing_r.q.val();
        self.s1_buffer.d.next = self.buffer_r.q.val();
        self.s2_writing.d.next = self.s1_writing.q.val();
        self.s2_buffer.d.next = self.s1_buffer.q.val();
        self.write_q.d.next = self.s2_writing.q.val();
        self.buffer_q.d.next = self.s2_buffer.q.val();
        for j in 0..P {
            self.x_r[j].clock.next = self.clock.val();
            self.holds_r[j].clock.next = self.clock.val();
            self.s1_ray[j].clock.next = self.clock.val();
            self.s1_x[j].clock.next = self.clock.val();
            self.s1_holds[j].clock.next = self.clock.val();
            self.s2_inside[j].clock.next = self.clock.val();
            self.s2_module[j].clock.next = self.clock.val();
            self.s2_address[j].clock.next = self.clock.val();
            self.s2_holds[j].clock.next = self.clock.val();
            self.s2_dsb[j].clock.next = self.clock.val();
            self.s2_write_address[j].clock.next = self.clock.val();
            self.s2_in_stream[j].clock.next = self.clock.val();
            self.holds_q[j].clock.next = self.clock.val();
            self.inside_q[j].clock.next = self.clock.val();
            self.module_q[j].clock.next = self.clock.val();
            self.dsb_q[j].clock.next = self.clock.val();
            self.write_address_q[j].clock.next = self.clock.val();
            self.in_stream_q[j].clock.next = self.clock.val();
            self.x_r[j].d.next = self.group.x[j].val();
            self.holds_r[j].d.next = self.group.holds[j].val();
            self.s1_ray[j].d.next = self.first_ray_r.q.val() + self.index[j].val();
            self.s1_x[j].d.next = self.x_r[j].q.val();
            self.s1_holds[j].d.next = self.holds_r[j].q.val();
            // Stage 2: each lane's memory module and address, and the 2-DSB
            // module and address of its ray (ray r of plane k to module
            // (r + k) mod P at r*G + k div P).
            self.lane_inside[j].next = self.s1_holds[j].q.val()
                & !self.s1_x[j].q.val().get_bit(15)
                & (self.s1_x[j].q.val() < self.n_x.val())
                & !self.s1_row.q.val().get_bit(15)
                & (self.s1_row.q.val() < self.n_y.val())
                & (self.s1_plane.q.val() < self.n_k.val());
            self.lane_module[j].next =
                (self.s1_x[j].q.val() + self.s1_row.q.val() + self.s1_plane.q.val())
                    & self.mask.val();
            // (`* one` widens the column to 32 bits inside the loop.)
            self.lane_column[j].next = self.s1_x[j].q.val() >> self.shift.val();
            self.lane_address[j].next = self.lane_column[j].val() * self.one.val()
                + self.s1_row.q.val() * self.row_words.val()
                + self.s1_plane_offset.q.val();
            self.lane_dsb[j].next =
                (self.s1_ray[j].q.val() + self.s1_plane.q.val()) & self.mask.val();
            self.lane_write_address[j].next = self.s1_ray[j].q.val() * self.segments.val()
                + bit_cast::<32, 16>(self.s1_plane_segment.val());
            self.s2_inside[j].d.next = self.lane_inside[j].val();
            self.s2_module[j].d.next = self.lane_module[j].val();
            self.s2_address[j].d.next = self.lane_address[j].val();
            self.s2_holds[j].d.next = self.s1_holds[j].q.val();
            self.s2_dsb[j].d.next = self.lane_dsb[j].val();
            self.s2_write_address[j].d.next = self.lane_write_address[j].val();
            self.s2_in_stream[j].d.next = self.s1_ray[j].q.val() < self.rays.val();
            // Stage 4's copies.
            self.holds_q[j].d.next = self.s2_holds[j].q.val();
            self.inside_q[j].d.next = self.s2_inside[j].q.val();
            self.module_q[j].d.next = self.s2_module[j].q.val();
            self.dsb_q[j].d.next = self.s2_dsb[j].q.val();
            self.write_address_q[j].d.next = self.s2_write_address[j].q.val();
            self.in_stream_q[j].d.next = self.s2_in_stream[j].q.val();
        }
        // Stage 3, lanes to memory modules: each module reads the voxel of
        // the lane in it (at most one: the lanes' x lie within P
        // consecutive).
        for m in 0..P {
            self.address[m].next = 0.into();
            self.reads[m].next = false;
            for j in 0..P {
                if self.s2_inside[j].q.val() & (self.s2_module[j].q.val() == self.index[m].val()) {
                    self.address[m].next = self.s2_address[j].q.val();
                    self.reads[m].next = true;
                }
            }
            self.memory[m].read_clock.next = self.clock.val();
            self.memory[m].write_clock.next = self.clock.val();
            self.memory[m].write_enable.next = self.load_enable.val()
                & (self.load_module.val() == self.module_id[m].val())
                & !self.external.val();
            self.memory[m].write_address.next = self.load_address.val().get_bits::<A>(0);
            self.memory[m].write_data.next = self.load_data.val();
            // Outside the volume the module reads word 0, and the voxel is 0.
            self.memory[m].read_address.next = 0.into();
            self.ext_addr[m].next = 0.into();
            if self.reads[m].val() & !self.external.val() {
                self.memory[m].read_address.next = self.address[m].val().get_bits::<A>(0);
            }
            if self.reads[m].val() & self.external.val() {
                self.ext_addr[m].next = self.address[m].val();
            }
            self.word[m].next = self.memory[m].read_data.val();
            if self.external.val() {
                self.word[m].next = self.ext_data[m].val();
            }
        }
        // Stage 4: memory modules back to lanes, and lanes to 2-DSB modules.
        for j in 0..P {
            self.value[j].next = 0.into();
            for m in 0..P {
                if self.inside_q[j].q.val() & (self.module_q[j].q.val() == self.index[m].val()) {
                    self.value[j].next = self.word[m].val();
                }
            }
        }
        for d in 0..P {
            self.dsb_data[d].next = 0.into();
            self.write_address[d].next = 0.into();
            self.dsb_write[d].next = false;
            for j in 0..P {
                if self.holds_q[j].q.val() & (self.dsb_q[j].q.val() == self.index[d].val()) {
                    self.dsb_data[d].next = self.value[j].val();
                    self.write_address[d].next = self.write_address_q[j].q.val();
                    self.dsb_write[d].next = self.in_stream_q[j].q.val();
                }
            }
            self.buffer0[d].write_clock.next = self.clock.val();
            self.buffer1[d].write_clock.next = self.clock.val();
            self.buffer2[d].write_clock.next = self.clock.val();
            self.buffer0[d].write_address.next = self.write_address[d].val().get_bits::<B>(0);
            self.buffer1[d].write_address.next = self.write_address[d].val().get_bits::<B>(0);
            self.buffer2[d].write_address.next = self.write_address[d].val().get_bits::<B>(0);
            self.buffer0[d].write_data.next = self.dsb_data[d].val();
            self.buffer1[d].write_data.next = self.dsb_data[d].val();
            self.buffer2[d].write_data.next = self.dsb_data[d].val();
            self.buffer0[d].write_enable.next = self.write_q.q.val()
                & self.dsb_write[d].val()
                & (self.buffer_q.q.val() == self.buffer_id[0].val());
            self.buffer1[d].write_enable.next = self.write_q.q.val()
                & self.dsb_write[d].val()
                & (self.buffer_q.q.val() == self.buffer_id[1].val());
            self.buffer2[d].write_enable.next = self.write_q.q.val()
                & self.dsb_write[d].val()
                & (self.buffer_q.q.val() == self.buffer_id[2].val());
        }
        // Reads: segment s of ray r at r*G + s in every module (the
        // schedule's count of reads); a clock later each module's `cur`
        // and `next` words are chosen and registered, and a clock after
        // that lane i takes module (r + i) mod P.
        self.read_address.next = 0.into();
        if self.schedule.reading.val() {
            self.read_address.next = self.schedule.read_address.val();
        }
        self.read_q.d.next = self.schedule.reading.val();
        self.lane_q.d.next = self.schedule.ray.val() & self.mask.val();
        self.cur_q.d.next = self.schedule.cur_buffer.val();
        self.next_q.d.next = self.schedule.next_buffer.val();
        self.read_q2.d.next = self.read_q.q.val();
        self.lane_q2.d.next = self.lane_q.q.val();
        for m in 0..P {
            self.buffer0[m].read_clock.next = self.clock.val();
            self.buffer1[m].read_clock.next = self.clock.val();
            self.buffer2[m].read_clock.next = self.clock.val();
            self.buffer0[m].read_address.next = self.read_address.val().get_bits::<B>(0);
            self.buffer1[m].read_address.next = self.read_address.val().get_bits::<B>(0);
            self.buffer2[m].read_address.next = self.read_address.val().get_bits::<B>(0);
            self.cur_m[m].clock.next = self.clock.val();
            self.next_m[m].clock.next = self.clock.val();
            self.cur_m[m].d.next = 0.into();
            if self.cur_q.q.val() == self.buffer_id[0].val() {
                self.cur_m[m].d.next = self.buffer0[m].read_data.val();
            }
            if self.cur_q.q.val() == self.buffer_id[1].val() {
                self.cur_m[m].d.next = self.buffer1[m].read_data.val();
            }
            if self.cur_q.q.val() == self.buffer_id[2].val() {
                self.cur_m[m].d.next = self.buffer2[m].read_data.val();
            }
            self.next_m[m].d.next = 0.into();
            if self.next_q.q.val() == self.buffer_id[0].val() {
                self.next_m[m].d.next = self.buffer0[m].read_data.val();
            }
            if self.next_q.q.val() == self.buffer_id[1].val() {
                self.next_m[m].d.next = self.buffer1[m].read_data.val();
            }
            if self.next_q.q.val() == self.buffer_id[2].val() {
                self.next_m[m].d.next = self.buffer2[m].read_data.val();
            }
        }
        for i in 0..P {
            self.cur[i].next = 0.into();
            self.next[i].next = 0.into();
            for m in 0..P {
                if ((self.index[i].val() + self.lane_q2.q.val()) & self.mask.val())
                    == self.index[m].val()
                {
                    self.cur[i].next = self.cur_m[m].q.val();
                    self.next[i].next = self.next_m[m].q.val();
                }
            }
        }
        self.valid.next = self.read_q2.q.val();
    }
}
