//! Waveforms of the whole-pipeline simulation: the VCD parses with vcd2fst,
//! and every signal the GTKWave save file names exists in it.

use scene::volume::builtin;
use std::collections::HashSet;
use testbenches::{assert_vcd_parses, scene};

/// Full names (`uut.cfb.n_s`) of every variable in a VCD.
fn vcd_names(path: &std::path::Path) -> HashSet<String> {
    let mut parser = vcd::Parser::new(std::io::BufReader::new(std::fs::File::open(path).unwrap()));
    let header = parser.parse_header().expect("VCD header parses");
    let mut names = HashSet::new();
    fn walk(items: &[vcd::ScopeItem], prefix: &str, names: &mut HashSet<String>) {
        for item in items {
            match item {
                vcd::ScopeItem::Scope(s) => {
                    walk(&s.items, &format!("{prefix}{}.", s.identifier), names)
                }
                vcd::ScopeItem::Var(v) => {
                    names.insert(format!("{prefix}{}", v.reference));
                }
                _ => {}
            }
        }
    }
    walk(&header.items, "", &mut names);
    names
}

#[test]
fn pipeline_vcd_parses_and_gtkw_names_its_signals() {
    let s = scene(
        r#"{"volume": {"builtin": "phantom", "dims": [10, 10, 8]}, "view": {"projection": "parallel", "rotate_deg": [70, 30, 0]},
            "mode": "mip", "image": [32, 32], "hardware": {"pipelines": 2}}"#,
    );
    let vol = builtin("phantom", [10, 10, 8], 8).unwrap();
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("vcd");
    std::fs::create_dir_all(&dir).unwrap();
    let vcd = dir.join("pipeline_p2.vcd");
    let r = cosim::sim::simulate::<cosim::cube4l::Cube4l>(
        &s,
        &s.camera(),
        &vol,
        cosim::Engine::RustHdl,
        Some(&vcd),
    )
    .unwrap();
    assert_eq!(r.mismatches, 0);
    assert_vcd_parses(&vcd);
    let names = vcd_names(&vcd);
    let gtkw = std::fs::read_to_string(vcd.with_extension("gtkw")).unwrap();
    let listed: Vec<&str> = gtkw.lines().filter(|l| l.starts_with("uut.")).collect();
    assert!(
        listed.len() > 20,
        "the save file lists {} signals",
        listed.len()
    );
    for l in listed {
        let name = l.split('[').next().unwrap();
        assert!(
            names.contains(name),
            "{name} is in the .gtkw but not in the VCD"
        );
    }
    assert!(
        gtkw.contains("-CFB lane 1")
            && gtkw.contains("-Compositing lane 0")
            && gtkw.contains("-Pixel out 1")
    );
}
