//! Compare two traces (VCD or FST, read with `wellen`) of the same design
//! from different simulators (rust-hdl, Verilator, Icarus) signal by signal
//! and cycle by cycle.
//!
//! - Signals are lined up by hierarchical name below the design's top: each
//!   trace's leading scopes (`uut.` for rust-hdl, `TOP.top.` for Verilator,
//!   `tb.uut.` for Icarus) are dropped by choosing, per trace, the number of
//!   leading scopes that lines up the most names. Bit ranges are ignored.
//! - Time is counted in cycles of the top's `clock`: each signal is sampled
//!   once per rising edge, after every change at that edge's timestamp, so
//!   timescales, clock periods and repeated timestamps do not matter.
//! - Values are compared as bit strings without leading zeros.

use hdl::common::units::CLOCK;
use std::collections::{BTreeMap, HashMap};
use std::path::Path;

/// A trace reduced to per-cycle samples of its signals.
#[derive(Debug, Clone)]
pub struct Trace {
    /// Full hierarchical name of each variable, with its signal's index.
    names: Vec<(Vec<String>, usize)>,
    /// Each variable's declared bit range (`[3:0]`), where it has one: part
    /// of its identity, so `data [3:0]` and `data [7:4]` differ.
    ranges: Vec<Option<String>>,
    /// Per signal: (cycle, value) at each cycle where the sampled value
    /// changed, starting with cycle 0.
    samples: HashMap<usize, Vec<(u64, String)>>,
    /// Rising clock edges seen.
    pub cycles: u64,
}

/// A bad trace file: unreadable, unparsable, or without a top clock.
#[derive(Debug, Clone)]
pub struct BadTrace(pub String);

impl BadTrace {
    /// `e` of the file `path`, in one line (`wellen` puts its errors' cause
    /// on a line of its own).
    fn of(path: &Path, e: &dyn std::fmt::Display) -> BadTrace {
        let e = e.to_string();
        let e: Vec<&str> = e.lines().map(str::trim).filter(|l| !l.is_empty()).collect();
        BadTrace(format!("{}: {}", path.display(), e.join(" ")))
    }
}

impl std::fmt::Display for BadTrace {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

fn canonical(bits: &str) -> String {
    let t = bits.trim_start_matches('0');
    if t.is_empty() {
        "0".into()
    } else {
        t.to_string()
    }
}

/// A name without Verilog's escaped-identifier backslash: Icarus writes
/// `\lanes$1$sr` where Verilator writes `lanes$1$sr`.
fn plain(name: &str) -> String {
    name.strip_prefix('\\').unwrap_or(name).to_string()
}

/// Deepest scope nesting read: the parser and the walk below recurse once
/// a scope, so a hostile header of thousands of nested scopes would
/// overflow the stack. Designs nest a few tens deep.
pub const MAX_SCOPE_DEPTH: usize = 256;

/// Widest variable read: `wellen` widens a short value to its variable's
/// width, so one `b0` for a variable declared 4 294 967 295 bits wide would
/// take 4 GB. Designs' widest buses are a few thousand bits.
pub const MAX_VAR_BITS: u32 = 1 << 20;

/// What a `$var` declares of its values, as `wellen` reads them.
#[derive(Debug, Clone, Copy)]
enum Kind {
    /// A bit vector this many bits wide (1 or more).
    Bits(u32),
    /// An event, or a variable 0 bits wide: its values are not read.
    Event,
    Real,
    Str,
}

/// A declared variable: its kind and its name, for the messages.
struct Declared {
    kind: Kind,
    name: String,
}

/// The characters of a bit value (VCD's four states and VHDL's nine).
fn is_bit(c: u8) -> bool {
    matches!(
        c,
        b'0' | b'1'
            | b'x'
            | b'X'
            | b'z'
            | b'Z'
            | b'h'
            | b'H'
            | b'u'
            | b'U'
            | b'w'
            | b'W'
            | b'l'
            | b'L'
            | b'-'
    )
}

/// A token as text for a message, cut short.
fn shown(t: &[u8]) -> String {
    let s = String::from_utf8_lossy(t);
    if s.chars().count() > 40 {
        format!("{}…", s.chars().take(40).collect::<String>())
    } else {
        s.into_owned()
    }
}

/// Where the scan is in the text.
enum State {
    /// Between header commands.
    Header,
    /// In a header command's body, up to its `$end`: the command, the
    /// line it started on, and its words (kept for `$scope` and `$var`).
    Command(Vec<u8>, usize, Vec<Vec<u8>>),
    /// In the value changes.
    Body,
    /// A vector, real or string value read, its id next: the value and
    /// its line.
    Id(Vec<u8>, usize),
    /// In a `$comment` of the value changes.
    Comment,
}

/// The header and value changes of a VCD text, checked for what `wellen`
/// (0.25) panics on instead of returning an error: values wider than their
/// variable or with characters that are not bits, reals that are not
/// numbers, a value for an undeclared id or with no id, more `$upscope`s
/// than `$scope`s, a `$scope` with no type, a second `$date`, `$version`
/// or `$timescale`. Also refused: scopes nested deeper than
/// [`MAX_SCOPE_DEPTH`] and variables wider than [`MAX_VAR_BITS`]. What
/// `wellen` refuses with an error of its own is left to it.
struct Scan {
    state: State,
    depth: usize,
    ids: HashMap<Vec<u8>, Declared>,
    /// The open scopes' names, and each variable's full name (the scopes'
    /// path, its name and its range) to its id and line: a scope closed and
    /// opened again is the same scope.
    path: Vec<String>,
    names: HashMap<String, (Vec<u8>, usize)>,
    date: bool,
    version: bool,
    timescale: bool,
    /// The header ended in a command `wellen` does not know (its error).
    done: bool,
    /// The line of `$enddefinitions`, and whether a word followed it.
    body: Option<(usize, bool)>,
    /// The last time step of the body.
    last_time: Option<u64>,
}

impl Scan {
    fn new() -> Scan {
        Scan {
            state: State::Header,
            depth: 0,
            ids: HashMap::new(),
            path: Vec::new(),
            names: HashMap::new(),
            date: false,
            version: false,
            timescale: false,
            done: false,
            body: None,
            last_time: None,
        }
    }

