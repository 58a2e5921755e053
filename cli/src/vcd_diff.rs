//! `cube vcd-diff`: compare two VCD traces of the same design (e.g. rust-hdl
//! against Verilator) signal by signal and cycle by cycle. Unlike the other
//! subcommands it returns its own exit code: 0 equal, 1 different, 2 bad
//! input (a bad trace, named with its line, a clock that is not 1 bit
//! wide, a bad option).

use cosim::vcd_diff::{compare_from, show as hex, Trace};
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct VcdDiffArgs {
    a: PathBuf,
    b: PathBuf,
    /// Compare only signals whose name below the top matches this glob
    /// (e.g. 'lanes$0.*' or '*.res').
    #[arg(long)]
    signals: Option<String>,
    /// How many first mismatches to print.
    #[arg(long, default_value_t = 10)]
    show: usize,
    /// The clock whose rising edges count the cycles: a 1-bit signal's
    /// name (the shallowest of that name) or its dotted path. A wider one
    /// is refused (exit 2).
    #[arg(long, default_value = "clock")]
    clock: String,
    /// Line B's first cycle up with A's cycle N (B traced clocks N.. of the
    /// run A traced whole: `cube sim --trace-clocks N..`); cycles printed
    /// are B's.
    #[arg(long, default_value_t = 0, value_name = "N")]
    a_from: u64,
}

/// Compares the traces and returns the exit code: 0 equal, 1 different, 2
/// bad input.
pub fn run(args: VcdDiffArgs) -> i32 {
    let VcdDiffArgs {
        a,
        b,
        signals,
        show,
        clock,
        a_from,
    } = args;
    let load = |p: &PathBuf| Trace::load_with_clock(p, &clock);
    let loaded = load(&a).and_then(|ta| Ok((ta, load(&b)?)));
    let c = match loaded.and_then(|(ta, tb)| compare_from(&ta, a_from, &tb, signals.as_deref())) {
        Ok(c) => c,
        Err(e) => {
            eprintln!(
                "cube: vcd-diff: {}",
                crate::message::one_line(&e.to_string())
            );
            return 2;
        }
    };
    println!(
        "{} signals compared over {} cycles ({} in A only, {} in B only)",
        c.compared,
        c.cycles_a.min(c.cycles_b),
        c.only_a.len(),
        c.only_b.len()
    );
    if c.cycles_a != c.cycles_b {
        println!(
            "lengths differ: A has {} cycles, B has {}",
            c.cycles_a, c.cycles_b
        );
    }
    for m in c.mismatches.iter().take(show) {
        println!(
            "cycle {}: {}: A {} B {}",
            m.cycle,
            m.signal,
            hex(&m.a),
            hex(&m.b)
        );
    }
    if c.equal() {
        println!("traces equal");
        0
    } else {
        println!("{} signals differ", c.mismatches.len());
        1
    }
}
