//! Springs that stand on the ground or carry boxes keep their energy and
//! never lift what rests on them (issue 13, springs + contacts).
//!
//! The physics. A body on a spring, the spring standing on the ground
//! (or a platform on a spring carrying boxes), started at rest with the
//! spring at its rest length under gravity g: the load falls, compresses
//! the spring to at most 2·M·g/k and comes back to the rest length; the
//! spring only ever pushes, so the body on the ground never leaves it and
//! the boxes never leave the platform; with no damping the energy
//! (kinetic + gravitational + spring) is constant.
//!
//! The step's invariant. The engine applies gravity as a kick before the
//! drift (`v += h·g`, then positions follow the velocity: symplectic Euler
//! for a constant force). For a free body that step keeps exactly
//! `E + ½·h·m·g·v`, not `E` (free fall: `ΔE = −½·m·|g|²·h²` per step,
//! `Δ(½·h·m·g·v) = +½·m·|g|²·h²`), and the trapezoidal spring step keeps
//! the same sum. A body held or carried by contacts follows all its
//! impulses (θ = 1, like the contact solver), and for it the plain energy
//! never rises: per step it changes by `−½·m·|Δv|²` plus the springs'
//! and contacts' own (non-positive) terms. So what must never rise is
//!
//! ```text
//! L = E + ½·h·Σ_{b free} m_b·g·v_b     (free: touching nothing)
//! ```
//!
//! (module docs of `clockwork2d::constraints`, "Springs and contacts").
//! Allowances, per tick:
//! * the blend: a free spring end integrated with θ > ½ adds at most
//!   `(θ − ½)·h·m·|g|·|Δv_s|` (`Δv_s = v' − v − h·g`, the spring's own
//!   velocity change, observed here), with `θ − ½ = min(½, (ω·h)⁸/512)`
//!   (`(ω·h)² = k·(w_a + w_b)·h²`; zero to 1e-7 where the step resolves
//!   the spring);
//! * the sweeps' stop: the spring solve stops when a sweep changes no
//!   impulse by more than 2⁻⁹ of the largest, so the impulse applied is
//!   the exact one for a stiffness off by at most that fraction, whose
//!   energy differs from this spring's by at most 2⁻⁹ of the spring
//!   energy: 2⁻⁹ × the largest spring energy so far (not per tick);
//! * rounding: positions and velocities are I32F32 (steps of 2⁻³²); a
//!   tick makes a few dozen rounded operations per body, each moving the
//!   energy by at most its rate (`m·(|v| + |g|·h)` per unit velocity,
//!   `k·|x|` per unit length) times 2⁻³²: 2⁻²⁶·(Σ m·(|v| + |g|) + k·|x|)
//!   covers 64 of them.
//!
//! The body on the ground may not rise above its resting height by more
//! than 2⁻²⁰ (rounding; exact answer: never), the boxes may not lift off
//! the platform by more than the contact slop 1e-4 (the solver's own
//! tolerance).
//!
//! Energy is computed in f64 from the state and the springs' parameters.
//! Figures: `cargo test --release --test spring_contacts_energy -- --nocapture`.

use clockwork2d::prelude::*;

/// The engine's tick.
const H: f64 = 1.0 / 60.0;
/// 20 s in release; 5 s in debug (the test profile is slow).
const TICKS: usize = if cfg!(debug_assertions) { 300 } else { 1200 };
/// 2⁻²⁶: rounding allowance factor (see the module docs).
const ROUNDING: f64 = 1.0 / 67_108_864.0;
/// 2⁻⁹: the spring sweeps' stopping tolerance (see the module docs).
const STOPPING: f64 = 1.0 / 512.0;

/// `θ − ½` of the engine's blend for `(ω·h)² = q`.
fn blend(q: f64) -> f64 {
    (q.powi(4) / 512.0).min(0.5)
}

/// One body's state in f64.
#[derive(Clone, Copy)]
struct State {
    m: f64,
    p: (f64, f64),
    v: (f64, f64),
}

fn state(world: &World, id: BodyId) -> State {
    let body = world.body(id).expect("live body");
    State {
        m: body.mass().to_f64(),
        p: body.position().to_f64(),
        v: body.velocity().to_f64(),
    }
}

