//! The register map by name: every register's (and every structured table
//! entry's) fields, each with its name, lowest bit, width and signedness
//! ([`MAP`]). The encoders (`cube4l::regs`, `cube3::regs`, the shader's
//! classification table) pack their words through it ([`pack`]), and
//! `docs/registers.md`'s address tables are generated from it
//! ([`markdown`]), so the words, their decoders' documentation and the
//! docs cannot drift apart. The hardware's decoders keep their own literal
//! bit offsets (`#[hdl_gen]` code); the co-simulations check them against
//! these words.

mod map;
pub mod markdown;

pub use map::MAP;

use crate::host::Reg;

/// One field of a word: bits `lsb .. lsb + bits`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Field {
    pub name: &'static str,
    pub lsb: u32,
    pub bits: u32,
    /// Two's complement (a negative value keeps its low `bits` bits).
    pub signed: bool,
    /// What the field holds; empty where the word's own doc says it.
    pub doc: &'static str,
}

impl Field {
    /// The field's bits, in place.
    pub fn mask(&self) -> u64 {
        (u64::MAX >> (64 - self.bits)) << self.lsb
    }

    /// `v`'s low `bits` bits, in place.
    pub fn place(&self, v: i64) -> u64 {
        ((v as u64) << self.lsb) & self.mask()
    }
}

/// A structured word of a lookup table (its window's entries share it).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Entry {
    /// The classification table (`host::Table::Classification`).
    Classification,
    /// Cube-3's increments tables (`host::ViewTable::Dx`, `Dy`).
    Increment,
    /// Cube-3's position tables (`host::ViewTable::PosX`, `PosY`).
    Pos,
    /// Cube-3's perspective groups (`host::ViewTable::Groups`).
    Group,
    /// Cube-3's lane bounds (`host::ViewTable::Bounds`, `Inner`).
    Bounds,
    /// Cube-3's lane voxels of a group (`host::ViewTable::GroupX`).
    GroupX,
}

/// What a layout describes: a register or a table's entries.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Word {
    Reg(Reg),
    Entry(Entry),
}

impl From<Reg> for Word {
    fn from(r: Reg) -> Word {
        Word::Reg(r)
    }
}

impl From<Entry> for Word {
    fn from(e: Entry) -> Word {
        Word::Entry(e)
    }
}

/// One word's fields, lowest first, and what it is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Layout {
    pub word: Word,
    /// The name the docs give it (a register's is its `Reg` variant's).
    pub name: &'static str,
    pub fields: &'static [Field],
    pub doc: &'static str,
}

impl Layout {
    /// The word holding `values`, which name every field in order.
    pub fn pack(&self, values: &[(&str, i64)]) -> u64 {
        let names: Vec<&str> = values.iter().map(|v| v.0).collect();
        let fields: Vec<&str> = self.fields.iter().map(|f| f.name).collect();
        assert_eq!(names, fields, "the fields of {}", self.name);
        self.fields
            .iter()
            .zip(values)
            .fold(0, |w, (f, &(_, v))| w | f.place(v))
    }
}

/// The layout of `word`.
pub fn layout(word: impl Into<Word>) -> &'static Layout {
    let word = word.into();
    MAP.iter()
        .find(|l| l.word == word)
        .unwrap_or_else(|| panic!("{word:?} is not in the register map"))
}

/// The word of `word` holding `values` (every field, by name, in order).
pub fn pack(word: impl Into<Word>, values: &[(&str, i64)]) -> u64 {
    layout(word).pack(values)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fields_fit_their_words_and_never_overlap() {
        for l in MAP {
            let mut used = 0u64;
            for f in l.fields {
                assert!(f.bits > 0 && f.lsb + f.bits <= 64, "{}.{}", l.name, f.name);
                assert_eq!(used & f.mask(), 0, "{}.{} overlaps", l.name, f.name);
                used |= f.mask();
            }
        }
        let words: Vec<Word> = MAP.iter().map(|l| l.word).collect();
        for (i, w) in words.iter().enumerate() {
            assert!(!words[..i].contains(w), "{w:?} twice");
        }
    }

    #[test]
    fn values_pack_into_their_fields() {
        assert_eq!(
            pack(Reg::Dims, &[("nx", 3), ("ny", 4), ("nz", 5)]),
            0x5_0004_0003
        );
        // Two's complement keeps a field's low bits, and a 64-bit field
        // the whole word.
        assert_eq!(
            pack(Reg::C3Origin, &[("u0", -1), ("v0", -2), ("offset", 7)]),
            0x7_fffe_ffff
        );
        assert_eq!(pack(Reg::Dx, &[("dx", -3)]), (-3i64) as u64);
        assert_eq!(
            pack(
                Reg::C3Schedule,
                &[
                    ("period_m1", 0x12_3456),
                    ("last_chunk", 0xab_cdef),
                    ("last_plane", 9)
                ]
            ),
            0x0009_abcd_ef12_3456
        );
        assert_eq!(
            pack(Entry::Increment, &[("magnitude", 5), ("negative", 1)]),
            0x1_0005
        );
    }

    #[test]
    #[should_panic(expected = "the fields of Dims")]
    fn a_misnamed_field_is_refused() {
        pack(Reg::Dims, &[("nx", 3), ("nz", 4), ("ny", 5)]);
    }
}
