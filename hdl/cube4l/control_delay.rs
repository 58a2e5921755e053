//! The control delay line of a Cube-4L pipeline (§3.5-3.7, Fig. 18): a
//! beat's control travels beside its voxel, from the shader input (T-1) to
//! the taps, the 2x2 selection and the bilinear unit (T) and on to the
//! compositor's result (T+L+1, L the bilinear unit's latency), where it
//! marks the result and, on ER, makes it a base-plane pixel; the shaded
//! sample waits for the bilinear unit (T -> T+L).

use super::bilinear::LATENCY;
use rust_hdl::prelude::*;

/// Registers from the shader input to the result (T-1 -> T+L+1).
const CONTROL: usize = LATENCY + 2;
// `hdl_gen` needs literal loop bounds and indices: the update below is
// written for L = 5.
const _: () = assert!(
    LATENCY == 5 && CONTROL == 7,
    "update the literals in ControlDelay::update"
);

/// Control and sample registers of one lane.
#[derive(LogicBlock, Default)]
pub struct ControlDelay {
    pub clock: Signal<In, Clock>,
    /// The beat's control at the shader input (T-1).
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
    /// The shader's sample (T).
    pub r: Signal<In, Bits<16>>,
    pub g: Signal<In, Bits<16>>,
    pub b: Signal<In, Bits<16>>,
    pub a: Signal<In, Bits<16>>,
    pub sample_valid: Signal<In, Bit>,
    /// At T: the voxel's position, SR, dx and dy.
    pub x_t: Signal<Out, Bits<16>>,
    pub y_t: Signal<Out, Bits<16>>,
    pub sr_t: Signal<Out, Bit>,
    pub dx_neg_t: Signal<Out, Bit>,
    pub dx_mag_t: Signal<Out, Bits<16>>,
    pub dy_neg_t: Signal<Out, Bit>,
    pub dy_mag_t: Signal<Out, Bits<16>>,
    /// The sample at T+L, as the compositor takes it.
    pub new_r: Signal<Out, Bits<16>>,
    pub new_g: Signal<Out, Bits<16>>,
    pub new_b: Signal<Out, Bits<16>>,
    pub new_a: Signal<Out, Bits<16>>,
    pub new_valid: Signal<Out, Bit>,
    /// At T+L+1, beside the composited value: a beat, one that is not
    /// padding, and the base-plane pixel on ER.
    pub res_beat: Signal<Out, Bit>,
    pub res_valid: Signal<Out, Bit>,
    pub px_valid: Signal<Out, Bit>,
    pub px_x: Signal<Out, Bits<16>>,
    pub px_y: Signal<Out, Bits<16>>,
    pub px_face: Signal<Out, Bits<3>>,
    // Control from T-1 to T, and on to T+L+1.
    x_q: DFF<Bits<16>>,
    y_q: DFF<Bits<16>>,
    sr_q: DFF<Bit>,
    dxn_q: DFF<Bit>,
    dxm_q: DFF<Bits<16>>,
    dyn_q: DFF<Bit>,
    dym_q: DFF<Bits<16>>,
    v_q: [DFF<Bit>; CONTROL],
    er_q: [DFF<Bit>; CONTROL],
    pad_q: [DFF<Bit>; CONTROL],
    bx_q: [DFF<Bits<16>>; CONTROL],
    by_q: [DFF<Bits<16>>; CONTROL],
    face_q: [DFF<Bits<3>>; CONTROL],
    // The sample from T to T+L.
    s_r: [DFF<Bits<16>>; LATENCY],
    s_g: [DFF<Bits<16>>; LATENCY],
    s_b: [DFF<Bits<16>>; LATENCY],
    s_a: [DFF<Bits<16>>; LATENCY],
    s_v: [DFF<Bit>; LATENCY],
}

impl Logic for ControlDelay {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, x_q, y_q, sr_q, dxn_q, dxm_q, dyn_q, dym_q);
        for i in 0..7 {
            self.v_q[i].clock.next = self.clock.val();
            self.er_q[i].clock.next = self.clock.val();
            self.pad_q[i].clock.next = self.clock.val();
            self.bx_q[i].clock.next = self.clock.val();
            self.by_q[i].clock.next = self.clock.val();
            self.face_q[i].clock.next = self.clock.val();
        }
        for i in 0..5 {
            self.s_r[i].clock.next = self.clock.val();
            self.s_g[i].clock.next = self.clock.val();
            self.s_b[i].clock.next = self.clock.val();
            self.s_a[i].clock.next = self.clock.val();
            self.s_v[i].clock.next = self.clock.val();
        }
        // T-1 -> T.
        self.x_q.d.next = self.x.val();
        self.y_q.d.next = self.y.val();
        self.sr_q.d.next = self.sr.val();
        self.dxn_q.d.next = self.dx_neg.val();
        self.dxm_q.d.next = self.dx_mag.val();
        self.dyn_q.d.next = self.dy_neg.val();
        self.dym_q.d.next = self.dy_mag.val();
        self.x_t.next = self.x_q.q.val();
        self.y_t.next = self.y_q.q.val();
        self.sr_t.next = self.sr_q.q.val();
        self.dx_neg_t.next = self.dxn_q.q.val();
        self.dx_mag_t.next = self.dxm_q.q.val();
        self.dy_neg_t.next = self.dyn_q.q.val();
        self.dy_mag_t.next = self.dym_q.q.val();
        // T-1 -> T+L+1.
        self.v_q[0].d.next = self.valid.val();
        self.er_q[0].d.next = self.er.val();
        self.pad_q[0].d.next = self.pad.val();
        self.bx_q[0].d.next = self.base_x.val();
        self.by_q[0].d.next = self.base_y.val();
        self.face_q[0].d.next = self.face.val();
        for i in 1..7 {
            self.v_q[i].d.next = self.v_q[i - 1].q.val();
            self.er_q[i].d.next = self.er_q[i - 1].q.val();
            self.pad_q[i].d.next = self.pad_q[i - 1].q.val();
            self.bx_q[i].d.next = self.bx_q[i - 1].q.val();
            self.by_q[i].d.next = self.by_q[i - 1].q.val();
            self.face_q[i].d.next = self.face_q[i - 1].q.val();
        }
        self.res_beat.next = self.v_q[6].q.val();
        self.res_valid.next = self.v_q[6].q.val() & !self.pad_q[6].q.val();
        self.px_valid.next = self.v_q[6].q.val() & self.er_q[6].q.val() & !self.pad_q[6].q.val();
        self.px_x.next = self.bx_q[6].q.val();
        self.px_y.next = self.by_q[6].q.val();
        self.px_face.next = self.face_q[6].q.val();
        // The sample, T -> T+L.
        self.s_r[0].d.next = self.r.val();
        self.s_g[0].d.next = self.g.val();
        self.s_b[0].d.next = self.b.val();
        self.s_a[0].d.next = self.a.val();
        self.s_v[0].d.next = self.sample_valid.val();
        for i in 1..5 {
            self.s_r[i].d.next = self.s_r[i - 1].q.val();
            self.s_g[i].d.next = self.s_g[i - 1].q.val();
            self.s_b[i].d.next = self.s_b[i - 1].q.val();
            self.s_a[i].d.next = self.s_a[i - 1].q.val();
            self.s_v[i].d.next = self.s_v[i - 1].q.val();
        }
        self.new_r.next = self.s_r[4].q.val();
        self.new_g.next = self.s_g[4].q.val();
        self.new_b.next = self.s_b[4].q.val();
        self.new_a.next = self.s_a[4].q.val();
        self.new_valid.next = self.s_v[4].q.val();
    }
}
