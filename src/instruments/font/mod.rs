//! The font the instruments write with: DejaVu Sans Mono, bundled (its licence, `LICENSE-DejaVu.txt`, is
//! beside it), so that captions and charts look the same on every machine and need none of its fonts. Text
//! is drawn into pictures through `ab_glyph`: light grey ink, anti-aliased over a dark grey background.

use crate::lesson::error::{Error, Result};
use ab_glyph::{Font, FontRef, PxScale, PxScaleFont, ScaleFont, point};

/// DejaVu Sans Mono, as a TrueType file.
pub const DEJAVU_SANS_MONO: &[u8] = include_bytes!("DejaVuSansMono.ttf");

/// The captions' font size in pixels, on a picture that fits [`SCREEN_WIDTH`].
pub const CAPTION_SIZE: f32 = 14.0;
/// The width of the screen a picture with captions is made for, in pixels: a projector's 1600 x 1000 (or a
/// laptop's). A wider picture is shown scaled down to it, so its captions are drawn larger by as much.
pub const SCREEN_WIDTH: f32 = 1600.0;
/// The background text is written on.
pub const CAPTION_BACKGROUND: [u8; 3] = [32, 32, 32];
/// The colour of the text.
pub const CAPTION_INK: [u8; 3] = [235, 235, 235];

/// The font size of the captions of a picture `width` pixels wide, at the interface scale `ui_scale`
/// (`--ui-scale`): [`CAPTION_SIZE`] times the scale, and larger by as much as the picture is wider than
/// [`SCREEN_WIDTH`], so that shown on that screen its text is as large as a narrower picture's.
pub fn caption_size(width: u32, ui_scale: f32) -> f32 {
    CAPTION_SIZE * ui_scale * (width as f32 / SCREEN_WIDTH).max(1.0)
}

/// The bundled font at the size `size`, in pixels (see [`caption_size`]).
pub fn caption_font(size: f32) -> Result<PxScaleFont<FontRef<'static>>> {
    let font = FontRef::try_from_slice(DEJAVU_SANS_MONO)
        .map_err(|e| Error::parameter("bundled caption font", "DejaVuSansMono", e))?;
    Ok(font.into_scaled(PxScale::from(size)))
}

/// The width of `text` in pixels, written in `font`.
pub fn text_width<F: Font>(font: &PxScaleFont<F>, text: &str) -> f32 {
    text.chars().map(|c| font.h_advance(font.glyph_id(c))).sum()
}

/// Draws one line of text in [`CAPTION_INK`] with its baseline at `y`, starting at `x`, anti-aliased over
/// what is there; what falls outside the picture is left out.
pub fn draw_text<F: Font>(out: &mut image::RgbImage, font: &PxScaleFont<F>, text: &str, mut x: f32, y: f32) {
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
