//! A constant table whose depth is chosen when the design is built, not by
//! its address type: rust-hdl's `ROM` (a combinational read, a `case` in
//! Verilog) that decodes only the low `bits` address bits and lists only
//! the words given. The lighting's tables are as deep as the scene's normal
//! width needs (`hardware.normal_bits`), behind addresses as wide as the
//! widest normal's; hence this widget, with its own Verilog.

use super::ram::bits_for;
use rust_hdl::prelude::*;

/// `2^bits` words of `D` (those past the words given read 0) behind an
/// `N`-bit address, of which the low `bits` are decoded.
#[derive(LogicBlock)]
pub struct DepthRom<D: Synth, const N: usize> {
    pub address: Signal<In, Bits<N>>,
    pub data: Signal<Out, D>,
    // Fields starting with `_` are not signals or blocks to rust-hdl.
    _bits: usize,
    _words: Vec<D>,
}

impl<D: Synth, const N: usize> DepthRom<D, N> {
    /// The table of `words` (2 to `2^N` of them), decoded by the low
    /// `bits_for(words.len())` address bits.
    pub fn new(words: Vec<D>) -> Self {
        let bits = bits_for(words.len() as u64) as usize;
        assert!(
            words.len() >= 2 && bits <= N,
            "a {N}-bit address holds 2 to 2^{N} words, not {}",
            words.len()
        );
        DepthRom {
            address: Default::default(),
            data: Default::default(),
            _bits: bits,
            _words: words,
        }
    }
}

impl<D: Synth, const N: usize> Logic for DepthRom<D, N> {
    fn update(&mut self) {
        let i = self.address.val().index() & ((1 << self._bits) - 1);
        self.data.next = self._words.get(i).copied().unwrap_or_default();
    }

    fn connect(&mut self) {
        self.data.connect();
    }

    fn hdl(&self) -> Verilog {
        let cases: Vec<String> = self
            ._words
            .iter()
            .enumerate()
            .map(|(i, w)| format!("  {}'d{i}: data = {};", self._bits, w.verilog()))
            .collect();
        Verilog::Custom(format!(
            "\
always @*
case (address[{msb}:0])
{cases}
  default: data = {default};
endcase
",
            msb = self._bits - 1,
            cases = cases.join("\n"),
            default = D::default().verilog(),
        ))
    }
}
