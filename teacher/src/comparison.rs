//! A student's picture against the teacher's reference: the workbook's own image difference
//! (`lecture6::instruments::compare`, what `--compare` prints), and its heat map written beside the
//! picture.

use lecture6::instruments::compare::{difference, heat_map_scaled, load_reference, with_colour_bar};
use std::path::Path;

/// The PSNR given to a picture equal to its reference (whose PSNR is infinite): a number a spreadsheet can
/// sort, above any real difference's (one level off in one channel of one pixel of a 4K picture is 133 dB).
pub const EQUAL_PSNR: f64 = 99.0;

/// How far a picture is from the reference.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Score {
    /// The root-mean-square difference of the 8-bit codes, in levels (0..255).
    pub rmse: f64,
    /// The peak signal-to-noise ratio in dB, [`EQUAL_PSNR`] for an equal picture.
    pub psnr: f64,
}

/// Compares the picture at `picture` with the reference at `reference` and writes the heat map of the
/// difference, with its colour bar, to `heat_map`. Fails with one line when a picture cannot be read or their
/// sizes differ.
pub fn compare(picture: &Path, reference: &Path, heat_map: &Path) -> Result<Score, String> {
    let actual = load_reference(picture).map_err(|e| e.to_string())?;
    let expected = load_reference(reference).map_err(|e| e.to_string())?;
    let d = difference(&actual, &expected).map_err(|e| e.to_string())?;
    let heat =
        with_colour_bar(&heat_map_scaled(&actual, &expected, d.max_diff).map_err(|e| e.to_string())?, d.max_diff)
            .map_err(|e| e.to_string())?;
    heat.save(heat_map).map_err(|e| format!("cannot write {}: {e}", heat_map.display()))?;
    Ok(Score { rmse: d.rmse_8bit, psnr: d.psnr.min(EQUAL_PSNR) })
}
