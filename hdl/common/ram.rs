//! A block RAM whose depth is chosen when the design is built, not by its
//! address type: the ring buffers and memory modules take the pipeline's
//! `N`-bit addresses and keep `2^bits` words, using the low `bits` address
//! bits, so that each scene's hardware holds only the words it needs.
//!
//! Words can be narrower than the data type too: with [`DepthRam::fields`]
//! only the given bit fields are stored (a compositing-buffer word holds
//! four `rgba_bits` channels in 16-bit slots, a voxel `voxel_bits` of 16),
//! and the others read as zero.
//!
//! The ports and timing are those of rust-hdl's `RAM` (a registered read, a
//! write on the clock edge), which fixes the depth at `2^N` and the width at
//! `D`; hence this widget, with its own Verilog. A memory of at most
//! [`DISTRIBUTED_WORDS`] words, or of at most [`DISTRIBUTED_BITS`] bits,
//! asks synthesis for LUT RAM.

use rust_hdl::core::timing::TimingInfo;
use rust_hdl::prelude::*;

#[derive(LogicBlock)]
pub struct DepthRam<D: Synth + std::ops::BitAnd<Output = D>, const N: usize> {
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
    /// Stored bit fields `(lowest bit, width)`, lowest first; every bit
    /// when empty. `_mask` has exactly their bits set.
    _fields: Vec<(usize, usize)>,
    _mask: Option<D>,
    /// Read in two clocks through banks of 2^[`BLOCK_BITS`] words, each with an
    /// output register of its own ([`DepthRam::bank_registers`]), or in
    /// three with a second register after it ([`DepthRam::relay`]); the
    /// words read a clock ago, and two, wait in `_stage`.
    _banked: bool,
    _relay: bool,
    _stage: [D; 2],
}

impl<D: Synth + std::ops::BitAnd<Output = D>, const N: usize> DepthRam<D, N> {
    /// `2^bits` words (1 <= bits <= N), all zero.
    pub fn new(bits: usize) -> Self {
        Self::with_words(1 << bits)
    }

    /// `words` words (2 <= words <= 2^N), all zero, addressed by the low
    /// `bits_for(words)` address bits; the addresses given must stay below
    /// `words` (a [`super::delay_line::DelayLine`]'s pointer wraps there).
    pub fn with_words(words: usize) -> Self {
        let bits = super::ram::bits_for(words as u64) as usize;
        assert!(
            words >= 2 && bits <= N,
            "a {N}-bit address holds 2 to 2^{N} words, not {words}"
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
            _words: vec![D::default(); words],
            _init: 0,
            _fields: Vec::new(),
            _mask: None,
            _banked: false,
            _relay: false,
            _stage: [D::default(); 2],
        }
    }

    /// Read in two clocks, not one: the memory is built as banks of
    /// 2^[`BLOCK_BITS`] words (an ECP5 DP16KD in its deepest shape holds
    /// that many 1-bit words, so a bank needs no depth cascade of its own),
    /// each bank's read word goes into a register of its own, and the bank
    /// is chosen after those registers. A block RAM's read then ends in a
    /// flip-flop that can sit beside it, with no selection or routing
    /// across the part in between: the DP16KD's own output register
    /// (`REGMODE = "OUTREG"`), built in the fabric because yosys does not
    /// set it. `read_data` is the registered words through the bank
    /// selection (a multiplexer after the registers, none with one bank).
    ///
    /// A banked memory's users never read the word written in the same
    /// clock (a [`super::banked_line::BankedLine`] reads one word ahead of
    /// its write; the CFB's voxel memory is written by the host's loads
    /// between sweeps, when no read is used), so its Verilog leaves a
    /// collision undefined (`(* no_rw_check *)`): otherwise yosys builds a
    /// bypass for it (the addresses compared, the written word registered,
    /// a LUT between each block RAM and its register; 30 LUT4 and 24
    /// flip-flops for four 16384x1 slices), and that shared compare pulled
    /// the bank registers away from their block RAMs (the shaded 256³
    /// build's path: a gradient line's DP16KD at row 82, its register at
    /// row 7).
    pub fn bank_registers(mut self) -> Self {
        self._banked = true;
        self
    }

    /// With [`DepthRam::bank_registers`]: a second register after each
    /// bank's, the bank chosen after it, so the read takes three clocks. The
    /// first register's only load is the second, so it sits beside its block
    /// RAM wherever the placer puts that RAM, and the second beside the
    /// logic the word feeds: with every DP16KD of a part in use, a line's
    /// block RAMs lie across the part, and a block RAM's clock-to-out
    /// (about 4.3 ns) and the route to a register beside the logic (3.6 ns
    /// from column 31 to 115) were the shaded 256³ build's critical path.
    pub fn relay(mut self) -> Self {
        assert!(self._banked, "a relay follows the bank registers");
        self._relay = true;
        self
    }

