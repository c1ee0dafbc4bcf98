//! # Model transforms (lecture 6, slide "Model трансформация")
//!
//! Every shape is intersected in its canonical form; a node's transform T (scale, then rotate, then
//! translate) places it in the world, and the ray goes the other way: intersect(o * T, r) =
//! intersect(o, r * T^-1). Look at:
//! - the red teapot, as the OBJ file has it, and the big blue one: the same mesh under the slide's
//!   transform (scale (2.0, 1.5, 0.9), rotate (0.8, 0.1, 0.2), translate (3.3, 0.0, 18.1));
//! - the planet ellipsoid: a scaled sphere whose highlight and map follow the stretch (normals by the
//!   inverse transpose, u/v untouched);
//! - the wooden box turned 31 degrees around Z, and the tilted checker square (a plane keeps its u/v);
//! - the small teapots: instances of the one mesh, each with its own transform and colour.
//!
//! Try: `--faceted`, `--teapot low`, `--mesh my_model.obj` (any OBJ, scaled to fit).
//!
//! Homework ideas: add a `--spin DEGREES` option that turns every teapot; make a ring of 100 teapot instances
//! and compare the memory with 100 copies; add a cylinder in canonical form (axis Y) and make an elliptic tube.

fn main() -> std::process::ExitCode {
    lecture6::cli::main::<lecture6::scenes::model_transform::Args>()
}
