//! Volume traversal of the quantized-voxel path (Mora, Jessel & Caubet,
//! §3.3): blocks, then the voxels inside each, in an order that is back to
//! front (the paper's) or front to back along every axis. Along any one
//! ray the voxels it crosses then come in ray order, which is all a pixel
//! needs. Each voxel's centre is its block's origin plus integer steps
//! (additions only); its square and subdivision come from shifts of that
//! fixed-point position.
//!
//! The image is cut into bands of `BAND` rows, rendered in parallel. A band
//! visits the blocks that reach it, in traversal order, and draws every
//! voxel that reaches it whole into a buffer with a margin as wide as any
//! footprint, so no pixel is clipped; only the band's own rows are kept.
//! A pixel's result therefore does not depend on the split into bands or
//! on the thread count.
//!
//! Front to back, a pixel whose opacity has reached `OPAQUE` takes nothing
//! more (early ray termination), and a block all of whose reachable pixels
//! in the band are opaque is skipped whole.

use super::classify::Classes;
use super::grid::{Grid, B, B3};
use super::view::{Footprint, ViewTables, BAND, FRAC};
use super::{Method, Params, Stats};
use rayon::prelude::*;
use scene::{Image, Mode, Traversal};

/// Front to back, a pixel at this opacity is finished: what could still
/// arrive changes its colour by at most 2^-10.
pub const OPAQUE: f32 = 1.0 - 1.0 / 1024.0;

const MASK: i64 = (1 << FRAC) - 1;

/// What a voxel adds to the pixels it covers: its colour and its term
/// (`classify`).
#[derive(Debug, Clone, Copy)]
struct Src {
    c: [f32; 3],
    t: f32,
}

/// A mode's per-voxel source and per-pixel operator.
trait Kind: Sync {
    /// Starting value of every channel of a pixel.
    const INIT: f32;
    /// Whether finished pixels and blocks are skipped (front to back).
    const OCCLUDES: bool;
    fn source(cl: &Classes, shade: &[[f32; 2]], v: usize, n: u16, g: u8) -> Option<Src>;
    fn apply(dst: &mut [f32; 4], s: &Src, w: f32);
}

/// The voxel's shaded colour.
#[inline(always)]
fn colour(cl: &Classes, shade: &[[f32; 2]], v: usize, n: u16) -> [f32; 3] {
    let c = cl.colour[v];
    if !cl.shaded {
        return c;
    }
    let [d, s] = shade[n as usize];
    c.map(|x| (x * d + s).min(1.0))
}

/// Composite and first-opaque: the voxel's opacity term, or None when it
/// adds nothing. (Boundary voxels never get here where gradients are
/// needed: the row ranges leave them out.)
#[inline(always)]
fn opacity(cl: &Classes, v: usize, g: u8) -> Option<f32> {
    let t = match &cl.gradient {
        None => cl.term[v],
        Some(gf) if cl.alpha[v] > 0.0 => {
            cl.shape(cl.alpha[v] as f64 * gf[g as usize] as f64) as f32
        }
        Some(_) => 0.0,
    };
    (t > 0.0).then_some(t)
}

/// Composite: the over operator; `SPLAT` takes opacity `1 − e^(−t·w)`.
struct Over<const F2B: bool, const SPLAT: bool>;

impl<const F2B: bool, const SPLAT: bool> Kind for Over<F2B, SPLAT> {
    const INIT: f32 = 0.0;
    const OCCLUDES: bool = F2B;
    #[inline(always)]
    fn source(cl: &Classes, shade: &[[f32; 2]], v: usize, n: u16, g: u8) -> Option<Src> {
        let t = opacity(cl, v, g)?;
        Some(Src {
            c: colour(cl, shade, v, n),
            t,
        })
    }
    #[inline(always)]
    fn apply(dst: &mut [f32; 4], s: &Src, w: f32) {
        let a = || if SPLAT { 1.0 - (-s.t * w).exp() } else { s.t };
        if F2B {
            if dst[3] < OPAQUE {
                let a = a();
                let k = (1.0 - dst[3]) * a;
                for (d, c) in dst.iter_mut().zip(s.c) {
                    *d += k * c;
                }
                dst[3] += k;
            }
        } else {
            // Back to front the accumulated opacity is never read (no
            // occlusion test; the image is the colour over black), so
            // only the colour channels are composited.
            let a = a();
            let k = 1.0 - a;
            for (d, c) in dst[..3].iter_mut().zip(s.c) {
                *d = c * a + k * *d;
            }
        }
    }
}

