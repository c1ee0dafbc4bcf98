//! What the examples write: PNG (8-bit sRGB), EXR and HDR (linear float), and the `--compare` report with its
//! heat map.

use crate::common;

use common::{root, run_example};

fn out_dir() -> std::path::PathBuf {
    let dir = root().join("target").join("output-test");
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn float_outputs_hold_the_linear_frame() {
    let frame = common::render::<common::examples::bitmap_textures::Options>(&["--width", "32", "--height", "24"]);
    for ext in ["exr", "hdr"] {
        let path = out_dir().join(format!("frame.{ext}"));
        frame.save(&path).unwrap();
        let back = image::open(&path).unwrap().to_rgb32f();
        assert_eq!(back.dimensions(), (32, 24));
        for (p, c) in back.pixels().zip(&frame.pixels) {
            for (a, b) in p.0.iter().zip(c.to_array()) {
                // EXR keeps f32 exactly; Radiance HDR keeps 8 bits of mantissa under an exponent shared by
                // the pixel's three channels, so its error is relative to the brightest one.
                let tolerance = if ext == "exr" { 0.0 } else { c.max_channel() / 128.0 };
                assert!((a - b).abs() <= tolerance, "{ext}: {a} vs {b}");
            }
        }
    }
}

#[test]
fn compare_prints_metrics_and_writes_a_heat_map() {
    let dir = out_dir();
    let reference = dir.join("reference.png");
    let output = dir.join("nearest.png");
    let heat = dir.join("nearest-diff.png");
    let _ = std::fs::remove_file(&heat);
    let small = ["--width", "80", "--height", "60"];
    assert!(
        run_example("bitmap_textures", &[&small[..], &["-o", reference.to_str().unwrap()]].concat()).status.success()
    );
    let args = [
        &small[..],
        &["--filter", "nearest", "-o", output.to_str().unwrap(), "--compare", reference.to_str().unwrap()],
    ]
    .concat();
    let out = run_example("bitmap_textures", &args);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(stdout.contains("RMSE") && stdout.contains("PSNR") && stdout.contains("max diff"), "{stdout}");
    let map = image::open(&heat).expect("heat map written").to_rgb8();
    assert!(map.width() == 80 && map.height() > 60, "the picture's heat map with its colour bar below it");
    let picture = image::imageops::crop_imm(&map, 0, 0, 80, 60).to_image();
    assert!(picture.pixels().any(|p| p.0 != [0, 0, 0]), "nearest and bilinear filtering differ somewhere");
    // Comparing with a reference of another size is one clear error.
    let out = run_example(
        "bitmap_textures",
        &["--width", "40", "--height", "30", "-o", output.to_str().unwrap(), "--compare", reference.to_str().unwrap()],
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("reference.png"));
}
