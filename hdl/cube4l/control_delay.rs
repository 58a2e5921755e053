//! The control delay line of a Cube-4L pipeline (§3.5-3.7, Fig. 18): a
//! beat's control travels beside its voxel, from the shader's input to the
//! taps, the 2x2 selection and the bilinear unit (the gather, T) and on to
//! the compositor's result (T+L+4, L the bilinear unit's latency), where it
//! marks the result and, on ER, makes it a base-plane pixel.
//!
//! The shader takes `shader::LATENCY` clocks, so its input is `T - 1 -
//! GATHER_DELAY` and its sample meets the bilinear unit's output at the
//! compositor at T+L with no register of its own (`config::GATHER_DELAY`).

use super::bilinear::LATENCY;
use super::config::GATHER_DELAY;
use crate::common::lane_copy::LaneCopy;
use rust_hdl::prelude::*;

/// Registers from the shader input to the gather, and to the result.
const GATHER: usize = 1 + GATHER_DELAY;
const RESULT: usize = GATHER + LATENCY + super::compositor::LATENCY;
// `hdl_gen` needs literal loop bounds and indices: the update below is
// written for a gather 10 clocks and a result 21 clocks after the input.
const _: () = assert!(
    GATHER == 10 && RESULT == 21,
    "update the literals in ControlDelay::update"
);

/// Control registers of one lane.
#[derive(LogicBlock, Default)]
pub struct ControlDelay {
    pub clock: Signal<In, Clock>,
    /// The beat's control at the shader input.
    pub valid: Signal<In, Bit>,
    pub er: Signal<In, Bit>,
    pub pad: Signal<In, Bit>,
    pub base_x: Signal<In, Bits<16>>,
    pub base_y: Signal<In, Bits<16>>,
    pub face: Signal<In, Bits<3>>,
    pub x: Signal<In, Bits<16>>,
    pub y: Signal<In, Bits<16>>,
    pub sr: Signal<In, Bit>,
    pub dx_neg: Signal<In, Bit>,
    pub dx_mag: Signal<In, Bits<16>>,
    pub dy_neg: Signal<In, Bit>,
    pub dy_mag: Signal<In, Bits<16>>,
    /// The `Dims` register (the slice's n_x and n_y).
    pub dims: Signal<In, Bits<64>>,
    /// The bits `x`, `y`, `base_x` and `base_y` can have in the build's
    /// largest volume, a constant: the registers above them are left out
    /// (16 bits a coordinate in every build would carry 61 registers of 16
    /// bits a lane, whatever the volume).
    pub coord_mask: Signal<In, Bits<16>>,
    /// At the gather (T): the voxel's x (for the taps), |dx| and |dy| (the
    /// bilinear weights).
    pub x_t: Signal<Out, Bits<16>>,
    pub dx_mag_t: Signal<Out, Bits<16>>,
    pub dy_mag_t: Signal<Out, Bits<16>>,
    /// At T, for the 2x2 selection, one copy for each bilinear channel
    /// (bits 0 to 6, as `Select2x2` reads them): SR, the signs of dx and dy, whether they
    /// are non-zero, and whether the x (y) neighbour by the sign of dx
    /// (dy) lies outside the slice, each tested a clock ahead. A channel's
    /// own copy drives only that channel's multiplexers, where one register
    /// drove all four channels' across the lane (the shaded 256³ build's
    /// path: |dy| → its zero test → a channel's cell register, 7.53 ns of
    /// routing).
    pub sel_t: [Signal<Out, Bits<7>>; 4],
    /// At T+L+4, beside the composited value: a beat, one that is not
    /// padding, and the base-plane pixel on ER.
    pub res_beat: Signal<Out, Bit>,
    pub res_valid: Signal<Out, Bit>,
    pub px_valid: Signal<Out, Bit>,
    pub px_x: Signal<Out, Bits<16>>,
    pub px_y: Signal<Out, Bits<16>>,
    pub px_face: Signal<Out, Bits<3>>,
    /// `n_x - 1` and `n_y - 1`, registered from `Dims` (constant in a
    /// sweep), the lane's own copies.
    nx_last: LaneCopy<Bits<16>>,
    ny_last: LaneCopy<Bits<16>>,
    /// The selection's flags at T-1, and their copies at T.
    x_out: Signal<Local, Bit>,
    y_out: Signal<Local, Bit>,
    dx_nz: Signal<Local, Bit>,
    dy_nz: Signal<Local, Bit>,
    sel: Signal<Local, Bits<7>>,
    sel_q: [LaneCopy<Bits<7>>; 4],
    // Control to the gather.
    x_q: [DFF<Bits<16>>; GATHER],
    /// y goes only as far as the slice-edge test a clock before T.
    y_q: [DFF<Bits<16>>; 9],
    /// SR and the signs go only as far as the selection's flags, a clock
    /// before T.
    sr_q: [DFF<Bit>; 9],
    dxn_q: [DFF<Bit>; 9],
    dxm_q: [DFF<Bits<16>>; GATHER],
    dyn_q: [DFF<Bit>; 9],
    dym_q: [DFF<Bits<16>>; GATHER],
    // Control to the result.
    v_q: [DFF<Bit>; RESULT],
    er_q: [DFF<Bit>; RESULT],
    pad_q: [DFF<Bit>; RESULT],
    bx_q: [DFF<Bits<16>>; RESULT],
    by_q: [DFF<Bits<16>>; RESULT],
    face_q: [DFF<Bits<3>>; RESULT],
}

