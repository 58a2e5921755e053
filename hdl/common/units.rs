//! What an architecture's units manifest (`cube4l::units`, `cube3::units`)
//! is made of: its optional [`Unit`]s, each with the configuration that
//! builds it and its instance names; the [`Layout`] of its emitted design
//! in stage files; and the Verilator [`lint_waivers`] of a design, with
//! those every emitted design needs. The `cosim` crate exports, prunes and
//! lints by them and names no instance of its own.

/// rust-hdl's name of the top module, the first segment of every module's
/// instance path (`top$lanes$2$shader`).
pub const TOP: &str = "top";

/// An optional unit of an architecture, over its configuration `C`.
#[derive(Debug, Clone, Copy)]
pub struct Unit<C: 'static> {
    /// Its name in reports (the export manifest's `units_left_out`).
    pub name: &'static str,
    /// Whether the configuration builds it.
    pub built: fn(&C) -> bool,
    /// The unit it sits in, as whether the configuration builds that: a
    /// unit is left out only where its parent is built (`None`: the design
    /// itself).
    pub within: Option<fn(&C) -> bool>,
    /// Its instance names, under their parents (`u$*`: every element of
    /// the array `u`), each checked against its struct by
    /// [`instance!`](crate::instance); empty for a unit that stays in the
    /// Verilog, disabled by constants, for synthesis to remove.
    pub instances: &'static [&'static str],
    /// The stage file of its first instance's module (of the modules that
    /// hold it, for a unit without instances).
    pub stage: &'static str,
}

/// A unit that a scene's hardware leaves out.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct LeftOut {
    pub name: &'static str,
    /// Its instance names, under their parents (`u$*`: every element of
    /// the array `u`); the emitted Verilog has no such instance. Empty for
    /// units that stay in the Verilog, disabled by constants, for synthesis
    /// to remove.
    pub instances: &'static [&'static str],
}

/// The units of `units` that configuration `c` leaves out, in order.
pub fn left_out<C>(units: &[Unit<C>], c: &C) -> Vec<LeftOut> {
    units
        .iter()
        .filter(|u| !(u.built)(c) && u.within.is_none_or(|w| w(c)))
        .map(|u| LeftOut {
            name: u.name,
            instances: u.instances,
        })
        .collect()
}

/// A segment of a [`Stage`]'s instance path.
#[derive(Debug, Clone, Copy)]
pub enum Seg {
    /// This instance.
    Is(&'static str),
    /// One of these instances.
    OneOf(&'static [&'static str]),
    /// Any instance (an array's index).
    Any,
    /// Any further segments, none included (only last).
    Rest,
}

/// The modules of a stage file: those whose instance path matches `path`.
/// (In a synthesis report's table, `CELL_STAGES`, `file` is the stage's
/// name and `path` a cell's, without the top.)
#[derive(Debug, Clone, Copy)]
pub struct Stage {
    pub path: &'static [Seg],
    pub file: &'static str,
}

/// The file of the first of `stages` whose path matches the instance
/// path `parts`.
pub fn stage_of(stages: &[Stage], parts: &[&str]) -> Option<&'static str> {
    stages.iter().find(|s| s.matches(parts)).map(|s| s.file)
}

impl Stage {
    fn matches(&self, parts: &[&str]) -> bool {
        let open = matches!(self.path.last(), Some(Seg::Rest));
        let fixed = &self.path[..self.path.len() - open as usize];
        let fits = if open {
            parts.len() >= fixed.len()
        } else {
            parts.len() == fixed.len()
        };
        fits && fixed.iter().zip(parts).all(|(s, p)| match s {
            Seg::Is(i) => i == p,
            Seg::OneOf(i) => i.contains(p),
            Seg::Any => true,
            Seg::Rest => unreachable!("a path's rest is its last segment"),
        })
    }
}

/// How an architecture's emitted design is laid out in files: the stage
/// files in reading order (the top first), the stages that say each
/// module's file (the first that matches; `other` when none does), and
/// the lint waivers every design of it needs beyond [`lint_waivers`]' own.
#[derive(Debug, Clone, Copy)]
pub struct Layout {
    pub files: &'static [&'static str],
    pub stages: &'static [Stage],
    pub other: &'static str,
    pub waivers: &'static str,
}

impl Layout {
    /// The file (one per stage) that holds module `name`. rust-hdl emits
    /// one module per instance, named by its path (`top$lanes$2$shader$lut`).
    pub fn stage_file(&self, name: &str) -> &'static str {
        let parts: Vec<&str> = name.split('$').collect();
        stage_of(self.stages, &parts).unwrap_or(self.other)
    }
}

