//! Shared by the benchmark programs that time renders inside their own process.

use std::time::Duration;

/// CPU time used by this process so far (user + system, all threads, including finished ones), if the
/// system tells: fields 14 and 15 of `/proc/self/stat`, in clock ticks of 1/100 s.
pub fn cpu_time() -> Option<Duration> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    // The command name, field 2, is in parentheses and may hold spaces: count fields after it.
    let fields: Vec<&str> = stat.rsplit_once(')')?.1.split_whitespace().collect();
    let ticks: u64 = fields.get(11)?.parse::<u64>().ok()? + fields.get(12)?.parse::<u64>().ok()?;
    Some(Duration::from_millis(ticks * 10))
}
