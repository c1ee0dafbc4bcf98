//! Side by side (`--side-by-side "OPTIONS"`): the example rendered twice, with its own options (A) and with
//! the alternative ones added (B), written as one picture A | B | difference heat map, with a caption under
//! each part: `fresnel --side-by-side "--fresnel exact"` shows what Schlick's approximation costs,
//! `glossy --side-by-side "--sampler random"` what disc samples stratified over the whole pixel gain.
//!
//! The captions are drawn with the DejaVu Sans Mono font the workbook bundles ([`crate::instruments::font`]), through `ab_glyph`, so nothing depends on the fonts of the machine.

use crate::app::cli::{Cli, Example};
use crate::instruments::compare;
use crate::instruments::font::DEJAVU_SANS_MONO;
use crate::lesson::error::{Error, Result};
use crate::lesson::render::save_atomically;
use ab_glyph::{Font, FontRef, PxScale, PxScaleFont, ScaleFont, point};
use std::ffi::OsString;
use std::path::Path;

/// The bundled font of the captions.
/// The captions' font size in pixels.
const CAPTION_SIZE: f32 = 14.0;
/// Space around a caption's text, in pixels.
const CAPTION_PADDING: u32 = 6;
const CAPTION_BACKGROUND: [u8; 3] = [32, 32, 32];
const CAPTION_INK: [u8; 3] = [235, 235, 235];

/// One part of a side-by-side picture.
pub struct Panel {
    pub image: image::RgbImage,
    pub caption: String,
}

/// The panels left to right, all of the same height, each with its caption (wrapped to its width) under it.
pub fn compose(panels: &[Panel]) -> Result<image::RgbImage> {
    let font = FontRef::try_from_slice(DEJAVU_SANS_MONO)
        .map_err(|e| Error::parameter("bundled caption font", "DejaVuSansMono", e))?;
    let font = font.as_scaled(PxScale::from(CAPTION_SIZE));
    let height = panels.first().map_or(0, |p| p.image.height());
    if panels.iter().any(|p| p.image.height() != height) {
        return Err(Error::parameter("side-by-side pictures", panels.len(), "must all have the same height"));
    }
    let lines: Vec<Vec<String>> = panels.iter().map(|p| wrap(&p.caption, columns(&font, p.image.width()))).collect();
    let line_height = (font.height() + font.line_gap()).ceil() as u32;
    let caption_height = lines.iter().map(Vec::len).max().unwrap_or(0) as u32 * line_height + 2 * CAPTION_PADDING;
    let width = panels.iter().map(|p| p.image.width()).sum();
    let mut out = image::RgbImage::from_pixel(width, height + caption_height, image::Rgb(CAPTION_BACKGROUND));
    let mut left = 0;
    for (panel, lines) in panels.iter().zip(&lines) {
        image::imageops::replace(&mut out, &panel.image, left as i64, 0);
        for (i, line) in lines.iter().enumerate() {
            let baseline = (height + CAPTION_PADDING + i as u32 * line_height) as f32 + font.ascent();
            draw_text(&mut out, &font, line, (left + CAPTION_PADDING) as f32, baseline);
        }
        left += panel.image.width();
    }
    Ok(out)
}

