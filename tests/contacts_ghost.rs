//! Ghost hits (issue 12): a speculative contact that cannot close does
//! nothing. A body that passes a corner or a gap with clearance is neither
//! slowed nor deflected, at any speed up to `max_speed`, bullet or not.
//!
//! Gravity is off, friction is the default: a body that never touches
//! anything must keep its velocity **bit for bit** (nothing else acts on
//! it), and its path must be the straight line, so the check is exact:
//! the final velocity equals the initial one, and the coordinate across
//! the motion never changes.
//!
//! Run with `--nocapture` to see the figures.

mod common;

use clockwork2d::prelude::*;

const DT: f64 = 1.0 / 60.0;

fn zero_gravity() -> World {
    World::new(WorldSettings {
        gravity: Vec2::ZERO,
        sleep_enabled: false,
        ..WorldSettings::default()
    })
}

/// Whether a body fired with `velocity` from `start` past the obstacles
/// keeps its velocity and its straight line; returns the ticks run and the
/// worst deviation (velocity change, sideways drift).
fn passes(
    world: &mut World,
    shape: Shape,
    start: Vec2,
    velocity: Vec2,
    bullet: bool,
    ticks: usize,
) -> (bool, f64) {
    let id = world
        .add_body(
            BodyDef::dynamic(shape)
                .position(start)
                .velocity(velocity)
                .bullet(bullet),
        )
        .unwrap();
    let (sx, sy) = (start.x.to_f64(), start.y.to_f64());
    let (vx, vy) = (velocity.x.to_f64(), velocity.y.to_f64());
    let norm = vx.hypot(vy);
    let mut worst = 0.0f64;
    let mut clean = true;
    for _ in 0..ticks {
        world.step();
        let b = world.body(id).unwrap();
        if b.velocity() != velocity {
            clean = false;
        }
        // Distance of the centre from the straight line of the shot.
        let (x, y) = (b.position().x.to_f64() - sx, b.position().y.to_f64() - sy);
        let off = (x * vy - y * vx).abs() / norm;
        worst = worst.max(off);
    }
    // Rounding of `position += v·h` is the only thing that may move the
    // centre off the exact line: an ulp per tick per axis.
    (clean && worst < 1e-6, worst)
}

/// The scene: a fixed 2×2 box whose bottom face is at y = 0.13, a
/// ball r 0.05 at (40, 0) moving (2000, 0), 0.08 below the box. It must
/// fly on untouched (before: stopped dead at x = 48.95; at 60 u/s,
/// deflected).
#[test]
fn ball_under_a_box_is_not_stopped_at_any_speed() {
    for speed in [2000.0, 60.0, 4096.0] {
        for bullet in [false, true] {
            let mut w = zero_gravity();
            w.add_body(BodyDef::fixed(Shape::aabb(vec2(1.0, 1.0))).position(vec2(50.0, 1.13)))
                .unwrap();
            let ticks = ((15.0 / (speed * DT)).ceil() as usize).max(3) + 2;
            let (ok, drift) = passes(
                &mut w,
                Shape::circle(fx(0.05)),
                vec2(40.0, 0.0),
                vec2(speed, 0.0),
                bullet,
                ticks,
            );
            println!(
                "ball under the box at {speed} u/s, bullet {bullet}: untouched {ok}, drift {drift:.2e}"
            );
            assert!(ok, "{speed} u/s bullet {bullet}: slowed or deflected");
        }
    }
}

