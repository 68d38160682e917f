//! The edge between the page's numbers (JavaScript doubles) and the
//! engine's fixed point, and the one error type the page sees.

use core::fmt;

use clockwork2d::prelude::{Fx, Vec2, WorldError};
use clockwork2d_scene::SceneError;
use wasm_bindgen::JsValue;

/// Why the playground refused a request. The world is unchanged after any
/// of them. In the browser it arrives as a thrown string (its `Display`).
#[derive(Clone, Debug, PartialEq)]
pub enum PlaygroundError {
    /// A number from the page is NaN or infinite.
    NotFinite {
        /// Which argument.
        what: &'static str,
    },
    /// A number from the page does not fit the fixed-point range (±2³¹).
    OutOfRange {
        /// Which argument.
        what: &'static str,
        /// The number given.
        value: f64,
    },
    /// No built-in scene (nor the grapple arena) has this name.
    UnknownScene(String),
    /// A drop shape other than `"ball"` or `"box"`.
    UnknownShape(String),
    /// The grapple controls were used outside the grapple arena.
    NotGrapple,
    /// The scene failed to build.
    Scene(SceneError),
    /// The engine refused the command (for example a body outside the world
    /// bounds).
    World(WorldError),
}

impl fmt::Display for PlaygroundError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PlaygroundError::NotFinite { what } => {
                write!(f, "{what} must be a finite number")
            }
            PlaygroundError::OutOfRange { what, value } => write!(
                f,
                "{what} = {value} is outside the fixed-point range (±2147483648)"
            ),
            PlaygroundError::UnknownScene(name) => write!(
                f,
                "unknown scene {name:?} (choose one of the built-in scenes or \"grapple\")"
            ),
            PlaygroundError::UnknownShape(name) => {
                write!(f, "unknown shape {name:?} (use \"ball\" or \"box\")")
            }
            PlaygroundError::NotGrapple => {
                write!(f, "the grapple controls work in the \"grapple\" scene only")
            }
            PlaygroundError::Scene(e) => write!(f, "scene: {e}"),
            PlaygroundError::World(e) => write!(f, "refused: {e}"),
        }
    }
}

impl std::error::Error for PlaygroundError {}

impl From<WorldError> for PlaygroundError {
    fn from(e: WorldError) -> Self {
        PlaygroundError::World(e)
    }
}

impl From<SceneError> for PlaygroundError {
    fn from(e: SceneError) -> Self {
        PlaygroundError::Scene(e)
    }
}

/// What JavaScript receives when a call fails: the message as a thrown
/// string. (Only the generated wasm glue calls this.)
impl From<PlaygroundError> for JsValue {
    fn from(e: PlaygroundError) -> Self {
        JsValue::from_str(&e.to_string())
    }
}

/// One number from the page, converted once to `Fx` with correct rounding
/// (the `fixed` crate's conversion rounds to nearest).
///
/// # Errors
/// [`PlaygroundError::NotFinite`] or [`PlaygroundError::OutOfRange`].
fn to_fx(value: f64, what: &'static str) -> Result<Fx, PlaygroundError> {
    if !value.is_finite() {
        return Err(PlaygroundError::NotFinite { what });
    }
    Fx::checked_from_num(value).ok_or(PlaygroundError::OutOfRange { what, value })
}

/// A point or vector from the page.
///
/// # Errors
/// As [`to_fx`], for either coordinate.
pub(crate) fn to_vec2(x: f64, y: f64, what: &'static str) -> Result<Vec2, PlaygroundError> {
    Ok(Vec2::new(to_fx(x, what)?, to_fx(y, what)?))
}
