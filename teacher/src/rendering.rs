//! A student's example run once, under the class's limits, and what its output says: the summary line
//! every example prints (time, rays), the warnings of its end-of-run report, its defaults
//! (`--print-defaults`), and, when it did not finish, why (its error, its panic's message, or the limit that
//! stopped it). A run stopped at a limit leaves no temporary file of its picture: the example removes it when
//! asked to stop, and what a killed run left is removed by the rule its next save would follow
//! ([`remove_stale_temporaries`]).

use crate::kept_output::run_kept;
use lecture6::app::cli::DEFAULTS_MARK;
use lecture6::app::limits::{Ending, Limits};
use lecture6::files::output::remove_stale_temporaries;
use std::path::Path;
use std::process::Command;
use std::time::Duration;

/// How a run went.
#[derive(Clone, Debug, PartialEq)]
pub struct Run {
    /// `Ok` when the picture was written; otherwise why not, in one line.
    pub outcome: Result<(), String>,
    /// The run's wall-clock time, in seconds (start to end, or to its kill).
    pub seconds: f64,
    /// The processor time it took, in seconds, where the system says.
    pub cpu_seconds: Option<f64>,
    /// The render's own time, from its summary line, in seconds.
    pub render_seconds: Option<f64>,
    /// The rays it traced, in millions, from its summary line.
    pub rays_millions: Option<f64>,
    /// The warnings of its end-of-run report, one each.
    pub warnings: Vec<String>,
    /// The settings it takes without options, each as its option and value (`("--spp", "5")`), from the
    /// line `--print-defaults` prints.
    pub defaults: Vec<(String, String)>,
}

/// The limits of a render: the class's, and the processor time it may take.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RunLimits {
    /// Wall-clock time, memory and output.
    pub limits: Limits,
    /// Processor time.
    pub cpu: Duration,
}

/// Runs `program` with `args` and `-o picture` in the folder `dir` under `limits`, its output into the file
/// `log`.
pub fn run(
    program: &Path,
    args: &[String],
    picture: &Path,
    dir: &Path,
    limits: &RunLimits,
    log: &Path,
) -> Result<Run, String> {
    let mut command = Command::new(program);
    // A panic's message without a backtrace: the log is read by a person, and the panic's place is enough.
    command.args(args).arg("-o").arg(picture).current_dir(dir).env("RUST_BACKTRACE", "0");
    let finished = run_kept(&mut command, &limits.limits, Some(limits.cpu), log);
    // A killed run's temporary file, removed whatever happened (a save in progress elsewhere keeps its own).
    remove_stale_temporaries(picture);
    let finished = finished?;
    let output = std::fs::read_to_string(log).unwrap_or_default();
    let (render_seconds, rays_millions) = summary(&output).unzip();
    let cpu_seconds = finished.cpu.map(|cpu| cpu.as_secs_f64());
    Ok(Run {
        outcome: outcome(finished.ending, (finished.elapsed, cpu_seconds), &output, limits),
        seconds: finished.elapsed.as_secs_f64(),
        cpu_seconds,
        render_seconds,
        rays_millions,
        warnings: warnings(&output),
        defaults: defaults(&output),
    })
}

/// `Ok` for a run that ended well; otherwise why it did not, in one line. `(elapsed, cpu_seconds)` is the
/// wall-clock time and the processor time it took.
fn outcome(
    ending: Ending,
    (elapsed, cpu_seconds): (Duration, Option<f64>),
    output: &str,
    limits: &RunLimits,
) -> Result<(), String> {
    let mib = |bytes: Option<u64>| bytes.map_or(String::new(), |b| format!(" of {} MiB", b >> 20));
    match ending {
        Ending::Exited(0) => Ok(()),
        Ending::TimedOut if elapsed < limits.limits.time => {
            Err(format!("stopped at the time limit of {} s of processor time", limits.cpu.as_secs_f64()))
        }
        Ending::TimedOut => Err(format!(
            "stopped at the wall-clock limit of {} s, having computed for {:.1} s (is it waiting for something?)",
            limits.limits.time.as_secs_f64(),
            cpu_seconds.unwrap_or_default()
        )),
        _ if output.contains("memory allocation of") => Err(format!(
            "stopped at the memory limit{}: {}",
            mib(limits.limits.memory),
            last_line(output, "memory allocation of")
        )),
        _ if output.contains("has overflowed its stack") => Err("its stack overflowed (endless recursion?)".into()),
        _ if output.contains(" panicked at ") => Err(panic_message(output)),
        Ending::Signal(25) => Err(format!("stopped at the output limit{}", mib(limits.limits.output))),
        Ending::Signal(signal) => Err(format!("killed by signal {signal}")),
        Ending::Exited(code) => Err(error_line(output).unwrap_or_else(|| format!("exit code {code}"))),
    }
}

/// The settings of the first line `--print-defaults` printed, each as its option and value.
fn defaults(output: &str) -> Vec<(String, String)> {
    let Some(line) = output.lines().find_map(|l| l.split_once(DEFAULTS_MARK).map(|(_, d)| d)) else {
        return Vec::new();
    };
    line.split(", ")
        .filter_map(|setting| setting.split_once(' '))
        .map(|(option, value)| (option.to_string(), value.trim().to_string()))
        .collect()
}

