//! `WorldSettings::max_speed` is the largest speed a body may have between
//! steps (clamped per axis): after every step, no body's velocity has a
//! component above it, whatever the collisions of the step did.
//!
//! The solve itself can produce more. A head-on elastic collision of a body
//! of mass `M` at speed `v` with a body of mass `m` at rest sends the light
//! one off at `2·M·v/(M + m)`: for `M ≫ m` and `v = max_speed` that is
//! nearly twice the limit. A chain of touching bodies, each half the mass
//! of the one before, multiplies it again at every link (`4/3` per link at
//! mass ratio 2). Before the stored velocities were clamped, a 1000:1 pair
//! left the step at 8 183.8 units/s under the default limit of 4 096.
//!
//! The cases: masses 1 / 1 000 / 2²⁰ against 1/1 024 and 1, restitution
//! 0, 0.5 and 1, along +x, −y and the diagonal, limits 100, 4 096 (the
//! default) and 65 536, substeps 1 and 4, gravity off and on, box or
//! circle striking, and a chain of five bodies halving in mass. Each runs
//! 120 ticks (the striker crosses 100 units at the limit in under 2 s).
//!
//! Besides the bound, the clamp must not stop the struck body: when the
//! physical answer is above the limit, the light body (1/1 024 under a
//! heavy striker, restitution 1, head-on along an axis) leaves at exactly
//! the limit along the striker's direction.

use clockwork2d::prelude::*;

/// Every component of every body's velocity is within `max_speed`.
fn assert_within_limit(world: &World, case: &str, tick: u32) {
    let max = world.settings().max_speed;
    for (id, body) in world.bodies() {
        let v = body.velocity();
        assert!(
            v.x.abs() <= max && v.y.abs() <= max,
            "{case}: {id:?} left tick {tick} at {v:?}, above max_speed {max}"
        );
    }
}

struct Case {
    heavy_mass: f64,
    light_mass: f64,
    restitution: f64,
    direction: (f64, f64),
    max_speed: f64,
    substeps: u32,
    gravity: f64,
    box_striker: bool,
}

/// Runs one striker against one resting body (or a chain of `links`
/// bodies halving in mass); returns the light end's velocity at the end.
fn run(case: &Case, links: u32) -> Vec2 {
    let name = format!(
        "M {} m {} e {} dir {:?} limit {} substeps {} g {} box {} links {links}",
        case.heavy_mass,
        case.light_mass,
        case.restitution,
        case.direction,
        case.max_speed,
        case.substeps,
        case.gravity,
        case.box_striker
    );
    let mut world = World::new(WorldSettings {
        gravity: vec2(0.0, case.gravity),
        max_speed: fx(case.max_speed),
        substeps: case.substeps,
        sleep_enabled: false,
        ..WorldSettings::default()
    });
    let (dx, dy) = case.direction;
    let v = vec2(dx * case.max_speed, dy * case.max_speed);
    let striker_shape = if case.box_striker {
        Shape::aabb(vec2(0.5, 0.5))
    } else {
        Shape::circle(fx(0.5))
    };
    world
        .add_body(
            BodyDef::dynamic(striker_shape)
                .position(vec2(-dx * 100.0, -dy * 100.0))
                .velocity(v)
                .mass(fx(case.heavy_mass))
                .restitution(fx(case.restitution))
                .friction(fx(0.0)),
        )
        .unwrap();
    // The struck bodies touch in a row along the direction, each half the
    // mass of the one before (one body when links == 1).
    let (len, mut mass) = ((dx * dx + dy * dy).sqrt(), case.light_mass);
    let (ux, uy) = (dx / len, dy / len);
    let mut last = None;
    for k in 0..links {
        let at = f64::from(k) * 0.5;
        last = Some(
            world
                .add_body(
                    BodyDef::dynamic(Shape::circle(fx(0.25)))
                        .position(vec2(ux * at, uy * at))
                        .mass(fx(mass))
                        .restitution(fx(case.restitution))
                        .friction(fx(0.0)),
                )
                .unwrap(),
        );
        mass = (mass / 2.0).max(1.0 / 1024.0);
    }
    for tick in 1..=120 {
        world.step();
        assert_within_limit(&world, &name, tick);
    }
    world.body(last.unwrap()).unwrap().velocity()
}

#[test]
fn no_body_leaves_a_step_faster_than_max_speed() {
    let mut cases = 0;
    for heavy_mass in [1.0, 1000.0, 1_048_576.0] {
        for light_mass in [1.0 / 1024.0, 1.0] {
            for restitution in [0.0, 0.5, 1.0] {
                for direction in [(1.0, 0.0), (0.0, -1.0), (1.0, 1.0)] {
                    for max_speed in [100.0, 4096.0, 65536.0] {
                        for (substeps, gravity, box_striker) in
                            [(1, 0.0, true), (4, 0.0, false), (1, -10.0, false)]
                        {
                            let case = Case {
                                heavy_mass,
                                light_mass,
                                restitution,
                                direction,
                                max_speed,
                                substeps,
                                gravity,
                                box_striker,
                            };
                            run(&case, 1);
                            cases += 1;
                        }
                    }
                }
            }
        }
    }
    println!("{cases} single impacts: no velocity component above max_speed after any tick");
}

#[test]
fn a_chain_of_halving_masses_stays_within_max_speed() {
    // Physically the last of five links halving from 1 leaves at
    // (4/3)^4 ≈ 3.2 times the striker's speed, under a striker of mass 2.
    for direction in [(1.0, 0.0), (0.0, -1.0), (1.0, 1.0)] {
        for max_speed in [100.0, 4096.0] {
            let case = Case {
                heavy_mass: 2.0,
                light_mass: 1.0,
                restitution: 1.0,
                direction,
                max_speed,
                substeps: 1,
                gravity: 0.0,
                box_striker: false,
            };
            run(&case, 5);
        }
    }
}

#[test]
fn a_light_body_struck_above_the_limit_leaves_at_the_limit() {
    // 2·M·v/(M + m) with M = 2^20, m = 1/1024: 2v·(1 − 2^-30) > v, so the
    // physical answer is above the limit and the clamp gives exactly it.
    for (dx, dy) in [(1.0, 0.0), (0.0, -1.0), (-1.0, 0.0)] {
        for max_speed in [100.0, 4096.0] {
            let case = Case {
                heavy_mass: 1_048_576.0,
                light_mass: 1.0 / 1024.0,
                restitution: 1.0,
                direction: (dx, dy),
                max_speed,
                substeps: 1,
                gravity: 0.0,
                box_striker: true,
            };
            let v = run(&case, 1);
            assert_eq!(
                (v.x, v.y),
                (fx(dx * max_speed), fx(dy * max_speed)),
                "struck along ({dx}, {dy}) under limit {max_speed}: left at {v:?}"
            );
        }
    }
}
