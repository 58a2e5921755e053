//! The integrable top: a module named after the build (`cube4l_NAME`,
//! `cube3_NAME`) around rust-hdl's `top`, whose port names carry no `$`
//! (`ext_addr$0` becomes `ext_addr_0`), with the ports grouped and
//! commented and an instantiation template in its header. rust-hdl names
//! the modules and signals inside `top` itself; the wrapper is what a user's
//! design instantiates ([docs/integration.md]).

use crate::harness::ports;
use hdl::common::units::CLOCK;

/// The wrapper module `module` around the `top` of `verilog` (the design's
/// whole Verilog or its `top.v`); `what` is a line naming the build.
pub fn wrapper(module: &str, verilog: &str, what: &str) -> Result<String, String> {
    let ports = ports(verilog)?;
    let clean = |n: &str| n.replace('$', "_");
    let mut names: Vec<String> = ports.iter().map(|p| clean(&p.name)).collect();
    names.push(CLOCK.into());
    let mut sorted = names.clone();
    sorted.sort();
    sorted.dedup();
    if sorted.len() != names.len() {
        return Err(format!("{module}: two ports share a name without `$`"));
    }
    let decl = |p: &crate::harness::Port| {
        let range = if p.bits > 1 {
            format!("[{}:0] ", p.bits - 1)
        } else {
            String::new()
        };
        format!(
            "{} wire {range}{}",
            if p.input { "input " } else { "output" },
            clean(&p.name)
        )
    };
    let mut decls = vec!["input  wire clock".to_string()];
    decls.extend(ports.iter().map(decl));
    let mut conns = vec![".clock(clock)".to_string()];
    conns.extend(
        ports
            .iter()
            .map(|p| format!(".{}({})", p.name, clean(&p.name))),
    );
    let template: Vec<String> = std::iter::once(CLOCK.to_string())
        .chain(ports.iter().map(|p| clean(&p.name)))
        .map(|n| format!("//     .{n}({n}),"))
        .collect();
    let mut template = template.join("\n");
    template.pop();
    Ok(format!(
        "\
// {what}: the integrable top (docs/integration.md). One clock; `reset` is
// synchronous, active high, where the build has one. Instantiation:
//
//   {module} u_render (
{template}
//   );
module {module} (
    {}
);
    top core (
        {}
    );
endmodule
",
        decls.join(",\n    "),
        conns.join(",\n        ")
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ports_lose_their_dollar_and_keep_their_widths() {
        let v = "module top(clock,reset,ext_addr$0,busy);\n    input wire  clock;\n    input wire  reset;\n    output reg  [31:0] ext_addr$0;\n    output reg  busy;\nendmodule\n";
        let w = wrapper("cube4l_x", v, "Cube-4L x").unwrap();
        assert!(w.contains("module cube4l_x (\n    input  wire clock,\n    input  wire reset,\n    output wire [31:0] ext_addr_0,\n    output wire busy\n);"), "{w}");
        assert!(w.contains(".ext_addr$0(ext_addr_0)"), "{w}");
        assert!(w.contains("//     .busy(busy)\n//   );"), "{w}");
        let clash = "module top(clock,a$0,a_0);\n    input wire  clock;\n    input wire  a$0;\n    input wire  a_0;\nendmodule\n";
        assert!(wrapper("m", clash, "m").is_err());
    }
}
