//! A body launched by a bounce towards a wall beyond the speculative margin
//! never passes into it (issue 13, N7's leftover, cause 1).
//!
//! A resting body struck by a faster one leaves at up to twice the
//! striker's speed (e = 1, the struck body much lighter), in a direction
//! its broad-phase region (its box at rest, grown by the margin 0.1) did
//! not look along: a wall 0.3 away was never paired with it. Rigid bodies
//! cannot interpenetrate whatever the speeds, so at every tick neither body
//! may be deeper in the wall than the linear slop (a speculative contact
//! may rest one slop deep), and the launched body stays on the striker's
//! side of the wall (passing wholly through is the worst case, and within
//! one tick the depth check alone could miss it).
//!
//! Variants: strikers a circle or a box, bullet or not, at 50-2000
//! units/s; struck bodies a box or a circle, 0.01× and 1× the striker's
//! mass, bullet or not; walls 0.02 and 2 thick, fixed or kinematic at
//! rest, 0.3 to 5 beyond the struck body; e = 1; at the origin and near
//! the world's bounds; along +x and along −y; gravity off.
//!
//! Figures print with `--nocapture`.

use clockwork2d::prelude::*;

const SLOP: f64 = 1e-4;
/// Read-back rounding of a position: an I32F32 step is 2.3e-10 and a
/// position is rounded a few times per step; 1e-9 is four steps.
const ROUND: f64 = 1e-9;
/// Half-size of both bodies (circle radius, box half side).
const SIZE: f64 = 0.25;

struct Case {
    speed: f64,
    striker_box: bool,
    striker_bullet: bool,
    struck_box: bool,
    struck_bullet: bool,
    /// Struck body's mass over the striker's.
    ratio: f64,
    wall: f64,
    kinematic: bool,
    gap: f64,
    origin: (f64, f64),
    down: bool,
}

fn shape(boxed: bool) -> Shape {
    if boxed {
        Shape::aabb(vec2(SIZE, SIZE))
    } else {
        Shape::circle(fx(SIZE))
    }
}

/// Worst depth of either body past the wall's near face (local s ≥ 0 is
/// the wall), and whether the struck body's centre ever got past it.
fn run(c: &Case) -> (f64, bool) {
    let mut world = World::new(WorldSettings {
        gravity: vec2(0.0, 0.0),
        sleep_enabled: false,
        ..WorldSettings::default()
    });
    let to_world = |s: f64, q: f64| {
        if c.down {
            vec2(c.origin.0 + q, c.origin.1 - s)
        } else {
            vec2(c.origin.0 + s, c.origin.1 + q)
        }
    };
    let along = |p: (f64, f64)| {
        if c.down {
            c.origin.1 - p.1
        } else {
            p.0 - c.origin.0
        }
    };
    let wall_half = if c.down {
        vec2(3.0, c.wall / 2.0)
    } else {
        vec2(c.wall / 2.0, 3.0)
    };
    let wall_def = if c.kinematic {
        BodyDef::kinematic(Shape::aabb(wall_half))
    } else {
        BodyDef::fixed(Shape::aabb(wall_half))
    };
    world
        .add_body(wall_def.position(to_world(c.wall / 2.0, 0.0)))
        .expect("wall");
    let mass = 0.1;
    let struck_at = -c.gap - SIZE;
    let struck = world
        .add_body(
            BodyDef::dynamic(shape(c.struck_box))
                .mass(fx(mass * c.ratio))
                .friction(fx(0.0))
                .restitution(fx(1.0))
                .bullet(c.struck_bullet)
                .position(to_world(struck_at, 0.0)),
        )
        .expect("struck");
    // The striker starts 1.3 ticks of flight before the struck body.
    let start = struck_at - 2.0 * SIZE - 1.3 * c.speed / 60.0 - 0.01;
    let v = if c.down {
        vec2(0.0, -c.speed)
    } else {
        vec2(c.speed, 0.0)
    };
    let striker = world
        .add_body(
            BodyDef::dynamic(shape(c.striker_box))
                .mass(fx(mass))
                .friction(fx(0.0))
                .restitution(fx(1.0))
                .bullet(c.striker_bullet)
                .position(to_world(start, 0.0))
                .velocity(v),
        )
        .expect("striker");
    let (mut depth, mut through) = (f64::MIN, false);
    for _ in 0..60 {
        world.step();
        for id in [striker, struck] {
            let s = along(world.body(id).unwrap().position().to_f64());
            depth = depth.max(s + SIZE);
            through |= id == struck && s > 0.0;
        }
    }
    (depth, through)
}

#[test]
fn a_body_launched_by_a_bounce_never_passes_into_a_wall_beyond_its_margin() {
    let mut cases = Vec::new();
    for speed in [50.0, 300.0, 2000.0] {
        for striker_box in [false, true] {
            for striker_bullet in [false, true] {
                for struck_box in [true, false] {
                    for struck_bullet in [false, true] {
                        for ratio in [0.01, 1.0] {
                            for wall in [0.02, 2.0] {
                                for kinematic in [false, true] {
                                    for gap in [0.3, 1.0, 5.0] {
                                        for (origin, down) in
                                            [((0.0, 0.0), false), ((30_000.0, -30_000.0), true)]
                                        {
                                            cases.push(Case {
                                                speed,
                                                striker_box,
                                                striker_bullet,
                                                struck_box,
                                                struck_bullet,
                                                ratio,
                                                wall,
                                                kinematic,
                                                gap,
                                                origin,
                                                down,
                                            });
                                        }
                                    }
                                }
                            }
                        }
                    }
                }
            }
        }
    }
    let mut failures = Vec::new();
    let mut worst = f64::MIN;
    for c in &cases {
        let (depth, through) = run(c);
        worst = worst.max(depth);
        if depth > SLOP + ROUND || through {
            failures.push(format!(
                "v {} striker box {} bullet {} struck box {} bullet {} ratio {} wall {} kinematic {} gap {} at {:?} down {}: depth {depth:.3e}, through {through}",
                c.speed, c.striker_box, c.striker_bullet, c.struck_box, c.struck_bullet,
                c.ratio, c.wall, c.kinematic, c.gap, c.origin, c.down
            ));
        }
    }
    println!(
        "{} launches: worst depth in the wall {worst:.3e}; {} fail",
        cases.len(),
        failures.len()
    );
    for f in failures
        .iter()
        .take(std::env::var("ALL").map_or(30, |_| usize::MAX))
    {
        println!("  {f}");
    }
    assert!(
        failures.is_empty(),
        "{} of {} launches fail",
        failures.len(),
        cases.len()
    );
}
