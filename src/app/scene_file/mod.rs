//! The course's scene files (`.qdmg`): a scene described in text instead of code, as the course's own
//! renderer reads it. The format is specified in `docs/qdmg-format.md` (the section numbers below
//! are its); this module reads the lecture-6 vocabulary of it and builds a [`Scene`].
//!
//! - [`parse`]: lines, comments and blocks, with line numbers (spec 1.1-1.5);
//! - [`values`]: numbers, colours, vectors and bools read as the course reads them (1.6);
//! - this module: each element reads its properties (1.7), names are resolved in their namespace (1.8),
//!   elements are filled in the course's order (1.9), and the scene is built.
//!
//! Supported elements: GlobalSettings, Camera, PointLight, Plane, Sphere, Cube, Mesh, Node, Lambert, Phong,
//! Refl (mirror and glossy), Refr, Layered, Fresnel, CheckerTexture, BitmapTexture, CubemapEnvironment.
//! The elements of later lectures (RectLight, CsgPlus, CsgAnd, CsgMinus, Heightfield, Const, BumpTexture,
//! Bumps) that no Node uses (directly or through a shader or texture it uses) are skipped with a warning
//! naming the line, as the spec's scene table counts them; a used one (and a RectLight, which lights the
//! scene by being there) is an error naming the line and the element, or, with
//! [`LoadOptions::skip_unsupported`], skipped with a warning (with whatever refers to it).
//!
//! Deviations from the course, each because the workbook's renderer differs or the course's behaviour is
//! undefined, as the spec recommends:
//! - Unknown properties are warnings, as in the course; so are the properties of later lectures that the
//!   workbook does not render (Camera `dof`, `autofocus`, stereo; GlobalSettings `gi`, `interactive`),
//!   which are read and ignored. The GlobalSettings keys of the lecture-6 era, `lightPos` and
//!   `lightIntensity` (which the course's homework-6 and homework-9 scenes still use, and which the course
//!   at HEAD ignores), become that era's single white point light, with a note.
//! - The camera's aspect ratio is the frame's (the workbook's camera takes it from the image size): an
//!   `aspectRatio` that differs from the frame's gives a warning instead of a stretched picture. Pixels are
//!   sampled at their centres, not at their top-left corners.
//! - `BitmapTexture` reads any image format the workbook reads (the course: BMP and EXR only) and samples
//!   with texel centres at half-integer coordinates (the course: at integers; a sub-texel shift).
//!   `assumedGamma` applies to the image's stored values, as in the course: without it (or with 1) the
//!   texture is data, its codes read as they are stored (grey 128 is 0.502: a roughness or mask map);
//!   `assumedGamma 2.2` decodes a colour picture from sRGB, another gamma in (0, 10) raises the values to it.
//! - A Node keeps the file's name for it (`Node ball { .. }` is `ball` in the ray tree and the end-of-run
//!   report); a Node without a name is called by its geometry and its place in the scene, `Sphere #1`.
//! - `Mesh` polygons are cut by ear clipping in their plane (the course: a fan, wrong for non-convex
//!   polygons); `autoSmooth` weights face normals by area (the course: unweighted).
//! - `CubemapEnvironment` reads the course's face layout (`negz` turned by 180° against OpenGL's); the
//!   workbook's own extension property `layout opengl` reads an OpenGL-layout folder instead.
//! - A missing Node `shader` skips the node with a warning; missing Node `geometry`, PointLight `pos` and
//!   Camera `position` are errors; so are the degenerate values the course does not check (zero scales,
//!   `glossiness 0`, BitmapTexture `scaling 0`), a file that cannot be decoded, and a Mesh with no
//!   triangle to render.
//! - A Refl or Refr `multiplier` must be within [0, 1], as on the command line (the course sets no range): a
//!   surface that gives back more light than it receives keeps the rays behind it above the weight at which
//!   they are pruned, and in a deep scene the ray tree grows without bound (`multiplier 1e10` on the glass
//!   with `maxTraceDepth 2147483647` hung).
//! - Numbers must be finite as the renderer's 32-bit floats, not only within the course's bounds (1e39 is
//!   within ±1e120 and would become infinity), colours and layer blends included; positions and lengths
//!   (positions, `O`, `R`, `halfSide`, a Plane's `y`, `translate`) stay within ±1e18, so that the renderer
//!   can square them. A Plane's `limit` beyond the 32-bit floats means no limit, as its default 1e99 does.
//! - Hostile files are refused: a scene file larger than [`MAX_SCENE_BYTES`], anything but a regular file
//!   (a FIFO, `/dev/zero`) where a file is named, images over the pixel budget
//!   ([`crate::lesson::image_file::MAX_IMAGE_PIXELS`]), Layered shaders nested more than 32 deep, and Layered
//!   shaders whose layers, theirs and so on make a hit shade more than
//!   [`crate::lesson::shader::MAX_SHADES_PER_HIT`] shaders (Layered shaders that share a shader of the level
//!   below in two layers double the work with each level), refused at the layer that passes it.
//! - Paths are resolved against the scene file's folder; an absolute path is used as it is (an extension).

mod elements;
mod loader;
pub mod parse;
mod reader;
pub mod values;

use crate::lesson::error::{Error, Result};
use crate::lesson::input;
use crate::lesson::scene::Scene;
use loader::Loader;
use std::path::Path;

