//! Voxel projection by quantized positions (Mora, Jessel & Caubet, §2.2,
//! Fig. 2, Eqs. 3-5).
//!
//! A voxel's projected centre `C` falls in the square of four neighbouring
//! pixels whose top-left pixel is `floor(C)`. Pixel `floor(C) + o` is in
//! the voxel's projection exactly when `C` is in that pixel's area of
//! effect, the template hexagon centred on the pixel (`hexagon`). The
//! square is cut into `n × n` subdivisions, and each subdivision is
//! classified once per view against every area-of-effect edge near the
//! square:
//!
//! - an offset whose area of effect holds the whole subdivision is a
//!   **sure** pixel;
//! - one whose area of effect misses it is left out;
//! - one whose edges cross the subdivision is **undecided**: it carries the
//!   crossing edges as `a·x + b·y >= -c` (Eq. 5), tested at run time with
//!   the centre's position `(x, y)` inside the square.
//!
//! Subdivisions with the same lists are grown into classes (4-connected
//! region growing), and a class keeps its sure pixels as single integer
//! offsets from the square's top-left pixel (Eq. 4: `pixel = square +
//! A[i]`): one addition and one addressing per pixel. The result is exact:
//! the subdivision decides which pixels need a test, never the answer.
//!
//! Building it is cheap because only the few edge lines that cross the
//! square need per-subdivision work; every other (offset, edge) pair has one
//! answer for the whole square.

use super::hexagon::Hexagon;
use glam::DVec2;
use rayon::prelude::*;
use std::collections::HashMap;
use std::ops::Range;

/// An undecided pixel: its offset and its edge equations
/// `eqs[first..first + len]`, all of which must hold.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Undecided {
    pub offset: [i32; 2],
    pub first: u32,
    pub len: u32,
}

/// One class of subdivisions.
#[derive(Debug, Clone, PartialEq)]
pub struct Class {
    pub sure: Vec<[i32; 2]>,
    pub undecided: Vec<Undecided>,
}

/// The per-view projection table.
#[derive(Debug, Clone)]
pub struct ProjectionTable {
    pub n: usize,
    /// Class of subdivision `(sx, sy)` at `sy * n + sx`.
    pub class_of: Vec<u16>,
    pub classes: Vec<Class>,
    /// Edge equations `[a, b, c]` of the undecided pixels: inside when
    /// `a·x + b·y >= -c`, `(x, y)` the centre's position in the square.
    pub eqs: Vec<[f64; 3]>,
}

/// Status of one (offset, edge) pair over a region of the square.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Side {
    In,
    Out,
    Crossed,
}

/// The side of edge `(a, b, c)` (already moved to the offset) over the box
/// `[x0, x1] × [y0, y1]`: its linear function's extremes lie at corners.
/// Rounding is monotone in each product and in the sum, so the smallest of
/// the four corners' computed values is the one at the corner that makes
/// each product smallest, and the largest the opposite corner: two
/// evaluations give exactly what all four would.
fn side(e: [f64; 3], x0: f64, x1: f64, y0: f64, y1: f64) -> Side {
    let f = |x: f64, y: f64| e[0] * x + e[1] * y + e[2];
    let ([xl, xh], [yl, yh]) = (
        if e[0] >= 0.0 { [x0, x1] } else { [x1, x0] },
        if e[1] >= 0.0 { [y0, y1] } else { [y1, y0] },
    );
    if f(xl, yl) >= 0.0 {
        Side::In
    } else if f(xh, yh) < 0.0 {
        Side::Out
    } else {
        Side::Crossed
    }
}

/// The first `i` in `0..n` with `p(i)`, for `p` false then true (`n` when
/// it is never true).
fn first(n: usize, p: impl Fn(usize) -> bool) -> usize {
    let (mut lo, mut hi) = (0, n);
    while lo < hi {
        let mid = (lo + hi) / 2;
        if p(mid) {
            hi = mid;
        } else {
            lo = mid + 1;
        }
    }
    lo
}

/// Along the row of `n` subdivisions from `y0`, those edge `e` leaves Out
/// and those it crosses. `side`'s two corners move one way with the column,
/// so In lies at one end of the row, Out at the other and Crossed between:
/// two bisections find them.
fn row_split(e: [f64; 3], n: usize, y0: f64, step: f64) -> (Range<usize>, Range<usize>) {
    let at = |sx: usize| {
        let x0 = sx as f64 * step;
        side(e, x0, x0 + step, y0, y0 + step)
    };
    if e[0] >= 0.0 {
        // Out, Crossed, In from left to right.
        let a = first(n, |sx| at(sx) != Side::Out);
        let b = first(n, |sx| at(sx) == Side::In);
        (0..a, a..b)
    } else {
        // In, Crossed, Out.
        let a = first(n, |sx| at(sx) != Side::In);
        let b = first(n, |sx| at(sx) == Side::Out);
        (b..n, a..b)
    }
}

