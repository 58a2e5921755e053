//! A [`DelayLine`] read through a register at each of its block RAMs (the
//! beam- and slice-length delays of §3.5-3.7 and Fig. 21's SFG, as Cube-4L's
//! compositing buffer and gradient unit keep them). Each bank of the line's
//! memory ([`DepthRam::bank_registers`]) ends in a flip-flop that can sit
//! beside its block RAM, and the bank is chosen after those flip-flops. A
//! [`super::registered_line::RegisteredLine`] ends in one register after
//! the memory's depth selection instead, so the block RAMs' read data must
//! cross the part to reach it: an ECP5 DP16KD's clock-to-out (about 4.3 ns
//! without its output register) and that routing (about 5 ns) were the
//! 256³ builds' critical path, at 101 MHz.
//!
//! A delay of L >= 4 is a ring of L - 2 words whose read takes three
//! clocks: the block RAM's, a register beside it and a second beside the
//! logic the word feeds ([`DepthRam::relay`]), so the same L clocks as a
//! `RegisteredLine` in a word less of memory. Its pointers are a pipeline
//! of registers: `head` steps around the ring, the
//! read address is `head` one clock later (one step ahead of the write),
//! and the write address the read address one clock later. The memory's
//! addresses come straight from flip-flops that may sit among the block
//! RAMs, while the ring's own loop (`head`, its increment and its wrap)
//! drives nothing else and stays compact: with the read address in the
//! loop, the loop followed it to the RAMs and was the shaded 256³ build's
//! critical path (10 cells, 1.84 ns logic and 7.87 ns routing). The
//! pointers settle three clocks after reset. The lengths 1 to 3 are a
//! register, `short`, fed from `data_in` or from one or two registers
//! before it.
//! With a gap in `write_enable` the output at t is still `data_in` of
//! t - L whenever clock t - L wrote, as in a `RegisteredLine`.
//!
//! The pointer's bound `L - 3` and the flags for the short lengths come from
//! registers, one clock after `last` (the users' `last` is a register the
//! view's `Beats` set between sweeps). Only that flag selects after the
//! banks' registers, where a `DelayLine`'s own length-1 selection would add
//! its compare of `last` (yosys merges the lanes' equal `last` registers,
//! so that compare's inputs come from across the part).
//!
//! [`DepthRam::bank_registers`]: super::ram::DepthRam::bank_registers
//! [`DepthRam::relay`]: super::ram::DepthRam::relay
//! [`DelayLine`]: super::delay_line::DelayLine

use super::lane_copy::LaneCopy;
use super::ram::DepthRam;
use rust_hdl::prelude::*;

/// A delay of up to `longest` clocks with an `N`-bit pointer, read through
/// a register at each block RAM.
#[derive(LogicBlock)]
pub struct BankedLine<D: Synth + std::ops::BitAnd<Output = D>, const N: usize> {
    pub clock: Signal<In, Clock>,
    pub data_in: Signal<In, D>,
    pub write_enable: Signal<In, Bit>,
    pub data_out: Signal<Out, D>,
    /// The delay less one, at most the longest less one.
    pub last: Signal<In, Bits<N>>,
    ram: DepthRam<D, N>,
    /// The ring's last slot, `last - 2`: the line's own register (every
    /// lane's lines have the same), as are the short lengths' flags.
    bound: LaneCopy<Bits<N>>,
    /// The ring's pointer, the read address (`head` one clock later) and
    /// the write address (the read address one clock later).
    head: DFF<Bits<N>>,
    rd: DFF<Bits<N>>,
    ptr: DFF<Bits<N>>,
    next: Signal<Local, Bits<N>>,
    /// The built ring's last slot: the pointer's bound.
    longest_last: Constant<Bits<N>>,
    /// Built for 4 or more (a line built for 3 or less is `short` alone).
    has_ring: Constant<Bit>,
    /// The delays of 1 to 3: `short` takes `data_in` (1), `one`, the last
    /// word written (2), or `two`, `one` a clock later (3); `is_short`,
    /// `is_one` and `is_two` say which `last` asks for.
    one: DFF<D>,
    two: DFF<D>,
    short: DFF<D>,
    is_short: LaneCopy<Bit>,
    is_one: LaneCopy<Bit>,
    is_two: LaneCopy<Bit>,
    mask: Constant<D>,
}

impl<D: Synth + std::ops::BitAnd<Output = D>, const N: usize> BankedLine<D, N> {
    /// A delay of up to `longest` clocks (1 <= longest < 2^N) storing
    /// `fields` of each word, as [`super::delay_line::DelayLine::new`].
    pub fn new(longest: usize, fields: &[(usize, usize)], mask: D) -> Self {
        assert!(
            longest >= 1 && longest < 1 << N,
            "a delay line with an {N}-bit pointer is 1 to 2^{N} - 1 clocks long, not {longest}"
        );
        // A ring of L - 2 words; a line built for 3 or less needs none (a
        // 2-word stub).
        let words = (longest.max(4) - 2).max(2);
        BankedLine {
            clock: Default::default(),
            data_in: Default::default(),
            write_enable: Default::default(),
            data_out: Default::default(),
            last: Default::default(),
            ram: DepthRam::with_words(words)
                .fields(fields, mask)
                .bank_registers()
                .relay(),
            bound: Default::default(),
            head: Default::default(),
            rd: Default::default(),
            ptr: Default::default(),
            next: Default::default(),
            longest_last: Constant::new(((words - 1) as u64).to_bits()),
            has_ring: Constant::new(longest >= 4),
            one: Default::default(),
            two: Default::default(),
            short: Default::default(),
            is_short: Default::default(),
            is_one: Default::default(),
            is_two: Default::default(),
            mask: Constant::new(mask),
        }
    }

