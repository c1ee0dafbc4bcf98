//! The environment (slides "Заден фон", "Интерфейс за заден фон"): what a ray that hits nothing sees. It
//! depends on the ray's direction only, never on where the ray starts.
//!
//! Two image-based environments, as on the slides:
//! - [`SphericalEnvironment`]: one equirectangular image (longitude across, latitude down);
//! - [`CubemapEnvironment`]: six square images, the faces of a cube around the scene; the largest absolute
//!   component of the direction picks the face and the other two index it.
//!
//! Both read any format [`Bitmap`] reads (PNG, JPEG, BMP in sRGB; Radiance HDR and OpenEXR in linear light,
//! keeping values above 1, so a sun can be much brighter than white) and filter bilinearly by default.
//!
//! # Conventions
//!
//! The world is the camera's: +Y is up and, with zero angles, the camera looks along +Z with +X to its
//! right. Every image is seen **from the inside, unmirrored**: looking at some part of the image from the
//! centre of the scene, the picture appears as it does in an image viewer.
//!
//! **Equirectangular** (2:1): the **centre of the image faces +Z** (what the default camera looks at).
//! `u = 0.5 + atan2(x, z) / 2π` runs left to right: -Z at the left and right edges (the seam), -X at a
//! quarter, +Z at the middle, +X at three quarters. `v = 0.5 - asin(y) / π` runs top to bottom: the top row
//! is straight up (+Y), the middle row the horizon, the bottom row straight down.
//!
//! **Cube map**: files `posx, negx, posy, negy, posz, negz` with any of the extensions in
//! [`FACE_EXTENSIONS`]. Each face spans 90° and its centre is its axis (the direction +X lands in the
//! middle of `posx`). Within a face, u runs left to right and v top to bottom along these directions:
//!
//! | face | centre | u (left → right) | v (top → bottom) |
//! |---|---|---|---|
//! | `posx` | +X | -Z | -Y |
//! | `negx` | -X | +Z | -Y |
//! | `posy` | +Y | +X | +Z |
//! | `negy` | -Y | +X | -Z |
//! | `posz` | +Z | +X | -Y |
//! | `negz` | -Z | -X | -Y |
//!
//! This is the layout of OpenGL and Direct3D cube maps, so skyboxes made for them (with these names) work
//! as they are. A camera with a 90° square view pointed along an axis sees exactly that face.
//!
//! **The course's layout** ([`CubemapLayout::Course`]) differs in one face: its `negz` image is the OpenGL
//! one turned by 180° (u along +X, v along +Y; it is the -Z face cut from a vertical-cross picture, where
//! that face stands on its head). The course's scene files and cube maps use it; such a face is turned when
//! it is loaded, so the look-up is the same for both layouts, but for one detail: the course's program reads
//! the nearest texel of a face at `floor(u (W - 1))`, not `floor(u W)`, as if its face were a texel narrower
//! (half a texel off at its middle), and a course-layout cube map read with the nearest texel (the slides'
//! look-up, `--slide`) reads it so, which keeps the class's skies where the course's program puts them.
//! Bilinear filtering (a step beyond the slides) reads texel centres where they are. Face files are found whatever the case of
//! their extension (`posx.PNG`); all six must be square and of one size.
//!
//! Deviation from the slides: the direction is not assumed to be of unit length (only its direction
//! matters), and a degenerate direction returns a colour of the image rather than failing (ledger:
//! `unit-free-direction`).

use crate::files::encoding;
use crate::lesson::beyond::Steps;
use crate::lesson::bitmap::{Bitmap, Filter, Wrap};
use crate::lesson::color::Color;
use crate::lesson::error::{Error, Result};
use crate::lesson::image_file::ImageFile;
use crate::lesson::math::Vector;
use rayon::prelude::*;
use std::any::Any;
use std::f32::consts::{FRAC_1_PI, PI};
use std::path::Path;
use std::sync::Arc;

impl Environment for SphericalEnvironment {
    fn get(&self, dir: Vector) -> Color {
        self.look_up(dir, self.filter)
    }

    fn into_sky(self: Arc<Self>) -> Sky {
        let filter = self.filter;
        Sky::Spherical(Arc::unwrap_or_clone(self), filter)
    }
}

