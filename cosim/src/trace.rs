//! Traces as a user asks for them: VCD or FST by the file's extension,
//! limited by scope, depth and clock range, with every simulation of a run
//! (a multi-sweep scene's memory loads) one after another in one file.
//!
//! Each engine first writes a VCD of its simulation into a scratch file:
//! rust-hdl's tracer, Icarus's `$dumpvars`, Verilator's `VerilatedVcdC`
//! (Verilator dumps only the asked clock range, so a full frame's trace of
//! a few clocks stays small). [`finish`] then streams those VCDs with
//! `wellen` into the file asked for, written with `fst-writer` or the `vcd`
//! crate, keeping only the signals and clocks the [`Limits`] name.
//!
//! Times are the engines' own: clock `t` spans `[10t, 10t + 10)`, its rising
//! edge at `10t + 5`. A later simulation of the run continues at the clock
//! after the previous one's last.

use hdl::common::units::{CLOCK, START};
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use wellen::{Hierarchy, ItemRef, SignalEncoding, SignalRef, SignalValueRef};

/// Time units of one clock in every engine's trace.
pub const CLOCK_TIME: u64 = 10;

/// A trace file's format.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    Vcd,
    Fst,
}

impl Format {
    /// The format a file's extension names: `.vcd` or `.fst`; anything else
    /// is an error, never a file written in the other format.
    pub fn of(path: &Path) -> Result<Format, String> {
        match path.extension().and_then(|e| e.to_str()) {
            Some("vcd") => Ok(Format::Vcd),
            Some("fst") => Ok(Format::Fst),
            _ => Err(format!(
                "{}: a trace's name ends in .vcd or .fst (its format)",
                path.display()
            )),
        }
    }
}

/// What a trace keeps. The top's `clock` and `start` are always kept.
#[derive(Debug, Clone, Default)]
pub struct Limits {
    /// Globs on a signal's dotted name below the design's top (`lanes$0.*`,
    /// `*shader*`); a signal is kept when any matches. Empty: every signal.
    pub scopes: Vec<glob::Pattern>,
    /// The deepest module below the top whose signals are kept (0: the
    /// top's own ports and registers).
    pub depth: Option<usize>,
    /// Clocks kept, `[first, end)`, counted from the run's first clock.
    pub clocks: Option<(u64, u64)>,
}

impl Limits {
    /// Whether a signal `below` the top (its scopes and name) is kept.
    fn keeps(&self, below: &[&str]) -> bool {
        if let [name] = below {
            if *name == CLOCK || *name == START {
                return true;
            }
        }
        let depth_ok = self.depth.is_none_or(|d| below.len() <= d + 1);
        let dotted = below.join(".");
        let scope_ok = self.scopes.is_empty() || self.scopes.iter().any(|p| p.matches(&dotted));
        depth_ok && scope_ok
    }

    /// The range of times kept, `[from, to)`.
    fn times(&self) -> (u64, u64) {
        self.clocks.map_or((0, u64::MAX), |(a, b)| {
            (a.saturating_mul(CLOCK_TIME), b.saturating_mul(CLOCK_TIME))
        })
    }
}

/// A trace to write: where, in which format, and what it keeps.
#[derive(Debug, Clone)]
pub struct Request {
    /// Where the trace is written.
    pub path: PathBuf,
    pub format: Format,
    pub limits: Limits,
    /// Where the caller moves it once written (a trace is written whole
    /// through a temporary name), which its save file names.
    pub lands_at: Option<PathBuf>,
}

impl Request {
    /// A trace at `path`, its format from the extension.
    pub fn new(path: &Path, limits: Limits) -> Result<Request, String> {
        if let Some((a, b)) = limits.clocks {
            if a >= b {
                return Err(format!("trace clocks {a}..{b}: an empty range"));
            }
        }
        Ok(Request {
            path: path.to_path_buf(),
            format: Format::of(path)?,
            limits,
            lands_at: None,
        })
    }
}

/// What [`finish`] wrote.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Written {
    /// Signals kept, of those the engine traced.
    pub signals: usize,
    pub of: usize,
    /// Simulations one after another in the file.
    pub parts: usize,
    /// The file's size.
    pub bytes: u64,
    /// The traced span in clocks, `[first, end)`.
    pub clocks: (u64, u64),
    /// The clock of the first part's first `start`, where an engineer looks
    /// first (before it the host writes its registers and tables, and every
    /// stage is idle); none when the trace holds no start.
    pub first_start: Option<u64>,
}

