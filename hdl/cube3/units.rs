//! The Cube-3 units manifest: each optional unit of a [`Cube3System`]
//! (the configuration that builds it, as [`Units`], its instances, its
//! stage file), the [`LAYOUT`] of the emitted design in stage files with
//! its lint waivers, the pixel bus the flows log and the [`waves`] of a
//! trace, every instance and port name checked against the rust-hdl
//! structs by [`instance!`](crate::instance).

use super::abc_estimator::AbcEstimator;
use super::abc_gradient::AbcUnit;
use super::cfb::BeamFetch;
use super::compositor::Rpc;
use super::config::Cube3Config;
use super::groups::Groups;
use super::ray_control::RayControl;
use super::rpc_node::RpcNode;
use super::schedule::Schedule;
use super::trilin_lanes::TrilinLanes;
use super::{Cube3, Cube3System, Cube3SystemConfig};
use crate::common::shader::Shader;
use crate::common::units::{under, Layout, Seg::*, Stage, Unit, Wave, TOP};
use crate::instance;
use golden_model::cube3::plan::Neighbourhood;
use rust_hdl::prelude::{Bit, DFF};

/// The structs the names are checked against (any sizes do).
type System = Cube3System<1, 1, 1, 1>;
type Pipeline = Cube3<1, 1>;

/// The units a Cube-3 build has.
pub struct Units {
    pub perspective: bool,
    pub gradient: bool,
    /// The shaders (composite and first-opaque), with lighting and
    /// gradient opacity.
    pub shaders: bool,
    pub lighting: bool,
    pub gradient_opacity: bool,
    pub xray: bool,
    /// The 26-neighbourhood's sums, the 10's basis (with the gradient
    /// units).
    pub n26: bool,
    pub n10: bool,
}

impl Units {
    /// The units of a system.
    pub fn of_system(c: &Cube3SystemConfig) -> Units {
        let p = &c.pipeline;
        Units {
            perspective: p.perspective,
            gradient: p.abc.is_some(),
            shaders: p.shading.is_some(),
            lighting: p.shading.as_ref().is_some_and(|s| s.lighting.is_some()),
            gradient_opacity: p
                .shading
                .as_ref()
                .is_some_and(|s| s.opacity.as_ref().and_then(|o| o.gm_shift).is_some()),
            xray: p.opacity.is_some(),
            n26: p
                .abc
                .as_ref()
                .is_some_and(|a| a.neighbourhood == Neighbourhood::N26),
            n10: p
                .abc
                .as_ref()
                .is_some_and(|a| a.neighbourhood == Neighbourhood::N10),
        }
    }
}

/// The optional units, in the order reports list them.
pub const UNITS: &[Unit<Units>] = &[
    Unit {
        name: "de-fanning (a parallel view's beams shift as a whole: no group tables, one template entry a plane)",
        built: |u| u.perspective,
        within: None,
        instances: &[instance!(Groups<1>, groups), instance!(Groups<1>, group_x[*])],
        stage: "beam_fetch.v",
    },
    Unit {
        name: "abc_gradient_units (no gradient: MIP, MinIP, X-ray, or neither shading nor gradient opacity)",
        built: |u| u.gradient,
        within: None,
        instances: &[instance!(Pipeline, abc)],
        stage: "abc_unit.v",
    },
    Unit {
        name: "abc_26_sums (the 26-neighbourhood's weighted differences)",
        built: |u| u.n26,
        within: Some(|u| u.gradient),
        instances: &[instance!(AbcEstimator, sums26)],
        stage: "abc_unit.v",
    },
    Unit {
        name: "abc_10_basis (the 10-neighbourhood's lerps, basis correction and registers)",
        built: |u| u.n10,
        within: Some(|u| u.gradient),
        instances: &[
            instance!(AbcEstimator, basis10),
            instance!(AbcUnit<1, 1>, regs10),
        ],
        stage: "abc_unit.v",
    },
    Unit {
        name: "leaf_stage (composite and first-opaque take the shaders; disabled by constants, for synthesis to remove)",
        built: |u| !u.shaders,
        within: None,
        instances: &[],
        stage: "cube3.v",
    },
    Unit {
        name: "lighting (the normal's dot products, their tables and registers)",
        built: |u| u.lighting,
        within: Some(|u| u.shaders),
        instances: &[instance!(Shader, lighting), instance!(Shader, normal)],
        stage: "shader.v",
    },
    Unit {
        name: "gradient_opacity (the magnitude bin and its table)",
        built: |u| u.gradient_opacity,
        within: Some(|u| u.shaders),
        instances: &[instance!(Shader, alpha_gm), instance!(Shader, gm_bin)],
        stage: "shader.v",
    },
    Unit {
        name: "shaders (MIP, MinIP and X-ray take the leaf stage)",
        built: |u| u.shaders,
        within: None,
        instances: &[instance!(Pipeline, shade[*])],
        stage: "shader.v",
    },
    Unit {
        name: "rpc_over_operator_multipliers",
        built: |u| u.shaders,
        within: None,
        instances: &[
            instance!(RpcNode, ch_r),
            instance!(RpcNode, ch_g),
            instance!(RpcNode, ch_b),
            instance!(RpcNode, ch_a),
        ],
        stage: "rpc.v",
    },
    Unit {
        name: "opacity_table (X-ray only)",
        built: |u| u.xray,
        within: None,
        instances: &[instance!(Pipeline, opacity)],
        stage: "cube3.v",
    },
];