/// `E` (kinetic + gravitational, gravity (0, −g)) plus `½·h·m·g·v` of the
/// free bodies.
fn invariant(bodies: &[(State, bool)], g: f64) -> f64 {
    bodies
        .iter()
        .map(|&(s, free)| {
            let e = 0.5 * s.m * (s.v.0 * s.v.0 + s.v.1 * s.v.1) + s.m * g * s.p.1;
            if free {
                e - 0.5 * H * s.m * g * s.v.1
            } else {
                e
            }
        })
        .sum()
}

/// A spring pair standing on the ground: bottom circle A resting on a
/// fixed box, top circle B one rest length above, joined by one vertical
/// spring (bendy or radial). Returns (worst rise of L beyond the
/// allowances, highest A above its resting height, max |E − E₀|/E₀).
fn spring_pair(omega_h: f64, radial: bool, g: f64) -> (f64, f64, f64) {
    let mut world = World::new(WorldSettings {
        sleep_enabled: false,
        gravity: vec2(0.0, -g),
        ..WorldSettings::default()
    });
    world
        .add_body(BodyDef::fixed(Shape::aabb(vec2(10.0, 0.5))).position(vec2(0.0, -0.5)))
        .expect("ground");
    let circle = |world: &mut World, y: f64| {
        world
            .add_body(BodyDef::dynamic(Shape::circle(fx(0.2))).position(vec2(0.0, y)))
            .expect("circle")
    };
    let a = circle(&mut world, 0.2);
    let b = circle(&mut world, 1.2);
    let m = state(&world, a).m;
    // (ω·h)² = k·(w_a + w_b)·h² = 2·k·h²/m.
    let q = omega_h * omega_h;
    let k = q * m / (2.0 * H * H);
    let spring = if radial {
        Constraint::radial_spring(Anchor::Body(a), Anchor::Body(b), fx(1.0), fx(k), fx(0.0))
    } else {
        Constraint::bendy_spring(Anchor::Body(a), Anchor::Body(b), vec2(k, k), fx(0.0))
            .with_rest_offset(vec2(0.0, 1.0))
    };
    world.add_constraint(spring).expect("spring");
    let spring_energy = |sa: State, sb: State| {
        let (dx, dy) = (sb.p.0 - sa.p.0, sb.p.1 - sa.p.1);
        let stretch = if radial {
            dx.hypot(dy) - 1.0
        } else {
            dx.hypot(dy - 1.0)
        };
        (0.5 * k * stretch * stretch, k * stretch.abs())
    };
    let measure = |world: &World| {
        let (sa, sb) = (state(world, a), state(world, b));
        let (u, force) = spring_energy(sa, sb);
        // A rests on the ground (contacts: no offset); B is free.
        (invariant(&[(sa, false), (sb, true)], g) + u, sa, sb, force)
    };
    let plain = |world: &World| {
        let (sa, sb) = (state(world, a), state(world, b));
        invariant(&[(sa, false), (sb, false)], g) + spring_energy(sa, sb).0
    };
    let (l0, _, mut last_b, _) = measure(&world);
    let e0 = plain(&world);
    let (mut allowance, mut worst, mut lift, mut swing) = (0.0f64, f64::MIN, 0.0f64, 0.0f64);
    let mut spring_max = 0.0f64;
    for _ in 0..TICKS {
        world.step();
        let (l, sa, sb, force) = measure(&world);
        let dv_spring = (sb.v.0 - last_b.v.0).hypot(sb.v.1 - last_b.v.1 + g * H);
        allowance += blend(q) * H * m * g * dv_spring
            + ROUNDING * (m * (sa.v.0.hypot(sa.v.1) + sb.v.0.hypot(sb.v.1) + 2.0 * g) + force);
        spring_max = spring_max.max(force * force / (2.0 * k));
        worst = worst.max(l - l0 - allowance - STOPPING * spring_max);
        lift = lift.max(sa.p.1 - 0.2);
        swing = swing.max((plain(&world) - e0).abs() / e0);
        last_b = sb;
    }
    (worst, lift, swing)
}

