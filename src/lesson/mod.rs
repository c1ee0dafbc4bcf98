//! The lesson: the slides' code. Nothing here imports the instruments or the application.

pub mod adaptive_aa;
pub mod bitmap;
pub mod camera;
pub mod color;
pub mod environment;
pub mod error;
pub mod frame;
pub mod geometry;
pub mod image_file;
pub mod input;
pub mod light;
pub mod math;
pub mod node;
pub mod photon_map;
pub mod ray;
pub mod render;
pub mod rng;
pub mod sampling;
pub mod scene;
pub mod shader;
pub mod spectral;
pub mod texture;
pub mod tone_mapping;
pub mod transform;
