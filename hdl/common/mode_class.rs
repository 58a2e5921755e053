//! The rendering modes a build can switch between at run time. Composite
//! and first-opaque share the over operator (first-opaque's threshold lives
//! in the classification table), MIP and MinIP share the scalar compositor
//! (MinIP is a register bit), and X-ray has its sum: three kinds of
//! hardware, and a scene's mode picks one.

use scene::Mode;

/// The hardware a mode needs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ModeClass {
    /// Composite and first-opaque.
    Over,
    /// MIP and MinIP.
    Scalar,
    /// X-ray.
    Xray,
}

impl ModeClass {
    pub const ALL: [ModeClass; 3] = [ModeClass::Over, ModeClass::Scalar, ModeClass::Xray];

    pub fn of(mode: Mode) -> ModeClass {
        match mode {
            Mode::Composite | Mode::FirstOpaque => ModeClass::Over,
            Mode::Mip | Mode::Minip => ModeClass::Scalar,
            Mode::Xray => ModeClass::Xray,
        }
    }

    /// The mode the class is built as (the stages take a `Mode`; the other
    /// mode of the class is a register or a table away).
    pub fn mode(self) -> Mode {
        match self {
            ModeClass::Over => Mode::Composite,
            ModeClass::Scalar => Mode::Mip,
            ModeClass::Xray => Mode::Xray,
        }
    }

    /// The class's word in a configuration's name.
    pub fn name(self) -> &'static str {
        match self {
            ModeClass::Over => "composite",
            ModeClass::Scalar => "mip",
            ModeClass::Xray => "xray",
        }
    }

    /// The modes the class renders, for messages.
    pub fn modes(self) -> &'static str {
        match self {
            ModeClass::Over => "composite and first-opaque",
            ModeClass::Scalar => "MIP and MinIP",
            ModeClass::Xray => "X-ray",
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_mode_has_one_class_that_builds_as_a_mode_of_it() {
        for mode in [
            Mode::Composite,
            Mode::FirstOpaque,
            Mode::Mip,
            Mode::Minip,
            Mode::Xray,
        ] {
            let c = ModeClass::of(mode);
            assert_eq!(ModeClass::of(c.mode()), c);
        }
        assert_eq!(ModeClass::of(Mode::FirstOpaque), ModeClass::Over);
        assert_eq!(ModeClass::of(Mode::Minip), ModeClass::Scalar);
    }
}
