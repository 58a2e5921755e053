//! Helpers shared by several subcommands: checking the reference step,
//! loading a scene and its volume, rendering with either architecture and
//! reporting the error against the reference.

use crate::methods::Arch;
use anyhow::{bail, Result};
use reference::metrics::ErrorMetrics;
use scene::volume::{Ordered, Volume, Voxels};
use scene::Image;
use scene::Scene;
use serde_json::{json, Value};
use std::cell::OnceCell;
use std::path::Path;
use std::time::Instant;

/// Clocks per frame of an architecture's RTL on `scene`, as its schedule
/// predicts them (`cosim::arch::Arch::expected_clocks`); none where the RTL
/// does not build the scene.
pub fn rtl_clocks<A: cosim::arch::Arch>(
    scene: &Scene,
    camera: &scene::Camera,
    dims: [usize; 3],
) -> Option<u64> {
    let build = A::needs(scene, camera, dims).ok()?;
    let parts = A::parts(scene, camera, dims, &build).ok()?;
    Some(parts.iter().map(A::expected_clocks).sum())
}

pub fn check_step(step: f64) -> Result<()> {
    if !(0.01..=4.0).contains(&step) {
        bail!("--ref-step {step} must lie in [0.01, 4]");
    }
    Ok(())
}

/// The angles of `--range FROM TO STEP`: `FROM + i·STEP` up to `TO`, so
/// each is exact to one rounding and the sweep ends even where
/// `FROM + STEP == FROM` in floating point.
pub fn angle_sweep(range: &[f64]) -> Result<Vec<f64>> {
    let [from, to, step] = [range[0], range[1], range[2]];
    let steps = (to - from) / step;
    let ok = from.abs() <= 1e6
        && to.abs() <= 1e6
        && step.is_finite()
        && step > 0.0
        && (0.0..=3600.0).contains(&steps);
    if !ok {
        bail!(
            "--range FROM TO STEP needs FROM and TO within ±1e6 degrees, STEP > 0, TO >= FROM and at most 3600 steps"
        );
    }
    Ok((0..=(steps + 1e-9).floor() as u32)
        .map(|i| from + i as f64 * step)
        .collect())
}

pub fn load(scene_path: &Path) -> Result<(Scene, Volume)> {
    let scene = Scene::load(scene_path)?;
    let vol = Volume::from_spec(&scene.volume, scene.hardware.voxel_bits)?;
    Ok((scene, vol))
}

/// The scene file's name (without its directory), as the exported designs
/// are named.
pub fn scene_name(scene_path: &Path) -> String {
    scene_path
        .file_name()
        .map(|n| n.to_string_lossy().to_string())
        .unwrap_or_default()
}

/// A scene named on the command line, loaded, with its name.
pub struct Loaded {
    pub name: String,
    pub scene: Scene,
    pub camera: scene::Camera,
}

impl Loaded {
    /// The scene as an export takes it (dims after any crop).
    pub fn export(&self) -> cosim::export::ExportScene<'_> {
        cosim::export::ExportScene {
            name: &self.name,
            scene: &self.scene,
            camera: &self.camera,
            dims: self.scene.volume.render_dims(),
        }
    }
}

