//! The snapshot payload: a compact, lossless image of a [`World`].
//!
//! Plain serde of `World` costs about 120 bytes per body, mostly because
//! every body repeats its shape, mass, inverse mass and material (about 50
//! bytes that are the same for every box of a pyramid). The payload keeps
//! those in a table of *prototypes* (deduplicated by exact bits, numbered in
//! order of first use) and each body names its prototype; contacts store
//! their slot pair as small deltas; the island key of an awake body
//! (`u32::MAX`) is stored as 0 by shifting by one. Everything is bincode's
//! standard configuration: little-endian varints, so small numbers take one
//! byte.
//!
//! Decoding bounds every table (see the `MAX_*` constants) so a small file
//! cannot make the decoder allocate gigabytes, then [`World::validate`]
//! checks the rebuilt world.

use serde::{Deserialize, Serialize};
use std::collections::BTreeMap;

use super::bounded_seq::bounded;
use super::error::SnapshotError;
use crate::collision::CachedContact;
use crate::constraints::ConstraintSlot;
use crate::dynamics::{Body, BodyKind};
use crate::geometry::Shape;
use crate::math::{Scalar, Vec2};
use crate::solver::StepContext;
use crate::world::{Event, Slot, World, WorldSettings};

/// Most body slots a snapshot may hold (2²¹, twice the largest scene).
/// Bounds decoding memory: an empty slot is 2 bytes in the file but over
/// 100 in memory.
pub const MAX_SNAPSHOT_SLOTS: usize = 1 << 21;
/// Most body prototypes (at most one per slot).
const MAX_PROTOS: usize = MAX_SNAPSHOT_SLOTS;
/// Most constraint slots a snapshot may hold (2²¹), for the same reason.
pub const MAX_SNAPSHOT_CONSTRAINTS: usize = 1 << 21;
/// Most cached contacts (2²³, four per body slot): each is at least 5
/// bytes in the file but about 64 in memory while decoding.
const MAX_CONTACTS: usize = 1 << 23;
/// Most sleeping islands (at most one per slot).
const MAX_ISLANDS: usize = MAX_SNAPSHOT_SLOTS;

/// Awake flag bit.
const FLAG_AWAKE: u8 = 1;
/// Frozen flag bit.
const FLAG_FROZEN: u8 = 2;

/// What bodies share: kind, shape, mass and material.
#[derive(Clone, Copy, Debug, Serialize, Deserialize)]
#[serde(bound = "")]
struct Proto<S: Scalar> {
    kind: BodyKind,
    shape: Shape<S>,
    mass: S,
    inverse_mass: S,
    restitution: S,
    friction: S,
    gravity_scale: S,
    bullet: bool,
}

/// Exact identity of a prototype (scalar bits, so `-0.0` and `0.0` of the
/// float reference types stay distinct and the image is lossless).
type ProtoKey = (u8, u8, [u64; 7], bool);

impl<S: Scalar> Proto<S> {
    fn of(b: &Body<S>) -> Self {
        Proto {
            kind: b.kind,
            shape: b.shape,
            mass: b.mass,
            inverse_mass: b.inverse_mass,
            restitution: b.restitution,
            friction: b.friction,
            gravity_scale: b.gravity_scale,
            bullet: b.bullet,
        }
    }

    fn key(&self) -> ProtoKey {
        let kind = match self.kind {
            BodyKind::Fixed => 0,
            BodyKind::Kinematic => 1,
            BodyKind::Dynamic => 2,
        };
        let (tag, x, y) = match self.shape {
            Shape::Circle { radius } => (0, radius.to_hash_bits(), 0),
            Shape::Aabb { half_extents } => (
                1,
                half_extents.x.to_hash_bits(),
                half_extents.y.to_hash_bits(),
            ),
        };
        let bits = [
            x,
            y,
            self.mass.to_hash_bits(),
            self.inverse_mass.to_hash_bits(),
            self.restitution.to_hash_bits(),
            self.friction.to_hash_bits(),
            self.gravity_scale.to_hash_bits(),
        ];
        (kind, tag, bits, self.bullet)
    }
}

