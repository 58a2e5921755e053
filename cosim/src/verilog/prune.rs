//! Leaving out what a scene does not need: the units an architecture's
//! part leaves out (`crate::arch::Arch::left_out`), removed from the
//! emitted Verilog.

use super::modules::split_modules;
use hdl::common::units::LeftOut;

/// The parent and instance name of module `name` when it is a unit in
/// `gone`: `…$u` for `u`, or an element `…$u$3` of an array for `u$*`.
fn unit_instance<'a>(name: &'a str, gone: &[&str]) -> Option<(&'a str, &'a str)> {
    let (parent, leaf) = name.rsplit_once('$')?;
    if gone.contains(&leaf) {
        return Some((parent, leaf));
    }
    if !leaf.is_empty() && leaf.bytes().all(|b| b.is_ascii_digit()) {
        let (outer, array) = parent.rsplit_once('$')?;
        if gone.iter().any(|g| g.strip_suffix("$*") == Some(array)) {
            return Some((outer, &name[outer.len() + 1..]));
        }
    }
    None
}

/// The names of `units`, for reports.
pub fn names(units: &[LeftOut]) -> Vec<&'static str> {
    units.iter().map(|u| u.name).collect()
}

/// Ports of a module, from its declarations: (name, is_output).
fn module_ports(text: &str) -> Vec<(String, bool)> {
    text.lines()
        .map(str::trim)
        .filter_map(|l| {
            let output = l.starts_with("output ");
            if !output && !l.starts_with("input ") {
                return None;
            }
            Some((
                l.trim_end_matches(';')
                    .split_whitespace()
                    .last()?
                    .to_string(),
                output,
            ))
        })
        .collect()
}

/// Remove the instances named in `units` from emitted Verilog: their
/// modules and every module below them, and their instantiation in the
/// parent, whose wires for their outputs become constant zero. The rust-hdl
/// description drives zero on those outputs too when the unit is disabled,
/// so simulation and the pruned Verilog agree signal for signal. The inputs
/// the parent computes for the removed instance stay, unread.
pub fn prune(verilog: &str, units: &[LeftOut]) -> Result<String, String> {
    let gone: Vec<&str> = units
        .iter()
        .flat_map(|u| u.instances.iter().copied())
        .collect();
    let mut modules = split_modules(verilog);
    let pruned: Vec<(String, Vec<(String, bool)>)> = modules
        .iter()
        .filter(|m| unit_instance(&m.name, &gone).is_some())
        .map(|m| (m.name.clone(), module_ports(&m.text)))
        .collect();
    // A unit inside another removed unit goes with it.
    let pruned: Vec<(String, Vec<(String, bool)>)> = pruned
        .iter()
        .filter(|(n, _)| !pruned.iter().any(|(p, _)| n.starts_with(&format!("{p}$"))))
        .cloned()
        .collect();
    modules.retain(|m| {
        !pruned
            .iter()
            .any(|(p, _)| m.name == *p || m.name.starts_with(&format!("{p}$")))
    });
    for (name, ports) in &pruned {
        let (parent, instance) = unit_instance(name, &gone).expect("a pruned unit");
        let m = modules
            .iter_mut()
            .find(|m| m.name == parent)
            .ok_or_else(|| format!("prune: no parent module {parent}"))?;
        let head = format!("{name} {instance}(");
        let mut out = String::with_capacity(m.text.len());
        let mut skipping = false;
        let mut found = false;
        for line in m.text.lines() {
            let t = line.trim();
            if t == head {
                skipping = true;
                found = true;
                continue;
            }
            if skipping {
                skipping = t != ");";
                continue;
            }
            let output_wire = ports.iter().any(|(p, out)| {
                *out && t.starts_with("wire ") && t.ends_with(&format!(" {instance}${p};"))
            });
            if output_wire {
                out.push_str(line.trim_end_matches(';'));
                out.push_str(" = 'h0;\n");
            } else {
                out.push_str(line);
                out.push('\n');
            }
        }
        if !found {
            return Err(format!("prune: no instance {instance} in {parent}"));
        }
        m.text = out;
    }
    Ok(modules
        .into_iter()
        .map(|m| m.text)
        .collect::<Vec<_>>()
        .join("\n"))
}

#[cfg(test)]
mod tests {
    use super::*;

    const TOY: &str = "\n\nmodule top(clock,q);\n    input wire  clock;\n    output reg  [3:0] q;\n    reg  u$a;\n    wire  [3:0] u$y;\n    top$u u(\n        .a(u$a),\n        .y(u$y)\n    );\n    always @(*) begin\n        u$a = clock;\n        q = u$y;\n    end\nendmodule // top\n\n\nmodule top$u(a,y);\n    input wire  a;\n    output reg  [3:0] y;\n    top$u$v v(\n    );\nendmodule // top$u\n\n\nmodule top$u$v();\nendmodule // top$u$v\n";

    #[test]
    fn split_keeps_every_module_in_order() {
        let names: Vec<String> = split_modules(TOY).into_iter().map(|m| m.name).collect();
        assert_eq!(names, ["top", "top$u", "top$u$v"]);
    }

    #[test]
    fn prune_removes_the_unit_and_zeroes_its_outputs() {
        let unit = LeftOut {
            name: "u",
            instances: &["u"],
        };
        let v = prune(TOY, &[unit]).unwrap();
        assert_eq!(split_modules(&v).len(), 1, "{v}");
        assert!(v.contains("wire  [3:0] u$y = 'h0;"), "{v}");
        assert!(!v.contains("top$u u("), "{v}");
        assert!(
            v.contains("u$a = clock;"),
            "the parent's input wiring stays"
        );
        let missing = LeftOut {
            name: "w",
            instances: &["w"],
        };
        assert_eq!(
            prune(TOY, &[missing]).unwrap(),
            split_modules(TOY)
                .into_iter()
                .map(|m| m.text)
                .collect::<Vec<_>>()
                .join("\n")
        );
    }

    #[test]
    fn prune_removes_every_element_of_an_array() {
        let toy = TOY
            .replace("top$u u(", "top$u$0 u$0(")
            .replace("u$y", "u$0$y")
            .replace("u$a", "u$0$a")
            .replace("module top$u(", "module top$u$0(")
            .replace("endmodule // top$u\n", "endmodule // top$u$0\n")
            .replace("top$u$v v(", "top$u$0$v v(")
            .replace("module top$u$v(", "module top$u$0$v(");
        let unit = LeftOut {
            name: "u",
            instances: &["u$*"],
        };
        let v = prune(&toy, &[unit]).unwrap();
        assert_eq!(split_modules(&v).len(), 1, "{v}");
        assert!(v.contains("wire  [3:0] u$0$y = 'h0;"), "{v}");
    }
}
