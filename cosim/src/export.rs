//! Verilog export, for any architecture ([`crate::arch::Arch`]): each part's
//! design as [`crate::verilog`] writes it, one file per stage with lint
//! waivers, and a manifest of its parameters and of the units left out,
//! into a directory written whole or not at all.

use crate::arch::Arch;
use crate::archs::LAYOUTS;
use crate::verilog::{names, wrapper, write_stage_files};
use hdl::common::units::TOP;
use scene::{Camera, Scene};
use std::path::Path;

/// The manifest's record of what the export wrote: each file's CRC-32 by
/// its path in the export (every file but `manifest.json` itself).
const RECORD: &str = "files_crc32";

/// Each file under `dir` (recursively), by its path relative to `dir`, and
/// its CRC-32 as 8 hex digits; `manifest.json` at the top is left out.
fn checksums(dir: &Path) -> std::io::Result<serde_json::Map<String, serde_json::Value>> {
    let mut out = serde_json::Map::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for entry in std::fs::read_dir(&d)? {
            let path = entry?.path();
            if path.is_dir() {
                stack.push(path);
                continue;
            }
            let rel = path.strip_prefix(dir).unwrap_or(&path).to_string_lossy();
            if rel != "manifest.json" {
                let crc = crc32fast::hash(&std::fs::read(&path)?);
                out.insert(rel.to_string(), format!("{crc:08x}").into());
            }
        }
    }
    Ok(out)
}

/// Whether `out` may be replaced by an export: it does not exist, it is an
/// empty directory, or it holds only what an earlier export wrote there,
/// unchanged: stage files, `lint.vlt`, the integrable top and part
/// directories (`sweep<i>/`, `base_plane<i>/`) by name, each file as the
/// CRC-32 its `manifest.json` records. A file edited since, a name an
/// export does not write, or a manifest without the record is a user's,
/// and is never deleted.
fn replaceable(out: &Path) -> Result<(), String> {
    // The integrable top, `ARCH_NAME.v` ([`integration_top`]).
    let integration = |name: &str| {
        name.ends_with(".v")
            && [crate::cube4l::Cube4l::NAME, crate::cube3::Cube3::NAME]
                .iter()
                .any(|a| name.starts_with(&format!("{a}_")))
    };
    let ours_file = |name: &str| {
        name == "lint.vlt"
            || integration(name)
            || LAYOUTS.iter().any(|(_, l)| l.files.contains(&name))
    };
    let ours_dir = |name: &str| {
        LAYOUTS.iter().map(|(part, _)| part).any(|p| {
            name.strip_prefix(p)
                .is_some_and(|i| !i.is_empty() && i.bytes().all(|b| b.is_ascii_digit()))
        })
    };
    let (top, rel) = (out.display().to_string(), |p: &Path| {
        p.strip_prefix(out)
            .unwrap_or(p)
            .to_string_lossy()
            .to_string()
    });
    let choose = "choose a new or empty directory";
    let io = |p: &Path, e: std::io::Error| format!("{}: {e}", p.display());
    let m = match std::fs::symlink_metadata(out) {
        Err(_) => return Ok(()),
        Ok(m) => m,
    };
    if !m.is_dir() {
        return Err(format!(
            "{top} exists and is not a directory; an export writes a directory"
        ));
    }
    if std::fs::read_dir(out)
        .map_err(|e| io(out, e))?
        .next()
        .is_none()
    {
        return Ok(());
    }
    // First each name, then each file against the manifest's record.
    let mut files = Vec::new();
    let mut stack = vec![(out.to_path_buf(), true)];
    while let Some((dir, at_top)) = stack.pop() {
        for entry in std::fs::read_dir(&dir).map_err(|e| io(&dir, e))? {
            let entry = entry.map_err(|e| io(&dir, e))?;
            let (path, name) = (
                entry.path(),
                entry.file_name().to_string_lossy().to_string(),
            );
            let kind = entry.file_type().map_err(|e| io(&path, e))?;
            if at_top && name == "manifest.json" && kind.is_file() {
                continue;
            }
            if kind.is_dir() && at_top && ours_dir(&name) {
                stack.push((path, false));
                continue;
            }
            if !kind.is_file() || !ours_file(&name) {
                let what = if kind.is_dir() {
                    "a directory"
                } else if kind.is_symlink() {
                    "a link"
                } else if kind.is_file() {
                    "a file"
                } else {
                    "a special file"
                };
                let why = if ours_file(&name) || (at_top && name == "manifest.json") {
                    "where an export writes a file"
                } else {
                    "which an export does not write"
                };
                return Err(format!(
                    "{} holds {name}, {what} {why}; {choose}",
                    dir.display()
                ));
            }
            files.push(path);
        }
    }
    let manifest = out.join("manifest.json");
    let record = std::fs::symlink_metadata(&manifest)
        .ok()
        .filter(|m| m.is_file())
        .and_then(|_| std::fs::read_to_string(&manifest).ok())
        .and_then(|t| serde_json::from_str::<serde_json::Value>(&t).ok())
        .and_then(|v| v.get(RECORD).and_then(|r| r.as_object()).cloned())
        .ok_or_else(|| {
            format!(
                "{top} is not empty and holds no manifest.json with the record of an \
                 export's files (`{RECORD}`), so what is in it is not known to be an \
                 export's; {choose}"
            )
        })?;
    for path in files {
        let crc = format!(
            "{:08x}",
            crc32fast::hash(&std::fs::read(&path).map_err(|e| io(&path, e))?)
        );
        if record.get(&rel(&path)).and_then(|v| v.as_str()) != Some(crc.as_str()) {
            return Err(format!(
                "{} is not the file the export that wrote {top} recorded in its \
                 manifest.json (edited since?); an export replaces only its own files \
                 unchanged: {choose}",
                path.display()
            ));
        }
    }
    Ok(())
}

