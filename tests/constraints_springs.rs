//! Accuracy and stability of the springs (issue 4): bendy springs and radial
//! ("rotational") springs against their analytic solutions.
//!
//! The engine integrates springs with the θ-method (see the module docs of
//! `clockwork2d::constraints`): for the linear system `y' = A·y` of one
//! spring axis, `(I − θhA)·y' = (I + (1−θ)hA)·y`, so each continuous
//! eigenvalue `s` of `A` becomes `z = (1 + (1−θ)·h·s) / (1 − θ·h·s)`, with
//! the documented blend `θ = 1/2 + min(1/2, (ω·h)⁸/512)`. At `ω·h = 0.1` that
//! is the trapezoidal rule to 2e-11: `|z| = 1 − 4e-13` (the amplitude keeps
//! all but 3e-9 of itself after 100 periods) and the period is longer than 2π/ω by
//! `≈ (ω·h)²/12` = 0.083 %. At `ω·h ≥ 2` it is implicit Euler (θ = 1): the
//! unresolvable mode is damped, never amplified (`|z| ≤ 1` for all θ ≥ 1/2).
//! Every tolerance below is either the target or derived from these
//! formulas (the helpers [`theta`] and [`z_of`] evaluate them); the measured
//! figures are printed (`--nocapture`).
//!
//! Measurements are taken in f64 from the fixed-point state (floats only at
//! the edge: `fx()` for literals, `to_f64()` for reports).

use std::f64::consts::PI;

use clockwork2d::prelude::*;

mod common;
use common::oscillators::{H, pos, settings, vel};

/// A dynamic circle of radius 0.1 with the given mass, position and velocity.
fn ball(world: &mut World, mass: f64, p: (f64, f64), vel: (f64, f64)) -> BodyId {
    world
        .add_body(
            BodyDef::dynamic(Shape::circle(fx(0.1)))
                .mass(fx(mass))
                .position(vec2(p.0, p.1))
                .velocity(vec2(vel.0, vel.1)),
        )
        .expect("ball")
}

/// Steps `n` ticks, recording `f(world)` before the first step and after
/// each step (`n + 1` samples, sample `i` at time `i·h`).
fn record(world: &mut World, n: usize, f: impl Fn(&World) -> f64) -> Vec<f64> {
    let mut out = Vec::with_capacity(n + 1);
    out.push(f(world));
    for _ in 0..n {
        world.step();
        out.push(f(world));
    }
    out
}

/// Times (in seconds) at which `series - level` changes sign from negative
/// to non-negative, linearly interpolated between samples.
fn rising_crossings(series: &[f64], level: f64) -> Vec<f64> {
    let mut out = Vec::new();
    for (i, pair) in series.windows(2).enumerate() {
        let (a, b) = (pair[0] - level, pair[1] - level);
        if a < 0.0 && b >= 0.0 {
            out.push((i as f64 + a / (a - b)) * H);
        }
    }
    out
}

/// Mean period from the first and last rising crossings.
fn period(series: &[f64], level: f64) -> f64 {
    let c = rising_crossings(series, level);
    assert!(
        c.len() >= 3,
        "not enough oscillations: {} crossings",
        c.len()
    );
    (c[c.len() - 1] - c[0]) / (c.len() - 1) as f64
}

/// Local extrema of the series (|value| peaks of both signs around
/// `level`), each refined by a parabola through the three samples around it:
/// `(time, value)`.
fn extrema(series: &[f64]) -> Vec<(f64, f64)> {
    let mut out = Vec::new();
    for (i, w) in series.windows(3).enumerate() {
        let (a, b, c) = (w[0], w[1], w[2]);
        let is_max = b > a && b >= c;
        let is_min = b < a && b <= c;
        if is_max || is_min {
            let denom = a - 2.0 * b + c;
            let offset = if denom == 0.0 {
                0.0
            } else {
                0.5 * (a - c) / denom
            };
            let value = b - 0.25 * (a - c) * offset;
            out.push(((i as f64 + 1.0 + offset) * H, value));
        }
    }
    out
}

