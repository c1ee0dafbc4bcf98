//! Caustics by photon mapping (slides "Caustics", "Photon Mapping", "Пример за photon map").
//!
//! Before the picture is rendered, photons are shot from the point lights (the slide's "обратен
//! raytracing": rays that start at the lamps), followed through mirrors, glass and layered surfaces, and
//! stored where they land on a diffuse surface after at least one reflection or refraction: the *caustic*
//! photon map. The stored photons go into a uniform grid. When a diffuse shader shades a point it asks the
//! map (through the light loop, [`crate::lesson::light::light_loop`]), which finds the k nearest photons
//! and turns their power into the caustic light arriving there.
//!
//! How a photon behaves at a surface is the shader's business: [`Shader::scatter_photon`] returns a
//! [`PhotonScatter`]: on a diffuse surface (Lambert, Phong) the photon lands; `Reflection`, `Refraction` and
//! `Layered` send it on, and the `Fresnel` texture takes part through a layer's blend.
//!
//! Where this differs from the slides, and why:
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
//!   index): no allocation per estimate, and measured faster than a k-d tree (kiddo's) on the workbook's
//!   scenes, whose estimates all use the same radius.
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
//!   spectrum. Photons are [`Ray`]s, so the glass bends each by the index at its wavelength and the map
//!   holds coloured light. The estimate is already the sum over the spectrum, so the diffuse shaders add it
//!   in every wavelength pass: the passes' colours add up to white, and the caustic is counted once.

use crate::lesson::color::Color;
use crate::lesson::error::{Error, Result};
use crate::lesson::geometry::Aabb;
use crate::lesson::math::{OrthonormalBasis, Vector, floor};
use crate::lesson::ray::Ray;
use crate::lesson::rng::Rng;
use crate::lesson::scene::{RECURSION_SAFETY_CAP, Scene};
use crate::lesson::spectral::{Band, bands, fit_to_gamut};
use rayon::prelude::*;
use std::cell::RefCell;
use std::f32::consts::PI;
use std::num::NonZeroUsize;
use std::time::{Duration, Instant};

#[cfg(doc)]
use crate::lesson::shader::Shader;

/// What a photon does where it hits a surface (see [`Shader::scatter_photon`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PhotonScatter {
    /// The surface is diffuse and the photon ends here. It is stored, its power multiplied by `scale`, if it
    /// was reflected or refracted on its way. `scale` is 1 except where a `Layered` shader chose this layer
    /// at random: then it is one over the probability of that choice.
    Land { scale: f32 },
    /// The photon goes on in the unit direction `dir`, its power multiplied by `filter`.
    Continue { dir: Vector, filter: Color },
    /// The photon is absorbed.
    Absorb,
}

/// Most photons a map may be asked for: 16 M photons already take about a gigabyte.
pub const MAX_PHOTONS: u32 = 1 << 24;
/// Most photons one estimate may gather.
pub const MAX_K: u32 = 10_000;
/// The cone filter's constant k >= 1 (Jensen's 1.1): the weight of a photon at distance d from the shaded
/// point, in a disc of radius r, is `1 - d / (CONE_FILTER_K * r)`.
pub const CONE_FILTER_K: f32 = 1.1;
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

/// The `--help` heading of the photon-mapping options (set per option: a heading set on the whole struct
/// would also cover the options that follow it in an example's own list).
const HEADING: &str = "Caustics (photon mapping)";

// The photon-mapping options every example accepts. (A plain comment, as on `cli::CommonArgs`: a doc comment
// here would become every example's `--help` description.)
#[derive(clap::Args, Clone, Debug, Default)]
pub struct PhotonArgs {
    /// Photons shot at the mirrors and glass for the caustic photon map; 0 renders without one.
    /// [default: the scene's own]
    #[arg(long, value_name = "N", help_heading = HEADING)]
    pub photons: Option<u32>,
    /// How many nearest photons each caustic estimate gathers. [default: the scene's own]
    #[arg(long, value_name = "K", help_heading = HEADING)]
    pub k: Option<u32>,
    /// The largest distance from a shaded point at which photons count. [default: the scene's own]
    #[arg(long, value_name = "R", help_heading = HEADING)]
    pub radius: Option<f32>,
    /// Draw each stored photon as a dot instead of estimating the caustic light from them.
    #[arg(long, help_heading = HEADING)]
    pub show_photons: bool,
}

