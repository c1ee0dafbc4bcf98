//! Chromatic dispersion as the slide writes it (slide "Хроматично пречупване"): the index of refraction
//! depends on the wavelength, so the frame is rendered K times, each pass at the centre of one of K equal
//! bands of the spectrum (the glass bending its rays by the index there), and the passes are added, each
//! times the colour of its band. The bands' colours add up to the light's white, so whatever looks the same
//! in every band keeps its colour.

use crate::lesson::color::Color;
use crate::lesson::scene::Scene;
use crate::lesson::spectral::{Band, bands};

/// One pass of the frame: the wavelength its rays carry (`None`: white light) and the colour it is added with.
#[derive(Clone, Copy, Debug)]
pub struct Pass {
    /// The wavelength of the pass in nanometres, or `None` for a white pass.
    pub wavelength: Option<f32>,
    /// What the pass's frame is multiplied by before it is added.
    pub color: Color,
}

/// The passes of a frame: K of them, one per band, for a scene with something dispersive in it; one white
/// pass otherwise. The bands, when there are some, are returned too.
pub fn passes(scene: &Scene, k: u32) -> (Vec<Pass>, Option<Vec<Band>>) {
    if !scene.is_dispersive() {
        return (vec![Pass { wavelength: None, color: Color::WHITE }], None);
    }
    let bands = bands(k, scene.illuminant);
    let passes = bands.iter().map(|band| Pass { wavelength: Some(band.centre()), color: band.color() }).collect();
    (passes, Some(bands))
}
