//! The scene of the slides "Reflection v0.1" and "Reflection v0.2", which the examples `reflect_v01` and
//! `reflect_v02` share: mirrors that reflect each other, where the depth limit decides what is seen.

use crate::app::workbook::{checker_floor, sky, texture};
use crate::lesson::camera::Camera;
use crate::lesson::color::Color;
use crate::lesson::error::{Error, Result};
use crate::lesson::geometry::{Cube, Sphere};
use crate::lesson::light::PointLight;
use crate::lesson::math::Vector;
use crate::lesson::node::Node;
use crate::lesson::scene::Scene;
use crate::lesson::shader::{Lambert, Phong, Reflection};
use std::sync::Arc;

/// The scene of the reflection examples (`reflect_v01`, `reflect_v02`): two mirror spheres reflecting
/// `multiplier` of the light and a red ball on a checker floor under the sky; with `facing_mirrors`, two
/// large framed mirrors facing each other along the camera's axis, one 140 units in front of the camera and
/// one 40 units behind it. The caller sets the depth limit, which is what the two examples are about.
pub fn mirror_room(multiplier: f32, facing_mirrors: bool) -> Result<Scene> {
    if !(0.0..=1.0).contains(&multiplier) {
        return Err(Error::parameter("--multiplier", multiplier, "must be between 0 and 1"));
    }
    // The camera looks along +Z at the height of the mirrors' centres, square-on to them.
    let mut scene = Scene::new(Camera { position: Vector::new(0.0, 30.0, -40.0), fov: 75.0, ..Camera::default() });
    // The sky and the frames' wood are read side by side, on two threads.
    let (sky, wood) = rayon::join(sky, || facing_mirrors.then(|| texture("wood.png")).transpose());
    scene.environment = Some(sky?);
    scene.ambient = Color::gray(0.15);
    scene.lights.push(PointLight::new(Vector::new(-80.0, 250.0, 20.0), Color::new(1.0, 0.96, 0.9), 75000.0));
    scene.add(checker_floor(150.0, 20.0));

    // One mirror shader and one wooden frame shader, shared by the nodes that use them.
    let mirror = Arc::new(Reflection::new(multiplier));
    scene.add(Node::new(Sphere::new(Vector::new(-28.0, 15.0, 45.0), 15.0), mirror.clone()));
    scene.add(Node::new(Sphere::new(Vector::new(28.0, 15.0, 45.0), 15.0), mirror.clone()));
    scene.add(Node::new(
        Sphere::new(Vector::new(0.0, 8.0, 70.0), 8.0),
        Phong::new(Color::new(0.75, 0.12, 0.08), 0.3, 60.0),
    ));

    if let Some(wood) = wood? {
        // Each mirror is a thin box in a slightly larger wooden frame just behind it.
        let wood = Arc::new(Lambert::new(wood));
        for z in [100.0f32, -80.0] {
            let behind = z + z.signum();
            scene.add(
                Node::new(Cube::new(Vector::ZERO, 1.0), mirror.clone())
                    .scale(Vector::new(60.0, 30.0, 0.5))
                    .translate(Vector::new(0.0, 30.0, z)),
            );
            scene.add(
                Node::new(Cube::new(Vector::ZERO, 1.0), wood.clone())
                    .scale(Vector::new(64.0, 34.0, 1.0))
                    .translate(Vector::new(0.0, 30.0, behind)),
            );
        }
    }
    Ok(scene)
}
