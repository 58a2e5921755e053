//! The view registers and tables of a Cube-3 base plane (`host::Reg::C3Stream
//! ..= C3Basis10Z`, `host::ViewTable`): what one base plane's stream (§2's
//! template rays, fetched as §3's Projection Ray Planes) and pipeline (the
//! cast rays, the lanes' bounds and templates, §4's ABC increments and
//! 10-neighbourhood basis) need, as the words the host writes before the
//! frame, so that one build renders any view of its class. The Cube-3 RTL's
//! configuration (`hdl::cube3::config`) fills these plain views; the words
//! are packed through `regmap`.

use crate::host::{Reg, ViewTable, Write};
use crate::regmap::{pack, Entry};

/// One clock of a perspective PRP's writes: plane `plane`, stream rays
/// `ray .. ray + x.len()` at beam positions `x` (increasing; those in the
/// volume in distinct memory modules, `x mod P` distinct).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Group {
    pub plane: usize,
    pub ray: usize,
    pub x: Vec<i32>,
}

/// What the beam fetch's words are made from.
#[derive(Debug, Clone, Copy)]
pub struct FetchView<'a> {
    pub p: usize,
    /// Traversal dims `[n_x, n_y, K]`.
    pub dims: [usize; 3],
    /// Stream rays `u0 .. u0 + rays` of scanlines `v0 .. v0 + scanlines`,
    /// `segments` a ray.
    pub u0: i32,
    pub v0: i32,
    pub rays: usize,
    pub scanlines: usize,
    pub segments: usize,
    /// Planes written per PRP, and the clocks of a scanline period.
    pub planes_written: usize,
    pub period: usize,
    /// The view's offset `O` (the pipeline's, in the fetch's origin word).
    pub offset: u32,
    /// The position tables (`ViewTable::PosX`, `PosY`).
    pub pos_x: &'a [i32],
    pub pos_y: &'a [i32],
    /// Perspective: the groups of every written plane (empty parallel).
    pub groups: &'a [Group],
}

/// The ABC units' part of a pipeline's words.
#[derive(Debug, Clone, Copy)]
pub struct AbcView<'a> {
    /// The increments `DX` by stream ray and `DY` by scanline.
    pub dx: &'a [i32],
    pub dy: &'a [i32],
    /// The 10 (parallel views): the weights `T` and basis correction `C`.
    pub basis10: Option<([u32; 2], [[i64; 3]; 3])>,
    /// Per plane: the inner box's bounds.
    pub inner: &'a [[u32; 4]],
}

/// What a pipeline's own words are made from.
#[derive(Debug, Clone, Copy)]
pub struct PipelineView<'a> {
    pub p: usize,
    pub segments: usize,
    /// The rays and scanlines cast `[ray_lo, ray_hi, line_lo, line_hi]`.
    pub cast: [u32; 4],
    /// The delay lines' lengths less one that the RTL's latencies set
    /// (`C3Delays`' `late_last`, `centre_last` and `flags_last`), and the
    /// ABC sample-plane lines' (`C3Lines`).
    pub late_last: i64,
    pub centre_last: i64,
    pub flags_last: i64,
    pub lines: [i64; 2],
    /// X-ray: the opacity table.
    pub opacity: Option<&'a [u32]>,
    pub abc: Option<AbcView<'a>>,
    /// Per plane: the inside bounds.
    pub bounds: &'a [[u32; 4]],
    /// The template weights of `wx_rays` rays and `wy_scanlines`
    /// scanlines, `K` a ray (scanline).
    pub wx: &'a [u32],
    pub wx_rays: usize,
    pub wy: &'a [u32],
    pub wy_scanlines: usize,
}

/// A register's write.
fn reg(r: Reg, values: &[(&str, i64)]) -> Write {
    Write {
        address: r.address(),
        data: pack(r, values),
    }
}

/// The 10-neighbourhood's registers: the weights `T` and the basis
/// correction's rows.
pub fn basis10_writes(t: [u32; 2], c: &[[i64; 3]; 3]) -> Vec<Write> {
    let row = |r: Reg, c: &[i64; 3]| reg(r, &[("c0", c[0]), ("c1", c[1]), ("c2", c[2])]);
    vec![
        reg(
            Reg::C3Weights10,
            &[("t_x", t[0] as i64), ("t_y", t[1] as i64)],
        ),
        row(Reg::C3Basis10X, &c[0]),
        row(Reg::C3Basis10Y, &c[1]),
        row(Reg::C3Basis10Z, &c[2]),
    ]
}