impl ProjectionTable {
    pub fn new(hex: &Hexagon, n: usize) -> ProjectionTable {
        assert!((1..=256).contains(&n));
        let h = hex.half_extent();
        // Offsets o with f - o inside the hexagon for some f in [0, 1)².
        let (ox0, ox1) = ((-h.x).floor() as i32, (1.0 + h.x).ceil() as i32);
        let (oy0, oy1) = ((-h.y).floor() as i32, (1.0 + h.y).ceil() as i32);
        // Edge e at offset o, as a function of the centre f in the square:
        // e(f - o) = a·f.x + b·f.y + (c - a·o.x - b·o.y).
        let moved = |o: [i32; 2], k: usize| {
            let e = hex.edges[k];
            [e.a, e.b, e.c - e.a * o[0] as f64 - e.b * o[1] as f64]
        };
        // Over the whole square: offsets always in, and offsets whose
        // status depends on the subdivision with the edges that decide it.
        let mut always = Vec::new();
        let mut open: Vec<([i32; 2], Vec<usize>)> = Vec::new();
        for oy in oy0..=oy1 {
            for ox in ox0..=ox1 {
                let o = [ox, oy];
                let mut crossing = Vec::new();
                let mut out = false;
                for k in 0..hex.edges.len() {
                    match side(moved(o, k), 0.0, 1.0, 0.0, 1.0) {
                        Side::In => {}
                        Side::Out => out = true,
                        Side::Crossed => crossing.push(k),
                    }
                }
                if out {
                    continue;
                }
                if crossing.is_empty() {
                    always.push(o);
                } else {
                    open.push((o, crossing));
                }
            }
        }
        // Each subdivision's key, `w` bytes at `(sy * n + sx) * w`: per open
        // offset, Out (`u8::MAX`), or In with the mask of its edges that
        // cross the subdivision (In with mask 0 is sure).
        let open_eqs: Vec<Vec<(usize, [f64; 3])>> = open
            .iter()
            .map(|(o, edges)| edges.iter().map(|&k| (k, moved(*o, k))).collect())
            .collect();
        let w = open.len().max(1);
        let step = 1.0 / n as f64;
        let mut keys = vec![0u8; n * n * w];
        keys.par_chunks_mut(n * w)
            .enumerate()
            .for_each(|(sy, row)| {
                for (j, eqs) in open_eqs.iter().enumerate() {
                    for &(k, e) in eqs {
                        let (out, crossed) = row_split(e, n, sy as f64 * step, step);
                        for sx in out {
                            row[sx * w + j] = u8::MAX;
                        }
                        for sx in crossed {
                            row[sx * w + j] |= 1 << k;
                        }
                    }
                }
            });
        let key = |i: usize| &keys[i * w..(i + 1) * w];
        // Region growing: 4-connected subdivisions with equal keys.
        let mut class_of = vec![u16::MAX; n * n];
        let mut class_keys: Vec<usize> = Vec::new();
        let mut stack = Vec::new();
        for seed in 0..n * n {
            if class_of[seed] != u16::MAX {
                continue;
            }
            let id = class_keys.len() as u16;
            class_keys.push(seed);
            class_of[seed] = id;
            stack.push(seed);
            while let Some(i) = stack.pop() {
                let (x, y) = (i % n, i / n);
                let near = [
                    (x > 0).then(|| i - 1),
                    (x + 1 < n).then(|| i + 1),
                    (y > 0).then(|| i - n),
                    (y + 1 < n).then(|| i + n),
                ];
                for j in near.into_iter().flatten() {
                    if class_of[j] == u16::MAX && key(j) == key(seed) {
                        class_of[j] = id;
                        stack.push(j);
                    }
                }
            }
        }
        // Each class's lists from its key; equal equation lists are shared.
        let mut eqs: Vec<[f64; 3]> = Vec::new();
        let mut eq_index: HashMap<Vec<[u64; 3]>, u32> = HashMap::new();
        let classes = class_keys
            .iter()
            .map(|&seed| {
                let mut sure = always.clone();
                let mut undecided = Vec::new();
                for ((o, _), &m) in open.iter().zip(key(seed)) {
                    if m == u8::MAX {
                        continue;
                    }
                    if m == 0 {
                        sure.push(*o);
                        continue;
                    }
                    let list: Vec<[f64; 3]> = (0..hex.edges.len())
                        .filter(|k| m >> k & 1 == 1)
                        .map(|k| moved(*o, k))
                        .collect();
                    let bits = list.iter().map(|e| e.map(f64::to_bits)).collect();
                    let first = *eq_index.entry(bits).or_insert_with(|| {
                        eqs.extend(&list);
                        (eqs.len() - list.len()) as u32
                    });
                    undecided.push(Undecided {
                        offset: *o,
                        first,
                        len: list.len() as u32,
                    });
                }
                Class { sure, undecided }
            })
            .collect();
        ProjectionTable {
            n,
            class_of,
            classes,
            eqs,
        }
    }