/// The pipeline's instances, under `top$pipeline`.
const PIPELINE: &str = instance!(System, pipeline);

/// The stage files of a Cube-3 system's design.
pub const LAYOUT: Layout = Layout {
    files: &[
        "top.v",
        "beam_fetch.v",
        "ray_control.v",
        "trilin_lanes.v",
        "trilin.v",
        "abc_unit.v",
        "shader.v",
        "cube3.v",
        "rpc.v",
    ],
    stages: &[
        Stage {
            path: &[Is(TOP)],
            file: "top.v",
        },
        Stage {
            path: &[Is(TOP), Is(instance!(System, fetch)), Rest],
            file: "beam_fetch.v",
        },
        Stage {
            path: &[
                Is(TOP),
                Is(PIPELINE),
                Is(instance!(Pipeline, control)),
                Rest,
            ],
            file: "ray_control.v",
        },
        Stage {
            path: &[
                Is(TOP),
                Is(PIPELINE),
                Is(instance!(Pipeline, lanes)),
                Is(instance!(TrilinLanes<1, 1>, units)),
                Rest,
            ],
            file: "trilin.v",
        },
        Stage {
            path: &[Is(TOP), Is(PIPELINE), Is(instance!(Pipeline, lanes)), Rest],
            file: "trilin_lanes.v",
        },
        Stage {
            path: &[Is(TOP), Is(PIPELINE), Is(instance!(Pipeline, rpc)), Rest],
            file: "rpc.v",
        },
        Stage {
            path: &[Is(TOP), Is(PIPELINE), Is(instance!(Pipeline, abc)), Rest],
            file: "abc_unit.v",
        },
        Stage {
            path: &[Is(TOP), Is(PIPELINE), Is(instance!(Pipeline, shade)), Rest],
            file: "shader.v",
        },
    ],
    other: "cube3.v",
    waivers: LINT_WAIVERS,
};

/// The stage of a cell of a synthesis report, from its instance path
/// without the top (`pipeline.lanes.units$1...`, split at `.` and `$`).
pub const CELL_STAGES: &[Stage] = &[
    Stage {
        path: &[Is(instance!(System, fetch)), Rest],
        file: "beam_fetch",
    },
    Stage {
        path: &[Is(PIPELINE), Is(instance!(Pipeline, control)), Rest],
        file: "ray_control",
    },
    Stage {
        path: &[
            Is(PIPELINE),
            Is(instance!(Pipeline, lanes)),
            Is(instance!(TrilinLanes<1, 1>, units)),
            Rest,
        ],
        file: "trilin",
    },
    Stage {
        path: &[Is(PIPELINE), Is(instance!(Pipeline, lanes)), Rest],
        file: "trilin_lanes",
    },
    Stage {
        path: &[Is(PIPELINE), Is(instance!(Pipeline, rpc)), Rest],
        file: "rpc",
    },
    Stage {
        path: &[Is(PIPELINE), Rest],
        file: "cube3",
    },
];