impl FetchView<'_> {
    /// A perspective view: the groups and rows come from tables.
    fn perspective(&self) -> bool {
        !self.groups.is_empty()
    }

    /// The beam fetch's view words: the stream, dims, strides, origin and
    /// schedule registers, the position tables and a perspective view's
    /// groups.
    pub fn writes(&self) -> Vec<Write> {
        let [nx, ny, nk] = self.dims.map(|d| d as i64);
        let (g, p) = (self.segments as i64, self.p);
        let b = (nx + p as i64 - 1) / p as i64;
        let persp = self.perspective();
        let planes = self.planes_written as i64;
        let (last_chunk, last_plane) = match persp {
            true => (self.groups.len() as i64 - 1, 0),
            false => (self.rays.div_ceil(p) as i64 - 1, planes - 1),
        };
        let mut w = vec![
            reg(
                Reg::C3Stream,
                &[
                    ("rays", self.rays as i64),
                    ("scanlines", self.scanlines as i64),
                    ("segments", g),
                    ("planes_written", planes),
                ],
            ),
            reg(Reg::C3Dims, &[("n_x", nx), ("n_y", ny), ("k", nk)]),
            reg(
                Reg::C3Address,
                &[
                    ("b", b),
                    ("b_n_y", b * ny),
                    ("row_stride", if persp { nk + 1 } else { 0 }),
                    ("template_stride", if persp { g } else { 0 }),
                ],
            ),
            reg(
                Reg::C3Origin,
                &[
                    ("u0", self.u0 as i64),
                    ("v0", self.v0 as i64),
                    ("offset", self.offset as i64),
                ],
            ),
            reg(
                Reg::C3Schedule,
                &[
                    ("period_m1", self.period as i64 - 1),
                    ("last_chunk", last_chunk),
                    ("last_plane", last_plane),
                ],
            ),
        ];
        let pos = |v: &[i32]| -> Vec<u64> {
            v.iter()
                .map(|&d| pack(Entry::Pos, &[("delta", d as i64)]))
                .collect()
        };
        w.extend(ViewTable::PosX.writes(pos(self.pos_x)));
        w.extend(ViewTable::PosY.writes(pos(self.pos_y)));
        if persp {
            w.extend(ViewTable::Groups.writes(self.groups.iter().map(|grp| {
                pack(
                    Entry::Group,
                    &[("plane", grp.plane as i64), ("ray", grp.ray as i64)],
                )
            })));
            for j in 0..p {
                w.extend(ViewTable::GroupX(j).writes(self.groups.iter().map(|grp| {
                    grp.x.get(j).map_or(0, |&x| {
                        pack(Entry::GroupX, &[("x", x as i64), ("holds", 1)])
                    })
                })));
            }
        }
        w
    }
}

