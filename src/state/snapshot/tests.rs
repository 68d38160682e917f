//! Invalid contents: worlds broken field by field (which only crate code
//! can do), snapshotted (encoding does not validate) and refused on
//! restore with the right part named.

use super::SnapshotError;
use crate::collision::CachedContact;
use crate::constraints::{Anchor, Constraint};
use crate::dynamics::{BodyDef, NO_ISLAND};
use crate::geometry::Shape;
use crate::math::{Fx, Scalar, Vec2, fx};
use crate::world::{World, WorldSettings};

/// A small world that has contacts, a sleeping island, a free slot and a
/// constraint.
fn sample() -> World {
    let mut w = World::new(WorldSettings::default());
    w.add_body(
        BodyDef::fixed(Shape::aabb(Vec2::new(fx(20.0), fx(0.5))))
            .position(Vec2::new(fx(0.0), fx(-0.5))),
    )
    .unwrap();
    for i in 0..4 {
        w.add_body(
            BodyDef::dynamic(Shape::aabb(Vec2::new(fx(0.5), fx(0.5))))
                .position(Vec2::new(fx(0.0), Fx::from_ratio(2 * i + 1, 2))),
        )
        .unwrap();
    }
    let gone = w
        .add_body(BodyDef::dynamic(Shape::circle(fx(0.25))).position(Vec2::new(fx(5.0), fx(3.0))))
        .unwrap();
    w.remove_body(gone).unwrap();
    let ball = w
        .add_body(BodyDef::dynamic(Shape::circle(fx(0.25))).position(Vec2::new(fx(8.0), fx(3.0))))
        .unwrap();
    w.add_constraint(Constraint::rope(
        Anchor::Point(Vec2::new(fx(8.0), fx(5.0))),
        Anchor::Body(ball),
        fx(2.5),
    ))
    .unwrap();
    let extra = w
        .add_body(BodyDef::dynamic(Shape::circle(fx(0.25))).position(Vec2::new(fx(-8.0), fx(3.0))))
        .unwrap();
    w.remove_body(extra).unwrap();
    for _ in 0..240 {
        w.step();
    }
    assert!(!w.sleeping_islands.is_empty(), "the stack should sleep");
    assert!(!w.contacts.is_empty());
    assert!(!w.free_list.is_empty());
    w
}

/// Restoring `w`'s snapshot must fail with `Invalid` in `part`.
#[track_caller]
fn refused(w: &World, part: &str) {
    match World::<Fx>::restore(&w.snapshot()) {
        Err(SnapshotError::Invalid(state)) => {
            assert_eq!(state.part, part, "wrong part for: {state}");
            assert!(!state.detail.is_empty());
        }
        other => panic!("expected Invalid({part}), got {other:?}"),
    }
}

fn first_dynamic(w: &World) -> usize {
    w.slots
        .iter()
        .position(|s| s.body.as_ref().is_some_and(|b| b.inverse_mass != Fx::ZERO))
        .unwrap()
}

#[test]
fn the_sample_restores() {
    let w = sample();
    let r = World::<Fx>::restore(&w.snapshot()).unwrap();
    assert_eq!(r.state_hash(), w.state_hash());
}

#[test]
fn bad_settings_are_refused() {
    let mut w = sample();
    w.settings.velocity_iterations = 0;
    refused(&w, "world");
    let mut w = sample();
    w.settings.dt = Fx::ZERO;
    refused(&w, "world");
}

#[test]
fn bad_bodies_are_refused() {
    let i = first_dynamic(&sample());
    type Breaker = Box<dyn Fn(&mut World)>;
    let cases: Vec<(&str, Breaker)> = vec![
        (
            "negative radius",
            Box::new(move |w: &mut World| {
                w.slots[i].body.as_mut().unwrap().shape = Shape::Circle { radius: fx(-1.0) };
            }),
        ),
        (
            "zero half extent",
            Box::new(move |w: &mut World| {
                w.slots[i].body.as_mut().unwrap().shape = Shape::Aabb {
                    half_extents: Vec2::new(fx(0.0), fx(1.0)),
                };
            }),
        ),
        (
            "inverse mass",
            Box::new(move |w: &mut World| {
                w.slots[i].body.as_mut().unwrap().inverse_mass = fx(3.0);
            }),
        ),
        (
            "zero mass",
            Box::new(move |w: &mut World| {
                w.slots[i].body.as_mut().unwrap().mass = Fx::ZERO;
            }),
        ),
        (
            "fixed with mass",
            Box::new(move |w: &mut World| {
                w.slots[0].body.as_mut().unwrap().mass = fx(1.0);
            }),
        ),
        (
            "restitution",
            Box::new(move |w: &mut World| {
                w.slots[i].body.as_mut().unwrap().restitution = fx(2.0);
            }),
        ),
        (
            "out of bounds",
            Box::new(move |w: &mut World| {
                w.slots[i].body.as_mut().unwrap().position = Vec2::new(fx(40000.0), fx(0.0));
            }),
        ),
        (
            "frozen outside the limit",
            Box::new(move |w: &mut World| {
                let b = w.slots[i].body.as_mut().unwrap();
                b.frozen = true;
                b.awake = true;
                b.island = NO_ISLAND;
                b.position = Vec2::new(Fx::MAX, fx(0.0));
            }),
        ),
        (
            "negative sleep time",
            Box::new(move |w: &mut World| {
                w.slots[i].body.as_mut().unwrap().sleep_time = fx(-1.0);
            }),
        ),
        (
            "awake fixed body",
            Box::new(move |w: &mut World| {
                w.slots[0].body.as_mut().unwrap().awake = true;
            }),
        ),
        (
            "fixed bullet",
            Box::new(move |w: &mut World| {
                w.slots[0].body.as_mut().unwrap().bullet = true;
            }),
        ),
    ];
    for (name, break_it) in cases {
        let mut w = sample();
        break_it(&mut w);
        match World::<Fx>::restore(&w.snapshot()) {
            Err(SnapshotError::Invalid(state)) => assert!(
                state.part == "bodies" || state.part == "sleep",
                "{name}: {state}"
            ),
            other => panic!("{name}: expected Invalid, got {other:?}"),
        }
    }
}

