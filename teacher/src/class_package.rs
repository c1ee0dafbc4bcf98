//! The package a class is built in: a throwaway Cargo package in the class's work folder that depends on
//! the workbook by path and has each submission as one of its examples. Its target folder is the
//! workbook's, and its manifest takes the workbook's profiles and lock file, so the dependencies the
//! workbook built are used as they are and the library is built once for the whole class; then each
//! submission is built alone (`cargo rustc --example`), under a time limit, so that a compile error stops
//! that student only.
//!
//! A submission's own code is built at `opt_level` (0 by default: a twelfth of the time of the release
//! profile's 3, and the render runs in the library, which keeps its own optimisation; docs/class.md has the
//! figures) and without debug information (a sixth of the size).

use lecture6::app::limits::{self, Ending, Limits};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use toml_edit::{DocumentMut, Item, Table, value};

/// The package's name, and so its crate's.
const NAME: &str = "class-submissions";

/// The throwaway package, written.
pub struct ClassPackage {
    manifest: PathBuf,
    target: PathBuf,
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
    /// Writes the package into `dir` for the workbook at `workbook`, with one example per `(name, source)`,
    /// built into the target folder `target`; a submission's own code at `opt_level`.
    pub fn create(
        dir: &Path,
        workbook: &Path,
        target: &Path,
        examples: &[(String, PathBuf)],
        opt_level: u8,
    ) -> Result<ClassPackage, String> {
        let io = |what: &str, path: &Path, e: std::io::Error| format!("cannot {what} {}: {e}", path.display());
        std::fs::create_dir_all(dir).map_err(|e| io("create the folder", dir, e))?;
        let workbook_manifest = workbook.join("Cargo.toml");
        let text =
            std::fs::read_to_string(&workbook_manifest).map_err(|e| io("read the manifest", &workbook_manifest, e))?;
        let workbook_doc: DocumentMut =
            text.parse().map_err(|e| format!("cannot read the manifest {}: {e}", workbook_manifest.display()))?;
        let manifest = dir.join("Cargo.toml");
        let text = manifest_text(&workbook_doc, workbook, examples, opt_level);
        std::fs::write(&manifest, text).map_err(|e| io("write", &manifest, e))?;
        // The workbook's versions of every dependency, so that its build of them is used.
        let lock = workbook.join("Cargo.lock");
        if lock.exists() {
            std::fs::copy(&lock, dir.join("Cargo.lock")).map_err(|e| io("copy", &lock, e))?;
        }
        // An example copied from the workbook finds the workbook's files beside the package's manifest
        // (`env!("CARGO_MANIFEST_DIR")/examples/data/...`), as it did beside the workbook's.
        for folder in ["examples", "textures"] {
            let link = dir.join(folder);
            if !link.exists() {
                link_folder(&workbook.join(folder), &link).map_err(|e| io("link", &link, e))?;
            }
        }
        Ok(ClassPackage { manifest, target: target.to_path_buf() })
    }

    /// Builds the workbook's library (and what it depends on; not the workbook's own programs) for the class,
    /// once, before any submission, so that no student's build time limit pays for it; its messages into the
    /// file `log`. Fails with the first
    /// error, naming the log.
    pub fn build_library(&self, limits: &Limits, log: &Path) -> Result<(), String> {
        let mut command = cargo(&["build", "--release", "--message-format", "short", "-p", "lecture6", "--lib"]);
        command.arg("--manifest-path").arg(&self.manifest).env("CARGO_TARGET_DIR", &self.target);
        let finished = run_logged(&mut command, limits, log)?;
        if finished.ending.succeeded() {
            return Ok(());
        }
        let messages = std::fs::read_to_string(log).unwrap_or_default();
        let why = first_error(&messages, None).unwrap_or_else(|| format!("{:?}", finished.ending));
        Err(format!("the workbook's library does not build for the class: {why} (see {})", log.display()))
    }

