//! The progressive renderer the live viewer draws with: its tiles add up to the plain render byte for byte
//! (a progressive caustic's too, pass by pass), and a cancelled render stops within one tile per worker.

use crate::common;

use common::examples::{dispersion, fresnel, glossy, photon_map};
use lecture6::app::cli::{Cli, Example};
use lecture6::instruments::progressive::{
    Outcome, TILE_SIZE, Update, coarse_settings, photon_passes, render_progressive, tiles,
};
use lecture6::lesson::render::{render, thread_pool};
use std::sync::Mutex;
use std::sync::atomic::{AtomicBool, AtomicU64, AtomicUsize, Ordering};

/// Renders the example progressively on `threads` threads and plainly, and checks that the pictures are the
/// same bit for bit, that the coarse pass came first, then every tile once (once per pass of a progressive
/// caustic, each later pass ended by its average), and that the tiles' rays (the viewer's rays per second)
/// are the plain render's.
fn same_as_plain_render<E: Example>(args: &[&str], threads: usize) {
    let cli: Cli<E> = common::parse(args);
    let (scene, settings) = cli.prepare().unwrap();
    let (plain, plain_stats) = render(&scene, &settings).unwrap();
    let seen = Mutex::new(Vec::new());
    let tile_rays = AtomicU64::new(0);
    let cancel = AtomicBool::new(false);
    let on_update = |update: Update| {
        seen.lock().unwrap().push(match update {
            Update::Coarse(frame) => (u32::MAX, frame.width, frame.height),
            Update::Tile(tile) => {
                tile_rays.fetch_add(tile.rays, Ordering::Relaxed);
                (tile.x, tile.y, tile.width * tile.height)
            }
            Update::Passes { pass, passes, frame } => {
                assert!(frame.pixels.iter().all(|c| c.is_finite()));
                (u32::MAX - passes, pass, frame.width * frame.height)
            }
        })
    };
    let outcome =
        thread_pool(Some(threads)).unwrap().install(|| render_progressive(&scene, &settings, &cancel, &on_update));
    let Outcome::Finished(frame, stats) = outcome.unwrap() else { panic!("an uncancelled render finished") };
    assert!(frame == plain, "{args:?}: the progressive picture differs from the plain render");
    assert_eq!(stats.counters.total(), plain_stats.counters.total(), "{args:?}: the picture's rays");
    if !settings.adaptive_aa {
        assert_eq!(tile_rays.into_inner(), plain_stats.counters.total(), "{args:?}: the tiles' rays");
    }
    let seen = seen.into_inner().unwrap();
    let coarse = coarse_settings(&settings);
    assert_eq!(seen[0], (u32::MAX, coarse.width, coarse.height), "the coarse pass comes first");
    let passes = photon_passes(&scene, &settings);
    let all_tiles = tiles(settings.width, settings.height);
    let mut rest = &seen[1..];
    for pass in 1..=passes {
        let (drawn, after) = rest.split_at(all_tiles.len());
        let mut drawn = drawn.to_vec();
        drawn.sort();
        let mut expected: Vec<_> = all_tiles.iter().map(|t| (t.x, t.y, t.width * t.height)).collect();
        expected.sort();
        assert_eq!(drawn, expected, "{args:?}: every tile once in pass {pass}");
        rest = after;
        if pass > 1 {
            assert_eq!(rest[0], (u32::MAX - passes, pass, settings.width * settings.height), "pass {pass}'s average");
            rest = &rest[1..];
        }
    }
    assert!(rest.is_empty(), "{args:?}: nothing after the last pass");
}

#[test]
fn tiles_add_up_to_the_plain_render() {
    // A size that is not a multiple of the tile size, so the edge tiles are partial.
    same_as_plain_render::<fresnel::Options>(&["--width", "90", "--height", "70", "--spp", "3"], 2);
    same_as_plain_render::<glossy::Options>(&["--width", "80", "--height", "45", "--spp", "4"], 1);
    // The adaptive pass, after the tiles.
    same_as_plain_render::<fresnel::Options>(&["--width", "60", "--height", "45", "--spp", "1", "--adaptive-aa"], 2);
    // Glossy samples shared out over a pixel whose extra samples come in the adaptive pass.
    same_as_plain_render::<glossy::Options>(&["--width", "48", "--height", "36", "--spp", "1", "--adaptive-aa"], 2);
}

#[test]
fn dispersive_tiles_add_up_to_the_plain_render() {
    same_as_plain_render::<dispersion::Options>(&["--width", "70", "--height", "40", "--spp", "2"], 2);
    same_as_plain_render::<dispersion::Options>(&["--width", "70", "--height", "40", "--spectral", "sampled"], 2);
}

#[test]
fn a_progressive_caustic_builds_up_pass_by_pass_to_the_plain_render() {
    let passes = ["--photon-passes", "3", "--photons", "20000"];
    same_as_plain_render::<photon_map::Options>(
        &[&["--width", "50", "--height", "40", "--spp", "1"], &passes[..]].concat(),
        2,
    );
    same_as_plain_render::<photon_map::Options>(
        &[&["--width", "40", "--height", "30", "--spp", "1", "--adaptive-aa"], &passes[..]].concat(),
        1,
    );
}

#[test]
fn tiles_cover_the_picture_centre_first() {
    let all = tiles(100, 70);
    assert_eq!(all.iter().map(|t| t.width * t.height).sum::<u32>(), 100 * 70);
    let first = &all[0];
    assert!(first.x <= 50 && 50 < first.x + first.width && first.y <= 35 && 35 < first.y + first.height);
    assert!(all.iter().all(|t| t.width <= TILE_SIZE && t.height <= TILE_SIZE && t.x + t.width <= 100));
}

/// Cancels the render when the `after`-th tile is done; on `threads` workers at most `threads - 1` more tiles
/// (those already being drawn) may follow.
fn cancel_after(after: usize, threads: usize) {
    let cli: Cli<fresnel::Options> = common::parse(&["--width", "256", "--height", "192", "--spp", "1"]);
    let (scene, settings) = cli.prepare().unwrap();
    let cancel = AtomicBool::new(false);
    let done = AtomicUsize::new(0);
    let on_update = |update: Update| {
        if let Update::Tile(_) = update
            && done.fetch_add(1, Ordering::SeqCst) + 1 == after
        {
            cancel.store(true, Ordering::SeqCst);
        }
    };
    let outcome =
        thread_pool(Some(threads)).unwrap().install(|| render_progressive(&scene, &settings, &cancel, &on_update));
    assert!(matches!(outcome.unwrap(), Outcome::Cancelled));
    let done = done.into_inner();
    let total = tiles(settings.width, settings.height).len();
    assert!(total > after + threads, "the test picture has enough tiles");
    assert!(
        (after..after + threads).contains(&done),
        "{done} tiles drawn after cancelling at {after} on {threads} threads"
    );
}

#[test]
fn a_cancelled_render_stops_within_one_tile() {
    cancel_after(3, 1);
    cancel_after(5, 2);
}

#[test]
fn a_render_cancelled_before_it_starts_draws_nothing() {
    let cli: Cli<fresnel::Options> = common::parse(&["--width", "64", "--height", "48"]);
    let (scene, settings) = cli.prepare().unwrap();
    let cancel = AtomicBool::new(true);
    let updates = AtomicUsize::new(0);
    let outcome = render_progressive(&scene, &settings, &cancel, &|_| {
        updates.fetch_add(1, Ordering::SeqCst);
    });
    assert!(matches!(outcome.unwrap(), Outcome::Cancelled));
    assert_eq!(updates.into_inner(), 0);
}
