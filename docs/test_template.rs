use crate::common;
use lecture6::lesson::frame::Frame;

/// The mean luminance of a picture, in linear light.
fn mean(frame: &Frame) -> f32 {
    frame.pixels.iter().map(|c| c.luminance()).sum::<f32>() / frame.pixels.len() as f32
}

#[test]
fn darker_mirrors_darken_the_picture_by_what_they_show() {
    let small = ["--width", "64", "--height", "48"];
    let render = |multiplier: &str| {
        let args = [&small[..], &["--multiplier", multiplier]].concat();
        mean(&common::render::<common::examples::reflect_v02::Options>(&args))
    };
    let (bright, dark, black) = (render("0.8"), render("0.4"), render("0"));
    // The mirrors show the rest of the scene: halving their colour halves what they add to the picture.
    let (added_bright, added_dark) = (bright - black, dark - black);
    assert!(added_bright > 0.0, "the mirrors show something: {bright} against {black}");
    assert!((added_dark / added_bright - 0.5).abs() < 0.05, "{added_dark} is not half of {added_bright}");
}
