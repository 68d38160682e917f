//! Coulomb friction against its analytic answers (issue 13 variants), at
//! the default step (dt = h = 1/60).
//!
//! * A body sliding on the ground at v₀ with friction μ (both bodies μ, so
//!   the pair's geometric mean is μ) decelerates at a = μ·g and stops
//!   after v₀²/(2μg). The integrator is semi-implicit Euler: each step the
//!   friction impulse (at most μ times the normal impulse m·g·h) takes
//!   a·h off the speed, then the position moves by the new speed times h,
//!   and the last step takes the speed exactly to zero. Its distance is
//!   the sum h·Σ v_k over the steps that end moving, which the test
//!   computes (`discrete_stop`); it differs from v₀²/(2a) by at most v₀·h/2
//!   + a·h² (half a step of motion at each end).
//! * A box on a kinematic platform that starts moving sideways at v: the
//!   box slips while friction accelerates it at μ·g, so it falls behind by
//!   the same sliding distance seen from the platform, then rides along
//!   without slipping (static friction holds it exactly: the relative x is
//!   constant from then on). A platform moving up or down at constant
//!   speed carries a two-box stack at its resting heights (two contacts in
//!   series: within 2·slop); one that starts moving down at v leaves the
//!   stack behind, which falls freely and lands on it after 2v/g.
//!
//! Figures print with `--nocapture`.

use clockwork2d::prelude::*;

const H: f64 = 1.0 / 60.0;
const SLOP: f64 = 1e-4;
/// Rounding allowance: positions and velocities are I32F32 (step 2.3e-10),
/// rounded a few times per tick over at most a few hundred ticks here.
const ROUND: f64 = 1e-6;

/// The semi-implicit Euler stopping distance: speeds v_k = v₀ − k·a·h
/// while positive, each moving the body v_k·h.
fn discrete_stop(v0: f64, a: f64) -> f64 {
    let mut v = v0;
    let mut d = 0.0;
    loop {
        v -= a * H;
        if v <= 0.0 {
            return d;
        }
        d += v * H;
    }
}

#[test]
fn a_body_sliding_to_rest_stops_after_v2_over_2_mu_g() {
    for (mu, v0, g, circle) in [
        (0.6, 5.0, 10.0, false),
        (0.6, 5.0, 10.0, true),
        (0.1, 5.0, 10.0, false),
        (1.0, 10.0, 10.0, false),
        (0.3, 3.0, 100.0, false),
        (0.05, 2.0, 10.0, true),
    ] {
        let mut world = World::new(WorldSettings {
            gravity: vec2(0.0, -g),
            ..WorldSettings::default()
        });
        world
            .add_body(
                BodyDef::fixed(Shape::aabb(vec2(500.0, 0.5)))
                    .position(vec2(0.0, -0.5))
                    .friction(fx(mu)),
            )
            .expect("ground");
        let shape = if circle {
            Shape::circle(fx(0.5))
        } else {
            Shape::aabb(vec2(0.5, 0.5))
        };
        let body = world
            .add_body(
                BodyDef::dynamic(shape)
                    .friction(fx(mu))
                    .position(vec2(0.0, 0.5))
                    .velocity(vec2(v0, 0.0)),
            )
            .expect("slider");
        let a = mu * g;
        let stop_ticks = (v0 / (a * H)).ceil() as u64;
        for _ in 0..stop_ticks + 60 {
            world.step();
        }
        let b = world.body(body).unwrap();
        let d = b.position().x.to_f64();
        let continuous = v0 * v0 / (2.0 * a);
        let discrete = discrete_stop(v0, a);
        println!(
            "slide μ {mu} v₀ {v0} g {g} circle {circle}: distance {d:.6}, v²/2μg {continuous:.6}, discrete sum {discrete:.6}, final v {:?}",
            b.velocity().to_f64()
        );
        assert!((d - discrete).abs() <= ROUND);
        assert!((d - continuous).abs() <= v0 * H / 2.0 + a * H * H + ROUND);
        assert_eq!(b.velocity().x, Fx::ZERO);
        assert!((b.position().y.to_f64() - 0.5).abs() <= SLOP);
    }
}

