//! A view table the host loads between frames (`golden_model::host`):
//! `words` words of `W` bits read *asynchronously*, as the ROMs of a
//! design built for one view were, so that the stages reading it keep
//! their timing. It is distributed (LUT) RAM, not block RAM: the view
//! tables are a few entries a plane or a ray (Cube-3's templates, bounds
//! and increments), and a registered read would move every address a
//! clock earlier. (Cube-3's de-fanning group and row tables, thousands of
//! words, are block RAM: [`super::table::Table`], addressed a clock
//! ahead.)
//!
//! The write port takes every host write in its window `base .. base +
//! words` (aligned to its depth); reads use the low `bits_for(words)` address bits (the depth is
//! a power of two, so every address reads a written word or zero, the same
//! in Rust and in Verilog). The Verilog is written here: rust-hdl's `RAM`
//! has a registered read and its `ROM` no write port.

use super::ram::bits_for;
use super::regs::ADDRESS_BITS;
use rust_hdl::core::timing::TimingInfo;
use rust_hdl::prelude::*;

/// A host-loaded table of `W`-bit words with an `N`-bit read address.
#[derive(LogicBlock)]
pub struct ViewRom<const W: usize, const N: usize> {
    pub clock: Signal<In, Clock>,
    pub host_write: Signal<In, Bit>,
    pub host_address: Signal<In, Bits<ADDRESS_BITS>>,
    pub host_data: Signal<In, Bits<64>>,
    /// The entry read, and its word in the same clock.
    pub address: Signal<In, Bits<N>>,
    pub data: Signal<Out, Bits<W>>,
    // Fields starting with `_` are not signals or blocks to rust-hdl.
    _base: u32,
    _bits: usize,
    _words: Vec<Bits<W>>,
}

impl<const W: usize, const N: usize> ViewRom<W, N> {
    /// At least `words` words (rounded up to a power of two, at most
    /// `2^N`), loaded from host address `base`.
    pub fn new(base: u32, words: usize) -> Self {
        let bits = bits_for(words.max(2) as u64) as usize;
        assert!(
            bits <= N,
            "a view table of {words} words in {N} address bits"
        );
        assert_eq!(base % (1 << bits), 0, "a view table's window is aligned");
        ViewRom {
            clock: Default::default(),
            host_write: Default::default(),
            host_address: Default::default(),
            host_data: Default::default(),
            address: Default::default(),
            data: Default::default(),
            _base: base,
            _bits: bits,
            _words: vec![Bits::default(); 1 << bits],
        }
    }

    /// Words of storage.
    pub fn depth(&self) -> usize {
        self._words.len()
    }

    fn slot(&self, address: u64) -> usize {
        (address as usize) & ((1 << self._bits) - 1)
    }
}

impl<const W: usize, const N: usize> Logic for ViewRom<W, N> {
    fn update(&mut self) {
        if self.clock.pos_edge() && self.host_write.val() {
            let a = self.host_address.val().index() as u64;
            let base = self._base as u64;
            if a >= base && a < base + self._words.len() as u64 {
                let i = self.slot(a);
                self._words[i] = self.host_data.val().get_bits::<W>(0);
            }
        }
        let i = self.slot(self.address.val().index() as u64);
        self.data.next = self._words[i];
    }

    fn connect(&mut self) {
        self.data.connect();
    }

    fn hdl(&self) -> Verilog {
        let (msb, last, w) = (self._bits - 1, self._words.len() - 1, W - 1);
        let (base, end) = (self._base, self._base as usize + self._words.len());
        Verilog::Custom(format!(
            "\
reg [{w}:0] mem[{last}:0];
integer i;
initial begin
   for (i = 0; i <= {last}; i = i + 1) mem[i] = {W}'d0;
end

always @(*) data = mem[address[{msb}:0]];

always @(posedge clock) begin
   if (host_write && host_address >= {ADDRESS_BITS}'d{base} && host_address < {ADDRESS_BITS}'d{end}) begin
      mem[host_address[{msb}:0]] <= host_data[{w}:0];
   end
end
",
        ))
    }

    fn timing(&self) -> Vec<TimingInfo> {
        vec![TimingInfo {
            name: "view_rom_write".into(),
            clock: "clock".into(),
            inputs: vec![
                "host_write".into(),
                "host_address".into(),
                "host_data".into(),
            ],
            outputs: vec![],
        }]
    }
}
