//! Caustics by photon mapping (slides "Caustics", "Photon Mapping", "Пример за photon map").
//!
//! Before the picture is rendered, photons are shot from the point lights (the slide's "обратен
//! raytracing": rays that start at the lamps), followed through mirrors, glass and layered surfaces, and
//! stored where they land on a diffuse surface after at least one reflection or refraction: the *caustic*
//! photon map. When a diffuse shader shades a point it asks the map (through the light loop,
//! [`crate::lesson::light::light_loop`]), which finds the k nearest photons and turns their power into the
//! caustic light arriving there.
//!
//! The slide's map ([`all_directions`]): photons shot in all directions, the k nearest found in a k-d tree
//! ([`kd_tree`]), their power over the area of the disc that holds them. The step beyond it,
//! [`Step::PhotonGrid`], is the rest of this page: photons aimed at the casters, a grid, a cone filter.
//!
//! How a photon behaves at a surface is the shader's business: a mirror's or glass's
//! [`CausticCaster::scatter_photon`](crate::lesson::shader::CausticCaster::scatter_photon) returns a
//! [`PhotonScatter`](crate::lesson::shader::PhotonScatter): on a diffuse surface (Lambert, Phong) the photon lands; `Reflection`, `Refraction` and
//! `Layered` send it on, and the `Fresnel` texture takes part through a layer's blend.
//!
//! Where the step differs from the slides, and why:
//! - The slide shoots photons "in all directions". Here each light aims only at the caustic casters (objects
//!   whose shader can reflect or refract a photon): each caster's bounding sphere, seen from the light, is a
//!   cone of directions, and every cone gets a share of the photons in proportion to the power the light
//!   sends into it. A photon carries the light's intensity over the photon density of its direction (photons
//!   per steradian), summed over the cones that contain it, so no photon is wasted on the sky or on diffuse
//!   walls and where two cones overlap no light is counted twice. A scene without casters builds no map.
//! - Within a cone the directions are not independent random ones but a spherical Fibonacci lattice (shifted
//!   at random per seed): evenly spread photons give a smoother caustic for the same count.
//! - Only caustics are mapped: a photon that reaches a diffuse surface straight from the lamp is direct
//!   light, which the shadow rays already compute exactly.
//! - Russian roulette ends the paths: after a bounce a photon survives with probability equal to the largest
//!   channel of the bounce's colour and its power is divided by that, so photon powers stay even and the
//!   estimate stays unbiased. The scene's `MAX_RAY_DEPTH` limits photon bounces as it limits rays (and so
//!   does the renderer's safety cap, for scenes without a limit).
//! - The search structure (the slide asks for one with fast k-nearest-neighbour search) is a uniform grid of
//!   cubic cells a quarter of the maximum radius wide, the photons sorted cell by cell: every photon within
//!   a radius of a point lies in the rows of cells along x that the ball of that radius around it touches,
//!   each read from where the ball enters the row to where it leaves it, as one contiguous run. An estimate
//!   searches a ball of a quarter, then of half the maximum radius before the whole one, and stops at the
//!   first that holds k photons, which then are the k nearest: in a dense caustic the nearest are close, and
//!   most of the photons of the largest ball are never read. The photons found are gathered into a
//!   per-thread buffer and the k nearest selected in place, by one integer key per photon (distance, then
//!   index): no allocation per estimate. docs/beyond-the-slides.md compares it with the k-d tree.
//! - The estimate gathers the k nearest photons within a maximum radius and weights them with Jensen's cone
//!   filter ("Realistic Image Synthesis Using Photon Mapping", 2001, section 7.2.2). When fewer than k
//!   photons lie within the maximum radius, every photon in that disc was found, so the disc is the one
//!   of the maximum radius; otherwise it is the one through the farthest photon found.
//! - The course's diffuse shaders multiply their colour by *irradiance* (a light's intensity over the squared
//!   distance), so the map returns irradiance too: the photons' power per area. Lambert and Phong add it to
//!   the light of the lamps.
//! - The map is built in parallel, each photon with its own random stream seeded from (seed, its index), and
//!   stored in index order: the same picture for any number of threads.
//! - Chromatic caustics (the slide: "всеки да носи информация само за определена дължина на вълната"): in a
//!   scene with dispersive materials every photon gets a wavelength and the colour of its band of the
//!   spectrum (see [`crate::lesson::spectral::Band`]). Photons are [`Ray`](crate::lesson::ray::Ray)s, so the glass bends each by the index
//!   at its wavelength and the map holds coloured light. The estimate is already the sum over the spectrum,
//!   so the diffuse shaders add it in every wavelength pass: the passes' colours add up to the light's, and
//!   the caustic is counted once. Its sum of single-wavelength colours may lie outside the sRGB gamut; since
//!   light arriving at a surface cannot be negative, the estimate's negative channels are clipped (whatever
//!   `--gamut` says of the picture).

