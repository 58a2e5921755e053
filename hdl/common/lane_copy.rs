//! A lane's own register of a value that holds for a frame: a view
//! register's field, or a value derived from such a copy a clock later
//! (`docs/registers.md` says when the lanes first read them), or a
//! datapath's own copy of an operand several datapaths share (the bilinear
//! unit's weights, one copy a channel).
//!
//! Hand-written Verilog, a plain register but for `(* keep *)` on its
//! always block: every lane's copy has the same D input, and yosys merges
//! equal registers into one, which then drives all the lanes across the
//! part (the shaded 256³ build's critical paths ran from such merged
//! registers, their routing three quarters of the path). Kept apart, each
//! copy is placed by its lane; only its D input, constant during a sweep,
//! crosses the part.

use rust_hdl::prelude::*;

/// A register that synthesis keeps as its own, never merged with an equal one.
#[derive(Clone, Debug, LogicBlock)]
pub struct LaneCopy<T: Synth> {
    pub d: Signal<In, T>,
    pub q: Signal<Out, T>,
    pub clock: Signal<In, Clock>,
    /// `(* keep *)` is emitted: false for a copy the build does not read
    /// (a parallel view's increments in a perspective build), which
    /// synthesis then removes as it would a plain register.
    _keep: bool,
}

impl<T: Synth> Default for LaneCopy<T> {
    fn default() -> LaneCopy<T> {
        LaneCopy::new(true)
    }
}

impl<T: Synth> LaneCopy<T> {
    /// A copy kept apart when `used`; otherwise a plain register, left for
    /// synthesis to remove.
    pub fn new(used: bool) -> LaneCopy<T> {
        LaneCopy {
            d: Default::default(),
            q: Default::default(),
            clock: Default::default(),
            _keep: used,
        }
    }
}

impl<T: Synth> Logic for LaneCopy<T> {
    fn update(&mut self) {
        if self.clock.pos_edge() {
            self.q.next = self.d.val();
        }
    }
    fn connect(&mut self) {
        self.q.connect();
    }
    fn hdl(&self) -> Verilog {
        Verilog::Custom(format!(
            "\
initial begin
   q = {:x};
end

{}always @(posedge clock) begin
   q <= d;
end
",
            T::default().verilog(),
            if self._keep { "(* keep *)\n" } else { "" }
        ))
    }
    fn timing(&self) -> Vec<TimingInfo> {
        vec![TimingInfo {
            name: "lane_copy".into(),
            clock: "clock".into(),
            inputs: vec!["d".into()],
            outputs: vec!["q".into()],
        }]
    }
}
