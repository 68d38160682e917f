//! Adding, removing and reading constraints.

use super::{World, WorldError};
use crate::constraints::{
    Anchor, Constraint, ConstraintEntry, ConstraintId, ConstraintSlot, constraint_body_pairs,
};
use crate::dynamics::BodyKind;
use crate::math::{Scalar, WORLD_LIMIT};

/// Largest stiffness or damping accepted (2²⁴ ≈ 1.7e7): a unit mass then
/// reaches ω·h ≈ 68 at 60 Hz, far beyond what a scene can resolve, while
/// `k·h²` stays well inside the number range.
const MAX_STIFFNESS: i32 = 1 << 24;
/// Most constraint slots.
const MAX_CONSTRAINT_SLOTS: usize = 1 << 31;

impl<S: Scalar> World<S> {
    /// Adds a constraint and wakes the bodies it attaches.
    ///
    /// # Errors
    /// [`WorldError::UnknownBody`] for an anchor naming a dead body,
    /// [`WorldError::InvalidConstraint`] for out-of-range parameters (both
    /// ends on the same body or on no body, negative lengths, stiffness or
    /// damping outside [0, 2²⁴], restitution outside [0, 1], offsets
    /// outside the world). The world is then unchanged.
    pub fn add_constraint(
        &mut self,
        constraint: Constraint<S>,
    ) -> Result<ConstraintId, WorldError> {
        self.validate_constraint(&constraint)?;
        if self.constraint_free_list.is_empty()
            && self.constraint_slots.len() >= MAX_CONSTRAINT_SLOTS
        {
            return Err(WorldError::TooManyConstraints);
        }
        let entry = ConstraintEntry {
            constraint,
            impulse: S::ZERO,
        };
        let index = match self.constraint_free_list.pop() {
            Some(index) => {
                if let Some(slot) = self.constraint_slots.get_mut(index as usize) {
                    slot.entry = Some(entry);
                }
                index
            }
            None => {
                let index = u32::try_from(self.constraint_slots.len())
                    .map_err(|_| WorldError::TooManyConstraints)?;
                self.constraint_slots.push(ConstraintSlot {
                    generation: 0,
                    entry: Some(entry),
                });
                index
            }
        };
        self.wake_constraint_bodies(&constraint);
        let generation = self.constraint_slots[index as usize].generation;
        Ok(ConstraintId::from_parts(index, generation))
    }

    /// Removes a constraint and wakes the bodies it attached.
    ///
    /// # Errors
    /// [`WorldError::UnknownConstraint`] for a stale or unknown id.
    pub fn remove_constraint(&mut self, id: ConstraintId) -> Result<Constraint<S>, WorldError> {
        let slot = self
            .constraint_slots
            .get_mut(id.index() as usize)
            .filter(|s| s.generation == id.generation() && s.entry.is_some())
            .ok_or(WorldError::UnknownConstraint(id))?;
        let entry = slot.entry.take().ok_or(WorldError::UnknownConstraint(id))?;
        slot.generation = slot.generation.wrapping_add(1);
        self.constraint_free_list.push(id.index());
        self.wake_constraint_bodies(&entry.constraint);
        Ok(entry.constraint)
    }

    /// The constraint with this id, if it is live.
    #[must_use]
    pub fn constraint(&self, id: ConstraintId) -> Option<&Constraint<S>> {
        self.constraint_slots
            .get(id.index() as usize)
            .filter(|s| s.generation == id.generation())
            .and_then(|s| s.entry.as_ref())
            .map(|e| &e.constraint)
    }

    /// All live constraints in id order.
    pub fn constraints(&self) -> impl Iterator<Item = (ConstraintId, &Constraint<S>)> {
        self.constraint_slots
            .iter()
            .zip(0u32..)
            .filter_map(|(slot, index)| {
                slot.entry.as_ref().map(|e| {
                    (
                        ConstraintId::from_parts(index, slot.generation),
                        &e.constraint,
                    )
                })
            })
    }