/// What an export is of: a build, and the scene that asked for it.
pub struct ExportScene<'a> {
    /// The scene's name in the manifest.
    pub name: &'a str,
    pub scene: &'a Scene,
    pub camera: &'a Camera,
    /// The volume's dims (after any crop).
    pub dims: [usize; 3],
}

/// Export build `build` of architecture `A` into `out`: its stage files,
/// lint waivers and `manifest.json` (its configuration, parameters and the
/// units left out; with a scene, the scene's parts and the register writes
/// each takes), one design in `out`. An architecture that takes its
/// tables' shapes from a scene (Cube-3) needs the scene to build it.
/// The directory is built beside `out` and renamed over it, so it is
/// written whole or not at all. Returns the manifest.
pub fn write_export<A: Arch>(
    out: &Path,
    build: &A::Config,
    scene: Option<&ExportScene>,
) -> Result<serde_json::Value, String> {
    write_dir(out, |tmp| {
        let parts = match scene {
            Some(s) => A::parts(s.scene, s.camera, s.dims, build)?,
            None => vec![],
        };
        // One design for the build: every part of it renders on it, its view
        // in registers and tables.
        let designs: Vec<(String, String)> = match A::design(build) {
            Ok(v) => vec![(".".to_string(), v)],
            Err(e) => match parts.first() {
                Some(p) => vec![(".".to_string(), A::verilog(p, None)?)],
                None => return Err(e),
            },
        };
        let left_out = A::left_out(build);
        let io = |e: std::io::Error| format!("{}: {e}", out.display());
        let mut files = Vec::new();
        for (sub, v) in &designs {
            let dir = tmp.join(sub);
            std::fs::create_dir_all(&dir).map_err(io)?;
            let mut written = write_stage_files(&dir, v, &left_out, &A::LAYOUT).map_err(io)?;
            let top = integration_top::<A>(build);
            let what = format!("{} {}", A::TITLE, A::config_name(build));
            std::fs::write(dir.join(format!("{top}.v")), wrapper(&top, v, &what)?).map_err(io)?;
            written.push(format!("{top}.v"));
            files.push(serde_json::json!({"dir": sub, "files": written}));
        }
        let mut manifest = serde_json::json!({
            "architecture": A::NAME,
            "configuration": A::config_name(build),
            "generator": format!("cube {} with rust-hdl 0.46", env!("CARGO_PKG_VERSION")),
            "top": TOP,
            "integration_top": integration_top::<A>(build),
            "parameters": A::manifest_parameters(build),
            "units_left_out": names(&left_out),
            "designs": files,
            "lint": "verilator --lint-only -Wall lint.vlt <files>",
        });
        if let Some(s) = scene {
            let entries: Vec<serde_json::Value> = parts.iter().map(A::manifest_part).collect();
            manifest["scene"] = serde_json::json!({
                "name": s.name,
                "volume_dims": s.dims,
                format!("{}s", A::PART): entries,
            });
        }
        Ok(manifest)
    })
}

/// The integrable top's module name: the architecture and the build.
pub fn integration_top<A: Arch>(build: &A::Config) -> String {
    format!("{}_{}", A::NAME, A::config_name(build))
}

