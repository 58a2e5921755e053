//! The Cube-3 pipeline (§5, Fig. 12) from the 2-D skewed buffers to the
//! base-plane pixels, for a parallel view in the modes that need no
//! gradient (MIP, MinIP, X-ray): the [`RayControl`], `P` TRILIN units fed by
//! [`TrilinLanes`], one leaf stage per unit, and the Ray Projection Cone
//! ([`Rpc`]), one segment of `P` samples per clock.
//!
//! **Streams.** The 2-DSBs of scanlines `v` and `v + 1` arrive as
//! `trilin_lanes` describes, scanline after scanline after `start`, one
//! segment on each clock with `valid`: `S·R·G` segments for `S` scanlines of
//! `R` rays of `G` segments, contiguous within a scanline (a pause between
//! scanlines is allowed). [`crate::beam_fetch`] fills and reads the
//! buffers.
//!
//! **Leaf stage.** Clock `t + trilin::LATENCY` for a cell taken at `t`: the
//! control's inside bit, delayed beside the units, gates the sample. MIP and
//! MinIP: the sample rounded to voxel bits, `(s + 2^(F-1)) >> F`, valid when
//! inside. X-ray: the opacity table at `(s >> F) >> shift` (a ROM per unit).
//! Outside the volume a leaf is 0 (and invalid: the golden model's empty
//! leaf). Registered, then the RPC's leaves.
//!
//! **Pixels.** Every ray of the stream leaves as one `done` pulse, in
//! stream order, `cell_delay + trilin::LATENCY + 1 + rpc::latency(P)`
//! clocks after its last segment entered ([`Cube3Config::pixel_delay`]);
//! the last ray of each scanline has no right neighbour in its buffer and
//! its pixel is not a base-plane pixel.

use crate::ray_control::RayControl;
use crate::rpc::Rpc;
use crate::trilin_lanes::TrilinLanes;
use golden_model::cube3::plan::{sample_pos, Template, View};
use golden_model::cube3::shade::Shader;
use rust_hdl::prelude::*;
use scene::Mode;

/// Address bits of the X-ray opacity ROM (`lut::OpacityLut` rows).
pub const OPACITY_BITS: usize = 12;

/// Everything a Cube-3 pipeline is built from.
#[derive(Debug, Clone)]
pub struct Cube3Config {
    pub p: usize,
    pub mode: Mode,
    /// Stream rays `u0 .. u0 + rays` of scanlines `v0 .. v0 + scanlines`.
    pub u0: i32,
    pub v0: i32,
    pub rays: usize,
    pub scanlines: usize,
    pub segments: usize,
    pub offset: u32,
    /// Every sample sits on the grid (`View::on_grid`): the weights and the
    /// offset are 0, so TRILIN's lerps pass their first voxel and synthesis
    /// folds their arithmetic away.
    pub on_grid: bool,
    pub weight_bits: u32,
    pub voxel_bits: u32,
    pub sample_frac: u32,
    pub rgba_bits: u32,
    /// Per plane `k`: the weights `[wx, wy]` and the inside bounds
    /// `[ray_lo, ray_hi, scanline_lo, scanline_hi]` (inclusive stream
    /// indices; empty as lo > hi).
    pub weights: Vec<[u32; 2]>,
    pub bounds: Vec<[u32; 4]>,
    /// X-ray: the opacity table and its row shift.
    pub opacity: Option<(Vec<u32>, u32)>,
}

