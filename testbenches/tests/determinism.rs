//! Determinism: the golden model and the reference render byte-identical
//! images at any thread count; only the time differs.

use scene::{Scene, Volume};

fn render_with(threads: usize, scene: &Scene, vol: &Volume) -> (Vec<u8>, Vec<u8>) {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .unwrap();
    pool.install(|| {
        let (golden, _) = golden_model::cube4l::render_image(scene, vol).unwrap();
        let cam = scene.camera();
        let reference = reference::render(scene, &cam, vol, reference::DEFAULT_STEP);
        let bytes = |img: &scene::Image| {
            img.rgb
                .iter()
                .flatten()
                .flat_map(|c| c.to_le_bytes())
                .collect::<Vec<u8>>()
        };
        (bytes(&golden), bytes(&reference))
    })
}

#[test]
fn images_are_byte_identical_at_one_and_two_threads() {
    for view in [
        r#"{"projection": "parallel", "rotate_deg": [70, 30, 0]}"#,
        r#"{"projection": "perspective", "eye": [15, 12, -20], "fov_deg": 60}"#,
    ] {
        let scene = testbenches::scene(&format!(
            r#"{{"volume": {{"builtin": "phantom", "dims": [32, 32, 24]}}, "view": {view}, "image": [64, 64],
                "shading": {{"enabled": true}}}}"#
        ));
        let vol = Volume::from_spec(&scene.volume, scene.hardware.voxel_bits).unwrap();
        let one = render_with(1, &scene, &vol);
        let two = render_with(2, &scene, &vol);
        assert!(
            one.0 == two.0,
            "golden model differs between 1 and 2 threads ({view})"
        );
        assert!(
            one.1 == two.1,
            "reference differs between 1 and 2 threads ({view})"
        );
        assert!(one.0.iter().any(|&b| b != 0), "a non-empty image");
    }
}