/// Where the direction `dir` lands in an equirectangular image: (u, v) in [0, 1] (see the module docs).
pub fn equirect_uv(dir: Vector) -> (f32, f32) {
    let u = 0.5 + dir.x.atan2(dir.z) * (0.5 * FRAC_1_PI);
    let v = 0.5 - dir.y.atan2(dir.x.hypot(dir.z)) * FRAC_1_PI;
    (u, v)
}

/// The face the direction `dir` points into, and where in it: (face, u, v) with u, v in [0, 1].
#[inline(always)]
pub fn cube_face_uv(dir: Vector) -> (CubeFace, f32, f32) {
    exercise!(cube_face_uv(dir));
    use CubeFace::*;
    let a = dir.abs();
    // The largest component picks the face. `major` is the component along the face's centre, `along_u` and
    // `along_v` those along its u and v directions: the rows of the table in the module docs, read
    // straight from `dir` (the products with the axes of `CubeFace::axes`, without the arithmetic).
    let (face, major, along_u, along_v) = if a.x >= a.y && a.x >= a.z {
        if dir.x >= 0.0 { (PosX, dir.x, -dir.z, -dir.y) } else { (NegX, -dir.x, dir.z, -dir.y) }
    } else if a.y >= a.z {
        if dir.y >= 0.0 { (PosY, dir.y, dir.x, dir.z) } else { (NegY, -dir.y, dir.x, -dir.z) }
    } else if dir.z >= 0.0 {
        (PosZ, dir.z, dir.x, -dir.y)
    } else {
        (NegZ, -dir.z, -dir.x, -dir.y)
    };
    // Project onto the face's plane at distance 1: the major component becomes 1.
    (face, 0.5 + 0.5 * along_u / major, 0.5 + 0.5 * along_v / major)
}

impl Environment for CubemapEnvironment {
    fn get(&self, dir: Vector) -> Color {
        self.look_up(dir, self.filter)
    }

    fn into_sky(self: Arc<Self>) -> Sky {
        let filter = self.filter;
        Sky::Cubemap(Arc::unwrap_or_clone(self), filter)
    }
}

/// The course's `Environment` interface (`getEnvironment(dir)`).
pub trait Environment: Any + Send + Sync + EnvironmentObject {
    /// The colour seen in the unit direction `dir`.
    fn get(&self, dir: Vector) -> Color;

    /// The environment as a trace reads it ([`Sky`]): for any environment but the workbook's own,
    /// the case that calls it through its trait object, [`Sky::Own`]. A new environment leaves it as it is.
    fn into_sky(self: Arc<Self>) -> Sky {
        Sky::Own(self.into_object())
    }
}

/// Any sized [`Environment`] as a trait object: what [`Environment::into_sky`] keeps of an environment that
/// is not one of the workbook's. Implemented for every environment; nothing to write.
pub trait EnvironmentObject {
    /// The environment behind a trait object.
    fn into_object(self: Arc<Self>) -> Arc<dyn Environment>;
}

impl<E: Environment> EnvironmentObject for E {
    fn into_object(self: Arc<Self>) -> Arc<dyn Environment> {
        self
    }
}

/// An environment as a trace reads it (the sky of a [`crate::lesson::scene::TraceContext`]): one of the
/// workbook's, each image-based one with the filter the scene's steps read it with (one texel, the slide's,
/// without [`Step::TexelFilter`](crate::lesson::beyond::Step::TexelFilter); its own filter with it), or any other through its trait object. The one
/// place that lists the workbook's environments.
#[derive(Clone)]
pub enum Sky {
    /// The same colour everywhere.
    Constant(ConstantEnvironment),
    /// One equirectangular image, read with the filter given.
    Spherical(SphericalEnvironment, Filter),
    /// Six images on a cube, read with the filter given.
    Cubemap(CubemapEnvironment, Filter),
    /// Any other environment, through its trait object.
    Own(Arc<dyn Environment>),
}

