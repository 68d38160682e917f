//! The [`World`]: bodies, the step pipeline, commands, events and queries.

mod bodies;
mod clone;
mod command;
mod command_apply;
mod constraints_api;
mod error;
mod events;
mod queries;
mod query_index;
mod settings;
mod step;

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

pub use command::{Command, CommandOutcome};
pub use error::WorldError;
pub use events::Event;
pub use queries::{BodyRayHit, QueryFilter};
pub use query_index::QueryIndex;
pub use settings::{MAX_ITERATIONS, MAX_SUBSTEPS, WorldSettings};
pub use step::contacts::MAX_BULLET_IMPACTS;

pub(crate) use bodies::{MAX_MASS, MAX_SHAPE_SIZE, MIN_MASS_RECIPROCAL};

use crate::collision::CachedContact;
use crate::constraints::ConstraintSlot;
use crate::dynamics::{Body, BodyId};
use crate::math::Fx;
use crate::math::Scalar;
use crate::solver::StepContext;

/// One slot of the body table: a generation counter and maybe a body.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) struct Slot<S: Scalar> {
    pub(crate) generation: u32,
    pub(crate) body: Option<Body<S>>,
}

/// A deterministic 2D physics world.
///
/// ```
/// use clockwork2d::prelude::*;
/// let mut world = World::new(WorldSettings::default());
/// let _ground = world
///     .add_body(BodyDef::fixed(Shape::aabb(Vec2::new(fx(20.0), fx(0.5))))
///         .position(Vec2::new(fx(0.0), fx(-0.5))))
///     .unwrap();
/// let ball = world
///     .add_body(BodyDef::dynamic(Shape::circle(fx(0.25)))
///         .position(Vec2::new(fx(0.0), fx(4.0))))
///     .unwrap();
/// for _ in 0..240 {
///     world.step();
/// }
/// let p = world.body(ball).unwrap().position();
/// assert!((p.y.to_f64() - 0.25).abs() < 0.01); // resting on the ground
/// ```
#[derive(Debug)]
pub struct World<S: Scalar = Fx> {
    pub(crate) settings: WorldSettings<S>,
    pub(crate) tick: u64,
    pub(crate) slots: Vec<Slot<S>>,
    /// Freed slot indices; the last one is reused first.
    pub(crate) free_list: Vec<u32>,
    /// Contacts of the last substep, sorted by slot pair, with their
    /// accumulated impulses (for warm starting) and touching state.
    pub(crate) contacts: Vec<CachedContact<S>>,
    /// Sleeping islands: key (smallest slot index of the island when it fell
    /// asleep) → member slot indices, ascending.
    pub(crate) sleeping_islands: BTreeMap<u32, Vec<u32>>,
    /// Constraint table (springs and ropes), like the body table.
    pub(crate) constraint_slots: Vec<ConstraintSlot<S>>,
    /// Freed constraint slot indices; the last one is reused first.
    pub(crate) constraint_free_list: Vec<u32>,
    /// Events of the last step.
    pub(crate) events: Vec<Event>,
    /// Working buffers reused every step (no allocation in steady state);
    /// derived data, not part of the state (never serialised).
    pub(crate) step_context: StepContext<S>,
}

impl World<Fx> {
    /// Creates an empty world of the default scalar [`Fx`] (no type
    /// annotation needed; [`World::new_generic`] for another scalar).
    ///
    /// ```
    /// use clockwork2d::prelude::*;
    /// let world = World::new(WorldSettings::default()); // World<Fx>
    /// assert_eq!(world.body_count(), 0);
    /// ```
    ///
    /// # Panics
    /// If `settings` are outside their documented ranges
    /// ([`WorldSettings::validate`]); a world is never quietly built with
    /// other settings than asked for. Use [`World::try_new`] for settings
    /// that come from a file or a peer.
    #[must_use]
    pub fn new(settings: WorldSettings<Fx>) -> Self {
        Self::new_generic(settings)
    }
}

impl<S: Scalar> World<S> {
    /// Creates an empty world of any scalar type, e.g.
    /// `World::<I48F16>::new_generic(WorldSettings::default())`.
    ///
    /// # Panics
    /// If `settings` are invalid, like [`World::new`].
    #[must_use]
    pub fn new_generic(settings: WorldSettings<S>) -> Self {
        match Self::try_new(settings) {
            Ok(world) => world,
            Err(e) => panic!("World::new: {e} (use World::try_new to handle invalid settings)"),
        }
    }

    /// Creates an empty world, refusing settings outside their ranges.
    ///
    /// # Errors
    /// [`WorldError::InvalidSettings`] naming the first bad field.
    pub fn try_new(settings: WorldSettings<S>) -> Result<Self, WorldError> {
        settings.validate()?;
        Ok(World {
            settings,
            tick: 0,
            slots: Vec::new(),
            free_list: Vec::new(),
            contacts: Vec::new(),
            sleeping_islands: BTreeMap::new(),
            constraint_slots: Vec::new(),
            constraint_free_list: Vec::new(),
            events: Vec::new(),
            step_context: StepContext::default(),
        })
    }

    /// The world's settings.
    #[must_use]
    pub fn settings(&self) -> &WorldSettings<S> {
        &self.settings
    }

    /// Ticks stepped so far.
    #[must_use]
    pub fn tick(&self) -> u64 {
        self.tick
    }

    /// The body with this id, or `None` if the id is stale or unknown.
    #[must_use]
    pub fn body(&self, id: BodyId) -> Option<&Body<S>> {
        let slot = self.slots.get(usize::try_from(id.index()).ok()?)?;
        if slot.generation != id.generation() {
            return None;
        }
        slot.body.as_ref()
    }

    /// All live bodies in id (slot) order.
    pub fn bodies(&self) -> impl Iterator<Item = (BodyId, &Body<S>)> {
        self.slots.iter().zip(0u32..).filter_map(|(slot, index)| {
            slot.body
                .as_ref()
                .map(|body| (BodyId::from_parts(index, slot.generation), body))
        })
    }

    /// Number of live bodies.
    #[must_use]
    pub fn body_count(&self) -> usize {
        self.slots.iter().filter(|s| s.body.is_some()).count()
    }

    /// The events of the last step (see [`Event`] for their order).
    #[must_use]
    pub fn events(&self) -> &[Event] {
        &self.events
    }

    /// Pairs of bodies touching after the last step, sorted by id.
    pub fn touching_pairs(&self) -> impl Iterator<Item = (BodyId, BodyId)> + '_ {
        self.contacts
            .iter()
            .filter(|c| c.touching)
            .map(|c| (self.id_of(c.a), self.id_of(c.b)))
    }

    /// The id of the live body in slot `index`.
    #[inline]
    pub(crate) fn id_of(&self, index: u32) -> BodyId {
        let generation = self
            .slots
            .get(index as usize)
            .map_or(0, |slot| slot.generation);
        BodyId::from_parts(index, generation)
    }

    /// The slot index of a live body, or an error for a stale id.
    pub(crate) fn live_index(&self, id: BodyId) -> Result<usize, WorldError> {
        let index = usize::try_from(id.index()).map_err(|_| WorldError::UnknownBody(id))?;
        match self.slots.get(index) {
            Some(slot) if slot.generation == id.generation() && slot.body.is_some() => Ok(index),
            _ => Err(WorldError::UnknownBody(id)),
        }
    }
}
