//! Cube-3's beam fetch into the 2-D skewed buffers (§2, Figs. 2 and 3; §5,
//! Fig. 12): the CFB delivers the PRP of each scanline as beams, the Fast
//! Bus shears (parallel) or de-fans (perspective) them so that each
//! discrete ray becomes a row, and three 2-DSBs in turn take a PRP while
//! the other two are read as the `cur` and `next` streams of
//! [`crate::trilin_lanes`].
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
//!   `K_w·ceil(R / P)` clocks a PRP, from counters and one ROM entry a
//!   plane.
//! - *Perspective* (de-fanning, Fig. 3): the rays diverge from the eye, so
//!   `X_k` grows by one or more from ray to ray and voxels between them are
//!   not fetched. A group is as many rays (up to `P`) as have their `x`
//!   within `P` consecutive voxels, which makes it conflict-free; the
//!   host lists the groups of every plane ([`Group`]) and ROMs hold them,
//!   one entry a clock, with `Y_k(v)` by scanline and plane. A PRP takes as
//!   many clocks as groups.
//!
//! **Fast Bus.** Ray `r` of plane `k` goes to 2-DSB module `(r + k) mod P`
//! at address `r·G + k div P`, so a ray's `P` planes of a segment lie in `P`
//! modules at one address. Memory module `m` takes the address of the lane
//! whose voxel it holds, and one clock later 2-DSB module `d` takes the
//! word of the lane whose ray it stores: a voxel may travel from any module
//! to any other in a clock (a `P`-way crossbar each way). In a parallel
//! view both are rotations, by `(x_0 + y + k) mod P` and `(r + k) mod P`;
//! between consecutive beams the first changes by `pos_x[k+1] - pos_x[k] +
//! pos_y[k+1] - pos_y[k] + 1`, the shift of the paper's Fast Bus. A
//! perspective view's lanes land in modules in any order, hence the
//! crossbar.
//!
//! **Reads.** Segment `s` of ray `r` reads address `r·G + s` of every module
//! of the `cur` and `next` buffers; lane `i` takes module `(r + i) mod P`.
//!
//! **Schedule.** Scanline periods of `T` clocks: in period `j` the buffer
//! `j mod 3` takes scanline `v_0 + j` (for `j <= S`) while, from period 2,
//! scanlines `v_0 + j - 2` (`cur`) and `v_0 + j - 1` (`next`) are read, `R·G`
//! segments on consecutive clocks, `valid` high. `T` is the longer of the
//! writes (the groups, and the read latency) and the reads (`R·G` and the
//! read latency): [`BeamFetchConfig::period`].

use crate::ram::DepthRam;
use golden_model::cube3::plan::{Template, View};
use rust_hdl::prelude::*;
use scene::volume::Volume;

/// Address bits of the parallel template ROM: up to 1023 planes.
pub const PLANE_BITS: usize = 10;
/// Address bits of the perspective group and row ROMs.
pub const GROUP_BITS: usize = 16;

/// One clock of a perspective PRP's writes: plane `plane`, stream rays
/// `ray .. ray + x.len()` at beam positions `x` (increasing, within `P`
/// consecutive voxels).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Group {
    pub plane: usize,
    pub ray: usize,
    pub x: Vec<i32>,
}

/// What the beam fetch is built from.
#[derive(Debug, Clone)]
pub struct BeamFetchConfig {
    pub p: usize,
    /// Traversal dims `[n_x, n_y, K]`.
    pub dims: [usize; 3],
    /// Stream rays `u0 .. u0 + rays` of scanlines `v0 .. v0 + scanlines`.
    pub u0: i32,
    pub v0: i32,
    pub rays: usize,
    pub scanlines: usize,
    pub segments: usize,
    /// Parallel: `pos_x[k]`, `pos_y[k]` for `k` in `0 ..= K`. Perspective:
    /// `pos_y[j·(K + 1) + k] = Y_k(v_0 + j) - v_0 - j` for the written
    /// scanlines `j` in `0 ..= S`, and `pos_x` is empty.
    pub pos_x: Vec<i32>,
    pub pos_y: Vec<i32>,
    /// Perspective: the groups of every written plane, in order.
    pub groups: Vec<Group>,
    /// The volume lives in external memory, not in on-chip modules.
    pub external: bool,
}

