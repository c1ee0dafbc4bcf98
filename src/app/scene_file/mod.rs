//! The course's scene files (`.qdmg`): a scene described in text instead of code, as the course's own
//! renderer reads it. The format is specified in the workbook's `qdmg-format.md` (the section numbers below
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
//! Bumps) are an error naming the line and the element, or, with [`LoadOptions::skip_unsupported`],
//! skipped with a warning (with whatever refers to them).
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
//!   `assumedGamma` applies to the image's stored values, as in the course: 8-bit images are linear unless
//!   `assumedGamma 2.2` (sRGB) or another gamma is given.
//! - `Mesh` polygons are cut by ear clipping in their plane (the course: a fan, wrong for non-convex
//!   polygons); `autoSmooth` weights face normals by area (the course: unweighted).
//! - `CubemapEnvironment` reads the course's face layout (`negz` turned by 180° against OpenGL's); the
//!   workbook's own extension property `layout opengl` reads an OpenGL-layout folder instead.
//! - A missing Node `shader` skips the node with a warning; missing Node `geometry`, PointLight `pos` and
//!   Camera `position` are errors; so are the degenerate values the course does not check (zero scales,
//!   `glossiness 0`, BitmapTexture `scaling 0`), and a file that cannot be decoded.
//! - Paths are resolved against the scene file's folder; an absolute path is used as it is (an extension).

pub mod parse;
pub mod values;

use crate::lesson::camera::{Camera, FovAxis};
use crate::lesson::color::{Color, linear_to_srgb, srgb_to_linear};
use crate::lesson::environment::{CubemapEnvironment, CubemapLayout, Environment};
use crate::lesson::error::{Error, Result};
use crate::lesson::geometry::{Cube, Geometry, Mesh, Plane, Sphere};
use crate::lesson::light::PointLight;
use crate::lesson::math::Vector;
use crate::lesson::node::Node;
use crate::lesson::scene::Scene;
use crate::lesson::shader::{ColorSource, Lambert, Layered, Phong, Reflection, Refraction, Shader};
use crate::lesson::texture::{BitmapTexture, CheckerTexture, Fresnel, FresnelMode, Texture};
use crate::lesson::transform::Transform;
use parse::{Block, Property};
use rayon::prelude::*;
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// How to load a scene file.
#[derive(Clone, Copy, Debug, Default)]
pub struct LoadOptions {
    /// Skip the elements of later lectures with a warning, instead of failing, so the rest renders.
    pub skip_unsupported: bool,
}

/// A loaded scene file: the scene, the render settings the file asks for, and the warnings.
pub struct SceneFile {
    pub scene: Scene,
    /// GlobalSettings `frameWidth` and `frameHeight`.
    pub width: u32,
    pub height: u32,
    /// GlobalSettings `wantAA`: the course's adaptive anti-aliasing.
    pub adaptive_aa: bool,
    /// Warnings and notes, each on one line naming the file and the line.
    pub warnings: Vec<String>,
}

/// The course keeps at most 32 layers of a Layered shader (and so does the workbook's).
const COURSE_MAX_LAYERS: usize = 32;

