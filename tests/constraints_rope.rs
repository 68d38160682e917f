//! Ropes (issue 4): pendulum period and stretch, chains, the rope's
//! restitution rule, and a rope acting together with a contact.
//!
//! A rope is an inequality row in the contact solver (module docs of
//! `clockwork2d::constraints`): slack below its length, and at full length
//! the velocity along the rope is removed (restitution 0) or reflected
//! (restitution 1) while the tangential velocity is kept. Chains of ropes
//! sharing bodies are solved by a direct block solver. Tolerances are the
//! issue's targets or derived from the discrete rule; the measured figures
//! are printed (`--nocapture`).

use std::f64::consts::PI;

use clockwork2d::prelude::*;

mod common;
use common::oscillators::{H, pos, settings, vel};

fn ball(world: &mut World, radius: f64, mass: f64, p: (f64, f64), vel: (f64, f64)) -> BodyId {
    world
        .add_body(
            BodyDef::dynamic(Shape::circle(fx(radius)))
                .mass(fx(mass))
                .position(vec2(p.0, p.1))
                .velocity(vec2(vel.0, vel.1)),
        )
        .expect("ball")
}

fn dist(a: (f64, f64), b: (f64, f64)) -> f64 {
    (b.0 - a.0).hypot(b.1 - a.1)
}

fn relative(measured: f64, expected: f64) -> f64 {
    (measured - expected) / expected
}

/// Mean period from the rising zero crossings of `series` (one sample per
/// tick), linearly interpolated.
fn period(series: &[f64]) -> f64 {
    let mut c = Vec::new();
    for (i, pair) in series.windows(2).enumerate() {
        let (a, b) = (pair[0], pair[1]);
        if a < 0.0 && b >= 0.0 {
            c.push((i as f64 + a / (a - b)) * H);
        }
    }
    assert!(c.len() >= 3, "not enough swings: {} crossings", c.len());
    (c[c.len() - 1] - c[0]) / (c.len() - 1) as f64
}

/// The exact period of a pendulum of length `l` with amplitude `theta0`:
/// `T = 2π√(l/g) / AGM(1, cos(θ₀/2))`.
fn large_amplitude_period(l: f64, g: f64, theta0: f64) -> f64 {
    let (mut a, mut b) = (1.0f64, (theta0 / 2.0).cos());
    for _ in 0..8 {
        (a, b) = ((a + b) / 2.0, (a * b).sqrt());
    }
    2.0 * PI * (l / g).sqrt() / a
}

/// A chain hanging from the fixed point (0, 0): `masses.len()` links of
/// radius `radius`, each rope `segment` long, laid out straight at angle
/// `angle` from the downward vertical. Returns the link ids, top first.
fn chain(world: &mut World, masses: &[f64], segment: f64, radius: f64, angle: f64) -> Vec<BodyId> {
    let (s, c) = angle.sin_cos();
    let mut ids: Vec<BodyId> = Vec::new();
    for (i, &m) in masses.iter().enumerate() {
        let r = segment * (i + 1) as f64;
        let id = ball(world, radius, m, (r * s, -r * c), (0.0, 0.0));
        let a = match ids.last() {
            Some(&prev) => Anchor::Body(prev),
            None => Anchor::Point(Vec2::ZERO),
        };
        world
            .add_constraint(Constraint::rope(a, Anchor::Body(id), fx(segment)))
            .expect("rope");
        ids.push(id);
    }
    ids
}

/// What a pendulum run measured.
struct Swing {
    /// Period of the last link's x (s).
    period: f64,
    /// Largest stretch of any segment over the run, as a fraction of the
    /// segment length.
    max_stretch: f64,
    /// Largest |x| of the last link over the first and last period.
    first_amplitude: f64,
    last_amplitude: f64,
}

/// Runs a chain pendulum (pivot at the origin) for `periods` periods of
/// `2π√(L/g)` and measures it.
fn swing(world: &mut World, links: &[BodyId], segment: f64, periods: f64) -> Swing {
    let total = segment * links.len() as f64;
    let t0 = 2.0 * PI * (total / 10.0).sqrt();
    let steps = (periods * t0 / H).ceil() as usize;
    let per_period = (t0 / H).ceil() as usize;
    let bob = links[links.len() - 1];
    let mut xs = vec![pos(world, bob).0];
    let mut max_stretch = 0.0f64;
    for _ in 0..steps {
        world.step();
        let mut previous = (0.0, 0.0);
        for &id in links {
            let p = pos(world, id);
            max_stretch = max_stretch.max((dist(previous, p) - segment) / segment);
            previous = p;
        }
        xs.push(pos(world, bob).0);
    }
    let peak = |s: &[f64]| s.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    Swing {
        period: period(&xs),
        max_stretch,
        first_amplitude: peak(&xs[..per_period]),
        last_amplitude: peak(&xs[xs.len() - per_period..]),
    }
}

