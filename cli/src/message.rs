//! Every line the kit prints to the user about a run (an error, a warning)
//! goes through [`one_line`]: whatever strings of the user's it quotes (a
//! 5 MB builtin name, a 1 MB raw path, a 100 kB `--config`, ANSI escapes)
//! come out cut and escaped, and the line stays one line. A number printed
//! in full decimal (5e-324 is 326 characters so) is shown in exponent form.

/// Longest run of characters without a space kept whole.
const MAX_WORD: usize = 200;

/// Longest line: beyond it the middle is left out, keeping the field
/// named at the start and the advice at the end.
const MAX_LINE: usize = 1000;

/// Longest number printed in full decimal; a longer one is shown as
/// `{:e}` (the same digits, so the same value).
const MAX_DECIMAL: usize = 24;

/// `msg` as one printable line: control characters (newlines, escapes)
/// shown as `\n`, `\u{1b}`; a float printed in full decimal and longer than
/// [`MAX_DECIMAL`] characters in exponent form; a word longer than [`MAX_WORD`] characters cut
/// with "…" and the count left out; a line longer than [`MAX_LINE`] cut in
/// the middle the same way.
pub fn one_line(msg: &str) -> String {
    let escaped: String = msg
        .chars()
        .flat_map(|c| {
            let shown: Vec<char> = if c.is_control() {
                c.escape_default().collect()
            } else {
                vec![c]
            };
            shown
        })
        .collect();
    let words: Vec<String> = escaped
        .split(' ')
        .map(|w| cut_word(&short_numbers(w)))
        .collect();
    cut_line(&words.join(" "))
}

/// `w` with each run of digits and points longer than [`MAX_DECIMAL`] that
/// is exactly how Rust prints some `f64` (`{}`) put as `{:e}`; other runs
/// (a user's string of digits) are kept.
fn short_numbers(w: &str) -> String {
    let numeric = |c: char| c.is_ascii_digit() || c == '.';
    let mut out = String::new();
    let mut rest = w;
    while let Some(start) = rest.find(numeric) {
        out += &rest[..start];
        let run = &rest[start..];
        let len = run.find(|c: char| !numeric(c)).unwrap_or(run.len());
        let digits = &run[..len];
        match digits.parse::<f64>() {
            Ok(x) if len > MAX_DECIMAL && x.is_finite() && format!("{x}") == digits => {
                out += &format!("{x:e}")
            }
            _ => out += digits,
        }
        rest = &run[len..];
    }
    out + rest
}

fn cut_word(w: &str) -> String {
    let n = w.chars().count();
    if n <= MAX_WORD {
        return w.to_string();
    }
    let head: String = w.chars().take(MAX_WORD).collect();
    format!("{head}… ({} more characters)", n - MAX_WORD)
}

fn cut_line(line: &str) -> String {
    let n = line.chars().count();
    if n <= MAX_LINE {
        return line.to_string();
    }
    let (head, tail) = (MAX_LINE * 3 / 5, MAX_LINE / 5);
    let start: String = line.chars().take(head).collect();
    let end: String = line.chars().skip(n - tail).collect();
    format!(
        "{start} … ({} characters left out) … {end}",
        n - head - tail
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn control_characters_are_escaped_and_the_line_stays_one() {
        assert_eq!(
            one_line("volume.builtin \"\u{1b}[31mred\" unknown\nsecond"),
            "volume.builtin \"\\u{1b}[31mred\" unknown\\nsecond"
        );
        assert_eq!(one_line("plain words, kept"), "plain words, kept");
    }

    #[test]
    fn a_float_in_full_decimal_is_put_in_exponent_form() {
        let tiny = format!("kernel[0] {} must be at least 1e-30", 5e-324);
        assert_eq!(one_line(&tiny), "kernel[0] 5e-324 must be at least 1e-30");
        let huge = format!("--clock-mhz {}, must lie in [0.1, 10000]", -1e300);
        assert_eq!(
            one_line(&huge),
            "--clock-mhz -1e300, must lie in [0.1, 10000]"
        );
        // A user's string of digits is not a printed float: kept (and cut).
        let typed = format!("builtin \"{}1\" unknown", "0".repeat(30));
        assert_eq!(one_line(&typed), typed);
        assert_eq!(one_line("step 0.25 of 16"), "step 0.25 of 16");
    }

    #[test]
    fn a_long_word_is_cut_and_counted() {
        let s = one_line(&format!("raw \"{}\" missing", "x".repeat(1 << 20)));
        assert!(s.starts_with("raw \"xxx"), "{s}");
        assert!(
            s.ends_with(&format!(
                "… ({} more characters) missing",
                (1 << 20) + 2 - MAX_WORD
            )),
            "{s}"
        );
        assert!(s.chars().count() < MAX_WORD + 60);
    }

    #[test]
    fn a_long_line_keeps_its_start_and_its_end() {
        let s = one_line(&format!(
            "field: {} use a smaller one",
            "ab ".repeat(10_000)
        ));
        assert!(s.starts_with("field: ab ab"), "{s}");
        assert!(s.ends_with("use a smaller one"), "{s}");
        assert!(s.contains("characters left out"));
        assert!(s.chars().count() <= MAX_LINE + 40);
    }
}
