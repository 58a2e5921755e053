//! What a Cube-3 system is built from (§2-5): the beam fetch's stream
//! ([`BeamFetchConfig`], with the perspective view's de-fanning [`Group`]s),
//! the pipeline's ([`Cube3Config`], with the ABC units' [`AbcConfig`]) and
//! both together ([`Cube3SystemConfig`]), with the address widths the
//! stages share. The stages take their configuration from here, never from
//! the pipeline or system that holds them.

use golden_model::cube3::plan::{sample_pos, Neighbourhood, Template, View};
use golden_model::cube3::shade::Shader;
use golden_model::cube3::shade::Shader as Shading;
use scene::volume::Volume;
use scene::Mode;

/// Address bits of the per-lane bounds ROMs: up to 256 segments a ray.
pub const SEGMENT_BITS: usize = 8;
/// Address bits of the template ROMs: up to 2^16 weights a lane.
pub const TEMPLATE_BITS: usize = 16;

/// Address bits of the parallel template ROM: up to 1023 planes.
pub const PLANE_BITS: usize = 10;
/// Address bits of the perspective group and row ROMs.
pub const GROUP_BITS: usize = 16;

/// One clock of a perspective PRP's writes: plane `plane`, stream rays
/// `ray .. ray + x.len()` at beam positions `x` (increasing, within `P`
/// consecutive voxels).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Group {
    pub plane: usize,
    pub ray: usize,
    pub x: Vec<i32>,
}

/// What the beam fetch is built from.
#[derive(Debug, Clone)]
pub struct BeamFetchConfig {
    pub p: usize,
    /// Traversal dims `[n_x, n_y, K]`.
    pub dims: [usize; 3],
    /// Stream rays `u0 .. u0 + rays` of scanlines `v0 .. v0 + scanlines`.
    pub u0: i32,
    pub v0: i32,
    pub rays: usize,
    pub scanlines: usize,
    pub segments: usize,
    /// Parallel: `pos_x[k]`, `pos_y[k]` for `k` in `0 ..= K`. Perspective:
    /// `pos_y[j·(K + 1) + k] = Y_k(v_0 + j) - v_0 - j` for the written
    /// scanlines `j` in `0 ..= S`, and `pos_x` is empty.
    pub pos_x: Vec<i32>,
    pub pos_y: Vec<i32>,
    /// Perspective: the groups of every written plane, in order.
    pub groups: Vec<Group>,
    /// The volume lives in external memory, not in on-chip modules.
    pub external: bool,
}

impl BeamFetchConfig {
    pub fn new(
        view: &View,
        p: usize,
        u0: i32,
        rays: usize,
        v0: i32,
        scanlines: usize,
    ) -> Result<BeamFetchConfig, String> {
        let mut c = BeamFetchConfig {
            p,
            dims: view.dims,
            u0,
            v0,
            rays,
            scanlines,
            segments: view.dims[2].div_ceil(p),
            pos_x: vec![],
            pos_y: vec![],
            groups: vec![],
            external: false,
        };
        match (&view.x, &view.y) {
            (Template::Parallel { pos: px, .. }, Template::Parallel { pos: py, .. }) => {
                c.pos_x = px.clone();
                c.pos_y = py.clone();
            }
            (Template::Perspective { .. }, Template::Perspective { .. }) => {
                if !view.x.covers(u0, rays) || !view.y.covers(v0, scanlines + 1) {
                    return Err(
                        "the stream's rays or scanlines lie outside the view's templates".into(),
                    );
                }
                let nk = view.dims[2];
                c.pos_y = (0..=scanlines as i32)
                    .flat_map(|j| (0..=nk).map(move |k| (j, k)))
                    .map(|(j, k)| view.y.pos(v0 + j, k) - v0 - j)
                    .collect();
                for k in 0..c.planes_written() {
                    let x = |r: usize| view.x.pos(u0 + r as i32, k);
                    let mut r = 0;
                    while r < rays {
                        let mut n = 1;
                        while n < p && r + n < rays && x(r + n) - x(r) < p as i32 {
                            if x(r + n) <= x(r + n - 1) {
                                return Err(format!(
                                    "plane {k}: rays {} and {} do not diverge",
                                    u0 + (r + n - 1) as i32,
                                    u0 + (r + n) as i32
                                ));
                            }
                            n += 1;
                        }
                        c.groups.push(Group {
                            plane: k,
                            ray: r,
                            x: (r..r + n).map(x).collect(),
                        });
                        r += n;
                    }
                }
            }
            _ => return Err("a view's templates are both parallel or both perspective".into()),
        }
        Ok(c)
    }

    /// A perspective view: the groups and rows come from ROMs.
    pub fn perspective(&self) -> bool {
        !self.groups.is_empty()
    }

