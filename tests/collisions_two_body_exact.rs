//! Two free bodies collide as Newton's law of restitution says: head-on
//! (circles and boxes, mass ratios 10⁻³ to 10³, one or both moving) and
//! oblique (circles, impact parameters 0.3–0.99 of the diameter), gravity
//! off, friction 0, at speeds from 2 to 300 units/s.
//!
//! The physics: along the contact normal `n` (the line of centres at the
//! instant of touching; for two boxes head-on the x axis) the pair takes
//! the impulse `j = −(1 + e)·v_n / (1/m₁ + 1/m₂)`, `v_n` the approach
//! speed along `n`; frictionless, the tangential velocities are untouched.
//! So `v₁' = v₁ + j·n/m₁`, `v₂' = v₂ − j·n/m₂`, momentum is kept exactly and,
//! with `e = 1`, kinetic energy too. An approach slower than the world's
//! `restitution_threshold` (1 unit/s by default) is treated as `e = 0` (the
//! documented rule); every case here approaches faster than that.
//!
//! Tolerance. The engine finds the instant of touching by its time of
//! impact and may solve the contact anywhere within the linear slop of
//! touching (gap `δ ∈ [0, slop]`). For circles of radius `r` whose line of
//! centres makes the angle `φ` with the motion, a gap `δ` turns the normal
//! by `tan φ · δ / (2r)` (d(sin φ) = −sin φ · dD / D at centre distance
//! `D = 2r`), so every velocity component may be off by
//! `speed · tan φ · slop / (2r)`. On top comes fixed-point rounding:
//! the normal is a unit vector to a few ulps of `q = 2⁻³²` (`speed · 10⁻⁸`
//! covers it), and the impulse and the inverse mass `1/m` are held to `q`
//! absolute, so each rounding of an impulse moves a body of mass `m` by
//! `q/m`; the solver's sweeps (8 velocity iterations, each touching the
//! row a few times) add at most 64 of them: `64·q/m_min`. Head-on
//! (`φ = 0`) only the rounding terms remain. Momentum is checked to
//! rounding alone (`(m₁ + m₂)·speed·10⁻⁸`); with `e = 1` the energy must
//! never exceed its start by more than rounding and is kept within the
//! normal-angle term.
//!
//! Sleep is off: a body left at a few thousandths of a unit per second (a
//! light striker rebounding off a 1000× heavier body leaves it at 0.004)
//! would otherwise fall asleep after `time_to_sleep` and stop, as designed.
//!
//! Run with `--nocapture` to see the table.

use clockwork2d::prelude::*;

const SLOP: f64 = 1e-4;
/// Fixed-point rounding allowance relative to the speed (see the header).
const ROUNDING: f64 = 1e-8;
/// The fixed-point resolution, 2⁻³².
const Q: f64 = 1.0 / 4_294_967_296.0;

fn free_space() -> World {
    World::new(WorldSettings {
        gravity: Vec2::ZERO,
        sleep_enabled: false,
        ..WorldSettings::default()
    })
}

/// Adds a frictionless body of mass `m` with restitution `e`.
fn body(
    world: &mut World,
    shape: Shape,
    m: f64,
    e: f64,
    at: (f64, f64),
    vel: (f64, f64),
) -> BodyId {
    world
        .add_body(
            BodyDef::dynamic(shape)
                .mass(fx(m))
                .friction(fx(0.0))
                .restitution(fx(e))
                .position(vec2(at.0, at.1))
                .velocity(vec2(vel.0, vel.1)),
        )
        .expect("body")
}

fn velocity(world: &World, id: BodyId) -> (f64, f64) {
    world.body(id).expect("body").velocity().to_f64()
}

/// The exact outcome of a collision along the unit normal `n` (from body 2
/// to body 1) of bodies with masses `m1`, `m2` and velocities `u1`, `u2`.
fn newton(
    n: (f64, f64),
    e: f64,
    (m1, u1): (f64, (f64, f64)),
    (m2, u2): (f64, (f64, f64)),
) -> ((f64, f64), (f64, f64)) {
    let vn = (u1.0 - u2.0) * n.0 + (u1.1 - u2.1) * n.1;
    assert!(vn < -1.0, "every case approaches faster than the threshold");
    let j = -(1.0 + e) * vn / (1.0 / m1 + 1.0 / m2);
    (
        (u1.0 + j * n.0 / m1, u1.1 + j * n.1 / m1),
        (u2.0 - j * n.0 / m2, u2.1 - j * n.1 / m2),
    )
}

fn kinetic(m: f64, v: (f64, f64)) -> f64 {
    0.5 * m * (v.0 * v.0 + v.1 * v.1)
}

fn worst_diff(a: (f64, f64), b: (f64, f64)) -> f64 {
    (a.0 - b.0).abs().max((a.1 - b.1).abs())
}

