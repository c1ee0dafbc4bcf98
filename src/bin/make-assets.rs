//! Draws every texture and writes every mesh of the workbook into `textures/` (see `lecture6::app::assets`).
//! Deterministic: running it again writes the same files.

use lecture6::Result;
use lecture6::app::assets::{ASSETS, HDR_ASSETS, MESHES};
use lecture6::files::output::save_atomically;
use std::path::Path;
use std::process::ExitCode;

fn main() -> ExitCode {
    match write_all(Path::new("textures")) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("make-assets: error: {e}");
            ExitCode::from(2)
        }
    }
}

fn write_all(dir: &Path) -> Result<()> {
    for asset in ASSETS {
        let path = dir.join(asset.name);
        let img = (asset.draw)();
        save_atomically(&path, |file| img.write_to(file, image::ImageFormat::Png))?;
        println!("{} ({}x{})", path.display(), img.width(), img.height());
    }
    for asset in HDR_ASSETS {
        let path = dir.join(asset.name);
        let img = (asset.draw)();
        save_atomically(&path, |file| img.write_to(file, image::ImageFormat::Hdr))?;
        println!("{} ({}x{}, linear HDR)", path.display(), img.width(), img.height());
    }
    for mesh in MESHES {
        let path = dir.join(mesh.name);
        let text = (mesh.write)();
        save_atomically(&path, |file| {
            std::io::Write::write_all(file, text.as_bytes()).map_err(image::ImageError::IoError)
        })?;
        println!("{} ({} bytes)", path.display(), text.len());
    }
    Ok(())
}
