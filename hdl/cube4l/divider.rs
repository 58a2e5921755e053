//! The sight-ray divider of the Cube-4L CFB (§3.1), for perspective views:
//! from a lane's counters N_s, N_B and N_b to its voxel's increments `dx`
//! and `dy` (sign and magnitude, 1.0 = 2^f) and the *invalid* bit, as
//! `golden_model::cube4l::plan::Sweep::increments` and `control` compute
//! them, pipelined over [`LATENCY`] clocks so that no clock holds more than
//! one 64-bit carry chain:
//!
//! 1. the lane's skewed x (`N_b*P + ((k - N_B - N_s) mod P)`);
//! 2. `S = P - V` in fixed point: `(x, y, z) << f` plus the negated eye;
//! 3. the magnitudes of S, the signs of `S_x/S_z` and `S_y/S_z`, and which
//!    of S_x and S_y are nonzero with S_z;
//! 4. the numerators `|S_x| << f + |S_z|/2` (rounding halves away from
//!    zero) and `|S_y| << f + |S_z|/2`, the denominator `|S_z|`, and
//!    `S_z = 0`;
//! 5. restoring division, one quotient bit a clock over 17 bits, clocks 5
//!    to 21 ([`DivStage`]), and, beside the first, the overflow test (a
//!    quotient of 2^17 or more, far beyond the 45-degree limit of 2^f);
//! 6. at clock 22, *invalid* (`S_z = 0`, an overflow, or `|dx|` or `|dy|`
//!    above 1.0), and an invalid voxel's saturated direction
//!    `sign(S_x) * sign(S_z)`;
//! 7. at clock 23, the same in a relay register: the result's register
//!    lies beside the division stages, the relay beside the lane's control,
//!    which reads it (the route between them was the perspective build's
//!    critical path).
//!
//! The CFB issues the divider's counters [`LATENCY`] clocks before the
//! control that reads its result (`super::counter_lead`). Only perspective
//! builds instantiate it.

use super::div_stage::DivStage;
use crate::common::bits16;
use rust_hdl::prelude::*;

/// Clocks from the counters to the registered increments.
pub const LATENCY: usize = 23;
// `hdl_gen` needs literal loop bounds: `update` is written for 17 division
// stages behind 4 front stages and before the result's two registers.
const _: () = assert!(LATENCY == 4 + 17 + 2, "update the literals in Divider");

// The flags carried through the division stages, by bit (literals in
// `update`, which `hdl_gen` needs): 0 and 1, `S_x / S_z` (`S_y / S_z`) is
// negative; 2 and 3, `S_x` (`S_y`) and `S_z` are both nonzero, so that an
// invalid voxel's increment saturates to one; 4, `S_z = 0`; 5 and 6, the
// quotient of x (y) would need more than 17 bits.

