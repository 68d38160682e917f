//! `Clone` for [`World`]: the state is copied, the step's working memory
//! is not.
//!
//! The step context (`World::step_context`) is derived data: buffers that every
//! step refills, plus the broad phase's x order of the last step, which is
//! only a starting guess for its sort (any order gives the same pairs). A
//! restored snapshot starts with an empty one and continues bit-identically,
//! so a clone does too, without copying buffers as large as the state.
//! `clone_from` (what a rollback load does) copies the state into the
//! existing allocations and keeps the target's own working memory, so
//! loading a saved world every frame allocates nothing in steady state.

use super::World;
use crate::math::Scalar;
use crate::solver::StepContext;

impl<S: Scalar> Clone for World<S> {
    fn clone(&self) -> Self {
        World {
            settings: self.settings,
            tick: self.tick,
            slots: self.slots.clone(),
            free_list: self.free_list.clone(),
            contacts: self.contacts.clone(),
            sleeping_islands: self.sleeping_islands.clone(),
            constraint_slots: self.constraint_slots.clone(),
            constraint_free_list: self.constraint_free_list.clone(),
            events: self.events.clone(),
            step_context: StepContext::default(),
        }
    }

    fn clone_from(&mut self, source: &Self) {
        // Destructured so that a new field cannot be forgotten here.
        let World {
            settings,
            tick,
            slots,
            free_list,
            contacts,
            sleeping_islands,
            constraint_slots,
            constraint_free_list,
            events,
            step_context: _,
        } = self;
        settings.clone_from(&source.settings);
        *tick = source.tick;
        slots.clone_from(&source.slots);
        free_list.clone_from(&source.free_list);
        contacts.clone_from(&source.contacts);
        sleeping_islands.clone_from(&source.sleeping_islands);
        constraint_slots.clone_from(&source.constraint_slots);
        constraint_free_list.clone_from(&source.constraint_free_list);
        events.clone_from(&source.events);
    }
}