/// First-opaque: the colour of the front-most voxel whose opacity reaches
/// the threshold (`term` is the opacity itself).
struct First<const F2B: bool>;

impl<const F2B: bool> Kind for First<F2B> {
    const INIT: f32 = 0.0;
    const OCCLUDES: bool = F2B;
    #[inline(always)]
    fn source(cl: &Classes, shade: &[[f32; 2]], v: usize, n: u16, g: u8) -> Option<Src> {
        let t = opacity(cl, v, g)?;
        (t >= cl.threshold).then(|| Src {
            c: colour(cl, shade, v, n),
            t,
        })
    }
    #[inline(always)]
    fn apply(dst: &mut [f32; 4], s: &Src, _w: f32) {
        if !F2B || dst[3] == 0.0 {
            *dst = [s.c[0], s.c[1], s.c[2], 1.0];
        }
    }
}

/// MIP.
struct Max;

impl Kind for Max {
    const INIT: f32 = 0.0;
    const OCCLUDES: bool = false;
    #[inline(always)]
    fn source(cl: &Classes, _: &[[f32; 2]], v: usize, _: u16, _: u8) -> Option<Src> {
        let t = cl.term[v];
        (t > 0.0).then_some(Src { c: [0.0; 3], t })
    }
    #[inline(always)]
    fn apply(dst: &mut [f32; 4], s: &Src, _w: f32) {
        dst[0] = dst[0].max(s.t);
    }
}

/// MinIP.
struct Min;

impl Kind for Min {
    const INIT: f32 = f32::INFINITY;
    const OCCLUDES: bool = false;
    #[inline(always)]
    fn source(cl: &Classes, _: &[[f32; 2]], v: usize, _: u16, _: u8) -> Option<Src> {
        Some(Src {
            c: [0.0; 3],
            t: cl.term[v],
        })
    }
    #[inline(always)]
    fn apply(dst: &mut [f32; 4], s: &Src, _w: f32) {
        dst[0] = dst[0].min(s.t);
    }
}

/// X-ray: the weighted sum; `SPLAT` weighs by the kernel.
struct Sum<const SPLAT: bool>;

impl<const SPLAT: bool> Kind for Sum<SPLAT> {
    const INIT: f32 = 0.0;
    const OCCLUDES: bool = false;
    #[inline(always)]
    fn source(cl: &Classes, _: &[[f32; 2]], v: usize, _: u16, _: u8) -> Option<Src> {
        let t = cl.term[v];
        (t > 0.0).then_some(Src { c: [0.0; 3], t })
    }
    #[inline(always)]
    fn apply(dst: &mut [f32; 4], s: &Src, w: f32) {
        dst[0] += if SPLAT { s.t * w } else { s.t };
    }
}

/// Counters of one band (each voxel and block counted in one band only).
#[derive(Default)]
struct Counts {
    inspected: u64,
    treated: u64,
    occluded: u64,
}