impl Sky {
    /// The same environment as a render that takes `steps` reads it.
    pub fn under(mut self, steps: Steps) -> Sky {
        if let Sky::Spherical(SphericalEnvironment { filter: own, .. }, filter)
        | Sky::Cubemap(CubemapEnvironment { filter: own, .. }, filter) = &mut self
        {
            *filter = own.under(steps);
        }
        self
    }
}

impl Environment for Sky {
    #[inline(always)]
    fn get(&self, dir: Vector) -> Color {
        match self {
            Sky::Constant(constant) => constant.get(dir),
            Sky::Spherical(spherical, filter) => spherical.look_up(dir, *filter),
            Sky::Cubemap(cubemap, filter) => cubemap.look_up(dir, *filter),
            Sky::Own(environment) => environment.get(dir),
        }
    }

    fn into_sky(self: Arc<Self>) -> Sky {
        Arc::unwrap_or_clone(self)
    }
}

/// The same colour in every direction (a uniformly lit sky, useful for tests and energy checks).
#[derive(Clone, Copy, Debug)]
pub struct ConstantEnvironment(pub Color);

impl Environment for ConstantEnvironment {
    #[inline(always)]
    fn get(&self, _dir: Vector) -> Color {
        self.0
    }

    fn into_sky(self: Arc<Self>) -> Sky {
        Sky::Constant(*self)
    }
}

/// Loads the environment at `path`: a folder is a cube map in the OpenGL layout (see
/// [`CubemapEnvironment::load`]), a file an equirectangular image (see [`SphericalEnvironment::load`]).
pub fn load(path: &Path) -> Result<Arc<dyn Environment>> {
    load_with_layout(path, CubemapLayout::OpenGl)
}

/// Loads the environment at `path` as [`load`] does, reading a cube map's faces in `layout`.
pub fn load_with_layout(path: &Path, layout: CubemapLayout) -> Result<Arc<dyn Environment>> {
    Ok(if path.is_dir() {
        Arc::new(CubemapEnvironment::load_layout(path, layout)?)
    } else {
        Arc::new(SphericalEnvironment::load(path)?)
    })
}

/// The unit direction that lands at (u, v) of an equirectangular image: the inverse of [`equirect_uv`].
pub fn equirect_direction(u: f32, v: f32) -> Vector {
    let longitude = (u - 0.5) * 2.0 * PI;
    let latitude = (0.5 - v) * PI;
    Vector::new(latitude.cos() * longitude.sin(), latitude.sin(), latitude.cos() * longitude.cos())
}

/// An environment from one equirectangular image (the slides' spherical environment).
#[derive(Clone, Debug)]
pub struct SphericalEnvironment {
    /// The equirectangular image (twice as wide as high), in linear light; its centre faces +Z.
    pub bitmap: Arc<Bitmap>,
    /// How the image is read between texel centres (bilinear unless changed with `with_filter`).
    pub filter: Filter,
}

impl SphericalEnvironment {
    /// A bilinearly filtered environment from an image in linear light.
    pub fn new(bitmap: Arc<Bitmap>) -> SphericalEnvironment {
        SphericalEnvironment { bitmap, filter: Filter::Bilinear }
    }

    /// Loads an equirectangular image file; one that is not twice as wide as high is refused (from its
    /// header, before it is decoded).
    pub fn load(path: &Path) -> Result<SphericalEnvironment> {
        let file = ImageFile::open(path)?;
        let (w, h) = file.dimensions();
        if w as u64 != 2 * h as u64 {
            return Err(Error::file(
                "cannot use environment",
                path,
                format!("an equirectangular image must be twice as wide as high (2:1), this one is {w}x{h}"),
            ));
        }
        Ok(SphericalEnvironment::new(Arc::new(Bitmap::from_file(file)?)))
    }

    /// The same environment read with `filter`.
    pub fn with_filter(self, filter: Filter) -> SphericalEnvironment {
        SphericalEnvironment { filter, ..self }
    }
}

impl SphericalEnvironment {
    /// The colour seen in the direction `dir`, the image read with `filter`.
    #[inline(always)]
    fn look_up(&self, dir: Vector, filter: Filter) -> Color {
        let (u, v) = equirect_uv(dir);
        // Longitude goes round (repeat); latitude stops at the poles (clamp).
        self.bitmap.sample(u, v, filter, (Wrap::Repeat, Wrap::Clamp))
    }
}