    /// One whitespace-separated word of the text, on `line`.
    fn word(&mut self, mut w: &[u8], line: usize) -> Result<(), String> {
        while !w.is_empty() && !self.done {
            match &mut self.state {
                State::Header => {
                    // `wellen` reports anything but a command here.
                    let Some(name) = w.strip_prefix(b"$") else {
                        self.done = true;
                        return Ok(());
                    };
                    match name {
                        b"var" | b"scope" | b"upscope" | b"date" | b"version" | b"timescale"
                        | b"comment" | b"enddefinitions" | b"attrbegin" | b"attrend" => {}
                        _ => {
                            self.done = true;
                            return Ok(());
                        }
                    }
                    self.state = State::Command(name.to_vec(), line, Vec::new());
                    return Ok(());
                }
                State::Command(cmd, start, words) => {
                    // The command's body ends at the first `$end`, inside a
                    // word or not (as `wellen` reads it).
                    let end = w.windows(4).position(|x| x == b"$end");
                    let (part, rest) = match end {
                        Some(i) => (&w[..i], &w[i + 4..]),
                        None => (w, &w[w.len()..]),
                    };
                    if !part.is_empty()
                        && matches!(&cmd[..], b"var" | b"scope" | b"date" | b"version")
                    {
                        words.push(part.to_vec());
                    }
                    if end.is_none() {
                        return Ok(());
                    }
                    let (cmd, start, words) = (std::mem::take(cmd), *start, std::mem::take(words));
                    self.state = State::Header;
                    self.command(&cmd, start, &words)?;
                    w = rest;
                }
                State::Body => {
                    if let Some((_, words)) = &mut self.body {
                        *words = true;
                    }
                    match w[0] {
                        b'#' => self.time(&w[1..], line)?,
                        c if is_bit(c) => self.value(&w[..1], &w[1..], line)?,
                        b'b' | b'B' | b'r' | b'R' | b's' | b'S' => {
                            self.state = State::Id(w.to_vec(), line)
                        }
                        _ => match w {
                            b"$comment" => self.state = State::Comment,
                            b"$dumpvars" | b"$end" | b"$dumpoff" | b"$dumpon" | b"$dumpall" => {}
                            _ => {
                                return Err(format!(
                                    "line {line}: `{}` is not a time, a value or a command",
                                    shown(w)
                                ))
                            }
                        },
                    }
                    return Ok(());
                }
                State::Id(value, vline) => {
                    let (value, vline) = (std::mem::take(value), *vline);
                    self.state = State::Body;
                    return self.value(&value, w, vline);
                }
                State::Comment => {
                    if w == b"$end" {
                        self.state = State::Body;
                    }
                    return Ok(());
                }
            }
        }
        Ok(())
    }

    /// A time step `#t`: a whole number, never before the last one
    /// (`wellen` warns on stdout and drops what follows a step back, so two
    /// traces that differ there would read as equal).
    fn time(&mut self, t: &[u8], line: usize) -> Result<(), String> {
        let Some(t) = std::str::from_utf8(t)
            .ok()
            .and_then(|t| t.parse::<u64>().ok())
        else {
            return Err(format!("line {line}: `#{}` is not a time", shown(t)));
        };
        if let Some(last) = self.last_time.filter(|&last| t < last) {
            return Err(format!("line {line}: time {t} comes after time {last}"));
        }
        self.last_time = Some(t);
        Ok(())
    }

