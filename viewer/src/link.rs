//! The pipe to the example: what the window sends (its requests, to the standard output) and what it
//! receives (the example's reports, from the standard input), which a thread of its own reads into
//! [`Shown`] as they come, asking the window to redraw.

use crate::window::Picked;
use eframe::egui;
use lecture6_viewer_protocol::wire::{Report, Request, Status, receive, send};
use std::io::{BufReader, BufWriter, Stdin, Write};
use std::sync::{Arc, Mutex};

/// What the example sent, as far as the window has not taken it yet.
#[derive(Default)]
pub struct Shown {
    /// The picture, 8-bit sRGB, `width` x `height`.
    pub rgb: Vec<u8>,
    /// The picture's width.
    pub width: u32,
    /// The picture's height.
    pub height: u32,
    /// The picture changed since the window last uploaded it.
    pub dirty: bool,
    /// How far the picture is.
    pub status: Status,
    /// The line under the status line.
    pub message: String,
    /// The ray tree of the pixel asked about, once it came.
    pub picked: Option<Picked>,
    /// The heat map of a comparison (its size and pixels), once it came.
    pub heat_map: Option<([u32; 2], Vec<u8>)>,
    /// The example has ended (or sent something that makes no sense): the window closes.
    pub ended: bool,
}

impl Shown {
    /// Takes in one report of the example.
    fn apply(&mut self, report: Report) {
        match report {
            Report::Pixels { width, height, x, y, w, h, rgb } => {
                if (self.width, self.height) != (width, height) {
                    (self.width, self.height) = (width, height);
                    self.rgb = vec![0; width as usize * height as usize * 3];
                }
                let fits = x.checked_add(w).is_some_and(|r| r <= width)
                    && y.checked_add(h).is_some_and(|b| b <= height)
                    && rgb.len() == w as usize * h as usize * 3;
                if !fits {
                    self.ended = true;
                    return;
                }
                for (row, pixels) in rgb.chunks_exact(w as usize * 3).enumerate() {
                    let start = ((y as usize + row) * width as usize + x as usize) * 3;
                    self.rgb[start..start + pixels.len()].copy_from_slice(pixels);
                }
                self.dirty = true;
            }
            Report::Status { status } => self.status = status,
            Report::Message { text } => self.message = text,
            Report::Picked { x, y, sees, tree } => self.picked = Some(Picked { x, y, sees, tree, picture: 0 }),
            Report::HeatMap { width, height, rgb } => self.heat_map = Some(([width, height], rgb)),
            // Said once, at the start: `main` has read it.
            Report::Hello { .. } => {}
        }
    }
}

/// The window's ends of the pipe.
pub struct Link {
    requests: Box<dyn Write + Send>,
    reports: Option<BufReader<Stdin>>,
    /// What the example sent.
    pub shown: Arc<Mutex<Shown>>,
}

impl Link {
    /// The link whose reports come from `reports` (its first one, the hello, read already).
    pub fn new(reports: BufReader<Stdin>) -> Link {
        Link { requests: Box::new(BufWriter::new(std::io::stdout())), reports: Some(reports), shown: Arc::default() }
    }

    /// A link to no example, for the window's tests: its requests go nowhere, and what it shows is what a
    /// test puts in [`Link::shown`].
    #[cfg(test)]
    pub fn detached() -> Link {
        Link { requests: Box::new(std::io::sink()), reports: None, shown: Arc::default() }
    }

    /// Starts reading the example's reports into [`Link::shown`], asking `ctx` to redraw after each.
    pub fn listen(mut self, ctx: egui::Context) -> Link {
        if let Some(mut reports) = self.reports.take() {
            let shown = self.shown.clone();
            std::thread::spawn(move || {
                loop {
                    let report = receive::<Report>(&mut reports);
                    let mut shown = shown.lock().expect("the window never panics holding what was sent");
                    match report {
                        Ok(report) => shown.apply(report),
                        Err(_) => shown.ended = true,
                    }
                    let ended = shown.ended;
                    drop(shown);
                    ctx.request_repaint();
                    if ended {
                        return;
                    }
                }
            });
        }
        self
    }

    /// Sends `request` to the example. When it has ended, the window closes at its next frame.
    pub fn send(&mut self, request: &Request) {
        if send(&mut self.requests, request).is_err() {
            self.shown.lock().expect("the window never panics holding what was sent").ended = true;
        }
    }
}