    /// Builds the example `name` under `limits`, its compiler's messages into the file `log`; `source` is
    /// its file, named by its file name alone in the first error.
    pub fn build(&self, name: &str, source: &Path, limits: &Limits, log: &Path) -> Result<Built, String> {
        let mut command = cargo(&["rustc", "--release", "--message-format", "short", "--example", name]);
        command
            .arg("--manifest-path")
            .arg(&self.manifest)
            .args(["--", "-C", "strip=debuginfo"])
            .env("CARGO_TARGET_DIR", &self.target);
        let finished = run_logged(&mut command, limits, log)?;
        let seconds = finished.elapsed.as_secs_f64();
        let program = match finished.ending {
            Ending::Exited(0) => Ok(self.target.join("release").join("examples").join(name)),
            Ending::TimedOut => {
                Err(format!("the build was stopped at its time limit of {} s", limits.time.as_secs_f64()))
            }
            ending => {
                let messages = std::fs::read_to_string(log).unwrap_or_default();
                Err(first_error(&messages, Some(source)).unwrap_or_else(|| format!("the build failed ({ending:?})")))
            }
        };
        Ok(Built { program, seconds })
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

/// The package's manifest: the examples, the workbook as a dependency (and clap, which the examples'
/// options derive from), and the workbook's profiles with the submissions' own code at `opt_level`.
fn manifest_text(workbook_doc: &DocumentMut, workbook: &Path, examples: &[(String, PathBuf)], opt_level: u8) -> String {
    let mut doc = DocumentMut::new();
    let mut package = Table::new();
    package["name"] = value(NAME);
    package["version"] = value("0.0.0");
    package["edition"] = value("2024");
    package["publish"] = value(false);
    // The linked `examples/` folder holds the workbook's examples, not the class's.
    package["autoexamples"] = value(false);
    doc["package"] = Item::Table(package);
    let mut dependencies = Table::new();
    let mut lecture6 = toml_edit::InlineTable::new();
    lecture6.insert("path", workbook.to_string_lossy().as_ref().into());
    dependencies["lecture6"] = value(lecture6);
    let mut clap = toml_edit::InlineTable::new();
    clap.insert("version", "4".into());
    clap.insert("features", toml_edit::Array::from_iter(["derive"]).into());
    dependencies["clap"] = value(clap);
    doc["dependencies"] = Item::Table(dependencies);
    let mut targets = toml_edit::ArrayOfTables::new();
    for (name, source) in examples {
        let mut example = Table::new();
        example["name"] = value(name.as_str());
        example["path"] = value(source.to_string_lossy().as_ref());
        targets.push(example);
    }
    doc["example"] = Item::ArrayOfTables(targets);
    let mut profile = workbook_doc.get("profile").cloned().unwrap_or_else(|| Item::Table(Table::new()));
    as_members(&mut profile, &members(workbook_doc));
    let own = &mut profile["release"]["package"][NAME];
    own["opt-level"] = value(i64::from(opt_level));
    own["debug"] = value(false);
    doc["profile"] = profile;
    doc["workspace"] = Item::Table(Table::new());
    doc.to_string()
}

/// The names of the workbook's own packages a class builds: the library's, and those it depends on by path
/// (not the optional ones: the class turns no feature on).
fn members(workbook_doc: &DocumentMut) -> Vec<String> {
    let package = workbook_doc.get("package").and_then(|p| p.get("name")).and_then(Item::as_str);
    let dependencies = workbook_doc.get("dependencies").and_then(Item::as_table_like);
    let by_path = dependencies.into_iter().flat_map(|deps| deps.iter()).filter_map(|(name, dependency)| {
        let optional = dependency.get("optional").and_then(Item::as_bool).unwrap_or(false);
        (dependency.get("path").is_some() && !optional).then(|| name.to_string())
    });
    package.map(String::from).into_iter().chain(by_path).collect()
}

/// Gives the workbook's own packages `members`, in the release profile of `profile`, the settings they have
/// in the workbook's workspace, where they are members: there the profile's `package."*"` (the
/// dependencies' settings, `debug = false`) does not apply to them, here it would, and the library would be
/// built again for the class with other settings. A setting the profile leaves at cargo's default is left as
/// `"*"` has it.
fn as_members(profile: &mut Item, members: &[String]) {
    let Some(release) = profile.get_mut("release").and_then(Item::as_table_like_mut) else { return };
    let all = release.get("package").and_then(|p| p.get("*")).and_then(Item::as_table_like);
    let own: Vec<(String, Item)> = all
        .into_iter()
        .flat_map(|all| all.iter())
        .filter_map(|(key, _)| Some((key.to_string(), release.get(key)?.clone())))
        .collect();
    for member in members {
        for (key, item) in &own {
            release.entry("package").or_insert(Item::Table(Table::new()))[member.as_str()][key.as_str()] = item.clone();
        }
    }
}

/// `link` made to lead to the folder `target`.
#[cfg(unix)]
fn link_folder(target: &Path, link: &Path) -> std::io::Result<()> {
    std::os::unix::fs::symlink(target, link)
}

/// Elsewhere the workbook's folders are not linked: an example that reads them by the package's folder
/// does not find them.
#[cfg(not(unix))]
fn link_folder(_target: &Path, _link: &Path) -> std::io::Result<()> {
    Ok(())
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

    #[test]
    fn the_manifest_takes_the_workbooks_profiles_and_lists_every_submission() {
        let workbook: DocumentMut = "[package]\nname = \"lecture6\"\n[dependencies]\nglam = \"0.34\"\n\
            protocol = { path = \"protocol\" }\nexercises = { path = \"exercises\", optional = true }\n\
            [profile.release]\ncodegen-units = 16\ndebug = \"line-tables-only\"\n\
            [profile.release.package.\"*\"]\ndebug = false\n"
            .parse()
            .expect("a manifest");
        let examples = [("s001_alice".to_string(), PathBuf::from("/class/hw \"1\"/alice.rs"))];
        let text = manifest_text(&workbook, Path::new("/work/lecture6"), &examples, 0);
        let doc: DocumentMut = text.parse().expect("the manifest written is TOML");
        assert_eq!(doc["example"][0]["path"].as_str(), Some("/class/hw \"1\"/alice.rs"));
        assert_eq!(doc["dependencies"]["lecture6"]["path"].as_str(), Some("/work/lecture6"));
        assert_eq!(doc["profile"]["release"]["codegen-units"].as_integer(), Some(16));
        assert_eq!(doc["profile"]["release"]["package"][NAME]["opt-level"].as_integer(), Some(0));
        // The library keeps the settings it has in the workbook, where `"*"` does not apply to it.
        assert_eq!(doc["profile"]["release"]["package"]["*"]["debug"].as_bool(), Some(false));
        let packages = doc["profile"]["release"]["package"].as_table_like().expect("the packages' settings");
        assert_eq!(packages.get("lecture6").and_then(|p| p["debug"].as_str()), Some("line-tables-only"));
        assert_eq!(packages.get("protocol").and_then(|p| p["debug"].as_str()), Some("line-tables-only"));
        // Not a registry crate, nor a package the class does not build (cargo warns of a setting for one).
        assert!(packages.get("glam").is_none() && packages.get("exercises").is_none());
    }
}
