//! The state hash: a fixed, documented digest of everything that affects
//! later steps.
//!
//! # Algorithm (version 1)
//!
//! The hash is **FNV-1a, 64-bit** (offset basis `0xcbf29ce484222325`, prime
//! `0x100000001b3`), applied byte by byte. Every value is fed as its
//! canonical little-endian bytes, whatever the machine's endianness:
//! `u8` as one byte, `u32` as 4 bytes, `u64` and every scalar as 8 bytes
//! (a scalar's bits are [`Scalar::to_hash_bits`]: the raw two's complement
//! value for fixed point), booleans as one byte 0/1.
//!
//! The state is split into parts, each hashed separately from a fresh
//! basis, so that a mismatch can name the part:
//!
//! 1. `world`: scalar id (u8), tick (u64), then every settings field in
//!    declaration order (vectors as x then y; the bounds as centre then half
//!    extents; counts as u32; `sleep_enabled` as a byte).
//! 2. `bodies`: slot count (u32), then per slot in index order: generation
//!    (u32), present (byte), and if present: kind (0 fixed, 1 kinematic,
//!    2 dynamic), shape (0 + radius, or 1 + half extents x, y), position x, y,
//!    velocity x, y, mass, inverse mass, restitution, friction, gravity
//!    scale, bullet, awake, frozen (bytes), sleep time, island key (u32).
//! 3. `contacts`: count (u32), then per cached contact in `(a, b)` order:
//!    a, b (u32), normal impulse, tangent impulse, touching (byte).
//! 4. `sleep`: island count (u32), then per island in key order: key,
//!    member count, members (u32 each).
//! 5. `allocator`: free-list length (u32), then its entries in order (u32).
//! 6. `constraints`: constraint slot count (u32), then per slot: generation
//!    (u32), present (byte), and if present: kind (0 bendy spring, 1 radial
//!    spring, 2 rope), both anchors (tag 0 point + x, y; 1 body + index,
//!    generation; 2 body offset + index, generation, x, y), the parameters
//!    in declaration order, then the accumulated impulse; then the constraint
//!    free list (length, entries).
//!
//! [`World::state_hash`] is FNV-1a-64 over the six part digests (u64 LE
//! each, in the order above).
//!
//! # The 128-bit form
//!
//! [`World::state_hash128`] feeds **the same canonical byte stream** of each
//! part into **FNV-1a, 128-bit** (offset basis
//! `0x6c62272e07bb014262b821756295c58d`, prime `2^88 + 0x13b`), then combines
//! the six 128-bit part digests (u128 LE each, same order) with FNV-1a-128.
//! It exists for rollback libraries that want a wider hash; the 64-bit value
//! is not a truncation of it.

mod digest;
mod fnv;

use std::collections::BTreeMap;

pub use digest::{PART_COUNT, StateDigest};
pub use fnv::{StateHasher, StateHasher128, StateSink};

use crate::collision::CachedContact;
use crate::constraints::{Anchor, Constraint, ConstraintSlot};
use crate::dynamics::BodyKind;
use crate::geometry::Shape;
use crate::math::Scalar;
use crate::world::{Slot, World, WorldSettings};

fn hash_anchor<S: Scalar, H: StateSink>(h: &mut H, anchor: &Anchor<S>) {
    match *anchor {
        Anchor::Point(p) => {
            h.u8(0);
            h.vec2(p);
        }
        Anchor::Body(id) => {
            h.u8(1);
            h.u32(id.index());
            h.u32(id.generation());
        }
        Anchor::BodyOffset(id, offset) => {
            h.u8(2);
            h.u32(id.index());
            h.u32(id.generation());
            h.vec2(offset);
        }
    }
}

fn len_u32(n: usize) -> u32 {
    u32::try_from(n).unwrap_or(u32::MAX)
}

impl<S: Scalar> World<S> {
    /// The state hash (see [`crate::hash`] for the exact algorithm): equal
    /// hashes on two peers mean equal states, on any machine.
    ///
    /// ```
    /// use clockwork2d::prelude::*;
    /// let mut a = World::new(WorldSettings::default());
    /// let mut b = World::new(WorldSettings::default());
    /// for w in [&mut a, &mut b] {
    ///     w.add_body(BodyDef::dynamic(Shape::circle(fx(0.5)))).unwrap();
    ///     w.step();
    /// }
    /// assert_eq!(a.state_hash(), b.state_hash());
    /// ```
    #[must_use]
    pub fn state_hash(&self) -> u64 {
        self.state_digest().combined()
    }

    /// The per-part digests of the state.
    #[must_use]
    pub fn state_digest(&self) -> StateDigest {
        let [world, bodies, contacts, sleep, allocator, constraints] =
            self.part_hashers::<StateHasher>();
        StateDigest {
            world: world.finish(),
            bodies: bodies.finish(),
            contacts: contacts.finish(),
            sleep: sleep.finish(),
            allocator: allocator.finish(),
            constraints: constraints.finish(),
        }
    }

    /// The 128-bit state hash (see [`crate::hash`], "The 128-bit form"), for
    /// rollback libraries that want a wider digest than [`Self::state_hash`].
    ///
    /// ```
    /// use clockwork2d::prelude::*;
    /// let mut a = World::new(WorldSettings::default());
    /// let b = a.clone();
    /// a.step();
    /// assert_ne!(a.state_hash128(), b.state_hash128());
    /// ```
    #[must_use]
    pub fn state_hash128(&self) -> u128 {
        let mut h = StateHasher128::default();
        for part in self.part_hashers::<StateHasher128>() {
            h.bytes(&part.finish().to_le_bytes());
        }
        h.finish()
    }

