//! The pictures a run writes (not a slide's lesson): which formats keep linear light, the checks before a
//! render that the output can be written, and the atomic save, so that a failed or interrupted run never
//! destroys an earlier picture nor leaves half a file.

use crate::files::error::{Error, Result};
use crate::files::input;
use std::io::BufWriter;
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use tempfile::NamedTempFile;

/// True for the files that keep linear light, floats above 1 included (`.exr`, `.hdr`); PNG and the other
/// 8-bit formats hold sRGB-encoded values from 0 to 1.
pub fn keeps_linear_light(path: &Path) -> bool {
    let ext = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
    matches!(ext.as_deref(), Some("exr" | "hdr"))
}

/// The format a picture written to `path` has, from its extension: `.png`, `.exr` or `.hdr`.
pub fn output_format(path: &Path) -> Result<image::ImageFormat> {
    let refuse = |reason: &str| Err(Error::file("cannot write image", path, reason));
    let name = path.file_name().map(|n| n.to_string_lossy().to_ascii_lowercase()).unwrap_or_default();
    // `.png` is a name without an extension to the file system: say what is missing, not what it lacks.
    if [".png", ".exr", ".hdr"].contains(&name.as_str()) {
        return refuse("the name before its extension is empty: write it as NAME.png, NAME.exr or NAME.hdr");
    }
    let ext = path.extension().and_then(|e| e.to_str()).map(str::to_ascii_lowercase);
    match ext.as_deref() {
        Some("png") => Ok(image::ImageFormat::Png),
        Some("exr") => Ok(image::ImageFormat::OpenExr),
        Some("hdr") => Ok(image::ImageFormat::Hdr),
        _ => refuse("the name must end in .png, .exr or .hdr"),
    }
}

/// How many bytes of the output's name the name of its temporary file keeps: enough to tell which picture
/// it becomes, few enough that the temporary name (these, two dots, [`RANDOM_CHARS`] and the suffix: 76
/// bytes at most) fits any file system's names (255 bytes on ext4, XFS, Btrfs, tmpfs and APFS, 143 with
/// eCryptfs) whatever the output's own name is.
const KEPT_NAME_BYTES: usize = 64;

/// The random characters of a temporary name, which make it new (tempfile's own count).
const RANDOM_CHARS: usize = 6;

/// What a temporary name ends with.
const TEMPORARY_SUFFIX: &str = ".tmp";

/// The part of a temporary name for `path` before its random characters: a dot (hidden), at most
/// [`KEPT_NAME_BYTES`] of the output's name (cut at a character), and a dot.
fn temporary_prefix(path: &Path) -> String {
    let name = path.file_name().map(|n| n.to_string_lossy()).unwrap_or_default();
    let mut end = name.len().min(KEPT_NAME_BYTES);
    while !name.is_char_boundary(end) {
        end -= 1;
    }
    format!(".{}.", &name[..end])
}

/// How many bytes the name of a temporary file for `path` has.
fn temporary_name_bytes(path: &Path) -> usize {
    temporary_prefix(path).len() + RANDOM_CHARS + TEMPORARY_SUFFIX.len()
}

/// The folder a picture at `path` goes in (`.` for a bare name).
fn folder_of(path: &Path) -> &Path {
    path.parent().filter(|d| !d.as_os_str().is_empty()).unwrap_or(Path::new("."))
}

