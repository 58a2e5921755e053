//! One lane's sample-plane history for Cube-3's ABC gradients (§4; §5,
//! Fig. 12: the above, current and below sample planes): the lane's sample
//! stream delayed through a chain of delay lines, with a tap at every
//! delay `a·T + b·G + c` for `a, b, c` in `0..3`.
//!
//! `G` is the clocks of a ray (its segments) and `T` the clocks from a
//! scanline's first segment to the next scanline's (`R·G` for `R` rays,
//! and more where the streams pause between scanlines), so tap `(a, b, c)`
//! holds, for the sample at the centre `(1, 1,
//! 1)`, the same lane's sample of scanline `v + 1 - a`, ray `u + 1 - b`, one
//! segment later (`c = 0`), the same (`c = 1`) or earlier (`c = 2`). Each
//! triple `c = 0, 1, 2` is a register pair; between triples the lines are
//! `G - 2` clocks long, and `T - 2G - 2` from one scanline to the next, so
//! the lane stores two sample planes and two rays beside its registers.
//! Each line ends in a register ([`RegisteredLine`]: a line one clock
//! shorter and a flip-flop), so a tap never reaches the estimators'
//! multipliers straight from a memory's read port.

use crate::common::registered_line::RegisteredLine;
use rust_hdl::prelude::*;

/// The chain's delay lines, in clocks, for scanlines every `scanline`
/// clocks and rays of `segments` clocks: within a scanline and from
/// scanline to scanline.
pub fn line_lengths(scanline: usize, segments: usize) -> Result<[usize; 8], String> {
    let (t, g) = (scanline, segments);
    if g < 3 || t < 2 * g + 3 {
        return Err(format!(
            "the ABC unit needs rays of at least 3 clocks and scanlines of more than 2 rays and 2 clocks: scanlines of {t} clocks, rays of {g}"
        ));
    }
    let (ray, line) = (g - 2, t - 2 * g - 2);
    Ok([ray, ray, line, ray, ray, line, ray, ray])
}

/// The history of one lane (`H`-bit delay-line pointers).
#[derive(LogicBlock)]
pub struct PlaneTaps<const H: usize> {
    pub clock: Signal<In, Clock>,
    /// The lines' lengths less one within a scanline (`G - 3`) and from
    /// one scanline to the next (`T - 2G - 3`): the view's, from the host.
    pub ray_last: Signal<In, Bits<H>>,
    pub line_last: Signal<In, Bits<H>>,
    pub sample: Signal<In, Bits<32>>,
    /// Tap `(a, b, c)` is `tabc` (one signal each: rust-hdl's Verilog
    /// generator resolves one array index per name, not a sub-block's).
    pub t000: Signal<Out, Bits<32>>,
    pub t001: Signal<Out, Bits<32>>,
    pub t002: Signal<Out, Bits<32>>,
    pub t010: Signal<Out, Bits<32>>,
    pub t011: Signal<Out, Bits<32>>,
    pub t012: Signal<Out, Bits<32>>,
    pub t020: Signal<Out, Bits<32>>,
    pub t021: Signal<Out, Bits<32>>,
    pub t022: Signal<Out, Bits<32>>,
    pub t100: Signal<Out, Bits<32>>,
    pub t101: Signal<Out, Bits<32>>,
    pub t102: Signal<Out, Bits<32>>,
    pub t110: Signal<Out, Bits<32>>,
    pub t111: Signal<Out, Bits<32>>,
    pub t112: Signal<Out, Bits<32>>,
    pub t120: Signal<Out, Bits<32>>,
    pub t121: Signal<Out, Bits<32>>,
    pub t122: Signal<Out, Bits<32>>,
    pub t200: Signal<Out, Bits<32>>,
    pub t201: Signal<Out, Bits<32>>,
    pub t202: Signal<Out, Bits<32>>,
    pub t210: Signal<Out, Bits<32>>,
    pub t211: Signal<Out, Bits<32>>,
    pub t212: Signal<Out, Bits<32>>,
    pub t220: Signal<Out, Bits<32>>,
    pub t221: Signal<Out, Bits<32>>,
    pub t222: Signal<Out, Bits<32>>,
    /// The first tap of each triple: the input, then each line's output.
    head: [Signal<Local, Bits<32>>; 9],
    one: [DFF<Bits<32>>; 9],
    two: [DFF<Bits<32>>; 9],
    lines: [RegisteredLine<Bits<32>, H>; 8],
    /// Which lines run from scanline to scanline.
    long: [Constant<Bit>; 8],
}

