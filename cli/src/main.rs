//! `cube`: render scenes with the Cube-4L golden model and the float
//! reference, and report run time and error.
//!
//! This file only parses the arguments and dispatches; each subcommand lives
//! in its own module, with the helpers they share in `common`.

mod angles;
mod budget;
mod common;
mod compare;
mod default_run;
mod gradients;
mod message;
mod methods;
mod output;
mod plot;
mod render;
mod reports;
mod scenes;
mod sim;
mod stage_vectors;
mod stop;
mod synth;
mod tradeoff;
mod vcd_diff;
mod verilog;
mod volume;

use clap::{Parser, Subcommand};

#[derive(Parser)]
#[command(
    name = "cube",
    version,
    about = "Cube volume-rendering kit (Cube-4L, Cube-3): golden models, float reference, error and run time"
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand)]
enum Command {
    /// Render a scene.
    Render(render::RenderArgs),
    /// Error and run time of the golden model against the reference while the
    /// view turns about the vertical axis (the Cube-3 §6 experiment).
    Angles(angles::AnglesArgs),
    /// Cube-3 Fig. 15: mean angle between each ABC gradient neighbourhood's
    /// normal and the analytic normal of the built-in sphere, at the
    /// threshold crossings, while the view turns; JSON and a plot.
    Gradients(gradients::GradientsArgs),
    /// Run the scene through the pipeline in simulation (rust-hdl, or the
    /// emitted Verilog under Icarus or Verilator), warp its base plane, and
    /// compare it with the golden model bit for bit (exit 0 only if every
    /// pixel matches).
    Sim(sim::SimArgs),
    /// Write the scene's pruned pipeline as Verilog: one file per stage, a
    /// top, Verilator lint waivers and a manifest of parameters and left-out
    /// units.
    Verilog(verilog::VerilogArgs),
    /// Synthesize the scene's pipeline with yosys and report cells, LUTs,
    /// flip-flops, block RAMs and DSPs; on iCE40, a design that fits an UP5K
    /// is placed and routed with nextpnr-ice40 for fmax, and the frame rate
    /// is projected for 256³ and 512³ volumes.
    Synth(synth::SynthArgs),
    /// Compare two traces (VCD or FST) of the same design (e.g. rust-hdl
    /// against Verilator) signal by signal and cycle by cycle. Exit 0 when
    /// equal, 1 when they differ, 2 on a bad trace file.
    VcdDiff(vcd_diff::VcdDiffArgs),
    /// Write a stage's Verilog with the golden model's stimulus and expected
    /// outputs as JSON, for a testbench outside the kit (the cocotb test in
    /// testbenches/cocotb).
    StageVectors(stage_vectors::StageVectorsArgs),
    /// Error of an image made elsewhere (a peer renderer's PNG) against the
    /// scene's float reference.
    Compare(compare::CompareArgs),
    /// Error against cost for every method that applies to the scene, over
    /// its precisions and parameters: JSON, CSV, a log-log plot with the
    /// Pareto front, and a Markdown table.
    Tradeoff(tradeoff::TradeoffArgs),
    /// Write the scene's volume (built-in or raw, windowed, at its voxel
    /// width) as a raw file, for renderers outside the kit.
    Volume(volume::VolumeArgs),
    /// List the built-in volumes.
    Scenes,
}

/// rust-hdl builds a pipeline's signals on the stack of the thread that
/// builds it: a perspective pipeline (the divider's stages in every lane of
/// both CFBs) takes more than the main thread's 8 MiB. The work runs on a
/// thread with room for it, and rust-hdl's simulation threads get as much
/// as the tests give them (`.cargo/config.toml`) unless the environment
/// says otherwise.
const STACK_BYTES: usize = 64 << 20;
const MIN_STACK_BYTES: &str = "33554432";

/// The renderers' worker threads recurse no deeper than any other code:
/// they get a main thread's 8 MiB, not rust-hdl's 32 (32 workers of 32 MiB
/// took 1 GiB of address space, and the pool could not start under a
/// 1.5 GB `ulimit -v`).
const WORKER_STACK_BYTES: usize = 8 << 20;

