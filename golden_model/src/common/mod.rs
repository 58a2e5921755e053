//! What the Cube-3 and Cube-4L golden models share, stage by stage: the view
//! planning helpers ([`plan`]: dominant axis, slab test, perspective ray
//! sums, compositing order), the gradient helpers of shading ([`gradient`]),
//! the one shader and classifier ([`shader`]), the compositing unit
//! ([`compositor`]) and the 2-D warp's shared parts ([`warp`]). Nothing here
//! depends on either architecture's folder.

pub mod compositor;
pub mod gradient;
pub mod plan;
pub mod shader;
pub mod warp;