    /// A header command ended.
    fn command(&mut self, cmd: &[u8], line: usize, words: &[Vec<u8>]) -> Result<(), String> {
        let again = |what: &str| Err(format!("line {line}: a second ${what}"));
        match cmd {
            b"scope" => {
                if words.is_empty() {
                    return Err(format!("line {line}: a $scope with no type or name"));
                }
                self.depth += 1;
                self.path
                    .push(String::from_utf8_lossy(words.get(1).unwrap_or(&words[0])).to_string());
                if self.depth > MAX_SCOPE_DEPTH {
                    return Err(format!(
                        "line {line}: scopes nest deeper than {MAX_SCOPE_DEPTH}"
                    ));
                }
            }
            b"upscope" => {
                if self.depth == 0 {
                    return Err(format!("line {line}: an $upscope with no $scope open"));
                }
                self.depth -= 1;
                self.path.pop();
            }
            b"var" if words.len() >= 4 => {
                // `wellen` reads any width that is a number, and refuses others.
                let width = std::str::from_utf8(&words[1])
                    .ok()
                    .and_then(|s| s.parse::<u32>().ok())
                    .ok_or_else(|| format!("line {line}: `{}` is not a width", shown(&words[1])))?;
                if width > MAX_VAR_BITS {
                    return Err(format!(
                        "line {line}: a variable {width} bits wide (at most {MAX_VAR_BITS} are read)"
                    ));
                }
                let name = words[3..]
                    .iter()
                    .map(|n| String::from_utf8_lossy(n))
                    .collect::<Vec<_>>()
                    .join(" ");
                let kind = match &words[0][..] {
                    b"string" => Kind::Str,
                    b"real" | b"realtime" | b"shortreal" | b"real_parameter" => Kind::Real,
                    b"event" => Kind::Event,
                    // `wellen` reads such a variable's values as nothing,
                    // so two traces would agree on it whatever they hold.
                    _ if width == 0 => {
                        return Err(format!(
                            "line {line}: `{}` is declared 0 bits wide (a {} has 1 bit or more)",
                            shown(name.as_bytes()),
                            shown(&words[0])
                        ))
                    }
                    _ => Kind::Bits(width),
                };
                // One name (with its range) twice in a scope under two ids,
                // also where the scope is opened again: the comparison
                // could see only one of them.
                let key = format!(
                    "{}.{}",
                    self.path.join("."),
                    name.split_whitespace().collect::<String>()
                );
                match self.names.get(&key) {
                    Some((id, first)) if *id != words[2] => {
                        return Err(format!(
                            "line {line}: `{}` is declared again, under another id (first on line {first}): give each variable of a scope its own name",
                            shown(name.as_bytes())
                        ))
                    }
                    Some(_) => {}
                    None => {
                        self.names.insert(key, (words[2].clone(), line));
                    }
                }
                self.ids.insert(words[2].clone(), Declared { kind, name });
            }
            b"date" if !words.is_empty() => {
                if self.date {
                    return again("date");
                }
                self.date = true;
            }
            b"version" if !words.is_empty() => {
                if self.version {
                    return again("version");
                }
                self.version = true;
            }
            b"timescale" => {
                if self.timescale {
                    return again("timescale");
                }
                self.timescale = true;
            }
            b"enddefinitions" => {
                self.state = State::Body;
                self.body = Some((line, false));
            }
            _ => {}
        }
        Ok(())
    }

    /// A value change: `value` (its first character says which kind) of
    /// the variable `id`, on `line`.
    fn value(&self, value: &[u8], id: &[u8], line: usize) -> Result<(), String> {
        if id.is_empty() {
            return Err(format!("line {line}: `{}` with no signal id", shown(value)));
        }
        let Some(var) = self.ids.get(id) else {
            return Err(format!(
                "line {line}: a value for `{}`, which no $var declares",
                shown(id)
            ));
        };
        let (v, name) = (shown(value), &var.name);
        match var.kind {
            Kind::Event => {}
            Kind::Bits(width) => {
                let mut bits = match value[0] {
                    b'b' | b'B' => &value[1..],
                    _ => value,
                };
                // pymtl3 writes `b0b101`; `wellen` drops the `0b`.
                if bits.len() > 2 && bits.starts_with(b"0b") {
                    bits = &bits[2..];
                }
                if let Some(&c) = bits.iter().find(|&&c| !is_bit(c)) {
                    return Err(format!(
                        "line {line}: `{v}` for `{name}`: `{}` is not a bit (0, 1, x, z, h, u, w, l or -)",
                        shown(&[c])
                    ));
                }
                if bits.len() > width as usize {
                    return Err(format!(
                        "line {line}: `{v}` is {} bits, wider than the {width}-bit `{name}`",
                        bits.len()
                    ));
                }
                if width > 1 && bits.len() < width as usize {
                    match bits.first() {
                        None => {
                            return Err(format!(
                                "line {line}: an empty value for the {width}-bit `{name}`"
                            ))
                        }
                        Some(b'0' | b'1' | b'x' | b'X' | b'z' | b'Z') => {}
                        Some(&c) => {
                            return Err(format!(
                                "line {line}: `{v}` is shorter than the {width}-bit `{name}` and `{}` does not extend (0, 1, x or z do)",
                                shown(&[c])
                            ))
                        }
                    }
                }
            }
            Kind::Real => {
                let number = match value[0] {
                    b'r' | b'R' => std::str::from_utf8(&value[1..]).ok(),
                    _ => {
                        return Err(format!(
                        "line {line}: `{v}` for the real `{name}` (a real value is r and a number)"
                    ))
                    }
                };
                match number.and_then(|n| n.parse::<f64>().ok()) {
                    None => {
                        return Err(format!(
                            "line {line}: `{v}` for the real `{name}`: not a number"
                        ))
                    }
                    // NaN equals nothing, and 1e400 and 1e500 both read as
                    // infinity: such values cannot be compared.
                    Some(x) if !x.is_finite() => {
                        return Err(format!(
                            "line {line}: `{v}` for the real `{name}`: not a finite number (a 64-bit real's magnitude is below 1.8e308)"
                        ))
                    }
                    Some(_) => {}
                }
            }
            Kind::Str => {
                if !matches!(value[0], b's' | b'S') {
                    return Err(format!(
                        "line {line}: `{v}` for the string `{name}` (a string value starts with s)"
                    ));
                }
                if std::str::from_utf8(value).is_err() {
                    return Err(format!(
                        "line {line}: a string value for `{name}` that is not UTF-8"
                    ));
                }
            }
        }
        Ok(())
    }

