//! A fault-injection campaign on the emitted Verilog of a shaded composite
//! Cube-3 scene. Each fault is one textual edit in one module of the
//! Verilog that `cube verilog --arch cube3` writes: the beam fetch reading
//! the wrong memory module, the Fast Bus rotated by one, a 2-DSB read from
//! the wrong one of the three buffers, a TRILIN weight bit, the major-axis
//! lerps' operands swapped, a swapped ABC tap, a gradient sign, an RPC
//! node's front and back swapped, the RPC accumulator not reset at a ray's
//! start, a template ROM bit and the ray control's inner bound off by one.
//! Every fault must be caught twice: by the pixel comparison with the
//! golden model, and by the trace comparison (`cube vcd-diff`'s `compare`)
//! against the fault-free trace from the same simulator, which names its
//! first bad cycle and signal.
//!
//! The simulator is Icarus (seconds per run, no build); both traces come
//! from it, so four-state X values match up. Run with `--nocapture` to print
//! the campaign table that docs/robustness.md shows.

use std::cell::OnceCell;

use cosim::cube3::Cube3;
use scene::volume::Volume;
use testbenches::faults::{campaign, fault, inject, line_of, module_text, run};
use testbenches::{require_tool, scene};

/// The assignments of `module` that start with `first` and `second`, the
/// second after the first: the text from one through the other, and that
/// text with their right-hand sides exchanged.
fn exchange(verilog: &str, module: &str, first: &str, second: &str) -> (String, String) {
    let (a, b) = (
        line_of(verilog, module, first),
        line_of(verilog, module, second),
    );
    let text = module_text(verilog, module);
    let start = text.find(&a).unwrap();
    let end = start + text[start..].find(&b).expect("the second after the first") + b.len();
    let ((la, ra), (lb, rb)) = (a.split_once(" = ").unwrap(), b.split_once(" = ").unwrap());
    let between = &text[start + a.len()..end - b.len()];
    let to = format!("{la} = {rb}{between}{lb} = {ra}");
    (text[start..end].to_string(), to)
}

#[test]
fn every_injected_fault_is_caught_by_pixels_and_by_the_trace() {
    require_tool("iverilog");
    let s = scene(
        r#"{"volume": {"builtin": "phantom", "dims": [10, 9, 8]}, "view": {"projection": "parallel", "rotate_deg": [25, 35, 0]},
            "mode": "composite", "shading": {"enabled": true, "specular": 0.6}, "image": [32, 32],
            "hardware": {"pipelines": 2}}"#,
    );
    let vol = Volume::from_spec(&s.volume, s.hardware.voxel_bits).unwrap();
    let cam = s.camera();
    let dir = tempfile::tempdir().unwrap();
    let run = |alter: &dyn Fn(&str) -> String, name: &str| {
        run::<Cube3>((&s, &cam, &vol), dir.path(), name, alter)
    };
    // The clean run keeps the Verilog it simulated: the faults' sites.
    let emitted = OnceCell::new();
    let (clean_pixels, clean) = run(&|v| emitted.get_or_init(|| v.to_string()).clone(), "clean");
    assert_eq!(
        clean_pixels, None,
        "the untouched Verilog matches the golden model"
    );
    let verilog: &str = emitted.get().expect("the clean run emitted its Verilog");

    let (fetch, control) = ("top$fetch", "top$pipeline$control");
    let (lerp_from, lerp_to) = exchange(
        verilog,
        "top$pipeline$lanes$units$1",
        "z$0$a = ",
        "z$0$b = ",
    );
    let (node_from, node_to) = exchange(
        verilog,
        "top$pipeline$rpc$nodes$0",
        "ch_r$front = ",
        "ch_r$back = ",
    );
    let rom = "top$pipeline$control$templates$wy_rom$1";
    let rom_write = line_of(verilog, rom, "mem[host_address");
    let faults = [
        fault(
            "memory-module swap",
            "beam fetch: lane 0 takes memory module 1's word for module 0's",
            fetch,
            "value$0 = word$0;",
            "value$0 = word$1;",
        ),
        fault(
            "Fast Bus rotation",
            "lane 0's ray r of plane k goes to 2-DSB module (r + k + 1) mod P",
            fetch,
            "lane_dsb$0 = (s1_ray$0$q + s1_plane$q) & mask;",
            "lane_dsb$0 = (s1_ray$0$q + s1_plane$q + 'h1) & mask;",
        ),
        fault(
            "2-DSB wrong buffer",
            "module 0's current word read from buffer 1 when buffer 0 is current",
            fetch,
            "cur_m$0$d = buffer0$0$read_data;",
            "cur_m$0$d = buffer1$0$read_data;",
        ),
        fault(
            "TRILIN weight bit",
            "lane 0's x weight: bit 7 (one half) flipped",
            "top$pipeline$lanes$units$0",
            "wx_q$0$d = wx;",
            "wx_q$0$d = wx ^ 'h80;",
        ),
        fault(
            "major-axis lerp order",
            "lane 1's first lerp along k (corner a) takes back and front swapped",
            "top$pipeline$lanes$units$1",
            &lerp_from,
            &lerp_to,
        ),
        fault(
            "ABC neighbour swap",
            "lane 1's k - 1 centre tap wired to its k + 1 centre tap",
            "top$pipeline$abc",
            "estimators$1$km4 = lanes$0$t111;",
            "estimators$1$km4 = lanes$0$t110;",
        ),
        fault(
            "gradient sign",
            "y gradient sign inverted (lane 0)",
            "top$pipeline$abc$estimators$0",
            "gy_q$0$d = yp - ym;",
            "gy_q$0$d = ym - yp;",
        ),
        fault(
            "RPC operand order",
            "RPC node 0: red's front and back swapped",
            "top$pipeline$rpc$nodes$0",
            &node_from,
            &node_to,
        ),
        fault(
            "RPC reset",
            "RPC accumulator not reset at a ray's start",
            "top$pipeline$rpc",
            "if (root_flags['h0]) begin",
            "if (1'b0) begin",
        ),
        fault(
            "template ROM bit",
            "lane 1's y-weight template: bit 6 of every host write flipped",
            rom,
            &rom_write,
            &rom_write.replace(';', " ^ 16'h40;"),
        ),
        // The volume bound (`bounds`, a sample inside the volume) is not a
        // fault of this scene, by either off-by-one on any of its four
        // sides: a sample it moves in or out lies on the volume's faces,
        // never inner, so the shader clears it either way, and the over
        // operator ignores a leaf's valid flag. The inner bound (inside by
        // the gradient's reach) decides which samples are shaded: its first
        // scanline changes pixels here (its last ray, at the phantom's x
        // faces, changes none).
        fault(
            "inside bound",
            "ray control: lane 0's first inner scanline taken as at the edge",
            control,
            "(unit_scanline >= inner$0$data",
            "(unit_scanline > inner$0$data",
        ),
    ];
    campaign(&faults, &clean, |f, i| {
        run(&|v| inject(v, f), &format!("fault{i}"))
    });
}
