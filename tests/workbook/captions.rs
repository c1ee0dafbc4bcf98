//! What the instruments write beside their pictures: the captions of `--side-by-side` (what each render
//! cost, the photon pass included), their size on a projector, and the heat views' legends on a shared
//! scale (`--legend-max`).

use crate::common;

use common::examples::{fresnel, photon_map};
use lecture6::app::cli::commands::render_cost;
use lecture6::instruments::debug_view::{DebugImage, DebugView, Legend, render_view_with};
use lecture6::instruments::font::{CAPTION_SIZE, caption_size};
use lecture6::instruments::side_by_side::{Panel, compose, compose_scaled};
use std::time::Duration;

/// The seconds a caption's cost starts with.
fn seconds(cost: &str) -> f64 {
    cost.split(' ').next().and_then(|s| s.parse().ok()).unwrap_or_else(|| panic!("no time first: {cost}"))
}

/// `photon_map --slide` spends most of its time in the photon pass, before the render: the caption counts it.
#[test]
fn a_side_by_side_caption_counts_the_photon_pass() {
    let args = ["--width", "32", "--height", "24", "--spp", "1", "--photons", "100000", "--slide", "-q"];
    let (_, stats) = common::parse::<photon_map::Options>(&args).render().unwrap();
    let pass = stats.photon_pass();
    assert!(pass > Duration::from_millis(20), "a photon pass of {pass:?}: too short to tell");
    let cost = render_cost(&stats);
    let whole = (stats.elapsed + pass).as_secs_f64();
    assert!((seconds(&cost) - whole).abs() <= 0.006, "{cost}: the render and its photon pass took {whole:.3} s");
    assert!(cost.contains(&format!("{:.2} s photon pass", pass.as_secs_f64())), "{cost}");
    // Without a photon map, the render's own time.
    let (_, stats) = common::parse::<fresnel::Options>(&["--width", "32", "--height", "24", "-q"]).render().unwrap();
    let cost = render_cost(&stats);
    assert!(!cost.contains("photon") && (seconds(&cost) - stats.elapsed.as_secs_f64()).abs() <= 0.006, "{cost}");
}

/// The captions' font is 14 pixels on a picture that fits a 1600-pixel screen, larger by as much as the
/// picture is wider (so that it shows at 14 pixels there), times `--ui-scale`; the text drawn grows with it.
#[test]
fn captions_grow_with_the_picture_and_the_interface_scale() {
    assert_eq!(caption_size(640, 1.0), CAPTION_SIZE);
    assert_eq!(caption_size(320, 1.0), CAPTION_SIZE, "a small picture keeps a legible caption");
    assert!((caption_size(3 * 640, 1.0) * 1600.0 / 1920.0 - CAPTION_SIZE).abs() < 1e-4);
    assert!((caption_size(3 * 640, 1.5) - 25.2).abs() < 1e-4);
    // The ink of one caption line, drawn at two scales: its height follows the scale.
    let ink_height = |ui_scale: f32| {
        let panel = Panel { image: image::RgbImage::new(300, 20), caption: "Ag".into() };
        let out = compose_scaled(&[panel], ui_scale).unwrap();
        let rows: Vec<u32> = (20..out.height()).filter(|&y| (0..300).any(|x| out.get_pixel(x, y)[0] > 128)).collect();
        rows.last().unwrap() - rows.first().unwrap() + 1
    };
    let (one, two) = (ink_height(1.0), ink_height(2.0));
    assert!((two as f32 / one as f32 - 2.0).abs() < 0.2, "ink {one} px at scale 1, {two} px at scale 2");
    // The default picture's caption is drawn as before: at 14 pixels, scale 1.
    let panel = || Panel { image: image::RgbImage::new(640, 20), caption: "fresnel".into() };
    assert!(compose(&[panel()]).unwrap() == compose_scaled(&[panel()], 1.0).unwrap());
}

/// `--view rays` scales its colours to its own largest count: the same count on the floor is another colour
/// next to `--exhaustive`'s larger counts. `--legend-max` puts both on one scale: the same count, the same
/// colour.
#[test]
fn two_heat_views_share_one_scale_with_legend_max() {
    let small = ["--width", "64", "--height", "48", "--spp", "1"];
    let view = |exhaustive: bool, max: Option<u32>| {
        let args: Vec<&str> = small.iter().copied().chain(exhaustive.then_some("--exhaustive")).collect();
        let (scene, settings) = common::parse::<fresnel::Options>(&args).prepare().unwrap();
        render_view_with(&scene, &settings, DebugView::Rays, Legend { max, ui_scale: 1.0 }).unwrap()
    };
    let (adaptive, exhaustive) = (view(false, None), view(true, None));
    assert!(exhaustive.range.1 > adaptive.range.1, "{:?} {:?}", exhaustive.range, adaptive.range);
    // A pixel of the matte floor: the same rays in both (no ray of a Lambert surface is pruned).
    let floor = (2, 46);
    let colours =
        |a: &DebugImage, b: &DebugImage| (*a.image.get_pixel(floor.0, floor.1), *b.image.get_pixel(floor.0, floor.1));
    let (a, b) = colours(&adaptive, &exhaustive);
    assert_ne!(a, b, "on their own scales the floor's count is two colours");
    let (adaptive, exhaustive) = (view(false, Some(2000)), view(true, Some(2000)));
    let (a, b) = colours(&adaptive, &exhaustive);
    assert_eq!(a, b, "on one scale the floor's count is one colour");
    assert!(adaptive.scale.contains("--legend-max 2000") && adaptive.ticks.iter().any(|t| t.value == 2000.0));
    assert_eq!(adaptive.ticks.first().map(|t| t.value), Some(1.0), "the fixed scale starts at 1");
}

#[test]
fn legend_max_needs_a_view_with_a_legend() {
    let out = common::run_example("fresnel", &["--legend-max", "100", "-o", "target/captions/no-view.png"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--view"), "{}", String::from_utf8_lossy(&out.stderr));
    let args = ["--view", "normals", "--legend-max", "100", "--width", "8", "--height", "6"];
    let out = common::run_example("fresnel", &[&args[..], &["-o", "target/captions/normals.png"]].concat());
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("--legend-max") && err.contains("no legend") && err.lines().count() == 1, "{err}");
}
