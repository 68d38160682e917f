//! Scenes for clockwork2d: a RON description of settings and bodies, with
//! generators for the usual arrangements (stacks, pyramids, grids, walls),
//! the built-in scenes, building a [`World`](clockwork2d::prelude::World) from a
//! scene, and the seeded scripted input ([`scripted_commands`]) that the
//! golden replays and the determinism suite are made of.
//!
//! This crate holds the text format (RON) so that the library itself
//! depends on `fixed`, `serde` and `bincode` only; the CLI, the determinism
//! suite, the tests, fuzzing and the web playground use it.
//!
//! Numbers in scene files are decimal literals; they are converted once,
//! at load time, with the scalar's correctly rounded conversion, so a scene
//! builds to bit-identical worlds on every machine.
//!
//! ```
//! use clockwork2d::prelude::*;
//! use clockwork2d_scene::Scene;
//! let scene = Scene::from_ron(r#"(
//!     name: "drop",
//!     bodies: [
//!         (kind: Fixed, shape: Box(half: (10.0, 0.5)), position: (0.0, -0.5)),
//!         (kind: Dynamic, shape: Circle(radius: 0.5), position: (0.0, 3.0)),
//!     ],
//! )"#).unwrap();
//! let world: World = scene.build().unwrap();
//! assert_eq!(world.body_count(), 2);
//! ```

#![forbid(unsafe_code)]
#![deny(clippy::float_arithmetic)]

mod build;
mod builtin;
mod error;
mod script;

use serde::{Deserialize, Serialize};

pub use builtin::{BUILTIN_SCENES, DEFAULT_SCENE, builtin};
pub use error::SceneError;
pub use script::scripted_commands;

/// Largest number of bodies a scene may create (bounds memory for
/// untrusted scene files).
pub const MAX_SCENE_BODIES: u64 = 1 << 20;

/// A scene: settings overrides, bodies and generators.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Scene {
    /// A short name.
    pub name: String,
    /// Overrides of the default [`WorldSettings`](clockwork2d::prelude::WorldSettings).
    #[serde(default)]
    pub settings: SceneSettings,
    /// Individual bodies.
    #[serde(default)]
    pub bodies: Vec<SceneBody>,
    /// Generated groups of bodies, added after `bodies`, in order.
    #[serde(default)]
    pub generators: Vec<Generator>,
    /// Constraints between the scene's bodies, referenced by creation index
    /// (`bodies` first, then each generator's bodies in order).
    #[serde(default)]
    pub constraints: Vec<SceneConstraint>,
}

/// A constraint end in a scene file.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum SceneAnchor {
    /// A fixed world point.
    Point((f64, f64)),
    /// The body with this creation index.
    Body(u32),
    /// The body with this creation index, plus an offset.
    BodyOffset(u32, (f64, f64)),
}

/// A constraint in a scene file (see [`clockwork2d::prelude::Constraint`]).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum SceneConstraint {
    /// A bendy spring pulling `b` toward `a + rest_offset`.
    BendySpring {
        /// Anchor pulled toward.
        a: SceneAnchor,
        /// Pulled anchor.
        b: SceneAnchor,
        /// Stiffness per axis.
        stiffness: (f64, f64),
        /// Damping.
        #[serde(default)]
        damping: f64,
        /// Rest offset of `b` from `a`.
        #[serde(default)]
        rest_offset: (f64, f64),
    },
    /// A radial spring.
    RadialSpring {
        /// Pivot.
        pivot: SceneAnchor,
        /// Body end.
        body: SceneAnchor,
        /// Rest length.
        rest_length: f64,
        /// Stiffness.
        stiffness: f64,
        /// Damping.
        #[serde(default)]
        damping: f64,
    },
    /// A rope.
    Rope {
        /// One end.
        a: SceneAnchor,
        /// Other end.
        b: SceneAnchor,
        /// Length.
        length: f64,
        /// Restitution.
        #[serde(default)]
        restitution: f64,
    },
}

/// Optional overrides of the world settings; absent fields keep defaults.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct SceneSettings {
    /// Gravity (x, y).
    pub gravity: Option<(f64, f64)>,
    /// Seconds per tick.
    pub dt: Option<f64>,
    /// Velocity iterations.
    pub velocity_iterations: Option<u32>,
    /// Position iterations.
    pub position_iterations: Option<u32>,
    /// Substeps.
    pub substeps: Option<u32>,
    /// Sleeping on or off.
    pub sleep_enabled: Option<bool>,
    /// Half extents of the world bounds (centred on the origin).
    pub bounds: Option<(f64, f64)>,
}

/// The shape of a scene body.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum SceneShape {
    /// A circle.
    Circle {
        /// Radius.
        radius: f64,
    },
    /// An axis-aligned box.
    Box {
        /// Half extents (x, y).
        half: (f64, f64),
    },
}

/// Body kinds in scene files.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum SceneKind {
    /// Fixed.
    Fixed,
    /// Kinematic.
    Kinematic,
    /// Dynamic.
    Dynamic,
}