/// The engine's documented θ for a spring with `(ω·h)² = q`.
fn theta(omega_h: f64) -> f64 {
    let q = (omega_h * omega_h).min(4.0);
    0.5 + (q.powi(4) / 512.0).min(0.5)
}

/// The θ-method's image `z = (1 + (1−θ)·h·s)/(1 − θ·h·s)` of the continuous
/// eigenvalue `s = re + i·im` (s⁻¹), as `(|z|, arg z)`.
fn z_of(re: f64, im: f64, theta: f64) -> (f64, f64) {
    let (nr, ni) = (1.0 + (1.0 - theta) * H * re, (1.0 - theta) * H * im);
    let (dr, di) = (1.0 - theta * H * re, -theta * H * im);
    (nr.hypot(ni) / dr.hypot(di), ni.atan2(nr) - di.atan2(dr))
}

/// The discrete period of an undamped spring of angular frequency `omega`.
fn predicted_period(omega: f64) -> f64 {
    let (_, angle) = z_of(0.0, omega, theta(omega * H));
    2.0 * PI * H / angle
}

fn relative(measured: f64, expected: f64) -> f64 {
    (measured - expected) / expected
}

// ---------------------------------------------------------------------------
// 1. Undamped bendy spring, ω·h = 0.1.

/// m = 1, k = 36 → ω = 6 rad/s, ω·h = 0.1 at 60 Hz; start displaced 1 unit
/// along x. Issue target: period within 0.5 % of 2π/ω and amplitude within
/// 1 % after 100 periods. The θ-method predicts a period error of +0.083 %
/// and an amplitude of `|z|^N` = 0.9996 after the 6 300 steps; the measured
/// period is also checked against the discrete prediction (to 0.01 %: the
/// zero crossings are interpolated linearly, an error far below a
/// thousandth of a tick at 63 ticks per period, averaged over 100 periods),
/// and the amplitude (the largest sample over the last period, which can
/// miss the true peak by at most `A·(ω·h)²/8` = 0.125 %) against `|z|^N`
/// to 0.2 %.
#[test]
fn bendy_spring_omega_h_0_1_period_within_0_5_percent_amplitude_within_1_percent_after_100_periods()
{
    let omega: f64 = 6.0;
    let mut world = World::new(settings(0.0));
    let body = ball(&mut world, 1.0, (1.0, 0.0), (0.0, 0.0));
    world
        .add_constraint(Constraint::bendy_spring(
            Anchor::Point(Vec2::ZERO),
            Anchor::Body(body),
            vec2(36.0, 36.0),
            fx(0.0),
        ))
        .unwrap();
    let analytic = 2.0 * PI / omega;
    // 100 periods plus a little, so the 100th period is complete.
    let steps = (101.0 * analytic / H).ceil() as usize;
    let x = record(&mut world, steps, |w| pos(w, body).0);
    let measured = period(&x, 0.0);
    let predicted = predicted_period(omega);
    let last_period = (analytic / H).ceil() as usize;
    let amplitude = x[x.len() - last_period..]
        .iter()
        .fold(0.0f64, |m, &xi| m.max(xi.abs()));
    let predicted_amplitude = z_of(0.0, omega, theta(omega * H)).0.powi(steps as i32);
    println!(
        "bendy ω·h=0.1: period {measured:.6} s, analytic {analytic:.6} s, error {:+.4} % \
         (θ-method prediction {:+.4} %); amplitude after 100 periods {amplitude:.6} \
         (prediction {predicted_amplitude:.6})",
        100.0 * relative(measured, analytic),
        100.0 * relative(predicted, analytic),
    );
    assert!(relative(measured, analytic).abs() < 0.005);
    assert!(relative(measured, predicted).abs() < 1e-4);
    assert!((amplitude - 1.0).abs() < 0.01);
    assert!(relative(amplitude, predicted_amplitude).abs() < 0.002);
    // y never moves: the axes are independent.
    assert_eq!(world.body(body).unwrap().position().y, fx(0.0));
}