impl BeamFetchConfig {
    pub fn new(
        view: &View,
        p: usize,
        u0: i32,
        rays: usize,
        v0: i32,
        scanlines: usize,
    ) -> Result<BeamFetchConfig, String> {
        let mut c = BeamFetchConfig {
            p,
            dims: view.dims,
            u0,
            v0,
            rays,
            scanlines,
            segments: view.dims[2].div_ceil(p),
            pos_x: vec![],
            pos_y: vec![],
            groups: vec![],
            external: false,
        };
        match (&view.x, &view.y) {
            (Template::Parallel { pos: px, .. }, Template::Parallel { pos: py, .. }) => {
                c.pos_x = px.clone();
                c.pos_y = py.clone();
            }
            (Template::Perspective { .. }, Template::Perspective { .. }) => {
                if !view.x.covers(u0, rays) || !view.y.covers(v0, scanlines + 1) {
                    return Err(
                        "the stream's rays or scanlines lie outside the view's templates".into(),
                    );
                }
                let nk = view.dims[2];
                c.pos_y = (0..=scanlines as i32)
                    .flat_map(|j| (0..=nk).map(move |k| (j, k)))
                    .map(|(j, k)| view.y.pos(v0 + j, k) - v0 - j)
                    .collect();
                for k in 0..c.planes_written() {
                    let x = |r: usize| view.x.pos(u0 + r as i32, k);
                    let mut r = 0;
                    while r < rays {
                        let mut n = 1;
                        while n < p && r + n < rays && x(r + n) - x(r) < p as i32 {
                            if x(r + n) <= x(r + n - 1) {
                                return Err(format!(
                                    "plane {k}: rays {} and {} do not diverge",
                                    u0 + (r + n - 1) as i32,
                                    u0 + (r + n) as i32
                                ));
                            }
                            n += 1;
                        }
                        c.groups.push(Group {
                            plane: k,
                            ray: r,
                            x: (r..r + n).map(x).collect(),
                        });
                        r += n;
                    }
                }
            }
            _ => return Err("a view's templates are both parallel or both perspective".into()),
        }
        Ok(c)
    }

    /// A perspective view: the groups and rows come from ROMs.
    pub fn perspective(&self) -> bool {
        !self.groups.is_empty()
    }

    /// Clocks of a PRP's writes.
    pub fn write_clocks(&self) -> usize {
        if self.perspective() {
            self.groups.len()
        } else {
            self.planes_written() * self.rays.div_ceil(self.p)
        }
    }

    /// Planes written per PRP.
    pub fn planes_written(&self) -> usize {
        (self.dims[2] + 1).min(self.segments * self.p)
    }

    /// Clocks of a scanline period.
    pub fn period(&self) -> usize {
        let writes = self.write_clocks() + 1;
        let reads = self.rays * self.segments + 1;
        writes.max(reads)
    }

    /// Clocks from `start` to the last segment read: `S + 2` periods.
    pub fn clocks(&self) -> usize {
        (self.scanlines + 2) * self.period()
    }

    /// Words per memory module: `b·n_y·K`.
    pub fn module_words(&self) -> usize {
        let [nx, ny, nk] = self.dims;
        nx.div_ceil(self.p) * ny * nk
    }

    /// The memory modules' contents: `vol` in `view`'s traversal order,
    /// skewed.
    pub fn modules(&self, vol: &Volume, view: &View) -> Vec<Vec<u16>> {
        let [nx, ny, nk] = self.dims;
        let b = nx.div_ceil(self.p);
        let mut m = vec![vec![0u16; self.module_words()]; self.p];
        for k in 0..nk {
            for y in 0..ny {
                for x in 0..nx {
                    let [u, v, w] = view
                        .voxel(x as i32, y as i32, k)
                        .expect("a traversal voxel inside the volume");
                    m[(x + y + k) % self.p][x / self.p + y * b + k * b * ny] = vol.get(u, v, w);
                }
            }
        }
        m
    }
}

/// A ROM of 16-bit two's-complement template entries.
fn rom16<const N: usize>(v: &[i32]) -> ROM<Bits<16>, N> {
    v.iter().map(|&x| ((x as u64) & 0xffff).to_bits()).into()
}

