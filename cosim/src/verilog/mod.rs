//! The emitted Verilog as the kit writes it, for any architecture: made
//! width-clean (`width_clean.rs`), with the units the scene does not need
//! pruned (`prune.rs`), each module's outputs written once per pass
//! (`write_once.rs`), and split into its modules (`modules.rs`) and then
//! into one file per stage with lint waivers (`split.rs`), and the
//! integrable top around it (`wrapper.rs`).

mod modules;
mod prune;
mod split;
mod width_clean;
mod wrapper;
mod write_once;

pub use hdl::common::units::{lint_waivers, Layout, LeftOut};
pub use modules::{split_modules, Module};
pub use prune::{names, prune};
pub use split::write_stage_files;
pub use width_clean::width_clean;
pub use wrapper::wrapper;
pub use write_once::{outputs_written_twice, write_once};

/// rust-hdl's Verilog as the kit writes it: width-clean, without `units`,
/// and with each module's outputs written once per pass.
pub fn clean_verilog(emitted: &str, units: &[LeftOut]) -> Result<String, String> {
    Ok(write_once(&prune(&width_clean(emitted), units)?))
}

/// Address bits of an on-chip memory module: 2^16 voxels per module
/// (defined with the RAM that holds them).
pub use hdl::common::ram::ON_CHIP_BITS;

/// Where the voxels live.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Memory {
    /// p block-RAM modules, each as deep as its share of the volume (up to
    /// 2^16 voxels), loaded through the load port (or initialised, for
    /// simulation).
    OnChip,
    /// An external RAM on each lane's `ext_addr`/`ext_data` port; the
    /// on-chip modules are 2-word stubs.
    External,
}

impl Memory {
    /// On chip when every module fits 2^16 voxels.
    pub fn for_volume(dims: [usize; 3], p: usize) -> Memory {
        if dims[0].div_ceil(p) * dims[1] * dims[2] <= 1 << ON_CHIP_BITS {
            Memory::OnChip
        } else {
            Memory::External
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Memory::OnChip => "on-chip",
            Memory::External => "external",
        }
    }
}