// ---------------------------------------------------------------------------
// 2. Stiff spring, ω·h = 10.

/// m = 1, k = 360 000 → ω = 600 rad/s, ω·h = 10 at 60 Hz (explicit Euler
/// would multiply the amplitude by √(1 + (ω·h)²) ≈ 10 every step). For
/// every θ ≥ 1/2 the θ-method never increases `E = k·x² + v²/m`, so
/// `|x| ≤ x₀ = 1` and `|v| ≤ ω·x₀ = 600` for ever; here θ = 1 (implicit
/// Euler) and the first step already divides the amplitude by
/// `1 + (ω·h)² = 101`. Only rounding can add: a few ulps (2⁻³²) per step,
/// so `E ≤ E₀·(1 + 1e-9)` at every step and `|x| ≤ 1 + 4 ulp`.
#[test]
fn stiff_spring_omega_h_10_never_exceeds_initial_amplitude_over_10000_steps() {
    let k = 360_000.0;
    let mut world = World::new(settings(0.0));
    let body = ball(&mut world, 1.0, (1.0, 0.0), (0.0, 0.0));
    world
        .add_constraint(Constraint::bendy_spring(
            Anchor::Point(Vec2::ZERO),
            Anchor::Body(body),
            vec2(k, k),
            fx(0.0),
        ))
        .unwrap();
    let ulp = 2f64.powi(-32);
    let e0 = k;
    let max_speed = world.settings().max_speed.to_f64();
    let (mut max_x, mut max_v, mut max_e) = (0.0f64, 0.0f64, 0.0f64);
    let mut first = None;
    for _ in 0..10_000 {
        world.step();
        let b = world.body(body).unwrap();
        assert!(!b.is_frozen(), "the body left the world");
        let (x, y) = b.position().to_f64();
        let (vx, vy) = b.velocity().to_f64();
        assert!(x.is_finite() && vx.is_finite());
        assert_eq!((y, vy), (0.0, 0.0));
        first.get_or_insert(x);
        max_x = max_x.max(x.abs());
        max_v = max_v.max(vx.abs());
        max_e = max_e.max(k * x * x + vx * vx);
    }
    println!(
        "stiff ω·h=10: x after one step {:.6} (implicit Euler: 1/101 = {:.6}); max |x| over \
         10 000 steps {max_x:.6}; max |v| {max_v:.3} (ω·x₀ = 600, max_speed {max_speed}); \
         max E/E₀ {:.3e}",
        first.unwrap_or(f64::NAN),
        1.0 / 101.0,
        max_e / e0,
    );
    assert!(max_x <= 1.0 + 4.0 * ulp);
    assert!(max_e <= e0 * (1.0 + 1e-9));
    assert!(max_v <= 600.0 * (1.0 + 1e-9));
    assert!(max_v < max_speed / 4.0, "velocity close to saturation");
}

// ---------------------------------------------------------------------------
// 3. Damped spring, ζ = 0.1.

