//! `run`, every example's `main`: parse the options, then render and write the picture (comparing it with a
//! reference if asked) and print one summary line, or run one of the instruments the options ask for.

use super::commands;
use super::console::{print_clap, print_stderr, print_stdout};
use super::defaults::defaults_line;
use super::example::{Cli, Example};
use super::help::help_command;
use super::step_effect;
use crate::app::parameter_ranges::out_of_range;
use crate::files::output::{check_output, keeps_linear_light, save_atomically};
use crate::instruments::compare::{self, Reference};
use crate::lesson::error::{Error, Result, printable};
use crate::lesson::frame::Frame;
use crate::lesson::image_file::ImageFile;
use crate::lesson::input;
use crate::lesson::render::{WORKER_STACK_SIZE, render, thread_pool, worker_stacks};
use crate::lesson::spectral::SpectralPlan;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// The name of the running example: its binary's file name (`fresnel`, or `hw1` for a student's copy).
fn program_name() -> String {
    std::env::args_os()
        .next()
        .and_then(|arg0| Path::new(&arg0).file_stem().map(|s| s.to_string_lossy().into_owned()))
        .unwrap_or_else(|| "example".to_string())
}

/// Runs an example end to end (parse the options, build the scene, render, write the picture, compare it
/// with a reference if asked, print one summary line): the whole `main` of every example. The example's
/// name, which names its default output `out/<name>.png`, is its binary's.
pub fn run<E: Example>() -> ExitCode {
    run_as::<E>(&program_name(), std::env::args_os().skip(1).collect())
}

/// [`run`] under the example's name `name`, with the options `argv`: a program that runs the workbook's
/// examples by name (the exercises' `draw`) writes `out/<name>.png` as the example's own binary does.
pub fn run_as<E: Example>(name: &str, argv: Vec<std::ffi::OsString>) -> ExitCode {
    remove_unfinished_on_signals();
    let name = name.to_string();
    let args = match Cli::<E>::parse_args(&name, argv.iter().cloned()) {
        Ok(args) => args,
        // --help shows the defaults the example's scene sets; --help and --version print to stdout and succeed.
        Err(e) if e.kind() == clap::error::ErrorKind::DisplayHelp => {
            let argv = std::iter::once(std::ffi::OsString::from(&name)).chain(argv);
            return match help_command::<E>(&name).try_get_matches_from(argv) {
                Err(help) => clap_exit(&name, &help),
                Ok(_) => clap_exit(&name, &e),
            };
        }
        Err(e) if !e.use_stderr() => return clap_exit(&name, &e),
        Err(e) => return refuse(&format!("{name}: {}", one_line(&e.to_string()))),
    };
    if args.common.window {
        return open_window(&name, args, argv);
    }
    // Everything runs on `--threads` threads: the scene's loading and the picture's encoding are parallel
    // too (the render builds its own pool of the same size).
    match workers(args.common.threads).and_then(|pool| pool.install(|| run_parsed(&name, &args))) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => refuse(&format!("{name}: error: {e}")),
    }
}

/// The address space the C allocator (glibc's) may reserve for a run of `threads` worker threads: an arena for
/// each thread that allocates, the main thread's included, up to 8 arenas per core, each made by mapping
/// 128 MiB and keeping the 64 MiB aligned within it. The workers make theirs as they start, while the next
/// ones' stacks are mapped; a worker whose stack takes the last of the address space cannot make its signal
/// stack, and the process aborts.
fn allocator_arenas(threads: usize) -> u64 {
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    (threads + 1).min(8 * cores) as u64 * ARENA
}

/// The address space one arena of the C allocator maps ([`allocator_arenas`]).
const ARENA: u64 = 128 << 20;

