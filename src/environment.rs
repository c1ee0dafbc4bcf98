//! The environment (slides "Заден фон", "Интерфейс за заден фон"): what a ray that hits nothing sees. It
//! depends on the ray's direction only, never on where the ray starts.

use crate::color::Color;
use crate::math::Vector;

/// The course's `Environment` interface (`getEnvironment(dir)`).
pub trait Environment: Send + Sync {
    /// The colour seen in the unit direction `dir`.
    fn get(&self, dir: Vector) -> Color;
}

/// The same colour in every direction (a uniformly lit sky, useful for tests and energy checks).
#[derive(Clone, Copy, Debug)]
pub struct ConstantEnvironment(pub Color);

impl Environment for ConstantEnvironment {
    fn get(&self, _dir: Vector) -> Color {
        self.0
    }
}