/// Verilator's configuration for a design with `units` pruned: the
/// waivers every emitted design needs, the architecture's, and those of the
/// pruned units, whose parents still compute the inputs they would have
/// read. Each waiver is narrow (one rule, matched on the signal or file) and
/// explained. (Verilator's configuration lexer stumbles on parentheses and
/// paired apostrophes inside comments, so the comments avoid them.)
pub fn lint_waivers(units: &[LeftOut], layout: &Layout) -> String {
    let mut s = String::from(
        "`verilator_config\n// rust-hdl names every module by its instance path, as in top$cfb$lanes$0, and\n// the kit groups one stage's modules per file, so only top.v can carry its\n// module's name.\n",
    );
    for f in layout.files.iter().filter(|f| **f != "top.v") {
        s.push_str(&format!("lint_off -rule DECLFILENAME -file \"*{f}\"\n"));
    }
    s.push_str("// Memory modules, buffers and delay lines are as deep as the scene needs:\n// they take wide pointers and addresses and use only the low bits.\nlint_off -rule UNUSEDSIGNAL -file \"*\" -match \"*Bits of signal are not used: 'read_address'*\"\nlint_off -rule UNUSEDSIGNAL -file \"*\" -match \"*Bits of signal are not used: 'write_address'*\"\n");
    s.push_str("// The host port carries 64-bit words: a shader table keeps only the bit\n// fields of its entries, and the light and half registers three 16-bit\n// components.\nlint_off -rule UNUSEDSIGNAL -file \"*shader.v\" -match \"*Bits of signal are not used: 'host_data'*\"\nlint_off -rule UNUSEDSIGNAL -file \"*shader.v\" -match \"*Bits of signal are not used: 'write_data'*\"\nlint_off -rule UNUSEDSIGNAL -file \"*shader.v\" -match \"*Bits of signal are not used: 'regs$q$*'*\"\n");
    s.push_str("// The lighting's square tables and reciprocal-norm ROM are as deep as the\n// build's normal width: their addresses are as wide as the widest normal\n// and they decode the low bits.\nlint_off -rule UNUSEDSIGNAL -file \"*shader.v\" -match \"*Bits of signal are not used: 'address'*\"\n");
    s.push_str("// A registered product's port p sits in the unorm multiplier's instance\n// of the same name, which Verilator takes for a declaration it hides.\nlint_off -rule VARHIDDEN -file \"*\" -match \"*hides declaration in upper scope: 'p'*\"\n");
    s.push_str("// A product the build does not read is a constant register that ignores\n// its operands: the lighting's upper products at normals up to 5 bits.\nlint_off -rule UNUSEDSIGNAL -file \"*shader.v\" -match \"*Signal is not used: 'a'\"\nlint_off -rule UNUSEDSIGNAL -file \"*shader.v\" -match \"*Signal is not used: 'b'\"\n");
    s.push_str(layout.waivers);
    let instances: Vec<&str> = units
        .iter()
        .flat_map(|u| u.instances.iter().copied())
        .collect();
    if !instances.is_empty() {
        s.push_str("// Units this scene leaves out are gone, but their parents still compute\n// the inputs they would have read.\n");
        for i in instances {
            s.push_str(&format!(
                "lint_off -rule UNUSEDSIGNAL -file \"*\" -match \"*Signal is not used: '{i}$*\"\n"
            ));
        }
    }
    s
}

/// A signal group of a trace: its name and its signals.
pub type Wave = (String, Vec<String>);

/// The signals `names` of the scope `prefix` (`top.cfb`), each a name and
/// its bit range (`("n_s", "[15:0]")`, empty for a bit).
pub fn under(prefix: &str, names: &[(&str, &str)]) -> Vec<String> {
    names
        .iter()
        .map(|(n, bits)| format!("{prefix}.{n}{bits}"))
        .collect()
}

/// The name of a port every architecture's top has, checked against both
/// tops.
macro_rules! top_port {
    ($f:ident) => {{
        let _ = crate::instance!(crate::cube4l::Pipeline<1, 1, 1>, $f);
        crate::instance!(crate::cube3::Cube3System<1, 1, 1, 1>, $f)
    }};
}

/// The ports of every architecture's top that the harnesses and wrappers
/// drive and read: the clock, `start`, the load port's enable, the host
/// port (`golden_model::host`), and the external voxel memory's arrays of
/// a port per module.
pub const CLOCK: &str = top_port!(clock);
pub const START: &str = top_port!(start);
pub const LOAD_ENABLE: &str = top_port!(load_enable);
pub const HOST_WRITE: &str = top_port!(host_write);
pub const HOST_ADDRESS: &str = top_port!(host_address);
pub const HOST_DATA: &str = top_port!(host_data);
pub const EXT_ADDR: &str = top_port!(ext_addr);
pub const EXT_DATA: &str = top_port!(ext_data);