    /// Clocks of a PRP's writes.
    pub fn write_clocks(&self) -> usize {
        if self.perspective() {
            self.groups.len()
        } else {
            self.planes_written() * self.rays.div_ceil(self.p)
        }
    }

    /// Planes written per PRP.
    pub fn planes_written(&self) -> usize {
        (self.dims[2] + 1).min(self.segments * self.p)
    }

    /// Clocks of a scanline period.
    pub fn period(&self) -> usize {
        let writes = self.write_clocks() + 1;
        let reads = self.rays * self.segments + 1;
        writes.max(reads)
    }

    /// Clocks from `start` to the last segment read: `S + 2` periods.
    pub fn clocks(&self) -> usize {
        (self.scanlines + 2) * self.period()
    }

    /// Words per memory module: `b·n_y·K`.
    pub fn module_words(&self) -> usize {
        let [nx, ny, nk] = self.dims;
        nx.div_ceil(self.p) * ny * nk
    }

    /// The memory modules' contents: `vol` in `view`'s traversal order,
    /// skewed.
    pub fn modules(&self, vol: &Volume, view: &View) -> Vec<Vec<u16>> {
        let [nx, ny, nk] = self.dims;
        let b = nx.div_ceil(self.p);
        let mut m = vec![vec![0u16; self.module_words()]; self.p];
        for k in 0..nk {
            for y in 0..ny {
                for x in 0..nx {
                    let [u, v, w] = view
                        .voxel(x as i32, y as i32, k)
                        .expect("a traversal voxel inside the volume");
                    m[(x + y + k) % self.p][x / self.p + y * b + k * b * ny] = vol.get(u, v, w);
                }
            }
        }
        m
    }
}

/// Address bits of the X-ray opacity ROM (`lut::OpacityLut` rows).
pub const OPACITY_BITS: usize = 12;

/// Everything a Cube-3 pipeline is built from.
#[derive(Debug, Clone)]
pub struct Cube3Config {
    pub p: usize,
    pub mode: Mode,
    /// Stream rays `u0 .. u0 + rays` of scanlines `v0 .. v0 + scanlines`;
    /// the first and last `halo` scanlines only feed the gradients.
    pub u0: i32,
    pub v0: i32,
    pub rays: usize,
    pub scanlines: usize,
    pub halo: usize,
    pub segments: usize,
    /// Clocks from one scanline's first segment to the next one's (the
    /// ABC unit's sample-plane distance).
    pub scanline_clocks: usize,
    pub offset: u32,
    /// Every sample sits on the grid (`View::on_grid`): the weights and the
    /// offset are 0, so TRILIN's lerps pass their first voxel and synthesis
    /// folds their arithmetic away.
    pub on_grid: bool,
    pub weight_bits: u32,
    pub voxel_bits: u32,
    pub sample_frac: u32,
    pub rgba_bits: u32,
    /// A perspective view: the templates, the increments and the cast
    /// rays differ from ray to ray.
    pub perspective: bool,
    /// The template weights: `wx[r·K + k]` of stream ray `r` and `wy[j·K +
    /// k]` of stream scanline `j` (perspective), or `wx[k]`, `wy[k]`
    /// (parallel).
    pub wx: Vec<u32>,
    pub wy: Vec<u32>,
    /// The rays and scanlines cast on this base plane `[ray_lo, ray_hi,
    /// scanline_lo, scanline_hi]` (inclusive stream indices): a perspective
    /// ray beyond 45° belongs to another base plane.
    pub cast: [u32; 4],
    /// Per plane `k`: the inside bounds `[ray_lo, ray_hi, scanline_lo,
    /// scanline_hi]` (inclusive stream indices; empty as lo > hi) and, with
    /// gradients, the inner box's.
    pub bounds: Vec<[u32; 4]>,
    pub inner: Vec<[u32; 4]>,
    /// X-ray: the opacity table and its row shift.
    pub opacity: Option<(Vec<u32>, u32)>,
    /// Composite and first-opaque: the golden model's shading tables.
    pub shading: Option<Shading>,
    /// With gradients: the ABC units' build.
    pub abc: Option<AbcConfig>,
}

/// What the ABC units are built from.
#[derive(Debug, Clone)]
pub struct AbcConfig {
    /// The 12-neighbourhood, else the 6.
    pub n12: bool,
    /// The increments `DX` of each stream ray and `DY` of each stream
    /// scanline (perspective), or the one of a parallel view.
    pub dx: Vec<i32>,
    pub dy: Vec<i32>,
    pub sample_bits: u32,
    pub gradient_bits: u32,
}

