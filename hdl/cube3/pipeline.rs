//! The Cube-3 pipeline (§5, Fig. 12) from the 2-D skewed buffers to the
//! base-plane pixels, for a parallel or perspective view in every mode: the
//! [`RayControl`], `P` TRILIN units fed by [`TrilinLanes`], the ABC units
//! ([`AbcUnit`]: gradients, then one [`Shader`] a unit) or a leaf stage,
//! and the Ray Projection Cone ([`Rpc`]), one segment of `P` samples per
//! clock.
//!
//! **Streams.** The 2-DSBs of scanlines `v` and `v + 1` arrive as
//! `trilin_lanes` describes, scanline after scanline after `start`, one
//! segment on each clock with `valid`: `S·R·G` segments for `S` scanlines of
//! `R` rays of `G` segments, contiguous within a scanline. A pause between
//! scanlines is allowed; with gradients every scanline must start
//! [`Cube3Config::scanline_clocks`] after the one before, as the beam
//! fetch's periods do. [`super::cfb`] fills and reads the buffers.
//!
//! **Leaf stage** (MIP, MinIP, X-ray; no ABC unit or shader). Clock `t +
//! trilin::LATENCY` for a cell taken at `t`: the control's inside bit,
//! delayed beside the units, gates the sample. MIP and MinIP: the sample
//! rounded to voxel bits, `(s + 2^(F-1)) >> F`, valid when inside. X-ray:
//! the opacity table at `(s >> F) >> shift` (a block RAM per unit the host
//! loads; its registered read is the leaf stage's register). Outside the
//! volume a leaf is 0 (and invalid: the golden model's empty leaf).
//! Registered, then the RPC's leaves.
//!
//! **ABC units** (composite, first-opaque). With gradients (shading or
//! gradient opacity) each unit's samples go through the [`AbcUnit`]: the
//! sample and its gradient leave `abc_unit::centre + abc_estimator::LATENCY`
//! clocks later, and the flags (inside and inner bits, valid, first, last)
//! wait as long in a delay line. The stream then carries one scanline more
//! on either side (the above plane of the first, the below plane of the
//! last). The [`Shader`] (Cube-4L's, built from Cube-3's tables:
//! `cube3::shade`) takes the value `s >> F`, `invalid` = outside the volume
//! and `at_edge` = outside the inner box, and registers the RPC's leaf.
//! Without gradients the shader takes the TRILIN sample directly.
//!
//! **Pixels.** Every ray of the stream leaves as one `done` pulse, in
//! stream order, [`Cube3Config::pixel_delay`] clocks after its last segment
//! entered; the last ray of each scanline has no right neighbour in its
//! buffer and its pixel is not a base-plane pixel, nor are those of the
//! halo scanlines.

use super::abc_gradient::AbcUnit;
use super::compositor::Rpc;
use super::config::{Cube3Config, Cube3Sizes, OPACITY_BITS};
use super::ray_control::RayControl;
use super::trilin_lanes::TrilinLanes;
use crate::common::delay_line::DelayLine;
use crate::common::regs::{Regs, ADDRESS_BITS};
use crate::common::shader::{Shader, ShaderConfig, LATENCY as SHADER_LATENCY};
use crate::common::table::Table;
use golden_model::host::{Reg, ShaderTables, ViewTable};
use rust_hdl::prelude::*;
use scene::Mode;

