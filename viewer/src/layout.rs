//! The window's layout: where the picture, the options, the clicked pixel's report and the status go, worked
//! out from the window's size alone (in egui's points, so at every interface scale), never from what the
//! panels hold. So the picture stays the largest thing on the screen with every panel open, a projector's
//! 1280 x 720 at `--ui-scale 1.5` included, and nothing moves when a box is ticked or a new ray tree comes
//! in: what moves a panel is the window's size, or a pixel's report opened or closed.
//!
//! The picture's area keeps at least [`PICTURE_SHARE`] of the window's width. The options take a column at
//! the left; the clicked pixel's report a column of its own at the right where the rest of the width holds
//! one wide enough to read a ray tree ([`PIXEL_MIN_WIDTH`]), and otherwise the lower part of the options'
//! column. The status (the camera, the status line, a message) is a band of a fixed height across the
//! bottom.

use eframe::egui::{Rect, Vec2, pos2};

/// The least share of the window's width the picture's area keeps, with every panel open.
pub const PICTURE_SHARE: f32 = 0.6;

/// The options' column's width, in points, where the window leaves that much beside the picture.
pub const OPTIONS_WIDTH: f32 = 300.0;

/// The narrowest a pixel's report may be in a column of its own, in points: its ray tree's lines wrap at
/// about 40 characters below that.
pub const PIXEL_MIN_WIDTH: f32 = 320.0;

/// The widest a pixel's report's column grows, in points.
pub const PIXEL_MAX_WIDTH: f32 = 520.0;

/// The share of the options' column the options keep when the pixel's report shares it (the report the
/// rest, below them).
pub const OPTIONS_SHARE_OF_COLUMN: f32 = 0.45;

/// Where each part of the window goes, in points.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Layout {
    /// The options and the steps beyond the slides.
    pub options: Rect,
    /// The clicked pixel's report, when one is open.
    pub pixel: Option<Rect>,
    /// Whether the report is in a column of its own, at the right (else under the options).
    pub pixel_beside: bool,
    /// The area the picture is fitted into.
    pub picture_area: Rect,
    /// The picture itself, as large as its area lets it be, centred in it.
    pub picture: Rect,
    /// The camera and the status line, across the bottom.
    pub status: Rect,
}

/// The layout of a window `window` points large, whose status band is `status_height` points high, showing
/// a picture of `picture` pixels, with a pixel's report open or not (`pixel_open`).
pub fn layout(window: Vec2, status_height: f32, picture: Vec2, pixel_open: bool) -> Layout {
    let status_height = status_height.clamp(0.0, window.y);
    let status = Rect::from_min_max(pos2(0.0, window.y - status_height), pos2(window.x, window.y));
    let top = window.y - status_height;
    let sides = window.x * (1.0 - PICTURE_SHARE);
    let options_width = OPTIONS_WIDTH.min(sides);
    let beside_width = (sides - options_width).min(PIXEL_MAX_WIDTH);
    let pixel_beside = pixel_open && beside_width >= PIXEL_MIN_WIDTH;
    let column = Rect::from_min_max(pos2(0.0, 0.0), pos2(options_width, top));
    let (options, pixel) = match (pixel_open, pixel_beside) {
        (false, _) => (column, None),
        (true, true) => (column, Some(Rect::from_min_max(pos2(window.x - beside_width, 0.0), pos2(window.x, top)))),
        (true, false) => {
            let split = top * OPTIONS_SHARE_OF_COLUMN;
            let (upper, lower) = (column.with_max_y(split), column.with_min_y(split));
            (upper, Some(lower))
        }
    };
    let right = if pixel_beside { window.x - beside_width } else { window.x };
    let picture_area = Rect::from_min_max(pos2(options_width, 0.0), pos2(right, top));
    Layout { options, pixel, pixel_beside, picture_area, picture: fitted(picture, picture_area), status }
}