pub mod all_directions;
mod build;
mod emitter;
mod grid;
pub mod kd_tree;
mod progressive;

pub use build::{default_radius, min_radius};
pub use emitter::{Emitter, strength, trace_photons};
pub use progressive::{ALPHA, MAX_PHOTON_PASSES, pass_seed, radius_scale};

use crate::lesson::beyond::Step;
use crate::lesson::color::Color;
use crate::lesson::error::{Error, Result};
use crate::lesson::geometry::Aabb;
use crate::lesson::math::Vector;
use crate::lesson::spectral::clip_to_gamut;
use crate::lesson::topic::{PhotonSeen, Recorder, Topic, record};
use grid::{CELLS_PER_RADIUS, Found, PhotonGrid, SEARCH_FRACTIONS};
use kd_tree::KdTree;
use std::cell::RefCell;
use std::f32::consts::PI;
use std::num::NonZeroUsize;
use std::sync::Arc;
use std::time::{Duration, Instant};

/// Most photons a map may be asked for: 16 M photons already take about a gigabyte.
pub const MAX_PHOTONS: u32 = 1 << 24;
/// Most photons one estimate may gather.
pub const MAX_K: u32 = 10_000;
include!("cone_filter_k.rs");
/// `--show-photons`: the radius of a photon's dot, as a fraction of the estimate's maximum radius.
pub const DOT_RADIUS: f32 = 0.25;
/// `--show-photons`: the irradiance of a dot, enough to turn any surface that is not black white (or the
/// photon's colour).
const DOT_IRRADIANCE: f32 = 1000.0;
/// Chromatic caustics: the bands of the spectrum a photon's wavelength is drawn from (its colour is its
/// band's); narrow enough that a band's colour is that of its wavelengths.
pub const PHOTON_BANDS: u32 = 64;
/// Keeps the photons' random streams apart from the pixels' (pixel keys are below 2^32).
const PHOTON_STREAM: u64 = 0x5048_4f54_4f4e_5321;

/// How a scene's photon map is made and used. Scenes set their own; the command line overrides them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PhotonSettings {
    /// Photons emitted; 0 builds no map.
    pub count: u32,
    /// How many nearest photons an estimate gathers.
    pub k: u32,
    /// The largest distance from the shaded point at which photons count; `None` is 1/100 of the diagonal
    /// of the box around the scene's bounded objects.
    pub max_radius: Option<f32>,
    /// Draw the photons as dots instead of estimating caustics (the slide's picture of a photon map).
    pub show: bool,
}

impl Default for PhotonSettings {
    fn default() -> PhotonSettings {
        PhotonSettings { count: 0, k: 50, max_radius: None, show: false }
    }
}

impl PhotonSettings {
    /// Rejects counts and radii that make no sense.
    pub fn check(&self) -> Result<()> {
        if self.count > MAX_PHOTONS {
            return Err(Error::parameter("photon count", self.count, format!("at most {MAX_PHOTONS}")));
        }
        if !(1..=MAX_K).contains(&self.k) {
            return Err(Error::parameter("photon k", self.k, format!("must be between 1 and {MAX_K}")));
        }
        if let Some(r) = self.max_radius
            && !(r.is_finite() && r > 0.0)
        {
            return Err(Error::parameter("photon radius", r, "must be a positive number"));
        }
        Ok(())
    }
}

/// A photon stored where it landed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StoredPhoton {
    /// Where the photon landed on a diffuse surface, in world space.
    pub position: Vector,
    /// The unit direction it travelled in when it landed.
    pub dir: Vector,
    /// Its power (flux); the powers of all photons add up to the light that reached the diffuse surfaces.
    pub power: Color,
}

/// What building a map took.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PhotonStats {
    /// Photons shot from the lights.
    pub emitted: u32,
    /// Photons stored: those that reached a diffuse surface after at least one reflection or refraction.
    pub stored: usize,
    /// Emitting and tracing the photons.
    pub trace_time: Duration,
    /// Building the search structure (the k-d tree or the grid).
    pub build_time: Duration,
}

/// Where a map finds the photons near a point: the slide's k-d tree, or the grid of the step
/// [`Step::PhotonGrid`].
enum Lookup {
    KdTree(KdTree),
    Grid(PhotonGrid),
}