#[test]
fn bad_allocators_are_refused() {
    let mut w = sample();
    w.free_list.push(0); // slot 0 is live
    refused(&w, "allocator");
    let mut w = sample();
    let f = w.free_list[0];
    w.free_list.push(f); // listed twice
    refused(&w, "allocator");
    let mut w = sample();
    w.free_list.push(10_000); // out of range
    refused(&w, "allocator");
    let mut w = sample();
    w.free_list.pop(); // an empty slot not listed
    refused(&w, "allocator");
}

#[test]
fn bad_contacts_are_refused() {
    let live = |w: &World| w.contacts[0];
    let mut w = sample();
    let c = live(&w);
    w.contacts.push(c); // repeated pair (also unsorted)
    refused(&w, "contacts");
    let mut w = sample();
    w.contacts.reverse();
    refused(&w, "contacts");
    let mut w = sample();
    w.contacts[0] = CachedContact {
        a: live(&w).b,
        b: live(&w).a,
        ..live(&w)
    };
    refused(&w, "contacts");
    let mut w = sample();
    let dead = w.free_list[0];
    w.contacts.insert(
        0,
        CachedContact {
            a: 0,
            b: dead,
            normal_impulse: Fx::ZERO,
            tangent_impulse: Fx::ZERO,
            touching: true,
        },
    );
    w.contacts.sort_by_key(|c| (c.a, c.b));
    refused(&w, "contacts");
    let mut w = sample();
    w.contacts.push(CachedContact {
        a: 1,
        b: u32::MAX,
        ..live(&w)
    });
    refused(&w, "contacts");
    let mut w = sample();
    w.contacts[0].normal_impulse = fx(-1.0);
    refused(&w, "contacts");
}

#[test]
fn bad_sleep_is_refused() {
    // A sleeper missing from its island.
    let mut w = sample();
    let (&key, _) = w.sleeping_islands.iter().next().unwrap();
    w.sleeping_islands.get_mut(&key).unwrap().pop();
    refused(&w, "sleep");
    // An island naming an awake body.
    let mut w = sample();
    let (_, members) = w.sleeping_islands.iter().next().unwrap();
    let m = members[0] as usize;
    let b = w.slots[m].body.as_mut().unwrap();
    b.awake = true;
    b.island = NO_ISLAND;
    refused(&w, "sleep");
    // An empty island.
    let mut w = sample();
    w.sleeping_islands.insert(9999, Vec::new());
    refused(&w, "sleep");
    // A dead member.
    let mut w = sample();
    let dead = w.free_list[0];
    w.sleeping_islands.insert(9999, vec![dead]);
    refused(&w, "sleep");
    // A member whose island key disagrees.
    let mut w = sample();
    let (&key, members) = w.sleeping_islands.iter().next().unwrap();
    let m = members[0] as usize;
    w.slots[m].body.as_mut().unwrap().island = key + 1;
    refused(&w, "sleep");
}

#[test]
fn bad_constraints_are_refused() {
    // An anchor naming a dead body.
    let mut w = sample();
    let dead = w.free_list[0];
    let gen_now = w.slots[dead as usize].generation;
    let entry = w
        .constraint_slots
        .iter_mut()
        .find_map(|s| s.entry.as_mut())
        .unwrap();
    entry.constraint = Constraint::rope(
        Anchor::Point(Vec2::new(fx(0.0), fx(5.0))),
        Anchor::Body(crate::dynamics::BodyId::from_parts(dead, gen_now)),
        fx(1.0),
    );
    refused(&w, "constraints");
    // A free list that does not match.
    let mut w = sample();
    w.constraint_free_list.push(0);
    refused(&w, "constraints");
}

#[test]
fn an_awake_body_with_an_island_key_is_refused() {
    let mut w = sample();
    let i = first_dynamic(&w);
    w.slots[i].body.as_mut().unwrap().awake = true;
    w.slots[i].body.as_mut().unwrap().island = 5;
    refused(&w, "bodies");
}
