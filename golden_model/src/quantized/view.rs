//! Per-view preprocessing of the quantized-voxel path: where voxels land
//! on the image, the projection classes or splat lists with their offsets
//! made single integers for the band buffers' row stride (Eq. 4), the
//! shading table over the normal codes (§3.1), the traversal order of the
//! blocks (§3.3), and which image bands each block reaches.
//!
//! Positions are fixed point with `FRAC` fractional bits of a pixel: the
//! centre of a voxel is its block's origin plus at most seven steps along
//! each axis, each step exact to `2^-(FRAC+1)` pixels, so a centre is
//! within `22 · 2^-33` pixels of its exact position. The integer part
//! names the square (its top-left pixel), the fraction the subdivision.

use super::grid::Grid;
use super::hexagon::Hexagon;
use super::normals::NormalCode;
use super::projection::ProjectionTable;
use super::splat::SplatTable;
use super::{Method, Params};
use glam::{DVec2, DVec3};
use rayon::prelude::*;
use scene::lighting::phong;
use scene::{Camera, Scene};

/// Fractional bits of a fixed-point image position.
pub const FRAC: u32 = 32;
/// Rows of an image band: the unit of parallel work.
pub const BAND: usize = 32;

/// A position in pixels as fixed point with `FRAC` fractional bits.
pub fn fixed(x: f64) -> i64 {
    (x * (1u64 << FRAC) as f64).round() as i64
}

/// Where voxels land on the image: pixel `(i, j)` is centred at `(i, j)`,
/// x to the right and y down.
#[derive(Debug, Clone, Copy)]
pub struct Geometry {
    /// Image offset of one voxel step along u, v and w.
    pub steps: [DVec2; 3],
    /// Image position of voxel (0, 0, 0).
    pub origin: DVec2,
    /// Voxel lengths per pixel.
    pub s: f64,
    /// Unit viewing direction (into the scene), dataset coordinates.
    pub forward: DVec3,
    pub width: usize,
    pub height: usize,
}

impl Geometry {
    pub fn new(camera: &Camera) -> Geometry {
        let s = camera.scale;
        let (w, h) = (camera.width as f64, camera.height as f64);
        let at = |p: DVec3| {
            let d = p - camera.origin;
            DVec2::new(
                d.dot(camera.right) / s + w / 2.0 - 0.5,
                h / 2.0 - 0.5 - d.dot(camera.up) / s,
            )
        };
        let origin = at(DVec3::ZERO);
        let steps = [DVec3::X, DVec3::Y, DVec3::Z].map(|e| at(e) - origin);
        Geometry {
            steps,
            origin,
            s,
            forward: camera.forward,
            width: camera.width as usize,
            height: camera.height as usize,
        }
    }

    /// The image position of voxel `p`.
    pub fn centre(&self, p: [usize; 3]) -> DVec2 {
        self.origin
            + self.steps[0] * p[0] as f64
            + self.steps[1] * p[1] as f64
            + self.steps[2] * p[2] as f64
    }

    /// The mean length of ray inside a voxel's cube, over the rays that
    /// cross it: volume over projected area, `1 / (|d_u| + |d_v| + |d_w|)`.
    pub fn chord(&self) -> f64 {
        1.0 / self.forward.abs().element_sum()
    }
}

/// Where one projection class's pixels lie in the footprint's lists.
#[derive(Debug, Clone, Copy)]
pub struct ClassRange {
    /// `sure[sure..sure + sure_len]`.
    pub sure: u32,
    pub sure_len: u32,
    /// `undecided[und..und + und_len]`.
    pub und: u32,
    pub und_len: u32,
}

/// A footprint table with offsets made single integers.
#[derive(Debug, Clone)]
pub enum Footprint {
    Projection {
        table: ProjectionTable,
        /// Per class: where its pixels lie in `sure` and `undecided`.
        ranges: Vec<ClassRange>,
        /// Each class's sure offsets in the window.
        sure: Vec<u32>,
        /// Undecided pixels as (offset in the window, first equation,
        /// equation count).
        undecided: Vec<(u32, u32, u32)>,
    },
    Splat {
        table: SplatTable,
        /// Offsets in the window.
        offsets: Vec<u32>,
    },
}

