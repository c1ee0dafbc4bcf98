//! The renderer's errors. Every error a user can cause names the file or the value at fault, prints as one
//! line, and makes the examples exit with code 2; none of them is a panic.

use std::path::{Path, PathBuf};

/// An error of the renderer: a file that cannot be read, decoded or written, or a parameter out of range.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// A file could not be read, decoded or written.
    #[error("{what} '{path}': {reason}")]
    File {
        /// What was being done, as the start of the message: "cannot read texture".
        what: &'static str,
        /// The file at fault.
        path: PathBuf,
        /// Why it failed: the underlying error (file system, decoder) or the scene file's line and message.
        reason: String,
    },
    /// A parameter is outside the range where it makes sense.
    #[error("invalid {name} {value}: {reason}")]
    Parameter {
        /// What was given the value: an option (`--multiplier`) or a description ("side-by-side pictures").
        name: &'static str,
        /// The value it was given, as text.
        value: String,
        /// Why the value makes no sense ("must be between 0 and 1").
        reason: String,
    },
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

/// The renderer's `Result`: [`Error`] unless another error type is named.
pub type Result<T, E = Error> = std::result::Result<T, E>;
