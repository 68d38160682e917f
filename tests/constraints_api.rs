//! The constraint API (issue 4): typed errors that leave the world
//! unchanged, generational ids, removal with bodies, commands, and
//! constraint state in the state hash and the snapshot.

use clockwork2d::prelude::*;

fn ball(world: &mut World, x: f64, y: f64) -> BodyId {
    world
        .add_body(BodyDef::dynamic(Shape::circle(fx(0.25))).position(vec2(x, y)))
        .expect("ball")
}

/// A world with a fixed ground, two dynamic balls and one fixed box.
fn scene() -> (World, BodyId, BodyId, BodyId) {
    let mut world = World::new(WorldSettings::default());
    let ground = world
        .add_body(BodyDef::fixed(Shape::aabb(vec2(20.0, 0.5))).position(vec2(0.0, -0.5)))
        .unwrap();
    let a = ball(&mut world, -1.0, 3.0);
    let b = ball(&mut world, 1.0, 3.0);
    (world, ground, a, b)
}

fn point(x: f64, y: f64) -> Anchor {
    Anchor::Point(vec2(x, y))
}

/// Every refused constraint must leave the world exactly as it was: the
/// same state hash, no constraint added, and the next id unchanged.
fn assert_refused(world: &mut World, constraint: Constraint, expected: &WorldError) {
    let hash = world.state_hash();
    let count = world.constraints().count();
    let result = world.add_constraint(constraint);
    match (&result, expected) {
        (Err(WorldError::InvalidConstraint { .. }), WorldError::InvalidConstraint { .. }) => {}
        (Err(e), _) => assert_eq!(e, expected, "{constraint:?}"),
        (Ok(id), _) => panic!("accepted {constraint:?} as {id}"),
    }
    assert_eq!(world.state_hash(), hash, "refusal changed the world");
    assert_eq!(world.constraints().count(), count);
}

#[test]
fn add_constraint_with_a_dead_body_is_unknown_body_and_leaves_the_world_unchanged() {
    let (mut world, _ground, a, b) = scene();
    let dead = ball(&mut world, 5.0, 3.0);
    world.remove_body(dead).unwrap();
    let never = BodyId::from_parts(999, 0);
    for bad in [dead, never] {
        let err = WorldError::UnknownBody(bad);
        assert_refused(
            &mut world,
            Constraint::rope(point(0.0, 5.0), Anchor::Body(bad), fx(1.0)),
            &err,
        );
        assert_refused(
            &mut world,
            Constraint::bendy_spring(Anchor::Body(a), Anchor::Body(bad), vec2(1.0, 1.0), fx(0.0)),
            &err,
        );
        assert_refused(
            &mut world,
            Constraint::radial_spring(
                Anchor::BodyOffset(bad, vec2(0.5, 0.0)),
                Anchor::Body(b),
                fx(1.0),
                fx(1.0),
                fx(0.0),
            ),
            &err,
        );
    }
    // A slot reused by a new body does not revive the old id.
    let reused = ball(&mut world, 5.0, 3.0);
    assert_eq!(reused.index(), dead.index());
    assert_ne!(reused, dead);
    assert_refused(
        &mut world,
        Constraint::rope(point(0.0, 5.0), Anchor::Body(dead), fx(1.0)),
        &WorldError::UnknownBody(dead),
    );
}

