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

use crate::constraints::{Anchor, Constraint};
use crate::dynamics::BodyKind;
use crate::geometry::Shape;
use crate::math::{Scalar, Vec2};
use std::collections::BTreeMap;

use crate::collision::CachedContact;
use crate::constraints::ConstraintSlot;
use crate::world::{Slot, World, WorldSettings};

const FNV_OFFSET: u64 = 0xcbf2_9ce4_8422_2325;
const FNV_PRIME: u64 = 0x0000_0100_0000_01b3;
const FNV128_OFFSET: u128 = 0x6c62_272e_07bb_0142_62b8_2175_6295_c58d;
const FNV128_PRIME: u128 = 0x0000_0000_0100_0000_0000_0000_0000_013b;

/// Something the canonical byte stream of the state can be fed into: the
/// 64-bit and the 128-bit FNV-1a hashers. The part digests are written once,
/// generically, so both hashes see exactly the same bytes.
pub trait StateSink {
    /// Feeds raw bytes.
    fn bytes(&mut self, bytes: &[u8]);
    /// Feeds one byte.
    fn u8(&mut self, v: u8) {
        self.bytes(&[v]);
    }
    /// Feeds a boolean as 0 or 1.
    fn bool(&mut self, v: bool) {
        self.u8(u8::from(v));
    }
    /// Feeds a `u32`, little endian.
    fn u32(&mut self, v: u32) {
        self.bytes(&v.to_le_bytes());
    }
    /// Feeds a `u64`, little endian.
    fn u64(&mut self, v: u64) {
        self.bytes(&v.to_le_bytes());
    }
    /// Feeds a scalar's canonical bits.
    fn scalar<S: Scalar>(&mut self, v: S) {
        self.u64(v.to_hash_bits());
    }
    /// Feeds a vector (x then y).
    fn vec2<S: Scalar>(&mut self, v: Vec2<S>) {
        self.scalar(v.x);
        self.scalar(v.y);
    }
}

/// An FNV-1a-64 hasher fed with canonical little-endian values.
#[derive(Clone, Copy, Debug)]
pub struct StateHasher(u64);

impl Default for StateHasher {
    fn default() -> Self {
        StateHasher(FNV_OFFSET)
    }
}

impl StateHasher {
    /// Feeds raw bytes.
    pub fn bytes(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 ^= u64::from(b);
            self.0 = self.0.wrapping_mul(FNV_PRIME);
        }
    }
    /// Feeds one byte.
    pub fn u8(&mut self, v: u8) {
        self.bytes(&[v]);
    }
    /// Feeds a boolean as 0 or 1.
    pub fn bool(&mut self, v: bool) {
        self.u8(u8::from(v));
    }
    /// Feeds a `u32`, little endian.
    pub fn u32(&mut self, v: u32) {
        self.bytes(&v.to_le_bytes());
    }
    /// Feeds a `u64`, little endian.
    pub fn u64(&mut self, v: u64) {
        self.bytes(&v.to_le_bytes());
    }
    /// Feeds a scalar's canonical bits.
    pub fn scalar<S: Scalar>(&mut self, v: S) {
        self.u64(v.to_hash_bits());
    }
    /// Feeds a vector (x then y).
    pub fn vec2<S: Scalar>(&mut self, v: Vec2<S>) {
        self.scalar(v.x);
        self.scalar(v.y);
    }
    /// The digest so far.
    #[must_use]
    pub fn finish(&self) -> u64 {
        self.0
    }
}

impl StateSink for StateHasher {
    fn bytes(&mut self, bytes: &[u8]) {
        StateHasher::bytes(self, bytes);
    }
}

/// An FNV-1a-128 hasher fed with canonical little-endian values (the
/// 128-bit twin of [`StateHasher`]).
#[derive(Clone, Copy, Debug)]
pub struct StateHasher128(u128);

impl Default for StateHasher128 {
    fn default() -> Self {
        StateHasher128(FNV128_OFFSET)
    }
}

impl StateHasher128 {
    /// The digest so far.
    #[must_use]
    pub fn finish(&self) -> u128 {
        self.0
    }
}

impl StateSink for StateHasher128 {
    fn bytes(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 ^= u128::from(b);
            self.0 = self.0.wrapping_mul(FNV128_PRIME);
        }
    }
}

/// Number of parts of the state hash (see the module docs).
pub const PART_COUNT: usize = 6;

/// The per-part digests of a world's state (see the module docs).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StateDigest {
    /// Tick, scalar and settings.
    pub world: u64,
    /// Every body slot.
    pub bodies: u64,
    /// The contact cache (warm-start impulses, touching flags).
    pub contacts: u64,
    /// Sleeping islands.
    pub sleep: u64,
    /// The id allocator's free list.
    pub allocator: u64,
    /// Constraints (springs, ropes) and their solver state.
    pub constraints: u64,
}

impl StateDigest {
    /// The single 64-bit state hash combining all parts.
    #[must_use]
    pub fn combined(&self) -> u64 {
        let mut h = StateHasher::default();
        for (_, part) in self.parts() {
            h.u64(part);
        }
        h.finish()
    }

    /// Every part as `(name, digest)`, in hash order. Replays store these
    /// values so that a later mismatch can name the part.
    #[must_use]
    pub fn parts(&self) -> [(&'static str, u64); PART_COUNT] {
        [
            ("world", self.world),
            ("bodies", self.bodies),
            ("contacts", self.contacts),
            ("sleep", self.sleep),
            ("allocator", self.allocator),
            ("constraints", self.constraints),
        ]
    }

    /// Names of the parts that differ between two digests.
    #[must_use]
    pub fn differing_parts(&self, other: &StateDigest) -> Vec<&'static str> {
        self.parts()
            .into_iter()
            .zip(other.parts())
            .filter(|((_, a), (_, b))| a != b)
            .map(|((name, _), _)| name)
            .collect()
    }
}

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
            scratch: _,
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fnv1a_matches_the_published_test_vectors() {
        // FNV-1a 64 of "" and of "a" (from the FNV reference test suite).
        let empty = StateHasher::default();
        assert_eq!(empty.finish(), 0xcbf2_9ce4_8422_2325);
        let mut a = StateHasher::default();
        a.bytes(b"a");
        assert_eq!(a.finish(), 0xaf63_dc4c_8601_ec8c);
    }

    #[test]
    fn fnv1a_128_matches_the_published_test_vectors() {
        // FNV-1a 128 of "", "a" and "foobar" (FNV reference test suite).
        assert_eq!(
            StateHasher128::default().finish(),
            0x6c62_272e_07bb_0142_62b8_2175_6295_c58d
        );
        let mut a = StateHasher128::default();
        StateSink::bytes(&mut a, b"a");
        assert_eq!(a.finish(), 0xd228_cb69_6f1a_8caf_7891_2b70_4e4a_8964);
        let mut f = StateHasher128::default();
        StateSink::bytes(&mut f, b"foobar");
        assert_eq!(f.finish(), 0x343e_1662_793c_64bf_6f0d_3597_ba44_6f18);
    }

    #[test]
    fn values_are_fed_little_endian() {
        let mut x = StateHasher::default();
        x.u32(0x0403_0201);
        let mut y = StateHasher::default();
        y.bytes(&[1, 2, 3, 4]);
        assert_eq!(x.finish(), y.finish());
    }
}