/// The clock of the first rising edge at which `signal` (a 1-bit variable,
/// by full name) is 1 in the engine trace `raw`: the stream stops there, so
/// only the trace up to it is read.
fn first_high(raw: &Path, signal: &str) -> Option<u64> {
    let opts = wellen::LoadOptions::default();
    let mut wave = wellen::stream::read_from_file(raw, &opts).ok()?;
    let h = wave.hierarchy();
    let sig = h
        .all_vars()
        .map(|v| &h[v])
        .find(|v| v.full_name(h) == signal)?
        .signal_ref();
    let mut found = None;
    let _ = wave.stream_changes(
        wellen::stream::Filter::include_signals(&[sig]),
        |t, _, value| -> Result<(), &'static str> {
            match value {
                SignalValueRef::BitVec(bv) if bv.bit_string() == "1" => {
                    found = Some(t / CLOCK_TIME);
                    Err("found")
                }
                _ => Ok(()),
            }
        },
    );
    found
}

/// A kept variable of the first part: its place in the output hierarchy.
struct Kept {
    full: String,
    width: u32,
    /// The first kept variable on the same signal (Verilator traces a port
    /// and its copies in the parents as one): this one is declared as its
    /// alias and gets no value changes of its own.
    alias_of: Option<usize>,
}

/// The output's hierarchy as the first trace's is walked.
#[derive(Default)]
struct Outline {
    nodes: Vec<Node>,
    kept: Vec<Kept>,
    /// Variables seen.
    of: usize,
    /// The first kept variable of each signal.
    first_of: HashMap<SignalRef, usize>,
}

/// Stream the engine traces `raws` (one per simulation, in order; the
/// design's top at the dotted scope `top`) into `req.path`. `clocks` is the
/// run's length in clocks (0 when unknown: the traces' own end). The engine
/// traces are scratch files: one, whole and in the format asked for, is
/// moved into place as it is.
pub fn finish(raws: &[PathBuf], top: &str, req: &Request, clocks: u64) -> Result<Written, String> {
    let first = raws.first().ok_or("no trace to write")?;
    let opts = wellen::LoadOptions::default();
    let open = |p: &Path| {
        wellen::stream::read_from_file(p, &opts).map_err(|e| format!("{}: {e}", p.display()))
    };
    let first_start = first_high(first, &format!("{top}.{START}"));
    let head = open(first)?;
    let h = head.hierarchy();
    let whole =
        req.limits.scopes.is_empty() && req.limits.depth.is_none() && req.limits.clocks.is_none();
    if raws.len() == 1 && whole && Format::of(first).ok() == Some(req.format) {
        let vars = h.all_vars().count();
        drop(head);
        std::fs::rename(first, &req.path)
            .or_else(|_| std::fs::copy(first, &req.path).map(|_| ()))
            .map_err(|e| format!("{}: {e}", req.path.display()))?;
        let bytes = std::fs::metadata(&req.path).map_or(0, |m| m.len());
        return Ok(Written {
            signals: vars,
            of: vars,
            parts: 1,
            bytes,
            clocks: (0, clocks),
            first_start,
        });
    }
    let top_path: Vec<&str> = top.split('.').collect();
    // The output hierarchy: the first part's, pruned to the kept variables.
    let mut outline = Outline::default();
    for item in h.items() {
        walk(
            h,
            item,
            &mut Vec::new(),
            &top_path,
            &req.limits,
            &mut outline,
        );
    }
    let Outline {
        nodes, kept, of, ..
    } = outline;
    let always = [format!("{top}.clock"), format!("{top}.start")];
    if kept.iter().all(|k| always.contains(&k.full)) {
        return Err(format!(
            "{}: the trace limits keep no signal (scopes are globs on names below the top, e.g. 'lanes$0.*')",
            req.path.display()
        ));
    }
    let mut sink = Sink::open(req, &nodes, &kept)?;
    let (from, to) = req.limits.times();
    let mut offset = 0u64;
    let mut last_time = 0u64;
    for raw in raws {
        let mut wave = open(raw)?;
        let h = wave.hierarchy();
        // This part's signals onto the output's, by full name (an alias
        // shares its first variable's changes).
        let by_name: HashMap<&str, usize> = kept
            .iter()
            .enumerate()
            .filter(|(_, k)| k.alias_of.is_none())
            .map(|(i, k)| (k.full.as_str(), i))
            .collect();
        let mut map: HashMap<SignalRef, Vec<usize>> = HashMap::new();
        for v in h.all_vars() {
            let var = &h[v];
            if let Some(&i) = by_name.get(var.full_name(h).as_str()) {
                map.entry(var.signal_ref()).or_default().push(i);
            }
        }
        let signals: Vec<SignalRef> = map.keys().copied().collect();
        // Values before `from`, emitted all at once when it is reached.
        let mut held: HashMap<usize, String> = HashMap::new();
        let mut started = false;
        let mut now = None;
        let mut end = offset;
        let result = wave.stream_changes(
            wellen::stream::Filter::include_signals(&signals),
            |t, signal, value| -> Result<(), String> {
                let t = t + offset;
                end = end.max(t);
                let SignalValueRef::BitVec(bv) = value else {
                    return Ok(());
                };
                let Some(outs) = map.get(&signal) else {
                    return Ok(());
                };
                if t >= to {
                    return Ok(());
                }
                if t < from {
                    for &o in outs {
                        held.insert(o, bv.bit_string());
                    }
                    return Ok(());
                }
                if !started {
                    started = true;
                    let at = from.max(offset);
                    if !held.is_empty() {
                        sink.time(at)?;
                        now = Some(at);
                        let mut h: Vec<_> = held.drain().collect();
                        h.sort();
                        for (o, v) in h {
                            sink.change(o, &v, kept[o].width)?;
                        }
                    }
                }
                if now != Some(t) {
                    sink.time(t)?;
                    now = Some(t);
                }
                let bits = bv.bit_string();
                for &o in outs {
                    sink.change(o, &bits, kept[o].width)?;
                }
                Ok(())
            },
        );
        result.map_err(|e| match e {
            wellen::stream::StreamError::Wellen(e) => format!("{}: {e}", raw.display()),
            wellen::stream::StreamError::Callback(e) => e,
        })?;
        last_time = last_time.max(end);
        // The next simulation starts at the clock after this one's last.
        offset = (end / CLOCK_TIME + 1) * CLOCK_TIME;
    }
    let span_end = clocks.max(last_time / CLOCK_TIME).min(to / CLOCK_TIME);
    sink.close()?;
    let bytes = std::fs::metadata(&req.path)
        .map_err(|e| format!("{}: {e}", req.path.display()))?
        .len();
    Ok(Written {
        signals: kept.len(),
        of,
        parts: raws.len(),
        bytes,
        clocks: (from / CLOCK_TIME, span_end),
        first_start: first_start.filter(|&c| c >= from / CLOCK_TIME && c < span_end),
    })
}