#[test]
fn a_box_on_a_moving_platform_slips_then_rides() {
    for (vx, mu) in [(2.0, 0.6), (2.0, 0.1), (1.0, 1.0)] {
        let mut world = World::new(WorldSettings::default());
        let platform = world
            .add_body(
                BodyDef::kinematic(Shape::aabb(vec2(20.0, 0.25)))
                    .position(vec2(0.0, -0.25))
                    .velocity(vec2(vx, 0.0))
                    .friction(fx(mu)),
            )
            .expect("platform");
        let cargo = world
            .add_body(
                BodyDef::dynamic(Shape::aabb(vec2(0.5, 0.5)))
                    .friction(fx(mu))
                    .position(vec2(0.0, 0.5)),
            )
            .expect("box");
        let a = mu * 10.0;
        // Seen from the platform the box starts at −v and slides to rest:
        // the same semi-implicit Euler sum as on fixed ground.
        let slip = -discrete_stop(vx, a);
        let caught = (vx / (a * H)).ceil() as u64 + 1;
        let rel = |world: &World| {
            world.body(cargo).unwrap().position().x.to_f64()
                - world.body(platform).unwrap().position().x.to_f64()
        };
        let mut at_catch = 0.0;
        for t in 1..=caught + 120 {
            world.step();
            if t == caught {
                at_catch = rel(&world);
            }
        }
        let end = rel(&world);
        println!(
            "platform at {vx} μ {mu}: box behind by {at_catch:.6} when caught (analytic {slip:.6}), {end:.6} two seconds later"
        );
        assert!((at_catch - slip).abs() <= ROUND);
        assert!((end - at_catch).abs() <= ROUND);
    }
}

#[test]
fn a_stack_on_a_platform_moving_up_or_down_rides_at_its_resting_heights() {
    for vy in [1.0, -1.0, 3.0, -3.0] {
        let mut world = World::new(WorldSettings::default());
        let platform = world
            .add_body(
                BodyDef::kinematic(Shape::aabb(vec2(20.0, 0.25)))
                    .position(vec2(0.0, -0.25))
                    .velocity(vec2(0.0, vy)),
            )
            .expect("platform");
        let boxes: Vec<BodyId> = [0.5, 1.5]
            .into_iter()
            .map(|y| {
                world
                    .add_body(BodyDef::dynamic(Shape::aabb(vec2(0.5, 0.5))).position(vec2(0.0, y)))
                    .expect("box")
            })
            .collect();
        // A platform moving down drops away from the resting stack, which
        // catches it up after falling for 2|v|/g.
        let landed = if vy < 0.0 {
            (2.0 * -vy / 10.0 / H).ceil() as u64
        } else {
            0
        };
        let mut worst = 0.0f64;
        for t in 1..=landed + 180 {
            world.step();
            let top = world.body(platform).unwrap().position().y.to_f64() + 0.25;
            // Half a second after landing (the first steps adjust the
            // stack to the platform's motion), both boxes at their resting
            // heights.
            if t > landed + 30 {
                for (k, &id) in boxes.iter().enumerate() {
                    let y = world.body(id).unwrap().position().y.to_f64();
                    worst = worst.max((y - (top + 0.5 + k as f64)).abs());
                }
            }
        }
        println!("platform moving at {vy}: worst height error of the stack {worst:.3e}");
        assert!(worst <= 2.0 * SLOP + ROUND);
    }
}

#[test]
fn a_stack_moving_with_its_platform_rides_without_slipping() {
    // A column spawned moving at the platform's velocity: no relative
    // motion, so friction has nothing to do and the boxes stay exactly
    // above the point of the platform they started on, at their resting
    // heights (n contacts in series: within n·slop).
    for (vx, n) in [(2.0, 5), (10.0, 10), (-7.0, 10)] {
        let mut world = World::new(WorldSettings::default());
        let platform = world
            .add_body(
                BodyDef::kinematic(Shape::aabb(vec2(100.0, 0.25)))
                    .position(vec2(0.0, -0.25))
                    .velocity(vec2(vx, 0.0)),
            )
            .expect("platform");
        let boxes: Vec<BodyId> = (0..n)
            .map(|i| {
                world
                    .add_body(
                        BodyDef::dynamic(Shape::aabb(vec2(0.5, 0.5)))
                            .position(vec2(0.0, 0.5 + i as f64))
                            .velocity(vec2(vx, 0.0)),
                    )
                    .expect("box")
            })
            .collect();
        let (mut slip, mut height) = (false, 0.0f64);
        for _ in 0..300 {
            world.step();
            let px = world.body(platform).unwrap().position().x;
            for (i, &id) in boxes.iter().enumerate() {
                let p = world.body(id).unwrap().position();
                slip |= p.x != px;
                height = height.max((p.y.to_f64() - 0.5 - i as f64).abs());
            }
        }
        println!(
            "{n} boxes riding a platform at {vx}: slipped {slip}, worst height error {height:.2e}"
        );
        assert!(!slip);
        assert!(height <= n as f64 * SLOP);
    }
}
