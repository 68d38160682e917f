//! The world's API contract (issue 3): validation with specific errors and
//! an unchanged world on error, stale ids refused by every entry point,
//! commands from an untrusted peer that can never panic, the documented
//! event order, and queries that never mutate and sort as documented.
//!
//! "Unchanged" is checked with `state_hash()`, which covers everything that
//! affects a later step (tick, settings, every slot, contact cache, sleeping
//! islands, id allocator), and where it matters by comparing with a clone
//! that never saw the refused request.

mod common;

use clockwork2d::prelude::*;
use common::{add_ground, add_stack};
use proptest::prelude::*;

/// A world with some history: ground, a settling 3-box stack, a ball.
fn busy_world() -> World {
    let mut w = World::new(WorldSettings::default());
    add_ground(&mut w);
    add_stack(&mut w, 3, 0.05);
    w.add_body(BodyDef::dynamic(Shape::circle(fx(0.3))).position(vec2(3.0, 2.0)))
        .unwrap();
    for _ in 0..20 {
        w.step();
    }
    w
}

// ---------------------------------------------------------------- add_body

#[test]
fn invalid_definitions_are_refused_with_the_specific_error_and_change_nothing() {
    let dynamic = |shape| BodyDef::dynamic(shape).position(vec2(0.0, 5.0));
    let circle = |r: f64| Shape::circle(fx(r));
    let aabb = |x: f64, y: f64| Shape::aabb(vec2(x, y));
    let cases: Vec<(&str, BodyDef, WorldError)> = vec![
        (
            "zero radius",
            dynamic(circle(0.0)),
            WorldError::NonPositiveSize,
        ),
        (
            "negative radius",
            dynamic(circle(-0.5)),
            WorldError::NonPositiveSize,
        ),
        (
            "most negative radius",
            dynamic(Shape::circle(Fx::MIN)),
            WorldError::NonPositiveSize,
        ),
        (
            "zero half width",
            dynamic(aabb(0.0, 1.0)),
            WorldError::NonPositiveSize,
        ),
        (
            "zero half height",
            dynamic(aabb(1.0, 0.0)),
            WorldError::NonPositiveSize,
        ),
        (
            "negative half width",
            dynamic(aabb(-1.0, 1.0)),
            WorldError::NonPositiveSize,
        ),
        (
            "negative half height",
            dynamic(aabb(1.0, -1e-9)),
            WorldError::NonPositiveSize,
        ),
        (
            "fixed, zero radius",
            BodyDef::fixed(circle(0.0)),
            WorldError::NonPositiveSize,
        ),
        (
            "kinematic, zero extent",
            BodyDef::kinematic(aabb(0.0, 0.0)),
            WorldError::NonPositiveSize,
        ),
        (
            "zero density",
            dynamic(circle(0.5)).density(fx(0.0)),
            WorldError::NonPositiveMass,
        ),
        (
            "negative density",
            dynamic(circle(0.5)).density(fx(-1.0)),
            WorldError::NonPositiveMass,
        ),
        (
            "zero mass",
            dynamic(aabb(0.5, 0.5)).mass(fx(0.0)),
            WorldError::NonPositiveMass,
        ),
        (
            "negative mass",
            dynamic(aabb(0.5, 0.5)).mass(fx(-2.0)),
            WorldError::NonPositiveMass,
        ),
        (
            "x beyond +bounds",
            dynamic(circle(0.5)).position(vec2(40_000.0, 0.0)),
            WorldError::OutOfBounds,
        ),
        (
            "y beyond -bounds",
            dynamic(circle(0.5)).position(vec2(0.0, -33_000.0)),
            WorldError::OutOfBounds,
        ),
        (
            "fixed beyond bounds",
            BodyDef::fixed(aabb(1.0, 1.0)).position(vec2(-32_769.0, 0.0)),
            WorldError::OutOfBounds,
        ),
    ];
    let mut world = busy_world();
    let untouched = world.clone();
    for (name, def, expected) in cases {
        let (hash, count) = (world.state_hash(), world.body_count());
        assert_eq!(world.add_body(def), Err(expected.clone()), "{name}");
        assert_eq!(world.state_hash(), hash, "{name}: the world changed");
        assert_eq!(world.body_count(), count, "{name}: the body count changed");
        // The same definition as a command is refused the same way.
        assert_eq!(
            world.apply(Command::Spawn(def)),
            Err(expected),
            "{name} (command)"
        );
        assert_eq!(
            world.state_hash(),
            hash,
            "{name}: the world changed (command)"
        );
    }
    // No id was consumed: the next body gets the id it would have got, and
    // both worlds continue identically.
    let mut reference = untouched;
    let def = BodyDef::dynamic(Shape::circle(fx(0.5))).position(vec2(-3.0, 3.0));
    assert_eq!(world.add_body(def), reference.add_body(def));
    for _ in 0..30 {
        world.step();
        reference.step();
    }
    assert_eq!(world.state_hash(), reference.state_hash());
}

