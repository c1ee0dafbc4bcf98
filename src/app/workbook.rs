//! What the workbook's examples share that is not a slide's lesson: the bundled textures (under
//! `textures/`, made by `cargo run --bin make-assets`), the sky and a checker floor. A homework built on an
//! example uses them the same way, or its own files in their place: a file named by [`texture`] or
//! [`texture_path`] is looked for beside the example that names it first (`examples/my_floor.png` for
//! `examples/hw1.rs`), then in `textures/`. (The scenes that examples share are lessons: they are in
//! [`crate::app::scenes`].)

use crate::files::encoding::{self, Encoding};
use crate::lesson::bitmap::{Bitmap, Filter};
use crate::lesson::color::Color;
use crate::lesson::environment::{self, CubemapEnvironment, Environment};
use crate::lesson::error::{Error, Result};
use crate::lesson::geometry::Plane;
use crate::lesson::math::Vector;
use crate::lesson::node::Node;
use crate::lesson::shader::Lambert;
use crate::lesson::texture::{BitmapTexture, CheckerTexture};
use std::panic::Location;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// The path of the file `name` an example asks for: beside the example's own source file if it is there
/// (`examples/my_floor.png` for `examples/hw1.rs`), else under the workbook's `textures/` (wherever it is
/// run from), which is also the path given when it is in neither place.
#[track_caller]
pub fn texture_path(name: &str) -> PathBuf {
    find(name, Location::caller().file()).unwrap_or_else(|_| bundled(name))
}

/// Loads the texture `name` as a colour (an 8- or 16-bit file decoded from sRGB to linear light),
/// bilinearly filtered and repeating: the example's own file beside its source, or the workbook's of that
/// name under `textures/` (see [`texture_path`]). When it is in neither, the error names both places.
#[track_caller]
pub fn texture(name: &str) -> Result<BitmapTexture> {
    load_texture(name, None, Filter::default())
}

/// Loads the texture `name` as data, not as a colour (a roughness, bump or mask map: the codes as they are
/// stored, without the sRGB decoding that [`texture`] applies; see [`BitmapTexture::load_data`]), bilinearly
/// filtered and repeating, found as [`texture_path`] finds it.
#[track_caller]
pub fn texture_data(name: &str) -> Result<BitmapTexture> {
    BitmapTexture::load_data(&texture_path(name))
}

// Data textures are read by the workbook's files layer (the encoding of 8-bit codes) on the lesson's types:
// the lesson's bitmap reads colours, as the slide does.
impl Bitmap {
    /// Loads an image file as data (a roughness, bump or mask map), not as a colour: the codes of an 8- or
    /// 16-bit file (PNG, JPEG, BMP) are read as they are stored, code / 255 or code / 65535, without the sRGB
    /// decoding (grey 128 is 0.502, where [`Bitmap::load`] makes it 0.216); floating-point files (HDR, EXR)
    /// are linear already and read as `load` reads them.
    pub fn load_data(path: &Path) -> Result<Bitmap> {
        encoding::reading_as(Encoding::Raw, || Bitmap::load(path))
    }
}

impl BitmapTexture {
    /// Loads the image at `path` as data, not as a colour (a roughness, bump or mask map): its codes as they
    /// are stored, without the sRGB decoding ([`Bitmap::load_data`]).
    pub fn load_data(path: &Path) -> Result<BitmapTexture> {
        Ok(BitmapTexture::new(Arc::new(Bitmap::load_data(path)?)))
    }
}

/// Loads the texture `name` as [`texture`] does, or the student's own file in its place when `custom` is
/// given.
#[track_caller]
pub fn load_texture(name: &str, custom: Option<&Path>, filter: Filter) -> Result<BitmapTexture> {
    let path = match custom {
        Some(custom) => custom.to_path_buf(),
        None => find(name, Location::caller().file())?,
    };
    Ok(BitmapTexture::new(Arc::new(Bitmap::load(&path)?)).with_filter(filter))
}

