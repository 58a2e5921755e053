//! A delay line of block RAM (the beam- and slice-length delays of §3.5-3.7
//! and Fig. 21's SFG): `data_out` at clock t is `data_in` of clock t - L,
//! for a length L from 1 to the longest the line is built for, set at run
//! time through `last` (L - 1: the view's slice and beam lengths are
//! registers the host writes). The line holds the words of its longest
//! delay, not the next power of two.
//!
//! A pointer counts 0..L-1 and wraps (and never passes the built length,
//! whatever `last` says); each clock the word at the pointer is
//! written and the word after it, the oldest, is read (a registered read).
//! The read pointer is a register of its own, one step ahead, and the write
//! pointer takes its value a clock later: the memory's read address comes
//! straight from a flip-flop, with no increment or wrap compare before the
//! memory (the shaded 256³ build's critical path ran through them).
//! A length of 1 is the register `one` beside the RAM (where the two
//! addresses would meet and the read would take the old word); a line
//! built for a length of 1 is that register alone. Without `write_enable` the slot
//! keeps its older word, as a ring buffer addressed by time does. Words can
//! store only some bit fields, as [`DepthRam::fields`].

use super::ram::DepthRam;
use rust_hdl::prelude::*;

/// A delay of `length` clocks with an `N`-bit pointer.
#[derive(LogicBlock)]
pub struct DelayLine<D: Synth + std::ops::BitAnd<Output = D>, const N: usize> {
    pub clock: Signal<In, Clock>,
    pub data_in: Signal<In, D>,
    pub write_enable: Signal<In, Bit>,
    pub data_out: Signal<Out, D>,
    /// The delay less one, at most the longest less one.
    pub last: Signal<In, Bits<N>>,
    ram: DepthRam<D, N>,
    /// The write pointer, and the read pointer (one step ahead) held as
    /// `rd ^ 1`, so that from the all-zero start it reads slot 1 while
    /// slot 0 is written.
    ptr: DFF<Bits<N>>,
    rd_flipped: DFF<Bits<N>>,
    rd: Signal<Local, Bits<N>>,
    next: Signal<Local, Bits<N>>,
    flip: Constant<Bits<N>>,
    /// The built length less one: the pointer's bound.
    longest_last: Constant<Bits<N>>,
    /// Built for a length of 1: the register `one` instead of the RAM (a
    /// 2-word stub). `one` also serves a longer line set to a length of 1.
    single: Constant<Bit>,
    one: DFF<D>,
    mask: Constant<D>,
}

impl<D: Synth + std::ops::BitAnd<Output = D>, const N: usize> DelayLine<D, N> {
    /// A delay of up to `longest` clocks (1 <= longest < 2^N) storing
    /// `fields` of each word; `mask` has exactly their bits (every bit when
    /// `fields` is empty).
    pub fn new(longest: usize, fields: &[(usize, usize)], mask: D) -> Self {
        assert!(
            longest >= 1 && longest < 1 << N,
            "a delay line with an {N}-bit pointer is 1 to 2^{N} - 1 clocks long, not {longest}"
        );
        let words = longest.max(2);
        DelayLine {
            clock: Default::default(),
            data_in: Default::default(),
            write_enable: Default::default(),
            data_out: Default::default(),
            last: Default::default(),
            ram: DepthRam::with_words(words).fields(fields, mask),
            ptr: Default::default(),
            rd_flipped: Default::default(),
            rd: Default::default(),
            next: Default::default(),
            flip: Constant::new(1u64.to_bits()),
            longest_last: Constant::new(((words - 1) as u64).to_bits()),
            single: Constant::new(longest == 1),
            one: Default::default(),
            mask: Constant::new(mask),
        }
    }

    /// Bits of storage: the RAM's words, or the register.
    pub fn memory_bits(&self) -> usize {
        if self.single.val() {
            0
        } else {
            self.ram.depth() * self.ram.word_bits()
        }
    }
}

impl<D: Synth + std::ops::BitAnd<Output = D>, const N: usize> Logic for DelayLine<D, N> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, ptr, rd_flipped, one);
        self.ram.read_clock.next = self.clock.val();
        self.ram.write_clock.next = self.clock.val();
        self.rd.next = self.rd_flipped.q.val() ^ self.flip.val();
        self.next.next = self.rd.val() + 1;
        if (self.rd.val() >= self.last.val()) | (self.rd.val() >= self.longest_last.val()) {
            self.next.next = 0.into();
        }
        self.rd_flipped.d.next = self.next.val() ^ self.flip.val();
        self.ptr.d.next = self.rd.val();
        self.ram.write_address.next = self.ptr.q.val();
        self.ram.write_data.next = self.data_in.val();
        self.ram.write_enable.next = self.write_enable.val() & !self.single.val();
        self.ram.read_address.next = self.rd.val();
        self.one.d.next = self.one.q.val();
        if self.write_enable.val() {
            self.one.d.next = self.data_in.val() & self.mask.val();
        }
        if self.single.val() | (self.last.val() == 0) {
            self.data_out.next = self.one.q.val();
        } else {
            self.data_out.next = self.ram.read_data.val();
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
        last: Signal<In, Bits<8>>,
        data_out: Signal<Out, Bits<16>>,
        line: DelayLine<Bits<16>, 8>,
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
    /// built for `longest` and set to `length`; the output must be the
    /// input `length` clocks back, or that slot's older word.
    fn check(longest: usize, length: usize) {
        let mut uut = Bench {
            clock: Default::default(),
            data_in: Default::default(),
            write_enable: Default::default(),
            last: Default::default(),
            data_out: Default::default(),
            line: DelayLine::new(longest, &[(0, 12)], 0x0fffu64.to_bits()),
        };
        uut.connect_all();
        let mut sim = Simulation::new();
        sim.add_clock(5, |x: &mut Box<Bench>| x.clock.next = !x.clock.val());
        sim.add_testbench(move |mut sim: Sim<Bench>| {
            let mut x = sim.init()?;
            // What each slot holds: the last word written `length` clocks
            // apart, as a ring addressed by time would.
            let mut slots = vec![0u64; length];
            let mut state = 12345u64;
            for t in 0..200usize {
                state = state.wrapping_mul(6364136223846793005).wrapping_add(1);
                let word = (state >> 20) & 0xffff;
                let we = t % 7 != 3;
                x.data_in.next = word.to_bits();
                x.write_enable.next = we;
                x.last.next = ((length - 1) as u64).to_bits();
                x = sim.wait(10, x)?;
                if we {
                    slots[t % length] = word & 0x0fff;
                }
                // After clock t: the slot written at clock t + 1 - length.
                let expect = slots[(t + 1) % length];
                sim_assert_eq!(sim, x.data_out.val(), expect.to_bits::<16>(), x);
            }
            sim.done(x)
        });
        sim.run(Box::new(uut), 10_000).unwrap();
    }

    #[test]
    fn output_is_the_input_length_clocks_back() {
        for length in [1, 2, 3, 7, 33] {
            check(length, length);
        }
        // Lines built longer, set shorter at run time.
        for (longest, length) in [(2, 1), (7, 1), (7, 3), (33, 2), (33, 20)] {
            check(longest, length);
        }
    }
}
