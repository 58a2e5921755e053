//! The JSON scene: volume, view, projection mode, transfer function, shading,
//! image size and hardware precision. Parsing rejects unknown keys and every
//! value the renderers cannot honour, with a one-line message.
//!
//! A scene as written is a [`SceneSpec`]; validating it is the only way to
//! a [`Scene`], the type every renderer and flow takes. A `Scene` reads as
//! its spec (it dereferences to one) but cannot be changed in place: to
//! vary a field, take [`Scene::spec`], change it and validate again. What
//! validation normalises (the light direction to a unit vector, a raw
//! path against the scene's folder, the camera) is what renderers read.

use crate::camera::{check_dir, Camera, ViewSpec};
use crate::error::{CubeError, Result};
use crate::volume::{max_value, VolumeSpec, BUILTINS};
use glam::DVec3;
use serde::de::{self, Deserializer, MapAccess, SeqAccess, Visitor};
use serde::Deserialize;
use std::marker::PhantomData;
use std::path::Path;

/// Largest accepted volume side; larger sides are treated as absurd input.
pub const MAX_DIM: usize = 4096;
/// Largest accepted voxel count: 2^28 (for example 512 x 512 x 1024). The
/// golden model keeps the volume as 16-bit voxels plus its compositing
/// buffers, the reference a min-max grid: about 1 GB at this size.
pub const MAX_VOXELS: usize = 1 << 28;
/// Largest accepted image side.
pub const MAX_IMAGE: u32 = 8192;

/// A scene as written, unchecked: build a [`Scene`] from it with
/// [`SceneSpec::validate`].
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneSpec {
    #[serde(deserialize_with = "object")]
    pub volume: VolumeSpec,
    #[serde(deserialize_with = "object")]
    pub view: ViewSpec,
    #[serde(default)]
    pub mode: Mode,
    #[serde(default, deserialize_with = "object")]
    pub transfer: Transfer,
    #[serde(default, deserialize_with = "object")]
    pub shading: Shading,
    #[serde(default = "default_image")]
    pub image: [u32; 2],
    #[serde(default, deserialize_with = "object")]
    pub hardware: Hardware,
    /// Cube-3 only: gradient neighbourhood and datapath widths.
    #[serde(default, deserialize_with = "object")]
    pub cube3: Cube3Spec,
    /// Quantized-voxel path only: subdivisions, normals, empty-space grid,
    /// traversal order and splat kernel.
    #[serde(default, deserialize_with = "object")]
    pub quantized: QuantizedSpec,
}

/// Parameters of the quantized-voxel path (Mora, Jessel & Caubet).
#[derive(Debug, Clone, Copy, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct QuantizedSpec {
    /// Subdivisions per side of the square of four pixels (§2.2, §2.3);
    /// default 64 for voxel projection, 32 for splatting (the paper's).
    pub subdivisions: Option<u32>,
    /// Quantized normal directions (§3.1): a power of two, 16..=32768.
    #[serde(default = "default_normals")]
    pub normals: u32,
    /// How a block is found empty (§3.2).
    #[serde(default)]
    pub empty_space: EmptySpace,
    /// Traversal order (§3.3).
    #[serde(default)]
    pub order: Traversal,
    /// Splat kernel `[b, r]` of `f(x) = b·e^(−r·x²)`, x in voxel lengths.
    #[serde(default = "default_kernel")]
    pub kernel: [f64; 2],
}

/// The smallest splat-kernel `b`: the weights are f32, whose normal range
/// ends near 1.2e-38; this leaves room for `b·π/r` at `r` = 100.
pub const MIN_KERNEL_B: f64 = 1e-30;

fn default_normals() -> u32 {
    8192
}

fn default_kernel() -> [f64; 2] {
    [0.446, 2.0]
}

impl Default for QuantizedSpec {
    fn default() -> Self {
        QuantizedSpec {
            subdivisions: None,
            normals: default_normals(),
            empty_space: EmptySpace::default(),
            order: Traversal::default(),
            kernel: default_kernel(),
        }
    }
}

/// Which block summary marks a block empty: its minimum alone (the
/// paper's grid: the opacity is zero from the minimum up), or its minimum
/// and maximum (zero over the block's value range).
#[derive(Debug, Clone, Copy, Deserialize, PartialEq, Eq, Default)]
#[serde(rename_all = "snake_case")]
pub enum EmptySpace {
    Min,
    #[default]
    MinMax,
}

