//! The Cube-4L units manifest: each optional unit of a [`Pipeline`] (the
//! configuration that builds it, its instances, its stage file), the
//! [`LAYOUT`] of the emitted design in stage files with its lint waivers,
//! the pixel bus the flows log and the [`waves`] of a trace, every
//! instance and port name checked against the rust-hdl structs by
//! [`instance!`](crate::instance).

use super::abc_gradient::AbcGradient;
use super::cfb::Cfb;
use super::cfb_lane::CfbLane;
use super::compositor::Compositor;
use super::lane_feed::LaneFeed;
use super::pipe_lane::PipeLane;
use super::tap_network::TapNetwork;
use super::{Pipeline, PipelineConfig};
use crate::common::mode_class::ModeClass;
use crate::common::shader::Shader;
use crate::common::units::{under, Layout, Seg::*, Stage, Unit, Wave, TOP};
use crate::instance;

/// The structs the names are checked against (any sizes do).
type Top = Pipeline<1, 1, 1>;
type Lane = PipeLane<1>;
type Cfb1 = Cfb<1, 1>;

/// The optional units, in the order reports list them.
pub const UNITS: &[Unit<PipelineConfig>] = &[
    Unit {
        name: "abc_gradient",
        built: |c| c.gradient(),
        within: None,
        instances: &[instance!(LaneFeed<1>, abc), instance!(Top, late)],
        stage: "abc_gradient.v",
    },
    Unit {
        name: "lighting (the normal's dot products, their tables and registers)",
        built: |c| c.shading,
        within: None,
        instances: &[instance!(Shader, lighting), instance!(Shader, normal)],
        stage: "shader.v",
    },
    Unit {
        name: "classification_table",
        built: |c| c.mode != ModeClass::Scalar,
        within: None,
        instances: &[instance!(Shader, lut)],
        stage: "shader.v",
    },
    Unit {
        name: "gradient_opacity (the magnitude bin and its table)",
        built: |c| c.gradient_opacity,
        within: None,
        instances: &[instance!(Shader, alpha_gm), instance!(Shader, gm_bin)],
        stage: "shader.v",
    },
    Unit {
        name: "shading_and_weighting_multipliers",
        built: |c| c.mode == ModeClass::Over,
        within: None,
        instances: &[
            instance!(Shader, lit_r),
            instance!(Shader, lit_g),
            instance!(Shader, lit_b),
            instance!(Shader, mul_r),
            instance!(Shader, mul_g),
            instance!(Shader, mul_b),
        ],
        stage: "shader.v",
    },
    Unit {
        name: "sight_ray_divider",
        built: |c| c.perspective,
        within: None,
        instances: &[instance!(CfbLane<1>, div), instance!(Cfb1, lead)],
        stage: "divider.v",
    },
];

/// The CFB and the late CFB (the control a gradient unit needs).
const CFBS: &[&str] = &[instance!(Top, cfb), instance!(Top, late)];
/// A lane's instances, under `top$lanes$k`.
const LANES: &str = instance!(Top, lanes);

/// The stage files of a Cube-4L design. Each stage's file holds that
/// stage's modules of every pipeline.
pub const LAYOUT: Layout = Layout {
    files: &[
        "top.v",
        "cfb.v",
        "divider.v",
        "abc_gradient.v",
        "shader.v",
        "pipe_lane.v",
        "tap_network.v",
        "bilinear.v",
        "compositor.v",
    ],
    stages: &[
        Stage {
            path: &[Is(TOP)],
            file: "top.v",
        },
        Stage {
            path: &[
                Is(TOP),
                OneOf(CFBS),
                Is(instance!(Cfb1, lanes)),
                Any,
                Is(instance!(CfbLane<1>, div)),
                Rest,
            ],
            file: "divider.v",
        },
        Stage {
            path: &[Is(TOP), OneOf(CFBS), Is(instance!(Cfb1, lead)), Rest],
            file: "divider.v",
        },
        Stage {
            path: &[Is(TOP), OneOf(CFBS), Rest],
            file: "cfb.v",
        },
        Stage {
            path: &[
                Is(TOP),
                Is(LANES),
                Any,
                Is(instance!(Lane, feed)),
                Is(instance!(LaneFeed<1>, abc)),
                Rest,
            ],
            file: "abc_gradient.v",
        },
        Stage {
            path: &[Is(TOP), Is(LANES), Any, Is(instance!(Lane, shader)), Rest],
            file: "shader.v",
        },
        Stage {
            path: &[Is(TOP), Is(LANES), Any, Is(instance!(Lane, taps)), Rest],
            file: "tap_network.v",
        },
        Stage {
            path: &[Is(TOP), Is(LANES), Any, Is(instance!(Lane, bilinear)), Rest],
            file: "bilinear.v",
        },
        Stage {
            path: &[
                Is(TOP),
                Is(LANES),
                Any,
                Is(instance!(Lane, compositor)),
                Rest,
            ],
            file: "compositor.v",
        },
    ],
    other: "pipe_lane.v",
    waivers: LINT_WAIVERS,
};