/// One line of the output's hierarchy.
enum Node {
    Scope(String),
    Var {
        name: String,
        width: u32,
        index: Option<(i64, i64)>,
    },
    Up,
}

/// Add `item` (below the scopes `path`) to `outline` when it is, or holds,
/// a kept variable.
fn walk<'a>(
    h: &'a Hierarchy,
    item: ItemRef,
    path: &mut Vec<&'a str>,
    top: &[&str],
    limits: &Limits,
    outline: &mut Outline,
) {
    match item {
        ItemRef::Scope(s) => {
            let scope = &h[s];
            let children: Vec<ItemRef> = scope.items(h).collect();
            // wellen reads a memory's words (`mem[0]`, `mem[1]`...) as a
            // scope `mem` of variables `[0]`, `[1]`...: they stay words of
            // the scope they are in.
            let words = !children.is_empty()
                && children.iter().all(|c| match c {
                    ItemRef::Var(v) => h[*v].name(h).starts_with('['),
                    ItemRef::Scope(_) => false,
                });
            if words {
                for child in children {
                    if let ItemRef::Var(v) = child {
                        let name = format!("{}{}", scope.name(h), h[v].name(h));
                        add_var(h, v, name, path, top, limits, outline);
                    }
                }
                return;
            }
            path.push(scope.name(h));
            let mark = outline.nodes.len();
            outline.nodes.push(Node::Scope(scope.name(h).to_string()));
            for child in children {
                walk(h, child, path, top, limits, outline);
            }
            if outline.nodes.len() == mark + 1 {
                outline.nodes.pop();
            } else {
                outline.nodes.push(Node::Up);
            }
            path.pop();
        }
        ItemRef::Var(v) => add_var(h, v, h[v].name(h).to_string(), path, top, limits, outline),
    }
}

/// Add the variable `v`, named `name` below the scopes `path`, to
/// `outline` when the limits keep it.
fn add_var(
    h: &Hierarchy,
    v: wellen::VarRef,
    name: String,
    path: &[&str],
    top: &[&str],
    limits: &Limits,
    outline: &mut Outline,
) {
    let var = &h[v];
    outline.of += 1;
    let SignalEncoding::BitVector(width) = var.signal_encoding(h) else {
        return;
    };
    let keep = match path.strip_prefix(top) {
        Some(below) => {
            let mut b: Vec<&str> = below.to_vec();
            b.push(&name);
            limits.keeps(&b)
        }
        // Outside the design's top: the harness's own signals.
        None => limits.scopes.is_empty() && limits.depth.is_none(),
    };
    if keep {
        let i = outline.kept.len();
        let alias_of = outline.first_of.get(&var.signal_ref()).copied();
        outline.first_of.entry(var.signal_ref()).or_insert(i);
        outline.nodes.push(Node::Var {
            name,
            width,
            index: var.index().map(|i| (i.msb(), i.lsb())),
        });
        outline.kept.push(Kept {
            full: var.full_name(h),
            width,
            alias_of,
        });
    }
}