/// The beam fetch for `P` lanes: `A`-bit memory and `B`-bit 2-DSB
/// addresses.
#[derive(LogicBlock)]
pub struct BeamFetch<const P: usize, const A: usize, const B: usize> {
    pub clock: Signal<In, Clock>,
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
    /// `j·(K + 1) + k` (perspective: `row_stride = K + 1`).
    pos_y: ROM<Bits<16>, 32>,
    row_stride: Constant<Bits<16>>,
    row_entry: Signal<Local, Bits<32>>,
    schedule: Schedule,
    /// The write side: this clock's plane, row and first ray, and per lane
    /// its ray, voxel `x`, module, address and whether it holds a ray and
    /// lies in the volume.
    row: Signal<Local, Bits<16>>,
    lane_ray: [Signal<Local, Bits<16>>; P],
    lane_inside: [Signal<Local, Bit>; P],
    lane_module: [Signal<Local, Bits<16>>; P],
    lane_column: [Signal<Local, Bits<16>>; P],
    lane_address: [Signal<Local, Bits<32>>; P],
    /// Per memory module: the address it reads, and whether it reads.
    address: [Signal<Local, Bits<32>>; P],
    reads: [Signal<Local, Bit>; P],
    /// One clock later, with the memory's data.
    holds_q: [DFF<Bit>; P],
    inside_q: [DFF<Bit>; P],
    module_q: [DFF<Bits<16>>; P],
    ray_q: [DFF<Bits<16>>; P],
    plane_q: DFF<Bits<16>>,
    write_q: DFF<Bit>,
    plane_segment: Signal<Local, Bits<16>>,
    buffer_q: DFF<Bits<2>>,
    value: [Signal<Local, Bits<16>>; P],
    /// Per 2-DSB module: the lane's word, ray and whether one is written.
    dsb_data: [Signal<Local, Bits<16>>; P],
    dsb_ray: [Signal<Local, Bits<16>>; P],
    dsb_write: [Signal<Local, Bit>; P],
    write_address: [Signal<Local, Bits<32>>; P],
    read_address: Signal<Local, Bits<32>>,
    /// The read side, one clock later: the rotation and the buffers.
    read_q: DFF<Bit>,
    lane_q: DFF<Bits<16>>,
    cur_q: DFF<Bits<2>>,
    next_q: DFF<Bits<2>>,
    index: [Constant<Bits<16>>; P],
    module_id: [Constant<Bits<8>>; P],
    buffer_id: [Constant<Bits<2>>; 3],
    one: Constant<Bits<16>>,
    mask: Constant<Bits<16>>,
    shift: Constant<Bits<16>>,
    n_x: Constant<Bits<16>>,
    n_y: Constant<Bits<16>>,
    n_k: Constant<Bits<16>>,
    row_words: Constant<Bits<16>>,
    plane_words: Constant<Bits<16>>,
    v0: Constant<Bits<16>>,
    rays: Constant<Bits<16>>,
    segments: Constant<Bits<16>>,
}