    /// The end of the text.
    fn end(&self) -> Result<(), String> {
        match &self.state {
            State::Id(value, line) => {
                Err(format!("line {line}: `{}` with no signal id", shown(value)))
            }
            // `wellen` takes one byte off an empty body's length (a panic
            // when it checks for overflow, as the tests' profile does).
            State::Body => match self.body {
                Some((line, false)) => Err(format!(
                    "line {line}: the trace ends at $enddefinitions, with no value changes"
                )),
                _ => Ok(()),
            },
            _ => Ok(()),
        }
    }
}

/// Check a VCD text with [`Scan`] before `wellen` reads it. A file that
/// does not open as VCD text (FST, read by a reader of its own) is not
/// scanned.
fn check_vcd_text(path: &Path) -> Result<(), String> {
    use std::io::BufRead;
    let io = |e: std::io::Error| e.to_string();
    let mut f = std::io::BufReader::with_capacity(1 << 16, std::fs::File::open(path).map_err(io)?);
    let text = f
        .fill_buf()
        .map_err(io)?
        .iter()
        .find(|b| !b.is_ascii_whitespace())
        .is_some_and(|&b| b == b'$');
    if !text {
        return Ok(());
    }
    let mut scan = Scan::new();
    let mut buf = Vec::new();
    let mut line = 0usize;
    loop {
        buf.clear();
        if f.read_until(b'\n', &mut buf).map_err(io)? == 0 {
            break;
        }
        line += 1;
        for w in buf
            .split(|b| b.is_ascii_whitespace())
            .filter(|w| !w.is_empty())
        {
            scan.word(w, line)?;
        }
        if scan.done {
            return Ok(());
        }
    }
    scan.end()
}

thread_local! {
    /// This thread is reading a trace under [`quietly`]: a panic of the
    /// parser is caught and reported as a bad trace, not printed.
    static QUIET: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Run `f`, catching a panic (the trace readers' on input they did not
/// expect) as its message, in one line, without printing it: the panic
/// hook is wrapped, once, to stay silent on a thread inside this call and
/// to print as before everywhere else.
fn quietly<T>(f: impl FnOnce() -> T) -> Result<T, String> {
    static HOOK: std::sync::Once = std::sync::Once::new();
    HOOK.call_once(|| {
        let previous = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            if !QUIET.with(|q| q.get()) {
                previous(info)
            }
        }));
    });
    let was = QUIET.with(|q| q.replace(true));
    let r = std::panic::catch_unwind(std::panic::AssertUnwindSafe(f));
    QUIET.with(|q| q.set(was));
    r.map_err(|payload| {
        let msg = payload
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "no message".into());
        let msg = msg.lines().next().unwrap_or("").trim();
        if msg.chars().count() > 160 {
            format!("{}…", msg.chars().take(160).collect::<String>())
        } else {
            msg.to_string()
        }
    })
}

impl Trace {
    /// Load a trace whose cycles are counted on the top's `clock`.
    pub fn load(path: &Path) -> Result<Trace, BadTrace> {
        Trace::load_with_clock(path, CLOCK)
    }

    /// Load a trace whose cycles are counted on `clock`: a 1-bit signal's
    /// name (the shallowest of that name is taken) or its whole dotted path.
    ///
    /// A VCD text is checked first ([`Scan`]: what the parser would panic
    /// on is refused naming its line); a panic of the parser on what the
    /// check let through is caught, silently, and refused as a bad trace.
    pub fn load_with_clock(path: &Path, clock: &str) -> Result<Trace, BadTrace> {
        let bad = |e: &dyn std::fmt::Display| BadTrace::of(path, e);
        // Refuse FIFOs and devices before opening: one with no writer would block.
        if !std::fs::metadata(path).map_err(|e| bad(&e))?.is_file() {
            return Err(bad(&"not a regular file"));
        }
        check_vcd_text(path).map_err(|e| bad(&e))?;
        quietly(|| Trace::read(path, clock)).unwrap_or_else(|panic| {
            Err(bad(&format!(
                "unreadable trace (the trace reader failed: {panic})"
            )))
        })
    }

