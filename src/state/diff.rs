//! Differences between two world states, in words a person can act on.
//!
//! ```
//! use clockwork2d::prelude::*;
//! use clockwork2d::diff::diff_snapshots;
//! let mut world = World::new(WorldSettings::default());
//! world.add_body(BodyDef::dynamic(Shape::circle(fx(0.5)))).unwrap();
//! let before = world.snapshot();
//! world.step();
//! let after = world.snapshot();
//! let differences = diff_snapshots(&before, &after).unwrap();
//! assert_eq!(differences[0].to_string(), "world: tick 0 vs 1");
//! assert!(differences.iter().any(|d| d.to_string().contains("body 0 (gen 0) position.y")));
//! ```
//!
//! Scalars are shown as their raw bits in hex (exact, as hashed) followed by
//! their decimal value (approximate, for reading).

use core::fmt;

use crate::dynamics::{Body, BodyId};
use crate::geometry::Shape;
use crate::math::Fx;
use crate::math::{Scalar, Vec2};
use crate::snapshot::SnapshotError;
use crate::world::World;

/// One difference between state A and state B.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Difference {
    /// The part of the state, named as in [`crate::hash::StateDigest`]
    /// (plus `"events"`).
    pub part: &'static str,
    /// What differs, e.g. `body 17 (gen 2) position.x 0x… (1.5) vs 0x… (1.25)`.
    pub description: String,
}

impl fmt::Display for Difference {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.part, self.description)
    }
}

/// Differences between two [`Fx`] snapshots (see [`diff_worlds`]).
///
/// # Errors
/// The [`SnapshotError`] of the first snapshot that cannot be restored.
pub fn diff_snapshots(a: &[u8], b: &[u8]) -> Result<Vec<Difference>, SnapshotError> {
    let a = World::<Fx>::restore(a)?;
    let b = World::<Fx>::restore(b)?;
    Ok(diff_worlds(&a, &b))
}

/// Every difference between two worlds, in the order of the state hash's
/// parts: world (tick, settings), bodies (slot by slot, field by field),
/// contacts, sleep, allocator, constraints, then events. Empty when the
/// states are identical (and so are their hashes).
#[must_use]
pub fn diff_worlds<S: Scalar>(a: &World<S>, b: &World<S>) -> Vec<Difference> {
    // Exhaustive on purpose (no `..`): a new field in `World` fails to
    // compile here until it is compared below (or named as derived).
    let World {
        settings: _,             // world
        tick: _,                 // world
        slots: _,                // bodies
        free_list: _,            // allocator
        contacts: _,             // contacts
        sleeping_islands: _,     // sleep
        constraint_slots: _,     // constraints
        constraint_free_list: _, // constraints
        events: _,               // events
        step_context: _,         // the step context: derived, never compared
    } = a;
    let mut d = Diff { out: Vec::new() };
    d.world(a, b);
    d.bodies(a, b);
    d.contacts(a, b);
    d.sleep(a, b);
    d.allocator(a, b);
    d.constraints(a, b);
    if a.events != b.events {
        d.push("events", format!("{:?} vs {:?}", a.events, b.events));
    }
    d.out
}

/// A scalar as exact bits and approximate decimal.
fn show<S: Scalar>(v: S) -> String {
    format!("0x{:016x} ({})", v.to_hash_bits(), v.to_f64())
}

struct Diff {
    out: Vec<Difference>,
}

impl Diff {
    fn push(&mut self, part: &'static str, description: String) {
        self.out.push(Difference { part, description });
    }

    fn scalar<S: Scalar>(&mut self, part: &'static str, what: &str, a: S, b: S) {
        if a.to_hash_bits() != b.to_hash_bits() {
            self.push(part, format!("{what} {} vs {}", show(a), show(b)));
        }
    }

    fn vec2<S: Scalar>(&mut self, part: &'static str, what: &str, a: Vec2<S>, b: Vec2<S>) {
        self.scalar(part, &format!("{what}.x"), a.x, b.x);
        self.scalar(part, &format!("{what}.y"), a.y, b.y);
    }

    fn plain<T: PartialEq + fmt::Debug>(&mut self, part: &'static str, what: &str, a: T, b: T) {
        if a != b {
            self.push(part, format!("{what} {a:?} vs {b:?}"));
        }
    }