/// Where the file `name` asked for by the source file `caller` (as the compiler names it) is: beside that
/// file, or else under the workbook's `textures/`; an error naming both places when it is in neither. The
/// library's own files (its scenes) take the bundled textures only.
fn find(name: &str, caller: &str) -> Result<PathBuf> {
    let workbook = Path::new(env!("CARGO_MANIFEST_DIR"));
    // The compiler names a file of the workbook's own package from the workbook's folder, any other by its
    // whole path.
    let source = workbook.join(caller);
    let own = source.strip_prefix(workbook).is_ok_and(|inside| inside.starts_with("src"));
    let beside = source.parent().filter(|_| !own).map(|folder| folder.join(name));
    match (beside, bundled(name)) {
        (Some(beside), _) if beside.exists() => Ok(beside),
        (_, bundled) if bundled.exists() => Ok(bundled),
        (beside, bundled) => Err(nowhere(name, beside.as_deref(), &bundled)),
    }
}

/// The error for the file `name`, found in neither place it was looked for.
fn nowhere(name: &str, beside: Option<&Path>, bundled: &Path) -> Error {
    let bundled = format!("in the workbook's textures/, {}", bundled.display());
    let looked = match beside {
        Some(beside) => format!("looked for beside the example, {}, and {bundled}", beside.display()),
        None => format!("looked for {bundled}"),
    };
    Error::file("cannot find texture", Path::new(name), looked)
}

/// The path of a file under the workbook's `textures/`.
fn bundled(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("textures").join(name)
}

/// The bundled sky (`textures/sky.hdr`) as an equirectangular environment.
pub fn sky() -> Result<Arc<dyn Environment>> {
    environment::load(&bundled("sky.hdr"))
}

/// The same sky as six cube faces (`textures/sky_cubemap/`).
pub fn sky_cubemap() -> Result<Arc<dyn Environment>> {
    Ok(Arc::new(CubemapEnvironment::load(&bundled("sky_cubemap"))?))
}

/// The direction of the bundled sky's sun.
pub fn sun_direction() -> Vector {
    crate::app::assets::sun_direction()
}

/// A square floor of `2 * half_size` units at y = 0, in light and dark grey squares of `square` units.
pub fn checker_floor(half_size: f32, square: f32) -> Node {
    let checker = CheckerTexture { color1: Color::gray(0.75), color2: Color::gray(0.18), scaling: 1.0 / square };
    Node::new(Plane::new(0.0, half_size), Lambert::new(checker))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_file_beside_the_example_comes_first_then_the_workbooks() {
        let dir = tempfile::tempdir().unwrap();
        let example = dir.path().join("hw1.rs").display().to_string();
        // Not beside it: the bundled one.
        assert_eq!(find("wood.png", &example).unwrap(), bundled("wood.png"));
        // Beside it: the student's, also when the workbook has one of that name.
        for name in ["my_floor.png", "wood.png"] {
            std::fs::write(dir.path().join(name), b"").unwrap();
            assert_eq!(find(name, &example).unwrap(), dir.path().join(name));
        }
        // An example of the workbook, named from its folder.
        let examples = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples");
        assert_eq!(find("fresnel.rs", "examples/hw1.rs").unwrap(), examples.join("fresnel.rs"));
        // The library's own scenes take the bundled textures.
        assert_eq!(find("mod.rs", "src/app/scenes/reflection.rs").ok(), None);
    }

    #[test]
    fn a_file_in_neither_place_is_refused_naming_both() {
        let message = find("my_floor.png", "examples/hw1.rs").unwrap_err().to_string();
        let workbook = Path::new(env!("CARGO_MANIFEST_DIR"));
        for place in [workbook.join("examples/my_floor.png"), workbook.join("textures/my_floor.png")] {
            assert!(message.contains(&place.display().to_string()), "{message}");
        }
        assert!(message.starts_with("cannot find texture 'my_floor.png': looked for beside the example"), "{message}");
    }
}