impl PhotonArgs {
    /// The scene's photon settings with the options given on the command line.
    pub fn apply(&self, settings: &mut PhotonSettings) {
        settings.count = self.photons.unwrap_or(settings.count);
        settings.k = self.k.unwrap_or(settings.k);
        settings.max_radius = self.radius.or(settings.max_radius);
        settings.show |= self.show_photons;
    }
}

/// A photon stored where it landed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StoredPhoton {
    pub position: Vector,
    /// The unit direction it travelled in when it landed.
    pub dir: Vector,
    /// Its power (flux); the powers of all photons add up to the light that reached the diffuse surfaces.
    pub power: Color,
}

/// What building a map took.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct PhotonStats {
    pub emitted: u32,
    pub stored: usize,
    /// Emitting and tracing the photons.
    pub trace_time: Duration,
    /// Building the search structure (the grid).
    pub build_time: Duration,
}

/// The set of directions in which one light sees one caustic caster: the cone around its bounding sphere.
#[derive(Clone, Copy, Debug)]
struct Cone {
    light: usize,
    axis: OrthonormalBasis,
    /// 1 - cos of the half-angle, kept as such because the cone of a small, far caster is so narrow that
    /// the cosine itself rounds to 1.
    one_minus_cos: f32,
    solid_angle: f32,
    /// The power the light sends into the cone (the mean of its channels).
    power: f32,
    /// The photons emitted into it, numbered from `first`.
    first: u32,
    count: u32,
    /// A random shift of the cone's lattice, in [0, 1)^2, so that another seed gives other directions.
    shift: (f32, f32),
}

impl Cone {
    /// The cone from `light_pos` around the sphere (`center`, `radius`); all directions if the light is
    /// inside the sphere or the caster is unbounded (`None`).
    fn new(light: usize, light_pos: Vector, sphere: Option<(Vector, f32)>, intensity: f32) -> Cone {
        let (axis, one_minus_cos) = match sphere {
            Some((center, radius)) if (center - light_pos).length() > radius => {
                let d = (center - light_pos).length();
                let sin2 = (radius / d) * (radius / d);
                // 1 - cos = sin^2 / (1 + cos), without cancellation.
                (OrthonormalBasis::new((center - light_pos) / d), sin2 / (1.0 + (1.0 - sin2).sqrt()))
            }
            _ => (OrthonormalBasis::new(Vector::Y), 2.0),
        };
        let solid_angle = 2.0 * PI * one_minus_cos;
        Cone {
            light,
            axis,
            one_minus_cos,
            solid_angle,
            power: intensity * solid_angle,
            first: 0,
            count: 0,
            shift: (0.0, 0.0),
        }
    }

    /// Direction `j` of the cone's `count`: a spherical Fibonacci lattice, spread evenly over the cone's solid
    /// angle (equal steps of cos(theta), golden-ratio steps of the azimuth), shifted by `shift`. An even
    /// spread of photons gives a smoother caustic than independent random directions for the same count.
    fn direction(&self, j: u32) -> Vector {
        const GOLDEN: f64 = 0.618_033_988_749_894_8; // 1 / the golden ratio
        let t = ((j as f32 + self.shift.0) / self.count as f32) * self.one_minus_cos; // 1 - cos(theta)
        let cos = 1.0 - t;
        let sin = (t * (2.0 - t)).max(0.0).sqrt();
        let phi = 2.0 * PI * ((j as f64 * GOLDEN + self.shift.1 as f64).fract() as f32);
        self.axis.to_world(sin * phi.cos(), sin * phi.sin(), cos).normalize()
    }

    /// Whether the unit direction `dir` lies in the cone.
    fn contains(&self, dir: Vector) -> bool {
        // |dir - axis|^2 = 2 (1 - cos): no cancellation for narrow cones.
        0.5 * (dir - self.axis.normal).length_squared() <= self.one_minus_cos
    }
}

/// How much light a colour carries, for sharing photons between cones and choosing between layers: the mean
/// of its channels.
pub fn strength(c: Color) -> f32 {
    (c.r() + c.g() + c.b()) / 3.0
}

