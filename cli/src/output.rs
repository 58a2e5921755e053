//! Whole-or-nothing output files: written to a temporary file beside the
//! target, then renamed over it. A target that is a FIFO or a device
//! (`/dev/stdout`, `/dev/null`, a named pipe) is written through, never
//! replaced; a directory is refused.

use anyhow::{bail, Context, Result};
use scene::Image;
use std::io::Write;
use std::path::Path;

/// What an output path names now.
pub enum Target {
    /// Nothing, or a regular file: written whole or not at all.
    File,
    /// A FIFO, a character device or a socket: written through.
    Special,
}

/// Check an output path before any work is done for it.
pub fn check_target(path: &Path) -> Result<Target> {
    match std::fs::metadata(path) {
        Ok(m) if m.is_dir() => bail!("{} is a directory, not a file", path.display()),
        Ok(m) if !m.is_file() => Ok(Target::Special),
        _ => Ok(Target::File),
    }
}

/// Open a special file for writing. A FIFO is opened without blocking, so
/// one with no reader is an error rather than a hang.
fn open_special(path: &Path) -> Result<std::fs::File> {
    use std::os::unix::fs::OpenOptionsExt;
    use std::os::unix::io::AsRawFd;
    let f = std::fs::OpenOptions::new()
        .write(true)
        .custom_flags(libc::O_NONBLOCK)
        .open(path)
        .with_context(|| format!("opening {} (a FIFO needs a reader)", path.display()))?;
    // Writes may block again, like any writer to a pipe.
    // SAFETY: fcntl on a descriptor this function owns.
    unsafe {
        let flags = libc::fcntl(f.as_raw_fd(), libc::F_GETFL);
        libc::fcntl(f.as_raw_fd(), libc::F_SETFL, flags & !libc::O_NONBLOCK);
    }
    Ok(f)
}

fn atomic_write(path: &Path, write: impl FnOnce(&mut std::fs::File) -> Result<()>) -> Result<()> {
    if let Target::Special = check_target(path)? {
        let mut f = open_special(path)?;
        return write(&mut f).with_context(|| format!("writing {}", path.display()));
    }
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
    write_png_rgb8(path, img.width, img.height, img.to_rgb8())
}

/// Write 8-bit RGB pixels (row major) as a PNG, whole or not at all.
pub fn write_png_rgb8(path: &Path, width: u32, height: u32, rgb: Vec<u8>) -> Result<()> {
    let buf = image::RgbImage::from_raw(width, height, rgb).context("image buffer size")?;
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