#[test]
fn out_of_range_constraints_are_invalid_and_leave_the_world_unchanged() {
    let (mut world, ground, a, b) = scene();
    let invalid = WorldError::InvalidConstraint { reason: "" };
    let cases = [
        // Negative or zero lengths.
        Constraint::rope(point(0.0, 5.0), Anchor::Body(a), fx(-1.0)),
        Constraint::rope(point(0.0, 5.0), Anchor::Body(a), fx(0.0)),
        Constraint::radial_spring(point(0.0, 5.0), Anchor::Body(a), fx(-0.5), fx(1.0), fx(0.0)),
        // Negative stiffness, on either axis.
        Constraint::bendy_spring(point(0.0, 5.0), Anchor::Body(a), vec2(-1.0, 1.0), fx(0.0)),
        Constraint::bendy_spring(point(0.0, 5.0), Anchor::Body(a), vec2(1.0, -1.0), fx(0.0)),
        Constraint::radial_spring(point(0.0, 5.0), Anchor::Body(a), fx(1.0), fx(-1.0), fx(0.0)),
        // Negative damping.
        Constraint::bendy_spring(point(0.0, 5.0), Anchor::Body(a), vec2(1.0, 1.0), fx(-0.1)),
        Constraint::radial_spring(point(0.0, 5.0), Anchor::Body(a), fx(1.0), fx(1.0), fx(-0.1)),
        // Stiffness above 2^24.
        Constraint::bendy_spring(point(0.0, 5.0), Anchor::Body(a), vec2(2e7, 1.0), fx(0.0)),
        // Restitution outside [0, 1].
        Constraint::rope(point(0.0, 5.0), Anchor::Body(a), fx(1.0)).with_restitution(fx(1.5)),
        Constraint::rope(point(0.0, 5.0), Anchor::Body(a), fx(1.0)).with_restitution(fx(-0.5)),
        // Both ends on the same body (with or without offsets).
        Constraint::rope(Anchor::Body(a), Anchor::Body(a), fx(1.0)),
        Constraint::bendy_spring(
            Anchor::BodyOffset(b, vec2(0.5, 0.0)),
            Anchor::Body(b),
            vec2(1.0, 1.0),
            fx(0.0),
        ),
        // Two points.
        Constraint::rope(point(0.0, 5.0), point(1.0, 5.0), fx(1.0)),
        // No dynamic end: a fixed body and a point.
        Constraint::rope(point(0.0, 5.0), Anchor::Body(ground), fx(1.0)),
        // A point outside the world.
        Constraint::rope(point(0.0, 40_000.0), Anchor::Body(a), fx(1.0)),
        // A rest offset outside the world.
        Constraint::bendy_spring(point(0.0, 5.0), Anchor::Body(a), vec2(1.0, 1.0), fx(0.0))
            .with_rest_offset(vec2(-40_000.0, 0.0)),
    ];
    for constraint in cases {
        assert_refused(&mut world, constraint, &invalid);
    }
    // The same world accepts valid ones afterwards, and every error message
    // says what is wrong.
    let err = world
        .add_constraint(Constraint::rope(Anchor::Body(a), Anchor::Body(a), fx(1.0)))
        .unwrap_err();
    assert!(err.to_string().contains("same body"), "{err}");
    world
        .add_constraint(Constraint::rope(Anchor::Body(a), Anchor::Body(b), fx(3.0)))
        .unwrap();
}

#[test]
fn builders_only_touch_their_own_kind() {
    let id = BodyId::from_parts(1, 0);
    let spring =
        Constraint::radial_spring(point(0.0, 0.0), Anchor::Body(id), fx(1.0), fx(2.0), fx(0.0));
    assert_eq!(spring.with_restitution(fx(1.0)), spring);
    assert_eq!(spring.with_rest_offset(vec2(1.0, 1.0)), spring);
    let rope = Constraint::rope(point(0.0, 0.0), Anchor::Body(id), fx(1.0));
    assert_eq!(rope.with_rest_offset(vec2(1.0, 1.0)), rope);
    assert_eq!(rope.anchors(), (point(0.0, 0.0), Anchor::Body(id)));
}

#[test]
fn remove_constraint_with_a_stale_id_is_unknown_constraint() {
    let (mut world, _ground, a, b) = scene();
    let rope = Constraint::rope(Anchor::Body(a), Anchor::Body(b), fx(3.0));
    let id = world.add_constraint(rope).unwrap();
    assert_eq!(world.constraint(id), Some(&rope));
    assert_eq!(world.remove_constraint(id), Ok(rope));
    assert_eq!(world.constraint(id), None);
    let hash = world.state_hash();
    assert_eq!(
        world.remove_constraint(id),
        Err(WorldError::UnknownConstraint(id))
    );
    assert_eq!(world.state_hash(), hash);
    // The slot is reused with a new generation; the old id stays stale.
    let again = world.add_constraint(rope).unwrap();
    assert_eq!(again.index(), id.index());
    assert_ne!(again.generation(), id.generation());
    assert_eq!(world.constraint(id), None);
    assert_eq!(
        world.remove_constraint(id),
        Err(WorldError::UnknownConstraint(id))
    );
    // Never issued.
    let never = ConstraintId::from_parts(77, 0);
    assert_eq!(
        world.remove_constraint(never),
        Err(WorldError::UnknownConstraint(never))
    );
    assert_eq!(
        world.constraints().map(|(c, _)| c).collect::<Vec<_>>(),
        [again]
    );
}

