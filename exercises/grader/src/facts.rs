//! The facts each exercise is checked against: values the slide's formula gives, invariants, conservation
//! of energy. Each check takes the function to check as an argument (so the grader's own tests can hand it a
//! wrong one) and returns the first wrong value as a sentence a student can act on.

use crate::{CONE_FILTER_K, Color, Face, Photon, Vector};
use glam::{Affine3A, EulerRot, Quat, Vec3};
use std::f32::consts::{FRAC_PI_4, PI};
use std::fmt::Display;

/// `Ok` when every fact holds; otherwise the first wrong value, in words.
pub type Facts = Result<(), String>;

/// A vector or colour with four decimals.
pub fn show(v: Vector) -> String {
    format!("({:.4}, {:.4}, {:.4})", v.x, v.y, v.z)
}

/// Fails unless `got` is within `tolerance` of `want`: "`what` should be `want`, got `got`".
fn expect_near(what: impl Display, got: f32, want: f32, tolerance: f32) -> Facts {
    if (got - want).abs() <= tolerance { Ok(()) } else { Err(format!("{what} should be {want:.4}, got {got:.4}")) }
}

/// Fails unless every coordinate of `got` is within `tolerance` of `want`.
fn expect_vector_near(what: impl Display, got: Vector, want: Vector, tolerance: f32) -> Facts {
    if (got - want).abs().max_element() <= tolerance {
        Ok(())
    } else {
        Err(format!("{what} should be {}, got {}", show(want), show(got)))
    }
}

/// Fails unless both coordinates of the point `got` are within `tolerance` of `want`.
fn expect_point_near(what: impl Display, got: (f32, f32), want: (f32, f32), tolerance: f32) -> Facts {
    if (got.0 - want.0).abs() <= tolerance && (got.1 - want.1).abs() <= tolerance {
        Ok(())
    } else {
        Err(format!("{what} should be ({:.4}, {:.4}), got ({:.4}, {:.4})", want.0, want.1, got.0, got.1))
    }
}

/// A deterministic stream of numbers in [0, 1) (xorshift), so the facts are the same at every run.
pub struct Stream(u32);

impl Stream {
    pub fn new(seed: u32) -> Stream {
        Stream(seed.max(1))
    }
    /// The next number.
    pub fn next_number(&mut self) -> f32 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 17;
        self.0 ^= self.0 << 5;
        (self.0 >> 8) as f32 / (1u32 << 24) as f32
    }
    /// A direction drawn evenly over the sphere.
    pub fn direction(&mut self) -> Vector {
        let z = 1.0 - 2.0 * self.next_number();
        let phi = 2.0 * PI * self.next_number();
        let s = (1.0 - z * z).max(0.0).sqrt();
        Vector::new(s * phi.cos(), s * phi.sin(), z)
    }
}

/// The normal of a floor, and the incoming direction that meets it `degrees` from the normal, coming down.
fn floor_ray(degrees: f32) -> (Vector, Vector) {
    let a = degrees.to_radians();
    (Vector::Y, Vector::new(a.sin(), -a.cos(), 0.0))
}

// ---------------------------------------------------------------------------------------------------------
// Bitmap textures

/// A bilinear filter: `(x, y, texel)`, with `texel(i, j)` the wrapped texel.
pub type Bilinear = dyn Fn(f32, f32, &dyn Fn(i64, i64) -> Color) -> Color;

