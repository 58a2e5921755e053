//! ABC gradient estimation of Cube-4L (§3.2, Figs. 8-17): central
//! differences at voxel positions, bit for bit as
//! `golden_model::cube4l::gradient::central_difference`, with only nearest-neighbour
//! links between pipelines.
//!
//! The gradient of slice z needs slice z+1, so the unit emits voxel t (with
//! all its CFB control) one slice later, `S + 1` clocks after the CFB did,
//! when the ahead (A) slice is streaming. Each pipeline keeps the behind (B)
//! and current (C) slices in ring buffers of block RAM. By the skew the six
//! neighbours of voxel (x, y, z) of lane k at beat t are:
//!
//! | neighbour | lane | beat |
//! |---|---|---|
//! | x+1 / x-1 | k+1 / k-1 | t + [x mod P = P-1] / t - [x mod P = 0] |
//! | y+1 / y-1 | k+1 / k-1 | t + B / t - B |
//! | z+1 / z-1 | k+1 / k-1 | t + S (the A slice, live from the CFB) / t - S |
//!
//! Every one is one link away. The x neighbours across a partial-beam end
//! come one beat early or late, from a register beside the tap (the
//! extension units of Figs. 14-15). This is the small-buffer variant of Fig.
//! 17: two slices buffered per pipeline and six voxel links (three each way)
//! instead of Fig. 16's four slices and two links. Voxels with a neighbour
//! outside the dataset (`at_edge`) get garbage gradients and are made
//! transparent by the shader, as in the golden model.

use crate::ram::DepthRam;
use rust_hdl::prelude::*;

/// One pipeline's gradient unit; `H` ring-buffer address bits (>= 2S + B + 4).
#[derive(LogicBlock)]
pub struct AbcGradient<const H: usize> {
    pub clock: Signal<In, Clock>,
    pub now: Signal<In, Bits<H>>,
    /// The CFB lane's beat.
    pub valid: Signal<In, Bit>,
    pub value: Signal<In, Bits<16>>,
    pub x: Signal<In, Bits<16>>,
    pub y: Signal<In, Bits<16>>,
    pub pad: Signal<In, Bit>,
    pub invalid: Signal<In, Bit>,
    pub dx_neg: Signal<In, Bit>,
    pub dx_mag: Signal<In, Bits<16>>,
    pub dy_neg: Signal<In, Bit>,
    pub dy_mag: Signal<In, Bits<16>>,
    pub sr: Signal<In, Bit>,
    pub er: Signal<In, Bit>,
    pub at_edge: Signal<In, Bit>,
    pub face: Signal<In, Bits<3>>,
    pub base_x: Signal<In, Bits<16>>,
    pub base_y: Signal<In, Bits<16>>,
    /// Neighbour links: from lane k-1 (its x-1, y-1, z-1 taps) ...
    pub from_left_xm: Signal<In, Bits<16>>,
    pub from_left_ym: Signal<In, Bits<16>>,
    pub from_left_zm: Signal<In, Bits<16>>,
    /// ... and from lane k+1 (its x+1, y+1 taps and its live voxel).
    pub from_right_xp: Signal<In, Bits<16>>,
    pub from_right_yp: Signal<In, Bits<16>>,
    pub from_right_zp: Signal<In, Bits<16>>,
    /// What this lane sends: to lane k+1 ...
    pub to_right_xm: Signal<Out, Bits<16>>,
    pub to_right_ym: Signal<Out, Bits<16>>,
    pub to_right_zm: Signal<Out, Bits<16>>,
    /// ... and to lane k-1.
    pub to_left_xp: Signal<Out, Bits<16>>,
    pub to_left_yp: Signal<Out, Bits<16>>,
    pub to_left_zp: Signal<Out, Bits<16>>,
    /// The delayed voxel, its control, and its gradient (sign and magnitude).
    pub o_valid: Signal<Out, Bit>,
    pub o_value: Signal<Out, Bits<16>>,
    pub o_x: Signal<Out, Bits<16>>,
    pub o_y: Signal<Out, Bits<16>>,
    pub o_pad: Signal<Out, Bit>,
    pub o_invalid: Signal<Out, Bit>,
    pub o_dx_neg: Signal<Out, Bit>,
    pub o_dx_mag: Signal<Out, Bits<16>>,
    pub o_dy_neg: Signal<Out, Bit>,
    pub o_dy_mag: Signal<Out, Bits<16>>,
    pub o_sr: Signal<Out, Bit>,
    pub o_er: Signal<Out, Bit>,
    pub o_edge: Signal<Out, Bit>,
    pub o_face: Signal<Out, Bits<3>>,
    pub o_base_x: Signal<Out, Bits<16>>,
    pub o_base_y: Signal<Out, Bits<16>>,
    pub gx_neg: Signal<Out, Bit>,
    pub gx_mag: Signal<Out, Bits<16>>,
    pub gy_neg: Signal<Out, Bit>,
    pub gy_mag: Signal<Out, Bits<16>>,
    pub gz_neg: Signal<Out, Bit>,
    pub gz_mag: Signal<Out, Bits<16>>,
    centre: DepthRam<Bits<123>, H>,
    ring_xm: DepthRam<Bits<16>, H>,
    ring_ym: DepthRam<Bits<16>, H>,
    ring_zm: DepthRam<Bits<16>, H>,
    ring_xp: DepthRam<Bits<16>, H>,
    ring_yp: DepthRam<Bits<16>, H>,
    hop_xm: DFF<Bits<16>>,
    hop_ym: DFF<Bits<16>>,
    hop_zm: DFF<Bits<16>>,
    hop_xp: DFF<Bits<16>>,
    hop_yp: DFF<Bits<16>>,
    hop_zp: DFF<Bits<16>>,
    prev_xm: DFF<Bits<16>>,
    prev_xp: DFF<Bits<16>>,
    word: Signal<Local, Bits<123>>,
    xm: Signal<Local, Bits<16>>,
    xp: Signal<Local, Bits<16>>,
    off_centre: Constant<Bits<H>>,
    off_xm: Constant<Bits<H>>,
    off_ym: Constant<Bits<H>>,
    off_zm: Constant<Bits<H>>,
    off_xp: Constant<Bits<H>>,
    off_yp: Constant<Bits<H>>,
    p_mask: Constant<Bits<16>>,
    enabled: Constant<Bit>,
}