/// Material and flags shared by scene bodies and generators.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct SceneMaterial {
    /// Density (mass = density × area).
    pub density: f64,
    /// Restitution.
    pub restitution: f64,
    /// Friction.
    pub friction: f64,
    /// Gravity scale.
    pub gravity_scale: f64,
    /// Bullet flag.
    pub bullet: bool,
}

impl Default for SceneMaterial {
    fn default() -> Self {
        SceneMaterial {
            density: 1.0,
            restitution: 0.0,
            friction: 0.6,
            gravity_scale: 1.0,
            bullet: false,
        }
    }
}

/// One body of a scene.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct SceneBody {
    /// Kind.
    pub kind: SceneKind,
    /// Shape.
    pub shape: SceneShape,
    /// Position (x, y).
    pub position: (f64, f64),
    /// Velocity (x, y).
    #[serde(default)]
    pub velocity: (f64, f64),
    /// Material.
    #[serde(default)]
    pub material: SceneMaterial,
}

/// A generated group of bodies.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub enum Generator {
    /// `count` dynamic boxes stacked vertically, bottom one resting on
    /// `base` (its bottom edge), separated by `gap`.
    Stack {
        /// Number of boxes.
        count: u32,
        /// Half extents of each box.
        half: (f64, f64),
        /// Centre of the bottom edge of the stack.
        base: (f64, f64),
        /// Vertical gap between boxes.
        gap: f64,
        /// Material.
        #[serde(default)]
        material: SceneMaterial,
    },
    /// A pyramid of `rows` rows of dynamic boxes (the bottom row has `rows`
    /// boxes), centres `spacing` apart horizontally, resting on `base`.
    Pyramid {
        /// Rows.
        rows: u32,
        /// Half extents of each box.
        half: (f64, f64),
        /// Horizontal distance between centres in a row.
        spacing: f64,
        /// Centre of the bottom edge of the pyramid.
        base: (f64, f64),
        /// Material.
        #[serde(default)]
        material: SceneMaterial,
    },
    /// A `columns × rows` grid of dynamic bodies of one shape, the first at
    /// `origin`, `spacing` apart; velocities drawn from a seeded generator
    /// (uniform in [-speed, speed] per axis, quantised to 1/1024).
    Grid {
        /// Columns.
        columns: u32,
        /// Rows.
        rows: u32,
        /// Shape of every body.
        shape: SceneShape,
        /// Centre of the first body.
        origin: (f64, f64),
        /// Distance between centres (x, y).
        spacing: (f64, f64),
        /// Largest initial speed per axis.
        #[serde(default)]
        speed: f64,
        /// Seed of the velocity generator.
        #[serde(default)]
        seed: u64,
        /// Material.
        #[serde(default)]
        material: SceneMaterial,
    },
    /// A chain hanging from a fixed `pivot`: `segments` circular links of
    /// radius `link_radius`, each `segment_length` further along
    /// `direction` (normalised at build time), joined by ropes (the first to
    /// the pivot).
    Chain {
        /// Fixed point the chain hangs from.
        pivot: (f64, f64),
        /// Direction of the chain from the pivot.
        direction: (f64, f64),
        /// Number of links.
        segments: u32,
        /// Rope length between links.
        segment_length: f64,
        /// Radius of each link.
        link_radius: f64,
        /// Material of the links.
        #[serde(default)]
        material: SceneMaterial,
    },
    /// Four walls of `thickness` enclosing the box `center ± half` (inner
    /// region), of the given kind.
    Walls {
        /// Fixed or kinematic.
        kind: SceneKind,
        /// Centre of the enclosed region.
        center: (f64, f64),
        /// Half extents of the enclosed region.
        half: (f64, f64),
        /// Wall thickness.
        thickness: f64,
    },
}

impl Scene {
    /// Parses a scene from RON text.
    ///
    /// # Errors
    /// [`SceneError::Parse`] with the position and reason.
    pub fn from_ron(text: &str) -> Result<Scene, SceneError> {
        // `implicit_some` lets settings be written `dt: 0.01` rather than
        // `dt: Some(0.01)`.
        ron::Options::default()
            .with_default_extension(ron::extensions::Extensions::IMPLICIT_SOME)
            .from_str(text)
            .map_err(|e| SceneError::Parse(e.to_string()))
    }

    /// Reads a scene file.
    ///
    /// # Errors
    /// [`SceneError::Io`] or [`SceneError::Parse`].
    pub fn from_file(path: &std::path::Path) -> Result<Scene, SceneError> {
        let text = std::fs::read_to_string(path)
            .map_err(|e| SceneError::Io(format!("{}: {e}", path.display())))?;
        Self::from_ron(&text)
    }

    /// Serialises the scene as pretty RON.
    #[must_use]
    pub fn to_ron(&self) -> String {
        ron::ser::to_string_pretty(self, ron::ser::PrettyConfig::default()).unwrap_or_default()
    }
}
