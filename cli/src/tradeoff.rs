//! `cube tradeoff`: error against cost for every method that applies to a
//! scene, over a grid of precisions and method parameters, with the Pareto
//! front. The standing requirement "report error against run time" as one
//! table, one plot and one JSON.
//!
//! A method is one entry of [`FAMILIES`]: its name, the architecture that
//! renders it, whether its cost is counted in hardware clocks, and the
//! scene patches of its grid. Adding a method is adding an entry.
//!
//! The yardstick is the float reference at a step where it has converged:
//! the step is halved until the reference at `s` and at `s/2` differ by less
//! than `--tolerance` (relative Euclidean, %), and the image at `s/2` is the
//! yardstick. Coarser reference steps are points of their own.
//!
//! A hardware point costs its RTL's clocks per frame (the schedule `cube
//! sim` asserts) at the fmax of the committed ECP5 report of the smallest
//! committed build that renders it ([`crate::reports`]), whose LUT4,
//! multipliers and block RAMs are its area; where no report has an fmax, at
//! an assumed clock, said so on the point.

use crate::common::render_repeat;
use crate::methods::Arch;
use crate::output::Files;
use crate::reports::{pricing_build, Measured};
use anyhow::{bail, Context, Result};
use indicatif::{ProgressBar, ProgressStyle};
use plotters::prelude::*;
use reference::metrics::{compare, ErrorMetrics};
use scene::volume::Volume;
use scene::{Image, Scene};
use serde_json::{json, Map, Value};
use std::collections::HashMap;
use std::path::{Path, PathBuf};

#[derive(clap::Args)]
pub struct TradeoffArgs {
    #[arg(long)]
    scene: PathBuf,
    /// Directory for tradeoff.json, .csv, .png and .md.
    #[arg(long)]
    out: PathBuf,
    /// Methods to sweep, comma-separated (default: every one that applies
    /// to the scene): reference, cube4l, cube3, true3d,
    /// quantized-projection, quantized-splat.
    #[arg(long, value_delimiter = ',')]
    methods: Option<Vec<String>>,
    /// Software times are the median of this many runs.
    #[arg(long, default_value_t = 3)]
    repeat: usize,
    /// Clock of every hardware point, in MHz, instead of the committed
    /// reports' fmax (marked "given" in every output).
    #[arg(long)]
    clock_mhz: Option<f64>,
    /// Convergence tolerance of the reference yardstick: relative Euclidean
    /// error (%) between steps s and s/2.
    #[arg(long, default_value_t = 0.1)]
    tolerance: f64,
}

/// The clock assumed for a hardware point that no placed-and-routed report
/// prices.
const ASSUMED_MHZ: f64 = 100.0;
/// Reference steps tried, coarsest first; the finest is the last resort.
const REF_STEPS: [f64; 7] = [1.0, 0.5, 0.25, 0.125, 0.0625, 0.03125, 0.015625];

/// One method of the sweep.
struct Family {
    name: &'static str,
    arch: Arch,
    /// Whether the method is hardware, costed in clocks.
    hardware: bool,
    /// The grid: each point's parameters as (name, value) and its patch of
    /// the scene JSON.
    grid: fn(&Scene) -> Vec<Variant>,
}

