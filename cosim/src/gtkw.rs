//! GTKWave save files: a VCD from any engine opens with its signals grouped
//! by stage.

use std::path::Path;

/// A GTKWave save file beside `vcd` that opens with the signals grouped by
/// stage: CFB counters, then per pipeline its CFB lane, compositing-buffer
/// taps, and pixel output. `top` is the design's scope in the VCD (`uut` for
/// rust-hdl, `TOP.top` for Verilator).
pub fn write_gtkw(vcd: &Path, p: usize, top: &str) -> std::io::Result<()> {
    let mut s = header(vcd);
    s.push_str(&format!("@28\n{top}.clock\n{top}.start\n"));
    group(
        &mut s,
        "CFB",
        under(
            &format!("{top}.cfb"),
            &["valid", "n_s[15:0]", "n_beam[15:0]", "n_b[15:0]", "bs"],
        ),
    );
    for k in 0..p {
        let cfb_lane = [
            "x[15:0]",
            "y[15:0]",
            "z[15:0]",
            "value[15:0]",
            "address[31:0]",
            "pad",
            "halo",
            "sr",
            "er",
            "at_edge",
            "invalid",
            "face[2:0]",
            "dx_neg",
            "dx_mag[15:0]",
            "dy_neg",
            "dy_mag[15:0]",
        ];
        group(
            &mut s,
            &format!("CFB lane {k}"),
            under(&format!("{top}.cfb.lanes${k}"), &cfb_lane),
        );
        let lane = format!("{top}.lanes${k}");
        let abc = [
            "value[15:0]",
            "o_value[15:0]",
            "gx_neg",
            "gx_mag[15:0]",
            "gy_neg",
            "gy_mag[15:0]",
            "gz_neg",
            "gz_mag[15:0]",
        ];
        group(
            &mut s,
            &format!("ABC gradient {k}"),
            under(&format!("{lane}.feed.abc"), &abc),
        );
        let shader = ["valid", "r[15:0]", "g[15:0]", "b[15:0]", "a[15:0]"];
        group(
            &mut s,
            &format!("Shader {k}"),
            under(&format!("{lane}.shader"), &shader),
        );
        let mut taps: Vec<String> = (0..9).map(|c| format!("{lane}.taps.a${c}[63:0]")).collect();
        taps.extend(under(&lane, &["res_valid", "res[63:0]"]));
        group(&mut s, &format!("Compositing lane {k}"), taps);
        group(
            &mut s,
            &format!("Pixel out {k}"),
            under(
                &lane,
                &["px_valid", "px_x[15:0]", "px_y[15:0]", "px_face[2:0]"],
            ),
        );
    }
    save(vcd, s)
}

/// The Cube-3 system's save file: the beam fetch's schedule and 2-DSB
/// streams, the ray control, each TRILIN unit and its leaf, and the RPC's
/// pixel out. `top` is the design's scope (`uut` for rust-hdl).
pub fn write_gtkw_cube3(vcd: &Path, c: &hdl::cube3::Cube3Config, top: &str) -> std::io::Result<()> {
    let p = c.p;
    let mut s = header(vcd);
    s.push_str(&format!("@28\n{top}.clock\n{top}.start\n"));
    let sch = format!("{top}.fetch.schedule");
    group(
        &mut s,
        "Beam fetch",
        under(
            &sch,
            &[
                "writing",
                "period[15:0]",
                "plane[15:0]",
                "chunk[15:0]",
                "reading",
                "ray[15:0]",
                "segment[15:0]",
            ],
        ),
    );
    let mut streams = vec![format!("{top}.fetch.valid")];
    for i in 0..p {
        streams.push(format!("{top}.fetch.cur${i}[15:0]"));
        streams.push(format!("{top}.fetch.next${i}[15:0]"));
    }
    group(&mut s, "2-DSB streams", streams);
    let pipe = format!("{top}.pipeline");
    group(
        &mut s,
        "Ray control",
        under(
            &format!("{pipe}.control"),
            &[
                "first",
                "unit_valid",
                "unit_first",
                "unit_last",
                "in_volume[7:0]",
            ],
        ),
    );
    for i in 0..p {
        let mut sigs = vec![
            format!("{pipe}.lanes.wx${i}[15:0]"),
            format!("{pipe}.lanes.wy${i}[15:0]"),
            format!("{pipe}.lanes.sample${i}[31:0]"),
        ];
        if c.shading.is_none() {
            sigs.push(format!("{pipe}.leaf_q${i}.q[31:0]"));
            sigs.push(format!("{pipe}.leaf_valid_q${i}.q"));
        }
        group(&mut s, &format!("TRILIN {i}"), sigs);
        if c.shading.is_some() {
            let mut sigs = vec![];
            if c.abc.is_some() {
                for g in ["centre", "gx", "gy", "gz"] {
                    sigs.push(format!("{pipe}.abc.{g}${i}[31:0]"));
                }
            }
            for o in ["r[31:0]", "g[15:0]", "b[15:0]", "a[15:0]", "valid"] {
                sigs.push(format!("{pipe}.shade${i}.{o}"));
            }
            group(&mut s, &format!("ABC unit {i}"), sigs);
        }
    }
    group(
        &mut s,
        "RPC",
        under(
            &format!("{pipe}.rpc"),
            &[
                "first",
                "last",
                "done",
                "pixel_r[31:0]",
                "pixel_a[15:0]",
                "has_sample",
            ],
        ),
    );
    save(vcd, s)
}

fn header(vcd: &Path) -> String {
    format!(
        "[dumpfile] \"{}\"\n[timestart] 0\n[size] 1400 900\n",
        vcd.display()
    )
}

fn group(s: &mut String, name: &str, sigs: Vec<String>) {
    s.push_str(&format!("@800200\n-{name}\n@22\n"));
    for sig in sigs {
        s.push_str(&sig);
        s.push('\n');
    }
    s.push_str(&format!("@1000200\n-{name}\n"));
}

fn under(prefix: &str, names: &[&str]) -> Vec<String> {
    names.iter().map(|n| format!("{prefix}.{n}")).collect()
}

/// Write the save file beside `vcd`, whole or not at all.
fn save(vcd: &Path, s: String) -> std::io::Result<()> {
    let gtkw = vcd.with_extension("gtkw");
    let tmp = gtkw.with_extension("gtkw.tmp");
    std::fs::write(&tmp, s)?;
    std::fs::rename(tmp, gtkw)
}
