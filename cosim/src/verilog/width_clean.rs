//! Width-clean Verilog: two of rust-hdl's emission habits rewritten so that
//! `verilator -Wall` sees matching widths, without changing a value.

/// Rewrite two of rust-hdl's emission habits that make every expression
/// width-mismatched for `verilator -Wall`, keeping rust-hdl's semantics:
/// - `bit_cast::<N, M>(e)` is emitted as the mask `((e) & N'h…)`, which
///   leaves the expression at the wider width; it becomes the
///   SystemVerilog size cast `N'(e)`, which truncates or zero-extends to N
///   bits exactly as `bit_cast` does in rust-hdl's simulation;
/// - every Rust integer literal is emitted as `32'h…`; it becomes the
///   unsized `'h…`, which is the same 32-bit unsigned value but which lint
///   lets take the width of its context.
///
/// Both forms are checked against the golden model by co-simulation.
pub fn width_clean(verilog: &str) -> String {
    unsize_literals(&size_casts(verilog))
}

fn size_casts(v: &str) -> String {
    let b = v.as_bytes();
    let mut out = String::with_capacity(v.len());
    // Positions of open parentheses not yet closed, in `out`.
    let mut open: Vec<usize> = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let c = b[i];
        if c == b'(' {
            open.push(out.len());
            out.push('(');
            i += 1;
            continue;
        }
        if c == b')' {
            let inner_open = open.pop();
            out.push(')');
            i += 1;
            // After `(e)`: ` & N'h<mask>)` closing an outer `(` right before it?
            if let (Some(start), Some((bits, len))) = (inner_open, cast_mask(&v[i..])) {
                if start > 0
                    && out.as_bytes()[start - 1] == b'('
                    && open.last() == Some(&(start - 1))
                {
                    open.pop();
                    let e = out[start + 1..out.len() - 1].to_string();
                    out.truncate(start - 1);
                    out.push_str(&format!("{bits}'({e})"));
                    i += len;
                }
            }
            continue;
        }
        let ch = v[i..].chars().next().expect("inside the text");
        out.push(ch);
        i += ch.len_utf8();
    }
    out
}

/// ` & N'h<2^N - 1>)` at the start of `s`: (N, its length).
fn cast_mask(s: &str) -> Option<(usize, usize)> {
    let rest = s.strip_prefix(" & ")?;
    let tick = rest.find('\'')?;
    let bits: usize = rest[..tick].parse().ok()?;
    let digits = rest[tick + 1..].strip_prefix('h')?;
    let end = digits.find(')')?;
    let mask = &digits[..end];
    let want = format!("{:x}", ones(bits));
    (bits > 0 && mask == want).then_some((bits, 3 + tick + 2 + end + 1))
}

/// 2^bits - 1 (bits up to 128).
fn ones(bits: usize) -> u128 {
    if bits >= 128 {
        u128::MAX
    } else {
        (1u128 << bits) - 1
    }
}

fn unsize_literals(v: &str) -> String {
    let mut out = String::with_capacity(v.len());
    let mut rest = v;
    while let Some(k) = rest.find("32'h") {
        let before = rest[..k].chars().last();
        out.push_str(&rest[..k]);
        if before.is_some_and(|c| c.is_ascii_alphanumeric() || c == '_' || c == '$') {
            out.push_str("32'h");
        } else {
            out.push_str("'h");
        }
        rest = &rest[k + 4..];
    }
    out.push_str(rest);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn casts_become_size_casts_and_literals_unsized() {
        let v = "  y = ((a + ((b) & 16'hffff)) & 32'hffffffff) + 32'h3 - 132'h1 + x32'h2;\n  z = ((c) & 16'hfff);\n";
        assert_eq!(
            width_clean(v),
            "  y = 32'(a + 16'(b)) + 'h3 - 132'h1 + x32'h2;\n  z = ((c) & 16'hfff);\n",
            "a mask that is not 2^N - 1 stays a mask"
        );
    }
}