/// How many characters of the (monospaced) font fit on a caption line of a panel `width` pixels wide.
fn columns<F: Font>(font: &PxScaleFont<F>, width: u32) -> usize {
    let advance = font.h_advance(font.glyph_id('M')).max(1.0);
    ((width.saturating_sub(2 * CAPTION_PADDING)) as f32 / advance).floor().max(1.0) as usize
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

/// Draws one line of text with its baseline at `y`, starting at `x`, anti-aliased over the background.
fn draw_text<F: Font>(out: &mut image::RgbImage, font: &PxScaleFont<F>, text: &str, mut x: f32, y: f32) {
    for c in text.chars() {
        let glyph = font.scaled_glyph(c);
        let advance = font.h_advance(glyph.id);
        let glyph = ab_glyph::Glyph { position: point(x, y), ..glyph };
        if let Some(outline) = font.outline_glyph(glyph) {
            let bounds = outline.px_bounds();
            outline.draw(|gx, gy, coverage| {
                let (px, py) = (bounds.min.x as i64 + gx as i64, bounds.min.y as i64 + gy as i64);
                if px < 0 || py < 0 || px >= out.width() as i64 || py >= out.height() as i64 {
                    return;
                }
                let pixel = out.get_pixel_mut(px as u32, py as u32);
                for ch in 0..3 {
                    let (bg, ink) = (pixel[ch] as f32, CAPTION_INK[ch] as f32);
                    pixel[ch] = (bg + (ink - bg) * coverage.clamp(0.0, 1.0)).round() as u8;
                }
            });
        }
        x += advance;
    }
}

/// The example's options `args` (without the program name) with `--side-by-side` and its value taken out.
fn without_side_by_side(args: &[OsString]) -> Vec<OsString> {
    let mut out = Vec::new();
    let mut skip_value = false;
    for arg in args {
        if std::mem::take(&mut skip_value) {
            continue;
        }
        match arg.to_str() {
            Some("--side-by-side") => skip_value = true,
            Some(a) if a.starts_with("--side-by-side=") => {}
            _ => out.push(arg.clone()),
        }
    }
    out
}

/// `--side-by-side`: renders the example `name` with its options `args` (as given on the command line,
/// without the program name) and again with the options `alternative` (split at white space) added after
/// them, where they win; writes A | B | difference to `--output` or `out/NAME-side-by-side.png` and returns
/// the lines to print.
pub fn side_by_side<E: Example>(name: &str, args: &[OsString], alternative: &str) -> Result<String> {
    let base = without_side_by_side(args);
    let alt: Vec<OsString> = alternative.split_whitespace().map(OsString::from).collect();
    let parse = |extra: &[OsString]| -> Result<Cli<E>> {
        let argv = std::iter::once(OsString::from(name)).chain(base.iter().cloned()).chain(extra.iter().cloned());
        let matches = Cli::<E>::command_named(name)
            .args_override_self(true)
            .try_get_matches_from(argv)
            .and_then(|m| <Cli<E> as clap::FromArgMatches>::from_arg_matches(&m));
        matches.map_err(|e| Error::parameter("--side-by-side", alternative, e.to_string().lines().next().unwrap_or("")))
    };
    let (a, b) = (parse(&[])?, parse(&alt)?);
    let words = |args: &[OsString]| args.iter().map(|a| a.to_string_lossy()).collect::<Vec<_>>().join(" ");
    let base_text = if base.is_empty() { "(its defaults)".to_string() } else { words(&base) };
    let mut panels = Vec::new();
    for (label, args, options) in [("A", &a, base_text.clone()), ("B", &b, format!("{base_text} + {alternative}"))] {
        let (frame, stats) = args.render()?;
        let secs = stats.elapsed.as_secs_f64();
        let rays = stats.counters.total() as f64 * 1e-6;
        panels.push(Panel {
            image: frame.to_rgb8(),
            caption: format!("{label}: {name} {options}\n{secs:.2} s, {rays:.2} M rays"),
        });
    }
    let (pa, pb) = (&panels[0].image, &panels[1].image);
    let diff = compare::difference(pa, pb).map_err(|_| {
        Error::parameter("--side-by-side", alternative, "changes the picture's size: A and B cannot be compared")
    })?;
    let heat = compare::heat_map(pa, pb)?;
    panels.push(Panel { caption: format!("difference A-B (black: equal, white: 64+ levels)\n{diff}"), image: heat });
    let picture = compose(&panels)?;
    let path = a.common.output.clone().unwrap_or_else(|| Path::new("out").join(format!("{name}-side-by-side.png")));
    save_atomically(&path, |tmp| picture.save_with_format(tmp, image::ImageFormat::Png))?;
    Ok(format!(
        "{name}: A | B | difference, {}x{} -> {}\n{name}: A - B: {diff}\n",
        picture.width(),
        picture.height(),
        path.display()
    ))
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
