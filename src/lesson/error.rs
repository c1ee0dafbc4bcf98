//! The renderer's errors. Every error a user can cause names the file or the value at fault, prints as one
//! line, and makes the examples exit with code 2; none of them is a panic. What an error echoes of its
//! input (a path, a value, a line of a file) is [`printable`]: a control character in it could otherwise
//! break the line, or with a carriage return overwrite it.

use std::path::{Path, PathBuf};

#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// A file could not be read, decoded or written.
    #[error("{what} '{}': {}", printable(&.path.display().to_string()), printable(.reason))]
    File { what: &'static str, path: PathBuf, reason: String },
    /// A parameter is outside the range where it makes sense.
    #[error("invalid {name} {}: {}", printable(.value), printable(.reason))]
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

/// `text` with its control characters (C0 and C1: `\r`, `\n`, `\v`, escape sequences, ...) and the Unicode
/// line and paragraph separators written as escapes (`\r`, `\u{b}`, `\u{2028}`), so that it prints on the
/// line it is given and cannot rewrite what the terminal shows.
pub fn printable(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        if c.is_control() || matches!(c, '\u{2028}' | '\u{2029}') {
            out.extend(c.escape_debug());
        } else {
            out.push(c);
        }
    }
    out
}

pub type Result<T, E = Error> = std::result::Result<T, E>;