struct Variant {
    params: Vec<(&'static str, Value)>,
    patch: Value,
    /// Cube-3 and True3D: the gradient neighbourhood.
    gradient: Option<u32>,
}

fn variant(params: Vec<(&'static str, Value)>, patch: Value) -> Variant {
    Variant {
        params,
        patch,
        gradient: None,
    }
}

const FAMILIES: [Family; 5] = [
    Family {
        name: "cube4l",
        arch: Arch::Cube4l,
        hardware: true,
        grid: cube4l_grid,
    },
    Family {
        name: "cube3",
        arch: Arch::Cube3,
        hardware: true,
        grid: cube3_grid,
    },
    Family {
        name: "true3d",
        arch: Arch::True3d,
        hardware: false,
        grid: true3d_grid,
    },
    Family {
        name: "quantized-projection",
        arch: Arch::QuantizedProjection,
        hardware: false,
        grid: projection_grid,
    },
    Family {
        name: "quantized-splat",
        arch: Arch::QuantizedSplat,
        hardware: false,
        grid: splat_grid,
    },
];

/// One width at a time around the scene's own: `frac_bits`, `rgba_bits`,
/// and `voxel_bits` (the transfer function and a raw volume's window scaled
/// with it, so the scene stays the same scene).
fn cube4l_grid(scene: &Scene) -> Vec<Variant> {
    let hw = scene.hardware;
    let mut v = Vec::new();
    for f in [4, 6, 8, 10, 12] {
        v.push(variant(
            hw_params(f, hw.rgba_bits, hw.voxel_bits),
            json!({"hardware": {"frac_bits": f}}),
        ));
    }
    for r in [5, 6, 8, 10, 12] {
        v.push(variant(
            hw_params(hw.frac_bits, r, hw.voxel_bits),
            json!({"hardware": {"rgba_bits": r}}),
        ));
    }
    for b in [8, 12, 16] {
        v.push(variant(
            hw_params(hw.frac_bits, hw.rgba_bits, b),
            json!({"hardware": {"voxel_bits": b}}),
        ));
    }
    // The normal's width matters only where the scene lights.
    if scene.lit() {
        for n in [4, 6, 7] {
            let mut params = hw_params(hw.frac_bits, hw.rgba_bits, hw.voxel_bits);
            params.push(("normal_bits", json!(n)));
            v.push(variant(params, json!({"hardware": {"normal_bits": n}})));
        }
    }
    v
}

fn hw_params(frac: u32, rgba: u32, voxel: u32) -> Vec<(&'static str, Value)> {
    vec![
        ("frac_bits", json!(frac)),
        ("rgba_bits", json!(rgba)),
        ("voxel_bits", json!(voxel)),
    ]
}

/// The four ABC neighbourhoods at the scene's widths, then the weight
/// (`frac_bits`) and sample widths one at a time at the 12-neighbourhood,
/// and the widths where the model's rounding stops mattering (12-bit
/// weights and RGBA unlit, 12-bit weights and 6-bit normals lit: within
/// 0.5 % of its float twin, docs/accuracy.md).
fn cube3_grid(scene: &Scene) -> Vec<Variant> {
    let hw = scene.hardware;
    let vb = hw.voxel_bits;
    let sb = scene.cube3.sample_bits(vb);
    let params = |g: u32, f: u32, s: u32| {
        vec![
            ("gradient", json!(g)),
            ("frac_bits", json!(f)),
            ("sample_bits", json!(s)),
        ]
    };
    let mut v = Vec::new();
    for g in [6, 10, 12, 26] {
        v.push(Variant {
            gradient: Some(g),
            ..variant(params(g, hw.frac_bits, sb), json!({}))
        });
    }
    for f in [4, 6, 10, 12] {
        v.push(Variant {
            gradient: Some(12),
            ..variant(params(12, f, sb), json!({"hardware": {"frac_bits": f}}))
        });
    }
    // The knees: 12-bit RGBA beside the weights, and lit, 6-bit normals.
    let knees = [("rgba_bits", 12), ("normal_bits", 6)];
    for (width, bits) in knees.into_iter().take(1 + scene.lit() as usize) {
        let mut knee = params(12, 12, sb);
        knee.push((width, json!(bits)));
        v.push(Variant {
            gradient: Some(12),
            ..variant(knee, json!({"hardware": {"frac_bits": 12, width: bits}}))
        });
    }
    for s in [vb, vb + 2, vb + 6, vb + 8] {
        v.push(Variant {
            gradient: Some(12),
            ..variant(
                params(12, hw.frac_bits, s),
                json!({"cube3": {"sample_bits": s, "gradient_bits": null}}),
            )
        });
    }
    v
}

fn true3d_grid(_: &Scene) -> Vec<Variant> {
    [6, 10, 12, 26]
        .map(|g| Variant {
            gradient: Some(g),
            ..variant(vec![("gradient", json!(g))], json!({}))
        })
        .into()
}

fn quantized(n: u32, normals: u32) -> Variant {
    variant(
        vec![("subdivisions", json!(n)), ("normals", json!(normals))],
        json!({"quantized": {"subdivisions": n, "normals": normals}}),
    )
}

fn projection_grid(_: &Scene) -> Vec<Variant> {
    let mut v: Vec<Variant> = [1, 4, 16, 64, 256].map(|n| quantized(n, 8192)).into();
    v.extend([64, 512, 2048, 32768].map(|k| quantized(64, k)));
    v
}

fn splat_grid(_: &Scene) -> Vec<Variant> {
    let mut v: Vec<Variant> = [2, 8, 16, 32, 64].map(|n| quantized(n, 8192)).into();
    v.extend([64, 512, 2048, 32768].map(|k| quantized(32, k)));
    v
}

/// One measured point.
struct Point {
    method: String,
    params: Map<String, Value>,
    error: ErrorMetrics,
    /// Median wall time of one render from the loaded volume (hardware
    /// methods: of their golden model).
    software_seconds: f64,
    /// The quantized path: its per-volume preprocessing, within
    /// `software_seconds` but not in the per-frame cost.
    volume_prep_seconds: Option<f64>,
    hw: Option<HwPrice>,
    cost_seconds: f64,
    image_hash: String,
    /// The golden model's warning that its error may exceed its usual
    /// range for this view (Cube-4L's near-edge perspective caveat).
    caveat: Option<Value>,
}

/// What a hardware point costs and where each figure comes from.
struct HwPrice {
    clocks: u64,
    /// "rtl" (the RTL's schedule) or "ideal" (samples over p: the RTL does
    /// not build this point).
    clocks_from: &'static str,
    mhz: f64,
    /// "measured" (the report's fmax), "given" (`--clock-mhz`) or
    /// "assumed".
    clock_from: &'static str,
    /// The committed build whose report priced the point.
    build: Option<Measured>,
}

impl HwPrice {
    fn frame_seconds(&self) -> f64 {
        self.clocks as f64 / (self.mhz * 1e6)
    }
}

/// How a tradeoff.json the command wrote begins (its first key, `about`,
/// sorts first).
const MARK: &str = "{\n  \"about\": \"written by cube tradeoff";

pub fn run(args: TradeoffArgs) -> Result<()> {
    if !(1..=100).contains(&args.repeat) {
        bail!("--repeat {} must lie in 1..=100", args.repeat);
    }
    if !(args.tolerance.is_finite() && args.tolerance > 0.0 && args.tolerance <= 10.0) {
        bail!("--tolerance {} must lie in (0, 10] %", args.tolerance);
    }
    if let Some(f) = args
        .clock_mhz
        .filter(|f| !(f.is_finite() && (0.1..=10_000.0).contains(f)))
    {
        bail!("--clock-mhz {f} must lie in [0.1, 10000]");
    }
    let generated = crate::reports::generated_dir();
    let text = scene::spec::read_text(&args.scene)?;
    let base: Value = serde_json::from_str(&text)
        .with_context(|| format!("{}: not JSON", args.scene.display()))?;
    let dir = args.scene.parent().map(Path::to_path_buf);
    let scene = Scene::from_json(&text, dir.as_deref())?;
    let wanted: Vec<String> = match &args.methods {
        Some(m) => {
            for name in m {
                if name != "reference" && !FAMILIES.iter().any(|f| f.name == name) {
                    bail!(
                        "--methods: unknown method '{name}' (reference, {})",
                        names()
                    );
                }
            }
            m.clone()
        }
        None => std::iter::once("reference".to_string())
            .chain(FAMILIES.iter().map(|f| f.name.to_string()))
            .collect(),
    };
    if std::fs::metadata(&args.out).is_ok_and(|m| !m.is_dir()) {
        bail!("--out {} is not a directory", args.out.display());
    }
    let files = [
        "tradeoff.json",
        "tradeoff.csv",
        "tradeoff.png",
        "tradeoff.md",
        "tradeoff_area.png",
    ]
    .map(|f| args.out.join(f));
    let mut run_files = Files::default();
    run_files.scene("--scene", &args.scene, &scene)?;
    for f in &files {
        run_files.output("--out", f)?;
    }
    // The five files are replaced only where a run of this command wrote
    // them: a user's tradeoff.md in --out is never lost.
    let ours = std::fs::read(&files[0]).is_ok_and(|b| b.starts_with(MARK.as_bytes()));
    if !ours {
        if let Some(f) = files.iter().find(|f| std::fs::symlink_metadata(f).is_ok()) {
            bail!(
                "--out {}: {} exists and no cube tradeoff run wrote it (the folder has no tradeoff.json of one): move it, or write elsewhere",
                args.out.display(),
                f.display()
            );
        }
    }

    // Which methods apply, and their grids.
    let mut plan: Vec<(&Family, Variant)> = Vec::new();
    let mut skipped: Vec<(String, String)> = Vec::new();
    for f in FAMILIES
        .iter()
        .filter(|f| wanted.iter().any(|w| w == f.name))
    {
        match applies(f, &scene) {
            Ok(()) => {
                // One-at-a-time sweeps meet at the scene's own point: keep it once.
                for v in (f.grid)(&scene) {
                    if !plan
                        .iter()
                        .any(|(g, w)| g.name == f.name && w.params == v.params)
                    {
                        plan.push((f, v));
                    }
                }
            }
            Err(why) if args.methods.is_some() => bail!("--methods: {} {why}", f.name),
            Err(why) => skipped.push((f.name.to_string(), why)),
        }
    }
    let with_reference = wanted.iter().any(|w| w == "reference");
    let bar = ProgressBar::new((plan.len() + REF_STEPS.len()) as u64);
    bar.set_style(
        ProgressStyle::with_template("{bar:40} {pos}/{len} {msg} [{elapsed}]")
            .expect("progress template"),
    );

    // The yardstick.
    let vol = Volume::from_spec(&scene.volume, scene.hardware.voxel_bits)?;
    let mut refs: Vec<(f64, Image, f64)> = Vec::new();
    let mut converged = None;
    for &step in &REF_STEPS {
        bar.set_message(format!("reference step {step}"));
        let r = render_repeat(&scene, &vol, Arch::Reference, step, None, args.repeat)?;
        bar.inc(1);
        if compare(&r.image, &r.image).is_none() {
            bail!(
                "tradeoff: the reference image has no foreground pixels (an empty volume, a transparent transfer function or a view that misses the volume): there is no error to weigh against cost"
            );
        }
        if let Some((s, prev, _)) = refs.last() {
            let d = compare(prev, &r.image)
                .expect("the reference has foreground pixels (checked above)")
                .rel_euclid_pct;
            if d < args.tolerance {
                converged = Some((*s, step, d));
                refs.push((step, r.image, r.seconds));
                break;
            }
        }
        refs.push((step, r.image, r.seconds));
    }
    bar.set_length((plan.len() + refs.len()) as u64);
    let (yard_step, yard) = {
        let (s, img, _) = refs.last().unwrap();
        (*s, img.clone())
    };
    let mut points = Vec::new();
    if with_reference {
        for (step, img, seconds) in &refs[..refs.len() - 1] {
            let mut params = Map::new();
            params.insert("step".into(), json!(step));
            points.push(point(
                "reference",
                params,
                img,
                &yard,
                *seconds,
                None,
                *seconds,
            ));
        }
    }

    // The methods.
    let mut volumes: HashMap<u32, Volume> = HashMap::new();
    volumes.insert(scene.hardware.voxel_bits, vol);
    for (f, v) in &plan {
        let label = v
            .params
            .iter()
            .map(|(k, x)| format!("{k} {x}"))
            .collect::<Vec<_>>()
            .join(", ");
        bar.set_message(format!("{} {label}", f.name));
        let s = patched(&base, &v.patch, &scene, dir.as_deref())
            .with_context(|| format!("{} {label}", f.name))?;
        let bits = s.hardware.voxel_bits;
        if let std::collections::hash_map::Entry::Vacant(e) = volumes.entry(bits) {
            e.insert(Volume::from_spec(&s.volume, bits)?);
        }
        let r = match render_repeat(
            &s,
            &volumes[&bits],
            f.arch,
            yard_step,
            v.gradient,
            args.repeat,
        ) {
            // A point past the memory or work budget is left out, and said.
            Err(e) if e.downcast_ref::<crate::budget::OverBudget>().is_some() => {
                skipped.push((format!("{} {label}", f.name), e.to_string()));
                bar.inc(1);
                continue;
            }
            r => r.with_context(|| format!("{} {label}", f.name))?,
        };
        let hw = match f.hardware {
            true => Some(
                price(f.arch, &s, &r.extra, args.clock_mhz, &generated)
                    .with_context(|| format!("{} {label}", f.name))?,
            ),
            false => None,
        };
        // Per frame: the quantized path's per-volume preprocessing is paid
        // once per volume, not per frame (it is in the row on its own).
        let cost = match &hw {
            Some(h) => h.frame_seconds(),
            None => r.extra["frame_seconds"].as_f64().unwrap_or(r.seconds),
        };
        let params: Map<String, Value> = v
            .params
            .iter()
            .map(|(k, x)| (k.to_string(), x.clone()))
            .collect();
        let mut p = point(f.name, params, &r.image, &yard, r.seconds, hw, cost);
        p.volume_prep_seconds = r.extra["volume_prep_seconds"].as_f64();
        p.caveat = Some(r.extra["accuracy_caveat"].clone()).filter(|c| !c.is_null());
        points.push(p);
        bar.inc(1);
    }
    bar.finish_and_clear();

    let front = pareto(&points);
    let assumed = points
        .iter()
        .filter(|p| p.hw.as_ref().is_some_and(|h| h.clock_from == "assumed"))
        .count();
    let clock = json!({
        "given_mhz": args.clock_mhz,
        "assumed_mhz": ASSUMED_MHZ,
        "points_assumed": assumed,
        "reports": generated.join("synth").display().to_string(),
    });
    let rows: Vec<Value> = points
        .iter()
        .enumerate()
        .map(|(i, p)| row_json(p, front.contains(&i)))
        .collect();
    let notes = identical_notes(&points);
    let yardstick = json!({
        "step": yard_step,
        "tolerance_pct": args.tolerance,
        "converged": converged.map(|(s, h, d)| json!({"step": s, "half": h, "difference_pct": d})),
    });
    let report = json!({
        "about": "written by cube tradeoff: the next run into this folder replaces its five files",
        "scene": args.scene.display().to_string(),
        "repeat": args.repeat,
        "threads": rayon::current_num_threads(),
        "clock": clock,
        "yardstick": yardstick,
        "skipped": skipped.iter().map(|(m, w)| json!({"method": m, "reason": w})).collect::<Vec<_>>(),
        "identical_images": notes,
        "points": rows,
    });
    // Everything is computed before anything is written.
    let png = plot(&points, &front)?;
    let area_png = plot_area(&points)?;
    let csv = csv(&points, &front);
    let md = markdown(&points, &front, &report);
    run_files.json(&files[0], &report)?;
    run_files.text(&files[1], &csv)?;
    run_files.png_rgb8(&files[2], PLOT_W, PLOT_H, png)?;
    run_files.text(&files[3], &md)?;
    run_files.png_rgb8(&files[4], PLOT_W, PLOT_H, area_png)?;
    run_files.commit()?;
    println!(
        "{} points, {} on the Pareto front; yardstick: reference at step {yard_step}{}; hardware points: {}",
        points.len(),
        front.len(),
        match converged {
            Some((s, h, d)) => format!(" (steps {s} and {h} differ by {d:.4} % < {} %)", json!(args.tolerance)),
            None => format!(" (NOT converged to {} %: the finest step tried)", json!(args.tolerance)),
        },
        hw_summary(&points)
    );
    for (m, w) in &skipped {
        println!("skipped {m}: {w}");
    }
    println!("wrote {}", args.out.display());
    Ok(())
}

fn names() -> String {
    FAMILIES.map(|f| f.name).join(", ")
}

/// Whether a method can render the scene at all, and if not why.
fn applies(f: &Family, scene: &Scene) -> std::result::Result<(), String> {
    use golden_model::quantized::{Method, Params};
    let r = match f.arch {
        Arch::QuantizedProjection => Params::of(scene, Method::Projection).map(|_| ()),
        Arch::QuantizedSplat => Params::of(scene, Method::Splat).map(|_| ()),
        // Cube-3 casts rays from the volume's faces: a perspective eye inside
        // the volume's slab has none.
        Arch::Cube3 => golden_model::cube3::plan::Plan::new(scene, &scene.camera()).map(|_| ()),
        Arch::True3d => reference::true3d::check(scene, &scene.camera()),
        _ => Ok(()),
    };
    r.map_err(|e| e.to_string())
}

/// The scene with `patch` merged into its JSON. Changing `voxel_bits`
/// rescales the transfer function's intensities and gradient magnitudes,
/// and gives a raw volume without a window the window of its own range, so
/// the same tissue keeps the same colour at every width.
fn patched(base: &Value, patch: &Value, scene: &Scene, dir: Option<&Path>) -> Result<Scene> {
    let mut v = base.clone();
    merge(&mut v, patch);
    let from = scene.hardware.voxel_bits;
    if let Some(to) = patch["hardware"]["voxel_bits"].as_u64() {
        let k = ((1u64 << to) - 1) as f64 / ((1u64 << from) - 1) as f64;
        let tf = &scene.transfer;
        let scale = |pts: Vec<Vec<f64>>| -> Vec<Vec<f64>> {
            pts.into_iter()
                .map(|mut p| {
                    p[0] *= k;
                    p
                })
                .collect()
        };
        v["transfer"] = json!({
            "opacity": scale(tf.opacity.iter().map(|p| p.to_vec()).collect()),
            "color": scale(tf.color.iter().map(|p| p.to_vec()).collect()),
            "gradient_opacity": tf.gradient_opacity.as_ref().map(|g| scale(g.iter().map(|p| p.to_vec()).collect())),
            "opaque_threshold": tf.opaque_threshold,
        });
        if tf.gradient_opacity.is_none() {
            v["transfer"]
                .as_object_mut()
                .unwrap()
                .remove("gradient_opacity");
        }
        if v["volume"].get("raw").is_some() && v["volume"].get("window").is_none() {
            // Only a raw volume's own range is known: the scene's width.
            v["volume"]["window"] = json!([0, (1u64 << from) - 1]);
        }
    }
    Ok(Scene::from_json(&v.to_string(), dir)?)
}

fn merge(a: &mut Value, b: &Value) {
    match (a, b) {
        (Value::Object(a), Value::Object(b)) => {
            for (k, v) in b {
                if v.is_null() {
                    a.remove(k);
                } else {
                    merge(a.entry(k.clone()).or_insert(Value::Null), v);
                }
            }
        }
        (a, b) => *a = b.clone(),
    }
}

/// A hardware point's price. Clocks: the RTL's schedule (Cube-4L always;
/// Cube-3 where its RTL builds the point, else its samples over its `p`
/// units, marked "ideal"). Clock and area: the committed report of the
/// smallest committed build that renders the point; `--clock-mhz`
/// overrides the clock; with neither, [`ASSUMED_MHZ`].
fn price(
    arch: Arch,
    scene: &Scene,
    extra: &Value,
    given_mhz: Option<f64>,
    generated: &Path,
) -> Result<HwPrice> {
    let p = scene.hardware.pipelines as u64;
    let (clocks, clocks_from) = match (arch, extra["clocks"].as_u64()) {
        (_, Some(c)) => (c, "rtl"),
        (Arch::Cube4l, None) => {
            bail!("the Cube-4L RTL does not build this scene: no clocks to cost it by")
        }
        (_, None) => (extra["samples"].as_u64().unwrap_or(0).div_ceil(p), "ideal"),
    };
    let camera = scene.camera();
    let dims = scene.volume.render_dims();
    let build = match arch {
        Arch::Cube4l => pricing_build::<cosim::cube4l::Cube4l>(generated, scene, &camera, dims),
        _ => pricing_build::<cosim::cube3::Cube3>(generated, scene, &camera, dims),
    };
    let (mhz, clock_from) = match (given_mhz, build.as_ref().and_then(|b| b.fmax_mhz)) {
        (Some(f), _) => (f, "given"),
        (None, Some(f)) => (f, "measured"),
        (None, None) => (ASSUMED_MHZ, "assumed"),
    };
    Ok(HwPrice {
        clocks,
        clocks_from,
        mhz,
        clock_from,
        build,
    })
}

/// One line on the hardware points' clocks: how many are measured, given
/// or assumed.
fn hw_summary(points: &[Point]) -> String {
    let count = |from: &str| {
        points
            .iter()
            .filter(|p| p.hw.as_ref().is_some_and(|h| h.clock_from == from))
            .count()
    };
    format!(
        "{} at a measured fmax, {} at a given clock, {} at an assumed {ASSUMED_MHZ} MHz",
        count("measured"),
        count("given"),
        count("assumed")
    )
}

fn point(
    method: &str,
    params: Map<String, Value>,
    img: &Image,
    yard: &Image,
    software_seconds: f64,
    hw: Option<HwPrice>,
    cost_seconds: f64,
) -> Point {
    use std::hash::{Hash, Hasher};
    let mut h = std::collections::hash_map::DefaultHasher::new();
    for p in &img.rgb {
        for c in p {
            c.to_bits().hash(&mut h);
        }
    }
    Point {
        method: method.to_string(),
        params,
        error: compare(img, yard).expect("the yardstick has foreground pixels (checked first)"),
        software_seconds,
        volume_prep_seconds: None,
        hw,
        cost_seconds,
        image_hash: format!("{:016x}", h.finish()),
        caveat: None,
    }
}

/// Indices of the points no other point beats in both cost and error
/// (relative Euclidean): sorted by cost, each keeps a smaller error than
/// every cheaper one.
fn pareto(points: &[Point]) -> Vec<usize> {
    let mut idx: Vec<usize> = (0..points.len()).collect();
    idx.sort_by(|&a, &b| {
        points[a]
            .cost_seconds
            .total_cmp(&points[b].cost_seconds)
            .then(
                points[a]
                    .error
                    .rel_euclid_pct
                    .total_cmp(&points[b].error.rel_euclid_pct),
            )
    });
    let mut best = f64::INFINITY;
    let mut front = Vec::new();
    for i in idx {
        let e = points[i].error.rel_euclid_pct;
        if e < best {
            best = e;
            front.push(i);
        }
    }
    front
}

fn params_text(p: &Point) -> String {
    p.params
        .iter()
        .map(|(k, v)| format!("{k}={v}"))
        .collect::<Vec<_>>()
        .join(" ")
}

fn row_json(p: &Point, on_front: bool) -> Value {
    json!({
        "method": p.method,
        "params": p.params,
        "error": crate::common::error_json(&Some(p.error)),
        "software_seconds": p.software_seconds,
        "volume_prep_seconds": p.volume_prep_seconds,
        "hardware": p.hw.as_ref().map(|h| json!({
            "clocks": h.clocks,
            "clocks_from": h.clocks_from,
            "clock_mhz": h.mhz,
            "clock_from": h.clock_from,
            "frame_seconds": h.frame_seconds(),
            "build": h.build.as_ref().map(|b| b.config.clone()),
            "luts": h.build.as_ref().map(|b| b.luts),
            "multipliers": h.build.as_ref().map(|b| b.multipliers),
            "block_rams": h.build.as_ref().map(|b| b.block_rams),
        })),
        "cost_seconds": p.cost_seconds,
        "pareto": on_front,
        "image_hash": p.image_hash,
        "accuracy_caveat": p.caveat,
    })
}

/// For each method, the points whose images are identical: the parameter
/// they differ in does not reach the image at those values.
fn identical_notes(points: &[Point]) -> Vec<Value> {
    let mut groups: Vec<(String, String, Vec<String>)> = Vec::new();
    for p in points {
        match groups
            .iter_mut()
            .find(|g| g.0 == p.method && g.1 == p.image_hash)
        {
            Some(g) => g.2.push(params_text(p)),
            None => groups.push((p.method.clone(), p.image_hash.clone(), vec![params_text(p)])),
        }
    }
    groups
        .into_iter()
        .filter(|g| g.2.len() > 1)
        .map(|(m, _, ps)| json!({"method": m, "points": ps}))
        .collect()
}

fn csv(points: &[Point], front: &[usize]) -> String {
    let mut s = String::from(
        "method,params,rel_euclid_pct,rmse,psnr_db,max_abs,software_seconds,clocks,clocks_from,clock_mhz,clock_from,build,luts,multipliers,block_rams,hardware_frame_seconds,cost_seconds,pareto,image_hash\n",
    );
    let opt = |v: Option<String>| v.unwrap_or_default();
    for (i, p) in points.iter().enumerate() {
        let h = p.hw.as_ref();
        let b = h.and_then(|h| h.build.as_ref());
        s += &format!(
            "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n",
            p.method,
            params_text(p),
            p.error.rel_euclid_pct,
            p.error.rmse,
            // Identical images have no finite PSNR: the field is empty.
            if p.error.psnr_db.is_finite() {
                p.error.psnr_db.to_string()
            } else {
                String::new()
            },
            p.error.max_abs,
            p.software_seconds,
            opt(h.map(|h| h.clocks.to_string())),
            opt(h.map(|h| h.clocks_from.to_string())),
            opt(h.map(|h| h.mhz.to_string())),
            opt(h.map(|h| h.clock_from.to_string())),
            opt(b.map(|b| b.config.clone())),
            opt(b.map(|b| b.luts.to_string())),
            opt(b.map(|b| b.multipliers.to_string())),
            opt(b.map(|b| b.block_rams.to_string())),
            opt(h.map(|h| h.frame_seconds().to_string())),
            p.cost_seconds,
            front.contains(&i),
            p.image_hash,
        );
    }
    s
}

fn markdown(points: &[Point], front: &[usize], report: &Value) -> String {
    let clock = &report["clock"];
    let mut s = format!(
        "# Error against cost: {}\n\nError: against the float reference at step {} (yardstick; convergence tolerance {} % relative Euclidean between steps s and s/2: {}).\nCost per frame: software methods, the median wall time of {} runs on this machine ({} threads; the quantized-voxel path's per-volume preprocessing, paid once per volume, is left out and listed in the JSON); hardware methods, the RTL's clocks per frame at the fmax of the committed ECP5 report of the smallest committed build that renders the point ({}).\n\n",
        report["scene"].as_str().unwrap_or(""),
        report["yardstick"]["step"],
        report["yardstick"]["tolerance_pct"],
        if report["yardstick"]["converged"].is_null() { "not reached, finest step used".to_string() } else { format!("{} % between {} and {}", fmt3(report["yardstick"]["converged"]["difference_pct"].as_f64().unwrap_or(0.0)), report["yardstick"]["converged"]["step"], report["yardstick"]["converged"]["half"]) },
        report["repeat"],
        report["threads"],
        if clock["points_assumed"].as_u64().unwrap_or(0) > 0 {
            format!("where none does, an ASSUMED {} MHz, marked on the point", clock["assumed_mhz"])
        } else {
            "every point measured or given".to_string()
        },
    );
    let line = |p: &Point| {
        let h = p.hw.as_ref();
        let b = h.and_then(|h| h.build.as_ref());
        format!(
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
            p.method,
            params_text(p),
            fmt3(p.error.rel_euclid_pct),
            crate::common::psnr_text(p.error.psnr_db, 3),
            fmt3(p.error.max_abs),
            fmt_time(p.cost_seconds),
            h.map(|h| format!(
                "{}{}",
                h.clocks,
                if h.clocks_from == "ideal" {
                    " (ideal)"
                } else {
                    ""
                }
            ))
            .unwrap_or_else(|| "—".into()),
            h.map(|h| match (h.clock_from, b) {
                ("measured", Some(b)) => format!("{:.1} MHz, `{}`", h.mhz, b.config),
                ("given", _) => format!("{} MHz (given)", h.mhz),
                (_, Some(b)) => format!("{} MHz ASSUMED (`{}` has no fmax)", h.mhz, b.config),
                _ => format!("{} MHz ASSUMED (no committed build renders it)", h.mhz),
            })
            .unwrap_or_else(|| "—".into()),
            b.map(|b| format!("{} / {} / {}", b.luts, b.multipliers, b.block_rams))
                .unwrap_or_else(|| "—".into()),
        )
    };
    let head = "| method | parameters | rel. Euclidean % | PSNR dB | max | cost | clocks | clock | LUT4 / MULT18 / DP16KD |\n|---|---|---|---|---|---|---|---|---|\n";
    s += "## Pareto front\n\n";
    s += head;
    for &i in front {
        s += &line(&points[i]);
    }
    s += "\n## Best point of each method (smallest error, then cost)\n\n";
    s += head;
    let mut methods: Vec<&str> = points.iter().map(|p| p.method.as_str()).collect();
    methods.dedup();
    for m in methods {
        let best = points
            .iter()
            .filter(|p| p.method == m)
            .min_by(|a, b| {
                a.error
                    .rel_euclid_pct
                    .total_cmp(&b.error.rel_euclid_pct)
                    .then(a.cost_seconds.total_cmp(&b.cost_seconds))
            })
            .unwrap();
        s += &line(best);
    }
    if let Some(notes) = report["identical_images"]
        .as_array()
        .filter(|n| !n.is_empty())
    {
        s += "\n## Identical images\n\nThese points of one method give byte-identical images: the parameter they differ in does not reach the image at these values (it is not on the critical path of the error; the error comes from another stage).\n\n";
        for n in notes {
            s += &format!(
                "- {}: {}\n",
                n["method"].as_str().unwrap_or(""),
                n["points"]
                    .as_array()
                    .map(|p| p
                        .iter()
                        .filter_map(|x| x.as_str())
                        .collect::<Vec<_>>()
                        .join("; "))
                    .unwrap_or_default()
            );
        }
    }
    let mut caveats: Vec<(&str, &str)> = points
        .iter()
        .filter_map(|p| Some((p.method.as_str(), p.caveat.as_ref()?["message"].as_str()?)))
        .collect();
    caveats.dedup();
    if !caveats.is_empty() {
        s += "\n## Accuracy caveats\n\nThe golden model warns that this view lies outside the range its error is known in:\n\n";
        for (m, c) in caveats {
            s += &format!("- {m}: {c}\n");
        }
    }
    if let Some(sk) = report["skipped"].as_array().filter(|n| !n.is_empty()) {
        s += "\n## Methods that do not apply\n\n";
        for n in sk {
            s += &format!(
                "- {}: {}\n",
                n["method"].as_str().unwrap_or(""),
                n["reason"].as_str().unwrap_or("")
            );
        }
    }
    s
}

fn fmt3(x: f64) -> String {
    if x.is_finite() {
        format!("{x:.3}")
    } else {
        "∞".into()
    }
}

fn fmt_time(t: f64) -> String {
    if t < 1e-3 {
        format!("{:.1} µs", t * 1e6)
    } else if t < 1.0 {
        format!("{:.2} ms", t * 1e3)
    } else {
        format!("{t:.2} s")
    }
}

const PLOT_W: u32 = 1000;
const PLOT_H: u32 = 650;

/// Where a zero error is drawn on a log axis: half the smallest non-zero
/// error (at most 1 %).
fn error_floor<'a>(points: impl Iterator<Item = &'a Point>) -> f64 {
    points
        .map(|p| p.error.rel_euclid_pct)
        .filter(|&e| e > 0.0)
        .fold(f64::INFINITY, f64::min)
        .min(1.0)
        / 2.0
}

/// Error against cost on log-log axes, one colour per method, the Pareto
/// front as a staircase.
fn plot(points: &[Point], front: &[usize]) -> Result<Vec<u8>> {
    plotters::style::register_font("sans-serif", FontStyle::Normal, dejavu::sans::regular())
        .map_err(|_| anyhow::anyhow!("registering the embedded font"))?;
    let floor = error_floor(points.iter());
    let err = |p: &Point| p.error.rel_euclid_pct.max(floor);
    let (t0, t1) = points.iter().fold((f64::INFINITY, 0.0f64), |(a, b), p| {
        (a.min(p.cost_seconds), b.max(p.cost_seconds))
    });
    let (e0, e1) = points.iter().fold((f64::INFINITY, 0.0f64), |(a, b), p| {
        (a.min(err(p)), b.max(err(p)))
    });
    let mut buf = vec![0u8; (PLOT_W * PLOT_H * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buf, (PLOT_W, PLOT_H)).into_drawing_area();
        root.fill(&WHITE)?;
        let caption = format!("Error against cost (hardware: {})", hw_summary(points));
        let mut chart = ChartBuilder::on(&root)
            .caption(caption, ("sans-serif", 20))
            .margin(15)
            .x_label_area_size(45)
            .y_label_area_size(60)
            .build_cartesian_2d(
                (t0 / 1.5..t1 * 1.5).log_scale(),
                (e0 / 1.5..e1 * 1.5).log_scale(),
            )?;
        chart
            .configure_mesh()
            .x_desc("cost per frame (s): software wall time, hardware clocks / clock rate")
            .y_desc("relative Euclidean error (%)")
            .draw()?;
        let colours = [
            RED,
            BLUE,
            GREEN,
            MAGENTA,
            CYAN,
            RGBColor(230, 140, 0),
            BLACK,
        ];
        let mut methods: Vec<&str> = points.iter().map(|p| p.method.as_str()).collect();
        methods.dedup();
        for (k, m) in methods.iter().enumerate() {
            let c = colours[k % colours.len()];
            let hw = points.iter().any(|p| p.method == *m && p.hw.is_some());
            chart
                .draw_series(
                    points
                        .iter()
                        .filter(|p| p.method == *m)
                        .map(|p| Circle::new((p.cost_seconds, err(p)), 5, c.filled())),
                )?
                .label(if hw {
                    format!("{m} (hardware)")
                } else {
                    m.to_string()
                })
                .legend(move |(x, y)| Circle::new((x + 10, y), 5, c.filled()));
        }
        let mut stair = Vec::new();
        for (j, &i) in front.iter().enumerate() {
            let p = &points[i];
            if j > 0 {
                stair.push((p.cost_seconds, err(&points[front[j - 1]])));
            }
            stair.push((p.cost_seconds, err(p)));
        }
        chart
            .draw_series(LineSeries::new(stair, BLACK.stroke_width(2)))?
            .label("Pareto front")
            .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLACK.stroke_width(2)));
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperRight)
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .draw()?;
        root.present()?;
    }
    Ok(buf)
}

