//! The one error type for bad input: scene files, volume files, dimensions,
//! views and parameters. Every message is a single line for the CLI.

use thiserror::Error;

#[derive(Debug, Error)]
pub enum CubeError {
    #[error("scene: {0}")]
    Scene(String),
    #[error("volume: {0}")]
    Volume(String),
    #[error("view: {0}")]
    View(String),
    #[error("hardware: {0}")]
    Hardware(String),
    #[error("{path}: {err}")]
    Io { path: String, err: std::io::Error },
}

pub type Result<T> = std::result::Result<T, CubeError>;
