//! # lecture6: a teaching ray tracer for lecture 6 of the ray-tracing course
//!
//! Each module implements the slide it is named after; its documentation says which, and where the Rust
//! differs from the slide's C++ and why.
//!
//! The crate is in four layers; each imports only from the layers above it in this list:
//!
//! - [`files`]: not a slide: the files a run reads, checked before they are opened, the pixel budget of its
//!   images, and its errors;
//! - [`lesson`]: the slides' code, which imports nothing from the two below;
//! - [`instruments`]: what makes the lesson visible (the ray tree, debug views, comparisons, the progressive
//!   renderer, the study and the viewer); they watch the renderer through the one observation hook the lesson
//!   owns ([`lesson::observer`]);
//! - [`app`]: the command line every example shares, the course's scene files and the workbook's files.
//!
//! | module | slides |
//! |---|---|
//! | [`lesson::math`] | faceforward, reflect, refract, Fresnel (Schlick and exact), orthonormal basis |
//! | [`lesson::color`], [`lesson::ray`], [`lesson::camera`], [`lesson::rng`] | the course's basic types |
//! | [`lesson::geometry`], [`lesson::transform`], [`lesson::node`] | geometry in canonical form; model transform; nodes and instancing |
//! | [`lesson::bitmap`], [`lesson::texture`] | bitmap textures; textures that drive shader properties; the Fresnel texture |
//! | [`lesson::environment`] | what rays that hit nothing see: constant, spherical (equirectangular) and cube-map environments |
//! | [`lesson::shader`] | Lambert, Phong, reflection (perfect and glossy), refraction, the Layered shader |
//! | [`lesson::light`], [`lesson::scene`] | point lights and shadow rays; the scene and `raytrace()` |
//! | [`lesson::render`], [`lesson::frame`], [`lesson::adaptive_aa`] | the parallel, deterministic renderer and the picture it makes; the course's adaptive anti-aliasing |
//! | [`instruments::tone_mapping`] | exposure and tone mapping: how linear light becomes the written picture (`--exposure`, `--tonemap`) |
//! | [`lesson::spectral`] | chromatic dispersion: wavelength-dependent IOR; the colours of wavelengths (CIE 1931 tables, D65 or equal-energy light, gamut mapping); wavelength passes, spectral and hero-wavelength sampling |
//! | [`lesson::photon_map`] | caustics by photon mapping: photon tracing, the photon grid, the caustic estimate |
//! | [`files::input`], [`files::image_file`], [`files::error`] | not a slide: the files a scene is read from, refused unless regular and within their caps; the pixel budget of the images a run holds; the errors |
//! | [`lesson::sampling`] | points in the unit disc for glossy reflections (random as on the slide, stratified per camera ray or over the whole pixel) |
//! | [`instruments::ray_tree`] | the ray tree of one pixel (`--trace-pixel`): every ray behind it, and how their colours add up |
//! | [`instruments::debug_view`] | false-colour views (`--view`): normals, u/v, what a shader looked up and got, depth, rays, shadow rays and depth reached per pixel |
//! | [`instruments::side_by_side`], [`instruments::compare`] | two renders and their difference in one captioned picture (`--side-by-side`); image differences (`--compare`) |
//! | [`instruments::progressive`] | the picture building up: a coarse pass, then tiles; cancellable (the live viewer draws with it) |
//! | [`instruments::study`] | run time versus error: renders at rising sample counts against a converged reference |
//! | [`instruments::test_kit`] | a shader of one's own tested at one hit, without a render: the furnace, the mirror limit, no NaN |
//! | [`instruments::viewer`] | the live window's example side (the window is the program `lecture6-viewer`, the workspace member `viewer/`): the picture building up, the options as controls, a moving camera |
//! | [`app::cli`] | the command line every example shares, and the `run` that is every example's `main` |
//! | [`app::scenes`] | the scenes examples share: the mirror room of the reflection slides, the dispersion studio |
//! | [`app::workbook`], [`app::assets`] | the bundled textures and the sky; the generated textures and the Utah teapot |
//! | [`app::scene_file`] | the course's `.qdmg` scene files |
//!
//! An example, or a homework, starts with `use lecture6::prelude::*;`, which brings in everything it needs to
//! build a scene and run it (see [`app::cli::Example`] for a whole example in 25 lines).

// A public item without a doc comment is warned about: students learn the library from its API pages. The
// library's own lint, not the package's (Cargo.toml's `[lints]`), which would hold a student's examples to it.
#![warn(missing_docs)]

pub mod app;
pub mod files;
pub mod instruments;
pub mod lesson;

pub use lesson::color::Color;
pub use lesson::error::{Error, Result};
pub use lesson::math::Vector;

/// Everything an example or a homework needs: `use lecture6::prelude::*;`.
pub mod prelude {
    pub use crate::app::cli::{Example, render_and_report, render_for_test, run};
    pub use crate::app::scenes;
    pub use crate::app::workbook::{
        self, checker_floor, load_texture, sky, sky_cubemap, texture, texture_data, texture_path,
    };
    pub use crate::instruments::test_kit::{self, OneHit, check_finite, check_furnace, check_mirror_limit};
    pub use crate::lesson::bitmap::{Bitmap, Filter, Wrap};
    pub use crate::lesson::camera::{Camera, FovAxis};
    pub use crate::lesson::color::Color;
    pub use crate::lesson::environment::{
        ConstantEnvironment, CubemapEnvironment, Environment, SphericalEnvironment, load as load_environment,
    };
    pub use crate::lesson::error::{Error, Result};
    pub use crate::lesson::geometry::{
        Aabb, Cube, Geometry, IntersectionInfo, IntoGeometry, Mesh, Plane, Prism, Shape, Sphere, TexCoords,
    };
    pub use crate::lesson::light::{PointLight, diffuse_light, light_loop};
    pub use crate::lesson::math::{Vector, faceforward, reflect, refract};
    pub use crate::lesson::node::Node;
    pub use crate::lesson::photon_map::PhotonSettings;
    pub use crate::lesson::ray::Ray;
    pub use crate::lesson::rng::Rng;
    pub use crate::lesson::sampling::DiscSampler;
    pub use crate::lesson::scene::{MAX_RAY_DEPTH, Scene, TraceContext};
    pub use crate::lesson::shader::{
        CausticCaster, ColorSource, IntoShader, Lambert, Layered, Material, Phong, PhotonScatter, Reflection,
        Refraction, Shader, fresnel_glass,
    };
    pub use crate::lesson::spectral::Ior;
    pub use crate::lesson::texture::{BitmapTexture, CheckerTexture, Fresnel, FresnelMode, Tex, Texture};
    pub use crate::lesson::transform::Transform;
    pub use std::path::{Path, PathBuf};
    pub use std::process::ExitCode;
    pub use std::sync::Arc;
}