impl Cube3Config {
    /// The pipeline of `view` for the pixels of scanlines `v0 .. v0 +
    /// scanlines`, with the gradients of neighbourhood `n` where the scene
    /// needs them.
    pub fn new(
        view: &View,
        shader: &Shading,
        n: Neighbourhood,
        p: usize,
        v0: i32,
        scanlines: usize,
    ) -> Result<Cube3Config, String> {
        if !matches!(p, 1 | 2 | 4 | 8) {
            return Err(format!("hardware.pipelines {p} unsupported (1, 2, 4 or 8)"));
        }
        let widths = shader.widths;
        let perspective = matches!(view.x, Template::Perspective { .. });
        let halo = shader.needs_gradient as usize;
        let (v0, scanlines) = (v0 - halo as i32, scanlines + 2 * halo);
        let u0 = view.u[0] - 1;
        let rays = (view.u[1] - view.u[0] + 4) as usize;
        // The stream's rays and scanlines, each within its template.
        let stream = |t: &Template, first: i32, n: usize, what: &str| match t.covers(first, n) {
            true => Ok((first..first + n as i32).collect::<Vec<i32>>()),
            false => Err(format!(
                "{what}s {first}..{} lie outside the view's templates",
                first + n as i32
            )),
        };
        let ray_u = stream(&view.x, u0, rays, "ray")?;
        let line_v = stream(&view.y, v0, scanlines, "scanline")?;
        let increments = |t: &Template, lines: &[i32]| -> Result<Vec<i32>, String> {
            let d: Vec<i32> = if perspective {
                lines.iter().map(|&l| t.d(l)).collect()
            } else {
                vec![t.d(0)]
            };
            match d.iter().any(|d| d.unsigned_abs() >= 1 << 16) {
                true => Err("ray increments beyond 16 bits".into()),
                false => Ok(d),
            }
        };
        let abc = match (shader.needs_gradient, n) {
            (false, _) => None,
            (true, Neighbourhood::N6 | Neighbourhood::N12) => Some(AbcConfig {
                n12: n == Neighbourhood::N12,
                dx: increments(&view.x, &ray_u)?,
                dy: increments(&view.y, &line_v)?,
                sample_bits: widths.sample_bits,
                gradient_bits: widths.gradient_bits,
            }),
            (true, n) => {
                let count = if n == Neighbourhood::N10 { 10 } else { 26 };
                return Err(format!(
                    "cube3.gradient {count} is not built in hardware (the 6 or the 12)"
                ));
            }
        };
        let w = view.weight_bits;
        let [nx, ny, nk] = view.dims.map(|n| n as i64);
        let within = |q: i64, lo: i64, hi: i64| q >= lo << w && q <= hi << w;
        // Stream indices `i` in `0..n` where `ok(i)`: an interval (positions
        // are linear in the ray), or empty as [1, 0].
        let interval = |n: usize, ok: &dyn Fn(i64) -> bool| {
            let hits: Vec<u32> = (0..n as u32).filter(|&i| ok(i as i64)).collect();
            match (hits.first(), hits.last()) {
                (Some(&lo), Some(&hi)) if hits.len() == (hi - lo + 1) as usize => Ok([lo, hi]),
                (None, _) => Ok([1, 0]),
                _ => Err("the inside test is not an interval of rays".to_string()),
            }
        };
        // The box `[m, n - 1 - m]` of every axis, plane by plane.
        let boxed = |m: i64| -> Result<Vec<[u32; 4]>, String> {
            (0..nk as usize)
                .map(|k| {
                    let zq = ((k as i64) << w) + view.offset as i64;
                    let r = interval(rays, &|r| {
                        let u = ray_u[r as usize];
                        within(zq, m, nk - 1 - m)
                            && within(sample_pos(u, k, view.x.d(u), w), m, nx - 1 - m)
                    })?;
                    let v = interval(scanlines, &|s| {
                        let v = line_v[s as usize];
                        within(sample_pos(v, k, view.y.d(v), w), m, ny - 1 - m)
                    })?;
                    Ok([r[0], r[1], v[0], v[1]])
                })
                .collect()
        };
        // Weights of every (perspective) or one (parallel) ray and
        // scanline, plane by plane.
        let weights = |t: &Template, lines: &[i32]| -> Vec<u32> {
            let lines = if perspective { lines } else { &lines[..1] };
            lines
                .iter()
                .flat_map(|&l| (0..view.dims[2]).map(move |k| t.weight(l, k)))
                .collect()
        };
        let one = 1u32 << w;
        let cast_x = interval(rays, &|r| view.x.d(ray_u[r as usize]).unsigned_abs() <= one)?;
        let cast_y = interval(scanlines, &|s| {
            view.y.d(line_v[s as usize]).unsigned_abs() <= one
        })?;
        if cast_x[0] > cast_x[1] || cast_y[0] > cast_y[1] {
            return Err("no ray of the stream is cast on this base plane".into());
        }
        let segments = view.dims[2].div_ceil(p);
        Ok(Cube3Config {
            p,
            mode: shader.mode,
            u0,
            v0,
            rays,
            scanlines,
            halo,
            segments,
            scanline_clocks: rays * segments,
            offset: view.offset,
            on_grid: view.on_grid,
            weight_bits: w,
            voxel_bits: widths.voxel_bits,
            sample_frac: widths.sample_frac(),
            rgba_bits: widths.rgba_bits,
            perspective,
            wx: weights(&view.x, &ray_u),
            wy: weights(&view.y, &line_v),
            cast: [cast_x[0], cast_x[1], cast_y[0], cast_y[1]],
            bounds: boxed(0)?,
            inner: if abc.is_some() { boxed(1)? } else { vec![] },
            opacity: (shader.mode == Mode::Xray).then(|| {
                let o = shader.opacity.as_ref().expect("X-ray has an opacity table");
                (o.table.clone(), o.shift)
            }),
            shading: matches!(shader.mode, Mode::Composite | Mode::FirstOpaque)
                .then(|| shader.clone()),
            abc,
        })
    }