/// Traversal order of the quantized-voxel path.
#[derive(Debug, Clone, Copy, Deserialize, PartialEq, Eq, Default)]
#[serde(rename_all = "snake_case")]
pub enum Traversal {
    /// The paper's: no accumulation buffer, no early termination.
    #[default]
    BackToFront,
    /// With early ray termination.
    FrontToBack,
}

impl QuantizedSpec {
    fn validate(&self) -> Result<()> {
        if let Some(n) = self.subdivisions {
            if !(1..=256).contains(&n) {
                return Err(CubeError::Scene(format!(
                    "quantized.subdivisions {n} unsupported (1..=256)"
                )));
            }
        }
        let n = self.normals;
        if !(n.is_power_of_two() && (16..=32768).contains(&n)) {
            return Err(CubeError::Scene(format!(
                "quantized.normals {n} unsupported (a power of two, 16..=32768)"
            )));
        }
        let [b, r] = self.kernel;
        // The splat weights are f32: below about 1.2e-38 b underflows to a
        // subnormal or to zero, and the weights turn to NaN (1e-100) or lose
        // their precision (X-ray, 1e-44: 79.8 % against 16.0 %). The bound
        // leaves f32 room for b·π/r and b·e^(-r·x²) near the centre.
        if !(b.is_finite()
            // serde_json's decimal is within a few ulps: "1e-30" reads
            // as 9.999999999999999e-31, and is taken.
            && (MIN_KERNEL_B * (1.0 - 1e-12)..=10.0).contains(&b)
            && r.is_finite()
            && (0.1..=100.0).contains(&r))
        {
            return Err(CubeError::Scene(format!(
                "quantized.kernel [{b}, {r}] unsupported (b in [{MIN_KERNEL_B:e}, 10], as the f32 splat weights hold it; r in [0.1, 100])"
            )));
        }
        Ok(())
    }
}

/// Cube-3 parameters. Its interpolation weights, templates and sample offset
/// take `hardware.frac_bits` fractional bits; its RPC has `hardware.pipelines`
/// leaves; `hardware.voxel_bits` and `hardware.rgba_bits` are shared.
#[derive(Debug, Clone, Copy, Deserialize, PartialEq, Eq)]
#[serde(deny_unknown_fields)]
pub struct Cube3Spec {
    /// ABC gradient neighbourhood: 6, 10, 12 or 26 (§4).
    #[serde(default = "default_neighbourhood")]
    pub gradient: u32,
    /// Width of an interpolated sample: `voxel_bits` integer bits plus
    /// `sample_bits - voxel_bits` fractional bits. Default `voxel_bits + 4`.
    pub sample_bits: Option<u32>,
    /// Width of a signed gradient component (saturated). Default
    /// `sample_bits + 3`: a central difference needs `sample_bits + 1`, and
    /// the shear correction of the 6-, 10- and 26-neighbourhoods adds up to
    /// two ray-direction terms.
    pub gradient_bits: Option<u32>,
}

fn default_neighbourhood() -> u32 {
    12
}

impl Default for Cube3Spec {
    fn default() -> Self {
        Cube3Spec {
            gradient: 12,
            sample_bits: None,
            gradient_bits: None,
        }
    }
}

impl Cube3Spec {
    /// Sample width for `voxel_bits`-bit voxels.
    pub fn sample_bits(&self, voxel_bits: u32) -> u32 {
        self.sample_bits.unwrap_or(voxel_bits + 4)
    }

    /// Gradient component width for `voxel_bits`-bit voxels.
    pub fn gradient_bits(&self, voxel_bits: u32) -> u32 {
        self.gradient_bits
            .unwrap_or(self.sample_bits(voxel_bits) + 3)
    }

    fn validate(&self, voxel_bits: u32) -> Result<()> {
        if ![6, 10, 12, 26].contains(&self.gradient) {
            return Err(CubeError::Hardware(format!(
                "cube3.gradient {} unsupported (6, 10, 12 or 26)",
                self.gradient
            )));
        }
        let sb = self.sample_bits(voxel_bits);
        if !(voxel_bits..=voxel_bits + 8).contains(&sb) {
            return Err(CubeError::Hardware(format!(
                "cube3.sample_bits {sb} unsupported (voxel_bits {voxel_bits} to voxel_bits + 8)"
            )));
        }
        let gb = self.gradient_bits(voxel_bits);
        if !(sb + 1..=31).contains(&gb) {
            return Err(CubeError::Hardware(format!(
                "cube3.gradient_bits {gb} unsupported (sample_bits + 1 = {} to 31)",
                sb + 1
            )));
        }
        Ok(())
    }
}