/// The elements of later lectures, which the workbook does not render, and what they are.
const UNSUPPORTED: [(&str, &str); 8] = [
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
fn namespace(class: &str) -> Option<Namespace> {
    Some(match class {
        "Plane" | "Sphere" | "Cube" | "CsgPlus" | "CsgAnd" | "CsgMinus" | "Mesh" | "Heightfield" => Namespace::Geometry,
        "Lambert" | "Phong" | "Refl" | "Refr" | "Layered" | "Const" => Namespace::Shader,
        "CheckerTexture" | "BitmapTexture" | "Fresnel" | "BumpTexture" | "Bumps" => Namespace::Texture,
        "Node" => Namespace::Node,
        _ => return None,
    })
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
enum Namespace {
    Geometry,
    Shader,
    Texture,
    Node,
}

impl Namespace {
    fn word(self) -> &'static str {
        match self {
            Namespace::Geometry => "geometry",
            Namespace::Shader => "shader",
            Namespace::Texture => "texture",
            Namespace::Node => "node",
        }
    }
}

/// The course's fill order (spec 1.9): the group of each class.
fn fill_group(class: &str) -> usize {
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

/// Loads the scene file at `path`. Errors are one line naming the file and the line; warnings go to
/// [`SceneFile::warnings`].
pub fn load(path: &Path, options: &LoadOptions) -> Result<SceneFile> {
    let bytes = std::fs::read(path).map_err(|e| Error::file("cannot read scene", path, e))?;
    let text = String::from_utf8_lossy(&bytes);
    let mut loader = Loader::new(path, options);
    let mut syntax_warnings = Vec::new();
    let blocks = parse::parse(&text, &mut syntax_warnings)
        .map_err(|e| Error::file("cannot load scene", path, format!("line {}: {}", e.line, e.message)))?;
    for (line, w) in syntax_warnings {
        loader.warn(line, w);
    }
    loader.run(&blocks)
}

/// Built elements of one namespace: `None` for an element that was skipped.
type Built<T> = HashMap<usize, Option<T>>;

struct Loader<'a> {
    path: &'a Path,
    dir: PathBuf,
    options: &'a LoadOptions,
    warnings: Vec<String>,
    /// Name -> index of the first block of that name, per namespace.
    names: HashMap<(Namespace, String), usize>,
    geometries: Built<Arc<dyn Geometry>>,
    textures: Built<Arc<dyn Texture>>,
    shaders: Built<Arc<dyn Shader>>,
    /// Shaders being built, to report a Layered that contains itself.
    building: Vec<usize>,
}

/// The GlobalSettings, merged over every GlobalSettings block (spec 1.10).
struct Settings {
    width: i64,
    height: i64,
    ambient: Color,
    max_depth: i64,
    want_aa: bool,
    /// The lecture-6 era's light: position (and line) and intensity.
    light_pos: Option<(Vector, usize)>,
    light_intensity: f64,
}

impl<'a> Loader<'a> {
    fn new(path: &'a Path, options: &'a LoadOptions) -> Loader<'a> {
        let dir = path.parent().map_or_else(PathBuf::new, Path::to_path_buf);
        Loader {
            path,
            dir,
            options,
            warnings: Vec::new(),
            names: HashMap::new(),
            geometries: HashMap::new(),
            textures: HashMap::new(),
            shaders: HashMap::new(),
            building: Vec::new(),
        }
    }

    fn error(&self, line: usize, message: impl std::fmt::Display) -> Error {
        Error::file("cannot load scene", self.path, format!("line {line}: {message}"))
    }

    fn warn(&mut self, line: usize, message: impl std::fmt::Display) {
        self.warnings.push(format!("{}:{line}: warning: {message}", self.path.display()));
    }

    fn note(&mut self, line: usize, message: impl std::fmt::Display) {
        self.warnings.push(format!("{}:{line}: note: {message}", self.path.display()));
    }

    fn run(mut self, blocks: &[Block]) -> Result<SceneFile> {
        for (i, b) in blocks.iter().enumerate() {
            if let (Some(ns), Some(name)) = (namespace(&b.class), &b.name) {
                match self.names.get(&(ns, name.clone())) {
                    Some(&first) => {
                        let first_line = blocks[first].line;
                        self.warn(
                            b.line,
                            format!(
                                "a {} called `{name}` is already defined at line {first_line}, which references get",
                                ns.word()
                            ),
                        );
                    }
                    None => {
                        self.names.insert((ns, name.clone()), i);
                    }
                }
            }
        }
        let mut order: Vec<usize> = (0..blocks.len()).collect();
        order.sort_by_key(|&i| fill_group(&blocks[i].class));
        let mut settings = Settings {
            width: 640,
            height: 480,
            ambient: Color::BLACK,
            max_depth: 4,
            want_aa: true,
            light_pos: None,
            light_intensity: 1.0,
        };
        let mut camera: Option<(Camera, f64, usize)> = None;
        let mut environment: Option<(Arc<dyn Environment>, usize)> = None;
        let mut lights = Vec::new();
        let mut nodes = Vec::new();
        for &i in &order {
            let b = &blocks[i];
            if let Some((_, what)) = UNSUPPORTED.iter().find(|(c, _)| *c == b.class) {
                self.unsupported(b, what)?;
                match namespace(&b.class) {
                    Some(Namespace::Geometry) => _ = self.geometries.insert(i, None),
                    Some(Namespace::Texture) => _ = self.textures.insert(i, None),
                    Some(Namespace::Shader) => _ = self.shaders.insert(i, None),
                    _ => {}
                }
                continue;
            }
            let mut r = Reader::new(b);
            match b.class.as_str() {
                "GlobalSettings" => self.global_settings(&mut r, &mut settings)?,
                "Camera" => {
                    if let Some((_, _, line)) = camera {
                        self.warn(
                            b.line,
                            format!("a second Camera (the first is at line {line}): the last one is used"),
                        );
                    }
                    let (c, aspect) = self.camera(&mut r)?;
                    camera = Some((c, aspect, b.line));
                }
                "CubemapEnvironment" => {
                    if let Some((_, line)) = environment {
                        self.warn(
                            b.line,
                            format!("a second CubemapEnvironment (the first is at line {line}): the last one is used"),
                        );
                    }
                    environment = Some((self.cubemap(&mut r)?, b.line));
                }
                "PointLight" => {
                    let pos = r.vector(&self, "pos")?.ok_or_else(|| self.required(b, "pos"))?;
                    let color = r.color(&self, "color", Color::WHITE)?;
                    let power = r.float(&self, "power", 1.0, -1e17, 1e17)?;
                    lights.push(PointLight::new(pos, color, power as f32));
                }
                "Plane" | "Sphere" | "Cube" | "Mesh" => {
                    let g = self.geometry(&mut r)?;
                    self.geometries.insert(i, Some(g));
                }
                "CheckerTexture" | "BitmapTexture" | "Fresnel" => {
                    let t = self.texture(&mut r)?;
                    self.textures.insert(i, Some(t));
                }
                "Lambert" | "Phong" | "Refl" | "Refr" | "Layered" => {
                    self.shader(blocks, i)?;
                    continue; // the shader read its own properties
                }
                "Node" => nodes.extend(self.node(&mut r, blocks)?),
                class => unreachable!("class {class} was checked by the parser"),
            }
            r.finish(&mut self);
        }
        let (mut camera, aspect, camera_line) =
            camera.ok_or_else(|| Error::file("cannot load scene", self.path, "there is no Camera block"))?;
        let frame_aspect = settings.width as f64 / settings.height as f64;
        if (aspect - frame_aspect).abs() > 1e-3 * frame_aspect {
            self.warn(camera_line, format!("aspectRatio {aspect} differs from the frame's {frame_aspect:.5}: the workbook's camera takes the frame's (the course stretches the picture)"));
        }
        camera.aspect = frame_aspect as f32;
        if let Some((pos, line)) = settings.light_pos {
            let power = settings.light_intensity;
            self.note(line, format!("lightPos and lightIntensity (the lecture-6 era's single light) become a white PointLight at {pos} of power {power}; the course at HEAD ignores them and renders the scene without it"));
            lights.push(PointLight::new(pos, Color::WHITE, power as f32));
        }
        let mut scene = Scene::new(camera);
        scene.ambient = settings.ambient;
        scene.max_depth = settings.max_depth as u32;
        scene.lights = lights;
        scene.environment = environment.map(|(e, _)| e);
        scene.nodes = nodes;
        Ok(SceneFile {
            scene,
            width: settings.width as u32,
            height: settings.height as u32,
            adaptive_aa: settings.want_aa,
            warnings: self.warnings,
        })
    }

    /// An element of a later lecture: an error, or a warning when such elements are skipped.
    fn unsupported(&mut self, b: &Block, what: &str) -> Result<()> {
        let message = format!("`{}` ({what}) belongs to a later lecture and is not rendered by the workbook", b.class);
        if !self.options.skip_unsupported {
            return Err(self.error(b.line, format!("{message} (--skip-unsupported renders the rest without it)")));
        }
        self.warn(b.line, format!("{message}: skipped, with whatever refers to it"));
        Ok(())
    }

    fn required(&self, b: &Block, property: &str) -> Error {
        self.error(b.end_line, format!("required property `{property}` not defined in `{}` (line {})", b.class, b.line))
    }

    /// A file or folder property, resolved against the scene file's folder (spec 2.1); it must exist.
    fn file(&self, p: &Property) -> Result<PathBuf> {
        let path = self.dir.join(&p.value);
        if !path.exists() {
            return Err(self.error(p.line, format!("required file not found: '{}'", path.display())));
        }
        Ok(path)
    }

    /// An error loading the file a property names: the file's own error, at the property's line.
    fn file_error(&self, p: &Property, e: Error) -> Error {
        self.error(p.line, e)
    }

    /// The element a reference names in its namespace: `Ok(None)` when it was skipped.
    fn reference<T: Clone>(
        &self,
        p: &Property,
        name: &str,
        ns: Namespace,
        built: impl FnOnce(&Self, usize) -> Option<Option<T>>,
    ) -> Result<(usize, Option<T>)> {
        let index = *self
            .names
            .get(&(ns, name.to_string()))
            .ok_or_else(|| self.error(p.line, format!("{} `{name}` not defined", ns.word())))?;
        Ok((index, built(self, index).flatten()))
    }

    fn global_settings(&mut self, r: &mut Reader, s: &mut Settings) -> Result<()> {
        s.width = r.int(self, "frameWidth", s.width, 1, 1920)?;
        s.height = r.int(self, "frameHeight", s.height, 1, 1920)?;
        s.ambient = r.color(self, "ambientLight", s.ambient)?;
        s.max_depth = r.int(self, "maxTraceDepth", s.max_depth, 0, i32::MAX as i64)?;
        s.want_aa = r.boolean(self, "wantAA", s.want_aa);
        if r.boolean(self, "gi", false) {
            let line = r.line_of("gi");
            self.warn(line, "path tracing (`gi`) belongs to a later lecture: the scene is ray traced instead");
        }
        if r.boolean(self, "interactive", false) {
            let line = r.line_of("interactive");
            self.warn(
                line,
                "`interactive` is not supported: the picture is rendered once, with anti-aliasing as `wantAA` says",
            );
        }
        // Read for their checks only: they do not change the picture (`saturation` only in stereo mode).
        r.int(self, "numPaths", 10, 1, i32::MAX as i64)?;
        r.float(self, "saturation", 1.0, 0.0, 1.0)?;
        r.int(self, "numThreads", 0, 0, 64)?;
        for key in ["wantPrepass", "fullscreen", "dbg"] {
            r.boolean(self, key, false);
        }
        if let Some(pos) = r.vector(self, "lightPos")? {
            s.light_pos = Some((pos, r.line_of("lightPos")));
        }
        s.light_intensity = r.float(self, "lightIntensity", s.light_intensity, -1e120, 1e120)?;
        Ok(())
    }

    /// The camera and its `aspectRatio`.
    fn camera(&mut self, r: &mut Reader) -> Result<(Camera, f64)> {
        let position = r.vector(self, "position")?.ok_or_else(|| self.required(r.block, "position"))?;
        let yaw = r.float(self, "yaw", 0.0, -1e120, 1e120)?;
        let pitch = r.float(self, "pitch", 0.0, -90.0, 90.0)?;
        let roll = r.float(self, "roll", 0.0, -1e120, 1e120)?;
        let fov = r.float(self, "fov", 90.0, 0.0001, 179.0)?;
        let aspect = r.float(self, "aspectRatio", 4.0 / 3.0, 1e-6, 1e120)?;
        for (key, what) in [("dof", "depth of field"), ("autofocus", "autofocus")] {
            if r.boolean(self, key, false) {
                let line = r.line_of(key);
                self.warn(line, format!("{what} (`{key}`) belongs to a later lecture: the camera is a pinhole"));
            }
        }
        r.float(self, "fNumber", 2.0, 0.0, 1e120)?;
        r.int(self, "numSamples", 32, 1, i32::MAX as i64)?;
        r.float(self, "focalPlaneDist", 100.0, 0.1, 1e120)?;
        if r.float(self, "stereoSeparation", 0.0, 0.0, 1e120)? > 0.0 {
            let line = r.line_of("stereoSeparation");
            self.warn(line, "stereo (`stereoSeparation`) belongs to a later lecture: one eye is rendered");
        }
        r.color(self, "leftMask", Color::new(1.0, 0.0, 0.0))?;
        r.color(self, "rightMask", Color::new(0.0, 1.0, 1.0))?;
        let camera = Camera {
            position,
            yaw: yaw as f32,
            pitch: pitch as f32,
            roll: roll as f32,
            fov: fov as f32,
            fov_axis: FovAxis::Diagonal,
            aspect: aspect as f32,
        };
        Ok((camera, aspect))
    }

    fn cubemap(&mut self, r: &mut Reader) -> Result<Arc<dyn Environment>> {
        let p = r.raw("folder").ok_or_else(|| self.required(r.block, "folder"))?;
        let folder = self.file(p)?;
        let layout = match r.raw("layout") {
            None => CubemapLayout::Course,
            Some(l) => match l.value.as_str() {
                "course" => CubemapLayout::Course,
                "opengl" => CubemapLayout::OpenGl,
                v => return Err(self.error(l.line, format!("unknown cube-map layout `{v}` (course or opengl)"))),
            },
        };
        let env = CubemapEnvironment::load_layout(&folder, layout).map_err(|e| self.file_error(p, e))?;
        Ok(Arc::new(env))
    }

    fn geometry(&mut self, r: &mut Reader) -> Result<Arc<dyn Geometry>> {
        Ok(match r.block.class.as_str() {
            "Plane" => {
                let y = r.float(self, "y", 0.0, -1e120, 1e120)?;
                let limit = r.float(self, "limit", 1e99, -1e120, 1e120)?;
                Arc::new(Plane::new(y as f32, limit as f32))
            }
            "Sphere" => {
                let center = r.vector(self, "O")?.unwrap_or(Vector::ZERO);
                let radius = r.float(self, "R", 1.0, -1e120, 1e120)?;
                Arc::new(Sphere::new(center, radius as f32))
            }
            "Cube" => {
                let center = r.vector(self, "O")?.unwrap_or(Vector::ZERO);
                let half_side = r.float(self, "halfSide", 0.5, -1e120, 1e120)?;
                Arc::new(Cube::new(center, half_side as f32))
            }
            _ => {
                let p = r.raw("file").ok_or_else(|| self.required(r.block, "file"))?;
                let path = self.file(p)?;
                let faceted = r.boolean(self, "faceted", false);
                let culling = r.boolean(self, "backfaceCulling", true);
                let auto_smooth = r.boolean(self, "autoSmooth", false);
                r.boolean(self, "useKDTree", true); // the acceleration structure: no effect on the picture
                let mesh = Mesh::load_auto_smooth(&path, auto_smooth).map_err(|e| self.file_error(p, e))?;
                let mesh = if faceted { mesh.with_faceted(true) } else { mesh };
                Arc::new(mesh.with_backface_culling(culling))
            }
        })
    }

    fn texture(&mut self, r: &mut Reader) -> Result<Arc<dyn Texture>> {
        Ok(match r.block.class.as_str() {
            "CheckerTexture" => {
                let color1 = r.color(self, "color1", Color::BLACK)?;
                let color2 = r.color(self, "color2", Color::BLACK)?;
                let scaling = r.float(self, "scaling", 1.0, -1e120, 1e120)?;
                // The course's squares are 5 / scaling units wide; the workbook's 1 / scaling.
                Arc::new(CheckerTexture { color1, color2, scaling: (scaling / 5.0) as f32 })
            }
            "BitmapTexture" => {
                let p = r.raw("file").ok_or_else(|| self.required(r.block, "file"))?;
                let path = self.file(p)?;
                let scaling = r.float(self, "scaling", 1.0, -1e120, 1e120)?;
                if scaling == 0.0 {
                    return Err(self.error(r.line_of("scaling"), "BitmapTexture `scaling` must not be 0"));
                }
                let gamma = r.float(self, "assumedGamma", 1.0, -1e17, 1e17)? as f32;
                let texture = BitmapTexture::load(&path).map_err(|e| self.file_error(p, e))?;
                let bitmap = with_assumed_gamma(&texture.bitmap, &path, gamma);
                Arc::new(BitmapTexture::new(Arc::new(bitmap)).with_scaling(scaling as f32))
            }
            _ => {
                let ior = r.float(self, "ior", 1.33, 1e-6, 10.0)?;
                Arc::new(Fresnel::new(ior as f32, FresnelMode::Schlick))
            }
        })
    }

    /// Builds the shader of block `i` (once; a Layered builds the shaders of its layers first).
    fn shader(&mut self, blocks: &[Block], i: usize) -> Result<Option<Arc<dyn Shader>>> {
        if let Some(built) = self.shaders.get(&i) {
            return Ok(built.clone());
        }
        let b = &blocks[i];
        if UNSUPPORTED.iter().any(|(c, _)| *c == b.class) {
            return Ok(None); // reported when its turn comes in the fill order
        }
        if self.building.contains(&i) {
            return Err(
                self.error(b.line, format!("the Layered shader `{}` contains itself", b.name.as_deref().unwrap_or("")))
            );
        }
        self.building.push(i);
        let mut r = Reader::new(b);
        let shader: Arc<dyn Shader> = match b.class.as_str() {
            "Lambert" => {
                let color = self.color_source(&mut r, Color::BLACK)?;
                Arc::new(Lambert::new(color))
            }
            "Phong" => {
                let color = self.color_source(&mut r, Color::gray(0.5))?;
                let exponent = r.float(self, "specularExponent", 10.0, -1e120, 1e120)?;
                let multiplier = r.float(self, "specularMultiplier", 0.4, -1e120, 1e120)?;
                Arc::new(Phong::new(color, multiplier as f32, exponent as f32))
            }
            "Refl" => {
                let multiplier = r.float(self, "multiplier", 0.99, -1e120, 1e120)? as f32;
                let glossiness = r.float(self, "glossiness", 1.0, 0.0, 1.0)?;
                let samples = r.int(self, "numSamples", 32, 1, i32::MAX as i64)?;
                if glossiness == 0.0 {
                    return Err(self.error(
                        r.line_of("glossiness"),
                        "Refl `glossiness` 0 is degenerate (an infinitely wide cone)",
                    ));
                }
                if glossiness == 1.0 {
                    Arc::new(Reflection::new(multiplier))
                } else {
                    let glossy = Reflection::glossy(Color::gray(multiplier), glossiness as f32, samples as u32);
                    Arc::new(glossy.map_err(|e| self.error(r.line_of("glossiness"), e))?)
                }
            }
            "Refr" => {
                let ior = r.float(self, "ior", 1.33, 1e-6, 10.0)?;
                let multiplier = r.float(self, "multiplier", 0.99, -1e120, 1e120)?;
                Arc::new(Refraction::new(ior as f32, multiplier as f32))
            }
            _ => Arc::new(self.layered(blocks, b)?),
        };
        if b.class != "Layered" {
            r.finish(self);
        }
        self.building.pop();
        self.shaders.insert(i, Some(shader.clone()));
        Ok(Some(shader))
    }

    /// A Lambert's or Phong's `color`, replaced entirely by its `texture` when it has one.
    fn color_source(&mut self, r: &mut Reader, default: Color) -> Result<ColorSource> {
        let color = r.color(self, "color", default)?;
        let Some(p) = r.raw("texture") else { return Ok(ColorSource::Color(color)) };
        match self.texture_ref(p, &p.value)? {
            Some(t) => Ok(ColorSource::Texture(t)),
            None => {
                self.warn(p.line, format!("texture `{}` was skipped: the colour is used instead", p.value));
                Ok(ColorSource::Color(color))
            }
        }
    }

    fn texture_ref(&self, p: &Property, name: &str) -> Result<Option<Arc<dyn Texture>>> {
        Ok(self.reference(p, name, Namespace::Texture, |s, i| s.textures.get(&i).cloned())?.1)
    }

    /// A Layered shader from its `layer SHADER COLOR [TEXTURE]` lines (spec 3.7); every other line is
    /// ignored without a warning, as in the course.
    fn layered(&mut self, blocks: &[Block], b: &Block) -> Result<Layered> {
        let mut layered = Layered::new();
        let syntax = "expected `layer SHADER (r, g, b) [TEXTURE]`";
        for p in b.properties.iter().filter(|p| p.name == "layer") {
            let (first, rest) = p.value.split_once(|c: char| c.is_ascii_whitespace()).unwrap_or((&p.value, ""));
            let shader_name = first.replace(',', "");
            let mut rest = rest.trim_matches(|c: char| c.is_ascii_whitespace());
            if rest.is_empty() {
                return Err(self.error(p.line, syntax));
            }
            let mut texture_name = None;
            if !rest.ends_with(')') {
                let (before, last) = rest.rsplit_once(|c: char| c.is_ascii_whitespace()).unwrap_or(("", rest));
                texture_name = Some(last.replace(',', ""));
                rest = before;
            }
            let blend = values::triple(rest)
                .ok_or_else(|| self.error(p.line, format!("{syntax}: the colour is not three numbers")))?;
            let blend = Color::new(blend[0] as f32, blend[1] as f32, blend[2] as f32);
            let index = *self
                .names
                .get(&(Namespace::Shader, shader_name.clone()))
                .ok_or_else(|| self.error(p.line, format!("{syntax}: shader `{shader_name}` not defined")))?;
            let texture = match texture_name.as_deref() {
                None | Some("NULL") => None,
                Some(name) => match self.names.get(&(Namespace::Texture, name.to_string())) {
                    None => return Err(self.error(p.line, format!("{syntax}: texture `{name}` not defined"))),
                    Some(t) => match self.textures.get(t).cloned().flatten() {
                        Some(t) => Some(t),
                        None => {
                            self.warn(
                                p.line,
                                format!("texture `{name}` was skipped: the layer is blended by its colour alone"),
                            );
                            None
                        }
                    },
                },
            };
            let Some(shader) = self.shader(blocks, index)? else {
                self.warn(p.line, format!("shader `{shader_name}` was skipped: so is this layer"));
                continue;
            };
            if layered.layers().len() == COURSE_MAX_LAYERS {
                self.warn(
                    p.line,
                    format!("more than {} layers: this one is dropped, as in the course", COURSE_MAX_LAYERS),
                );
                continue;
            }
            layered.add_layer(shader, blend, texture);
        }
        Ok(layered)
    }

    /// A Node: `None` when it is skipped (no shader, or a skipped geometry or shader).
    fn node(&mut self, r: &mut Reader, blocks: &[Block]) -> Result<Option<Node>> {
        let b = r.block;
        let gp = r.raw("geometry").ok_or_else(|| self.required(b, "geometry"))?;
        let (_, geometry) = self.reference(gp, &gp.value, Namespace::Geometry, |s, i| s.geometries.get(&i).cloned())?;
        let shader = match r.raw("shader") {
            None => {
                self.warn(b.line, "a Node without a `shader` is not rendered (as in the course)");
                None
            }
            Some(sp) => {
                let (index, _) = self.reference(sp, &sp.value, Namespace::Shader, |_, _| Some(None::<()>))?;
                self.shader(blocks, index)?
            }
        };
        if let Some(bp) = r.raw("bump") {
            self.texture_ref(bp, &bp.value)?;
            self.warn(bp.line, "bump mapping (`bump`) belongs to a later lecture: the node is rendered without it");
        }
        let transform = self.transform(r)?;
        let (Some(geometry), Some(shader)) = (geometry, shader) else {
            if r.raw_line("shader").is_some() {
                self.warn(b.line, "this Node refers to a skipped element and is not rendered");
            }
            return Ok(None);
        };
        let mut node = Node::new(geometry, shader);
        node.transform = transform;
        Ok(Some(node))
    }

    /// The transform of a Node (spec 3.3): `scale` and `rotate` lines composed in file order, each applied
    /// after the ones before; the last `translate` line applied after them all, wherever it stands.
    fn transform(&mut self, r: &mut Reader) -> Result<Option<Transform>> {
        let mut t = Transform::IDENTITY;
        let mut offset = None;
        let mut any = false;
        for k in 0..r.block.properties.len() {
            let p = &r.block.properties[k];
            if !matches!(p.name.as_str(), "scale" | "rotate" | "translate") {
                continue;
            }
            r.used[k] = true;
            any = true;
            let v = values::triple(&p.value)
                .ok_or_else(|| self.error(p.line, format!("`{}`: expected three double values", p.name)))?;
            let v = Vector::new(v[0] as f32, v[1] as f32, v[2] as f32);
            match p.name.as_str() {
                "scale" => {
                    if v.x == 0.0 || v.y == 0.0 || v.z == 0.0 || !v.is_finite() {
                        return Err(
                            self.error(p.line, format!("`scale {v}`: a zero or infinite scale cannot be undone"))
                        );
                    }
                    t = t.scale(v);
                }
                // yaw, pitch, roll; within one line pitch (about X) first, then yaw (about Y), then roll.
                "rotate" => t = t.rotate(0.0, v.y, 0.0).rotate(v.x, 0.0, 0.0).rotate(0.0, 0.0, v.z),
                _ => offset = Some(v),
            }
        }
        if let Some(o) = offset {
            t = t.translate(o);
        }
        t.check().map_err(|e| self.error(r.block.line, e))?;
        Ok(any.then_some(t))
    }
}