#[test]
fn positions_at_the_bounds_are_accepted_and_just_beyond_refused() {
    let settings = WorldSettings {
        bounds: Aabb::new(vec2(0.0, 0.0), vec2(100.0, 50.0)),
        ..WorldSettings::default()
    };
    let mut world = World::new(settings);
    let def = |x, y| BodyDef::fixed(Shape::circle(fx(0.5))).position(vec2(x, y));
    assert!(
        world.add_body(def(100.0, -50.0)).is_ok(),
        "the boundary is inside"
    );
    let hash = world.state_hash();
    let just_beyond = Fx::from_num(100) + Fx::DELTA;
    let beyond = BodyDef::fixed(Shape::circle(fx(0.5))).position(Vec2::new(just_beyond, Fx::ZERO));
    assert_eq!(world.add_body(beyond), Err(WorldError::OutOfBounds));
    assert_eq!(world.add_body(def(0.0, 50.5)), Err(WorldError::OutOfBounds));
    assert_eq!(world.state_hash(), hash);
}

// ---------------------------------------------------------------- stale ids

/// Every command variant naming `id`.
fn every_command(id: BodyId) -> Vec<Command> {
    vec![
        Command::Despawn(id),
        Command::ApplyImpulse {
            body: id,
            impulse: vec2(1.0, 0.0),
        },
        Command::SetVelocity {
            body: id,
            velocity: vec2(0.0, 1.0),
        },
        Command::SetPosition {
            body: id,
            position: vec2(0.0, 3.0),
        },
        Command::Wake(id),
    ]
}

fn assert_refused_everywhere(world: &mut World, id: BodyId, what: &str) {
    let hash = world.state_hash();
    assert!(world.body(id).is_none(), "{what}: body() found it");
    assert_eq!(
        world.remove_body(id).err(),
        Some(WorldError::UnknownBody(id)),
        "{what}: remove_body"
    );
    assert_eq!(
        world.state_hash(),
        hash,
        "{what}: remove_body changed the world"
    );
    for command in every_command(id) {
        assert_eq!(
            world.apply(command.clone()),
            Err(WorldError::UnknownBody(id)),
            "{what}: {command:?}"
        );
        assert_eq!(
            world.state_hash(),
            hash,
            "{what}: {command:?} changed the world"
        );
    }
}

