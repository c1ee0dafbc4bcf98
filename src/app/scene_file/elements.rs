//! Each element of the lecture-6 vocabulary read from its block (spec 3): settings, camera, geometry,
//! textures, shaders, nodes and their transforms.

use super::loader::{Loader, Settings};
use super::parse::{Block, Property};
use super::reader::{MAX_COORDINATE, Reader, checked_triple};
use super::values::is_space;
use super::*;
use crate::lesson::bitmap::Bitmap;
use crate::lesson::camera::{Camera, FOV_LIMITS, FovAxis};
use crate::lesson::color::{Color, srgb_to_linear};
use crate::lesson::environment::{CubemapEnvironment, CubemapLayout, Environment};
use crate::lesson::error::{Result, printable};
use crate::lesson::geometry::{Cube, Geometry, Mesh, Plane, Sphere};
use crate::lesson::math::Vector;
use crate::lesson::node::Node;
use crate::lesson::shader::{
    ColorSource, IntoShader, Lambert, Layered, MAX_SHADES_PER_HIT, Material, Phong, Reflection, Refraction,
    shades_per_hit,
};
use crate::lesson::texture::{BitmapTexture, CheckerTexture, Fresnel, FresnelMode, Texture};
use crate::lesson::transform::Transform;
use rayon::prelude::*;
use std::sync::Arc;

