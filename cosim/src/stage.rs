//! One stage's emitted Verilog on per-clock input vectors, under Icarus or
//! Verilator: the stage testbenches drive the rust-hdl simulation and the
//! Verilog with the same vectors and compare both with the golden model on
//! every clock.
//!
//! The stage is rust-hdl's `top` module (`generate_verilog`). A generated
//! testbench (Verilog for Icarus, C++ for Verilator) reads one line of
//! hexadecimal inputs per clock, sets them, raises the clock and then writes
//! every output as hexadecimal: the values a rust-hdl testbench reads after
//! `wait_clock_cycle!`.

use std::path::Path;
use std::process::Command;

/// A simulator for a stage.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StageEngine {
    Iverilog,
    Verilator,
}

/// A port of the `top` module: name and width.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Port {
    pub name: String,
    pub bits: usize,
    pub input: bool,
}

/// The ports of rust-hdl's `top` module in declaration order, without the
/// clock.
pub fn ports(verilog: &str) -> Result<Vec<Port>, String> {
    let top = verilog
        .split("\nmodule ")
        .find(|m| m.starts_with("top("))
        .or_else(|| {
            verilog
                .strip_prefix("module ")
                .filter(|m| m.starts_with("top("))
        })
        .ok_or("no `module top(` in the stage's Verilog")?;
    let header = &top[4..top.find(");").ok_or("unterminated port list")?];
    let names: Vec<&str> = header.split(',').map(str::trim).collect();
    let mut out = Vec::new();
    for name in names.iter().filter(|n| **n != "clock") {
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
        out.push(Port {
            name: name.to_string(),
            bits,
            input: decl.starts_with("input "),
        });
    }
    Ok(out)
}

/// Run the stage for `vectors.len()` clocks; `vectors[t]` holds the inputs
/// (in [`ports`] order, inputs only) set before clock edge `t`. Returns the
/// outputs after each edge, `None` where a bit is unknown.
pub fn run_stage(
    engine: StageEngine,
    verilog: &str,
    vectors: &[Vec<u64>],
) -> Result<Vec<Vec<Option<u64>>>, String> {
    let run = run_stage_logged(engine, verilog, vectors, vectors.len(), None, None, None)?;
    Ok(run.logged.into_iter().map(|(_, o)| o).collect())
}

/// The inputs of clock `t` for a design started by `start` at clock 0,
/// every other input 0.
pub fn start_only(ports: &[Port], t: usize) -> Vec<u64> {
    ports
        .iter()
        .filter(|p| p.input)
        .map(|p| (p.name == "start" && t == 0) as u64)
        .collect()
}

/// A logged clock: its number and the outputs, `None` where unknown.
pub type Logged = (usize, Vec<Option<u64>>);

/// A stage run: its logged clocks, and the seconds spent compiling the
/// Verilog and simulating it.
#[derive(Debug, Clone)]
pub struct StageRun {
    pub logged: Vec<Logged>,
    pub build_seconds: f64,
    pub run_seconds: f64,
}