#[test]
fn stale_and_unknown_ids_are_refused_by_remove_body_and_every_command() {
    let mut world = busy_world();
    let ball = world
        .add_body(BodyDef::dynamic(Shape::circle(fx(0.25))).position(vec2(-4.0, 1.0)))
        .unwrap();
    world.step();
    let removed = world.remove_body(ball).expect("first removal");
    assert_eq!(removed.kind(), BodyKind::Dynamic);
    assert_refused_everywhere(&mut world, ball, "removed body");

    // The slot is reused with a new generation; the old id still names
    // nothing, and commands with it do not reach the new body.
    let newcomer = world
        .add_body(BodyDef::dynamic(Shape::circle(fx(0.25))).position(vec2(-4.0, 1.0)))
        .unwrap();
    assert_eq!(newcomer.index(), ball.index(), "the freed slot is reused");
    assert_ne!(newcomer.generation(), ball.generation());
    assert_refused_everywhere(&mut world, ball, "stale id of a reused slot");
    assert!(world.body(newcomer).is_some());

    // Ids that were never issued.
    assert_refused_everywhere(
        &mut world,
        BodyId::from_parts(12_345, 0),
        "never-issued index",
    );
    let future = BodyId::from_parts(newcomer.index(), newcomer.generation() + 5);
    assert_refused_everywhere(&mut world, future, "future generation");
    assert_refused_everywhere(
        &mut world,
        BodyId::from_parts(u32::MAX, u32::MAX),
        "u32::MAX",
    );

    // Inside step_with: each refused command reports UnknownBody, and the
    // tick is exactly the tick without them.
    let mut reference = world.clone();
    let results = world.step_with(&every_command(ball));
    assert_eq!(results, vec![Err(WorldError::UnknownBody(ball)); 5]);
    reference.step();
    assert_eq!(world.state_hash(), reference.state_hash());
}

#[test]
fn commands_of_the_wrong_kind_are_refused_and_change_nothing() {
    let mut world = busy_world();
    let ground = world.bodies().next().unwrap().0;
    let platform = world
        .add_body(BodyDef::kinematic(Shape::aabb(vec2(1.0, 0.2))).position(vec2(-6.0, 3.0)))
        .unwrap();
    let ball = world.bodies().last().map(|(id, _)| id).unwrap();
    world.step();
    let hash = world.state_hash();
    let cases = [
        (
            Command::ApplyImpulse {
                body: ground,
                impulse: vec2(1.0, 0.0),
            },
            WorldError::NotDynamic(ground),
        ),
        (
            Command::ApplyImpulse {
                body: platform,
                impulse: vec2(1.0, 0.0),
            },
            WorldError::NotDynamic(platform),
        ),
        (
            Command::SetVelocity {
                body: ground,
                velocity: vec2(1.0, 0.0),
            },
            WorldError::FixedBody(ground),
        ),
        (
            Command::SetVelocity {
                body: ball,
                velocity: vec2(5000.0, 0.0),
            },
            WorldError::SpeedTooLarge,
        ),
        (
            Command::ApplyImpulse {
                body: platform,
                impulse: vec2(1e9, 0.0),
            },
            WorldError::NotDynamic(platform),
        ),
        (
            Command::SetPosition {
                body: ball,
                position: vec2(0.0, 40_000.0),
            },
            WorldError::OutOfBounds,
        ),
    ];
    for (command, expected) in cases {
        assert_eq!(world.apply(command.clone()), Err(expected), "{command:?}");
        assert_eq!(world.state_hash(), hash, "{command:?} changed the world");
    }
}

// ------------------------------------------------------- untrusted commands

/// Any fixed-point value at all (raw bits), or a moderate one, or an edge.
fn any_scalar() -> impl Strategy<Value = Fx> {
    prop_oneof![
        3 => (-50.0..50.0f64).prop_map(fx),
        2 => any::<i64>().prop_map(Fx::from_bits),
        1 => prop_oneof![
            Just(Fx::ZERO),
            Just(Fx::MAX),
            Just(Fx::MIN),
            Just(Fx::DELTA),
            Just(-Fx::DELTA),
            Just(Fx::from_num(32_768)),
        ],
    ]
}

fn any_vec2() -> impl Strategy<Value = Vec2> {
    (any_scalar(), any_scalar()).prop_map(|(x, y)| Vec2::new(x, y))
}

/// Ids near the live ones (so many commands hit live bodies) plus wild ones.
fn any_id() -> impl Strategy<Value = BodyId> {
    prop_oneof![
        6 => (0u32..16, 0u32..3).prop_map(|(i, g)| BodyId::from_parts(i, g)),
        1 => (any::<u32>(), any::<u32>()).prop_map(|(i, g)| BodyId::from_parts(i, g)),
    ]
}

