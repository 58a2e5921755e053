//! Volume traversal of the quantized-voxel path (Mora, Jessel & Caubet,
//! §3.3): blocks, then the voxels inside each, in an order that is back to
//! front (the paper's) or front to back along every axis. Along any one
//! ray the voxels it crosses then come in ray order, which is all a pixel
//! needs. Each voxel's centre is its block's origin plus integer steps
//! (additions only); its square and subdivision come from shifts of that
//! fixed-point position. Within a row of a block only the voxels the
//! classification flags as able to add anything are visited.
//!
//! A projected voxel draws its class's sure pixels, then its undecided
//! ones, a failed edge test masking its pixel rather than branching
//! around it (the tests' outcomes are not predictable). Its pixels are
//! indexed in its footprint window, checked once per voxel.
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
use super::grid::{Grid, Voxel, B, B3};
use super::view::{ClassRange, Footprint, ViewTables, Window, BAND, FRAC};
use super::{Method, Params, Stats};
use glam::{BVec4A, Vec4};
use scene::{Image, Mode, Traversal};
use std::cmp::Reverse;
use std::sync::Mutex;

/// Front to back, a pixel at this opacity is finished: what could still
/// arrive changes its colour by at most 2^-10.
pub const OPAQUE: f32 = 1.0 - 1.0 / 1024.0;

const MASK: i64 = (1 << FRAC) - 1;

/// A mode's per-voxel source and per-pixel operator. Pixels are `Vec4`
/// (red, green, blue, opacity) so the over operator is one four-lane
/// multiply and add; every lane is the same IEEE operation, in the same
/// order, as the scalar form.
trait Kind: Sync {
    /// What a voxel adds to the pixels it covers.
    type Src: Copy;
    /// Starting value of every channel of a pixel.
    const INIT: f32;
    /// Whether finished pixels and blocks are skipped (front to back).
    const OCCLUDES: bool;
    fn source(cl: &Classes, shade: &[[f32; 2]], v: usize, n: u16, g: u8) -> Option<Self::Src>;
    fn apply(dst: &mut Vec4, s: &Self::Src, w: f32);
    /// The image's colour of a finished pixel: its colour lanes, for the
    /// modes that composite colours.
    #[inline(always)]
    fn pixel(p: Vec4) -> [f64; 3] {
        [p.x, p.y, p.z].map(|x| x as f64)
    }
    /// `apply` when `on`, else leave `dst` as it is, without a branch: the
    /// undecided pixels of a projection class go through here.
    #[inline(always)]
    fn apply_if(dst: &mut Vec4, s: &Self::Src, w: f32, on: bool) {
        let mut new = *dst;
        Self::apply(&mut new, s, w);
        *dst = Vec4::select(BVec4A::splat(on), new, *dst);
    }
}

