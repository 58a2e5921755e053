//! What the host writes into the hardware between frames, as the
//! VolumePro boards' hosts did: the view registers and the lookup tables,
//! through one write port (`host_write`, a 24-bit `host_address`, a 64-bit
//! `host_data`, one word a clock). The golden model computes exactly the
//! words the host writes, so a testbench can write them and the hardware
//! renders what the golden model renders.
//!
//! The address map (every register's fields are in [`crate::regmap`], and
//! `docs/registers.md`'s tables are generated from it):
//!
//! | addresses | what |
//! |---|---|
//! | `0x000000 ..= 0x0000ff` | registers, 64 bits each ([`Reg`]) |
//! | `0x010000 + i` | classification LUT entry `i` (`regmap::Entry::Classification`) |
//! | `0x020000 + i` | gradient-opacity LUT entry `(row << 4) | bin`: alpha |
//! | `0x030000 + i` | diffuse term by cosine index `i` |
//! | `0x031000 + i` | specular term by cosine index `i` |
//! | `0x040000 ..` | Cube-3's view tables ([`ViewTable`]) |
//!
//! A table occupies the low addresses of its window; each unit that holds a
//! copy of a table (a lane's shader, say) takes every write to its window,
//! so one write loads all copies at once.

use crate::fixed::max_of;
use crate::lut::{ColourLut, Lighting, OpacityLut};
use crate::regmap::{pack, Entry};
use scene::Mode;

/// One write of the host port.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Write {
    pub address: u32,
    pub data: u64,
}

/// Bits of the host port's address.
pub const ADDRESS_BITS: usize = 24;

/// The registers, by address; their fields are in [`crate::regmap::MAP`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
#[repr(u32)]
pub enum Reg {
    /// The shader's light and half vectors in the gradient's space
    /// (`lut::Lighting::light` and `half`).
    Light = 0x10,
    Half = 0x11,
    /// The gradient-opacity LUT's magnitude shift (`OpacityLut::gm_shift`
    /// plus the sample's fractional bits for Cube-3).
    GmShift = 0x12,
    /// Cube-4L's view (`cube4l::regs::ViewRegs`): the pipeline-space dims,
    Dims = 0x20,
    /// the slices,
    Slices = 0x21,
    /// the pipeline axes of dataset u, v, w,
    Axes = 0x22,
    /// the skewed memory's strides,
    Address = 0x23,
    /// the frame registers dx and dy,
    Dx = 0x24,
    Dy = 0x25,
    /// the negated eye,
    EyeX = 0x26,
    EyeY = 0x27,
    EyeZ = 0x28,
    /// the beats of a slice and of a beam,
    Beats = 0x29,
    /// the order and the scalar mode.
    Order = 0x2a,
    /// Cube-3's view (`cube3::regs`): the stream,
    C3Stream = 0x30,
    /// the traversal dims,
    C3Dims = 0x31,
    /// the memory's, rows' and templates' strides,
    C3Address = 0x32,
    /// the stream's first ray and scanline and the view's offset,
    C3Origin = 0x33,
    /// the fetch's schedule,
    C3Schedule = 0x34,
    /// the cast rays and scanlines,
    C3Cast = 0x35,
    /// the delay lines' lengths less one,
    C3Delays = 0x36,
    /// the ABC sample-plane lines' lengths less one,
    C3Lines = 0x37,
    /// and the 10-neighbourhood's weights and basis correction's rows (one
    /// set, a parallel view's).
    C3Weights10 = 0x38,
    C3Basis10X = 0x39,
    C3Basis10Y = 0x3a,
    C3Basis10Z = 0x3b,
}

impl Reg {
    pub fn address(self) -> u32 {
        self as u32
    }
}

/// The lookup tables, by window.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Table {
    /// Classification: colour and opacity by intensity (first-opaque's
    /// threshold applied).
    Classification,
    /// Opacity by intensity row and gradient-magnitude bin.
    GradientOpacity,
    /// The lighting terms by cosine index.
    Diffuse,
    Specular,
}

impl Table {
    pub fn base(self) -> u32 {
        match self {
            Table::Classification => 0x01_0000,
            Table::GradientOpacity => 0x02_0000,
            Table::Diffuse => 0x03_0000,
            Table::Specular => 0x03_1000,
        }
    }

