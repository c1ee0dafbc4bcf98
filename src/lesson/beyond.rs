//! The steps beyond the slides, by name. The default reading renders with them; `--slide`
//! ([`crate::lesson::slide`]) with none. Each is a unit of its own beside the slide's version, says in its
//! doc comment what it changes, is tested against the slide's version and measured in
//! docs/beyond-the-slides.md.
//!
//! Built with the feature `audit-steps`, every step records that it ran (`take_reached`); the test
//! `tests/slide_audit.rs` renders every example with `--slide` and checks that no step was reached. The
//! plain build compiles the records to nothing.

/// A step beyond the slides.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Step {
    /// Adaptive ray-tree depth control: a ray too weak to change its pixel is not traced
    /// ([`crate::lesson::scene::Scene::min_ray_weight`]).
    AdaptiveDepth,
    /// The two-phase nearest hit: the nearest hit found first, only the winner's surface described
    /// ([`crate::lesson::geometry::Geometry::hit`]).
    TwoPhaseHit,
    /// The BVH over a scene's nodes, and the tie rule for coincident faces ([`crate::lesson::node::NodeTree`]).
    NodeTree,
    /// A mesh's BVH with four-wide watertight triangle tests ([`crate::lesson::geometry::Mesh`]).
    MeshBvh,
    /// Texels read through [`crate::lesson::bitmap::Bitmap::sample`]: bilinear filtering and wrapping.
    TexelFilter,
    /// Stratified anti-aliasing samples: a jittered grid or N-rooks ([`crate::lesson::render::Stratifier`]).
    StratifiedAa,
    /// Stratified and joint points of the unit disc for glossy reflections ([`crate::lesson::sampling`]).
    DiscSamples,
    /// The workbook's glossy mirror: its disc samples and its split depth
    /// ([`crate::lesson::shader::GLOSSY_SPLIT_DEPTH`]).
    GlossySplit,
    /// Hero-wavelength and spectral sampling instead of K passes ([`crate::lesson::render`]).
    HeroWavelengths,
    /// The photon grid and its estimate ([`crate::lesson::photon_map`]).
    PhotonGrid,
    /// Photons aimed at the caustic casters along a Fibonacci lattice ([`crate::lesson::photon_map::Emitter`]).
    AimedEmission,
    /// The Layered shader from the top down, shading only the layers that show ([`crate::lesson::shader::Layered`]).
    LayerPruning,
    /// Rendering in coordinates relative to the camera
    /// ([`crate::lesson::scene::Scene::relative_to_camera`]).
    CameraRelative,
    /// The workbook's own shapes, shaders and textures called through an enum instead of a trait object
    /// ([`crate::lesson::dispatch`]), a student's type as one more case.
    StaticDispatch,
}

impl Step {
    /// Every step, in the order of the ledger.
    pub const ALL: [Step; 14] = [
        Step::AdaptiveDepth,
        Step::TwoPhaseHit,
        Step::NodeTree,
        Step::MeshBvh,
        Step::TexelFilter,
        Step::StratifiedAa,
        Step::DiscSamples,
        Step::GlossySplit,
        Step::HeroWavelengths,
        Step::PhotonGrid,
        Step::AimedEmission,
        Step::LayerPruning,
        Step::CameraRelative,
        Step::StaticDispatch,
    ];
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
    REACHED.fetch_or(1 << step as u32, std::sync::atomic::Ordering::Relaxed);
}

/// The steps that ran since the last call, and forgets them (feature `audit-steps`).
#[cfg(feature = "audit-steps")]
pub fn take_reached() -> Vec<Step> {
    let reached = REACHED.swap(0, std::sync::atomic::Ordering::Relaxed);
    Step::ALL.into_iter().filter(|&step| reached & (1 << step as u32) != 0).collect()
}
