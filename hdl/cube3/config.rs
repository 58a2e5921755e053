//! What a Cube-3 system is built from (§2-5): the beam fetch's stream
//! ([`BeamFetchConfig`], with the perspective view's de-fanning [`Group`]s),
//! the pipeline's ([`Cube3Config`], with the ABC units' [`AbcConfig`]) and
//! both together ([`Cube3SystemConfig`]), with the address widths the
//! stages share. The stages take their configuration from here, never from
//! the pipeline or system that holds them.

use golden_model::common::shader::Shader;
use golden_model::common::shader::Shader as Shading;
use golden_model::cube3::plan::{sample_pos, Neighbourhood, Template, View};
pub use golden_model::cube3::regs::Group;
use golden_model::cube3::regs::{AbcView, FetchView, PipelineView};
use golden_model::host::Write;
use scene::volume::Volume;
use scene::Mode;

/// Address bits of the per-lane bounds tables: up to 256 segments a ray.
pub const SEGMENT_BITS: usize = 8;
/// Address bits of the template tables: up to 2^16 weights a lane.
pub const TEMPLATE_BITS: usize = 16;

/// Address bits of the parallel `pos_x` table: up to 1024 planes.
pub const PLANE_BITS: usize = 10;
/// Address bits of the perspective group and row tables: `(n + 1)·(2n +
/// 4)` groups, 132 612 for a 256 class.
pub const GROUP_BITS: usize = 18;