fn any_def() -> impl Strategy<Value = BodyDef> {
    (
        0u8..3,
        prop_oneof![
            any_scalar().prop_map(Shape::circle),
            any_vec2().prop_map(Shape::aabb),
        ],
        any_vec2(),
        any_vec2(),
        (any::<bool>(), any_scalar()),
        (any_scalar(), any_scalar(), any_scalar(), any::<bool>()),
    )
        .prop_map(
            |(kind, shape, position, velocity, (by_mass, m), (e, mu, g, bullet))| {
                let def = match kind {
                    0 => BodyDef::fixed(shape),
                    1 => BodyDef::kinematic(shape),
                    _ => BodyDef::dynamic(shape),
                };
                let def = def
                    .position(position)
                    .velocity(velocity)
                    .restitution(e)
                    .friction(mu)
                    .gravity_scale(g)
                    .bullet(bullet);
                if by_mass { def.mass(m) } else { def.density(m) }
            },
        )
}

/// One operation of an untrusted peer: a command, or a tick passing.
#[derive(Clone, Debug)]
enum Op {
    Apply(Command),
    Step,
}

fn any_op() -> impl Strategy<Value = Op> {
    prop_oneof![
        2 => any_def().prop_map(|d| Op::Apply(Command::Spawn(d))),
        1 => any_id().prop_map(|id| Op::Apply(Command::Despawn(id))),
        2 => (any_id(), any_vec2()).prop_map(|(body, impulse)| Op::Apply(Command::ApplyImpulse { body, impulse })),
        2 => (any_id(), any_vec2()).prop_map(|(body, velocity)| Op::Apply(Command::SetVelocity { body, velocity })),
        2 => (any_id(), any_vec2()).prop_map(|(body, position)| Op::Apply(Command::SetPosition { body, position })),
        1 => any_id().prop_map(|id| Op::Apply(Command::Wake(id))),
        3 => Just(Op::Step),
    ]
}

/// Every live body is inside the world bounds (frozen ones are clamped
/// onto them) and no coordinate saturated.
fn assert_sane(world: &World) {
    let bounds = world.settings().bounds;
    for (id, body) in world.bodies() {
        assert!(
            bounds.contains_point(body.position()),
            "{id:?} outside the bounds: {:?}",
            body.position()
        );
        let max = world.settings().max_speed;
        let vel = body.velocity();
        assert!(
            vel.x.abs() <= max && vel.y.abs() <= max,
            "{id:?} faster than max_speed: {vel:?}"
        );
    }
}

/// Cases of the untrusted-peer property: each case is up to 40 operations
/// on a 6-body world plus a few ticks, so this stays around a second.
const CASES: u32 = if cfg!(debug_assertions) { 256 } else { 1024 };

proptest! {
    #![proptest_config(ProptestConfig::with_cases(CASES))]

    /// Any sequence of commands with any ids and any fixed-point numbers:
    /// no panic; a refused command leaves the hash unchanged; the world stays
    /// sane; and the same sequence given to `step_with` on a copy ends in the
    /// same state as applying it one by one.
    #[test]
    fn untrusted_command_sequences_never_panic_or_corrupt(ops in prop::collection::vec(any_op(), 1..40)) {
        let mut world = busy_world();
        let mut batched = world.clone();
        let mut pending = Vec::new();
        for op in ops {
            match op {
                Op::Apply(command) => {
                    let before = world.state_hash();
                    if world.apply(command.clone()).is_err() {
                        prop_assert_eq!(world.state_hash(), before, "refused {:?} changed the world", command);
                    }
                    pending.push(command);
                }
                Op::Step => {
                    world.step();
                    batched.step_with(&pending);
                    pending.clear();
                    assert_sane(&world);
                    prop_assert_eq!(world.state_hash(), batched.state_hash());
                }
            }
        }
        world.step();
        batched.step_with(&pending);
        assert_sane(&world);
        prop_assert_eq!(world.state_hash(), batched.state_hash());
        for _ in 0..5 {
            world.step();
            assert_sane(&world);
        }
    }
}

// ------------------------------------------------------------------- events