/// Checks, before any work, that a picture can be written to `path` as [`save_atomically`] writes it: its
/// name names `format` when one is given (an 8-bit picture such as a debug view is PNG only) or one of
/// [`output_format`]'s; what is there already is a regular file that may be written (a FIFO, a device
/// node or a read-only file is refused: the rename would replace it with a regular file, or change the
/// mode a read-only file was given); and its folder takes the files the save makes, its temporary file and
/// the picture's own name. That is probed with a file whose name is as long as the longer of the two, made
/// and removed at once; where the folder does not exist yet, nothing is made for it: the nearest folder
/// that exists is probed with a folder of the longest name the save will make, removed at once, so that a
/// refused run leaves nothing behind.
pub fn check_output(path: &Path, format: Option<image::ImageFormat>) -> Result<()> {
    let refuse = |reason: String| Error::file("cannot write image", path, reason);
    let named = output_format(path)?;
    if let Some(format) = format.filter(|&f| f != named) {
        let ext = format.extensions_str()[0];
        return Err(refuse(format!("this picture is written as {format:?} only: its name must end in .{ext}")));
    }
    if let Ok(metadata) = std::fs::metadata(path) {
        if !metadata.is_file() {
            return Err(refuse(format!(
                "it is {}; a picture is written only as a regular file",
                input::kind(metadata.file_type())
            )));
        }
        if metadata.permissions().readonly() {
            return Err(refuse("it is read-only; make it writable, or write elsewhere with -o".into()));
        }
    }
    let name_bytes = path.file_name().map_or(0, |n| n.len());
    let file_name = name_bytes.max(temporary_name_bytes(path));
    // The folders the save would make, and the nearest one that exists.
    let mut existing = folder_of(path);
    let mut longest = file_name;
    let found = loop {
        match std::fs::metadata(existing) {
            Err(e) if e.kind() == std::io::ErrorKind::NotFound && folder_of(existing) != existing => {
                longest = longest.max(existing.file_name().map_or(0, |n| n.len()));
                existing = folder_of(existing);
            }
            found => break found,
        }
    };
    match found {
        Ok(metadata) if !metadata.is_dir() => {
            return Err(refuse(format!("'{}' is a file, not a folder", existing.display())));
        }
        Err(e) => return Err(refuse(format!("its folder '{}' cannot be read: {e}", existing.display()))),
        Ok(_) => {}
    }
    let made = if existing == folder_of(path) {
        probe_builder(file_name).tempfile_in(existing).map(drop)
    } else {
        probe_builder(longest).tempdir_in(existing).map(drop)
    };
    made.map_err(|e| {
        let folder = existing.display();
        if e.kind() == std::io::ErrorKind::InvalidFilename {
            refuse(format!("its folder '{folder}' takes no name of {longest} bytes, and the save would make one"))
        } else {
            refuse(format!("its folder '{folder}' takes no new file: {e}"))
        }
    })
}

/// A temporary file or folder of a name `bytes` long, for [`check_output`]'s probe.
fn probe_builder(bytes: usize) -> tempfile::Builder<'static, 'static> {
    const PREFIX: &str = ".probe.";
    let mut builder = tempfile::Builder::new();
    builder.prefix(PREFIX).rand_bytes(bytes.saturating_sub(PREFIX.len()).max(RANDOM_CHARS));
    builder
}

/// The temporary files being written now, which a signal that ends the process should not leave behind
/// (see [`remove_unfinished`]).
static UNFINISHED: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// Removes the temporary files being written now. For the handler of a signal that ends the process
/// (INT, TERM, HUP): the earlier picture stays as it was, and nothing half written is left beside it.
pub fn remove_unfinished() {
    let unfinished = UNFINISHED.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
    for path in unfinished.iter() {
        let _ = std::fs::remove_file(path);
    }
}

/// A temporary file listed in [`UNFINISHED`] while it lives.
struct Unfinished(PathBuf);

impl Unfinished {
    /// Creates a temporary file with `create` and lists it, holding the list's lock from before the file
    /// exists until it is listed: a signal's handler, which takes the lock first, finds every temporary file
    /// listed, however soon after its creation the signal comes.
    fn create(create: impl FnOnce() -> Result<NamedTempFile>) -> Result<(NamedTempFile, Unfinished)> {
        let mut unfinished = UNFINISHED.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
        let file = create()?;
        let path = file.path().to_path_buf();
        unfinished.push(path.clone());
        Ok((file, Unfinished(path)))
    }
}

impl Drop for Unfinished {
    fn drop(&mut self) {
        UNFINISHED.lock().unwrap_or_else(|poisoned| poisoned.into_inner()).retain(|p| *p != self.0);
    }
}