/// "panicked at FILE:LINE:COLUMN: MESSAGE", from the first panic in `output` (the message may take several
/// lines, up to the note about backtraces).
fn panic_message(output: &str) -> String {
    let mut lines = output.lines().skip_while(|l| !l.contains(" panicked at "));
    let place = lines.next().and_then(|l| l.split(" panicked at ").nth(1)).unwrap_or("").trim_end_matches(':');
    let message: Vec<&str> =
        lines.take_while(|l| !l.starts_with("note: ") && !l.starts_with("stack backtrace")).collect();
    format!("panicked at {place}: {}", message.join(" ").trim())
}

/// The last line of `output` that contains `what`.
fn last_line<'a>(output: &'a str, what: &str) -> &'a str {
    output.lines().rev().find(|l| l.contains(what)).unwrap_or("").trim()
}

/// The error an example printed before it exited with an error: its line `name: error: ...`, or the last
/// line of its output.
fn error_line(output: &str) -> Option<String> {
    let line = output
        .lines()
        .find(|l| l.contains(": error: "))
        .or_else(|| output.lines().rev().find(|l| !l.trim().is_empty()))?;
    Some(line.split_once(": ").map_or(line, |(_, rest)| rest).trim().to_string())
}

/// The render's time in seconds and its rays in millions, from the summary line every example prints:
/// `name: 320x240, 4 spp, 0.312 s, 2 threads, 1.70 M rays, 5.45 Mrays/s -> picture.png`.
fn summary(output: &str) -> Option<(f64, f64)> {
    let line = output.lines().find(|l| l.contains(" spp") && l.contains(" M rays, "))?;
    let parts: Vec<&str> = line.split(", ").collect();
    let seconds = parts.iter().find_map(|p| p.strip_suffix(" s")?.parse().ok())?;
    let rays = parts.iter().find_map(|p| p.strip_suffix(" M rays")?.parse().ok())?;
    Some((seconds, rays))
}

/// The warnings of the end-of-run report: every line `name: warning: ...`, without its `name: warning: `.
fn warnings(output: &str) -> Vec<String> {
    output.lines().filter_map(|l| l.split_once(": warning: ")).map(|(_, w)| w.trim().to_string()).collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::Duration;

    const LIMITS: RunLimits = RunLimits {
        limits: Limits { time: Duration::from_secs(600), memory: Some(1 << 30), output: None },
        cpu: Duration::from_secs(60),
    };

    #[test]
    fn the_summary_and_the_reports_warnings_are_read_from_the_output() {
        let output = "s001_alice: 320x240, 4 spp, 0.312 s, 2 threads, 1.70 M rays, 5.45 Mrays/s -> a.png\n\
            s001_alice: warning: 12 sample(s) came back NaN or infinite and were shown as black; made by x\n\
            s001_alice: warning: a shader gives more light than it receives\n\
            s001_alice: defaults: --spp 20000, --width 640, --max-depth 8, --ior 1.5\n";
        assert_eq!(summary(output), Some((0.312, 1.70)));
        assert_eq!(
            warnings(output),
            [
                "12 sample(s) came back NaN or infinite and were shown as black; made by x",
                "a shader gives more light than it receives"
            ]
        );
        assert_eq!(outcome(Ending::Exited(0), (Duration::from_secs(1), Some(0.3)), output, &LIMITS), Ok(()));
        let read = defaults(output);
        let read: Vec<(&str, &str)> = read.iter().map(|(o, v)| (o.as_str(), v.as_str())).collect();
        assert_eq!(read, [("--spp", "20000"), ("--width", "640"), ("--max-depth", "8"), ("--ior", "1.5")]);
    }

    #[test]
    fn a_run_that_did_not_finish_says_why() {
        let panic = "thread 'main' (7) panicked at /class/alice.rs:12:5:\nthe floor is lava\nnote: run with `RUST_BACKTRACE=1`\n";
        assert_eq!(
            outcome(Ending::Exited(101), (Duration::ZERO, None), panic, &LIMITS),
            Err("panicked at /class/alice.rs:12:5: the floor is lava".into())
        );
        assert_eq!(
            outcome(Ending::TimedOut, (Duration::from_secs(61), Some(60.02)), "", &LIMITS),
            Err("stopped at the time limit of 60 s of processor time".into())
        );
        assert_eq!(
            outcome(Ending::TimedOut, (Duration::from_secs(600), Some(0.5)), "", &LIMITS),
            Err("stopped at the wall-clock limit of 600 s, having computed for 0.5 s (is it waiting for something?)"
                .into())
        );
        let hog = "memory allocation of 80000000000 bytes failed\n";
        assert_eq!(
            outcome(Ending::Signal(6), (Duration::ZERO, None), hog, &LIMITS),
            Err("stopped at the memory limit of 1024 MiB: memory allocation of 80000000000 bytes failed".into())
        );
        let refused = "s001_alice: error: --ior -1: must be a positive number\n";
        assert_eq!(
            outcome(Ending::Exited(2), (Duration::ZERO, None), refused, &LIMITS),
            Err("error: --ior -1: must be a positive number".into())
        );
    }
}