/// The per-body state.
#[derive(Clone, Copy, Debug, Serialize, Deserialize)]
#[serde(bound = "")]
struct CompactBody<S: Scalar> {
    proto: u32,
    position: Vec2<S>,
    velocity: Vec2<S>,
    flags: u8,
    sleep_time: S,
    /// The island key plus one (wrapping), so "no island" is 0: one byte.
    island_plus_one: u32,
}

#[derive(Clone, Copy, Debug, Serialize, Deserialize)]
#[serde(bound = "")]
struct CompactSlot<S: Scalar> {
    generation: u32,
    body: Option<CompactBody<S>>,
}

/// A cached contact with its pair as deltas: `a` from the previous
/// contact's `a`, `b` from `a` (wrapping, so any list round-trips exactly;
/// validation then insists on the sorted order the engine keeps).
#[derive(Clone, Copy, Debug, Serialize, Deserialize)]
#[serde(bound = "")]
struct CompactContact<S: Scalar> {
    a_delta: u32,
    b_delta: u32,
    normal_impulse: S,
    tangent_impulse: S,
    touching: bool,
}

/// The payload as written: borrowed where the world's own layout is
/// already compact. Field order must match [`PayloadIn`].
#[derive(Serialize)]
#[serde(bound = "")]
struct PayloadOut<'a, S: Scalar> {
    settings: &'a WorldSettings<S>,
    tick: u64,
    protos: Vec<Proto<S>>,
    slots: Vec<CompactSlot<S>>,
    free_list: &'a [u32],
    contacts: Vec<CompactContact<S>>,
    sleeping_islands: Vec<(u32, &'a [u32])>,
    constraint_slots: &'a [ConstraintSlot<S>],
    constraint_free_list: &'a [u32],
    events: &'a [Event],
}

/// The payload as read, every table bounded. Field order must match
/// [`PayloadOut`].
#[derive(Deserialize)]
#[serde(bound = "")]
struct PayloadIn<S: Scalar> {
    settings: WorldSettings<S>,
    tick: u64,
    #[serde(deserialize_with = "bounded::<_, _, MAX_PROTOS>")]
    protos: Vec<Proto<S>>,
    #[serde(deserialize_with = "bounded::<_, _, MAX_SNAPSHOT_SLOTS>")]
    slots: Vec<CompactSlot<S>>,
    #[serde(deserialize_with = "bounded::<_, _, MAX_SNAPSHOT_SLOTS>")]
    free_list: Vec<u32>,
    #[serde(deserialize_with = "bounded::<_, _, MAX_CONTACTS>")]
    contacts: Vec<CompactContact<S>>,
    #[serde(deserialize_with = "bounded::<_, _, MAX_ISLANDS>")]
    sleeping_islands: Vec<(u32, Vec<u32>)>,
    #[serde(deserialize_with = "bounded::<_, _, MAX_SNAPSHOT_CONSTRAINTS>")]
    constraint_slots: Vec<ConstraintSlot<S>>,
    #[serde(deserialize_with = "bounded::<_, _, MAX_SNAPSHOT_CONSTRAINTS>")]
    constraint_free_list: Vec<u32>,
    #[serde(deserialize_with = "bounded::<_, _, MAX_CONTACTS>")]
    events: Vec<Event>,
}