/// Render the frame: the image and the counters.
pub fn render(
    mode: Mode,
    grid: &Grid,
    view: &ViewTables,
    cl: &Classes,
    params: &Params,
) -> (Image, Stats) {
    let f2b = params.order == Traversal::FrontToBack;
    let splat = params.method == Method::Splat;
    let bands = match (mode, f2b, splat) {
        (Mode::Composite, false, false) => run(Over::<false, false>, grid, view, cl),
        (Mode::Composite, true, false) => run(Over::<true, false>, grid, view, cl),
        (Mode::Composite, false, true) => run(Over::<false, true>, grid, view, cl),
        (Mode::Composite, true, true) => run(Over::<true, true>, grid, view, cl),
        (Mode::FirstOpaque, false, _) => run(First::<false>, grid, view, cl),
        (Mode::FirstOpaque, true, _) => run(First::<true>, grid, view, cl),
        (Mode::Mip, ..) => run(Max, grid, view, cl),
        (Mode::Minip, ..) => run(Min, grid, view, cl),
        (Mode::Xray, _, false) => run(Sum::<false>, grid, view, cl),
        (Mode::Xray, _, true) => run(Sum::<true>, grid, view, cl),
    };
    let (w, h) = (view.geom.width, view.geom.height);
    let mut img = Image::black(w as u32, h as u32);
    let mut stats = Stats {
        voxels: grid.dims.iter().product::<usize>() as u64,
        blocks: cl.live.len() as u64,
        blocks_live: cl.live.iter().filter(|&&l| l).count() as u64,
        classes: view.classes,
        entries: view.entries,
        ..Stats::default()
    };
    for (k, (px, c)) in bands.into_iter().enumerate() {
        stats.inspected += c.inspected;
        stats.treated += c.treated;
        stats.occluded += c.occluded;
        let out = &mut img.rgb[k * BAND * w..(k * BAND * w + px.len())];
        for (o, p) in out.iter_mut().zip(px) {
            *o = match mode {
                Mode::Composite | Mode::FirstOpaque => [p[0], p[1], p[2]].map(|x| x as f64),
                Mode::Mip => [p[0] as f64; 3],
                Mode::Minip => [if p[0].is_finite() { p[0] as f64 } else { 0.0 }; 3],
                Mode::Xray => [(p[0] as f64).min(1.0); 3],
            };
        }
    }
    (img, stats)
}

fn run<K: Kind>(
    _: K,
    grid: &Grid,
    view: &ViewTables,
    cl: &Classes,
) -> Vec<(Vec<[f32; 4]>, Counts)> {
    match &view.footprint {
        Footprint::Projection {
            table,
            sure_start,
            sure,
            und_start,
            undecided,
        } => {
            let fp = Projected {
                class_of: &table.class_of,
                sure_start,
                sure,
                und_start,
                undecided,
                eqs: &table.eqs,
            };
            bands::<K, _>(&fp, grid, view, cl)
        }
        Footprint::Splat { table, offsets } => {
            let fp = Splatted {
                start: &table.start,
                offsets,
                weights: &table.weights,
            };
            bands::<K, _>(&fp, grid, view, cl)
        }
    }
}

fn bands<K: Kind, F: Draw>(
    fp: &F,
    grid: &Grid,
    view: &ViewTables,
    cl: &Classes,
) -> Vec<(Vec<[f32; 4]>, Counts)> {
    (0..view.bands.len())
        .into_par_iter()
        .map(|band| render_band::<K, F>(fp, grid, view, cl, band))
        .collect()
}

/// A footprint table: draws one voxel whose centre lies in subdivision
/// `cell` at fixed-point position `(fx, fy)` in its square, the square's
/// top-left pixel at `base` in the buffer.
trait Draw: Sync {
    fn draw<K: Kind>(
        &self,
        buf: &mut [[f32; 4]],
        cell: usize,
        fx: u64,
        fy: u64,
        base: isize,
        src: &Src,
    );
}

/// §2.2: the class's sure pixels, and the undecided ones that pass their
/// edge tests (Eq. 5).
struct Projected<'a> {
    class_of: &'a [u16],
    sure_start: &'a [u32],
    sure: &'a [isize],
    und_start: &'a [u32],
    undecided: &'a [(isize, u32, u32)],
    eqs: &'a [[f64; 3]],
}

impl Draw for Projected<'_> {
    #[inline(always)]
    fn draw<K: Kind>(
        &self,
        buf: &mut [[f32; 4]],
        cell: usize,
        fx: u64,
        fy: u64,
        base: isize,
        src: &Src,
    ) {
        let c = self.class_of[cell] as usize;
        for &o in &self.sure[self.sure_start[c] as usize..self.sure_start[c + 1] as usize] {
            K::apply(&mut buf[(base + o) as usize], src, 1.0);
        }
        let und = &self.undecided[self.und_start[c] as usize..self.und_start[c + 1] as usize];
        if und.is_empty() {
            return;
        }
        let scale = 1.0 / (1u64 << FRAC) as f64;
        let (x, y) = (fx as f64 * scale, fy as f64 * scale);
        for &(o, first, len) in und {
            let inside = self.eqs[first as usize..(first + len) as usize]
                .iter()
                .all(|e| e[0] * x + e[1] * y >= -e[2]);
            if inside {
                K::apply(&mut buf[(base + o) as usize], src, 1.0);
            }
        }
    }
}