/// At most this many renderer threads, whatever `RAYON_NUM_THREADS` says.
const MAX_WORKERS: usize = 1024;

/// Under an address-space limit, glibc's malloc keeps at most this many
/// arenas (each reserves 64 MiB; by default up to 8 a core, 1 GiB on two
/// cores, taken while the workers start), so that what the pool takes is
/// known before it starts.
const ARENAS: u64 = 4;

/// What the run takes beside what is mapped when the pool starts and the
/// workers' stacks: the heap's arenas, and room for the work.
const ROOM_BYTES: u64 = (256 << 20) + ARENAS * (64 << 20);

/// Cap malloc's arenas where an address-space limit is set (see
/// [`ARENAS`]); before any thread starts.
fn cap_arenas() {
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    if budget::address_limit().is_some() {
        // SAFETY: mallopt changes a malloc tunable; no thread runs yet.
        unsafe {
            libc::mallopt(libc::M_ARENA_MAX, ARENAS as libc::c_int);
        }
    }
}

/// How many renderer threads to start: `RAYON_NUM_THREADS` (0 or unset:
/// one a core), refused above [`MAX_WORKERS`] or where their stacks do not
/// fit the address-space limit (`ulimit -v`), before any of them starts.
fn pool_threads() -> anyhow::Result<(usize, String)> {
    let asked = match std::env::var("RAYON_NUM_THREADS") {
        Err(std::env::VarError::NotPresent) => None,
        Err(std::env::VarError::NotUnicode(v)) => anyhow::bail!(
            "RAYON_NUM_THREADS={} is not a whole number of threads",
            v.to_string_lossy()
        ),
        Ok(v) => match v.trim().parse::<usize>() {
            Ok(0) => None,
            Ok(n) => Some(n),
            Err(_) => anyhow::bail!(
                "RAYON_NUM_THREADS={v} is not a whole number of threads (0 or unset: one a core)"
            ),
        },
    };
    let n = asked.unwrap_or_else(|| std::thread::available_parallelism().map_or(1, |n| n.get()));
    let name = asked.map_or_else(
        || format!("one a core, {n}"),
        |n| format!("RAYON_NUM_THREADS={n}"),
    );
    let each = WORKER_STACK_BYTES >> 20;
    if n > MAX_WORKERS {
        anyhow::bail!(
            "cannot start the worker threads ({name}, {each} MiB of stack each): at most {MAX_WORKERS}; set RAYON_NUM_THREADS lower"
        );
    }
    let stack = WORKER_STACK_BYTES as u64;
    if let Err((need, limit)) = budget::threads_fit(n as u64, stack, ROOM_BYTES) {
        let fit = limit
            .saturating_sub(need.saturating_sub(n as u64 * (stack + budget::THREAD_MARGIN_BYTES)))
            / (stack + budget::THREAD_MARGIN_BYTES);
        // RAYON_NUM_THREADS=0 means one a core: with no thread that fits,
        // only more memory helps.
        let advice = match fit {
            0 => "allow more memory: not one worker fits".to_string(),
            _ => format!("set RAYON_NUM_THREADS to at most {fit}, or allow more memory"),
        };
        anyhow::bail!(
            "cannot start the worker threads ({name}, {each} MiB of stack each): with what the run maps and {} MiB of room they take {} MiB of address space, over the limit of {} MiB (ulimit -v); {advice}",
            ROOM_BYTES >> 20,
            need >> 20,
            limit >> 20,
        );
    }
    Ok((n, name))
}

/// Start the renderers' thread pool (`RAYON_NUM_THREADS` of them, or one a
/// core), or say in one line why it cannot start.
fn start_pool() -> anyhow::Result<()> {
    let (n, name) = pool_threads()?;
    rayon::ThreadPoolBuilder::new()
        .num_threads(n)
        .stack_size(WORKER_STACK_BYTES)
        .build_global()
        .map_err(|e| {
            anyhow::anyhow!(
                "cannot start the worker threads ({name}, {} MiB of stack each): {e}; set RAYON_NUM_THREADS lower, or allow more memory (ulimit -v)",
                WORKER_STACK_BYTES >> 20
            )
        })
}

