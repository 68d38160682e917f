//! Under gravity, a body that passes fixed bodies with clearance moves
//! exactly as if they were not there: a circle or a box (size 0.05)
//! falling down a shaft whose sides are `clearance` away (past the corner of
//! a ledge, between the ledge and a wall), and a circle or box (size 0.5)
//! sliding frictionless along the floor under an overhang whose bottom
//! face is `clearance` above it. Clearances from 0.0002 (twice the linear
//! slop) to 0.05, falls from 0.5 to 50 (up to 40 units/s, 0.67 units a
//! tick: 3300 clearances), slides at 0.5 to 500 units/s, bullet and not.
//!
//! The physics: a contact force acts only where bodies touch. A body whose
//! path never comes within its clearance of an obstacle feels nothing from
//! it, so its trajectory is the free one. The reference is the same scene
//! without the obstacles, stepped alongside: the engine's own free flight,
//! which tests/contacts_bounce.rs checks against the exact parabola. The
//! comparison is exact (bit for bit): a speculative or ghost contact that
//! slows or deflects the body by any amount is a failure.
//!
//! (tests/contacts_ghost.rs does the same with gravity off; gravity bends
//! the path, so a body falling past a corner approaches it along a curve.)

use clockwork2d::prelude::*;

const TICK: f64 = 1.0 / 60.0;

fn world_without_sleep() -> World {
    World::new(WorldSettings {
        sleep_enabled: false,
        ..WorldSettings::default()
    })
}

fn fixed_box(world: &mut World, half: (f64, f64), at: (f64, f64)) {
    world
        .add_body(BodyDef::fixed(Shape::aabb(vec2(half.0, half.1))).position(vec2(at.0, at.1)))
        .expect("fixed box");
}

fn shape(square: bool, size: f64) -> Shape {
    if square {
        Shape::aabb(vec2(size, size))
    } else {
        Shape::circle(fx(size))
    }
}

/// Steps `with` and `without` together until `done(without)`, returning
/// the ticks run and whether the body's position and velocity stayed equal
/// bit for bit.
fn same_path(
    (with, a): (&mut World, BodyId),
    (without, b): (&mut World, BodyId),
    max_ticks: usize,
    done: impl Fn(&World, BodyId) -> bool,
) -> (usize, bool) {
    for tick in 1..=max_ticks {
        with.step();
        without.step();
        let (p, q) = (with.body(a).unwrap(), without.body(b).unwrap());
        if p.position() != q.position() || p.velocity() != q.velocity() {
            return (tick, false);
        }
        if done(without, b) {
            return (tick, true);
        }
    }
    (max_ticks, true)
}

/// A ledge (top y = 0, right face x = 0) and a wall whose left face is
/// `0.1 + 2·clearance`: a shaft of width `0.1 + 2·clearance` that the body
/// (0.1 across) falls down with `clearance` on each side, passing the
/// ledge's corner (0, 0).
#[test]
fn a_body_falling_past_a_corner_with_clearance_falls_freely() {
    let mut runs = 0;
    for clearance in [0.0002, 0.001, 0.01, 0.05] {
        for drop in [0.5, 5.0, 50.0] {
            for square in [false, true] {
                for bullet in [false, true] {
                    let make = |obstacles: bool| {
                        let mut world = world_without_sleep();
                        if obstacles {
                            fixed_box(&mut world, (1.5, 0.5), (-1.5, -0.5));
                            fixed_box(&mut world, (1.0, 50.0), (1.1 + 2.0 * clearance, -40.0));
                        }
                        let id = world
                            .add_body(
                                BodyDef::dynamic(shape(square, 0.05))
                                    .bullet(bullet)
                                    .position(vec2(0.05 + clearance, drop)),
                            )
                            .expect("body");
                        (world, id)
                    };
                    let (mut with, a) = make(true);
                    let (mut without, b) = make(false);
                    // Down to y = −30: 80 units below the highest start.
                    let (ticks, same) =
                        same_path((&mut with, a), (&mut without, b), 600, |w, id| {
                            w.body(id).unwrap().position().to_f64().1 < -30.0
                        });
                    let speed = without.body(b).unwrap().velocity().to_f64().1.abs();
                    assert!(
                        same,
                        "clearance {clearance}, drop {drop}, square {square}, bullet {bullet}: the path changed at tick {ticks}"
                    );
                    assert!(ticks < 600, "the fall did not reach the bottom");
                    runs += 1;
                    if clearance == 0.0002 && drop == 50.0 && !square && !bullet {
                        println!(
                            "falling 80 units past the corner with clearance {clearance}: {ticks} ticks, {speed:.1} units/s at the bottom, bit-identical to free fall"
                        );
                    }
                }
            }
        }
    }
    println!("{runs} falls past a corner: every path bit-identical to free fall");
}

/// A floor (top y = 0) and an overhang over x ∈ [5, 8] whose bottom face is
/// `clearance` above the sliding body's top (y = 1 + clearance).
#[test]
fn a_body_sliding_under_an_overhang_with_clearance_is_untouched() {
    let mut runs = 0;
    for clearance in [0.0002, 0.001, 0.01] {
        for speed in [0.5, 5.0, 50.0, 500.0] {
            for square in [false, true] {
                for bullet in [false, true] {
                    let make = |obstacles: bool| {
                        let mut world = world_without_sleep();
                        fixed_box(&mut world, (2000.0, 0.5), (0.0, -0.5));
                        if obstacles {
                            fixed_box(&mut world, (1.5, 0.5), (6.5, 1.5 + clearance));
                        }
                        let id = world
                            .add_body(
                                BodyDef::dynamic(shape(square, 0.5))
                                    .friction(fx(0.0))
                                    .bullet(bullet)
                                    .position(vec2(0.0, 0.5))
                                    .velocity(vec2(speed, 0.0)),
                            )
                            .expect("body");
                        (world, id)
                    };
                    let (mut with, a) = make(true);
                    let (mut without, b) = make(false);
                    // Past the overhang's far end (x = 8) by a margin: 20 units.
                    let ticks = ((20.0 / (speed * TICK)).ceil() as usize).min(2400);
                    let (at, same) =
                        same_path((&mut with, a), (&mut without, b), ticks, |_, _| false);
                    assert!(
                        same,
                        "clearance {clearance}, {speed} units/s, square {square}, bullet {bullet}: the path changed at tick {at}"
                    );
                    runs += 1;
                }
            }
        }
    }
    println!("{runs} slides under an overhang: every path bit-identical to the open floor");
}
