//! `Mesh` (slide "Model трансформация": "a teapot standing on its base, spout towards +X"): a triangle
//! mesh read from a Wavefront OBJ file, in its canonical form; a node's transform places it anywhere, and
//! several nodes can share one mesh (instancing).
//!
//! - Loading: tobj, from a regular file of at most [`MAX_OBJ_BYTES`]; polygons are cut into triangles in
//!   their own plane by ear clipping (see [`polygon`]), so non-convex faces keep their shape. Triangles
//!   with a zero area or a non-finite vertex are dropped (they cannot be hit and have no normal), so an
//!   empty or degenerate file gives an empty mesh, never a NaN.
//! - Shading: smooth with the file's vertex normals; a file without normals is faceted, as the course renders
//!   it, unless it is loaded with `auto_smooth` (the course's `autoSmooth`, the examples' `--smooth`), which
//!   sums the area-weighted face normals around each vertex (the course sums unit face normals, unweighted:
//!   a small difference on meshes of uneven triangles). `faceted` uses the face normals.
//!   `geometric_normal` is the face normal, turned to the side of the shading normal.
//! - u/v: from the file when it has texture coordinates (as written there), else the barycentric
//!   coordinates of the hit.
//! - Intersection: a [`Bvh`] built once at load time, whose leaves hold whole groups of four triangles,
//!   and the watertight ray-triangle test of Woop, Benthin and Wald, four triangles at a time (see
//!   [`triangle4`](super::triangle4): no cracks between neighbours, and a hit closer than the rounding
//!   error of its `t` is rejected, so a shadow or reflected ray never finds the triangle it starts on).
//!   The hit point's error bound is pbrt-v4's for barycentric interpolation, `gamma(7) * sum |b_i p_i|`.

use super::bvh::Bvh;
use super::polygon;
pub use super::triangle4::intersect_triangle;
use super::triangle4::{LANES, ShearedRay, Triangle4};
use super::{Aabb, Geometry, Hit, IntersectionInfo, Shape};
use crate::files::obj;
use crate::lesson::error::{Error, Result};
use crate::lesson::input;
use crate::lesson::math::{MAX_COORDINATE, Vector, gamma};
use crate::lesson::ray::Ray;
use std::path::Path;
use std::sync::Arc;

/// A triangle mesh with a BVH; see the module documentation.
#[derive(Clone, Debug)]
pub struct Mesh {
    bvh: Bvh,
    /// The triangles, four to a [`Triangle4`], in the order of the BVH's slots (slot `i` is lane `i % 4` of
    /// `triangles[i / 4]`; the slots that pad a leaf to whole groups of four hold no triangle).
    triangles: Vec<Triangle4>,
    /// How many slots hold a triangle.
    triangle_count: usize,
    /// The vertex normals of the triangle in each slot.
    normals: Vec<[Vector; 3]>,
    /// The texture coordinates of the triangle in each slot; empty when the file has none.
    uvs: Vec<[[f32; 2]; 3]>,
    /// Shade with the face normals instead of the interpolated vertex normals.
    pub faceted: bool,
    /// Ignore the triangles whose front (the side their corners wind counter-clockwise around, as the file
    /// lists them) faces away from the ray, for every ray: the course's `backfaceCulling`.
    pub backface_culling: bool,
}

/// The largest OBJ file read: 128 MiB, over two million triangles. The file is read whole and the mesh
/// built from it takes several times its size in memory, so a larger file is refused from its size before
/// anything is read.
pub const MAX_OBJ_BYTES: u64 = 128 << 20;

/// Extensions of image files, which are refused as meshes with a message saying so.
const IMAGE_EXTENSIONS: [&str; 8] = ["png", "jpg", "jpeg", "bmp", "hdr", "exr", "tga", "gif"];

/// Why the OBJ text `text` is refused when a finite vertex lies beyond ±[`MAX_COORDINATE`]: the line of
/// the first such `v` line, and the bound.
fn too_far(text: &str) -> String {
    let beyond = |line: &str| {
        let mut words = line.split_ascii_whitespace();
        let coordinate = |w: &str| w.parse::<f32>().is_ok_and(|c| c.is_finite() && c.abs() as f64 > MAX_COORDINATE);
        words.next() == Some("v") && words.take(3).any(coordinate)
    };
    let line = text.lines().position(beyond).map_or(String::new(), |i| format!("line {}: ", i + 1));
    format!(
        "{line}a vertex lies beyond ±{MAX_COORDINATE:e}, where the renderer's 32-bit floats can no longer square its \
         distances"
    )
}

/// Index triples into a list of attributes, one per triangle.
type Indices = [[u32; 3]];