/// §2.3: the subdivision's pixels with their kernel weights.
struct Splatted<'a> {
    start: &'a [u32],
    offsets: &'a [isize],
    weights: &'a [f32],
}

impl Draw for Splatted<'_> {
    #[inline(always)]
    fn draw<K: Kind>(
        &self,
        buf: &mut [[f32; 4]],
        cell: usize,
        _: u64,
        _: u64,
        base: isize,
        src: &Src,
    ) {
        let (s, t) = (self.start[cell] as usize, self.start[cell + 1] as usize);
        for (&o, &w) in self.offsets[s..t].iter().zip(&self.weights[s..t]) {
            K::apply(&mut buf[(base + o) as usize], src, w);
        }
    }
}

/// The indices `i` in `[0, n)` with `lo <= a + i·d < hi`, as a range.
fn span(a: i64, d: i64, lo: i64, hi: i64, n: i64) -> (i64, i64) {
    let (i0, i1) = match d.signum() {
        0 => return if lo <= a && a < hi { (0, n) } else { (0, 0) },
        1 => (ceil_div(lo - a, d), ceil_div(hi - a, d)),
        _ => ((a - hi).div_euclid(-d) + 1, (a - lo).div_euclid(-d) + 1),
    };
    (i0.clamp(0, n), i1.clamp(0, n))
}

fn ceil_div(a: i64, d: i64) -> i64 {
    -(-a).div_euclid(d)
}