/// Where the photons come from: every (light, caustic caster) cone gets a share of the photons in
/// proportion to the power the light sends into it.
#[derive(Clone, Debug)]
pub struct Emitter {
    cones: Vec<Cone>,
    /// For a scene with dispersive materials, the bands of the photons' wavelengths; empty for white light.
    bands: Vec<Band>,
}

impl Emitter {
    /// The emitter of `count` photons for a scene, or `None` when nothing can make a caustic: no caster, or
    /// no light.
    pub fn new(scene: &Scene, count: u32, seed: u64) -> Option<Emitter> {
        let spheres: Vec<Option<(Vector, f32)>> = scene
            .nodes
            .iter()
            .filter(|node| node.shader.casts_caustics())
            .map(|node| node.bounds().map(|b| (b.center(), 0.5 * (b.max - b.min).length())))
            .collect();
        let mut cones = Vec::new();
        for (i, light) in scene.lights.iter().enumerate() {
            let intensity = strength(light.color) * light.intensity;
            if !(intensity > 0.0 && intensity.is_finite()) {
                continue;
            }
            cones.extend(spheres.iter().map(|&sphere| Cone::new(i, light.position, sphere, intensity)));
        }
        // A caster too small to see from the light (its cone's solid angle rounds to 0) gets no photons.
        cones.retain(|c| c.power > 0.0);
        if cones.is_empty() {
            return None;
        }
        let total: f64 = cones.iter().map(|c| c.power as f64).sum();
        // Each cone's share, rounded so that the shares add up to `count` (largest remainders).
        let exact: Vec<f64> = cones.iter().map(|c| c.power as f64 / total * count as f64).collect();
        let mut counts: Vec<u32> = exact.iter().map(|&e| e.floor() as u32).collect();
        let mut by_remainder: Vec<usize> = (0..cones.len()).collect();
        by_remainder.sort_by(|&a, &b| (exact[b] - exact[b].floor()).total_cmp(&(exact[a] - exact[a].floor())));
        let missing = count - counts.iter().sum::<u32>();
        by_remainder.iter().take(missing as usize).for_each(|&i| counts[i] += 1);
        let mut first = 0;
        for (k, (cone, n)) in cones.iter_mut().zip(counts).enumerate() {
            let mut rng = Rng::for_keys(&[seed, PHOTON_STREAM, u64::MAX - k as u64]);
            (cone.first, cone.count, cone.shift) = (first, n, (rng.next_f32(), rng.next_f32()));
            first += n;
        }
        let bands = if scene.is_dispersive() { bands(PHOTON_BANDS) } else { Vec::new() };
        Some(Emitter { cones, bands })
    }

    /// Photon number `index`: its ray from the light and its power. In a dispersive scene the photon gets a
    /// wavelength in one of the [`PHOTON_BANDS`] bands of the visible range, and carries the colour of its
    /// band times the number of bands, so that together the photons are as white as the light.
    fn emit(&self, scene: &Scene, index: u32, rng: &mut Rng) -> (Ray, Color) {
        let chosen = self.cones.partition_point(|c| c.first + c.count <= index);
        let cone = &self.cones[chosen];
        let dir = cone.direction(index - cone.first);
        // The light's intensity over the photon density in this direction, summed over all the light's
        // cones that contain it (cones may overlap; each photon then carries its share of the light once).
        let density = self
            .cones
            .iter()
            .enumerate()
            .filter(|&(j, c)| c.light == cone.light && (j == chosen || c.contains(dir)))
            .map(|(_, c)| c.count as f32 / c.solid_angle)
            .sum::<f32>();
        let light = &scene.lights[cone.light];
        let power = light.color * (light.intensity / density);
        if self.bands.is_empty() {
            return (Ray::new(light.position, dir), power);
        }
        // The bands are equal parts of the visible range. Photon j of a cone takes band j mod the number of
        // bands (shifted per cone), so every band gets its share of each cone's photons, evenly spread over
        // the cone, and a uniformly random wavelength within the band.
        let k = self.bands.len() as u32;
        let band = &self.bands[((index - cone.first + (cone.shift.0 * k as f32) as u32) % k) as usize];
        let ray = Ray { wavelength: Some(band.at(rng.next_f32())), ..Ray::new(light.position, dir) };
        (ray, power * band.color() * self.bands.len() as f32)
    }