fn default_image() -> [u32; 2] {
    [256, 256]
}

#[derive(Debug, Clone, Copy, Deserialize, PartialEq, Eq, Default)]
#[serde(rename_all = "snake_case")]
pub enum Mode {
    #[default]
    Composite,
    Mip,
    Minip,
    Xray,
    FirstOpaque,
}

impl Mode {
    /// Modes that shade, and so need gradients and the reflectance map.
    pub fn uses_colour(self) -> bool {
        matches!(self, Mode::Composite | Mode::FirstOpaque)
    }
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Transfer {
    /// `[intensity, opacity per voxel length]`, intensities in voxel units.
    pub opacity: Vec<[f64; 2]>,
    /// `[intensity, r, g, b]`, colours in [0, 1].
    pub color: Vec<[f64; 4]>,
    /// Optional `[gradient magnitude (voxel units per voxel), factor]`; when
    /// present the opacity LUT gains a gradient-magnitude index.
    pub gradient_opacity: Option<Vec<[f64; 2]>>,
    /// First-opaque mode: opacity at which a voxel counts as opaque.
    #[serde(default = "default_threshold")]
    pub opaque_threshold: f64,
}

fn default_threshold() -> f64 {
    0.5
}

impl Default for Transfer {
    fn default() -> Self {
        Transfer {
            opacity: vec![[0.0, 0.0], [80.0, 0.0], [100.0, 0.75], [255.0, 0.75]],
            color: vec![[0.0, 1.0, 1.0, 1.0], [255.0, 1.0, 1.0, 1.0]],
            gradient_opacity: None,
            opaque_threshold: 0.5,
        }
    }
}

#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Shading {
    pub enabled: bool,
    /// Direction towards the light in camera space (x right, y up, z towards
    /// the viewer).
    #[serde(default = "default_light")]
    pub light_dir: [f64; 3],
    #[serde(default = "default_ambient")]
    pub ambient: f64,
    #[serde(default = "default_diffuse")]
    pub diffuse: f64,
    #[serde(default = "default_specular")]
    pub specular: f64,
    #[serde(default = "default_shininess")]
    pub shininess: f64,
}

fn default_light() -> [f64; 3] {
    [0.3, 0.3, 1.0]
}
fn default_ambient() -> f64 {
    0.2
}
fn default_diffuse() -> f64 {
    0.6
}
fn default_specular() -> f64 {
    0.3
}
fn default_shininess() -> f64 {
    10.0
}

impl Default for Shading {
    fn default() -> Self {
        Shading {
            enabled: true,
            light_dir: default_light(),
            ambient: default_ambient(),
            diffuse: default_diffuse(),
            specular: default_specular(),
            shininess: default_shininess(),
        }
    }
}

#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Hardware {
    #[serde(default = "default_pipelines")]
    pub pipelines: usize,
    #[serde(default = "default_voxel_bits")]
    pub voxel_bits: u32,
    #[serde(default = "default_frac_bits")]
    pub frac_bits: u32,
    #[serde(default = "default_rgba_bits")]
    pub rgba_bits: u32,
    /// Bits per signed component of the quantized normal the lighting
    /// takes (the golden models' `quantize_normal`); an RTL build is made
    /// for one width (`_q` in its configuration's name when not 5).
    #[serde(default = "default_normal_bits")]
    pub normal_bits: u32,
}

fn default_pipelines() -> usize {
    4
}
fn default_voxel_bits() -> u32 {
    8
}
fn default_frac_bits() -> u32 {
    8
}
fn default_rgba_bits() -> u32 {
    8
}
/// The normal widths (`normal_bits`) the golden models and the RTL take:
/// the reciprocal-norm table, a word per `|q|²`, grows about fourfold a
/// bit (1 024 words at 5 bits, 65 536 at 8).
pub const NORMAL_BITS: std::ops::RangeInclusive<u32> = 3..=8;

fn default_normal_bits() -> u32 {
    5
}

impl Default for Hardware {
    fn default() -> Self {
        Hardware {
            pipelines: 4,
            voxel_bits: 8,
            frac_bits: 8,
            rgba_bits: 8,
            normal_bits: 5,
        }
    }
}

/// Largest scene file read: far beyond any real scene (a transfer function
/// of thousands of points is a few hundred kB).
pub const MAX_SCENE_BYTES: u64 = 16 << 20;
/// How long a scene read from a FIFO or device waits for data.
pub const PIPE_WAIT_MS: i32 = 10_000;

