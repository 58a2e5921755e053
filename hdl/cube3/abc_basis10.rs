//! The 10-neighbourhood's gradient of one Cube-3 ABC unit (§4, Fig. 10),
//! bit for bit as `golden_model::cube3::abc::gradient`'s `N10`, for
//! parallel views: the left and right (above and below) samples are
//! replaced by the points of the neighbour rays that lie in the plane
//! through the centre orthogonal to the ray, linearly interpolated between
//! two of their samples with the weight `T_x` (`T_y`):
//!
//! ```text
//! G_x = lerp(S(1, 0, 0), S(1, 0, -s_x), T_x) - lerp(S(-1, 0, 0), S(-1, 0, s_x), T_x)
//! G_y = lerp(S(0, 1, 0), S(0, 1, -s_y), T_y) - lerp(S(0, -1, 0), S(0, -1, s_y), T_y)
//! G_r = S(0, 0, 1) - S(0, 0, -1)
//! g_i = (C_i0·G_x + C_i1·G_y + C_i2·G_r + 2^(W-1)) >> W    (arithmetic)
//! ```
//!
//! with `s_x = sign(DX)`, and the differences along the basis `a_x`, `a_y`,
//! `r` brought to the traversal axes by the basis correction `C`. The host
//! computes `T` and `C` from the view's increments and loads them
//! (`C3Weights10`, `C3Basis10X/Y/Z`, sixteen-bit two's-complement fields):
//! a perspective view's would differ from ray to ray, which this unit does
//! not hold.
//!
//! Clocks 0-1: the four lerps (`Lerp`, two clocks) and `G_r`; clock 2: the
//! three differences, and each coefficient's sign and magnitude,
//! registered; clock 3: the nine products, registered; then the sums and
//! the shift leave combinationally, [`LATENCY`] clocks after the taps, as
//! the 6's shear does. Only 10-neighbourhood builds instantiate it.

use super::signed_product::SignedProduct;
use crate::common::lerp::{self, Lerp};
use rust_hdl::prelude::*;

/// Clocks from the taps to the gradient (before the estimator's
/// saturation and output register).
pub const LATENCY: usize = 4;
const _: () = assert!(lerp::LATENCY == 2, "update AbcBasis10's clocks");

/// One lane's 10-neighbourhood gradient.
#[derive(LogicBlock)]
pub struct AbcBasis10 {
    pub clock: Signal<In, Clock>,
    /// The taps (numbered as the estimator's: `kp{3a + b}` = `S(1 - b, 1 -
    /// a, +1)`).
    pub xp: Signal<In, Bits<32>>,
    pub xm: Signal<In, Bits<32>>,
    pub yp: Signal<In, Bits<32>>,
    pub ym: Signal<In, Bits<32>>,
    pub kp1: Signal<In, Bits<32>>,
    pub kp3: Signal<In, Bits<32>>,
    pub kp4: Signal<In, Bits<32>>,
    pub kp5: Signal<In, Bits<32>>,
    pub kp7: Signal<In, Bits<32>>,
    pub km1: Signal<In, Bits<32>>,
    pub km3: Signal<In, Bits<32>>,
    pub km4: Signal<In, Bits<32>>,
    pub km5: Signal<In, Bits<32>>,
    pub km7: Signal<In, Bits<32>>,
    /// The centre ray's increments (only their signs are read).
    pub dx_neg: Signal<In, Bit>,
    pub dx_mag: Signal<In, Bits<16>>,
    pub dy_neg: Signal<In, Bit>,
    pub dy_mag: Signal<In, Bits<16>>,
    /// `T_x | T_y << 16`, and the rows of `C`.
    pub weights: Signal<In, Bits<64>>,
    pub basis_x: Signal<In, Bits<64>>,
    pub basis_y: Signal<In, Bits<64>>,
    pub basis_z: Signal<In, Bits<64>>,
    /// `g` of the taps [`LATENCY`] clocks back, 64-bit two's complement.
    pub gx: Signal<Out, Bits<64>>,
    pub gy: Signal<Out, Bits<64>>,
    pub gz: Signal<Out, Bits<64>>,
    half: Constant<Bits<64>>,
    shift: Constant<Bits<8>>,
    sx_pos: Signal<Local, Bit>,
    sx_neg: Signal<Local, Bit>,
    sy_pos: Signal<Local, Bit>,
    sy_neg: Signal<Local, Bit>,
    x_far: Signal<Local, Bits<32>>,
    xm_far: Signal<Local, Bits<32>>,
    y_far: Signal<Local, Bits<32>>,
    ym_far: Signal<Local, Bits<32>>,
    right: Lerp,
    left: Lerp,
    below: Lerp,
    above: Lerp,
    gr_q: [DFF<Bits<32>>; 2],
    // Clock 2.
    g_q: [DFF<Bits<32>>; 3],
    c_neg_q: [DFF<Bit>; 9],
    c_mag_q: [DFF<Bits<16>>; 9],
    c: [Signal<Local, Bits<16>>; 9],
    // Clock 3.
    products: [SignedProduct; 9],
    p_q: [DFF<Bits<64>>; 9],
    sum: [Signal<Local, Bits<64>>; 3],
    g: [Signal<Local, Bits<64>>; 3],
}