fn face_normal(tri: &[Vector; 3]) -> Vector {
    (tri[1] - tri[0]).cross(tri[2] - tri[0])
}

/// Checks that every index of `indices` is below `len`.
fn check_indices(indices: &Indices, len: usize, what: &'static str) -> Result<()> {
    match indices.iter().flatten().find(|&&i| i as usize >= len) {
        Some(&i) => Err(Error::parameter(what, i, format!("there are only {len}"))),
        None => Ok(()),
    }
}

impl Mesh {
    /// A mesh from vertex positions and triangles (index triples), with smooth normals computed from the
    /// faces and barycentric u/v.
    pub fn new(positions: &[Vector], triangles: &Indices) -> Result<Mesh> {
        Mesh::from_parts(positions, triangles, None, None)
    }

    /// A mesh from positions and triangles, with optional vertex normals and texture coordinates, each
    /// with its own index triples (as OBJ files store them).
    pub fn from_parts(
        positions: &[Vector],
        triangles: &Indices,
        normals: Option<(&[Vector], &Indices)>,
        uvs: Option<(&[[f32; 2]], &Indices)>,
    ) -> Result<Mesh> {
        check_indices(triangles, positions.len(), "vertex index")?;
        if let Some((n, idx)) = normals {
            check_indices(idx, n.len(), "normal index")?;
            if idx.len() != triangles.len() {
                return Err(Error::parameter("normal indices", idx.len(), "one triple per triangle is needed"));
            }
        }
        if let Some((t, idx)) = uvs {
            check_indices(idx, t.len(), "texture coordinate index")?;
            if idx.len() != triangles.len() {
                return Err(Error::parameter("uv indices", idx.len(), "one triple per triangle is needed"));
            }
        }
        let corners = |t: &[u32; 3]| t.map(|i| positions[i as usize]);
        // Keep the triangles that can be hit: finite and of non-zero area.
        let keep: Vec<usize> = (0..triangles.len())
            .filter(|&i| {
                let tri = corners(&triangles[i]);
                let n = face_normal(&tri);
                tri.iter().all(|v| v.is_finite()) && n.is_finite() && n != Vector::ZERO
            })
            .collect();
        let computed: Vec<Vector>;
        let (normal_values, normal_indices) = match normals {
            Some(n) => n,
            None => {
                // Area-weighted vertex normals: the unnormalised face normal is twice the area times the
                // unit normal.
                let mut sum = vec![Vector::ZERO; positions.len()];
                for &i in &keep {
                    let t = &triangles[i];
                    let n = face_normal(&corners(t));
                    t.iter().for_each(|&v| sum[v as usize] += n);
                }
                computed = sum.into_iter().map(|n| n.normalize_or_zero()).collect();
                (&computed[..], triangles)
            }
        };
        let boxes: Vec<Aabb> = keep.iter().map(|&i| Aabb::from_points(corners(&triangles[i]))).collect();
        let (bvh, slots) = Bvh::build_in_groups(&boxes, LANES);
        // The triangle (its index in the file) in each slot.
        let original: Vec<Option<usize>> = slots.iter().map(|k| k.map(|k| keep[k as usize])).collect();
        let group = |four: &[Option<usize>]| {
            let present: Vec<[Vector; 3]> = four.iter().flatten().map(|&t| corners(&triangles[t])).collect();
            Triangle4::new(&present)
        };
        Ok(Mesh {
            bvh,
            // A leaf's padding comes after its triangles, so the present ones fill the first lanes.
            triangles: original.chunks(LANES).map(group).collect(),
            triangle_count: keep.len(),
            normals: original
                .iter()
                .map(|k| {
                    k.map_or([Vector::ZERO; 3], |t| {
                        normal_indices[t].map(|i| normal_values[i as usize].normalize_or_zero())
                    })
                })
                .collect(),
            uvs: uvs.map_or_else(Vec::new, |(values, idx)| {
                original.iter().map(|k| k.map_or([[0.0; 2]; 3], |t| idx[t].map(|i| values[i as usize]))).collect()
            }),
            faceted: false,
            backface_culling: false,
        })
    }

    /// Loads a Wavefront OBJ file (every object in it, polygons triangulated in their plane, see
    /// [`polygon`]). A mesh whose file has no normals is faceted, as the course renders it;
    /// [`Mesh::load_auto_smooth`] computes smooth normals for it instead. A missing, unreadable or malformed
    /// file is an error naming it (and the OS error, or the line at fault).
    pub fn load(path: &Path) -> Result<Mesh> {
        Mesh::load_auto_smooth(path, false)
    }

