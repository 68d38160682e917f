//! Bounces (issue 12): a body dropped on fixed ground bounces at the
//! instant of contact, with `e` times the speed it has at the surface, and
//! never gains energy.
//!
//! # How a bounce is measured (from positions only)
//!
//! Between contacts a body moves under gravity alone, and semi-implicit
//! Euler (`v' = v + g·h`, `x' = x + v'·h`) puts the tick samples of a free
//! flight **exactly on a parabola** of acceleration `g`: the second
//! difference `y_{n+1} − 2y_n + y_{n−1} = h·(v_{n+1} − v_n) = −g·h²` is the
//! parabola's. So each flight is a known parabola, read off two consecutive
//! samples: the velocity of the parabola at sample `y_n` is the chord
//! velocity `(y_n − y_{n−1})/h` corrected by half a tick of gravity,
//! `u_n = (y_n − y_{n−1})/h − g·h/2` (the chord velocity is the parabola's
//! at mid-interval). From it:
//!
//! * the **speed at the surface** (height `z = 0` of the body's lowest
//!   point) of the incoming flight, `√(u² + 2 g z)` at its last sample,
//!   and the **launch speed** of the outgoing flight, the same at its first
//!   samples (energy along one parabola is exact);
//! * the **turning height**: where the incoming and the outgoing parabolas
//!   cross (a bounce at the surface has them meet at `z = 0`; the old bounce
//!   at the start of the tick met them up to `|v|·h` higher);
//! * the **apex** of each flight, `z + u²/(2g)` (the parabola's top), and
//!   the highest sample.
//!
//! Nothing here reads the engine's velocities: the figures are properties
//! of the trajectory.
//!
//! Run with `--nocapture` to see the tables.

mod common;

use clockwork2d::prelude::*;
use common::add_ground;

const G: f64 = 10.0;
const DT: f64 = 1.0 / 60.0;

/// The shape dropped: a circle or a box of the same half height.
#[derive(Clone, Copy, Debug)]
enum Dropped {
    Circle,
    Box,
}

const HALF: f64 = 0.25;

fn world(substeps: u32) -> World {
    World::new(WorldSettings {
        substeps,
        sleep_enabled: false,
        ..WorldSettings::default()
    })
}

/// One bounce, measured from the samples around it.
#[derive(Clone, Copy, Debug)]
struct Bounce {
    /// Speed at the surface of the incoming flight.
    impact: f64,
    /// Launch speed of the outgoing flight.
    launch: f64,
    /// Height (of the lowest point) where the two flights' parabolas meet.
    turn: f64,
}

/// All that a drop produced.
struct Drop {
    bounces: Vec<Bounce>,
    /// Apex of each flight (parabola top), the release first.
    apexes: Vec<f64>,
    /// Highest sample of each flight, the release first.
    sampled_apexes: Vec<f64>,
    /// Lowest sample of the lowest point over the run (penetration < 0).
    lowest: f64,
}

/// Drops `shape` with its lowest point `height` above the ground top
/// (y = 0), restitution `e`, and records `seconds` of samples.
fn drop(shape: Dropped, height: f64, e: f64, substeps: u32, seconds: f64) -> Drop {
    let mut w = world(substeps);
    add_ground(&mut w);
    let s = match shape {
        Dropped::Circle => Shape::circle(fx(HALF)),
        Dropped::Box => Shape::aabb(vec2(HALF, HALF)),
    };
    let id = w
        .add_body(
            BodyDef::dynamic(s)
                .position(vec2(0.0, height + HALF))
                .restitution(fx(e)),
        )
        .unwrap();
    let ticks = (seconds / DT).round() as usize;
    let mut z = vec![height];
    for _ in 0..ticks {
        w.step();
        z.push(w.body(id).unwrap().position().y.to_f64() - HALF);
    }
    analyse(&z, height)
}

/// Parabola velocity at sample `n` from the chord ending there.
fn u_back(z: &[f64], n: usize) -> f64 {
    (z[n] - z[n - 1]) / DT - G * DT / 2.0
}

/// Parabola velocity at sample `n` from the chord starting there.
fn u_forward(z: &[f64], n: usize) -> f64 {
    (z[n + 1] - z[n]) / DT + G * DT / 2.0
}