/// The pixels of a band buffer that a voxel's footprint can reach: every
/// footprint offset is an index below `len` from the square's top-left
/// pixel moved by `lo`.
#[derive(Debug, Clone, Copy)]
pub struct Window {
    pub lo: isize,
    pub len: usize,
}

impl Window {
    /// The window of the voxel whose square's top-left pixel is `buf[base]`
    /// (one bounds check per voxel; its offsets then index it unchecked).
    #[inline(always)]
    pub fn at<T>(self, buf: &mut [T], base: isize) -> &mut [T] {
        &mut buf[(base + self.lo) as usize..][..self.len]
    }
}

/// Everything a frame needs that depends on the view alone.
#[derive(Debug, Clone)]
pub struct ViewTables {
    pub geom: Geometry,
    pub footprint: Footprint,
    pub n: usize,
    /// Smallest and largest pixel offset of any footprint entry.
    pub ext: [[i32; 2]; 2],
    /// Rows and columns of margin around a band's buffer, and its stride.
    pub margin: usize,
    pub stride: usize,
    /// Where a footprint's offsets point, from the square's top-left pixel.
    pub window: Window,
    /// Per normal code (directions, then flat): ambient + diffuse, and
    /// specular.
    pub shade: Vec<[f32; 2]>,
    /// Per axis: whether the traversal walks it downwards.
    pub descending: [bool; 3],
    /// Per band: the blocks that reach it, in traversal order.
    pub bands: Vec<Vec<u32>>,
    /// Per block: fixed-point image position of its first voxel.
    pub block_origin: Vec<[i64; 2]>,
    /// Per block: the pixels its footprints can reach, `[x0, x1, y0, y1]`
    /// inclusive.
    pub block_box: Vec<[i32; 4]>,
    /// Fixed-point image offset of one voxel step along u, v and w.
    pub steps: [[i64; 2]; 3],
    /// Footprint entries in the table.
    pub entries: u64,
    /// Projection classes or splat subdivisions.
    pub classes: u64,
}