/// One face of a cube map.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CubeFace {
    /// The face around +X (file `posx`).
    PosX,
    /// The face around -X (file `negx`).
    NegX,
    /// The face around +Y, straight up (file `posy`).
    PosY,
    /// The face around -Y, straight down (file `negy`).
    NegY,
    /// The face around +Z, where the default camera looks (file `posz`).
    PosZ,
    /// The face around -Z, behind the default camera (file `negz`).
    NegZ,
}

impl CubeFace {
    /// The faces in the order [`CubemapEnvironment::new`] takes them.
    pub const ALL: [CubeFace; 6] =
        [CubeFace::PosX, CubeFace::NegX, CubeFace::PosY, CubeFace::NegY, CubeFace::PosZ, CubeFace::NegZ];

    /// The face's file name without extension.
    pub fn name(self) -> &'static str {
        ["posx", "negx", "posy", "negy", "posz", "negz"][self as usize]
    }

    /// The face's centre direction and the directions its u and v run along (the table in the module docs).
    pub fn axes(self) -> (Vector, Vector, Vector) {
        let (x, y, z) = (Vector::X, Vector::Y, Vector::Z);
        match self {
            CubeFace::PosX => (x, -z, -y),
            CubeFace::NegX => (-x, z, -y),
            CubeFace::PosY => (y, x, z),
            CubeFace::NegY => (-y, x, -z),
            CubeFace::PosZ => (z, x, -y),
            CubeFace::NegZ => (-z, -x, -y),
        }
    }
}

/// The unit direction through (u, v) of a cube face: the inverse of [`cube_face_uv`].
pub fn cube_face_direction(face: CubeFace, u: f32, v: f32) -> Vector {
    let (centre, u_axis, v_axis) = face.axes();
    (centre + (2.0 * u - 1.0) * u_axis + (2.0 * v - 1.0) * v_axis).normalize()
}

/// The extensions a cube face file may have, tried in this order.
pub const FACE_EXTENSIONS: [&str; 6] = ["png", "jpg", "jpeg", "bmp", "hdr", "exr"];

/// How the six images of a cube map are oriented (see the module documentation).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum CubemapLayout {
    /// OpenGL's and Direct3D's: the skyboxes found on the web, and the workbook's own `sky_cubemap`.
    #[default]
    OpenGl,
    /// The course's: `negz` turned by 180° against OpenGL's. The course's cube maps and scene files.
    Course,
}

/// The image turned by 180° (upside down and mirrored).
fn half_turn(bitmap: &Bitmap) -> Bitmap {
    let (w, h) = (bitmap.width(), bitmap.height());
    let pixels = (0..h).flat_map(|y| (0..w).map(move |x| bitmap.get_pixel(w - 1 - x, h - 1 - y))).collect();
    Bitmap::from_pixels(w, h, pixels)
}

/// An environment from six images on the faces of a cube (the slides' cube map).
#[derive(Clone, Debug)]
pub struct CubemapEnvironment {
    /// In the order of [`CubeFace::ALL`].
    pub faces: [Arc<Bitmap>; 6],
    /// How the faces are read between texel centres (bilinear unless changed with `with_filter`).
    pub filter: Filter,
    /// The course's look-up of the nearest texel (its layout's, [`CubemapLayout::Course`]).
    course_lookup: bool,
}

impl CubemapEnvironment {
    /// The colour seen in the direction `dir`, the faces read with `filter`.
    #[inline(always)]
    fn look_up(&self, dir: Vector, filter: Filter) -> Color {
        let (face, u, v) = cube_face_uv(dir);
        let bitmap = &self.faces[face as usize];
        if self.course_lookup && filter == Filter::Nearest {
            // The course's program takes texel floor(u (W - 1)): its face a texel narrower than the image.
            let span = |n: usize, t: f32| (t * (n - 1) as f32) as usize;
            return bitmap.get_pixel(span(bitmap.width(), u), span(bitmap.height(), v));
        }
        // Bilinear filtering stops at the face's edge rather than reading the neighbouring face.
        bitmap.sample(u, v, filter, (Wrap::Clamp, Wrap::Clamp))
    }
}