    /// The photons emitted in all.
    pub fn count(&self) -> u32 {
        self.cones.iter().map(|c| c.count).sum()
    }
}

/// Follows photon number `index` from its light until it lands, is absorbed or leaves the scene; the photon
/// as stored, if it landed on a diffuse surface after a reflection or refraction.
fn trace_photon(scene: &Scene, emitter: &Emitter, seed: u64, index: u32) -> Option<StoredPhoton> {
    let mut rng = Rng::for_keys(&[seed, PHOTON_STREAM, index as u64]);
    let (mut ray, mut power) = emitter.emit(scene, index, &mut rng);
    loop {
        if ray.depth > scene.max_depth.min(RECURSION_SAFETY_CAP) {
            return None;
        }
        let (info, node) = scene.closest_hit(&ray)?;
        match node.shader.scatter_photon(&ray, &info, &mut rng) {
            PhotonScatter::Land { scale } => {
                return (ray.depth > 0).then(|| StoredPhoton { position: info.ip, dir: ray.dir, power: power * scale });
            }
            PhotonScatter::Continue { dir, filter } => {
                // Russian roulette.
                let survival = filter.max_channel().min(1.0);
                if survival.is_nan() || rng.next_f32() >= survival {
                    return None;
                }
                power = power * filter / survival;
                ray = ray.spawn(&info, dir, filter.max_channel());
            }
            PhotonScatter::Absorb => return None,
        }
    }
}

/// Emits the emitter's photons and traces them in parallel (on the current rayon pool); the stored ones, in
/// the order of their indices whatever the number of threads.
pub fn trace_photons(scene: &Scene, emitter: &Emitter, seed: u64) -> Vec<StoredPhoton> {
    (0..emitter.count()).into_par_iter().filter_map(|i| trace_photon(scene, emitter, seed, i)).collect()
}

/// The caustic photon map: the stored photons in a grid, and how estimates are made from them.
pub struct PhotonMap {
    photons: Vec<StoredPhoton>,
    grid: PhotonGrid,
    k: NonZeroUsize,
    max_radius: f32,
    show: bool,
    pub stats: PhotonStats,
}

impl std::fmt::Debug for PhotonMap {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("PhotonMap")
            .field("stats", &self.stats)
            .field("k", &self.k)
            .field("max_radius", &self.max_radius)
            .field("show", &self.show)
            .finish_non_exhaustive()
    }
}

thread_local! {
    /// The photons an estimate found, reused from estimate to estimate.
    static FOUND: RefCell<Vec<Found>> = const { RefCell::new(Vec::new()) };
}

/// The radii, as fractions of the maximum radius, of the balls an estimate searches for its k nearest
/// photons, smallest first (the last is the maximum radius itself). Measured on `photon_map`, whose caustic
/// is dense: 14% less CPU time for the whole render than searching the maximum radius at once.
const SEARCH_FRACTIONS: [f32; 3] = [0.25, 0.5, 1.0];

/// A photon an estimate found: its squared distance from the point and its index, in one integer ordered
/// by the distance first and by the index among photons at the same distance (the order of a non-negative
/// float's bits is that of its values), so that choosing the k nearest compares integers and is the same
/// every time.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
struct Found(u64);

impl Found {
    fn new(d2: f32, index: u32) -> Found {
        debug_assert!(d2 >= 0.0);
        Found(((d2.to_bits() as u64) << 32) | index as u64)
    }
    fn d2(self) -> f32 {
        f32::from_bits((self.0 >> 32) as u32)
    }
    fn index(self) -> usize {
        self.0 as u32 as usize
    }
}

impl PhotonMap {
    /// Builds the scene's photon map as its `photons` settings say, on the current rayon pool; `None` when
    /// the settings ask for no photons or the scene has nothing that casts caustics.
    pub fn build(scene: &Scene, seed: u64) -> Result<Option<PhotonMap>> {
        let settings = scene.photons;
        settings.check()?;
        if settings.count == 0 {
            return Ok(None);
        }
        let Some(emitter) = Emitter::new(scene, settings.count, seed) else {
            return Ok(None);
        };
        let start = Instant::now();
        let photons = trace_photons(&scene.with_node_tree(), &emitter, seed);
        let trace_time = start.elapsed();
        let max_radius = settings.max_radius.unwrap_or_else(|| default_radius(scene, &photons));
        let mut map = PhotonMap::new(photons, settings.k, max_radius, settings.show)?;
        map.stats.emitted = settings.count;
        map.stats.trace_time = trace_time;
        Ok(Some(map))
    }