/// m = 1, k = 36 (ω = 6), c = 2ζωm = 1.2 with ζ = 0.1: the envelope decays
/// as e^{-ζωt}, ζω = 0.6 s⁻¹. Measured from successive extrema (both signs,
/// refined by parabolas) with a least-squares fit of ln|x_peak| over time.
/// Issue target: within 2 % of ζω. The θ-method predicts `−ln|z|/h` with
/// `s = −ζω + iω√(1−ζ²)`: 0.5985 (−0.25 %); the fit is also checked against
/// that to 0.1 %.
#[test]
fn damped_spring_zeta_0_1_decay_rate_within_2_percent_of_zeta_omega() {
    let (omega, zeta): (f64, f64) = (6.0, 0.1);
    let c = 2.0 * zeta * omega;
    let mut world = World::new(settings(0.0));
    let body = ball(&mut world, 1.0, (1.0, 0.0), (0.0, 0.0));
    world
        .add_constraint(Constraint::bendy_spring(
            Anchor::Point(Vec2::ZERO),
            Anchor::Body(body),
            vec2(omega * omega, omega * omega),
            fx(c),
        ))
        .unwrap();
    // Six periods: the amplitude falls to ~2 % (far above rounding).
    let steps = (6.0 * 2.0 * PI / omega / H) as usize;
    let x = record(&mut world, steps, |w| pos(w, body).0);
    let peaks: Vec<(f64, f64)> = extrema(&x)
        .into_iter()
        .map(|(t, value)| (t, value.abs().ln()))
        .collect();
    assert!(peaks.len() >= 10, "{} peaks", peaks.len());
    let n = peaks.len() as f64;
    let (st, sy) = peaks
        .iter()
        .fold((0.0, 0.0), |(a, b), &(t, y)| (a + t, b + y));
    let (mt, my) = (st / n, sy / n);
    let (num, den) = peaks.iter().fold((0.0, 0.0), |(a, b), &(t, y)| {
        (a + (t - mt) * (y - my), b + (t - mt) * (t - mt))
    });
    let measured = -num / den;
    let analytic = zeta * omega;
    let (modulus, _) = z_of(
        -zeta * omega,
        omega * (1.0 - zeta * zeta).sqrt(),
        theta(omega * H),
    );
    let predicted = -modulus.ln() / H;
    println!(
        "damped ζ=0.1: decay rate {measured:.5} s⁻¹ from {} extrema, ζω = {analytic:.5}, error \
         {:+.3} % (θ-method prediction {predicted:.5}, {:+.3} %)",
        peaks.len(),
        100.0 * relative(measured, analytic),
        100.0 * relative(predicted, analytic),
    );
    assert!(relative(measured, analytic).abs() < 0.02);
    assert!(relative(measured, predicted).abs() < 0.001);
}

// ---------------------------------------------------------------------------
// 4. Radial spring.

/// The same damped oscillator on a radial spring: pivot (0, 0), rest length
/// L = 2, started 1 beyond it on the x axis, k = 36, c = 1.2, m = 1. The
/// motion stays on the pole, where the radial spring's stretch is
/// `|r| − L` and its damping acts on the true length change, so the
/// analytic envelope and the θ-method prediction are those above (ζω =
/// 0.6 s⁻¹, within 2 %; prediction to 0.1 %).
#[test]
fn damped_radial_spring_zeta_0_1_decay_rate_within_2_percent_of_zeta_omega() {
    let (omega, zeta, rest): (f64, f64, f64) = (6.0, 0.1, 2.0);
    let c = 2.0 * zeta * omega;
    let mut world = World::new(settings(0.0));
    let body = ball(&mut world, 1.0, (rest + 1.0, 0.0), (0.0, 0.0));
    world
        .add_constraint(Constraint::radial_spring(
            Anchor::Point(Vec2::ZERO),
            Anchor::Body(body),
            fx(rest),
            fx(omega * omega),
            fx(c),
        ))
        .unwrap();
    let steps = (6.0 * 2.0 * PI / omega / H) as usize;
    let x = record(&mut world, steps, |w| {
        let (px, py) = pos(w, body);
        px.hypot(py) - rest
    });
    let peaks: Vec<(f64, f64)> = extrema(&x)
        .into_iter()
        .map(|(t, value)| (t, value.abs().ln()))
        .collect();
    assert!(peaks.len() >= 10, "{} peaks", peaks.len());
    let n = peaks.len() as f64;
    let (st, sy) = peaks
        .iter()
        .fold((0.0, 0.0), |(a, b), &(t, y)| (a + t, b + y));
    let (mt, my) = (st / n, sy / n);
    let (num, den) = peaks.iter().fold((0.0, 0.0), |(a, b), &(t, y)| {
        (a + (t - mt) * (y - my), b + (t - mt) * (t - mt))
    });
    let measured = -num / den;
    let analytic = zeta * omega;
    let (modulus, _) = z_of(
        -zeta * omega,
        omega * (1.0 - zeta * zeta).sqrt(),
        theta(omega * H),
    );
    let predicted = -modulus.ln() / H;
    println!(
        "damped radial ζ=0.1: decay rate {measured:.5} s⁻¹ from {} extrema, ζω = {analytic:.5}, \
         error {:+.3} % (θ-method prediction {predicted:.5}, {:+.3} %)",
        peaks.len(),
        100.0 * relative(measured, analytic),
        100.0 * relative(predicted, analytic),
    );
    assert!(relative(measured, analytic).abs() < 0.02);
    assert!(relative(measured, predicted).abs() < 0.001);
}