/// The voxel's shaded colour, with opacity lane 1.
#[inline(always)]
fn colour(cl: &Classes, shade: &[[f32; 2]], v: usize, n: u16) -> Vec4 {
    let [r, g, b] = cl.colour[v];
    let c = Vec4::new(r, g, b, 1.0);
    if !cl.shaded {
        return c;
    }
    let [d, s] = shade[n as usize];
    let mut c = (c * d + Vec4::splat(s)).min(Vec4::ONE);
    c.w = 1.0;
    c
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

/// A composited voxel: its colour `c` (opacity lane 1) and opacity term
/// `t`; projected back to front, also `pre = c·α` and `k = 1 − α`, the
/// per-voxel halves of the over operator.
#[derive(Clone, Copy)]
struct Coloured {
    c: Vec4,
    t: f32,
    pre: Vec4,
    k: f32,
}

/// Composite: the over operator; `SPLAT` takes opacity `1 − e^(−t·w)`.
struct Over<const F2B: bool, const SPLAT: bool>;

impl<const F2B: bool, const SPLAT: bool> Kind for Over<F2B, SPLAT> {
    type Src = Coloured;
    const INIT: f32 = 0.0;
    const OCCLUDES: bool = F2B;
    #[inline(always)]
    fn source(cl: &Classes, shade: &[[f32; 2]], v: usize, n: u16, g: u8) -> Option<Coloured> {
        let t = opacity(cl, v, g)?;
        let c = colour(cl, shade, v, n);
        // Projection takes α = t at every pixel: form the voxel's half of
        // the back-to-front operator once.
        let (pre, k) = if SPLAT || F2B {
            (Vec4::ZERO, 0.0)
        } else {
            (c * t, 1.0 - t)
        };
        Some(Coloured { c, t, pre, k })
    }
    #[inline(always)]
    fn apply(dst: &mut Vec4, s: &Coloured, w: f32) {
        let a = || if SPLAT { 1.0 - (-s.t * w).exp() } else { s.t };
        if F2B {
            // The opacity lane of `c` is 1: it accumulates k.
            if dst.w < OPAQUE {
                let k = (1.0 - dst.w) * a();
                *dst += k * s.c;
            }
        } else if SPLAT {
            // Back to front the accumulated opacity is never read (no
            // occlusion test; the image is the colour over black).
            let a = a();
            *dst = s.c * a + (1.0 - a) * *dst;
        } else {
            *dst = s.pre + s.k * *dst;
        }
    }
}

/// First-opaque: the colour of the front-most voxel whose opacity reaches
/// the threshold (`term` is the opacity itself).
struct First<const F2B: bool>;

impl<const F2B: bool> Kind for First<F2B> {
    type Src = Vec4;
    const INIT: f32 = 0.0;
    const OCCLUDES: bool = F2B;
    #[inline(always)]
    fn source(cl: &Classes, shade: &[[f32; 2]], v: usize, n: u16, g: u8) -> Option<Vec4> {
        let t = opacity(cl, v, g)?;
        (t >= cl.threshold).then(|| colour(cl, shade, v, n))
    }
    #[inline(always)]
    fn apply(dst: &mut Vec4, c: &Vec4, _w: f32) {
        if !F2B || dst.w == 0.0 {
            *dst = *c;
        }
    }
}

/// MIP.
struct Max;

impl Kind for Max {
    type Src = f32;
    const INIT: f32 = 0.0;
    const OCCLUDES: bool = false;
    #[inline(always)]
    fn source(cl: &Classes, _: &[[f32; 2]], v: usize, _: u16, _: u8) -> Option<f32> {
        let t = cl.term[v];
        (t > 0.0).then_some(t)
    }
    #[inline(always)]
    fn apply(dst: &mut Vec4, t: &f32, _w: f32) {
        dst.x = dst.x.max(*t);
    }
    #[inline(always)]
    fn pixel(p: Vec4) -> [f64; 3] {
        [p.x as f64; 3]
    }
}

/// MinIP.
struct Min;

impl Kind for Min {
    type Src = f32;
    const INIT: f32 = f32::INFINITY;
    const OCCLUDES: bool = false;
    #[inline(always)]
    fn source(cl: &Classes, _: &[[f32; 2]], v: usize, _: u16, _: u8) -> Option<f32> {
        Some(cl.term[v])
    }
    #[inline(always)]
    fn apply(dst: &mut Vec4, t: &f32, _w: f32) {
        dst.x = dst.x.min(*t);
    }
    #[inline(always)]
    fn pixel(p: Vec4) -> [f64; 3] {
        [if p.x.is_finite() { p.x as f64 } else { 0.0 }; 3]
    }
}

/// X-ray: the weighted sum; `SPLAT` weighs by the kernel.
struct Sum<const SPLAT: bool>;

impl<const SPLAT: bool> Kind for Sum<SPLAT> {
    type Src = f32;
    const INIT: f32 = 0.0;
    const OCCLUDES: bool = false;
    #[inline(always)]
    fn source(cl: &Classes, _: &[[f32; 2]], v: usize, _: u16, _: u8) -> Option<f32> {
        let t = cl.term[v];
        (t > 0.0).then_some(t)
    }
    #[inline(always)]
    fn apply(dst: &mut Vec4, t: &f32, w: f32) {
        dst.x += if SPLAT { t * w } else { *t };
    }
    #[inline(always)]
    fn pixel(p: Vec4) -> [f64; 3] {
        [(p.x as f64).min(1.0); 3]
    }
}

/// Counters of one band (each voxel and block counted in one band only).
#[derive(Default)]
struct Counts {
    inspected: u64,
    treated: u64,
    occluded: u64,
}

impl std::ops::AddAssign for Counts {
    fn add_assign(&mut self, c: Counts) {
        self.inspected += c.inspected;
        self.treated += c.treated;
        self.occluded += c.occluded;
    }
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
    let (w, h) = (view.geom.width, view.geom.height);
    let mut img = Image::black(w as u32, h as u32);
    let out = &mut img.rgb;
    let c = match (mode, f2b, splat) {
        (Mode::Composite, false, false) => run(Over::<false, false>, grid, view, cl, out),
        (Mode::Composite, true, false) => run(Over::<true, false>, grid, view, cl, out),
        (Mode::Composite, false, true) => run(Over::<false, true>, grid, view, cl, out),
        (Mode::Composite, true, true) => run(Over::<true, true>, grid, view, cl, out),
        (Mode::FirstOpaque, false, _) => run(First::<false>, grid, view, cl, out),
        (Mode::FirstOpaque, true, _) => run(First::<true>, grid, view, cl, out),
        (Mode::Mip, ..) => run(Max, grid, view, cl, out),
        (Mode::Minip, ..) => run(Min, grid, view, cl, out),
        (Mode::Xray, _, false) => run(Sum::<false>, grid, view, cl, out),
        (Mode::Xray, _, true) => run(Sum::<true>, grid, view, cl, out),
    };
    let stats = Stats {
        voxels: grid.dims.iter().product::<usize>() as u64,
        blocks: cl.live.len() as u64,
        blocks_live: cl.live.iter().filter(|&&l| l).count() as u64,
        inspected: c.inspected,
        treated: c.treated,
        occluded: c.occluded,
        classes: view.classes,
        entries: view.entries,
    };
    (img, stats)
}

fn run<K: Kind>(
    _: K,
    grid: &Grid,
    view: &ViewTables,
    cl: &Classes,
    out: &mut [[f64; 3]],
) -> Counts {
    match &view.footprint {
        Footprint::Projection {
            table,
            ranges,
            sure,
            undecided,
        } => {
            let fp = Projected {
                window: view.window,
                class_of: &table.class_of,
                ranges,
                sure,
                undecided,
                eqs: &table.eqs,
            };
            bands::<K, _>(&fp, grid, view, cl, out)
        }
        Footprint::Splat { table, offsets } => {
            let fp = Splatted {
                window: view.window,
                start: &table.start,
                offsets,
                weights: &table.weights,
            };
            bands::<K, _>(&fp, grid, view, cl, out)
        }
    }
}

/// Render every band into its rows of `out`. The bands' work differs
/// widely (a volume covers some of the image's rows only), so they are
/// taken heaviest first (by live blocks), each by the next idle thread:
/// no thread is left with a heavy band while the others wait. The order
/// does not change a pixel.
fn bands<K: Kind, F: Draw>(
    fp: &F,
    grid: &Grid,
    view: &ViewTables,
    cl: &Classes,
    out: &mut [[f64; 3]],
) -> Counts {
    let live = |band: usize| {
        view.bands[band]
            .iter()
            .filter(|&&b| cl.live[b as usize])
            .count()
    };
    let mut jobs: Vec<_> = out.chunks_mut(BAND * view.geom.width).enumerate().collect();
    jobs.sort_by_key(|&(band, _)| Reverse(live(band)));
    let queue = Mutex::new(jobs.into_iter());
    let total = Mutex::new(Counts::default());
    rayon::scope(|s| {
        for _ in 0..rayon::current_num_threads() {
            s.spawn(|_| loop {
                let job = queue.lock().unwrap().next();
                let Some((band, rows)) = job else { break };
                let c = render_band::<K, F>(fp, grid, view, cl, band, rows);
                *total.lock().unwrap() += c;
            });
        }
    });
    total.into_inner().unwrap()
}

/// A footprint table: draws one voxel whose centre lies in subdivision
/// `cell` at fixed-point position `(fx, fy)` in its square, the square's
/// top-left pixel at `base` in the buffer.
trait Draw: Sync {
    fn draw<K: Kind>(
        &self,
        buf: &mut [Vec4],
        cell: usize,
        fx: u64,
        fy: u64,
        base: isize,
        src: &K::Src,
    );
}

/// §2.2: the class's sure pixels, and the undecided ones that pass their
/// edge tests (Eq. 5).
struct Projected<'a> {
    window: Window,
    class_of: &'a [u16],
    ranges: &'a [ClassRange],
    sure: &'a [u32],
    undecided: &'a [(u32, u32, u32)],
    eqs: &'a [[f64; 3]],
}

