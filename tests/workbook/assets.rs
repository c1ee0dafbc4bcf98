//! The textures and meshes under `textures/` are exactly what the asset generator makes.

use crate::common;

use lecture6::app::assets::{ASSETS, HDR_ASSETS};

#[test]
fn bundled_textures_match_the_generator() {
    for asset in ASSETS {
        let path = common::root().join("textures").join(asset.name);
        let on_disk = image::open(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display())).to_rgb8();
        let drawn = (asset.draw)();
        assert!(on_disk == drawn, "{} is stale: run `cargo run --release --bin make-assets`", path.display());
        let bytes = std::fs::metadata(&path).unwrap().len();
        assert!(bytes < 500_000, "{} is {bytes} bytes: keep textures small", path.display());
    }
}

#[test]
fn bundled_hdr_images_match_the_generator() {
    for asset in HDR_ASSETS {
        let path = common::root().join("textures").join(asset.name);
        let on_disk = image::open(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display())).to_rgb32f();
        // Radiance HDR stores 8-bit mantissas with a shared exponent: compare after the same encoding.
        let mut encoded = Vec::new();
        (asset.draw)().write_to(&mut std::io::Cursor::new(&mut encoded), image::ImageFormat::Hdr).unwrap();
        let drawn = image::load_from_memory_with_format(&encoded, image::ImageFormat::Hdr).unwrap().to_rgb32f();
        assert!(on_disk == drawn, "{} is stale: run `cargo run --release --bin make-assets`", path.display());
        let bytes = std::fs::metadata(&path).unwrap().len();
        assert!(bytes < 500_000, "{} is {bytes} bytes: keep textures small", path.display());
    }
}

#[test]
fn bundled_meshes_match_the_generator() {
    for mesh in lecture6::app::assets::MESHES {
        let path = common::root().join("textures").join(mesh.name);
        let on_disk = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        assert!(on_disk == (mesh.write)(), "{} is stale: run `cargo run --release --bin make-assets`", path.display());
        assert!(on_disk.len() < 600_000, "{} is {} bytes: keep meshes small", path.display(), on_disk.len());
    }
}
