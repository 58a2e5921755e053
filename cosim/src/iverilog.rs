//! The Icarus Verilog engine: the emitted pipeline Verilog with a generated
//! Verilog testbench that clocks it, starts one sweep and logs every pixel
//! on the pixel bus, and can dump a VCD of the design (scope `tb.uut`).

use crate::export::ON_CHIP_BITS as A;
use crate::pixel_log::parse_pixel_log;
use golden_model::cube4l::plan::Sweep;
use golden_model::cube4l::BasePlane;

/// Simulate emitted pipeline Verilog (from [`crate::export::pipeline_verilog`] with on-chip
/// memory preloaded, possibly altered)
/// under Icarus for one sweep; returns the base plane of the pixels it put
/// out and its clock count. `vcd` names a VCD of the design to write.
pub fn run_icarus(
    verilog: &str,
    p: usize,
    sweep: &Sweep,
    mode: scene::Mode,
    vcd: Option<&std::path::Path>,
) -> Result<(BasePlane, u64), String> {
    let beats = ((sweep.z1 - sweep.z0 + 1) * sweep.dims[1] * sweep.dims[0].div_ceil(p)) as u64;
    static RUNS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let run = RUNS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let dir = std::env::temp_dir().join(format!("cube-iverilog-{}-{run}", std::process::id()));
    std::fs::create_dir_all(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    let result = (|| {
        std::fs::write(dir.join("top.v"), verilog).map_err(|e| e.to_string())?;
        std::fs::write(dir.join("tb.v"), testbench_verilog(p, beats, vcd.is_some()))
            .map_err(|e| e.to_string())?;
        crate::tool::run(
            std::process::Command::new("iverilog")
                .args(["-g2012", "-o", "sim.vvp", "top.v", "tb.v"])
                .current_dir(&dir),
            "Icarus Verilog (iverilog)",
        )?;
        crate::tool::run_watched(
            std::process::Command::new("vvp")
                .args(["-n", "sim.vvp"])
                .current_dir(&dir),
            "Icarus Verilog (vvp)",
            &dir.join("heartbeat"),
            crate::tool::ICARUS_STALL,
        )?;
        let log = std::fs::read_to_string(dir.join("pixels.txt")).map_err(|e| e.to_string())?;
        // The trace first: it shows what went wrong when the log is bad.
        if let Some(path) = vcd {
            std::fs::copy(dir.join("trace.vcd"), path)
                .map_err(|e| format!("{}: {e}", path.display()))?;
        }
        let (base, cycles) = parse_pixel_log(&log, sweep, mode)?;
        // Counted like the rust-hdl engine: from the clock that registers start.
        Ok((base, cycles + 1))
    })();
    let _ = std::fs::remove_dir_all(&dir);
    result
}

/// A Verilog testbench for the emitted `top`: clock, one start pulse, and a
/// log line `x y face res` for every pixel on the bus until `beats` beats
/// have come out; then `cycles N` (or `timeout`); and a heartbeat for the
/// stall watch (`crate::tool::run_watched`). With `dump`, every signal of
/// the design goes to `trace.vcd`.
fn testbench_verilog(p: usize, beats: u64, dump: bool) -> String {
    let mut v =
        String::from("`timescale 1ns/1ps\nmodule tb;\n  reg clock = 0;\n  reg start = 0;\n");
    let mut ports = String::from(
        ".clock(clock), .start(start), .load_enable(1'b0), .load_module(8'd0), .load_address({A}'d0), .load_data(16'd0)",
    )
    .replace("{A}", &A.to_string());
    let mut log = String::new();
    for k in 0..p {
        v.push_str(&format!(
            "  wire px_valid${k};\n  wire [15:0] px_x${k};\n  wire [15:0] px_y${k};\n  wire [2:0] px_face${k};\n  wire res_beat${k};\n  wire res_valid${k};\n  wire [63:0] res${k};\n"
        ));
        ports.push_str(&format!(", .ext_data${k}(16'd0)"));
        for n in [
            "px_valid",
            "px_x",
            "px_y",
            "px_face",
            "res_beat",
            "res_valid",
            "res",
        ] {
            ports.push_str(&format!(", .{n}${k}({n}${k})"));
        }
        log.push_str(&format!(
            "      if (px_valid${k}) $fdisplay(f, \"%0d %0d %0d %0d\", px_x${k}, px_y${k}, px_face${k}, res${k});\n"
        ));
    }
    v.push_str(&format!(
        "  top uut({ports});\n  always #5 clock = ~clock;\n{}",
        crate::tool::heartbeat_verilog()
    ));
    v.push_str(&format!(
        "  integer f;\n  integer beats = 0;\n  integer cycles = 0;\n  initial begin\n{dump}    f = $fopen(\"pixels.txt\", \"w\");\n    @(negedge clock) start = 1;\n    @(negedge clock) start = 0;\n    while (beats < {beats}) begin\n      @(posedge clock);\n      #1;\n      cycles = cycles + 1;\n      if (res_beat$0) beats = beats + 1;\n{log}      if (cycles > {limit}) begin\n        $fdisplay(f, \"timeout\");\n        beats = {beats};\n      end\n    end\n    $fdisplay(f, \"cycles %0d\", cycles);\n    $fclose(f);\n    $finish;\n  end\nendmodule\n",
        limit = 2 * beats + 1000,
        dump = if dump {
            "    $dumpfile(\"trace.vcd\");\n    $dumpvars(0, uut);\n"
        } else {
            ""
        }
    ));
    v
}