fn render_band<K: Kind, F: Draw>(
    fp: &F,
    grid: &Grid,
    view: &ViewTables,
    cl: &Classes,
    band: usize,
) -> (Vec<[f32; 4]>, Counts) {
    let (w, h) = (view.geom.width, view.geom.height);
    let (y0, y1) = (band * BAND, ((band + 1) * BAND).min(h));
    let (m, stride) = (view.margin, view.stride);
    let mut buf = vec![[K::INIT; 4]; (y1 - y0 + 2 * m) * stride];
    let [[ex0, ey0], [ex1, ey1]] = view.ext.map(|e| e.map(|x| x as i64));
    let one = 1i64 << FRAC;
    // Centres whose footprint reaches the band's rows and the image's
    // columns, and those of the band's own rows (where a voxel is
    // counted; rows beyond the image count in the nearest band).
    let (cy_lo, cy_hi) = ((y0 as i64 - ey1) * one, (y1 as i64 - ey0) * one);
    let (cx_lo, cx_hi) = (-ex1 * one, (w as i64 - ex0) * one);
    let home_lo = if band == 0 {
        i64::MIN / 2
    } else {
        y0 as i64 * one
    };
    let home_hi = if y1 == h {
        i64::MAX / 2
    } else {
        y1 as i64 * one
    };
    let n = view.n as u64;
    let steps = view.steps;
    let dims = grid.dims;
    let mut counts = Counts::default();
    for &b in &view.bands[band] {
        let b = b as usize;
        if !cl.live[b] {
            continue;
        }
        let [bx0, bx1, by0, by1] = view.block_box[b];
        if K::OCCLUDES
            && finished(
                &buf,
                [bx0, bx1, by0.max(y0 as i32), by1.min(y1 as i32 - 1)],
                y0,
                m,
                stride,
                w,
            )
        {
            let centre = ((by0 + by1) / 2).clamp(0, h as i32 - 1) as usize;
            if centre / BAND == band {
                counts.occluded += grid.voxels(b);
            }
            continue;
        }
        let e = grid.extent(b);
        let first = grid.first(b);
        // Where gradients are needed the boundary voxels are transparent:
        // cut them from the ranges.
        let cut = |a: usize| -> (usize, usize) {
            if !cl.inner {
                return (0, e[a]);
            }
            (
                (first[a] == 0) as usize,
                e[a] - (first[a] + e[a] == dims[a]) as usize,
            )
        };
        let ((i_lo, i_hi), (j_lo, j_hi), (k_lo, k_hi)) = (cut(0), cut(1), cut(2));
        let [ox, oy] = view.block_origin[b];
        // A block whose footprints stay within the band's rows, its home
        // rows and the image's columns needs no per-row ranges.
        let whole = by0 >= y0 as i32 && by1 < y1 as i32 && bx0 >= 0 && bx1 < w as i32;
        // The t-th index of lo..hi in the traversal's direction along a.
        let at = |a: usize, lo: usize, hi: usize, t: usize| {
            if view.descending[a] {
                hi - 1 - t
            } else {
                lo + t
            }
        };
        for tk in 0..k_hi.saturating_sub(k_lo) {
            let k = at(2, k_lo, k_hi, tk);
            for tj in 0..j_hi.saturating_sub(j_lo) {
                let j = at(1, j_lo, j_hi, tj);
                let rx = ox + k as i64 * steps[2][0] + j as i64 * steps[1][0];
                let ry = oy + k as i64 * steps[2][1] + j as i64 * steps[1][1];
                // The voxels of this row whose footprint reaches the band,
                // and those whose centre lies in its home rows.
                let [sx, sy] = steps[0];
                let (i0, i1, h0, h1) = if whole {
                    (i_lo as i64, i_hi as i64, i_lo as i64, i_hi as i64)
                } else {
                    let (ax, bx) = span(rx, sx, cx_lo, cx_hi, i_hi as i64);
                    let (ay, by) = span(ry, sy, cy_lo, cy_hi, i_hi as i64);
                    let (h0, h1) = span(ry, sy, home_lo, home_hi, i_hi as i64);
                    (ax.max(ay).max(i_lo as i64), bx.min(by), h0, h1)
                };
                if i0 >= i1 {
                    continue;
                }
                counts.inspected += (i1.min(h1) - i0.max(h0)).max(0) as u64;
                let row = b * B3 + (k * B + j) * B;
                for ti in 0..(i1 - i0) as usize {
                    let i = at(0, i0 as usize, i1 as usize, ti);
                    let idx = row + i;
                    let Some(src) = K::source(
                        cl,
                        &view.shade,
                        grid.values[idx] as usize,
                        grid.normals[idx],
                        grid.gmag[idx],
                    ) else {
                        continue;
                    };
                    counts.treated += ((i as i64) >= h0 && (i as i64) < h1) as u64;
                    let cx = rx + i as i64 * sx;
                    let cy = ry + i as i64 * sy;
                    let (px, py) = (cx >> FRAC, cy >> FRAC);
                    let (fx, fy) = ((cx & MASK) as u64, (cy & MASK) as u64);
                    let cell = ((fy * n) >> FRAC) as usize * view.n + ((fx * n) >> FRAC) as usize;
                    let base =
                        ((py - y0 as i64 + m as i64) * stride as i64 + px + m as i64) as isize;
                    fp.draw::<K>(&mut buf, cell, fx, fy, base, &src);
                }
            }
        }
    }
    let mut out = Vec::with_capacity((y1 - y0) * w);
    for r in 0..y1 - y0 {
        let s = (r + m) * stride + m;
        out.extend_from_slice(&buf[s..s + w]);
    }
    (out, counts)
}

/// Whether every pixel of the box `[x0, x1, y0, y1]` (inclusive, image
/// coordinates, rows within the band) is finished.
fn finished(
    buf: &[[f32; 4]],
    [x0, x1, y0, y1]: [i32; 4],
    band_y0: usize,
    m: usize,
    stride: usize,
    w: usize,
) -> bool {
    let (x0, x1) = (x0.max(0), x1.min(w as i32 - 1));
    for y in y0..=y1 {
        let r = (y as usize - band_y0 + m) * stride + m;
        for x in x0..=x1 {
            if buf[r + x as usize][3] < OPAQUE {
                return false;
            }
        }
    }
    true
}