/// Error against area: the hardware points priced by a committed report,
/// at that build's LUT4 (log-log), one colour per method; a plot that says
/// so when no point has a report.
fn plot_area(points: &[Point]) -> Result<Vec<u8>> {
    let priced: Vec<(&Point, f64)> = points
        .iter()
        .filter_map(|p| Some((p, p.hw.as_ref()?.build.as_ref()?.luts as f64)))
        .collect();
    let mut buf = vec![0u8; (PLOT_W * PLOT_H * 3) as usize];
    {
        let root = BitMapBackend::with_buffer(&mut buf, (PLOT_W, PLOT_H)).into_drawing_area();
        root.fill(&WHITE)?;
        if priced.is_empty() {
            root.draw(&Text::new(
                "Error against area: not available (no hardware point has a committed report)",
                (40, PLOT_H as i32 / 2),
                ("sans-serif", 20),
            ))?;
            root.present()?;
            drop(root);
            return Ok(buf);
        }
        let floor = error_floor(priced.iter().map(|(p, _)| *p));
        let err = |p: &Point| p.error.rel_euclid_pct.max(floor);
        let (l0, l1) = priced
            .iter()
            .fold((f64::INFINITY, 0.0f64), |(a, b), (_, l)| {
                (a.min(*l), b.max(*l))
            });
        let (e0, e1) = priced
            .iter()
            .fold((f64::INFINITY, 0.0f64), |(a, b), (p, _)| {
                (a.min(err(p)), b.max(err(p)))
            });
        let mut chart = ChartBuilder::on(&root)
            .caption(
                "Error against area (the build each point was priced by)",
                ("sans-serif", 20),
            )
            .margin(15)
            .x_label_area_size(45)
            .y_label_area_size(60)
            .build_cartesian_2d(
                (l0 / 1.5..l1 * 1.5).log_scale(),
                (e0 / 1.5..e1 * 1.5).log_scale(),
            )?;
        chart
            .configure_mesh()
            .x_desc("LUT4 on an LFE5U-85F (committed report)")
            .y_desc("relative Euclidean error (%)")
            .draw()?;
        let mut methods: Vec<&str> = priced.iter().map(|(p, _)| p.method.as_str()).collect();
        methods.dedup();
        for (k, m) in methods.iter().enumerate() {
            let c = [RED, BLUE, GREEN, MAGENTA][k % 4];
            chart
                .draw_series(
                    priced
                        .iter()
                        .filter(|(p, _)| p.method == *m)
                        .map(|(p, l)| Circle::new((*l, err(p)), 5, c.filled())),
                )?
                .label(m.to_string())
                .legend(move |(x, y)| Circle::new((x + 10, y), 5, c.filled()));
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperRight)
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .draw()?;
        root.present()?;
    }
    Ok(buf)
}