    /// [`Trace::load_with_clock`] after its checks.
    fn read(path: &Path, clock: &str) -> Result<Trace, BadTrace> {
        let bad = |e: &dyn std::fmt::Display| BadTrace::of(path, e);
        let mut wave = wellen::stream::read_from_file(path, &wellen::LoadOptions::default())
            .map_err(|e| bad(&e))?;
        let h = wave.hierarchy();
        // Every variable's path (scopes, then its name without a bit
        // range) and its signal: aliases share one signal.
        let mut names: Vec<(Vec<String>, usize)> = Vec::new();
        let mut ranges: Vec<Option<String>> = Vec::new();
        for v in h.all_vars() {
            let var = &h[v];
            let mut full: Vec<String> = var.full_name(h).split('.').map(plain).collect();
            if let Some(last) = full.last_mut() {
                *last = plain(var.name(h));
            }
            names.push((full, var.signal_ref().index()));
            ranges.push(var.index().map(|i| {
                if i.msb() == i.lsb() {
                    format!("[{}]", i.msb())
                } else {
                    format!("[{}:{}]", i.msb(), i.lsb())
                }
            }));
        }
        // The clock: the shallowest variable of that name, or that path
        // (matched before ranges join the names below).
        let (clock_at, _) = names
            .iter()
            .enumerate()
            .filter(|(_, (n, _))| n.last().is_some_and(|l| l == clock) || n.join(".") == clock)
            .min_by_key(|(_, (n, _))| n.len())
            .ok_or_else(|| {
                bad(&format!(
                    "no `{clock}` signal (name the clock with --clock)"
                ))
            })?;
        // A 1-bit signal: a bus's value is never "1" after "0" as a bit
        // string, so it would count no cycle (or its low bit's, silently).
        let var = &h[h.all_vars().nth(clock_at).expect("a variable per name")];
        match var.signal_encoding(h) {
            wellen::SignalEncoding::BitVector(1) => {}
            wellen::SignalEncoding::BitVector(w) => {
                return Err(bad(&format!(
                    "the clock `{clock}` is {w} bits wide; the clock must be a 1-bit signal (name it with --clock)"
                )))
            }
            wellen::SignalEncoding::Real | wellen::SignalEncoding::String => {
                return Err(bad(&format!(
                    "the clock `{clock}` is a {}, not a 1-bit signal (name the clock with --clock)",
                    if var.is_real(h) { "real" } else { "string" }
                )))
            }
        }
        let clock = names[clock_at].1;
        // Variables of one path told apart only by their ranges (a bus
        // declared bit by bit, `data [0]`, `data [1]`) keep their ranges in
        // their names; a name of its own matches the other trace's by
        // name, and its range is compared there.
        let mut paths: HashMap<Vec<String>, usize> = HashMap::new();
        for (n, _) in &names {
            *paths.entry(n.clone()).or_default() += 1;
        }
        for (i, (n, _)) in names.iter_mut().enumerate() {
            if paths[&*n] > 1 {
                if let (Some(last), Some(r)) = (n.last_mut(), ranges[i].take()) {
                    last.push_str(&r);
                }
            }
        }
        // The value of each signal now, and the signals changed since the
        // last sample: a sample touches only those.
        let slots = names.iter().map(|(_, c)| c + 1).max().unwrap_or(0);
        let mut current: Vec<Option<String>> = vec![None; slots];
        let mut dirty: Vec<usize> = Vec::new();
        let mut samples: HashMap<usize, Vec<(u64, String)>> = HashMap::new();
        let mut cycles = 0u64;
        let mut clock_was = String::from("0");
        let mut rose = false;
        let sample = |current: &[Option<String>],
                      dirty: &mut Vec<usize>,
                      samples: &mut HashMap<usize, Vec<(u64, String)>>,
                      cycle: u64| {
            for id in dirty.drain(..) {
                let Some(v) = &current[id] else { continue };
                let s = samples.entry(id).or_default();
                if s.last().is_none_or(|(_, last)| last != v) {
                    s.push((cycle, v.clone()));
                }
            }
        };
        let mut now = None;
        wave.stream_changes(wellen::stream::Filter::all(), |t, signal, value| {
            // A new time ends the instant of a rising edge: sample it.
            if now != Some(t) {
                now = Some(t);
                if rose {
                    sample(&current, &mut dirty, &mut samples, cycles);
                    cycles += 1;
                    rose = false;
                }
            }
            // Reals and strings are compared as values too, each kind
            // marked so that no value of one reads as one of another.
            let v = match value {
                wellen::SignalValueRef::BitVec(bv) => canonical(&bv.bit_string()),
                wellen::SignalValueRef::Real(x) => format!("real {x:?}"),
                wellen::SignalValueRef::String(t) => format!("string {t:?}"),
                wellen::SignalValueRef::Event => return Ok::<(), ()>(()),
            };
            let id = signal.index();
            if id == clock {
                rose |= clock_was == "0" && v == "1";
                clock_was = v.clone();
            }
            if id < current.len() {
                if current[id].as_ref() != Some(&v) {
                    dirty.push(id);
                }
                current[id] = Some(v);
            }
            Ok(())
        })
        .map_err(|e| match e {
            wellen::stream::StreamError::Wellen(e) => bad(&e),
            wellen::stream::StreamError::Callback(()) => bad(&"unreadable value"),
        })?;
        if rose {
            sample(&current, &mut dirty, &mut samples, cycles);
            cycles += 1;
        }
        if cycles == 0 {
            return Err(bad(&"the clock never rises"));
        }
        Ok(Trace {
            names,
            ranges,
            samples,
            cycles,
        })
    }

