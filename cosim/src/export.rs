//! Verilog export, for any architecture ([`crate::arch::Arch`]): each part's
//! design as [`crate::verilog`] writes it, one file per stage with lint
//! waivers, and a manifest of its parameters and of the units left out,
//! into a directory written whole or not at all.

use crate::arch::Arch;
use crate::archs::LAYOUTS;
use crate::verilog::{names, wrapper, write_stage_files};
use scene::{Camera, Scene};
use std::path::Path;

/// Whether `out` may be replaced by an export: it does not exist, or it is
/// a directory holding only what an export of some architecture writes
/// (stage files, `lint.vlt`, `manifest.json`, and part directories such as
/// `sweep<i>/` or `base_plane<i>/` of the same). Anything else is a
/// user's, and is never deleted.
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
    fn check(
        dir: &Path,
        top: bool,
        ours_file: &dyn Fn(&str) -> bool,
        ours_dir: &dyn Fn(&str) -> bool,
    ) -> Result<(), String> {
        let entries = std::fs::read_dir(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
        for entry in entries {
            let entry = entry.map_err(|e| format!("{}: {e}", dir.display()))?;
            let name = entry.file_name().to_string_lossy().to_string();
            let kind = entry
                .file_type()
                .map_err(|e| format!("{}: {e}", dir.display()))?;
            let ours = if kind.is_dir() {
                top && ours_dir(&name) && check(&entry.path(), false, ours_file, ours_dir).is_ok()
            } else {
                kind.is_file() && (ours_file(&name) || (top && name == "manifest.json"))
            };
            if !ours {
                return Err(format!(
                    "{} holds {name}, which an export does not write; choose a new or empty directory",
                    dir.display()
                ));
            }
        }
        Ok(())
    }
    match std::fs::symlink_metadata(out) {
        Err(_) => Ok(()),
        Ok(m) if m.is_dir() => check(out, true, &ours_file, &ours_dir),
        Ok(_) => Err(format!(
            "{} exists and is not a directory; an export writes a directory",
            out.display()
        )),
    }
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
    replaceable(out)?;
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
    write_dir(out, |tmp| {
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
            "top": "top",
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

/// Build the export directory `out` through `fill` (given a fresh directory
/// beside `out`, it writes the files and returns the manifest, which goes to
/// `manifest.json`), then rename it over `out`: written whole or not at
/// all. `out` must be replaceable (see [`replaceable`]).
fn write_dir(
    out: &Path,
    fill: impl FnOnce(&Path) -> Result<serde_json::Value, String>,
) -> Result<serde_json::Value, String> {
    replaceable(out)?;
    let parent = match out.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => std::path::PathBuf::from("."),
    };
    out.file_name()
        .ok_or_else(|| format!("{} is not a directory path", out.display()))?;
    let io = |e: std::io::Error| format!("{}: {e}", out.display());
    std::fs::create_dir_all(&parent).map_err(io)?;
    // Short names, so that any legal name of `out` has room beside it.
    let tmp = parent.join(format!(".cube-{}-export.tmp", std::process::id()));
    let _ = std::fs::remove_dir_all(&tmp);
    let result = (|| {
        std::fs::create_dir_all(&tmp).map_err(io)?;
        let manifest = fill(&tmp)?;
        let text = serde_json::to_string_pretty(&manifest).map_err(|e| e.to_string())? + "\n";
        std::fs::write(tmp.join("manifest.json"), text).map_err(io)?;
        let old = parent.join(format!(".cube-{}-export.old", std::process::id()));
        if out.exists() {
            std::fs::rename(out, &old).map_err(io)?;
        }
        std::fs::rename(&tmp, out).map_err(io)?;
        let _ = std::fs::remove_dir_all(&old);
        Ok(manifest)
    })();
    if result.is_err() {
        let _ = std::fs::remove_dir_all(&tmp);
    }
    result
}
