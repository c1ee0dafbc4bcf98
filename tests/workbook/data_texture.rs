//! Data textures: a bitmap loaded as data (a roughness, bump or mask map) holds the codes as they are stored,
//! without the sRGB decoding a colour texture gets, for 8- and 16-bit PNG, JPEG and BMP; floating-point
//! files are linear either way.

use crate::common::root;
use lecture6::lesson::bitmap::Bitmap;
use lecture6::lesson::color::srgb_to_linear;
use lecture6::prelude::*;

/// A scratch folder for the test's images.
fn folder() -> PathBuf {
    let dir = root().join("target").join("data-texture-tests");
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Half an 8-bit step: a value read within it of `code / 255` is that code and no other.
const HALF_STEP: f32 = 0.5 / 255.0;

#[test]
fn grey_128_is_read_as_0_502_as_data_and_0_216_as_a_colour() {
    let dir = folder();
    let grey8 = image::GrayImage::from_pixel(4, 4, image::Luma([128]));
    let rgb8 = image::RgbImage::from_pixel(4, 4, image::Rgb([128, 128, 128]));
    // 128 * 257 is the 16-bit code of the same grey, 0.50196.
    let grey16 = image::ImageBuffer::<image::Luma<u16>, Vec<u16>>::from_pixel(4, 4, image::Luma([128 * 257]));
    let files = [
        (dir.join("grey8.png"), grey8.save(dir.join("grey8.png"))),
        (dir.join("rgb8.png"), rgb8.save(dir.join("rgb8.png"))),
        (dir.join("grey16.png"), grey16.save(dir.join("grey16.png"))),
        // A flat picture keeps its value through JPEG's compression.
        (dir.join("grey.jpg"), rgb8.save(dir.join("grey.jpg"))),
        (dir.join("grey.bmp"), rgb8.save(dir.join("grey.bmp"))),
    ];
    let stored = 128.0 / 255.0;
    for (path, saved) in files {
        saved.unwrap();
        let data = BitmapTexture::load_data(&path).unwrap().bitmap.get_pixel(1, 2);
        assert_eq!(format!("{:.3}", data.r()), "0.502", "{}", path.display());
        assert!(
            [data.r(), data.g(), data.b()].iter().all(|c| (c - stored).abs() < HALF_STEP),
            "{}: {data:?}",
            path.display()
        );
        // The same file as a colour is decoded from sRGB into linear light.
        let colour = BitmapTexture::load(&path).unwrap().bitmap.get_pixel(1, 2);
        assert_eq!(format!("{:.3}", colour.r()), "0.216", "{}", path.display());
        assert!((colour.r() - srgb_to_linear(stored)).abs() < srgb_to_linear(stored) * HALF_STEP);
    }
}

#[test]
fn the_workbooks_data_texture_is_its_stored_codes_and_a_float_file_is_linear_either_way() {
    let codes = image::open(texture_path("mirror_mask.png")).unwrap().to_rgb8();
    let data = texture_data("mirror_mask.png").unwrap();
    let colour = texture("mirror_mask.png").unwrap();
    let (w, h) = codes.dimensions();
    for (x, y) in [(0, 0), (w / 2, h / 3), (w - 1, h - 1)] {
        let code = codes.get_pixel(x, y)[0];
        let (x, y) = (x as usize, y as usize);
        assert_eq!(data.bitmap.get_pixel(x, y).r(), code as f32 / 255.0, "texel ({x}, {y})");
        assert_eq!(colour.bitmap.get_pixel(x, y).r(), srgb_to_linear(code as f32 / 255.0), "texel ({x}, {y})");
    }
    // Radiance HDR is linear light already: read as data, it is read as it is.
    let sky = texture_path("sky.hdr");
    let (data, colour) = (Bitmap::load_data(&sky).unwrap(), Bitmap::load(&sky).unwrap());
    for (x, y) in [(0, 0), (data.width() / 2, data.height() / 4)] {
        assert_eq!(data.get_pixel(x, y), colour.get_pixel(x, y));
    }
}