/// Run the stage for `clocks` clocks, holding the last vector's inputs
/// after `vectors` ends. With `when`, only the clocks where that one-bit
/// output is 1 are logged. Returns `(clock, outputs)` per logged clock.
/// `vcd` names a VCD of the whole design to write (scope `tb.uut` under
/// Icarus, `TOP.top` under Verilator). With `memory` (Verilator only), the
/// harness is the external RAM of modules `ext_addr$m` / `ext_data$m`: the
/// word at the address presented before a rising edge is on `ext_data$m`
/// after it.
pub fn run_stage_logged(
    engine: StageEngine,
    verilog: &str,
    vectors: &[Vec<u64>],
    clocks: usize,
    when: Option<&str>,
    vcd: Option<&Path>,
    memory: Option<&[Vec<u16>]>,
) -> Result<StageRun, String> {
    if memory.is_some() && engine != StageEngine::Verilator {
        return Err("the external memory model needs --engine verilator".into());
    }
    let ports = ports(verilog)?;
    let outputs: Vec<&Port> = ports.iter().filter(|p| !p.input).collect();
    let when = match when {
        Some(w) => Some(
            outputs
                .iter()
                .position(|p| p.name == w)
                .ok_or_else(|| format!("the stage has no output {w}"))?,
        ),
        None => None,
    };
    static RUNS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let run = RUNS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let dir = std::env::temp_dir().join(format!("cube-stage-{}-{run}", std::process::id()));
    std::fs::create_dir_all(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let result = (|| {
        std::fs::write(dir.join("top.v"), verilog).map_err(|e| e.to_string())?;
        let tb = Testbench {
            ports: &ports,
            vectors: vectors.len(),
            clocks,
            when,
            trace: vcd.is_some(),
            modules: memory.map_or(0, |m| m.len()),
        };
        for (m, words) in memory.unwrap_or_default().iter().enumerate() {
            let bytes: Vec<u8> = words.iter().flat_map(|w| w.to_le_bytes()).collect();
            std::fs::write(dir.join(format!("module{m}.bin")), bytes).map_err(|e| e.to_string())?;
        }
        match engine {
            StageEngine::Iverilog => std::fs::write(dir.join("tb.v"), tb.verilog()),
            StageEngine::Verilator => std::fs::write(dir.join("harness.cpp"), tb.cpp()),
        }
        .map_err(|e| e.to_string())?;
        let lines: Vec<String> = vectors
            .iter()
            .map(|v| {
                v.iter()
                    .map(|x| format!("{x:x}"))
                    .collect::<Vec<_>>()
                    .join(" ")
            })
            .collect();
        std::fs::write(dir.join("in.hex"), lines.join("\n") + "\n").map_err(|e| e.to_string())?;
        let (build_seconds, run_seconds) = simulate(engine, &dir, vcd.is_some())?;
        if let Some(path) = vcd {
            std::fs::copy(dir.join("trace.vcd"), path)
                .map_err(|e| format!("{}: {e}", path.display()))?;
        }
        let log = std::fs::read_to_string(dir.join("out.hex")).map_err(|e| e.to_string())?;
        let mut outs = Vec::new();
        for l in log.lines() {
            let mut words = l.split_whitespace();
            let t = words
                .next()
                .and_then(|w| usize::from_str_radix(w, 16).ok())
                .ok_or("a log line without its clock")?;
            outs.push((t, words.map(|h| u64::from_str_radix(h, 16).ok()).collect()));
        }
        if when.is_none() && outs.len() != clocks {
            return Err(format!("the stage wrote {} clocks of {clocks}", outs.len()));
        }
        Ok(StageRun {
            logged: outs,
            build_seconds,
            run_seconds,
        })
    })();
    let _ = std::fs::remove_dir_all(&dir);
    result
}

/// Compile and run; the seconds of each.
fn simulate(engine: StageEngine, dir: &Path, trace: bool) -> Result<(f64, f64), String> {
    let started = std::time::Instant::now();
    let build = |started: std::time::Instant| started.elapsed().as_secs_f64();
    match engine {
        StageEngine::Iverilog => {
            crate::tool::run(
                Command::new("iverilog")
                    .args(["-g2012", "-o", "sim.vvp", "-s", "tb", "top.v", "tb.v"])
                    .current_dir(dir),
                "Icarus Verilog (iverilog)",
            )?;
            let built = build(started);
            let run = std::time::Instant::now();
            crate::tool::run_watched(
                Command::new("vvp").args(["-n", "sim.vvp"]).current_dir(dir),
                "Icarus Verilog (vvp)",
                &dir.join("heartbeat"),
                crate::tool::ICARUS_STALL,
            )?;
            Ok((built, run.elapsed().as_secs_f64()))
        }
        StageEngine::Verilator => {
            crate::tool::run(
                Command::new("verilator")
                    .args([
                        "--cc",
                        "--exe",
                        "--build",
                        "-j",
                        "2",
                        // Every register starts at zero, as in rust-hdl.
                        "--x-assign",
                        "0",
                        "--x-initial",
                        "0",
                        "-Wno-fatal",
                        "-Wno-lint",
                        "-Wno-style",
                        "--top-module",
                        "top",
                        "top.v",
                        "harness.cpp",
                    ])
                    .args(trace.then_some("--trace"))
                    .current_dir(dir),
                "Verilator",
            )?;
            let built = build(started);
            let run = std::time::Instant::now();
            crate::tool::run(
                Command::new("obj_dir/Vtop").current_dir(dir),
                "the Verilator model",
            )?;
            Ok((built, run.elapsed().as_secs_f64()))
        }
    }
}

/// The generated testbench: inputs from `in.hex`, one line per clock for
/// `vectors` clocks (then held), and per logged clock a line of the clock
/// and every output in hexadecimal in `out.hex`. The Icarus testbench also
/// beats a heartbeat for the stall watch (`crate::tool::run_watched`).
struct Testbench<'a> {
    ports: &'a [Port],
    vectors: usize,
    clocks: usize,
    /// Log only where this output (an index among the outputs) is 1.
    when: Option<usize>,
    /// Dump every signal to `trace.vcd`.
    trace: bool,
    /// External memory modules served from `module{m}.bin` (Verilator).
    modules: usize,
}