impl Draw for Projected<'_> {
    #[inline(always)]
    fn draw<K: Kind>(
        &self,
        buf: &mut [Vec4],
        cell: usize,
        fx: u64,
        fy: u64,
        base: isize,
        src: &K::Src,
    ) {
        let win = self.window.at(buf, base);
        let r = self.ranges[self.class_of[cell] as usize];
        for &o in &self.sure[r.sure as usize..(r.sure + r.sure_len) as usize] {
            // SAFETY: every offset is below the window's length
            // (asserted where the view tables are built).
            K::apply(unsafe { win.get_unchecked_mut(o as usize) }, src, 1.0);
        }
        if r.und_len == 0 {
            return;
        }
        let scale = 1.0 / (1u64 << FRAC) as f64;
        let (x, y) = (fx as f64 * scale, fy as f64 * scale);
        for &(o, first, len) in &self.undecided[r.und as usize..(r.und + r.und_len) as usize] {
            let mut inside = true;
            for e in &self.eqs[first as usize..(first + len) as usize] {
                inside &= e[0] * x + e[1] * y >= -e[2];
            }
            // SAFETY: as for the sure pixels.
            K::apply_if(
                unsafe { win.get_unchecked_mut(o as usize) },
                src,
                1.0,
                inside,
            );
        }
    }
}