    /// Names with `skip` leading scopes dropped, to signals.
    fn named(&self, skip: usize) -> BTreeMap<String, usize> {
        self.named_ranges(skip)
            .into_iter()
            .map(|(n, (c, _))| (n, c))
            .collect()
    }

    /// Names with `skip` leading scopes dropped, to signals and ranges.
    fn named_ranges(&self, skip: usize) -> BTreeMap<String, (usize, Option<&str>)> {
        self.names
            .iter()
            .zip(&self.ranges)
            .filter(|((n, _), _)| n.len() > skip)
            .map(|((n, c), r)| (n[skip..].join("."), (*c, r.as_deref())))
            .collect()
    }

    /// The sampled value of `signal` at `cycle`.
    fn at(&self, signal: usize, cycle: u64) -> &str {
        let Some(s) = self.samples.get(&signal) else {
            return "x";
        };
        match s.partition_point(|(c, _)| *c <= cycle) {
            0 => "x",
            i => &s[i - 1].1,
        }
    }
}

/// One signal's first differing cycle.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SignalMismatch {
    pub cycle: u64,
    pub signal: String,
    pub a: String,
    pub b: String,
}

/// The outcome of a comparison.
#[derive(Debug, Clone)]
pub struct Comparison {
    pub compared: usize,
    /// Signals (aligned names) in one trace only.
    pub only_a: Vec<String>,
    pub only_b: Vec<String>,
    pub cycles_a: u64,
    pub cycles_b: u64,
    /// Each differing signal's first mismatch, earliest first.
    pub mismatches: Vec<SignalMismatch>,
}

impl Comparison {
    pub fn equal(&self) -> bool {
        self.mismatches.is_empty() && self.cycles_a == self.cycles_b
    }
}

/// Show a bit string as hex when it is all 0/1.
pub fn show(bits: &str) -> String {
    if bits.chars().all(|c| c == '0' || c == '1') && bits.len() <= 128 {
        format!("{:#x}", u128::from_str_radix(bits, 2).unwrap_or(0))
    } else {
        bits.to_string()
    }
}

/// Compare two traces over the signals whose aligned name matches `pattern`
/// (a glob; every signal when `None`).
pub fn compare(a: &Trace, b: &Trace, pattern: Option<&str>) -> Result<Comparison, BadTrace> {
    compare_from(a, 0, b, pattern)
}

