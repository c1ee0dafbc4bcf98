//! Running a program under a time and a memory limit (not a slide's lesson: the teaching tools). The class
//! command builds and renders each student's submission this way, and the exercise grader checks each
//! exercise this way, so that an infinite loop, a runaway render or a memory hog stops that one program and
//! the rest of the class, or of the exercises, is graded on.
//!
//! The program runs in a process group of its own: at its time limit the whole group is killed, so a
//! `cargo build` stops with every `rustc` it started. The memory limit is the program's address space
//! (`RLIMIT_AS`), past which an allocation fails (a Rust program aborts with "memory allocation of N bytes
//! failed"); the output limit is the largest file it may write (`RLIMIT_FSIZE`), past which the write fails
//! with `SIGXFSZ`. Both are set between `fork` and `exec`, on Unix; elsewhere only the time limit holds.
//! While a limited program runs, INT, TERM and HUP sent to this process end that program's group too
//! ([`stop_children_on_signals`]), since it no longer shares the terminal's.

use std::process::{Child, Command, ExitStatus};
use std::sync::atomic::{AtomicI32, Ordering};
use std::time::{Duration, Instant};
use wait_timeout::ChildExt;

/// What a limited program may use.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limits {
    /// Wall-clock time, from its start to its end.
    pub time: Duration,
    /// Address space in bytes, or `None` for no limit.
    pub memory: Option<u64>,
    /// The largest file it may write, in bytes, or `None` for no limit.
    pub output: Option<u64>,
}

/// How a limited program ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Ending {
    /// It exited with this code.
    Exited(i32),
    /// A signal ended it (not ours): its number. `SIGABRT` (6) is how a Rust program ends when an
    /// allocation fails or its stack overflows, `SIGXFSZ` (25) a file past the output limit.
    Signal(i32),
    /// It ran past its time limit and was killed, with its process group.
    TimedOut,
}

impl Ending {
    /// Whether it exited with code 0.
    pub fn succeeded(self) -> bool {
        self == Ending::Exited(0)
    }
}

/// A limited program's ending and how long it ran.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Finished {
    /// How it ended.
    pub ending: Ending,
    /// Wall-clock time from its start to its end (its kill, when it timed out).
    pub elapsed: Duration,
}

/// The process group of the limited program running now (0: none), for [`stop_children_on_signals`].
static RUNNING: AtomicI32 = AtomicI32::new(0);

/// Runs `command` under `limits` and waits for it (its standard streams as the caller set them: a file
/// each, so that nothing blocks on a full pipe). One limited program at a time.
pub fn run(command: &mut Command, limits: &Limits) -> std::io::Result<Finished> {
    confine(command, limits);
    let start = Instant::now();
    let mut child = command.spawn()?;
    let group = i32::try_from(child.id()).unwrap_or(0);
    RUNNING.store(group, Ordering::SeqCst);
    let waited = child.wait_timeout(limits.time);
    let ending = match waited {
        Ok(Some(status)) => Ok(ending_of(status)),
        Ok(None) => kill(&mut child, group).map(|()| Ending::TimedOut),
        Err(e) => kill(&mut child, group).and(Err(e)),
    };
    RUNNING.store(0, Ordering::SeqCst);
    Ok(Finished { ending: ending?, elapsed: start.elapsed() })
}

/// Kills the program's process group (the program itself where there are no groups) and reaps it.
fn kill(child: &mut Child, group: i32) -> std::io::Result<()> {
    kill_group(group);
    let _ = child.kill();
    child.wait().map(|_| ())
}

/// The [`Ending`] an exit status says.
fn ending_of(status: ExitStatus) -> Ending {
    #[cfg(unix)]
    if let Some(signal) = std::os::unix::process::ExitStatusExt::signal(&status) {
        return Ending::Signal(signal);
    }
    Ending::Exited(status.code().unwrap_or(-1))
}

/// Sets up `command` to start in a process group of its own, with the memory and output limits.
#[cfg(unix)]
fn confine(command: &mut Command, limits: &Limits) {
    use std::os::unix::process::CommandExt;
    let (memory, output) = (limits.memory, limits.output);
    command.process_group(0);
    // SAFETY: between fork and exec the closure only calls setrlimit, which is async-signal-safe, on
    // values computed before the fork; it allocates nothing and takes no lock.
    #[allow(unsafe_code)]
    unsafe {
        command.pre_exec(move || {
            for (resource, bytes) in [(libc::RLIMIT_AS, memory), (libc::RLIMIT_FSIZE, output)] {
                if let Some(bytes) = bytes {
                    let limit = libc::rlimit { rlim_cur: bytes as libc::rlim_t, rlim_max: bytes as libc::rlim_t };
                    if libc::setrlimit(resource, &limit) != 0 {
                        return Err(std::io::Error::last_os_error());
                    }
                }
            }
            Ok(())
        });
    }
}