/// The bitmap as the course decodes it with `assumedGamma` (spec 3.8): the stored values (what the file
/// holds: 8-bit values / 255, or the floats of an HDR or EXR file) through the sRGB curve for exactly
/// 2.2, through `c^gamma` for another gamma in (0, 10), and unchanged otherwise; exactly 0 and 1 stay.
fn with_assumed_gamma(
    bitmap: &crate::lesson::bitmap::Bitmap,
    path: &Path,
    gamma: f32,
) -> crate::lesson::bitmap::Bitmap {
    let ext = path.extension().map(|e| e.to_string_lossy().to_ascii_lowercase()).unwrap_or_default();
    // The workbook decodes 8-bit images as sRGB and keeps floating-point ones linear.
    let stored = |c: f32| if matches!(ext.as_str(), "hdr" | "exr") { c } else { linear_to_srgb(c) };
    let decode = |c: f32| {
        let s = stored(c);
        if s == 0.0 || s == 1.0 {
            s
        } else if gamma == 2.2 {
            srgb_to_linear(s)
        } else if gamma > 0.0 && gamma < 10.0 && gamma != 1.0 {
            s.powf(gamma)
        } else {
            s
        }
    };
    let (w, h) = (bitmap.width(), bitmap.height());
    // Texel by texel in parallel (on the current rayon pool): two `powf` per channel are a serial step
    // before the render otherwise.
    let pixels = (0..w * h)
        .into_par_iter()
        .map(|i| {
            let [r, g, b] = bitmap.get_pixel(i % w, i / w).to_array();
            Color::new(decode(r), decode(g), decode(b))
        })
        .collect();
    crate::lesson::bitmap::Bitmap::from_pixels(w, h, pixels)
}