/// The build subcommand `cmd` works on: `config` by name, or the
/// configuration the scene at `scene_path` needs; with both, the scene must
/// be one the configuration renders (the refusal names why, and what the
/// scene needs). Returns the loaded scene too.
pub fn choose_build<A: cosim::arch::Arch>(
    cmd: &str,
    scene_path: Option<&Path>,
    config: Option<&str>,
) -> Result<(Option<Loaded>, A::Config)> {
    let err = |e: String| anyhow::anyhow!("{cmd}: {e}");
    let loaded = match scene_path {
        Some(path) => {
            let scene = Scene::load(path)?;
            let camera = scene.camera();
            Some(Loaded {
                name: scene_name(path),
                scene,
                camera,
            })
        }
        None => None,
    };
    let needed = match &loaded {
        Some(l) => {
            let s = l.export();
            Some(A::needs(s.scene, s.camera, s.dims).map_err(err)?)
        }
        None => None,
    };
    let build = match (config, needed) {
        (Some(name), needed) => {
            let build = A::parse_config(name).map_err(err)?;
            if let Some(n) = needed {
                if let Some(why) = A::refuses(&build, &n) {
                    bail!(
                        "{cmd}: configuration {name} cannot render {}: {why} (it needs {})",
                        scene_path.map_or(String::new(), |p| p.display().to_string()),
                        A::config_name(&n)
                    );
                }
            }
            build
        }
        (None, Some(n)) => n,
        (None, None) => bail!("{cmd}: give --scene, --config or both"),
    };
    Ok((loaded, build))
}

#[derive(Debug)]
pub struct Rendered {
    pub image: Image,
    pub seconds: f64,
    pub extra: Value,
}

/// Render with `arch`; `gradient` overrides the scene's Cube-3 neighbourhood
/// (Cube-3 and True3D). The golden models keep their traversal-order copies
/// of the volume in `vol` for the next render; a copy's time is the
/// volume's preparation (`volume_prep_seconds`, in every render of the
/// volume; null where the view reads the volume as it is), not the frame's
/// (`frame_seconds`).
pub fn render_arch(
    scene: &Scene,
    ordered: &Ordered,
    arch: Arch,
    ref_step: f64,
    gradient: Option<u32>,
) -> Result<Rendered> {
    render_with(scene, ordered, arch, ref_step, gradient, &Kept::default())
}

/// Prints a warning line once per run, however many renders of the scene
/// the subcommand makes (`tradeoff` renders one scene many times).
fn warn_once(message: &str) {
    static SAID: std::sync::Mutex<Vec<String>> = std::sync::Mutex::new(Vec::new());
    let mut said = SAID.lock().unwrap_or_else(|e| e.into_inner());
    if !said.iter().any(|m| m == message) {
        eprintln!("cube: warning: {}", crate::message::one_line(message));
        said.push(message.to_string());
    }
}

/// What [`render_repeat`]'s renders of one scene and volume work out once
/// and share.
#[derive(Default)]
struct Kept {
    /// The golden models' RTL clock count (Cube-3 takes about as long to
    /// work it out as a quarter of a frame).
    clocks: OnceCell<Option<u64>>,
    /// The quantized path's grid (per volume), and the seconds it took.
    grid: OnceCell<(golden_model::quantized::Grid, f64)>,
}

