//! Every output of a run, written one way. Before any work, [`Files`]
//! checks a run's outputs against its inputs and against each other; then
//! the run's outputs land together or not at all:
//!
//! - an output that is an input of the run, or another output of it, is
//!   refused with one line naming both flags; so is a directory the run
//!   replaces ([`Files::output_dir`]) that holds an input;
//! - an output's folder must be a folder the user may write (missing
//!   folders are created when the outputs are written, and removed again if
//!   the run fails); a path that ends in `/`, `.` or `..` is not a file;
//! - a symlink is followed and its target written; the link stays;
//! - a regular file is replaced through a short temporary file beside it
//!   (`.cube-PID-N.tmp`), keeping its mode (and, run as root, its owner);
//!   one the user may not write is refused, as `cp` refuses it;
//! - a FIFO, a device, or any path reached through `/dev` or `/proc`
//!   (`/dev/stdout` into a redirected log) is written through, appending,
//!   never replaced; a FIFO with no reader is an error, not a hang;
//! - a directory is refused.
//!
//! A run stages each output ([`Files::png`], [`Files::json`], ...): a file
//! is written whole to its temporary file, a special file's bytes are kept.
//! [`Files::commit`] then writes the special files and, only when each was
//! written, renames every temporary file into place. A run that fails
//! before it commits (or a failed special write) leaves no output and no
//! temporary file behind.

use anyhow::{bail, Context, Result};
use scene::Image;
use std::io::Write;
use std::os::unix::fs::MetadataExt;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

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

/// Refuse a file path whose last part is not a name (`x.png/`, `x/.`,
/// `..`, or nothing): the file would land under another name.
fn file_name(path: &Path) -> Result<()> {
    use std::os::unix::ffi::OsStrExt;
    let bytes = path.as_os_str().as_bytes();
    let last = bytes.rsplit(|&b| b == b'/').next().unwrap_or(bytes);
    if last.is_empty() || last == b"." || last == b".." {
        bail!(
            "{}: not a file name (a file's path may not end in '/', '.' or '..')",
            path.display()
        );
    }
    long_names(path)
}

/// Longest name of a file or folder (Linux's `NAME_MAX`).
const NAME_MAX: usize = 255;

/// Refuse a path with a part longer than a file name may be, before any
/// work (the rename at the end would fail).
fn long_names(path: &Path) -> Result<()> {
    use std::os::unix::ffi::OsStrExt;
    match path
        .as_os_str()
        .as_bytes()
        .split(|&b| b == b'/')
        .find(|part| part.len() > NAME_MAX)
    {
        Some(part) => bail!(
            "{}: a name in it is {} bytes, longer than the {NAME_MAX} a file name may have",
            path.display(),
            part.len()
        ),
        None => Ok(()),
    }
}

/// Check the folder a file output is written in, before any work: it (or,
/// where folders are missing, the nearest one that exists) is a directory
/// the user may create files in.
fn check_folder(target: &Path, path: &Path) -> Result<()> {
    let mut dir = target.parent();
    while let Some(d) = dir {
        match std::fs::metadata(d) {
            Ok(m) if m.is_dir() => {
                if !access(d, libc::W_OK | libc::X_OK) {
                    bail!(
                        "{}: permission denied (its folder {} is not writable)",
                        path.display(),
                        d.display()
                    );
                }
                return Ok(());
            }
            Ok(_) => bail!("{}: {} is not a directory", path.display(), d.display()),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => dir = d.parent(),
            Err(e) => bail!("{}: {}: {e}", path.display(), d.display()),
        }
    }
    Ok(())
}

/// Check an output path before any work is done for it.
pub fn check_target(path: &Path) -> Result<Target> {
    file_name(path)?;
    let (target, system) = resolve(path)?;
    match std::fs::metadata(&target) {
        Ok(m) if m.is_dir() => bail!("{} is a directory, not a file", path.display()),
        Ok(m) if !m.is_file() => Ok(Target::Special),
        _ if system => Ok(Target::Special),
        Ok(_) => {
            if !access(&target, libc::W_OK) {
                bail!(
                    "{}: permission denied (the file is not writable)",
                    path.display()
                );
            }
            check_folder(&target, path)?;
            Ok(Target::File(target))
        }
        Err(_) => {
            check_folder(&target, path)?;
            Ok(Target::File(target))
        }
    }
}

