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

use std::collections::{BTreeMap, HashMap};
use std::path::Path;

/// A trace reduced to per-cycle samples of its signals.
#[derive(Debug, Clone)]
pub struct Trace {
    /// Full hierarchical name of each variable, with its signal's index.
    names: Vec<(Vec<String>, usize)>,
    /// Per signal: (cycle, value) at each cycle where the sampled value
    /// changed, starting with cycle 0.
    samples: HashMap<usize, Vec<(u64, String)>>,
    /// Rising clock edges seen.
    pub cycles: u64,
}

/// A bad trace file: unreadable, unparsable, or without a top clock.
#[derive(Debug, Clone)]
pub struct BadTrace(pub String);

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

/// Check, before parsing, that the header's `$scope`s nest at most `max`
/// deep (a scan of its words up to `$enddefinitions`). A file that does not
/// open as VCD text (FST, whose reader does not recurse) is not scanned.
fn scope_depth_within(path: &Path, max: usize) -> std::io::Result<()> {
    use std::io::BufRead;
    let mut f = std::io::BufReader::new(std::fs::File::open(path)?);
    let text = f
        .fill_buf()?
        .iter()
        .find(|b| !b.is_ascii_whitespace())
        .is_some_and(|&b| b == b'$');
    if !text {
        return Ok(());
    }
    let mut depth = 0usize;
    for line in f.split(b'\n') {
        for word in line?.split(|b| b.is_ascii_whitespace()) {
            match word {
                b"$scope" => {
                    depth += 1;
                    if depth > max {
                        return Err(std::io::Error::other(format!(
                            "scopes nest deeper than {max}"
                        )));
                    }
                }
                b"$upscope" => depth = depth.saturating_sub(1),
                b"$enddefinitions" => return Ok(()),
                _ => {}
            }
        }
    }
    Ok(())
}

impl Trace {
    /// Load a trace whose cycles are counted on the top's `clock`.
    pub fn load(path: &Path) -> Result<Trace, BadTrace> {
        Trace::load_with_clock(path, "clock")
    }

    /// Load a trace whose cycles are counted on `clock`: a signal's name
    /// (the shallowest of that name is taken) or its whole dotted path.
    pub fn load_with_clock(path: &Path, clock: &str) -> Result<Trace, BadTrace> {
        let bad = |e: &dyn std::fmt::Display| BadTrace(format!("{}: {e}", path.display()));
        // Refuse FIFOs and devices before opening: one with no writer would block.
        if !std::fs::metadata(path).map_err(|e| bad(&e))?.is_file() {
            return Err(bad(&"not a regular file"));
        }
        scope_depth_within(path, MAX_SCOPE_DEPTH).map_err(|e| bad(&e))?;
        let mut wave = wellen::stream::read_from_file(path, &wellen::LoadOptions::default())
            .map_err(|e| bad(&e))?;
        let h = wave.hierarchy();
        // Every variable's path (scopes, then its name without a bit
        // range) and its signal: aliases share one signal.
        let names: Vec<(Vec<String>, usize)> = h
            .all_vars()
            .map(|v| {
                let var = &h[v];
                let mut full: Vec<String> = var.full_name(h).split('.').map(plain).collect();
                if let Some(last) = full.last_mut() {
                    *last = plain(var.name(h));
                }
                (full, var.signal_ref().index())
            })
            .collect();
        // The clock: the shallowest variable of that name, or that path.
        let clock = names
            .iter()
            .filter(|(n, _)| n.last().is_some_and(|l| l == clock) || n.join(".") == clock)
            .min_by_key(|(n, _)| n.len())
            .map(|(_, c)| *c)
            .ok_or_else(|| {
                bad(&format!(
                    "no `{clock}` signal (name the clock with --clock)"
                ))
            })?;
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
            let v = match value {
                wellen::SignalValueRef::BitVec(bv) => canonical(&bv.bit_string()),
                _ => return Ok::<(), ()>(()),
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
            samples,
            cycles,
        })
    }

    /// Names with `skip` leading scopes dropped, to signals.
    fn named(&self, skip: usize) -> BTreeMap<String, usize> {
        self.names
            .iter()
            .filter(|(n, _)| n.len() > skip)
            .map(|(n, c)| (n[skip..].join("."), *c))
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