/// A scene file's text, read without blocking forever and without
/// reading more than [`MAX_SCENE_BYTES`]; a byte-order mark is skipped.
pub fn read_text(path: &Path) -> Result<String> {
    use std::io::Read;
    use std::os::unix::fs::OpenOptionsExt;
    use std::os::unix::io::AsRawFd;
    let io = |err| CubeError::Io {
        path: path.display().to_string(),
        err,
    };
    let meta = std::fs::metadata(path).map_err(io)?;
    if meta.is_dir() {
        return Err(scene_err(format!("{} is a directory", path.display())));
    }
    // Opening a FIFO for reading blocks until a writer comes: not so with
    // O_NONBLOCK, and poll then waits a bounded time for data.
    let f = std::fs::OpenOptions::new()
        .read(true)
        .custom_flags(libc::O_NONBLOCK)
        .open(path)
        .map_err(io)?;
    if !meta.is_file() {
        let mut pfd = libc::pollfd {
            fd: f.as_raw_fd(),
            events: libc::POLLIN,
            revents: 0,
        };
        // SAFETY: one pollfd this function owns.
        let ready = unsafe { libc::poll(&mut pfd, 1, PIPE_WAIT_MS) };
        if ready <= 0 {
            return Err(scene_err(format!(
                "{}: nothing to read after {} s (a FIFO with no writer?)",
                path.display(),
                PIPE_WAIT_MS / 1000
            )));
        }
        // SAFETY: fcntl on a descriptor this function owns.
        unsafe {
            let flags = libc::fcntl(f.as_raw_fd(), libc::F_GETFL);
            libc::fcntl(f.as_raw_fd(), libc::F_SETFL, flags & !libc::O_NONBLOCK);
        }
    }
    let mut bytes = Vec::new();
    f.take(MAX_SCENE_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(io)?;
    if bytes.len() as u64 > MAX_SCENE_BYTES {
        return Err(scene_err(format!(
            "{}: larger than {} MiB, not a scene",
            path.display(),
            MAX_SCENE_BYTES >> 20
        )));
    }
    let text = String::from_utf8(bytes)
        .map_err(|e| scene_err(format!("{}: not UTF-8 text ({e})", path.display())))?;
    Ok(match text.strip_prefix('\u{feff}') {
        Some(rest) => rest.to_string(),
        None => text,
    })
}

/// Longest message echoed from the parser: a value the user gave is
/// quoted in it, and may be megabytes long.
const MAX_MESSAGE: usize = 200;

/// `msg`, cut to [`MAX_MESSAGE`] characters with the length left out named.
fn truncated(msg: String) -> String {
    let n = msg.chars().count();
    if n <= MAX_MESSAGE {
        return msg;
    }
    let head: String = msg.chars().take(MAX_MESSAGE).collect();
    format!("{head}… ({} more characters)", n - MAX_MESSAGE)
}

fn scene_err(msg: impl Into<String>) -> CubeError {
    CubeError::Scene(msg.into())
}

/// Deserialise a struct from a JSON object only. serde's derived structs
/// also take a sequence (`"hardware": [1, 8, 8, 8, 5]` filled the fields in
/// order, silently); every struct-valued field of the scene, and the scene
/// itself, is read through this one function, which refuses an array in
/// one line naming the field.
pub(crate) fn object<'de, D, T>(d: D) -> std::result::Result<T, D::Error>
where
    D: Deserializer<'de>,
    T: Deserialize<'de>,
{
    d.deserialize_any(ObjectVisitor(PhantomData))
}

/// [`object`] for an optional struct: `null` or absent is `None`.
pub(crate) fn optional_object<'de, D, T>(d: D) -> std::result::Result<Option<T>, D::Error>
where
    D: Deserializer<'de>,
    T: Deserialize<'de>,
{
    d.deserialize_any(OptionalObjectVisitor(PhantomData))
}

struct ObjectVisitor<T>(PhantomData<T>);

impl<'de, T: Deserialize<'de>> Visitor<'de> for ObjectVisitor<T> {
    type Value = T;
    fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str("an object")
    }
    fn visit_map<A: MapAccess<'de>>(self, map: A) -> std::result::Result<T, A::Error> {
        T::deserialize(de::value::MapAccessDeserializer::new(map))
    }
    fn visit_seq<A: SeqAccess<'de>>(self, _: A) -> std::result::Result<T, A::Error> {
        Err(de::Error::custom(ARRAY_FOR_OBJECT))
    }
}

