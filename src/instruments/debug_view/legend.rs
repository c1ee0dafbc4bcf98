//! The legend of a heat view (`--view rays`, `shadow-rays`, `depth-reached`): the ramp's colour bar (the one
//! every heat map draws, [`ramp_bar_under`]), ticks under it labelled with the values whose colours the bar
//! shows there, and a caption saying what is counted and on which scale, in the bundled font the captions of
//! `--side-by-side` use ([`compose_scaled`]).
//!
//! The legend is a strip added below the view, never drawn over it: pixel (x, y) of the picture is pixel
//! (x, y) of the render, and the picture is taller than the render by the strip.

use super::heat;
use crate::instruments::compare::ramp_bar_under;
use crate::instruments::font::{CAPTION_BACKGROUND, CAPTION_INK, caption_font, caption_size, draw_text, text_width};
use crate::instruments::side_by_side::{Panel, compose_scaled};
use crate::lesson::error::Result;
use ab_glyph::ScaleFont;

/// How a heat view places its values on the ramp, from black (0) to white (1).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum HeatScale {
    /// Evenly from `lo` (black) to `hi` (white): the depth reached, a few small whole numbers.
    Linear { lo: f32, hi: f32 },
    /// By the logarithm, from `lo`, the smallest count of at least 1 (black), to `hi`, the largest (white):
    /// each doubling of a count moves its colour as far, so that a matte surface's few rays and a glass's
    /// hundreds both show. A count of 0 has no place on it.
    Log { lo: f32, hi: f32 },
}

impl HeatScale {
    /// Where `value` lies on the ramp, from 0 to 1; `None` for a value the scale has no place for (below 1
    /// on the log scale: a count of 0).
    pub(super) fn position(self, value: f32) -> Option<f32> {
        let (lo, hi, value) = match self {
            HeatScale::Linear { lo, hi } => (lo, hi, value),
            HeatScale::Log { lo, hi } if value >= 1.0 => (lo.ln(), hi.ln(), value.ln()),
            HeatScale::Log { .. } => return None,
        };
        Some(if hi > lo { ((value - lo) / (hi - lo)).clamp(0.0, 1.0) } else { 0.0 })
    }

    /// The values at black and at white.
    pub(super) fn ends(self) -> (f32, f32) {
        match self {
            HeatScale::Linear { lo, hi } | HeatScale::Log { lo, hi } => (lo, hi),
        }
    }

    /// The values worth a tick, the ends first, then the ones between, ascending: every whole number on the
    /// linear scale (the depths reached, at most 16 of them), every 1, 2, 5, 10, 20, 50, ... on the log scale.
    fn tick_values(self) -> Vec<f32> {
        let (lo, hi) = self.ends();
        let between: Vec<f32> = match self {
            HeatScale::Linear { .. } => (lo.floor() as i64 + 1..hi.ceil() as i64).map(|v| v as f32).collect(),
            HeatScale::Log { .. } => (0..)
                .flat_map(|power| [1.0, 2.0, 5.0].map(|m| m * 10f32.powi(power)))
                .take_while(|&v| v < hi)
                .filter(|&v| v > lo)
                .collect(),
        };
        let ends = if hi > lo { vec![lo, hi] } else { vec![lo] };
        ends.into_iter().chain(between).collect()
    }
}

/// One labelled tick of a heat view's legend.
#[derive(Clone, Debug, PartialEq)]
pub struct Tick {
    /// The value at the tick (a count of rays, a depth): the colour bar shows this value's colour in the
    /// tick's column.
    pub value: f32,
    /// The column of the picture the tick is drawn at.
    pub x: u32,
    /// What is written under the tick: the value.
    pub label: String,
}

/// The length of a tick mark under the colour bar, in pixels.
const TICK_LENGTH: u32 = 4;
/// The least space between two labels, in pixels.
const LABEL_GAP: f32 = 8.0;
/// The least space between a label and the side of the picture, in pixels (a glyph's ink may reach a
/// little past its advance).
const LABEL_MARGIN: f32 = 2.0;

/// The ticks that fit under a colour bar `width` pixels wide, left to right: the ends of the scale first,
/// then the values between it is worth marking, each kept if its label, `label_width(label)` pixels wide
/// and centred on its tick (moved inside the bar at the ends), keeps [`LABEL_GAP`] from the labels kept.
fn ticks(scale: HeatScale, width: u32, label_width: impl Fn(&str) -> f32) -> Vec<Tick> {
    // Each tick kept, with the span of its label.
    let mut kept: Vec<(Tick, (f32, f32))> = Vec::new();
    for value in scale.tick_values() {
        let Some(position) = scale.position(value) else { continue };
        let x = ((position * width as f32) as u32).min(width.saturating_sub(1));
        let label = format!("{value}");
        let label_width = label_width(&label);
        let left = label_left(x, label_width, width);
        let span = (left, left + label_width);
        let fits = span.1 <= width as f32 - LABEL_MARGIN;
        let clear = kept.iter().all(|(_, (l, r))| span.1 + LABEL_GAP <= *l || *r + LABEL_GAP <= span.0);
        if fits && clear {
            kept.push((Tick { value, x, label }, span));
        }
    }
    let mut ticks: Vec<Tick> = kept.into_iter().map(|(tick, _)| tick).collect();
    ticks.sort_by_key(|tick| tick.x);
    ticks
}

/// Where a label `label_width` pixels wide starts: centred on the tick at column `x`, moved right or left
/// to stay [`LABEL_MARGIN`] inside a bar `width` pixels wide.
fn label_left(x: u32, label_width: f32, width: u32) -> f32 {
    (x as f32 + 0.5 - label_width / 2.0).min(width as f32 - LABEL_MARGIN - label_width).max(LABEL_MARGIN)
}

/// The heat view `view` with its legend in a strip below it: the colour bar of the ramp, the ticks of
/// `scale` that fit with their labels, and `caption` (what is shown, on which scale) wrapped to the view's
/// width, the text at the interface scale `ui_scale` ([`caption_size`]); and the ticks drawn.
pub(super) fn with_legend(
    view: &image::RgbImage,
    scale: HeatScale,
    caption: &str,
    ui_scale: f32,
) -> Result<(image::RgbImage, Vec<Tick>)> {
    let font = caption_font(caption_size(view.width(), ui_scale))?;
    let ticks = ticks(scale, view.width(), |label| text_width(&font, label));
    let barred = ramp_bar_under(view, heat);
    let line_height = (font.height() + font.line_gap()).ceil() as u32;
    let marks_top = barred.height();
    let mut labelled = image::RgbImage::from_pixel(
        view.width(),
        marks_top + TICK_LENGTH + line_height,
        image::Rgb(CAPTION_BACKGROUND),
    );
    image::imageops::replace(&mut labelled, &barred, 0, 0);
    let baseline = (marks_top + TICK_LENGTH) as f32 + font.ascent();
    for tick in &ticks {
        for y in marks_top..marks_top + TICK_LENGTH {
            labelled.put_pixel(tick.x, y, image::Rgb(CAPTION_INK));
        }
        let left = label_left(tick.x, text_width(&font, &tick.label), view.width());
        draw_text(&mut labelled, &font, &tick.label, left, baseline);
    }
    let picture = compose_scaled(&[Panel { image: labelled, caption: caption.to_string() }], ui_scale)?;
    Ok((picture, ticks))
}