impl<const H: usize> AbcGradient<H> {
    /// Address bits of the B/C-slice rings: they hold the longest delay,
    /// two slices and a beam, with a margin of 8.
    pub fn ring_bits(s: u32, b: u32) -> usize {
        crate::cfb::bits_for((2 * s + b + 9) as u64) as usize
    }

    /// `s` beats per slice, `b` per beam, `p` pipelines, voxels of
    /// `voxel_bits`. Without `enabled` (a scene without gradients) the rings
    /// are 2-word stubs.
    pub fn new(s: u32, b: u32, p: u32, voxel_bits: u32, enabled: bool) -> AbcGradient<H> {
        let ring = |bits: usize| {
            DepthRam::new(bits).fields(
                &[(0, voxel_bits as usize)],
                ((1u64 << voxel_bits) - 1).to_bits(),
            )
        };
        let bits = if enabled {
            Self::ring_bits(s, b).min(H)
        } else {
            1
        };
        let mask = (1i64 << H) - 1;
        // Read address = now + hops + 1 - delay, delays relative to the output
        // stage, which is S + 1 clocks after the CFB.
        let off =
            |hops: i64, delay: i64| Constant::new((((hops + 1 - delay) & mask) as u64).to_bits());
        let (s, b) = (s as i64, b as i64);
        AbcGradient {
            clock: Default::default(),
            now: Default::default(),
            valid: Default::default(),
            value: Default::default(),
            x: Default::default(),
            y: Default::default(),
            pad: Default::default(),
            invalid: Default::default(),
            dx_neg: Default::default(),
            dx_mag: Default::default(),
            dy_neg: Default::default(),
            dy_mag: Default::default(),
            sr: Default::default(),
            er: Default::default(),
            at_edge: Default::default(),
            face: Default::default(),
            base_x: Default::default(),
            base_y: Default::default(),
            from_left_xm: Default::default(),
            from_left_ym: Default::default(),
            from_left_zm: Default::default(),
            from_right_xp: Default::default(),
            from_right_yp: Default::default(),
            from_right_zp: Default::default(),
            to_right_xm: Default::default(),
            to_right_ym: Default::default(),
            to_right_zm: Default::default(),
            to_left_xp: Default::default(),
            to_left_yp: Default::default(),
            to_left_zp: Default::default(),
            o_valid: Default::default(),
            o_value: Default::default(),
            o_x: Default::default(),
            o_y: Default::default(),
            o_pad: Default::default(),
            o_invalid: Default::default(),
            o_dx_neg: Default::default(),
            o_dx_mag: Default::default(),
            o_dy_neg: Default::default(),
            o_dy_mag: Default::default(),
            o_sr: Default::default(),
            o_er: Default::default(),
            o_edge: Default::default(),
            o_face: Default::default(),
            o_base_x: Default::default(),
            o_base_y: Default::default(),
            gx_neg: Default::default(),
            gx_mag: Default::default(),
            gy_neg: Default::default(),
            gy_mag: Default::default(),
            gz_neg: Default::default(),
            gz_mag: Default::default(),
            centre: DepthRam::new(bits),
            ring_xm: ring(bits),
            ring_ym: ring(bits),
            ring_zm: ring(bits),
            ring_xp: ring(bits),
            ring_yp: ring(bits),
            hop_xm: Default::default(),
            hop_ym: Default::default(),
            hop_zm: Default::default(),
            hop_xp: Default::default(),
            hop_yp: Default::default(),
            hop_zp: Default::default(),
            prev_xm: Default::default(),
            prev_xp: Default::default(),
            word: Default::default(),
            xm: Default::default(),
            xp: Default::default(),
            off_centre: off(0, s + 1),
            off_xm: off(1, s + 1),
            off_ym: off(1, s + 1 + b),
            off_zm: off(1, 2 * s + 1),
            off_xp: off(1, s),
            off_yp: off(1, s + 1 - b),
            p_mask: Constant::new(((p - 1) as u64).to_bits()),
            enabled: Constant::new(enabled),
        }
    }
}