/// The stage of a cell of a synthesis report, from its instance path
/// without the top (`lanes$0.bilinear.ch$0...`, split at `.` and `$`).
pub const CELL_STAGES: &[Stage] = &[
    Stage {
        path: &[
            OneOf(CFBS),
            Is(instance!(Cfb1, lanes)),
            Any,
            Is(instance!(CfbLane<1>, div)),
            Rest,
        ],
        file: "divider",
    },
    Stage {
        path: &[OneOf(CFBS), Is(instance!(Cfb1, lead)), Rest],
        file: "divider",
    },
    Stage {
        path: &[Is(instance!(Top, cfb)), Rest],
        file: "cfb",
    },
    Stage {
        path: &[Is(instance!(Top, late)), Rest],
        file: "cfb (late control)",
    },
    Stage {
        path: &[
            Is(LANES),
            Any,
            Is(instance!(Lane, feed)),
            Is(instance!(LaneFeed<1>, abc)),
            Rest,
        ],
        file: "abc_gradient",
    },
    Stage {
        path: &[Is(LANES), Any, Is(instance!(Lane, feed)), Rest],
        file: "lane_feed",
    },
    Stage {
        path: &[Is(LANES), Any, Is(instance!(Lane, shader)), Rest],
        file: "shader",
    },
    Stage {
        path: &[Is(LANES), Any, Is(instance!(Lane, taps)), Rest],
        file: "tap_network",
    },
    Stage {
        path: &[Is(LANES), Any, Is(instance!(Lane, cells)), Rest],
        file: "select2x2",
    },
    Stage {
        path: &[Is(LANES), Any, Is(instance!(Lane, bilinear)), Rest],
        file: "bilinear",
    },
    Stage {
        path: &[Is(LANES), Any, Is(instance!(Lane, compositor)), Rest],
        file: "compositor",
    },
    Stage {
        path: &[Is(LANES), Any, Is(instance!(Lane, ctl)), Rest],
        file: "control_delay",
    },
    Stage {
        path: &[Is(LANES), Rest],
        file: "pipe_lane",
    },
    // The host-loaded register file (`common/regs.rs`).
    Stage {
        path: &[Is(instance!(Top, view)), Rest],
        file: "regs",
    },
];