    /// The writes that load `words` into the table from entry 0.
    pub fn writes(self, words: impl IntoIterator<Item = u64>) -> Vec<Write> {
        window_writes(self.base(), words)
    }
}

/// Cube-3's view tables, by window: each unit's (lane's) copy at its own
/// window where the lanes hold different words.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ViewTable {
    /// X-ray: opacity by intensity row.
    XrayOpacity,
    /// The ABC centre ray's increments `DX`, `DY` (sign in bit 16) by
    /// stream ray and scanline (one entry for a parallel view).
    Dx,
    Dy,
    /// Parallel: `X_k(u) - u` by plane. Perspective: unused.
    PosX,
    /// `Y_k(v) - v` by plane (parallel) or scanline and plane.
    PosY,
    /// Perspective: each de-fanning group's `plane | first ray << 16`.
    Groups,
    /// Lane `j`'s inside bounds and inner bounds by segment: `ray_lo |
    /// ray_hi << 16 | line_lo << 32 | line_hi << 48`.
    Bounds(usize),
    Inner(usize),
    /// Lane `j`'s template weights by (ray or scanline and) segment.
    Wx(usize),
    Wy(usize),
    /// Perspective: lane `j`'s voxel `x` of each group (bit 16: it holds a
    /// ray).
    GroupX(usize),
}

impl ViewTable {
    pub fn base(self) -> u32 {
        let lane = |base: u32, j: usize, stride: u32| {
            assert!(j < 8, "a table of lane {j}: at most 8 lanes");
            base + j as u32 * stride
        };
        match self {
            ViewTable::XrayOpacity => 0x04_0000,
            ViewTable::Dx => 0x05_0000,
            ViewTable::Dy => 0x06_0000,
            ViewTable::PosX => 0x07_0000,
            ViewTable::PosY => 0x20_0000,
            ViewTable::Groups => 0x24_0000,
            ViewTable::Bounds(j) => lane(0x0a_0000, j, 0x100),
            ViewTable::Inner(j) => lane(0x0a_1000, j, 0x100),
            ViewTable::Wx(j) => lane(0x10_0000, j, 0x1_0000),
            ViewTable::Wy(j) => lane(0x18_0000, j, 0x1_0000),
            ViewTable::GroupX(j) => lane(0x28_0000, j, 0x4_0000),
        }
    }

    /// The writes that load `words` into the table from entry 0.
    pub fn writes(self, words: impl IntoIterator<Item = u64>) -> Vec<Write> {
        window_writes(self.base(), words)
    }
}

/// The writes that load `words` into a window from `base`.
fn window_writes(base: u32, words: impl IntoIterator<Item = u64>) -> Vec<Write> {
    words
        .into_iter()
        .enumerate()
        .map(|(i, data)| Write {
            address: base + i as u32,
            data,
        })
        .collect()
}

/// Three signed components in 16-bit fields, x lowest: `Light`'s and
/// `Half`'s layout.
pub fn pack3(v: [i32; 3]) -> u64 {
    let [x, y, z] = v.map(|c| c as i64);
    pack(Reg::Light, &[("x", x), ("y", y), ("z", z)])
}

/// What a shader is built from: the golden model's tables, Cube-4L's or
/// Cube-3's.
#[derive(Debug, Clone, Copy)]
pub struct ShaderTables<'a> {
    pub mode: Mode,
    pub rgba_bits: u32,
    pub colour: Option<&'a ColourLut>,
    pub opacity: Option<&'a OpacityLut>,
    pub lighting: Option<&'a Lighting>,
    pub threshold: u32,
    /// Right shift of the gradient magnitude before the opacity LUT's own
    /// (Cube-3: the sample's fractional bits).
    pub magnitude_shift: u32,
}

