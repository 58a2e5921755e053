//! Memory and work bounded before they are spent: every render the CLI
//! runs (`render`, `compare`, `angles`, `tradeoff`, the default run) is
//! first estimated from the validated scene, and refused with the figure
//! when it would exceed this machine's memory budget or run for hours.
//!
//! The estimates are upper-leaning fits of measured peaks (allocated bytes,
//! within about 2x), method by method; docs/robustness.md gives each
//! formula and its measurements. What grows without bound is the quantized
//! path's footprint tables (with the pixels per voxel `p` and the
//! subdivisions `n`) and every image (24 bytes a pixel).

use crate::common::Arch;
use scene::{Projection, Scene};

/// Largest work accepted, in elementary steps (a footprint entry drawn, a
/// sample taken): at a few ns each, about ten minutes on two cores.
pub const MAX_WORK: f64 = 2e11;

/// The memory budget in bytes: half this machine's memory, and at most
/// 80 % of the address-space limit (`ulimit -v`) where one is set.
pub fn budget_bytes() -> u64 {
    // SAFETY: sysconf and getrlimit have no memory preconditions beyond a
    // valid rlimit to write.
    let (pages, page, limit) = unsafe {
        let mut r: libc::rlimit = std::mem::zeroed();
        let limit = if libc::getrlimit(libc::RLIMIT_AS, &mut r) == 0 {
            r.rlim_cur
        } else {
            libc::RLIM_INFINITY
        };
        (
            libc::sysconf(libc::_SC_PHYS_PAGES),
            libc::sysconf(libc::_SC_PAGESIZE),
            limit,
        )
    };
    let physical = if pages > 0 && page > 0 {
        pages as u64 * page as u64
    } else {
        8 << 30
    };
    let mut budget = physical / 2;
    if limit != libc::RLIM_INFINITY {
        budget = budget.min(limit / 10 * 8);
    }
    budget
}

/// What a render of `scene` with `arch` would take.
#[derive(Debug, Clone, Copy)]
pub struct Estimate {
    pub bytes: f64,
    pub work: f64,
}

/// Estimate a render, from the validated scene alone.
pub fn estimate(scene: &Scene, arch: Arch, ref_step: f64) -> Estimate {
    let [w, h] = scene.image.map(|x| x as f64);
    let pixels = w * h;
    let d = scene.volume.render_dims().map(|x| x as f64);
    let voxels = d[0] * d[1] * d[2];
    let threads = rayon::current_num_threads() as f64;
    // The volume (16-bit voxels), the image (three f64 a pixel) and its
    // 8-bit copy for the PNG.
    let common = 2.0 * voxels + 27.0 * pixels;
    // The sweeps' pipeline-space dims [nx, ny, nz], nz the major axis; for
    // a view no sweep can plan, the largest side on every axis.
    let cam = scene.camera();
    let plan = golden_model::cube4l::plan::Plan::new(scene, &cam).ok();
    let sweeps: Vec<[f64; 3]> = match &plan {
        Some(p) => p.sweeps.iter().map(|s| s.dims.map(|x| x as f64)).collect(),
        None => vec![[d[0].max(d[1]).max(d[2]); 3]],
    };
    // The traversal-order copies the golden models keep for the whole
    // render (2 bytes a voxel each): Cube-4L's for a sweep along y, Cube-3's
    // for each major axis but z (both, where no sweep can plan).
    let axes: Vec<usize> = match &plan {
        Some(p) => p.sweeps.iter().map(|s| s.axis()).collect(),
        None => vec![0, 1],
    };
    let copies =
        |copied: &[usize]| 2.0 * voxels * copied.iter().filter(|a| axes.contains(a)).count() as f64;
    // A sheared plane: each side grows by up to one voxel a slice.
    let plane = |s: &[f64; 3]| (s[0] + s[2] + 4.0) * (s[1] + s[2] + 4.0);
    let diag = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
    match arch {
        Arch::Cube4l => Estimate {
            bytes: common
                + copies(&[1])
                + sweeps
                    .iter()
                    .map(|s| 17.0 * (s[0] + 2.0 * s[2]) * (s[1] + 2.0 * s[2]) + 32.0 * s[0] * s[1])
                    .sum::<f64>(),
            work: voxels * sweeps.len() as f64 + pixels,
        },
        Arch::Cube3 => Estimate {
            bytes: common
                + copies(&[0, 1])
                + sweeps
                    .iter()
                    .map(|s| 20.0 * threads * (s[0] + s[2] + 4.0) * s[2] + 34.0 * plane(s))
                    .sum::<f64>(),
            work: sweeps.iter().map(|s| plane(s) * s[2]).sum::<f64>() + pixels,
        },
        Arch::True3d | Arch::ShearedFloat => Estimate {
            bytes: common + sweeps.iter().map(|s| 80.0 * plane(s)).sum::<f64>(),
            work: sweeps.iter().map(|s| plane(s) * s[2]).sum::<f64>() * 10.0,
        },
        Arch::Reference => Estimate {
            bytes: common + voxels / 512.0,
            // Every pixel's ray across the volume's diagonal.
            work: pixels * diag / ref_step.max(1e-6),
        },
        Arch::QuantizedProjection | Arch::QuantizedSplat => quantized(scene, &cam, arch, common),
    }
}

