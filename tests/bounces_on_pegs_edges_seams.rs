//! A body dropped from rest bounces back to `e²·h` wherever it lands
//! flat: on the ground near the origin and near the world's bounds
//! (y = −32 000), on the top point of a fixed circle, on a fixed box's top
//! face 0.01 inside its edge, exactly on the seam between two flush floor
//! tiles (a circle, and a box), for `e` = 1 and 0.5.
//!
//! The physics: the engine times a bounce to the instant of contact and
//! launches with `e` times the speed at the surface (tests/contacts_bounce.rs).
//! Where the contact normal is vertical (each landing here: a circle on a
//! face or on a circle's top point, a box on a face, a seam under the
//! body's centre), the outgoing flight is vertical with apex `e²` times the
//! incoming one's. Semi-implicit Euler from rest at height `h` samples the
//! parabola `y_n = h − g·h_t²·n(n+1)/2` (`h_t` the tick), whose vertex is
//! `g·h_t²/8` above `h`; the highest sample of the outgoing flight lies at
//! most `g·h_t²/8` below that flight's vertex. With the contact itself
//! settled anywhere within the linear slop, the first apex (highest sample
//! after the bounce, measured from the surface) must be within
//! `(1 + e²)·g·h_t²/8 + slop` of `e²·h` (8e-4 here), never higher than
//! that: energy is never gained.
//!
//! Run with `--nocapture` to see the table.

use clockwork2d::prelude::*;

const G: f64 = 10.0;
const TICK: f64 = 1.0 / 60.0;
const SLOP: f64 = 1e-4;
/// The dropped body's radius or half extent.
const SIZE: f64 = 0.25;
const DROP: f64 = 2.0;

/// Where the body lands; the surface is at `y = level`.
#[derive(Clone, Copy, Debug)]
enum Landing {
    Ground,
    /// The top point of a fixed circle of radius 0.5.
    CircleTop,
    /// A fixed unit box's top face, the body's centre 0.01 inside its edge.
    NearEdge,
    /// Two flush fixed tiles meeting under the body's centre.
    Seam,
}

fn fixed(world: &mut World, shape: Shape, at: (f64, f64)) {
    world
        .add_body(BodyDef::fixed(shape).position(vec2(at.0, at.1)))
        .expect("fixed body");
}

/// The first apex above the surface after the first bounce.
fn first_apex(landing: Landing, square: bool, e: f64, level: f64) -> f64 {
    let mut world = World::new(WorldSettings::default());
    let mut x = 0.0;
    match landing {
        Landing::Ground => fixed(&mut world, Shape::aabb(vec2(50.0, 0.5)), (0.0, level - 0.5)),
        Landing::CircleTop => fixed(&mut world, Shape::circle(fx(0.5)), (0.0, level - 0.5)),
        Landing::NearEdge => {
            fixed(&mut world, Shape::aabb(vec2(0.5, 0.5)), (0.0, level - 0.5));
            x = 0.49;
        }
        Landing::Seam => {
            fixed(&mut world, Shape::aabb(vec2(1.0, 0.5)), (-1.0, level - 0.5));
            fixed(&mut world, Shape::aabb(vec2(1.0, 0.5)), (1.0, level - 0.5));
        }
    }
    let shape = if square {
        Shape::aabb(vec2(SIZE, SIZE))
    } else {
        Shape::circle(fx(SIZE))
    };
    let body = world
        .add_body(
            BodyDef::dynamic(shape)
                .restitution(fx(e))
                .position(vec2(x, level + SIZE + DROP)),
        )
        .expect("dropped body");
    let (mut bounced, mut apex, mut previous_vy) = (false, f64::MIN, 0.0);
    // The fall takes ~38 ticks, the rise as many: 150 ticks cover both.
    for _ in 0..150 {
        world.step();
        let b = world.body(body).unwrap();
        let vy = b.velocity().to_f64().1;
        if !bounced && vy > 0.0 && previous_vy < 0.0 {
            bounced = true;
        }
        if bounced {
            apex = apex.max(b.position().to_f64().1 - SIZE - level);
            if vy < 0.0 && previous_vy >= 0.0 {
                break;
            }
        }
        previous_vy = vy;
    }
    assert!(bounced, "{landing:?}: no bounce");
    apex
}

#[test]
fn flat_landings_bounce_back_to_e_squared_h() {
    let cases: &[(Landing, bool, f64)] = &[
        (Landing::Ground, false, 0.0),
        (Landing::Ground, false, -32_000.0),
        (Landing::Ground, true, -32_000.0),
        (Landing::CircleTop, false, 0.0),
        (Landing::NearEdge, false, 0.0),
        (Landing::NearEdge, true, 0.0),
        (Landing::Seam, false, 0.0),
        (Landing::Seam, true, 0.0),
    ];
    for &(landing, square, level) in cases {
        for e in [1.0, 0.5] {
            let apex = first_apex(landing, square, e, level);
            let expected = e * e * DROP;
            let tolerance = (1.0 + e * e) * G * TICK * TICK / 8.0 + SLOP;
            println!(
                "{} on {landing:?} at level {level}, e {e}: first apex {apex:.5} (e^2 h {expected:.5}, tolerance {tolerance:.1e})",
                if square { "box" } else { "circle" }
            );
            assert!(
                (apex - expected).abs() <= tolerance,
                "{landing:?} square {square} e {e}: apex {apex} against {expected}"
            );
        }
    }
}
