//! `cube volume`: the scene's volume as it is rendered (built-in or raw,
//! windowed, at the scene's voxel width) written as a raw file, so that
//! renderers outside the kit (the peers in `scripts/peers`) read the same
//! voxels.

use crate::common::load;
use crate::output::Files;
use anyhow::Result;
use std::path::PathBuf;

#[derive(clap::Args)]
pub struct VolumeArgs {
    #[arg(long)]
    scene: PathBuf,
    /// The raw file: x fastest, then y, then z; one byte a voxel at 8-bit
    /// voxels, two (little-endian) at 12 and 16.
    #[arg(long)]
    out: PathBuf,
}

pub fn run(args: VolumeArgs) -> Result<()> {
    let (scene, vol) = load(&args.scene)?;
    let mut files = Files::default();
    files.scene("--scene", &args.scene, &scene)?;
    files.output("--out", &args.out)?;
    let (bytes, kind) = if vol.bits == 8 {
        (vol.data.iter().map(|&v| v as u8).collect::<Vec<u8>>(), "u8")
    } else {
        (
            vol.data.iter().flat_map(|v| v.to_le_bytes()).collect(),
            "u16 little-endian",
        )
    };
    files.bytes(&args.out, &bytes)?;
    files.commit()?;
    let [nx, ny, nz] = vol.dims;
    println!(
        "{}: {nx}x{ny}x{nz} {kind} voxels, x fastest",
        args.out.display()
    );
    Ok(())
}