/// The run's worker threads, `--threads` of them (the render, the photon map and the views run on them too),
/// each with a stack of [`WORKER_STACK_SIZE`]. Where the system limits the address space (`ulimit -v`, as
/// `/proc/self/limits` says), a count whose stacks do not fit beside what the process has taken and the
/// allocator's arenas ([`allocator_arenas`]) is refused before any thread starts, naming the option, what the
/// stacks need and how many threads fit. That count leaves room for one arena more than this run had taken:
/// whether the thread that waits for signals has made its arena before the check depends on timing, and the
/// count must fit in the next run too.
fn workers(threads: Option<usize>) -> Result<rayon::ThreadPool> {
    if let (Some(count), Some((limit, taken))) = (threads, address_space()) {
        let fits_beside =
            |taken: u64, n: usize| taken + n as u64 * WORKER_STACK_SIZE as u64 + allocator_arenas(n) <= limit;
        let fits = |n: usize| fits_beside(taken, n);
        if !fits(count) {
            let gib = |bytes: u64| bytes as f64 / (1u64 << 30) as f64;
            return Err(Error::parameter(
                "--threads",
                count,
                format!(
                    "{}; this process may take {:.1} GiB of address space (ulimit -v), {:.1} GiB are taken and the \
                     C allocator may reserve {:.1} GiB for the threads: at most {} fit",
                    worker_stacks(count),
                    gib(limit),
                    gib(taken),
                    gib(allocator_arenas(count)),
                    (1..count).take_while(|&n| fits_beside(taken + ARENA, n)).last().unwrap_or(0)
                ),
            ));
        }
    }
    thread_pool(threads).map_err(|e| match (e, threads) {
        (Error::Parameter { reason, .. }, Some(count)) => Error::parameter("--threads", count, reason),
        (e, _) => e,
    })
}

/// The address space this process may take (its soft limit) and has taken, in bytes, where the system
/// limits it and says so (Linux's `/proc/self/limits` and `/proc/self/status`).
fn address_space() -> Option<(u64, u64)> {
    let field = |file: &str, name: &str| -> Option<u64> {
        let text = std::fs::read_to_string(file).ok()?;
        text.lines().find_map(|line| line.strip_prefix(name)?.split_whitespace().next()?.parse().ok())
    };
    let limit = field("/proc/self/limits", "Max address space")?;
    Some((limit, field("/proc/self/status", "VmSize:")? * 1024))
}

/// A homework's own test (`cargo test --release --example hw1`, a `#[cfg(test)] mod tests` in its file):
/// renders the example `E` with the options `args`, as its binary would but without writing anything, and
/// returns its picture. Panics, failing the test, if the options are refused, the scene cannot be built, or
/// the end-of-run report says anything: a NaN or infinite sample, a ray that found the surface it left, a
/// ray made with `Ray::new` in a shader, a shader that returns more light than its rays and its light loop
/// brought it (N rays added up and not divided by N), a normal that is not of unit length, a ray traced in a
/// direction that is not, a shader that reads the wavelength without saying so, a course shader's parameter
/// outside the range it takes (a multiplier above 1). A correct shader, of one ray or of N, passes.
///
/// ```no_run
/// # use lecture6::prelude::*;
/// # #[derive(clap::Args, Clone, Debug)]
/// # pub struct Options {}
/// # impl Example for Options {
/// #     const DEFAULT_SPP: u32 = 1;
/// #     fn scene(&self) -> Result<Scene> { Ok(Scene::new(Camera::default())) }
/// # }
/// let picture = render_for_test::<Options>(&["--width", "80", "--height", "60", "--spp", "1"]);
/// assert_eq!(picture.width, 80);
/// ```
pub fn render_for_test<E: Example>(args: &[&str]) -> Frame {
    let (frame, warnings) = render_and_report::<E>(args).unwrap_or_else(|e| panic!("{e}"));
    assert!(warnings.is_empty(), "the end-of-run report of {args:?}:\n{}", warnings.join("\n"));
    frame
}

/// [`render_for_test`] for a test that decides for itself: renders the example `E` with the options `args`,
/// as its binary would but without writing anything, and returns its picture and the end-of-run report's
/// lines (none for a sound render) without judging them, so that the test's own assertion decides (that a
/// deliberately wrong shader is named, say). It never panics: options refused and a scene that cannot be
/// built are its error, on one line.
pub fn render_and_report<E: Example>(args: &[&str]) -> std::result::Result<(Frame, Vec<String>), String> {
    let cli = Cli::<E>::parse_args("homework", args).map_err(|e| format!("{args:?}: {}", one_line(&e.to_string())))?;
    let (scene, settings) = cli.prepare().map_err(|e| format!("{args:?}: {e}"))?;
    let (frame, stats) = render(&scene, &settings).map_err(|e| format!("{args:?}: {e}"))?;
    Ok((frame, [stats.warnings, out_of_range(&scene)].concat()))
}

