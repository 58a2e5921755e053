//! The Cube-4L golden model: ray-slice-sweeping (§2) through the whole
//! pipeline CFB -> ABC gradient -> shader/classifier -> bilinear unit ->
//! compositor, one slice at a time, producing the base-plane image of each
//! sweep (the shader and the compositing unit are the kit's, in `common`). The slice is processed in raster order; the hardware's skewed
//! order (`cfb::CfbStream`) visits the same voxels with the same control, and
//! the result of a slice does not depend on the order within it.
//!
//! Software shortcuts that cannot change a bit of the result: a voxel whose
//! opacity row is zero skips gradient and shading (its composite is the
//! identity), and front to back a cell whose gathered opacity is already
//! full skips the voxel (`mul(0, x) = 0`), and a voxel that leaves an
//! empty cell empty, with nothing but empty cells around it in the previous
//! slice, is skipped whole (`render_sweep`).

pub mod caveat;
pub mod cfb;
pub mod compositor;
pub mod dram;
pub mod frame;
pub mod gradient;
pub mod plan;
pub mod regs;
pub mod warp;

pub use frame::{BasePlane, Frame, Stats};

use crate::common::compositor::{composite, reset_value};
use crate::common::plan::Order;
use crate::common::shader::Shader;
use compositor::{gather, gather_row};
use gradient::central_difference;
use plan::{Control, Face, Plan, Rays, Sweep};
use rayon::prelude::*;
use scene::volume::{InOrder, Voxels};
use scene::{Camera, Mode, Scene};

/// A pixel leaving on ER: base-plane address, value and face.
type PixelOut = ([usize; 2], [u32; 4], Face);

/// Columns `lo..hi` of a compositing-buffer row that may hold something
/// other than the reset value (`lo >= hi`: the whole row is reset).
#[derive(Debug, Clone, Copy)]
struct Span {
    lo: usize,
    hi: usize,
}

const EMPTY: Span = Span {
    lo: usize::MAX,
    hi: 0,
};

impl Span {
    /// Column `x` alone.
    fn column(x: usize) -> Span {
        Span { lo: x, hi: x + 1 }
    }

    fn union(self, o: Span) -> Span {
        Span {
            lo: self.lo.min(o.lo),
            hi: self.hi.max(o.hi),
        }
    }
}

/// The columns of `row` within `within` that hold something other than
/// the reset value, as a span from the first to the last (`within` may be
/// empty, its start past its end).
fn nonreset(row: &[[u32; 4]], within: std::ops::Range<usize>, reset: [u32; 4]) -> Span {
    if within.is_empty() {
        return EMPTY;
    }
    let cells = &row[within.clone()];
    match cells.iter().position(|c| *c != reset) {
        Some(i) => Span {
            lo: within.start + i,
            hi: within.end - cells.iter().rev().position(|c| *c != reset).unwrap_or(0),
        },
        None => EMPTY,
    }
}

/// Whether compositing voxel `v` leaves every cell as it is, whatever its
/// control bits: composite, first-opaque and X-ray, its opacity row is zero
/// (`Shader::is_zero`: a zero sample, `acc + mul(M - a, 0) = acc` front to
/// back, `0 + mul(M, acc) = acc` back to front, `acc + 0` in X-ray); MIP, it
/// is 0 (`max(acc, 0)`); MinIP, it is the largest voxel (`min(acc, max)`).
fn is_identity(shader: &Shader, v: u32) -> bool {
    match shader.mode {
        Mode::Mip => v == 0,
        Mode::Minip => v == crate::fixed::max_of(shader.voxel_bits),
        _ => shader.is_zero(v),
    }
}