/// The documented order: contact ends, contact begins (by pair ids), slept,
/// woke, frozen (by id).
fn order_key(event: &Event) -> (u8, BodyId, Option<BodyId>) {
    match *event {
        Event::ContactEnded(a, b) => (0, a, Some(b)),
        Event::ContactBegan(a, b) => (1, a, Some(b)),
        Event::Slept(a) => (2, a, None),
        Event::Woke(a) => (3, a, None),
        Event::Frozen(a) => (4, a, None),
    }
}

#[test]
fn events_come_in_the_documented_order() {
    // Small bounds so that a body can leave them: y ∈ [-10, 30].
    let settings = WorldSettings {
        bounds: Aabb::new(vec2(0.0, 10.0), vec2(20.0, 20.0)),
        ..WorldSettings::default()
    };
    let mut world = World::new(settings);
    add_ground(&mut world);
    // Two stacks that settle and sleep, a bouncing ball that begins and
    // ends contacts, and later a ball that wakes a stack and a body shot out
    // of the bounds.
    let left: Vec<BodyId> = (0..3)
        .map(|i| common::add_unit_box(&mut world, -5.0, 0.5 + 1.05 * f64::from(i)))
        .collect();
    let right: Vec<BodyId> = (0..3)
        .map(|i| common::add_unit_box(&mut world, 5.0, 0.5 + 1.05 * f64::from(i)))
        .collect();
    world
        .add_body(
            BodyDef::dynamic(Shape::circle(fx(0.3)))
                .position(vec2(0.0, 4.0))
                .restitution(fx(0.8)),
        )
        .unwrap();
    let mut seen = [0usize; 5];
    for tick in 0..400u64 {
        let commands = match tick {
            150 => vec![
                Command::Spawn(BodyDef::dynamic(Shape::circle(fx(0.25))).position(vec2(-5.0, 5.0))),
                Command::Spawn(BodyDef::dynamic(Shape::circle(fx(0.25))).position(vec2(5.0, 5.0))),
                Command::Spawn(
                    BodyDef::dynamic(Shape::circle(fx(0.2)))
                        .position(vec2(0.0, 20.0))
                        .velocity(vec2(0.0, 100.0)),
                ),
            ],
            250 => vec![Command::Wake(left[1]), Command::Despawn(right[0])],
            _ => Vec::new(),
        };
        for r in world.step_with(&commands) {
            r.unwrap();
        }
        let events = world.events();
        for event in events {
            seen[usize::from(order_key(event).0)] += 1;
            if let Event::ContactBegan(a, b) | Event::ContactEnded(a, b) = *event {
                assert!(a < b, "tick {}: pair not ordered: {event:?}", world.tick());
            }
        }
        for pair in events.windows(2) {
            assert!(
                order_key(&pair[0]) < order_key(&pair[1]),
                "tick {}: {:?} before {:?} (all: {events:?})",
                world.tick(),
                pair[0],
                pair[1]
            );
        }
    }
    println!("events: ended/began/slept/woke/frozen counts {seen:?}");
    assert!(
        seen.iter().all(|&n| n > 0),
        "some kind of event never happened: {seen:?}"
    );
}

// ------------------------------------------------------------------ queries

