//! How a class is built: each submission as an example of the workbook's own package, in the workbook's
//! target folder, so that the library and every crate it depends on are the very build the workbook's
//! examples and the teacher's tool use, compiled once per clone. (Cargo names a build of a package that
//! is found by its path by that path relative to the workspace it is built in: a package of the class's
//! own that depends on the workbook by path builds the library again, under another name, whatever its
//! profiles and features.) The library is built before any submission, so that no student's build time
//! limit pays for it; then each submission is built alone (`cargo rustc --example`), under a time limit, so
//! that a compile error stops that student only.
//!
//! A submission is put into the workbook's `examples/` folder as `examples/<id>/main.rs` for the time of
//! its build only (cargo finds an example so), and its own code is built at `opt_level` (0 by default: a
//! twelfth of the time of the release profile's 3, and the render runs in the library, which keeps its own
//! optimisation; docs/class.md has the figures) and without debug information (a sixth of the size). The
//! program stays in the target folder's `release/examples/<id>`.

use lecture6::app::limits::{self, Ending, Limits};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

/// Where and how the class's submissions are built: as examples of the workbook's package.
pub struct ClassPackage {
    workbook: PathBuf,
    target: PathBuf,
    opt_level: u8,
}

/// One submission's build: the program, or the first compiler error.
#[derive(Clone, Debug, PartialEq)]
pub struct Built {
    /// The program built, or the first error (one line: where and what).
    pub program: Result<PathBuf, String>,
    /// How long the build took, in seconds.
    pub seconds: f64,
}

impl ClassPackage {
    /// The class built as examples of the workbook at `workbook`, into the target folder `target`; a
    /// submission's own code at `opt_level`.
    pub fn new(workbook: &Path, target: &Path, opt_level: u8) -> ClassPackage {
        ClassPackage { workbook: workbook.to_path_buf(), target: target.to_path_buf(), opt_level }
    }

    /// `cargo` with `args` on the workbook's manifest and into the class's target folder.
    fn cargo(&self, args: &[&str]) -> Command {
        let mut command = cargo(args);
        command.arg("--manifest-path").arg(self.workbook.join("Cargo.toml")).env("CARGO_TARGET_DIR", &self.target);
        command
    }

    /// Builds the workbook's library (and what it depends on; not the workbook's own programs) for the class,
    /// once, before any submission (a no-op where the workbook's examples or the teacher's tool built it
    /// already), its messages into the file `log`. Fails with the first error, naming the log.
    pub fn build_library(&self, limits: &Limits, log: &Path) -> Result<(), String> {
        let mut command = self.cargo(&["build", "--release", "--message-format", "short", "--lib"]);
        let finished = run_logged(&mut command, limits, log)?;
        if finished.ending.succeeded() {
            return Ok(());
        }
        let messages = std::fs::read_to_string(log).unwrap_or_default();
        let why = first_error(&messages, None).unwrap_or_else(|| format!("{:?}", finished.ending));
        Err(format!("the workbook's library does not build for the class: {why} (see {})", log.display()))
    }

    /// Builds `source` as the example `name` under `limits`, its compiler's messages into the file `log`,
    /// with `source` named by its file name alone in the first error.
    pub fn build(&self, name: &str, source: &Path, limits: &Limits, log: &Path) -> Result<Built, String> {
        let _placed = Placed::new(&self.workbook.join(placed_as(name)), source)?;
        let opt_level = format!("opt-level={}", self.opt_level);
        let mut command = self.cargo(&["rustc", "--release", "--message-format", "short", "--example", name]);
        command.args(["--", "-C", &opt_level, "-C", "debuginfo=0", "-C", "strip=debuginfo"]);
        let finished = run_logged(&mut command, limits, log)?;
        let seconds = finished.elapsed.as_secs_f64();
        let program = match finished.ending {
            Ending::Exited(0) => Ok(self.target.join("release").join("examples").join(name)),
            Ending::TimedOut => {
                Err(format!("the build was stopped at its time limit of {} s", limits.time.as_secs_f64()))
            }
            ending => {
                let messages = std::fs::read_to_string(log).unwrap_or_default();
                let short = source.file_name().map_or_else(|| name.into(), |f| f.to_string_lossy());
                let error = first_error(&messages, None).map(|e| e.replace(&placed_as(name), &short));
                Err(error.unwrap_or_else(|| format!("the build failed ({ending:?})")))
            }
        };
        Ok(Built { program, seconds })
    }
}