fn analyse(z: &[f64], release: f64) -> Drop {
    let mut bounces = Vec::new();
    let mut apexes = vec![release];
    let mut sampled_apexes = vec![release];
    let lowest = z.iter().copied().fold(f64::INFINITY, f64::min);
    // A sample n is in free flight when the three samples around it lie on
    // one parabola of acceleration g (second difference −g·h², to rounding).
    let free = |n: usize| {
        n >= 1 && n + 1 < z.len() && ((z[n + 1] - 2.0 * z[n] + z[n - 1]) + G * DT * DT).abs() < 1e-6
    };
    let mut n = 2;
    while n + 2 < z.len() {
        // Incoming flight ends at sample a (descending, free at a-1), the
        // next free sample b starts the outgoing flight (ascending).
        let descending = z[n] < z[n - 1];
        if !(descending && free(n - 1) && !free(n)) {
            n += 1;
            continue;
        }
        let a = n;
        let mut b = a + 1;
        while b + 2 < z.len() && !(free(b + 1) && z[b + 1] > z[b]) {
            b += 1;
        }
        if b + 2 >= z.len() {
            break;
        }
        let ui = u_back(z, a);
        let uo = u_forward(z, b);
        let impact = (ui * ui + 2.0 * G * z[a]).sqrt();
        let launch = (uo * uo + 2.0 * G * z[b]).sqrt();
        // The two parabolas, as functions of time from sample a:
        // zi(t) = z_a + ui t − g t²/2, zo(t) = z_b + uo (t − T) − g (t − T)²/2
        // with T = (b − a)·h. Their difference is linear in t; its root is
        // the turning instant.
        let t_gap = (b - a) as f64 * DT;
        // zi − zo = (z_a − z_b + uo T + g T²/2) + t (ui − uo − g T)
        let c0 = z[a] - z[b] + uo * t_gap + G * t_gap * t_gap / 2.0;
        let c1 = ui - uo - G * t_gap;
        let t = -c0 / c1;
        let turn = z[a] + ui * t - G * t * t / 2.0;
        bounces.push(Bounce {
            impact,
            launch,
            turn,
        });
        // Apex of the outgoing flight, if it rises (launch above rounding).
        if uo > 0.0 {
            apexes.push(z[b] + uo * uo / (2.0 * G));
            let mut m = b;
            let mut top = z[b];
            while m + 1 < z.len() && z[m + 1] >= z[m] {
                m += 1;
                top = top.max(z[m]);
            }
            sampled_apexes.push(top);
        }
        n = b + 1;
    }
    Drop {
        bounces,
        apexes,
        sampled_apexes,
        lowest,
    }
}

/// Launch = e · impact within 1 % for every bounce whose impact is well
/// above the restitution threshold (1 u/s; bounces below it are meant to
/// stop), turning within the linear slop (1e-4) of the surface, never
/// below it by more than the slop, no apex above the one before.
fn check_drop(shape: Dropped, height: f64, e: f64) {
    let d = drop(shape, height, e, 1, 20.0);
    println!("{shape:?} drop {height} m, e = {e}:");
    let mut measured = 0;
    for (i, b) in d.bounces.iter().enumerate() {
        let ratio = b.launch / b.impact;
        println!(
            "  bounce {i}: impact {:.4} u/s, launch {:.4} u/s, launch/impact {:.5} (e = {e}), turn at {:+.2e}",
            b.impact, b.launch, ratio, b.turn
        );
        // Only bounces whose launch is clear of the threshold: below
        // ~1.5 u/s impact the bounce may legitimately be suppressed.
        if b.impact * e < 1.5 {
            continue;
        }
        measured += 1;
        assert!(
            (ratio - e).abs() <= 0.01 * e,
            "{shape:?} {height} m e={e}: bounce {i} launch/impact {ratio} not within 1 % of {e}"
        );
        // The linear slop is 1e-4; the measurement itself (floats from
        // fixed-point samples) is good to ~1e-8.
        assert!(
            b.turn.abs() <= 1e-4,
            "{shape:?} {height} m e={e}: bounce {i} turned at {} (beyond the slop)",
            b.turn
        );
    }
    assert!(measured >= 1, "no bounce was measured");
    for (i, pair) in d.apexes.windows(2).enumerate() {
        println!(
            "  apex {} / apex {i} = {:.5} (e² = {:.5})",
            i + 1,
            pair[1] / pair[0],
            e * e
        );
    }
    for (i, pair) in d.sampled_apexes.windows(2).enumerate() {
        // Each flight's apex is at most the previous one's (e ≤ 1); for
        // e = 1 the sampled maximum can move by the sampling of the
        // parabola's top, g·h²/8 = 3.5e-4 at most, under 0.1 % of 0.5 m.
        let allowed = if e >= 1.0 { pair[0] * 1e-3 } else { 0.0 };
        assert!(
            pair[1] <= pair[0] + allowed,
            "{shape:?} {height} m e={e}: flight {} rose to {} above the previous {}",
            i + 1,
            pair[1],
            pair[0]
        );
    }
    assert!(
        d.lowest >= -1e-4,
        "{shape:?} {height} m e={e}: sank {} below the surface",
        -d.lowest
    );
}

