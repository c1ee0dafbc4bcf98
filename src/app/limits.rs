//! Running a program under a time and a memory limit (not a slide's lesson: the teaching tools). The class
//! command builds and renders each student's submission this way, and the exercise grader checks each
//! exercise this way, so that an infinite loop, a runaway render or a memory hog stops that one program and
//! the rest of the class, or of the exercises, is graded on.
//!
//! The program runs in a process group of its own. Its time limit is wall-clock time, and, where one is
//! given ([`run_with_cpu_limit`]), the processor time it has taken (user and system, all its threads; read
//! from Linux's `/proc/PID/stat` while it runs, and from `wait4` when it ends): a CPU limit is fair to
//! programs run side by side on a busy machine, where the wall clock would charge each for the others. At a
//! limit the group is asked to stop first (TERM: an example then removes the temporary file of a picture it
//! is writing) and killed [`GRACE`] later if it has not, so a `cargo build` stops with every `rustc` it
//! started. The memory limit is the program's address space (`RLIMIT_AS`), past which an allocation fails (a
//! Rust program aborts with "memory allocation of N bytes failed"); the output limit is the largest file it
//! may write (`RLIMIT_FSIZE`), past which the write fails with `SIGXFSZ`. Both are set between `fork` and
//! `exec`, on Unix; elsewhere only the wall-clock limit holds, and a program at it is killed outright. While
//! limited programs run, INT, TERM and HUP sent to this process end their groups too
//! ([`stop_children_on_signals`]), since they no longer share the terminal's.

use std::process::{Child, Command, ExitStatus};
use std::sync::Mutex;
use std::time::{Duration, Instant};

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
    /// It ran past its time limit (wall-clock or CPU) and was stopped, with its process group.
    TimedOut,
}

impl Ending {
    /// Whether it exited with code 0.
    pub fn succeeded(self) -> bool {
        self == Ending::Exited(0)
    }
}

/// A limited program's ending, how long it ran and the processor time it took.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Finished {
    /// How it ended.
    pub ending: Ending,
    /// Wall-clock time from its start to its end (its kill, when it timed out).
    pub elapsed: Duration,
    /// The processor time it took, user and system, its threads and the children it waited for included;
    /// `None` where the system does not say (outside Unix).
    pub cpu: Option<Duration>,
}

/// How long a program asked to stop at its time limit (TERM) has to end before it is killed (KILL): an
/// example's signal handler removes its temporary file in far less (a few milliseconds for a large one).
pub const GRACE: Duration = Duration::from_secs(2);

/// How often a running program's time is looked at: a program past its limit runs at most this much longer
/// before it is asked to stop.
const POLL: Duration = Duration::from_millis(20);

/// The process groups of the limited programs running now, for [`stop_children_on_signals`].
static RUNNING: Mutex<Vec<u32>> = Mutex::new(Vec::new());

/// A program listed in [`RUNNING`] while it runs.
struct Listed(u32);

impl Listed {
    fn new(group: u32) -> Listed {
        RUNNING.lock().unwrap_or_else(|poisoned| poisoned.into_inner()).push(group);
        Listed(group)
    }
}

impl Drop for Listed {
    fn drop(&mut self) {
        RUNNING.lock().unwrap_or_else(|poisoned| poisoned.into_inner()).retain(|&g| g != self.0);
    }
}

/// Runs `command` under `limits` and waits for it (its standard streams as the caller set them: a file
/// each, or a pipe the caller reads while it waits). Several limited programs may run at once, from
/// different threads.
pub fn run(command: &mut Command, limits: &Limits) -> std::io::Result<Finished> {
    run_with_cpu_limit(command, limits, None)
}

/// [`run`], the program stopped as well once it has taken `cpu` of processor time. Where its processor time
/// cannot be read while it runs (outside Linux), `cpu` is a wall-clock limit.
pub fn run_with_cpu_limit(command: &mut Command, limits: &Limits, cpu: Option<Duration>) -> std::io::Result<Finished> {
    confine(command, limits);
    let start = Instant::now();
    let mut child = command.spawn()?;
    let _listed = Listed::new(child.id());
    let over = |child: &Child| {
        let elapsed = start.elapsed();
        elapsed >= limits.time || cpu.is_some_and(|cpu| running_cpu_time(child).unwrap_or(elapsed) >= cpu)
    };
    loop {
        if let Some((status, used)) = reap(&mut child)? {
            return Ok(Finished { ending: ending_of(status), elapsed: start.elapsed(), cpu: used });
        }
        if over(&child) {
            let (_, used) = stop(&mut child)?;
            return Ok(Finished { ending: Ending::TimedOut, elapsed: start.elapsed(), cpu: used });
        }
        std::thread::sleep(POLL);
    }
}