impl PipelineView<'_> {
    /// The pipeline's own view words: the cast-ray, delay and line
    /// registers, the X-ray opacity table, the increments (and the 10's
    /// registers), and each lane's bounds and templates.
    pub fn writes(&self) -> Vec<Write> {
        let (g, p, c) = (self.segments as i64, self.p, self.cast);
        let span = |lo: u32, hi: u32| hi.wrapping_sub(lo) as i64;
        let mut w = vec![
            reg(
                Reg::C3Cast,
                &[
                    ("ray_lo", c[0] as i64),
                    ("ray_span", span(c[0], c[1])),
                    ("line_lo", c[2] as i64),
                    ("line_span", span(c[2], c[3])),
                ],
            ),
            reg(
                Reg::C3Delays,
                &[
                    ("late_last", self.late_last),
                    ("lane_last", g - 2),
                    ("centre_last", self.centre_last),
                    ("flags_last", self.flags_last),
                ],
            ),
            reg(
                Reg::C3Lines,
                &[("ray_last", self.lines[0]), ("line_last", self.lines[1])],
            ),
        ];
        if let Some(table) = self.opacity {
            w.extend(ViewTable::XrayOpacity.writes(table.iter().map(|&v| v as u64)));
        }
        if let Some(a) = &self.abc {
            let inc = |d: &[i32]| -> Vec<u64> {
                d.iter()
                    .map(|&d| {
                        pack(
                            Entry::Increment,
                            &[
                                ("magnitude", d.unsigned_abs() as i64),
                                ("negative", (d < 0) as i64),
                            ],
                        )
                    })
                    .collect()
            };
            w.extend(ViewTable::Dx.writes(inc(a.dx)));
            w.extend(ViewTable::Dy.writes(inc(a.dy)));
            if let Some((t, c)) = &a.basis10 {
                w.extend(basis10_writes(*t, c));
            }
        }
        for j in 0..p {
            w.extend(ViewTable::Bounds(j).writes(self.by_segment(self.bounds, j)));
            if let Some(a) = &self.abc {
                w.extend(ViewTable::Inner(j).writes(self.by_segment(a.inner, j)));
            }
            w.extend(ViewTable::Wx(j).writes(self.template(self.wx, self.wx_rays, j)));
            w.extend(ViewTable::Wy(j).writes(self.template(self.wy, self.wy_scanlines, j)));
        }
        w
    }

    /// Lane `j`'s bounds words of `b`, by segment `s` (plane `s·P + j`;
    /// empty beyond the planes).
    fn by_segment(&self, b: &[[u32; 4]], j: usize) -> Vec<u64> {
        (0..self.segments)
            .map(|s| {
                let [rl, rh, vl, vh] = b.get(s * self.p + j).copied().unwrap_or([1, 0, 1, 0]);
                pack(
                    Entry::Bounds,
                    &[
                        ("ray_lo", rl as i64),
                        ("ray_hi", rh as i64),
                        ("line_lo", vl as i64),
                        ("line_hi", vh as i64),
                    ],
                )
            })
            .collect()
    }

    /// Lane `j`'s template words of `wt` (`lines` rays or scanlines):
    /// weight `k = s·P + j` of line `r` at `r·G + s` (0 beyond `K`).
    fn template(&self, wt: &[u32], lines: usize, j: usize) -> Vec<u64> {
        let nk = wt.len() / lines;
        (0..lines * self.segments)
            .map(|a| {
                let (r, k) = (a / self.segments, (a % self.segments) * self.p + j);
                if k < nk {
                    wt[r * nk + k] as u64
                } else {
                    0
                }
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn data(w: &[Write], address: u32) -> Vec<u64> {
        w.iter()
            .filter(|w| w.address == address)
            .map(|w| w.data)
            .collect()
    }

    /// A parallel 5·4·3 traversal through two units: words worked by hand.
    #[test]
    fn a_small_parallel_fetch_packs_by_hand() {
        let f = FetchView {
            p: 2,
            dims: [5, 4, 3],
            u0: -1,
            v0: 2,
            rays: 9,
            scanlines: 6,
            segments: 2,
            planes_written: 4,
            period: 21,
            offset: 3,
            pos_x: &[0, -1],
            pos_y: &[1],
            groups: &[],
        };
        let w = f.writes();
        // rays 9, scanlines 6, G 2, planes 4.
        assert_eq!(data(&w, 0x30), [0x0004_0002_0006_0009]);
        assert_eq!(data(&w, 0x31), [0x0003_0004_0005]);
        // b = ceil(5 / 2) = 3, b·n_y = 12, no perspective strides.
        assert_eq!(data(&w, 0x32), [0x000c_0003]);
        // u0 -1 and v0 2 in 16 bits, offset 3.
        assert_eq!(data(&w, 0x33), [0x0003_0002_ffff]);
        // period 21 - 1, last chunk ceil(9 / 2) - 1 = 4, last plane 3.
        assert_eq!(data(&w, 0x34), [0x0003_0000_0400_0014]);
        assert_eq!(data(&w, 0x07_0000), [0]);
        assert_eq!(data(&w, 0x07_0001), [0xffff]);
        assert_eq!(data(&w, 0x20_0000), [1]);
        assert_eq!(w.len(), 8);
    }

    #[test]
    fn a_perspective_fetch_writes_its_groups() {
        let groups = [
            Group {
                plane: 0,
                ray: 0,
                x: vec![-1, 0],
            },
            Group {
                plane: 1,
                ray: 2,
                x: vec![3],
            },
        ];
        let f = FetchView {
            p: 2,
            dims: [4, 4, 2],
            u0: 0,
            v0: 0,
            rays: 3,
            scanlines: 1,
            segments: 1,
            planes_written: 2,
            period: 6,
            offset: 0,
            pos_x: &[],
            pos_y: &[0, 0],
            groups: &groups,
        };
        let w = f.writes();
        // Strides K + 1 = 3 and G = 1; last group 1, no last plane.
        assert_eq!(data(&w, 0x32), [0x0001_0003_0008_0002]);
        assert_eq!(data(&w, 0x34), [0x0100_0005]);
        assert_eq!(data(&w, 0x24_0000), [0]);
        assert_eq!(data(&w, 0x24_0001), [1 | 2 << 16]);
        // Lane 0: x -1 and 3, each held; lane 1: 0 held, then none.
        assert_eq!(data(&w, 0x28_0000), [0x1_ffff]);
        assert_eq!(data(&w, 0x28_0001), [0x1_0003]);
        assert_eq!(data(&w, 0x2c_0000), [0x1_0000]);
        assert_eq!(data(&w, 0x2c_0001), [0]);
    }

    /// Two units, three planes in two segments, with gradients and the 10.
    #[test]
    fn a_small_pipeline_packs_by_hand() {
        let bounds = [[0, 4, 1, 5], [1, 3, 1, 5], [2, 2, 0, 0]];
        let inner = [[1, 3, 2, 4], [1, 0, 1, 0], [2, 2, 2, 2]];
        let v = PipelineView {
            p: 2,
            segments: 2,
            cast: [1, 6, 0, 3],
            late_last: 2,
            centre_last: 0,
            flags_last: 40,
            lines: [1, 9],
            opacity: None,
            abc: Some(AbcView {
                dx: &[-3],
                dy: &[2],
                basis10: Some(([10, 20], [[1, -1, 0], [0, 2, -2], [3, 0, 0]])),
                inner: &inner,
            }),
            bounds: &bounds,
            wx: &[7, 8, 9],
            wx_rays: 1,
            wy: &[4, 5, 6],
            wy_scanlines: 1,
        };
        let w = v.writes();
        assert_eq!(data(&w, 0x35), [0x0003_0000_0005_0001]);
        // G - 2 = 0 in the lanes' field.
        assert_eq!(data(&w, 0x36), [0x0028_0000_0000_0002]);
        assert_eq!(data(&w, 0x37), [0x0009_0001]);
        assert_eq!(data(&w, 0x05_0000), [0x1_0003]);
        assert_eq!(data(&w, 0x06_0000), [2]);
        assert_eq!(data(&w, 0x38), [0x0014_000a]);
        assert_eq!(data(&w, 0x39), [0xffff_0001]);
        assert_eq!(data(&w, 0x3a), [0xfffe_0002_0000]);
        assert_eq!(data(&w, 0x3b), [3]);
        // Lane 0 holds planes 0 and 2, lane 1 plane 1 and none.
        assert_eq!(data(&w, 0x0a_0000), [0x0005_0001_0004_0000]);
        assert_eq!(data(&w, 0x0a_0001), [0x0000_0000_0002_0002]);
        assert_eq!(data(&w, 0x0a_0100), [0x0005_0001_0003_0001]);
        assert_eq!(data(&w, 0x0a_0101), [0x0000_0001_0000_0001]);
        assert_eq!(data(&w, 0x0a_1001), [0x0002_0002_0002_0002]);
        assert_eq!(data(&w, 0x0a_1100), [0x0000_0001_0000_0001]);
        // Weights k = s·2 + j.
        assert_eq!(data(&w, 0x10_0000), [7]);
        assert_eq!(data(&w, 0x10_0001), [9]);
        assert_eq!(data(&w, 0x11_0000), [8]);
        assert_eq!(data(&w, 0x11_0001), [0]);
        assert_eq!(data(&w, 0x19_0000), [5]);
    }
}