/// `out` as an absolute path with no `.` or `..` in it: its parent's
/// longest existing ancestor resolved (links followed), the rest of the
/// path below it taken as written. Also the first folder of that rest,
/// which the export creates (and removes again if it fails). A path that
/// ends in `..`, or that goes up (`..`) from a folder that does not exist,
/// names no directory to write.
fn resolve(out: &Path) -> Result<(std::path::PathBuf, Option<std::path::PathBuf>), String> {
    use std::path::Component;
    let not_a_dir = || format!("{} does not name a directory to write", out.display());
    let name = match out.components().next_back() {
        Some(Component::Normal(n)) => n.to_os_string(),
        _ => return Err(not_a_dir()),
    };
    let parent: std::path::PathBuf = {
        let mut c = out.components();
        c.next_back();
        c.as_path().to_path_buf()
    };
    let parent = if parent.as_os_str().is_empty() {
        std::path::PathBuf::from(".")
    } else {
        parent
    };
    let mut existing = parent.as_path();
    let mut rest = Vec::new();
    loop {
        match std::fs::metadata(existing) {
            Ok(_) => break,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {}
            Err(e) => return Err(format!("{}: {e}", existing.display())),
        }
        match (existing.file_name(), existing.parent()) {
            (Some(n), Some(up)) => {
                rest.push(n.to_os_string());
                existing = if up.as_os_str().is_empty() {
                    Path::new(".")
                } else {
                    up
                };
            }
            // A trailing `..` or `.` of a folder that does not exist.
            _ => return Err(not_a_dir()),
        }
    }
    if existing.components().any(|c| c == Component::ParentDir) && !rest.is_empty() {
        return Err(not_a_dir());
    }
    let mut dir = std::fs::canonicalize(existing).map_err(|e| format!("{}: {e}", out.display()))?;
    let created = rest.last().map(|first| dir.join(first));
    for n in rest.iter().rev() {
        dir.push(n);
    }
    Ok((dir.join(name), created))
}

/// Build the export directory `out` through `fill` (given a fresh directory
/// beside `out`, made before any work, it writes the files and returns the
/// manifest, which goes to `manifest.json` with the record of each file's
/// CRC-32), then rename it over `out`: written whole or not at all. `out`
/// must be replaceable (see [`replaceable`]); a directory it replaces keeps
/// its mode and, where the process may set it, its owner. A run that fails
/// leaves `out` as it was, and removes the folders it made.
fn write_dir(
    out: &Path,
    fill: impl FnOnce(&Path) -> Result<serde_json::Value, String>,
) -> Result<serde_json::Value, String> {
    let (target, created) = resolve(out)?;
    replaceable(&target)?;
    let io = |e: std::io::Error| format!("{}: {e}", out.display());
    let parent = target
        .parent()
        .ok_or_else(|| format!("{} is not a directory path", out.display()))?;
    let before = std::fs::symlink_metadata(&target).ok();
    if let (Some(m), Ok(up)) = (&before, std::fs::metadata(parent)) {
        use std::os::unix::fs::MetadataExt;
        if m.dev() != up.dev() {
            return Err(format!(
                "{} is a mount point, which an export cannot replace; choose a folder inside it",
                out.display()
            ));
        }
    }
    // Short names, so that any legal name of `out` has room beside it.
    let tmp = parent.join(format!(".cube-{}-export.tmp", std::process::id()));
    let old = parent.join(format!(".cube-{}-export.old", std::process::id()));
    let result = (|| {
        std::fs::create_dir_all(parent).map_err(io)?;
        let _ = std::fs::remove_dir_all(&tmp);
        std::fs::create_dir(&tmp).map_err(io)?;
        let mut manifest = fill(&tmp)?;
        manifest[RECORD] = checksums(&tmp).map_err(io)?.into();
        let text = serde_json::to_string_pretty(&manifest).map_err(|e| e.to_string())? + "\n";
        std::fs::write(tmp.join("manifest.json"), text).map_err(io)?;
        if let Some(m) = &before {
            use std::os::unix::fs::MetadataExt;
            std::fs::set_permissions(&tmp, m.permissions()).map_err(io)?;
            // Only a privileged process may give a folder away; otherwise
            // the folder is the process's, as it was to be able to write it.
            let _ = std::os::unix::fs::chown(&tmp, Some(m.uid()), Some(m.gid()));
            std::fs::rename(&target, &old).map_err(io)?;
        }
        if let Err(e) = std::fs::rename(&tmp, &target) {
            if before.is_some() {
                let _ = std::fs::rename(&old, &target);
            }
            return Err(io(e));
        }
        let _ = std::fs::remove_dir_all(&old);
        Ok(manifest)
    })();
    if result.is_err() {
        let _ = std::fs::remove_dir_all(&tmp);
        if let Some(c) = created {
            let _ = std::fs::remove_dir_all(c);
        }
    }
    result
}