/// Two boxes resting on the ground, apart, joined by a slack rope (so one
/// island), and a third box far away (its own island). All three fall
/// asleep. Removing one end of the rope removes the rope and wakes its
/// partner; the unrelated sleeper stays asleep.
#[test]
fn removing_a_body_removes_its_constraints_and_wakes_partners() {
    let mut world = World::new(WorldSettings::default());
    world
        .add_body(BodyDef::fixed(Shape::aabb(vec2(20.0, 0.5))).position(vec2(0.0, -0.5)))
        .unwrap();
    let boxed = |world: &mut World, x: f64| {
        world
            .add_body(BodyDef::dynamic(Shape::aabb(vec2(0.5, 0.5))).position(vec2(x, 0.5)))
            .unwrap()
    };
    let a = boxed(&mut world, -2.0);
    let b = boxed(&mut world, 2.0);
    let c = boxed(&mut world, 10.0);
    let rope = world
        .add_constraint(Constraint::rope(Anchor::Body(a), Anchor::Body(b), fx(5.0)))
        .unwrap();
    let spring = world
        .add_constraint(Constraint::bendy_spring(
            point(-2.0, 3.0),
            Anchor::Body(a),
            vec2(0.0, 0.0),
            fx(0.0),
        ))
        .unwrap();
    for _ in 0..120 {
        world.step();
    }
    for id in [a, b, c] {
        assert!(!world.body(id).unwrap().is_awake(), "{id} should sleep");
    }
    world.remove_body(a).unwrap();
    assert_eq!(world.constraint(rope), None);
    assert_eq!(world.constraint(spring), None);
    assert_eq!(world.constraints().count(), 0);
    assert!(world.body(b).unwrap().is_awake(), "partner woken");
    assert!(!world.body(c).unwrap().is_awake(), "unrelated sleeper kept");
    assert_eq!(
        world.remove_constraint(rope),
        Err(WorldError::UnknownConstraint(rope))
    );
}

/// Adding a constraint to a sleeping body wakes it.
#[test]
fn adding_a_constraint_wakes_the_bodies_it_attaches() {
    let mut world = World::new(WorldSettings::default());
    world
        .add_body(BodyDef::fixed(Shape::aabb(vec2(20.0, 0.5))).position(vec2(0.0, -0.5)))
        .unwrap();
    let a = world
        .add_body(BodyDef::dynamic(Shape::aabb(vec2(0.5, 0.5))).position(vec2(0.0, 0.5)))
        .unwrap();
    for _ in 0..120 {
        world.step();
    }
    assert!(!world.body(a).unwrap().is_awake());
    world
        .add_constraint(Constraint::bendy_spring(
            point(3.0, 3.0),
            Anchor::Body(a),
            vec2(10.0, 10.0),
            fx(1.0),
        ))
        .unwrap();
    assert!(world.body(a).unwrap().is_awake());
    for _ in 0..30 {
        world.step();
    }
    let p = world.body(a).unwrap().position().to_f64();
    assert!(p.0 > 0.1 && p.1 > 0.6, "the spring pulled it: {p:?}");
}

