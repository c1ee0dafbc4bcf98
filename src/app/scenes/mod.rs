//! The scenes the examples share, or that are too long to read inside their example: each is the lesson of
//! its slide, in a module named after it.

pub mod dispersion;
pub mod reflection;

pub use reflection::mirror_room;
