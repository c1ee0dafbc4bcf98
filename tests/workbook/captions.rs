//! What the instruments write beside their pictures: the captions of `--side-by-side` (what each render
//! cost, the photon pass included).

use crate::common;

use common::examples::{fresnel, photon_map};
use lecture6::app::cli::commands::render_cost;
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