/// Removes the temporary files that earlier saves to `path` left in `dir` when they were killed (KILL
/// cannot be handled): the files of [`temporary_prefix`]'s name that no process holds locked. A save
/// holds its temporary file locked until it is renamed, and the lock ends with its process.
fn remove_stale(dir: &Path, path: &Path) {
    let prefix = temporary_prefix(path);
    let Ok(entries) = std::fs::read_dir(dir) else { return };
    for entry in entries.flatten() {
        let name = entry.file_name();
        let name = name.to_string_lossy();
        let ours =
            name.len() == temporary_name_bytes(path) && name.starts_with(&prefix) && name.ends_with(TEMPORARY_SUFFIX);
        // A regular file only (the type of the entry itself, a link not followed), opened without blocking.
        if !ours || !entry.file_type().is_ok_and(|t| t.is_file()) {
            continue;
        }
        let mut options = std::fs::OpenOptions::new();
        options.read(true);
        #[cfg(unix)]
        std::os::unix::fs::OpenOptionsExt::custom_flags(&mut options, libc::O_NONBLOCK | libc::O_NOFOLLOW);
        if let Ok(file) = options.open(entry.path())
            && file.try_lock().is_ok()
        {
            let _ = std::fs::remove_file(entry.path());
        }
    }
}

/// Removes the temporary files that saves to `path` left when their process was killed before it could
/// remove them (KILL, or a limit the kernel enforces): the rule the next save to `path` follows
/// ([`save_atomically`]), for a program that runs another and knows it will not write again (the class
/// command, after a student's program it stopped). A save in progress holds its file locked and keeps it.
pub fn remove_stale_temporaries(path: &Path) {
    remove_stale(folder_of(path), path);
}

/// Whether the open `file` still has a name: a save that found its new temporary file unlocked (before it
/// locked it) may have removed it as stale.
fn still_named(file: &std::fs::File) -> std::io::Result<bool> {
    #[cfg(unix)]
    return Ok(std::os::unix::fs::MetadataExt::nlink(&file.metadata()?) > 0);
    #[cfg(not(unix))]
    {
        // Elsewhere an open file cannot be removed.
        let _ = file;
        Ok(true)
    }
}

/// Writes a file through `write`, which is given a temporary file in the folder of `path` (made if needed):
/// a new file with a random name, created exclusively, so that it is never a file that exists already nor a
/// link planted at a name someone could guess, and short whatever the name of `path` (76 bytes at most).
/// It is renamed over `path` only when it is complete, so a failure never destroys an earlier file (the
/// temporary file is removed, and so it is when INT, TERM or HUP ends the run: [`remove_unfinished`]). It is
/// held locked while it is written; the unlocked temporary files of `path` that a killed run left are
/// removed first.
pub fn save_atomically(
    path: &Path,
    write: impl FnOnce(&mut BufWriter<NamedTempFile>) -> image::ImageResult<()>,
) -> Result<()> {
    let fail = |e: &dyn std::fmt::Display| Error::file("cannot write image", path, e);
    let dir = folder_of(path);
    std::fs::create_dir_all(dir).map_err(|e| Error::file("cannot create the folder for", path, e))?;
    remove_stale(dir, path);
    let prefix = temporary_prefix(path);
    let mut builder = tempfile::Builder::new();
    builder.prefix(&prefix).rand_bytes(RANDOM_CHARS).suffix(TEMPORARY_SUFFIX);
    // Readable as any new file is (0o666 less the umask), not only by its owner as temporary files are.
    #[cfg(unix)]
    builder.permissions(std::os::unix::fs::PermissionsExt::from_mode(0o666));
    let create = || loop {
        let temporary = builder.tempfile_in(dir).map_err(|e| fail(&e))?;
        temporary.as_file().lock().map_err(|e| fail(&e))?;
        if still_named(temporary.as_file()).map_err(|e| fail(&e))? {
            return Ok(temporary);
        }
    };
    let (temporary, _unfinished) = Unfinished::create(create)?;
    let mut file = BufWriter::new(temporary);
    write(&mut file).map_err(|e| fail(&e))?;
    let file = file.into_inner().map_err(|e| fail(e.error()))?;
    file.persist(path).map_err(|e| fail(&e.error))?;
    Ok(())
}