    /// Store only the bit fields `(lowest bit, width)` of each word; `mask`
    /// has exactly those bits set. Fields that cover the whole word change
    /// nothing.
    pub fn fields(mut self, fields: &[(usize, usize)], mask: D) -> Self {
        let mut f = fields.to_vec();
        f.sort_unstable();
        assert!(
            f.windows(2).all(|w| w[0].0 + w[0].1 <= w[1].0)
                && f.last().is_none_or(|&(lo, w)| w > 0 && lo + w <= D::BITS),
            "fields {f:?} overlap or exceed {} bits",
            D::BITS
        );
        if f.iter().map(|f| f.1).sum::<usize>() < D::BITS {
            self._fields = f;
            self._mask = Some(mask);
        }
        self
    }

    /// Bits stored per word.
    pub fn word_bits(&self) -> usize {
        if self._fields.is_empty() {
            D::BITS
        } else {
            self._fields.iter().map(|f| f.1).sum()
        }
    }

    /// Words of storage.
    pub fn depth(&self) -> usize {
        self._words.len()
    }

    /// Initial contents, from word 0 (at most `depth` words).
    pub fn preload(&mut self, words: impl IntoIterator<Item = D>) {
        self._words.fill(D::default());
        let mut n = 0;
        for (slot, w) in self._words.iter_mut().zip(words) {
            *slot = self._mask.map_or(w, |m| w & m);
            n += 1;
        }
        self._init = n;
    }

    fn index(&self, address: Bits<N>) -> usize {
        (address.index()) & ((1 << self._bits) - 1)
    }
}

impl<D: Synth + std::ops::BitAnd<Output = D>, const N: usize> Logic for DepthRam<D, N> {
    fn update(&mut self) {
        if self.read_clock.pos_edge() {
            let word = self._words[self.index(self.read_address.val())];
            if self._relay {
                self.read_data.next = self._stage[1];
                self._stage = [word, self._stage[0]];
            } else if self._banked {
                self.read_data.next = self._stage[0];
                self._stage[0] = word;
            } else {
                self.read_data.next = word;
            }
        }
        if self.write_clock.pos_edge() && self.write_enable.val() {
            let i = self.index(self.write_address.val());
            let w = self.write_data.val();
            self._words[i] = self._mask.map_or(w, |m| w & m);
        }
    }

    fn connect(&mut self) {
        self.read_data.connect();
    }