/// The lint waivers every emitted Cube-3 system needs beyond those of
/// every design (`common::units::lint_waivers`).
const LINT_WAIVERS: &str = r#"// The beam fetch's write addresses and load address are as wide as its
// largest memory: each module and buffer uses the low bits.
lint_off -rule UNUSEDSIGNAL -file "*beam_fetch.v" -match "*Bits of signal are not used: 'write_address$*"
lint_off -rule UNUSEDSIGNAL -file "*beam_fetch.v" -match "*Bits of signal are not used: 'load_address'*"
// A 2-DSB word and the X-ray opacity table store only the bits a voxel
// (an opacity) has: the rest of the 16- or 32-bit datapath word is unread.
lint_off -rule UNUSEDSIGNAL -file "*beam_fetch.v" -match "*Bits of signal are not used: 'write_data'*"
// The schedule's chunk counter (and its next value) is as wide as its
// 24-bit register field; the group tables take its low GROUP_BITS, a
// parallel chunk its low 16.
lint_off -rule UNUSEDSIGNAL -file "*beam_fetch.v" -match "*Bits of signal are not used: 'chunk'*"
lint_off -rule UNUSEDSIGNAL -file "*beam_fetch.v" -match "*Bits of signal are not used: 'chunk_next'*"
// The opacity table, as long as the scene's, takes the low bits of a unit's
// opacity row.
lint_off -rule UNUSEDSIGNAL -file "*cube3.v" -match "*Bits of signal are not used: 'row$*"
// The ray control's delayed word carries segment, ray, scanline and valid
// in 64 bits; the bits above valid are spare.
lint_off -rule UNUSEDSIGNAL -file "*ray_control.v" -match "*Bits of signal are not used: 'late$data_out'*"
// The inside and inner bits have one lane bit per unit of up to 8; with
// fewer units the lane bits above them are unused.
lint_off -rule UNUSEDPARAM -file "*ray_control.v" -match "*Parameter is not used: 'lane_bit$*"
lint_off -rule UNUSEDPARAM -file "*cube3.v" -match "*Parameter is not used: 'lane_bit$*"
lint_off -rule UNUSEDPARAM -file "*cube3.v" -match "*Parameter is not used: 'inner_bit$*"
// One flag word rides beside the units: the leaf stage or the shaders take
// its inside and inner bits, the RPC one clock later its valid, first and
// last bits;
lint_off -rule UNUSEDSIGNAL -file "*cube3.v" -match "*Bits of signal are not used: 'rpc_flags_q$q'*"
// its delay line through the ABC units stores only those bits;
lint_off -rule UNUSEDSIGNAL -file "*cube3.v" -match "*Bits of signal are not used: 'write_data'*"
// and after the accumulator only the last-segment flag is read.
lint_off -rule UNUSEDSIGNAL -file "*rpc.v" -match "*Bits of signal are not used: 'node_flags_q$*$q'*"
// The shaders' value is the sample's integer part, voxel bits wide: the
// top bits of s >> F are zero.
lint_off -rule UNUSEDSIGNAL -file "*cube3.v" -match "*Bits of signal are not used: 'index$*"
// The host port carries 64-bit words: each view register block keeps the
// fields its stage reads, each view table the bits of its entries, and a
// table's read address is as wide as its largest view's (the low bits
// address its words);
lint_off -rule UNUSEDSIGNAL -file "*.v" -match "*Bits of signal are not used: 'host_data'*"
lint_off -rule UNUSEDSIGNAL -file "*.v" -match "*Bits of signal are not used: 'regs$q$*'*"
lint_off -rule UNUSEDSIGNAL -file "*.v" -match "*Bits of signal are not used: 'address'*"
// the entry arithmetic of the templates and rows is 32 bits wide.
lint_off -rule UNUSEDSIGNAL -file "*ray_control.v" -match "*Bits of signal are not used: 'w?_entry'*"
lint_off -rule UNUSEDSIGNAL -file "*beam_fetch.v" -match "*Bits of signal are not used: 'row_entry'*"
// Each lane's sample-plane history offers all 27 taps; the neighbouring
// lanes read their middle ones (plane k), and only the first and the last
// lane's taps of the next and previous segment cross to the other end.
lint_off -rule UNUSEDSIGNAL -file "*abc_unit.v" -match "*Signal is not used: 'lanes$*$t*"
"#;
/// The pixel bus: a pixel a clock while `done`, its fields as the flows
/// log them (the ray's colour and opacity, and whether it met a sample).
pub const PIXEL_VALID: &str = instance!(System, done);
pub const PIXEL: [&str; 5] = [
    instance!(System, pixel_r),
    instance!(System, pixel_g),
    instance!(System, pixel_b),
    instance!(System, pixel_a),
    instance!(System, has_sample),
];