/// `Command::AddConstraint` / `RemoveConstraint` through `step_with`: the
/// outcomes carry the id; a refused command does not stop the others; and
/// a command run gives exactly the state (hash) of the same calls made
/// directly before `step()`.
#[test]
fn constraint_commands_through_step_with_match_direct_calls() {
    let (mut by_command, _g, a, b) = scene();
    let (mut direct, ..) = scene();
    let rope = Constraint::rope(Anchor::Body(a), Anchor::Body(b), fx(2.5));
    let spring =
        Constraint::radial_spring(point(0.0, 6.0), Anchor::Body(a), fx(2.0), fx(40.0), fx(0.5));
    let results = by_command.step_with(&[
        Command::AddConstraint(rope),
        Command::AddConstraint(Constraint::rope(Anchor::Body(a), Anchor::Body(a), fx(1.0))),
        Command::AddConstraint(spring),
    ]);
    assert_eq!(results.len(), 3);
    let Ok(CommandOutcome::ConstraintAdded(rope_id)) = results[0] else {
        panic!("{:?}", results[0]);
    };
    assert!(matches!(
        results[1],
        Err(WorldError::InvalidConstraint { .. })
    ));
    let Ok(CommandOutcome::ConstraintAdded(spring_id)) = results[2] else {
        panic!("{:?}", results[2]);
    };
    assert_eq!(direct.add_constraint(rope), Ok(rope_id));
    assert_eq!(direct.add_constraint(spring), Ok(spring_id));
    direct.step();
    assert_eq!(by_command.state_hash(), direct.state_hash());
    for _ in 0..30 {
        by_command.step();
        direct.step();
    }
    let results = by_command.step_with(&[
        Command::RemoveConstraint(rope_id),
        Command::RemoveConstraint(rope_id),
    ]);
    assert_eq!(results[0], Ok(CommandOutcome::Applied));
    assert_eq!(results[1], Err(WorldError::UnknownConstraint(rope_id)));
    direct.remove_constraint(rope_id).unwrap();
    direct.step();
    assert_eq!(by_command.state_hash(), direct.state_hash());
    assert_eq!(by_command.constraint(rope_id), None);
    assert_eq!(by_command.constraint(spring_id), Some(&spring));
}

/// A rope (slack at first, then taut with a warm-start impulse) and a
/// spring on a falling ball, plus a chain: two identical runs have equal
/// hashes at every tick, and each differs from the run without
/// constraints from the moment a constraint is added (before any step).
#[test]
fn constraint_state_is_in_the_state_hash() {
    let build = |with: bool| {
        let (mut world, _g, a, b) = scene();
        if with {
            world
                .add_constraint(Constraint::rope(point(-1.0, 5.0), Anchor::Body(a), fx(2.5)))
                .unwrap();
            world
                .add_constraint(Constraint::bendy_spring(
                    Anchor::Body(a),
                    Anchor::BodyOffset(b, vec2(0.0, 0.5)),
                    vec2(5.0, 5.0),
                    fx(0.2),
                ))
                .unwrap();
        }
        world
    };
    let (mut one, mut two, mut without) = (build(true), build(true), build(false));
    assert_ne!(one.state_hash(), without.state_hash());
    assert_ne!(
        one.state_digest().constraints,
        without.state_digest().constraints
    );
    for tick in 0..240 {
        assert_eq!(one.state_hash(), two.state_hash(), "tick {tick}");
        assert_eq!(one.state_hash128(), two.state_hash128(), "tick {tick}");
        one.step();
        two.step();
        without.step();
        assert_ne!(one.state_hash(), without.state_hash(), "tick {tick}");
    }
    // Parameters are hashed too: a different rope length is another state.
    let (mut x, _g, a, _b) = scene();
    let (mut y, ..) = scene();
    x.add_constraint(Constraint::rope(point(0.0, 5.0), Anchor::Body(a), fx(2.0)))
        .unwrap();
    y.add_constraint(Constraint::rope(point(0.0, 5.0), Anchor::Body(a), fx(2.5)))
        .unwrap();
    assert_ne!(x.state_hash(), y.state_hash());
    // So are the ids: removing and re-adding bumps the generation.
    let id = x.constraints().next().unwrap().0;
    let c = x.remove_constraint(id).unwrap();
    let hash_removed = x.state_hash();
    x.add_constraint(c).unwrap();
    assert_ne!(x.state_hash(), hash_removed);
}

/// A snapshot taken mid-swing (rope taut with a warm-start impulse, spring
/// stretched) restores to a world that continues bit-identically.
#[test]
fn snapshot_mid_swing_with_constraints_continues_bit_identically() {
    let (mut world, _g, a, b) = scene();
    world
        .add_constraint(Constraint::rope(point(-2.5, 4.5), Anchor::Body(a), fx(2.5)))
        .unwrap();
    world
        .add_constraint(Constraint::radial_spring(
            Anchor::Body(a),
            Anchor::Body(b),
            fx(1.5),
            fx(30.0),
            fx(0.3),
        ))
        .unwrap();
    for _ in 0..45 {
        world.step();
    }
    let mut restored: World = World::restore(&world.snapshot()).expect("restore");
    assert_eq!(restored.state_hash(), world.state_hash());
    for tick in 0..120 {
        world.step();
        restored.step();
        assert_eq!(restored.state_hash(), world.state_hash(), "tick {tick}");
    }
}