#[derive(LogicBlock)]
pub struct Divider {
    pub clock: Signal<In, Clock>,
    /// The counters as the CFB issues them.
    pub n_s: Signal<In, Bits<16>>,
    pub n_beam: Signal<In, Bits<16>>,
    pub n_b: Signal<In, Bits<16>>,
    /// The negated eye, in fixed point (the host's registers).
    pub eye_x: Signal<In, Bits<64>>,
    pub eye_y: Signal<In, Bits<64>>,
    pub eye_z: Signal<In, Bits<64>>,
    /// The increments of the voxel whose counters came [`LATENCY`] clocks
    /// earlier: sign (only when nonzero) and magnitude (at most 1.0, in
    /// the CFB's 16-bit increments), positive (and nonzero), and *invalid*.
    pub dx_neg: Signal<Out, Bit>,
    pub dx_mag: Signal<Out, Bits<16>>,
    pub dx_pos: Signal<Out, Bit>,
    pub dy_neg: Signal<Out, Bit>,
    pub dy_mag: Signal<Out, Bits<16>>,
    pub dy_pos: Signal<Out, Bit>,
    pub invalid: Signal<Out, Bit>,
    lane: Constant<Bits<16>>,
    p_mask: Constant<Bits<16>>,
    p_shift: Constant<Bits<8>>,
    frac: Constant<Bits<8>>,
    one: Constant<Bits<32>>,
    enabled: Constant<Bit>,
    // 1: the skewed x, beside its y and z.
    xc: DFF<Bits<16>>,
    yc: DFF<Bits<16>>,
    zc: DFF<Bits<16>>,
    // 2: S.
    sx: DFF<Bits<64>>,
    sy: DFF<Bits<64>>,
    sz: DFF<Bits<64>>,
    // 3: |S| and the flags.
    mx: DFF<Bits<64>>,
    my: DFF<Bits<64>>,
    mz: DFF<Bits<64>>,
    f3: DFF<Bits<7>>,
    // 4: the division's operands.
    num_x: DFF<Bits<64>>,
    num_y: DFF<Bits<64>>,
    den: DFF<Bits<64>>,
    f4: DFF<Bits<7>>,
    // 5: the overflow tests, beside the first division stage.
    ovf: DFF<Bits<7>>,
    x_neg: Signal<Local, Bit>,
    y_neg: Signal<Local, Bit>,
    x_nz: Signal<Local, Bit>,
    y_nz: Signal<Local, Bit>,
    z_zero: Signal<Local, Bit>,
    x_ovf: Signal<Local, Bit>,
    y_ovf: Signal<Local, Bit>,
    stages: [DivStage; 17],
    // 22: the result.
    inval: Signal<Local, Bit>,
    dxm: Signal<Local, Bits<32>>,
    dym: Signal<Local, Bits<32>>,
    flags: Signal<Local, Bits<7>>,
    dxn_q: DFF<Bit>,
    dxm_q: DFF<Bits<16>>,
    dyn_q: DFF<Bit>,
    dym_q: DFF<Bits<16>>,
    inval_q: DFF<Bit>,
    dxp_q: DFF<Bit>,
    dyp_q: DFF<Bit>,
    // 23: the relay.
    dxn_r: DFF<Bit>,
    dxm_r: DFF<Bits<16>>,
    dxp_r: DFF<Bit>,
    dyn_r: DFF<Bit>,
    dym_r: DFF<Bits<16>>,
    dyp_r: DFF<Bit>,
    inval_r: DFF<Bit>,
}

impl Divider {
    /// Lane `lane` of `p`, with `frac` fractional bits. Without `enabled`
    /// (parallel views) the outputs are zero, as in the emitted Verilog,
    /// which leaves the divider out (`export::prune`).
    pub fn new(lane: u32, p: u32, frac: u32, enabled: bool) -> Divider {
        Divider {
            clock: Default::default(),
            n_s: Default::default(),
            n_beam: Default::default(),
            n_b: Default::default(),
            eye_x: Default::default(),
            eye_y: Default::default(),
            eye_z: Default::default(),
            dx_neg: Default::default(),
            dx_mag: Default::default(),
            dx_pos: Default::default(),
            dy_neg: Default::default(),
            dy_mag: Default::default(),
            dy_pos: Default::default(),
            invalid: Default::default(),
            lane: Constant::new(bits16(lane)),
            p_mask: Constant::new(bits16(p - 1)),
            p_shift: Constant::new((p.trailing_zeros() as u64).to_bits()),
            frac: Constant::new((frac as u64).to_bits()),
            one: Constant::new((1u64 << frac).to_bits()),
            enabled: Constant::new(enabled),
            xc: Default::default(),
            yc: Default::default(),
            zc: Default::default(),
            sx: Default::default(),
            sy: Default::default(),
            sz: Default::default(),
            mx: Default::default(),
            my: Default::default(),
            mz: Default::default(),
            f3: Default::default(),
            num_x: Default::default(),
            num_y: Default::default(),
            den: Default::default(),
            f4: Default::default(),
            ovf: Default::default(),
            x_neg: Default::default(),
            y_neg: Default::default(),
            x_nz: Default::default(),
            y_nz: Default::default(),
            z_zero: Default::default(),
            x_ovf: Default::default(),
            y_ovf: Default::default(),
            stages: std::array::from_fn(|k| DivStage::new(16 - k as u32)),
            inval: Default::default(),
            dxm: Default::default(),
            dym: Default::default(),
            flags: Default::default(),
            dxn_q: Default::default(),
            dxm_q: Default::default(),
            dyn_q: Default::default(),
            dym_q: Default::default(),
            inval_q: Default::default(),
            dxp_q: Default::default(),
            dyp_q: Default::default(),
            dxn_r: Default::default(),
            dxm_r: Default::default(),
            dxp_r: Default::default(),
            dyn_r: Default::default(),
            dym_r: Default::default(),
            dyp_r: Default::default(),
            inval_r: Default::default(),
        }
    }
}