    /// Loads an OBJ file as [`Mesh::load`] does; when the file has no normals and `auto_smooth` is set (the
    /// course's `autoSmooth`, the examples' `--smooth`), smooth vertex normals are computed for it.
    pub fn load_auto_smooth(path: &Path, auto_smooth: bool) -> Result<Mesh> {
        let fail = |reason: String| Error::file("cannot read mesh", path, reason);
        let ext = path.extension().map(|e| e.to_string_lossy().to_ascii_lowercase()).unwrap_or_default();
        if IMAGE_EXTENSIONS.contains(&ext.as_str()) {
            return Err(fail(format!("it is an image (.{ext}), not an OBJ file")));
        }
        let bytes = input::read_capped(path, "cannot read mesh", "an OBJ file", MAX_OBJ_BYTES)?;
        let (text, polylines) = obj::text(&bytes);
        obj::check_face_indices(&text).map_err(fail)?;
        let bytes = text.as_bytes();
        let options =
            tobj::LoadOptions { triangulate: false, single_index: false, ignore_points: true, ignore_lines: true };
        let mut rest: &[u8] = bytes;
        // Materials are not needed: a missing .mtl file is not an error.
        let (models, _) = tobj::load_obj_buf(&mut rest, &options, |_| Err(tobj::LoadError::OpenFileFailed))
            .map_err(|e| fail(obj::error(bytes, bytes.len() - rest.len(), e)))?;
        if polylines && models.iter().all(|m| m.mesh.indices.is_empty()) {
            return Err(fail("it has only polylines (`l` lines) and no faces: a line has no surface to render".into()));
        }
        let mut positions = Vec::new();
        let mut triangles = Vec::new();
        let (mut normals, mut normal_indices) = (Vec::new(), Vec::new());
        let (mut uvs, mut uv_indices) = (Vec::new(), Vec::new());
        let (mut all_normals, mut all_uvs) = (true, true);
        for model in &models {
            let m = &model.mesh;
            let (p0, n0, t0) = (positions.len() as u32, normals.len() as u32, uvs.len() as u32);
            positions.extend(m.positions.chunks_exact(3).map(|p| Vector::new(p[0], p[1], p[2])));
            normals.extend(m.normals.chunks_exact(3).map(|n| Vector::new(n[0], n[1], n[2])));
            uvs.extend(m.texcoords.chunks_exact(2).map(|t| [t[0], t[1]]));
            all_normals &= m.normal_indices.len() == m.indices.len();
            all_uvs &= m.texcoord_indices.len() == m.indices.len();
            let mut first = 0;
            // tobj leaves the arities empty when every face is a triangle.
            let arities: Vec<usize> = if m.face_arities.is_empty() {
                vec![3; m.indices.len() / 3]
            } else {
                m.face_arities.iter().map(|&a| a as usize).collect()
            };
            for arity in arities {
                let face = first..first + arity;
                first += arity;
                let corners: Vec<Vector> =
                    m.indices[face.clone()].iter().map(|&i| positions[(p0 + i) as usize]).collect();
                for t in polygon::triangulate(&corners) {
                    let pick = |idx: &[u32], base: u32| t.map(|k| idx[face.start + k] + base);
                    triangles.push(pick(&m.indices, p0));
                    if all_normals {
                        normal_indices.push(pick(&m.normal_indices, n0));
                    }
                    if all_uvs {
                        uv_indices.push(pick(&m.texcoord_indices, t0));
                    }
                }
            }
        }
        if positions.iter().any(|p| p.is_finite() && p.abs().max_element() as f64 > MAX_COORDINATE) {
            return Err(fail(too_far(&text)));
        }
        let has_normals = all_normals && !normals.is_empty();
        let normals = has_normals.then_some((&normals[..], &normal_indices[..]));
        let uvs = (all_uvs && !uvs.is_empty()).then_some((&uvs[..], &uv_indices[..]));
        let mesh = Mesh::from_parts(&positions, &triangles, normals, uvs).map_err(|e| fail(e.to_string()))?;
        Ok(mesh.with_faceted(!has_normals && !auto_smooth))
    }

    /// The same mesh shaded with its face normals (`true`) or smoothly (`false`).
    pub fn with_faceted(mut self, faceted: bool) -> Mesh {
        self.faceted = faceted;
        self
    }

    /// The same mesh, ignoring (`true`) or seeing (`false`) the triangles a ray meets from their back.
    pub fn with_backface_culling(mut self, culling: bool) -> Mesh {
        self.backface_culling = culling;
        self
    }

    /// The triangle in slot `i`.
    fn triangle(&self, i: usize) -> [Vector; 3] {
        self.triangles[i / LANES].get(i % LANES).expect("a hit slot holds a triangle")
    }

