//! Scene of the `model_transform` example (slide "Model трансформация"): shapes intersected in their
//! canonical form and placed in the world by each node's transform T (scale, then rotate, then translate).
//!
//! - Two teapots share one mesh: the canonical one, untransformed (standing on its base at the origin, spout
//!   towards +X), and the slide's example: scale (2.0, 1.5, 0.9), rotate (0.8, 0.1, 0.2), translate
//!   (3.3, 0.0, 18.1). The slide gives the angles without a unit; they are read as radians (45.8, 5.7 and
//!   11.5 degrees), since in degrees the turn would not be visible. [`Transform`] takes degrees.
//! - An ellipsoid: a unit sphere scaled (3, 1.2, 1.2) and turned; it keeps the planet map's u/v, so the map
//!   stretches with it, and its normals (by the inverse transpose) keep the highlight in the right place.
//! - A box: a cube scaled into a tall block and rotated 31 degrees around Z (the slide's example).
//! - A tilted plane: the canonical horizontal plane, pitched and turned; its checker u/v go with it.
//! - Instancing: three more teapots from the same mesh (one `Arc`), each with its own transform and shader.
//!
//! `--mesh FILE.obj` puts any OBJ in place of every teapot, scaled and centred to the teapot's bounding box;
//! `--faceted` shades with face normals (a mesh without normals is faceted unless `--smooth`); `--teapot low` loads the coarse teapot.
//!
//! [`Transform`]: crate::transform::Transform

use crate::camera::Camera;
use crate::cli::{CommonArgs, Example};
use crate::color::Color;
use crate::error::{Error, Result};
use crate::geometry::{Cube, Geometry, Mesh, Plane, Sphere};
use crate::light::PointLight;
use crate::math::Vector;
use crate::node::Node;
use crate::scene::Scene;
use crate::shader::{Lambert, Phong, Shader};
use std::path::PathBuf;
use std::sync::Arc;

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
#[derive(clap::Parser, Clone, Debug)]
#[command(name = "model_transform", version)]
pub struct Args {
    #[command(flatten)]
    pub common: CommonArgs,
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

impl Args {
    /// Loads the teapot mesh, or the student's own in its place, and returns a maker of nodes that share
    /// it, each first fitted to the teapot's bounding box (bottom centre on bottom centre, the same largest
    /// extent).
    fn mesh_nodes(&self) -> Result<impl Fn(Arc<dyn Shader>) -> Node> {
        let bundled = match self.teapot {
            Teapot::Low => "teapot_low.obj",
            Teapot::High => "teapot.obj",
        };
        let teapot_path = super::texture_path(bundled);
        let teapot = Mesh::load(&teapot_path)?;
        let teapot_box = teapot.bounds().ok_or_else(|| Error::file("cannot use mesh", &teapot_path, "it is empty"))?;
        let (mesh, fit) = match &self.mesh {
            None => (teapot, None),
            Some(path) => {
                let mesh = Mesh::load_auto_smooth(path, self.smooth)?;
                let b = mesh.bounds().ok_or_else(|| Error::file("cannot use mesh", path, "it has no triangles"))?;
                let bottom = |b: &crate::geometry::Aabb| Vector::new(b.center().x, b.min.y, b.center().z);
                let scale = (teapot_box.max - teapot_box.min).max_element() / (b.max - b.min).max_element();
                (mesh, Some((bottom(&b), scale, bottom(&teapot_box))))
            }
        };
        let mesh: Arc<dyn Geometry> = Arc::new(if self.faceted { mesh.with_faceted(true) } else { mesh });
        Ok(move |shader: Arc<dyn Shader>| {
            let node = Node::new(mesh.clone(), shader);
            match fit {
                None => node,
                Some((from, scale, to)) => node.translate(-from).scale(Vector::splat(scale)).translate(to),
            }
        })
    }
}

impl Example for Args {
    const NAME: &'static str = "model_transform";
    const DEFAULT_SPP: u32 = 4;

    fn common(&self) -> &CommonArgs {
        &self.common
    }

    fn build_scene(&self) -> Result<Scene> {
        let mut scene = Scene::new(Camera {
            position: Vector::new(-1.0, 13.0, -15.0),
            pitch: -29.0,
            fov: 82.0,
            ..Camera::default()
        });
        scene.ambient = Color::gray(0.12);
        scene.lights.push(PointLight::new(Vector::new(-14.0, 30.0, -12.0), Color::WHITE, 1500.0));

        let tiles = super::load_texture("floor_tiles.png", None, Default::default())?.with_scaling(8.0);
        scene.add(Node::new(Arc::new(Plane::new(0.0, 60.0)), Arc::new(Lambert::new(tiles))));

        let teapot = self.mesh_nodes()?;
        let phong = |r, g, b| -> Arc<dyn Shader> { Arc::new(Phong::new(Color::new(r, g, b), 0.35, 40.0)) };
        // The canonical teapot, as the file has it, and the slide's transform of it.
        scene.add(teapot(phong(0.75, 0.18, 0.12)));
        let [yaw, pitch, roll] = SLIDE_ROTATE.map(f32::to_degrees);
        scene.add(
            teapot(phong(0.15, 0.35, 0.75)).scale(SLIDE_SCALE).rotate(yaw, pitch, roll).translate(SLIDE_TRANSLATE),
        );
        // More instances of the same mesh, each with its own transform and shader.
        let instances = [
            (Vector::new(-10.0, 0.0, -1.0), -40.0, Color::new(0.85, 0.65, 0.2)),
            (Vector::new(-5.5, 0.0, -3.0), 25.0, Color::new(0.2, 0.6, 0.3)),
            (Vector::new(7.5, 0.0, -2.5), 150.0, Color::new(0.85, 0.85, 0.8)),
        ];
        for (position, yaw, color) in instances {
            let shader: Arc<dyn Shader> = Arc::new(Phong::new(color, 0.35, 40.0));
            scene.add(teapot(shader).scale(Vector::splat(0.55)).rotate(yaw, 0.0, 0.0).translate(position));
        }

        // An ellipsoid from the unit sphere: the planet map stretches with it.
        let planet = super::load_texture("world.png", None, Default::default())?;
        scene.add(
            Node::new(Arc::new(Sphere::new(Vector::ZERO, 1.0)), Arc::new(Phong::new(planet, 0.3, 30.0)))
                .scale(Vector::new(3.0, 1.2, 1.2))
                .rotate(-30.0, 0.0, 0.0)
                .translate(Vector::new(-10.0, 1.2, 9.0)),
        );

        // A box from the unit cube, rotated 31 degrees around Z.
        let wood = super::load_texture("wood.png", None, Default::default())?;
        scene.add(
            Node::new(Arc::new(Cube::new(Vector::ZERO, 1.0)), Arc::new(Lambert::new(wood)))
                .scale(Vector::new(1.2, 3.0, 1.2))
                .rotate(0.0, 0.0, 31.0)
                .translate(Vector::new(10.0, 3.2, 6.0)),
        );

        // A tilted square from the horizontal plane: its u/v (canonical x and z) go with it.
        let checker = super::load_texture("checker8.png", None, crate::bitmap::Filter::Nearest)?.with_scaling(3.0);
        scene.add(
            Node::new(Arc::new(Plane::new(0.0, 3.0)), Arc::new(Lambert::new(checker)))
                .rotate(0.0, -60.0, 0.0)
                .rotate(-25.0, 0.0, 0.0)
                .translate(Vector::new(-9.5, 4.0, 19.0)),
        );
        Ok(scene)
    }
}