/// What makes a map the map of a later pass of a progressive caustic ([`progressive`]): the first pass's
/// map, which gives each point its r_1, and this pass's ratio r_i^2 / r_1^2.
struct Pass {
    first: Arc<PhotonMap>,
    area_scale: f32,
}

/// The caustic photon map: the stored photons in a k-d tree or a grid, and how estimates are made from them.
pub struct PhotonMap {
    photons: Vec<StoredPhoton>,
    lookup: Lookup,
    k: NonZeroUsize,
    max_radius: f32,
    show: bool,
    /// A later pass of a progressive caustic: its estimate gathers within its pass's radius.
    pass: Option<Pass>,
    /// What building the map took: photons emitted and stored, and the time spent.
    pub stats: PhotonStats,
}

thread_local! {
    /// The photons an estimate found, reused from estimate to estimate.
    static FOUND: RefCell<Vec<Found>> = const { RefCell::new(Vec::new()) };
}

impl PhotonMap {
    /// A map of the given photons: sorts them into the grid.
    pub fn new(photons: Vec<StoredPhoton>, k: u32, max_radius: f32, show: bool) -> Result<PhotonMap> {
        PhotonMap::with_lookup(photons, k, max_radius, show, true)
    }

    /// A map of the given photons in a grid (`grid`) or the slide's k-d tree.
    fn with_lookup(photons: Vec<StoredPhoton>, k: u32, max_radius: f32, show: bool, grid: bool) -> Result<PhotonMap> {
        let k = NonZeroUsize::new(k as usize).ok_or_else(|| Error::parameter("photon k", k, "must be at least 1"))?;
        let start = Instant::now();
        let lookup = match grid {
            true => Lookup::Grid(PhotonGrid::new(&photons, |photon| photon.position, max_radius)),
            false => Lookup::KdTree(KdTree::new(photons.iter().map(|photon| photon.position))),
        };
        let stats = PhotonStats { stored: photons.len(), build_time: start.elapsed(), ..PhotonStats::default() };
        Ok(PhotonMap { photons, lookup, k, max_radius, show, pass: None, stats })
    }

    /// The stored photons.
    pub fn photons(&self) -> &[StoredPhoton] {
        &self.photons
    }

    /// The caustic irradiance at the point `p` of a diffuse surface whose normal `n` faces the viewer
    /// (the slide's "K-те най-близки съседа"): the power of the k nearest photons within the maximum radius
    /// that arrived on this side of the surface, over the area of the disc through the farthest of them (the
    /// disc of the maximum radius when fewer than k lie within it); with the grid, weighted by the cone
    /// filter. With `--show-photons`, a bright dot where a photon lies instead.
    pub fn irradiance(&self, p: Vector, n: Vector) -> Color {
        self.irradiance_recorded(p, n, None)
    }

    /// [`PhotonMap::irradiance`], telling `recorder`, if given, the photons it found, k and the radius
    /// ([`Topic::Photons`]).
    pub fn irradiance_recorded(&self, p: Vector, n: Vector, recorder: Option<&mut dyn Recorder>) -> Color {
        if self.show {
            return self.dot(p);
        }
        let grid = match &self.lookup {
            Lookup::KdTree(tree) => return self.kd_tree_irradiance(tree, p, n, recorder),
            Lookup::Grid(grid) => grid,
        };
        beyond!(PhotonGrid);
        if let Some(pass) = &self.pass {
            return self.pass_irradiance(grid, pass, p, n, recorder);
        }
        FOUND.with_borrow_mut(|found| {
            let Some(r2) = self.nearest_disc(grid, p, found) else {
                return Color::BLACK;
            };
            exercise!(irradiance_estimate(&mut found.iter().map(|f| (f.d2(), &self.photons[f.index()])), r2, n));
            self.cone_filtered(found, n, r2, recorder)
        })
    }

    /// The k nearest photons to `p` within the maximum radius, left in `found`, and the squared radius of
    /// their disc: through the farthest of them, or the maximum radius when fewer than k lie within it.
    /// `None` when no photon lies within the maximum radius.
    fn nearest_disc(&self, grid: &PhotonGrid, p: Vector, found: &mut Vec<Found>) -> Option<f32> {
        let max_r2 = self.max_radius * self.max_radius;
        let k = self.k.get();
        // Where photons are dense (a caustic), the k nearest lie much closer than the maximum radius:
        // a smaller ball holding k photons holds the k nearest of the larger one (every photon outside
        // it is farther than every photon inside), so smaller balls are searched first, and the result
        // is the same as searching the largest at once.
        for fraction in SEARCH_FRACTIONS {
            grid.within(p, max_r2 * fraction * fraction, found);
            if found.len() >= k {
                break;
            }
        }
        if found.is_empty() {
            return None;
        }
        if found.len() < k {
            return Some(max_r2);
        }
        if found.len() > k {
            // The k nearest first (ties by photon index, so the choice is the same every time).
            found.select_nth_unstable(k - 1);
            found.truncate(k);
        }
        Some(found.iter().fold(0.0, |m, f| f.d2().max(m)))
    }

