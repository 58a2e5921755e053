//! The volume as DRAM holds it (Cube-4L §3.1's skewed CFB, laid out for a
//! burst memory): one copy of the skewed volume for each major axis, in
//! that sweep's pipeline order, as VolPack keeps one copy per principal
//! axis. In copy `a` the pipeline-space voxel `(x, y, z)` of a sweep along
//! dataset axis `a` sits in module `(x + y + z) mod p` at module address
//! `x div p + y·b + z·b·n_y` ([`super::cfb::skew`] in pipeline space, with
//! `b = ceil(n_x / p)`). At a beat `(N_s, N_B, N_b)` every lane reads the
//! same module address `N_b + N_B·b + N_s·b·n_y` (the skew puts the beat's
//! voxels in distinct modules), so one memory word holds the beat: the `p`
//! modules' voxels at that address, module `k` at byte `k·voxel_bytes`, and
//! a sweep reads its copy's words in increasing order, one a clock. Every
//! burst is used whole on every major axis; the single skewed copy of
//! [`super::cfb::SkewedMemory`] strides `b` or `b·n_v` words a clock on two
//! of the three. A lane past the end of a beam (`x >= n_x`) finds 0 in its
//! byte. Copies start on [`ALIGN`]-byte boundaries, so that no burst of up to
//! 256 beats of up to 16 bytes crosses one.
//!
//! The cost is memory: three copies of `p·b·n_y·n_z` voxels. The cost it
//! avoids is on chip: a brick layout needs a reorder buffer of block RAM,
//! and the shaded 256³ build has none left.

use super::cfb::skew;
use scene::volume::Volume;

/// A copy's first byte is a multiple of this: AXI4 bursts do not cross
/// 4 KiB, and 256 beats of 16 bytes are 4 KiB.
pub const ALIGN: usize = 4096;

/// Where one major axis's copy lies.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Copy {
    /// The dataset axis the sweeps of this copy run along (pipeline z).
    pub axis: usize,
    /// Pipeline axis `i` is dataset axis `perm[i]` (as [`super::plan::Sweep`]).
    pub perm: [usize; 3],
    /// Pipeline-space dims `[n_x, n_y, n_z]`.
    pub dims: [usize; 3],
    /// Words of a beam, `ceil(n_x / p)`, and of a slice, `b·n_y`.
    pub b: usize,
    pub slab: usize,
    /// First byte of the copy.
    pub base: usize,
}

impl Copy {
    /// The byte address of the word a sweep of this copy reads at beat
    /// `(n_s, n_beam, n_b)`: slice, beam and partial beam.
    pub fn beat_address(&self, word_bytes: usize, n_s: usize, n_beam: usize, n_b: usize) -> usize {
        self.base + (n_b + n_beam * self.b + n_s * self.slab) * word_bytes
    }

    /// Words of the copy: `b·n_y·n_z`.
    pub fn words(&self) -> usize {
        self.slab * self.dims[2]
    }
}

/// The layout of a volume for `p` pipelines: its word and the three copies.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DramLayout {
    pub p: usize,
    /// Bytes of a voxel: 1 for 8-bit voxels, 2 (little-endian) for 12 and 16.
    pub voxel_bytes: usize,
    /// Bytes of a word (a beat of all `p` lanes): `p·voxel_bytes`.
    pub word_bytes: usize,
    /// Copy `a` for the sweeps along dataset axis `a`.
    pub copies: [Copy; 3],
    /// Bytes of the image, every copy with its alignment.
    pub bytes: usize,
}

impl DramLayout {
    /// The layout of a `dims` volume of `bits`-bit voxels for `p` pipelines.
    pub fn new(dims: [usize; 3], bits: u32, p: usize) -> DramLayout {
        let voxel_bytes = if bits <= 8 { 1 } else { 2 };
        let word_bytes = p * voxel_bytes;
        let mut base = 0;
        let copies = std::array::from_fn(|axis| {
            // The sweep's permutation ([`super::plan::Sweep`]).
            let perm = [(axis + 1) % 3, (axis + 2) % 3, axis];
            let dims = perm.map(|a| dims[a]);
            let b = dims[0].div_ceil(p);
            let copy = Copy {
                axis,
                perm,
                dims,
                b,
                slab: b * dims[1],
                base,
            };
            base += (copy.words() * word_bytes).next_multiple_of(ALIGN);
            copy
        });
        DramLayout {
            p,
            voxel_bytes,
            word_bytes,
            copies,
            bytes: base,
        }
    }