    /// One hasher per part, each fed its part's canonical bytes: the single
    /// place that lists the parts and their order, so the 64- and the
    /// 128-bit hashes cannot disagree about what the state is.
    fn part_hashers<H: StateSink + Default>(&self) -> [H; PART_COUNT] {
        // Exhaustive on purpose (no `..`): a new field in `World` fails to
        // compile here until it is hashed or named as not being state.
        let World {
            settings,
            tick,
            slots,
            free_list,
            contacts,
            sleeping_islands,
            constraint_slots,
            constraint_free_list,
            // This tick's output, not state that affects a later step.
            events: _,
            // Derived buffers of the step (the step context).
            step_context: _,
        } = self;
        let mut parts: [H; PART_COUNT] = Default::default();
        let [world, bodies, contacts_part, sleep, allocator, constraints] = &mut parts;
        feed_world(world, settings, *tick);
        feed_bodies(bodies, slots);
        feed_contacts(contacts_part, contacts);
        feed_sleep(sleep, sleeping_islands);
        feed_allocator(allocator, free_list);
        feed_constraints(constraints, constraint_slots, constraint_free_list);
        parts
    }
}

fn feed_world<S: Scalar, H: StateSink>(h: &mut H, settings: &WorldSettings<S>, tick: u64) {
    // Exhaustive on purpose: a new setting fails to compile here until it
    // is hashed (in a fixed place of the order below).
    let WorldSettings {
        gravity,
        dt,
        velocity_iterations,
        position_iterations,
        substeps,
        sleep_enabled,
        sleep_linear_threshold,
        time_to_sleep,
        restitution_threshold,
        linear_slop,
        position_correction,
        max_correction,
        speculative_margin,
        max_speed,
        bounds,
    } = *settings;
    h.u8(S::ID);
    h.u64(tick);
    h.vec2(gravity);
    h.scalar(dt);
    h.u32(velocity_iterations);
    h.u32(position_iterations);
    h.u32(substeps);
    h.bool(sleep_enabled);
    for v in [
        sleep_linear_threshold,
        time_to_sleep,
        restitution_threshold,
        linear_slop,
        position_correction,
        max_correction,
        speculative_margin,
        max_speed,
    ] {
        h.scalar(v);
    }
    h.vec2(bounds.center);
    h.vec2(bounds.half_extents);
}

fn feed_bodies<S: Scalar, H: StateSink>(h: &mut H, slots: &[Slot<S>]) {
    h.u32(len_u32(slots.len()));
    for slot in slots {
        h.u32(slot.generation);
        h.bool(slot.body.is_some());
        let Some(b) = &slot.body else { continue };
        h.u8(match b.kind {
            BodyKind::Fixed => 0,
            BodyKind::Kinematic => 1,
            BodyKind::Dynamic => 2,
        });
        match b.shape {
            Shape::Circle { radius } => {
                h.u8(0);
                h.scalar(radius);
            }
            Shape::Aabb { half_extents } => {
                h.u8(1);
                h.vec2(half_extents);
            }
        }
        h.vec2(b.position);
        h.vec2(b.velocity);
        for v in [
            b.mass,
            b.inverse_mass,
            b.restitution,
            b.friction,
            b.gravity_scale,
        ] {
            h.scalar(v);
        }
        h.bool(b.bullet);
        h.bool(b.awake);
        h.bool(b.frozen);
        h.scalar(b.sleep_time);
        h.u32(b.island);
    }
}

fn feed_contacts<S: Scalar, H: StateSink>(h: &mut H, contacts: &[CachedContact<S>]) {
    h.u32(len_u32(contacts.len()));
    for c in contacts {
        h.u32(c.a);
        h.u32(c.b);
        h.scalar(c.normal_impulse);
        h.scalar(c.tangent_impulse);
        h.bool(c.touching);
    }
}

fn feed_sleep<H: StateSink>(h: &mut H, sleeping_islands: &BTreeMap<u32, Vec<u32>>) {
    h.u32(len_u32(sleeping_islands.len()));
    for (key, members) in sleeping_islands {
        h.u32(*key);
        h.u32(len_u32(members.len()));
        for m in members {
            h.u32(*m);
        }
    }
}

fn feed_constraints<S: Scalar, H: StateSink>(
    h: &mut H,
    constraint_slots: &[ConstraintSlot<S>],
    constraint_free_list: &[u32],
) {
    h.u32(len_u32(constraint_slots.len()));
    for slot in constraint_slots {
        h.u32(slot.generation);
        h.bool(slot.entry.is_some());
        let Some(entry) = &slot.entry else { continue };
        let (a, b) = entry.constraint.anchors();
        let tag = match entry.constraint {
            Constraint::BendySpring { .. } => 0,
            Constraint::RadialSpring { .. } => 1,
            Constraint::Rope { .. } => 2,
        };
        h.u8(tag);
        hash_anchor(h, &a);
        hash_anchor(h, &b);
        match entry.constraint {
            Constraint::BendySpring {
                rest_offset,
                stiffness,
                damping,
                ..
            } => {
                h.vec2(rest_offset);
                h.vec2(stiffness);
                h.scalar(damping);
            }
            Constraint::RadialSpring {
                rest_length,
                stiffness,
                damping,
                ..
            } => {
                h.scalar(rest_length);
                h.scalar(stiffness);
                h.scalar(damping);
            }
            Constraint::Rope {
                max_length,
                restitution,
                ..
            } => {
                h.scalar(max_length);
                h.scalar(restitution);
            }
        }
        h.scalar(entry.impulse);
    }
    h.u32(len_u32(constraint_free_list.len()));
    for i in constraint_free_list {
        h.u32(*i);
    }
}

fn feed_allocator<H: StateSink>(h: &mut H, free_list: &[u32]) {
    h.u32(len_u32(free_list.len()));
    for i in free_list {
        h.u32(*i);
    }
}
