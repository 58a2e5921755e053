//! The methods a run renders with (`--arch`), and the architectures with
//! RTL (`--arch` of `sim`, `verilog` and `synth`).

use clap::ValueEnum;

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Arch {
    Cube4l,
    /// The Cube-3 golden model (Sheared3D of the paper's §6).
    Cube3,
    /// Cube-3's discrete rays with exact tri-linear samples, in float.
    True3d,
    /// Cube-3's sheared tri-linear interpolation in float: the golden model
    /// without quantization (separates interpolation from quantization).
    ShearedFloat,
    /// The quantized-voxel path: voxel projection by quantized positions.
    QuantizedProjection,
    /// The quantized-voxel path: quantized splatting.
    QuantizedSplat,
    Reference,
}

impl Arch {
    /// Whether `--gradient` (an ABC neighbourhood) applies: Cube-3 and its
    /// float twins.
    pub fn takes_gradient(self) -> bool {
        matches!(self, Arch::Cube3 | Arch::True3d | Arch::ShearedFloat)
    }

    pub fn name(self) -> &'static str {
        match self {
            Arch::Cube4l => "cube4l",
            Arch::Cube3 => "cube3",
            Arch::True3d => "true3d",
            Arch::ShearedFloat => "sheared-float",
            Arch::QuantizedProjection => "quantized-projection",
            Arch::QuantizedSplat => "quantized-splat",
            Arch::Reference => "reference",
        }
    }
}

/// An architecture with RTL: the `--arch` of `sim`, `verilog` and `synth`.
#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum HwArch {
    /// Cube-4L: parallel and perspective views in every mode.
    Cube4l,
    /// Cube-3: parallel and perspective views in every mode (the 6 or the
    /// 12 gradient neighbourhood).
    Cube3,
}

impl HwArch {
    pub fn arch(self) -> cosim::archs::ArchName {
        match self {
            HwArch::Cube4l => cosim::archs::ArchName::Cube4l,
            HwArch::Cube3 => cosim::archs::ArchName::Cube3,
        }
    }
}