#[test]
fn queries_never_mutate_and_sort_as_documented() {
    let settings = WorldSettings {
        gravity: Vec2::ZERO,
        ..WorldSettings::default()
    };
    let mut world = World::new(settings);
    // Ids in order of creation: b before a, two boxes whose near faces are
    // both exactly at x = 4.5, so a tie on distance must go to b (smaller
    // id). They overlap, but a kinematic and a fixed body do not interact.
    let b = world
        .add_body(BodyDef::kinematic(Shape::aabb(vec2(0.5, 0.3))).position(vec2(5.0, 0.0)))
        .unwrap();
    let a = world
        .add_body(BodyDef::fixed(Shape::aabb(vec2(0.5, 0.5))).position(vec2(5.0, 0.0)))
        .unwrap();
    let c = world
        .add_body(BodyDef::dynamic(Shape::circle(fx(1.0))).position(vec2(10.0, 0.0)))
        .unwrap();
    let d = world
        .add_body(BodyDef::kinematic(Shape::aabb(vec2(1.0, 1.0))).position(vec2(20.0, 0.0)))
        .unwrap();
    let _off_axis = world
        .add_body(BodyDef::dynamic(Shape::circle(fx(0.5))).position(vec2(3.0, 5.0)))
        .unwrap();
    let behind = world
        .add_body(BodyDef::fixed(Shape::aabb(vec2(0.5, 0.5))).position(vec2(-5.0, 0.0)))
        .unwrap();
    world.step();
    let hash = world.state_hash();
    let (tick, events) = (world.tick(), world.events().to_vec());

    let origin = Vec2::ZERO;
    let east = vec2(1.0, 0.0);
    let all = QueryFilter::default();

    let hit = world.raycast(origin, east, fx(100.0)).unwrap();
    assert_eq!(hit.body, b, "tie at 4.5 goes to the smaller id");
    assert_eq!(hit.hit.distance, fx(4.5), "box faces are exact");
    // Any non-zero direction length gives the same answer.
    assert_eq!(
        world
            .raycast(origin, vec2(7.0, 0.0), fx(100.0))
            .map(|h| h.body),
        Some(b)
    );

    let hits = world.raycast_all(origin, east, fx(100.0), &all);
    let ids: Vec<BodyId> = hits.iter().map(|h| h.body).collect();
    assert_eq!(ids, vec![b, a, c, d]);
    let distances: Vec<f64> = hits.iter().map(|h| h.hit.distance.to_f64()).collect();
    for (got, want) in distances.iter().zip([4.5, 4.5, 9.0, 19.0]) {
        assert!((got - want).abs() < 1e-8, "distances {distances:?}");
    }
    assert_eq!(hits[1].hit.distance, fx(4.5), "box faces are exact");
    // The circle's distance goes through a square root: within 1e-8.
    println!(
        "queries: ray hit on the circle at {:.12} (exact 9)",
        distances[2]
    );
    assert_eq!(hits[3].hit.distance, fx(19.0), "box faces are exact");
    for pair in hits.windows(2) {
        assert!((pair[0].hit.distance, pair[0].body) <= (pair[1].hit.distance, pair[1].body));
    }
    let near: Vec<BodyId> = world
        .raycast_all(origin, east, fx(10.0), &all)
        .iter()
        .map(|h| h.body)
        .collect();
    assert_eq!(near, vec![b, a, c]);

    let only_fixed = QueryFilter {
        kinematic: false,
        dynamic: false,
        ..QueryFilter::default()
    };
    assert_eq!(
        world
            .raycast_filtered(origin, east, fx(100.0), &only_fixed)
            .map(|h| h.body),
        Some(a)
    );
    let only_dynamic = QueryFilter {
        kinematic: false,
        fixed: false,
        ..QueryFilter::default()
    };
    assert_eq!(
        world
            .raycast_filtered(origin, east, fx(100.0), &only_dynamic)
            .map(|h| h.body),
        Some(c)
    );
    let not_b = QueryFilter {
        exclude: Some(b),
        ..QueryFilter::default()
    };
    assert_eq!(
        world
            .raycast_filtered(origin, east, fx(100.0), &not_b)
            .map(|h| h.body),
        Some(a)
    );
    assert!(
        world.raycast(origin, Vec2::ZERO, fx(100.0)).is_none(),
        "zero direction"
    );
    assert!(
        world.raycast(origin, east, fx(-1.0)).is_none(),
        "negative distance"
    );
    assert!(
        world
            .raycast_all(origin, Vec2::ZERO, fx(100.0), &all)
            .is_empty()
    );
    assert!(
        world.raycast(origin, east, fx(4.0)).is_none(),
        "out of reach"
    );

    let area = Aabb::new(vec2(5.0, 0.0), vec2(0.1, 0.1));
    assert_eq!(world.query_aabb(&area, &all), vec![b, a]);
    let wide = Aabb::new(vec2(0.0, 0.0), vec2(100.0, 100.0));
    let everything = world.query_aabb(&wide, &all);
    assert_eq!(everything.len(), 6);
    assert!(
        everything.windows(2).all(|w| w[0] < w[1]),
        "query_aabb not in id order"
    );
    let no_dynamic = QueryFilter {
        dynamic: false,
        ..QueryFilter::default()
    };
    assert_eq!(world.query_aabb(&wide, &no_dynamic), vec![b, a, d, behind]);
    assert_eq!(world.query_point(vec2(5.0, 0.0), &all), vec![b, a]);
    assert_eq!(
        world.query_point(vec2(5.5, 0.0), &all),
        vec![b, a],
        "boundaries are included"
    );
    assert_eq!(
        world.query_point(vec2(5.5, 0.5), &all),
        vec![a],
        "a's corner, above b"
    );
    assert_eq!(world.query_point(vec2(5.0, 0.0), &not_b), vec![a]);
    assert_eq!(
        world.query_point(vec2(11.0, 0.0), &all),
        vec![c],
        "on the circle"
    );
    assert!(world.query_point(vec2(0.0, 0.0), &all).is_empty());

    // Hammer every query from many origins; nothing may change.
    for k in 0..200 {
        let o = vec2(f64::from(k % 20) - 10.0, f64::from(k / 20) - 5.0);
        let dir = vec2(f64::from(k % 7) - 3.0, f64::from(k % 5) - 2.0);
        let _ = world.raycast(o, dir, fx(50.0));
        let _ = world.raycast_all(o, dir, fx(50.0), &all);
        let _ = world.query_aabb(&Aabb::new(o, vec2(1.0, 1.0)), &all);
        let _ = world.query_point(o, &all);
    }
    assert_eq!(world.state_hash(), hash, "a query changed the world");
    assert_eq!(world.tick(), tick);
    assert_eq!(world.events(), &events[..], "a query changed the events");
}