    /// Bits of storage in memory (the registers not counted).
    pub fn memory_bits(&self) -> usize {
        if !self.has_ring.val() {
            0
        } else {
            self.ram.depth() * self.ram.word_bits()
        }
    }
}

impl<D: Synth + std::ops::BitAnd<Output = D>, const N: usize> Logic for BankedLine<D, N> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, bound, head, rd, ptr, one, two, short, is_short, is_one, is_two);
        self.ram.read_clock.next = self.clock.val();
        self.ram.write_clock.next = self.clock.val();
        self.bound.d.next = self.last.val() - 2;
        self.is_short.d.next = self.last.val() < 3;
        self.is_one.d.next = self.last.val() == 0;
        self.is_two.d.next = self.last.val() == 1;
        // The ring: the read address one step ahead of the write address.
        self.next.next = self.head.q.val() + 1;
        if (self.head.q.val() >= self.bound.q.val())
            | (self.head.q.val() >= self.longest_last.val())
        {
            self.next.next = 0.into();
        }
        self.head.d.next = self.next.val();
        self.rd.d.next = self.head.q.val();
        self.ptr.d.next = self.rd.q.val();
        self.ram.write_address.next = self.ptr.q.val();
        self.ram.write_data.next = self.data_in.val();
        self.ram.write_enable.next = self.write_enable.val() & self.has_ring.val();
        self.ram.read_address.next = self.rd.q.val();
        // The short lengths.
        self.one.d.next = self.one.q.val();
        if self.write_enable.val() {
            self.one.d.next = self.data_in.val() & self.mask.val();
        }
        self.two.d.next = self.one.q.val();
        self.short.d.next = self.two.q.val();
        if self.is_two.q.val() {
            self.short.d.next = self.one.q.val();
        }
        if self.is_one.q.val() {
            self.short.d.next = self.short.q.val();
            if self.write_enable.val() {
                self.short.d.next = self.data_in.val() & self.mask.val();
            }
        }
        self.data_out.next = self.ram.read_data.val();
        if self.is_short.q.val() | !self.has_ring.val() {
            self.data_out.next = self.short.q.val();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(LogicBlock)]
    struct Bench {
        clock: Signal<In, Clock>,
        data_in: Signal<In, Bits<16>>,
        write_enable: Signal<In, Bit>,
        last: Signal<In, Bits<16>>,
        data_out: Signal<Out, Bits<16>>,
        line: BankedLine<Bits<16>, 16>,
    }

    impl Logic for Bench {
        #[hdl_gen]
        fn update(&mut self) {
            self.line.clock.next = self.clock.val();
            self.line.last.next = self.last.val();
            self.line.data_in.next = self.data_in.val();
            self.line.write_enable.next = self.write_enable.val();
            self.data_out.next = self.line.data_out.val();
        }
    }

    /// Drive a pseudo-random stream with gaps in `write_enable` into a line
    /// built for `longest` and set to `length`: from the fourth clock on
    /// (the bound's register, then the pointers' pipeline), every output
    /// whose clock t - length wrote is that word.
    fn check(longest: usize, length: usize) {
        let mut uut = Bench {
            clock: Default::default(),
            data_in: Default::default(),
            write_enable: Default::default(),
            last: Default::default(),
            data_out: Default::default(),
            line: BankedLine::new(longest, &[(0, 12)], 0x0fffu64.to_bits()),
        };
        uut.connect_all();
        let clocks = length + 200;
        let mut sim = Simulation::new();
        sim.add_clock(5, |x: &mut Box<Bench>| x.clock.next = !x.clock.val());
        sim.add_testbench(move |mut sim: Sim<Bench>| {
            let mut x = sim.init()?;
            let mut written = Vec::new();
            let mut state = 12345u64;
            let mut checked = 0;
            for t in 0..clocks {
                state = state.wrapping_mul(6364136223846793005).wrapping_add(1);
                let word = (state >> 20) & 0xffff;
                let we = t % 7 != 3;
                x.data_in.next = word.to_bits();
                x.write_enable.next = we;
                x.last.next = ((length - 1) as u64).to_bits();
                x = sim.wait(10, x)?;
                written.push(we.then_some(word & 0x0fff));
                // After clock t: the word of clock t + 1 - length.
                if t + 1 >= length + 3 {
                    if let Some(expect) = written[t + 1 - length] {
                        sim_assert_eq!(sim, x.data_out.val(), expect.to_bits::<16>(), x);
                        checked += 1;
                    }
                }
            }
            sim_assert!(sim, checked > 120, x);
            sim.done(x)
        });
        sim.run(Box::new(uut), 10 * clocks as u64 + 100).unwrap();
    }

    #[test]
    fn output_is_the_input_length_clocks_back() {
        for length in [1, 2, 3, 4, 5, 7, 33] {
            check(length, length);
        }
        // Lines built longer, set shorter at run time.
        for (longest, length) in [
            (2, 1),
            (3, 1),
            (3, 2),
            (4, 3),
            (5, 4),
            (7, 1),
            (7, 2),
            (7, 3),
            (7, 4),
            (33, 20),
        ] {
            check(longest, length);
        }
    }

    /// A line deeper than one bank (16384 words): the bank chosen after
    /// the banks' registers.
    #[test]
    fn lines_of_several_banks() {
        check(20_000, 20_000);
        check(20_000, 16_385);
    }
}
