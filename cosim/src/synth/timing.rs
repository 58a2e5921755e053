//! nextpnr's timing report (`--report`, the same JSON from nextpnr-ecp5 and
//! nextpnr-ice40): the fmax and the critical path, with the stage of its
//! first and last cell.

use hdl::common::units;
use hdl::{cube3, cube4l};

/// One end of the critical path: the cell and the stage it belongs to.
#[derive(Debug, Clone, PartialEq)]
pub struct PathEnd {
    pub cell: String,
    pub stage: &'static str,
}

#[derive(Debug, Clone, PartialEq)]
pub struct Timing {
    pub fmax_mhz: f64,
    pub from: PathEnd,
    pub to: PathEnd,
    /// The path's delay split into logic and routing, in ns.
    pub logic_ns: f64,
    pub routing_ns: f64,
    /// Cells the path crosses, in order (start and end included).
    pub cells: Vec<String>,
}

/// The stage of a cell, from the instance path nextpnr names it by
/// (`lanes$0.bilinear.ch$0...`; Cube-3: `pipeline.lanes.units$1...`), as the
/// architectures' units manifests (`CELL_STAGES`) group them.
pub fn stage_of(cell: &str) -> &'static str {
    // The iCE40 run places the design inside a wrapper (`uut`).
    let cell = cell.strip_prefix("uut.").unwrap_or(cell);
    let parts: Vec<&str> = cell.split(['.', '$']).collect();
    [cube4l::units::CELL_STAGES, cube3::units::CELL_STAGES]
        .iter()
        .find_map(|s| units::stage_of(s, &parts))
        .unwrap_or(units::TOP)
}

/// Parse nextpnr's `--report` JSON.
pub fn parse_report(text: &str) -> Result<Timing, String> {
    let r: serde_json::Value =
        serde_json::from_str(text).map_err(|e| format!("nextpnr report: {e}"))?;
    let fmax_mhz = r["fmax"]
        .as_object()
        .and_then(|m| {
            m.values()
                .filter_map(|c| c["achieved"].as_f64())
                .reduce(f64::min)
        })
        .ok_or("nextpnr report: no fmax")?;
    let path = r["critical_paths"]
        .as_array()
        .and_then(|p| p.first())
        .and_then(|p| p["path"].as_array())
        .ok_or("nextpnr report: no critical path")?;
    let cell = |seg: &serde_json::Value, end: &str| {
        seg[end]["cell"].as_str().unwrap_or_default().to_string()
    };
    let mut cells: Vec<String> = Vec::new();
    let (mut logic_ns, mut routing_ns) = (0.0, 0.0);
    for seg in path {
        let d = seg["delay"].as_f64().unwrap_or(0.0);
        if seg["type"] == "routing" {
            routing_ns += d;
        } else {
            logic_ns += d;
        }
        for end in ["from", "to"] {
            let c = cell(seg, end);
            if !c.is_empty() && cells.last() != Some(&c) {
                cells.push(c);
            }
        }
    }
    // The ends are the first and last cells of the design: nextpnr's own
    // (`$nextpnr_…`, a carry chain's feed-in) carry no instance path.
    let ours = |c: &&String| !c.starts_with("$nextpnr");
    let first = (cells.iter().find(ours).or(cells.first()))
        .cloned()
        .ok_or("nextpnr report: empty path")?;
    let last = (cells.iter().rev().find(ours).or(cells.last()))
        .cloned()
        .unwrap_or_default();
    Ok(Timing {
        fmax_mhz,
        from: PathEnd {
            stage: stage_of(&first),
            cell: first,
        },
        to: PathEnd {
            stage: stage_of(&last),
            cell: last,
        },
        logic_ns,
        routing_ns,
        cells,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn report_gives_fmax_path_ends_and_their_stages() {
        let text = r#"{"fmax": {"clock": {"achieved": 58.2, "constraint": 12}},
          "critical_paths": [{"from": "posedge clock", "to": "posedge clock", "path": [
            {"type": "clk-to-q", "from": {"cell": "lanes$0.cells.y_FF"}, "to": {"cell": "lanes$0.cells.y_FF"}, "delay": 0.4},
            {"type": "routing", "from": {"cell": "lanes$0.cells.y_FF"}, "to": {"cell": "lanes$0.bilinear.ch$0.m_MULT"}, "delay": 1.0},
            {"type": "logic", "from": {"cell": "lanes$0.bilinear.ch$0.m_MULT"}, "to": {"cell": "lanes$0.bilinear.ch$0.m_MULT"}, "delay": 3.0},
            {"type": "setup", "from": {"cell": "lanes$0.bilinear.ch$0.m_MULT"}, "to": {"cell": "lanes$0.compositor.q_FF"}, "delay": 0.1}
          ]}], "utilization": {}}"#;
        let t = parse_report(text).unwrap();
        assert_eq!(t.fmax_mhz, 58.2);
        assert_eq!(t.from.stage, "select2x2");
        assert_eq!(t.to.cell, "lanes$0.compositor.q_FF");
        assert_eq!(t.to.stage, "compositor");
        assert_eq!(t.cells.len(), 3);
        assert!((t.logic_ns - 3.5).abs() < 1e-9 && (t.routing_ns - 1.0).abs() < 1e-9);
        assert_eq!(stage_of("late.lanes$1.div.stages$3.rx_FF"), "divider");
        assert_eq!(stage_of("cfb.lead.ns_q$17_FF"), "divider");
        assert_eq!(stage_of("lanes$3.feed.abc.line_a.ram"), "abc_gradient");
        assert_eq!(stage_of("uut.lanes$0.shader.r_q"), "shader");
        assert_eq!(stage_of("uut.view.r$0.q_SB_DFFE_Q_15_DFFLC"), "regs");
        // A path that starts in a cell nextpnr made (a carry chain's feed-in).
        let text = text.replace(
            r#"[
            {"type": "clk-to-q""#,
            r#"[
            {"type": "logic", "from": {"cell": "$nextpnr_ICESTORM_LC_1"}, "to": {"cell": "$nextpnr_ICESTORM_LC_1"}, "delay": 0.2},
            {"type": "clk-to-q""#,
        );
        let t = parse_report(&text).unwrap();
        assert_eq!(t.from.cell, "lanes$0.cells.y_FF");
        assert_eq!(t.cells.len(), 4);
        assert!(parse_report("{}").is_err());
    }
}