/// The bilinear filter.
pub fn bilinear(bilinear: &Bilinear) -> Facts {
    // An image whose texels are (column, row, column * row): bilinear filtering reproduces it exactly
    // between the centres, so the colour at (x, y) is the one at (x - 0.5, y - 0.5).
    let ramp = |i: i64, j: i64| Color::new(i as f32, j as f32, (i * j) as f32);
    let expected = |x: f32, y: f32| Color::new(x - 0.5, y - 0.5, (x - 0.5) * (y - 0.5));
    let centre = bilinear(2.5, 1.5, &ramp);
    expect_vector_near(
        "At the centre of texel (2, 1), (x, y) = (2.5, 1.5), the filter returns that texel alone; its colour",
        centre,
        ramp(2, 1),
        1e-4,
    )?;
    expect_vector_near(
        "Halfway between the centres of texels (0, 0) and (1, 0), at (1, 0.5), the filter returns their average; its colour",
        bilinear(1.0, 0.5, &ramp),
        (ramp(0, 0) + ramp(1, 0)) * 0.5,
        1e-4,
    )?;
    // Texels of squares, (column^2, row^2, 0): a point a quarter texel up and to the left of the first
    // centre lies between texels -1 and 0, 3/4 of the way to 0.
    let squares = |i: i64, j: i64| Color::new((i * i) as f32, (j * j) as f32, 0.0);
    expect_vector_near(
        "At (0.25, 0.25), a quarter texel left of and above the centre of texel (0, 0), the filter mixes texels \
         -1 and 0 in each direction (texel(-1, j) is the wrapped neighbour), 1/4 and 3/4; on the texels \
         (column^2, row^2, 0) its colour",
        bilinear(0.25, 0.25, &squares),
        Color::new(0.25, 0.25, 0.0),
        1e-4,
    )?;
    let mut stream = Stream::new(7);
    for _ in 0..200 {
        let (x, y) = (-3.0 + 13.0 * stream.next_number(), -3.0 + 13.0 * stream.next_number());
        expect_vector_near(
            format!(
                "On the texels (column, row, column * row), which bilinear filtering reproduces exactly, the colour \
                 at ({x:.4}, {y:.4})"
            ),
            bilinear(x, y, &ramp),
            expected(x, y),
            1e-3,
        )?;
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------------------------
// Model transform

/// The inverse of an affine transform.
pub fn transform_inverse(inverse: &dyn Fn(Affine3A) -> Affine3A) -> Facts {
    let slide_scale = Vec3::new(2.0, 1.5, 0.9);
    let slide_rotation = Quat::from_euler(EulerRot::YXZ, 0.8, 0.1, 0.2);
    let slide_translation = Vec3::new(3.3, 0.0, 18.1);
    let translation = Affine3A::from_translation(slide_translation);
    let got = inverse(translation);
    if (got.matrix3 - glam::Mat3A::IDENTITY).abs().to_cols_array().iter().any(|&e| e > 1e-5)
        || (got.translation - Vector::new(-3.3, 0.0, -18.1)).abs().max_element() > 1e-4
    {
        return Err(format!(
            "A translation by (3.3, 0, 18.1) should be undone by the translation (-3.3, 0, -18.1) alone; got the \
             translation {} and the linear part (columns) {}, {}, {}",
            show(got.translation),
            show(got.matrix3.x_axis),
            show(got.matrix3.y_axis),
            show(got.matrix3.z_axis)
        ));
    }
    let scale = inverse(Affine3A::from_scale(slide_scale));
    expect_vector_near(
        "A scale by (2, 1.5, 0.9) should be undone by the scale (1/2, 1/1.5, 1/0.9): the diagonal of its inverse",
        Vector::new(scale.matrix3.x_axis.x, scale.matrix3.y_axis.y, scale.matrix3.z_axis.z),
        Vector::new(0.5, 1.0 / 1.5, 1.0 / 0.9),
        1e-5,
    )?;
    let rotation = glam::Mat3A::from_quat(slide_rotation);
    let got = inverse(Affine3A::from_mat3(rotation.into())).matrix3;
    for (k, (g, w)) in
        [got.x_axis, got.y_axis, got.z_axis].into_iter().zip(rotation.transpose().to_cols_array_2d()).enumerate()
    {
        expect_vector_near(
            format!("A rotation is undone by its transpose: column {} of the inverse of the slide's rotation", k + 1),
            g,
            Vector::from_array(w),
            1e-5,
        )?;
    }
    let slide = Affine3A::from_scale_rotation_translation(slide_scale, slide_rotation, slide_translation);
    // Not only the slide's order: a rotation after the translation and a second, non-uniform scale.
    let other = Affine3A::from_scale(Vec3::new(1.0, 3.0, 0.5))
        * Affine3A::from_rotation_x(0.7)
        * Affine3A::from_translation(Vec3::new(-40.0, 2.0, 5.0))
        * Affine3A::from_rotation_z(-1.2)
        * Affine3A::from_scale(Vec3::new(0.2, 4.0, 1.5));
    let cases = [
        (slide, "the slide's transform (scale (2, 1.5, 0.9), rotate (0.8, 0.1, 0.2), translate (3.3, 0, 18.1))"),
        (other, "a transform that scales, rotates, translates, rotates and scales again"),
    ];
    for (t, name) in cases {
        let t_inverse = inverse(t);
        for p in [Vector::new(1.0, 2.0, 3.0), Vector::new(-7.0, 0.5, 11.0), Vector::ZERO] {
            let moved = t.transform_point3a(p);
            let tolerance = 1e-4 * (1.0 + p.abs().max_element().max(moved.abs().max_element()));
            expect_vector_near(
                format!(
                    "For {name}, the inverse should take T(p) = {} back to p = {}; it gives a point that",
                    show(moved),
                    show(p)
                ),
                t_inverse.transform_point3a(moved),
                p,
                tolerance,
            )?;
        }
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------------------------
// Environment

/// The face's centre and the directions its u and v grow along (the exercise's table).
fn face_axes(face: Face) -> (Vector, Vector, Vector) {
    let (x, y, z) = (Vector::X, Vector::Y, Vector::Z);
    match face {
        Face::PosX => (x, -z, -y),
        Face::NegX => (-x, z, -y),
        Face::PosY => (y, x, z),
        Face::NegY => (-y, x, -z),
        Face::PosZ => (z, x, -y),
        Face::NegZ => (-z, -x, -y),
    }
}

/// The cube map's face and texel choice.
pub fn cube_map(cube_face_uv: &dyn Fn(Vector) -> (Face, f32, f32)) -> Facts {
    let faces = [Face::PosX, Face::NegX, Face::PosY, Face::NegY, Face::PosZ, Face::NegZ];
    for face in faces {
        let centre = face_axes(face).0;
        let (got, u, v) = cube_face_uv(centre);
        if got != face || (u - 0.5).abs() > 1e-5 || (v - 0.5).abs() > 1e-5 {
            return Err(format!(
                "The direction {} should land in the middle of {face:?}, (u, v) = (0.5, 0.5); got {got:?} at ({u:.4}, \
                 {v:.4})",
                show(centre)
            ));
        }
    }
    let (face, u, v) = cube_face_uv(Vector::new(0.5, 0.0, 1.0));
    if face != Face::PosZ || (u - 0.75).abs() > 1e-5 || (v - 0.5).abs() > 1e-5 {
        return Err(format!(
            "The direction (0.5, 0, 1) should land on PosZ at (u, v) = (0.75, 0.5) (u grows along +X); got {face:?} \
             at ({u:.4}, {v:.4})"
        ));
    }
    let (face, u, v) = cube_face_uv(Vector::new(0.0, 0.5, 1.0));
    if face != Face::PosZ || (u - 0.5).abs() > 1e-5 || (v - 0.25).abs() > 1e-5 {
        return Err(format!(
            "The direction (0, 0.5, 1) should land on PosZ at (u, v) = (0.5, 0.25) (v grows along -Y, down); got \
             {face:?} at ({u:.4}, {v:.4})"
        ));
    }
    let mut stream = Stream::new(11);
    for _ in 0..500 {
        let dir = stream.direction();
        let (face, u, v) = cube_face_uv(dir);
        // The face's centre is the axis of the direction's largest component, on the side it points to.
        let (along, largest) = (dir.dot(face_axes(face).0), dir.abs().max_element());
        if along < largest {
            return Err(format!(
                "The direction {} should land on the face of its largest component ({largest:.4} in size); got \
                 {face:?}, along whose centre it goes {along:.4}",
                show(dir)
            ));
        }
        if !((0.0..=1.0).contains(&u) && (0.0..=1.0).contains(&v)) {
            return Err(format!("The direction {} lands at (u, v) = ({u:.4}, {v:.4}), outside [0, 1]", show(dir)));
        }
        let (centre, u_axis, v_axis) = face_axes(face);
        let back = (centre + (2.0 * u - 1.0) * u_axis + (2.0 * v - 1.0) * v_axis).normalize();
        expect_vector_near(
            format!(
                "The direction {} lands on {face:?} at (u, v) = ({u:.4}, {v:.4}); by the table of the faces, the \
                 direction through that point",
                show(dir)
            ),
            back,
            dir,
            1e-4,
        )?;
        let (face3, u3, v3) = cube_face_uv(3.0 * dir);
        if face3 != face || (u3 - u).abs() > 1e-5 || (v3 - v).abs() > 1e-5 {
            return Err(format!(
                "Only the direction counts, not its length: {} lands on {face:?} at ({u:.4}, {v:.4}), but three times \
                 it on {face3:?} at ({u3:.4}, {v3:.4})",
                show(dir)
            ));
        }
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------------------------
// Reflection & refraction

/// `faceforward`.
pub fn faceforward(faceforward: &dyn Fn(Vector, Vector) -> Vector) -> Facts {
    let n = Vector::Y;
    expect_vector_near(
        "A ray coming down onto a floor (i = (0, -1, 0)) sees its normal n = (0, 1, 0) as it is: faceforward(n, i)",
        faceforward(n, -Vector::Y),
        n,
        0.0,
    )?;
    expect_vector_near(
        "A ray coming up from under a floor (i = (0, 1, 0)) sees its normal n = (0, 1, 0) turned: faceforward(n, i)",
        faceforward(n, Vector::Y),
        -n,
        0.0,
    )?;
    let mut stream = Stream::new(3);
    for _ in 0..500 {
        let (n, i) = (stream.direction(), stream.direction());
        let got = faceforward(n, i);
        if got != n && got != -n {
            return Err(format!(
                "faceforward(n, i) must be n or -n; for n = {} and i = {} it is {}",
                show(n),
                show(i),
                show(got)
            ));
        }
        if got.dot(i) > 0.0 {
            return Err(format!(
                "faceforward(n, i) must face i (dot(i, faceforward(n, i)) <= 0); for n = {} and i = {} it is {}, \
                 which faces away",
                show(n),
                show(i),
                show(got)
            ));
        }
    }
    Ok(())
}

/// `refract`.
pub fn refract(refract: &dyn Fn(Vector, Vector, f32) -> Option<Vector>) -> Facts {
    let (n, i) = floor_ray(0.0);
    match refract(i, n, 1.0 / 1.5) {
        Some(t) => expect_vector_near(
            "A ray along the normal, entering glass of index 1.5, passes straight on: refract",
            t,
            i,
            1e-5,
        )?,
        None => {
            return Err(
                "A ray along the normal, entering glass of index 1.5, passes straight on; refract gave None".into()
            );
        }
    }
    let (n, i) = floor_ray(45.0);
    let sin_t = 45f32.to_radians().sin() / 1.5;
    let want = Vector::new(sin_t, -(1.0 - sin_t * sin_t).sqrt(), 0.0);
    match refract(i, n, 1.0 / 1.5) {
        Some(t) => expect_vector_near(
            format!(
                "A ray meeting glass of index 1.5 at 45 degrees from the normal (i = {}, n = (0, 1, 0), \
                 eta1_over_eta2 = 1/1.5) bends towards the normal, sin(theta2) = sin(45) / 1.5: refract",
                show(i)
            ),
            t,
            want,
            1e-4,
        )?,
        None => return Err("A ray entering glass of index 1.5 at 45 degrees refracts; refract gave None".into()),
    }
    let (n, i) = floor_ray(60.0);
    if let Some(t) = refract(i, n, 1.5) {
        return Err(format!(
            "Leaving glass of index 1.5 at 60 degrees from the normal (eta1_over_eta2 = 1.5), sin(theta2) would be \
             1.5 sin(60) = 1.30 > 1: total internal reflection, so refract should give None; it gave Some({})",
            show(t)
        ));
    }
    let mut stream = Stream::new(5);
    for k in 0..400 {
        let eta = if k % 2 == 0 { 1.0 / 1.5 } else { 1.5 };
        let n = stream.direction();
        let d = stream.direction();
        let i = if d.dot(n) > 0.0 { -d } else { d };
        let cos_i = -i.dot(n);
        let sin_i = (1.0 - cos_i * cos_i).max(0.0).sqrt();
        let case = format!("i = {}, n = {}, eta1_over_eta2 = {eta:.4}", show(i), show(n));
        let got = refract(i, n, eta);
        let sin_t = eta * sin_i;
        if (sin_t - 1.0).abs() < 1e-3 {
            continue; // at the critical angle itself either answer is right
        }
        let Some(t) = got else {
            if sin_t < 1.0 {
                return Err(format!("For {case} a ray refracts (sin(theta2) = {sin_t:.4} < 1); refract gave None"));
            }
            continue;
        };
        if sin_t > 1.0 {
            return Err(format!(
                "For {case} sin(theta2) would be {sin_t:.4} > 1: total internal reflection, so refract should give \
                 None; it gave Some({})",
                show(t)
            ));
        }
        expect_near(format!("For {case}, the length of the refracted ray"), t.length(), 1.0, 1e-3)?;
        expect_near(
            format!("For {case}, the refracted ray must stay in the plane of i and n: its dot product with i x n"),
            t.dot(i.cross(n)),
            0.0,
            1e-3,
        )?;
        if t.dot(n) >= 0.0 {
            return Err(format!(
                "For {case}, the refracted ray {} must go through the surface (dot(t, n) < 0)",
                show(t)
            ));
        }
        expect_near(
            format!("For {case}, Snell's law: sin(theta2) = eta1_over_eta2 sin(theta1)"),
            t.cross(n).length(),
            sin_t,
            1e-3,
        )?;
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------------------------
// Layered shader

/// The layer weight.
pub fn layered_blend(layer_weight: &dyn Fn(Color, Color) -> Color) -> Facts {
    expect_vector_near(
        "The top layer, opaque (blend 1), covers everything: its weight",
        layer_weight(Color::ONE, Color::ONE),
        Color::ONE,
        1e-6,
    )?;
    expect_vector_near(
        "A layer under an opaque one (uncovered 0) cannot be seen: its weight",
        layer_weight(Color::ZERO, Color::splat(0.7)),
        Color::ZERO,
        1e-6,
    )?;
    expect_vector_near(
        "A transparent layer (blend 0) adds nothing: its weight",
        layer_weight(Color::splat(0.6), Color::ZERO),
        Color::ZERO,
        1e-6,
    )?;
    let mut stream = Stream::new(9);
    let color = |stream: &mut Stream| Color::new(stream.next_number(), stream.next_number(), stream.next_number());
    for count in 1..=5 {
        for _ in 0..40 {
            // Bottom to top: (colour, blend).
            let layers: Vec<(Color, Color)> = (0..count).map(|_| (color(&mut stream), color(&mut stream))).collect();
            let mut slide = Color::ZERO;
            for &(c, blend) in &layers {
                slide = slide * (Color::ONE - blend) + c * blend;
            }
            let mut res = Color::ZERO;
            let mut uncovered = Color::ONE;
            let mut weights = Color::ZERO;
            for &(c, blend) in layers.iter().rev() {
                let weight = layer_weight(uncovered, blend);
                res += c * weight;
                weights += weight;
                uncovered *= Color::ONE - blend;
            }
            let stack: Vec<String> =
                layers.iter().map(|(c, b)| format!("colour {} blend {}", show(*c), show(*b))).collect();
            expect_vector_near(
                format!(
                    "For the layers (bottom to top) [{}], the slide's loop gives res = {}; walked from the top with \
                     your weights, the colour",
                    stack.join("; "),
                    show(slide)
                ),
                res,
                slide,
                1e-4,
            )?;
            expect_vector_near(
                format!(
                    "For the layers (bottom to top) [{}], the weights and what is left uncovered must add up to white \
                     (no light made or lost): they add up to",
                    stack.join("; ")
                ),
                weights + uncovered,
                Color::ONE,
                1e-4,
            )?;
        }
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------------------------
// Fresnel

/// The reflectance Schlick's formula gives (with the workbook's rule for rays leaving the denser medium), for
/// a ray entering glass of index 1.5 at 0, 1, ..., 89 degrees from the normal: numbers, not the formula, so
/// that the grader a student receives holds no answer (the grader's own tests check them against it).
pub const SCHLICK_ENTERING_GLASS: [f32; 90] = [
    0.040000, 0.040000, 0.040000, 0.040000, 0.040000, 0.040000, 0.040000, 0.040000, 0.040000, 0.040000, 0.040000,
    0.040000, 0.040000, 0.040000, 0.040000, 0.040000, 0.040000, 0.040000, 0.040000, 0.040000, 0.040001, 0.040001,
    0.040002, 0.040003, 0.040005, 0.040007, 0.040010, 0.040015, 0.040021, 0.040030, 0.040041, 0.040057, 0.040078,
    0.040105, 0.040140, 0.040186, 0.040244, 0.040318, 0.040411, 0.040528, 0.040673, 0.040852, 0.041073, 0.041343,
    0.041672, 0.042069, 0.042548, 0.043122, 0.043807, 0.044621, 0.045583, 0.046718, 0.048051, 0.049609, 0.051426,
    0.053536, 0.055978, 0.058795, 0.062036, 0.065752, 0.070000, 0.074843, 0.080347, 0.086588, 0.093644, 0.101601,
    0.110552, 0.120597, 0.131841, 0.144400, 0.158395, 0.173956, 0.191220, 0.210332, 0.231448, 0.254730, 0.280348,
    0.308483, 0.339322, 0.373063, 0.409910, 0.450077, 0.493785, 0.541264, 0.592752, 0.648492, 0.708736, 0.773742,
    0.843774, 0.919102,
];

/// Schlick's reflectance for a ray leaving glass of index 1.5 at 30 degrees from the normal, by the cosine of
/// the refracted ray (0.6614).
pub const SCHLICK_LEAVING_GLASS_AT_30: f32 = 0.044270;

/// Schlick's approximation.
pub fn fresnel_schlick(fresnel: &dyn Fn(Vector, Vector, f32) -> f32) -> Facts {
    let entering = 1.0 / 1.5;
    let (n, i) = floor_ray(0.0);
    expect_near(
        "Head-on (i = (0, -1, 0), n = (0, 1, 0)), entering glass of index 1.5 (eta1_over_eta2 = 1/1.5), the \
         reflectance is f0 = ((1 - 1/1.5) / (1 + 1/1.5))^2: fresnel",
        fresnel(i, n, entering),
        0.04,
        1e-4,
    )?;
    expect_near(
        "Head-on, leaving glass of index 1.5 (eta1_over_eta2 = 1.5), the reflectance is f0 = ((1 - 1.5) / (1 + \
         1.5))^2 = 0.04 too: fresnel",
        fresnel(i, n, 1.5),
        0.04,
        1e-4,
    )?;
    let (n, i) = floor_ray(60.0);
    expect_near(
        "At 60 degrees from the normal, entering glass of index 1.5, Schlick's formula gives f0 + (1 - f0) (1 - cos \
         60)^5 = 0.04 + 0.96 / 32: fresnel",
        fresnel(i, n, entering),
        0.07,
        1e-4,
    )?;
    let (n, i) = floor_ray(90.0);
    expect_near(
        "At a grazing angle (90 degrees from the normal), everything is reflected: fresnel",
        fresnel(i, n, entering),
        1.0,
        1e-4,
    )?;
    let (n, i) = floor_ray(45.0);
    expect_near(
        "Leaving glass of index 1.5 at 45 degrees from the normal, past the critical angle (41.8 degrees), nothing \
         gets out (total internal reflection): fresnel",
        fresnel(i, n, 1.5),
        1.0,
        1e-4,
    )?;
    let (n, i) = floor_ray(30.0);
    expect_near(
        "Leaving glass of index 1.5 at 30 degrees from the normal, Schlick's formula takes the cosine of the \
         refracted ray outside (cos_t = sqrt(1 - 1.5^2 sin^2 30) = 0.6614), not of the incoming one: fresnel",
        fresnel(i, n, 1.5),
        SCHLICK_LEAVING_GLASS_AT_30,
        1e-4,
    )?;
    let mut previous = 0.0;
    for (degrees, &want) in SCHLICK_ENTERING_GLASS.iter().enumerate() {
        let (n, i) = floor_ray(degrees as f32);
        let r = fresnel(i, n, entering);
        if !(0.0..=1.0).contains(&r) || r + 1e-6 < previous {
            return Err(format!(
                "Entering glass, the reflectance must stay between 0 and 1 and grow with the angle; at {degrees} \
                 degrees fresnel gives {r:.4} (at one degree less, {previous:.4})"
            ));
        }
        expect_near(
            format!(
                "At {degrees} degrees from the normal, entering glass of index 1.5, Schlick's formula gives fresnel"
            ),
            r,
            want,
            1e-4,
        )?;
        previous = r;
    }
    Ok(())
}

/// The exact Fresnel reflectance (unpolarised light) of a ray entering glass of index 1.5 at 0, 1, ..., 89
/// degrees from the normal (see [`SCHLICK_ENTERING_GLASS`]).
pub const EXACT_ENTERING_GLASS: [f32; 90] = [
    0.040000, 0.040000, 0.040000, 0.040000, 0.040000, 0.040001, 0.040002, 0.040004, 0.040006, 0.040010, 0.040015,
    0.040023, 0.040032, 0.040045, 0.040061, 0.040081, 0.040105, 0.040135, 0.040172, 0.040215, 0.040266, 0.040327,
    0.040398, 0.040480, 0.040576, 0.040686, 0.040813, 0.040958, 0.041123, 0.041310, 0.041523, 0.041762, 0.042032,
    0.042336, 0.042677, 0.043058, 0.043484, 0.043960, 0.044489, 0.045079, 0.045734, 0.046461, 0.047267, 0.048159,
    0.049147, 0.050240, 0.051447, 0.052780, 0.054251, 0.055874, 0.057663, 0.059634, 0.061806, 0.064197, 0.066829,
    0.069726, 0.072913, 0.076420, 0.080277, 0.084520, 0.089187, 0.094319, 0.099964, 0.106172, 0.113001, 0.120513,
    0.128779, 0.137874, 0.147885, 0.158906, 0.171043, 0.184412, 0.199144, 0.215385, 0.233297, 0.253061, 0.274879,
    0.298981, 0.325620, 0.355087, 0.387704, 0.423840, 0.463911, 0.508389, 0.557814, 0.612800, 0.674053, 0.742386,
    0.818735, 0.904185,
];

/// The exact Fresnel reflectance of a ray entering glass of index 1.5 at Brewster's angle (atan 1.5).
pub const EXACT_AT_BREWSTER: f32 = 0.073964;

/// The exact Fresnel equations.
pub fn fresnel_exact(fresnel_exact: &dyn Fn(Vector, Vector, f32) -> f32) -> Facts {
    let entering = 1.0 / 1.5;
    let (n, i) = floor_ray(0.0);
    expect_near(
        "Head-on (i = (0, -1, 0), n = (0, 1, 0)), entering glass of index 1.5, the reflectance is ((1.5 - 1) / (1.5 + \
         1))^2: fresnel_exact",
        fresnel_exact(i, n, entering),
        0.04,
        1e-4,
    )?;
    let brewster = 1.5f64.atan();
    let (n, i) = floor_ray(brewster.to_degrees() as f32);
    expect_near(
        "At Brewster's angle (56.31 degrees, tan = 1.5), entering glass of index 1.5, rp = 0 and R = rs^2 / 2: \
         fresnel_exact",
        fresnel_exact(i, n, entering),
        EXACT_AT_BREWSTER,
        1e-4,
    )?;
    let (n, i) = floor_ray(90.0);
    expect_near(
        "At a grazing angle (90 degrees from the normal), everything is reflected: fresnel_exact",
        fresnel_exact(i, n, entering),
        1.0,
        1e-4,
    )?;
    let (n, i) = floor_ray(45.0);
    expect_near(
        "Leaving glass of index 1.5 at 45 degrees from the normal, past the critical angle, nothing gets out (total \
         internal reflection): fresnel_exact",
        fresnel_exact(i, n, 1.5),
        1.0,
        1e-4,
    )?;
    for degrees in [10.0f32, 30.0, 40.0] {
        let theta_t = (degrees.to_radians().sin() * 1.5).asin().to_degrees();
        let (n, i) = floor_ray(degrees);
        let (n_out, i_out) = floor_ray(theta_t);
        let leaving = fresnel_exact(i, n, 1.5);
        let entering_back = fresnel_exact(i_out, n_out, entering);
        if (leaving - entering_back).abs() > 1e-4 {
            return Err(format!(
                "The equations are symmetric: leaving glass of index 1.5 at {degrees} degrees from the normal \
                 reflects as much as entering it along the refracted ray's path, at {theta_t:.2} degrees; \
                 fresnel_exact gives {leaving:.4} and {entering_back:.4}"
            ));
        }
    }
    for (degrees, &want) in EXACT_ENTERING_GLASS.iter().enumerate() {
        let (n, i) = floor_ray(degrees as f32);
        expect_near(
            format!(
                "At {degrees} degrees from the normal, entering glass of index 1.5, the Fresnel equations give \
                 fresnel_exact"
            ),
            fresnel_exact(i, n, entering),
            want,
            1e-4,
        )?;
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------------------------
// Glossy reflections

/// The slide's random point in the unit disc, drawing from `random()`.
pub type RandomDiscPoint = dyn Fn(&mut dyn FnMut() -> f32) -> (f32, f32);

/// Points in the unit disc: the slide's random one and the concentric mapping.
pub fn glossy_disc(
    random_unit_disc_point: &RandomDiscPoint,
    concentric_disc: &dyn Fn(f32, f32) -> (f32, f32),
) -> Facts {
    let from = |numbers: &[f32]| {
        let mut numbers = numbers.iter().copied();
        random_unit_disc_point(&mut || {
            numbers.next().expect(
                "random_unit_disc_point drew more random numbers than the slide's rejection needs: \
                                   two a point, until one lies in the disc",
            )
        })
    };
    let (x, y) = from(&[0.5, 0.75]);
    expect_point_near(
        "From the random numbers 0.5, 0.75 (x = 2 * 0.5 - 1, then y = 2 * 0.75 - 1), the slide's point in the disc",
        (x, y),
        (0.0, 0.5),
        1e-6,
    )?;
    let (x, y) = from(&[0.0, 0.0, 0.5, 0.5]);
    expect_point_near(
        "From the random numbers 0, 0 (the corner (-1, -1), outside the disc: drawn again), then 0.5, 0.5, the point",
        (x, y),
        (0.0, 0.0),
        1e-6,
    )?;
    let mut stream = Stream::new(13);
    let count = 40_000;
    let (mut sum, mut sum_r2, mut inner, mut quadrants) = (Vector::ZERO, 0.0, 0, [0u32; 4]);
    for _ in 0..count {
        let (x, y) = random_unit_disc_point(&mut || stream.next_number());
        let r2 = x * x + y * y;
        if r2 > 1.0 + 1e-6 {
            return Err(format!("random_unit_disc_point gave ({x:.4}, {y:.4}), outside the unit disc"));
        }
        sum += Vector::new(x, y, 0.0);
        sum_r2 += r2;
        inner += (r2 < 0.25) as u32;
        quadrants[(x < 0.0) as usize * 2 + (y < 0.0) as usize] += 1;
    }
    let n = count as f32;
    expect_near(
        format!("Evenly spread over the disc, the {count} random points' mean squared distance from the centre"),
        sum_r2 / n,
        0.5,
        0.01,
    )?;
    expect_near(
        format!("Evenly spread over the disc, the fraction of the {count} random points within radius 1/2"),
        inner as f32 / n,
        0.25,
        0.01,
    )?;
    expect_point_near(
        format!("Evenly spread over the disc, the mean of the {count} random points"),
        (sum.x / n, sum.y / n),
        (0.0, 0.0),
        0.01,
    )?;
    for (k, &q) in quadrants.iter().enumerate() {
        expect_near(
            format!("The fraction of the random points in quarter {} of the disc", k + 1),
            q as f32 / n,
            0.25,
            0.01,
        )?;
    }
    let s = FRAC_PI_4.sin();
    let values = [
        ((0.5, 0.5), (0.0, 0.0), "the centre of the square goes to the centre of the disc"),
        ((1.0, 0.5), (1.0, 0.0), "the middle of the right edge goes to (1, 0)"),
        ((0.5, 1.0), (0.0, 1.0), "the middle of the top edge goes to (0, 1)"),
        ((0.0, 0.5), (-1.0, 0.0), "the middle of the left edge goes to (-1, 0)"),
        ((0.5, 0.0), (0.0, -1.0), "the middle of the bottom edge goes to (0, -1)"),
        ((1.0, 1.0), (s, s), "the corner (1, 1) goes to the circle at 45 degrees"),
        ((0.75, 0.5), (0.5, 0.0), "(0.75, 0.5) goes to (0.5, 0)"),
        ((1.0, 0.75), ((PI / 8.0).cos(), (PI / 8.0).sin()), "(1, 0.75) goes to the circle at 22.5 degrees"),
    ];
    for ((u, v), (x, y), fact) in values {
        let (gx, gy) = concentric_disc(u, v);
        expect_point_near(
            format!("In the concentric mapping {fact}: concentric_disc({u}, {v})"),
            (gx, gy),
            (x, y),
            1e-4,
        )?;
    }
    for k in 0..=64 {
        let t = k as f32 / 64.0;
        for (u, v) in [(t, 0.0), (t, 1.0), (0.0, t), (1.0, t)] {
            let (x, y) = concentric_disc(u, v);
            expect_near(
                format!(
                    "The edge of the square goes to the unit circle: the distance from the centre of \
                     concentric_disc({u:.4}, {v:.4})"
                ),
                x.hypot(y),
                1.0,
                1e-4,
            )?;
        }
    }
    // Keeping areas: the 64 x 64 cells' centres, counted by eighths of the disc and inside radius 1/2.
    let (mut inner, mut eighths) = (0u32, [0u32; 8]);
    for a in 0..64 {
        for b in 0..64 {
            let (x, y) = concentric_disc((a as f32 + 0.5) / 64.0, (b as f32 + 0.5) / 64.0);
            inner += (x.hypot(y) < 0.5) as u32;
            let angle = y.atan2(x).rem_euclid(2.0 * PI);
            eighths[((angle / FRAC_PI_4) as usize).min(7)] += 1;
        }
    }
    expect_near(
        "The concentric mapping keeps areas: the fraction of a grid of the square's points within radius 1/2",
        inner as f32 / 4096.0,
        0.25,
        0.005,
    )?;
    for (k, &e) in eighths.iter().enumerate() {
        expect_near(
            format!(
                "The concentric mapping keeps areas: the fraction of a grid of the square's points in eighth {} of \
                 the disc",
                k + 1
            ),
            e as f32 / 4096.0,
            0.125,
            0.005,
        )?;
    }
    Ok(())
}

/// The glossy cone: the scaling and the direction.
pub fn glossy_cone(
    glossy_scaling: &dyn Fn(f32) -> f32,
    glossy_direction: &dyn Fn(Vector, Vector, Vector, Vector, f32, (f32, f32)) -> Option<Vector>,
) -> Facts {
    // tan((1 - glossiness) * pi/2) at the slides' glossinesses.
    for (glossiness, scaling) in [(1.0f32, 0.0), (0.95, 0.0787017), (0.8, 0.3249197), (0.5, 1.0)] {
        expect_near(
            format!("The slide's scaling = tan((1 - glossiness) * pi/2) at glossiness {glossiness}"),
            glossy_scaling(glossiness),
            scaling,
            1e-5,
        )?;
    }
    let (n, t, b) = (Vector::Y, Vector::X, Vector::Z);
    let (_, i) = floor_ray(45.0);
    let mirror = Vector::new(i.x, -i.y, 0.0);
    match glossy_direction(i, n, t, b, 0.3, (0.0, 0.0)) {
        Some(d) => expect_vector_near(
            "The centre of the disc, (0, 0), tilts nothing: the mirror direction of a ray at 45 degrees; \
             glossy_direction",
            d,
            mirror,
            1e-5,
        )?,
        None => return Err("The centre of the disc gives the mirror direction; glossy_direction gave None".into()),
    }
    match glossy_direction(i, n, t, b, 0.0, (0.8, -0.3)) {
        Some(d) => expect_vector_near(
            "A perfect mirror (scaling 0) reflects every disc point in the mirror direction; glossy_direction",
            d,
            mirror,
            1e-5,
        )?,
        None => {
            return Err(
                "A perfect mirror (scaling 0) reflects in the mirror direction; glossy_direction gave None".into()
            );
        }
    }
    let down = -Vector::Y;
    let cases = [
        ((0.5, 0.0), Vector::new(0.8, 0.6, 0.0), "the tangent (1, 0, 0)"),
        ((0.0, 0.5), Vector::new(0.0, 0.6, 0.8), "the bitangent (0, 0, 1)"),
    ];
    for ((x, y), want, along) in cases {
        let what = format!(
            "A ray straight down onto a floor (normal (0, 1, 0)), scaling 1, the disc point ({x}, {y}): the normal \
             tilted along {along} to normalize(n + {x} * tangent + {y} * bitangent), and the ray reflected about \
             it; glossy_direction"
        );
        match glossy_direction(down, n, t, b, 1.0, (x, y)) {
            Some(d) => expect_vector_near(what, d, want, 1e-4)?,
            None => return Err(format!("{what} gave None, but the reflection {} leaves the surface", show(want))),
        }
    }
    let grazing = Vector::new(1.0, -0.2, 0.0).normalize();
    if let Some(d) = glossy_direction(grazing, n, t, b, 1.0, (1.0, 0.0)) {
        return Err(format!(
            "A grazing ray {} reflected about a normal tilted by the disc point (1, 0) goes under the surface; \
             glossy_direction should give None, it gave Some({})",
            show(grazing),
            show(d)
        ));
    }
    let mut stream = Stream::new(17);
    for _ in 0..500 {
        let (x, y) = (2.0 * stream.next_number() - 1.0, 2.0 * stream.next_number() - 1.0);
        let d = stream.direction();
        let incoming = if d.y < 0.0 { d } else { Vector::new(d.x, -d.y, d.z) };
        let scaling = 2.0 * stream.next_number();
        let tilted = (n + x * scaling * t + y * scaling * b).normalize();
        let reflected = crate::reflect(incoming, tilted);
        let got = glossy_direction(incoming, n, t, b, scaling, (x, y));
        let case =
            format!("the incoming ray {}, scaling {scaling:.4}, the disc point ({x:.4}, {y:.4})", show(incoming));
        match got {
            Some(dir) => {
                if dir.y <= 0.0 {
                    return Err(format!(
                        "For {case} glossy_direction gave {}, which goes under the surface: it should give None",
                        show(dir)
                    ));
                }
                expect_vector_near(
                    format!("For {case}, the reflection about the tilted normal"),
                    dir,
                    reflected,
                    1e-4,
                )?;
            }
            None if reflected.y > 1e-4 => {
                return Err(format!(
                    "For {case} the reflection {} leaves the surface; glossy_direction gave None",
                    show(reflected)
                ));
            }
            None => {}
        }
    }
    Ok(())
}

// ---------------------------------------------------------------------------------------------------------
// Photon mapping

/// The photon map's estimate.
pub fn photon_estimate(irradiance_estimate: &dyn Fn(&[Photon], f32, Vector) -> Color) -> Facts {
    let n = Vector::Y;
    let down = -Vector::Y;
    let area_of_the_filter = (1.0 - 2.0 / (3.0 * CONE_FILTER_K)) * PI;
    expect_vector_near(
        "No photons give no caustic light: the estimate",
        irradiance_estimate(&[], 1.0, n),
        Color::ZERO,
        0.0,
    )?;
    let power = Color::new(1.0, 2.0, 3.0);
    let centre = Photon { distance_squared: 0.0, dir: down, power };
    expect_vector_near(
        "One photon of power (1, 2, 3) right at the shaded point, in a disc of radius 1, counts fully: power / ((1 - \
         2 / (3 k)) pi r^2) with k = 1.1; the estimate",
        irradiance_estimate(&[centre], 1.0, n),
        power / area_of_the_filter,
        1e-4,
    )?;
    let behind = Photon { dir: Vector::Y, ..centre };
    expect_vector_near(
        "A photon that arrived from behind the surface (dir (0, 1, 0), normal (0, 1, 0)) does not light it: the \
         estimate",
        irradiance_estimate(&[behind], 1.0, n),
        Color::ZERO,
        1e-6,
    )?;
    let half = Photon { distance_squared: 0.25, dir: down, power: Color::ONE };
    expect_vector_near(
        "One photon of power 1 at distance 0.5, in a disc of radius 1, has the cone filter's weight 1 - 0.5 / (1.1 * \
         1); the estimate",
        irradiance_estimate(&[half], 1.0, n),
        Color::splat((1.0 - 0.5 / CONE_FILTER_K) / area_of_the_filter),
        1e-4,
    )?;
    let red = Photon { power: Color::X, ..centre };
    let got = irradiance_estimate(&[red], 4.0, n);
    expect_vector_near(
        "A red photon (power (1, 0, 0)) at the centre of a disc of radius 2 gives red light only, 1 / ((1 - 2 / (3 \
         k)) pi 4): the estimate",
        got,
        Color::X / (area_of_the_filter * 4.0),
        1e-4,
    )?;
    // Photons spread evenly over a disc of radius 2, of total power 10: the filter neither makes nor loses
    // light, so the estimate is the power over the area.
    let radius = 2.0f32;
    let steps = 120;
    let cell = 2.0 * radius / steps as f32;
    let mut photons = Vec::new();
    for a in 0..steps {
        for b in 0..steps {
            let (x, y) = (-radius + (a as f32 + 0.5) * cell, -radius + (b as f32 + 0.5) * cell);
            let d2 = x * x + y * y;
            if d2 <= radius * radius {
                photons.push(Photon { distance_squared: d2, dir: down, power: Color::ONE });
            }
        }
    }
    let each = 10.0 / photons.len() as f32;
    for p in &mut photons {
        p.power *= each;
    }
    expect_vector_near(
        format!(
            "{} photons of total power 10 spread evenly over a disc of radius 2 give their power over its area, 10 / \
             (4 pi) (the cone filter neither makes nor loses light); the estimate",
            photons.len()
        ),
        irradiance_estimate(&photons, radius * radius, n),
        Color::splat(10.0 / (PI * radius * radius)),
        0.01,
    )?;
    Ok(())
}