/// Render one sweep to its base plane.
///
/// A voxel whose composite is the identity ([`is_identity`]) inside
/// the slice (no ER there) makes its cell what the bilinear unit gathers,
/// with no control bits, shading or compositing. The empty-space skip: when
/// the cell's 3x3 neighbourhood in the previous slice is all reset, that is
/// the reset value exactly (`lerp_frac(a, a, w) = a`; the bilinear unit reads
/// inside the 3x3 since |dx|, |dy| <= 1), and the gather is skipped too.
pub fn render_sweep(vol: &dyn Voxels, sweep: &Sweep, shader: &Shader) -> (BasePlane, Stats) {
    let [nx, ny, _] = sweep.dims;
    let frac = sweep.frac;
    // A sweep whose rows run across the dataset's slices reads a copy of
    // the volume in its own order (`Voxels::in_order`): at a stride of a
    // whole slice every voxel of a row falls in one cache set. Other
    // sweeps read the volume as it is (a copy costs more than it saves).
    let own = vol.volume();
    let ds = [1, own.dims[0], own.dims[0] * own.dims[1]];
    let (copy, strides) = match sweep.perm[0] {
        2 => (vol.in_order(sweep.perm), [1, nx, nx * ny]),
        _ => (InOrder::Own(&own.data), sweep.perm.map(|a| ds[a])),
    };
    let voxels: &[u16] = &copy;
    let reset = reset_value(shader.mode, shader.voxel_bits);
    let mut base = BasePlane::new(sweep);
    let mut prev = vec![reset; nx * ny];
    let mut next = vec![reset; nx * ny];
    let mut prev_span = vec![EMPTY; ny];
    let mut next_span = vec![EMPTY; ny];
    let mut stats = Stats::default();
    let parallel = match sweep.rays {
        Rays::Parallel { dx, dy } => Some((dx, dy)),
        Rays::Perspective { .. } => None,
    };
    // Front to back, a full opacity hides everything behind it.
    let full = crate::fixed::max_of(shader.rgba_bits);
    let hides = sweep.order == Order::FrontToBack
        && matches!(shader.mode, Mode::Composite | Mode::FirstOpaque);
    let opaque_front = |acc: [u32; 4]| hides && acc[3] == full;
    let identity: Vec<bool> = (0..=crate::fixed::max_of(shader.voxel_bits))
        .map(|v| is_identity(shader, v))
        .collect();
    for z in sweep.z0..=sweep.z1 {
        let first = z == sweep.z0;
        let last = z == sweep.z1;
        let spans = &prev_span;
        let outputs: Vec<(Vec<PixelOut>, Stats)> = next
            .par_chunks_mut(nx)
            .zip(next_span.par_iter_mut())
            .enumerate()
            .map(|(y, (row, span))| {
                let mut out = Vec::new();
                let mut st = Stats::default();
                // Columns whose 3x3 neighbourhood in the previous slice
                // may hold something other than reset.
                let near = spans[y.saturating_sub(1)..(y + 2).min(ny)]
                    .iter()
                    .fold(EMPTY, |a, &s| a.union(s));
                let busy = near.lo.saturating_sub(1)..near.hi.saturating_add(1);
                let inner_row = !last && y > 0 && y + 1 < ny;
                st.voxels += nx as u64;
                let row_at = y * strides[1] + z * strides[2];
                // The whole datapath for voxel `x` whose gathered value is
                // `acc` (the caller counts an opaque `acc` as terminated):
                // control bits, shading, compositing and the pixel on ER.
                let datapath = |x: usize,
                                c: &Control,
                                acc: [u32; 4],
                                st: &mut Stats,
                                out: &mut Vec<PixelOut>| {
                    let at = row_at + x * strides[0];
                    let v = voxels[at] as u32;
                    let cell = if opaque_front(acc) {
                        acc
                    } else {
                        if shader.mode.uses_colour() && !shader.transparent(v, c.invalid, c.edge) {
                            st.shaded += 1;
                        }
                        let sample = shader.sample(v, c.invalid, c.edge, || {
                            central_difference(|ox, oy, oz| {
                                let i = at as isize
                                    + ox * strides[0] as isize
                                    + oy * strides[1] as isize
                                    + oz * strides[2] as isize;
                                voxels[i as usize]
                            })
                        });
                        let (r, clipped) =
                            composite(shader.mode, sweep.order, acc, &sample, shader.rgba_bits);
                        st.saturations += clipped as u64;
                        r
                    };
                    if c.er {
                        let addr = sweep
                            .base_address(x, y, z, c.face)
                            .expect("ER cells have a face");
                        out.push((addr, cell, c.face));
                    }
                    cell
                };
                // What the bilinear unit gathers for cell `x` (one at a time).
                let gathered = |x: usize, (dx, dy): (i32, i32)| {
                    if first {
                        reset
                    } else {
                        gather(&prev, nx, ny, x, y, dx, dy, frac, reset)
                    }
                };
                // Voxel `x` through the whole datapath on its own: its
                // control bits, what it gathers, and an opaque gather counted.
                let alone = |x: usize, st: &mut Stats, out: &mut Vec<PixelOut>| {
                    let c = sweep.control(x, y, z);
                    let acc = gathered(x, (c.dx, c.dy));
                    st.terminated += opaque_front(acc) as u64;
                    datapath(x, &c, acc, st, out)
                };
                // A parallel view's row inside the slice's border gathers at
                // once (`gather_row`), reset where the previous slice is all
                // reset around the cell. An inner voxel whose composite is
                // the identity then leaves its cell as it is, so only the
                // others and the two border voxels go through the datapath;
                // an opaque gathered cell is counted as the loop below would.
                // Each way gives the columns that may hold something other
                // than reset.
                *span = match parallel {
                    Some((dx, dy)) if !first && inner_row && nx > 2 => {
                        let (lo, hi) = (busy.start.max(1), busy.end.min(nx - 1));
                        // The row holds slice z - 2's cells: reset outside
                        // their span already.
                        if span.lo < span.hi {
                            row[span.lo..span.hi].fill(reset);
                        }
                        // The composited voxels that are not reset (the
                        // gathered cells are scanned below).
                        let mut composited = EMPTY;
                        if lo < hi {
                            gather_row(&prev, nx, y, (lo, hi), dx, dy, frac, &mut row[lo..hi]);
                            if hides {
                                let n = row[lo..hi].iter().filter(|c| c[3] == full).count();
                                st.terminated += n as u64;
                            }
                        }
                        for x in [0, nx - 1] {
                            row[x] = alone(x, &mut st, &mut out);
                            if row[x] != reset {
                                composited = composited.union(Span::column(x));
                            }
                        }
                        // An inner voxel's control bits do not depend on
                        // its x here: one increment, no face, no x edge.
                        let c = sweep.control(1, y, z);
                        for x in 1..nx - 1 {
                            if !identity[voxels[row_at + x * strides[0]] as usize] {
                                debug_assert_eq!(c, sweep.control(x, y, z));
                                row[x] = datapath(x, &c, row[x], &mut st, &mut out);
                                if row[x] != reset {
                                    composited = composited.union(Span::column(x));
                                }
                            }
                        }
                        nonreset(row, lo..hi, reset).union(composited)
                    }
                    _ => {
                        for x in 0..nx {
                            let v = voxels[row_at + x * strides[0]] as usize;
                            let inner = inner_row && x > 0 && x + 1 < nx;
                            if inner && identity[v] {
                                // No ER inside the slice, and the voxel's
                                // composite is the identity: the cell is what
                                // it gathers.
                                row[x] = if first || !busy.contains(&x) {
                                    reset
                                } else {
                                    let d = match parallel {
                                        Some(d) => d,
                                        None => {
                                            let c = sweep.control(x, y, z);
                                            (c.dx, c.dy)
                                        }
                                    };
                                    let cell = gathered(x, d);
                                    st.terminated += opaque_front(cell) as u64;
                                    cell
                                };
                            } else {
                                row[x] = alone(x, &mut st, &mut out);
                            }
                        }
                        nonreset(row, 0..nx, reset)
                    }
                };
                st.pixels_out += out.len() as u64;
                (out, st)
            })
            .collect();
        for (out, st) in outputs {
            stats = stats + st;
            for (addr, px, face) in out {
                base.put(addr, px, face);
            }
        }
        std::mem::swap(&mut prev, &mut next);
        std::mem::swap(&mut prev_span, &mut next_span);
    }
    (base, stats)
}

/// Render every sweep of the view (`vol`: a [`scene::volume::Volume`], or
/// an [`scene::volume::Ordered`] that keeps its traversal-order copies for
/// the next frame).
pub fn render(scene: &Scene, camera: &Camera, vol: &dyn Voxels) -> scene::Result<Frame> {
    let plan = Plan::new(scene, camera)?;
    let mut bases = Vec::new();
    let mut stats = Stats::default();
    for sweep in &plan.sweeps {
        let shader = Shader::new(scene, camera, sweep);
        // On a pool thread, each slice's rows are shared out without waking
        // the calling thread.
        let (b, s) = rayon::scope(|_| render_sweep(vol, sweep, &shader));
        bases.push(b);
        stats = stats + s;
    }
    Ok(Frame { plan, bases, stats })
}

/// Render a scene with the golden model all the way to the final image.
pub fn render_image(scene: &Scene, vol: &dyn Voxels) -> scene::Result<(scene::Image, Frame)> {
    let camera = scene.camera();
    let frame = render(scene, &camera, vol)?;
    let hw = scene.hardware;
    let img = warp::warp(&frame, &camera, scene.mode, hw.rgba_bits, hw.voxel_bits);
    Ok((img, frame))
}