/// [`compare`], with B's cycle 0 lined up with A's cycle `from` (B traced a
/// clock range of A's run: `cube sim --trace-clocks`). Mismatches and
/// `cycles_a` count from there.
pub fn compare_from(
    a: &Trace,
    from: u64,
    b: &Trace,
    pattern: Option<&str>,
) -> Result<Comparison, BadTrace> {
    let pat = pattern
        .map(glob::Pattern::new)
        .transpose()
        .map_err(|e| BadTrace(format!("--signals: {e}")))?;
    let mut best = (0, 0, 0);
    for sa in 0..3 {
        let na = a.named(sa);
        for sb in 0..3 {
            let nb = b.named(sb);
            let common = na.keys().filter(|k| nb.contains_key(*k)).count();
            if common > best.0 {
                best = (common, sa, sb);
            }
        }
    }
    let (na, nb) = (a.named(best.1), b.named(best.2));
    let (ra, rb) = (a.named_ranges(best.1), b.named_ranges(best.2));
    let keep = |k: &str| pat.as_ref().is_none_or(|p| p.matches(k));
    let common: Vec<&String> = na
        .keys()
        .filter(|k| nb.contains_key(*k) && keep(k))
        .collect();
    if common.is_empty() {
        return Err(BadTrace(
            "the traces have no signal in common (check --signals)".into(),
        ));
    }
    let cycles_a = a.cycles.saturating_sub(from);
    let cycles = cycles_a.min(b.cycles);
    let mut mismatches = Vec::new();
    for name in &common {
        let (ca, cb) = (na[*name], nb[*name]);
        // The bit range is part of a signal: `data [3:0]` is not
        // `data [7:4]`, whatever their values (a side without a range
        // matches any).
        if let (Some(x), Some(y)) = (ra[*name].1, rb[*name].1) {
            if x != y {
                mismatches.push(SignalMismatch {
                    cycle: 0,
                    signal: name.to_string(),
                    a: format!("bits {x}"),
                    b: format!("bits {y}"),
                });
                continue;
            }
        }
        // Cycles where either side changes: the only places a difference can start.
        let mut points: Vec<u64> = a
            .samples
            .get(&ca)
            .into_iter()
            .flatten()
            .filter_map(|(c, _)| c.checked_sub(from))
            .collect();
        points.extend(b.samples.get(&cb).into_iter().flatten().map(|(c, _)| *c));
        points.push(0);
        points.sort_unstable();
        points.dedup();
        if let Some(&c) = points
            .iter()
            .filter(|&&c| c < cycles)
            .find(|&&c| a.at(ca, c + from) != b.at(cb, c))
        {
            mismatches.push(SignalMismatch {
                cycle: c,
                signal: name.to_string(),
                a: a.at(ca, c + from).to_string(),
                b: b.at(cb, c).to_string(),
            });
        }
    }
    mismatches.sort_by(|x, y| (x.cycle, &x.signal).cmp(&(y.cycle, &y.signal)));
    Ok(Comparison {
        compared: common.len(),
        only_a: na
            .keys()
            .filter(|k| !nb.contains_key(*k) && keep(k))
            .cloned()
            .collect(),
        only_b: nb
            .keys()
            .filter(|k| !na.contains_key(*k) && keep(k))
            .cloned()
            .collect(),
        cycles_a,
        cycles_b: b.cycles,
        mismatches,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A header with a 1-bit clock `!` and an 8-bit `ctl` (`#`), then `body`.
    fn vcd(body: &str) -> String {
        format!(
            "$timescale 1ns $end\n$scope module uut $end\n$var wire 1 ! clock $end\n$var wire 8 # ctl $end\n$upscope $end\n$enddefinitions $end\n#0\n0!\nb0 #\n#5\n1!\n{body}\n#10\n0!\n"
        )
    }

    fn load(text: &str, clock: &str) -> Result<Trace, String> {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("t.vcd");
        std::fs::write(&path, text).unwrap();
        Trace::load_with_clock(&path, clock).map_err(|e| e.0)
    }

    /// Refused in one line naming the file and `line`, holding `needle`.
    fn refused(text: &str, line: usize, needle: &str) {
        let e = load(text, "clock").unwrap_err();
        assert!(!e.contains('\n'), "one line: {e}");
        assert!(e.contains("t.vcd: "), "the file: {e}");
        assert!(e.contains(&format!("line {line}:")), "line {line}: {e}");
        assert!(e.contains(needle), "'{needle}' not in: {e}");
    }

    #[test]
    fn what_wellen_panics_on_is_refused_naming_the_line() {
        load(&vcd("b1 #"), "clock").unwrap();
        load(&vcd("b11111111 #"), "clock").unwrap();
        load(&vcd("bx #\nbz1 #\nb0b101 #\n1#"), "clock").unwrap();
        refused(
            &vcd("b111111111 #"),
            12,
            "9 bits, wider than the 8-bit `ctl`",
        );
        refused(&vcd("b12 #"), 12, "`2` is not a bit");
        refused(&vcd("b1q #"), 12, "`q` is not a bit");
        refused(&vcd("bh1 #"), 12, "does not extend");
        refused(&vcd("b #"), 12, "an empty value");
        refused(&vcd("r1.5 #"), 12, "`r` is not a bit");
        refused(&vcd("b1q !"), 12, "`q` is not a bit");
        refused(&vcd("b10 !"), 12, "wider than the 1-bit `clock`");
        refused(&vcd("1%"), 12, "no $var declares");
        refused(&format!("{}b1", vcd("")), 15, "with no signal id");
        refused(&vcd("1"), 12, "with no signal id");
        refused(&vcd("q#"), 12, "not a time, a value or a command");
        let up = vcd("").replace(
            "$upscope $end\n",
            "$upscope $end\n$upscope $end\n$upscope $end\n",
        );
        refused(&up, 6, "an $upscope with no $scope open");
        let up = vcd("").replace(
            "$upscope $end\n",
            "$upscope $end\n$upscope $end\n$var wire 1 $ q $end\n",
        );
        refused(&up, 6, "an $upscope with no $scope open");
        refused(
            &vcd("").replace("module uut", ""),
            2,
            "a $scope with no type",
        );
        refused(
            &format!("$date a $end\n$date b $end\n{}", vcd("")),
            2,
            "a second $date",
        );
        refused(
            &format!("$version a $end\n$version b $end\n{}", vcd("")),
            2,
            "a second $version",
        );
        refused(
            &format!("$timescale 1ps $end\n{}", vcd("")),
            2,
            "a second $timescale",
        );
        refused(
            &vcd("").replace("wire 8 #", "wire 4294967295 #"),
            4,
            "4294967295 bits wide",
        );
        let real =
            vcd("r1.5 %\nr1e3 %\nr-2 %").replace("$upscope", "$var real 64 % f $end\n$upscope");
        load(&real, "clock").unwrap();
        refused(&real.replace("r-2", "rnan"), 15, "not a finite number");
        refused(&real.replace("r-2", "r1e400"), 15, "not a finite number");
        refused(&real.replace("r-2", "rx"), 15, "not a number");
        refused(&real.replace("r-2 %", "b1 %"), 15, "for the real `f`");
        refused(&real.replace("r-2 %", "1%"), 15, "for the real `f`");
        let string = vcd("shello %").replace("$upscope", "$var string 1 % s $end\n$upscope");
        load(&string, "clock").unwrap();
        refused(&string.replace("shello", "b1"), 13, "for the string `s`");
        // A `$end` inside a word ends its command, as wellen reads it; a
        // comment's words are not read.
        refused(
            "$scope module m $end $var wire 1 ! clock $end $upscope $end $enddefinitions $end",
            1,
            "no value changes",
        );
        load(
            &vcd("$comment b12 # $end").replace("clock $end", "clock$end"),
            "clock",
        )
        .unwrap();
    }

    #[test]
    fn the_clock_must_be_one_bit_wide() {
        let e = load(&vcd("b1 #"), "ctl").unwrap_err();
        assert!(
            e.contains("`ctl` is 8 bits wide") && e.contains("1-bit"),
            "{e}"
        );
        assert!(!e.contains('\n'), "{e}");
        let real = vcd("r1.5 %").replace("$upscope", "$var real 64 % f $end\n$upscope");
        let e = load(&real, "f").unwrap_err();
        assert!(e.contains("`f` is a real"), "{e}");
    }

    #[test]
    fn a_panic_of_the_reader_is_caught_silently() {
        let r = quietly(|| -> u32 { panic!("deep\ninside") });
        assert_eq!(r.unwrap_err(), "deep");
        assert_eq!(quietly(|| 7).unwrap(), 7);
        // An `$attrbegin` naming an enum table never declared: the scan
        // leaves attributes to wellen, which indexes a map with it.
        let text = vcd("").replace("$var wire 8", "$attrbegin misc 07 \"\" 5 $end\n$var wire 8");
        let e = load(&text, "clock").unwrap_err();
        assert!(e.contains("the trace reader failed"), "{e}");
        assert!(!e.contains('\n'), "{e}");
    }

    /// Issue 70 re-probe: reals and strings were not compared (two traces
    /// that differed only there were equal); a 0-bit wire's values were
    /// read as nothing; one name under two ids in a scope, and a bus's
    /// bit range, were lost.
    #[test]
    fn reals_strings_ranges_and_names_are_part_of_the_comparison() {
        let with = |var: &str, first: &str, second: &str| {
            format!(
                "$timescale 1ns $end\n$scope module uut $end\n$var wire 1 ! clock $end\n{var}\n$upscope $end\n$enddefinitions $end\n#0\n0!\n{first}\n#5\n1!\n#10\n0!\n{second}\n#15\n1!\n"
            )
        };
        let differ = |a: &str, b: &str, what: &str| {
            let (a, b) = (load(a, "clock").unwrap(), load(b, "clock").unwrap());
            let c = compare(&a, &b, None).unwrap();
            assert!(!c.equal(), "{what}: equal");
            assert_eq!(c.mismatches[0].signal, "uut.data", "{what}");
            assert!(compare(&a, &a, None).unwrap().equal(), "{what}: itself");
        };
        let real = "$var real 64 \" data $end";
        differ(
            &with(real, "r1.5 \"", "r2.5 \""),
            &with(real, "r1.5 \"", "r3.5 \""),
            "reals",
        );
        let string = "$var string 1 \" data $end";
        differ(
            &with(string, "sHello \"", "sx \""),
            &with(string, "sWorld \"", "sx \""),
            "strings",
        );
        differ(
            &with("$var wire 4 \" data [3:0] $end", "b0 \"", "b1 \""),
            &with("$var wire 4 \" data [7:4] $end", "b0 \"", "b1 \""),
            "ranges",
        );
        // A side without a range matches by name (rust-hdl writes none).
        let a = load(
            &with("$var wire 4 \" data [3:0] $end", "b0 \"", "b1 \""),
            "clock",
        )
        .unwrap();
        let b = load(&with("$var wire 4 \" data $end", "b0 \"", "b1 \""), "clock").unwrap();
        assert!(compare(&a, &b, None).unwrap().equal());
        refused(
            &with("$var wire 0 \" data $end", "b0000 \"", "b0 \""),
            4,
            "`data` is declared 0 bits wide",
        );
        refused(
            &with(
                "$var wire 4 \" data $end\n$var wire 4 # data $end",
                "b0 \"\nb1 #",
                "b1 \"",
            ),
            5,
            "`data` is declared again, under another id (first on line 4)",
        );
        // Also in a scope closed and opened again.
        refused(
            &with(
                "$scope module m $end\n$var wire 1 \" a $end\n$upscope $end\n$scope module m $end\n$var wire 1 # a $end\n$upscope $end",
                "0\"\n0#",
                "1#",
            ),
            8,
            "`a` is declared again, under another id (first on line 5)",
        );
        // The same id twice is an alias, and a bus declared bit by bit
        // names each bit.
        load(
            &with(
                "$var wire 4 \" data $end\n$var wire 4 \" data $end",
                "b0 \"",
                "b1 \"",
            ),
            "clock",
        )
        .unwrap();
        load(
            &with(
                "$var wire 1 \" data [0] $end\n$var wire 1 # data [1] $end",
                "0\"\n0#",
                "1\"",
            ),
            "clock",
        )
        .unwrap();
    }
}
