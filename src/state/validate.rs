//! Deep validation of a world read from untrusted bytes (a snapshot or the
//! initial state of a replay).
//!
//! A decoded world is only accepted if the engine could have produced it:
//! every invariant that the step pipeline relies on (indices in range, lists
//! sorted, sleepers registered in their island, ...) is checked here, so a
//! hostile file can at worst be refused, never make a later step panic,
//! index out of bounds or loop forever. One function per part of the state,
//! named like the parts of the state hash.

use crate::dynamics::{Body, BodyId, BodyKind, NO_ISLAND};
use crate::geometry::Shape;
use crate::math::{Scalar, Vec2, WORLD_LIMIT};
use crate::world::{MAX_MASS, MAX_SHAPE_SIZE, MIN_MASS_RECIPROCAL, World};
use core::fmt;

/// The world described by a file breaks an invariant of the engine: the
/// part of the state and what is wrong, in words.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct InvalidState {
    /// The part of the state (the names of [`StateDigest`](crate::hash::StateDigest)'s
    /// parts, plus `"replay"` for a replay's own tables).
    pub part: &'static str,
    /// What is wrong, naming the body, contact or island.
    pub detail: String,
}

impl fmt::Display for InvalidState {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.part, self.detail)
    }
}

impl InvalidState {
    /// The invariant of `part` that `detail` says is broken.
    pub(crate) fn new(part: &'static str, detail: impl Into<String>) -> Self {
        InvalidState {
            part,
            detail: detail.into(),
        }
    }
}

impl std::error::Error for InvalidState {}

/// `true` if `v` is NaN (only the float reference scalars have one).
fn is_nan<S: Scalar>(v: S) -> bool {
    v.partial_cmp(&S::ZERO).is_none()
}

fn vec_is_nan<S: Scalar>(v: Vec2<S>) -> bool {
    is_nan(v.x) || is_nan(v.y)
}

impl<S: Scalar> World<S> {
    /// Checks every invariant of the state.
    ///
    /// # Errors
    /// [`InvalidState`] naming the part and what is wrong.
    pub(crate) fn validate(&self) -> Result<(), InvalidState> {
        // Exhaustive on purpose: a new field in `World` fails to compile here
        // until someone decides how to validate it.
        let World {
            settings,
            tick: _,
            slots: _,
            free_list: _,
            contacts: _,
            sleeping_islands: _,
            constraint_slots: _,
            constraint_free_list: _,
            // Events are the last step's output; nothing reads them back.
            events: _,
            step_context: _,
        } = self;
        settings
            .validate()
            .map_err(|e| InvalidState::new("world", e.to_string()))?;
        self.validate_bodies()?;
        self.validate_allocator()?;
        self.validate_contacts()?;
        self.validate_sleep()?;
        self.validate_constraints()?;
        Ok(())
    }

    /// The live body in slot `index`, if any.
    fn live(&self, index: u32) -> Option<&Body<S>> {
        self.slots
            .get(usize::try_from(index).ok()?)
            .and_then(|s| s.body.as_ref())
    }

