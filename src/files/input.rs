//! The files a scene is read from (textures, environments, meshes, scene files): not a slide's lesson, but
//! what keeps a bad or hostile file from hanging the renderer, filling its memory or being written over.
//!
//! - Only regular files are read. A folder, a FIFO, a device or a socket is refused from its metadata before
//!   it is opened: opening a FIFO blocks until someone writes to it, and `/dev/zero` never ends. The file is
//!   opened non-blocking too, so that a FIFO put in its place between the check and the opening cannot block
//!   either, and it is checked again once open.
//! - Text files are read up to a cap ([`read_capped`]): a file larger than its cap is refused from its size
//!   before anything is read, and one that grows while it is read stops at the cap.
//! - Every file opened here is noted, so that a run can refuse to write its picture, or anything else, over
//!   one of its own inputs ([`check_not_an_input`]). The note is kept for the whole process: a run is one
//!   process, and the list only grows by the files the process reads.

use crate::files::error::{Error, Result};
use std::fs::File;
use std::io::Read;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// The canonical paths of the files this process has opened through [`open`].
static FILES_READ: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// What a file that is not a regular file is, for the message that refuses it.
pub(crate) fn kind(file_type: std::fs::FileType) -> &'static str {
    if file_type.is_dir() {
        return "a folder";
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if file_type.is_fifo() {
            return "a FIFO (named pipe)";
        }
        if file_type.is_char_device() || file_type.is_block_device() {
            return "a device";
        }
        if file_type.is_socket() {
            return "a socket";
        }
    }
    "not a regular file"
}

/// Fails unless `metadata` is a regular file's.
fn regular(metadata: &std::fs::Metadata, what: &'static str, path: &Path) -> Result<()> {
    if metadata.is_file() {
        return Ok(());
    }
    Err(Error::file(what, path, format!("it is {}, not a regular file", kind(metadata.file_type()))))
}

/// Opens the regular file at `path` for reading and returns it with its size in bytes; `what` says what
/// was being done in the error ("cannot read mesh"). Anything but a regular file is refused without
/// blocking (see the module documentation). The file is noted as one of this process's inputs.
pub fn open(path: &Path, what: &'static str) -> Result<(File, u64)> {
    let fail = |e: std::io::Error| Error::file(what, path, e);
    regular(&std::fs::metadata(path).map_err(fail)?, what, path)?;
    let mut options = std::fs::OpenOptions::new();
    options.read(true);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        // Reads of a regular file never block; a FIFO swapped in after the check is opened without waiting.
        options.custom_flags(libc::O_NONBLOCK);
    }
    let file = options.open(path).map_err(fail)?;
    let metadata = file.metadata().map_err(fail)?;
    regular(&metadata, what, path)?;
    if let Ok(canonical) = std::fs::canonicalize(path) {
        let mut read = FILES_READ.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
        if !read.contains(&canonical) {
            read.push(canonical);
        }
    }
    Ok((file, metadata.len()))
}

/// Reads the whole regular file at `path` ([`open`]), refusing one larger than `cap` bytes; `noun` names
/// the kind of file in that message ("a scene file").
pub fn read_capped(path: &Path, what: &'static str, noun: &str, cap: u64) -> Result<Vec<u8>> {
    let too_large =
        |size: String| Error::file(what, path, format!("it is {size} bytes long; {noun} may be at most {cap} bytes"));
    let (file, size) = open(path, what)?;
    if size > cap {
        return Err(too_large(size.to_string()));
    }
    let mut bytes = Vec::with_capacity(size as usize);
    // One byte past the cap tells a file that grew past it from one that ends exactly there.
    file.take(cap + 1).read_to_end(&mut bytes).map_err(|e| Error::file(what, path, e))?;
    if bytes.len() as u64 > cap {
        return Err(too_large(format!("more than {cap}")));
    }
    Ok(bytes)
}

/// Fails if writing `output` would replace one of the files this process has read (a texture, a mesh, a
/// scene file or a file it names, a reference picture): `what` names the output in the message ("the
/// picture"). Paths are compared once resolved, so another spelling of the same file, or a link to it, is
/// caught; an output that does not exist yet cannot be an input.
pub fn check_not_an_input(output: &Path, what: &str) -> Result<()> {
    let Ok(canonical) = std::fs::canonicalize(output) else { return Ok(()) };
    let read = FILES_READ.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
    if read.contains(&canonical) {
        return Err(Error::file(
            "refusing to write over an input",
            output,
            format!("{what} would replace a file this run reads; write it elsewhere with -o"),
        ));
    }
    Ok(())
}