/// Asks the program's group to stop (TERM), kills it [`GRACE`] later if the program has not ended (KILL),
/// and reaps it; then kills what is left of its group (a child that outlived it).
fn stop(child: &mut Child) -> std::io::Result<(ExitStatus, Option<Duration>)> {
    signal_group(child, Signal::Terminate);
    let asked = Instant::now();
    while asked.elapsed() < GRACE {
        if let Some(ended) = reap(child)? {
            signal_group(child, Signal::Kill);
            return Ok(ended);
        }
        std::thread::sleep(POLL);
    }
    signal_group(child, Signal::Kill);
    loop {
        if let Some(ended) = reap(child)? {
            return Ok(ended);
        }
        std::thread::sleep(POLL);
    }
}

/// The signals a limited program's group is sent.
#[derive(Clone, Copy)]
enum Signal {
    /// TERM: stop, after cleaning up.
    Terminate,
    /// KILL: stop now.
    Kill,
}

/// The [`Ending`] an exit status says.
fn ending_of(status: ExitStatus) -> Ending {
    #[cfg(unix)]
    if let Some(signal) = std::os::unix::process::ExitStatusExt::signal(&status) {
        return Ending::Signal(signal);
    }
    Ending::Exited(status.code().unwrap_or(-1))
}

/// The program's exit status and processor time if it has ended (reaping it), `None` while it runs.
#[cfg(unix)]
fn reap(child: &mut Child) -> std::io::Result<Option<(ExitStatus, Option<Duration>)>> {
    use std::os::unix::process::ExitStatusExt;
    let pid = libc::pid_t::try_from(child.id()).map_err(std::io::Error::other)?;
    let mut status = 0;
    // SAFETY: an all-zero rusage is a valid value of this plain C struct.
    #[allow(unsafe_code)]
    let mut usage: libc::rusage = unsafe { std::mem::zeroed() };
    loop {
        // SAFETY: wait4 writes only to the two locals it is given; the pid is our own child's, not yet
        // reaped (it is reaped here only, once).
        #[allow(unsafe_code)]
        let reaped = unsafe { libc::wait4(pid, &mut status, libc::WNOHANG, &mut usage) };
        match reaped {
            0 => return Ok(None),
            -1 if std::io::Error::last_os_error().kind() == std::io::ErrorKind::Interrupted => continue,
            -1 => return Err(std::io::Error::last_os_error()),
            _ => break,
        }
    }
    let seconds = |t: libc::timeval| Duration::new(t.tv_sec as u64, t.tv_usec as u32 * 1000);
    Ok(Some((ExitStatus::from_raw(status), Some(seconds(usage.ru_utime) + seconds(usage.ru_stime)))))
}

/// Elsewhere the exit status alone.
#[cfg(not(unix))]
fn reap(child: &mut Child) -> std::io::Result<Option<(ExitStatus, Option<Duration>)>> {
    Ok(child.try_wait()?.map(|status| (status, None)))
}

/// The processor time the running program has taken so far (user and system, all its threads), from Linux's
/// `/proc/PID/stat`; `None` where it cannot be read.
#[cfg(target_os = "linux")]
fn running_cpu_time(child: &Child) -> Option<Duration> {
    let stat = std::fs::read_to_string(format!("/proc/{}/stat", child.id())).ok()?;
    // The fields after the command's name (which may hold spaces and parentheses): the state is field 3,
    // utime and stime are fields 14 and 15, in clock ticks.
    let fields: Vec<&str> = stat.rsplit_once(')')?.1.split_whitespace().collect();
    let ticks: u64 = fields.get(11)?.parse::<u64>().ok()? + fields.get(12)?.parse::<u64>().ok()?;
    // SAFETY: sysconf only reads a constant of the system.
    #[allow(unsafe_code)]
    let per_second = unsafe { libc::sysconf(libc::_SC_CLK_TCK) };
    (per_second > 0).then(|| Duration::from_secs_f64(ticks as f64 / per_second as f64))
}

