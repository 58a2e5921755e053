//! Every output of a run, written one way. Before any work, [`Files`]
//! checks a run's outputs against its inputs and against each other; then
//! each is written whole or not at all:
//!
//! - an output that is an input of the run, or another output of it, is
//!   refused with one line naming both flags;
//! - a symlink is followed and its target written; the link stays;
//! - a regular file is replaced through a temporary file beside it, keeping
//!   its mode (and, run as root, its owner); one the user may not write is
//!   refused, as `cp` refuses it;
//! - a FIFO, a device, or any path reached through `/dev` or `/proc`
//!   (`/dev/stdout` into a redirected log) is written through, appending,
//!   never replaced; a FIFO with no reader is an error, not a hang;
//! - a directory is refused.

use anyhow::{bail, Context, Result};
use scene::Image;
use std::io::Write;
use std::os::unix::fs::MetadataExt;
use std::path::{Path, PathBuf};

/// What an output path names now.
pub enum Target {
    /// Nothing, or a regular file (through any symlinks): written whole or
    /// not at all, at this path.
    File(PathBuf),
    /// A FIFO, a character device or a socket, or anything under `/dev` or
    /// `/proc`: written through.
    Special,
}

/// Symlinks followed before a path is refused as a loop.
const MAX_LINKS: usize = 40;

/// `path` with its symlinks followed to the file they name (which need not
/// exist), and whether the chain passed through `/dev` or `/proc`.
fn follow(path: &Path) -> Result<(PathBuf, bool)> {
    let mut p = std::path::absolute(path)
        .with_context(|| format!("{}: not a usable path", path.display()))?;
    let mut system = false;
    for _ in 0..MAX_LINKS {
        system |= p.starts_with("/dev") || p.starts_with("/proc");
        match std::fs::symlink_metadata(&p) {
            Ok(m) if m.file_type().is_symlink() => {
                let to = std::fs::read_link(&p)
                    .with_context(|| format!("reading the link {}", p.display()))?;
                p = match p.parent() {
                    Some(dir) => dir.join(to),
                    None => to,
                };
            }
            _ => return Ok((p, system)),
        }
    }
    bail!("{}: too many levels of symbolic links", path.display())
}

/// `path` resolved: its links followed and its missing folders settled
/// ([`settled`]), and whether the way passed through `/dev` or `/proc`.
fn resolve(path: &Path) -> Result<(PathBuf, bool)> {
    let (target, system) = follow(path)?;
    Ok((settled(&target), system))
}

/// Check an output path before any work is done for it.
pub fn check_target(path: &Path) -> Result<Target> {
    let (target, system) = resolve(path)?;
    match std::fs::metadata(&target) {
        Ok(m) if m.is_dir() => bail!("{} is a directory, not a file", path.display()),
        Ok(m) if !m.is_file() => Ok(Target::Special),
        _ if system => Ok(Target::Special),
        Ok(_) => {
            if !writable(&target) {
                bail!(
                    "{}: permission denied (the file is not writable)",
                    path.display()
                );
            }
            Ok(Target::File(target))
        }
        Err(_) => Ok(Target::File(target)),
    }
}

/// Whether this process may write `path` (`access(2)`, as `cp` asks).
fn writable(path: &Path) -> bool {
    use std::os::unix::ffi::OsStrExt;
    let Ok(c) = std::ffi::CString::new(path.as_os_str().as_bytes()) else {
        return false;
    };
    // SAFETY: a NUL-terminated path this function owns.
    unsafe { libc::access(c.as_ptr(), libc::W_OK) == 0 }
}

/// A file's identity, through symlinks: device and inode when it exists,
/// else its absolute path with the folder's links resolved.
#[derive(PartialEq)]
enum Id {
    Inode(u64, u64),
    Path(PathBuf),
}

/// The identity of a resolved path ([`resolve`]).
fn identity(target: PathBuf) -> Id {
    match std::fs::metadata(&target) {
        Ok(m) => Id::Inode(m.dev(), m.ino()),
        Err(_) => Id::Path(target),
    }
}

/// Where an absolute path will lead once its missing folders are created:
/// the longest existing ancestor with its links resolved, then the rest
/// taken lexically (a missing folder cannot be a link, so `missing/..` is
/// the folder it lies in).
fn settled(path: &Path) -> PathBuf {
    use std::path::Component;
    let mut base = path.to_path_buf();
    let mut rest = Vec::new();
    let canon = loop {
        if let Ok(c) = base.canonicalize() {
            break c;
        }
        // The last component (a name, or `..`) is taken lexically below.
        match (base.components().next_back(), base.parent()) {
            (Some(last), Some(parent)) => {
                rest.push(last.as_os_str().to_os_string());
                base = parent.to_path_buf();
            }
            _ => break base,
        }
    };
    let mut out = canon;
    for c in rest.iter().rev() {
        match Path::new(c).components().next() {
            Some(Component::ParentDir) => {
                out.pop();
            }
            Some(Component::CurDir) | None => {}
            _ => out.push(c),
        }
    }
    out
}

/// The files a run reads and writes, checked before it does any work.
#[derive(Default)]
pub struct Files {
    inputs: Vec<(String, Id)>,
    outputs: Vec<(String, Id)>,
}

