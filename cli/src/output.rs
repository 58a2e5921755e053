//! Whole-or-nothing output files: written to a temporary file beside the
//! target, then renamed over it.

use anyhow::{Context, Result};
use scene::Image;
use std::io::Write;
use std::path::Path;

fn atomic_write(path: &Path, write: impl FnOnce(&mut std::fs::File) -> Result<()>) -> Result<()> {
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
    let name = path
        .file_name()
        .with_context(|| format!("{} is not a file path", path.display()))?;
    let tmp = dir.join(format!(
        ".{}.tmp{}",
        name.to_string_lossy(),
        std::process::id()
    ));
    let result = (|| {
        let mut f =
            std::fs::File::create(&tmp).with_context(|| format!("creating {}", tmp.display()))?;
        write(&mut f)?;
        f.sync_all()?;
        std::fs::rename(&tmp, path).with_context(|| format!("renaming to {}", path.display()))
    })();
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result
}

pub fn write_png(path: &Path, img: &Image) -> Result<()> {
    let buf = image::RgbImage::from_raw(img.width, img.height, img.to_rgb8())
        .context("image buffer size")?;
    atomic_write(path, |f| {
        let mut w = std::io::BufWriter::new(f);
        buf.write_to(&mut w, image::ImageFormat::Png)
            .with_context(|| format!("encoding {}", path.display()))?;
        w.flush()?;
        Ok(())
    })
}

pub fn write_json(path: &Path, v: &serde_json::Value) -> Result<()> {
    atomic_write(path, |f| {
        serde_json::to_writer_pretty(&mut *f, v)?;
        f.write_all(b"\n")?;
        Ok(())
    })
}

pub fn write_text(path: &Path, text: &str) -> Result<()> {
    atomic_write(path, |f| {
        f.write_all(text.as_bytes())?;
        Ok(())
    })
}
