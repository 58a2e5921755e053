//! One pipeline's share of Cube-4L's Cubic Frame Buffer (§3.1, Figs. 5-7
//! and 13): its skewed memory module, the pipeline-to-dataset transform,
//! the module address, the control bits and, for perspective views, the
//! per-voxel divider. A sub-block of [`super::cfb::Cfb`], which holds the
//! shared counters. The view comes from the host's registers
//! (`golden_model::cube4l::regs::ViewRegs`, one 64-bit word each).

use super::config::PipelineConfig;
use super::divider::Divider;
use crate::common::bits16;
use crate::common::dsp_product::DspProduct;
use crate::common::lane_copy::LaneCopy;
use crate::common::ram::DepthRam;
use rust_hdl::prelude::*;

/// One pipeline's share of the CFB: its memory module, skew, address and control.
#[derive(LogicBlock)]
pub struct CfbLane<const A: usize> {
    pub clock: Signal<In, Clock>,
    /// The view registers: `Dims`, `Slices`, `Axes`, `Address`, `Dx`, `Dy`
    /// and the negated eye.
    pub dims: Signal<In, Bits<64>>,
    pub slices: Signal<In, Bits<64>>,
    pub axes: Signal<In, Bits<64>>,
    pub address_reg: Signal<In, Bits<64>>,
    pub dx: Signal<In, Bits<64>>,
    pub dy: Signal<In, Bits<64>>,
    pub eye_x: Signal<In, Bits<64>>,
    pub eye_y: Signal<In, Bits<64>>,
    pub eye_z: Signal<In, Bits<64>>,
    /// Shared counters N_s (slice z), N_B (beam y) and N_b (partial beam)
    /// as issued, for the perspective divider; for the address (the same,
    /// or `counter_lead::LEAD` clocks later with a divider); and
    /// `ADDRESS_STAGES + 1` clocks after the address's (`c_`), a clock ahead
    /// of the control computed beside the memory read's last register, for
    /// its skewed x and padding test; N_s and N_B a clock later, for the
    /// rest of the control.
    pub d_n_s: Signal<In, Bits<16>>,
    pub d_n_beam: Signal<In, Bits<16>>,
    pub d_n_b: Signal<In, Bits<16>>,
    pub a_n_s: Signal<In, Bits<16>>,
    pub a_n_beam: Signal<In, Bits<16>>,
    pub a_n_b: Signal<In, Bits<16>>,
    pub c_n_s: Signal<In, Bits<16>>,
    pub c_n_beam: Signal<In, Bits<16>>,
    pub c_n_b: Signal<In, Bits<16>>,
    pub n_s: Signal<In, Bits<16>>,
    pub n_beam: Signal<In, Bits<16>>,
    /// Load port: a write when `load_enable` and `load_module` names this lane.
    pub load_enable: Signal<In, Bit>,
    pub load_module: Signal<In, Bits<8>>,
    pub load_address: Signal<In, Bits<A>>,
    pub load_data: Signal<In, Bits<16>>,
    /// External memory port: the read address, and the word it returns one
    /// clock later.
    pub ext_addr: Signal<Out, Bits<32>>,
    pub ext_data: Signal<In, Bits<16>>,
    /// Outputs, one clock after the delayed counters (`ADDRESS_STAGES +
    /// READ_STAGES` after the issued ones).
    pub value: Signal<Out, Bits<16>>,
    pub x: Signal<Out, Bits<16>>,
    pub y: Signal<Out, Bits<16>>,
    pub z: Signal<Out, Bits<16>>,
    pub address: Signal<Out, Bits<32>>,
    pub pad: Signal<Out, Bit>,
    pub sr: Signal<Out, Bit>,
    pub er: Signal<Out, Bit>,
    /// A direct neighbour lies outside the dataset (`Control::edge`).
    pub at_edge: Signal<Out, Bit>,
    /// `golden_model::cube4l::plan::Face` as a number (0 = none).
    pub face: Signal<Out, Bits<3>>,
    pub base_x: Signal<Out, Bits<16>>,
    pub base_y: Signal<Out, Bits<16>>,
    /// A halo slice (outside z0..=z1): streamed for gradients only.
    pub halo: Signal<Out, Bit>,
    /// Sight-ray increments (sign and magnitude, 1.0 = 2^f) and the invalid bit.
    pub dx_neg: Signal<Out, Bit>,
    pub dx_mag: Signal<Out, Bits<16>>,
    pub dy_neg: Signal<Out, Bit>,
    pub dy_mag: Signal<Out, Bits<16>>,
    pub invalid: Signal<Out, Bit>,
    memory: DepthRam<Bits<16>, A>,
    lane: Constant<Bits<16>>,
    p_mask: Constant<Bits<16>>,
    p_shift: Constant<Bits<8>>,
    perspective: Constant<Bit>,
    external: Constant<Bit>,
    // The registers' fields.
    /// The fields the control derives its values from, copied as they are
    /// (`Dims`' three sides, `Slices`' `z0` and `z1`, `Axes`, and `Dx`'s and
    /// `Dy`'s sign and low 32 bits): the route from the register file
    /// across the part ends in a register, and the arithmetic on them lies
    /// beside the lane, a clock later.
    view_dims: LaneCopy<Bits<48>>,
    view_slices: LaneCopy<Bits<32>>,
    view_axes: LaneCopy<Bits<6>>,
    view_dx: LaneCopy<Bits<33>>,
    view_dy: LaneCopy<Bits<33>>,
    /// `n_x` (copied from `Dims`: the address's first stage reads it a clock
    /// after the start), and, from the copies, `n - 1` of each axis and the
    /// base plane's border `z1 - z0`: no subtraction from a view register
    /// lies before the padding test, the exit-face compares and the
    /// base-plane sums.
    nx: LaneCopy<Bits<16>>,
    nx_last: LaneCopy<Bits<16>>,
    ny_last: LaneCopy<Bits<16>>,
    nz_last: LaneCopy<Bits<16>>,
    z0: Signal<Local, Bits<16>>,
    z1: Signal<Local, Bits<16>>,
    border: LaneCopy<Bits<16>>,
    u_from: Signal<Local, Bits<2>>,
    v_from: Signal<Local, Bits<2>>,
    w_from: Signal<Local, Bits<2>>,
    /// The strides `b_u` and `b_u * n_v` (split into 16-bit halves for two
    /// 16x16 multipliers), the lane's own copies of `Address`: the stride
    /// products' operands come from beside their multipliers, not from the
    /// register file across the part.
    b_u: LaneCopy<Bits<16>>,
    slab_lo: LaneCopy<Bits<16>>,
    slab_hi: LaneCopy<Bits<16>>,
    dx_abs: Signal<Local, Bits<16>>,
    dy_abs: Signal<Local, Bits<16>>,
    /// The parallel view's increments, registered from the copies of `Dx`
    /// and `Dy` (two clocks behind the register file): they hold for a
    /// frame, and the control reads them `ADDRESS_STAGES + 2` clocks after
    /// the start at the earliest. Sign (when nonzero), magnitude, and
    /// positive-and-nonzero.
    par_dxn: LaneCopy<Bit>,
    par_dxm: LaneCopy<Bits<16>>,
    par_dx_pos: LaneCopy<Bit>,
    par_dyn: LaneCopy<Bit>,
    par_dym: LaneCopy<Bits<16>>,
    par_dy_pos: LaneCopy<Bit>,
    /// Perspective views: the sight-ray increments, from the issued counters.
    pub(crate) div: Divider,
    dxn: Signal<Local, Bit>,
    dxm: Signal<Local, Bits<16>>,
    dyn_: Signal<Local, Bit>,
    dym: Signal<Local, Bits<16>>,
    inval: Signal<Local, Bit>,
    dx_pos: Signal<Local, Bit>,
    dx_neg_nz: Signal<Local, Bit>,
    dy_pos: Signal<Local, Bit>,
    dy_neg_nz: Signal<Local, Bit>,
    dxn_q: DFF<Bit>,
    dxm_q: DFF<Bits<16>>,
    dyn_q: DFF<Bit>,
    dym_q: DFF<Bits<16>>,
    inval_q: DFF<Bit>,
    halo_q: DFF<Bit>,
    /// The control's skewed x and padding test, from the counters a clock
    /// before the control's, registered: the test's compare lies before
    /// the register, its fan-out (the increments' clear, the exit faces)
    /// after.
    c_xc: Signal<Local, Bits<16>>,
    xc_r: DFF<Bits<16>>,
    pad_r: DFF<Bit>,
    xc: Signal<Local, Bits<16>>,
    // The address pipeline: the issued counters' skewed x and dataset
    // (u, v, w), registered; the products, registered; their sum.
    a_xc: Signal<Local, Bits<16>>,
    a_u: DFF<Bits<16>>,
    a_v: DFF<Bits<16>>,
    a_w: DFF<Bits<16>>,
    a_pad: DFF<Bit>,
    m_u: DFF<Bits<32>>,
    /// The products' registers are the multipliers' own ([`DspProduct`]).
    m_v: DspProduct,
    m_w_lo: DspProduct,
    m_w_hi: DspProduct,
    m_pad: DFF<Bit>,
    addr: DFF<Bits<32>>,
    is_pad: Signal<Local, Bit>,
    face_c: Signal<Local, Bits<3>>,
    /// The exit-face tests and the base-plane sums, from the counters a
    /// clock ahead, registered beside `xc_r`: the control's clock only
    /// chooses among them by the increments' signs. `depth` is `z1 - n_s`;
    /// the sums are `border + x`, `border + x + depth`, `border - depth`,
    /// `border + y` and `border + y + depth`.
    c_depth: Signal<Local, Bits<16>>,
    x_last_r: DFF<Bit>,
    x_first_r: DFF<Bit>,
    y_last_r: DFF<Bit>,
    y_first_r: DFF<Bit>,
    s_last_r: DFF<Bit>,
    bx_at_r: DFF<Bits<16>>,
    bx_far_r: DFF<Bits<16>>,
    b_near_r: DFF<Bits<16>>,
    by_at_r: DFF<Bits<16>>,
    by_far_r: DFF<Bits<16>>,
    bx: Signal<Local, Bits<16>>,
    by: Signal<Local, Bits<16>>,
    x_q: DFF<Bits<16>>,
    y_q: DFF<Bits<16>>,
    z_q: DFF<Bits<16>>,
    addr_q: DFF<Bits<32>>,
    addr_q2: DFF<Bits<32>>,
    addr_q3: DFF<Bits<32>>,
    pad_q: DFF<Bit>,
    /// The external port's word, registered twice: the memory module's own
    /// read takes the same three clocks (a register at each of its block
    /// RAMs and a relay register beside the lane).
    ext_q: DFF<Bits<16>>,
    ext_q2: DFF<Bits<16>>,
    sr_q: DFF<Bit>,
    edge_q: DFF<Bit>,
    face_q: DFF<Bits<3>>,
    bx_q: DFF<Bits<16>>,
    by_q: DFF<Bits<16>>,
}