/// [`render_arch`], taking from `kept` what an earlier render of the same
/// scene and volume worked out.
fn render_with(
    scene: &Scene,
    ordered: &Ordered,
    arch: Arch,
    ref_step: f64,
    gradient: Option<u32>,
    kept: &Kept,
) -> Result<Rendered> {
    crate::budget::check(scene, arch, ref_step)?;
    let vol = ordered.volume();
    let copied = ordered.copy_seconds().unwrap_or(0.0);
    let t = Instant::now();
    // A golden model's frame, without the copies it made.
    let without_copies = |seconds: f64| seconds - (ordered.copy_seconds().unwrap_or(0.0) - copied);
    let rendered: Result<Rendered> = match arch {
        Arch::Cube4l => {
            let (image, frame) = golden_model::cube4l::render_image(scene, ordered)?;
            let seconds = t.elapsed().as_secs_f64();
            let frame_seconds = without_copies(seconds);
            let s = frame.stats;
            let caveat = frame.plan.caveat.map(|c| {
                warn_once(&c.to_string());
                json!({
                    "message": c.to_string(),
                    "eye_inside": c.inside,
                    "edge_voxels": c.edge_voxels,
                    "expected_error_percent": c.expected_error_percent,
                })
            });
            // The RTL's schedule: what `cube sim` counts.
            let clocks = *kept.clocks.get_or_init(|| {
                rtl_clocks::<cosim::cube4l::Cube4l>(scene, &scene.camera(), vol.dims)
            });
            Ok(Rendered {
                image,
                seconds,
                extra: json!({
                    "sweeps": frame.plan.sweeps.len(),
                    "clocks": clocks,
                    "voxels": s.voxels,
                    "voxels_shaded": s.shaded,
                    "voxels_terminated": s.terminated,
                    "saturations": s.saturations,
                    "volume_prep_seconds": ordered.copy_seconds(),
                    "frame_seconds": frame_seconds,
                    "voxels_per_second": s.voxels as f64 / frame_seconds,
                    "accuracy_caveat": caveat,
                }),
            })
        }
        Arch::Cube3 => {
            let n = golden_model::cube3::neighbourhood(scene, gradient)?;
            let (image, frame) = golden_model::cube3::render_image(scene, ordered, n)?;
            let seconds = t.elapsed().as_secs_f64();
            let frame_seconds = without_copies(seconds);
            let s = frame.stats;
            let v = &frame.plan.views[0];
            // The RTL's schedule for this neighbourhood, where it builds it.
            let rtl = scene.with(|s| s.cube3.gradient = n.count())?;
            let clocks = *kept
                .clocks
                .get_or_init(|| rtl_clocks::<cosim::cube3::Cube3>(&rtl, &rtl.camera(), vol.dims));
            Ok(Rendered {
                image,
                seconds,
                extra: json!({
                    "gradient": n.count(),
                    "base_planes": frame.plan.views.len(),
                    "offset": v.offset,
                    "weight_bits": frame.widths.weight_bits,
                    "sample_bits": frame.widths.sample_bits,
                    "gradient_bits": frame.widths.gradient_bits,
                    "pipelines": frame.pipelines,
                    "trilin_left_out": frame.plan.views.iter().all(|v| v.on_grid),
                    "rays": s.rays,
                    "samples": s.samples,
                    "clocks": clocks,
                    "samples_interpolated": s.interpolated,
                    "samples_shaded": s.shaded,
                    "samples_terminated": s.terminated,
                    "gradient_saturations": s.gradient_saturations,
                    "composite_saturations": s.composite_saturations,
                    "weight_clamps": s.weight_clamps,
                    "volume_prep_seconds": ordered.copy_seconds(),
                    "frame_seconds": frame_seconds,
                    "samples_per_second": s.samples as f64 / frame_seconds,
                }),
            })
        }
        Arch::True3d | Arch::ShearedFloat => {
            let cam = scene.camera();
            let n = gradient.unwrap_or(scene.cube3.gradient);
            let interp = if arch == Arch::True3d {
                reference::true3d::Interp::Exact
            } else {
                reference::true3d::Interp::Sheared
            };
            let image = reference::true3d::render(scene, &cam, vol, n, interp)?;
            Ok(Rendered {
                image,
                seconds: t.elapsed().as_secs_f64(),
                extra: json!({ "gradient": n }),
            })
        }
        Arch::QuantizedProjection | Arch::QuantizedSplat => {
            use golden_model::quantized::{self as q, Method};
            let method = if arch == Arch::QuantizedProjection {
                Method::Projection
            } else {
                Method::Splat
            };
            let params = q::Params::of(scene, method)?;
            // The grid's time is the volume's preparation, in every render
            // (as the golden models' copies are).
            let (grid, volume_s) = kept.grid.get_or_init(|| {
                let t = Instant::now();
                (q::Grid::new(vol, params.normals), t.elapsed().as_secs_f64())
            });
            let tc = Instant::now();
            let mut classes = q::Classes::new(scene, grid, &params);
            let classify_s = tc.elapsed().as_secs_f64();
            let (image, s, times, view) = q::frame(scene, grid, &mut classes, &params)?;
            let seconds = t.elapsed().as_secs_f64();
            // A transfer-function change: the same function set again,
            // timed through classification and rendering.
            let tf = Instant::now();
            q::reclassify(scene, grid, &view, &params);
            let tf_change_s = tf.elapsed().as_secs_f64();
            let frame_s = times.view + times.render;
            Ok(Rendered {
                image,
                seconds,
                extra: json!({
                    "subdivisions": params.n,
                    "normals": params.normals,
                    "empty_space": format!("{:?}", params.empty_space),
                    "order": format!("{:?}", params.order),
                    "volume_prep_seconds": volume_s,
                    "view_prep_seconds": times.view,
                    "classify_seconds": classify_s,
                    "render_seconds": times.render,
                    "frame_seconds": frame_s,
                    "tf_change_seconds": tf_change_s,
                    "voxels": s.voxels,
                    "blocks": s.blocks,
                    "blocks_live": s.blocks_live,
                    "voxels_inspected": s.inspected,
                    "voxels_treated": s.treated,
                    "voxels_occluded": s.occluded,
                    "classes": s.classes,
                    "table_entries": s.entries,
                    "treated_per_second": s.treated as f64 / times.render,
                }),
            })
        }
        Arch::Reference => {
            let cam = scene.camera();
            let image = reference::render(scene, &cam, vol, ref_step);
            Ok(Rendered {
                image,
                seconds: t.elapsed().as_secs_f64(),
                // The camera in dataset voxel coordinates, for aligning
                // other renderers (scripts/peers).
                extra: json!({
                    "step": ref_step,
                    "camera": {
                        "right": cam.right.to_array(),
                        "up": cam.up.to_array(),
                        "forward": cam.forward.to_array(),
                        "origin": cam.origin.to_array(),
                        "scale": cam.scale,
                    },
                }),
            })
        }
    };
    finite(arch, rendered?)
}