impl Cube3Config {
    /// The pipeline of `view` for scanlines `v0 .. v0 + scanlines`.
    pub fn new(
        view: &View,
        shader: &Shader,
        p: usize,
        v0: i32,
        scanlines: usize,
    ) -> Result<Cube3Config, String> {
        let (Template::Parallel { d: dx, .. }, Template::Parallel { d: dy, .. }) =
            (&view.x, &view.y)
        else {
            return Err("the Cube-3 pipeline is built for parallel views only so far".into());
        };
        if shader.needs_gradient || matches!(shader.mode, Mode::Composite | Mode::FirstOpaque) {
            return Err(format!(
                "the Cube-3 pipeline is built for MIP, MinIP and X-ray only so far, not {:?}",
                shader.mode
            ));
        }
        if !matches!(p, 1 | 2 | 4 | 8) {
            return Err(format!("hardware.pipelines {p} unsupported (1, 2, 4 or 8)"));
        }
        let w = view.weight_bits;
        let [nx, ny, nk] = view.dims.map(|n| n as i64);
        let u0 = view.u[0] - 1;
        let rays = (view.u[1] - view.u[0] + 4) as usize;
        let within = |q: i64, hi: i64| q >= 0 && q <= hi << w;
        // Stream indices `i` in `0..n` where `ok(i)`: an interval (positions
        // are linear in the ray), or empty as [1, 0].
        let interval = |n: usize, ok: &dyn Fn(i64) -> bool| {
            let hits: Vec<u32> = (0..n as u32).filter(|&i| ok(i as i64)).collect();
            match (hits.first(), hits.last()) {
                (Some(&lo), Some(&hi)) if hits.len() == (hi - lo + 1) as usize => Ok([lo, hi]),
                (None, _) => Ok([1, 0]),
                _ => Err("the inside test is not an interval of rays".to_string()),
            }
        };
        let mut bounds = Vec::new();
        for k in 0..nk as usize {
            let zq = ((k as i64) << w) + view.offset as i64;
            let r = interval(rays, &|r| {
                within(zq, nk - 1) && within(sample_pos(u0 + r as i32, k, *dx, w), nx - 1)
            })?;
            let v = interval(scanlines, &|s| {
                within(sample_pos(v0 + s as i32, k, *dy, w), ny - 1)
            })?;
            bounds.push([r[0], r[1], v[0], v[1]]);
        }
        let widths = shader.widths;
        Ok(Cube3Config {
            p,
            mode: shader.mode,
            u0,
            v0,
            rays,
            scanlines,
            segments: view.dims[2].div_ceil(p),
            offset: view.offset,
            on_grid: view.on_grid,
            weight_bits: w,
            voxel_bits: widths.voxel_bits,
            sample_frac: widths.sample_frac(),
            rgba_bits: widths.rgba_bits,
            weights: (0..view.dims[2])
                .map(|k| [view.x.weight(0, k), view.y.weight(0, k)])
                .collect(),
            bounds,
            opacity: (shader.mode == Mode::Xray).then(|| {
                let o = shader.opacity.as_ref().expect("X-ray has an opacity table");
                (o.table.clone(), o.shift)
            }),
        })
    }

    /// Clocks from a ray's last segment entering the streams to its pixel.
    pub fn pixel_delay(&self) -> usize {
        crate::trilin_lanes::cell_delay(self.segments)
            + crate::trilin::LATENCY
            + 1
            + crate::rpc::latency(self.p)
            - 1
    }
}

/// The Cube-3 pipeline with `P` units (`H`-bit delay-line pointers).
#[derive(LogicBlock)]
pub struct Cube3<const P: usize, const H: usize> {
    pub clock: Signal<In, Clock>,
    /// Restart at the first segment of the first ray.
    pub start: Signal<In, Bit>,
    /// A segment enters the streams this clock.
    pub valid: Signal<In, Bit>,
    pub cur: [Signal<In, Bits<16>>; P],
    pub next: [Signal<In, Bits<16>>; P],
    /// A ray's base-plane pixel, in stream order.
    pub done: Signal<Out, Bit>,
    pub pixel_r: Signal<Out, Bits<32>>,
    pub pixel_g: Signal<Out, Bits<16>>,
    pub pixel_b: Signal<Out, Bits<16>>,
    pub pixel_a: Signal<Out, Bits<16>>,
    pub has_sample: Signal<Out, Bit>,
    control: RayControl<P, H>,
    lanes: TrilinLanes<P, H>,
    /// `[inside bits, valid, first, last]` from the units to the leaf
    /// stage (`trilin::LATENCY` clocks) and to the RPC (one more).
    flags_q: [DFF<Bits<16>>; 8],
    xray: Constant<Bit>,
    half: Constant<Bits<32>>,
    frac: Constant<Bits<8>>,
    row_shift: Constant<Bits<8>>,
    lane_bit: [Constant<Bits<16>>; 8],
    /// X-ray: each unit's opacity row and table.
    row: [Signal<Local, Bits<32>>; P],
    opacity: [ROM<Bits<32>, OPACITY_BITS>; P],
    leaf_q: [DFF<Bits<32>>; P],
    leaf_valid_q: [DFF<Bit>; P],
    rpc: Rpc<P>,
}

