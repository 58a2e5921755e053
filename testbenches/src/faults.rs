//! Fault campaigns on emitted Verilog (`fault_campaign.rs` for Cube-4L,
//! `cube3_fault_campaign.rs` for Cube-3): a fault is one textual edit in
//! one module; each run is an Icarus simulation with its trace, and every
//! fault must be caught twice, by the pixels against the golden model and
//! by the trace against the fault-free one (`cube vcd-diff`'s `compare`).

use cosim::arch::Arch;
use cosim::sim::simulate_altered;
use cosim::vcd_diff::{compare, Trace};
use cosim::verilog::split_modules;
use cosim::Engine;
use scene::volume::Volume;
use scene::{Camera, Scene};
use std::path::Path;

/// One edit: in module `module`, the first `from` becomes `to`.
pub struct Fault {
    pub kind: &'static str,
    pub what: String,
    pub module: &'static str,
    pub from: String,
    pub to: String,
}

pub fn fault(kind: &'static str, what: &str, module: &'static str, from: &str, to: &str) -> Fault {
    Fault {
        kind,
        what: what.into(),
        module,
        from: from.into(),
        to: to.into(),
    }
}

/// The text of module `name` in `verilog`.
pub fn module_text(verilog: &str, name: &str) -> String {
    split_modules(verilog)
        .into_iter()
        .find(|m| m.name == name)
        .unwrap_or_else(|| panic!("no module {name} in the emitted Verilog"))
        .text
}

/// `verilog` with `f` applied.
pub fn inject(verilog: &str, f: &Fault) -> String {
    let text = module_text(verilog, f.module);
    assert!(
        text.contains(&f.from),
        "fault site '{}' not found in {}",
        f.from,
        f.module
    );
    verilog.replacen(&text, &text.replacen(&f.from, &f.to, 1), 1)
}

/// The line of `module` that starts (after indentation) with `prefix`.
pub fn line_of(verilog: &str, module: &str, prefix: &str) -> String {
    module_text(verilog, module)
        .lines()
        .map(str::trim)
        .find(|l| l.starts_with(prefix))
        .unwrap_or_else(|| panic!("no line '{prefix}' in {module}"))
        .to_string()
}

/// Simulate the scene's Verilog, altered by `alter`, under Icarus with a
/// trace written to `dir/name.fst`: the pixels' difference from the golden
/// model (`None` when there is none; a pixel the golden model could never
/// output is an error of the run, a difference all the same) and the trace.
pub fn run<A: Arch>(
    (s, cam, vol): (&Scene, &Camera, &Volume),
    dir: &Path,
    name: &str,
    alter: &dyn Fn(&str) -> String,
) -> (Option<String>, Trace) {
    let vcd = dir.join(format!("{name}.fst"));
    let trace = crate::trace_to(&vcd);
    let pixels = match simulate_altered::<A>(s, cam, vol, Engine::Iverilog, Some(&trace), alter) {
        Ok(r) => (r.mismatches > 0).then(|| format!("{} pixels", r.mismatches)),
        Err(e) => Some(e),
    };
    (pixels, Trace::load(&vcd).unwrap())
}

/// Run every fault (`run_fault(fault, i)`), print the campaign's table (the
/// one docs/robustness.md shows) and fail on any fault the pixels or the
/// trace let through.
pub fn campaign(
    faults: &[Fault],
    clean: &Trace,
    run_fault: impl Fn(&Fault, usize) -> (Option<String>, Trace),
) {
    let mut table = vec![
        "| # | kind | fault | base-plane pixels differing | first bad cycle | first signal |"
            .to_string(),
        "|---|---|---|---|---|---|".to_string(),
    ];
    let mut missed = Vec::new();
    for (i, f) in faults.iter().enumerate() {
        let (pixels, trace) = run_fault(f, i);
        let c = compare(clean, &trace, None).unwrap();
        let first = c.mismatches.first();
        table.push(format!(
            "| {} | {} | {} | {} | {} | `{}` |",
            i + 1,
            f.kind,
            f.what,
            pixels.as_deref().unwrap_or("none"),
            first.map_or("-".into(), |m| m.cycle.to_string()),
            first.map_or("-", |m| m.signal.as_str()),
        ));
        if pixels.is_none() || c.equal() {
            missed.push(f.what.clone());
        }
    }
    println!("{}", table.join("\n"));
    assert!(missed.is_empty(), "faults not caught: {missed:?}");
}
