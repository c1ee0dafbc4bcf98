//! The loader of a scene file: names resolved in their namespaces (spec 1.8), the blocks built in the
//! course's order (1.9), and the helpers every element's reader uses: errors and warnings with the line,
//! files resolved against the scene file's folder, references.

use super::parse::{Block, Property};
use super::reader::Reader;
use super::*;
use crate::lesson::camera::Camera;
use crate::lesson::color::Color;
use crate::lesson::environment::Environment;
use crate::lesson::error::{Error, Result, printable};
use crate::lesson::geometry::Geometry;
use crate::lesson::light::PointLight;
use crate::lesson::math::Vector;
use crate::lesson::scene::Scene;
use crate::lesson::shader::Material;
use crate::lesson::texture::Texture;
use std::collections::{HashMap, HashSet};
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// Built elements of one namespace: `None` for an element that was skipped.
pub(super) type Built<T> = HashMap<usize, Option<T>>;

pub(super) struct Loader<'a> {
    pub(super) path: &'a Path,
    pub(super) dir: PathBuf,
    pub(super) options: &'a LoadOptions,
    pub(super) warnings: Vec<String>,
    /// The file is not UTF-8 and was read byte by byte, each byte as one character (see `text_of`).
    pub(super) bytes_as_chars: bool,
    /// Name -> index of the first block of that name, per namespace.
    pub(super) names: HashMap<(Namespace, String), usize>,
    pub(super) geometries: Built<Arc<dyn Geometry>>,
    pub(super) textures: Built<Arc<dyn Texture>>,
    pub(super) shaders: Built<Material>,
    /// Shaders being built, to report a Layered that contains itself.
    pub(super) building: Vec<usize>,
    /// How many shaders one hit of each built shader shades, by its address
    /// ([`crate::lesson::shader::shades_per_hit`]; the shaders live in `shaders`).
    pub(super) counted_shades: HashMap<usize, u64>,
    /// The largest channel of the light a surface a unit from a lamp gets (the lamp's colour times its
    /// power), or of the ambient light, over the scene's lights: they are read before the textures and
    /// shaders, whose colours and multipliers scale it ([`Reader::surface_color`]).
    pub(super) brightest_light: f64,
}

/// The GlobalSettings, merged over every GlobalSettings block (spec 1.10).
pub(super) struct Settings {
    pub(super) width: i64,
    pub(super) height: i64,
    pub(super) ambient: Color,
    pub(super) max_depth: i64,
    pub(super) want_aa: bool,
    /// The lecture-6 era's light: position (and line) and intensity.
    pub(super) light_pos: Option<(Vector, usize)>,
    pub(super) light_intensity: f64,
}