/// The Cube-3 pipeline with `P` units (`H`-bit delay-line pointers).
#[derive(LogicBlock)]
pub struct Cube3<const P: usize, const H: usize> {
    pub clock: Signal<In, Clock>,
    /// The host port: the view's registers and tables, the shaders' tables
    /// and light.
    pub host_write: Signal<In, Bit>,
    pub host_address: Signal<In, Bits<ADDRESS_BITS>>,
    pub host_data: Signal<In, Bits<64>>,
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
    /// `C3Origin`, `C3Delays`, `C3Lines`.
    regs: Regs<3>,
    pub(crate) control: RayControl<P, H>,
    pub(crate) lanes: TrilinLanes<P, H>,
    /// `[inside bits, valid, first, last, cast, inner bits]` (bits 0-7, 8,
    /// 9, 10, 11, 16-23) from the units to the leaf stage (`trilin::LATENCY` clocks),
    /// through the ABC delay (`flags_line`), and to the RPC (one more).
    flags_q: [DFF<Bits<32>>; 7],
    flags_line: DelayLine<Bits<32>, H>,
    leaf_flags: Signal<Local, Bits<32>>,
    /// The flags, on beside the shaders (`shader::LATENCY - 1` more clocks
    /// than the leaf stage's one).
    shade_flags_q: [DFF<Bits<32>>; SHADER_LATENCY - 1],
    rpc_flags_q: DFF<Bits<32>>,
    /// The cast bits of the rays in the RPC (bit `latency - 1` is the
    /// pixel's): an uncast ray's pixel is 0 without a sample.
    cast_q: DFF<Bits<8>>,
    cast_bit: Constant<Bits<8>>,
    pixel_cast: Signal<Local, Bit>,
    gradients: Constant<Bit>,
    shaded: Constant<Bit>,
    xray: Constant<Bit>,
    half: Constant<Bits<32>>,
    frac: Constant<Bits<8>>,
    row_shift: Constant<Bits<8>>,
    lane_bit: [Constant<Bits<32>>; 8],
    inner_bit: [Constant<Bits<32>>; 8],
    /// X-ray: each unit's opacity row and table (its registered read is
    /// the leaf stage's register).
    row: [Signal<Local, Bits<32>>; P],
    pub(crate) opacity: [Table<32, OPACITY_BITS>; P],
    pub(crate) leaf_q: [DFF<Bits<32>>; P],
    pub(crate) leaf_valid_q: [DFF<Bit>; P],
    /// The ABC units: the gradients, then the shaders.
    pub(crate) abc: AbcUnit<P, H>,
    /// The shaders' value `s >> F` and gradient.
    index: [Signal<Local, Bits<32>>; P],
    gx: [Signal<Local, Bits<32>>; P],
    gy: [Signal<Local, Bits<32>>; P],
    gz: [Signal<Local, Bits<32>>; P],
    pub(crate) shade: [Shader; P],
    pub(crate) rpc: Rpc<P>,
}

