//! The bilinear unit (Cube-4L §3.5-3.6, Figs. 3 and 18): it reads the
//! one-slice compositing buffer where the voxel's sight ray meets the
//! previous slice. The compositing unit it feeds is both architectures'
//! (`common::compositor`).
//!
//! The ray through voxel `(x, y)` meets the previous slice at `(x - dx, y - dy)`,
//! inside the 3x3 region around the voxel because |dx|, |dy| <= 1. The signs
//! of dx and dy narrow it to 2x2: neighbour `x - sign(dx)` with weight `|dx|`.
//! Cells outside the slice read as the reset value (nothing accumulated).

use crate::fixed::{lerp_frac, lerp_i32};

/// The bilinear unit: accumulated value where the sight ray of cell `(x, y)`
/// meets the previous slice `prev` (`nx * ny` cells, x fastest).
/// Each channel: `top = lerp(c[y][x], c[y][x'], |dx|)`,
/// `bottom = lerp(c[y'][x], c[y'][x'], |dx|)`, `lerp(top, bottom, |dy|)` with
/// `x' = x - sign(dx)`, `y' = y - sign(dy)` and `lerp` = `fixed::lerp_frac`.
#[allow(clippy::too_many_arguments)]
pub fn gather(
    prev: &[[u32; 4]],
    nx: usize,
    ny: usize,
    x: usize,
    y: usize,
    dx: i32,
    dy: i32,
    frac: u32,
    reset: [u32; 4],
) -> [u32; 4] {
    let (wx, wy) = (dx.unsigned_abs(), dy.unsigned_abs());
    let (c00, c10, c01, c11) = if x > 0 && y > 0 && x + 1 < nx && y + 1 < ny {
        // Inside the slice's border: all four cells are in it.
        let i = x + nx * y;
        let ix = (i as isize - dx.signum() as isize) as usize;
        let iy = (i as isize - dy.signum() as isize * nx as isize) as usize;
        let ixy = (ix as isize - dy.signum() as isize * nx as isize) as usize;
        (prev[i], prev[ix], prev[iy], prev[ixy])
    } else {
        let cell = |cx: isize, cy: isize| -> [u32; 4] {
            if cx < 0 || cy < 0 || cx >= nx as isize || cy >= ny as isize {
                reset
            } else {
                prev[cx as usize + nx * cy as usize]
            }
        };
        let (x, y) = (x as isize, y as isize);
        let (x2, y2) = (x - dx.signum() as isize, y - dy.signum() as isize);
        (cell(x, y), cell(x2, y), cell(x, y2), cell(x2, y2))
    };
    let any = (0..4).fold(0, |a, i| a | c00[i] | c10[i] | c01[i] | c11[i]);
    if frac <= 16 && any < 1 << (30 - frac) {
        // Every product of a difference and a weight fits 31 bits: the same
        // lerps in i32, four channels at once.
        let lerp = |a: [u32; 4], b: [u32; 4], w: u32| -> [u32; 4] {
            std::array::from_fn(|i| lerp_i32(a[i] as i32, b[i] as i32, w as i32, frac) as u32)
        };
        return lerp(lerp(c00, c10, wx), lerp(c01, c11, wx), wy);
    }
    std::array::from_fn(|i| {
        let top = lerp_frac(c00[i], c10[i], wx, frac);
        let bottom = lerp_frac(c01[i], c11[i], wx, frac);
        lerp_frac(top, bottom, wy, frac)
    })
}

