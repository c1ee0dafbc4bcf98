//! The steps beyond the slides, by name, and which of them a render takes ([`Steps`], the scene's
//! [`steps`](crate::lesson::scene::Scene::steps)).
//!
//! One renderer serves both readings. Each step is a setting whose first choice is the slide's: the slide's
//! version of a technique is the plain code in that technique's own file, and the step is one call beside
//! it, taken when the scene's `steps` hold it. `--slide` renders with [`Steps::SLIDES`] (none of them), the
//! default with [`Steps::ALL`]; `--step NAME` adds one to `--slide` and `--no-step NAME` takes one from the
//! default, so a teacher can show them one at a time. docs/beyond-the-slides.md measures each.
//!
//! What is not a step holds in both readings: the recursion's safety cap and the branching bound
//! ([`crate::lesson::branching`]), the end-of-run report ([`crate::lesson::diagnostics`]), the robust ray
//! offsets ([`crate::lesson::ray::Ray::spawn`]), the progress line and the refusals of impossible settings.
//!
//! Built with the feature `audit-steps`, every step records that it ran (`take_reached`); the test
//! `tests/slide_audit.rs` renders every example with `--slide` and checks that no step was reached. The
//! plain build compiles the records to nothing.

/// A step beyond the slides.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Step {
    /// Adaptive ray-tree depth control: a ray too weak to change its pixel is not traced
    /// ([`crate::lesson::scene::Scene::min_ray_weight`]). The slide's: every ray down to `MAX_RAY_DEPTH`.
    AdaptiveDepth,
    /// The two-phase nearest hit: the nearest hit found first, only the winner's surface described
    /// ([`crate::lesson::geometry::Geometry::hit`]). The slide's: every node's full `intersect`.
    TwoPhaseHit,
    /// The BVH over a scene's nodes, and the tie rule for coincident faces ([`crate::lesson::node::NodeTree`]).
    /// The slide's: the loop over the nodes.
    NodeTree,
    /// A mesh's BVH with four-wide watertight triangle tests ([`crate::lesson::geometry::Mesh`]). The slide's:
    /// the mesh's box, then its triangles one by one.
    MeshBvh,
    /// Texels read through each texture's own filter, bilinear by default
    /// ([`crate::lesson::bitmap::Bitmap::sample`]). The slide's: the one texel a point falls in.
    TexelFilter,
    /// Stratified anti-aliasing samples: a jittered grid or N-rooks ([`crate::lesson::render::Stratifier`]).
    /// The slide's: random points of the pixel.
    StratifiedAa,
    /// Stratified and joint points of the unit disc for glossy reflections, each mirror's own sampler
    /// ([`crate::lesson::sampling`]). The slide's: random points of the disc.
    DiscSamples,
    /// Hero-wavelength and spectral sampling instead of K passes ([`crate::lesson::render`]). The slide's: K
    /// wavelength passes.
    HeroWavelengths,
    /// Photons aimed at the caustic casters along a Fibonacci lattice, ended by Russian roulette, and stored in
    /// a grid whose estimate is cone-filtered ([`crate::lesson::photon_map`]). The slide's: photons in all
    /// directions, the k nearest from a k-d tree ([`crate::lesson::photon_map::kd_tree`]).
    PhotonGrid,
    /// The Layered shader from the top down, shading only the layers that show
    /// ([`crate::lesson::shader::Layered`]). The slide's: every layer, bottom to top.
    LayerPruning,
    /// Rendering in coordinates relative to the camera
    /// ([`crate::lesson::scene::Scene::relative_to_camera`]). The slide's: world coordinates.
    CameraRelative,
}

impl Step {
    /// Every step, in the order of the ledger.
    pub const ALL: [Step; 11] = [
        Step::AdaptiveDepth,
        Step::TwoPhaseHit,
        Step::NodeTree,
        Step::MeshBvh,
        Step::TexelFilter,
        Step::StratifiedAa,
        Step::DiscSamples,
        Step::HeroWavelengths,
        Step::PhotonGrid,
        Step::LayerPruning,
        Step::CameraRelative,
    ];

