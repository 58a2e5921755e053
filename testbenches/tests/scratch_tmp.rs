use rust_hdl::prelude::*;
#[test]
fn dump() {
    for (deg, f) in [(45.0, "g45"), (40.0, "g40")] {
        let s = testbenches::scene(&format!(
            r#"{{"volume": {{"builtin": "phantom", "dims": [12, 12, 10]}}, "view": {{"projection": "parallel", "rotate_deg": [0, {deg}, 0]}}, "mode": "mip", "image": [16, 16]}}"#
        ));
        let cam = s.camera().unwrap();
        let plan = golden_model::cube3::plan::Plan::new(&s, &cam).unwrap();
        let view = &plan.views[0];
        let shader = golden_model::cube3::shade::Shader::new(&s, &cam, view);
        let c = hdl::cube3::Cube3Config::new(view, &shader, 2, 3, 3).unwrap();
        println!("{f} on_grid {}", c.on_grid);
        let mut uut = hdl::cube3::Cube3::<2, 8>::new(&c).unwrap();
        uut.connect_all();
        std::fs::write(format!("/tmp/vt/{f}.v"), generate_verilog(&uut)).unwrap();
    }
}
