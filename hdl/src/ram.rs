//! A block RAM whose depth is chosen when the design is built, not by its
//! address type: the ring buffers and memory modules take the pipeline's
//! `N`-bit addresses and keep `2^bits` words, using the low `bits` address
//! bits, so that each scene's hardware holds only the words it needs.
//!
//! The ports and timing are those of rust-hdl's `RAM` (a registered read, a
//! write on the clock edge), which fixes the depth at `2^N`; hence this
//! widget, with its own Verilog.

use rust_hdl::core::timing::TimingInfo;
use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct DepthRam<D: Synth, const N: usize> {
    pub read_address: Signal<In, Bits<N>>,
    pub read_clock: Signal<In, Clock>,
    pub read_data: Signal<Out, D>,
    pub write_address: Signal<In, Bits<N>>,
    pub write_clock: Signal<In, Clock>,
    pub write_data: Signal<In, D>,
    pub write_enable: Signal<In, bool>,
    // Fields starting with `_` are not signals or blocks to rust-hdl.
    _bits: usize,
    _words: Vec<D>,
    /// Words given at build time (block-RAM initialisation).
    _init: usize,
}

impl<D: Synth, const N: usize> DepthRam<D, N> {
    /// `2^bits` words (1 <= bits <= N), all zero.
    pub fn new(bits: usize) -> Self {
        assert!(
            (1..=N).contains(&bits),
            "a {N}-bit address holds 1 to {N} address bits, not {bits}"
        );
        DepthRam {
            read_address: Default::default(),
            read_clock: Default::default(),
            read_data: Default::default(),
            write_address: Default::default(),
            write_clock: Default::default(),
            write_data: Default::default(),
            write_enable: Default::default(),
            _bits: bits,
            _words: vec![D::default(); 1 << bits],
            _init: 0,
        }
    }

    /// Initial contents, from word 0 (at most `2^bits` words).
    pub fn preload(&mut self, words: impl IntoIterator<Item = D>) {
        self._words.fill(D::default());
        let mut n = 0;
        for (slot, w) in self._words.iter_mut().zip(words) {
            *slot = w;
            n += 1;
        }
        self._init = n;
    }

    fn index(&self, address: Bits<N>) -> usize {
        (address.index()) & ((1 << self._bits) - 1)
    }
}

impl<D: Synth, const N: usize> Logic for DepthRam<D, N> {
    fn update(&mut self) {
        if self.read_clock.pos_edge() {
            self.read_data.next = self._words[self.index(self.read_address.val())];
        }
        if self.write_clock.pos_edge() && self.write_enable.val() {
            let i = self.index(self.write_address.val());
            self._words[i] = self.write_data.val();
        }
    }

    fn connect(&mut self) {
        self.read_data.connect();
    }

    fn hdl(&self) -> Verilog {
        let init = if self._init > 0 {
            let lines: Vec<String> = self._words[..self._init]
                .iter()
                .enumerate()
                .map(|(i, w)| format!("   mem[{i}] = {};", w.verilog()))
                .collect();
            format!("initial begin\n{}\nend\n", lines.join("\n"))
        } else {
            String::new()
        };
        let msb = self._bits - 1;
        Verilog::Custom(format!(
            "\
reg [{d}:0] mem[{last}:0];
{init}
always @(posedge read_clock) begin
   read_data <= mem[read_address[{msb}:0]];
end

always @(posedge write_clock) begin
   if (write_enable) begin
      mem[write_address[{msb}:0]] <= write_data;
   end
end
",
            d = D::BITS - 1,
            last = (1usize << self._bits) - 1,
        ))
    }

    fn timing(&self) -> Vec<TimingInfo> {
        vec![
            TimingInfo {
                name: "ram_read".into(),
                clock: "read_clock".into(),
                inputs: vec!["read_address".into()],
                outputs: vec!["read_data".into()],
            },
            TimingInfo {
                name: "ram_write".into(),
                clock: "write_clock".into(),
                inputs: vec![
                    "write_address".into(),
                    "write_data".into(),
                    "write_enable".into(),
                ],
                outputs: vec![],
            },
        ]
    }
}