struct OptionalObjectVisitor<T>(PhantomData<T>);

impl<'de, T: Deserialize<'de>> Visitor<'de> for OptionalObjectVisitor<T> {
    type Value = Option<T>;
    fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str("an object or null")
    }
    fn visit_unit<E: de::Error>(self) -> std::result::Result<Option<T>, E> {
        Ok(None)
    }
    fn visit_none<E: de::Error>(self) -> std::result::Result<Option<T>, E> {
        Ok(None)
    }
    fn visit_map<A: MapAccess<'de>>(self, map: A) -> std::result::Result<Option<T>, A::Error> {
        T::deserialize(de::value::MapAccessDeserializer::new(map)).map(Some)
    }
    fn visit_seq<A: SeqAccess<'de>>(self, _: A) -> std::result::Result<Option<T>, A::Error> {
        Err(de::Error::custom(ARRAY_FOR_OBJECT))
    }
}

const ARRAY_FOR_OBJECT: &str = "expected an object, found an array";

/// The scene itself, read through [`object`].
struct TopLevel(SceneSpec);

impl<'de> Deserialize<'de> for TopLevel {
    fn deserialize<D: Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        object(d).map(TopLevel)
    }
}

/// Parse scene JSON, naming the field at fault: `mode: unknown variant ...`,
/// `volume.dims: expected 3 values, found more`.
fn parse(text: &str) -> Result<SceneSpec> {
    let mut de = serde_json::Deserializer::from_str(text);
    let TopLevel(scene) = serde_path_to_error::deserialize(&mut de).map_err(|e| {
        let path = e.path().to_string();
        let inner = e.into_inner();
        let at = format!("line {} column {}", inner.line(), inner.column());
        let mut msg = inner.to_string();
        // serde_json appends the position; put it once at the end.
        if let Some(i) = msg.find(" at line ") {
            msg.truncate(i);
        }
        // A fixed-size array given too many values: serde_json says only
        // that characters trail where it expected the array's end.
        if path != "." {
            match msg.as_str() {
                "trailing characters" => msg = "too many values for this array".into(),
                // What serde_json says of a number or array where a name
                // (an enum) or other kind of value belongs.
                "expected value" => msg = "a value of the wrong kind or missing here".into(),
                _ => {}
            }
        }
        let msg = truncated(msg);
        if path == "." {
            scene_err(format!("{msg} ({at})"))
        } else {
            scene_err(format!("{path}: {msg} ({at})"))
        }
    })?;
    de.end()
        .map_err(|e| scene_err(format!("{e} after the scene object")))?;
    Ok(scene)
}

/// A validated scene: every bound checked, the light direction a unit
/// vector, a raw path resolved, the camera built. Only
/// [`SceneSpec::validate`] makes one; it reads as its spec.
#[derive(Debug, Clone)]
pub struct Scene {
    spec: SceneSpec,
    camera: Camera,
}

impl std::ops::Deref for Scene {
    type Target = SceneSpec;
    fn deref(&self) -> &SceneSpec {
        &self.spec
    }
}

impl Scene {
    /// Parse and validate a scene. Relative raw paths are resolved against
    /// `base` (the scene file's folder).
    pub fn from_json(text: &str, base: Option<&Path>) -> Result<Scene> {
        // A byte-order mark, as some editors write, is not JSON: skip it.
        let text = text.strip_prefix('\u{feff}').unwrap_or(text);
        let mut s = parse(text)?;
        if let (Some(raw), Some(base)) = (&s.volume.raw, base) {
            if raw.is_relative() {
                s.volume.raw = Some(base.join(raw));
            }
        }
        s.validate()
    }

    /// A copy of the validated spec, to change and validate again.
    pub fn spec(&self) -> SceneSpec {
        self.spec.clone()
    }

    /// This scene with `change` applied to its spec, validated again.
    pub fn with(&self, change: impl FnOnce(&mut SceneSpec)) -> Result<Scene> {
        let mut s = self.spec();
        change(&mut s);
        s.validate()
    }

    /// The scene is lit: a mode with colour, and shading enabled (the
    /// lighting's tables, and its normal width, matter only then).
    pub fn lit(&self) -> bool {
        self.mode.uses_colour() && self.shading.enabled
    }

    /// The camera this scene's view defines, in dataset voxel coordinates.
    pub fn camera(&self) -> Camera {
        self.camera.clone()
    }