impl<const P: usize, const A: usize, const B: usize> BeamFetch<P, A, B> {
    pub fn new(c: &BeamFetchConfig) -> Result<BeamFetch<P, A, B>, String> {
        let [nx, ny, nk] = c.dims;
        let b = nx.div_ceil(P);
        if c.p != P || !P.is_power_of_two() || P > 8 {
            return Err(format!(
                "hardware.pipelines {} unsupported (1, 2, 4 or 8)",
                c.p
            ));
        }
        if b * ny >= 1 << 16
            || (!c.external && c.module_words() > 1 << A)
            || c.rays * c.segments > 1 << B
        {
            return Err(format!(
                "a {nx}x{ny}x{nk} volume needs more memory than this build's {A}-bit modules and {B}-bit buffers"
            ));
        }
        if nk >= 1 << PLANE_BITS {
            return Err(format!(
                "{nk} planes: the templates hold at most {}",
                (1 << PLANE_BITS) - 1
            ));
        }
        if c.groups.len() > 1 << GROUP_BITS || c.pos_y.len() > 1 << GROUP_BITS {
            return Err(format!(
                "{} groups of rays and {} rows: the perspective templates hold at most 2^{GROUP_BITS}",
                c.groups.len(),
                c.pos_y.len()
            ));
        }
        let k = |v: i64| Constant::new(((v as u64) & 0xffff).to_bits());
        let words = if c.external {
            2
        } else {
            c.module_words().max(2)
        };
        let ram = || DepthRam::with_words(words);
        let buffer = || DepthRam::with_words((c.rays * c.segments).max(2));
        Ok(BeamFetch {
            clock: Default::default(),
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
            external: Constant::new(c.external),
            memory: std::array::from_fn(|_| ram()),
            word: std::array::from_fn(|_| Default::default()),
            buffer0: std::array::from_fn(|_| buffer()),
            buffer1: std::array::from_fn(|_| buffer()),
            buffer2: std::array::from_fn(|_| buffer()),
            group: Groups::new(c),
            pos_y: rom16(&c.pos_y),
            row_entry: Default::default(),
            row_stride: k(if c.perspective() { nk as i64 + 1 } else { 0 }),
            schedule: Schedule::new(c),
            row: Default::default(),
            lane_ray: std::array::from_fn(|_| Default::default()),
            lane_inside: std::array::from_fn(|_| Default::default()),
            lane_module: std::array::from_fn(|_| Default::default()),
            lane_column: std::array::from_fn(|_| Default::default()),
            lane_address: std::array::from_fn(|_| Default::default()),
            address: std::array::from_fn(|_| Default::default()),
            reads: std::array::from_fn(|_| Default::default()),
            holds_q: std::array::from_fn(|_| Default::default()),
            inside_q: std::array::from_fn(|_| Default::default()),
            module_q: std::array::from_fn(|_| Default::default()),
            ray_q: std::array::from_fn(|_| Default::default()),
            plane_q: Default::default(),
            write_q: Default::default(),
            plane_segment: Default::default(),
            buffer_q: Default::default(),
            value: std::array::from_fn(|_| Default::default()),
            dsb_data: std::array::from_fn(|_| Default::default()),
            dsb_ray: std::array::from_fn(|_| Default::default()),
            dsb_write: std::array::from_fn(|_| Default::default()),
            write_address: std::array::from_fn(|_| Default::default()),
            read_address: Default::default(),
            read_q: Default::default(),
            lane_q: Default::default(),
            cur_q: Default::default(),
            next_q: Default::default(),
            index: std::array::from_fn(|m| k(m as i64)),
            module_id: std::array::from_fn(|m| Constant::new((m as u64).to_bits())),
            buffer_id: std::array::from_fn(|b| Constant::new((b as u64).to_bits())),
            one: k(1),
            mask: k(P as i64 - 1),
            shift: k(P.trailing_zeros() as i64),
            n_x: k(nx as i64),
            n_y: k(ny as i64),
            n_k: k(nk as i64),
            row_words: k(b as i64),
            plane_words: k((b * ny) as i64),
            v0: k(c.v0 as i64),
            rays: k(c.rays as i64),
            segments: k(c.segments as i64),
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
        dff_setup!(self, clock, plane_q, write_q, buffer_q, read_q, lane_q, cur_q, next_q);
        self.schedule.clock.next = self.clock.val();
        self.schedule.start.next = self.start.val();
        // This clock's group of rays, and its beam's row.
        self.group.chunk.next = self.schedule.chunk.val();
        self.group.plane_count.next = self.schedule.plane.val();
        self.row_entry.next = self.schedule.period.val() * self.row_stride.val()
            + bit_cast::<32, 16>(self.group.plane.val());
        self.pos_y.address.next = self.row_entry.val();
        self.row.next = self.v0.val() + self.schedule.period.val() + self.pos_y.data.val();
        for j in 0..P {
            self.lane_ray[j].next = self.group.first_ray.val() + self.index[j].val();
            self.lane_inside[j].next = self.group.holds[j].val()
                & !self.group.x[j].val().get_bit(15)
                & (self.group.x[j].val() < self.n_x.val())
                & !self.row.val().get_bit(15)
                & (self.row.val() < self.n_y.val())
                & (self.group.plane.val() < self.n_k.val());
            self.lane_module[j].next =
                (self.group.x[j].val() + self.row.val() + self.group.plane.val()) & self.mask.val();
            // (`* one` widens the column to 32 bits inside the loop.)
            self.lane_column[j].next = self.group.x[j].val() >> self.shift.val();
            self.lane_address[j].next = self.lane_column[j].val() * self.one.val()
                + self.row.val() * self.row_words.val()
                + self.group.plane.val() * self.plane_words.val();
            self.holds_q[j].clock.next = self.clock.val();
            self.inside_q[j].clock.next = self.clock.val();
            self.module_q[j].clock.next = self.clock.val();
            self.ray_q[j].clock.next = self.clock.val();
            self.holds_q[j].d.next = self.group.holds[j].val();
            self.inside_q[j].d.next = self.lane_inside[j].val();
            self.module_q[j].d.next = self.lane_module[j].val();
            self.ray_q[j].d.next = self.lane_ray[j].val();
        }
        // Lanes to memory modules: each module reads the voxel of the lane
        // in it (at most one: the lanes' x lie within P consecutive).
        for m in 0..P {
            self.address[m].next = 0.into();
            self.reads[m].next = false;
            for j in 0..P {
                if self.lane_inside[j].val() & (self.lane_module[j].val() == self.index[m].val()) {
                    self.address[m].next = self.lane_address[j].val();
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
        self.plane_q.d.next = self.group.plane.val();
        self.write_q.d.next = self.schedule.writing.val();
        self.plane_segment.next = self.plane_q.q.val() >> self.shift.val();
        self.buffer_q.d.next = self.schedule.write_buffer.val();
        // Memory modules back to lanes, and lanes to 2-DSB modules: ray r
        // of plane k to module (r + k) mod P at address r*G + k div P.
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
            self.dsb_ray[d].next = 0.into();
            self.dsb_write[d].next = false;
            for j in 0..P {
                if self.holds_q[j].q.val()
                    & (((self.ray_q[j].q.val() + self.plane_q.q.val()) & self.mask.val())
                        == self.index[d].val())
                {
                    self.dsb_data[d].next = self.value[j].val();
                    self.dsb_ray[d].next = self.ray_q[j].q.val();
                    self.dsb_write[d].next = true;
                }
            }
            self.write_address[d].next = self.dsb_ray[d].val() * self.segments.val()
                + bit_cast::<32, 16>(self.plane_segment.val());
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
                & (self.dsb_ray[d].val() < self.rays.val())
                & (self.buffer_q.q.val() == self.buffer_id[0].val());
            self.buffer1[d].write_enable.next = self.write_q.q.val()
                & self.dsb_write[d].val()
                & (self.dsb_ray[d].val() < self.rays.val())
                & (self.buffer_q.q.val() == self.buffer_id[1].val());
            self.buffer2[d].write_enable.next = self.write_q.q.val()
                & self.dsb_write[d].val()
                & (self.dsb_ray[d].val() < self.rays.val())
                & (self.buffer_q.q.val() == self.buffer_id[2].val());
        }
        // Reads: segment s of ray r at r*G + s in every module; lane i takes
        // module (r + i) mod P a clock later.
        self.read_address.next = 0.into();
        if self.schedule.reading.val() {
            self.read_address.next = self.schedule.ray.val() * self.segments.val()
                + bit_cast::<32, 16>(self.schedule.segment.val());
        }
        self.read_q.d.next = self.schedule.reading.val();
        self.lane_q.d.next = self.schedule.ray.val() & self.mask.val();
        self.cur_q.d.next = self.schedule.cur_buffer.val();
        self.next_q.d.next = self.schedule.next_buffer.val();
        for m in 0..P {
            self.buffer0[m].read_clock.next = self.clock.val();
            self.buffer1[m].read_clock.next = self.clock.val();
            self.buffer2[m].read_clock.next = self.clock.val();
            self.buffer0[m].read_address.next = self.read_address.val().get_bits::<B>(0);
            self.buffer1[m].read_address.next = self.read_address.val().get_bits::<B>(0);
            self.buffer2[m].read_address.next = self.read_address.val().get_bits::<B>(0);
        }
        for i in 0..P {
            self.cur[i].next = 0.into();
            self.next[i].next = 0.into();
            for m in 0..P {
                if ((self.index[i].val() + self.lane_q.q.val()) & self.mask.val())
                    == self.index[m].val()
                {
                    if self.cur_q.q.val() == self.buffer_id[0].val() {
                        self.cur[i].next = self.buffer0[m].read_data.val();
                    }
                    if self.cur_q.q.val() == self.buffer_id[1].val() {
                        self.cur[i].next = self.buffer1[m].read_data.val();
                    }
                    if self.cur_q.q.val() == self.buffer_id[2].val() {
                        self.cur[i].next = self.buffer2[m].read_data.val();
                    }
                    if self.next_q.q.val() == self.buffer_id[0].val() {
                        self.next[i].next = self.buffer0[m].read_data.val();
                    }
                    if self.next_q.q.val() == self.buffer_id[1].val() {
                        self.next[i].next = self.buffer1[m].read_data.val();
                    }
                    if self.next_q.q.val() == self.buffer_id[2].val() {
                        self.next[i].next = self.buffer2[m].read_data.val();
                    }
                }
            }
        }
        self.valid.next = self.read_q.q.val();
    }
}

/// This clock's group of rays, at most `P`: a parallel chunk from the
/// schedule's counters (`P` rays from `chunk·P`, `x` from the plane's
/// template), or a perspective group from the ROMs (the schedule's chunk
/// counts groups): its plane, first ray and each lane's `x` and whether it
/// holds a ray.
#[derive(LogicBlock)]
struct Groups<const P: usize> {
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
    fn new(c: &BeamFetchConfig) -> Groups<P> {
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

/// The scanline periods: which plane and chunk are written, which ray and
/// segment are read, and the buffers' roles.
#[derive(LogicBlock)]
struct Schedule {
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
    fn new(c: &BeamFetchConfig) -> Schedule {
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
