//! The DRAM image (`golden_model::cube4l::dram`): every beat of every sweep
//! the golden CFB streams is one word of its copy, the words in increasing
//! order, for every view, pipeline count and voxel width; and the burst
//! efficiency it gives on each major axis, beside the single skewed copy's.

use golden_model::cube4l::cfb::{skew, CfbStream, SkewedMemory};
use golden_model::cube4l::dram::{burst_efficiency, DramLayout};
use golden_model::cube4l::plan::Plan;
use scene::volume::builtin;
use testbenches::scene;

const VIEWS: &[&str] = &[
    r#"{"projection": "parallel"}"#,
    r#"{"projection": "parallel", "rotate_deg": [70, 30, 0]}"#,
    r#"{"projection": "parallel", "rotate_deg": [0, 90, 0]}"#,
    r#"{"projection": "parallel", "rotate_deg": [90, 0, 0]}"#,
    r#"{"projection": "parallel", "rotate_deg": [-20, 135, 10]}"#,
    r#"{"projection": "perspective", "eye": [5, 6, -9], "fov_deg": 100}"#,
    r#"{"projection": "perspective", "eye": [3, 4, 2], "fov_deg": 90}"#,
];

#[test]
fn every_beat_is_one_word_read_in_order() {
    for dims in [[8, 8, 8], [10, 6, 7], [5, 9, 12]] {
        for bits in [8, 12] {
            let vol = builtin("phantom", dims, bits).unwrap();
            for p in [1, 2, 4, 8] {
                let layout = DramLayout::new(dims, bits, p);
                let image = layout.image(&vol).unwrap();
                let mem = SkewedMemory::new(&vol, p);
                let mut axes = [false; 3];
                for view in VIEWS {
                    let s = scene(&format!(
                        r#"{{"volume": {{"builtin": "phantom", "dims": {dims:?}}}, "view": {view},
                            "image": [16, 16], "hardware": {{"pipelines": {p}, "voxel_bits": {bits}}}}}"#
                    ));
                    let plan = Plan::new(&s, &s.camera()).unwrap();
                    for sweep in &plan.sweeps {
                        let copy = layout.copies[sweep.perm[2]];
                        axes[copy.axis] = true;
                        assert_eq!((copy.perm, copy.dims), (sweep.perm, sweep.dims));
                        let first = sweep.z0 * copy.slab;
                        for (t, beat) in CfbStream::new(&mem, vol.dims, sweep).enumerate() {
                            let a = copy.beat_address(
                                layout.word_bytes,
                                beat.n_s,
                                beat.n_beam,
                                beat.n_b,
                            );
                            let at = |what: &str| {
                                format!("{dims:?} {bits}-bit p={p} {view} beat {t}: {what}")
                            };
                            assert_eq!(
                                a,
                                copy.base + (first + t) * layout.word_bytes,
                                "{}",
                                at("out of order")
                            );
                            let word = &image[a..a + layout.word_bytes];
                            for (k, lane) in beat.lanes.iter().enumerate() {
                                let v = &word[k * layout.voxel_bytes..(k + 1) * layout.voxel_bytes];
                                let mut le = [0u8; 2];
                                le[..v.len()].copy_from_slice(v);
                                let want = if lane.pad { 0 } else { lane.value };
                                assert_eq!(
                                    u16::from_le_bytes(le),
                                    want,
                                    "{}",
                                    at(&format!("lane {k}"))
                                );
                            }
                        }
                    }
                }
                assert_eq!(axes, [true; 3], "the views sweep along every axis");
            }
        }
    }
}

/// Burst efficiency on each major axis of a 64³ 8-bit volume at p = 4:
/// x16 DDR3's 16-byte bursts, a line buffer a lane. The single skewed copy
/// (each module a region of its own, as the four SRAMs are today) strides
/// on two axes; the DRAM image reads every byte of every burst.
#[test]
fn the_dram_image_uses_every_burst_on_every_axis() {
    let (n, p, burst) = (64, 4, 16);
    let vol = builtin("sphere", [n; 3], 8).unwrap();
    let mem = SkewedMemory::new(&vol, p);
    let layout = DramLayout::new([n; 3], 8, p);
    let module_bytes = mem.modules[0].len();
    let mut table = Vec::new();
    for (axis, rotate) in [(0, "[0, 90, 0]"), (1, "[90, 0, 0]"), (2, "[0, 0, 0]")] {
        let s = scene(&format!(
            r#"{{"volume": {{"builtin": "sphere", "dims": [{n},{n},{n}]}},
                "view": {{"projection": "parallel", "rotate_deg": {rotate}}}, "image": [16, 16],
                "hardware": {{"pipelines": {p}}}}}"#
        ));
        let plan = Plan::new(&s, &s.camera()).unwrap();
        let sweep = &plan.sweeps[0];
        assert_eq!(sweep.perm[2], axis);
        let copy = layout.copies[axis];
        let single = CfbStream::new(&mem, vol.dims, sweep).map(|beat| {
            let lanes = beat.lanes.iter().enumerate();
            lanes
                .map(|(k, l)| {
                    let [u, v, w] = sweep.dataset(l.pos[0], l.pos[1], l.pos[2]);
                    let (m, i) = skew(u, v, w, p, mem.b, n);
                    assert_eq!(m, k);
                    (!l.pad).then_some(k * module_bytes + i)
                })
                .collect()
        });
        let dram = CfbStream::new(&mem, vol.dims, sweep).map(|beat| {
            let a = copy.beat_address(layout.word_bytes, beat.n_s, beat.n_beam, beat.n_b);
            (0..p).map(|k| Some(a + k)).collect()
        });
        let single = burst_efficiency(single, 1, burst, p).unwrap();
        let dram = burst_efficiency(dram, 1, burst, p).unwrap();
        table.push(format!(
            "{}: single copy {single:.4}, dram image {dram:.4}",
            ["x", "y", "z"][axis]
        ));
        assert_eq!(dram, 1.0, "axis {axis}");
        if axis == 2 {
            assert_eq!(single, 1.0);
        } else {
            assert!(single <= 1.0 / 16.0 + 1e-9, "axis {axis}: {single}");
        }
    }
    println!(
        "burst efficiency, 64³ 8-bit, p = 4, 16-byte bursts:\n{}",
        table.join("\n")
    );
}
