//! The map itself: every register's fields, then the structured table
//! entries'. The table windows' addresses are `host::Table` and
//! `host::ViewTable`.

use super::{Entry, Field, Layout, Word};
use crate::host::Reg;

/// An unsigned field.
const fn u(name: &'static str, lsb: u32, bits: u32, doc: &'static str) -> Field {
    Field {
        name,
        lsb,
        bits,
        signed: false,
        doc,
    }
}

/// A two's-complement field.
const fn s(name: &'static str, lsb: u32, bits: u32, doc: &'static str) -> Field {
    Field {
        name,
        lsb,
        bits,
        signed: true,
        doc,
    }
}

const fn reg(r: Reg, name: &'static str, fields: &'static [Field], doc: &'static str) -> Layout {
    Layout {
        word: Word::Reg(r),
        name,
        fields,
        doc,
    }
}

const fn entry(
    e: Entry,
    name: &'static str,
    fields: &'static [Field],
    doc: &'static str,
) -> Layout {
    Layout {
        word: Word::Entry(e),
        name,
        fields,
        doc,
    }
}

const VECTOR: &[Field] = &[s("x", 0, 16, ""), s("y", 16, 16, ""), s("z", 32, 16, "")];
const BASIS_ROW: &[Field] = &[s("c0", 0, 16, ""), s("c1", 16, 16, ""), s("c2", 32, 16, "")];