    /// A map of the given photons: sorts them into the grid.
    pub fn new(photons: Vec<StoredPhoton>, k: u32, max_radius: f32, show: bool) -> Result<PhotonMap> {
        let k = NonZeroUsize::new(k as usize).ok_or_else(|| Error::parameter("photon k", k, "must be at least 1"))?;
        let start = Instant::now();
        let grid = PhotonGrid::new(&photons, max_radius);
        let stats = PhotonStats { stored: photons.len(), build_time: start.elapsed(), ..PhotonStats::default() };
        Ok(PhotonMap { photons, grid, k, max_radius, show, stats })
    }

    pub fn photons(&self) -> &[StoredPhoton] {
        &self.photons
    }

    /// The caustic irradiance at the point `p` of a diffuse surface whose normal `n` faces the viewer
    /// (the slide's "K-те най-близки съседа"): the power of the k nearest photons within the maximum radius
    /// that arrived on this side of the surface, weighted by the cone filter, over the disc's area. With
    /// `--show-photons`, a bright dot where a photon lies instead.
    pub fn irradiance(&self, p: Vector, n: Vector) -> Color {
        if self.show {
            return self.dot(p);
        }
        let max_r2 = self.max_radius * self.max_radius;
        let k = self.k.get();
        FOUND.with_borrow_mut(|found| {
            // Where photons are dense (a caustic), the k nearest lie much closer than the maximum radius:
            // a smaller ball holding k photons holds the k nearest of the larger one (every photon outside
            // it is farther than every photon inside), so smaller balls are searched first, and the result
            // is the same as searching the largest at once.
            for fraction in SEARCH_FRACTIONS {
                self.grid.within(p, max_r2 * fraction * fraction, found);
                if found.len() >= k {
                    break;
                }
            }
            if found.is_empty() {
                return Color::BLACK;
            }
            let r2 = if found.len() < k {
                max_r2
            } else {
                if found.len() > k {
                    // The k nearest first (ties by photon index, so the choice is the same every time).
                    found.select_nth_unstable(k - 1);
                    found.truncate(k);
                }
                found.iter().fold(0.0, |m, f| f.d2().max(m))
            };
            let filter_radius = CONE_FILTER_K * r2.sqrt();
            let mut sum = Color::BLACK;
            for f in found.iter() {
                let (d2, photon) = (f.d2(), &self.photons[f.index()]);
                if photon.dir.dot(n) < 0.0 {
                    sum += photon.power * (1.0 - d2.sqrt() / filter_radius);
                }
            }
            // Photons of single wavelengths carry colours outside the sRGB gamut; their sum is brought back
            // to it.
            fit_to_gamut(sum / ((1.0 - 2.0 / (3.0 * CONE_FILTER_K)) * PI * r2))
        })
    }

    /// `--show-photons`: a dot of the nearest photon's colour if one lies within the dot radius.
    fn dot(&self, p: Vector) -> Color {
        let dot_radius = DOT_RADIUS * self.max_radius;
        let nearest = FOUND.with_borrow_mut(|found| {
            self.grid.within(p, dot_radius * dot_radius, found);
            found.iter().copied().min()
        });
        let Some(nearest) = nearest else {
            return Color::BLACK;
        };
        let color = fit_to_gamut(self.photons[nearest.index()].power);
        color * (DOT_IRRADIANCE / color.max_channel())
    }
}

/// The photons sorted into a uniform grid of cubic cells, [`CELLS_PER_RADIUS`] to `max_radius` (or fewer,
/// see [`CELLS_PER_PHOTON`]; see the module documentation). Cell (x, y, z) is number `x + nx * (y + ny * z)`, so a row of cells along x is one run.
struct PhotonGrid {
    origin: Vector,
    /// The cells' width, and one over it.
    cell: f32,
    inv_cell: f32,
    dims: [usize; 3],
    /// The photons of cell c are `entries[starts[c] .. starts[c + 1]]`.
    starts: Vec<u32>,
    /// Each photon's position and index, cell by cell (in index order within a cell).
    entries: Vec<([f32; 3], u32)>,
}

