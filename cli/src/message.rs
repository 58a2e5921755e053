//! Every line the kit prints to the user about a run (an error, a warning)
//! goes through [`one_line`]: whatever strings of the user's it quotes (a
//! 5 MB builtin name, a 1 MB raw path, a 100 kB `--config`, ANSI escapes)
//! come out cut and escaped, and the line stays one line.

/// Longest run of characters without a space kept whole.
const MAX_WORD: usize = 200;

/// Longest line: beyond it the middle is left out, keeping the field
/// named at the start and the advice at the end.
const MAX_LINE: usize = 1000;

/// `msg` as one printable line: control characters (newlines, escapes)
/// shown as `\n`, `\u{1b}`; a word longer than [`MAX_WORD`] characters cut
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
    let words: Vec<String> = escaped.split(' ').map(cut_word).collect();
    cut_line(&words.join(" "))
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