/// The refusal messages state the ranges the checks apply (issue 13: the
/// mass message said "between 1e-6 and 1e9" while masses outside
/// [2⁻¹⁰, 2²⁰] were refused, so a user making 0.01-sized boxes at density
/// 1 was told a range that admits them). Each bound is probed from both
/// sides, one fixed-point step (2⁻³²) apart, by mass and by density, and
/// the message must name the bound values.
#[test]
fn range_errors_state_the_ranges_that_are_checked() {
    let step = |v: Fx, by: i64| Fx::from_bits(v.to_bits() + by);
    let lo = fx(1.0 / 1024.0);
    let hi = fx(1048576.0);
    let add = |mass: Fx| {
        let mut world = World::new(WorldSettings::default());
        world.add_body(BodyDef::dynamic(Shape::circle(fx(0.5))).mass(mass))
    };
    assert!(add(lo).is_ok(), "the lower bound itself is allowed");
    assert!(add(hi).is_ok(), "the upper bound itself is allowed");
    for mass in [step(lo, -1), step(hi, 1)] {
        assert_eq!(add(mass), Err(WorldError::MassOutOfRange), "mass {mass}");
    }
    // By density: a box of half size 0.01 at density 1 has mass 4e-4.
    let mut world = World::new(WorldSettings::default());
    let err = world
        .add_body(BodyDef::dynamic(Shape::aabb(vec2(0.01, 0.01))))
        .unwrap_err();
    assert_eq!(err, WorldError::MassOutOfRange);
    let message = err.to_string();
    println!("{message}");
    assert!(
        message.contains("1/1024") && message.contains("1048576"),
        "the message names the bounds: {message}"
    );
    assert!(
        !message.contains("1e-6") && !message.contains("1e9"),
        "{message}"
    );
    // Speed: the check is per component; the message says so.
    let max = WorldSettings::<Fx>::default().max_speed;
    let mut world = World::new(WorldSettings::default());
    assert!(
        world
            .add_body(BodyDef::dynamic(Shape::circle(fx(0.5))).velocity(Vec2::new(max, max)))
            .is_ok(),
        "both components at max_speed are allowed (speed √2·max_speed)"
    );
    let err = world
        .add_body(
            BodyDef::dynamic(Shape::circle(fx(0.5))).velocity(Vec2::new(step(max, 1), Fx::ZERO)),
        )
        .unwrap_err();
    assert_eq!(err, WorldError::SpeedTooLarge);
    assert!(err.to_string().contains("each component"), "{err}");
}
