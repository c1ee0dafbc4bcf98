//! The course's adaptive anti-aliasing (format spec, appendix A.2) as an option of the renderer: more
//! samples exactly where neighbours differ, the same picture whatever the thread count.

use crate::common;

use lecture6::app::scene_file::{LoadOptions, load};
use lecture6::lesson::adaptive_aa::marked;
use lecture6::lesson::color::Color;
use lecture6::lesson::frame::Frame;
use lecture6::lesson::render::{RenderSettings, render};

fn fresnel_file() -> lecture6::app::scene_file::SceneFile {
    load(&common::root().join("examples/data/fresnel.qdmg"), &LoadOptions::default()).unwrap()
}

#[test]
fn only_pixels_that_differ_from_a_neighbour_change_and_the_picture_is_deterministic() {
    let file = fresnel_file();
    let plain = RenderSettings { width: 160, height: 120, spp: 1, ..Default::default() };
    let (single, _) = render(&file.scene, &plain).unwrap();
    let adaptive = RenderSettings { adaptive_aa: true, threads: Some(1), ..plain };
    let (refined, stats) = render(&file.scene, &adaptive).unwrap();
    let (again, _) = render(&file.scene, &RenderSettings { threads: Some(2), ..adaptive }).unwrap();
    assert_eq!(refined.pixels, again.pixels, "the same picture on 1 and 2 threads");
    let marks = marked(&single);
    let count = marks.iter().filter(|&&m| m).count();
    assert!(count > 0 && count < marks.len() / 2, "{count} of {} pixels marked", marks.len());
    for ((m, a), b) in marks.iter().zip(&single.pixels).zip(&refined.pixels) {
        if !m {
            assert_eq!(a, b, "an unmarked pixel keeps its single sample");
        }
    }
    let changed = marks.iter().zip(single.pixels.iter().zip(&refined.pixels)).filter(|(m, (a, b))| **m && a != b);
    assert!(changed.count() > count / 2, "marked pixels get new samples");
    // Four more camera rays per marked pixel.
    let (_, plain_stats) = render(&file.scene, &plain).unwrap();
    assert_eq!(stats.counters.rays_by_depth[0], plain_stats.counters.rays_by_depth[0] + 4 * count as u64);
    assert!(refined.pixels.iter().all(|p| p.is_finite()));
}

#[test]
fn adaptive_anti_aliasing_starts_from_one_sample() {
    let file = fresnel_file();
    let settings = RenderSettings { width: 16, height: 12, spp: 4, adaptive_aa: true, ..Default::default() };
    let e = render(&file.scene, &settings).err().map(|e| e.to_string()).unwrap_or_default();
    assert!(e.contains("one sample per pixel"), "{e}");
}

#[test]
fn pixels_next_to_an_edge_are_marked_and_flat_ones_are_not() {
    let mut frame = Frame::new(6, 4);
    for y in 0..4 {
        for x in 3..6 {
            frame.pixels[y * 6 + x] = Color::gray(0.5);
        }
    }
    // Above 1 both sides clamp to 1: no difference.
    frame.pixels[0] = Color::gray(5.0);
    frame.pixels[1] = Color::gray(1.0);
    let m = marked(&frame);
    for y in 0..4 {
        let row: Vec<bool> = m[y * 6..y * 6 + 6].to_vec();
        assert_eq!(&row[2..4], &[true, true], "row {y}");
        assert!(!row[5], "row {y}");
    }
    assert!(m[0] && m[1], "a pixel of 1 beside black is marked");
    assert!(!m[6 * 3], "bottom-left is flat black");
}