#[test]
fn a_spring_standing_on_the_ground_never_gains_energy_or_lifts_its_foot() {
    // The spring compresses to at most 2·m·g/k = 4·g·h²/(ω·h)²; the
    // circles are 0.6 apart at rest length, so each pair keeps that under
    // 0.25 (the top body never touches the bottom one, which would be
    // another contact, inelastic).
    let cases = [
        (0.1, 2.0),
        (0.3, 10.0),
        (1.0, 10.0),
        (1.0, 100.0),
        (3.0, 10.0),
        (3.0, 100.0),
        (10.0, 100.0),
    ];
    for radial in [false, true] {
        for (omega_h, g) in cases {
            assert!(4.0 * g * H * H / (omega_h * omega_h) < 0.25);
            {
                let (worst, lift, swing) = spring_pair(omega_h, radial, g);
                let kind = if radial { "radial" } else { "bendy" };
                println!(
                    "{kind} pair on the ground, ω·h {omega_h}, g {g}: L − L₀ beyond allowances {worst:+.3e} J, foot lift {lift:.2e}, |E − E₀|/E₀ ≤ {swing:.4}"
                );
                assert!(
                    worst <= 0.0,
                    "{kind} ω·h {omega_h} g {g}: energy rose {worst:e} J beyond the allowances"
                );
                assert!(
                    lift <= 1.0 / 1_048_576.0,
                    "{kind} ω·h {omega_h} g {g}: the bottom body lifted {lift}"
                );
            }
        }
    }
}

/// A platform (2 × 0.2, mass 1) on a bendy spring to a fixed point below,
/// `boxes` unit boxes stacked on it, at rest at the spring's rest length.
/// Returns (worst rise of E beyond rounding, largest gap between the
/// platform and the first box).
fn spring_platform(omega_h: f64, boxes: usize, g: f64) -> (f64, f64) {
    let mut world = World::new(WorldSettings {
        sleep_enabled: false,
        gravity: vec2(0.0, -g),
        ..WorldSettings::default()
    });
    let platform = world
        .add_body(
            BodyDef::dynamic(Shape::aabb(vec2(1.0, 0.1)))
                .mass(fx(1.0))
                .position(vec2(0.0, 0.0)),
        )
        .expect("platform");
    // A point anchor: (ω·h)² = k·h²/m_platform.
    let k = omega_h * omega_h / (H * H);
    world
        .add_constraint(
            Constraint::bendy_spring(
                Anchor::Point(vec2(0.0, -1.0)),
                Anchor::Body(platform),
                vec2(k, k),
                fx(0.0),
            )
            .with_rest_offset(vec2(0.0, 1.0)),
        )
        .expect("spring");
    let ids: Vec<BodyId> = (0..boxes)
        .map(|i| {
            world
                .add_body(
                    BodyDef::dynamic(Shape::aabb(vec2(0.5, 0.5)))
                        .position(vec2(0.0, 0.6 + i as f64)),
                )
                .expect("box")
        })
        .collect();
    let measure = |world: &World| {
        let sp = state(world, platform);
        let mut bodies = vec![(sp, false)];
        bodies.extend(ids.iter().map(|&id| (state(world, id), false)));
        let (x, y) = sp.p;
        let stretch = x.hypot(y);
        let speeds: f64 = bodies
            .iter()
            .map(|(s, _)| s.m * (s.v.0.hypot(s.v.1) + g))
            .sum();
        (
            invariant(&bodies, g) + 0.5 * k * stretch * stretch,
            ROUNDING * (speeds + k * stretch),
        )
    };
    let (e0, _) = measure(&world);
    let (mut allowance, mut worst, mut gap) = (0.0f64, f64::MIN, 0.0f64);
    for _ in 0..TICKS {
        world.step();
        let (e, rounding) = measure(&world);
        allowance += rounding;
        worst = worst.max(e - e0 - allowance);
        gap = gap.max(state(&world, ids[0]).p.1 - state(&world, platform).p.1 - 0.6);
    }
    (worst, gap)
}

#[test]
fn a_springy_platform_never_gains_energy_or_throws_its_boxes() {
    for omega_h in [0.1, 0.3, 1.0, 3.0] {
        for (boxes, g) in [(1, 10.0), (3, 10.0), (3, 100.0)] {
            let (worst, gap) = spring_platform(omega_h, boxes, g);
            println!(
                "platform ω·h {omega_h}, {boxes} boxes, g {g}: E − E₀ beyond rounding {worst:+.3e} J, box lift {gap:.2e}"
            );
            assert!(
                worst <= 0.0,
                "platform ω·h {omega_h} boxes {boxes} g {g}: energy rose {worst:e} J"
            );
            assert!(
                gap <= 1e-4,
                "platform ω·h {omega_h} boxes {boxes} g {g}: boxes lifted {gap}"
            );
        }
    }
}