impl<const A: usize> CfbLane<A> {
    /// Lane `k` of `c`'s CFB; `external`: the voxels come from external RAM
    /// (or from none: the late CFB recomputes the control only).
    pub fn new(k: u32, c: &PipelineConfig, external: bool) -> CfbLane<A> {
        let p = c.p;
        CfbLane {
            clock: Default::default(),
            dims: Default::default(),
            slices: Default::default(),
            axes: Default::default(),
            address_reg: Default::default(),
            dx: Default::default(),
            dy: Default::default(),
            eye_x: Default::default(),
            eye_y: Default::default(),
            eye_z: Default::default(),
            d_n_s: Default::default(),
            d_n_beam: Default::default(),
            d_n_b: Default::default(),
            a_n_s: Default::default(),
            a_n_beam: Default::default(),
            a_n_b: Default::default(),
            c_n_s: Default::default(),
            c_n_beam: Default::default(),
            c_n_b: Default::default(),
            n_s: Default::default(),
            n_beam: Default::default(),
            load_enable: Default::default(),
            load_module: Default::default(),
            load_address: Default::default(),
            load_data: Default::default(),
            ext_addr: Default::default(),
            ext_data: Default::default(),
            value: Default::default(),
            x: Default::default(),
            y: Default::default(),
            z: Default::default(),
            address: Default::default(),
            pad: Default::default(),
            sr: Default::default(),
            er: Default::default(),
            at_edge: Default::default(),
            face: Default::default(),
            base_x: Default::default(),
            base_y: Default::default(),
            halo: Default::default(),
            dx_neg: Default::default(),
            dx_mag: Default::default(),
            dy_neg: Default::default(),
            dy_mag: Default::default(),
            invalid: Default::default(),
            // A 2-word stub when the voxels live in external RAM.
            memory: {
                let m = DepthRam::new(if external {
                    1
                } else {
                    (c.memory_bits() as usize).min(A)
                })
                .fields(
                    &[(0, c.voxel_bits as usize)],
                    ((1u64 << c.voxel_bits) - 1).to_bits(),
                );
                if external {
                    m
                } else {
                    m.bank_registers().relay()
                }
            },
            lane: Constant::new(bits16(k)),
            p_mask: Constant::new(bits16(p - 1)),
            p_shift: Constant::new((p.trailing_zeros() as u64).to_bits()),
            perspective: Constant::new(c.perspective),
            external: Constant::new(external),
            view_dims: Default::default(),
            view_slices: Default::default(),
            view_axes: Default::default(),
            view_dx: LaneCopy::new(!c.perspective),
            view_dy: LaneCopy::new(!c.perspective),
            nx: Default::default(),
            nx_last: Default::default(),
            ny_last: Default::default(),
            nz_last: Default::default(),
            z0: Default::default(),
            z1: Default::default(),
            border: Default::default(),
            u_from: Default::default(),
            v_from: Default::default(),
            w_from: Default::default(),
            b_u: Default::default(),
            slab_lo: Default::default(),
            slab_hi: Default::default(),
            dx_abs: Default::default(),
            dy_abs: Default::default(),
            par_dxn: LaneCopy::new(!c.perspective),
            par_dxm: LaneCopy::new(!c.perspective),
            par_dx_pos: LaneCopy::new(!c.perspective),
            par_dyn: LaneCopy::new(!c.perspective),
            par_dym: LaneCopy::new(!c.perspective),
            par_dy_pos: LaneCopy::new(!c.perspective),
            div: Divider::new(k, p, c.frac_bits, c.perspective),
            dxn: Default::default(),
            dxm: Default::default(),
            dyn_: Default::default(),
            dym: Default::default(),
            inval: Default::default(),
            dx_pos: Default::default(),
            dx_neg_nz: Default::default(),
            dy_pos: Default::default(),
            dy_neg_nz: Default::default(),
            dxn_q: Default::default(),
            dxm_q: Default::default(),
            dyn_q: Default::default(),
            dym_q: Default::default(),
            inval_q: Default::default(),
            halo_q: Default::default(),
            c_xc: Default::default(),
            xc_r: Default::default(),
            pad_r: Default::default(),
            xc: Default::default(),
            a_xc: Default::default(),
            a_u: Default::default(),
            a_v: Default::default(),
            a_w: Default::default(),
            a_pad: Default::default(),
            m_u: Default::default(),
            m_v: Default::default(),
            m_w_lo: Default::default(),
            m_w_hi: Default::default(),
            m_pad: Default::default(),
            addr: Default::default(),
            is_pad: Default::default(),
            face_c: Default::default(),
            c_depth: Default::default(),
            x_last_r: Default::default(),
            x_first_r: Default::default(),
            y_last_r: Default::default(),
            y_first_r: Default::default(),
            s_last_r: Default::default(),
            bx_at_r: Default::default(),
            bx_far_r: Default::default(),
            b_near_r: Default::default(),
            by_at_r: Default::default(),
            by_far_r: Default::default(),
            bx: Default::default(),
            by: Default::default(),
            x_q: Default::default(),
            y_q: Default::default(),
            z_q: Default::default(),
            addr_q: Default::default(),
            addr_q2: Default::default(),
            addr_q3: Default::default(),
            pad_q: Default::default(),
            ext_q: Default::default(),
            ext_q2: Default::default(),
            sr_q: Default::default(),
            edge_q: Default::default(),
            face_q: Default::default(),
            bx_q: Default::default(),
            by_q: Default::default(),
        }
    }