impl Loader<'_> {
    pub(super) fn global_settings(&mut self, r: &mut Reader, s: &mut Settings) -> Result<()> {
        s.width = r.int(self, "frameWidth", s.width, 1, 1920)?;
        s.height = r.int(self, "frameHeight", s.height, 1, 1920)?;
        s.ambient = r.color(self, "ambientLight", s.ambient)?;
        s.max_depth = r.int(self, "maxTraceDepth", s.max_depth, 0, i32::MAX as i64)?;
        if let Some(cap) = self.options.max_trace_depth
            && s.max_depth > cap as i64
        {
            return Err(self.error(
                r.line_of("maxTraceDepth"),
                format!(
                    "`maxTraceDepth` {}: at most {cap} with --exhaustive or --slide (without the step adaptive-depth): \
                     nothing prunes the ray tree then, and every glass surface splits a ray in two, so a sample's \
                     rays can double with each level",
                    s.max_depth
                ),
            ));
        }
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
        // The lecture-6 era's white light, and the ambient light, light the surfaces as a lamp does.
        let era_light = if s.light_pos.is_some() { s.light_intensity.abs() } else { 0.0 };
        let ambient = s.ambient.0.to_array().iter().fold(0.0, |m: f64, &c| m.max(c.abs() as f64));
        self.brightest_light = self.brightest_light.max(era_light).max(ambient);
        Ok(())
    }

    /// The camera and its `aspectRatio`.
    pub(super) fn camera(&mut self, r: &mut Reader) -> Result<(Camera, f64)> {
        let position = r.vector(self, "position")?.ok_or_else(|| self.required(r.block, "position"))?;
        let yaw = r.float(self, "yaw", 0.0, -1e120, 1e120)?;
        let pitch = r.float(self, "pitch", 0.0, -90.0, 90.0)?;
        let roll = r.float(self, "roll", 0.0, -1e120, 1e120)?;
        let fov = r.float(self, "fov", 90.0, *FOV_LIMITS.start(), *FOV_LIMITS.end())?;
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

    pub(super) fn cubemap(&mut self, r: &mut Reader) -> Result<Arc<dyn Environment>> {
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

    pub(super) fn geometry(&mut self, r: &mut Reader) -> Result<Arc<dyn Geometry>> {
        Ok(match r.block.class.as_str() {
            "Plane" => {
                let y = r.length(self, "y", 0.0)?;
                // A limit beyond the 32-bit floats (the default 1e99) becomes infinity: no limit.
                let limit = r.number(self, "limit", 1e99, -1e120, 1e120)?;
                Arc::new(Plane::new(y as f32, limit as f32))
            }
            "Sphere" => {
                let center = r.vector(self, "O")?.unwrap_or(Vector::ZERO);
                let radius = r.length(self, "R", 1.0)?;
                if radius < 0.0 {
                    self.warn(
                        r.line_of("R"),
                        format!(
                            "`R {}` is negative: the sphere of radius {} is used, as the course draws it (its \
                             normals point out whatever the sign)",
                            r.raw_line("R").map_or("", |p| p.value.as_str()),
                            -radius
                        ),
                    );
                }
                Arc::new(Sphere::new(center, radius.abs() as f32))
            }
            "Cube" => {
                let center = r.vector(self, "O")?.unwrap_or(Vector::ZERO);
                let half_side = r.length(self, "halfSide", 0.5)?;
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
                if mesh.triangle_count() == 0 {
                    return Err(self.error(
                        p.line,
                        format!(
                            "the mesh '{}' has no triangles to render (no faces, or only faces of no area or with \
                             a vertex that is not a finite number)",
                            path.display()
                        ),
                    ));
                }
                let mesh = if faceted { mesh.with_faceted(true) } else { mesh };
                Arc::new(mesh.with_backface_culling(culling))
            }
        })
    }

    pub(super) fn texture(&mut self, r: &mut Reader) -> Result<Arc<dyn Texture>> {
        Ok(match r.block.class.as_str() {
            "CheckerTexture" => {
                let color1 = r.surface_color(self, "color1", Color::BLACK)?;
                let color2 = r.surface_color(self, "color2", Color::BLACK)?;
                let scaling = r.float(self, "scaling", 1.0, -1e120, 1e120)?;
                // The course's squares are 5 / scaling units wide; the workbook's 1 / scaling.
                Arc::new(CheckerTexture { color1, color2, scaling: (scaling / 5.0) as f32 })
            }
            "BitmapTexture" => {
                let p = r.raw("file").ok_or_else(|| self.required(r.block, "file"))?;
                let path = self.file(p)?;
                // The course's `scaling` of a bitmap is its tile size, the workbook's name for the same number.
                let scaling = r.float(self, "scaling", 1.0, -1e120, 1e120)?;
                if scaling == 0.0 {
                    return Err(self.error(r.line_of("scaling"), "BitmapTexture `scaling` must not be 0"));
                }
                let gamma = r.float(self, "assumedGamma", 1.0, -1e17, 1e17)? as f32;
                // The stored values, decoded as `assumedGamma` says: as they are by default (a data texture).
                let stored = Bitmap::load_data(&path).map_err(|e| self.file_error(p, e))?;
                let bitmap = with_assumed_gamma(stored, gamma);
                Arc::new(BitmapTexture::new(Arc::new(bitmap)).with_tile_size(scaling as f32))
            }
            _ => {
                let ior = r.float(self, "ior", 1.33, 1e-6, 10.0)?;
                Arc::new(Fresnel::new(ior as f32, FresnelMode::Schlick))
            }
        })
    }

    /// Builds the shader of block `i` (once; a Layered builds the shaders of its layers first).
    pub(super) fn shader(&mut self, blocks: &[Block], i: usize) -> Result<Option<Material>> {
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
        if b.class == "Layered" && self.building.len() == MAX_LAYERED_NESTING {
            let outer = &blocks[self.building[0]];
            return Err(self.error(
                b.line,
                format!(
                    "`{}` would be level {} of Layered shaders nested in `{}` (line {}): Layered shaders \
                     nest at most {MAX_LAYERED_NESTING} deep",
                    b.name.as_deref().unwrap_or(""),
                    MAX_LAYERED_NESTING + 1,
                    outer.name.as_deref().unwrap_or(""),
                    outer.line
                ),
            ));
        }
        self.building.push(i);
        let mut r = Reader::new(b);
        let shader: Material = match b.class.as_str() {
            "Lambert" => {
                let color = self.color_source(&mut r, Color::BLACK)?;
                Lambert::new(color).into_shader()
            }
            "Phong" => {
                let color = self.color_source(&mut r, Color::gray(0.5))?;
                // A negative exponent makes the highlight infinite where its cosine is 0.
                let exponent = r.float(self, "specularExponent", 10.0, 0.0, 1e120)?;
                let multiplier = r.float(self, "specularMultiplier", 0.4, -1e120, 1e120)?;
                r.check_lit(self, "specularMultiplier", &[multiplier])?;
                Phong::new(color, multiplier as f32, exponent as f32).into_shader()
            }
            "Refl" => {
                let multiplier = r.float(self, "multiplier", 0.99, 0.0, 1.0)? as f32;
                let glossiness = r.float(self, "glossiness", 1.0, 0.0, 1.0)?;
                let samples = r.int(self, "numSamples", 32, 1, i32::MAX as i64)?;
                // Glossiness 0 (an unbounded cone) is refused by `Reflection::glossy`, as on the command line.
                if glossiness == 1.0 {
                    Reflection::new(multiplier).into_shader()
                } else {
                    let glossy = Reflection::glossy(Color::gray(multiplier), glossiness as f32, samples as u32);
                    glossy.map_err(|e| self.error(r.line_of("glossiness"), e))?.into_shader()
                }
            }
            "Refr" => {
                let ior = r.float(self, "ior", 1.33, 1e-6, 10.0)?;
                let multiplier = r.float(self, "multiplier", 0.99, 0.0, 1.0)?;
                Refraction::new(ior as f32, multiplier as f32).into_shader()
            }
            _ => self.layered(blocks, b)?.into_shader(),
        };
        if b.class != "Layered" {
            r.finish(self);
        }
        self.building.pop();
        self.shaders.insert(i, Some(shader.clone()));
        Ok(Some(shader))
    }

    /// A Lambert's or Phong's `color`, replaced entirely by its `texture` when it has one.
    pub(super) fn color_source(&mut self, r: &mut Reader, default: Color) -> Result<ColorSource> {
        let color = r.surface_color(self, "color", default)?;
        let Some(p) = r.raw("texture") else { return Ok(ColorSource::Color(color)) };
        match self.texture_ref(p, &p.value)? {
            Some(t) => Ok(ColorSource::Texture(t.into_tex())),
            None => {
                self.warn(p.line, format!("texture `{}` was skipped: the colour is used instead", p.value));
                Ok(ColorSource::Color(color))
            }
        }
    }

    pub(super) fn texture_ref(&self, p: &Property, name: &str) -> Result<Option<Arc<dyn Texture>>> {
        Ok(self.reference(p, name, Namespace::Texture, |s, i| s.textures.get(&i).cloned())?.1)
    }

    /// A Layered shader from its `layer SHADER COLOR [TEXTURE]` lines (spec 3.7); every other line is
    /// ignored without a warning, as in the course.
    /// The shaders one hit of it shades (the Layered itself, and every layer's count) may not pass
    /// [`MAX_SHADES_PER_HIT`]: the layer that takes the count past it is refused at its line.
    pub(super) fn layered(&mut self, blocks: &[Block], b: &Block) -> Result<Layered> {
        let mut layered = Layered::new();
        let mut shades = 1u64;
        let (name, line) = (b.name.as_deref().unwrap_or(""), b.line);
        let syntax = "expected `layer SHADER (r, g, b) [TEXTURE]`";
        for p in b.properties.iter().filter(|p| p.name == "layer") {
            let (first, rest) = p.value.split_once(is_space).unwrap_or((&p.value, ""));
            let shader_name = first.replace(',', "");
            let mut rest = rest.trim_matches(is_space);
            if rest.is_empty() {
                return Err(self.error(p.line, syntax));
            }
            let mut texture_name = None;
            if !rest.ends_with(')') {
                let (before, last) = rest.rsplit_once(is_space).unwrap_or(("", rest));
                texture_name = Some(last.replace(',', ""));
                rest = before;
            }
            let blend = values::triple(rest)
                .ok_or_else(|| self.error(p.line, format!("{syntax}: the colour is not three numbers")))?;
            let [r, g, b] = checked_triple(blend, None)
                .map_err(|reason| self.error(p.line, format!("the layer's colour `{rest}`: {reason}")))?;
            let blend = Color::new(r, g, b);
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
            let layer_shades = shades_per_hit(&shader, &mut self.counted_shades);
            shades = shades.saturating_add(layer_shades);
            if shades > MAX_SHADES_PER_HIT {
                return Err(self.error(
                    p.line,
                    format!(
                        "the Layered shader `{name}` (line {line}) would shade {shades} shaders at every hit with this layer, \
                         whose `{shader_name}` shades {layer_shades} (its layers, theirs and so on, each as often as \
                         a layer names it): a hit may shade at most {MAX_SHADES_PER_HIT}"
                    ),
                ));
            }
            layered.add_layer(shader, blend, texture);
        }
        Ok(layered)
    }

    /// A Node: `None` when it is skipped (no shader, or a skipped geometry or shader).
    pub(super) fn node(&mut self, r: &mut Reader, blocks: &[Block]) -> Result<Option<Node>> {
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
        // The ray tree and the end-of-run report call the node by the file's name for it (its control
        // characters, if any, shown as escapes, as in every text the loader echoes).
        node.name = b.name.as_deref().map(printable);
        Ok(Some(node))
    }

    /// The transform of a Node (spec 3.3): `scale` and `rotate` lines composed in file order, each applied
    /// after the ones before; the last `translate` line applied after them all, wherever it stands.
    pub(super) fn transform(&mut self, r: &mut Reader) -> Result<Option<Transform>> {
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
            // A translation is a position; scales and angles need only be finite (the product of the scales
            // is checked with the whole transform below).
            let bound = (p.name == "translate").then_some(MAX_COORDINATE);
            let v = checked_triple(v, bound)
                .map_err(|reason| self.error(p.line, format!("`{} {}`: {reason}", p.name, p.value)))?;
            let v = Vector::from_array(v);
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

/// The bitmap as the course decodes it with `assumedGamma` (spec 3.8), from its stored values (what the file
/// holds, [`Bitmap::load_data`]: 8-bit values / 255, or the floats of an HDR or EXR file): through the sRGB
/// curve for exactly 2.2, through `c^gamma` for another gamma in (0, 10), and unchanged otherwise (the
/// default, 1: the bitmap as it was loaded); exactly 0 and 1 stay.
pub(super) fn with_assumed_gamma(stored: Bitmap, gamma: f32) -> Bitmap {
    let curve: fn(f32, f32) -> f32 = if gamma == 2.2 {
        |s, _| srgb_to_linear(s)
    } else if gamma > 0.0 && gamma < 10.0 && gamma != 1.0 {
        f32::powf
    } else {
        return stored;
    };
    let decode = |s: f32| if s == 0.0 || s == 1.0 { s } else { curve(s, gamma) };
    let (w, h) = (stored.width(), stored.height());
    // Texel by texel in parallel (on the current rayon pool): a `powf` per channel is a serial step before
    // the render otherwise.
    let pixels = (0..w * h)
        .into_par_iter()
        .map(|i| {
            let [r, g, b] = stored.get_pixel(i % w, i / w).to_array();
            Color::new(decode(r), decode(g), decode(b))
        })
        .collect();
    Bitmap::from_pixels(w, h, pixels)
}
