//! The architectures the kit knows, by name: the one place a run-time
//! choice (`cube sim --arch cube3`) becomes a type.

use crate::arch::Arch;
use crate::cube3::Cube3;
use crate::cube4l::Cube4l;
use crate::verilog::Layout;

/// Every architecture's part name and export layout (an export directory
/// holds what one of them writes).
pub const LAYOUTS: [(&str, Layout); 2] =
    [(Cube4l::PART, Cube4l::LAYOUT), (Cube3::PART, Cube3::LAYOUT)];

/// The architectures, by name.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ArchName {
    Cube4l,
    Cube3,
}

/// Work for an architecture known only at run time: [`ArchName::with`]
/// calls `run::<A>`.
pub trait ForArch {
    type Output;
    fn run<A: Arch>(self) -> Self::Output;
}

impl ArchName {
    pub fn name(self) -> &'static str {
        match self {
            ArchName::Cube4l => Cube4l::NAME,
            ArchName::Cube3 => Cube3::NAME,
        }
    }

    /// Run `f` for this architecture.
    pub fn with<F: ForArch>(self, f: F) -> F::Output {
        match self {
            ArchName::Cube4l => f.run::<Cube4l>(),
            ArchName::Cube3 => f.run::<Cube3>(),
        }
    }
}

#[cfg(test)]
mod tests {
    use hdl::common::units::{Layout, Unit};
    use std::path::Path;

    /// Every unit of `units` whose first instance's module is in a
    /// committed export of `arch` sits in the stage file the manifest
    /// names; returns how many units were found.
    fn check<C>(arch: &str, units: &[Unit<C>], layout: &Layout) -> usize {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../generated_verilog");
        let mut found = std::collections::BTreeSet::new();
        for build in std::fs::read_dir(root.join(arch)).unwrap() {
            let dir = build.unwrap().path();
            for file in layout.files {
                let Ok(text) = std::fs::read_to_string(dir.join(file)) else {
                    continue;
                };
                for m in crate::verilog::split_modules(&text) {
                    let parts: Vec<&str> = m.name.split('$').collect();
                    let leaf = match parts.as_slice() {
                        [.., a, i] if i.bytes().all(|b| b.is_ascii_digit()) => *a,
                        [.., l] => *l,
                        [] => continue,
                    };
                    for u in units {
                        let first = u.instances.first().map(|i| i.trim_end_matches("$*"));
                        if first == Some(leaf) {
                            assert_eq!((u.name, *file), (u.name, u.stage), "{arch}: {}", m.name);
                            found.insert(u.name);
                        }
                    }
                }
            }
        }
        found.len()
    }

    #[test]
    fn each_unit_sits_in_its_stage_file() {
        use hdl::{cube3, cube4l};
        assert!(check("cube4l", cube4l::units::UNITS, &cube4l::units::LAYOUT) >= 4);
        assert!(check("cube3", cube3::units::UNITS, &cube3::units::LAYOUT) >= 6);
    }
}
