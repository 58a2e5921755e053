//! A fault-injection campaign on the emitted Verilog of a shaded composite
//! scene. Each fault is one textual edit in one module of the Verilog that
//! `cube verilog` writes: a bit dropped on the host's table-load path,
//! swapped neighbour links, an off-by-one delay, stuck control bits (SR, ER,
//! the partial-beam start BS, invalid), wrong rounding constants, dropped
//! saturations, a wrong 2x2 selection, a gradient sign and a wiring fault in
//! the lighting's dot product. Every
//! fault must be caught twice: by the pixel comparison with the golden model,
//! and by the trace comparison (`cube vcd-diff`'s `compare`) against the
//! fault-free trace from the same simulator, which names its first bad
//! cycle and signal.
//!
//! The simulator is Icarus (seconds per run, no build); both traces come
//! from it, so four-state X values match up. Run with `--nocapture` to print
//! the campaign table that the README shows.

use cosim::cube4l::Cube4l;
use scene::volume::builtin;
use testbenches::faults::{campaign, fault, inject, line_of, run};
use testbenches::{emitted_sweep, require_tool, scene, EmittedSweep};

#[test]
fn every_injected_fault_is_caught_by_pixels_and_by_the_trace() {
    require_tool("iverilog");
    let s = scene(
        r#"{"volume": {"builtin": "sphere", "dims": [12, 12, 10]}, "view": {"projection": "parallel", "rotate_deg": [70, 30, 0]},
            "mode": "composite", "shading": {"enabled": true, "specular": 0.6}, "image": [32, 32],
            "hardware": {"pipelines": 2}}"#,
    );
    let vol = builtin("sphere", s.volume.dims, 8).unwrap();
    let cam = s.camera();
    let EmittedSweep { part, verilog } = emitted_sweep(&s, &vol);
    let (sweep, config) = (&part.sweep, &part.config);
    let dir = tempfile::tempdir().unwrap();
    let run =
        |v: &str, name: &str| run::<Cube4l>((&s, &cam, &vol), dir.path(), name, &|_| v.to_string());
    let (clean_pixels, clean) = run(&verilog, "clean");
    assert_eq!(
        clean_pixels, None,
        "the untouched Verilog matches the golden model"
    );

    let rows = "top$lanes$0$taps$rows";
    let pick0 = line_of(&verilog, rows, "localparam  pick$0");
    // With a gradient unit the lanes' control comes from the late CFB.
    let ctl = if config.gradient() { "late" } else { "cfb" };
    // Tap (e_x, e_y) serves x - sign(dx), y - sign(dy): tap 5 is (-1, -1),
    // tap 7 is (-1, 1).
    let (used, other) = match sweep.rays {
        golden_model::cube4l::plan::Rays::Parallel { dy, .. } if dy < 0 => (7, 5),
        _ => (5, 7),
    };
    let x_tap = match sweep.rays {
        golden_model::cube4l::plan::Rays::Parallel { dx, .. } if dx < 0 => 2,
        _ => 1,
    };
    let faults = [
        fault(
            "table load",
            "classification table: opacity bit 0 of every host write dropped",
            "top$lanes$0$shader$lut",
            "ram$write_data = 64'(host_data);",
            "ram$write_data = 64'(host_data) & ~64'h1000000000000;",
        ),
        fault(
            "swapped neighbour link",
            "ABC gradient: lane 1 takes its own x-link",
            "top",
            "lanes$1$g_from_left_xm = lanes$0$g_to_right_xm;",
            "lanes$1$g_from_left_xm = lanes$1$g_to_right_xm;",
        ),
        // A link of whichever of taps 5 and 7 (the two that cross a
        // neighbour link at p = 2) the signs of dx and dy select.
        fault(
            "swapped neighbour link",
            &format!("compositing buffer: lane 1's tap-{used} link carries tap {other}"),
            "top",
            &format!("lanes$1$t{used}i1 = lanes$0$t{used}s0;"),
            &format!("lanes$1$t{used}i1 = lanes$0$t{other}s0;"),
        ),
        fault(
            "off-by-one delay",
            "compositing-buffer tap 0 takes its value one clock late",
            rows,
            &pick0,
            &pick0.replace(';', "0;"),
        ),
        fault(
            "stuck control bit",
            "SR stuck at 0 (lane 0)",
            "top",
            &format!("lanes$0$sr = {ctl}$sr$0;"),
            "lanes$0$sr = 1'b0;",
        ),
        fault(
            "stuck control bit",
            "ER stuck at 0 (lane 0)",
            "top",
            &format!("lanes$0$er = {ctl}$er$0;"),
            "lanes$0$er = 1'b0;",
        ),
        fault(
            "stuck control bit",
            "BS, the partial-beam start, stuck at 0 (lane 0's taps)",
            "top$lanes$0$taps",
            "first = (x & p_mask) == 'h0;",
            "first = 1'b0;",
        ),
        fault(
            "stuck control bit",
            "invalid stuck at 1 (lane 0)",
            "top",
            &format!("lanes$0$invalid = {ctl}$invalid$0;"),
            "lanes$0$invalid = 1'b1;",
        ),
        fault(
            "wrong rounding constant",
            "bilinear lerp truncates (half = 0)",
            "top$lanes$0$bilinear$ch$0$bottom",
            "localparam  half = 64'h80;",
            "localparam  half = 64'h0;",
        ),
        fault(
            "wrong rounding constant",
            "unorm multiplier of the over operator truncates",
            "top$lanes$0$compositor$ch_r$mul",
            "localparam  half = 'h80;",
            "localparam  half = 'h0;",
        ),
        fault(
            "wrong rounding constant",
            "normal quantizer rounds a positive component down",
            "top$lanes$0$shader$normal",
            "half_q$d = (smear ^ (smear >> one)) >> mag_bits;",
            "half_q$d = 'h0;",
        ),
        fault(
            "dropped saturation",
            "normal quantizer: x component not saturated",
            "top$lanes$0$shader$normal",
            "if ((sum_q$0$q & sat_mask_q$q) != 'h0) begin",
            "if (1'b0) begin",
        ),
        fault(
            "dropped saturation",
            "shaded colour: red not saturated after the specular add",
            "top$lanes$0$shader$lit_r",
            "if ((u >> shift2) != 'h0) begin",
            "if (1'b0) begin",
        ),
        // The neighbour that the sign of dx selects, swapped for the other.
        fault(
            "wrong 2x2 selection",
            "x neighbour taken on the wrong side of the ray (channel 0)",
            "top$lanes$0$cells",
            &format!("w10$0 = a${x_tap};"),
            &format!("w10$0 = a${};", 3 - x_tap),
        ),
        fault(
            "gradient sign",
            "x gradient sign inverted (lane 0)",
            "top$lanes$0$feed$abc",
            "gx_neg_pass = xp < xm;",
            "gx_neg_pass = xp > xm;",
        ),
        fault(
            "wiring",
            "lighting: the normal's z magnitude wired from its y",
            "top$lanes$0$shader$lighting",
            "qm$2 = 16'(q_mag$2);",
            "qm$2 = 16'(q_mag$1);",
        ),
    ];
    campaign(&faults, &clean, |f, i| {
        run(&inject(&verilog, f), &format!("fault{i}"))
    });
}
