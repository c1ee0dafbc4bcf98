//! A student's example run once, under the class's limits, and what its output says: the summary line
//! every example prints (time, rays), the warnings of its end-of-run report, and, when it did not finish,
//! why (its error, its panic's message, or the limit that stopped it).

use crate::class_package::run_logged;
use lecture6::app::limits::{Ending, Limits};
use std::path::Path;
use std::process::Command;

/// How a run went.
#[derive(Clone, Debug, PartialEq)]
pub struct Run {
    /// `Ok` when the picture was written; otherwise why not, in one line.
    pub outcome: Result<(), String>,
    /// The run's wall-clock time, in seconds (start to end, or to its kill).
    pub seconds: f64,
    /// The render's own time, from its summary line, in seconds.
    pub render_seconds: Option<f64>,
    /// The rays it traced, in millions, from its summary line.
    pub rays_millions: Option<f64>,
    /// The warnings of its end-of-run report, one each.
    pub warnings: Vec<String>,
}

/// Runs `program` with `args` in the folder `dir` under `limits`, its output into the file `log`.
pub fn run(program: &Path, args: &[String], dir: &Path, limits: &Limits, log: &Path) -> Result<Run, String> {
    let mut command = Command::new(program);
    // A panic's message without a backtrace: the log is read by a person, and the panic's place is enough.
    command.args(args).current_dir(dir).env("RUST_BACKTRACE", "0");
    let finished = run_logged(&mut command, limits, log)?;
    let output = std::fs::read_to_string(log).unwrap_or_default();
    let (render_seconds, rays_millions) = summary(&output).unzip();
    Ok(Run {
        outcome: outcome(finished.ending, &output, limits),
        seconds: finished.elapsed.as_secs_f64(),
        render_seconds,
        rays_millions,
        warnings: warnings(&output),
    })
}

/// `Ok` for a run that ended well; otherwise why it did not, in one line.
fn outcome(ending: Ending, output: &str, limits: &Limits) -> Result<(), String> {
    let mib = |bytes: Option<u64>| bytes.map_or(String::new(), |b| format!(" of {} MiB", b >> 20));
    match ending {
        Ending::Exited(0) => Ok(()),
        Ending::TimedOut => Err(format!("stopped at the time limit of {} s", limits.time.as_secs_f64())),
        _ if output.contains("memory allocation of") => Err(format!(
            "stopped at the memory limit{}: {}",
            mib(limits.memory),
            last_line(output, "memory allocation of")
        )),
        _ if output.contains("has overflowed its stack") => Err("its stack overflowed (endless recursion?)".into()),
        _ if output.contains(" panicked at ") => Err(panic_message(output)),
        Ending::Signal(25) => Err(format!("stopped at the output limit{}", mib(limits.output))),
        Ending::Signal(signal) => Err(format!("killed by signal {signal}")),
        Ending::Exited(code) => Err(error_line(output).unwrap_or_else(|| format!("exit code {code}"))),
    }
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

    const LIMITS: Limits = Limits { time: Duration::from_secs(60), memory: Some(1 << 30), output: None };

    #[test]
    fn the_summary_and_the_reports_warnings_are_read_from_the_output() {
        let output = "s001_alice: 320x240, 4 spp, 0.312 s, 2 threads, 1.70 M rays, 5.45 Mrays/s -> a.png\n\
            s001_alice: warning: 12 sample(s) came back NaN or infinite and were shown as black; made by x\n\
            s001_alice: warning: a shader gives more light than it receives\n";
        assert_eq!(summary(output), Some((0.312, 1.70)));
        assert_eq!(
            warnings(output),
            [
                "12 sample(s) came back NaN or infinite and were shown as black; made by x",
                "a shader gives more light than it receives"
            ]
        );
        assert_eq!(outcome(Ending::Exited(0), output, &LIMITS), Ok(()));
    }

    #[test]
    fn a_run_that_did_not_finish_says_why() {
        let panic = "thread 'main' (7) panicked at /class/alice.rs:12:5:\nthe floor is lava\nnote: run with `RUST_BACKTRACE=1`\n";
        assert_eq!(
            outcome(Ending::Exited(101), panic, &LIMITS),
            Err("panicked at /class/alice.rs:12:5: the floor is lava".into())
        );
        assert_eq!(outcome(Ending::TimedOut, "", &LIMITS), Err("stopped at the time limit of 60 s".into()));
        let hog = "memory allocation of 80000000000 bytes failed\n";
        assert_eq!(
            outcome(Ending::Signal(6), hog, &LIMITS),
            Err("stopped at the memory limit of 1024 MiB: memory allocation of 80000000000 bytes failed".into())
        );
        let refused = "s001_alice: error: --ior -1: must be a positive number\n";
        assert_eq!(
            outcome(Ending::Exited(2), refused, &LIMITS),
            Err("error: --ior -1: must be a positive number".into())
        );
    }
}
