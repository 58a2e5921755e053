//! Synthesizable rust-hdl descriptions of the Cube-4L pipeline stages, one
//! stage per file, each matched bit for bit against the golden model in
//! `golden_model` by the testbenches. Present so far: [`compositor`] (the
//! compositing unit). The CFB, ABC gradient, shader, bilinear unit with its
//! compositing-buffer FIFO, and the p-pipeline top level are still to come.

pub mod compositor;