impl<const H: usize> Logic for AbcGradient<H> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, hop_xm, hop_ym, hop_zm, hop_xp, hop_yp, hop_zp, prev_xm, prev_xp);
        self.centre.read_clock.next = self.clock.val();
        self.centre.write_clock.next = self.clock.val();
        self.ring_xm.read_clock.next = self.clock.val();
        self.ring_xm.write_clock.next = self.clock.val();
        self.ring_ym.read_clock.next = self.clock.val();
        self.ring_ym.write_clock.next = self.clock.val();
        self.ring_zm.read_clock.next = self.clock.val();
        self.ring_zm.write_clock.next = self.clock.val();
        self.ring_xp.read_clock.next = self.clock.val();
        self.ring_xp.write_clock.next = self.clock.val();
        self.ring_yp.read_clock.next = self.clock.val();
        self.ring_yp.write_clock.next = self.clock.val();
        // Every CFB clock goes into the rings at address `now` (the B and C
        // slices); the centre word carries the voxel with its control.
        self.word.next = bit_cast::<123, 16>(self.value.val())
            | (bit_cast::<123, 16>(self.x.val()) << 16)
            | (bit_cast::<123, 16>(self.y.val()) << 32)
            | (bit_cast::<123, 16>(self.base_x.val()) << 48)
            | (bit_cast::<123, 16>(self.base_y.val()) << 64)
            | (bit_cast::<123, 1>(self.valid.val().into()) << 80)
            | (bit_cast::<123, 1>(self.pad.val().into()) << 81)
            | (bit_cast::<123, 1>(self.sr.val().into()) << 82)
            | (bit_cast::<123, 1>(self.er.val().into()) << 83)
            | (bit_cast::<123, 1>(self.at_edge.val().into()) << 84)
            | (bit_cast::<123, 3>(self.face.val()) << 85)
            | (bit_cast::<123, 1>(self.dx_neg.val().into()) << 88)
            | (bit_cast::<123, 16>(self.dx_mag.val()) << 89)
            | (bit_cast::<123, 1>(self.dy_neg.val().into()) << 105)
            | (bit_cast::<123, 16>(self.dy_mag.val()) << 106)
            | (bit_cast::<123, 1>(self.invalid.val().into()) << 122);
        self.centre.write_address.next = self.now.val();
        self.centre.write_data.next = self.word.val();
        self.centre.write_enable.next = true;
        self.ring_xm.write_address.next = self.now.val();
        self.ring_xm.write_data.next = self.value.val();
        self.ring_xm.write_enable.next = true;
        self.ring_ym.write_address.next = self.now.val();
        self.ring_ym.write_data.next = self.value.val();
        self.ring_ym.write_enable.next = true;
        self.ring_zm.write_address.next = self.now.val();
        self.ring_zm.write_data.next = self.value.val();
        self.ring_zm.write_enable.next = true;
        self.ring_xp.write_address.next = self.now.val();
        self.ring_xp.write_data.next = self.value.val();
        self.ring_xp.write_enable.next = true;
        self.ring_yp.write_address.next = self.now.val();
        self.ring_yp.write_data.next = self.value.val();
        self.ring_yp.write_enable.next = true;
        // Taps, read so that they line up S + 1 clocks after the CFB.
        self.centre.read_address.next = self.now.val() + self.off_centre.val();
        self.ring_xm.read_address.next = self.now.val() + self.off_xm.val();
        self.ring_ym.read_address.next = self.now.val() + self.off_ym.val();
        self.ring_zm.read_address.next = self.now.val() + self.off_zm.val();
        self.ring_xp.read_address.next = self.now.val() + self.off_xp.val();
        self.ring_yp.read_address.next = self.now.val() + self.off_yp.val();
        self.to_right_xm.next = self.ring_xm.read_data.val();
        self.to_right_ym.next = self.ring_ym.read_data.val();
        self.to_right_zm.next = self.ring_zm.read_data.val();
        self.to_left_xp.next = self.ring_xp.read_data.val();
        self.to_left_yp.next = self.ring_yp.read_data.val();
        self.to_left_zp.next = self.value.val();
        // One register per link.
        self.hop_xm.d.next = self.from_left_xm.val();
        self.hop_ym.d.next = self.from_left_ym.val();
        self.hop_zm.d.next = self.from_left_zm.val();
        self.hop_xp.d.next = self.from_right_xp.val();
        self.hop_yp.d.next = self.from_right_yp.val();
        self.hop_zp.d.next = self.from_right_zp.val();
        self.prev_xm.d.next = self.hop_xm.q.val();
        self.prev_xp.d.next = self.hop_xp.q.val();
        // Partial-beam ends: x-1 of a partial beam's first voxel is one beat
        // older, x+1 of its last voxel one beat newer.
        self.xm.next = self.hop_xm.q.val();
        if (self.centre.read_data.val().get_bits::<16>(16) & self.p_mask.val()) == 0 {
            self.xm.next = self.prev_xm.q.val();
        }
        self.xp.next = self.prev_xp.q.val();
        if (self.centre.read_data.val().get_bits::<16>(16) & self.p_mask.val()) == self.p_mask.val()
        {
            self.xp.next = self.hop_xp.q.val();
        }
        // Central differences as sign and magnitude.
        self.gx_neg.next = self.xp.val() < self.xm.val();
        self.gx_mag.next = self.xp.val() - self.xm.val();
        if self.xp.val() < self.xm.val() {
            self.gx_mag.next = self.xm.val() - self.xp.val();
        }
        self.gy_neg.next = self.hop_yp.q.val() < self.hop_ym.q.val();
        self.gy_mag.next = self.hop_yp.q.val() - self.hop_ym.q.val();
        if self.hop_yp.q.val() < self.hop_ym.q.val() {
            self.gy_mag.next = self.hop_ym.q.val() - self.hop_yp.q.val();
        }
        self.gz_neg.next = self.hop_zp.q.val() < self.hop_zm.q.val();
        self.gz_mag.next = self.hop_zp.q.val() - self.hop_zm.q.val();
        if self.hop_zp.q.val() < self.hop_zm.q.val() {
            self.gz_mag.next = self.hop_zm.q.val() - self.hop_zp.q.val();
        }
        // The delayed voxel and its control.
        self.o_value.next = self.centre.read_data.val().get_bits::<16>(0);
        self.o_x.next = self.centre.read_data.val().get_bits::<16>(16);
        self.o_y.next = self.centre.read_data.val().get_bits::<16>(32);
        self.o_base_x.next = self.centre.read_data.val().get_bits::<16>(48);
        self.o_base_y.next = self.centre.read_data.val().get_bits::<16>(64);
        self.o_valid.next = self.centre.read_data.val().get_bit(80);
        self.o_pad.next = self.centre.read_data.val().get_bit(81);
        self.o_sr.next = self.centre.read_data.val().get_bit(82);
        self.o_er.next = self.centre.read_data.val().get_bit(83);
        self.o_edge.next = self.centre.read_data.val().get_bit(84);
        self.o_face.next = self.centre.read_data.val().get_bits::<3>(85);
        self.o_dx_neg.next = self.centre.read_data.val().get_bit(88);
        self.o_dx_mag.next = self.centre.read_data.val().get_bits::<16>(89);
        self.o_dy_neg.next = self.centre.read_data.val().get_bit(105);
        self.o_dy_mag.next = self.centre.read_data.val().get_bits::<16>(106);
        self.o_invalid.next = self.centre.read_data.val().get_bit(122);
        // Left out of the scene's hardware (see `export::prune`): every
        // output is zero, as in the emitted Verilog, which has no unit.
        if !self.enabled.val() {
            self.to_right_xm.next = 0.into();
            self.to_right_ym.next = 0.into();
            self.to_right_zm.next = 0.into();
            self.to_left_xp.next = 0.into();
            self.to_left_yp.next = 0.into();
            self.to_left_zp.next = 0.into();
            self.o_value.next = 0.into();
            self.o_x.next = 0.into();
            self.o_y.next = 0.into();
            self.o_dx_mag.next = 0.into();
            self.o_dy_mag.next = 0.into();
            self.o_base_x.next = 0.into();
            self.o_base_y.next = 0.into();
            self.gx_mag.next = 0.into();
            self.gy_mag.next = 0.into();
            self.gz_mag.next = 0.into();
            self.o_valid.next = false;
            self.o_pad.next = false;
            self.o_invalid.next = false;
            self.o_dx_neg.next = false;
            self.o_dy_neg.next = false;
            self.o_sr.next = false;
            self.o_er.next = false;
            self.o_edge.next = false;
            self.gx_neg.next = false;
            self.gy_neg.next = false;
            self.gz_neg.next = false;
            self.o_face.next = 0.into();
        }
    }
}