impl ViewTables {
    pub fn new(scene: &Scene, camera: &Camera, grid: &Grid, params: &Params) -> ViewTables {
        let geom = Geometry::new(camera);
        let n = params.n;
        let (tables, ext) = match params.method {
            Method::Projection => {
                let t = ProjectionTable::new(&Hexagon::of_steps(geom.steps), n);
                let e = t.extent();
                (Ok(t), e)
            }
            Method::Splat => {
                let t = SplatTable::new(params.kernel, n, geom.s);
                let e = t.extent();
                (Err(t), e)
            }
        };
        let span = (ext[1][0] - ext[0][0]).max(ext[1][1] - ext[0][1]) as usize;
        let margin = span + 1;
        let stride = geom.width + 2 * margin;
        let lin = |o: &[i32; 2]| o[1] as isize * stride as isize + o[0] as isize;
        // Each offset lies within ext per axis, so its single integer lies
        // in lin(ext[0])..=lin(ext[1]).
        let window = Window {
            lo: lin(&ext[0]),
            len: (lin(&ext[1]) - lin(&ext[0])) as usize + 1,
        };
        let rel = |o: &[i32; 2]| {
            let r = lin(o) - window.lo;
            assert!(
                (0..window.len as isize).contains(&r),
                "footprint offset outside its window"
            );
            r as u32
        };
        let (footprint, entries, classes) = match tables {
            Ok(table) => {
                let (mut ranges, mut sure, mut undecided) = (Vec::new(), Vec::new(), Vec::new());
                for c in &table.classes {
                    let first = sure.len();
                    sure.extend(c.sure.iter().map(rel));
                    ranges.push(ClassRange {
                        sure: first as u32,
                        sure_len: c.sure.len() as u32,
                        und: undecided.len() as u32,
                        und_len: c.undecided.len() as u32,
                    });
                    undecided.extend(c.undecided.iter().map(|u| (rel(&u.offset), u.first, u.len)));
                }
                let e = table
                    .classes
                    .iter()
                    .map(|c| c.sure.len() + c.undecided.len())
                    .sum::<usize>() as u64;
                let k = table.classes.len() as u64;
                (
                    Footprint::Projection {
                        table,
                        ranges,
                        sure,
                        undecided,
                    },
                    e,
                    k,
                )
            }
            Err(table) => {
                let offsets: Vec<u32> = table.offsets.iter().map(rel).collect();
                let e = offsets.len() as u64;
                (Footprint::Splat { table, offsets }, e, (n * n) as u64)
            }
        };
        let shade = shade_table(scene, camera, &grid.code);
        let back_to_front = params.order == scene::Traversal::BackToFront;
        // Back to front visits far voxels first: along an axis the view
        // direction points up, the far end is the high end.
        let descending = [0, 1, 2].map(|a| (geom.forward[a] > 0.0) == back_to_front);
        let steps = geom.steps.map(|s| [fixed(s.x), fixed(s.y)]);
        let count = grid.blocks.iter().product::<usize>();
        let (block_origin, block_box): (Vec<_>, Vec<_>) = (0..count)
            .into_par_iter()
            .map(|b| {
                let first = grid.first(b);
                let o = geom.centre(first);
                let e = grid.extent(b);
                let (mut lo, mut hi) = (DVec2::splat(f64::MAX), DVec2::splat(f64::MIN));
                for k in 0..8 {
                    let p =
                        [0, 1, 2].map(|a| first[a] + if k >> a & 1 == 1 { e[a] - 1 } else { 0 });
                    let q = geom.centre(p);
                    lo = lo.min(q);
                    hi = hi.max(q);
                }
                let bbox = [
                    lo.x.floor() as i32 + ext[0][0],
                    hi.x.floor() as i32 + ext[1][0],
                    lo.y.floor() as i32 + ext[0][1],
                    hi.y.floor() as i32 + ext[1][1],
                ];
                ([fixed(o.x), fixed(o.y)], bbox)
            })
            .unzip();
        let bands_n = geom.height.div_ceil(BAND);
        let mut bands = vec![Vec::new(); bands_n];
        let along = |a: usize, k: usize| {
            let m = grid.blocks[a];
            if descending[a] {
                m - 1 - k
            } else {
                k
            }
        };
        for kz in 0..grid.blocks[2] {
            for ky in 0..grid.blocks[1] {
                for kx in 0..grid.blocks[0] {
                    let b = grid.block([along(0, kx), along(1, ky), along(2, kz)]);
                    let [x0, x1, y0, y1] = block_box[b];
                    if x1 < 0 || x0 >= geom.width as i32 || y1 < 0 || y0 >= geom.height as i32 {
                        continue;
                    }
                    let first = (y0.max(0) as usize) / BAND;
                    let last = (y1 as usize).min(geom.height - 1) / BAND;
                    for band in &mut bands[first..=last] {
                        band.push(b as u32);
                    }
                }
            }
        }
        ViewTables {
            geom,
            footprint,
            n,
            ext,
            margin,
            stride,
            window,
            shade,
            descending,
            bands,
            block_origin,
            block_box,
            steps,
            entries,
            classes,
        }
    }
}

/// Ambient + diffuse and specular per normal code, for the scene's light
/// and this view (the flat code: ambient alone). Without shading every
/// code gives (1, 0).
fn shade_table(scene: &Scene, camera: &Camera, code: &NormalCode) -> Vec<[f32; 2]> {
    let sh = &scene.shading;
    let count = code.count() as usize;
    if !sh.enabled {
        return vec![[1.0, 0.0]; count + 1];
    }
    let light = camera
        .camera_to_dataset(DVec3::from_array(sh.light_dir))
        .normalize();
    let viewer = -camera.forward;
    let mut t: Vec<[f32; 2]> = (0..count)
        .into_par_iter()
        .map(|i| {
            let (d, s) = phong(sh, code.decode(i as u16), light, viewer);
            [d as f32, s as f32]
        })
        .collect();
    t.push([sh.ambient as f32, 0.0]);
    t
}
