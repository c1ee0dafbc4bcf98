//! The textures under `textures/` are exactly what the asset generator draws.

mod common;

use lecture6::assets::ASSETS;

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