/// Every render comes out through here, so no figure made from its image
/// (an error, a plot, a table) can be NaN: a pixel that is not a finite
/// number is an error naming it, never an image or a figure.
fn finite(arch: Arch, r: Rendered) -> Result<Rendered> {
    let w = r.image.width.max(1) as usize;
    if let Some(i) = r
        .image
        .rgb
        .iter()
        .position(|p| p.iter().any(|c| !c.is_finite()))
    {
        bail!(
            "{}: pixel ({}, {}) is {:?}, not a number an image holds: the scene's figures are beyond what this method computes in",
            arch.name(),
            i % w,
            i / w,
            r.image.rgb[i]
        );
    }
    Ok(r)
}

/// Render `repeat` times: `seconds` and every `*_seconds` detail become
/// the median over the runs; the image and the other details are the last
/// run's (every architecture is deterministic).
pub fn render_repeat(
    scene: &Scene,
    vol: &Volume,
    arch: Arch,
    ref_step: f64,
    gradient: Option<u32>,
    repeat: usize,
) -> Result<Rendered> {
    // Every run's times, and the last run's image only: memory does not
    // grow with the repeats.
    let mut times: Vec<(f64, Value)> = Vec::with_capacity(repeat);
    let mut last = None;
    let ordered = Ordered::new(vol);
    let kept = Kept::default();
    for _ in 0..repeat.max(1) {
        let r = render_with(scene, &ordered, arch, ref_step, gradient, &kept)?;
        times.push((r.seconds, r.extra.clone()));
        last = Some(r);
    }
    let Rendered { image, extra, .. } = last.expect("at least one run");
    let median = |f: &dyn Fn(&(f64, Value)) -> f64| {
        let mut v: Vec<f64> = times.iter().map(f).collect();
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    let seconds = median(&|r| r.0);
    let mut extra = extra;
    if let Value::Object(map) = &mut extra {
        let keys: Vec<String> = map
            .keys()
            .filter(|k| k.ends_with("_seconds"))
            .cloned()
            .collect();
        for k in keys {
            map[&k] = json!(median(&|r| r.1[&k].as_f64().unwrap_or(f64::NAN)));
        }
        if repeat > 1 {
            map.insert("repeat".into(), json!(repeat));
        }
    }
    Ok(Rendered {
        image,
        seconds,
        extra,
    })
}

/// What an error figure says when neither image has a foreground pixel.
pub const NO_FOREGROUND: &str = "n/a (neither image has a foreground pixel: nothing to measure)";

/// A figure to `digits` decimals, or `n/a` when there is none.
pub fn na_or(x: Option<f64>, digits: usize) -> String {
    x.map_or("n/a".into(), |x| format!("{x:.digits$}"))
}

/// What the PSNR figure says for two identical images (no error, so no
/// finite ratio; JSON gives null).
pub const IDENTICAL: &str = "n/a (identical images)";

/// The PSNR to `digits` decimals, or [`IDENTICAL`] when it is infinite.
pub fn psnr_text(db: f64, digits: usize) -> String {
    if db.is_finite() {
        format!("{db:.digits$}")
    } else {
        IDENTICAL.into()
    }
}

/// The PSNR with its unit, or [`IDENTICAL`].
pub fn psnr_db_text(db: f64, digits: usize) -> String {
    if db.is_finite() {
        format!("{db:.digits$} dB")
    } else {
        IDENTICAL.into()
    }
}

/// The error figures on one line, or why there are none.
pub fn error_line(m: &Option<ErrorMetrics>) -> String {
    match m {
        None => format!("error {NO_FOREGROUND}"),
        Some(m) => format!(
            "error: rel. Euclidean {:.3} % (foreground / sqrt 3; all pixels {:.3} %, of the reference's magnitude {} %), RMSE {:.5}, PSNR {}, max {:.4}",
            m.rel_euclid_pct,
            m.rel_euclid_all_pct,
            na_or(m.rel_euclid_to_ref_pct, 3),
            m.rmse,
            psnr_db_text(m.psnr_db, 2),
            m.max_abs
        ),
    }
}

/// The error figures as JSON: each `"n/a"` when there is nothing to
/// measure, with `foreground_pixels` 0 and the reason.
pub fn error_json(m: &Option<ErrorMetrics>) -> Value {
    let Some(m) = m else {
        return json!({
            "rel_euclid_pct": "n/a",
            "rel_euclid_all_pct": "n/a",
            "rel_euclid_to_ref_pct": "n/a",
            "rmse": "n/a",
            "psnr_db": "n/a",
            "max_abs": "n/a",
            "foreground_pixels": 0,
            "not_available": NO_FOREGROUND,
        });
    };
    json!({
        "rel_euclid_pct": m.rel_euclid_pct,
        "rel_euclid_all_pct": m.rel_euclid_all_pct,
        "rel_euclid_to_ref_pct": m.rel_euclid_to_ref_pct.map_or(json!("n/a"), |x| json!(x)),
        "rmse": m.rmse,
        "psnr_db": if m.psnr_db.is_finite() { json!(m.psnr_db) } else { json!(null) },
        "max_abs": m.max_abs,
        "foreground_pixels": m.foreground_pixels,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A NaN or infinite pixel ends the run with its place, before any
    /// figure is made from it.
    #[test]
    fn a_pixel_that_is_not_finite_is_an_error() {
        let image = |bad: f64| Image {
            width: 3,
            height: 2,
            rgb: (0..6)
                .map(|i| if i == 4 { [0.5, bad, 0.0] } else { [0.5; 3] })
                .collect(),
        };
        let of = |bad| Rendered {
            image: image(bad),
            seconds: 0.0,
            extra: Value::Null,
        };
        for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            let e = finite(Arch::QuantizedSplat, of(bad))
                .unwrap_err()
                .to_string();
            assert!(e.starts_with("quantized-splat: pixel (1, 1) is"), "{e}");
        }
        assert!(finite(Arch::QuantizedSplat, of(0.25)).is_ok());
    }
}
