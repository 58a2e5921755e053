//! `cube volume`: the scene's volume as it is rendered (built-in or raw,
//! windowed, at the scene's voxel width) written as a raw file, so that
//! renderers outside the kit (the peers in `scripts/peers`) read the same
//! voxels; or, with `--layout dram`, as the memory image a Cube-4L build
//! reads from DRAM (`golden_model::cube4l::dram`), with its address map.

use crate::common::load;
use crate::output::Files;
use anyhow::{anyhow, Result};
use golden_model::cube4l::dram::DramLayout;
use std::path::PathBuf;

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum Layout {
    /// x fastest, then y, then z.
    Raw,
    /// One skewed copy per major axis, a beat of the scene's pipelines a
    /// word (docs/integration.md#the-volume-in-dram).
    Dram,
}

#[derive(clap::Args)]
pub struct VolumeArgs {
    #[arg(long)]
    scene: PathBuf,
    /// The file: one byte a voxel at 8-bit voxels, two (little-endian) at
    /// 12 and 16.
    #[arg(long)]
    out: PathBuf,
    #[arg(long, value_enum, default_value = "raw")]
    layout: Layout,
    /// `--layout dram`: the address map as JSON (each copy's base, words
    /// and strides).
    #[arg(long)]
    map: Option<PathBuf>,
}

pub fn run(args: VolumeArgs) -> Result<()> {
    let (scene, vol) = load(&args.scene)?;
    let mut files = Files::default();
    files.scene("--scene", &args.scene, &scene)?;
    files.output("--out", &args.out)?;
    if let Some(m) = &args.map {
        if args.layout != Layout::Dram {
            return Err(anyhow!("--map is the address map of --layout dram"));
        }
        files.output("--map", m)?;
    }
    let [nx, ny, nz] = vol.dims;
    match args.layout {
        Layout::Raw => {
            let (width, kind) = match vol.bits {
                8 => (1, "u8"),
                _ => (2, "u16 little-endian"),
            };
            let mut bytes = Vec::new();
            bytes
                .try_reserve_exact(vol.data.len() * width)
                .map_err(|_| {
                    anyhow!(
                        "--out: the {nx}x{ny}x{nz} volume's {} bytes are more memory than this process may have",
                        vol.data.len() * width
                    )
                })?;
            for v in &vol.data {
                bytes.extend_from_slice(&v.to_le_bytes()[..width]);
            }
            files.bytes(&args.out, &bytes)?;
            files.commit()?;
            println!(
                "{}: {nx}x{ny}x{nz} {kind} voxels, x fastest",
                args.out.display()
            );
        }
        Layout::Dram => {
            let p = scene.hardware.pipelines;
            let layout = DramLayout::new(vol.dims, vol.bits, p);
            let image = layout.image(&vol).map_err(|_| {
                anyhow!(
                    "--layout dram: the image of {nx}x{ny}x{nz} at p = {p} is {} bytes, more memory than this process may have",
                    layout.bytes
                )
            })?;
            files.bytes(&args.out, &image)?;
            if let Some(m) = &args.map {
                files.json(m, &map_json(&layout))?;
            }
            files.commit()?;
            println!(
                "{}: {} bytes, {nx}x{ny}x{nz} {}-byte voxels in three skewed copies (major axis x, y, z at {}), a word of {} bytes a beat of {p} pipelines",
                args.out.display(),
                layout.bytes,
                layout.voxel_bytes,
                layout.copies.map(|c| format!("{:#x}", c.base)).join(", "),
                layout.word_bytes,
            );
        }
    }
    Ok(())
}

/// The address map `--map` writes.
fn map_json(l: &DramLayout) -> serde_json::Value {
    let axis = |a: usize| ["x", "y", "z"][a];
    let copies: Vec<serde_json::Value> = l
        .copies
        .iter()
        .map(|c| {
            serde_json::json!({
                "major_axis": axis(c.axis),
                "pipeline_axes": c.perm.map(axis),
                "pipeline_dims": c.dims,
                "base": c.base,
                "words": c.words(),
                "beam_words": c.b,
                "slice_words": c.slab,
            })
        })
        .collect();
    serde_json::json!({
        "layout": "dram: one skewed copy per major axis, a beat of every pipeline a word",
        "pipelines": l.p,
        "voxel_bytes": l.voxel_bytes,
        "word_bytes": l.word_bytes,
        "align": golden_model::cube4l::dram::ALIGN,
        "bytes": l.bytes,
        "word": "module k's voxel at byte k*voxel_bytes, little-endian; a lane past its beam's end finds 0",
        "address": "base + (n_b + n_beam*beam_words + n_s*slice_words)*word_bytes at beat (slice n_s, beam n_beam, partial beam n_b) of a sweep along major_axis",
        "copies": copies,
    })
}