/// At most this many cells per photon: a radius small against the photons' spread widens the cells
/// instead of allocating an empty grid of millions of cells.
const CELLS_PER_PHOTON: f32 = 2.0;

/// Cells across the maximum radius: the smallest ball an estimate searches (see [`SEARCH_FRACTIONS`]) is
/// then a cell wide, and larger balls read few photons outside them.
const CELLS_PER_RADIUS: f32 = 4.0;

impl PhotonGrid {
    fn new(photons: &[StoredPhoton], max_radius: f32) -> PhotonGrid {
        let bounds = Aabb::from_points(photons.iter().map(|p| p.position));
        let extent = if photons.is_empty() { Vector::ZERO } else { bounds.max - bounds.min };
        let max_cells = (CELLS_PER_PHOTON * photons.len() as f32).max(1.0);
        // A zero radius finds only photons at the point itself, with cells of any width.
        let mut cell = if max_radius > 0.0 { max_radius / CELLS_PER_RADIUS } else { f32::MIN_POSITIVE };
        let dims = loop {
            let dims = [0, 1, 2].map(|k| (extent[k] / cell) as usize + 1);
            let cells = dims.iter().map(|&d| d as f32).product::<f32>();
            if cells <= max_cells {
                break dims;
            }
            cell *= (cells / max_cells).cbrt().max(1.0 + f32::EPSILON.sqrt());
        };
        let origin = if photons.is_empty() { Vector::ZERO } else { bounds.min };
        let mut grid = PhotonGrid { origin, cell, inv_cell: 1.0 / cell, dims, starts: Vec::new(), entries: Vec::new() };
        // A counting sort of the photons by cell.
        let cell_of: Vec<usize> = photons
            .iter()
            .map(|p| {
                let [x, y, z] = grid.coords(p.position).map(|c| c.clamp(0, i64::MAX) as usize);
                grid.index(x.min(dims[0] - 1), y.min(dims[1] - 1), z.min(dims[2] - 1))
            })
            .collect();
        let mut starts = vec![0u32; dims[0] * dims[1] * dims[2] + 1];
        for &c in &cell_of {
            starts[c + 1] += 1;
        }
        for c in 1..starts.len() {
            starts[c] += starts[c - 1];
        }
        let mut next = starts.clone();
        let mut entries = vec![([0.0; 3], 0); photons.len()];
        for (i, (photon, &c)) in photons.iter().zip(&cell_of).enumerate() {
            entries[next[c] as usize] = (photon.position.to_array(), i as u32);
            next[c] += 1;
        }
        grid.starts = starts;
        grid.entries = entries;
        grid
    }

    /// The cell coordinates of a point (outside the grid: below 0 or at or above `dims`).
    fn coords(&self, p: Vector) -> [i64; 3] {
        let c = (p - self.origin) * self.inv_cell;
        [c.x, c.y, c.z].map(|v| floor(v) as i64)
    }

    /// The cell coordinate along axis `k` of a point whose coordinate there is `v` (as in `coords`).
    fn coord(&self, k: usize, v: f32) -> i64 {
        floor((v - self.origin[k]) * self.inv_cell) as i64
    }

    fn index(&self, x: usize, y: usize, z: usize) -> usize {
        x + self.dims[0] * (y + self.dims[1] * z)
    }