impl Testbench<'_> {
    fn inputs(&self) -> Vec<usize> {
        (0..self.ports.len())
            .filter(|&i| self.ports[i].input)
            .collect()
    }

    fn outputs(&self) -> Vec<usize> {
        (0..self.ports.len())
            .filter(|&i| !self.ports[i].input)
            .collect()
    }

    /// Verilog for Icarus: the stage's inputs as registers, its outputs
    /// written one time step after each rising edge.
    fn verilog(&self) -> String {
        let decl = |p: &Port, kind: &str, i: usize| {
            let range = if p.bits > 1 {
                format!("[{}:0] ", p.bits - 1)
            } else {
                String::new()
            };
            format!("    {kind} {range}p{i};\n")
        };
        let mut v = String::from("`timescale 1ns/1ps\nmodule tb;\n    reg clock = 0;\n");
        for (i, p) in self.ports.iter().enumerate() {
            v += &decl(p, if p.input { "reg" } else { "wire" }, i);
        }
        let conns: Vec<String> = std::iter::once("clock".to_string())
            .chain((0..self.ports.len()).map(|i| format!("p{i}")))
            .collect();
        v += &format!("    top uut({});\n", conns.join(", "));
        let (ins, outs) = (self.inputs(), self.outputs());
        let fmt = |n: usize| vec!["%h"; n].join(" ");
        let list = |ix: &[usize]| {
            ix.iter()
                .map(|i| format!("p{i}"))
                .collect::<Vec<_>>()
                .join(", ")
        };
        v += &crate::tool::heartbeat_verilog();
        v += "    integer fin, fout, r, t;\n    initial begin\n";
        if self.trace {
            v += "        $dumpfile(\"trace.vcd\");\n        $dumpvars(0, uut);\n";
        }
        v += "        fin = $fopen(\"in.hex\", \"r\");\n        fout = $fopen(\"out.hex\", \"w\");\n";
        v += &format!(
            "        for (t = 0; t < {}; t = t + 1) begin\n",
            self.clocks
        );
        if !ins.is_empty() {
            v += &format!(
                "            if (t < {}) r = $fscanf(fin, \"{}\\n\", {});\n",
                self.vectors,
                fmt(ins.len()),
                list(&ins)
            );
        }
        v += "            #5 clock = 1;\n            #1;\n";
        let when = self
            .when
            .map_or("1'b1".to_string(), |w| format!("p{}", outs[w]));
        v += &format!(
            "            if ({when}) $fwrite(fout, \"%h {}\\n\", t, {});\n",
            fmt(outs.len()),
            list(&outs)
        );
        v += "            #4 clock = 0;\n        end\n        $fclose(fout);\n        $finish;\n    end\nendmodule\n";
        v
    }

    /// The same testbench as C++ for Verilator: the model's ports are named
    /// as in Verilog with `$` escaped as `__024`.
    fn cpp(&self) -> String {
        let field = |i: usize| format!("top->{}", self.ports[i].name.replace('$', "__024"));
        let mut c = String::from(
            "#include \"Vtop.h\"\n#include \"verilated.h\"\n#include <cstdio>\n\nint main(int argc, char** argv) {\n    Verilated::commandArgs(argc, argv);\n    Vtop* top = new Vtop;\n    FILE* in = fopen(\"in.hex\", \"r\");\n    FILE* out = fopen(\"out.hex\", \"w\");\n    unsigned long long v;\n",
        );
        // The trace: a dump after each evaluation, the rising edges at
        // 10t + 5 (rust-hdl's clock of period 10).
        if self.trace {
            c = c.replace(
                "#include <cstdio>",
                "#include <cstdio>\n#include \"verilated_vcd_c.h\"",
            );
            c += "    Verilated::traceEverOn(true);\n    VerilatedVcdC* vcd = new VerilatedVcdC;\n    top->trace(vcd, 99);\n    vcd->open(\"trace.vcd\");\n";
        }
        let dump = |at: &str| {
            if self.trace {
                format!("        vcd->dump((vluint64_t)({at}));\n")
            } else {
                String::new()
            }
        };
        if self.modules > 0 {
            c = c.replace("#include <cstdio>", "#include <cstdio>\n#include <vector>");
            c += &format!("    std::vector<unsigned short> mem[{}];\n", self.modules);
            c += &format!("    unsigned long long addr[{}] = {{0}};\n", self.modules);
            c += &format!(
                "    for (int m = 0; m < {}; m++) {{\n        char path[32];\n        snprintf(path, sizeof path, \"module%d.bin\", m);\n        FILE* f = fopen(path, \"rb\");\n        if (!f) return 2;\n        fseek(f, 0, SEEK_END);\n        long n = ftell(f) / 2;\n        fseek(f, 0, SEEK_SET);\n        mem[m].resize(n);\n        if (fread(mem[m].data(), 2, n, f) != (size_t)n) return 2;\n        fclose(f);\n    }}\n",
                self.modules
            );
        }
        let serve = |c: &mut String, what: &str| {
            for m in 0..self.modules {
                *c += &match what {
                    "address" => format!("        addr[{m}] = top->ext_addr__024{m};\n"),
                    _ => format!(
                        "        top->ext_data__024{m} = addr[{m}] < mem[{m}].size() ? mem[{m}][addr[{m}]] : 0;\n"
                    ),
                };
            }
        };
        c += "    top->clock = 0;\n    top->eval();\n";
        c += &format!("    for (long t = 0; t < {}; t++) {{\n", self.clocks);
        c += &format!("        if (t < {}) {{\n", self.vectors);
        for i in self.inputs() {
            c += &format!(
                "            if (fscanf(in, \"%llx\", &v) != 1) return 1;\n            {} = v;\n",
                field(i)
            );
        }
        c += "        }\n        top->eval();\n";
        c += &dump("10 * t");
        serve(&mut c, "address");
        c += "        top->clock = 1;\n        top->eval();\n";
        if self.modules > 0 {
            serve(&mut c, "data");
            c += "        top->eval();\n";
        }
        c += &dump("10 * t + 5");
        let outs = self.outputs();
        let when = self.when.map_or("true".to_string(), |w| field(outs[w]));
        c += &format!("        if ({when}) {{\n            fprintf(out, \"%lx\", t);\n");
        for &i in &outs {
            c += &format!(
                "            fprintf(out, \" %llx\", (unsigned long long){});\n",
                field(i)
            );
        }
        c += "            fprintf(out, \"\\n\");\n        }\n        top->clock = 0;\n        top->eval();\n    }\n    fclose(out);\n";
        if self.trace {
            c += "    vcd->close();\n";
        }
        c += "    delete top;\n    return 0;\n}\n";
        c
    }
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