    fn world<S: Scalar>(&mut self, a: &World<S>, b: &World<S>) {
        if a.tick != b.tick {
            self.push("world", format!("tick {} vs {}", a.tick, b.tick));
        }
        let (x, y) = (&a.settings, &b.settings);
        let p = "world";
        self.vec2(p, "settings.gravity", x.gravity, y.gravity);
        self.scalar(p, "settings.dt", x.dt, y.dt);
        self.plain(
            p,
            "settings.velocity_iterations",
            x.velocity_iterations,
            y.velocity_iterations,
        );
        self.plain(
            p,
            "settings.position_iterations",
            x.position_iterations,
            y.position_iterations,
        );
        self.plain(p, "settings.substeps", x.substeps, y.substeps);
        self.plain(
            p,
            "settings.sleep_enabled",
            x.sleep_enabled,
            y.sleep_enabled,
        );
        for (name, u, v) in [
            (
                "settings.sleep_linear_threshold",
                x.sleep_linear_threshold,
                y.sleep_linear_threshold,
            ),
            ("settings.time_to_sleep", x.time_to_sleep, y.time_to_sleep),
            (
                "settings.restitution_threshold",
                x.restitution_threshold,
                y.restitution_threshold,
            ),
            ("settings.linear_slop", x.linear_slop, y.linear_slop),
            (
                "settings.position_correction",
                x.position_correction,
                y.position_correction,
            ),
            (
                "settings.max_correction",
                x.max_correction,
                y.max_correction,
            ),
            (
                "settings.speculative_margin",
                x.speculative_margin,
                y.speculative_margin,
            ),
            ("settings.max_speed", x.max_speed, y.max_speed),
        ] {
            self.scalar(p, name, u, v);
        }
        self.vec2(
            p,
            "settings.bounds.center",
            x.bounds.center,
            y.bounds.center,
        );
        self.vec2(
            p,
            "settings.bounds.half_extents",
            x.bounds.half_extents,
            y.bounds.half_extents,
        );
    }

    fn bodies<S: Scalar>(&mut self, a: &World<S>, b: &World<S>) {
        let p = "bodies";
        if a.slots.len() != b.slots.len() {
            self.push(p, format!("{} slots vs {}", a.slots.len(), b.slots.len()));
        }
        for (index, (sa, sb)) in (0u32..).zip(a.slots.iter().zip(&b.slots)) {
            match (&sa.body, &sb.body) {
                (Some(x), Some(y)) if sa.generation == sb.generation => {
                    self.body(BodyId::from_parts(index, sa.generation), x, y);
                }
                (x, y) => {
                    let side = |generation: u32, body: &Option<Body<S>>| match body {
                        Some(_) => format!("{}", BodyId::from_parts(index, generation)),
                        None => format!("empty (gen {generation})"),
                    };
                    if sa.generation != sb.generation || x.is_some() != y.is_some() {
                        self.push(
                            p,
                            format!(
                                "slot {index}: {} vs {}",
                                side(sa.generation, x),
                                side(sb.generation, y)
                            ),
                        );
                    }
                }
            }
        }
        for (index, slot) in (0u32..).zip(&a.slots).skip(b.slots.len()) {
            self.push(
                p,
                format!("slot {index} (gen {}) only in A", slot.generation),
            );
        }
        for (index, slot) in (0u32..).zip(&b.slots).skip(a.slots.len()) {
            self.push(
                p,
                format!("slot {index} (gen {}) only in B", slot.generation),
            );
        }
    }

    fn body<S: Scalar>(&mut self, id: BodyId, x: &Body<S>, y: &Body<S>) {
        let p = "bodies";
        let f = |field: &str| format!("{id} {field}");
        self.plain(p, &f("kind"), x.kind, y.kind);
        match (x.shape, y.shape) {
            (Shape::Circle { radius: r }, Shape::Circle { radius: s }) => {
                self.scalar(p, &f("shape.radius"), r, s);
            }
            (Shape::Aabb { half_extents: h }, Shape::Aabb { half_extents: k }) => {
                self.vec2(p, &f("shape.half_extents"), h, k);
            }
            (u, v) => self.push(p, format!("{} {u:?} vs {v:?}", f("shape"))),
        }
        self.vec2(p, &f("position"), x.position, y.position);
        self.vec2(p, &f("velocity"), x.velocity, y.velocity);
        self.scalar(p, &f("mass"), x.mass, y.mass);
        self.scalar(p, &f("inverse_mass"), x.inverse_mass, y.inverse_mass);
        self.scalar(p, &f("restitution"), x.restitution, y.restitution);
        self.scalar(p, &f("friction"), x.friction, y.friction);
        self.scalar(p, &f("gravity_scale"), x.gravity_scale, y.gravity_scale);
        self.plain(p, &f("bullet"), x.bullet, y.bullet);
        self.plain(p, &f("awake"), x.awake, y.awake);
        self.plain(p, &f("frozen"), x.frozen, y.frozen);
        self.scalar(p, &f("sleep_time"), x.sleep_time, y.sleep_time);
        self.plain(p, &f("island"), x.island, y.island);
    }

