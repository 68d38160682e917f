//! Found by the `world_commands` fuzz target: a body spawned (or teleported)
//! onto a sleeping body did not wake it, so the sleeper stayed inside the
//! newcomer for good (a dynamic ball held 4 units deep inside a fixed
//! circle for the rest of the run). A sleeping body takes no part in the
//! step, and nothing else touched it.
//!
//! The two minimised fuzz inputs (`fuzz/seeds/world_commands/spawn_on_sleeper_*`)
//! decode to: no gravity, sleeping allowed at zero speed after zero time,
//! a dynamic ball left to fall asleep, then a fixed circle spawned on the
//! same centre (radius 4 over a ball of 1/16; two circles of 13/16). The
//! tests below are those scenes with the fixed body spawned off-centre,
//! concentric and teleported, and the converse (no reach, no wake).
//!
//! # The bound checked
//! Once woken, the position solver removes per iteration at most
//! `max_correction` (0.2 units by default) of the depth, then a fraction
//! `position_correction` (0.8) of what is left above the slop. The deepest
//! overlap here is below 1.5 units, so 8 iterations at the capped rate and
//! a few of geometric decay suffice: a few steps at 3 position iterations
//! per step. The test allows 60 steps (1 s) and asks for a depth no more
//! than `linear_slop` + 1/32 (the fuzz target's tolerance) at the end.

use clockwork2d::prelude::*;

/// Depth allowed at the end (units): the slop plus the fuzz target's 1/32.
fn allowed_depth(world: &World) -> f64 {
    world.settings().linear_slop.to_f64() + 1.0 / 32.0
}

/// Penetration depth of a circle and a circle, or a circle and a box, from
/// positions alone (`f64`; negative is a gap).
fn depth(a: &Body<Fx>, b: &Body<Fx>) -> f64 {
    let (pa, pb) = (a.position(), b.position());
    let (ax, ay, bx, by) = (pa.x.to_f64(), pa.y.to_f64(), pb.x.to_f64(), pb.y.to_f64());
    let Shape::Circle { radius } = a.shape() else {
        panic!("the first body is a ball");
    };
    let r = radius.to_f64();
    match b.shape() {
        Shape::Circle { radius } => r + radius.to_f64() - (ax - bx).hypot(ay - by),
        Shape::Aabb { half_extents } => {
            let (hx, hy) = (half_extents.x.to_f64(), half_extents.y.to_f64());
            let (dx, dy) = (ax - bx, ay - by);
            if dx.abs() <= hx && dy.abs() <= hy {
                // Centre inside: radius plus the way to the nearest face.
                r + (hx - dx.abs()).min(hy - dy.abs())
            } else {
                let (qx, qy) = (dx.clamp(-hx, hx), dy.clamp(-hy, hy));
                r - (dx - qx).hypot(dy - qy)
            }
        }
    }
}

/// The fuzz input's world: no gravity, sleeping at zero speed after zero
/// time, and a ball of radius 1/16 at rest, stepped until it sleeps.
fn sleeping_ball(radius: f64) -> (World, BodyId) {
    let settings = WorldSettings {
        gravity: vec2(0.0, 0.0),
        sleep_linear_threshold: Fx::ZERO,
        time_to_sleep: Fx::ZERO,
        ..WorldSettings::default()
    };
    let mut world = World::new(settings);
    let ball = world
        .add_body(BodyDef::dynamic(Shape::circle(fx(radius))).position(vec2(-7.5, -7.75)))
        .unwrap();
    for _ in 0..15 {
        world.step();
    }
    assert!(
        !world.body(ball).unwrap().is_awake(),
        "the ball should sleep"
    );
    (world, ball)
}

/// Steps up to 60 times and checks that the overlap of `ball` and `other`
/// has dropped to the allowed depth and stays there.
fn settles_out_of(mut world: World, ball: BodyId, other: BodyId, what: &str) {
    let start = depth(world.body(ball).unwrap(), world.body(other).unwrap());
    let mut settled_at = None;
    for _ in 0..60 {
        world.step();
        let d = depth(world.body(ball).unwrap(), world.body(other).unwrap());
        if d <= allowed_depth(&world) {
            settled_at.get_or_insert(world.tick());
        } else {
            settled_at = None;
        }
    }
    let end = depth(world.body(ball).unwrap(), world.body(other).unwrap());
    println!("{what}: depth {start:.4} -> {end:.6}, out since tick {settled_at:?}");
    assert!(
        settled_at.is_some(),
        "{what}: still {end} deep after 60 steps (allowed {})",
        allowed_depth(&world)
    );
}

#[test]
fn a_fixed_circle_spawned_over_a_sleeping_ball_wakes_it_and_pushes_it_out() {
    let (mut world, ball) = sleeping_ball(1.0 / 16.0);
    let wall = world
        .add_body(BodyDef::fixed(Shape::circle(fx(1.0))).position(vec2(-7.0, -7.75)))
        .unwrap();
    assert!(world.events().contains(&Event::Woke(ball)), "no Woke event");
    assert!(world.body(ball).unwrap().is_awake());
    settles_out_of(world, ball, wall, "offset centres");
}

#[test]
fn a_fixed_circle_spawned_concentric_with_a_sleeping_ball_pushes_it_out() {
    // The second minimised input: the same centre (no normal from the
    // geometry; the engine picks one). Radius 1 + 1/16 deep at the start.
    let (mut world, ball) = sleeping_ball(1.0 / 16.0);
    let wall = world
        .add_body(BodyDef::fixed(Shape::circle(fx(1.0))).position(vec2(-7.5, -7.75)))
        .unwrap();
    assert!(world.body(ball).unwrap().is_awake());
    settles_out_of(world, ball, wall, "coincident centres");
}

#[test]
fn a_fixed_box_teleported_onto_a_sleeping_ball_wakes_it_and_pushes_it_out() {
    let (mut world, ball) = sleeping_ball(0.25);
    let wall = world
        .add_body(BodyDef::fixed(Shape::aabb(vec2(1.0, 0.5))).position(vec2(5.0, 5.0)))
        .unwrap();
    world.step();
    assert!(!world.body(ball).unwrap().is_awake());
    world
        .apply(Command::SetPosition {
            body: wall,
            position: vec2(-7.5, -7.25),
        })
        .unwrap();
    assert!(world.events().contains(&Event::Woke(ball)), "no Woke event");
    settles_out_of(world, ball, wall, "teleported box");
}

#[test]
fn a_spawn_that_does_not_reach_a_sleeping_ball_leaves_it_asleep() {
    // The converse: waking is for bodies the newcomer's box touches, not
    // for the whole world (a sleeping pile stays asleep under a spawn far
    // away).
    let (mut world, ball) = sleeping_ball(1.0 / 16.0);
    world
        .add_body(BodyDef::fixed(Shape::circle(fx(1.0))).position(vec2(-5.0, -7.75)))
        .unwrap();
    assert!(!world.body(ball).unwrap().is_awake());
    assert!(!world.events().contains(&Event::Woke(ball)));
}
