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
                    s.parse::<u64>()
                        .map_err(|e| format!("pixel log '{line}': {e}"))
                };
                base.put(
                    [n(x)? as usize, n(y)? as usize],
                    unpack(mode, n(res)?),
                    face_of(n(face)? as u32),
                );
            }
            _ => return Err(format!("unexpected line in the pixel log: '{line}'")),
        }
    }
    Ok((base, cycles.ok_or("the pixel log has no clock count")?))
}

pub(crate) fn face_of(code: u32) -> Face {
    [
        Face::None,
        Face::Last,
        Face::XPos,
        Face::XNeg,
        Face::YPos,
        Face::YNeg,
    ][code as usize]
}
