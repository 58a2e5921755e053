//! Outputs written once per pass: a rewrite of rust-hdl's combinational
//! blocks so that event-driven simulators settle.
//!
//! rust-hdl emits each module's logic as one `always @(*)` block that often
//! writes an output twice: a default, then an override under a condition.
//! The final value is right, but an event-driven simulator (Icarus) sees
//! the default too, as a glitch on the port. The parent's block reads that
//! output and writes the module's inputs, with glitches of its own, so the
//! two blocks can wake each other forever within one time step: the whole
//! Cube-3 pipeline with its ABC units stalled Icarus this way. Verilator
//! and rust-hdl evaluate the blocks in order and never see a glitch.
//!
//! The rewrite gives each such output a shadow register, written in its
//! place everywhere in the block, and copies the shadow to the output once,
//! at the block's end. Every value the block computes is unchanged; only
//! the intermediate values no longer leave the module. With every output
//! changing at most once per pass, a pass of a block wakes another only on
//! a real change, and the blocks settle as the data path is acyclic.

use super::modules::split_modules;

/// The shadow register of output `name`: `name_pass`, with as many more
/// `_` as it takes to be a new name in `module`.
fn shadow(name: &str, module: &str) -> String {
    let mut s = format!("{name}_pass");
    while module.contains(&s) {
        s.push('_');
    }
    s
}

/// Whether `c` continues a Verilog identifier (rust-hdl uses `$` inside).
fn ident(c: u8) -> bool {
    c.is_ascii_alphanumeric() || c == b'_' || c == b'$'
}

/// `text` with every whole identifier `from` replaced by `to`.
fn rename(text: &str, from: &str, to: &str) -> String {
    let b = text.as_bytes();
    let mut out = String::with_capacity(text.len());
    let mut last = 0;
    for (i, _) in text.match_indices(from) {
        let j = i + from.len();
        let whole = (i == 0 || !ident(b[i - 1])) && (j == b.len() || !ident(b[j]));
        if whole && i >= last {
            out.push_str(&text[last..i]);
            out.push_str(to);
            last = j;
        }
    }
    out.push_str(&text[last..]);
    out
}

/// The outputs a module declares as `reg`: (name, declaration range such
/// as `[15:0] `, empty for one bit).
fn output_regs(text: &str) -> Vec<(String, String)> {
    text.lines()
        .filter_map(|l| {
            let rest = l.trim().strip_prefix("output reg")?.trim_end_matches(';');
            let name = rest.split_whitespace().last()?;
            let range = rest.trim()[..rest.trim().len() - name.len()].trim();
            let range = if range.is_empty() {
                String::new()
            } else {
                format!("{range} ")
            };
            Some((name.to_string(), range))
        })
        .collect()
}

/// How many blocking assignments `block` makes to `name`.
fn writes(block: &str, name: &str) -> usize {
    block
        .lines()
        .filter(|l| {
            l.trim().strip_prefix(name).is_some_and(|r| {
                r.trim_start().starts_with('=') && !r.trim_start().starts_with("==")
            })
        })
        .count()
}

const OPEN: &str = "    always @(*) begin\n";
const CLOSE: &str = "\n    end\n";

/// Where the body of a module's `always @(*)` block lies in its text.
fn comb_block(text: &str) -> Option<std::ops::Range<usize>> {
    let body = text.find(OPEN)? + OPEN.len();
    let len = text[body..].find(CLOSE)?;
    Some(body..body + len)
}

/// One module with each output that its `always @(*)` block writes more
/// than once routed through a shadow register.
fn module(text: &str) -> String {
    let Some(at) = comb_block(text) else {
        return text.to_string();
    };
    let mut block = text[at.clone()].to_string();
    let mut decls = String::new();
    for (name, range) in output_regs(text) {
        if writes(&block, &name) < 2 {
            continue;
        }
        let s = shadow(&name, text);
        block = rename(&block, &name, &s);
        block += &format!("\n        {name} = {s};");
        decls += &format!("    reg  {range}{s};\n");
    }
    let start = at.start - OPEN.len();
    format!("{}{decls}{OPEN}{block}{}", &text[..start], &text[at.end..])
}

/// Emitted Verilog with every module's outputs written once per pass of its
/// combinational block (see the module documentation).
pub fn write_once(verilog: &str) -> String {
    split_modules(verilog)
        .iter()
        .map(|m| module(&m.text))
        .collect::<Vec<_>>()
        .join("\n")
}

/// Outputs that a module's `always @(*)` block writes more than once, as
/// `module.output`: none in Verilog that went through [`write_once`].
pub fn outputs_written_twice(verilog: &str) -> Vec<String> {
    let mut found = Vec::new();
    for m in split_modules(verilog) {
        let Some(at) = comb_block(&m.text) else {
            continue;
        };
        for (name, _) in output_regs(&m.text) {
            if writes(&m.text[at.clone()], &name) > 1 {
                found.push(format!("{}.{name}", m.name));
            }
        }
    }
    found
}

#[cfg(test)]
mod tests {
    use super::*;

    const CHILD: &str = "module top$s(v,y);\n    input wire  [3:0] v;\n    output reg  [3:0] y;\n    output reg  z;\n    \n    // Update code\n    always @(*) begin\n        y = v;\n        if (v[3]) begin\n            y = 4'h7;\n        end\n        z = y[0];\n        y_x = y;\n    end\n    \nendmodule // top$s\n";

    #[test]
    fn an_output_written_twice_goes_through_a_shadow() {
        let v = write_once(CHILD);
        assert!(
            v.contains("    reg  [3:0] y_pass;\n    always @(*) begin\n"),
            "{v}"
        );
        assert!(v.contains("        y_pass = v;\n"), "{v}");
        assert!(v.contains("            y_pass = 4'h7;\n"), "{v}");
        // Reads within the block take the shadow; a longer name is kept.
        assert!(
            v.contains(
                "        z = y_pass[0];\n        y_x = y_pass;\n        y = y_pass;\n    end\n"
            ),
            "{v}"
        );
        assert_eq!(outputs_written_twice(CHILD), ["top$s.y"]);
        assert!(outputs_written_twice(&v).is_empty(), "{v}");
        // Once is enough: a second pass changes nothing.
        assert_eq!(write_once(&v), v);
    }

    #[test]
    fn a_taken_shadow_name_gets_another() {
        let taken = CHILD.replace("y_x", "y_pass");
        let v = write_once(&taken);
        assert!(v.contains("reg  [3:0] y_pass_;"), "{v}");
        assert!(v.contains("        y = y_pass_;\n"), "{v}");
    }
}
