//! The CFB stream generator: exact skew, coverage, control bits and pixel
//! addresses, and equality of stream-order processing with the golden model.

use golden_model::common::shader::Shader;
use golden_model::cube4l::cfb::{skew, CfbStream, SkewedMemory};
use golden_model::cube4l::plan::Plan;
use golden_model::cube4l::render_sweep;
use scene::volume::{builtin, Volume};
use std::collections::HashSet;
use testbenches::{render_from_stream, scene};

fn views() -> Vec<&'static str> {
    vec![
        r#"{"projection": "parallel"}"#,
        r#"{"projection": "parallel", "rotate_deg": [70, 30, 0]}"#,
        r#"{"projection": "parallel", "rotate_deg": [0, 45, 0]}"#,
        r#"{"projection": "parallel", "rotate_deg": [-20, 135, 10]}"#,
        r#"{"projection": "parallel", "rotate_deg": [90, 0, 0]}"#,
        r#"{"projection": "perspective", "eye": [5, 6, -9], "fov_deg": 100}"#,
        r#"{"projection": "perspective", "eye": [30, 4, 7], "fov_deg": 60}"#,
    ]
}

fn setup(dims: [usize; 3], view: &str, p: usize, mode: &str) -> (scene::Scene, Volume) {
    let s = scene(&format!(
        r#"{{"volume": {{"builtin": "phantom", "dims": {dims:?}}}, "view": {view}, "mode": "{mode}",
            "image": [24, 24], "hardware": {{"pipelines": {p}}}}}"#
    ));
    let v = builtin("phantom", dims, 8).unwrap();
    (s, v)
}

#[test]
fn skewed_memory_places_every_voxel_once() {
    let vol = builtin("ramp", [10, 7, 5], 12).unwrap();
    for p in [1, 2, 4, 8] {
        let mem = SkewedMemory::new(&vol, p);
        let mut used = HashSet::new();
        for w in 0..5 {
            for v in 0..7 {
                for u in 0..10 {
                    let (k, i) = skew(u, v, w, p, mem.b, 7);
                    assert_eq!(k, (u + v + w) % p);
                    assert!(used.insert((k, i)), "p={p}: ({u},{v},{w}) collides");
                    assert_eq!(mem.modules[k][i], vol.get(u, v, w));
                }
            }
        }
    }
}

#[test]
fn partial_beam_voxels_lie_in_distinct_modules() {
    // Skewing makes any p consecutive voxels along any axis conflict free.
    for p in [2usize, 4, 8] {
        for (u, v, w) in [(3, 5, 7), (0, 0, 0), (9, 1, 4)] {
            for axis in 0..3 {
                let ks: HashSet<usize> = (0..p)
                    .map(|i| {
                        let mut c = [u, v, w];
                        c[axis] += i;
                        (c[0] + c[1] + c[2]) % p
                    })
                    .collect();
                assert_eq!(ks.len(), p);
            }
        }
    }
}

#[test]
fn stream_covers_each_voxel_once_with_its_control() {
    for dims in [[8, 8, 8], [10, 6, 7], [12, 9, 5]] {
        for p in [1, 2, 4, 8] {
            for view in views() {
                let (s, vol) = setup(dims, view, p, "composite");
                let cam = s.camera();
                let plan = Plan::new(&s, &cam).unwrap();
                let mem = SkewedMemory::new(&vol, p);
                for sweep in &plan.sweeps {
                    let stream = CfbStream::new(&mem, vol.dims, sweep);
                    let expected_cycles = stream.cycles();
                    let b = sweep.dims[0].div_ceil(p);
                    let slices = sweep.z1 - sweep.z0 + 1;
                    assert_eq!(expected_cycles, (slices * sweep.dims[1] * b) as u64);
                    let mut seen = HashSet::new();
                    let mut pixels = HashSet::new();
                    let mut cycles = 0;
                    for (t, beat) in stream.enumerate() {
                        assert_eq!(beat.cycle, t as u64);
                        assert_eq!(beat.lanes.len(), p);
                        cycles += 1;
                        for (k, lane) in beat.lanes.iter().enumerate() {
                            let [x, y, z] = lane.pos;
                            assert_eq!(
                                (x + y + z) % p,
                                k,
                                "lane {k} holds a voxel of another module"
                            );
                            assert_eq!(x / p, beat.n_b);
                            assert_eq!((y, z), (beat.n_beam, beat.n_s));
                            assert_eq!(lane.bs, beat.n_b == 0);
                            if lane.pad {
                                assert!(
                                    x >= sweep.dims[0] && lane.control.invalid && !lane.control.er
                                );
                                continue;
                            }
                            let [u, v, w] = sweep.dataset(x, y, z);
                            assert_eq!(lane.value, vol.get(u, v, w));
                            assert_eq!(mem.modules[k][lane.address], lane.value);
                            assert!(seen.insert(lane.pos), "{:?} emitted twice", lane.pos);
                            assert_eq!(lane.control, sweep.control(x, y, z));
                            assert_eq!(lane.control.sr, z == sweep.z0);
                            assert_eq!(lane.pixel.is_some(), lane.control.er);
                            if let Some(px) = lane.pixel {
                                assert!(pixels.insert(px), "pixel address {px:?} written twice");
                            }
                        }
                    }
                    assert_eq!(cycles, expected_cycles);
                    assert_eq!(seen.len(), sweep.dims[0] * sweep.dims[1] * slices);
                }
            }
        }
    }
}

#[test]
fn stream_order_processing_equals_golden_model() {
    for mode in ["composite", "mip", "minip", "xray", "first_opaque"] {
        for (dims, p) in [
            ([8, 8, 8], 4),
            ([10, 6, 7], 2),
            ([9, 12, 6], 8),
            ([7, 7, 9], 1),
        ] {
            for view in views() {
                let (s, vol) = setup(dims, view, p, mode);
                let cam = s.camera();
                let plan = Plan::new(&s, &cam).unwrap();
                for sweep in &plan.sweeps {
                    let shader = Shader::new(&s, &cam, sweep);
                    let (golden, _) = render_sweep(&vol, sweep, &shader);
                    let (streamed, cycles) = render_from_stream(&vol, sweep, &shader, p);
                    assert_eq!(
                        cycles,
                        ((sweep.z1 - sweep.z0 + 1) * sweep.dims[1] * sweep.dims[0].div_ceil(p))
                            as u64
                    );
                    for i in 0..golden.pixels.len() {
                        assert_eq!(
                            (golden.pixels[i], golden.faces[i]),
                            (streamed.pixels[i], streamed.faces[i]),
                            "{mode} {dims:?} p={p} {view}: base-plane pixel ({}, {}) differs",
                            i % golden.width,
                            i / golden.width
                        );
                    }
                }
            }
        }
    }
}