/// The lint waivers every emitted Cube-4L design needs beyond those of
/// every design (`common::units::lint_waivers`).
const LINT_WAIVERS: &str = r#"// The view registers are 64-bit words of 16-bit, or for the axes 2-bit,
// fields that the host writes; each stage reads the fields it needs, see
// docs/registers.md.
lint_off -rule UNUSEDSIGNAL -file "*cfb.v" -match "*Bits of signal are not used: 'dims'*"
lint_off -rule UNUSEDSIGNAL -file "*cfb.v" -match "*Bits of signal are not used: 'slices'*"
lint_off -rule UNUSEDSIGNAL -file "*cfb.v" -match "*Bits of signal are not used: 'axes'*"
lint_off -rule UNUSEDSIGNAL -file "*cfb.v" -match "*Bits of signal are not used: 'address_reg'*"
lint_off -rule UNUSEDSIGNAL -file "*cfb.v" -match "*Bits of signal are not used: 'beats'*"
lint_off -rule UNUSEDSIGNAL -file "*abc_gradient.v" -match "*Bits of signal are not used: 'beats'*"
lint_off -rule UNUSEDSIGNAL -file "*tap_network.v" -match "*Bits of signal are not used: 'beats'*"
lint_off -rule UNUSEDSIGNAL -file "*pipe_lane.v" -match "*Bits of signal are not used: 'dims'*"
lint_off -rule UNUSEDSIGNAL -file "*pipe_lane.v" -match "*Bits of signal are not used: 'order'*"
lint_off -rule UNUSEDSIGNAL -file "*compositor.v" -match "*Bits of signal are not used: 'order'*"
// dx and dy are 64-bit two's-complement words; their magnitude is at most
// one in the sweep's fraction bits, so a lane copies the sign and the low
// half only.
lint_off -rule UNUSEDSIGNAL -file "*cfb.v" -match "*Bits of signal are not used: 'dx'*"
lint_off -rule UNUSEDSIGNAL -file "*cfb.v" -match "*Bits of signal are not used: 'dy'*"
// Each CFB lane's dataset z and memory address are observability outputs:
// the CFB testbench compares them with the golden model's stream, and the
// waveforms show them; the pipeline itself needs neither.
lint_off -rule UNUSEDSIGNAL -file "*top.v" -match "*Signal is not used: 'cfb$z$*'*"
lint_off -rule UNUSEDSIGNAL -file "*top.v" -match "*Signal is not used: 'cfb$address$*'*"
// The late CFB, with a gradient unit, recomputes the control only: its voxel,
// memory port, sweep status and observability outputs are unread.
lint_off -rule UNUSEDSIGNAL -file "*top.v" -match "*Signal is not used: 'late$value$*'*"
lint_off -rule UNUSEDSIGNAL -file "*top.v" -match "*Signal is not used: 'late$ext_addr$*'*"
lint_off -rule UNUSEDSIGNAL -file "*top.v" -match "*Signal is not used: 'late$busy'*"
lint_off -rule UNUSEDSIGNAL -file "*top.v" -match "*Signal is not used: 'late$n_*'*"
lint_off -rule UNUSEDSIGNAL -file "*top.v" -match "*Signal is not used: 'late$bs'*"
lint_off -rule UNUSEDSIGNAL -file "*top.v" -match "*Signal is not used: 'late$z$*'*"
lint_off -rule UNUSEDSIGNAL -file "*top.v" -match "*Signal is not used: 'late$address$*'*"
// Delay lines and memory modules store only the bits the scene can set: the
// voxel bits of a voxel, and four channels of RGBA bits in the 16-bit slots
// of a composited word.
lint_off -rule UNUSEDSIGNAL -file "*" -match "*Bits of signal are not used: 'write_data'*"
// The bilinear unit's four channels share one 32-bit datapath, which X-ray
// needs for its sum in channel 0; channels 1-3 carry 16-bit values.
lint_off -rule UNUSEDSIGNAL -file "*pipe_lane.v" -match "*bilinear$out$*"
// The sight-ray divider's last stage leaves the remainders and the
// denominator behind: the quotients are all it answers.
lint_off -rule UNUSEDSIGNAL -file "*divider.v" -match "*Signal is not used: 'stages$16$*'*"
// The shader's r is as wide as Cube-3's RPC leaves (32 bits); a Cube-4L lane
// takes its low 16.
lint_off -rule UNUSEDSIGNAL -file "*pipe_lane.v" -match "*Bits of signal are not used: 'shader$r'*"
"#;
/// The pulse that counts a sweep's beats: lane 0's, one a clock.
pub const BEAT: &str = instance!(Top, res_beat[0]);
/// The pixel bus, arrays of a port per lane: the valid, and the fields
/// the flows log (base-plane x and y, face, composited value).
pub const PIXEL_VALID: &str = instance!(Top, px_valid);
pub const PIXEL: [&str; 4] = [
    instance!(Top, px_x),
    instance!(Top, px_y),
    instance!(Top, px_face),
    instance!(Top, res),
];