    /// The memory image of `vol`: each copy's words, voxels little-endian,
    /// padding and alignment 0; an error when the memory cannot be had.
    pub fn image(&self, vol: &Volume) -> Result<Vec<u8>, std::collections::TryReserveError> {
        let mut out = Vec::new();
        out.try_reserve_exact(self.bytes)?;
        out.resize(self.bytes, 0u8);
        for c in &self.copies {
            let [nx, ny, nz] = c.dims;
            for z in 0..nz {
                for y in 0..ny {
                    for x in 0..nx {
                        let mut d = [0; 3];
                        d[c.perm[0]] = x;
                        d[c.perm[1]] = y;
                        d[c.perm[2]] = z;
                        let (k, i) = skew(x, y, z, self.p, c.b, ny);
                        let at = c.base + i * self.word_bytes + k * self.voxel_bytes;
                        let v = vol.get(d[0], d[1], d[2]).to_le_bytes();
                        out[at..at + self.voxel_bytes].copy_from_slice(&v[..self.voxel_bytes]);
                    }
                }
            }
        }
        Ok(out)
    }
}

/// The share of the bytes a burst memory moves that a sweep uses. `beats`
/// gives each beat's byte address of each lane's voxel (`voxel_bytes`
/// each; `None` for a padding lane, which uses nothing); the memory moves
/// `burst`-byte lines, and the reader keeps the last `buffers` lines it
/// fetched (least recently used out), so a line is fetched again only once
/// it has left them. `None` when nothing was read.
pub fn burst_efficiency(
    beats: impl IntoIterator<Item = Vec<Option<usize>>>,
    voxel_bytes: usize,
    burst: usize,
    buffers: usize,
) -> Option<f64> {
    let (mut used, mut fetched) = (0usize, 0usize);
    let mut kept: std::collections::VecDeque<usize> = Default::default();
    for a in beats.into_iter().flatten() {
        let Some(a) = a else { continue };
        used += voxel_bytes;
        let line = a / burst;
        match kept.iter().position(|&l| l == line) {
            Some(i) => {
                kept.remove(i);
            }
            None => fetched += burst,
        }
        kept.push_back(line);
        if kept.len() > buffers {
            kept.pop_front();
        }
    }
    (fetched > 0).then(|| used as f64 / fetched as f64)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn copies_are_aligned_and_hand_computed() {
        // 10×6×7 at 8 bits, p = 4: the x copy is (y, z, x) = 6×7×10, b = 2,
        // slab 14, 140 words of 4 bytes = 560 bytes, one 4 KiB page; the y
        // copy is (z, x, y) = 7×10×6, b = 2, slab 20, 120 words; the z copy
        // (x, y, z) = 10×6×7, b = 3, slab 18, 126 words.
        let l = DramLayout::new([10, 6, 7], 8, 4);
        assert_eq!((l.voxel_bytes, l.word_bytes), (1, 4));
        let c = l.copies;
        assert_eq!(
            (c[0].dims, c[0].b, c[0].slab, c[0].base),
            ([6, 7, 10], 2, 14, 0)
        );
        assert_eq!(
            (c[1].dims, c[1].b, c[1].slab, c[1].base),
            ([7, 10, 6], 2, 20, 4096)
        );
        assert_eq!(
            (c[2].dims, c[2].b, c[2].slab, c[2].base),
            ([10, 6, 7], 3, 18, 8192)
        );
        assert_eq!(l.bytes, 3 * 4096);
        assert_eq!(c[2].beat_address(4, 1, 2, 1), 8192 + (1 + 2 * 3 + 18) * 4);
        // 12-bit voxels take two bytes.
        assert_eq!(DramLayout::new([4, 4, 4], 12, 2).word_bytes, 4);
    }

    #[test]
    fn burst_efficiency_counts_what_a_stride_wastes() {
        // Four lanes reading 4 consecutive bytes a beat, 16-byte bursts:
        // every byte used.
        let linear = (0..16).map(|t| (0..4).map(|k| Some(4 * t + k)).collect());
        assert_eq!(burst_efficiency(linear, 1, 16, 4), Some(1.0));
        // Each lane 64 bytes from the next and 1024 bytes a beat: a burst
        // for every voxel, 1 byte of 16 used.
        let strided = (0..16).map(|t| (0..4).map(|k| Some(64 * k + 1024 * t)).collect());
        assert_eq!(burst_efficiency(strided, 1, 16, 4), Some(1.0 / 16.0));
        // A lane that stays in its line keeps it across the others' fetches:
        // lane k walks its own region byte by byte.
        let lanes = (0..16).map(|t| (0..4).map(|k| Some(4096 * k + t)).collect());
        assert_eq!(burst_efficiency(lanes, 1, 16, 4), Some(1.0));
        // Padding lanes use nothing; nothing read is not available.
        let pads = (0..4).map(|t| vec![Some(4 * t), None, None, None]);
        assert_eq!(burst_efficiency(pads, 1, 16, 4), Some(0.25));
        assert_eq!(burst_efficiency(std::iter::empty(), 1, 16, 4), None);
    }
}