/// The largest rectangle of `size`'s proportions in `area`, centred in it (none for an empty picture).
pub fn fitted(size: Vec2, area: Rect) -> Rect {
    if size.x <= 0.0 || size.y <= 0.0 {
        return Rect::from_center_size(area.center(), Vec2::ZERO);
    }
    let scale = (area.width() / size.x).min(area.height() / size.y).max(0.0);
    Rect::from_center_size(area.center(), size * scale)
}

#[cfg(test)]
mod tests {
    use super::*;
    use eframe::egui::vec2;

    /// A window of `pixels` at the interface scale `ui_scale`, in points.
    fn points(pixels: Vec2, ui_scale: f32) -> Vec2 {
        pixels / ui_scale
    }

    /// The status band's height in egui's default style: three rows of an interactive widget and the space
    /// below it (18 + 3 points), and the panel's margins.
    const STATUS: f32 = 3.0 * 21.0 + 16.0;

    /// The height of a row of egui's default style.
    const ROW: f32 = 21.0;

    #[test]
    fn on_a_projector_with_every_panel_open_the_picture_keeps_most_of_the_width() {
        let window = points(vec2(1280.0, 720.0), 1.5);
        for picture in [vec2(640.0, 480.0), vec2(320.0, 240.0), vec2(1920.0, 1080.0)] {
            let open = layout(window, STATUS, picture, true);
            assert!(open.picture.width() >= PICTURE_SHARE * window.x, "{picture:?}: {open:?}");
            let pixel = open.pixel.expect("the report is open");
            for other in [open.options, pixel, open.status] {
                assert!(other.width() * other.height() < open.picture.width() * open.picture.height(), "{open:?}");
                // Side by side at most: sharing an edge, not a point inside.
                assert!(!other.intersects(open.picture.shrink(0.5)), "{open:?}");
            }
            assert!(open.options.height() > 4.0 * ROW && pixel.height() > 4.0 * ROW, "{open:?}");
        }
    }

    #[test]
    fn a_wide_window_gives_the_report_a_column_of_its_own_and_the_picture_its_share() {
        for (pixels, scale) in [(vec2(1920.0, 1080.0), 1.0), (vec2(2560.0, 1440.0), 1.5), (vec2(1280.0, 720.0), 1.0)] {
            let window = points(pixels, scale);
            let open = layout(window, STATUS, vec2(640.0, 480.0), true);
            assert!(open.picture_area.width() >= PICTURE_SHARE * window.x - 0.01, "{pixels:?}: {open:?}");
            let pixel = open.pixel.unwrap();
            assert_eq!(open.pixel_beside, pixel.width() >= PIXEL_MIN_WIDTH, "{open:?}");
            assert!(pixel.width() >= PIXEL_MIN_WIDTH || pixel.min.x == 0.0, "{open:?}");
        }
        assert!(layout(vec2(1920.0, 1080.0), STATUS, vec2(640.0, 480.0), true).pixel_beside);
        assert!(!layout(points(vec2(1280.0, 720.0), 1.5), STATUS, vec2(640.0, 480.0), true).pixel_beside);
    }

    #[test]
    fn the_options_stay_where_they_are_whatever_the_picture_and_move_only_for_a_report() {
        let window = points(vec2(1280.0, 720.0), 1.5);
        let base = layout(window, STATUS, vec2(640.0, 480.0), false);
        for picture in [vec2(320.0, 240.0), vec2(1.0, 1.0), vec2(0.0, 0.0), vec2(4000.0, 100.0)] {
            let other = layout(window, STATUS, picture, false);
            assert_eq!(
                (other.options, other.status, other.picture_area),
                (base.options, base.status, base.picture_area)
            );
            assert!(base.picture_area.expand(0.01).contains_rect(other.picture), "{other:?}");
        }
        assert_eq!(base.options.min, layout(window, STATUS, vec2(640.0, 480.0), true).options.min);
    }
}
