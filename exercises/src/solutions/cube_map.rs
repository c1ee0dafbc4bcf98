//! The solution of the exercise in src/cube_map.rs (the teacher's copy only).

use crate::{Face, Vector};

pub fn cube_face_uv(dir: Vector) -> (Face, f32, f32) {
    let a = dir.abs();
    // The face, its centre, and the directions its u and v grow along (the table of the exercise).
    let (face, centre, u_axis, v_axis) = if a.x >= a.y && a.x >= a.z {
        if dir.x >= 0.0 {
            (Face::PosX, Vector::X, -Vector::Z, -Vector::Y)
        } else {
            (Face::NegX, -Vector::X, Vector::Z, -Vector::Y)
        }
    } else if a.y >= a.z {
        if dir.y >= 0.0 {
            (Face::PosY, Vector::Y, Vector::X, Vector::Z)
        } else {
            (Face::NegY, -Vector::Y, Vector::X, -Vector::Z)
        }
    } else if dir.z >= 0.0 {
        (Face::PosZ, Vector::Z, Vector::X, -Vector::Y)
    } else {
        (Face::NegZ, -Vector::Z, -Vector::X, -Vector::Y)
    };
    // Onto the face's plane at distance 1: the largest component becomes 1.
    let major = dir.dot(centre);
    (face, 0.5 + 0.5 * dir.dot(u_axis) / major, 0.5 + 0.5 * dir.dot(v_axis) / major)
}
