use rust_hdl::prelude::*;
#[test]
fn dump() {
    for (mode, f) in [("mip", "s_mip"), ("xray", "s_xray")] {
        let s = testbenches::scene(&format!(
            r#"{{"volume": {{"builtin": "phantom", "dims": [20, 18, 16]}}, "view": {{"projection": "parallel", "rotate_deg": [25, 35, 0]}}, "mode": "{mode}", "image": [16, 16], "hardware": {{"pipelines": 4}}}}"#
        ));
        let cam = s.camera().unwrap();
        let plan = golden_model::cube3::plan::Plan::new(&s, &cam).unwrap();
        let view = &plan.views[0];
        let shader = golden_model::cube3::shade::Shader::new(&s, &cam, view);
        let c = hdl::cube3_system::Cube3SystemConfig::new(
            view,
            &shader,
            4,
            view.v[0],
            (view.v[1] - view.v[0] + 1) as usize,
        )
        .unwrap();
        let mut uut = hdl::cube3_system::Cube3System::<4, 16, 16, 9>::new(&c).unwrap();
        uut.connect_all();
        std::fs::write(
            format!("/tmp/vt/{f}.v"),
            cosim::export::width_clean(&generate_verilog(&uut)),
        )
        .unwrap();
    }
}
