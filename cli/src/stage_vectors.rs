//! `cube stage-vectors`: write a stage's emitted Verilog and its stimulus
//! with the golden model's expected outputs (`cosim::stage_vectors`), for a
//! testbench outside the kit: `testbenches/cocotb/run.py DIR` drives them
//! with cocotb under Icarus or Verilator.

use crate::output::Files;
use anyhow::{bail, Result};
use clap::ValueEnum;
use golden_model::common::plan::Order;
use scene::Mode;
use std::path::PathBuf;

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
enum StageMode {
    Composite,
    Mip,
    Minip,
    Xray,
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
enum StageOrder {
    FrontToBack,
    BackToFront,
}

#[derive(clap::Args)]
pub struct StageVectorsArgs {
    /// The stage (the Cube-4L compositor, §3.7).
    #[arg(long, default_value = "compositor")]
    stage: String,
    #[arg(long, value_enum, default_value = "composite")]
    mode: StageMode,
    #[arg(long, value_enum, default_value = "front-to-back")]
    order: StageOrder,
    /// Bits of each RGBA channel (4..=15).
    #[arg(long, default_value_t = 8)]
    rgba_bits: u32,
    /// Clocks of stimulus (1..=100000; 100000 write a 30 MB JSON and take
    /// about 360 MB).
    #[arg(long, default_value_t = 1000)]
    clocks: usize,
    /// The operand generator's seed.
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// The folder for STAGE.v and STAGE.json.
    #[arg(long)]
    out: PathBuf,
}

/// The most clocks of stimulus `stage-vectors` writes.
const MAX_CLOCKS: usize = 100_000;

pub fn run(args: StageVectorsArgs) -> Result<()> {
    if !cosim::stage_vectors::STAGES.contains(&args.stage.as_str()) {
        bail!(
            "stage-vectors: --stage {}: the stages are {}",
            args.stage,
            cosim::stage_vectors::STAGES.join(", ")
        );
    }
    if !(4..=15).contains(&args.rgba_bits) {
        bail!(
            "stage-vectors: --rgba-bits {} unsupported (4..=15)",
            args.rgba_bits
        );
    }
    // The vectors are built whole as JSON before they are written, about
    // 3.6 kB of memory a clock (1000000 took 3.5 GB for a 298 MB file and
    // aborted under a 3 GB limit); 100000 take 360 MB.
    if !(1..=MAX_CLOCKS).contains(&args.clocks) {
        bail!(
            "stage-vectors: --clocks {} outside 1..={MAX_CLOCKS}",
            args.clocks
        );
    }
    if std::fs::metadata(&args.out).is_ok_and(|m| !m.is_dir()) {
        bail!(
            "stage-vectors: --out {} is not a folder (it names the folder for {}.v and {}.json)",
            args.out.display(),
            args.stage,
            args.stage
        );
    }
    let mode = match args.mode {
        StageMode::Composite => Mode::Composite,
        StageMode::Mip => Mode::Mip,
        StageMode::Minip => Mode::Minip,
        StageMode::Xray => Mode::Xray,
    };
    let order = match args.order {
        StageOrder::FrontToBack => Order::FrontToBack,
        StageOrder::BackToFront => Order::BackToFront,
    };
    let files =
        cosim::stage_vectors::compositor(mode, order, args.rgba_bits, args.clocks, args.seed);
    let (v, j) = (
        args.out.join(format!("{}.v", args.stage)),
        args.out.join(format!("{}.json", args.stage)),
    );
    // The two files land together or not at all, and replace only the
    // kit's own (each begins with its mark).
    let mut outs = Files::default();
    let advice = "move it, or write elsewhere";
    outs.kits(
        "the stage's Verilog",
        &v,
        cosim::stage_vectors::VERILOG_MARK,
        advice,
    )?;
    outs.kits(
        "the stage's vectors",
        &j,
        cosim::stage_vectors::JSON_MARK,
        advice,
    )?;
    outs.text(&v, &files.verilog)?;
    outs.json(&j, &files.vectors)?;
    outs.commit()?;
    println!(
        "wrote {} and {} ({} clocks; outputs {} clocks after their inputs)",
        v.display(),
        j.display(),
        args.clocks,
        files.vectors["latency"]
    );
    Ok(())
}