    /// Read and validate a scene file: at most [`MAX_SCENE_BYTES`]; a FIFO
    /// or device is waited on for [`PIPE_WAIT_MS`] at most, so one with no
    /// writer is an error, not a hang.
    pub fn load(path: &Path) -> Result<Scene> {
        Scene::from_json(&read_text(path)?, path.parent())
    }
}

impl SceneSpec {
    /// Check every field, and normalise what renderers read: the light
    /// direction becomes a unit vector (scaled by its largest component
    /// first, so that neither 1e300 nor a subnormal overflows or vanishes).
    pub fn validate(mut self) -> Result<Scene> {
        self.check()?;
        self.shading.light_dir = match check_dir("shading.light_dir", self.shading.light_dir) {
            Ok(l) => l.to_array(),
            // Unused without shading: the default, so that no table or
            // register is built from an unchecked value.
            Err(_) if !self.shading.enabled => {
                DVec3::from_array(default_light()).normalize().to_array()
            }
            Err(e) => return Err(e),
        };
        let camera = Camera::new(&self.view, self.volume.render_dims(), self.image)?;
        Ok(Scene { spec: self, camera })
    }

    fn check(&self) -> Result<()> {
        let hw = &self.hardware;
        if ![8, 12, 16].contains(&hw.voxel_bits) {
            return Err(CubeError::Hardware(format!(
                "voxel_bits {} unsupported (8, 12 or 16)",
                hw.voxel_bits
            )));
        }
        // The 16x16 multiplier bounds the operands: a lerp multiplies a signed
        // (rgba_bits+1)-bit difference by a (frac_bits+1)-bit weight.
        if !(4..=15).contains(&hw.rgba_bits) {
            return Err(CubeError::Hardware(format!(
                "rgba_bits {} unsupported (4..=15: the lerp's signed difference must fit a 16-bit multiplier)",
                hw.rgba_bits
            )));
        }
        if !(2..=15).contains(&hw.frac_bits) {
            return Err(CubeError::Hardware(format!(
                "frac_bits {} unsupported (2..=15: the weight 1.0 = 2^frac_bits must fit a 16-bit multiplier)",
                hw.frac_bits
            )));
        }
        if !NORMAL_BITS.contains(&hw.normal_bits) {
            return Err(CubeError::Hardware(format!(
                "normal_bits {} unsupported (3..=8: the reciprocal-norm table grows fourfold a bit)",
                hw.normal_bits
            )));
        }
        if !hw.pipelines.is_power_of_two() || hw.pipelines > 16 {
            return Err(CubeError::Hardware(format!(
                "pipelines {} unsupported (1, 2, 4, 8 or 16)",
                hw.pipelines
            )));
        }
        self.cube3.validate(hw.voxel_bits)?;
        self.quantized.validate()?;
        let d = self.volume.dims;
        if d.iter().any(|n| !(2..=MAX_DIM).contains(n)) {
            return Err(CubeError::Volume(format!(
                "dims {d:?} out of range (each side 2..={MAX_DIM})"
            )));
        }
        if d.iter().product::<usize>() > MAX_VOXELS {
            return Err(CubeError::Volume(format!(
                "dims {d:?} exceed {MAX_VOXELS} voxels"
            )));
        }
        match (&self.volume.builtin, &self.volume.raw) {
            (Some(_), Some(_)) => return Err(scene_err("volume has both 'builtin' and 'raw'")),
            (None, None) => return Err(scene_err("volume needs 'builtin' or 'raw'")),
            (Some(b), None) => {
                if !BUILTINS.iter().any(|(n, _)| n == b) {
                    return Err(scene_err(format!(
                        "unknown builtin volume '{b}' (see `cube scenes`)"
                    )));
                }
                if self.volume.kind.is_some() || self.volume.window.is_some() {
                    return Err(scene_err("'type' and 'window' apply only to raw volumes"));
                }
                if let Some(w) = self.volume.shell {
                    if b != "sphere" {
                        return Err(scene_err(
                            "volume.shell applies only to the built-in sphere",
                        ));
                    }
                    if !(0.5..=crate::volume::MAX_SHELL).contains(&w) {
                        return Err(scene_err(format!(
                            "volume.shell {w} must lie in 0.5..={} voxels",
                            crate::volume::MAX_SHELL
                        )));
                    }
                }
            }
            (None, Some(_)) => {
                if self.volume.shell.is_some() {
                    return Err(scene_err(
                        "volume.shell applies only to the built-in sphere",
                    ));
                }
                if self.volume.kind.is_none() {
                    return Err(scene_err("raw volume needs 'type' (u8, u16 or i16)"));
                }
            }
        }
        if let Some(c) = self.volume.crop {
            // checked_add: an offset or size near usize::MAX must not wrap.
            let inside = (0..3).all(|a| {
                c.dims[a] >= 2
                    && c.offset[a]
                        .checked_add(c.dims[a])
                        .is_some_and(|e| e <= d[a])
            });
            if !inside {
                return Err(CubeError::Volume(format!(
                    "crop offset {:?} dims {:?} must lie inside dims {d:?} with each side >= 2",
                    c.offset, c.dims
                )));
            }
        }
        if let Some([lo, hi]) = self.volume.window {
            if !lo.is_finite() || !hi.is_finite() || hi <= lo {
                return Err(scene_err(format!(
                    "volume.window [{lo}, {hi}] must be finite with hi > lo"
                )));
            }
            if !(hi - lo).is_finite() {
                return Err(scene_err(format!(
                    "volume.window [{lo}, {hi}]: hi - lo overflows; give a window within ±1e300"
                )));
            }
        }
        let [w, h] = self.image;
        if w == 0 || h == 0 || w > MAX_IMAGE || h > MAX_IMAGE {
            return Err(scene_err(format!(
                "image [{w}, {h}] out of range (1..={MAX_IMAGE})"
            )));
        }
        self.validate_transfer()
    }