impl Logic for Divider {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(
            self, clock, xc, yc, zc, sx, sy, sz, mx, my, mz, f3, num_x, num_y, den, f4, ovf, dxn_q,
            dxm_q, dyn_q, dym_q, inval_q, dxp_q, dyp_q, dxn_r, dxm_r, dxp_r, dyn_r, dym_r, dyp_r,
            inval_r
        );
        // 1: the skew.
        self.xc.d.next = (self.n_b.val() << self.p_shift.val())
            | ((self.lane.val() - self.n_beam.val() - self.n_s.val()) & self.p_mask.val());
        self.yc.d.next = self.n_beam.val();
        self.zc.d.next = self.n_s.val();
        // 2: S = P - V.
        self.sx.d.next =
            (bit_cast::<64, 16>(self.xc.q.val()) << self.frac.val()) + self.eye_x.val();
        self.sy.d.next =
            (bit_cast::<64, 16>(self.yc.q.val()) << self.frac.val()) + self.eye_y.val();
        self.sz.d.next =
            (bit_cast::<64, 16>(self.zc.q.val()) << self.frac.val()) + self.eye_z.val();
        // 3: magnitudes and flags.
        self.mx.d.next = self.sx.q.val();
        if self.sx.q.val().get_bit(63) {
            self.mx.d.next = 0 - self.sx.q.val();
        }
        self.my.d.next = self.sy.q.val();
        if self.sy.q.val().get_bit(63) {
            self.my.d.next = 0 - self.sy.q.val();
        }
        self.mz.d.next = self.sz.q.val();
        if self.sz.q.val().get_bit(63) {
            self.mz.d.next = 0 - self.sz.q.val();
        }
        self.x_neg.next = self.sx.q.val().get_bit(63) ^ self.sz.q.val().get_bit(63);
        self.y_neg.next = self.sy.q.val().get_bit(63) ^ self.sz.q.val().get_bit(63);
        self.x_nz.next = (self.sx.q.val() != 0) & (self.sz.q.val() != 0);
        self.y_nz.next = (self.sy.q.val() != 0) & (self.sz.q.val() != 0);
        self.f3.d.next = bit_cast::<7, 1>(self.x_neg.val().into())
            | (bit_cast::<7, 1>(self.y_neg.val().into()) << 1)
            | (bit_cast::<7, 1>(self.x_nz.val().into()) << 2)
            | (bit_cast::<7, 1>(self.y_nz.val().into()) << 3);
        // 4: the operands.
        self.num_x.d.next = (self.mx.q.val() << self.frac.val()) + (self.mz.q.val() >> 1);
        self.num_y.d.next = (self.my.q.val() << self.frac.val()) + (self.mz.q.val() >> 1);
        self.den.d.next = self.mz.q.val();
        self.z_zero.next = self.mz.q.val() == 0;
        self.f4.d.next = self.f3.q.val() | (bit_cast::<7, 1>(self.z_zero.val().into()) << 4);
        // 5-21: the quotient, bit 16 first; the overflow tests beside bit 16.
        self.x_ovf.next = self.num_x.q.val() >= (self.den.q.val() << 17);
        self.y_ovf.next = self.num_y.q.val() >= (self.den.q.val() << 17);
        self.ovf.d.next = (bit_cast::<7, 1>(self.x_ovf.val().into()) << 5)
            | (bit_cast::<7, 1>(self.y_ovf.val().into()) << 6);
        for k in 0..17 {
            self.stages[k].clock.next = self.clock.val();
        }
        self.stages[0].rem_x.next = self.num_x.q.val();
        self.stages[0].rem_y.next = self.num_y.q.val();
        self.stages[0].den.next = self.den.q.val();
        self.stages[0].q_x.next = 0.into();
        self.stages[0].q_y.next = 0.into();
        self.stages[0].flags.next = self.f4.q.val();
        self.stages[1].flags.next = self.stages[0].flags_out.val() | self.ovf.q.val();
        for k in 1..17 {
            self.stages[k].rem_x.next = self.stages[k - 1].rem_x_out.val();
            self.stages[k].rem_y.next = self.stages[k - 1].rem_y_out.val();
            self.stages[k].den.next = self.stages[k - 1].den_out.val();
            self.stages[k].q_x.next = self.stages[k - 1].q_x_out.val();
            self.stages[k].q_y.next = self.stages[k - 1].q_y_out.val();
        }
        for k in 2..17 {
            self.stages[k].flags.next = self.stages[k - 1].flags_out.val();
        }
        // 22: invalid, and its saturated direction.
        self.flags.next = self.stages[16].flags_out.val();
        self.inval.next = self.flags.val().get_bit(4)
            | self.flags.val().get_bit(5)
            | self.flags.val().get_bit(6)
            | (self.stages[16].q_x_out.val() > self.one.val())
            | (self.stages[16].q_y_out.val() > self.one.val());
        self.dxm.next = self.stages[16].q_x_out.val();
        self.dym.next = self.stages[16].q_y_out.val();
        if self.inval.val() {
            self.dxm.next = 0.into();
            if self.flags.val().get_bit(2) {
                self.dxm.next = self.one.val();
            }
            self.dym.next = 0.into();
            if self.flags.val().get_bit(3) {
                self.dym.next = self.one.val();
            }
        }
        self.dxm_q.d.next = bit_cast::<16, 32>(self.dxm.val());
        self.dym_q.d.next = bit_cast::<16, 32>(self.dym.val());
        self.dxn_q.d.next = self.flags.val().get_bit(0) & (self.dxm.val() != 0);
        self.dyn_q.d.next = self.flags.val().get_bit(1) & (self.dym.val() != 0);
        self.dxp_q.d.next = !self.flags.val().get_bit(0) & (self.dxm.val() != 0);
        self.dyp_q.d.next = !self.flags.val().get_bit(1) & (self.dym.val() != 0);
        self.inval_q.d.next = self.inval.val();
        // 23: the relay.
        self.dxn_r.d.next = self.dxn_q.q.val();
        self.dxm_r.d.next = self.dxm_q.q.val();
        self.dxp_r.d.next = self.dxp_q.q.val();
        self.dyn_r.d.next = self.dyn_q.q.val();
        self.dym_r.d.next = self.dym_q.q.val();
        self.dyp_r.d.next = self.dyp_q.q.val();
        self.inval_r.d.next = self.inval_q.q.val();
        self.dx_neg.next = self.dxn_r.q.val();
        self.dx_mag.next = self.dxm_r.q.val();
        self.dx_pos.next = self.dxp_r.q.val();
        self.dy_neg.next = self.dyn_r.q.val();
        self.dy_mag.next = self.dym_r.q.val();
        self.dy_pos.next = self.dyp_r.q.val();
        self.invalid.next = self.inval_r.q.val();
        if !self.enabled.val() {
            self.dx_neg.next = false;
            self.dx_mag.next = 0.into();
            self.dx_pos.next = false;
            self.dy_neg.next = false;
            self.dy_mag.next = 0.into();
            self.dy_pos.next = false;
            self.invalid.next = false;
        }
    }
}
