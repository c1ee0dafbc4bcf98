//! The renderer's errors. Every error a user can cause names the file or the value at fault, prints as one
//! line, and makes the examples exit with code 2; none of them is a panic. What an error echoes of its
//! input (a path, a value, a line of a file) is [`printable`]: a control character in it could otherwise
//! break the line, or with a carriage return overwrite it.

use std::path::{Path, PathBuf};

/// An error of the renderer: a file that cannot be read, decoded or written, or a parameter out of range.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// A file could not be read, decoded or written.
    #[error("{what} '{}': {}", printable(&.path.display().to_string()), printable(.reason))]
    File {
        /// What was being done, as the start of the message: "cannot read texture".
        what: &'static str,
        /// The file at fault.
        path: PathBuf,
        /// Why it failed: the underlying error (file system, decoder) or the scene file's line and message.
        reason: String,
    },
    /// A parameter is outside the range where it makes sense.
    #[error("invalid {name} {}: {}", printable(.value), printable(.reason))]
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

/// `text` with its control characters (C0 and C1: `\r`, `\n`, `\v`, escape sequences, ...) and the Unicode
/// line and paragraph separators written as escapes (`\r`, `\u{b}`, `\u{2028}`), so that it prints on the
/// line it is given and cannot rewrite what the terminal shows. The characters that look like a space or
/// like nothing (a no-break space, a zero-width space, a byte-order mark) are named, so that a value that
/// looks right but is refused shows why.
pub fn printable(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        if let Some(name) = invisible(c) {
            out.push_str(&format!("<U+{:04X} {name}>", c as u32));
        } else if c.is_control() || matches!(c, '\u{2028}' | '\u{2029}') {
            out.extend(c.escape_debug());
        } else {
            out.push(c);
        }
    }
    out
}

/// The name of a character that cannot be seen, or looks like a plain space.
fn invisible(c: char) -> Option<&'static str> {
    Some(match c {
        '\u{a0}' => "no-break space",
        '\u{202f}' => "narrow no-break space",
        '\u{200b}' => "zero-width space",
        '\u{200c}' => "zero-width non-joiner",
        '\u{200d}' => "zero-width joiner",
        '\u{2060}' => "word joiner",
        '\u{feff}' => "byte-order mark",
        _ => return None,
    })
}

/// The renderer's `Result`: [`Error`] unless another error type is named.
pub type Result<T, E = Error> = std::result::Result<T, E>;