    /// Whether the triangle in slot `i` is ignored by a ray along `dir` (back-face culling).
    pub fn culled(&self, i: usize, dir: Vector) -> bool {
        self.backface_culling && face_normal(&self.triangle(i)).dot(dir) > 0.0
    }

    /// The number of triangles (after dropping degenerate ones).
    pub fn triangle_count(&self) -> usize {
        self.triangle_count
    }

    /// The triangles' vertices, in the order the BVH stores them.
    pub fn triangles(&self) -> Vec<[Vector; 3]> {
        self.triangles.iter().flat_map(|four| (0..LANES).filter_map(|lane| four.get(lane))).collect()
    }

    /// Every triangle with its slot, one by one, for a search that tests them all (the slide's,
    /// [`Mesh::hit_one_by_one`]).
    pub fn slots(&self) -> impl Iterator<Item = (usize, [Vector; 3])> + '_ {
        (0..self.triangles.len() * LANES).filter_map(|i| self.triangles[i / LANES].get(i % LANES).map(|t| (i, t)))
    }

    /// The acceleration structure (for the benchmark's report).
    pub fn bvh(&self) -> &Bvh {
        &self.bvh
    }

    /// The hit point, normals, u/v and error bound of a hit on triangle `i`.
    fn info(&self, i: usize, t: f32, b: [f32; 3]) -> IntersectionInfo {
        let tri = &self.triangle(i);
        let terms = [tri[0] * b[0], tri[1] * b[1], tri[2] * b[2]];
        let ip = terms[0] + terms[1] + terms[2];
        let error = gamma(7) * (terms[0].abs() + terms[1].abs() + terms[2].abs()).max_element();
        let face = face_normal(tri).normalize();
        let n = &self.normals[i];
        let smooth = (n[0] * b[0] + n[1] * b[1] + n[2] * b[2]).normalize_or_zero();
        let normal = if self.faceted || smooth == Vector::ZERO { face } else { smooth };
        let geometric_normal = if face.dot(normal) < 0.0 { -face } else { face };
        let (u, v) = match self.uvs.get(i) {
            Some(uv) => (
                uv[0][0] * b[0] + uv[1][0] * b[1] + uv[2][0] * b[2],
                uv[0][1] * b[0] + uv[1][1] * b[1] + uv[2][1] * b[2],
            ),
            None => (b[1], b[2]),
        };
        IntersectionInfo::new(ip, normal, t, (u, v)).with_geometric_normal(geometric_normal).with_error(error)
    }
}

impl Geometry for Mesh {
    fn intersect(&self, ray: &Ray, t_max: f32) -> Option<IntersectionInfo> {
        self.hit(ray, t_max).and_then(|hit| self.surface(ray, &hit))
    }

    /// The triangle and the barycentric coordinates of the hit; normals and u/v wait for the winner.
    fn hit(&self, ray: &Ray, t_max: f32) -> Option<Hit> {
        beyond!(MeshBvh);
        let sheared = ShearedRay::new(ray);
        let mut best = None;
        self.bvh.traverse(ray.start, ray.dir, t_max, |slots, t_max| {
            for group in slots.step_by(LANES) {
                let hits = sheared.hit(&self.triangles[group / LANES], *t_max);
                // The hits in lane order, each kept if still closer than the best so far: the same choice
                // as testing the triangles one by one.
                for lane in hits.lanes() {
                    if hits.before(lane, *t_max) && !self.culled(group + lane, ray.dir) {
                        let (t, coords) = hits.get(lane);
                        *t_max = t;
                        best = Some(Hit { distance: t, part: (group + lane) as u32, coords });
                    }
                }
            }
            false
        });
        best
    }

    fn surface(&self, _ray: &Ray, hit: &Hit) -> Option<IntersectionInfo> {
        Some(self.info(hit.part as usize, hit.distance, hit.coords))
    }

    fn intersects(&self, ray: &Ray, t_max: f32) -> bool {
        beyond!(MeshBvh);
        let sheared = ShearedRay::new(ray);
        let mut hit = false;
        self.bvh.traverse(ray.start, ray.dir, t_max, |slots, t_max| {
            hit = slots.step_by(LANES).any(|group| {
                let hits = sheared.hit(&self.triangles[group / LANES], *t_max);
                hits.lanes().any(|lane| !self.culled(group + lane, ray.dir))
            });
            hit
        });
        hit
    }

    fn bounds(&self) -> Option<Aabb> {
        self.bvh.bounds()
    }

    fn into_shape(self: Arc<Self>) -> Shape {
        Shape::Mesh { mesh: self, bvh: true }
    }
}