/// How to load a scene file.
#[derive(Clone, Copy, Debug, Default)]
pub struct LoadOptions {
    /// Skip the elements of later lectures with a warning, instead of failing, so the rest renders.
    pub skip_unsupported: bool,
    /// The deepest `maxTraceDepth` the render can take, if it has a cap: a render without adaptive depth
    /// control (`--exhaustive`, `--slide`) takes at most 64 ([`crate::app::cli::CommonArgs::max_trace_depth`]).
    /// A deeper one is refused, naming its line.
    pub max_trace_depth: Option<u32>,
}

/// A loaded scene file: the scene, the render settings the file asks for, and the warnings.
pub struct SceneFile {
    /// The scene the file describes.
    pub scene: Scene,
    /// GlobalSettings `frameWidth`, in pixels.
    pub width: u32,
    /// GlobalSettings `frameHeight`, in pixels.
    pub height: u32,
    /// GlobalSettings `wantAA`: the course's adaptive anti-aliasing.
    pub adaptive_aa: bool,
    /// Warnings and notes, each on one line naming the file and the line.
    pub warnings: Vec<String>,
}

/// The largest scene file read: 16 MiB, thousands of times the course's largest. It is read whole, so a
/// larger file (a sparse file of gigabytes, say) is refused from its size before anything is read.
pub const MAX_SCENE_BYTES: u64 = 16 << 20;

/// The course keeps at most 32 layers of a Layered shader (and so does the workbook's).
pub(super) const COURSE_MAX_LAYERS: usize = 32;

/// How deep Layered shaders may nest (a Layered among the layers of a Layered, and so on, 32 Layered
/// shaders in a chain at most). Loading and shading both recurse once per level, so a chain of thousands
/// would overflow the stack; no scene needs more than a few levels.
pub(super) const MAX_LAYERED_NESTING: usize = 32;

/// The elements of later lectures, which the workbook does not render, and what they are.
pub(super) const UNSUPPORTED: [(&str, &str); 8] = [
    ("RectLight", "area lights"),
    ("CsgPlus", "constructive solid geometry"),
    ("CsgAnd", "constructive solid geometry"),
    ("CsgMinus", "constructive solid geometry"),
    ("Heightfield", "height fields"),
    ("Const", "the unlit shader of later scenes"),
    ("BumpTexture", "bump mapping"),
    ("Bumps", "bump mapping"),
];

/// The namespace of an element class (spec 1.8); `None` for the classes nothing refers to.
pub(super) fn namespace(class: &str) -> Option<Namespace> {
    Some(match class {
        "Plane" | "Sphere" | "Cube" | "CsgPlus" | "CsgAnd" | "CsgMinus" | "Mesh" | "Heightfield" => Namespace::Geometry,
        "Lambert" | "Phong" | "Refl" | "Refr" | "Layered" | "Const" => Namespace::Shader,
        "CheckerTexture" | "BitmapTexture" | "Fresnel" | "BumpTexture" | "Bumps" => Namespace::Texture,
        "Node" => Namespace::Node,
        _ => return None,
    })
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(super) enum Namespace {
    Geometry,
    Shader,
    Texture,
    Node,
}

impl Namespace {
    pub(super) fn word(self) -> &'static str {
        match self {
            Namespace::Geometry => "geometry",
            Namespace::Shader => "shader",
            Namespace::Texture => "texture",
            Namespace::Node => "node",
        }
    }
}

/// The course's fill order (spec 1.9): the group of each class.
pub(super) fn fill_group(class: &str) -> usize {
    match class {
        "GlobalSettings" => 0,
        "Camera" => 1,
        "CubemapEnvironment" => 2,
        "PointLight" | "RectLight" => 3,
        _ => match namespace(class) {
            Some(Namespace::Geometry) => 4,
            Some(Namespace::Texture) => 5,
            Some(Namespace::Shader) => 6,
            _ => 7,
        },
    }
}

/// The text of a scene file, without a UTF-8 byte-order mark; and whether it was read byte by byte. A file
/// that is not UTF-8 (Windows-1251, the course's Cyrillic encoding, or Latin-1) has each byte read as the
/// character of that number (U+0000 to U+00FF): every byte stays itself, so two names that differ in their
/// bytes differ in the text, and a file name is found by its bytes ([`Loader::file`]).
fn text_of(bytes: Vec<u8>) -> (String, bool) {
    let bytes = match bytes.strip_prefix(b"\xef\xbb\xbf") {
        Some(rest) => rest.to_vec(),
        None => bytes,
    };
    match String::from_utf8(bytes) {
        Ok(text) => (text, false),
        Err(e) => (e.into_bytes().iter().map(|&b| char::from(b)).collect(), true),
    }
}

/// Loads the scene file at `path`. Errors are one line naming the file and the line; warnings go to
/// [`SceneFile::warnings`].
pub fn load(path: &Path, options: &LoadOptions) -> Result<SceneFile> {
    let bytes = input::read_capped(path, "cannot read scene", "a scene file", MAX_SCENE_BYTES)?;
    let (text, bytes_as_chars) = text_of(bytes);
    let mut loader = Loader::new(path, options);
    loader.bytes_as_chars = bytes_as_chars;
    let mut syntax_warnings = Vec::new();
    let blocks = parse::parse(&text, &mut syntax_warnings)
        .map_err(|e| Error::file("cannot load scene", path, format!("line {}: {}", e.line, e.message)))?;
    for (line, w) in syntax_warnings {
        loader.warn(line, w);
    }
    loader.run(&blocks)
}
