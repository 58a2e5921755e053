//! A [`DelayLine`] whose output comes from a flip-flop (the beam- and
//! slice-length delays of §3.5-3.7 and Fig. 21's SFG, as Cube-4L's
//! compositing buffer and gradient unit keep them): the memory's read data
//! goes only into a register, never through routing into logic, another
//! memory's write port or a link to the next pipeline. An ECP5 block RAM's
//! clock-to-out is about 4.6 ns before routing (the shaded 256³ build's
//! critical path ran from one into the next line's write port).
//!
//! A delay of L is a line of L - 1 and the register, so the same L clocks
//! at the same memory (one word less). A length of 1 is the register
//! alone, fed as the line's own length-1 register is. With a gap in
//! `write_enable` the output at t is still `data_in` of t - L whenever
//! clock t - L wrote; a clock that did not write leaves an older word, as
//! in a [`DelayLine`], though not the same older word.
//!
//! The inner line's length comes from a register of its own, `last - 1`,
//! one clock after `last` (the users' `last` is a register the view's
//! `Beats` set between sweeps).

use super::delay_line::DelayLine;
use rust_hdl::prelude::*;

/// A delay of up to `longest` clocks with an `N`-bit pointer and a
/// registered output.
#[derive(LogicBlock)]
pub struct RegisteredLine<D: Synth + std::ops::BitAnd<Output = D>, const N: usize> {
    pub clock: Signal<In, Clock>,
    pub data_in: Signal<In, D>,
    pub write_enable: Signal<In, Bit>,
    pub data_out: Signal<Out, D>,
    /// The delay less one, at most the longest less one.
    pub last: Signal<In, Bits<N>>,
    line: DelayLine<D, N>,
    line_last: DFF<Bits<N>>,
    out: DFF<D>,
    mask: Constant<D>,
}

impl<D: Synth + std::ops::BitAnd<Output = D>, const N: usize> RegisteredLine<D, N> {
    /// A delay of up to `longest` clocks (1 <= longest < 2^N) storing
    /// `fields` of each word, as [`DelayLine::new`].
    pub fn new(longest: usize, fields: &[(usize, usize)], mask: D) -> Self {
        assert!(
            longest >= 1 && longest < 1 << N,
            "a delay line with an {N}-bit pointer is 1 to 2^{N} - 1 clocks long, not {longest}"
        );
        RegisteredLine {
            clock: Default::default(),
            data_in: Default::default(),
            write_enable: Default::default(),
            data_out: Default::default(),
            last: Default::default(),
            line: DelayLine::new((longest - 1).max(1), fields, mask),
            line_last: Default::default(),
            out: Default::default(),
            mask: Constant::new(mask),
        }
    }

    /// Bits of storage in memory (the registers not counted).
    pub fn memory_bits(&self) -> usize {
        self.line.memory_bits()
    }
}

impl<D: Synth + std::ops::BitAnd<Output = D>, const N: usize> Logic for RegisteredLine<D, N> {
    #[hdl_gen]
    fn update(&mut self) {
        dff_setup!(self, clock, line_last, out);
        self.line.clock.next = self.clock.val();
        self.line_last.d.next = self.last.val() - 1;
        self.line.last.next = self.line_last.q.val();
        self.line.data_in.next = self.data_in.val();
        self.line.write_enable.next = self.write_enable.val();
        self.out.d.next = self.line.data_out.val();
        if self.last.val() == 0 {
            self.out.d.next = self.out.q.val();
            if self.write_enable.val() {
                self.out.d.next = self.data_in.val() & self.mask.val();
            }
        }
        self.data_out.next = self.out.q.val();
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
        line: RegisteredLine<Bits<16>, 8>,
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
    /// built for `longest` and set to `length`: from the third clock on
    /// (the inner length's register), every output whose clock t - length
    /// wrote is that word.
    fn check(longest: usize, length: usize) {
        let mut uut = Bench {
            clock: Default::default(),
            data_in: Default::default(),
            write_enable: Default::default(),
            last: Default::default(),
            data_out: Default::default(),
            line: RegisteredLine::new(longest, &[(0, 12)], 0x0fffu64.to_bits()),
        };
        uut.connect_all();
        let mut sim = Simulation::new();
        sim.add_clock(5, |x: &mut Box<Bench>| x.clock.next = !x.clock.val());
        sim.add_testbench(move |mut sim: Sim<Bench>| {
            let mut x = sim.init()?;
            let mut written = Vec::new();
            let mut state = 12345u64;
            let mut checked = 0;
            for t in 0..200usize {
                state = state.wrapping_mul(6364136223846793005).wrapping_add(1);
                let word = (state >> 20) & 0xffff;
                let we = t % 7 != 3;
                x.data_in.next = word.to_bits();
                x.write_enable.next = we;
                x.last.next = ((length - 1) as u64).to_bits();
                x = sim.wait(10, x)?;
                written.push(we.then_some(word & 0x0fff));
                // After clock t: the word of clock t + 1 - length.
                if t + 1 >= length + 2 {
                    if let Some(expect) = written[t + 1 - length] {
                        sim_assert_eq!(sim, x.data_out.val(), expect.to_bits::<16>(), x);
                        checked += 1;
                    }
                }
            }
            sim_assert!(sim, checked > 120, x);
            sim.done(x)
        });
        sim.run(Box::new(uut), 10_000).unwrap();
    }

    #[test]
    fn output_is_the_input_length_clocks_back() {
        for length in [1, 2, 3, 4, 7, 33] {
            check(length, length);
        }
        // Lines built longer, set shorter at run time.
        for (longest, length) in [(2, 1), (3, 2), (7, 1), (7, 3), (33, 2), (33, 20)] {
            check(longest, length);
        }
    }
}