    fn contacts<S: Scalar>(&mut self, a: &World<S>, b: &World<S>) {
        let p = "contacts";
        // Both lists are sorted by pair: a merge join.
        let (mut i, mut j) = (0, 0);
        loop {
            match (a.contacts.get(i), b.contacts.get(j)) {
                (Some(x), Some(y)) if (x.a, x.b) == (y.a, y.b) => {
                    let w = format!("contact ({}, {})", x.a, x.b);
                    self.scalar(
                        p,
                        &format!("{w} normal_impulse"),
                        x.normal_impulse,
                        y.normal_impulse,
                    );
                    self.scalar(
                        p,
                        &format!("{w} tangent_impulse"),
                        x.tangent_impulse,
                        y.tangent_impulse,
                    );
                    self.plain(p, &format!("{w} touching"), x.touching, y.touching);
                    i += 1;
                    j += 1;
                }
                (Some(x), y) if y.is_none_or(|y| (x.a, x.b) < (y.a, y.b)) => {
                    self.push(p, format!("contact ({}, {}) only in A", x.a, x.b));
                    i += 1;
                }
                (_, Some(y)) => {
                    self.push(p, format!("contact ({}, {}) only in B", y.a, y.b));
                    j += 1;
                }
                _ => break,
            }
        }
    }

    fn sleep<S: Scalar>(&mut self, a: &World<S>, b: &World<S>) {
        let p = "sleep";
        for (key, members) in &a.sleeping_islands {
            match b.sleeping_islands.get(key) {
                None => self.push(p, format!("island {key} {members:?} only in A")),
                Some(other) if other != members => {
                    self.push(p, format!("island {key} members {members:?} vs {other:?}"));
                }
                Some(_) => {}
            }
        }
        for (key, members) in &b.sleeping_islands {
            if !a.sleeping_islands.contains_key(key) {
                self.push(p, format!("island {key} {members:?} only in B"));
            }
        }
    }

    fn allocator<S: Scalar>(&mut self, a: &World<S>, b: &World<S>) {
        if a.free_list != b.free_list {
            self.push(
                "allocator",
                format!("free list {:?} vs {:?}", a.free_list, b.free_list),
            );
        }
    }

    fn constraints<S: Scalar>(&mut self, a: &World<S>, b: &World<S>) {
        let p = "constraints";
        let (x, y) = (&a.constraint_slots, &b.constraint_slots);
        if x.len() != y.len() {
            self.push(p, format!("{} constraint slots vs {}", x.len(), y.len()));
        }
        for (index, (sa, sb)) in x.iter().zip(y).enumerate() {
            if sa.generation != sb.generation {
                self.push(
                    p,
                    format!(
                        "constraint slot {index} generation {} vs {}",
                        sa.generation, sb.generation
                    ),
                );
            }
            match (&sa.entry, &sb.entry) {
                (Some(u), Some(v)) => {
                    let w = format!("constraint {index} (gen {})", sa.generation);
                    if u.constraint != v.constraint {
                        self.push(p, format!("{w} {:?} vs {:?}", u.constraint, v.constraint));
                    }
                    self.scalar(p, &format!("{w} impulse"), u.impulse, v.impulse);
                }
                (None, None) => {}
                (u, v) => self.push(
                    p,
                    format!(
                        "constraint slot {index}: {} vs {}",
                        if u.is_some() { "live" } else { "empty" },
                        if v.is_some() { "live" } else { "empty" }
                    ),
                ),
            }
        }
        if a.constraint_free_list != b.constraint_free_list {
            self.push(
                p,
                format!(
                    "constraint free list {:?} vs {:?}",
                    a.constraint_free_list, b.constraint_free_list
                ),
            );
        }
    }
}
