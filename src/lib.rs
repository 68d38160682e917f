//! # clockwork2d
//!
//! A deterministic 2D physics engine. Every number on the simulation path is
//! fixed point ([`Fx`] = `I32F32` by default), so the same inputs give
//! bit-identical results on every machine, architecture and build profile.
//!
//! ```
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
pub mod geometry;
pub mod math;
pub mod replay;
mod solver;
mod state;
pub mod world;

pub use state::{diff, hash, snapshot};

pub use constraints::{Anchor, Constraint, ConstraintId};
pub use dynamics::{Body, BodyDef, BodyId, BodyKind, MassSpec};
pub use math::{Fx, Scalar, Vec2, WideScalar, fx};
pub use world::QueryIndex;
pub use world::{
    BodyRayHit, Command, CommandOutcome, Event, QueryFilter, World, WorldError, WorldSettings,
};

/// Everything a typical user needs, in one import.
pub mod prelude {
    pub use crate::constraints::{Anchor, Constraint, ConstraintId};
    pub use crate::dynamics::{Body, BodyDef, BodyId, BodyKind, MassSpec};
    pub use crate::geometry::*;
    pub use crate::math::{Fx, Scalar, Vec2, WORLD_LIMIT, WideScalar, fx};
    pub use crate::world::QueryIndex;
    pub use crate::world::{
        BodyRayHit, Command, CommandOutcome, Event, QueryFilter, World, WorldError, WorldSettings,
    };
}
