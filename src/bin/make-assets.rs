//! Draws every texture of the workbook into `textures/` (see `lecture6::assets`). Deterministic: running it
//! again writes the same pictures.

use lecture6::assets::ASSETS;
use lecture6::render::save_atomically;
use std::path::Path;
use std::process::ExitCode;

fn main() -> ExitCode {
    let dir = Path::new("textures");
    for asset in ASSETS {
        let path = dir.join(asset.name);
        let img = (asset.draw)();
        if let Err(e) = save_atomically(&path, |tmp| img.save_with_format(tmp, image::ImageFormat::Png)) {
            eprintln!("make-assets: error: {e}");
            return ExitCode::from(2);
        }
        println!("{} ({}x{})", path.display(), img.width(), img.height());
    }
    ExitCode::SUCCESS
}
