//! [`Command`]: every mutation of a world, as data.
//!
//! Commands are what replays record and lockstep peers exchange. Applying a
//! command validates it completely first, so a command from an untrusted
//! peer either takes effect or is refused with a [`WorldError`] and leaves
//! the world unchanged. It never panics.

use serde::{Deserialize, Serialize};

use crate::constraints::{Constraint, ConstraintId};
use crate::dynamics::{BodyDef, BodyId};
use crate::math::Fx;
use crate::math::{Scalar, Vec2};

/// One mutation of the world.
///
/// ```
/// use clockwork2d::prelude::*;
/// let mut world = World::new(WorldSettings::default());
/// let out = world.apply(Command::Spawn(BodyDef::dynamic(Shape::circle(fx(0.5))))).unwrap();
/// let CommandOutcome::Spawned(ball) = out else { unreachable!() };
/// world.apply(Command::ApplyImpulse { body: ball, impulse: Vec2::new(fx(1.0), fx(0.0)) }).unwrap();
/// assert!(world.apply(Command::Despawn(ball)).is_ok());
/// assert!(world.apply(Command::Despawn(ball)).is_err()); // stale id: refused
/// ```
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub enum Command<S: Scalar = Fx> {
    /// Adds a body; its id is the next one the allocator gives.
    Spawn(BodyDef<S>),
    /// Removes a body (waking what touched it).
    Despawn(BodyId),
    /// Adds `impulse / mass` to a dynamic body's velocity and wakes it.
    ApplyImpulse {
        /// The body.
        body: BodyId,
        /// Impulse (mass × units/s).
        impulse: Vec2<S>,
    },
    /// Sets the velocity of a dynamic or kinematic body and wakes it.
    SetVelocity {
        /// The body.
        body: BodyId,
        /// New velocity (units/s).
        velocity: Vec2<S>,
    },
    /// Teleports a body (any kind) and wakes it and what it touched.
    SetPosition {
        /// The body.
        body: BodyId,
        /// New position, inside the world bounds.
        position: Vec2<S>,
    },
    /// Wakes a body and its island.
    Wake(BodyId),
    /// Adds a constraint (waking the bodies it attaches).
    AddConstraint(Constraint<S>),
    /// Removes a constraint (waking the bodies it attached).
    RemoveConstraint(ConstraintId),
}

/// What a successful command did.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum CommandOutcome {
    /// A body was added with this id.
    Spawned(BodyId),
    /// A constraint was added with this id.
    ConstraintAdded(ConstraintId),
    /// The command took effect.
    Applied,
}