impl ShaderTables<'_> {
    /// Opacity as the hardware's tables hold it: first-opaque's threshold
    /// applied (`alpha >= threshold ? M : 0`).
    fn alpha(&self, a: u32) -> u64 {
        match self.mode {
            Mode::FirstOpaque if a >= self.threshold => max_of(self.rgba_bits) as u64,
            Mode::FirstOpaque => 0,
            _ => a as u64,
        }
    }

    /// The classification LUT's words: `r | g << 16 | b << 32 | alpha << 48`
    /// (colour 0 without a colour LUT); empty without an opacity LUT.
    pub fn classification(&self) -> Vec<u64> {
        let Some(o) = self.opacity else {
            return vec![];
        };
        // With a gradient dimension the first bin of each row stands for
        // the row here; the gradient-opacity LUT holds every bin.
        let bins = if o.gm_shift.is_some() { 16 } else { 1 };
        (0..o.table.len() / bins)
            .map(|i| {
                let rgb = self.colour.map_or([0; 3], |c| c.table[i]);
                let [r, g, b] = rgb.map(|c| c as i64);
                let alpha = self.alpha(o.table[i * bins]) as i64;
                pack(
                    Entry::Classification,
                    &[("r", r), ("g", g), ("b", b), ("alpha", alpha)],
                )
            })
            .collect()
    }

    /// The gradient-opacity LUT's words; empty without gradient opacity.
    pub fn gradient_opacity(&self) -> Vec<u64> {
        match self.opacity {
            Some(o) if o.gm_shift.is_some() => o.table.iter().map(|&a| self.alpha(a)).collect(),
            _ => vec![],
        }
    }

    /// The gradient magnitude's total shift, with gradient opacity.
    pub fn gm_shift(&self) -> Option<u32> {
        self.opacity
            .and_then(|o| o.gm_shift)
            .map(|s| s + self.magnitude_shift)
    }

    /// The writes that load this shader's tables (units the scene leaves
    /// out get nothing).
    pub fn table_writes(&self) -> Vec<Write> {
        let mut w = Table::Classification.writes(self.classification());
        w.extend(Table::GradientOpacity.writes(self.gradient_opacity()));
        if let Some(l) = self.lighting {
            w.extend(Table::Diffuse.writes(l.diffuse.iter().map(|&d| d as u64)));
            w.extend(Table::Specular.writes(l.specular.iter().map(|&s| s as u64)));
        }
        w
    }

    /// The writes of this shader's registers.
    pub fn register_writes(&self) -> Vec<Write> {
        let mut w = Vec::new();
        if let Some(s) = self.gm_shift() {
            w.push(Write {
                address: Reg::GmShift.address(),
                data: s as u64,
            });
        }
        if let Some(l) = self.lighting {
            w.push(Write {
                address: Reg::Light.address(),
                data: pack3(l.light),
            });
            w.push(Write {
                address: Reg::Half.address(),
                data: pack3(l.half),
            });
        }
        w
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn signed_components_pack_into_16_bit_fields() {
        assert_eq!(pack3([0, 0, 0]), 0);
        assert_eq!(pack3([1, 2, 3]), 1 | 2 << 16 | 3 << 32);
        assert_eq!(pack3([-1, 0, -2048]), 0xffff | 0xf800 << 32);
    }

    #[test]
    fn tables_land_in_their_windows() {
        let w = Table::Specular.writes([7, 8]);
        assert_eq!(
            w,
            [
                Write {
                    address: 0x03_1000,
                    data: 7
                },
                Write {
                    address: 0x03_1001,
                    data: 8
                }
            ]
        );
        // The windows do not overlap the registers or each other.
        assert!(Reg::GmShift.address() < Table::Classification.base());
        assert!(Table::Classification.base() + 4096 <= Table::GradientOpacity.base());
        assert!(Table::GradientOpacity.base() + 65536 <= Table::Diffuse.base());
        assert!(Table::Diffuse.base() + 1024 <= Table::Specular.base());
        // Cube-3's view tables lie above them, each lane's in its own
        // window, aligned to its size.
        assert_eq!(ViewTable::Bounds(3).base(), 0x0a_0300);
        assert_eq!(ViewTable::Wy(7).base(), 0x1f_0000);
        assert!(Table::Specular.base() + 4096 <= ViewTable::XrayOpacity.base());
        assert!(ViewTable::Bounds(7).base() + 256 <= ViewTable::Inner(0).base());
        assert!(ViewTable::Inner(7).base() + 256 <= ViewTable::Wx(0).base());
        // The perspective tables of a 256 class: 2^18 rows and groups.
        assert!(ViewTable::Wy(7).base() + 0x1_0000 <= ViewTable::PosY.base());
        assert!(ViewTable::PosY.base() + 0x4_0000 <= ViewTable::Groups.base());
        assert!(ViewTable::Groups.base() + 0x4_0000 <= ViewTable::GroupX(0).base());
        assert!(ViewTable::GroupX(7).base() + 0x4_0000 <= 1 << ADDRESS_BITS);
    }
}