// ---------------------------------------------------------------------------
// 6. Rope pendulum.

/// Rope pendulum, L = 1, 5° amplitude, g = 10, bob mass `mass` (radius
/// 0.05), 20 periods. Issue target: period within 1 % of 2π√(L/g) =
/// 1.98692 s (the exact 5° period is 0.048 % longer; both are printed) and
/// stretch never above 0.5 % of L.
fn rope_pendulum(mass: f64) {
    let mut world = World::new(settings(10.0));
    let links = chain(&mut world, &[mass], 1.0, 0.05, 5f64.to_radians());
    let s = swing(&mut world, &links, 1.0, 20.0);
    let small = 2.0 * PI * 0.1f64.sqrt();
    let exact = large_amplitude_period(1.0, 10.0, 5f64.to_radians());
    println!(
        "rope pendulum, bob {mass}: period {:.6} s vs 2π√(L/g) {small:.6} ({:+.4} %), vs exact \
         5° {exact:.6} ({:+.4} %); max stretch {:.4} % of L; amplitude {:.5} → {:.5} after 20 \
         periods",
        s.period,
        100.0 * relative(s.period, small),
        100.0 * relative(s.period, exact),
        100.0 * s.max_stretch,
        s.first_amplitude,
        s.last_amplitude,
    );
    assert!(relative(s.period, small).abs() < 0.01);
    assert!(s.max_stretch <= 0.005);
}

#[test]
fn rope_pendulum_l1_5_degrees_period_within_1_percent_stretch_under_0_5_percent() {
    rope_pendulum(1.0);
}

#[test]
fn rope_pendulum_bob_ten_times_heavier_period_within_1_percent_stretch_under_0_5_percent() {
    rope_pendulum(10.0);
}

/// A chain of 10 segments of 0.1 (total L = 1) with 10 equal links of mass
/// 0.1 (radius 0.02, so neighbours never touch), started straight at 5°.
/// Every segment's stretch must stay at most 0.5 % of the segment length
/// over 20 periods of 2π√(L/g). (A chain is a compound pendulum; its period
/// is not 2π√(L/g), so it is printed, not checked.)
#[test]
fn rope_chain_of_10_equal_links_every_segment_stretch_under_0_5_percent() {
    let mut world = World::new(settings(10.0));
    let links = chain(&mut world, &[0.1; 10], 0.1, 0.02, 5f64.to_radians());
    let s = swing(&mut world, &links, 0.1, 20.0);
    println!(
        "chain of 10 equal links: max segment stretch {:.4} % of the segment; bottom link \
         period {:.5} s",
        100.0 * s.max_stretch,
        s.period
    );
    assert!(s.max_stretch <= 0.005);
}

/// A chain of 10 light links (mass 0.1) and a bob of 10 at its end (11
/// segments of 0.1; mass ratio 100), started straight at 5°, with
/// `substeps = 2`: every segment's stretch at most 0.5 %.
///
/// Known limitation (documented, not tested): with the default single
/// substep this chain is unstable (measured: a segment stretched to 380
/// times its length within 20 periods). The rows are solved exactly per
/// substep (block solver), but their directions are frozen at the start of
/// the substep. A light link between two ropes carrying the bob's weight
/// T ≈ 100 is held sideways by the geometric stiffness 2T/ℓ, so it
/// oscillates sideways at ω = √(2T/(m·ℓ)) = √(2·100/(0.1·0.1)) ≈ 141 rad/s,
/// ω·h ≈ 2.4 at 60 Hz; with the directions updated once per (sub)step that
/// motion is integrated explicitly, stable only for ω·h < 2. Two substeps
/// give ω·h ≈ 1.2.
#[test]
fn rope_chain_light_links_heavy_bob_mass_ratio_100_with_2_substeps_stretch_under_0_5_percent() {
    let mut s = settings(10.0);
    s.substeps = 2;
    let mut world = World::new(s);
    let mut masses = vec![0.1; 10];
    masses.push(10.0);
    let links = chain(&mut world, &masses, 0.1, 0.02, 5f64.to_radians());
    let s = swing(&mut world, &links, 0.1, 20.0);
    println!(
        "chain of 10 links of 0.1 + bob of 10, 2 substeps: max segment stretch {:.4} %; bob \
         period {:.5} s",
        100.0 * s.max_stretch,
        s.period
    );
    assert!(s.max_stretch <= 0.005);
}

