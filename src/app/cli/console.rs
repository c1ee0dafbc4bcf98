//! What an example prints, written so that a stream it cannot write to never becomes a panic: `println!`
//! panics when stdout is a pipe whose reader went away (`| head -1`) or a full device (`> /dev/full`), and a
//! panic exits with code 101 and a message that blames the program. Every line an example prints goes
//! through [`print_stdout`] or [`print_stderr`]:
//!
//! - A stream whose reader went away (a broken pipe) is closed for the rest of the run: what would go to it
//!   is dropped, and the run goes on to its end (the picture is written, the exit code is 0).
//! - Any other failure (a full device, an I/O error) is an error of the run, naming the stream: one line on
//!   stderr, where that can still be written, and exit code 2, as for any other error.

use crate::lesson::error::{Error, Result};
use std::io::Write;
use std::path::Path;
use std::sync::atomic::{AtomicBool, Ordering};

/// One of the two streams an example prints to, and whether its reader went away.
struct Stream {
    /// The name the error message gives it.
    name: &'static str,
    /// Its reader went away: nothing more is written to it.
    closed: AtomicBool,
}

static STDOUT: Stream = Stream { name: "standard output", closed: AtomicBool::new(false) };
static STDERR: Stream = Stream { name: "standard error", closed: AtomicBool::new(false) };

impl Stream {
    /// What writing to this stream gave, as the module documentation says: a broken pipe closes the
    /// stream quietly, any other failure is an error naming it.
    fn settle(&self, written: std::io::Result<()>) -> Result<()> {
        match written {
            Ok(()) => Ok(()),
            Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => {
                self.closed.store(true, Ordering::SeqCst);
                Ok(())
            }
            Err(e) => Err(Error::file("cannot write to", Path::new(self.name), e)),
        }
    }

    /// Writes `text` to `out`, this stream, unless its reader went away; see [`Stream::settle`].
    fn print(&self, mut out: impl Write, text: &str) -> Result<()> {
        if self.closed.load(Ordering::SeqCst) {
            return Ok(());
        }
        self.settle(out.write_all(text.as_bytes()).and_then(|()| out.flush()))
    }
}

/// Writes `text` to stdout as it is (its lines end with their `\n`): an error only if stdout cannot take it
/// for another reason than a reader that went away (see the module documentation).
pub fn print_stdout(text: &str) -> Result<()> {
    STDOUT.print(std::io::stdout().lock(), text)
}

/// Writes `text` to stderr as it is (its lines end with their `\n`), as [`print_stdout`] writes to stdout.
pub fn print_stderr(text: &str) -> Result<()> {
    STDERR.print(std::io::stderr().lock(), text)
}

/// Prints what clap made of the command line (`--help`, `--version`, or why it is refused) to the stream
/// clap chose, as [`print_stdout`] and [`print_stderr`] do.
pub(super) fn print_clap(message: &clap::Error) -> Result<()> {
    let stream = if message.use_stderr() { &STDERR } else { &STDOUT };
    if stream.closed.load(Ordering::SeqCst) {
        return Ok(());
    }
    stream.settle(message.print())
}
