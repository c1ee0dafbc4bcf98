//! # Model transforms (lecture 6, slide "Model трансформация")
//!
//! The slide's code: `Node::intersect` and the loop over the nodes in `src/lesson/node.rs`, and the teapot's triangles
//! one by one in `src/lesson/geometry/one_by_one.rs`. `--slide` renders this example with the slides' choice of every
//! step beyond them (`--step NAME` adds one back); `--side-by-side "--slide"` shows what they change
//! (docs/beyond-the-slides.md).
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
//! Try: `--faceted`, `--smooth` (for a mesh without normals, faceted otherwise), `--teapot low`, `--mesh my_model.obj` (any OBJ, scaled to fit).
//!
//! Homework ideas: add a `--spin DEGREES` option that turns every teapot; make a ring of 100 teapot instances
//! and compare the memory with 100 copies; add a cylinder in canonical form (axis Y) and make an elliptic tube.

use lecture6::prelude::*;

/// Which bundled teapot to load.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Teapot {
    /// textures/teapot_low.obj: 992 triangles.
    Low,
    /// textures/teapot.obj: 9,120 triangles.
    High,
}

/// Model transforms: canonical shapes placed by scale, rotate, translate; an ellipsoid, a rotated box, a
/// tilted plane, and teapot instances sharing one mesh.
#[derive(clap::Args, Clone, Debug)]
pub struct Options {
    /// A Wavefront OBJ of your own to use in place of the teapot (scaled and centred to fit).
    #[arg(long, value_name = "FILE.obj")]
    pub mesh: Option<PathBuf>,
    /// Shade meshes with their face normals instead of smooth vertex normals.
    #[arg(long)]
    pub faceted: bool,
    /// Compute smooth normals for a mesh whose file has none (such meshes are faceted otherwise, as the
    /// course renders them).
    #[arg(long)]
    pub smooth: bool,
    /// Which bundled teapot to use.
    #[arg(long, value_enum, default_value_t = Teapot::High)]
    pub teapot: Teapot,
}

/// The slide's example transform, its angles read as radians.
const SLIDE_SCALE: Vector = Vector::new(2.0, 1.5, 0.9);
const SLIDE_ROTATE: [f32; 3] = [0.8, 0.1, 0.2];
const SLIDE_TRANSLATE: Vector = Vector::new(3.3, 0.0, 18.1);

impl Options {
    /// A node of the one shared teapot mesh (or the student's own, moved and scaled to stand where the
    /// teapot stands) with `shader`: every call is another instance of the same mesh, not a copy.
    fn teapot(&self, mesh: &Arc<Mesh>, fit: Option<Transform>, color: Color) -> Node {
        let mut node = Node::new(mesh.clone(), Phong::new(color, 0.35, 40.0));
        node.transform = fit;
        node
    }

    /// Loads the mesh the options ask for, and the transform that fits it to the bundled teapot's place
    /// (bottom centre on bottom centre, the same largest extent; none for the teapot itself).
    fn load_mesh(&self) -> Result<(Arc<Mesh>, Option<Transform>)> {
        let bundled = texture_path(match self.teapot {
            Teapot::Low => "teapot_low.obj",
            Teapot::High => "teapot.obj",
        });
        let faceted = |mesh: Mesh| if self.faceted { mesh.with_faceted(true) } else { mesh };
        let teapot = faceted(Mesh::load(&bundled)?);
        let Some(path) = &self.mesh else { return Ok((Arc::new(teapot), None)) };
        let mesh = faceted(Mesh::load_auto_smooth(path, self.smooth)?);
        let empty = |path: &Path| Error::file("cannot use mesh", path, "it has no triangles");
        let (to, from) = (teapot.bounds().ok_or_else(|| empty(&bundled))?, mesh.bounds().ok_or_else(|| empty(path))?);
        let bottom = |b: &Aabb| Vector::new(b.center().x, b.min.y, b.center().z);
        let scale = (to.max - to.min).max_element() / (from.max - from.min).max_element();
        let fit = Transform::default().translate(-bottom(&from)).scale(Vector::splat(scale)).translate(bottom(&to));
        Ok((Arc::new(mesh), Some(fit)))
    }
}

impl Example for Options {
    const DEFAULT_SPP: u32 = 4;

    fn scene(&self) -> Result<Scene> {
        let camera = Camera { position: Vector::new(-1.0, 13.0, -15.0), pitch: -29.0, fov: 82.0, ..Camera::default() };
        let mut scene = Scene::new(camera);
        scene.ambient = Color::gray(0.12);
        scene.lights.push(PointLight::new(Vector::new(-14.0, 30.0, -12.0), Color::WHITE, 1500.0));
        scene.add(Node::new(Plane::new(0.0, 60.0), Lambert::new(texture("floor_tiles.png")?.with_tile_size(8.0))));

        // The canonical teapot, as the file has it, and the slide's transform of the same mesh.
        let (mesh, fit) = self.load_mesh()?;
        scene.add(self.teapot(&mesh, fit, Color::new(0.75, 0.18, 0.12)));
        let [yaw, pitch, roll] = SLIDE_ROTATE.map(f32::to_degrees);
        let slide = self.teapot(&mesh, fit, Color::new(0.15, 0.35, 0.75));
        scene.add(slide.scale(SLIDE_SCALE).rotate(yaw, pitch, roll).translate(SLIDE_TRANSLATE));
        // More instances of the same mesh, each with its own transform and shader.
        let instances = [
            (Vector::new(-10.0, 0.0, -1.0), -40.0, Color::new(0.85, 0.65, 0.2)),
            (Vector::new(-5.5, 0.0, -3.0), 25.0, Color::new(0.2, 0.6, 0.3)),
            (Vector::new(7.5, 0.0, -2.5), 150.0, Color::new(0.85, 0.85, 0.8)),
        ];
        for (position, yaw, color) in instances {
            let small = self.teapot(&mesh, fit, color);
            scene.add(small.scale(Vector::splat(0.55)).rotate(yaw, 0.0, 0.0).translate(position));
        }

        // An ellipsoid from the unit sphere: the planet map stretches with it.
        scene.add(
            Node::new(Sphere::new(Vector::ZERO, 1.0), Phong::new(texture("world.png")?, 0.3, 30.0))
                .scale(Vector::new(3.0, 1.2, 1.2))
                .rotate(-30.0, 0.0, 0.0)
                .translate(Vector::new(-10.0, 1.2, 9.0)),
        );

        // A box from the unit cube, rotated 31 degrees around Z.
        scene.add(
            Node::new(Cube::new(Vector::ZERO, 1.0), Lambert::new(texture("wood.png")?))
                .scale(Vector::new(1.2, 3.0, 1.2))
                .rotate(0.0, 0.0, 31.0)
                .translate(Vector::new(10.0, 3.2, 6.0)),
        );

        // A tilted square from the horizontal plane: its u/v (canonical x and z) go with it.
        let checker = load_texture("checker8.png", None, Filter::Nearest)?.with_tile_size(3.0);
        scene.add(
            Node::new(Plane::new(0.0, 3.0), Lambert::new(checker))
                .rotate(0.0, -60.0, 0.0)
                .rotate(-25.0, 0.0, 0.0)
                .translate(Vector::new(-9.5, 4.0, 19.0)),
        );
        Ok(scene)
    }
}

fn main() -> ExitCode {
    run::<Options>()
}
