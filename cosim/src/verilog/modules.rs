//! An emitted design as its Verilog modules, in order.

/// One Verilog module of an emitted design.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Module {
    pub name: String,
    pub text: String,
}

/// Split emitted Verilog into its modules, in order (the top first).
pub fn split_modules(verilog: &str) -> Vec<Module> {
    let mut out = Vec::new();
    let mut current: Option<Module> = None;
    for line in verilog.lines() {
        if current.is_none() {
            if let Some(rest) = line.strip_prefix("module ") {
                let name = rest
                    .split(|c: char| c == '(' || c.is_whitespace())
                    .next()
                    .unwrap_or_default()
                    .to_string();
                current = Some(Module {
                    name,
                    text: String::new(),
                });
            } else {
                continue;
            }
        }
        let m = current.as_mut().expect("inside a module");
        m.text.push_str(line);
        m.text.push('\n');
        if line.starts_with("endmodule") {
            out.extend(current.take());
        }
    }
    out
}