impl<const P: usize, const H: usize> Cube3<P, H> {
    pub fn new(c: &Cube3Config) -> Result<Cube3<P, H>, String> {
        assert_eq!(c.p, P, "the configuration's p");
        let control = RayControl::new(c)?;
        let lanes = TrilinLanes::new(
            c.segments,
            c.offset,
            c.weight_bits,
            c.voxel_bits,
            c.sample_frac,
        )?;
        let (table, shift) = c.opacity.clone().unwrap_or((vec![0], 0));
        if table.len() > 1 << OPACITY_BITS {
            return Err(format!(
                "an opacity table of {} rows is too long",
                table.len()
            ));
        }
        let rom = || -> ROM<Bits<32>, OPACITY_BITS> {
            table.iter().map(|&v| (v as u64).to_bits()).into()
        };
        Ok(Cube3 {
            clock: Default::default(),
            start: Default::default(),
            valid: Default::default(),
            cur: std::array::from_fn(|_| Default::default()),
            next: std::array::from_fn(|_| Default::default()),
            done: Default::default(),
            pixel_r: Default::default(),
            pixel_g: Default::default(),
            pixel_b: Default::default(),
            pixel_a: Default::default(),
            has_sample: Default::default(),
            control,
            lanes,
            flags_q: Default::default(),
            xray: Constant::new(c.mode == Mode::Xray),
            half: Constant::new(((1u64 << c.sample_frac) >> 1).to_bits()),
            frac: Constant::new((c.sample_frac as u64).to_bits()),
            row_shift: Constant::new((shift as u64).to_bits()),
            lane_bit: std::array::from_fn(|i| Constant::new((1u64 << i).to_bits())),
            row: std::array::from_fn(|_| Default::default()),
            opacity: std::array::from_fn(|_| rom()),
            leaf_q: std::array::from_fn(|_| Default::default()),
            leaf_valid_q: std::array::from_fn(|_| Default::default()),
            rpc: Rpc::new(c.mode, c.rgba_bits, c.voxel_bits),
        })
    }
}

impl<const P: usize, const H: usize> Logic for Cube3<P, H> {
    #[hdl_gen]
    fn update(&mut self) {
        self.control.clock.next = self.clock.val();
        self.lanes.clock.next = self.clock.val();
        self.rpc.clock.next = self.clock.val();
        self.control.start.next = self.start.val();
        self.control.valid.next = self.valid.val();
        self.lanes.first.next = self.control.first.val();
        // The flags beside the units: inside bits 0-7, valid 8, first 9,
        // last 10.
        for j in 0..8 {
            self.flags_q[j].clock.next = self.clock.val();
        }
        self.flags_q[0].d.next = bit_cast::<16, 8>(self.control.in_volume.val())
            | (bit_cast::<16, 1>(self.control.unit_valid.val().into()) << 8)
            | (bit_cast::<16, 1>(self.control.unit_first.val().into()) << 9)
            | (bit_cast::<16, 1>(self.control.unit_last.val().into()) << 10);
        for j in 1..8 {
            self.flags_q[j].d.next = self.flags_q[j - 1].q.val();
        }
        for i in 0..P {
            self.lanes.cur[i].next = self.cur[i].val();
            self.lanes.next[i].next = self.next[i].val();
            self.lanes.wx[i].next = self.control.wx[i].val();
            self.lanes.wy[i].next = self.control.wy[i].val();
            // The leaf stage, trilin::LATENCY clocks after the cell.
            self.leaf_q[i].clock.next = self.clock.val();
            self.leaf_valid_q[i].clock.next = self.clock.val();
            self.row[i].next =
                (self.lanes.sample[i].val() >> self.frac.val()) >> self.row_shift.val();
            self.opacity[i].address.next = self.row[i].val().get_bits::<OPACITY_BITS>(0);
            self.leaf_valid_q[i].d.next = (self.flags_q[6].q.val() & self.lane_bit[i].val()).any();
            self.leaf_q[i].d.next = 0.into();
            if (self.flags_q[6].q.val() & self.lane_bit[i].val()).any() {
                self.leaf_q[i].d.next =
                    (self.lanes.sample[i].val() + self.half.val()) >> self.frac.val();
                if self.xray.val() {
                    self.leaf_q[i].d.next = self.opacity[i].data.val();
                }
            }
            self.rpc.leaf_r[i].next = self.leaf_q[i].q.val();
            self.rpc.leaf_g[i].next = 0.into();
            self.rpc.leaf_b[i].next = 0.into();
            self.rpc.leaf_a[i].next = 0.into();
            self.rpc.leaf_valid[i].next = self.leaf_valid_q[i].q.val();
        }
        self.rpc.first.next =
            self.flags_q[7].q.val().get_bit(9) & self.flags_q[7].q.val().get_bit(8);
        self.rpc.last.next =
            self.flags_q[7].q.val().get_bit(10) & self.flags_q[7].q.val().get_bit(8);
        self.done.next = self.rpc.done.val();
        self.pixel_r.next = self.rpc.pixel_r.val();
        self.pixel_g.next = self.rpc.pixel_g.val();
        self.pixel_b.next = self.rpc.pixel_b.val();
        self.pixel_a.next = self.rpc.pixel_a.val();
        self.has_sample.next = self.rpc.has_sample.val();
    }
}
