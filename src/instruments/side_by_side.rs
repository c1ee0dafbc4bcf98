//! Side by side (`--side-by-side "OPTIONS"`): the example rendered twice, with its own options (A) and with
//! the alternative ones added (B), written as one picture A | B | difference heat map, with a caption under
//! each part: `fresnel --side-by-side "--fresnel exact"` shows what Schlick's approximation costs,
//! `glossy --side-by-side "--sampler random"` what disc samples stratified over the whole pixel gain.
//!
//! The captions are drawn with the DejaVu Sans Mono font the workbook bundles ([`crate::instruments::font`]), through `ab_glyph`, so nothing depends on the fonts of the machine.
//! Their size follows the picture's width and the interface scale (`--ui-scale`, [`caption_size`]): on a
//! projector of 1600 x 1000 the captions of three 640-pixel panels show as large as on a 640-pixel picture.

use crate::instruments::compare;
use crate::instruments::font::{CAPTION_BACKGROUND, CAPTION_SIZE, caption_font, caption_size, draw_text};
use crate::lesson::error::Result;
use ab_glyph::{Font, PxScaleFont, ScaleFont};

/// Space around a caption's text, in pixels, at the captions' size [`CAPTION_SIZE`].
const CAPTION_PADDING: f32 = 6.0;

/// One part of a side-by-side picture.
pub struct Panel {
    /// The picture, 8 bits per channel, as it is shown.
    pub image: image::RgbImage,
    /// The text written under it (wrapped to the picture's width).
    pub caption: String,
}

/// The panels left to right, top-aligned, each with its caption (wrapped to its width) under the tallest
/// (the difference panel is taller by its colour bar), at the interface scale 1 ([`compose_scaled`]).
pub fn compose(panels: &[Panel]) -> Result<image::RgbImage> {
    compose_scaled(panels, 1.0)
}

/// [`compose`] with the captions at the interface scale `ui_scale` (`--ui-scale`): their font
/// [`caption_size`] for the whole picture's width.
pub fn compose_scaled(panels: &[Panel], ui_scale: f32) -> Result<image::RgbImage> {
    let width = panels.iter().map(|p| p.image.width()).sum();
    let size = caption_size(width, ui_scale);
    let font = caption_font(size)?;
    let padding = (CAPTION_PADDING * size / CAPTION_SIZE).round() as u32;
    let height = panels.iter().map(|p| p.image.height()).max().unwrap_or(0);
    let lines: Vec<Vec<String>> =
        panels.iter().map(|p| wrap(&p.caption, columns(&font, p.image.width().saturating_sub(2 * padding)))).collect();
    let line_height = (font.height() + font.line_gap()).ceil() as u32;
    let caption_height = lines.iter().map(Vec::len).max().unwrap_or(0) as u32 * line_height + 2 * padding;
    let mut out = image::RgbImage::from_pixel(width, height + caption_height, image::Rgb(CAPTION_BACKGROUND));
    let mut left = 0;
    for (panel, lines) in panels.iter().zip(&lines) {
        image::imageops::replace(&mut out, &panel.image, left as i64, 0);
        for (i, line) in lines.iter().enumerate() {
            let baseline = (height + padding + i as u32 * line_height) as f32 + font.ascent();
            draw_text(&mut out, &font, line, (left + padding) as f32, baseline);
        }
        left += panel.image.width();
    }
    Ok(out)
}

/// How many characters of the (monospaced) font fit on a line `width` pixels wide.
fn columns<F: Font>(font: &PxScaleFont<F>, width: u32) -> usize {
    let advance = font.h_advance(font.glyph_id('M')).max(1.0);
    (width as f32 / advance).floor().max(1.0) as usize
}

/// `text` broken into lines of at most `columns` characters, between words where it can be.
fn wrap(text: &str, columns: usize) -> Vec<String> {
    let mut lines = Vec::new();
    for paragraph in text.lines() {
        let mut line = String::new();
        for word in paragraph.split_whitespace() {
            let mut word: Vec<char> = word.chars().collect();
            while word.len() > columns {
                if !line.is_empty() {
                    lines.push(std::mem::take(&mut line));
                }
                lines.push(word.drain(..columns).collect());
            }
            let needed = line.chars().count() + usize::from(!line.is_empty()) + word.len();
            if needed > columns && !line.is_empty() {
                lines.push(std::mem::take(&mut line));
            }
            if !line.is_empty() {
                line.push(' ');
            }
            line.extend(word);
        }
        lines.push(line);
    }
    lines
}

/// A | B | difference: the two renders `a` and `b`, each with its caption, and the heat map of their
/// difference with its colour bar, as one picture with its captions at the interface scale `ui_scale`; and
/// the difference in words. The heat map is the one `--compare` writes: white at the largest difference
/// ([`compare::heat_map_scale`]). Fails when the two are not of the same size.
pub fn a_b_difference(a: Panel, b: Panel, ui_scale: f32) -> Result<(image::RgbImage, compare::Difference)> {
    let diff = compare::difference(&a.image, &b.image)?;
    let heat = compare::colour_bar_under(&compare::heat_map_scaled(&a.image, &b.image, diff.max_diff)?);
    let caption = format!("difference A-B: {}\n{diff}", compare::heat_map_scale(diff.max_diff));
    let picture = compose_scaled(&[a, b, Panel { caption, image: heat }], ui_scale)?;
    Ok((picture, diff))
}

#[cfg(test)]
mod tests {
    use super::wrap;

    #[test]
    fn captions_wrap_between_words_and_split_long_words() {
        assert_eq!(wrap("ab cd ef", 5), ["ab cd", "ef"]);
        assert_eq!(wrap("abcdefgh", 3), ["abc", "def", "gh"]);
        assert_eq!(wrap("one\ntwo", 10), ["one", "two"]);
    }
}