/// Radial spring: pivot (0, 0), rest length L = 2, k = 16, m = 1 → radial
/// ω = 4 rad/s; gravity 10. Hanging straight down, started 0.5 beyond the
/// static equilibrium with no tangential motion, the distance oscillates
/// about `L + m·g/k = 2.625` (the θ-method spring with the engine's
/// gravity step has exactly this fixed point) with period 2π/ω = 1.5708 s
/// (θ-method prediction +0.037 %; issue target 1 %). The oscillation
/// centre is the mean of the parabola-refined extrema (error ≪ 1e-4 at
/// ω·h = 0.067); tolerance 1e-3. The body stays on the vertical line.
#[test]
fn radial_spring_vertical_hang_oscillates_about_l_plus_mg_over_k_with_period_within_1_percent() {
    let (rest, k, m, g): (f64, f64, f64, f64) = (2.0, 16.0, 1.0, 10.0);
    let omega = (k / m).sqrt();
    let equilibrium = rest + m * g / k;
    let mut world = World::new(settings(g));
    let body = ball(&mut world, m, (0.0, -(equilibrium + 0.5)), (0.0, 0.0));
    world
        .add_constraint(Constraint::radial_spring(
            Anchor::Point(Vec2::ZERO),
            Anchor::Body(body),
            fx(rest),
            fx(k),
            fx(0.0),
        ))
        .unwrap();
    let analytic = 2.0 * PI / omega;
    let steps = (20.0 * analytic / H) as usize;
    let mut max_sideways = 0.0f64;
    let d = record(&mut world, steps, |w| {
        let (x, y) = pos(w, body);
        x.hypot(y)
    });
    for _ in 0..10 {
        world.step();
        max_sideways = max_sideways.max(pos(&world, body).0.abs());
    }
    let ext = extrema(&d);
    let (hi, lo): (Vec<f64>, Vec<f64>) = (
        ext.iter()
            .map(|e| e.1)
            .filter(|&x| x > equilibrium)
            .collect(),
        ext.iter()
            .map(|e| e.1)
            .filter(|&x| x < equilibrium)
            .collect(),
    );
    let centre =
        (hi.iter().sum::<f64>() / hi.len() as f64 + lo.iter().sum::<f64>() / lo.len() as f64) / 2.0;
    let measured = period(&d, centre);
    println!(
        "radial hang: centre {centre:.6} (L + mg/k = {equilibrium}), radial period \
         {measured:.6} s vs 2π/ω = {analytic:.6} s ({:+.4} %, θ-method prediction {:+.4} %), \
         max |x| {max_sideways:e}",
        100.0 * relative(measured, analytic),
        100.0 * relative(predicted_period(omega), analytic),
    );
    assert!((centre - equilibrium).abs() < 1e-3);
    assert!(relative(measured, analytic).abs() < 0.01);
    assert_eq!(max_sideways, 0.0, "no force perpendicular to the pole");
}

