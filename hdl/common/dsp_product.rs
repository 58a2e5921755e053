//! A 16x16 product into a register: `p = a * b` a clock after `a` and
//! `b`, the same as a `DFF` whose D input is the product, written so that
//! an ECP5 build puts the register inside the multiplier.
//!
//! Hand-written Verilog: yosys maps a product to an ECP5 `MULT18X18D` but
//! never packs a register into it, so a product register is a fabric
//! flip-flop, and the route from the multiplier's column to it lies in the
//! same clock as the multiply (`A`/`B` to `P` is 3.07 ns at speed 8; the
//! shaded 256³ build's critical path was such a route, 5.22 of its 8.68 ns
//! routing). With `CUBE_ECP5_DSP` defined (`cube synth --target ecp5`
//! defines it) the module is a `MULT18X18D` with its output register
//! (`REG_OUTPUT_CLK = "CLK0"`; 2.64 ns from `A`/`B` to it, 0.58 ns from
//! the clock to `P`); without it, and in every simulator, a behavioural
//! register of the same product, bit for bit. Both start at zero (the
//! primitive's register is cleared at configuration).
//!
//! A product the build does not read is built [`DspProduct::new`]`(false)`:
//! its output is zero and no multiplier is instantiated (synthesis removes
//! an unread behavioural multiply, never an unread primitive).

use rust_hdl::prelude::*;

/// A registered 16x16 product, in the multiplier's own output register on
/// an ECP5.
#[derive(Clone, Debug, LogicBlock)]
pub struct DspProduct {
    pub clock: Signal<In, Clock>,
    pub a: Signal<In, Bits<16>>,
    pub b: Signal<In, Bits<16>>,
    /// `a * b` of the clock before.
    pub p: Signal<Out, Bits<32>>,
    _used: bool,
}

impl Default for DspProduct {
    fn default() -> DspProduct {
        DspProduct::new(true)
    }
}

impl DspProduct {
    /// A product the build reads when `used`; otherwise zero, and no
    /// multiplier.
    pub fn new(used: bool) -> DspProduct {
        DspProduct {
            clock: Default::default(),
            a: Default::default(),
            b: Default::default(),
            p: Default::default(),
            _used: used,
        }
    }
}

/// `.X0(v[0]), .X1(v[1]), ...` for `n` bits of port group `X`.
fn bits(port: char, n: usize, value: impl Fn(usize) -> String) -> String {
    (0..n)
        .map(|i| format!(".{port}{i}({})", value(i)))
        .collect::<Vec<_>>()
        .join(", ")
}

impl Logic for DspProduct {
    fn update(&mut self) {
        if self.clock.pos_edge() {
            self.p.next = if self._used {
                self.a.val() * self.b.val()
            } else {
                0.into()
            };
        }
    }
    fn connect(&mut self) {
        self.p.connect();
    }
    fn hdl(&self) -> Verilog {
        if !self._used {
            // A constant register: synthesis removes it.
            return Verilog::Custom(
                "initial begin\n   p = 32'h0;\nend\n\nalways @(posedge clock) begin\n   p <= 32'h0;\nend\n"
                    .into(),
            );
        }
        let operand = |port| {
            bits(port, 18, |i| {
                if i < 16 {
                    format!("{}[{i}]", port.to_ascii_lowercase())
                } else {
                    "1'b0".into()
                }
            })
        };
        Verilog::Custom(format!(
            "\
`ifdef CUBE_ECP5_DSP
wire [35:0] product;
MULT18X18D #(
   .REG_INPUTA_CLK(\"NONE\"), .REG_INPUTB_CLK(\"NONE\"), .REG_PIPELINE_CLK(\"NONE\"),
   .REG_OUTPUT_CLK(\"CLK0\"), .REG_OUTPUT_CE(\"CE0\"), .REG_OUTPUT_RST(\"RST0\")
) mult (
   {},
   {},
   {},
   .SIGNEDA(1'b0), .SIGNEDB(1'b0), .SOURCEA(1'b0), .SOURCEB(1'b0),
   .CLK0(clock), .CE0(1'b1), .RST0(1'b0),
   {}
);
always @(*) begin
   p = product[31:0];
end
`else
initial begin
   p = 32'h0;
end

always @(posedge clock) begin
   p <= a * b;
end
`endif
",
            operand('A'),
            operand('B'),
            bits('C', 18, |_| "1'b0".into()),
            bits('P', 36, |i| format!("product[{i}]")),
        ))
    }
    fn timing(&self) -> Vec<TimingInfo> {
        vec![TimingInfo {
            name: "dsp_product".into(),
            clock: "clock".into(),
            inputs: vec!["a".into(), "b".into()],
            outputs: vec!["p".into()],
        }]
    }
}