    /// The class of the subdivision holding `f` (position in the square,
    /// each coordinate in [0, 1)).
    pub fn class_at(&self, f: DVec2) -> &Class {
        let cell = |t: f64| ((t * self.n as f64) as usize).min(self.n - 1);
        &self.classes[self.class_of[cell(f.y) * self.n + cell(f.x)] as usize]
    }

    /// Whether an undecided pixel is covered by a voxel centred at `f`.
    pub fn decide(&self, u: &Undecided, f: DVec2) -> bool {
        self.eqs[u.first as usize..(u.first + u.len) as usize]
            .iter()
            .all(|e| e[0] * f.x + e[1] * f.y >= -e[2])
    }

    /// The pixel offsets (from `floor(C)`) a voxel centred at `floor(C) + f`
    /// covers: the class's sure pixels and the undecided ones that pass.
    pub fn project(&self, f: DVec2) -> Vec<[i32; 2]> {
        let c = self.class_at(f);
        let mut out = c.sure.clone();
        out.extend(
            c.undecided
                .iter()
                .filter(|u| self.decide(u, f))
                .map(|u| u.offset),
        );
        out
    }

    /// Smallest and largest offset of any listed pixel: `[min, max]`.
    pub fn extent(&self) -> [[i32; 2]; 2] {
        let mut e = [[i32::MAX; 2], [i32::MIN; 2]];
        for c in &self.classes {
            for o in c.sure.iter().chain(c.undecided.iter().map(|u| &u.offset)) {
                for a in 0..2 {
                    e[0][a] = e[0][a].min(o[a]);
                    e[1][a] = e[1][a].max(o[a]);
                }
            }
        }
        e
    }

    /// Share of subdivisions with at least one undecided pixel.
    pub fn undecided_share(&self) -> f64 {
        let busy = self
            .class_of
            .iter()
            .filter(|&&c| !self.classes[c as usize].undecided.is_empty())
            .count();
        busy as f64 / self.class_of.len() as f64
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn axis_view_at_one_pixel_per_voxel() {
        // Looking down w at one pixel per voxel: the hexagon is the unit
        // square, and a centre at f covers exactly pixel floor(C) (offset
        // 0, 0) when f = (0.5, 0.5), and also the pixels to the right and
        // below when f is at the square's corner 0 (edges included).
        let hex = Hexagon::of_steps([DVec2::X, DVec2::Y, DVec2::ZERO]);
        let t = ProjectionTable::new(&hex, 8);
        let mut p = t.project(DVec2::new(0.5, 0.5));
        p.sort();
        assert_eq!(p, vec![[0, 0], [0, 1], [1, 0], [1, 1]]);
        let mut p = t.project(DVec2::new(0.3, 0.7));
        p.sort();
        assert_eq!(p, vec![[0, 1]]);
    }

    #[test]
    fn classes_are_few_and_shared() {
        let d = glam::DVec3::new(1.0, 2.0, 2.0) / 3.0;
        let right = glam::DVec3::new(2.0, -2.0, 1.0) / 3.0;
        let down = d.cross(right);
        let s = 0.8;
        let hex = Hexagon::of_steps([0, 1, 2].map(|a| DVec2::new(right[a], down[a]) / s));
        let t = ProjectionTable::new(&hex, 64);
        assert!(t.classes.len() < 200, "{} classes", t.classes.len());
        let share = t.undecided_share();
        assert!(share > 0.0 && share < 0.25, "{share}");
        assert!(t
            .classes
            .iter()
            .all(|c| !c.sure.is_empty() || !c.undecided.is_empty()));
    }
}