/// [`gather`] for cells `lo..hi` of row `y` at once, one `(dx, dy)` for
/// the whole row (a parallel view), inside the slice's border (`1 <= lo`,
/// `hi <= nx - 1`, `0 < y < ny - 1`): the same lerps, channel by channel,
/// in vector lanes where every product fits 31 bits (as [`gather`]'s own
/// shortcut), else one cell at a time.
#[allow(clippy::too_many_arguments)]
pub fn gather_row(
    prev: &[[u32; 4]],
    nx: usize,
    y: usize,
    (lo, hi): (usize, usize),
    dx: i32,
    dy: i32,
    frac: u32,
    out: &mut [[u32; 4]],
) {
    let n = hi - lo;
    let at = |offset: isize| {
        let i = (y * nx + lo) as isize + offset;
        &prev[i as usize..i as usize + n]
    };
    let (sx, sy) = (dx.signum() as isize, dy.signum() as isize * nx as isize);
    let cells = [at(0), at(-sx), at(-sy), at(-sx - sy)];
    let (wx, wy) = (dx.unsigned_abs(), dy.unsigned_abs());
    let any = cells
        .iter()
        .fold(0, |a, c| a | c.as_flattened().iter().fold(0, |o, &v| o | v));
    if frac <= 16 && any < 1 << (30 - frac) {
        let flat = cells.map(|c| c.as_flattened());
        return row_i32(out.as_flattened_mut(), flat, [wx, wy, frac]);
    }
    for (k, o) in out.iter_mut().enumerate() {
        *o = std::array::from_fn(|i| {
            let top = lerp_frac(cells[0][k][i], cells[1][k][i], wx, frac);
            let bottom = lerp_frac(cells[2][k][i], cells[3][k][i], wx, frac);
            lerp_frac(top, bottom, wy, frac)
        });
    }
}

/// [`gather_row`]'s lerps in i32 over the row's channels.
fn row_i32(out: &mut [u32], c: [&[u32]; 4], w: [u32; 3]) {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") {
        // SAFETY: the CPU has AVX2, checked just above.
        return unsafe { row_i32_avx2(out, c, w) };
    }
    row_i32_lanes(out, c, w)
}

/// [`row_i32_lanes`] compiled for AVX2's eight 32-bit lanes (a vector
/// multiply of 32-bit words, which the x86-64 baseline lacks).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn row_i32_avx2(out: &mut [u32], c: [&[u32]; 4], w: [u32; 3]) {
    row_i32_lanes(out, c, w)
}