    /// Replaces the contents of `found` by the photons within squared distance `r2` of `p` (up to the
    /// rounding of the cells' boundaries).
    fn within(&self, p: Vector, r2: f32, found: &mut Vec<Found>) {
        found.clear();
        if !p.is_finite() {
            return;
        }
        let r = r2.sqrt();
        let (low, high) = (self.coords(p - r), self.coords(p + r));
        // The cells the box of radius r around the point touches, clipped to the grid; none when the box
        // lies outside it.
        let clip = |k: usize, from: i64, to: i64| from.max(0)..=to.min(self.dims[k] as i64 - 1);
        let q = p.to_array();
        // How far the point is from the slab of cells number c along axis k (0 inside it).
        let gap = |k: usize, c: i64| {
            let start = self.origin[k] + c as f32 * self.cell;
            (start - q[k]).max(q[k] - (start + self.cell)).max(0.0)
        };
        for z in clip(2, low[2], high[2]) {
            let dz2 = gap(2, z).powi(2);
            for y in clip(1, low[1], high[1]) {
                // The ball meets this row of cells along x where x is within `half` of the point's.
                let rest = r2 - dz2 - gap(1, y).powi(2);
                if rest < 0.0 {
                    continue;
                }
                let half = rest.sqrt();
                let xs = clip(0, self.coord(0, q[0] - half), self.coord(0, q[0] + half));
                if xs.is_empty() {
                    continue;
                }
                let first = self.starts[self.index(*xs.start() as usize, y as usize, z as usize)] as usize;
                let end = self.starts[self.index(*xs.end() as usize, y as usize, z as usize) + 1] as usize;
                for &(pos, i) in &self.entries[first..end] {
                    let d2 = (pos[0] - q[0]).powi(2) + (pos[1] - q[1]).powi(2) + (pos[2] - q[2]).powi(2);
                    if d2 <= r2 {
                        found.push(Found::new(d2, i));
                    }
                }
            }
        }
    }
}

/// The default maximum radius: 1/100 of the diagonal of the box around the scene's bounded objects (or, if
/// none is bounded, around the photons).
pub fn default_radius(scene: &Scene, photons: &[StoredPhoton]) -> f32 {
    let corners: Vec<Vector> = scene.nodes.iter().filter_map(|n| n.bounds()).flat_map(|b| [b.min, b.max]).collect();
    let bounds = if corners.is_empty() {
        Aabb::from_points(photons.iter().map(|p| p.position))
    } else {
        Aabb::from_points(corners)
    };
    let diagonal = (bounds.max - bounds.min).length();
    // A box of no size holds at most one point: any radius finds it.
    if diagonal.is_finite() && diagonal > 0.0 { diagonal / 100.0 } else { 1.0 }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The grid finds exactly the photons a scan of all of them finds, for radii up to the one it was
    /// built for, points inside, at the edge of and outside the photons' box, and photons on a surface
    /// (a plane, as on the workbook's floors) as well as in a volume.
    #[test]
    fn the_grid_finds_what_a_scan_of_every_photon_finds() {
        let mut rng = Rng::for_keys(&[7]);
        let mut random = |scale: f32| (rng.next_f32() - 0.5) * scale;
        for flat in [true, false] {
            let photons: Vec<StoredPhoton> = (0..3000)
                .map(|_| StoredPhoton {
                    position: Vector::new(random(20.0), if flat { 1.0 } else { random(20.0) }, random(20.0)),
                    dir: Vector::NEG_Y,
                    power: Color::WHITE,
                })
                .collect();
            let max_radius = 1.5;
            let grid = PhotonGrid::new(&photons, max_radius);
            let mut found = Vec::new();
            for _ in 0..300 {
                let p = Vector::new(random(26.0), if flat { 1.0 + random(4.0) } else { random(26.0) }, random(26.0));
                let r2 = (max_radius * (0.2 + random(1.6).abs())).powi(2);
                grid.within(p, r2, &mut found);
                found.sort();
                let mut scan: Vec<Found> = (0..photons.len())
                    .filter_map(|i| {
                        let d = photons[i].position - p;
                        let d2 = d.x.powi(2) + d.y.powi(2) + d.z.powi(2);
                        (d2 <= r2).then(|| Found::new(d2, i as u32))
                    })
                    .collect();
                scan.sort();
                assert_eq!(found, scan, "around {p} within {}", r2.sqrt());
            }
        }
    }

    #[test]
    fn found_photons_order_by_distance_then_index() {
        let mut v = [Found::new(2.0, 1), Found::new(0.5, 9), Found::new(2.0, 0), Found::new(0.0, 5)];
        v.sort();
        assert_eq!(v.iter().map(|f| (f.d2(), f.index())).collect::<Vec<_>>(), [(0.0, 5), (0.5, 9), (2.0, 0), (2.0, 1)]);
    }
}