/// Makes INT, TERM and HUP end the run as they would, after removing the temporary file of a picture being
/// written ([`crate::files::output::remove_unfinished`]): the earlier picture is kept as it was, and nothing half written is left.
/// Where the handler cannot be installed the run goes on without it.
#[cfg(unix)]
fn remove_unfinished_on_signals() {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    let Ok(mut signals) = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP]) else { return };
    std::thread::spawn(move || {
        for signal in signals.forever() {
            crate::files::output::remove_unfinished();
            let _ = signal_hook::low_level::emulate_default_handler(signal);
        }
    });
}

/// Elsewhere the signals end the run as they would.
#[cfg(not(unix))]
fn remove_unfinished_on_signals() {}

/// Prints `line` on stderr (if it can be written: there is nowhere else to say it) and returns exit code 2,
/// the code of every error.
fn refuse(line: &str) -> ExitCode {
    let _ = print_stderr(&format!("{line}\n"));
    ExitCode::from(2)
}

/// Prints what clap made of the command line (`--help`, `--version`) and returns clap's exit code, or 2
/// when it cannot be printed.
fn clap_exit(name: &str, message: &clap::Error) -> ExitCode {
    match print_clap(message) {
        Ok(()) => ExitCode::from(u8::try_from(message.exit_code()).unwrap_or(2)),
        Err(e) => refuse(&format!("{name}: error: {e}")),
    }
}

/// `--window`: the live viewer, with the options as given on the command line, and as its controls.
fn open_window<E: Example>(name: &str, args: Cli<E>, argv: Vec<std::ffi::OsString>) -> ExitCode {
    match super::controls::<E>(name, &argv) {
        Ok(controls) => crate::instruments::viewer::run(name, args, controls),
        Err(e) => refuse(&format!("{name}: {}", one_line(&e.to_string()))),
    }
}

/// A clap error message on one line: its lines joined, without the usage and the pointer to --help, and
/// what it echoes of the arguments [`printable`].
pub fn one_line(message: &str) -> String {
    let keep = |l: &&str| !(l.is_empty() || l.starts_with("Usage:") || l.starts_with("For more information"));
    printable(&message.lines().map(str::trim).filter(keep).collect::<Vec<_>>().join(" "))
}

/// Fails unless writing the picture to `output` (and its heat map to `heat_map`) leaves the reference
/// `reference` as it is: `-o REF.png --compare REF.png` would overwrite the reference with the render and
/// report a perfect match.
fn check_not_the_reference(reference: &Path, output: &Path, heat_map: &Path) -> Result<()> {
    let same_file = |a: &Path, b: &Path| matches!((resolved(a), resolved(b)), (Some(a), Some(b)) if a == b);
    for (what, path) in [("the picture", output), ("the heat map", heat_map)] {
        if same_file(reference, path) {
            return Err(Error::file(
                "refusing to write over the reference",
                reference,
                format!("{what} would go to {}; write the render elsewhere with -o", path.display()),
            ));
        }
    }
    Ok(())
}

/// The absolute path a file would have once written, links followed: each component of the path that
/// exists is resolved as the file system has it, the rest (a folder `save` would create) as written.
fn resolved(path: &Path) -> Option<PathBuf> {
    let mut resolved = PathBuf::new();
    for component in std::path::absolute(path).ok()?.components() {
        match component {
            std::path::Component::ParentDir => {
                resolved.pop();
            }
            std::path::Component::CurDir => {}
            part => {
                resolved.push(part);
                if let Ok(real) = std::fs::canonicalize(&resolved) {
                    resolved = real;
                }
            }
        }
    }
    Some(resolved)
}