impl<const P: usize, const H: usize> Cube3<P, H> {
    /// The units of `c` (its p, mode, widths, gradient and shading units;
    /// not its view) for the views of `s`.
    pub fn new(c: &Cube3Config, s: &Cube3Sizes) -> Result<Cube3<P, H>, String> {
        assert_eq!(c.p, P, "the configuration's p");
        let control = RayControl::new(s)?;
        let lanes = TrilinLanes::new(s.segments(), c.weight_bits, c.voxel_bits, c.sample_frac)?;
        let (table, shift) = c.opacity.clone().unwrap_or((vec![0], 0));
        if table.len() > 1 << OPACITY_BITS {
            return Err(format!(
                "an opacity table of {} rows is too long",
                table.len()
            ));
        }
        let abc_delay = match c.abc {
            Some(_) => {
                super::abc_gradient::centre(s.period(), s.segments())
                    + super::abc_estimator::LATENCY
            }
            None => 1,
        };
        if abc_delay >= 1 << H {
            return Err(format!(
                "the ABC delay of {abc_delay} clocks needs more than {H} pointer bits"
            ));
        }
        let abc = match &c.abc {
            Some(a) => AbcUnit::new(
                s.period(),
                s.segments(),
                a.neighbourhood,
                c.weight_bits,
                a.sample_bits,
                a.gradient_bits,
            )?,
            None => AbcUnit::left_out(s.segments())?,
        };
        let shader = || -> Result<Shader, String> {
            match &c.shading {
                Some(s) => {
                    if s.gradient_bits > 31 {
                        return Err(format!(
                            "cube3.gradient_bits {} unsupported by the shader (at most 31)",
                            s.gradient_bits
                        ));
                    }
                    let config = ShaderConfig::of(
                        &s.tables(),
                        s.voxel_bits,
                        s.needs_gradient,
                        s.gradient_bits > 17,
                    );
                    Ok(Shader::new(&config))
                }
                None => Ok(Shader::left_out()),
            }
        };
        let mut shade = Vec::with_capacity(P);
        for _ in 0..P {
            shade.push(shader()?);
        }
        Ok(Cube3 {
            clock: Default::default(),
            host_write: Default::default(),
            host_address: Default::default(),
            host_data: Default::default(),
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
            regs: Regs::new([Reg::C3Origin, Reg::C3Delays, Reg::C3Lines].map(Reg::address)),
            control,
            lanes,
            flags_q: Default::default(),
            flags_line: DelayLine::new(abc_delay, &[(0, 12), (16, 8)], 0x00ff_0fffu64.to_bits()),
            leaf_flags: Default::default(),
            shade_flags_q: Default::default(),
            rpc_flags_q: Default::default(),
            cast_q: Default::default(),
            cast_bit: Constant::new((1u64 << (super::compositor::latency(P) - 1)).to_bits()),
            pixel_cast: Default::default(),
            gradients: Constant::new(c.abc.is_some()),
            shaded: Constant::new(c.shading.is_some()),
            xray: Constant::new(c.mode == Mode::Xray),
            half: Constant::new(((1u64 << c.sample_frac) >> 1).to_bits()),
            frac: Constant::new((c.sample_frac as u64).to_bits()),
            row_shift: Constant::new((shift as u64).to_bits()),
            lane_bit: std::array::from_fn(|i| Constant::new((1u64 << i).to_bits())),
            inner_bit: std::array::from_fn(|i| Constant::new((1u64 << (16 + i)).to_bits())),
            row: std::array::from_fn(|_| Default::default()),
            opacity: std::array::from_fn(|_| {
                Table::new(
                    ViewTable::XrayOpacity.base(),
                    table.len(),
                    &[(0, c.rgba_bits as usize)],
                )
            }),
            leaf_q: std::array::from_fn(|_| Default::default()),
            leaf_valid_q: std::array::from_fn(|_| Default::default()),
            abc,
            index: std::array::from_fn(|_| Default::default()),
            gx: std::array::from_fn(|_| Default::default()),
            gy: std::array::from_fn(|_| Default::default()),
            gz: std::array::from_fn(|_| Default::default()),
            shade: shade.try_into().ok().expect("P shaders"),
            rpc: Rpc::new(c.mode, c.rgba_bits, c.voxel_bits),
        })
    }
}

impl<const P: usize, const H: usize> Cube3<P, H> {
    /// Give every shader's tables the contents the host would load
    /// (block-RAM initialisation, for simulation).
    pub fn preload_tables(&mut self, tables: &ShaderTables) {
        for s in self.shade.iter_mut() {
            s.preload(tables);
        }
    }
}

// `hdl_gen` needs literal loop bounds: the flags' registers beside the
// shaders are written for a 17-clock shader.
const _: () = assert!(SHADER_LATENCY == 17, "update the shaders' flag registers");