/// The signal groups of a trace of a `p`-lane build, under `top` (the
/// design's scope).
pub fn waves(p: u32, top: &str) -> Vec<Wave> {
    type Lane1 = CfbLane<1>;
    type Abc = AbcGradient<1>;
    let cfb = format!("{top}.{}", instance!(Top, cfb));
    let mut w: Vec<Wave> = vec![(
        "CFB".into(),
        under(
            &cfb,
            &[
                (instance!(Cfb1, valid), ""),
                (instance!(Cfb1, n_s), "[15:0]"),
                (instance!(Cfb1, n_beam), "[15:0]"),
                (instance!(Cfb1, n_b), "[15:0]"),
                (instance!(Cfb1, bs), ""),
            ],
        ),
    )];
    for k in 0..p {
        let cfb_lane = [
            (instance!(Lane1, x), "[15:0]"),
            (instance!(Lane1, y), "[15:0]"),
            (instance!(Lane1, z), "[15:0]"),
            (instance!(Lane1, value), "[15:0]"),
            (instance!(Lane1, address), "[31:0]"),
            (instance!(Lane1, pad), ""),
            (instance!(Lane1, halo), ""),
            (instance!(Lane1, sr), ""),
            (instance!(Lane1, er), ""),
            (instance!(Lane1, at_edge), ""),
            (instance!(Lane1, invalid), ""),
            (instance!(Lane1, face), "[2:0]"),
            (instance!(Lane1, dx_neg), ""),
            (instance!(Lane1, dx_mag), "[15:0]"),
            (instance!(Lane1, dy_neg), ""),
            (instance!(Lane1, dy_mag), "[15:0]"),
        ];
        w.push((
            format!("CFB lane {k}"),
            under(&format!("{cfb}.{}${k}", instance!(Cfb1, lanes)), &cfb_lane),
        ));
        let lane = format!("{top}.{LANES}${k}");
        let abc = [
            (instance!(Abc, value), "[15:0]"),
            (instance!(Abc, o_value), "[15:0]"),
            (instance!(Abc, gx_neg), ""),
            (instance!(Abc, gx_mag), "[15:0]"),
            (instance!(Abc, gy_neg), ""),
            (instance!(Abc, gy_mag), "[15:0]"),
            (instance!(Abc, gz_neg), ""),
            (instance!(Abc, gz_mag), "[15:0]"),
        ];
        let feed = instance!(Lane, feed);
        let abc_unit = instance!(LaneFeed<1>, abc);
        w.push((
            format!("ABC gradient {k}"),
            under(&format!("{lane}.{feed}.{abc_unit}"), &abc),
        ));
        let shader = [
            (instance!(Shader, valid), ""),
            (instance!(Shader, r), "[15:0]"),
            (instance!(Shader, g), "[15:0]"),
            (instance!(Shader, b), "[15:0]"),
            (instance!(Shader, a), "[15:0]"),
        ];
        w.push((
            format!("Shader {k}"),
            under(&format!("{lane}.{}", instance!(Lane, shader)), &shader),
        ));
        let (taps, a) = (instance!(Lane, taps), instance!(TapNetwork<1>, a));
        let mut signals: Vec<String> = (0..9)
            .map(|c| format!("{lane}.{taps}.{a}${c}[63:0]"))
            .collect();
        signals.extend(under(
            &lane,
            &[
                (instance!(Lane, res_valid), ""),
                (instance!(Lane, res), "[63:0]"),
            ],
        ));
        w.push((format!("Compositing lane {k}"), signals));
        w.push((
            format!("Pixel out {k}"),
            under(
                &lane,
                &[
                    (instance!(Lane, px_valid), ""),
                    (instance!(Lane, px_x), "[15:0]"),
                    (instance!(Lane, px_y), "[15:0]"),
                    (instance!(Lane, px_face), "[2:0]"),
                ],
            ),
        ));
    }
    w
}

/// The compositor's ports as `cube stage-vectors` drives and reads it on
/// its own: its clock; the accumulated and the new RGBA, the sample's
/// valid and the order register; the composited RGBA.
pub const COMPOSITOR_CLOCK: &str = instance!(Compositor, clock);
pub const COMPOSITOR_INPUTS: [&str; 10] = [
    instance!(Compositor, acc_r),
    instance!(Compositor, acc_g),
    instance!(Compositor, acc_b),
    instance!(Compositor, acc_a),
    instance!(Compositor, new_r),
    instance!(Compositor, new_g),
    instance!(Compositor, new_b),
    instance!(Compositor, new_a),
    instance!(Compositor, new_valid),
    instance!(Compositor, order),
];
pub const COMPOSITOR_OUTPUTS: [&str; 4] = [
    instance!(Compositor, out_r),
    instance!(Compositor, out_g),
    instance!(Compositor, out_b),
    instance!(Compositor, out_a),
];