impl AbcBasis10 {
    /// `W` fractional bits; `wide`: samples of more than 16 bits.
    pub fn new(weight_bits: u32, wide: bool) -> AbcBasis10 {
        let lerp = || Lerp::new(weight_bits, wide);
        AbcBasis10 {
            clock: Default::default(),
            xp: Default::default(),
            xm: Default::default(),
            yp: Default::default(),
            ym: Default::default(),
            kp1: Default::default(),
            kp3: Default::default(),
            kp4: Default::default(),
            kp5: Default::default(),
            kp7: Default::default(),
            km1: Default::default(),
            km3: Default::default(),
            km4: Default::default(),
            km5: Default::default(),
            km7: Default::default(),
            dx_neg: Default::default(),
            dx_mag: Default::default(),
            dy_neg: Default::default(),
            dy_mag: Default::default(),
            weights: Default::default(),
            basis_x: Default::default(),
            basis_y: Default::default(),
            basis_z: Default::default(),
            gx: Default::default(),
            gy: Default::default(),
            gz: Default::default(),
            half: Constant::new((1u64 << (weight_bits - 1)).to_bits()),
            shift: Constant::new((weight_bits as u64).to_bits()),
            sx_pos: Default::default(),
            sx_neg: Default::default(),
            sy_pos: Default::default(),
            sy_neg: Default::default(),
            x_far: Default::default(),
            xm_far: Default::default(),
            y_far: Default::default(),
            ym_far: Default::default(),
            right: lerp(),
            left: lerp(),
            below: lerp(),
            above: lerp(),
            gr_q: Default::default(),
            g_q: Default::default(),
            c_neg_q: Default::default(),
            c_mag_q: Default::default(),
            c: Default::default(),
            products: std::array::from_fn(|_| SignedProduct::new(wide)),
            p_q: Default::default(),
            sum: Default::default(),
            g: Default::default(),
        }
    }
}