/// §2.3: the subdivision's pixels with their kernel weights.
struct Splatted<'a> {
    window: Window,
    start: &'a [u32],
    offsets: &'a [u32],
    weights: &'a [f32],
}

impl Draw for Splatted<'_> {
    #[inline(always)]
    fn draw<K: Kind>(
        &self,
        buf: &mut [Vec4],
        cell: usize,
        _: u64,
        _: u64,
        base: isize,
        src: &K::Src,
    ) {
        let win = self.window.at(buf, base);
        let (s, t) = (self.start[cell] as usize, self.start[cell + 1] as usize);
        for (&o, &w) in self.offsets[s..t].iter().zip(&self.weights[s..t]) {
            // SAFETY: every offset is below the window's length (asserted
            // where the view tables are built).
            K::apply(unsafe { win.get_unchecked_mut(o as usize) }, src, w);
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

/// The voxels `lo..hi` of a block's row, as bits (`0 <= lo <= hi <= B`,
/// as `span` gives them).
fn row_bits(lo: i64, hi: i64) -> u8 {
    ((1u32 << hi) - (1u32 << lo)) as u8
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
    out: &mut [[f64; 3]],
) -> Counts {
    let (w, h) = (view.geom.width, view.geom.height);
    let (y0, y1) = (band * BAND, ((band + 1) * BAND).min(h));
    let (m, stride) = (view.margin, view.stride);
    let mut buf = vec![Vec4::splat(K::INIT); (y1 - y0 + 2 * m) * stride];
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
        // A block whose footprints stay within the image's columns needs
        // no per-row range across them, and one within the band's rows
        // (and so its home rows) none down them.
        let cols_in = bx0 >= 0 && bx1 < w as i32;
        let rows_in = by0 >= y0 as i32 && by1 < y1 as i32;
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
                let all = (0, i_hi as i64);
                let (ax, bx) = match cols_in {
                    true => all,
                    false => span(rx, sx, cx_lo, cx_hi, i_hi as i64),
                };
                let ((ay, by), (h0, h1)) = match rows_in {
                    true => (all, all),
                    false => (
                        span(ry, sy, cy_lo, cy_hi, i_hi as i64),
                        span(ry, sy, home_lo, home_hi, i_hi as i64),
                    ),
                };
                let (i0, i1) = (ax.max(ay).max(i_lo as i64), bx.min(by));
                if i0 >= i1 {
                    continue;
                }
                counts.inspected += (i1.min(h1) - i0.max(h0)).max(0) as u64;
                // The row's voxels that can add anything, within i0..i1;
                // those in its home rows count as treated unless their
                // source turns out empty.
                let mut bits = cl.rows[b * B * B + k * B + j] & row_bits(i0, i1);
                if bits == 0 {
                    continue;
                }
                let home = row_bits(h0, h1);
                counts.treated += (bits & home).count_ones() as u64;
                let row = b * B3 + (k * B + j) * B;
                let voxels: &[Voxel; B] = grid.voxels[row..row + B].try_into().unwrap();
                let gmag: &[u8; B] = grid.gmag[row..row + B].try_into().unwrap();
                while bits != 0 {
                    let i = if view.descending[0] {
                        7 - bits.leading_zeros() as usize
                    } else {
                        bits.trailing_zeros() as usize
                    } & (B - 1);
                    bits ^= 1 << i;
                    let Voxel { value, normal } = voxels[i];
                    let Some(src) = K::source(cl, &view.shade, value as usize, normal, gmag[i])
                    else {
                        counts.treated -= (home >> i & 1) as u64;
                        continue;
                    };
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
    for (r, row) in out.chunks_mut(w).enumerate() {
        let s = (r + m) * stride + m;
        for (o, p) in row.iter_mut().zip(&buf[s..s + w]) {
            *o = K::pixel(*p);
        }
    }
    counts
}

/// Whether every pixel of the box `[x0, x1, y0, y1]` (inclusive, image
/// coordinates, rows within the band) is finished.
fn finished(
    buf: &[Vec4],
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
            if buf[r + x as usize].w < OPAQUE {
                return false;
            }
        }
    }
    true
}