/// Clearance sweep: a body passing a fixed box's corner with a clearance
/// from 0.001 to 0.2, at speeds from 1 to 2000 u/s, bullet and not,
/// circle and box, moving along an axis just below the bottom face and
/// diagonally past the corner. Zero slowed or deflected.
#[test]
fn clearance_sweep_past_a_corner_is_never_touched() {
    let clearances = [0.001, 0.002, 0.005, 0.01, 0.03, 0.08, 0.2];
    let speeds = [1.0, 3.0, 10.0, 30.0, 60.0, 150.0, 400.0, 1000.0, 2000.0];
    let mut failures = Vec::new();
    let mut runs = 0;
    for &clearance in &clearances {
        for &speed in &speeds {
            for bullet in [false, true] {
                for (shape, half) in [
                    (Shape::circle(fx(0.05)), 0.05),
                    (Shape::aabb(vec2(0.05, 0.05)), 0.05),
                ] {
                    // Box half 1 at the origin: bottom face y = -1, corner
                    // (1, -1). The shot ends 1.5 past the far side.
                    // (a) Along +x, below the bottom face.
                    let y = -1.0 - half - clearance;
                    let start_x = -1.0 - half - (2.5 * speed * DT).max(0.3);
                    let ticks = ((3.0 - start_x) / (speed * DT)).ceil() as usize + 1;
                    let mut w = zero_gravity();
                    w.add_body(BodyDef::fixed(Shape::aabb(vec2(1.0, 1.0))))
                        .unwrap();
                    let (ok, drift) = passes(
                        &mut w,
                        shape,
                        vec2(start_x, y),
                        vec2(speed, 0.0),
                        bullet,
                        ticks.min(400),
                    );
                    runs += 1;
                    if !ok {
                        failures.push(format!("axis: clearance {clearance}, {speed} u/s, bullet {bullet}, {shape:?}: drift {drift:.2e}"));
                    }
                    // (b) Diagonally (direction (1, 1)/√2) past the corner
                    // (1, -1): the closest approach of the path to the
                    // corner is half-width + clearance (circle: distance
                    // from the corner to the line; box: the box's corner
                    // on the line x − y = const passes the box's corner
                    // with an L∞ gap of the clearance).
                    let (line_offset, label) = match shape {
                        Shape::Circle { .. } => ((half + clearance) * 2f64.sqrt(), "diag circle"),
                        Shape::Aabb { .. } => (2.0 * half + clearance, "diag box"),
                    };
                    // Centre path: (c.x + t, c.y + t) with c below-right of
                    // the corner: x − y = 2 + line_offset.
                    let back = (2.5 * speed * DT).max(0.5) / 2f64.sqrt();
                    let cx = 1.0 + line_offset / 2.0 - back;
                    let cy = -1.0 - line_offset / 2.0 - back;
                    let diag_speed = speed / 2f64.sqrt();
                    let ticks = ((2.0 * back + 2.0) / (diag_speed * DT)).ceil() as usize + 1;
                    let mut w = zero_gravity();
                    w.add_body(BodyDef::fixed(Shape::aabb(vec2(1.0, 1.0))))
                        .unwrap();
                    let (ok, drift) = passes(
                        &mut w,
                        shape,
                        vec2(cx, cy),
                        vec2(diag_speed, diag_speed),
                        bullet,
                        ticks.min(400),
                    );
                    runs += 1;
                    if !ok {
                        failures.push(format!("{label}: clearance {clearance}, {speed} u/s, bullet {bullet}: drift {drift:.2e}"));
                    }
                }
            }
        }
    }
    println!(
        "clearance sweep: {runs} runs, {} slowed or deflected",
        failures.len()
    );
    for f in failures.iter().take(20) {
        println!("  {f}");
    }
    assert!(
        failures.is_empty(),
        "{} of {runs} shots were touched",
        failures.len()
    );
}

/// A body passing another *circle* with clearance (the circle–circle
/// speculative contact), both fixed and dynamic targets.
#[test]
fn passing_a_circle_with_clearance_is_never_touched() {
    let mut failures = 0;
    let mut runs = 0;
    for clearance in [0.001, 0.01, 0.1] {
        for speed in [5.0, 100.0, 2000.0] {
            for fixed_target in [true, false] {
                let mut w = zero_gravity();
                let def = if fixed_target {
                    BodyDef::fixed(Shape::circle(fx(0.5)))
                } else {
                    BodyDef::dynamic(Shape::circle(fx(0.5)))
                };
                let target = w.add_body(def).unwrap();
                let y = -(0.5 + 0.05 + clearance);
                let start_x = -(2.5 * speed * DT).max(1.0);
                let ticks = ((2.0 - start_x) / (speed * DT)).ceil() as usize + 1;
                let (ok, _) = passes(
                    &mut w,
                    Shape::circle(fx(0.05)),
                    vec2(start_x, y),
                    vec2(speed, 0.0),
                    false,
                    ticks,
                );
                runs += 1;
                let target_still = w.body(target).unwrap().velocity() == Vec2::ZERO;
                if !(ok && target_still) {
                    failures += 1;
                    println!("touched: clearance {clearance}, {speed} u/s, fixed {fixed_target}");
                }
            }
        }
    }
    println!("passing a circle: {runs} runs, {failures} touched");
    assert_eq!(failures, 0);
}

/// A bullet through an open gap, wider than the bullet, between two fixed
/// boxes, passes: at the gap's centre and off-centre by up to the spare
/// width less the clearance.
#[test]
fn bullet_through_an_open_gap_passes() {
    for gap in [0.12, 0.2, 1.0] {
        for speed in [100.0, 1000.0, 4000.0] {
            for offset_fraction in [0.0, 0.4, -0.4] {
                let mut w = zero_gravity();
                // Two boxes 2 tall, the gap between y = -gap/2 and gap/2.
                w.add_body(
                    BodyDef::fixed(Shape::aabb(vec2(0.5, 1.0)))
                        .position(vec2(10.0, gap / 2.0 + 1.0)),
                )
                .unwrap();
                w.add_body(
                    BodyDef::fixed(Shape::aabb(vec2(0.5, 1.0)))
                        .position(vec2(10.0, -gap / 2.0 - 1.0)),
                )
                .unwrap();
                let r = 0.05;
                let spare = gap / 2.0 - r;
                let y = offset_fraction * spare;
                let ticks = (20.0 / (speed * DT)).ceil() as usize + 1;
                let (ok, drift) = passes(
                    &mut w,
                    Shape::circle(fx(r)),
                    vec2(0.0, y),
                    vec2(speed, 0.0),
                    true,
                    ticks,
                );
                println!(
                    "gap {gap}, {speed} u/s, offset {y:+.3}: passed untouched {ok} (drift {drift:.1e})"
                );
                assert!(
                    ok,
                    "gap {gap}, {speed} u/s, offset {y}: the bullet was stopped or deflected"
                );
            }
        }
    }
}