/// The quantized path: its footprint tables grow with `p²` (`p` pixels
/// per voxel) and with `n²` (subdivisions), its band buffers with `p`.
fn quantized(scene: &Scene, cam: &scene::Camera, arch: Arch, common: f64) -> Estimate {
    let splat = arch == Arch::QuantizedSplat;
    let [w, h] = scene.image.map(|x| x as f64);
    let d = scene.volume.render_dims().map(|x| x as f64);
    let n = scene
        .quantized
        .subdivisions
        .unwrap_or(if splat { 32 } else { 64 }) as f64;
    let padded: f64 = d.iter().map(|x| (x / 8.0).ceil() * 8.0).product();
    // Parallel views only (the method refuses others): the pixel spacing.
    let p = if scene.view.projection == Projection::Parallel {
        1.0 / cam.scale
    } else {
        1.0
    };
    let f = cam.forward.abs();
    let (entries, margin, footprint) = if splat {
        let e = n * n * std::f64::consts::PI * 4.0 * p * p;
        (e, 4.0 * p + 3.0, 4.0 * std::f64::consts::PI * p * p)
    } else {
        // A view down an axis draws rectangles: a handful of classes.
        let axis_aligned = [f.x, f.y, f.z].iter().filter(|&&c| c > 1e-9).count() == 1;
        let classes = if axis_aligned {
            25.0
        } else {
            (n * n).min(12.0 * p * p)
        };
        let area = p * p * (f.x + f.y + f.z);
        (classes * (area + 4.0 * p), 1.7 * p + 2.0, area.max(1.0))
    };
    let threads = rayon::current_num_threads() as f64;
    let keys = if splat { 0.0 } else { n * n * (5.0 * p + 40.0) };
    let bytes = common
        + 5.0 * padded
        + 16.0 * threads * (32.0 + 2.0 * margin) * (w + 2.0 * margin)
        + 40.0 * w * h
        + 32.0 * entries
        + keys;
    // Drawing: each voxel under the image puts its footprint into every
    // band of 32 rows it reaches, twice (the timed transfer-function
    // change renders again); building the tables touches each entry.
    let columns = (d[0] * d[1]).min((w / p + 5.0) * (h / p + 5.0));
    let bands = (h / 32.0).ceil().min(1.0 + margin / 32.0);
    let depth = d[0].max(d[1]).max(d[2]);
    let work = 2.0 * columns * depth * footprint * bands + 20.0 * entries;
    Estimate { bytes, work }
}

