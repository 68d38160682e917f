//! # clockwork2d
//!
//! A deterministic 2D physics engine. Every number on the simulation path is
//! fixed point ([`Fx`](math::Fx) = `I32F32` by default), so the same inputs give
//! bit-identical results on every machine, architecture and build profile.
//! `use clockwork2d::prelude::*;` imports what a game uses; ARCHITECTURE.md
//! in the repository describes the modules.
//!
//! ```
//! use clockwork2d::geometry::contact_circle_circle;
//! use clockwork2d::prelude::*;
//! let a = Circle::new(Vec2::new(fx(0.0), fx(0.0)), fx(1.0));
//! let b = Circle::new(Vec2::new(fx(1.5), fx(0.0)), fx(1.0));
//! let c = contact_circle_circle(&a, &b);
//! assert_eq!(c.separation, fx(-0.5));
//! assert_eq!(c.normal, Vec2::new(fx(1.0), fx(0.0)));
//! ```
#![forbid(unsafe_code)]
#![deny(clippy::float_arithmetic)]

mod collision;
pub mod constraints;
pub mod dynamics;
pub mod generational_id;
pub mod geometry;
pub mod math;
pub mod replay;
mod solver;
mod state;
pub mod world;

pub use state::{diff, hash, snapshot};

/// What a game uses, in one import: the scalar and vectors, the world and
/// its settings, bodies, shapes, constraints, commands, events, queries and
/// the errors. Each item's home is its module (`clockwork2d::world::World`,
/// ...); the geometry queries (`contact_*`, `ray_*`, `toi_*`) are in
/// [`geometry`].
pub mod prelude {
    pub use crate::constraints::{Anchor, Constraint, ConstraintId};
    pub use crate::dynamics::{Body, BodyDef, BodyId, BodyKind, MassSpec};
    pub use crate::geometry::{Aabb, Circle, Ray, RayHit, Shape};
    pub use crate::math::{Fx, Scalar, Vec2, fx, vec2};
    pub use crate::snapshot::SnapshotError;
    pub use crate::world::{
        BodyRayHit, Command, CommandOutcome, Event, QueryFilter, QueryIndex, World, WorldError,
        WorldSettings,
    };
}
