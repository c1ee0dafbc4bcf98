//! The progress bar an example draws on stderr while it renders (when stderr is a terminal and `--quiet`
//! is not given): the renderer's [`Progress`] drawn with indicatif.

use crate::lesson::render::Progress;
use indicatif::{ProgressBar, ProgressStyle};
use std::io::IsTerminal;

/// A progress bar counted in camera samples: a row that runs away still moves it, and its estimate of the
/// time left.
pub struct SampleBar(ProgressBar);

impl SampleBar {
    /// The bar, if stderr is a terminal to draw it on.
    pub fn on_terminal() -> Option<SampleBar> {
        std::io::stderr().is_terminal().then(|| {
            let bar = ProgressBar::new(0);
            bar.set_style(
                ProgressStyle::with_template(
                    "{elapsed_precise} [{bar:40}] {human_pos}/{human_len} samples, {eta} left",
                )
                .expect("valid template")
                .progress_chars("=> "),
            );
            SampleBar(bar)
        })
    }
}

impl Progress for SampleBar {
    fn begin(&self, samples: u64) {
        self.0.set_length(samples);
    }
    fn advance(&self, samples: u64) {
        self.0.inc(samples);
    }
    fn end(&self) {
        self.0.finish_and_clear();
    }
}
