//! The counters' lead of a perspective Cube-4L CFB (§3.1): the sight-ray
//! [`super::divider`] takes the counters N_s, N_B and N_b as they are issued
//! and answers [`super::divider::LATENCY`] clocks later, so the address
//! pipeline and the control take them [`LEAD`] clocks after issue, and the
//! control meets the divider's answer. A shift register of `LEAD` stages
//! for the counters and the running bit, which a reset clears. Only
//! perspective builds instantiate it.

use super::cfb_stages::{ADDRESS_STAGES, READ_STAGES};
use super::divider;
use rust_hdl::prelude::*;

/// Clocks from issue to the address pipeline: the divider's latency less
/// the address stages and the memory read's clocks before the one the
/// control is computed in, beside the read's last register.
pub const LEAD: usize = divider::LATENCY - ADDRESS_STAGES - (READ_STAGES - 1);
// `hdl_gen` needs literal loop bounds: `update` is written for 18 stages.
const _: () = assert!(LEAD == 18, "update the literals in CounterLead");

#[derive(LogicBlock)]
pub struct CounterLead {
    pub clock: Signal<In, Clock>,
    /// Synchronous reset: no beat leaves the lead afterwards.
    pub reset: Signal<In, Bit>,
    pub running: Signal<In, Bit>,
    pub n_s: Signal<In, Bits<16>>,
    pub n_beam: Signal<In, Bits<16>>,
    pub n_b: Signal<In, Bits<16>>,
    /// The same, `LEAD` clocks later.
    pub running_out: Signal<Out, Bit>,
    pub n_s_out: Signal<Out, Bits<16>>,
    pub n_beam_out: Signal<Out, Bits<16>>,
    pub n_b_out: Signal<Out, Bits<16>>,
    /// A beat is in the lead.
    pub busy: Signal<Out, Bit>,
    run_q: [DFF<Bit>; LEAD],
    ns_q: [DFF<Bits<16>>; LEAD],
    nbeam_q: [DFF<Bits<16>>; LEAD],
    nb_q: [DFF<Bits<16>>; LEAD],
    enabled: Constant<Bit>,
}

impl CounterLead {
    /// Without `enabled` (parallel views) the outputs are zero, as in the
    /// emitted Verilog, which leaves the lead out (`export::prune`).
    pub fn new(enabled: bool) -> CounterLead {
        CounterLead {
            clock: Default::default(),
            reset: Default::default(),
            running: Default::default(),
            n_s: Default::default(),
            n_beam: Default::default(),
            n_b: Default::default(),
            running_out: Default::default(),
            n_s_out: Default::default(),
            n_beam_out: Default::default(),
            n_b_out: Default::default(),
            busy: Default::default(),
            run_q: Default::default(),
            ns_q: Default::default(),
            nbeam_q: Default::default(),
            nb_q: Default::default(),
            enabled: Constant::new(enabled),
        }
    }
}

impl Logic for CounterLead {
    #[hdl_gen]
    fn update(&mut self) {
        for i in 0..18 {
            self.run_q[i].clock.next = self.clock.val();
            self.ns_q[i].clock.next = self.clock.val();
            self.nbeam_q[i].clock.next = self.clock.val();
            self.nb_q[i].clock.next = self.clock.val();
        }
        self.run_q[0].d.next = self.running.val();
        self.ns_q[0].d.next = self.n_s.val();
        self.nbeam_q[0].d.next = self.n_beam.val();
        self.nb_q[0].d.next = self.n_b.val();
        for i in 1..18 {
            self.run_q[i].d.next = self.run_q[i - 1].q.val();
            self.ns_q[i].d.next = self.ns_q[i - 1].q.val();
            self.nbeam_q[i].d.next = self.nbeam_q[i - 1].q.val();
            self.nb_q[i].d.next = self.nb_q[i - 1].q.val();
        }
        self.busy.next = self.running.val()
            | self.run_q[0].q.val()
            | self.run_q[1].q.val()
            | self.run_q[2].q.val()
            | self.run_q[3].q.val()
            | self.run_q[4].q.val()
            | self.run_q[5].q.val()
            | self.run_q[6].q.val()
            | self.run_q[7].q.val()
            | self.run_q[8].q.val()
            | self.run_q[9].q.val()
            | self.run_q[10].q.val()
            | self.run_q[11].q.val()
            | self.run_q[12].q.val()
            | self.run_q[13].q.val()
            | self.run_q[14].q.val()
            | self.run_q[15].q.val()
            | self.run_q[16].q.val()
            | self.run_q[17].q.val();
        if self.reset.val() {
            for i in 0..18 {
                self.run_q[i].d.next = false;
            }
        }
        self.running_out.next = self.run_q[17].q.val();
        self.n_s_out.next = self.ns_q[17].q.val();
        self.n_beam_out.next = self.nbeam_q[17].q.val();
        self.n_b_out.next = self.nb_q[17].q.val();
        if !self.enabled.val() {
            self.running_out.next = false;
            self.n_s_out.next = 0.into();
            self.n_beam_out.next = 0.into();
            self.n_b_out.next = 0.into();
            self.busy.next = false;
        }
    }
}