/// A chain of 10 links (mass 0.2, segments of 0.15) released horizontal:
/// it falls and whips, and its end link turns by up to ~0.6 rad per tick.
/// Target (the issue's): no segment ever stretches more than 0.5 %.
///
/// A rope row's direction is set at the start of the substep, so a link
/// moving sideways by `v_t·h` ends up stretched by `≈ (v_t·h)²/(2ℓ)`, a
/// second-order term the linearised separation `s + (d_b − d_a)·n` cannot
/// see (before the fix: 18.1 % at the whip, tick 101). The position
/// iterations therefore re-linearise each rope about the current positions
/// (non-linear Gauss–Seidel; `relinearise_rope_rows`), which brings the
/// worst segment to 0.17 %.
#[test]
fn rope_chain_released_horizontal_every_segment_stretch_under_0_5_percent() {
    let mut world = World::new(settings(10.0));
    let links = chain(&mut world, &[0.2; 10], 0.15, 0.05, PI / 2.0);
    let mut worst = (0.0f64, 0usize, 0usize);
    for tick in 0..600 {
        world.step();
        let mut previous = (0.0, 0.0);
        for (i, &id) in links.iter().enumerate() {
            let p = pos(&world, id);
            let stretch = (dist(previous, p) - 0.15) / 0.15;
            if stretch > worst.0 {
                worst = (stretch, tick, i);
            }
            previous = p;
        }
    }
    println!(
        "chain released horizontal: max segment stretch {:.3} % (tick {}, segment {})",
        100.0 * worst.0,
        worst.1,
        worst.2
    );
    assert!(worst.0 <= 0.005);
}

// ---------------------------------------------------------------------------
// 7. Rope restitution.

/// What happened when the rope went taut.
struct Catch {
    /// Velocity before the rope acted.
    before: (f64, f64),
    /// Velocity after the tick in which the rope first acted.
    after: (f64, f64),
    /// Unit vector pivot → body at the start of that tick (the row's axis).
    axis: (f64, f64),
    /// Slack at the start of that tick.
    slack: f64,
}

const ROPE: f64 = 2.0;
/// The straight path reaches full length at (2, 0), at 0.3 s + half a tick
/// (so the catch falls inside a tick, not on its boundary).
const IMPACT: (f64, f64) = (ROPE, 0.0);
/// Radial (+x at the impact point) and tangential (+y) components, both
/// above the world's restitution threshold of 1 unit/s.
const V_IN: (f64, f64) = (3.0, 1.5);

/// Gravity 0; a body flies straight towards the end of a rope of length 2
/// attached at the origin. Steps until the rope acts (velocity changes),
/// then `after` more ticks, recording the distances and velocities.
fn catch(restitution: f64, after: usize) -> (Catch, World, BodyId) {
    let t = 0.3 + H / 2.0;
    let start = (IMPACT.0 - V_IN.0 * t, IMPACT.1 - V_IN.1 * t);
    let mut world = World::new(settings(0.0));
    let body = ball(&mut world, 0.1, 1.0, start, V_IN);
    world
        .add_constraint(
            Constraint::rope(Anchor::Point(Vec2::ZERO), Anchor::Body(body), fx(ROPE))
                .with_restitution(fx(restitution)),
        )
        .unwrap();
    for _ in 0..60 {
        let p = pos(&world, body);
        let before = vel(&world, body);
        world.step();
        let now = vel(&world, body);
        if dist(before, now) > 1e-6 {
            let d = p.0.hypot(p.1);
            let c = Catch {
                before,
                after: now,
                axis: (p.0 / d, p.1 / d),
                slack: ROPE - d,
            };
            for _ in 0..after {
                world.step();
            }
            return (c, world, body);
        }
    }
    panic!("the rope never went taut");
}

fn dot(a: (f64, f64), b: (f64, f64)) -> f64 {
    a.0 * b.0 + a.1 * b.1
}