/// Every register and structured table entry.
pub const MAP: &[Layout] = &[
    // The shader's, Cube-4L's and Cube-3's.
    reg(Reg::Light, "Light", VECTOR, "the light vector in the gradient's space"),
    reg(Reg::Half, "Half", VECTOR, "the half vector, as `Light`"),
    reg(
        Reg::GmShift,
        "GmShift",
        &[u("shift", 0, 8, "")],
        "the gradient magnitude's right shift before the gradient-opacity bins (the opacity LUT's, plus the sample's fractional bits for Cube-3)",
    ),
    // Cube-4L's view (`cube4l::regs`).
    reg(
        Reg::Dims,
        "Dims",
        &[u("nx", 0, 16, ""), u("ny", 16, 16, ""), u("nz", 32, 16, "")],
        "the sweep's pipeline-space dims",
    ),
    reg(
        Reg::Slices,
        "Slices",
        &[
            u("z0", 0, 16, ""),
            u("z1", 16, 16, ""),
            u("stream_z0", 32, 16, ""),
            u("stream_z1", 48, 16, ""),
        ],
        "the slices composited, `z0 ..= z1`, and those streamed (one halo slice more each end that lies in the dataset, with a gradient unit)",
    ),
    reg(
        Reg::Axes,
        "Axes",
        &[u("u", 0, 2, ""), u("v", 2, 2, ""), u("w", 4, 2, "")],
        "the pipeline axis (0 x, 1 y, 2 z) of dataset u, v, w",
    ),
    reg(
        Reg::Address,
        "Address",
        &[
            u("b_u", 0, 16, "partial beams per u beam, `⌈n_u/p⌉`"),
            u("slab", 16, 32, "partial beams per w slab, `b_u·n_v`"),
        ],
        "the skewed memory's strides",
    ),
    reg(
        Reg::Dx,
        "Dx",
        &[s("dx", 0, 64, "")],
        "parallel views: the frame register dx (the configuration's fractional bits)",
    ),
    reg(Reg::Dy, "Dy", &[s("dy", 0, 64, "")], "parallel views: dy, as `Dx`"),
    reg(
        Reg::EyeX,
        "EyeX",
        &[s("neg_eye", 0, 64, "")],
        "perspective views: the eye's x in pipeline space, negated (fixed point)",
    ),
    reg(Reg::EyeY, "EyeY", &[s("neg_eye", 0, 64, "")], "the eye's y, as `EyeX`"),
    reg(Reg::EyeZ, "EyeZ", &[s("neg_eye", 0, 64, "")], "the eye's z, as `EyeX`"),
    reg(
        Reg::Beats,
        "Beats",
        &[
            u("slice", 0, 32, "`ny·⌈nx/p⌉`"),
            u("beam", 32, 32, "`⌈nx/p⌉`"),
        ],
        "beats (clocks) of a slice and of a beam; the delay lines take their lengths from it, three clocks behind (each unit's own copy, `S - B`, then each line's length less one)",
    ),
    reg(
        Reg::Order,
        "Order",
        &[u("front_to_back", 0, 1, ""), u("minip", 1, 1, "MinIP rather than MIP")],
        "the sweep's order and the scalar modes' class",
    ),
    // Cube-3's view (`cube3::regs`).
    reg(
        Reg::C3Stream,
        "C3Stream",
        &[
            u("rays", 0, 16, "`R`"),
            u("scanlines", 16, 16, "`S`"),
            u("segments", 32, 16, "`G`"),
            u("planes_written", 48, 16, "a PRP's, `min(K + 1, G·p)`"),
        ],
        "the stream",
    ),
    reg(
        Reg::C3Dims,
        "C3Dims",
        &[u("n_x", 0, 16, ""), u("n_y", 16, 16, ""), u("k", 32, 16, "")],
        "the traversal dims `n_x`, `n_y`, `K`",
    ),
    reg(
        Reg::C3Address,
        "C3Address",
        &[
            u("b", 0, 16, "`⌈n_x/p⌉`"),
            u("b_n_y", 16, 16, "`b·n_y`"),
            u("row_stride", 32, 16, "perspective `K + 1`, parallel 0"),
            u("template_stride", 48, 16, "perspective `G`, parallel 0"),
        ],
        "the memory's strides, and the rows' and templates'",
    ),
    reg(
        Reg::C3Origin,
        "C3Origin",
        &[
            s("u0", 0, 16, ""),
            s("v0", 16, 16, ""),
            u("offset", 32, 16, "the view's `O`"),
        ],
        "the stream's first ray and scanline, and the view's offset",
    ),
    reg(
        Reg::C3Schedule,
        "C3Schedule",
        &[
            u("period_m1", 0, 24, "the scanline period less one"),
            u("last_chunk", 24, 24, "a PRP's last write chunk (parallel) or group (perspective)"),
            u("last_plane", 48, 16, "parallel: the last plane written; perspective 0"),
        ],
        "the fetch's schedule (24-bit period and chunk: a perspective 256 class has up to 132 612 groups a PRP)",
    ),
    reg(
        Reg::C3Cast,
        "C3Cast",
        &[
            u("ray_lo", 0, 16, ""),
            u("ray_span", 16, 16, "`ray_hi - ray_lo`"),
            u("line_lo", 32, 16, ""),
            u("line_span", 48, 16, "`line_hi - line_lo`"),
        ],
        "the rays and scanlines cast on this base plane (stream indices)",
    ),
    reg(
        Reg::C3Delays,
        "C3Delays",
        &[
            u("late_last", 0, 16, "the ray control's late line, the TRILIN cells' delay: `G`"),
            u("lane_last", 16, 16, "the lanes' counters: `G - 2`"),
            u("centre_last", 32, 16, "the ABC centre ray's increments: trilin latency + G - 1 (perspective; 0 parallel)"),
            u("flags_last", 48, 16, "the flags: ABC delay - 1"),
        ],
        "the delay lines' lengths less one",
    ),
    reg(
        Reg::C3Lines,
        "C3Lines",
        &[
            u("ray_last", 0, 16, "within a scanline: `G - 3`"),
            u("line_last", 16, 16, "from scanline to scanline: `T - 2G - 3`"),
        ],
        "the ABC sample-plane lines' lengths less one",
    ),
    reg(
        Reg::C3Weights10,
        "C3Weights10",
        &[u("t_x", 0, 16, ""), u("t_y", 16, 16, "")],
        "the 10-neighbourhood's weights `T` (`W` fractional bits; a parallel view's)",
    ),
    reg(
        Reg::C3Basis10X,
        "C3Basis10X",
        BASIS_ROW,
        "the 10-neighbourhood's basis correction, row x: `C_x0`, `C_x1`, `C_x2` (`W` fractional bits)",
    ),
    reg(Reg::C3Basis10Y, "C3Basis10Y", BASIS_ROW, "row y, as `C3Basis10X`"),
    reg(Reg::C3Basis10Z, "C3Basis10Z", BASIS_ROW, "row z, as `C3Basis10X`"),
    // The tables' structured entries.
    entry(
        Entry::Classification,
        "classification",
        &[
            u("r", 0, 16, ""),
            u("g", 16, 16, ""),
            u("b", 32, 16, ""),
            u("alpha", 48, 16, "first-opaque's threshold applied"),
        ],
        "colour and opacity by intensity",
    ),
    entry(
        Entry::Increment,
        "increment",
        &[u("magnitude", 0, 16, ""), u("negative", 16, 1, "")],
        "the ABC centre ray's increment `DX` or `DY`",
    ),
    entry(
        Entry::Pos,
        "position",
        &[s("delta", 0, 16, "")],
        "`X_k(u) - u` or `Y_k(v) - v`",
    ),
    entry(
        Entry::Group,
        "group",
        &[u("plane", 0, 16, ""), u("ray", 16, 16, "the group's first stream ray")],
        "a perspective de-fanning group",
    ),
    entry(
        Entry::Bounds,
        "bounds",
        &[
            u("ray_lo", 0, 16, ""),
            u("ray_hi", 16, 16, ""),
            u("line_lo", 32, 16, ""),
            u("line_hi", 48, 16, ""),
        ],
        "a lane's inclusive stream rays and scanlines of a plane (empty as lo > hi)",
    ),
    entry(
        Entry::GroupX,
        "group voxel",
        &[s("x", 0, 16, ""), u("holds", 16, 1, "the lane holds a ray")],
        "a lane's voxel `x` of a perspective group",
    ),
];
