//! What an example of the lecture6 workbook and its live window say to each other: the example's options as
//! controls ([`controls`]) and the messages through the pipe between the two programs ([`wire`]).
//!
//! The example (the `lecture6` library) and the window (the `lecture6-viewer` program) share only this
//! crate, which depends on nothing: building the window after the examples compiles this crate's one
//! version and the window toolkit, never the library again (docs/building.md).

pub mod controls;
pub mod wire;

/// The interface scales `--ui-scale` (and the window's control) take: from half the size to four times it.
pub const UI_SCALES: std::ops::RangeInclusive<f32> = 0.5..=4.0;
