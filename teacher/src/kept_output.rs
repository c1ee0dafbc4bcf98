//! What a program the class command runs prints, kept within a bound: its first and its last
//! [`KEPT_BYTES`] (the first lines say what it set out to do, the last how it ended: its summary line, its
//! end-of-run report, its panic), and how much was cut between them. It is read from a pipe while the program
//! runs ([`run_kept`]), so a program that prints without end costs no more memory than one that prints a
//! line, and its log file holds the two ends with a line saying what was cut.

use lecture6::app::limits::{self, Finished, Limits};
use std::collections::VecDeque;
use std::io::Read;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::Duration;

/// How many bytes are kept of each end of a program's output.
pub const KEPT_BYTES: usize = 64 << 10;

/// A program's output, its two ends kept.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct KeptOutput {
    /// The first [`KEPT_BYTES`] bytes.
    head: Vec<u8>,
    /// The last [`KEPT_BYTES`] bytes after the head.
    tail: VecDeque<u8>,
    /// How many bytes the program wrote in all.
    total: u64,
}

impl KeptOutput {
    /// Reads `reader` to its end, keeping both ends.
    pub fn read_from(mut reader: impl Read) -> std::io::Result<KeptOutput> {
        let mut kept = KeptOutput::default();
        let mut buffer = vec![0u8; KEPT_BYTES];
        loop {
            match reader.read(&mut buffer) {
                Ok(0) => return Ok(kept),
                Ok(n) => kept.push(&buffer[..n]),
                Err(e) if e.kind() == std::io::ErrorKind::Interrupted => {}
                Err(e) => return Err(e),
            }
        }
    }

    /// Takes in `bytes`, the next the program wrote.
    pub fn push(&mut self, mut bytes: &[u8]) {
        self.total += bytes.len() as u64;
        let room = KEPT_BYTES - self.head.len();
        let (first, rest) = bytes.split_at(room.min(bytes.len()));
        self.head.extend_from_slice(first);
        bytes = rest;
        if bytes.len() >= KEPT_BYTES {
            self.tail.clear();
            bytes = &bytes[bytes.len() - KEPT_BYTES..];
        }
        let over = (self.tail.len() + bytes.len()).saturating_sub(KEPT_BYTES);
        self.tail.drain(..over);
        self.tail.extend(bytes);
    }

    /// How many bytes the program wrote.
    pub fn total(&self) -> u64 {
        self.total
    }

    /// The output as the log keeps it: all of it when it fits, otherwise its first lines, a line saying how
    /// much was cut, and its last lines (whole lines: the line cut through at either end goes with the cut).
    pub fn text(&self) -> String {
        let tail: Vec<u8> = self.tail.iter().copied().collect();
        if self.total == (self.head.len() + tail.len()) as u64 {
            return String::from_utf8_lossy(&[self.head.as_slice(), &tail].concat()).into_owned();
        }
        let head = match self.head.iter().rposition(|&b| b == b'\n') {
            Some(end) => &self.head[..=end],
            None => &[],
        };
        let tail = match tail.iter().position(|&b| b == b'\n') {
            Some(start) => &tail[start + 1..],
            None => &[],
        };
        let cut = self.total - (head.len() + tail.len()) as u64;
        format!("{}{}\n{}", String::from_utf8_lossy(head), cut_line(cut, self.total), String::from_utf8_lossy(tail))
    }
}

/// Runs `command` under `limits`, stopped as well once it has taken `cpu` of processor time
/// ([`limits::run_with_cpu_limit`]), its input closed; its output and errors are read through a pipe while it
/// runs, their two ends kept and written to the file `log` when it ends.
pub fn run_kept(command: &mut Command, limits: &Limits, cpu: Option<Duration>, log: &Path) -> Result<Finished, String> {
    let cannot_run = |e: std::io::Error| format!("cannot run {:?}: {e}", command.get_program());
    let (reader, writer) = std::io::pipe().map_err(cannot_run)?;
    let errors = writer.try_clone().map_err(cannot_run)?;
    command.stdin(Stdio::null()).stdout(writer).stderr(errors);
    let reading = std::thread::spawn(move || KeptOutput::read_from(reader));
    let finished = limits::run_with_cpu_limit(command, limits, cpu);
    // The command's own ends of the pipe, closed: the reader's end comes when the program's are closed too.
    command.stdout(Stdio::null()).stderr(Stdio::null());
    let kept = reading.join().unwrap_or_else(|_| Ok(KeptOutput::default()));
    let finished = finished.map_err(|e| format!("cannot run {:?}: {e}", command.get_program()))?;
    let kept = kept.map_err(|e| format!("cannot read the output of {:?}: {e}", command.get_program()))?;
    std::fs::write(log, kept.text()).map_err(|e| format!("cannot write {}: {e}", log.display()))?;
    Ok(finished)
}

/// The line that stands for the `cut` bytes of an output of `total` bytes left out of its log.
pub fn cut_line(cut: u64, total: u64) -> String {
    format!(
        "[... {} cut here of {} in all: the log keeps the first and the last {} KiB ...]",
        size(cut),
        size(total),
        KEPT_BYTES >> 10
    )
}

/// Whether `line` is the line [`cut_line`] writes.
pub fn is_cut_line(line: &str) -> bool {
    line.starts_with("[... ") && line.contains(" cut here of ") && line.ends_with(" ...]")
}

/// A number of bytes as a person reads it: `812 bytes`, `141.3 MB`.
fn size(bytes: u64) -> String {
    match bytes {
        0..1_000 => format!("{bytes} bytes"),
        1_000..1_000_000 => format!("{:.1} kB", bytes as f64 / 1e3),
        1_000_000..1_000_000_000 => format!("{:.1} MB", bytes as f64 / 1e6),
        _ => format!("{:.1} GB", bytes as f64 / 1e9),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_short_output_is_kept_whole() {
        let text = "fresnel: 320x240, 5 spp, 0.3 s\nfresnel: warning: NaN\n";
        let kept = KeptOutput::read_from(text.as_bytes()).expect("read");
        assert_eq!((kept.text(), kept.total()), (text.to_string(), text.len() as u64));
    }

    #[test]
    fn a_huge_output_keeps_its_first_and_last_lines_and_says_what_was_cut() {
        // 24 MB of numbered lines, fed in pieces of odd sizes, as a pipe gives them.
        let lines: Vec<String> = (0..1_000_000).map(|i| format!("line {i:07} of chatter\n")).collect();
        let whole = lines.concat();
        let mut kept = KeptOutput::default();
        for piece in whole.as_bytes().chunks(4093) {
            kept.push(piece);
        }
        assert!(kept.head.len() <= KEPT_BYTES && kept.tail.len() <= KEPT_BYTES);
        let text = kept.text();
        assert!(text.len() <= 2 * KEPT_BYTES + 200, "{} bytes kept", text.len());
        assert!(text.starts_with("line 0000000 of chatter\nline 0000001 "), "{}", &text[..60]);
        assert!(text.ends_with("line 0999999 of chatter\n"));
        // Whole lines on both sides of the cut, and the cut's size is what is missing.
        let (head, rest) = text.split_once("[... ").expect("the cut is said");
        let (cut, tail) = rest.split_once('\n').expect("the cut is one line");
        assert!(head.ends_with(" of chatter\n") && tail.starts_with("line "), "{cut}");
        let missing = whole.len() - head.len() - tail.len();
        assert_eq!(format!("[... {cut}"), cut_line(missing as u64, whole.len() as u64));
        assert!(is_cut_line(&format!("[... {cut}")) && !is_cut_line("line 0000000 of chatter"));
    }
}