impl Logic for AbcBasis10 {
    #[hdl_gen]
    fn update(&mut self) {
        for i in 0..2 {
            self.gr_q[i].clock.next = self.clock.val();
        }
        for i in 0..3 {
            self.g_q[i].clock.next = self.clock.val();
        }
        for i in 0..9 {
            self.c_neg_q[i].clock.next = self.clock.val();
            self.c_mag_q[i].clock.next = self.clock.val();
            self.p_q[i].clock.next = self.clock.val();
        }
        self.right.clock.next = self.clock.val();
        self.left.clock.next = self.clock.val();
        self.below.clock.next = self.clock.val();
        self.above.clock.next = self.clock.val();
        // Clock 0: each neighbour ray's second sample, on the plane the sign
        // of the increment selects (the same sample when it is zero).
        self.sx_pos.next = !self.dx_neg.val() & self.dx_mag.val().any();
        self.sx_neg.next = self.dx_neg.val() & self.dx_mag.val().any();
        self.sy_pos.next = !self.dy_neg.val() & self.dy_mag.val().any();
        self.sy_neg.next = self.dy_neg.val() & self.dy_mag.val().any();
        self.x_far.next = self.xp.val();
        self.xm_far.next = self.xm.val();
        if self.sx_pos.val() {
            self.x_far.next = self.km3.val();
            self.xm_far.next = self.kp5.val();
        }
        if self.sx_neg.val() {
            self.x_far.next = self.kp3.val();
            self.xm_far.next = self.km5.val();
        }
        self.y_far.next = self.yp.val();
        self.ym_far.next = self.ym.val();
        if self.sy_pos.val() {
            self.y_far.next = self.km1.val();
            self.ym_far.next = self.kp7.val();
        }
        if self.sy_neg.val() {
            self.y_far.next = self.kp1.val();
            self.ym_far.next = self.km7.val();
        }
        // Clocks 0-1: the lerps, and G_r waiting beside them.
        self.right.a.next = self.xp.val();
        self.right.b.next = self.x_far.val();
        self.right.w.next = self.weights.val().get_bits::<16>(0);
        self.left.a.next = self.xm.val();
        self.left.b.next = self.xm_far.val();
        self.left.w.next = self.weights.val().get_bits::<16>(0);
        self.below.a.next = self.yp.val();
        self.below.b.next = self.y_far.val();
        self.below.w.next = self.weights.val().get_bits::<16>(16);
        self.above.a.next = self.ym.val();
        self.above.b.next = self.ym_far.val();
        self.above.w.next = self.weights.val().get_bits::<16>(16);
        self.gr_q[0].d.next = self.kp4.val() - self.km4.val();
        self.gr_q[1].d.next = self.gr_q[0].q.val();
        // Clock 2: the differences; the coefficients in sign and magnitude.
        self.g_q[0].d.next = self.right.y.val() - self.left.y.val();
        self.g_q[1].d.next = self.below.y.val() - self.above.y.val();
        self.g_q[2].d.next = self.gr_q[1].q.val();
        self.c[0].next = self.basis_x.val().get_bits::<16>(0);
        self.c[1].next = self.basis_x.val().get_bits::<16>(16);
        self.c[2].next = self.basis_x.val().get_bits::<16>(32);
        self.c[3].next = self.basis_y.val().get_bits::<16>(0);
        self.c[4].next = self.basis_y.val().get_bits::<16>(16);
        self.c[5].next = self.basis_y.val().get_bits::<16>(32);
        self.c[6].next = self.basis_z.val().get_bits::<16>(0);
        self.c[7].next = self.basis_z.val().get_bits::<16>(16);
        self.c[8].next = self.basis_z.val().get_bits::<16>(32);
        for i in 0..9 {
            self.c_neg_q[i].d.next = self.c[i].val().get_bit(15);
            self.c_mag_q[i].d.next = self.c[i].val();
            if self.c[i].val().get_bit(15) {
                self.c_mag_q[i].d.next = !self.c[i].val() + 1;
            }
        }
        // Clock 3: C_ij·G_j, product i·3 + j.
        for i in 0..3 {
            for j in 0..3 {
                self.products[i * 3 + j].g.next = self.g_q[j].q.val();
                self.products[i * 3 + j].d_neg.next = self.c_neg_q[i * 3 + j].q.val();
                self.products[i * 3 + j].d_mag.next = self.c_mag_q[i * 3 + j].q.val();
            }
        }
        for i in 0..9 {
            self.p_q[i].d.next = self.products[i].y.val();
        }
        // Clock 4: the rows' sums, rounded and shifted (arithmetic).
        for i in 0..3 {
            self.sum[i].next = self.p_q[i * 3].q.val()
                + self.p_q[i * 3 + 1].q.val()
                + self.p_q[i * 3 + 2].q.val()
                + self.half.val();
            self.g[i].next = self.sum[i].val() >> self.shift.val();
            if self.sum[i].val().get_bit(63) {
                self.g[i].next = !((!self.sum[i].val()) >> self.shift.val());
            }
        }
        self.gx.next = self.g[0].val();
        self.gy.next = self.g[1].val();
        self.gz.next = self.g[2].val();
    }
}