impl Logic for ControlDelay {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, nx_last, ny_last);
        for i in 0..10 {
            self.x_q[i].clock.next = self.clock.val();
            self.dxm_q[i].clock.next = self.clock.val();
            self.dym_q[i].clock.next = self.clock.val();
        }
        for i in 0..21 {
            self.v_q[i].clock.next = self.clock.val();
            self.er_q[i].clock.next = self.clock.val();
            self.pad_q[i].clock.next = self.clock.val();
            self.bx_q[i].clock.next = self.clock.val();
            self.by_q[i].clock.next = self.clock.val();
            self.face_q[i].clock.next = self.clock.val();
        }
        // The input -> the gather.
        self.x_q[0].d.next = self.x.val() & self.coord_mask.val();
        self.y_q[0].d.next = self.y.val() & self.coord_mask.val();
        self.sr_q[0].d.next = self.sr.val();
        self.dxn_q[0].d.next = self.dx_neg.val();
        self.dxm_q[0].d.next = self.dx_mag.val();
        self.dyn_q[0].d.next = self.dy_neg.val();
        self.dym_q[0].d.next = self.dy_mag.val();
        for i in 1..10 {
            self.x_q[i].d.next = self.x_q[i - 1].q.val();
            self.dxm_q[i].d.next = self.dxm_q[i - 1].q.val();
            self.dym_q[i].d.next = self.dym_q[i - 1].q.val();
        }
        for i in 0..9 {
            self.y_q[i].clock.next = self.clock.val();
            self.sr_q[i].clock.next = self.clock.val();
            self.dxn_q[i].clock.next = self.clock.val();
            self.dyn_q[i].clock.next = self.clock.val();
        }
        for i in 1..9 {
            self.y_q[i].d.next = self.y_q[i - 1].q.val();
            self.sr_q[i].d.next = self.sr_q[i - 1].q.val();
            self.dxn_q[i].d.next = self.dxn_q[i - 1].q.val();
            self.dyn_q[i].d.next = self.dyn_q[i - 1].q.val();
        }
        self.x_t.next = self.x_q[9].q.val();
        self.dx_mag_t.next = self.dxm_q[9].q.val();
        self.dy_mag_t.next = self.dym_q[9].q.val();
        // The slice-edge tests of the 2x2 selection, from the control at T-1.
        self.nx_last.d.next = self.dims.val().get_bits::<16>(0) - 1;
        self.ny_last.d.next = self.dims.val().get_bits::<16>(16) - 1;
        self.x_out.next = false;
        if self.dxm_q[8].q.val() != 0 {
            if self.dxn_q[8].q.val() {
                self.x_out.next = self.x_q[8].q.val() == self.nx_last.q.val();
            } else {
                self.x_out.next = self.x_q[8].q.val() == 0;
            }
        }
        self.y_out.next = false;
        if self.dym_q[8].q.val() != 0 {
            if self.dyn_q[8].q.val() {
                self.y_out.next = self.y_q[8].q.val() == self.ny_last.q.val();
            } else {
                self.y_out.next = self.y_q[8].q.val() == 0;
            }
        }
        // The selection's flags (`Select2x2`'s bits 0 to 6), from the
        // control at T-1, into each channel's copy.
        self.dx_nz.next = self.dxm_q[8].q.val() != 0;
        self.dy_nz.next = self.dym_q[8].q.val() != 0;
        self.sel.next = bit_cast::<7, 1>(self.sr_q[8].q.val().into())
            | (bit_cast::<7, 1>(self.dxn_q[8].q.val().into()) << 1)
            | (bit_cast::<7, 1>(self.dx_nz.val().into()) << 2)
            | (bit_cast::<7, 1>(self.dyn_q[8].q.val().into()) << 3)
            | (bit_cast::<7, 1>(self.dy_nz.val().into()) << 4)
            | (bit_cast::<7, 1>(self.x_out.val().into()) << 5)
            | (bit_cast::<7, 1>(self.y_out.val().into()) << 6);
        for ch in 0..4 {
            self.sel_q[ch].clock.next = self.clock.val();
            self.sel_q[ch].d.next = self.sel.val();
            self.sel_t[ch].next = self.sel_q[ch].q.val();
        }
        // The input -> the result.
        self.v_q[0].d.next = self.valid.val();
        self.er_q[0].d.next = self.er.val();
        self.pad_q[0].d.next = self.pad.val();
        self.bx_q[0].d.next = self.base_x.val() & self.coord_mask.val();
        self.by_q[0].d.next = self.base_y.val() & self.coord_mask.val();
        self.face_q[0].d.next = self.face.val();
        for i in 1..21 {
            self.v_q[i].d.next = self.v_q[i - 1].q.val();
            self.er_q[i].d.next = self.er_q[i - 1].q.val();
            self.pad_q[i].d.next = self.pad_q[i - 1].q.val();
            self.bx_q[i].d.next = self.bx_q[i - 1].q.val();
            self.by_q[i].d.next = self.by_q[i - 1].q.val();
            self.face_q[i].d.next = self.face_q[i - 1].q.val();
        }
        self.res_beat.next = self.v_q[20].q.val();
        self.res_valid.next = self.v_q[20].q.val() & !self.pad_q[20].q.val();
        self.px_valid.next = self.v_q[20].q.val() & self.er_q[20].q.val() & !self.pad_q[20].q.val();
        self.px_x.next = self.bx_q[20].q.val();
        self.px_y.next = self.by_q[20].q.val();
        self.px_face.next = self.face_q[20].q.val();
    }
}