impl<'a> Loader<'a> {
    pub(super) fn new(path: &'a Path, options: &'a LoadOptions) -> Loader<'a> {
        let dir = path.parent().map_or_else(PathBuf::new, Path::to_path_buf);
        Loader {
            path,
            dir,
            options,
            warnings: Vec::new(),
            bytes_as_chars: false,
            names: HashMap::new(),
            geometries: HashMap::new(),
            textures: HashMap::new(),
            shaders: HashMap::new(),
            building: Vec::new(),
            counted_shades: HashMap::new(),
            brightest_light: 0.0,
        }
    }

    pub(super) fn error(&self, line: usize, message: impl std::fmt::Display) -> Error {
        Error::file("cannot load scene", self.path, format!("line {line}: {message}"))
    }

    pub(super) fn warn(&mut self, line: usize, message: impl std::fmt::Display) {
        self.warnings.push(printable(&format!("{}:{line}: warning: {message}", self.path.display())));
    }

    pub(super) fn note(&mut self, line: usize, message: impl std::fmt::Display) {
        self.warnings.push(printable(&format!("{}:{line}: note: {message}", self.path.display())));
    }

    pub(super) fn run(mut self, blocks: &[Block]) -> Result<SceneFile> {
        for (i, b) in blocks.iter().enumerate() {
            if let (Some(ns), Some(name)) = (namespace(&b.class), &b.name) {
                match self.names.get(&(ns, name.clone())) {
                    Some(&first) => {
                        let first_line = blocks[first].line;
                        self.warn(
                            b.line,
                            format!(
                                "a {} called `{name}` is already defined at line {first_line}: references get that one, and this one is never used",
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
        let used = self.reachable_from_nodes(blocks);
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
                if namespace(&b.class).is_some() && !used.contains(&i) {
                    self.warn(
                        b.line,
                        format!("`{}` ({what}) belongs to a later lecture; no node uses it, so it is skipped", b.class),
                    );
                } else {
                    self.unsupported(b, what)?;
                }
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
                    // The light's intensity, its colour times its power, must itself be a finite number.
                    let intensity = color.0.to_array().map(|c| c as f64 * power);
                    if let Some(&c) = intensity.iter().find(|&&c| !(c as f32).is_finite()) {
                        return Err(self.error(
                            r.line_of("color"),
                            format!(
                                "the light's colour times its power is {c:.2e}: not a finite 32-bit number (the \
                                 renderer's numbers end at 3.4e38)"
                            ),
                        ));
                    }
                    let brightest = intensity.iter().fold(0.0, |m: f64, c| m.max(c.abs()));
                    self.brightest_light = self.brightest_light.max(brightest);
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

    /// The blocks that the file's Nodes reach through their references, directly or through other elements
    /// (a Node's shader, that shader's textures, ...): what the spec's scene table calls *used*. Every word
    /// of a property value that names a geometry, a shader or a texture counts as a reference to it (names
    /// resolve to the first block of that name, spec 1.8).
    fn reachable_from_nodes(&self, blocks: &[Block]) -> HashSet<usize> {
        let mut reached = HashSet::new();
        let mut todo: Vec<usize> = (0..blocks.len()).filter(|&i| blocks[i].class == "Node").collect();
        while let Some(i) = todo.pop() {
            if !reached.insert(i) {
                continue;
            }
            for word in blocks[i].properties.iter().flat_map(|p| p.value.split_ascii_whitespace()) {
                for ns in [Namespace::Geometry, Namespace::Shader, Namespace::Texture] {
                    todo.extend(self.names.get(&(ns, word.to_string())));
                }
            }
        }
        reached
    }

    /// An element of a later lecture that the scene uses (or a light): an error, or a warning when such elements are skipped.
    pub(super) fn unsupported(&mut self, b: &Block, what: &str) -> Result<()> {
        let message = format!("`{}` ({what}) belongs to a later lecture and is not rendered by the workbook", b.class);
        if !self.options.skip_unsupported {
            return Err(self.error(b.line, format!("{message} (--skip-unsupported renders the rest without it)")));
        }
        self.warn(b.line, format!("{message}: skipped, with whatever refers to it"));
        Ok(())
    }

    pub(super) fn required(&self, b: &Block, property: &str) -> Error {
        self.error(b.end_line, format!("required property `{property}` not defined in `{}` (line {})", b.class, b.line))
    }

    /// A file or folder property, resolved against the scene file's folder (spec 2.1); it must exist.
    pub(super) fn file(&self, p: &Property) -> Result<PathBuf> {
        let path = self.dir.join(self.file_name(&p.value));
        if !path.exists() {
            return Err(self.error(p.line, format!("required file not found: '{}'", path.display())));
        }
        Ok(path)
    }

    /// The file name a property's value `value` names: its bytes as the scene file has them.
    fn file_name(&self, value: &str) -> PathBuf {
        #[cfg(unix)]
        if self.bytes_as_chars {
            use std::os::unix::ffi::OsStringExt;
            // Every character of a file read byte by byte is one byte.
            return PathBuf::from(std::ffi::OsString::from_vec(value.chars().map(|c| c as u8).collect()));
        }
        PathBuf::from(value)
    }

    /// An error loading the file a property names: the file's own error, at the property's line.
    pub(super) fn file_error(&self, p: &Property, e: Error) -> Error {
        self.error(p.line, e)
    }

    /// The element a reference names in its namespace: `Ok(None)` when it was skipped.
    pub(super) fn reference<T: Clone>(
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
}