impl Files {
    /// A file the run reads (`what` names it: `--scene`, `volume.raw`).
    pub fn input(&mut self, what: &str, path: &Path) -> Result<()> {
        let id = identity(resolve(path)?.0);
        self.inputs.push((format!("{what} {}", path.display()), id));
        Ok(())
    }

    /// A scene file and the raw volume it names.
    pub fn scene(&mut self, what: &str, path: &Path, scene: &scene::Scene) -> Result<()> {
        self.input(what, path)?;
        if let Some(raw) = &scene.volume.raw {
            self.input(&format!("{what}'s volume.raw"), raw)?;
        }
        Ok(())
    }

    /// A file written beside an output, which the user did not name: also
    /// refused when it exists and the kit did not write it (its first line
    /// is not [`cosim::gtkw::MARK`]).
    pub fn companion(&mut self, what: &str, path: &Path) -> Result<()> {
        self.output(what, path)?;
        if let Ok(text) = std::fs::read(resolve(path)?.0) {
            if !text.starts_with(cosim::gtkw::MARK.as_bytes()) {
                bail!(
                    "{what} {} exists and was not written by cube: move it, or trace elsewhere",
                    path.display()
                );
            }
        }
        Ok(())
    }

    /// A file the run writes: refused if it is a directory, a file the user
    /// may not write, an input, or another output of the run.
    pub fn output(&mut self, what: &str, path: &Path) -> Result<()> {
        let named = format!("{what} {}", path.display());
        let (special, id) = match check_target(path).with_context(|| what.to_string())? {
            Target::File(t) => (false, identity(t)),
            Target::Special => (true, identity(resolve(path)?.0)),
        };
        if let Some((input, _)) = self.inputs.iter().find(|(_, i)| *i == id) {
            bail!("{named} would replace the input {input}");
        }
        // A device or pipe may take several outputs, one after another.
        if !special {
            if let Some((other, _)) = self.outputs.iter().find(|(_, o)| *o == id) {
                bail!("{named} is also {other}: give each output its own file");
            }
        }
        self.outputs.push((named, id));
        Ok(())
    }
}

/// Open a special file for writing, appending. A FIFO is opened without
/// blocking, so one with no reader is an error rather than a hang.
fn open_special(path: &Path) -> Result<std::fs::File> {
    use std::os::unix::fs::OpenOptionsExt;
    use std::os::unix::io::AsRawFd;
    let f = std::fs::OpenOptions::new()
        .append(true)
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

/// A temporary path beside `target`, in its folder (created if missing),
/// ending in `.ext`.
fn temp_beside(target: &Path, ext: &str) -> Result<PathBuf> {
    let dir = match target.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    std::fs::create_dir_all(dir).with_context(|| format!("creating {}", dir.display()))?;
    let name = target
        .file_name()
        .with_context(|| format!("{} is not a file path", target.display()))?;
    Ok(dir.join(format!(
        ".{}.tmp{}.{ext}",
        name.to_string_lossy(),
        std::process::id()
    )))
}

/// Move a finished `tmp` over `target` (a regular file or nothing): an
/// existing file's mode, and as root its owner, carry over.
fn replace(tmp: &Path, target: &Path) -> Result<()> {
    if let Ok(m) = std::fs::metadata(target) {
        std::fs::set_permissions(tmp, m.permissions())?;
        // SAFETY: geteuid has no preconditions.
        if unsafe { libc::geteuid() } == 0 {
            std::os::unix::fs::chown(tmp, Some(m.uid()), Some(m.gid()))?;
        }
    }
    std::fs::rename(tmp, target).with_context(|| format!("renaming to {}", target.display()))
}

fn atomic_write(path: &Path, write: impl FnOnce(&mut std::fs::File) -> Result<()>) -> Result<()> {
    let target = match check_target(path)? {
        Target::Special => {
            let mut f = open_special(path)?;
            return write(&mut f).with_context(|| format!("writing {}", path.display()));
        }
        Target::File(t) => t,
    };
    let tmp = temp_beside(&target, "tmp")?;
    crate::stop::remove_on_stop(&tmp);
    let result = (|| {
        let mut f =
            std::fs::File::create(&tmp).with_context(|| format!("creating {}", tmp.display()))?;
        write(&mut f)?;
        f.sync_all()?;
        replace(&tmp, &target)
    })();
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result
}

/// Where a tool that writes its own file (a simulator's trace) writes for
/// `path`: a temporary file beside the file `path` names, ending in `.ext`,
/// for [`keep`].
pub fn temp_for(path: &Path, ext: &str) -> Result<PathBuf> {
    match check_target(path)? {
        Target::Special => bail!("{}: not a regular file", path.display()),
        Target::File(t) => temp_beside(&t, ext),
    }
}

/// Put a finished temporary file from [`temp_for`] in place of `path`.
pub fn keep(tmp: &Path, path: &Path) -> Result<()> {
    match check_target(path)? {
        Target::Special => bail!("{}: not a regular file", path.display()),
        Target::File(t) => replace(tmp, &t),
    }
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

pub fn write_bytes(path: &Path, bytes: &[u8]) -> Result<()> {
    atomic_write(path, |f| {
        f.write_all(bytes)?;
        Ok(())
    })
}

pub fn write_text(path: &Path, text: &str) -> Result<()> {
    write_bytes(path, text.as_bytes())
}