/// The largest angle (rad) between the row's axis (the rope direction at
/// the start of the catching tick) and the direction at the geometric
/// impact point: the body is at most one tick before the impact, during
/// which its direction from the pivot turns by at most
/// `|v_t|·h / (L − |v_r|·h)`.
fn axis_bound() -> f64 {
    V_IN.1 * H / (ROPE - V_IN.0 * H)
}

/// Restitution 1 (the origin document's mirror rule): the rope reflects the
/// velocity about its axis. Against the row's own axis this is exact up to
/// rounding (one row against a fixed point: the solver's first iteration is
/// exact): `v' = v − 2(v·n)n` to 1e-6. Against the geometric impact
/// direction, the reflected radial velocity is `−3` and the tangential
/// velocity `1.5` within `2·δ·|v|` (a reflection about an axis turned by δ
/// turns the result by 2δ; δ from [`axis_bound`]: 0.0128 rad → 0.086).
/// Afterwards the rope is slack and the body flies straight (velocity
/// unchanged for 30 ticks, distance below L).
#[test]
fn rope_restitution_1_reverses_radial_velocity_and_keeps_tangential() {
    let (c, mut world, body) = catch(1.0, 0);
    let vn = dot(c.before, c.axis);
    let mirror = (
        c.before.0 - 2.0 * vn * c.axis.0,
        c.before.1 - 2.0 * vn * c.axis.1,
    );
    let radial = dot(c.after, (1.0, 0.0));
    let tangential = dot(c.after, (0.0, 1.0));
    let bound = 2.0 * axis_bound() * V_IN.0.hypot(V_IN.1);
    println!(
        "rope e=1: in (radial {}, tangential {}), out (radial {radial:.5}, tangential \
         {tangential:.5}); bound {bound:.4}; mirror-rule error {:.2e}; slack at the catch \
         {:.4}",
        V_IN.0,
        V_IN.1,
        dist(c.after, mirror),
        c.slack
    );
    assert!(dist(c.after, mirror) < 1e-6);
    assert!((radial + V_IN.0).abs() < bound);
    assert!((tangential - V_IN.1).abs() < bound);
    for _ in 0..30 {
        world.step();
        assert!(dist(vel(&world, body), c.after) < 1e-9, "the rope is slack");
        assert!(pos(&world, body).0.hypot(pos(&world, body).1) < ROPE);
    }
}

/// Restitution 0 (a real rope): the velocity along the rope is removed and
/// the tangential velocity kept, so the body goes round the pivot at the
/// rope's length with speed `|v_t| = 1.5`.
///
/// Checked 10 ticks after the catch, over the next 60 ticks:
/// * the radial speed, `d|r|/dt` by central differences, stays near 0;
///   the discrete rule turns the body by `θ = v_t·h/L` per tick along the
///   tangent of the previous direction, so |r| wobbles by about
///   `L·θ²/2` per tick before position correction: tolerance
///   `v_t²·h/L` = 0.019 units/s (0.6 % of the 3 units/s radial speed in);
/// * the speed stays `|v_t|` within 1 %: the rule removes the radial
///   component along an axis that lags the motion by ≤ θ, a relative speed
///   loss of ≤ θ²/2 = 4e-5 per tick (0.3 % over 70 ticks), plus the axis
///   error of the catch itself, `δ·|v|/|v_t|` (δ from [`axis_bound`]);
/// * the distance stays within 0.5 % of L.
#[test]
fn rope_restitution_0_removes_radial_velocity_and_keeps_tangential() {
    let (c, mut world, body) = catch(0.0, 10);
    let speed_in = V_IN.1;
    let mut d = Vec::new();
    let mut worst_speed = 0.0f64;
    for _ in 0..60 {
        let p = pos(&world, body);
        d.push(p.0.hypot(p.1));
        let u = vel(&world, body);
        worst_speed = worst_speed.max(relative(u.0.hypot(u.1), speed_in).abs());
        world.step();
    }
    let radial_speed = d
        .windows(3)
        .map(|w| ((w[2] - w[0]) / (2.0 * H)).abs())
        .fold(0.0f64, f64::max);
    let stretch = d
        .iter()
        .map(|x| relative(*x, ROPE).abs())
        .fold(0.0f64, f64::max);
    let theta = V_IN.1 * H / ROPE;
    let radial_tolerance = V_IN.1 * V_IN.1 * H / ROPE;
    let speed_tolerance = 70.0 * theta * theta / 2.0 + axis_bound() * V_IN.0.hypot(V_IN.1) / V_IN.1;
    println!(
        "rope e=0: velocity at the catch {:?} → {:?} (axis {:?}, slack {:.4}); afterwards max \
         |d|r|/dt| {radial_speed:.5} (tolerance {radial_tolerance:.4}), max |speed/|v_t| − 1| \
         {worst_speed:.5} (tolerance {speed_tolerance:.4}), max |stretch| {:.4} %",
        c.before,
        c.after,
        c.axis,
        c.slack,
        100.0 * stretch
    );
    assert!(radial_speed < radial_tolerance);
    assert!(worst_speed < speed_tolerance.min(0.01));
    assert!(stretch < 0.005);
}