/// Elsewhere a running program's processor time is not read.
#[cfg(not(target_os = "linux"))]
fn running_cpu_time(_child: &Child) -> Option<Duration> {
    None
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

/// Sends `signal` to the process group of the program `child` leads.
#[cfg(unix)]
fn signal_group(child: &Child, signal: Signal) {
    kill_group(child.id(), signal);
}

/// Elsewhere there are no groups: the program alone is killed, at once.
#[cfg(not(unix))]
fn signal_group(child: &mut Child, signal: Signal) {
    if let Signal::Kill = signal {
        let _ = child.kill();
    }
}

/// Sends `signal` to the process group `group`.
#[cfg(unix)]
fn kill_group(group: u32, signal: Signal) {
    let signal = match signal {
        Signal::Terminate => libc::SIGTERM,
        Signal::Kill => libc::SIGKILL,
    };
    if let Ok(group) = libc::pid_t::try_from(group)
        && group > 0
    {
        // SAFETY: kill takes plain integers; a group that is gone already makes it fail, harmlessly.
        #[allow(unsafe_code)]
        unsafe {
            libc::kill(-group, signal);
        }
    }
}

/// Makes INT, TERM and HUP end the limited programs running at the time (their whole process groups) before
/// this process ends as they would end it. Call it once, at the start of a program that runs others under
/// limits; where the handler cannot be installed, nothing changes.
#[cfg(unix)]
pub fn stop_children_on_signals() {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    let Ok(mut signals) = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP]) else { return };
    std::thread::spawn(move || {
        for signal in signals.forever() {
            for &group in RUNNING.lock().unwrap_or_else(|poisoned| poisoned.into_inner()).iter() {
                kill_group(group, Signal::Kill);
            }
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
    fn a_program_at_its_limit_is_asked_to_stop_before_it_is_killed() {
        // The shell's handler of TERM removes its file, as an example's removes its temporary picture.
        let dir = tempfile::tempdir().expect("a temporary folder");
        let file = dir.path().join("unfinished");
        let polite = format!("trap 'rm -f {0}; exit 0' TERM; touch {0}; while :; do :; done", file.display());
        let finished = run(Command::new("sh").args(["-c", &polite]), &limits(0.5)).expect("sh runs");
        assert_eq!(finished.ending, Ending::TimedOut);
        assert!(!file.exists(), "the program was not asked to stop: its file is still there");
        assert!(finished.elapsed < limits(0.5).time + GRACE, "{:?}", finished.elapsed);
        // One that does not listen is killed after the grace period.
        let deaf = "trap '' TERM; while :; do :; done";
        let finished = run(Command::new("sh").args(["-c", deaf]), &limits(0.5)).expect("sh runs");
        assert_eq!(finished.ending, Ending::TimedOut);
        assert!(finished.elapsed >= limits(0.5).time + GRACE, "killed before its grace: {:?}", finished.elapsed);
        assert!(finished.elapsed < Duration::from_secs(10), "{:?}", finished.elapsed);
    }

    #[cfg(target_os = "linux")]
    #[test]
    fn the_cpu_limit_counts_processor_time_not_the_wall_clock() {
        let cpu = Duration::from_millis(300);
        // Waiting takes no processor time: a program that sleeps past its CPU limit finishes.
        let sleeper = run_with_cpu_limit(Command::new("sleep").arg("0.6"), &limits(30.0), Some(cpu)).expect("runs");
        assert_eq!(sleeper.ending, Ending::Exited(0));
        assert!(sleeper.elapsed >= Duration::from_millis(600) && sleeper.cpu < Some(cpu), "{sleeper:?}");
        // Computing does: a loop is stopped once it has taken its limit.
        let mut spin = Command::new("sh");
        spin.args(["-c", "while :; do :; done"]);
        let spinner = run_with_cpu_limit(&mut spin, &limits(30.0), Some(cpu)).expect("sh runs");
        assert_eq!(spinner.ending, Ending::TimedOut);
        assert!(spinner.cpu >= Some(cpu) && spinner.elapsed < Duration::from_secs(10), "{spinner:?}");
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