/// How the compiler names the file of the example `name` in its messages and a program's panics name it:
/// from the workbook's folder, where it was placed (a message is to name the submission's own file
/// instead).
pub fn placed_as(name: &str) -> String {
    format!("examples/{name}/main.rs")
}

/// A submission put into the workbook's `examples/` folder as `<folder>/main.rs` for the time of its build:
/// the folder is removed when it is dropped, whatever became of the build.
struct Placed {
    folder: PathBuf,
}

impl Placed {
    /// `source` copied to `file`, `<folder>/main.rs` (a folder of that name left by a build that was
    /// stopped is replaced).
    fn new(file: &Path, source: &Path) -> Result<Placed, String> {
        let folder = file.parent().expect("a file in a folder of its own");
        let _ = std::fs::remove_dir_all(folder);
        std::fs::create_dir_all(folder).map_err(|e| format!("cannot create {}: {e}", folder.display()))?;
        let placed = Placed { folder: folder.to_path_buf() };
        std::fs::copy(source, file)
            .map_err(|e| format!("cannot copy {} to {}: {e}", source.display(), file.display()))?;
        Ok(placed)
    }
}

impl Drop for Placed {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.folder);
    }
}

/// `cargo` (the one running this program, if any) with `args`.
pub fn cargo(args: &[&str]) -> Command {
    let mut command = Command::new(std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into()));
    command.args(args);
    command
}

/// Runs `command` under `limits`, its output and errors into the file `log` as it goes (a build's messages,
/// to be read while it runs), its input closed.
pub fn run_logged(command: &mut Command, limits: &Limits, log: &Path) -> Result<limits::Finished, String> {
    let file = std::fs::File::create(log).map_err(|e| format!("cannot write {}: {e}", log.display()))?;
    let err = file.try_clone().map_err(|e| format!("cannot write {}: {e}", log.display()))?;
    command.stdin(Stdio::null()).stdout(file).stderr(err);
    limits::run(command, limits).map_err(|e| format!("cannot run {:?}: {e}", command.get_program()))
}

/// The first error in the compiler's messages (`--message-format short`: `file:line:column: error[E...]:
/// what`), with the file `source` named by its name alone; `None` when there is none.
pub fn first_error(messages: &str, source: Option<&Path>) -> Option<String> {
    let line = messages.lines().map(str::trim).find(|line| {
        (line.starts_with("error") || line.contains(": error"))
            && !line.starts_with("error: could not compile")
            && !line.contains("aborting due to")
    })?;
    Some(match source.and_then(|s| Some((s.to_str()?, s.file_name()?.to_str()?))) {
        Some((full, short)) => line.replace(full, short),
        None => line.to_string(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_first_error_is_the_compilers_first_with_the_file_named_shortly() {
        let source = Path::new("/class/hw1/alice.rs");
        let messages = "   Compiling class-submissions v0.0.0 (/class/build)\n\
            /class/hw1/alice.rs:3:5: warning: unused variable: `x`\n\
            /class/hw1/alice.rs:7:9: error[E0425]: cannot find value `y` in this scope\n\
            /class/hw1/alice.rs:9:1: error[E0308]: mismatched types\n\
            error: could not compile `class-submissions` (example \"s001_alice\") due to 2 previous errors\n";
        assert_eq!(
            first_error(messages, Some(source)).as_deref(),
            Some("alice.rs:7:9: error[E0425]: cannot find value `y` in this scope")
        );
        assert_eq!(first_error("error: could not compile `x`", Some(source)), None);
        assert_eq!(
            first_error("error[E0601]: `main` function not found in crate `s001_alice`", None).as_deref(),
            Some("error[E0601]: `main` function not found in crate `s001_alice`")
        );
    }
}
