//! [`SceneError`]: why a scene could not be loaded or built.

use core::fmt;

use clockwork2d::world::WorldError;

/// Why a scene could not be loaded or built.
#[derive(Clone, Debug, PartialEq)]
pub enum SceneError {
    /// The file could not be read.
    Io(String),
    /// The text is not a valid scene.
    Parse(String),
    /// A number that is NaN or infinite.
    NotFinite {
        /// Where (e.g. "body 3 position").
        what: String,
    },
    /// A value the scene format does not allow (e.g. a zero direction).
    Invalid {
        /// Where.
        what: String,
        /// Why.
        reason: &'static str,
    },
    /// More bodies than [`super::MAX_SCENE_BODIES`].
    TooManyBodies(u64),
    /// No built-in scene has this name and no such file exists.
    Unknown(String),
    /// A constraint names a body index the scene does not create.
    BadReference {
        /// Which constraint.
        what: String,
        /// The index given.
        index: u32,
        /// How many bodies the scene creates.
        bodies: usize,
    },
    /// The world refused a body or the settings.
    World {
        /// Which body ("body 3", "generator 1 body 17", "settings").
        what: String,
        /// Why.
        error: WorldError,
    },
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SceneError::Io(e) => write!(f, "cannot read scene: {e}"),
            SceneError::Parse(e) => write!(f, "invalid scene file: {e}"),
            SceneError::NotFinite { what } => write!(f, "{what}: number is not finite"),
            SceneError::Invalid { what, reason } => write!(f, "{what}: {reason}"),
            SceneError::TooManyBodies(n) => write!(
                f,
                "scene would create {n} bodies; at most {} are allowed",
                super::MAX_SCENE_BODIES
            ),
            SceneError::Unknown(name) => write!(
                f,
                "no built-in scene or file named {name:?} (built-in: {})",
                super::BUILTIN_SCENES
                    .iter()
                    .map(|(n, _)| *n)
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
            SceneError::BadReference {
                what,
                index,
                bodies,
            } => write!(
                f,
                "{what}: body index {index} does not exist (the scene creates {bodies} bodies, indices 0..{bodies})"
            ),
            SceneError::World { what, error } => write!(f, "{what}: {error}"),
        }
    }
}

impl std::error::Error for SceneError {}