/// Whether this process may use `path` as `mode` asks (`access(2)`, as
/// `cp` asks).
fn access(path: &Path, mode: libc::c_int) -> bool {
    use std::os::unix::ffi::OsStrExt;
    let Ok(c) = std::ffi::CString::new(path.as_os_str().as_bytes()) else {
        return false;
    };
    // SAFETY: a NUL-terminated path this function owns.
    unsafe { libc::access(c.as_ptr(), mode) == 0 }
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

/// A file the run reads.
struct Input {
    /// Its flag and path, for messages.
    named: String,
    /// Its path, links followed.
    at: PathBuf,
    id: Id,
    /// Its hard links.
    links: u64,
}

/// Where an output lands.
enum Place {
    /// A regular file (or nothing yet), at this resolved path.
    File(PathBuf),
    /// Written through ([`Target::Special`]).
    Special,
    /// A directory the run replaces as a whole.
    Dir,
}

/// A registered output.
struct Output {
    named: String,
    path: PathBuf,
    id: Id,
    place: Place,
}

/// An output written but not yet in place.
enum Staged {
    /// A finished temporary file, renamed over `target` at commit.
    File { tmp: PathBuf, target: PathBuf },
    /// A special file's bytes, written through at commit.
    Special { path: PathBuf, bytes: Vec<u8> },
}

/// The files a run reads and writes, checked before it does any work, and
/// its outputs, which land together at [`Files::commit`] or not at all
/// (dropped uncommitted, the set removes its temporary files and the
/// folders it made).
#[derive(Default)]
pub struct Files {
    inputs: Vec<Input>,
    outputs: Vec<Output>,
    staged: Vec<Staged>,
    /// Folders made for the outputs, outermost first.
    made: Vec<PathBuf>,
}

/// Entries looked at for hard links to an input in a directory a run
/// replaces; a larger directory is not a directory an export wrote.
const MAX_DIR_ENTRIES: usize = 100_000;

/// A distinct temporary name each time, short enough beside any legal name.
fn temp_name(ext: &str) -> String {
    static NEXT: AtomicU64 = AtomicU64::new(0);
    let n = NEXT.fetch_add(1, Ordering::Relaxed);
    format!(".cube-{}-{n}.{ext}", std::process::id())
}

impl Files {
    /// A file the run reads (`what` names it: `--scene`, `volume.raw`).
    pub fn input(&mut self, what: &str, path: &Path) -> Result<()> {
        let at = resolve(path)?.0;
        let links = std::fs::metadata(&at).map_or(1, |m| m.nlink());
        let id = identity(at.clone());
        self.inputs.push(Input {
            named: format!("{what} {}", path.display()),
            at,
            id,
            links,
        });
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
        self.kits(what, path, cosim::gtkw::MARK, "move it, or trace elsewhere")
    }

    /// An output that replaces only a file the kit wrote: refused when
    /// `path` is a file that does not begin with `mark` (`advice` says what
    /// to do instead).
    pub fn kits(&mut self, what: &str, path: &Path, mark: &str, advice: &str) -> Result<()> {
        self.output(what, path)?;
        let at = resolve(path)?.0;
        if std::fs::metadata(&at).is_ok_and(|m| m.is_file()) {
            let mut head = Vec::new();
            if let Ok(f) = std::fs::File::open(&at) {
                use std::io::Read;
                let _ = f.take(mark.len() as u64).read_to_end(&mut head);
            }
            if head != mark.as_bytes() {
                bail!(
                    "{what} {} exists and was not written by cube: {advice}",
                    path.display()
                );
            }
        }
        Ok(())
    }

    /// A file the run writes: refused if it is a directory, a file the user
    /// may not write (or in a folder where it may not be made), an input,
    /// or another output of the run.
    pub fn output(&mut self, what: &str, path: &Path) -> Result<()> {
        let named = format!("{what} {}", path.display());
        let (place, id) = match check_target(path).with_context(|| what.to_string())? {
            Target::File(t) => (Place::File(t.clone()), identity(t)),
            Target::Special => (Place::Special, identity(resolve(path)?.0)),
        };
        if let Some(input) = self.inputs.iter().find(|i| i.id == id) {
            bail!("{named} would replace the input {}", input.named);
        }
        // A device or pipe may take several outputs, one after another.
        if !matches!(place, Place::Special) {
            if let Some(other) = self.outputs.iter().find(|o| o.id == id) {
                bail!(
                    "{named} is also {}: give each output its own file",
                    other.named
                );
            }
        }
        self.outputs.push(Output {
            named,
            path: path.to_path_buf(),
            id,
            place,
        });
        Ok(())
    }

    /// A directory the run replaces as a whole (an export): every file in
    /// it now is among the files it would write, so it is refused when an
    /// input lies in it, or is a hard link to a file in it.
    pub fn output_dir(&mut self, what: &str, dir: &Path) -> Result<()> {
        long_names(dir)?;
        let named = format!("{what} {}", dir.display());
        let at = resolve(dir)?.0;
        let inside = |i: &Input| {
            i.at.starts_with(&at)
                || (i.links > 1 && matches!(i.id, Id::Inode(..)) && holds(&at, &i.id))
        };
        if let Some(input) = self.inputs.iter().find(|i| inside(i)) {
            bail!("{named} would replace the input {}", input.named);
        }
        if let Some(other) = self.outputs.iter().find(|o| match &o.place {
            Place::File(t) => t.starts_with(&at),
            _ => false,
        }) {
            bail!(
                "{named} would replace {}: give each output its own place",
                other.named
            );
        }
        self.outputs.push(Output {
            named,
            path: dir.to_path_buf(),
            id: identity(at),
            place: Place::Dir,
        });
        Ok(())
    }

    /// Where a staged output of `path` lands (registering it first if the
    /// run did not): a file's resolved path, or `None` for a special file.
    fn place(&mut self, path: &Path) -> Result<Option<PathBuf>> {
        if !self.outputs.iter().any(|o| o.path == path) {
            self.output("the output", path)?;
        }
        let o = self
            .outputs
            .iter()
            .find(|o| o.path == path)
            .expect("registered");
        match &o.place {
            Place::File(t) => Ok(Some(t.clone())),
            Place::Special => Ok(None),
            Place::Dir => bail!("{} is a directory output, not a file", path.display()),
        }
    }

    /// Make `dir` and any missing folders above it, remembering each one.
    fn make_dirs(&mut self, dir: &Path) -> Result<()> {
        let mut missing = Vec::new();
        let mut d = Some(dir);
        while let Some(p) = d {
            if std::fs::symlink_metadata(p).is_ok() || p.as_os_str().is_empty() {
                break;
            }
            missing.push(p.to_path_buf());
            d = p.parent();
        }
        for m in missing.into_iter().rev() {
            match std::fs::create_dir(&m) {
                Ok(()) => self.made.push(m),
                Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => {}
                Err(e) => return Err(e).with_context(|| format!("creating {}", m.display())),
            }
        }
        Ok(())
    }

    /// A temporary path beside `target` (its folder made), ending in `.ext`.
    fn temp_beside(&mut self, target: &Path, ext: &str) -> Result<PathBuf> {
        let dir = match target.parent() {
            Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
            _ => PathBuf::from("."),
        };
        self.make_dirs(&dir)?;
        let tmp = dir.join(temp_name(ext));
        crate::stop::remove_on_stop(&tmp);
        Ok(tmp)
    }

    /// Stage output `path`: `write` writes its bytes, buffered, to its
    /// temporary file (or, for a special file, to memory).
    fn stage(
        &mut self,
        path: &Path,
        write: impl FnOnce(&mut dyn Write) -> Result<()>,
    ) -> Result<()> {
        let what = || format!("writing {}", path.display());
        match self.place(path)? {
            None => {
                let mut bytes = Vec::new();
                write(&mut bytes).with_context(what)?;
                self.staged.push(Staged::Special {
                    path: path.to_path_buf(),
                    bytes,
                });
            }
            Some(target) => {
                let tmp = self.temp_beside(&target, "tmp")?;
                // Staged first, so that a failure below removes it.
                self.staged.push(Staged::File {
                    tmp: tmp.clone(),
                    target,
                });
                let f = std::fs::File::create(&tmp)
                    .with_context(|| format!("creating {}", tmp.display()))?;
                let mut w = std::io::BufWriter::with_capacity(1 << 20, f);
                write(&mut w).with_context(what)?;
                let f = w
                    .into_inner()
                    .map_err(|e| e.into_error())
                    .with_context(what)?;
                f.sync_all().with_context(what)?;
            }
        }
        Ok(())
    }

    /// Stage an image as a PNG.
    pub fn png(&mut self, path: &Path, img: &Image) -> Result<()> {
        self.png_rgb8(path, img.width, img.height, img.to_rgb8())
    }

    /// Stage 8-bit RGB pixels (row major) as a PNG.
    pub fn png_rgb8(&mut self, path: &Path, width: u32, height: u32, rgb: Vec<u8>) -> Result<()> {
        let buf = image::RgbImage::from_raw(width, height, rgb).context("image buffer size")?;
        let mut png = std::io::Cursor::new(Vec::new());
        buf.write_to(&mut png, image::ImageFormat::Png)
            .with_context(|| format!("encoding {}", path.display()))?;
        self.bytes(path, png.get_ref())
    }

    /// Stage a JSON document (pretty, with a final newline).
    pub fn json(&mut self, path: &Path, v: &serde_json::Value) -> Result<()> {
        self.stage(path, |w| {
            serde_json::to_writer_pretty(&mut *w, v)?;
            w.write_all(b"\n")?;
            Ok(())
        })
    }

    /// Stage bytes.
    pub fn bytes(&mut self, path: &Path, bytes: &[u8]) -> Result<()> {
        self.stage(path, |w| Ok(w.write_all(bytes)?))
    }

    /// Stage text.
    pub fn text(&mut self, path: &Path, text: &str) -> Result<()> {
        self.bytes(path, text.as_bytes())
    }

    /// Where a tool that writes its own file (a simulator's trace) writes
    /// output `path`: a temporary file beside it, ending in `.ext`, which
    /// lands at `path` at commit (and is removed if the run fails).
    pub fn temp_for(&mut self, path: &Path, ext: &str) -> Result<PathBuf> {
        let Some(target) = self.place(path)? else {
            bail!("{}: not a regular file", path.display());
        };
        let tmp = self.temp_beside(&target, ext)?;
        self.staged.push(Staged::File {
            tmp: tmp.clone(),
            target,
        });
        Ok(tmp)
    }

    /// A temporary file `tmp` a tool writes beside one from
    /// [`Files::temp_for`] (a trace's save file): it lands at `path`.
    pub fn temp_at(&mut self, tmp: &Path, path: &Path) -> Result<()> {
        let Some(target) = self.place(path)? else {
            bail!("{}: not a regular file", path.display());
        };
        crate::stop::remove_on_stop(tmp);
        self.staged.push(Staged::File {
            tmp: tmp.to_path_buf(),
            target,
        });
        Ok(())
    }

    /// Put every staged output in place: the special files are written
    /// first (a failure there removes the temporary files, so nothing
    /// lands), then each temporary file is renamed over its target.
    pub fn commit(mut self) -> Result<()> {
        for s in &self.staged {
            if let Staged::Special { path, bytes } = s {
                let mut f = open_special(path)?;
                f.write_all(bytes)
                    .and_then(|()| f.flush())
                    .with_context(|| format!("writing {}", path.display()))?;
            }
        }
        let staged = std::mem::take(&mut self.staged);
        let mut rest = staged.into_iter();
        while let Some(s) = rest.next() {
            if let Staged::File { tmp, target } = &s {
                if let Err(e) = replace(tmp, target) {
                    // What is not yet in place is removed with the set.
                    self.staged = std::iter::once(s).chain(rest).collect();
                    return Err(e);
                }
            }
        }
        self.made.clear();
        Ok(())
    }
}

impl Drop for Files {
    /// Uncommitted: remove the temporary files and the folders made for
    /// them (those left empty).
    fn drop(&mut self) {
        for s in &self.staged {
            if let Staged::File { tmp, .. } = s {
                let _ = std::fs::remove_file(tmp);
            }
        }
        for d in self.made.iter().rev() {
            let _ = std::fs::remove_dir(d);
        }
    }
}

/// Whether directory `dir` holds a file (at any depth, links not followed)
/// with identity `id`.
fn holds(dir: &Path, id: &Id) -> bool {
    let mut todo = vec![dir.to_path_buf()];
    let mut seen = 0;
    while let Some(d) = todo.pop() {
        let Ok(entries) = std::fs::read_dir(&d) else {
            continue;
        };
        for e in entries.flatten() {
            seen += 1;
            if seen > MAX_DIR_ENTRIES {
                return false;
            }
            let Ok(m) = std::fs::symlink_metadata(e.path()) else {
                continue;
            };
            if m.is_dir() {
                todo.push(e.path());
            } else if *id == Id::Inode(m.dev(), m.ino()) {
                return true;
            }
        }
    }
    false
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
        .map_err(|e| {
            // Only a FIFO with no reader gives ENXIO; a path through a file
            // that is not a folder gives ENOTDIR.
            let why = match e.raw_os_error() {
                Some(libc::ENXIO) => " (a FIFO needs a reader)".to_string(),
                Some(libc::ENOTDIR) => path
                    .parent()
                    .filter(|p| !p.as_os_str().is_empty())
                    .map_or(String::new(), |p| {
                        format!(" ({} is not a folder)", p.display())
                    }),
                _ => String::new(),
            };
            anyhow::anyhow!("opening {}{why}: {e}", path.display())
        })?;
    // Writes may block again, like any writer to a pipe.
    // SAFETY: fcntl on a descriptor this function owns.
    unsafe {
        let flags = libc::fcntl(f.as_raw_fd(), libc::F_GETFL);
        libc::fcntl(f.as_raw_fd(), libc::F_SETFL, flags & !libc::O_NONBLOCK);
    }
    Ok(f)
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