// ---------------------------------------------------------------------------
// 8. A rope and the ground together.

/// Pivot (0, 2) above a ground whose top is y = 0; a bob of radius 0.25
/// on a rope of 1.8 (bob and ground friction 0.1), slightly longer than the 1.75 from the
/// pivot to the bob resting on the ground. Gravity is tilted, (2, −10), so
/// the bob slides along the ground away from the pivot until the rope goes
/// taut, and then rests in the corner between rope and ground, at
/// x = √(1.8² − 1.75²) = 0.4213, y = 0.25, with the rope pulling (it
/// holds the sideways gravity) and the ground pushing (the rope's tangent
/// there points into the ground): both rows active in the same solve, at
/// every tick once it has settled. (Friction 0.1 × weight 10 = 1 < 2, so
/// static friction cannot hold it anywhere else on the ground; it damps
/// the small swings after the rope catches it, which lift it off the
/// ground: removing the radial velocity leaves the tangential one, which
/// points up.) Released at rest on the ground at (0.2, 0.25), over 10 s
/// (sleep on, the default): it never penetrates the ground by more than
/// 0.01, the rope never stretches by more than 0.5 %, it is taut on the
/// ground for the whole last second and ends at the corner (within 0.01)
/// at rest.
#[test]
fn rope_and_ground_together_bob_rests_on_ground_without_penetrating_or_overstretching() {
    let mut world = World::new(WorldSettings {
        gravity: vec2(2.0, -10.0),
        ..WorldSettings::default()
    });
    world
        .add_body(
            BodyDef::fixed(Shape::aabb(vec2(10.0, 0.5)))
                .friction(fx(0.1))
                .position(vec2(0.0, -0.5)),
        )
        .unwrap();
    let pivot = (0.0, 2.0);
    let bob = world
        .add_body(
            BodyDef::dynamic(Shape::circle(fx(0.25)))
                .mass(fx(1.0))
                .friction(fx(0.1))
                .position(vec2(0.2, 0.25)),
        )
        .unwrap();
    world
        .add_constraint(Constraint::rope(
            Anchor::Point(vec2(pivot.0, pivot.1)),
            Anchor::Body(bob),
            fx(1.8),
        ))
        .unwrap();
    let corner = ((1.8f64 * 1.8 - 1.75 * 1.75).sqrt(), 0.25);
    let (mut penetration, mut stretch, mut taut_on_ground) = (0.0f64, 0.0f64, 0usize);
    for tick in 0..600 {
        world.step();
        let p = pos(&world, bob);
        penetration = penetration.max(0.25 - p.1);
        stretch = stretch.max(relative(dist(pivot, p), 1.8));
        let on_ground = (p.1 - 0.25).abs() < 1e-3;
        if tick >= 540 && on_ground && relative(dist(pivot, p), 1.8).abs() < 1e-3 {
            taut_on_ground += 1;
        }
    }
    let (p, u) = (pos(&world, bob), vel(&world, bob));
    println!(
        "rope + ground: max penetration {penetration:.5}, max stretch {:.4} %, ticks taut on \
         the ground in the last second {taut_on_ground}/60; final position ({:.5}, {:.5}) vs corner ({:.5}, \
         0.25), speed {:.2e}",
        100.0 * stretch,
        p.0,
        p.1,
        corner.0,
        u.0.hypot(u.1)
    );
    assert_eq!(taut_on_ground, 60, "rope and ground did not act together");
    assert!(penetration < 0.01);
    assert!(stretch <= 0.005);
    assert!(dist(p, corner) < 0.01, "resting in the corner");
    assert!(u.0.hypot(u.1) < 0.05, "at rest");
}