/// Radial spring, gravity 0, body at the rest length L = 2 moving purely
/// tangentially at 3 units/s (k = 16, m = 1). The spring's force is along
/// the pole only, so the angular momentum about the pivot, `r × v`, must be
/// conserved. The tolerance is rounding: each step changes `r × v` by a few
/// ulps of `|r|·|v|` (≈ 6 · 2⁻³²), so 1e-6 relative over 600 steps (10 s)
/// is a generous bound.
///
/// (An earlier formulation, with the axis frozen at `r`, changed `r × v` by
/// `(1−θ)·h·v×v'` per step, always the same sign: +14 % in 600 steps. The
/// radial row now pushes along the θ-lever of its ends, which keeps it;
/// see `clockwork2d::constraints`, "Radial springs".)
#[test]
fn radial_spring_no_perpendicular_force_angular_momentum_conserved_over_600_steps() {
    let mut world = World::new(settings(0.0));
    let body = ball(&mut world, 1.0, (2.0, 0.0), (0.0, 3.0));
    world
        .add_constraint(Constraint::radial_spring(
            Anchor::Point(Vec2::ZERO),
            Anchor::Body(body),
            fx(2.0),
            fx(16.0),
            fx(0.0),
        ))
        .unwrap();
    let l0 = 2.0 * 3.0;
    let mut worst = 0.0f64;
    let mut max_distance = 0.0f64;
    for _ in 0..600 {
        world.step();
        let ((x, y), (vx, vy)) = (pos(&world, body), vel(&world, body));
        let l = x * vy - y * vx;
        worst = worst.max(relative(l, l0).abs());
        max_distance = max_distance.max(x.hypot(y));
    }
    println!(
        "radial, gravity 0: max relative change of r×v over 600 steps {worst:.3e}; \
         max distance {max_distance:.4}"
    );
    assert!(worst < 1e-6);
}

/// Radial spring swinging under gravity: pivot (0, 0), rest length 2,
/// k = 16 (radial ω = 4), m = 1, g = 10, released from the horizontal
/// (2, 0) at rest. It must swing through the bottom to the other side, and
/// the total energy `½m|v|² + ½k(d − L)² + m·g·y` must stay what it was
/// (0). Velocities are taken as central differences of positions, which
/// are exact for the engine's gravity step (the trajectory is a parabola
/// between spring impulses), so the energy error is the integrator's:
/// O((ω·h)²) of the energy scale m·g·L = 20, i.e. well under 1 % over
/// 10 s if the scheme is conservative.
///
#[test]
fn radial_spring_swing_from_horizontal_conserves_energy_within_1_percent_over_10_s() {
    let (rest, k, m, g): (f64, f64, f64, f64) = (2.0, 16.0, 1.0, 10.0);
    let mut world = World::new(settings(g));
    let body = ball(&mut world, m, (rest, 0.0), (0.0, 0.0));
    world
        .add_constraint(Constraint::radial_spring(
            Anchor::Point(Vec2::ZERO),
            Anchor::Body(body),
            fx(rest),
            fx(k),
            fx(0.0),
        ))
        .unwrap();
    let p: Vec<(f64, f64)> = {
        let mut out = vec![pos(&world, body)];
        for _ in 0..600 {
            world.step();
            out.push(pos(&world, body));
        }
        out
    };
    let scale = m * g * rest;
    let (mut worst, mut min_x, mut max_stretch) = (0.0f64, f64::MAX, 0.0f64);
    for i in 1..p.len() - 1 {
        let (x, y) = p[i];
        let vx = (p[i + 1].0 - p[i - 1].0) / (2.0 * H);
        let vy = (p[i + 1].1 - p[i - 1].1) / (2.0 * H);
        let d = x.hypot(y);
        let energy = 0.5 * m * (vx * vx + vy * vy) + 0.5 * k * (d - rest).powi(2) + m * g * y;
        worst = worst.max(energy.abs() / scale);
        min_x = min_x.min(x);
        max_stretch = max_stretch.max(d - rest);
    }
    println!(
        "radial swing: max |ΔE|/(mgL) over 10 s = {worst:.4}; min x {min_x:.3}; max stretch \
         {max_stretch:.3}"
    );
    assert!(min_x < -1.0, "the body swings to the other side");
    assert!(worst < 0.01);
}

