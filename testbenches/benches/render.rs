//! Golden models (Cube-4L, Cube-3 with the 12-neighbourhood), True3D and the
//! float reference at 128^3 and 256^3 (phantom, composite,
//! 70/30 degree view, 256x256 image). Throughput is reported in voxels per
//! second of the volume rendered; divide by the thread count for per-thread
//! figures (`RAYON_NUM_THREADS=1` measures one thread directly). The golden
//! models read the volume through an `Ordered`, as `cube render --repeat`
//! does: its traversal-order copy is made in the first frame and kept.

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use scene::volume::{builtin, Ordered};
use testbenches::scene;

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("render");
    g.sample_size(10);
    for n in [128usize, 256] {
        let s = scene(&format!(
            r#"{{"volume": {{"builtin": "phantom", "dims": [{n},{n},{n}]}},
                "view": {{"projection": "parallel", "rotate_deg": [70, 30, 0]}},
                "transfer": {{"opacity": [[0, 0.0], [60, 0.0], [80, 0.05], [150, 0.3], [200, 0.6], [255, 0.8]],
                              "color": [[0, 0.9, 0.6, 0.5], [255, 1.0, 1.0, 0.95]]}},
                "image": [256, 256]}}"#
        ));
        let vol = builtin("phantom", [n, n, n], 8).unwrap();
        let ordered = Ordered::new(&vol);
        let cam = s.camera();
        g.throughput(Throughput::Elements((n * n * n) as u64));
        g.bench_function(format!("cube4l_golden_{n}"), |b| {
            b.iter(|| golden_model::cube4l::render_image(&s, &ordered).unwrap())
        });
        g.bench_function(format!("cube3_golden_{n}"), |b| {
            b.iter(|| {
                golden_model::cube3::render_image(
                    &s,
                    &ordered,
                    golden_model::cube3::plan::Neighbourhood::N12,
                )
                .unwrap()
            })
        });
        g.bench_function(format!("true3d_{n}"), |b| {
            b.iter(|| {
                reference::true3d::render(&s, &cam, &vol, 12, reference::true3d::Interp::Exact)
                    .unwrap()
            })
        });
        g.bench_function(format!("reference_{n}"), |b| {
            b.iter(|| reference::render(&s, &cam, &vol, reference::DEFAULT_STEP))
        });
    }
    g.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