    fn hdl(&self) -> Verilog {
        let msb = self._bits - 1;
        // The stored word of `w`: its fields, the highest first.
        let stored = |w: &str| -> String {
            if self._fields.is_empty() {
                return w.to_string();
            }
            let parts: Vec<String> = self
                ._fields
                .iter()
                .rev()
                .map(|&(lo, width)| format!("{w}[{}:{lo}]", lo + width - 1))
                .collect();
            format!("{{{}}}", parts.join(", "))
        };
        // The data word of a stored word `s`: its fields in place, zeros
        // between them.
        let expand = |s: &str| -> String {
            if self._fields.is_empty() {
                return s.to_string();
            }
            let mut read = Vec::new();
            let (mut top, mut offset) = (D::BITS, self.word_bits());
            for &(lo, w) in self._fields.iter().rev() {
                if top > lo + w {
                    read.push(format!("{}'d0", top - lo - w));
                }
                read.push(format!("{s}[{}:{}]", offset - 1, offset - w));
                offset -= w;
                top = lo;
            }
            if top > 0 {
                read.push(format!("{top}'d0"));
            }
            format!("{{{}}}", read.join(", "))
        };
        // Banks of `bank_words`, the last one shorter: one bank unless
        // `bank_registers` asked for them.
        let words = self._words.len();
        let bank_bits = if self._banked {
            BLOCK_BITS.min(self._bits)
        } else {
            self._bits
        };
        let bank_words = 1usize << bank_bits;
        let banks = words.div_ceil(bank_words);
        // A short or small memory is LUT RAM: a block RAM for 64 words, or
        // for a 256-entry table of 8-bit words, would waste most of its 18
        // Kbit (yosys picks block RAM for wide ones).
        let style = if words <= DISTRIBUTED_WORDS || words * self.word_bits() <= DISTRIBUTED_BITS {
            "(* ram_style = \"distributed\" *)\n"
        } else {
            ""
        };
        let d = self.word_bits() - 1;
        let low = format!("[{}:0]", bank_bits - 1);
        // Each bank in slices of the word as wide as one block RAM is at
        // the bank's depth (a DP16KD holds 16384x1, 8192x2, 4096x4, 2048x9,
        // 1024x18 or 512x36), so that every slice is one block RAM with no
        // selection of its own before the bank's register.
        let deepest = bank_words.min(words);
        let slice = if !style.is_empty() {
            d + 1
        } else {
            match deepest {
                0..=512 => 36,
                513..=1024 => 18,
                1025..=2048 => 9,
                2049..=4096 => 4,
                4097..=8192 => 2,
                _ => 1,
            }
        };
        let slices: Vec<(usize, usize)> = (0..=d)
            .step_by(slice)
            .map(|lo| (lo, (lo + slice - 1).min(d)))
            .collect();
        // Initial contents of bank `b`'s word `i`, slice by slice.
        let init_slices = |b: usize, i: usize| -> String {
            slices
                .iter()
                .enumerate()
                .map(|(j, &(lo, hi))| format!("   mem_{b}_{j}[{i}] = init_stored[{hi}:{lo}];\n"))
                .collect()
        };
        let init = if self._init > 0 {
            let lines: Vec<String> = self._words[..self._init]
                .iter()
                .enumerate()
                .map(|(i, w)| {
                    let word = format!("   init_word = {}'({});\n", D::BITS, w.verilog());
                    if self._banked {
                        format!(
                            "{word}   init_stored = {};\n{}",
                            stored("init_word"),
                            init_slices(i / bank_words, i % bank_words)
                        )
                    } else {
                        format!("{word}   mem[{i}] = {};", stored("init_word"))
                    }
                })
                .collect();
            let stored_reg = if self._banked {
                format!("reg [{d}:0] init_stored;\n")
            } else {
                String::new()
            };
            format!(
                "reg [{}:0] init_word;\n{stored_reg}initial begin\n{}\nend\n",
                D::BITS - 1,
                lines.join("\n")
            )
        } else {
            String::new()
        };
        if !self._banked {
            return Verilog::Custom(format!(
                "\
{style}reg [{d}:0] mem[{last}:0];
{init}
always @(posedge read_clock) begin
   read_data <= {read};
end

always @(posedge write_clock) begin
   if (write_enable) begin
      mem[write_address{low}] <= {stored};
   end
end
",
                last = words - 1,
                read = expand(&format!("mem[read_address{low}]")),
                stored = stored("write_data"),
            ));
        }
        let mut decl = format!("wire [{d}:0] stored_word = {};\n", stored("write_data"));
        // The registers the banks are chosen from.
        let out = if self._relay { "r" } else { "q" };
        let mut reads = String::new();
        let mut writes = String::new();
        let mut choose = String::new();
        for b in 0..banks {
            let depth = bank_words.min(words - b * bank_words);
            for (j, &(lo, hi)) in slices.iter().enumerate() {
                decl += &format!(
                    "{style}(* no_rw_check *)\nreg [{}:0] mem_{b}_{j}[{}:0];\n",
                    hi - lo,
                    depth - 1
                );
                reads += &format!("   rd_{b}[{hi}:{lo}] <= mem_{b}_{j}[read_address{low}];\n");
            }
            decl += &format!("reg [{d}:0] rd_{b};\nreg [{d}:0] q_{b};\n");
            reads += &format!("   q_{b} <= rd_{b};\n");
            if self._relay {
                decl += &format!("reg [{d}:0] r_{b};\n");
                reads += &format!("   r_{b} <= q_{b};\n");
            }
            let hit = if banks > 1 {
                format!(" && write_address[{msb}:{bank_bits}] == {b}")
            } else {
                String::new()
            };
            let stores: String = slices
                .iter()
                .enumerate()
                .map(|(j, &(lo, hi))| {
                    format!("      mem_{b}_{j}[write_address{low}] <= stored_word[{hi}:{lo}];\n")
                })
                .collect();
            writes += &format!("   if (write_enable{hit}) begin\n{stores}   end\n");
            choose += &format!(
                "      {b}: read_data = {};\n",
                expand(&format!("{out}_{b}"))
            );
        }
        let select = if banks > 1 {
            let s = self._bits - bank_bits - 1;
            decl += &format!("reg [{s}:0] sel_1;\nreg [{s}:0] sel_2;\n");
            reads += &format!("   sel_1 <= read_address[{msb}:{bank_bits}];\n   sel_2 <= sel_1;\n");
            let sel = if self._relay {
                decl += &format!("reg [{s}:0] sel_3;\n");
                reads += "   sel_3 <= sel_2;\n";
                "sel_3"
            } else {
                "sel_2"
            };
            format!(
                "always @(*) begin\n   case ({sel})\n{choose}      default: read_data = {};\n   endcase\nend\n",
                expand(&format!("{out}_0"))
            )
        } else {
            format!(
                "always @(*) begin\n   read_data = {};\nend\n",
                expand(&format!("{out}_0"))
            )
        };
        Verilog::Custom(format!(
            "\
{decl}{init}
always @(posedge read_clock) begin
{reads}end

always @(posedge write_clock) begin
{writes}end

{select}"
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

/// Address bits of a bank of [`DepthRam::bank_registers`]: 16384 words,
/// an ECP5 DP16KD's depth in its 1-bit shape.
pub const BLOCK_BITS: usize = 14;

/// Memories of at most this many words are built as LUT RAM.
pub const DISTRIBUTED_WORDS: usize = 64;

/// ... and memories of at most this many bits: an eighth of an ECP5 block
/// RAM's 18 Kbit or less (about 100 LUT4 for 256 words of 8 bits).
pub const DISTRIBUTED_BITS: usize = 2048;

/// Address bits of an on-chip memory module: 2^16 words. Larger voxel
/// memories are external RAM.
pub const ON_CHIP_BITS: usize = 16;

/// Address bits for `n` words (at least 1).
pub fn bits_for(n: u64) -> u32 {
    (64 - n.saturating_sub(1).leading_zeros()).max(1)
}