    /// Rays with their own `wx` template: every stream ray (perspective) or
    /// one.
    pub fn wx_rays(&self) -> usize {
        if self.perspective {
            self.rays
        } else {
            1
        }
    }

    /// Scanlines with their own `wy` template.
    pub fn wy_scanlines(&self) -> usize {
        if self.perspective {
            self.scanlines
        } else {
            1
        }
    }

    /// Clocks from the first segment entering the streams to just after
    /// the last: a scanline every `scanline_clocks`, the last one's `R·G`
    /// segments.
    pub fn stream_clocks(&self) -> usize {
        (self.scanlines - 1) * self.scanline_clocks + self.rays * self.segments
    }

    /// Clocks from a ray's last segment entering the streams to its pixel.
    pub fn pixel_delay(&self) -> usize {
        super::trilin_lanes::cell_delay(self.segments)
            + super::trilin::LATENCY
            + self.abc_delay()
            + self.leaf_latency()
            + super::compositor::latency(self.p)
            - 1
    }

    /// Clocks from a sample (with its gradient) to its RPC leaf: the leaf
    /// stage's register, or the shader's pipeline.
    pub fn leaf_latency(&self) -> usize {
        match self.shading {
            Some(_) => crate::common::shader::LATENCY,
            None => 1,
        }
    }

    /// Clocks from a sample leaving TRILIN to it and its gradient leaving
    /// the ABC unit (0 without gradients).
    pub fn abc_delay(&self) -> usize {
        match self.abc {
            Some(_) => {
                super::abc_gradient::centre(self.scanline_clocks, self.segments)
                    + super::abc_estimator::LATENCY
            }
            None => 0,
        }
    }
}

/// Both halves' configurations, for the same stream.
#[derive(Debug, Clone)]
pub struct Cube3SystemConfig {
    pub fetch: BeamFetchConfig,
    pub pipeline: Cube3Config,
}

impl Cube3SystemConfig {
    /// The pixels of scanlines `v0 .. v0 + scanlines` of `view`
    /// (`Cube3Config::new`).
    pub fn new(
        view: &View,
        shader: &Shader,
        n: Neighbourhood,
        p: usize,
        v0: i32,
        scanlines: usize,
    ) -> Result<Cube3SystemConfig, String> {
        let mut pipeline = Cube3Config::new(view, shader, n, p, v0, scanlines)?;
        let fetch = BeamFetchConfig::new(
            view,
            p,
            pipeline.u0,
            pipeline.rays,
            pipeline.v0,
            pipeline.scanlines,
        )?;
        pipeline.scanline_clocks = fetch.period();
        Ok(Cube3SystemConfig { fetch, pipeline })
    }

    /// The clock the first segment enters the pipeline: the fetch reads
    /// from its third period on (two PRPs in the buffers), a clock after
    /// `start` registers and a clock after the read.
    pub fn first_entry(&self) -> usize {
        2 * self.fetch.period() + 2
    }

    /// Clocks from `start` (clock 0) to just after the last pixel: the
    /// last scanline's last segment enters `R·G - 1` clocks after its
    /// first, and leaves as a pixel `pixel_delay` clocks later.
    pub fn clocks(&self) -> usize {
        let last_entry = self.first_entry() + self.pipeline.stream_clocks() - 1;
        last_entry + self.pipeline.pixel_delay() + 1
    }
}