/// The signal groups of a trace of a system built for `c`, under `top`
/// (the design's scope).
pub fn waves(c: &Cube3Config, top: &str) -> Vec<Wave> {
    type Fetch = BeamFetch<1, 1, 1>;
    type Lanes = TrilinLanes<1, 1>;
    let fetch = format!("{top}.{}", instance!(System, fetch));
    let mut w: Vec<Wave> = vec![(
        "Beam fetch".into(),
        under(
            &format!("{fetch}.{}", instance!(Fetch, schedule)),
            &[
                (instance!(Schedule, writing), ""),
                (instance!(Schedule, period), "[15:0]"),
                (instance!(Schedule, plane), "[15:0]"),
                (instance!(Schedule, chunk), "[15:0]"),
                (instance!(Schedule, reading), ""),
                (instance!(Schedule, ray), "[15:0]"),
            ],
        ),
    )];
    let mut streams = vec![format!("{fetch}.{}", instance!(Fetch, valid))];
    let (cur, next) = (instance!(Fetch, cur), instance!(Fetch, next));
    for i in 0..c.p {
        streams.push(format!("{fetch}.{cur}${i}[15:0]"));
        streams.push(format!("{fetch}.{next}${i}[15:0]"));
    }
    w.push(("2-DSB streams".into(), streams));
    let pipe = format!("{top}.{PIPELINE}");
    type Control = RayControl<1, 1>;
    w.push((
        "Ray control".into(),
        under(
            &format!("{pipe}.{}", instance!(Pipeline, control)),
            &[
                (instance!(Control, first), ""),
                (instance!(Control, unit_valid), ""),
                (instance!(Control, unit_first), ""),
                (instance!(Control, unit_last), ""),
                (instance!(Control, in_volume), "[7:0]"),
            ],
        ),
    ));
    let lanes = format!("{pipe}.{}", instance!(Pipeline, lanes));
    let (abc, shade) = (instance!(Pipeline, abc), instance!(Pipeline, shade));
    for i in 0..c.p {
        let mut sigs = vec![
            format!("{lanes}.{}${i}[15:0]", instance!(Lanes, wx)),
            format!("{lanes}.{}${i}[15:0]", instance!(Lanes, wy)),
            format!("{lanes}.{}${i}[31:0]", instance!(Lanes, sample)),
        ];
        if c.shading.is_none() {
            let q = instance!(DFF<Bit>, q);
            sigs.push(format!(
                "{pipe}.{}${i}.{q}[31:0]",
                instance!(Pipeline, leaf_q)
            ));
            sigs.push(format!(
                "{pipe}.{}${i}.{q}",
                instance!(Pipeline, leaf_valid_q)
            ));
        }
        w.push((format!("TRILIN {i}"), sigs));
        if c.shading.is_some() {
            let mut sigs = vec![];
            if c.abc.is_some() {
                type Abc = AbcUnit<1, 1>;
                for g in [
                    instance!(Abc, centre),
                    instance!(Abc, gx),
                    instance!(Abc, gy),
                    instance!(Abc, gz),
                ] {
                    sigs.push(format!("{pipe}.{abc}.{g}${i}[31:0]"));
                }
            }
            for (o, bits) in [
                (instance!(Shader, r), "[31:0]"),
                (instance!(Shader, g), "[15:0]"),
                (instance!(Shader, b), "[15:0]"),
                (instance!(Shader, a), "[15:0]"),
                (instance!(Shader, valid), ""),
            ] {
                sigs.push(format!("{pipe}.{shade}${i}.{o}{bits}"));
            }
            w.push((format!("ABC unit {i}"), sigs));
        }
    }
    w.push((
        "RPC".into(),
        under(
            &format!("{pipe}.{}", instance!(Pipeline, rpc)),
            &[
                (instance!(Rpc<1>, first), ""),
                (instance!(Rpc<1>, last), ""),
                (instance!(Rpc<1>, done), ""),
                (instance!(Rpc<1>, pixel_r), "[31:0]"),
                (instance!(Rpc<1>, pixel_a), "[15:0]"),
                (instance!(Rpc<1>, has_sample), ""),
            ],
        ),
    ));
    w
}