/// Checks one finished collision against the exact answer.
#[allow(clippy::too_many_arguments)]
fn check(
    label: &str,
    world: &World,
    (id1, m1, u1): (BodyId, f64, (f64, f64)),
    (id2, m2, u2): (BodyId, f64, (f64, f64)),
    n: (f64, f64),
    e: f64,
    normal_turn: f64,
) {
    let (x1, x2) = newton(n, e, (m1, u1), (m2, u2));
    let (g1, g2) = (velocity(world, id1), velocity(world, id2));
    let speed = (u1.0 - u2.0).hypot(u1.1 - u2.1);
    let err = worst_diff(g1, x1).max(worst_diff(g2, x2));
    let bound = speed * (normal_turn + ROUNDING) + 64.0 * Q / m1.min(m2);
    let p0 = (m1 * u1.0 + m2 * u2.0, m1 * u1.1 + m2 * u2.1);
    let p = (m1 * g1.0 + m2 * g2.0, m1 * g1.1 + m2 * g2.1);
    let momentum_err = worst_diff(p, p0);
    let momentum_bound = (m1 + m2) * speed * ROUNDING;
    let (ke0, ke) = (
        kinetic(m1, u1) + kinetic(m2, u2),
        kinetic(m1, g1) + kinetic(m2, g2),
    );
    println!(
        "{label}: v1 ({:.6}, {:.6}) exact ({:.6}, {:.6}); v2 ({:.6}, {:.6}) exact ({:.6}, {:.6}); error {err:.2e} (bound {bound:.2e}); momentum error {momentum_err:.2e}; KE {ke:.6} of {ke0:.6}",
        g1.0, g1.1, x1.0, x1.1, g2.0, g2.1, x2.0, x2.1
    );
    assert!(
        err <= bound,
        "{label}: velocities off by {err:e} (bound {bound:e})"
    );
    assert!(
        momentum_err <= momentum_bound,
        "{label}: momentum changed by {momentum_err:e} (bound {momentum_bound:e})"
    );
    let ke_rounding = ke0 * ROUNDING + speed * 64.0 * Q * (1.0 + m1.max(m2) / m1.min(m2));
    assert!(
        ke <= ke0 + ke_rounding,
        "{label}: kinetic energy rose from {ke0} to {ke}"
    );
    if e == 1.0 {
        let kept = ke0 * (1.0 - 2.0 * (normal_turn + ROUNDING)) - ke_rounding;
        assert!(ke >= kept, "{label}: elastic collision kept {ke} of {ke0}");
    }
}

/// Head-on along x: body 1 from the left, body 2 from the right.
#[test]
fn head_on_collisions_match_newtons_law() {
    let cases: &[(bool, f64, f64, f64, f64)] = &[
        // (boxes?, m2 / m1, u1, u2, e)
        (false, 1.0, 2.0, 0.0, 1.0),
        (false, 3.0, 2.0, 0.0, 1.0),
        (false, 1000.0, 2.0, 0.0, 1.0),
        (false, 0.001, 2.0, 0.0, 1.0),
        (false, 1.0, 2.0, 0.0, 0.5),
        (false, 4.0, 300.0, 0.0, 0.5),
        (false, 1.0, 1.5, 0.0, 1.0),
        (true, 1.0, 5.0, -5.0, 1.0),
        (true, 10.0, 30.0, -1.0, 1.0),
        (true, 0.01, 30.0, -30.0, 0.3),
        (true, 100.0, 250.0, 0.0, 1.0),
        (true, 1.0, 40.0, 0.0, 0.0),
    ];
    for &(boxes, m2, u1, u2, e) in cases {
        let shape = if boxes {
            Shape::aabb(vec2(0.5, 0.5))
        } else {
            Shape::circle(fx(0.5))
        };
        let mut world = free_space();
        // Start 6 apart (5 of gap): the fastest pair closes it within a
        // tick, the slowest (1.5 units/s) within 3.4 s.
        let a = body(&mut world, shape, 1.0, e, (-3.0, 0.0), (u1, 0.0));
        let b = body(&mut world, shape, m2, e, (3.0, 0.0), (u2, 0.0));
        for _ in 0..300 {
            world.step();
        }
        let label = format!(
            "head-on {} m2 {m2} u ({u1}, {u2}) e {e}",
            if boxes { "boxes" } else { "circles" }
        );
        check(
            &label,
            &world,
            (a, 1.0, (u1, 0.0)),
            (b, m2, (u2, 0.0)),
            (-1.0, 0.0),
            e,
            0.0,
        );
    }
}

/// Oblique: circle 1 moving along +x, circle 2 at rest at the origin, the
/// path of 1's centre `b · 2r` above 2's centre.
#[test]
fn oblique_circle_collisions_match_newtons_law() {
    let cases: &[(f64, f64, f64, f64, f64)] = &[
        // (m2, speed, impact parameter b, e, radius)
        (1.0, 20.0, 0.5, 1.0, 0.5),
        (1.0, 60.0, 0.5, 1.0, 0.5),
        (1.0, 200.0, 0.5, 1.0, 0.5),
        (3.0, 30.0, 0.3, 1.0, 0.5),
        (1.0, 30.0, 0.99, 1.0, 0.5),
        (1.0, 30.0, 0.5, 0.5, 0.5),
        (1.0, 100.0, 0.5, 1.0, 0.05),
        (0.01, 50.0, 0.7, 1.0, 0.2),
        (100.0, 50.0, 0.7, 0.8, 2.0),
    ];
    for &(m2, speed, b, e, r) in cases {
        let mut world = free_space();
        let start_x = -(speed * 0.5).max(5.0 * r);
        let a = body(
            &mut world,
            Shape::circle(fx(r)),
            1.0,
            e,
            (start_x, b * 2.0 * r),
            (speed, 0.0),
        );
        let t = body(
            &mut world,
            Shape::circle(fx(r)),
            m2,
            e,
            (0.0, 0.0),
            (0.0, 0.0),
        );
        for _ in 0..120 {
            world.step();
        }
        // At touching, circle 1's centre is at (−√(4r² − s²), s), s = 2rb.
        let s = 2.0 * r * b;
        let n = (-(4.0 * r * r - s * s).sqrt() / (2.0 * r), s / (2.0 * r));
        let tan_phi = b / (1.0 - b * b).sqrt();
        let normal_turn = tan_phi * SLOP / (2.0 * r);
        let label = format!("oblique m2 {m2} speed {speed} b {b} e {e} r {r}");
        check(
            &label,
            &world,
            (a, 1.0, (speed, 0.0)),
            (t, m2, (0.0, 0.0)),
            n,
            e,
            normal_turn,
        );
    }
}