impl CubemapEnvironment {
    /// A bilinearly filtered cube map from six images in linear light, in the order of [`CubeFace::ALL`].
    pub fn new(faces: [Arc<Bitmap>; 6]) -> CubemapEnvironment {
        CubemapEnvironment { faces, filter: Filter::Bilinear, course_lookup: false }
    }

    /// Loads the six faces `posx, negx, posy, negy, posz, negz` (each with one of [`FACE_EXTENSIONS`], in
    /// any case) from the folder `dir`, in the OpenGL layout.
    pub fn load(dir: &Path) -> Result<CubemapEnvironment> {
        CubemapEnvironment::load_layout(dir, CubemapLayout::OpenGl)
    }

    /// Loads the six faces from the folder `dir`, in `layout`. A missing or unreadable face is an error
    /// naming its file (a face that is a folder or a FIFO is reported as such); so are faces that are not
    /// square or not all of one size, which is checked from the six headers before any face is decoded.
    pub fn load_layout(dir: &Path, layout: CubemapLayout) -> Result<CubemapEnvironment> {
        let entries: Vec<std::path::PathBuf> = std::fs::read_dir(dir)
            .map_err(|e| Error::file("cannot read cube map folder", dir, e))?
            .filter_map(|e| e.ok().map(|e| e.path()))
            .collect();
        let find = |face: CubeFace| {
            let named = |ext: &str| {
                entries.iter().find(|p| {
                    let lower = |s: Option<&std::ffi::OsStr>| s.map(|s| s.to_string_lossy().to_ascii_lowercase());
                    p.file_stem().is_some_and(|s| s == face.name()) && lower(p.extension()).as_deref() == Some(ext)
                })
            };
            FACE_EXTENSIONS.iter().find_map(|ext| named(ext)).ok_or_else(|| {
                Error::file(
                    "cannot find cube face",
                    &dir.join(face.name()),
                    format!("no {}.png, .jpg, .jpeg, .bmp, .hdr or .exr in the folder", face.name()),
                )
            })
        };
        // The headers are read one face after the other, in the order of `ALL`, so that an error (a face
        // over the pixel budget) always names the same face.
        let paths: Vec<&std::path::PathBuf> = CubeFace::ALL.into_iter().map(find).collect::<Result<_>>()?;
        let files: Vec<ImageFile> = paths.iter().map(|path| ImageFile::open(path)).collect::<Result<_>>()?;
        let (size, _) = files[0].dimensions();
        for (path, file) in paths.iter().zip(&files) {
            let (w, h) = file.dimensions();
            if w != h || w != size {
                return Err(Error::file(
                    "cannot use cube face",
                    path,
                    format!(
                        "it is {w}x{h}; the six faces of a cube map must be square and of one size ({size}x{size})"
                    ),
                ));
            }
        }
        // The six files are decoded in parallel; an error names the first failing face in the order of `ALL`.
        // Read on the pool's threads as on this one (`--encoding`).
        let reading = encoding::reading();
        let decode = |(face, file): (CubeFace, ImageFile)| {
            let bitmap = encoding::reading_as(reading, || Bitmap::from_file(file))?;
            let turned = layout == CubemapLayout::Course && face == CubeFace::NegZ;
            Ok::<_, Error>(Arc::new(if turned { half_turn(&bitmap) } else { bitmap }))
        };
        let faces: Vec<(CubeFace, ImageFile)> = CubeFace::ALL.into_iter().zip(files).collect();
        let decoded: Vec<Result<Arc<Bitmap>>> = faces.into_par_iter().map(decode).collect();
        let faces: [_; 6] = decoded.into_iter().collect::<Result<Vec<_>>>()?.try_into().expect("six faces");
        Ok(CubemapEnvironment { course_lookup: layout == CubemapLayout::Course, ..CubemapEnvironment::new(faces) })
    }

    /// The same cube map read with `filter`.
    pub fn with_filter(self, filter: Filter) -> CubemapEnvironment {
        CubemapEnvironment { filter, ..self }
    }
}
