//! The origin document's rope demo: a player in an enclosed area aims,
//! ray-casts to the border of the area, attaches a rope at the hit point and
//! swings; then lets go and aims again.
//!
//! The aim directions are scripted. For each: the player jumps, and at the
//! top of the jump casts a ray (ignoring itself) to the walls, attaches a
//! rope of the current distance at the hit point, reels it in to 55 % of
//! that length at 6 units/s (each tick the rope is replaced by a shorter one
//! with a `RemoveConstraint` + `AddConstraint` command pair), swings for
//! 2.5 s, lets go (`remove_constraint`) and falls for 1.5 s. The attach points and the
//! player's path (every 15 ticks) are printed. The whole script is run twice
//! and the final state hashes compared: it is deterministic.
//!
//! Run with `cargo run --release --example grapple`.

use clockwork2d::prelude::*;

/// Inside of the area: x in [-10, 10], y in [0, 10].
const HALF_WIDTH: f64 = 10.0;
const HEIGHT: f64 = 10.0;
/// Scripted aims (any length) and the sideways speed of the jump before each.
const AIMS: [((f64, f64), f64); 5] = [
    ((0.6, 1.0), 2.0),
    ((-0.8, 1.0), -2.0),
    ((0.2, 1.0), 1.0),
    ((-1.0, 0.6), -3.0),
    ((0.9, 1.0), 3.0),
];
/// Reeling: the rope shortens by this much per tick (6 units/s) down to
/// this fraction of its length at attachment.
const REEL_PER_TICK: f64 = 0.1;
const REEL_TO: f64 = 0.55;
const SWING_TICKS: usize = 150;
const FALL_TICKS: usize = 90;
const PRINT_EVERY: usize = 15;

fn walls(world: &mut World) -> Result<(), WorldError> {
    let t = 0.5;
    for (half, centre) in [
        ((HALF_WIDTH + 2.0 * t, t), (0.0, -t)),         // floor
        ((HALF_WIDTH + 2.0 * t, t), (0.0, HEIGHT + t)), // ceiling
        ((t, HEIGHT / 2.0 + t), (-HALF_WIDTH - t, HEIGHT / 2.0)), // left
        ((t, HEIGHT / 2.0 + t), (HALF_WIDTH + t, HEIGHT / 2.0)), // right
    ] {
        world.add_body(
            BodyDef::fixed(Shape::aabb(vec2(half.0, half.1))).position(vec2(centre.0, centre.1)),
        )?;
    }
    Ok(())
}

fn position(world: &World, id: BodyId) -> (f64, f64) {
    world
        .body(id)
        .map_or((f64::NAN, f64::NAN), |b| b.position().to_f64())
}

/// Runs the script; prints when `verbose`. Returns the final state hash.
fn run(verbose: bool) -> Result<u64, WorldError> {
    let mut world = World::new(WorldSettings::default());
    walls(&mut world)?;
    let player = world.add_body(
        BodyDef::dynamic(Shape::circle(fx(0.3)))
            .mass(fx(1.0))
            .position(vec2(0.0, 0.3)),
    )?;
    let filter = QueryFilter {
        exclude: Some(player),
        ..QueryFilter::default()
    };
    let path = |world: &World, phase: &str| {
        if verbose && world.tick() % PRINT_EVERY as u64 == 0 {
            let p = position(world, player);
            println!(
                "  tick {:>4} {phase:<6} ({:>8.3}, {:>7.3})",
                world.tick(),
                p.0,
                p.1
            );
        }
    };
    for (n, &((ax, ay), jump_x)) in AIMS.iter().enumerate() {
        // Jump, and wait for the top of the jump (at most one second).
        world.apply(Command::SetVelocity {
            body: player,
            velocity: vec2(jump_x, 7.0),
        })?;
        for _ in 0..60 {
            world.step();
            path(&world, "jump");
            if world
                .body(player)
                .is_some_and(|b| !b.velocity().y.is_positive())
            {
                break;
            }
        }
        let from = world.body(player).map_or(Vec2::ZERO, |b| b.position());
        let Some(hit) = world.raycast_filtered(from, vec2(ax, ay), fx(100.0), &filter) else {
            if verbose {
                println!("aim {n} ({ax}, {ay}): no hit");
            }
            continue;
        };
        let attach = Anchor::Point(hit.hit.point);
        let mut length = hit.hit.distance.to_f64();
        let mut rope = world.add_constraint(Constraint::rope(
            attach,
            Anchor::Body(player),
            hit.hit.distance,
        ))?;
        if verbose {
            let (f, p) = (from.to_f64(), hit.hit.point.to_f64());
            println!(
                "aim {n} ({ax}, {ay}) from ({:.3}, {:.3}) at tick {}: rope attached at ({:.3}, \
                 {:.3}), length {length:.3}",
                f.0,
                f.1,
                world.tick(),
                p.0,
                p.1,
            );
        }
        let shortest = length * REEL_TO;
        while length > shortest {
            length = (length - REEL_PER_TICK).max(shortest);
            let results = world.step_with(&[
                Command::RemoveConstraint(rope),
                Command::AddConstraint(Constraint::rope(attach, Anchor::Body(player), fx(length))),
            ]);
            match results.as_slice() {
                [Ok(_), Ok(CommandOutcome::ConstraintAdded(id))] => rope = *id,
                other => panic!("reeling failed: {other:?}"),
            }
            path(&world, "reel");
        }
        for _ in 0..SWING_TICKS {
            world.step();
            path(&world, "swing");
        }
        world.remove_constraint(rope)?;
        if verbose {
            let p = position(&world, player);
            println!(
                "  released at tick {} at ({:.3}, {:.3})",
                world.tick(),
                p.0,
                p.1
            );
        }
        for _ in 0..FALL_TICKS {
            world.step();
            path(&world, "fall");
        }
    }
    let p = position(&world, player);
    if verbose {
        println!("end at tick {} at ({:.3}, {:.3})", world.tick(), p.0, p.1);
    }
    Ok(world.state_hash())
}

fn main() -> Result<(), WorldError> {
    let first = run(true)?;
    let second = run(false)?;
    println!("state hash {first:016x}; second run {second:016x}");
    assert_eq!(first, second, "the script must be deterministic");
    Ok(())
}
