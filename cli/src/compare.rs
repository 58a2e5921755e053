//! `cube compare`: the error of an image made elsewhere (a peer renderer,
//! an earlier run) against the scene's float reference, with the metrics
//! every `render --compare-reference` reports.

use crate::common::{check_step, error_json, error_line, load, render_arch};
use crate::methods::Arch;
use crate::output::Files;
use anyhow::{bail, Context, Result};
use reference::metrics::{compare, difference};
use scene::volume::Ordered;
use scene::Image;
use serde_json::json;
use std::path::{Path, PathBuf};

#[derive(clap::Args)]
pub struct CompareArgs {
    #[arg(long)]
    scene: PathBuf,
    /// The image to judge: a PNG of the scene's image size, row 0 at the top,
    /// 8-bit channels read as linear values in [0, 1].
    #[arg(long)]
    image: PathBuf,
    #[arg(long)]
    json: Option<PathBuf>,
    /// Difference image against the reference (x8).
    #[arg(long)]
    diff: Option<PathBuf>,
    #[arg(long, default_value_t = reference::DEFAULT_STEP, allow_negative_numbers = true)]
    ref_step: f64,
}

pub fn run(args: CompareArgs) -> Result<()> {
    check_step(args.ref_step)?;
    let (scene, vol) = load(&args.scene)?;
    let mut files = Files::default();
    files.scene("--scene", &args.scene, &scene)?;
    files.input("--image", &args.image)?;
    for (flag, path) in [("--json", &args.json), ("--diff", &args.diff)] {
        if let Some(p) = path {
            files.output(flag, p)?;
        }
    }
    let img = read_png(&args.image, scene.image)?;
    let r = render_arch(
        &scene,
        &Ordered::new(&vol),
        Arch::Reference,
        args.ref_step,
        None,
    )?;
    let m = compare(&img, &r.image);
    println!(
        "{}: {} (reference {:.3} s)",
        args.image.display(),
        error_line(&m),
        r.seconds
    );
    if let Some(d) = &args.diff {
        files.png(d, &difference(&img, &r.image, 8.0))?;
    }
    if let Some(j) = &args.json {
        files.json(
            j,
            &json!({
                "scene": args.scene.display().to_string(),
                "image": args.image.display().to_string(),
                "error": error_json(&m),
                "reference_seconds": r.seconds,
                "ref_step": args.ref_step,
            }),
        )?;
    }
    files.commit()
}

/// The image to judge, of the scene's size `[w, h]` (checked from its
/// header, before any pixel is decoded). An alpha channel is composited on
/// black, as the kit's renderers composite, and said so.
fn read_png(path: &std::path::Path, [w, h]: [u32; 2]) -> Result<Image> {
    let meta = std::fs::metadata(path).with_context(|| format!("reading {}", path.display()))?;
    if !meta.is_file() {
        bail!("{} is not a regular file", path.display());
    }
    let open = || -> Result<_> {
        image::ImageReader::open(path)
            .with_context(|| format!("reading {}", path.display()))?
            .with_guessed_format()
            .with_context(|| format!("reading {}", path.display()))
    };
    // The header alone, without the decoder's memory limit (it refuses a
    // 2^31 x 1 header as "Memory limit exceeded" before the size can be
    // named); the pixels are decoded, under the limit, only at the scene's
    // size.
    let mut header = open()?;
    header.no_limits();
    // The png crate refuses some sizes (4294967295 x 4294967295) even
    // without limits; a PNG's size is then read from its IHDR chunk.
    let (width, height) = match header.into_dimensions() {
        Ok(d) => d,
        Err(e) => png_size(path)
            .ok_or(e)
            .with_context(|| format!("decoding {} as an image", path.display()))?,
    };
    if (width, height) != (w, h) {
        bail!(
            "{} is {width}x{height}; the scene's image is {w}x{h}",
            path.display()
        );
    }
    let decoded = open()?
        .decode()
        .with_context(|| format!("decoding {} as an image", path.display()))?;
    let alpha = decoded.color().has_alpha();
    let rgba = decoded.to_rgba8();
    if alpha && rgba.pixels().any(|p| p.0[3] < 255) {
        println!(
            "note: {} has transparent pixels: composited on black",
            path.display()
        );
    }
    Ok(Image {
        width,
        height,
        rgb: rgba
            .pixels()
            .map(|p| {
                let a = p.0[3] as f64 / 255.0;
                [0, 1, 2].map(|c| p.0[c] as f64 / 255.0 * a)
            })
            .collect(),
    })
}

/// A PNG's width and height from its IHDR chunk (the first, right after
/// the signature); none when the file does not begin as a PNG does.
fn png_size(path: &Path) -> Option<(u32, u32)> {
    use std::io::Read;
    let mut head = [0u8; 24];
    std::fs::File::open(path).ok()?.read_exact(&mut head).ok()?;
    let be = |at: usize| u32::from_be_bytes(head[at..at + 4].try_into().unwrap());
    (head[..8] == *b"\x89PNG\r\n\x1a\n" && &head[12..16] == b"IHDR").then(|| (be(16), be(20)))
}
