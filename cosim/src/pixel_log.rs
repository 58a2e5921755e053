//! The pixel log that the Verilog engines' harnesses write: `x y face res`
//! per pixel on the pixel bus, then `cycles N` (or `timeout`), read back
//! into a base plane.

use golden_model::cube4l::plan::{Face, Sweep};
use golden_model::cube4l::BasePlane;
use hdl::pipeline::unpack;

/// Parse a Verilog engine's pixel log: `x y face res` per pixel on the bus,
/// then `cycles N` (or `timeout`).
pub fn parse_pixel_log(
    log: &str,
    sweep: &Sweep,
    mode: scene::Mode,
) -> Result<(BasePlane, u64), String> {
    let mut base = BasePlane::new(sweep);
    let mut cycles = None;
    for line in log.lines() {
        let f: Vec<&str> = line.split_whitespace().collect();
        match f.as_slice() {
            ["cycles", c] => cycles = c.parse::<u64>().ok(),
            ["timeout"] => return Err("the Verilog pipeline did not finish the sweep".into()),
            [x, y, face, res] => {
                let n = |s: &str| {
                    if s.bytes().any(|b| b"xXzZ".contains(&b)) {
                        return Err(format!(
                            "the RTL put out an undefined (X or Z) pixel: '{line}' (x y face value)"
                        ));
                    }
                    s.parse::<u64>()
                        .map_err(|e| format!("pixel log '{line}': {e}"))
                };
                place(&mut base, [n(x)?, n(y)?], n(face)?, unpack(mode, n(res)?))?;
            }
            _ => return Err(format!("unexpected line in the pixel log: '{line}'")),
        }
    }
    Ok((base, cycles.ok_or("the pixel log has no clock count")?))
}

/// Put a pixel the RTL output into `base`, or say why the golden model
/// could never have output it: an address outside the base plane, or a face
/// code that names no face.
pub(crate) fn place(
    base: &mut BasePlane,
    [x, y]: [u64; 2],
    face: u64,
    value: [u32; 4],
) -> Result<(), String> {
    const FACES: [Face; 6] = [
        Face::None,
        Face::Last,
        Face::XPos,
        Face::XNeg,
        Face::YPos,
        Face::YNeg,
    ];
    let stray = |why: &str| {
        format!(
            "the RTL put out a pixel at ({x}, {y}) with face code {face}: {why} (base plane {} x {})",
            base.width, base.height
        )
    };
    if x >= base.width as u64 || y >= base.height as u64 {
        return Err(stray("outside the base plane"));
    }
    let Some(&f) = FACES.get(face as usize).filter(|&&f| f != Face::None) else {
        return Err(stray("no such face"));
    };
    base.put([x as usize, y as usize], value, f);
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sweep() -> Sweep {
        let s = scene::Scene::from_json(
            r#"{"volume": {"builtin": "sphere", "dims": [6,5,4]}, "view": {"projection": "parallel", "rotate_deg": [20, 30, 0]}, "image": [8, 8]}"#,
            None,
        )
        .unwrap();
        let cam = s.camera().unwrap();
        golden_model::cube4l::plan::Plan::new(&s, &cam)
            .unwrap()
            .sweeps
            .remove(0)
    }

    #[test]
    fn stray_pixels_are_reported_not_panicked_on() {
        let s = sweep();
        let mut base = BasePlane::new(&s);
        assert!(place(&mut base, [0, 0], 1, [1, 2, 3, 4]).is_ok());
        assert_eq!(base.faces[0], Face::Last);
        let e = place(&mut base, [0, 0], 7, [0; 4]).unwrap_err();
        assert!(
            e.contains("face code 7") && e.contains("no such face"),
            "{e}"
        );
        let e = place(&mut base, [0, 0], 0, [0; 4]).unwrap_err();
        assert!(e.contains("no such face"), "{e}");
        let e = place(&mut base, [u64::MAX, 0], 1, [0; 4]).unwrap_err();
        assert!(e.contains("outside the base plane"), "{e}");
        let log = format!("{} 0 1 5\ncycles 9\n", base.width);
        let e = parse_pixel_log(&log, &s, scene::Mode::Mip).unwrap_err();
        assert!(e.contains("outside the base plane"), "{e}");
        let (b, c) = parse_pixel_log("1 1 2 5\ncycles 9\n", &s, scene::Mode::Mip).unwrap();
        assert_eq!(
            (b.pixels[1 + b.width], b.faces[1 + b.width], c),
            ([5, 0, 0, 0], Face::XPos, 9)
        );
    }
}