/// Encodes the world's state (everything but the derived step context).
pub(crate) fn encode<S: Scalar>(world: &World<S>) -> Vec<u8> {
    // Exhaustive on purpose: a new field in `World` fails to compile here
    // until it is written to the payload (and checked in `validate`), so a
    // snapshot can never silently drop state.
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
    } = world;
    let mut protos = Vec::new();
    let mut proto_index: BTreeMap<ProtoKey, u32> = BTreeMap::new();
    let compact_slots = slots
        .iter()
        .map(|slot| CompactSlot {
            generation: slot.generation,
            body: slot.body.as_ref().map(|b| {
                let proto = Proto::of(b);
                let next = u32::try_from(protos.len()).unwrap_or(u32::MAX);
                let index = *proto_index.entry(proto.key()).or_insert_with(|| {
                    protos.push(proto);
                    next
                });
                CompactBody {
                    proto: index,
                    position: b.position,
                    velocity: b.velocity,
                    flags: u8::from(b.awake) * FLAG_AWAKE + u8::from(b.frozen) * FLAG_FROZEN,
                    sleep_time: b.sleep_time,
                    island_plus_one: b.island.wrapping_add(1),
                }
            }),
        })
        .collect();
    let mut previous_a = 0u32;
    let compact_contacts = contacts
        .iter()
        .map(|c| {
            let out = CompactContact {
                a_delta: c.a.wrapping_sub(previous_a),
                b_delta: c.b.wrapping_sub(c.a),
                normal_impulse: c.normal_impulse,
                tangent_impulse: c.tangent_impulse,
                touching: c.touching,
            };
            previous_a = c.a;
            out
        })
        .collect();
    let payload = PayloadOut {
        settings,
        tick: *tick,
        protos,
        slots: compact_slots,
        free_list,
        contacts: compact_contacts,
        sleeping_islands: sleeping_islands
            .iter()
            .map(|(k, members)| (*k, members.as_slice()))
            .collect(),
        constraint_slots,
        constraint_free_list,
        events,
    };
    super::envelope::encode(&payload)
}

/// Decodes a payload into a world. The world is *not* validated yet.
pub(crate) fn decode<S: Scalar>(payload: &[u8]) -> Result<World<S>, SnapshotError> {
    let p: PayloadIn<S> = super::envelope::decode(payload)?;
    let proto_count = p.protos.len();
    let mut slots = Vec::with_capacity(p.slots.len());
    for (index, slot) in p.slots.iter().enumerate() {
        let body = match slot.body {
            None => None,
            Some(c) => {
                let proto = usize::try_from(c.proto)
                    .ok()
                    .and_then(|i| p.protos.get(i))
                    .ok_or_else(|| {
                        SnapshotError::invalid(
                            "bodies",
                            format!("slot {index} names prototype {} of {proto_count}", c.proto),
                        )
                    })?;
                if c.flags & !(FLAG_AWAKE | FLAG_FROZEN) != 0 {
                    return Err(SnapshotError::invalid(
                        "bodies",
                        format!("slot {index} has unknown flag bits 0x{:02x}", c.flags),
                    ));
                }
                Some(Body {
                    kind: proto.kind,
                    shape: proto.shape,
                    position: c.position,
                    velocity: c.velocity,
                    mass: proto.mass,
                    inverse_mass: proto.inverse_mass,
                    restitution: proto.restitution,
                    friction: proto.friction,
                    gravity_scale: proto.gravity_scale,
                    bullet: proto.bullet,
                    awake: c.flags & FLAG_AWAKE != 0,
                    frozen: c.flags & FLAG_FROZEN != 0,
                    sleep_time: c.sleep_time,
                    island: c.island_plus_one.wrapping_sub(1),
                })
            }
        };
        slots.push(Slot {
            generation: slot.generation,
            body,
        });
    }
    let mut previous_a = 0u32;
    let contacts = p
        .contacts
        .iter()
        .map(|c| {
            let a = previous_a.wrapping_add(c.a_delta);
            previous_a = a;
            CachedContact {
                a,
                b: a.wrapping_add(c.b_delta),
                normal_impulse: c.normal_impulse,
                tangent_impulse: c.tangent_impulse,
                touching: c.touching,
            }
        })
        .collect();
    let mut sleeping_islands = BTreeMap::new();
    let mut previous_key = None;
    for (key, members) in p.sleeping_islands {
        // The writer emits keys in map order; anything else (including a
        // repeated key, which a map would silently merge) is refused.
        if previous_key.is_some_and(|k| k >= key) {
            return Err(SnapshotError::invalid(
                "sleep",
                format!("island keys are not strictly increasing at key {key}"),
            ));
        }
        previous_key = Some(key);
        sleeping_islands.insert(key, members);
    }
    Ok(World {
        settings: p.settings,
        tick: p.tick,
        slots,
        free_list: p.free_list,
        contacts,
        sleeping_islands,
        constraint_slots: p.constraint_slots,
        constraint_free_list: p.constraint_free_list,
        events: p.events,
        step_context: StepContext::default(),
    })
}