fn main() {
    if std::env::var_os("RUST_MIN_STACK").is_none() {
        std::env::set_var("RUST_MIN_STACK", MIN_STACK_BYTES);
    }
    cap_arenas();
    // Signals are blocked here, before any thread starts, so that every
    // thread inherits the mask and only the watcher takes them.
    stop::watch();
    on_spawn_failure();
    let worker = match std::thread::Builder::new()
        .name("cube".into())
        .stack_size(STACK_BYTES)
        .spawn(run)
    {
        Ok(w) => w,
        Err(e) => no_thread(&format!(
            "cannot start the main thread ({} MiB of stack): {e}",
            STACK_BYTES >> 20
        )),
    };
    // A panic has printed its message on the worker; exit as Rust does.
    if worker.join().is_err() {
        std::process::exit(101);
    }
}

/// A thread that cannot start (under `ulimit -v`, rust-hdl's simulation
/// threads take `RUST_MIN_STACK` each, and std's `spawn` panics) ends the
/// run in one line, with its tools stopped and its temporary work removed.
fn on_spawn_failure() {
    let default = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        let p = info.payload();
        let msg = p
            .downcast_ref::<String>()
            .map(String::as_str)
            .or_else(|| p.downcast_ref::<&str>().copied())
            .unwrap_or("");
        if msg.starts_with("failed to spawn thread") {
            no_thread(&format!("cannot start a thread: {msg}"));
        }
        default(info)
    }));
}

/// Say why a thread could not start, clean up, and exit 1.
fn no_thread(why: &str) -> ! {
    eprintln!(
        "cube: {}",
        message::one_line(&format!(
            "{why}; allow more memory (ulimit -v), or set RAYON_NUM_THREADS lower"
        ))
    );
    stop::clean_up();
    std::process::exit(1)
}

fn run() {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        // Help and version go to stdout as clap prints them.
        Err(e) if !e.use_stderr() => e.exit(),
        // Bad input: one line, exit 1, like every other error (vcd-diff:
        // 2, as its help says; 1 there means "the traces differ").
        Err(e) => {
            // clap's first paragraph, joined (a missing argument is named
            // on the line after the message); its usage text is left out.
            let text = e.to_string();
            let first: Vec<&str> = text
                .lines()
                .map(str::trim)
                .take_while(|l| !l.is_empty())
                .collect();
            eprintln!(
                "cube: {} (see cube --help)",
                message::one_line(first.join(" ").trim_start_matches("error: "))
            );
            let vcd_diff = std::env::args().nth(1).is_some_and(|a| a == "vcd-diff");
            std::process::exit(if vcd_diff { 2 } else { 1 });
        }
    };
    if let Err(e) = start_pool() {
        eprintln!("cube: {}", message::one_line(&format!("{e:#}")));
        std::process::exit(1);
    }
    let r = match cli.command {
        None => default_run::run(),
        Some(Command::Render(args)) => render::run(args),
        Some(Command::Angles(args)) => angles::run(args),
        Some(Command::Gradients(args)) => gradients::run(args),
        Some(Command::Sim(args)) => sim::run(args),
        Some(Command::Verilog(args)) => verilog::run(args),
        Some(Command::Synth(args)) => synth::run(args),
        // vcd-diff sets its own exit code (2 for a bad file) and prints its
        // own errors.
        Some(Command::VcdDiff(args)) => std::process::exit(vcd_diff::run(args)),
        Some(Command::StageVectors(args)) => stage_vectors::run(args),
        Some(Command::Compare(args)) => compare::run(args),
        Some(Command::Tradeoff(args)) => tradeoff::run(args),
        Some(Command::Volume(args)) => volume::run(args),
        Some(Command::Scenes) => scenes::run(),
    };
    if let Err(e) = r {
        eprintln!("cube: {}", message::one_line(&format!("{e:#}")));
        std::process::exit(1);
    }
}