/// Reads the properties of one block (spec 1.7): the first line of a name wins, and every line nobody
/// read is a warning when the block is done.
struct Reader<'b> {
    block: &'b Block,
    used: Vec<bool>,
}

impl<'b> Reader<'b> {
    fn new(block: &'b Block) -> Reader<'b> {
        Reader { block, used: vec![false; block.properties.len()] }
    }

    /// The first line of the property `name`, marked as read.
    fn raw(&mut self, name: &str) -> Option<&'b Property> {
        let k = self.block.properties.iter().position(|p| p.name == name)?;
        self.used[k] = true;
        Some(&self.block.properties[k])
    }

    /// The first line of the property `name`, without marking it.
    fn raw_line(&self, name: &str) -> Option<&'b Property> {
        self.block.properties.iter().find(|p| p.name == name)
    }

    /// The line of the property `name` (or of the block, when it has none).
    fn line_of(&self, name: &str) -> usize {
        self.raw_line(name).map_or(self.block.line, |p| p.line)
    }

    fn float(&mut self, l: &Loader, name: &str, default: f64, min: f64, max: f64) -> Result<f64> {
        let Some(p) = self.raw(name) else { return Ok(default) };
        let (v, _) = values::leading_float(&p.value)
            .ok_or_else(|| l.error(p.line, format!("`{name}`: invalid number `{}`", p.value)))?;
        if !(min..=max).contains(&v) {
            return Err(l.error(p.line, format!("`{name}` {v}: value outside the allowed bounds [{min}, {max}]")));
        }
        Ok(v)
    }

    fn int(&mut self, l: &Loader, name: &str, default: i64, min: i64, max: i64) -> Result<i64> {
        let Some(p) = self.raw(name) else { return Ok(default) };
        let v = values::leading_int(&p.value)
            .ok_or_else(|| l.error(p.line, format!("`{name}`: invalid integer `{}`", p.value)))?;
        if !(min..=max).contains(&v) {
            return Err(l.error(p.line, format!("`{name}` {v}: value outside the allowed bounds [{min}, {max}]")));
        }
        Ok(v)
    }

    fn boolean(&mut self, l: &mut Loader, name: &str, default: bool) -> bool {
        let Some(p) = self.raw(name) else { return default };
        let (v, usual) = values::boolean(&p.value);
        if !usual {
            l.warn(p.line, format!("`{name} {}` reads as true (only `off`, `false` and `0` are false)", p.value));
        }
        v
    }

    fn triple(&mut self, l: &Loader, name: &str, what: &str) -> Result<Option<[f64; 3]>> {
        let Some(p) = self.raw(name) else { return Ok(None) };
        values::triple(&p.value)
            .map(Some)
            .ok_or_else(|| l.error(p.line, format!("`{name}`: invalid {what} `{}`", p.value)))
    }

    fn color(&mut self, l: &Loader, name: &str, default: Color) -> Result<Color> {
        Ok(self.triple(l, name, "color")?.map_or(default, |c| Color::new(c[0] as f32, c[1] as f32, c[2] as f32)))
    }

    fn vector(&mut self, l: &Loader, name: &str) -> Result<Option<Vector>> {
        Ok(self.triple(l, name, "vector")?.map(|v| Vector::new(v[0] as f32, v[1] as f32, v[2] as f32)))
    }

    /// Reports every line of the block that was not read.
    fn finish(self, l: &mut Loader) {
        for (p, used) in self.block.properties.iter().zip(self.used) {
            if !used {
                l.warn(p.line, format!("property `{}` isn't recognized by `{}` (ignored)", p.name, self.block.class));
            }
        }
    }
}