fn run_parsed<E: Example>(name: &str, args: &Cli<E>) -> Result<()> {
    if args.common.print_defaults {
        print_stdout(&format!("{}\n", defaults_line::<E>(name)))?;
    }
    if let Some(pixel) = args.common.trace_pixel {
        print_stdout(&commands::trace_pixel(name, args, pixel)?)?;
        return Ok(());
    }
    if let Some(alternative) = &args.common.side_by_side {
        let given: Vec<_> = std::env::args_os().skip(1).collect();
        print_stdout(&commands::side_by_side::<E>(name, &given, alternative)?)?;
        return Ok(());
    }
    if let Some(view) = args.common.view {
        print_stdout(&commands::write_view(name, args, view)?)?;
        return Ok(());
    }
    let output = args.output_path(name);
    let stem = output.file_stem().map(|s| s.to_string_lossy()).unwrap_or_default();
    let heat_path = output.with_file_name(format!("{stem}-diff.png"));
    // The reference's header is read, and its path checked against the outputs', before anything is
    // rendered; it is decoded once the render's size is known to match it, before anything is traced.
    let reference_file = match &args.common.compare {
        Some(path) => {
            check_not_the_reference(path, &output, &heat_path)?;
            Some((path, ImageFile::open_unbudgeted(path)?))
        }
        None => None,
    };
    // Where the picture and the heat map go is checked before any work; nothing is made until the render is
    // done.
    check_output(&output, None)?;
    if reference_file.is_some() {
        check_output(&heat_path, Some(image::ImageFormat::Png))?;
    }
    let mut reference = None;
    let quiet = args.common.quiet;
    let mut scope = None;
    let (frame, stats, settings) = args.render_checked(|scene, settings| {
        scope = Some(step_effect::Scope::of(scene, settings));
        // Every input has been read by now (the scene's files, the reference): no output may replace one.
        input::check_not_an_input(&output, "the picture")?;
        if let Some((path, file)) = reference_file {
            compare::check_reference_size(path, file.dimensions(), settings.width, settings.height)?;
            input::check_not_an_input(&heat_path, "the heat map")?;
            reference = Some((path, Reference::decode(file, path)?));
        }
        if !quiet {
            for note in args.options_without_effect(scene) {
                print_stderr(&format!("{name}: note: {note}\n"))?;
            }
        }
        Ok(())
    })?;
    if let Some(scope) = scope.filter(|_| !quiet) {
        for note in step_effect::notes(&args.common, &scope, &stats.counters) {
            print_stderr(&format!("{name}: note: {note}\n"))?;
        }
    }
    // The picture as written: exposed, and tone mapped for an 8-bit file; the comparison sees the same.
    let frame = args.film().develop(frame, keeps_linear_light(&output));
    frame.save(&output)?;
    if !args.common.quiet {
        let rays = stats.counters.total();
        let secs = stats.elapsed.as_secs_f64();
        let spectral = match &stats.spectral {
            SpectralPlan::White => String::new(),
            plan => format!(" ({plan})"),
        };
        // The rays the branching bound did not trace (they took their siblings' mean colour), when there are any.
        let shared = match stats.counters.shared_rays {
            0 => String::new(),
            n => format!(", {n} more shared by the branching bound"),
        };
        print_stdout(&format!(
            "{}: {}x{}, {} spp{}{}, {:.3} s, {} thread{}, {:.2} M rays{shared}, {:.2} Mrays/s -> {}\n",
            name,
            settings.width,
            settings.height,
            settings.spp,
            if settings.adaptive_aa { " + adaptive AA" } else { "" },
            spectral,
            secs,
            stats.threads,
            if stats.threads == 1 { "" } else { "s" },
            rays as f64 * 1e-6,
            rays as f64 * 1e-6 / secs.max(1e-9),
            output.display()
        ))?;
        for warning in &stats.warnings {
            print_stdout(&format!("{name}: warning: {warning}\n"))?;
        }
        if let Some(p) = &stats.photons {
            let trace = p.trace_time.as_secs_f64();
            print_stdout(&format!(
                "{}: photon map: {} photons emitted, {} stored, traced in {:.3} s ({:.2} M photons/s), grid \
                 built in {:.3} s\n",
                name,
                p.emitted,
                p.stored,
                trace,
                p.emitted as f64 * 1e-6 / trace.max(1e-9),
                p.build_time.as_secs_f64()
            ))?;
        }
    }
    if let Some((path, (reference, _charge))) = &reference {
        let comparison = compare::compare(&frame, reference)?;
        save_atomically(&heat_path, |file| comparison.heat_map.write_to(file, image::ImageFormat::Png))?;
        print_stdout(&format!(
            "compared with {}: {comparison}; heat map -> {}\n",
            path.display(),
            heat_path.display()
        ))?;
    }
    Ok(())
}
