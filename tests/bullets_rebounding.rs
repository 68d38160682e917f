//! Rebounding bullets stay inside a closed box of thin walls: a bullet
//! (circle r 0.05 or box of half 0.05, restitution 1, friction 0) fired at
//! 200–4000 units/s inside a 10 × 10 room whose fixed walls are 0.1, 0.02
//! or 0.01 thick bounces off them hundreds of times in 10 s and never
//! gets through, gravity off and on.
//!
//! At 1000 units/s and 60 Hz the bullet crosses the room in 0.6 ticks, so
//! it meets a wall, rebounds and meets the next one within one step: each
//! step needs several times of impact, and a thin wall (4000 units/s
//! against 0.02: 3300 thicknesses a step) is only stopped by continuous
//! collision.
//!
//! The physics:
//! * **Containment.** The bullet's surface never goes past a wall's inner
//!   face by more than the linear slop (a resting contact may overlap by
//!   the slop; a bullet is never resting here, so this is generous).
//! * **Speed, gravity off.** The walls are fixed and the bullet elastic
//!   and frictionless: an e = 1 reflection off a fixed wall only flips one
//!   component, so the speed must stay what it was. It must not fall
//!   either, beyond rounding: each reflection rounds the flipped component
//!   by a few ulps of `2⁻³²`, and 600 ticks × up to 8 bounces × 4 ulps is
//!   far below the `10⁻⁵` relative allowed here, while a lost or damped
//!   bounce would lose a whole normal component.
//! * With gravity only containment is checked (the energy of several
//!   impacts inside one step under gravity is not settled yet).
//!
//! Run with `--nocapture` to see the table.

use clockwork2d::prelude::*;

const SLOP: f64 = 1e-4;
const TICKS: usize = 600;
/// Half the room's inner width and height.
const ROOM: f64 = 5.0;
/// The bullet's radius or half extent.
const BULLET: f64 = 0.05;

/// A closed room `[−ROOM, ROOM]²` of fixed walls `wall` thick.
fn room(gravity: bool, wall: f64) -> World {
    let mut world = World::new(WorldSettings {
        gravity: if gravity {
            vec2(0.0, -10.0)
        } else {
            Vec2::ZERO
        },
        sleep_enabled: false,
        ..WorldSettings::default()
    });
    let t = wall / 2.0;
    for (hx, hy, x, y) in [
        (ROOM + wall, t, 0.0, -ROOM - t),
        (ROOM + wall, t, 0.0, ROOM + t),
        (t, ROOM, -ROOM - t, 0.0),
        (t, ROOM, ROOM + t, 0.0),
    ] {
        world
            .add_body(BodyDef::fixed(Shape::aabb(vec2(hx, hy))).position(vec2(x, y)))
            .expect("wall");
    }
    world
}

#[test]
fn bullets_never_leave_a_room_of_thin_walls() {
    // (wall thickness, speed, angle in degrees, gravity, square bullet)
    let shots: [(f64, f64, f64, bool, bool); 10] = [
        (0.1, 1000.0, 0.0, false, false),
        (0.1, 1000.0, 37.0, false, false),
        (0.1, 1000.0, 45.0, false, false),
        (0.1, 1000.0, 37.0, false, true),
        (0.02, 4000.0, 23.0, false, false),
        (0.02, 4000.0, 61.0, false, true),
        (0.1, 1000.0, 37.0, true, false),
        (0.01, 3000.0, 1.0, true, false),
        (0.1, 200.0, 60.0, true, false),
        (0.01, 2000.0, 80.0, true, true),
    ];
    for &(wall, speed, angle_deg, gravity, square) in &shots {
        let mut world = room(gravity, wall);
        let a = angle_deg.to_radians();
        let shape = if square {
            Shape::aabb(vec2(BULLET, BULLET))
        } else {
            Shape::circle(fx(BULLET))
        };
        let bullet = world
            .add_body(
                BodyDef::dynamic(shape)
                    .restitution(fx(1.0))
                    .friction(fx(0.0))
                    .bullet(true)
                    .position(vec2(0.0, 0.0))
                    .velocity(vec2(speed * a.cos(), speed * a.sin())),
            )
            .expect("bullet");
        let (mut worst_past, mut min_speed, mut max_speed) = (f64::MIN, f64::MAX, 0.0f64);
        for tick in 1..=TICKS {
            world.step();
            let b = world.body(bullet).unwrap();
            let (x, y) = b.position().to_f64();
            let v = b.velocity().to_f64();
            let past = x.abs().max(y.abs()) + BULLET - ROOM;
            worst_past = worst_past.max(past);
            assert!(
                past <= SLOP,
                "wall {wall} speed {speed} angle {angle_deg}: the bullet is {past} past a wall's inner face at tick {tick}"
            );
            let now = v.0.hypot(v.1);
            min_speed = min_speed.min(now);
            max_speed = max_speed.max(now);
        }
        println!(
            "wall {} speed {} angle {} gravity {} {}: worst past the inner face {worst_past:.6}, speed {min_speed:.4}..{max_speed:.4}",
            wall,
            speed,
            angle_deg,
            gravity,
            if square { "square" } else { "circle" }
        );
        if !gravity {
            let tolerance = 1e-5 * speed;
            assert!(
                max_speed <= speed + tolerance && min_speed >= speed - tolerance,
                "elastic rebounds changed the speed: {min_speed}..{max_speed} of {}",
                speed
            );
        }
    }
}