    /// The caustic irradiance of the photons `found` in the disc of squared radius `r2` at a point of normal
    /// `n`: those that arrived on the viewer's side, weighted by the cone filter of that disc, over its area.
    fn cone_filtered(&self, found: &[Found], n: Vector, r2: f32, recorder: Option<&mut dyn Recorder>) -> Color {
        let filter_radius = CONE_FILTER_K * r2.sqrt();
        let cone = |d2: f32| 1.0 - d2.sqrt() / filter_radius;
        let mut sum = Color::BLACK;
        for f in found.iter() {
            let (d2, photon) = (f.d2(), &self.photons[f.index()]);
            if photon.dir.dot(n) < 0.0 {
                sum += photon.power * cone(d2);
            }
        }
        let irradiance = arriving_light(sum / ((1.0 - 2.0 / (3.0 * CONE_FILTER_K)) * PI * r2));
        record(recorder, || self.topic(found.iter().map(|f| (f.d2(), f.index())).collect(), n, r2, cone));
        irradiance
    }

    /// What an estimate at a point of normal `n` found: the photons `found` (squared distance and index), each
    /// that arrived on the viewer's side counted `weight(d2)` times, in a disc of squared radius `r2`.
    fn topic(&self, found: Vec<(f32, usize)>, n: Vector, r2: f32, weight: impl Fn(f32) -> f32) -> Topic {
        let photons = found
            .into_iter()
            .map(|(d2, index)| {
                let (photon, distance) = (&self.photons[index], d2.sqrt());
                let weight = if photon.dir.dot(n) < 0.0 { weight(d2) } else { 0.0 };
                PhotonSeen { index, distance, power: photon.power, weight }
            })
            .collect();
        Topic::Photons { k: self.k.get(), radius: r2.sqrt(), max_radius: self.max_radius, photons }
    }

    /// The slide's estimate: the k nearest photons from the k-d tree, their power over the disc's area.
    fn kd_tree_irradiance(&self, tree: &KdTree, p: Vector, n: Vector, recorder: Option<&mut dyn Recorder>) -> Color {
        let (max_r2, k) = (self.max_radius * self.max_radius, self.k.get());
        let found = tree.nearest(p, k, max_r2);
        let r2 = if found.len() < k { max_r2 } else { found.iter().fold(0.0, |m, (d2, _)| d2.max(m)) };
        if found.is_empty() || r2 <= 0.0 {
            return Color::BLACK;
        }
        let mut sum = Color::BLACK;
        for &(_, i) in &found {
            let photon = &self.photons[i as usize];
            if photon.dir.dot(n) < 0.0 {
                sum += photon.power;
            }
        }
        let irradiance = arriving_light(sum / (PI * r2));
        record(recorder, || self.topic(found.iter().map(|&(d2, i)| (d2, i as usize)).collect(), n, r2, |_| 1.0));
        irradiance
    }

    /// `--show-photons`: a dot of the nearest photon's colour if one lies within the dot radius.
    fn dot(&self, p: Vector) -> Color {
        let dot_r2 = (DOT_RADIUS * self.max_radius).powi(2);
        let nearest = match &self.lookup {
            Lookup::KdTree(tree) => tree.nearest(p, 1, dot_r2).first().map(|&(_, i)| i as usize),
            Lookup::Grid(grid) => FOUND.with_borrow_mut(|found| {
                grid.within(p, dot_r2, found);
                found.iter().copied().min().map(Found::index)
            }),
        };
        let Some(nearest) = nearest else {
            return Color::BLACK;
        };
        let color = clip_to_gamut(self.photons[nearest].power);
        color * (DOT_IRRADIANCE / color.max_channel())
    }
}

/// The caustic light an estimate gives, from the photons' powers over the disc's area: photons of single
/// wavelengths carry colours outside the sRGB gamut, and so may their sum, but the light arriving at a
/// surface cannot be negative, so negative channels are clipped (whatever `--gamut` says of the picture).
/// Every estimate ends here: the map's own, the slides' reading's and a student's in the graded exercise.
pub fn arriving_light(estimate: Color) -> Color {
    clip_to_gamut(estimate)
}
