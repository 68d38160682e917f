//! Closed loops of ropes (issue 13): a ring of `n` light links (mass 0.1,
//! ropes of about 0.1) with one body `ratio` times a link, placed as a
//! circle at rest and hung from a fixed point by one more rope to its top
//! link, at the default settings (and substeps 2 and 4). The ropes form a
//! cycle, which the tree solve cannot take; groups of up to 64 rows take
//! the block solver, with the ropes' sideways stiffness.
//!
//! Bounds (the chain tests' bounds, `tests/solver_chains.rs`):
//! * worst stretch `(|x_k − x_{k+1}| − ℓ_k)/ℓ_k` under the 1 % at
//!   every tick (before the sideways stiffness in the block solver: 4.1 %
//!   for 20 links at 100×, 38 000 % at 1000×, 17 000 % for 40 links at
//!   100×);
//! * never growing: the last second no worse than the first second or the
//!   slop (1e-4 on a rope of `ℓ`), plus [`ROUNDING`] (as for chains; the
//!   block solver's position passes do not hold ropes within the slop, so
//!   a loop may end a few 1e-6 of its length beyond the slop, where a
//!   chain ends within it);
//! * total energy (kinetic + gravitational, zero at the start) never above
//!   what the position passes may lift: each rope pulled back to within
//!   the slop raises what hangs below it by at most the slop, and a link
//!   hangs below at most `n/2 + 1` ropes (the hanger and the shorter way
//!   round), so the bound is `g·slop·M·(n/2 + 1)`.
//!
//! Figures print with `--nocapture`.

use std::f64::consts::PI;

use clockwork2d::prelude::*;

mod common;
use common::oscillators::{pos, vel};

const SLOP: f64 = 1e-4;
const G: f64 = 10.0;
const LINK_MASS: f64 = 0.1;
/// Allowance on a compared stretch: the settling passes stop within the
/// slop or at the fixed-point floor (a few 1e-8 of length, i.e. a few
/// 1e-7 of a 0.1 rope's length).
const ROUNDING: f64 = 1e-6;
/// Ticks per run in this profile (debug `cargo test` runs 5 s; the
/// release run covers 20 s).
const TICKS: usize = if cfg!(debug_assertions) { 300 } else { 1200 };

struct Ring {
    worst: f64,
    first_second: f64,
    last_second: f64,
    slop_fraction: f64,
    highest_energy: f64,
    lift: f64,
}

fn hang_ring(n: usize, ratio: f64, substeps: u32) -> Ring {
    let mut world = World::new(WorldSettings {
        substeps,
        ..WorldSettings::default()
    });
    let radius = 0.1 * n as f64 / (2.0 * PI);
    let links: Vec<(BodyId, f64)> = (0..n)
        .map(|i| {
            let angle = 2.0 * PI * i as f64 / n as f64;
            let mass = if i == n / 2 {
                LINK_MASS * ratio
            } else {
                LINK_MASS
            };
            let id = world
                .add_body(
                    BodyDef::dynamic(Shape::circle(fx(0.01)))
                        .mass(fx(mass))
                        .position(vec2(radius * angle.sin(), -radius + radius * angle.cos())),
                )
                .expect("link");
            (id, mass)
        })
        .collect();
    let next = |i: usize| (i + 1) % n;
    let lengths: Vec<f64> = (0..n)
        .map(|i| {
            let (p, q) = (pos(&world, links[i].0), pos(&world, links[next(i)].0));
            (p.0 - q.0).hypot(p.1 - q.1)
        })
        .collect();
    for i in 0..n {
        world
            .add_constraint(Constraint::rope(
                Anchor::Body(links[i].0),
                Anchor::Body(links[next(i)].0),
                fx(lengths[i]),
            ))
            .expect("rope");
    }
    world
        .add_constraint(Constraint::rope(
            Anchor::Point(vec2(0.0, 0.1)),
            Anchor::Body(links[0].0),
            fx(0.1),
        ))
        .expect("hanger");
    let start: Vec<f64> = links.iter().map(|&(id, _)| pos(&world, id).1).collect();
    let total_mass: f64 = links.iter().map(|&(_, m)| m).sum();
    let shortest = lengths.iter().copied().fold(f64::MAX, f64::min);
    let mut ring = Ring {
        worst: 0.0,
        first_second: 0.0,
        last_second: 0.0,
        slop_fraction: SLOP / shortest,
        highest_energy: f64::MIN,
        lift: G * SLOP * total_mass * (n / 2 + 1) as f64,
    };
    for tick in 0..TICKS {
        world.step();
        let mut stretch = 0.0f64;
        for i in 0..n {
            let (p, q) = (pos(&world, links[i].0), pos(&world, links[next(i)].0));
            stretch = stretch.max(((p.0 - q.0).hypot(p.1 - q.1) - lengths[i]) / lengths[i]);
        }
        ring.worst = ring.worst.max(stretch);
        if tick < 60 {
            ring.first_second = ring.first_second.max(stretch);
        }
        if tick + 60 >= TICKS {
            ring.last_second = ring.last_second.max(stretch);
        }
        let energy: f64 = links
            .iter()
            .zip(&start)
            .map(|(&(id, m), &y0)| {
                let (p, v) = (pos(&world, id), vel(&world, id));
                0.5 * m * (v.0 * v.0 + v.1 * v.1) + m * G * (p.1 - y0)
            })
            .sum();
        ring.highest_energy = ring.highest_energy.max(energy);
    }
    println!(
        "ring of {n} ropes, body {ratio}x, substeps {substeps}: worst stretch {:.4} %, first second {:.4} %, last second {:.4} % (slop {:.4} %), highest energy {:+.4} J (bound {:.4})",
        ring.worst * 100.0,
        ring.first_second * 100.0,
        ring.last_second * 100.0,
        ring.slop_fraction * 100.0,
        ring.highest_energy,
        ring.lift
    );
    ring
}

fn check(n: usize, ratio: f64, substeps: u32) {
    let r = hang_ring(n, ratio, substeps);
    assert!(r.worst < 0.01, "ring {n} {ratio}x: stretched {}", r.worst);
    assert!(
        r.last_second <= r.first_second.max(r.slop_fraction) + ROUNDING,
        "ring {n} {ratio}x: stretch grew from {} to {}",
        r.first_second,
        r.last_second
    );
    assert!(
        r.highest_energy <= r.lift,
        "ring {n} {ratio}x gained energy: {}",
        r.highest_energy
    );
}

/// Rings of 6, 20 and 40 ropes with a body 1×, 100×, 300× and 1000× a
/// link, at the defaults.
#[test]
fn rings_of_ropes_hung_from_a_point_keep_their_length() {
    for &(n, ratio) in &[
        (20, 100.0),
        (20, 1000.0),
        (20, 300.0),
        (20, 1.0),
        (6, 100.0),
        (40, 100.0),
        (40, 1000.0),
    ] {
        check(n, ratio, 1);
    }
}

/// More substeps are never worse than the bounds: substeps 2 and 4.
#[test]
fn rings_of_ropes_keep_their_length_with_more_substeps() {
    for &(n, ratio) in &[(20, 100.0), (20, 1000.0), (40, 100.0)] {
        for substeps in [2, 4] {
            check(n, ratio, substeps);
        }
    }
}