/// A body exactly at the pivot: the direction is undefined, and the engine
/// documents that the body is pushed along +Y. Rest length 1, k = 16,
/// gravity 0: no panic, x stays exactly 0 and the body moves up; it then
/// oscillates along the y axis about distance 1.
#[test]
fn radial_spring_body_at_pivot_is_pushed_along_plus_y_without_panic() {
    let mut world = World::new(settings(0.0));
    let body = ball(&mut world, 1.0, (3.0, 4.0), (0.0, 0.0));
    world
        .add_constraint(Constraint::radial_spring(
            Anchor::Point(vec2(3.0, 4.0)),
            Anchor::Body(body),
            fx(1.0),
            fx(16.0),
            fx(0.0),
        ))
        .unwrap();
    world.step();
    let (vx, vy) = vel(&world, body);
    assert_eq!(vx, 0.0);
    assert!(vy > 0.0, "pushed along +Y, got vy = {vy}");
    let mut max_y = 0.0f64;
    for _ in 0..120 {
        world.step();
        let (x, y) = pos(&world, body);
        assert_eq!(x, 3.0);
        max_y = max_y.max(y - 4.0);
    }
    println!("radial, body at pivot: max height above the pivot {max_y:.4} (rest length 1)");
    assert!(max_y > 1.0 && max_y < 2.0 + 1e-6);
}

/// Body–body radial spring (gravity 0): the impulses on the two ends are
/// equal and opposite, so the total momentum `m_a v_a + m_b v_b` stays
/// what it was (zero here) to rounding: each step adds at most a few ulps
/// per body, 1e-6 over 600 steps. Masses 1 and 3, rest length 1, k = 30.
#[test]
fn radial_spring_between_two_bodies_conserves_linear_momentum() {
    let mut world = World::new(settings(0.0));
    let a = ball(&mut world, 1.0, (0.0, 0.0), (0.0, 0.0));
    let b = ball(&mut world, 3.0, (1.5, 0.5), (0.0, 0.0));
    world
        .add_constraint(Constraint::radial_spring(
            Anchor::Body(a),
            Anchor::Body(b),
            fx(1.0),
            fx(30.0),
            fx(0.0),
        ))
        .unwrap();
    let mut worst = 0.0f64;
    for _ in 0..600 {
        world.step();
        let (va, vb) = (vel(&world, a), vel(&world, b));
        let px = va.0 + 3.0 * vb.0;
        let py = va.1 + 3.0 * vb.1;
        worst = worst.max(px.hypot(py));
    }
    println!("radial body–body: max |total momentum| over 600 steps {worst:.3e}");
    assert!(worst < 1e-6);
}

// ---------------------------------------------------------------------------
// 5. Bendy spring: independent axes and the rest offset.

