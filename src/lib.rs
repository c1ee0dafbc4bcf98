//! # lecture6: a teaching ray tracer for lecture 6 of the ray-tracing course
//!
//! Each module implements the slide it is named after; its documentation says which, and where the Rust
//! differs from the slide's C++ and why.
//!
//! | module | slides |
//! |---|---|
//! | [`math`] | faceforward, reflect, refract, Fresnel (Schlick and exact), orthonormal basis |
//! | [`color`], [`ray`], [`camera`], [`rng`] | the course's basic types |
//! | [`geometry`], [`transform`], [`node`] | geometry in canonical form; model transform; nodes and instancing |
//! | [`bitmap`], [`texture`] | bitmap textures; textures that drive shader properties; the Fresnel texture |
//! | [`environment`] | what rays that hit nothing see: constant, spherical (equirectangular) and cube-map environments |
//! | [`shader`] | Lambert, Phong, reflection (perfect and glossy), refraction, the Layered shader |
//! | [`light`], [`scene`] | point lights and shadow rays; the scene and `raytrace()` |
//! | [`render`], [`adaptive_aa`] | the parallel, deterministic renderer; the course's adaptive anti-aliasing |
//! | [`spectral`] | chromatic dispersion: wavelength-dependent IOR, wavelength passes and their colours |
//! | [`photon_map`] | caustics by photon mapping: photon tracing, the k-d tree, the caustic estimate |
//! | [`sampling`] | points in the unit disc for glossy reflections (random as on the slide, and stratified) |
//! | [`study`] | run time versus error: renders at rising sample counts against a converged reference |
//! | [`scenes`], [`cli`] | the examples' scenes and their shared command line |
//! | [`scene_file`] | the course's `.qdmg` scene files |
//! | [`compare`], [`assets`], [`teapot`] | image differences; the generated textures; the Utah teapot |

pub mod adaptive_aa;
pub mod assets;
pub mod bitmap;
pub mod camera;
pub mod cli;
pub mod color;
pub mod compare;
pub mod environment;
pub mod error;
pub mod geometry;
pub mod light;
pub mod math;
pub mod node;
pub mod photon_map;
pub mod ray;
pub mod render;
pub mod rng;
pub mod sampling;
pub mod scene;
pub mod scene_file;
pub mod scenes;
pub mod shader;
pub mod spectral;
pub mod study;
pub mod teapot;
pub mod texture;
pub mod transform;

pub use color::Color;
pub use error::{Error, Result};
pub use math::Vector;
