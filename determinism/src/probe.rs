//! [`Probe`]: folds what a scenario observes besides the state (ray-cast
//! answers, query results, command outcomes, events) into one running
//! FNV-1a-64 digest, with the same canonical little-endian encoding as the
//! state hash ([`clockwork2d::hash`]).
//!
//! The probe digest at a checkpoint covers everything observed since the
//! start of the run, so a query answer that differs at any tick changes
//! every later checkpoint.
//!
//! # Encoding
//!
//! Each record starts with a tag byte:
//!
//! | tag | record |
//! |---|---|
//! | 1 | ray miss |
//! | 2 | ray hit: body index, generation (u32 each), distance, point x, y, normal x, y (scalar bits) |
//! | 3 | id list: length (u32), then index, generation per id |
//! | 4 | command applied: outcome code (u8: 1 spawned, 2 constraint added, 3 applied), then for ids index and generation |
//! | 5 | command refused: error code (u8, see [`error_code`]), then for ids index and generation |
//! | 6 | events: count (u32), then per event a code (u8: 1 contact ended, 2 began, 3 slept, 4 woke, 5 frozen) and its ids |
//! | 7 | a scalar observation (scalar bits) |

use clockwork2d::constraints::ConstraintId;
use clockwork2d::dynamics::BodyId;
use clockwork2d::hash::StateHasher;
use clockwork2d::math::{Fx, Vec2};
use clockwork2d::world::{BodyRayHit, CommandOutcome, Event, WorldError};

/// A running digest of a scenario's observations.
#[derive(Clone, Copy, Debug, Default)]
pub struct Probe {
    hasher: StateHasher,
}

/// A stable code for each [`WorldError`] variant (part of the probe
/// encoding; a new variant needs a new code).
#[must_use]
pub fn error_code(error: &WorldError) -> u8 {
    match error {
        WorldError::NonPositiveSize => 1,
        WorldError::ShapeTooLarge => 2,
        WorldError::NonPositiveMass => 3,
        WorldError::MassOutOfRange => 4,
        WorldError::MaterialOutOfRange { .. } => 5,
        WorldError::OutOfBounds => 6,
        WorldError::SpeedTooLarge => 7,
        WorldError::UnknownBody(_) => 8,
        WorldError::NotDynamic(_) => 9,
        WorldError::FixedBody(_) => 10,
        WorldError::TooManyBodies => 11,
        WorldError::UnknownConstraint(_) => 12,
        WorldError::InvalidConstraint { .. } => 13,
        WorldError::TooManyConstraints => 14,
        WorldError::InvalidSettings { .. } => 15,
    }
}

/// A short name for each [`WorldError`] variant (for the coverage
/// statistics).
#[must_use]
pub fn error_name(error: &WorldError) -> &'static str {
    match error {
        WorldError::NonPositiveSize => "NonPositiveSize",
        WorldError::ShapeTooLarge => "ShapeTooLarge",
        WorldError::NonPositiveMass => "NonPositiveMass",
        WorldError::MassOutOfRange => "MassOutOfRange",
        WorldError::MaterialOutOfRange { .. } => "MaterialOutOfRange",
        WorldError::OutOfBounds => "OutOfBounds",
        WorldError::SpeedTooLarge => "SpeedTooLarge",
        WorldError::UnknownBody(_) => "UnknownBody",
        WorldError::NotDynamic(_) => "NotDynamic",
        WorldError::FixedBody(_) => "FixedBody",
        WorldError::TooManyBodies => "TooManyBodies",
        WorldError::UnknownConstraint(_) => "UnknownConstraint",
        WorldError::InvalidConstraint { .. } => "InvalidConstraint",
        WorldError::TooManyConstraints => "TooManyConstraints",
        WorldError::InvalidSettings { .. } => "InvalidSettings",
    }
}

impl Probe {
    /// The digest of everything observed so far.
    #[must_use]
    pub fn finish(&self) -> u64 {
        self.hasher.finish()
    }

    fn body_id(&mut self, id: BodyId) {
        self.hasher.u32(id.index());
        self.hasher.u32(id.generation());
    }

    fn constraint_id(&mut self, id: ConstraintId) {
        self.hasher.u32(id.index());
        self.hasher.u32(id.generation());
    }

    fn vec2(&mut self, v: Vec2<Fx>) {
        self.hasher.vec2(v);
    }

    /// Folds a ray-cast answer (hit or miss).
    pub fn ray(&mut self, hit: Option<&BodyRayHit<Fx>>) {
        match hit {
            None => self.hasher.u8(1),
            Some(h) => {
                self.hasher.u8(2);
                self.body_id(h.body);
                self.hasher.scalar(h.hit.distance);
                self.vec2(h.hit.point);
                self.vec2(h.hit.normal);
            }
        }
    }

    /// Folds a list of ray hits (as from `raycast_all`).
    pub fn rays(&mut self, hits: &[BodyRayHit<Fx>]) {
        self.hasher.u8(3);
        self.hasher
            .u32(u32::try_from(hits.len()).unwrap_or(u32::MAX));
        for h in hits {
            self.ray(Some(h));
        }
    }

    /// Folds a list of body ids (as from `query_aabb` / `query_point`).
    pub fn ids(&mut self, ids: &[BodyId]) {
        self.hasher.u8(3);
        self.hasher
            .u32(u32::try_from(ids.len()).unwrap_or(u32::MAX));
        for &id in ids {
            self.body_id(id);
        }
    }

    /// Folds one command result.
    pub fn result(&mut self, result: &Result<CommandOutcome, WorldError>) {
        match result {
            Ok(outcome) => {
                self.hasher.u8(4);
                match *outcome {
                    CommandOutcome::Spawned(id) => {
                        self.hasher.u8(1);
                        self.body_id(id);
                    }
                    CommandOutcome::ConstraintAdded(id) => {
                        self.hasher.u8(2);
                        self.constraint_id(id);
                    }
                    CommandOutcome::Applied => self.hasher.u8(3),
                }
            }
            Err(error) => {
                self.hasher.u8(5);
                self.hasher.u8(error_code(error));
                match *error {
                    WorldError::UnknownBody(id)
                    | WorldError::NotDynamic(id)
                    | WorldError::FixedBody(id) => self.body_id(id),
                    WorldError::UnknownConstraint(id) => self.constraint_id(id),
                    _ => {}
                }
            }
        }
    }

    /// Folds the events of one step, in the world's order.
    pub fn events(&mut self, events: &[Event]) {
        self.hasher.u8(6);
        self.hasher
            .u32(u32::try_from(events.len()).unwrap_or(u32::MAX));
        for event in events {
            match *event {
                Event::ContactEnded(a, b) => {
                    self.hasher.u8(1);
                    self.body_id(a);
                    self.body_id(b);
                }
                Event::ContactBegan(a, b) => {
                    self.hasher.u8(2);
                    self.body_id(a);
                    self.body_id(b);
                }
                Event::Slept(a) => {
                    self.hasher.u8(3);
                    self.body_id(a);
                }
                Event::Woke(a) => {
                    self.hasher.u8(4);
                    self.body_id(a);
                }
                Event::Frozen(a) => {
                    self.hasher.u8(5);
                    self.body_id(a);
                }
            }
        }
    }

    /// Folds one scalar observation.
    pub fn scalar(&mut self, value: Fx) {
        self.hasher.u8(7);
        self.hasher.scalar(value);
    }
}