impl<const P: usize, const H: usize> Logic for Cube3<P, H> {
    #[hdl_gen]
    fn update(&mut self) {
        // The view's registers.
        self.regs.clock.next = self.clock.val();
        self.regs.host_write.next = self.host_write.val();
        self.regs.host_address.next = self.host_address.val();
        self.regs.host_data.next = self.host_data.val();
        self.lanes.offset.next = self.regs.q[0].val().get_bits::<16>(32);
        self.lanes.line_last.next = self.regs.q[1].val().get_bits::<H>(16);
        self.flags_line.last.next = self.regs.q[1].val().get_bits::<H>(48);
        self.abc.ray_last.next = self.regs.q[2].val().get_bits::<H>(0);
        self.abc.line_last.next = self.regs.q[2].val().get_bits::<H>(16);
        self.control.clock.next = self.clock.val();
        self.control.host_write.next = self.host_write.val();
        self.control.host_address.next = self.host_address.val();
        self.control.host_data.next = self.host_data.val();
        self.lanes.clock.next = self.clock.val();
        self.abc.clock.next = self.clock.val();
        self.abc.host_write.next = self.host_write.val();
        self.abc.host_address.next = self.host_address.val();
        self.abc.host_data.next = self.host_data.val();
        self.rpc.clock.next = self.clock.val();
        self.flags_line.clock.next = self.clock.val();
        self.rpc_flags_q.clock.next = self.clock.val();
        self.cast_q.clock.next = self.clock.val();
        self.control.start.next = self.start.val();
        self.control.valid.next = self.valid.val();
        self.lanes.first.next = self.control.first.val();
        // The flags beside the units.
        for j in 0..7 {
            self.flags_q[j].clock.next = self.clock.val();
        }
        self.flags_q[0].d.next = bit_cast::<32, 8>(self.control.in_volume.val())
            | (bit_cast::<32, 1>(self.control.unit_valid.val().into()) << 8)
            | (bit_cast::<32, 1>(self.control.unit_first.val().into()) << 9)
            | (bit_cast::<32, 1>(self.control.unit_last.val().into()) << 10)
            | (bit_cast::<32, 1>(self.control.unit_cast.val().into()) << 11)
            | (bit_cast::<32, 8>(self.control.in_inner.val()) << 16);
        for j in 1..7 {
            self.flags_q[j].d.next = self.flags_q[j - 1].q.val();
        }
        // With gradients the flags wait for the ABC units.
        self.flags_line.write_enable.next = true;
        self.flags_line.data_in.next = self.flags_q[6].q.val();
        self.leaf_flags.next = self.flags_q[6].q.val();
        if self.gradients.val() {
            self.leaf_flags.next = self.flags_line.data_out.val();
        }
        for j in 0..16 {
            self.shade_flags_q[j].clock.next = self.clock.val();
        }
        self.shade_flags_q[0].d.next = self.leaf_flags.val();
        for j in 1..16 {
            self.shade_flags_q[j].d.next = self.shade_flags_q[j - 1].q.val();
        }
        self.rpc_flags_q.d.next = self.leaf_flags.val();
        if self.shaded.val() {
            self.rpc_flags_q.d.next = self.shade_flags_q[15].q.val();
        }
        self.abc.dx_neg.next = self.control.dx_neg.val();
        self.abc.dx_mag.next = self.control.dx_mag.val();
        self.abc.dy_neg.next = self.control.dy_neg.val();
        self.abc.dy_mag.next = self.control.dy_mag.val();
        for i in 0..P {
            self.lanes.cur[i].next = self.cur[i].val();
            self.lanes.next[i].next = self.next[i].val();
            self.lanes.wx[i].next = self.control.wx[i].val();
            self.lanes.wy[i].next = self.control.wy[i].val();
            self.abc.sample[i].next = self.lanes.sample[i].val();
            // The leaf stage, trilin::LATENCY clocks after the cell.
            self.leaf_q[i].clock.next = self.clock.val();
            self.leaf_valid_q[i].clock.next = self.clock.val();
            self.row[i].next =
                (self.lanes.sample[i].val() >> self.frac.val()) >> self.row_shift.val();
            self.opacity[i].clock.next = self.clock.val();
            self.opacity[i].host_write.next = self.host_write.val();
            self.opacity[i].host_address.next = self.host_address.val();
            self.opacity[i].host_data.next = self.host_data.val();
            self.opacity[i].address.next = self.row[i].val().get_bits::<OPACITY_BITS>(0);
            self.leaf_valid_q[i].d.next = (self.flags_q[6].q.val() & self.lane_bit[i].val()).any();
            self.leaf_q[i].d.next = 0.into();
            if (self.flags_q[6].q.val() & self.lane_bit[i].val()).any() {
                self.leaf_q[i].d.next =
                    (self.lanes.sample[i].val() + self.half.val()) >> self.frac.val();
            }
            // The shaders: the sample and its gradient (zero without).
            self.index[i].next = self.lanes.sample[i].val() >> self.frac.val();
            self.gx[i].next = 0.into();
            self.gy[i].next = 0.into();
            self.gz[i].next = 0.into();
            if self.gradients.val() {
                self.index[i].next = self.abc.centre[i].val() >> self.frac.val();
                self.gx[i].next = self.abc.gx[i].val();
                self.gy[i].next = self.abc.gy[i].val();
                self.gz[i].next = self.abc.gz[i].val();
            }
            self.shade[i].clock.next = self.clock.val();
            self.shade[i].host_write.next = self.host_write.val();
            self.shade[i].host_address.next = self.host_address.val();
            self.shade[i].host_data.next = self.host_data.val();
            self.shade[i].value.next = self.index[i].val().get_bits::<16>(0);
            self.shade[i].invalid.next = !(self.leaf_flags.val() & self.lane_bit[i].val()).any();
            self.shade[i].at_edge.next = !(self.leaf_flags.val() & self.inner_bit[i].val()).any();
            self.shade[i].gx_neg.next = self.gx[i].val().get_bit(31);
            self.shade[i].gx_mag.next = self.gx[i].val();
            if self.gx[i].val().get_bit(31) {
                self.shade[i].gx_mag.next = !self.gx[i].val() + 1;
            }
            self.shade[i].gy_neg.next = self.gy[i].val().get_bit(31);
            self.shade[i].gy_mag.next = self.gy[i].val();
            if self.gy[i].val().get_bit(31) {
                self.shade[i].gy_mag.next = !self.gy[i].val() + 1;
            }
            self.shade[i].gz_neg.next = self.gz[i].val().get_bit(31);
            self.shade[i].gz_mag.next = self.gz[i].val();
            if self.gz[i].val().get_bit(31) {
                self.shade[i].gz_mag.next = !self.gz[i].val() + 1;
            }
            self.rpc.leaf_r[i].next = self.leaf_q[i].q.val();
            if self.xray.val() {
                self.rpc.leaf_r[i].next = 0.into();
                if self.leaf_valid_q[i].q.val() {
                    self.rpc.leaf_r[i].next = self.opacity[i].data.val();
                }
            }
            self.rpc.leaf_g[i].next = 0.into();
            self.rpc.leaf_b[i].next = 0.into();
            self.rpc.leaf_a[i].next = 0.into();
            self.rpc.leaf_valid[i].next = self.leaf_valid_q[i].q.val();
            if self.shaded.val() {
                self.rpc.leaf_r[i].next = self.shade[i].r.val();
                self.rpc.leaf_g[i].next = self.shade[i].g.val();
                self.rpc.leaf_b[i].next = self.shade[i].b.val();
                self.rpc.leaf_a[i].next = self.shade[i].a.val();
                self.rpc.leaf_valid[i].next = self.shade[i].valid.val();
            }
        }
        self.rpc.first.next =
            self.rpc_flags_q.q.val().get_bit(9) & self.rpc_flags_q.q.val().get_bit(8);
        self.rpc.last.next =
            self.rpc_flags_q.q.val().get_bit(10) & self.rpc_flags_q.q.val().get_bit(8);
        self.cast_q.d.next = (self.cast_q.q.val() << 1)
            | bit_cast::<8, 1>(self.rpc_flags_q.q.val().get_bit(11).into());
        self.pixel_cast.next = (self.cast_q.q.val() & self.cast_bit.val()).any();
        self.done.next = self.rpc.done.val();
        self.pixel_r.next = 0.into();
        self.pixel_g.next = 0.into();
        self.pixel_b.next = 0.into();
        self.pixel_a.next = 0.into();
        self.has_sample.next = false;
        if self.pixel_cast.val() {
            self.pixel_r.next = self.rpc.pixel_r.val();
            self.pixel_g.next = self.rpc.pixel_g.val();
            self.pixel_b.next = self.rpc.pixel_b.val();
            self.pixel_a.next = self.rpc.pixel_a.val();
            self.has_sample.next = self.rpc.has_sample.val();
        }
    }
}