    fn validate_bodies(&self) -> Result<(), InvalidState> {
        let bad =
            |id: BodyId, what: &str| Err(InvalidState::new("bodies", format!("{id}: {what}")));
        let max_size = S::from_int(MAX_SHAPE_SIZE);
        let limit = S::from_int(WORLD_LIMIT);
        let bounds = self.settings.bounds;
        let max_speed = self.settings.max_speed;
        let thousand = S::from_int(1000);
        for (slot, index) in self.slots.iter().zip(0u32..) {
            let Some(b) = &slot.body else { continue };
            let id = BodyId::from_parts(index, slot.generation);
            let size_ok = |v: S| v.is_positive() && v <= max_size;
            let shape_ok = match b.shape {
                Shape::Circle { radius } => size_ok(radius),
                Shape::Aabb { half_extents } => size_ok(half_extents.x) && size_ok(half_extents.y),
            };
            if !shape_ok {
                return bad(id, "shape size must be in (0, 4096]");
            }
            if b.kind == BodyKind::Dynamic {
                if b.mass < S::from_ratio(1, MIN_MASS_RECIPROCAL) || b.mass > S::from_int(MAX_MASS)
                {
                    return bad(id, "mass must be in [1/1024, 2^20]");
                }
                // Exactly what `add_body` computes, so the solver sees the
                // same inverse mass as in the recorded run.
                if b.inverse_mass != S::ONE.div(b.mass) {
                    return bad(id, "inverse mass is not 1 / mass");
                }
            } else if b.mass != S::ZERO || b.inverse_mass != S::ZERO {
                return bad(
                    id,
                    "fixed and kinematic bodies have zero mass and inverse mass",
                );
            }
            if b.restitution.is_negative() || b.restitution > S::ONE || is_nan(b.restitution) {
                return bad(id, "restitution must be in [0, 1]");
            }
            if b.friction.is_negative() || b.friction > thousand || is_nan(b.friction) {
                return bad(id, "friction must be in [0, 1000]");
            }
            if b.gravity_scale.abs() > thousand || is_nan(b.gravity_scale) {
                return bad(id, "gravity scale must be in [-1000, 1000]");
            }
            if b.bullet && b.kind != BodyKind::Dynamic {
                return bad(id, "only dynamic bodies can be bullets");
            }
            if b.frozen {
                // Frozen bodies are clamped to the bounds when they leave;
                // accept anything inside the documented world.
                let p = b.position;
                if !(p.x.abs() <= limit && p.y.abs() <= limit) {
                    return bad(id, "frozen body outside the world limit ±32768");
                }
            } else if !bounds.contains_point(b.position) {
                return bad(id, "position outside the world bounds");
            }
            if vec_is_nan(b.velocity) {
                return bad(id, "velocity is NaN");
            }
            if b.sleep_time.is_negative() || is_nan(b.sleep_time) {
                return bad(id, "sleep time must be non-negative");
            }
            match b.kind {
                BodyKind::Fixed => {
                    if b.velocity != Vec2::ZERO || b.awake || b.frozen {
                        return bad(id, "a fixed body is never moving, awake or frozen");
                    }
                }
                BodyKind::Kinematic => {
                    if !b.awake {
                        return bad(id, "a kinematic body never sleeps");
                    }
                    if b.velocity.x.abs() > max_speed || b.velocity.y.abs() > max_speed {
                        return bad(id, "kinematic velocity above max_speed");
                    }
                }
                BodyKind::Dynamic => {
                    if !b.awake && b.frozen {
                        return bad(id, "a frozen body cannot sleep");
                    }
                    // The step clamps every awake body to `max_speed` per
                    // axis at write-back, `add_body` and the velocity
                    // commands refuse more, and a body falls asleep at
                    // rest: no world the engine makes holds a faster one.
                    // A sleeping body is never written back, so one
                    // restored faster would keep its speed for ever.
                    if b.velocity.x.abs() > max_speed || b.velocity.y.abs() > max_speed {
                        return bad(id, "velocity above max_speed");
                    }
                }
            }
            // Membership of sleepers is checked with the islands.
            if b.awake && b.island != NO_ISLAND {
                return bad(id, "an awake body has a sleeping-island key");
            }
        }
        Ok(())
    }

    fn validate_allocator(&self) -> Result<(), InvalidState> {
        let bad = |what: String| Err(InvalidState::new("allocator", what));
        let mut listed = vec![false; self.slots.len()];
        for &index in &self.free_list {
            let Some(seen) = usize::try_from(index).ok().and_then(|i| listed.get_mut(i)) else {
                return bad(format!("free slot {index} is out of range"));
            };
            if *seen {
                return bad(format!("free slot {index} is listed twice"));
            }
            *seen = true;
            if self.live(index).is_some() {
                return bad(format!("free slot {index} holds a live body"));
            }
        }
        let empty = self.slots.iter().filter(|s| s.body.is_none()).count();
        if empty != self.free_list.len() {
            return bad(format!(
                "{empty} empty slots but {} in the free list",
                self.free_list.len()
            ));
        }
        Ok(())
    }