/// The output file being written.
enum Sink {
    Fst {
        body: Box<fst_writer::FstBodyWriter<std::io::BufWriter<std::fs::File>>>,
        ids: Vec<fst_writer::FstSignalId>,
    },
    Vcd {
        w: vcd::Writer<std::io::BufWriter<std::fs::File>>,
        ids: Vec<vcd::IdCode>,
    },
}

/// FST value changes are buffered in memory; a block is written out when
/// this much has gathered.
const FST_FLUSH_BYTES: usize = 32 << 20;

impl Sink {
    fn open(req: &Request, outline: &[Node], kept: &[Kept]) -> Result<Sink, String> {
        let io = |e: &dyn std::fmt::Display| format!("{}: {e}", req.path.display());
        match req.format {
            Format::Fst => {
                let info = fst_writer::FstInfo {
                    start_time: 0,
                    timescale_exponent: -12,
                    version: "cube".into(),
                    date: String::new(),
                    file_type: fst_writer::FstFileType::Verilog,
                };
                let mut head = fst_writer::open_fst(&req.path, &info).map_err(|e| io(&e))?;
                let mut ids = Vec::new();
                for node in outline {
                    match node {
                        Node::Scope(name) => head
                            .scope(name, "", fst_writer::FstScopeType::Module)
                            .map_err(|e| io(&e))?,
                        Node::Up => head.up_scope().map_err(|e| io(&e))?,
                        Node::Var {
                            name, width, index, ..
                        } => {
                            let name = match index {
                                Some((m, l)) => format!("{name} [{m}:{l}]"),
                                _ => name.clone(),
                            };
                            let alias = kept[ids.len()].alias_of.map(|a| ids[a]);
                            ids.push(
                                head.var(
                                    name,
                                    fst_writer::FstSignalType::bit_vec(*width),
                                    fst_writer::FstVarType::Wire,
                                    fst_writer::FstVarDirection::Implicit,
                                    alias,
                                )
                                .map_err(|e| io(&e))?,
                            );
                        }
                    }
                }
                let body = head.finish().map_err(|e| io(&e))?;
                Ok(Sink::Fst {
                    body: Box::new(body),
                    ids,
                })
            }
            Format::Vcd => {
                let f = std::fs::File::create(&req.path).map_err(|e| io(&e))?;
                let mut w = vcd::Writer::new(std::io::BufWriter::new(f));
                let mut ids = Vec::new();
                (|| -> std::io::Result<()> {
                    w.timescale(1, vcd::TimescaleUnit::PS)?;
                    for node in outline {
                        match node {
                            Node::Scope(name) => w.add_module(name)?,
                            Node::Up => w.upscope()?,
                            Node::Var {
                                name, width, index, ..
                            } => {
                                let index = index
                                    .map(|(m, l)| vcd::ReferenceIndex::Range(m as i32, l as i32));
                                let id = match kept[ids.len()].alias_of {
                                    Some(a) => {
                                        w.var_def(vcd::VarType::Wire, *width, ids[a], name, index)?;
                                        ids[a]
                                    }
                                    None => w.add_var(vcd::VarType::Wire, *width, name, index)?,
                                };
                                ids.push(id);
                            }
                        }
                    }
                    w.enddefinitions()
                })()
                .map_err(|e| io(&e))?;
                Ok(Sink::Vcd { w, ids })
            }
        }
    }

    fn time(&mut self, t: u64) -> Result<(), String> {
        match self {
            Sink::Fst { body, .. } => {
                if body.size() >= FST_FLUSH_BYTES {
                    body.flush().map_err(|e| e.to_string())?;
                }
                body.time_change(t).map_err(|e| e.to_string())
            }
            Sink::Vcd { w, .. } => w.timestamp(t).map_err(|e| e.to_string()),
        }
    }

    fn change(&mut self, out: usize, bits: &str, width: u32) -> Result<(), String> {
        match self {
            Sink::Fst { body, ids } => body
                .signal_change(ids[out], bits.as_bytes())
                .map_err(|e| e.to_string()),
            Sink::Vcd { w, ids } => {
                let mut v = bits.bytes().map(|b| match b {
                    b'0' => vcd::Value::V0,
                    b'1' => vcd::Value::V1,
                    b'z' | b'Z' => vcd::Value::Z,
                    _ => vcd::Value::X,
                });
                if width == 1 {
                    w.change_scalar(ids[out], v.next_back().unwrap_or(vcd::Value::X))
                } else {
                    w.change_vector(ids[out], v)
                }
                .map_err(|e| e.to_string())
            }
        }
    }

    fn close(self) -> Result<(), String> {
        match self {
            Sink::Fst { body, .. } => (*body).finish().map(|_| ()).map_err(|e| e.to_string()),
            Sink::Vcd { mut w, .. } => w.flush().map_err(|e| e.to_string()),
        }
    }
}
