//! Rebounds (issue 12): the motion after a bounce within a tick is checked
//! against the world like any other motion. A fast body between two fixed
//! walls never leaves them, keeps its speed (e = 1), never gains energy.
//!
//! Gravity is off (gravity scale 0) unless a test says otherwise, so a
//! shot is a straight line and its speed is a conserved quantity: with
//! e = 1 and fixed walls, each bounce reverses the normal velocity exactly.
//!
//! Run with `--nocapture` to see the figures.

mod common;

use clockwork2d::prelude::*;
use clockwork2d::world::MAX_BULLET_IMPACTS;

const DT: f64 = 1.0 / 60.0;

/// The linear slop (default settings): the tolerance of "touching".
const SLOP: f64 = 1e-4;

/// Fixed walls of half extents (`half_thickness`, 2) centred at `left` and
/// `right`, and a shot of `shape` from `start` with `velocity`.
struct Corridor {
    world: World,
    shot: BodyId,
    /// The shot's centre must stay within these (inner faces minus its
    /// half extent along x).
    lo: f64,
    hi: f64,
}

#[allow(clippy::too_many_arguments)] // one call per scene variant, every field named at the call
fn corridor(
    left: f64,
    right: f64,
    half_thickness: f64,
    shape: Shape,
    half_x: f64,
    start: Vec2,
    velocity: Vec2,
    bullet: bool,
    gravity_scale: f64,
) -> Corridor {
    let mut world = World::new(WorldSettings {
        sleep_enabled: false,
        ..WorldSettings::default()
    });
    for x in [left, right] {
        world
            .add_body(BodyDef::fixed(Shape::aabb(vec2(half_thickness, 2.0))).position(vec2(x, 0.0)))
            .unwrap();
    }
    // A floor and ceiling close the corridor for shots with gravity.
    for y in [-2.1, 2.1] {
        world
            .add_body(
                BodyDef::fixed(Shape::aabb(vec2((right - left) / 2.0 + 1.0, 0.1)))
                    .position(vec2((left + right) / 2.0, y)),
            )
            .unwrap();
    }
    let shot = world
        .add_body(
            BodyDef::dynamic(shape)
                .position(start)
                .velocity(velocity)
                .restitution(fx(1.0))
                .friction(fx(0.0))
                .gravity_scale(fx(gravity_scale))
                .bullet(bullet),
        )
        .unwrap();
    Corridor {
        world,
        shot,
        lo: left + half_thickness + half_x,
        hi: right - half_thickness - half_x,
    }
}

/// What a run showed.
struct Run {
    /// Worst excursion of the centre beyond the allowed range (≤ 0: inside).
    worst_outside: f64,
    /// Speed range over the run, relative to the initial speed.
    min_speed: f64,
    max_speed: f64,
    first_x: f64,
}

fn run(c: &mut Corridor, ticks: usize) -> Run {
    let v0 = c.world.body(c.shot).unwrap().velocity();
    let speed0 = v0.x.to_f64().hypot(v0.y.to_f64());
    let mut r = Run {
        worst_outside: f64::NEG_INFINITY,
        min_speed: f64::INFINITY,
        max_speed: 0.0,
        first_x: 0.0,
    };
    for tick in 0..ticks {
        c.world.step();
        let b = c.world.body(c.shot).unwrap();
        let x = b.position().x.to_f64();
        if tick == 0 {
            r.first_x = x;
        }
        r.worst_outside = r.worst_outside.max(c.lo - x).max(x - c.hi);
        let speed = b.velocity().x.to_f64().hypot(b.velocity().y.to_f64()) / speed0;
        r.min_speed = r.min_speed.min(speed);
        r.max_speed = r.max_speed.max(speed);
    }
    r
}

/// The scene: walls `aabb(0.1, 2)` at x = 5 and x = −3, a bullet
/// circle r 0.05 at the origin at (600, 0). Continuous motion: it reaches
/// the right wall (inner face 4.9, centre 4.85) after 4.85 units, turns,
/// and travels the remaining 10 − 4.85 = 5.15 back: x = −0.3 after one tick.
#[test]
fn rebound_between_two_walls_never_passes_either_wall() {
    for bullet in [true, false] {
        let mut c = corridor(
            -3.0,
            5.0,
            0.1,
            Shape::circle(fx(0.05)),
            0.05,
            vec2(0.0, 0.0),
            vec2(600.0, 0.0),
            bullet,
            0.0,
        );
        let r = run(&mut c, 600);
        println!(
            "two walls, 600 u/s, bullet {bullet}: x after one tick {:.4} (continuous: -0.3000), worst excursion beyond a wall {:+.2e}, speed in [{:.6}, {:.6}] of the initial",
            r.first_x, r.worst_outside, r.min_speed, r.max_speed
        );
        assert!(
            r.worst_outside <= SLOP,
            "left the corridor by {}",
            r.worst_outside
        );
        assert!(r.max_speed <= 1.0 + 1e-9, "gained speed: {}", r.max_speed);
        if bullet {
            // The first tick is exactly one bounce: the position is the
            // continuous one up to the TOI's rounding (far below 1e-6).
            assert!(
                (r.first_x + 0.3).abs() < 1e-6,
                "first tick ended at {}",
                r.first_x
            );
            assert!(r.min_speed >= 0.99, "lost speed: {}", r.min_speed);
        }
    }
}

/// The unfolded coordinate of a shot bouncing between `lo` and `hi`: its
/// position on a loop of length `2(hi − lo)` (out along +x, back along −x).
fn unfolded(x: f64, vx: f64, lo: f64, hi: f64) -> f64 {
    if vx >= 0.0 {
        x - lo
    } else {
        2.0 * (hi - lo) - (x - lo)
    }
}