    fn validate_contacts(&self) -> Result<(), InvalidState> {
        let mut previous: Option<(u32, u32)> = None;
        for c in &self.contacts {
            let bad = |what: &str| {
                Err(InvalidState::new(
                    "contacts",
                    format!("contact ({}, {}): {what}", c.a, c.b),
                ))
            };
            if c.a >= c.b {
                return bad("the first slot must be the smaller");
            }
            if previous.is_some_and(|p| p >= (c.a, c.b)) {
                return bad("contacts are not sorted by pair, or repeat a pair");
            }
            previous = Some((c.a, c.b));
            if self.live(c.a).is_none() || self.live(c.b).is_none() {
                return bad("names a slot without a live body");
            }
            if c.normal_impulse.is_negative() || is_nan(c.normal_impulse) {
                return bad("the normal impulse is negative");
            }
            if is_nan(c.tangent_impulse) {
                return bad("the tangent impulse is NaN");
            }
        }
        Ok(())
    }

    fn validate_sleep(&self) -> Result<(), InvalidState> {
        let mut members_total = 0usize;
        for (&key, members) in &self.sleeping_islands {
            let bad =
                |what: String| Err(InvalidState::new("sleep", format!("island {key}: {what}")));
            if members.is_empty() {
                return bad("has no members".to_owned());
            }
            if members.windows(2).any(|w| w.first() >= w.get(1)) {
                return bad("members are not strictly ascending".to_owned());
            }
            for &m in members {
                let Some(b) = self.live(m) else {
                    return bad(format!("member slot {m} holds no live body"));
                };
                if b.kind != BodyKind::Dynamic || b.awake || b.frozen {
                    return bad(format!("member slot {m} is not a sleeping dynamic body"));
                }
                if b.island != key {
                    return bad(format!("member slot {m} says it is in island {}", b.island));
                }
            }
            members_total += members.len();
        }
        // Every member names its island and keys are unique, so no body is
        // in two islands; equal counts then mean every sleeper is listed.
        let sleepers = self
            .slots
            .iter()
            .filter_map(|s| s.body.as_ref())
            .filter(|b| b.kind == BodyKind::Dynamic && !b.awake)
            .count();
        if sleepers != members_total {
            return Err(InvalidState::new(
                "sleep",
                format!("{sleepers} sleeping bodies but {members_total} island members"),
            ));
        }
        Ok(())
    }

    fn validate_constraints(&self) -> Result<(), InvalidState> {
        let bad = |what: String| Err(InvalidState::new("constraints", what));
        for (slot, index) in self.constraint_slots.iter().zip(0u32..) {
            let Some(entry) = &slot.entry else { continue };
            // The same checks `add_constraint` makes: live anchors, ranges.
            if let Err(e) = self.validate_constraint(&entry.constraint) {
                return bad(format!("constraint {index} (gen {}): {e}", slot.generation));
            }
            if is_nan(entry.impulse) {
                return bad(format!("constraint {index}: impulse is NaN"));
            }
        }
        let mut listed = vec![false; self.constraint_slots.len()];
        for &index in &self.constraint_free_list {
            let Some(seen) = usize::try_from(index).ok().and_then(|i| listed.get_mut(i)) else {
                return bad(format!("free constraint slot {index} is out of range"));
            };
            if *seen {
                return bad(format!("free constraint slot {index} is listed twice"));
            }
            *seen = true;
        }
        for (slot, seen) in self.constraint_slots.iter().zip(&listed) {
            if slot.entry.is_some() == *seen {
                return bad(
                    "the constraint free list is not exactly the empty constraint slots".to_owned(),
                );
            }
        }
        Ok(())
    }
}