impl<const H: usize> PlaneTaps<H> {
    /// For scanlines of up to `scanline` clocks and rays of up to
    /// `segments` (the shortest rays, of 3 segments, leave the longest
    /// lines between scanlines).
    pub fn new(scanline: usize, segments: usize) -> Result<PlaneTaps<H>, String> {
        let [ray, _, line, ..] = line_lengths(scanline, segments)?;
        let longest = line_lengths(scanline, 3)?[2];
        let lengths = [
            ray,
            ray,
            line.max(longest),
            ray,
            ray,
            line.max(longest),
            ray,
            ray,
        ];
        if let Some(l) = lengths.iter().find(|&&l| l >= 1 << H) {
            return Err(format!(
                "a sample-plane line of {l} clocks needs more than {H} pointer bits"
            ));
        }
        Ok(PlaneTaps {
            clock: Default::default(),
            ray_last: Default::default(),
            line_last: Default::default(),
            sample: Default::default(),
            t000: Default::default(),
            t001: Default::default(),
            t002: Default::default(),
            t010: Default::default(),
            t011: Default::default(),
            t012: Default::default(),
            t020: Default::default(),
            t021: Default::default(),
            t022: Default::default(),
            t100: Default::default(),
            t101: Default::default(),
            t102: Default::default(),
            t110: Default::default(),
            t111: Default::default(),
            t112: Default::default(),
            t120: Default::default(),
            t121: Default::default(),
            t122: Default::default(),
            t200: Default::default(),
            t201: Default::default(),
            t202: Default::default(),
            t210: Default::default(),
            t211: Default::default(),
            t212: Default::default(),
            t220: Default::default(),
            t221: Default::default(),
            t222: Default::default(),
            head: Default::default(),
            one: Default::default(),
            two: Default::default(),
            lines: lengths.map(|l| RegisteredLine::new(l, &[], (u32::MAX as u64).to_bits())),
            long: std::array::from_fn(|t| Constant::new(t % 3 == 2)),
        })
    }

    /// Bits of block RAM in the lines.
    pub fn memory_bits(&self) -> usize {
        self.lines.iter().map(|l| l.memory_bits()).sum()
    }
}

impl<const H: usize> Logic for PlaneTaps<H> {
    #[hdl_gen]
    fn update(&mut self) {
        self.head[0].next = self.sample.val();
        // The lines first: each triple's head is assigned before it is read
        // (a block that reads a signal before assigning it is circular to
        // Verilator).
        for t in 0..8 {
            self.lines[t].clock.next = self.clock.val();
            self.lines[t].last.next = self.ray_last.val();
            if self.long[t].val() {
                self.lines[t].last.next = self.line_last.val();
            }
            self.lines[t].write_enable.next = true;
            self.lines[t].data_in.next = self.two[t].q.val();
            self.head[t + 1].next = self.lines[t].data_out.val();
        }
        for t in 0..9 {
            self.one[t].clock.next = self.clock.val();
            self.two[t].clock.next = self.clock.val();
            self.one[t].d.next = self.head[t].val();
            self.two[t].d.next = self.one[t].q.val();
        }
        self.t000.next = self.head[0].val();
        self.t001.next = self.one[0].q.val();
        self.t002.next = self.two[0].q.val();
        self.t010.next = self.head[1].val();
        self.t011.next = self.one[1].q.val();
        self.t012.next = self.two[1].q.val();
        self.t020.next = self.head[2].val();
        self.t021.next = self.one[2].q.val();
        self.t022.next = self.two[2].q.val();
        self.t100.next = self.head[3].val();
        self.t101.next = self.one[3].q.val();
        self.t102.next = self.two[3].q.val();
        self.t110.next = self.head[4].val();
        self.t111.next = self.one[4].q.val();
        self.t112.next = self.two[4].q.val();
        self.t120.next = self.head[5].val();
        self.t121.next = self.one[5].q.val();
        self.t122.next = self.two[5].q.val();
        self.t200.next = self.head[6].val();
        self.t201.next = self.one[6].q.val();
        self.t202.next = self.two[6].q.val();
        self.t210.next = self.head[7].val();
        self.t211.next = self.one[7].q.val();
        self.t212.next = self.two[7].q.val();
        self.t220.next = self.head[8].val();
        self.t221.next = self.one[8].q.val();
        self.t222.next = self.two[8].q.val();
    }
}