/// The body of [`row_i32`]; `w` is `[|dx|, |dy|, frac]`.
#[inline(always)]
fn row_i32_lanes(out: &mut [u32], c: [&[u32]; 4], w: [u32; 3]) {
    let [wx, wy, frac] = w;
    let n = out.len();
    let lerp = |a: i32, b: i32, w: i32| lerp_i32(a, b, w, frac);
    // Exact lengths, so that the loop has no bounds checks.
    let [a, b, c, d] = c.map(|s| &s[..n]);
    for k in 0..n {
        let top = lerp(a[k] as i32, b[k] as i32, wx as i32);
        let bottom = lerp(c[k] as i32, d[k] as i32, wx as i32);
        out[k] = lerp(top, bottom, wy as i32) as u32;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_row_gathers_as_its_cells_do() {
        let (nx, ny) = (13, 5);
        let mut x = 0x2545_f491_4f6c_dd1du64;
        let mut next = |bits: u32| {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            (x >> 11) as u32 & ((1u64 << bits) - 1) as u32
        };
        // 8-bit colours (the vector lanes), and X-ray sums past 2^22 (one
        // cell at a time).
        for bits in [8, 16, 26] {
            for frac in [4, 8, 12] {
                let prev: Vec<[u32; 4]> = (0..nx * ny)
                    .map(|_| std::array::from_fn(|_| next(bits)))
                    .collect();
                let one = 1i32 << frac;
                for (dx, dy) in [(0, 0), (one, -one), (-(one / 3), one / 2), (5, -7)] {
                    for y in 1..ny - 1 {
                        let mut row = vec![[0; 4]; nx - 2];
                        gather_row(&prev, nx, y, (1, nx - 1), dx, dy, frac, &mut row);
                        for (k, got) in row.iter().enumerate() {
                            let want = gather(&prev, nx, ny, k + 1, y, dx, dy, frac, [0; 4]);
                            assert_eq!(
                                *got,
                                want,
                                "bits {bits} frac {frac} d ({dx}, {dy}) at ({}, {y})",
                                k + 1
                            );
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn gather_at_zero_and_unit_increments() {
        let prev: Vec<[u32; 4]> = (0..9).map(|i| [i * 10, 0, 0, 0]).collect();
        assert_eq!(gather(&prev, 3, 3, 1, 1, 0, 0, 8, [0; 4])[0], 40);
        assert_eq!(gather(&prev, 3, 3, 1, 1, 256, 0, 8, [0; 4])[0], 30);
        assert_eq!(gather(&prev, 3, 3, 1, 1, -256, -256, 8, [0; 4])[0], 80);
        assert_eq!(gather(&prev, 3, 3, 1, 1, 128, 0, 8, [0; 4])[0], 35);
        assert_eq!(gather(&prev, 3, 3, 0, 0, 256, 256, 8, [7; 4])[0], 7);
    }

    /// `round_half_up((a * (2^f - w) + b * w) / 2^f)`, exactly.
    fn lerp_exact(a: u32, b: u32, w: u32, frac: u32) -> u32 {
        let one = 1i128 << frac;
        let num = a as i128 * (one - w as i128) + b as i128 * w as i128;
        (2 * num + one).div_euclid(2 * one) as u32
    }

    /// The bilinear unit by its definition: the ray leaves `(x, y)` towards
    /// `(x - dx, y - dy)`; the 2x2 cells around that point, cells outside the
    /// slice reading `reset`.
    #[allow(clippy::too_many_arguments)]
    fn gather_by_definition(
        prev: &[[u32; 4]],
        nx: usize,
        ny: usize,
        x: usize,
        y: usize,
        dx: i32,
        dy: i32,
        frac: u32,
        reset: [u32; 4],
    ) -> [u32; 4] {
        let at = |cx: i64, cy: i64| {
            if (0..nx as i64).contains(&cx) && (0..ny as i64).contains(&cy) {
                prev[cy as usize * nx + cx as usize]
            } else {
                reset
            }
        };
        let step = |d: i32| match d {
            d if d > 0 => 1,
            d if d < 0 => -1,
            _ => 0,
        };
        let (x, y) = (x as i64, y as i64);
        let (xn, yn) = (x - step(dx), y - step(dy));
        let (wx, wy) = (dx.unsigned_abs(), dy.unsigned_abs());
        std::array::from_fn(|i| {
            let top = lerp_exact(at(x, y)[i], at(xn, y)[i], wx, frac);
            let bottom = lerp_exact(at(x, yn)[i], at(xn, yn)[i], wx, frac);
            lerp_exact(top, bottom, wy, frac)
        })
    }

    #[test]
    fn gather_matches_definition_everywhere() {
        // A 4x3 slice with distinct values per cell and channel, every cell
        // (edges and corners included), increments of both signs.
        let (nx, ny) = (4, 3);
        let prev: Vec<[u32; 4]> = (0..12u32)
            .map(|i| [i * 21 + 3, 255 - i * 17, (i * 97) % 256, i * 5])
            .collect();
        let reset = [9, 250, 7, 131];
        let ds = [-256, -255, -200, -128, -1, 0, 1, 77, 128, 129, 256];
        for y in 0..ny {
            for x in 0..nx {
                for &dx in &ds {
                    for &dy in &ds {
                        assert_eq!(
                            gather(&prev, nx, ny, x, y, dx, dy, 8, reset),
                            gather_by_definition(&prev, nx, ny, x, y, dx, dy, 8, reset),
                            "({x}, {y}) d ({dx}, {dy})"
                        );
                    }
                }
            }
        }
        // Wide X-ray sums (past the i32 shortcut): the i64 lerps.
        let wide: Vec<[u32; 4]> = prev.iter().map(|c| c.map(|v| v << 20)).collect();
        for y in 0..ny {
            for x in 0..nx {
                for &d in &ds {
                    assert_eq!(
                        gather(&wide, nx, ny, x, y, d, -d, 8, reset),
                        gather_by_definition(&wide, nx, ny, x, y, d, -d, 8, reset),
                        "wide ({x}, {y}) d {d}"
                    );
                }
            }
        }
        // Other fractional widths: 2 and 12 bits.
        for (frac, d) in [(2u32, 3i32), (12, -2900)] {
            for y in 0..ny {
                for x in 0..nx {
                    assert_eq!(
                        gather(&prev, nx, ny, x, y, d, -d, frac, reset),
                        gather_by_definition(&prev, nx, ny, x, y, d, -d, frac, reset)
                    );
                }
            }
        }
    }

    #[test]
    fn one_wide_cell_takes_the_i64_lerps() {
        // The i32 shortcut is for cells whose every word is below
        // 2^(30 - frac); one wide word among the four cells (or channels)
        // must send the whole lerp to the i64 path, whichever cell holds it
        // and whatever the other words are. B = 2^28 in a 3x3 slice of 0s,
        // d = (1/2, 1/2) at (1, 1): the cells are c00 = [4], c10 = [3],
        // c01 = [1], c11 = [0]; each half lerp of B and 0 is exact.
        const B: u32 = 1 << 28;
        // (index, words) of the cells that are not 0; the gathered words.
        type Case = (&'static [(usize, [u32; 4])], [u32; 4]);
        let cases: [Case; 6] = [
            // c11 alone: top 0, bottom B/2, B/4.
            (&[(0, [B, 0, 0, 0])], [B / 4, 0, 0, 0]),
            // c01 = c11: top 0, bottom B, B/2.
            (&[(1, [B, 0, 0, 0]), (0, [B, 0, 0, 0])], [B / 2, 0, 0, 0]),
            // c10 alone: top B/2, bottom 0, B/4.
            (&[(3, [B, 0, 0, 0])], [B / 4, 0, 0, 0]),
            // c10 = c01: top B/2, bottom B/2, B/2.
            (&[(3, [B, 0, 0, 0]), (1, [B, 0, 0, 0])], [B / 2, 0, 0, 0]),
            // c00 = c10: top B, bottom 0, B/2.
            (&[(4, [B, 0, 0, 0]), (3, [B, 0, 0, 0])], [B / 2, 0, 0, 0]),
            // c00 alone, the same word in two channels: B/4 in each.
            (&[(4, [B, B, 0, 0])], [B / 4, B / 4, 0, 0]),
        ];
        for (cells, want) in cases {
            let mut prev = vec![[0u32; 4]; 9];
            for &(i, v) in cells {
                prev[i] = v;
            }
            assert_eq!(
                gather(&prev, 3, 3, 1, 1, 128, 128, 8, [0; 4]),
                want,
                "{cells:?}"
            );
            let mut row = [[0u32; 4]; 1];
            gather_row(&prev, 3, 1, (1, 2), 128, 128, 8, &mut row);
            assert_eq!(row[0], want, "row, {cells:?}");
        }
    }

    #[test]
    fn gather_edges_by_hand() {
        // prev[x + 3y] = 10 * (x + 3y), reset 7.
        let prev: Vec<[u32; 4]> = (0..9).map(|i| [i * 10, 0, 0, 0]).collect();
        let g = |x, y, dx, dy| gather(&prev, 3, 3, x, y, dx, dy, 8, [7, 0, 0, 0])[0];
        // Row 0 and column 0 are inside the slice.
        assert_eq!(g(1, 0, 0, 0), 10);
        assert_eq!(g(0, 1, 0, 0), 30);
        assert_eq!(g(0, 0, 0, 0), 0);
        assert_eq!(g(2, 2, 0, 0), 80);
        // Row -1 is outside: lerp(10, 7, 1/2) = 8.5 -> 9 (half up).
        assert_eq!(g(1, 0, 0, 128), 9);
        assert_eq!(g(1, 0, 0, 256), 7);
        // Row 3 and column 3 are outside.
        assert_eq!(g(1, 2, 0, -256), 7);
        assert_eq!(g(2, 1, -256, 0), 7);
        // lerp(70, 7, 1/2) = 38.5 -> 39.
        assert_eq!(g(1, 2, 0, -128), 39);
        // Corner outside on both axes: top = lerp(80, 7, 1/4) = 61.75 -> 62,
        // bottom = 7, lerp(62, 7, 3/4) = 20.75 -> 21.
        assert_eq!(g(2, 2, -64, -192), 21);
    }
}