    /// The step's name on the command line (`--step`, `--no-step`) and in the ledger.
    pub fn name(self) -> &'static str {
        match self {
            Step::AdaptiveDepth => "adaptive-depth",
            Step::TwoPhaseHit => "two-phase-hit",
            Step::NodeTree => "node-bvh",
            Step::MeshBvh => "mesh-bvh",
            Step::TexelFilter => "texel-filter",
            Step::StratifiedAa => "stratified-pixels",
            Step::DiscSamples => "disc-samples",
            Step::HeroWavelengths => "hero-wavelengths",
            Step::PhotonGrid => "photon-grid",
            Step::LayerPruning => "layer-pruning",
            Step::CameraRelative => "camera-relative",
        }
    }

    /// What the step does, in one line (the command line's help, the ledger).
    pub fn summary(self) -> &'static str {
        match self {
            Step::AdaptiveDepth => "a ray too weak to change its pixel is not traced (--exhaustive leaves it out)",
            Step::TwoPhaseHit => "the nearest hit first, only the winner's surface described",
            Step::NodeTree => "a BVH over the scene's nodes (above 8 nodes)",
            Step::MeshBvh => "a mesh's BVH with four-wide triangle tests, not its triangles one by one",
            Step::TexelFilter => "each texture's own filter (bilinear by default), not one texel",
            Step::StratifiedAa => "stratified anti-aliasing samples, not random points of the pixel",
            Step::DiscSamples => "each glossy mirror's own disc sampler (joint by default), not random points",
            Step::HeroWavelengths => "hero-wavelength or spectral sampling (--spectral), not K passes",
            Step::PhotonGrid => {
                "photons aimed at the casters, in a grid, cone-filtered: not in all directions and a k-d tree"
            }
            Step::LayerPruning => "Layered shaders shade only the layers that show, from the top down",
            Step::CameraRelative => "a scene far from the origin is rendered relative to the camera",
        }
    }

    const fn bit(self) -> u32 {
        1 << self as u32
    }
}

/// Which steps beyond the slides a render takes: a set of [`Step`]s. The default is every step.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Steps(u32);

impl Steps {
    /// The slides' reading (`--slide`): no step beyond the slides.
    pub const SLIDES: Steps = Steps(0);
    /// The default reading: every step.
    pub const ALL: Steps = Steps((1 << Step::ALL.len()) - 1);

    /// Whether the render takes `step`.
    #[inline(always)]
    pub const fn has(self, step: Step) -> bool {
        self.0 & step.bit() != 0
    }

    /// These steps and `step`.
    pub const fn with(self, step: Step) -> Steps {
        Steps(self.0 | step.bit())
    }

    /// These steps without `step`.
    pub const fn without(self, step: Step) -> Steps {
        Steps(self.0 & !step.bit())
    }

    /// The steps taken, in the order of the ledger.
    pub fn iter(self) -> impl Iterator<Item = Step> {
        Step::ALL.into_iter().filter(move |&step| self.has(step))
    }
}

impl Default for Steps {
    fn default() -> Steps {
        Steps::ALL
    }
}

/// `beyond!(Step)`: records, in a build with the feature `audit-steps`, that the step ran; nothing at all
/// in the plain build.
macro_rules! beyond {
    ($step:ident) => {
        #[cfg(feature = "audit-steps")]
        $crate::lesson::beyond::record($crate::lesson::beyond::Step::$step);
    };
}

#[cfg(feature = "audit-steps")]
static REACHED: std::sync::atomic::AtomicU32 = std::sync::atomic::AtomicU32::new(0);

/// Records that `step` ran (feature `audit-steps`).
#[cfg(feature = "audit-steps")]
pub fn record(step: Step) {
    REACHED.fetch_or(step.bit(), std::sync::atomic::Ordering::Relaxed);
}

/// The steps that ran since the last call, and forgets them (feature `audit-steps`).
#[cfg(feature = "audit-steps")]
pub fn take_reached() -> Vec<Step> {
    let reached = REACHED.swap(0, std::sync::atomic::Ordering::Relaxed);
    Steps(reached).iter().collect()
}
