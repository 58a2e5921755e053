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