    /// Give the memory module initial contents (block-RAM initialisation).
    pub fn preload(&mut self, words: &[u16]) {
        self.memory
            .preload(words.iter().map(|&w| (w as u64).to_bits::<16>()));
    }
}

impl<const A: usize> Logic for CfbLane<A> {
    // The halo test is written `n_s + 1 <= z0` so that Verilator sees no
    // constant compare when z0 = 0.
    #[allow(clippy::int_plus_one)]
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self,
            clock,
            x_q,
            y_q,
            z_q,
            addr_q,
            addr_q2,
            addr_q3,
            pad_q,
            ext_q,
            ext_q2,
            sr_q,
            edge_q,
            face_q,
            bx_q,
            by_q,
            dxn_q,
            dxm_q,
            dyn_q,
            dym_q,
            inval_q,
            halo_q,
            a_u,
            a_v,
            a_w,
            a_pad,
            m_u,
            m_pad,
            addr,
            xc_r,
            pad_r,
            x_last_r,
            x_first_r,
            y_last_r,
            y_first_r,
            s_last_r,
            bx_at_r,
            bx_far_r,
            b_near_r,
            by_at_r,
            by_far_r,
            nx,
            b_u,
            slab_lo,
            slab_hi,
            view_dims,
            view_slices,
            view_axes,
            view_dx,
            view_dy,
            nx_last,
            ny_last,
            nz_last,
            border,
            par_dxn,
            par_dxm,
            par_dx_pos,
            par_dyn,
            par_dym,
            par_dy_pos
        );
        // The view registers' fields, copied beside the lane.
        self.view_dims.d.next = self.dims.val().get_bits::<48>(0);
        self.view_slices.d.next = self.slices.val().get_bits::<32>(0);
        self.view_axes.d.next = self.axes.val().get_bits::<6>(0);
        self.view_dx.d.next = bit_cast::<33, 32>(self.dx.val().get_bits::<32>(0))
            | (bit_cast::<33, 1>(self.dx.val().get_bits::<1>(63)) << 32);
        self.view_dy.d.next = bit_cast::<33, 32>(self.dy.val().get_bits::<32>(0))
            | (bit_cast::<33, 1>(self.dy.val().get_bits::<1>(63)) << 32);
        self.nx.d.next = self.dims.val().get_bits::<16>(0);
        self.nx_last.d.next = self.view_dims.q.val().get_bits::<16>(0) - 1;
        self.ny_last.d.next = self.view_dims.q.val().get_bits::<16>(16) - 1;
        self.nz_last.d.next = self.view_dims.q.val().get_bits::<16>(32) - 1;
        self.z0.next = self.view_slices.q.val().get_bits::<16>(0);
        self.z1.next = self.view_slices.q.val().get_bits::<16>(16);
        self.border.d.next = self.z1.val() - self.z0.val();
        self.u_from.next = self.view_axes.q.val().get_bits::<2>(0);
        self.v_from.next = self.view_axes.q.val().get_bits::<2>(2);
        self.w_from.next = self.view_axes.q.val().get_bits::<2>(4);
        self.b_u.d.next = self.address_reg.val().get_bits::<16>(0);
        self.slab_lo.d.next = self.address_reg.val().get_bits::<16>(16);
        self.slab_hi.d.next = self.address_reg.val().get_bits::<16>(32);
        // |Dx| and |Dy|: the magnitudes the lanes take are 16 bits, the
        // low 16 bits of the negation need only the register's.
        self.dx_abs.next = self.view_dx.q.val().get_bits::<16>(0);
        if self.view_dx.q.val().get_bit(32) {
            self.dx_abs.next = 0 - self.view_dx.q.val().get_bits::<16>(0);
        }
        self.dy_abs.next = self.view_dy.q.val().get_bits::<16>(0);
        if self.view_dy.q.val().get_bit(32) {
            self.dy_abs.next = 0 - self.view_dy.q.val().get_bits::<16>(0);
        }
        self.par_dxm.d.next = self.dx_abs.val();
        // Non-zero tested on the register, not on the negation (`-x` is
        // zero mod 2^32 only where `x` is): a reduction beside the chain.
        self.par_dxn.d.next =
            self.view_dx.q.val().get_bit(32) & (self.view_dx.q.val().get_bits::<32>(0) != 0);
        self.par_dx_pos.d.next =
            !self.view_dx.q.val().get_bit(32) & (self.view_dx.q.val().get_bits::<32>(0) != 0);
        self.par_dym.d.next = self.dy_abs.val();
        self.par_dyn.d.next =
            self.view_dy.q.val().get_bit(32) & (self.view_dy.q.val().get_bits::<32>(0) != 0);
        self.par_dy_pos.d.next =
            !self.view_dy.q.val().get_bit(32) & (self.view_dy.q.val().get_bits::<32>(0) != 0);
        self.memory.read_clock.next = self.clock.val();
        self.memory.write_clock.next = self.clock.val();
        self.memory.write_enable.next =
            self.load_enable.val() & (bit_cast::<16, 8>(self.load_module.val()) == self.lane.val());
        self.memory.write_address.next = self.load_address.val();
        self.memory.write_data.next = self.load_data.val();
        // The address, in four clocks (`ADDRESS_STAGES` and the RAM's
        // registered read; its bank and relay registers make six). 1: skew, the lane's x within the partial beam,
        // and pipeline to dataset coordinates.
        self.a_xc.next = (self.a_n_b.val() << self.p_shift.val())
            | ((self.lane.val() - self.a_n_beam.val() - self.a_n_s.val()) & self.p_mask.val());
        self.a_pad.d.next = self.a_xc.val() >= self.nx.q.val();
        self.a_u.d.next = self.a_xc.val();
        if self.u_from.val() == 1 {
            self.a_u.d.next = self.a_n_beam.val();
        }
        if self.u_from.val() == 2 {
            self.a_u.d.next = self.a_n_s.val();
        }
        self.a_v.d.next = self.a_xc.val();
        if self.v_from.val() == 1 {
            self.a_v.d.next = self.a_n_beam.val();
        }
        if self.v_from.val() == 2 {
            self.a_v.d.next = self.a_n_s.val();
        }
        self.a_w.d.next = self.a_xc.val();
        if self.w_from.val() == 1 {
            self.a_w.d.next = self.a_n_beam.val();
        }
        if self.w_from.val() == 2 {
            self.a_w.d.next = self.a_n_s.val();
        }
        // 2: the products of i = u div P + v*b + w*b*n_v.
        self.m_u.d.next = bit_cast::<32, 16>(self.a_u.q.val()) >> self.p_shift.val();
        self.m_v.clock.next = self.clock.val();
        self.m_w_lo.clock.next = self.clock.val();
        self.m_w_hi.clock.next = self.clock.val();
        self.m_v.a.next = self.a_v.q.val();
        self.m_v.b.next = self.b_u.q.val();
        self.m_w_lo.a.next = self.a_w.q.val();
        self.m_w_lo.b.next = self.slab_lo.q.val();
        self.m_w_hi.a.next = self.a_w.q.val();
        self.m_w_hi.b.next = self.slab_hi.q.val();
        self.m_pad.d.next = self.a_pad.q.val();
        // 3: their sum, registered apart from the RAM's address register
        // (it fans out to every block RAM of the module).
        self.addr.d.next =
            self.m_u.q.val() + self.m_v.p.val() + self.m_w_lo.p.val() + (self.m_w_hi.p.val() << 16);
        if self.m_pad.q.val() {
            self.addr.d.next = 0.into();
        }
        self.memory.read_address.next = bit_cast::<A, 32>(self.addr.q.val());
        self.ext_addr.next = self.addr.q.val();
        // The control, from the delayed counters: the same skew, and the
        // padding test, a clock ahead and registered.
        self.c_xc.next = (self.c_n_b.val() << self.p_shift.val())
            | ((self.lane.val() - self.c_n_beam.val() - self.c_n_s.val()) & self.p_mask.val());
        self.xc_r.d.next = self.c_xc.val();
        self.pad_r.d.next = self.c_xc.val() >= self.nx.q.val();
        self.xc.next = self.xc_r.q.val();
        self.is_pad.next = self.pad_r.q.val();
        self.c_depth.next = self.z1.val() - self.c_n_s.val();
        self.x_last_r.d.next = self.c_xc.val() == self.nx_last.q.val();
        self.x_first_r.d.next = self.c_xc.val() == 0;
        self.y_last_r.d.next = self.c_n_beam.val() == self.ny_last.q.val();
        self.y_first_r.d.next = self.c_n_beam.val() == 0;
        self.s_last_r.d.next = self.c_n_s.val() == self.z1.val();
        self.bx_at_r.d.next = self.border.q.val() + self.c_xc.val();
        self.bx_far_r.d.next = self.border.q.val() + self.c_xc.val() + self.c_depth.val();
        self.b_near_r.d.next = self.border.q.val() - self.c_depth.val();
        self.by_at_r.d.next = self.border.q.val() + self.c_n_beam.val();
        self.by_far_r.d.next = self.border.q.val() + self.c_n_beam.val() + self.c_depth.val();
        // Sight-ray increments: frame registers, or the per-voxel divider.
        self.div.clock.next = self.clock.val();
        self.div.n_s.next = self.d_n_s.val();
        self.div.n_beam.next = self.d_n_beam.val();
        self.div.n_b.next = self.d_n_b.val();
        self.div.eye_x.next = self.eye_x.val();
        self.div.eye_y.next = self.eye_y.val();
        self.div.eye_z.next = self.eye_z.val();
        self.dxn.next = self.par_dxn.q.val();
        self.dxm.next = self.par_dxm.q.val();
        self.dyn_.next = self.par_dyn.q.val();
        self.dym.next = self.par_dym.q.val();
        self.dx_pos.next = self.par_dx_pos.q.val();
        self.dx_neg_nz.next = self.par_dxn.q.val();
        self.dy_pos.next = self.par_dy_pos.q.val();
        self.dy_neg_nz.next = self.par_dyn.q.val();
        self.inval.next = false;
        if self.perspective.val() {
            self.dxn.next = self.div.dx_neg.val();
            self.dyn_.next = self.div.dy_neg.val();
            self.dxm.next = self.div.dx_mag.val();
            self.dym.next = self.div.dy_mag.val();
            self.inval.next = self.div.invalid.val();
            self.dx_pos.next = self.div.dx_pos.val();
            self.dx_neg_nz.next = self.div.dx_neg.val();
            self.dy_pos.next = self.div.dy_pos.val();
            self.dy_neg_nz.next = self.div.dy_neg.val();
        }
        if self.is_pad.val() {
            self.dxm.next = 0.into();
            self.dym.next = 0.into();
            self.dxn.next = false;
            self.dyn_.next = false;
        }
        // Exit face and base-plane address.
        self.face_c.next = 0.into();
        self.bx.next = self.bx_at_r.q.val();
        self.by.next = self.by_at_r.q.val();
        if self.x_last_r.q.val() & self.dx_pos.val() {
            self.face_c.next = 2.into();
            self.bx.next = self.bx_far_r.q.val();
        } else if self.x_first_r.q.val() & self.dx_neg_nz.val() {
            self.face_c.next = 3.into();
            self.bx.next = self.b_near_r.q.val();
        } else if self.y_last_r.q.val() & self.dy_pos.val() {
            self.face_c.next = 4.into();
            self.by.next = self.by_far_r.q.val();
        } else if self.y_first_r.q.val() & self.dy_neg_nz.val() {
            self.face_c.next = 5.into();
            self.by.next = self.b_near_r.q.val();
        }
        if self.s_last_r.q.val() {
            self.face_c.next = 1.into();
            self.bx.next = self.bx_at_r.q.val();
            self.by.next = self.by_at_r.q.val();
        }
        if self.is_pad.val() | self.inval.val() {
            self.face_c.next = 0.into();
        }
        if self.face_c.val() == 0 {
            self.bx.next = 0.into();
            self.by.next = 0.into();
        }
        self.x_q.d.next = self.xc.val();
        self.y_q.d.next = self.n_beam.val();
        self.z_q.d.next = self.n_s.val();
        self.addr_q.d.next = self.addr.q.val();
        self.addr_q2.d.next = self.addr_q.q.val();
        self.addr_q3.d.next = self.addr_q2.q.val();
        self.pad_q.d.next = self.is_pad.val();
        self.sr_q.d.next = self.n_s.val() == self.z0.val();
        self.edge_q.d.next = self.is_pad.val()
            | self.x_first_r.q.val()
            | self.y_first_r.q.val()
            | (self.n_s.val() == 0)
            | self.x_last_r.q.val()
            | self.y_last_r.q.val()
            | (self.n_s.val() == self.nz_last.q.val());
        self.face_q.d.next = self.face_c.val();
        self.bx_q.d.next = self.bx.val();
        self.by_q.d.next = self.by.val();
        self.dxn_q.d.next = self.dxn.val();
        self.dxm_q.d.next = self.dxm.val();
        self.dyn_q.d.next = self.dyn_.val();
        self.dym_q.d.next = self.dym.val();
        self.inval_q.d.next = self.inval.val() | self.is_pad.val();
        self.halo_q.d.next =
            (self.n_s.val() + 1 <= self.z0.val()) | (self.n_s.val() > self.z1.val());
        // Outputs: registered control beside the RAM's registered read.
        self.ext_q.d.next = self.ext_data.val();
        self.ext_q2.d.next = self.ext_q.q.val();
        self.value.next = self.memory.read_data.val();
        if self.external.val() {
            self.value.next = self.ext_q2.q.val();
        }
        if self.pad_q.q.val() {
            self.value.next = 0.into();
        }
        self.x.next = self.x_q.q.val();
        self.y.next = self.y_q.q.val();
        self.z.next = self.z_q.q.val();
        self.address.next = self.addr_q3.q.val();
        self.pad.next = self.pad_q.q.val();
        self.sr.next = self.sr_q.q.val();
        self.er.next = self.face_q.q.val() != 0;
        self.at_edge.next = self.edge_q.q.val();
        self.face.next = self.face_q.q.val();
        self.base_x.next = self.bx_q.q.val();
        self.base_y.next = self.by_q.q.val();
        self.dx_neg.next = self.dxn_q.q.val();
        self.dx_mag.next = self.dxm_q.q.val();
        self.dy_neg.next = self.dyn_q.q.val();
        self.dy_mag.next = self.dym_q.q.val();
        self.invalid.next = self.inval_q.q.val();
        self.halo.next = self.halo_q.q.val();
    }
}