    fn validate_transfer(&self) -> Result<()> {
        let t = &self.transfer;
        let vmax = max_value(self.hardware.voxel_bits) as f64;
        let check_points = |name: &str, xs: Vec<f64>, ys: Vec<f64>, ymax: f64| -> Result<()> {
            if xs.is_empty() {
                return Err(scene_err(format!(
                    "transfer.{name} needs at least one point"
                )));
            }
            for w in xs.windows(2) {
                if w[1] < w[0] {
                    return Err(scene_err(format!(
                        "transfer.{name} points must be sorted by their first value"
                    )));
                }
            }
            if xs.iter().chain(ys.iter()).any(|v| !v.is_finite()) {
                return Err(scene_err(format!("transfer.{name} has a non-finite value")));
            }
            if ys.iter().any(|&y| !(0.0..=ymax).contains(&y)) {
                return Err(scene_err(format!(
                    "transfer.{name} values must lie in [0, {ymax}]"
                )));
            }
            Ok(())
        };
        check_points(
            "opacity",
            t.opacity.iter().map(|p| p[0]).collect(),
            t.opacity.iter().map(|p| p[1]).collect(),
            1.0,
        )?;
        check_points(
            "color",
            t.color.iter().map(|p| p[0]).collect(),
            t.color.iter().flat_map(|p| [p[1], p[2], p[3]]).collect(),
            1.0,
        )?;
        if let Some(g) = &t.gradient_opacity {
            check_points(
                "gradient_opacity",
                g.iter().map(|p| p[0]).collect(),
                g.iter().map(|p| p[1]).collect(),
                1.0,
            )?;
            // No gradient exceeds vmax * sqrt(3) / 2 voxel units per voxel
            // (half the central difference, per component), so larger
            // magnitudes could never be looked up.
            if g.iter().any(|p| p[0] < 0.0 || p[0] > vmax) {
                return Err(scene_err(format!(
                    "transfer.gradient_opacity magnitudes must lie in [0, {vmax}] for voxel_bits {}",
                    self.hardware.voxel_bits
                )));
            }
        }
        if t.opacity.iter().any(|p| p[0] < 0.0 || p[0] > vmax) {
            return Err(scene_err(format!(
                "transfer.opacity intensities must lie in [0, {vmax}] for voxel_bits {}",
                self.hardware.voxel_bits
            )));
        }
        if !(t.opaque_threshold > 0.0 && t.opaque_threshold <= 1.0) {
            return Err(scene_err("transfer.opaque_threshold must lie in (0, 1]"));
        }
        let s = &self.shading;
        for (n, v) in [
            ("ambient", s.ambient),
            ("diffuse", s.diffuse),
            ("specular", s.specular),
        ] {
            if !(0.0..=1.0).contains(&v) {
                return Err(scene_err(format!("shading.{n} {v} must lie in [0, 1]")));
            }
        }
        if !(s.shininess.is_finite() && s.shininess >= 0.0 && s.shininess <= 1000.0) {
            return Err(scene_err("shading.shininess must lie in [0, 1000]"));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const MIN: &str = r#"{"volume": {"builtin": "sphere", "dims": [16,16,16]}, "view": {"projection": "parallel"}}"#;

    #[test]
    fn minimal_scene_parses_with_defaults() {
        let s = Scene::from_json(MIN, None).unwrap();
        assert_eq!(s.hardware.pipelines, 4);
        assert_eq!(s.mode, Mode::Composite);
        assert_eq!(s.image, [256, 256]);
    }

    fn err_of(text: &str) -> String {
        Scene::from_json(text, None).unwrap_err().to_string()
    }

    #[test]
    fn bad_scenes_give_clear_errors() {
        assert!(
            err_of(&MIN.replace("\"view\"", "\"bogus\": 1, \"view\"")).contains("unknown field")
        );
        assert!(err_of(&MIN.replace("[16,16,16]", "[0,16,16]")).contains("out of range"));
        assert!(err_of(&MIN.replace("[16,16,16]", "[100000,16,16]")).contains("out of range"));
        assert!(err_of(&MIN.replace("sphere", "teapot")).contains("unknown builtin"));
        assert!(
            err_of(&MIN.replace("parallel\"", "parallel\", \"rotate_deg\": [1e999, 0, 0]"))
                .contains("scene")
        );
        assert!(err_of(&MIN.replace("}}", "}, \"mode\": \"bogus\"}")).contains("unknown variant"));
        let persp = MIN.replace(
            "\"projection\": \"parallel\"",
            "\"projection\": \"perspective\", \"eye\": [8,8,-20], \"up\": [0,0,0]",
        );
        assert!(err_of(&persp).contains("zero length"));
        let crop = MIN.replace(
            "[16,16,16]}",
            "[16,16,16], \"crop\": {\"offset\": [8, 0, 0], \"dims\": [9, 4, 4]}}",
        );
        assert!(err_of(&crop).contains("crop"));
        for (shell, why) in [("0.1", "must lie in"), ("17", "must lie in")] {
            let text = MIN.replace("[16,16,16]}", &format!("[16,16,16], \"shell\": {shell}}}"));
            let e = err_of(&text);
            assert!(
                e.contains("volume.shell") && e.contains(why),
                "{shell}: {e}"
            );
        }
        let ramp = MIN
            .replace("sphere\"", "ramp\"")
            .replace("[16,16,16]}", "[16,16,16], \"shell\": 2}");
        assert!(err_of(&ramp).contains("only to the built-in sphere"));
        let hw = MIN.replace("}}", "}, \"hardware\": {\"voxel_bits\": 10}}");
        assert!(err_of(&hw).contains("voxel_bits"));
        let hw = MIN.replace("}}", "}, \"hardware\": {\"rgba_bits\": 16}}");
        assert!(err_of(&hw).contains("rgba_bits"));
        for bad in [0, 2, 9, 4_000_000_000u32] {
            let hw = MIN.replace(
                "}}",
                &format!("}}, \"hardware\": {{\"normal_bits\": {bad}}}}}"),
            );
            assert!(err_of(&hw).contains("normal_bits"), "{bad}");
        }
        let hw = MIN.replace("}}", "}, \"hardware\": {\"pipelines\": 3}}");
        assert!(err_of(&hw).contains("pipelines"));
        for (q, field) in [
            (r#""subdivisions": 0"#, "quantized.subdivisions"),
            (r#""subdivisions": 257"#, "quantized.subdivisions"),
            (r#""normals": 1000"#, "quantized.normals"),
            (r#""normals": 8"#, "quantized.normals"),
            (r#""kernel": [0, 2]"#, "quantized.kernel"),
            (r#""kernel": [0.446, 1e999]"#, "scene"),
            (r#""order": "sideways""#, "unknown variant"),
            (r#""empty_space": "max""#, "unknown variant"),
            (r#""bogus": 1"#, "unknown field"),
        ] {
            let text = MIN.replace("}}", &format!("}}, \"quantized\": {{{q}}}}}"));
            let e = err_of(&text);
            assert!(e.contains(field), "{q}: {e}");
        }
    }

    #[test]
    fn parallel_rays_are_orthonormal() {
        let s = Scene::from_json(
            &MIN.replace("parallel\"", "parallel\", \"rotate_deg\": [70, 30, 0]"),
            None,
        )
        .unwrap();
        let c = s.camera();
        assert!((c.right.dot(c.up)).abs() < 1e-12);
        assert!((c.right.cross(c.up) - (-c.forward)).length() < 1e-12);
    }
}