/// Refuse a render that would exceed the memory budget or run for hours,
/// in one line with the figures.
pub fn check(scene: &Scene, arch: Arch, ref_step: f64) -> Result<(), OverBudget> {
    let e = estimate(scene, arch, ref_step);
    let budget = budget_bytes() as f64;
    let gib = |b: f64| b / (1u64 << 30) as f64;
    if e.bytes > budget {
        return Err(OverBudget(format!(
            "{}: this scene needs about {:.1} GiB, over the memory budget of {:.1} GiB (half this machine's memory, or 80 % of ulimit -v); a smaller image, zoom or quantized.subdivisions needs less",
            arch.name(),
            gib(e.bytes),
            gib(budget)
        )));
    }
    if e.work > MAX_WORK {
        return Err(OverBudget(format!(
            "{}: this scene needs about {:.0e} steps of work (the limit is {MAX_WORK:.0e}, about ten minutes); a smaller image, zoom or quantized.subdivisions needs less",
            arch.name(),
            e.work
        )));
    }
    Ok(())
}

/// A render [`check`] refuses, with its one-line reason: a type of its
/// own, so that `tradeoff` can leave the point out where other errors end
/// the run.
#[derive(Debug)]
pub struct OverBudget(String);

impl std::fmt::Display for OverBudget {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for OverBudget {}

#[cfg(test)]
mod tests {
    use super::*;

    fn scene(volume: &str, view: &str, image: u32, extra: &str) -> Scene {
        Scene::from_json(
            &format!(
                r#"{{"volume": {volume}, "view": {{"projection": "parallel", {view}}}, "image": [{image}, {image}]{extra}}}"#
            ),
            None,
        )
        .unwrap()
    }

    /// A view whose golden model keeps a traversal-order copy costs 2 bytes
    /// a voxel more than one that reads the volume as it is (a cube, so
    /// that the sweeps' own terms are equal).
    #[test]
    fn kept_copies_are_counted() {
        let cube = r#"{"builtin": "sphere", "dims": [64, 64, 64]}"#;
        let bytes = |rot: &str, arch| {
            estimate(
                &scene(cube, &format!(r#""rotate_deg": {rot}"#), 64, ""),
                arch,
                0.5,
            )
            .bytes
        };
        let n = 2.0 * 64f64.powi(3);
        assert_eq!(
            bytes("[90, 0, 0]", Arch::Cube4l) - bytes("[0, 0, 0]", Arch::Cube4l),
            n
        );
        assert_eq!(
            bytes("[0, 90, 0]", Arch::Cube4l),
            bytes("[0, 0, 0]", Arch::Cube4l)
        );
        assert_eq!(
            bytes("[0, 90, 0]", Arch::Cube3) - bytes("[0, 0, 0]", Arch::Cube3),
            n
        );
        assert_eq!(
            bytes("[90, 0, 0]", Arch::Cube3) - bytes("[0, 0, 0]", Arch::Cube3),
            n
        );
    }

    /// Peaks measured with `/usr/bin/time -v` (resident MB; allocations
    /// can be larger): each estimate covers its peak, within a factor 6.
    #[test]
    fn estimates_cover_the_measured_peaks() {
        let sphere = r#"{"builtin": "sphere", "dims": [32, 32, 32]}"#;
        let slab = r#"{"builtin": "sphere", "dims": [2048, 2048, 16]}"#;
        for (s, arch, measured_mb) in [
            (
                scene(sphere, r#""zoom": 300"#, 256, ""),
                Arch::QuantizedProjection,
                890.0,
            ),
            (
                scene(sphere, r#""zoom": 10, "rotate_deg": [30, 40, 0]"#, 256, ""),
                Arch::QuantizedProjection,
                242.0,
            ),
            (
                scene(sphere, r#""zoom": 10"#, 256, ""),
                Arch::QuantizedSplat,
                542.0,
            ),
            (
                scene(
                    sphere,
                    r#""zoom": 3"#,
                    256,
                    r#", "quantized": {"subdivisions": 128}"#,
                ),
                Arch::QuantizedSplat,
                767.0,
            ),
            (scene(sphere, r#""zoom": 1"#, 8192, ""), Arch::Cube4l, 508.0),
            (
                scene(slab, r#""rotate_deg": [0, 90, 0]"#, 256, ""),
                Arch::Cube4l,
                404.0,
            ),
        ] {
            let e = estimate(&s, arch, 0.5).bytes / 1e6;
            assert!(
                e >= measured_mb && e <= 6.0 * measured_mb,
                "{}: estimate {e:.0} MB against {measured_mb} MB measured",
                arch.name()
            );
        }
    }
}
