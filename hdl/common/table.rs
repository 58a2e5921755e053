//! A lookup table the host loads between frames (`golden_model::host`): a
//! block RAM of up to `2^N` words of `W` bits with a registered read, whose
//! write port takes every host write in its window `base .. base + 2^N`, so
//! one write loads every copy of the table at once. For simulation it can
//! start with contents ([`Table::preload`]), as a block RAM's initialisation.

use super::ram::DepthRam;
use super::regs::ADDRESS_BITS;
use rust_hdl::prelude::*;

/// A table of `W`-bit words, `N` address bits, at a host window.
#[derive(LogicBlock)]
pub struct Table<const W: usize, const N: usize> {
    pub clock: Signal<In, Clock>,
    pub host_write: Signal<In, Bit>,
    pub host_address: Signal<In, Bits<ADDRESS_BITS>>,
    pub host_data: Signal<In, Bits<64>>,
    /// The entry read, and its word one clock later.
    pub address: Signal<In, Bits<N>>,
    pub data: Signal<Out, Bits<W>>,
    ram: DepthRam<Bits<W>, N>,
    base: Constant<Bits<ADDRESS_BITS>>,
    window: Constant<Bits<ADDRESS_BITS>>,
}

impl<const W: usize, const N: usize> Table<W, N> {
    /// `words` words (at least 2, at most `2^N`) storing the bit fields
    /// `(lowest bit, width)` of each word, loaded from host address `base`.
    pub fn new(base: u32, words: usize, fields: &[(usize, usize)]) -> Self {
        let words = words.max(2);
        assert!(
            words <= 1 << N,
            "a table of {words} words in {N} address bits"
        );
        let mask = fields
            .iter()
            .fold(0u64, |m, &(lo, w)| m | (((1u128 << w) - 1) as u64) << lo)
            .to_bits();
        Table {
            clock: Default::default(),
            host_write: Default::default(),
            host_address: Default::default(),
            host_data: Default::default(),
            address: Default::default(),
            data: Default::default(),
            ram: DepthRam::with_words(words).fields(fields, mask),
            base: Constant::new((base as u64).to_bits()),
            window: Constant::new(((base as u64) + (1u64 << N)).to_bits()),
        }
    }

    /// Initial contents from entry 0 (simulation; a block RAM's
    /// initialisation).
    pub fn preload(&mut self, words: impl IntoIterator<Item = u64>) {
        self.ram.preload(words.into_iter().map(|w| w.to_bits()));
    }

    /// Bits of storage.
    pub fn memory_bits(&self) -> usize {
        self.ram.depth() * self.ram.word_bits()
    }
}

impl<const W: usize, const N: usize> Logic for Table<W, N> {
    #[hdl_gen]
    fn update(&mut self) {
        self.ram.read_clock.next = self.clock.val();
        self.ram.write_clock.next = self.clock.val();
        self.ram.write_enable.next = self.host_write.val()
            & (self.host_address.val() >= self.base.val())
            & (self.host_address.val() < self.window.val());
        self.ram.write_address.next =
            bit_cast::<N, ADDRESS_BITS>(self.host_address.val() - self.base.val());
        self.ram.write_data.next = bit_cast::<W, 64>(self.host_data.val());
        self.ram.read_address.next = self.address.val();
        self.data.next = self.ram.read_data.val();
    }
}
