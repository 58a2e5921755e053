//! The depths of the Cube-4L CFB's address and read pipelines (§3.1, the
//! CFB's skewed memory): what the counters' lead (`counter_lead`) and a
//! sweep's fill (`config::fill_clocks`) are counted from.

/// Registered stages of the CFB's address before the block-RAM read: the
/// skew and pipeline-to-dataset transform, the stride products, their sum.
pub const ADDRESS_STAGES: usize = 3;

/// Clocks from the CFB's registered address to its voxel on the lanes: the
/// block RAM's registered read, the register beside it and a relay register
/// beside the lane (`DepthRam::relay`; for external memory, the word's
/// registers after its one-clock read).
pub const READ_STAGES: usize = 3;