/// A bullet between walls 1.0 apart (inner faces) at 1000 u/s, e = 1: it
/// never escapes, keeps its speed within 1 %, never gains energy. The
/// ideal number of bounces per tick is `v·dt / (gap − 2r)` = 16.67 / 0.9 =
/// 18.5. Bounces within a tick are not observable from outside, but the
/// travel is: the unfolded coordinate must advance by `v·dt` modulo the
/// loop length each tick (a shot that stopped at the bounce cap would fall
/// behind the ideal phase).
#[test]
fn bullet_between_walls_one_apart_never_escapes() {
    for (speed, shape, half_x, label) in [
        (1000.0, Shape::circle(fx(0.05)), 0.05, "circle r 0.05"),
        (1000.0, Shape::aabb(vec2(0.05, 0.05)), 0.05, "box 0.1×0.1"),
        (400.0, Shape::circle(fx(0.05)), 0.05, "circle r 0.05"),
        (2500.0, Shape::circle(fx(0.1)), 0.1, "circle r 0.1"),
    ] {
        // Inner faces at ±0.5: walls 0.2 thick centred at ±0.6.
        let mut c = corridor(
            -0.6,
            0.6,
            0.1,
            shape,
            half_x,
            vec2(0.0, 0.0),
            vec2(speed, 0.0),
            true,
            0.0,
        );
        let (lo, hi) = (c.lo, c.hi);
        let loop_length = 2.0 * (hi - lo);
        let ideal_travel = speed * DT;
        let ideal_bounces = ideal_travel / (hi - lo);
        let mut worst_outside = f64::NEG_INFINITY;
        let (mut min_speed, mut max_speed) = (f64::INFINITY, 0.0f64);
        let mut phase_matches = 0;
        let mut worst_phase = 0.0f64;
        let ticks = 600;
        let mut previous = unfolded(0.0, speed, lo, hi);
        for _ in 0..ticks {
            c.world.step();
            let b = c.world.body(c.shot).unwrap();
            let (x, vx) = (b.position().x.to_f64(), b.velocity().x.to_f64());
            worst_outside = worst_outside.max(lo - x).max(x - hi);
            let s = b.velocity().x.to_f64().hypot(b.velocity().y.to_f64()) / speed;
            min_speed = min_speed.min(s);
            max_speed = max_speed.max(s);
            let u = unfolded(x, vx, lo, hi);
            let advance = (u - previous).rem_euclid(loop_length);
            let error = (advance - ideal_travel.rem_euclid(loop_length)).abs();
            let error = error.min(loop_length - error);
            worst_phase = worst_phase.max(error);
            if error < 1e-4 {
                phase_matches += 1;
            }
            previous = u;
        }
        // With the ideal travel every tick the bullet made the ideal number
        // of bounces; beyond the cap it stops at its last impact.
        let capped = ideal_bounces > f64::from(MAX_BULLET_IMPACTS);
        println!(
            "{label} at {speed} u/s between walls 1.0 apart: ideal {ideal_bounces:.2} bounces per tick (cap {MAX_BULLET_IMPACTS}); travel matched the ideal in {phase_matches}/{ticks} ticks (worst phase error {worst_phase:.2e}){}; worst excursion {worst_outside:+.2e}; speed in [{min_speed:.6}, {max_speed:.6}]",
            if capped {
                ", capped: at most the cap per tick"
            } else {
                ", so the ideal bounces per tick"
            }
        );
        if !capped {
            assert_eq!(
                phase_matches, ticks,
                "{label}: travel fell behind the ideal"
            );
        }
        assert!(worst_outside <= SLOP, "{label} escaped by {worst_outside}");
        assert!(min_speed >= 0.99, "{label} lost speed: {min_speed}");
        assert!(max_speed <= 1.0 + 1e-9, "{label} gained speed: {max_speed}");
    }
}

/// Variants: walls at other distances, diagonal shots, gravity on, boxes;
/// the shot stays inside, never gains speed.
#[test]
fn rebound_variants_stay_inside() {
    let mut worst = f64::NEG_INFINITY;
    let mut cases = 0;
    for (left, right) in [(-3.0, 5.0), (-0.3, 0.45), (-20.0, 1.0), (-1.0, 30.0)] {
        for speed in [90.0, 600.0, 3000.0] {
            for (shape, half_x) in [
                (Shape::circle(fx(0.05)), 0.05),
                (Shape::circle(fx(0.12)), 0.12),
                (Shape::aabb(vec2(0.08, 0.03)), 0.08),
            ] {
                for (gravity_scale, vy) in [(0.0, 0.0), (1.0, 0.0), (0.0, 0.3)] {
                    let mut c = corridor(
                        left,
                        right,
                        0.1,
                        shape,
                        half_x,
                        vec2(0.0, 0.0),
                        vec2(speed, vy * speed),
                        true,
                        gravity_scale,
                    );
                    let r = run(&mut c, 240);
                    worst = worst.max(r.worst_outside);
                    cases += 1;
                    assert!(
                        r.worst_outside <= SLOP,
                        "walls ({left}, {right}), {speed} u/s, {shape:?}, g {gravity_scale}, vy {vy}: out by {}",
                        r.worst_outside
                    );
                    if gravity_scale == 0.0 {
                        assert!(r.max_speed <= 1.0 + 1e-9, "gained speed {}", r.max_speed);
                    }
                }
            }
        }
    }
    println!("{cases} corridor variants: worst excursion beyond a wall {worst:+.2e}");
}