#[test]
fn circle_bounces_launch_at_e_times_the_impact_speed_at_the_surface() {
    for height in [5.0, 0.5] {
        for e in [0.5, 0.8, 1.0] {
            check_drop(Dropped::Circle, height, e);
        }
    }
}

#[test]
fn box_bounces_launch_at_e_times_the_impact_speed_at_the_surface() {
    for height in [5.0, 0.5] {
        for e in [0.5, 0.8, 1.0] {
            check_drop(Dropped::Box, height, e);
        }
    }
}

/// Variants: other heights, other restitutions.
#[test]
fn bounce_variants_other_heights_and_restitutions() {
    for (shape, height, e) in [
        (Dropped::Circle, 2.0, 0.3),
        (Dropped::Circle, 12.0, 0.9),
        (Dropped::Box, 1.3, 0.7),
        (Dropped::Box, 8.0, 0.95),
        (Dropped::Circle, 0.2, 1.0),
    ] {
        check_drop(shape, height, e);
    }
}

/// e = 1 over 60 s: no apex more than 0.1 % above the one before, the
/// last within 2 % of the release height.
#[test]
fn elastic_bounce_keeps_its_apex_for_a_minute() {
    for shape in [Dropped::Circle, Dropped::Box] {
        for height in [5.0, 0.5] {
            let d = drop(shape, height, 1.0, 1, 60.0);
            let first = d.apexes[0];
            let last = *d.apexes.last().unwrap();
            let worst_rise = d
                .sampled_apexes
                .windows(2)
                .map(|p| p[1] / p[0] - 1.0)
                .fold(f64::NEG_INFINITY, f64::max);
            println!(
                "{shape:?} e=1 from {height} m: {} flights in 60 s, apex {first:.5} → {last:.5} (drift {:+.4} %), worst apex-to-apex rise {:+.4} %",
                d.apexes.len(),
                (last / first - 1.0) * 100.0,
                worst_rise * 100.0
            );
            assert!(d.apexes.len() > 10);
            assert!(
                worst_rise <= 1e-3,
                "an apex rose {worst_rise} above the one before"
            );
            assert!(
                (last / first - 1.0).abs() < 0.02,
                "apex drifted from {first} to {last}"
            );
        }
    }
}

/// The apex ratios against e² for substeps 1, 2, 4, 8 (the README's
/// accuracy table). The ratio of parabola tops is e² exactly for an exact
/// bounce (the energy along each flight is exact, see the module notes),
/// so the table shows the bounce's own error; the ratio of *sampled* tops
/// adds the sampling of the top, at most g·h²/8 per apex.
#[test]
fn apex_ratios_against_e_squared_by_substeps() {
    println!("| substeps | e | h1/h0 | h2/h1 | h3/h2 | e² |");
    for e in [0.5, 0.8] {
        for substeps in [1, 2, 4, 8] {
            let d = drop(Dropped::Circle, 5.0, e, substeps, 8.0);
            let ratios: Vec<f64> = d.apexes.windows(2).map(|p| p[1] / p[0]).collect();
            println!(
                "| {substeps} | {e} | {} | {:.5} |",
                ratios
                    .iter()
                    .take(3)
                    .map(|r| format!("{r:.5}"))
                    .collect::<Vec<_>>()
                    .join(" | "),
                e * e
            );
            // Every bounce at least 1.5 u/s launch: ratio within 2 % of e²
            // (launch within 1 % of e·impact squares to 2 %).
            for (i, r) in ratios.iter().enumerate() {
                let impact = (2.0 * G * d.apexes[i]).sqrt();
                if impact * e >= 1.5 {
                    assert!(
                        (r / (e * e) - 1.0).abs() <= 0.02,
                        "substeps {substeps}, e {e}: ratio {i} = {r}"
                    );
                }
            }
        }
    }
}
