//! The renderer's errors. Every error a user can cause names the file or the value at fault, prints as one
//! line, and makes the examples exit with code 2; none of them is a panic.

use std::path::{Path, PathBuf};

#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// A file could not be read, decoded or written.
    #[error("{what} '{path}': {reason}")]
    File { what: &'static str, path: PathBuf, reason: String },
    /// A parameter is outside the range where it makes sense.
    #[error("invalid {name} {value}: {reason}")]
    Parameter { name: &'static str, value: String, reason: String },
}

impl Error {
    /// An error about the file at `path`; `what` says what was being done ("cannot read texture").
    pub fn file(what: &'static str, path: &Path, reason: impl ToString) -> Error {
        Error::File { what, path: path.to_path_buf(), reason: reason.to_string() }
    }
    /// An error about the parameter `name`, which was given `value`.
    pub fn parameter(name: &'static str, value: impl std::fmt::Display, reason: impl ToString) -> Error {
        Error::Parameter { name, value: value.to_string(), reason: reason.to_string() }
    }
}

pub type Result<T, E = Error> = std::result::Result<T, E>;