/// Elsewhere only the time limit holds.
#[cfg(not(unix))]
fn confine(_command: &mut Command, _limits: &Limits) {}

/// Kills the process group `group` (0: none).
#[cfg(unix)]
fn kill_group(group: i32) {
    if group > 0 {
        // SAFETY: kill takes plain integers; a group that is gone already makes it fail, harmlessly.
        #[allow(unsafe_code)]
        unsafe {
            libc::kill(-group, libc::SIGKILL);
        }
    }
}

#[cfg(not(unix))]
fn kill_group(_group: i32) {}

/// Makes INT, TERM and HUP end the limited program running at the time (its whole process group) before
/// this process ends as they would end it. Call it once, at the start of a program that runs others under
/// limits; where the handler cannot be installed, nothing changes.
#[cfg(unix)]
pub fn stop_children_on_signals() {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    let Ok(mut signals) = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP]) else { return };
    std::thread::spawn(move || {
        for signal in signals.forever() {
            kill_group(RUNNING.load(Ordering::SeqCst));
            let _ = signal_hook::low_level::emulate_default_handler(signal);
        }
    });
}

/// Elsewhere the limited programs share the console and its Ctrl-C.
#[cfg(not(unix))]
pub fn stop_children_on_signals() {}

/// A limit given in seconds on a command line or in the environment, refused unless it is a positive
/// number of seconds: the error names the option (or variable) and the value.
pub fn seconds(what: &str, value: &str) -> Result<Duration, String> {
    match value.trim().parse::<f64>() {
        Ok(s) if s.is_finite() && s > 0.0 && s < 1e9 => Ok(Duration::from_secs_f64(s)),
        _ => Err(format!("{what} {value:?}: must be a positive number of seconds")),
    }
}

#[cfg(all(test, unix))]
mod tests {
    use super::*;

    fn limits(seconds: f64) -> Limits {
        Limits { time: Duration::from_secs_f64(seconds), memory: None, output: None }
    }

    #[test]
    fn a_program_past_its_time_limit_is_killed_with_its_children() {
        // The shell waits for a child that would outlive it: both are in the group that is killed.
        let dir = tempfile::tempdir().expect("a temporary folder");
        let pid_file = dir.path().join("pid");
        let mut command = Command::new("sh");
        command.args(["-c", &format!("sleep 30 & echo $! > {}; wait", pid_file.display())]);
        let finished = run(&mut command, &limits(0.5)).expect("sh runs");
        assert_eq!(finished.ending, Ending::TimedOut);
        assert!(finished.elapsed < Duration::from_secs(10), "{:?}", finished.elapsed);
        let sleep: i32 = std::fs::read_to_string(&pid_file).expect("the shell wrote it").trim().parse().expect("a pid");
        // Killed, it is reaped by whoever adopted it: its pid is soon gone.
        let gone = (0..200).any(|_| {
            std::thread::sleep(Duration::from_millis(10));
            // SAFETY: kill with signal 0 only asks whether the process exists.
            #[allow(unsafe_code)]
            unsafe {
                libc::kill(sleep, 0) != 0
            }
        });
        assert!(gone, "the shell's child {sleep} outlived the time limit");
    }

    #[test]
    fn an_exit_code_and_a_signal_are_told_apart() {
        let exit = run(Command::new("sh").args(["-c", "exit 3"]), &limits(30.0)).expect("sh runs");
        assert_eq!(exit.ending, Ending::Exited(3));
        let signal = run(Command::new("sh").args(["-c", "kill -ABRT $$"]), &limits(30.0)).expect("sh runs");
        assert_eq!(signal.ending, Ending::Signal(libc::SIGABRT));
        assert!(run(&mut Command::new("true"), &limits(30.0)).expect("true runs").ending.succeeded());
    }

    #[test]
    fn a_file_past_the_output_limit_stops_the_program() {
        let dir = tempfile::tempdir().expect("a temporary folder");
        let file = dir.path().join("big");
        let mut command = Command::new("sh");
        command
            .args(["-c", &format!("head -c 100000 /dev/zero > {}", file.display())])
            .stderr(std::process::Stdio::null());
        let finished = run(&mut command, &Limits { output: Some(10_000), ..limits(30.0) }).expect("sh runs");
        assert!(!finished.ending.succeeded(), "{:?}", finished.ending);
        assert!(std::fs::metadata(&file).map_or(0, |m| m.len()) <= 10_000);
    }

    #[test]
    fn a_limit_in_seconds_must_be_positive() {
        assert_eq!(seconds("--time-limit", "2.5"), Ok(Duration::from_millis(2500)));
        for bad in ["0", "-1", "nan", "inf", "soon"] {
            let e = seconds("--time-limit", bad).expect_err(bad);
            assert!(e.starts_with("--time-limit ") && e.contains("positive number of seconds"), "{e}");
        }
    }
}