/// Different stiffness per axis: k_x = 36 (ω_x = 6), k_y = 16 (ω_y = 4),
/// m = 1, anchor (3, 2) with rest offset (0.5, −0.25), so the rest position
/// is (3.5, 1.75); started 1 unit beyond it on both axes. Each axis must
/// oscillate with its own period (within 0.5 % of 2π/ω, the issue's
/// target; θ-method prediction +0.083 % and +0.037 %) about the rest
/// position (centre of the parabola-refined extrema within 1e-4).
#[test]
fn bendy_spring_axes_are_independent_and_centred_on_anchor_plus_rest_offset() {
    let (kx, ky) = (36.0f64, 16.0f64);
    let rest = (3.5, 1.75);
    let mut world = World::new(settings(0.0));
    let body = ball(&mut world, 1.0, (rest.0 + 1.0, rest.1 + 1.0), (0.0, 0.0));
    world
        .add_constraint(
            Constraint::bendy_spring(
                Anchor::Point(vec2(3.0, 2.0)),
                Anchor::Body(body),
                vec2(kx, ky),
                fx(0.0),
            )
            .with_rest_offset(vec2(0.5, -0.25)),
        )
        .unwrap();
    let steps = (20.0 * 2.0 * PI / 4.0 / H) as usize;
    let mut xs = vec![pos(&world, body).0];
    let mut ys = vec![pos(&world, body).1];
    for _ in 0..steps {
        world.step();
        let (x, y) = pos(&world, body);
        xs.push(x);
        ys.push(y);
    }
    let centre = |series: &[f64]| {
        let e = extrema(series);
        let max = e.iter().map(|p| p.1).fold(f64::MIN, f64::max);
        let min = e.iter().map(|p| p.1).fold(f64::MAX, f64::min);
        (max + min) / 2.0
    };
    let (cx, cy) = (centre(&xs), centre(&ys));
    let (tx, ty) = (period(&xs, cx), period(&ys, cy));
    let (ax, ay) = (2.0 * PI / kx.sqrt(), 2.0 * PI / ky.sqrt());
    println!(
        "bendy per axis: x period {tx:.6} ({:+.4} %), y period {ty:.6} ({:+.4} %); \
         centre ({cx:.6}, {cy:.6}) vs rest ({}, {})",
        100.0 * relative(tx, ax),
        100.0 * relative(ty, ay),
        rest.0,
        rest.1
    );
    assert!(relative(tx, ax).abs() < 0.005);
    assert!(relative(ty, ay).abs() < 0.005);
    assert!((cx - rest.0).abs() < 1e-4 && (cy - rest.1).abs() < 1e-4);
}

/// The rest offset between two bodies: a damped body–body bendy spring
/// (masses 1 and 2, k = (20, 20), c = 4) settles with `b − a` equal to the
/// rest offset (1, −0.5), to far below a thousandth (after 10 s the
/// slowest mode, decay rate ≥ 3 s⁻¹, has shrunk by e⁻³⁰).
#[test]
fn bendy_spring_between_two_bodies_settles_at_the_rest_offset() {
    let mut world = World::new(settings(0.0));
    let a = ball(&mut world, 1.0, (0.0, 0.0), (0.0, 0.0));
    let b = ball(&mut world, 2.0, (3.0, 2.0), (0.0, 0.0));
    world
        .add_constraint(
            Constraint::bendy_spring(Anchor::Body(a), Anchor::Body(b), vec2(20.0, 20.0), fx(4.0))
                .with_rest_offset(vec2(1.0, -0.5)),
        )
        .unwrap();
    for _ in 0..600 {
        world.step();
    }
    let (pa, pb) = (pos(&world, a), pos(&world, b));
    let offset = (pb.0 - pa.0, pb.1 - pa.1);
    println!(
        "bendy body–body: settled offset ({:.8}, {:.8})",
        offset.0, offset.1
    );
    assert!((offset.0 - 1.0).abs() < 1e-6 && (offset.1 + 0.5).abs() < 1e-6);
}

/// Under gravity the bendy spring's equilibrium is shifted by `m·g/k_y`:
/// anchor (0, 5), rest offset (0, −1), k = (50, 50), c = 10, m = 2, g = 10
/// → rest at y = 4 − 0.4 = 3.6 (the θ-method step with the engine's
/// gravity step has exactly this fixed point), x = 0.
#[test]
fn bendy_spring_under_gravity_settles_at_rest_offset_minus_mg_over_k() {
    let mut world = World::new(settings(10.0));
    let body = ball(&mut world, 2.0, (1.0, 5.0), (0.0, 0.0));
    world
        .add_constraint(
            Constraint::bendy_spring(
                Anchor::Point(vec2(0.0, 5.0)),
                Anchor::Body(body),
                vec2(50.0, 50.0),
                fx(10.0),
            )
            .with_rest_offset(vec2(0.0, -1.0)),
        )
        .unwrap();
    for _ in 0..900 {
        world.step();
    }
    let (x, y) = pos(&world, body);
    println!("bendy under gravity: settled at ({x:.8}, {y:.8}), expected (0, 3.6)");
    assert!(x.abs() < 1e-6 && (y - 3.6).abs() < 1e-6);
}
