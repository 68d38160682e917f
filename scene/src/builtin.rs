//! The scenes shipped in `scenes/`, compiled in so the CLI runs them by
//! name on any machine.

use super::{Scene, SceneError};

/// The scene `cargo run --release` runs when none is named.
pub const DEFAULT_SCENE: &str = "mixed";

/// `(name, RON text)` of every built-in scene.
pub const BUILTIN_SCENES: &[(&str, &str)] = &[
    ("stack", include_str!("../../scenes/stack.ron")),
    ("pyramid", include_str!("../../scenes/pyramid.ron")),
    ("balls", include_str!("../../scenes/balls.ron")),
    ("bullets", include_str!("../../scenes/bullets.ron")),
    ("mixed", include_str!("../../scenes/mixed.ron")),
    ("springs", include_str!("../../scenes/springs.ron")),
    ("rope", include_str!("../../scenes/rope.ron")),
    (
        "large_pyramid",
        include_str!("../../scenes/large_pyramid.ron"),
    ),
    ("balls5000", include_str!("../../scenes/balls5000.ron")),
    (
        "springs_grid",
        include_str!("../../scenes/springs_grid.ron"),
    ),
    (
        "ropes_chains",
        include_str!("../../scenes/ropes_chains.ron"),
    ),
];

/// The built-in scene called `name`.
///
/// # Errors
/// [`SceneError::Unknown`] for a name that is not built in;
/// [`SceneError::Parse`] cannot happen for shipped scenes (a test checks).
pub fn builtin(name: &str) -> Result<Scene, SceneError> {
    BUILTIN_SCENES
        .iter()
        .find(|(n, _)| *n == name)
        .ok_or_else(|| SceneError::Unknown(name.to_owned()))
        .and_then(|(_, text)| Scene::from_ron(text))
}