/// Clocks from a group's schedule count to its voxels' 2-DSB write
/// ([`super::cfb`]'s write stages): the row's `pos_y` read (the group
/// registered beside it), the row, the lanes' addresses, and the memory
/// modules' read.
pub const WRITE_LATENCY: usize = 4;

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
                let (nx, nk) = (view.dims[0] as i32, view.dims[2]);
                c.pos_y = (0..=scanlines as i32)
                    .flat_map(|j| (0..=nk).map(move |k| (j, k)))
                    .map(|(j, k)| view.y.pos(v0 + j, k) - v0 - j)
                    .collect();
                for k in 0..c.planes_written() {
                    let x = |r: usize| view.x.pos(u0 + r as i32, k);
                    if let Some(r) = (1..rays).find(|&r| x(r) <= x(r - 1)) {
                        return Err(format!(
                            "plane {k}: rays {} and {} do not diverge",
                            u0 + r as i32 - 1,
                            u0 + r as i32
                        ));
                    }
                    // A group is the next rays, up to P, while those whose
                    // voxel lies in the volume keep to distinct memory
                    // modules (x + y + k) mod P, i.e. distinct x mod P (y
                    // and k are the group's); the others read no module.
                    let reads = |x: i32| k < nk && (0..nx).contains(&x);
                    let mut r = 0;
                    while r < rays {
                        let mut used = 0u64;
                        let mut n = 0;
                        while n < p && r + n < rays {
                            let xn = x(r + n);
                            if reads(xn) {
                                let bit = 1u64 << xn.rem_euclid(p as i32);
                                if used & bit != 0 {
                                    break;
                                }
                                used |= bit;
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

    /// A perspective view: the groups and rows come from tables.
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
        let writes = self.write_clocks() + WRITE_LATENCY;
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

/// Address bits of the X-ray opacity table (`lut::OpacityLut` rows).
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
    /// The neighbourhood: the 6, 10, 12 or 26.
    pub neighbourhood: Neighbourhood,
    /// The 10 (parallel views): the view's weights `T` and basis
    /// correction `C` (`golden_model::cube3::abc::RayCoeffs`).
    pub basis10: Option<([u32; 2], [[i64; 3]; 3])>,
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
        crate::common::lanes::built(p)?;
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
        let basis10 = match (n, perspective) {
            (Neighbourhood::N10, true) if shader.needs_gradient => {
                return Err("cube3.gradient 10 is built in hardware for parallel views only: a perspective view's basis correction differs from ray to ray (the 6, 12 or 26 render it)".to_string());
            }
            (Neighbourhood::N10, false) => {
                let c = golden_model::cube3::abc::RayCoeffs::new(
                    view.x.d(0),
                    view.y.d(0),
                    view.weight_bits,
                );
                let fits = |v: i64| (-(1 << 15)..1 << 15).contains(&v);
                if !c.c10.iter().flatten().all(|&v| fits(v)) || c.t.iter().any(|&t| t >= 1 << 16) {
                    return Err(
                        "the 10-neighbourhood's basis correction exceeds its 16-bit registers"
                            .to_string(),
                    );
                }
                Some((c.t, c.c10))
            }
            _ => None,
        };
        let abc = match (shader.needs_gradient, n) {
            (false, _) => None,
            (true, _) => Some(AbcConfig {
                neighbourhood: n,
                basis10,
                dx: increments(&view.x, &ray_u)?,
                dy: increments(&view.y, &line_v)?,
                sample_bits: shader.voxel_bits + shader.sample_frac,
                gradient_bits: shader.gradient_bits,
            }),
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
            weight_bits: w,
            voxel_bits: shader.voxel_bits,
            sample_frac: shader.sample_frac,
            rgba_bits: shader.rgba_bits,
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

    /// Of the `R·S·G` segments the stream carries: how many hold a sample
    /// inside the volume ([`Cube3Config::bounds`]), and how many belong to
    /// stream rays (a ray and a scanline) that hold any. The rest of a
    /// crossing ray's segments, and every segment of a ray that misses the
    /// volume, carry nothing a pixel takes (a gradient's neighbour rays and
    /// scanlines aside).
    pub fn segments_inside(&self) -> (usize, usize) {
        let p = self.p;
        let (mut inside, mut crossing) = (0, 0);
        for j in 0..self.scanlines as u32 {
            for r in 0..self.rays as u32 {
                let holds = |b: &[u32; 4]| b[0] <= r && r <= b[1] && b[2] <= j && j <= b[3];
                let n = self
                    .bounds
                    .chunks(p)
                    .filter(|segment| segment.iter().any(holds))
                    .count();
                inside += n;
                crossing += if n > 0 { self.segments } else { 0 };
            }
        }
        (inside, crossing)
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
    /// `start` registers, a clock after the read, and a clock after the
    /// buffers' words are registered.
    pub fn first_entry(&self) -> usize {
        2 * self.fetch.period() + 3
    }

    /// Clocks from `start` (clock 0) to just after the last pixel: the
    /// last scanline's last segment enters `R·G - 1` clocks after its
    /// first, and leaves as a pixel `pixel_delay` clocks later.
    pub fn clocks(&self) -> usize {
        let last_entry = self.first_entry() + self.pipeline.stream_clocks() - 1;
        last_entry + self.pipeline.pixel_delay() + 1
    }
}

/// What a Cube-3 build is sized for: every view, transfer function and
/// light of volumes up to `n` voxels a side, through `p` units. The memory
/// depths, delay lines and view tables take these bounds; the view's own
/// values are registers and tables the host writes
/// ([`Cube3SystemConfig::view_writes`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Cube3Sizes {
    pub n: usize,
    pub p: usize,
    pub perspective: bool,
    /// The ABC units are built: a halo scanline each side.
    pub gradients: bool,
    /// Bits of a voxel: the 2-DSBs store these bits of each word.
    pub voxel_bits: u32,
}

impl Cube3Sizes {
    /// Segments of the longest ray: `ceil(n / p)`.
    pub fn segments(&self) -> usize {
        self.n.div_ceil(self.p)
    }

    /// Planes of a PRP: `K + 1`.
    pub fn planes(&self) -> usize {
        self.n + 1
    }

    /// Stream rays: a base plane's rays span at most `2n - 1` pixels (a
    /// sheared or diverging ray moves at most one voxel a plane), and the
    /// stream has two more each side.
    pub fn rays(&self) -> usize {
        2 * self.n + 4
    }

    /// Stream scanlines, the gradients' halo included.
    pub fn scanlines(&self) -> usize {
        self.rays() + 2 * self.gradients as usize
    }

    /// Perspective de-fanning groups of a PRP: at most a ray each.
    pub fn groups(&self) -> usize {
        if self.perspective {
            self.planes() * self.rays()
        } else {
            0
        }
    }

    /// The longest scanline period ([`BeamFetchConfig::period`]).
    pub fn period(&self) -> usize {
        let writes = if self.perspective {
            self.groups()
        } else {
            self.planes() * self.rays().div_ceil(self.p)
        };
        (writes + WRITE_LATENCY).max(self.rays() * self.segments() + 1)
    }

    /// Words of a memory module: `ceil(n / p)·n²`.
    pub fn module_words(&self) -> usize {
        self.segments() * self.n * self.n
    }

    /// The volume lives in external memory (a module beyond the on-chip
    /// `2^ON_CHIP_BITS` words).
    pub fn external(&self) -> bool {
        self.module_words() > 1 << crate::common::ram::ON_CHIP_BITS
    }

    /// Why this build cannot render the base plane `c`, if it cannot.
    pub fn refuses(&self, c: &Cube3SystemConfig) -> Option<String> {
        let (f, q) = (&c.fetch, &c.pipeline);
        let checks = [
            (
                f.dims.iter().copied().max().unwrap_or(0),
                self.n,
                "a volume side",
            ),
            (f.segments, self.segments(), "segments a ray"),
            (f.rays, self.rays(), "stream rays"),
            (
                f.scanlines.max(q.scanlines),
                self.scanlines(),
                "stream scanlines",
            ),
            (f.groups.len(), self.groups(), "de-fanning groups"),
            (f.period(), self.period(), "clocks a scanline period"),
        ];
        if f.perspective() != self.perspective || (q.abc.is_some() != self.gradients) {
            return Some("another projection or gradient unit".into());
        }
        checks
            .iter()
            .find(|(v, max, _)| v > max)
            .map(|(v, max, what)| format!("{v} {what}, the build holds {max}"))
    }
}

impl BeamFetchConfig {
    /// The beam fetch's view words (`golden_model::cube3::regs::FetchView`),
    /// with the pipeline's `offset`.
    pub fn view_writes(&self, offset: u32) -> Vec<Write> {
        FetchView {
            p: self.p,
            dims: self.dims,
            u0: self.u0,
            v0: self.v0,
            rays: self.rays,
            scanlines: self.scanlines,
            segments: self.segments,
            planes_written: self.planes_written(),
            period: self.period(),
            offset,
            pos_x: &self.pos_x,
            pos_y: &self.pos_y,
            groups: &self.groups,
        }
        .writes()
    }
}

impl Cube3Config {
    /// The pipeline's own view words
    /// (`golden_model::cube3::regs::PipelineView`), with the delay lines'
    /// lengths this RTL's latencies set.
    pub fn view_writes(&self) -> Vec<Write> {
        let g = self.segments as i64;
        // The centre line ends a clock before the centre: the increments'
        // tables are read into a register.
        let centre_last = if self.perspective {
            (super::trilin::LATENCY as i64 + g + 1) - 2
        } else {
            0
        };
        let lines = match self.abc {
            Some(_) => super::plane_taps::line_lengths(self.scanline_clocks, self.segments)
                .map_or([1, 1], |l| [l[0] as i64 - 1, l[2] as i64 - 1]),
            None => [0, 0],
        };
        PipelineView {
            p: self.p,
            segments: self.segments,
            cast: self.cast,
            late_last: super::trilin_lanes::cell_delay(self.segments) as i64 - 1,
            centre_last,
            flags_last: self.abc_delay().max(1) as i64 - 1,
            lines,
            opacity: self.opacity.as_ref().map(|(table, _)| &table[..]),
            abc: self.abc.as_ref().map(|a| AbcView {
                dx: &a.dx,
                dy: &a.dy,
                basis10: a.basis10,
                inner: &self.inner,
            }),
            bounds: &self.bounds,
            wx: &self.wx,
            wx_rays: self.wx_rays(),
            wy: &self.wy,
            wy_scanlines: self.wy_scanlines(),
        }
        .writes()
    }
}

impl Cube3SystemConfig {
    /// The words the host writes before this base plane's frame: the view
    /// registers and tables (`golden_model::host::Reg::C3Stream ..=
    /// C3Basis10Z`, `ViewTable`) of the beam fetch, then of the pipeline.
    /// The shader's tables and light are written beside them
    /// (`Shader::tables`).
    pub fn view_writes(&self) -> Vec<Write> {
        let mut w = self.fetch.view_writes(self.pipeline.offset);
        w.extend(self.pipeline.view_writes());
        w
    }
}