    /// Removes every constraint attached to the body in slot `index` (called
    /// when the body is removed). Returns how many were removed.
    pub(crate) fn remove_constraints_of(&mut self, index: u32) -> usize {
        let mut removed = 0;
        for (slot_index, slot) in (0u32..).zip(self.constraint_slots.iter_mut()) {
            let attached = slot.entry.as_ref().is_some_and(|e| {
                let (a, b) = e.constraint.anchors();
                a.body().is_some_and(|id| id.index() == index)
                    || b.body().is_some_and(|id| id.index() == index)
            });
            if attached {
                slot.entry = None;
                slot.generation = slot.generation.wrapping_add(1);
                self.constraint_free_list.push(slot_index);
                removed += 1;
            }
        }
        removed
    }

    fn wake_constraint_bodies(&mut self, constraint: &Constraint<S>) {
        let (a, b) = constraint.anchors();
        for anchor in [a, b] {
            if let Some(id) = anchor.body()
                && self.live_index(id).is_ok()
            {
                self.wake_index(id.index());
            }
        }
    }

    /// Checks a constraint against the live bodies and the ranges.
    pub(crate) fn validate_constraint(&self, constraint: &Constraint<S>) -> Result<(), WorldError> {
        let invalid = |reason| Err(WorldError::InvalidConstraint { reason });
        let (a, b) = constraint.anchors();
        let limit = S::from_int(WORLD_LIMIT);
        for anchor in [a, b] {
            let p = anchor.local_point();
            if p.x.abs() > limit || p.y.abs() > limit {
                return invalid("anchor points and offsets must lie within ±32768");
            }
            if let Some(id) = anchor.body() {
                self.live_index(id)?;
            }
        }
        let moving = |anchor: &Anchor<S>| {
            anchor
                .body()
                .and_then(|id| self.body(id))
                .is_some_and(|body| body.kind == BodyKind::Dynamic)
        };
        match (a.body(), b.body()) {
            (None, None) => return invalid("at least one end must be attached to a body"),
            (Some(x), Some(y)) if x == y => return invalid("both ends are on the same body"),
            _ => {}
        }
        if !moving(&a) && !moving(&b) {
            return invalid("at least one end must be a dynamic body");
        }
        let max_k = S::from_int(MAX_STIFFNESS);
        let in_range = |v: S| !v.is_negative() && v <= max_k;
        match *constraint {
            Constraint::BendySpring {
                rest_offset,
                stiffness,
                damping,
                ..
            } => {
                if !in_range(stiffness.x) || !in_range(stiffness.y) || !in_range(damping) {
                    return invalid("stiffness and damping must be in [0, 2^24]");
                }
                if rest_offset.x.abs() > limit || rest_offset.y.abs() > limit {
                    return invalid("rest offset must lie within ±32768");
                }
            }
            Constraint::RadialSpring {
                rest_length,
                stiffness,
                damping,
                ..
            } => {
                if !in_range(stiffness) || !in_range(damping) {
                    return invalid("stiffness and damping must be in [0, 2^24]");
                }
                if rest_length.is_negative() || rest_length > limit {
                    return invalid("rest length must be in [0, 32768]");
                }
            }
            Constraint::Rope {
                max_length,
                restitution,
                ..
            } => {
                if !max_length.is_positive() || max_length > limit {
                    return invalid("rope length must be in (0, 32768]");
                }
                if restitution.is_negative() || restitution > S::ONE {
                    return invalid("rope restitution must be in [0, 1]");
                }
            }
        }
        Ok(())
    }
}

impl<S: Scalar> World<S> {
    /// Wakes every body joined by a constraint to the body in slot `index`.
    pub(crate) fn wake_constraint_partners(&mut self, index: u32) {
        let partners: Vec<u32> = constraint_body_pairs(&self.constraint_slots)
            .filter_map(|(x, y)| {
                if x.index() == index {
                    Some(y.index())
                } else if y.index() == index {
                    Some(x.index())
                } else {
                    None
                }
            })
            .collect();
        for p in partners {
            self.wake_index(p);
        }
    }
}
