//! Circles stacked and piled (issue 13 variants), at the default settings.
//!
//! * A column of n circles standing on the ground (exactly above one
//!   another, so every normal is ±y), free or between two walls that
//!   touch it: n contacts in series, each resting at most one linear slop
//!   deep, so no circle sits more than n·slop below its ideal height;
//!   nothing lifts one (no energy source), so none rises above it; x never
//!   changes (exactly, in fixed point); the column sleeps. Heavy circles
//!   on top (×100, ×1000) change none of this.
//! * Many circles dropped into a closed box: nobody leaves. A contact
//!   with a fixed wall stops a circle at the wall (speculative contact)
//!   and the position pass brings any overlap back to the slop, so no
//!   centre may get further than `r + slop` past a wall's face; the
//!   bound below allows ten slops for what the velocity iterations leave
//!   in a pile while it lands. The pile comes to rest and sleeps: it falls
//!   20 units in √(2·20/10) = 2 s, and must be asleep by 10 s.
//!
//! Figures print with `--nocapture`.

use clockwork2d::prelude::*;

mod common;
use common::{Rng, add_ground};

const HZ: u64 = 60;
const SLOP: f64 = 1e-4;
/// Fixed-point rounding allowance on a compared height: four I32F32 steps.
const ROUND: f64 = 1e-9;

fn wall(world: &mut World, x: f64, half_height: f64) {
    world
        .add_body(
            BodyDef::fixed(Shape::aabb(vec2(0.5, half_height))).position(vec2(x, half_height)),
        )
        .expect("wall");
}

/// A column of `n` circles of radius `r` on the ground at x = 0, the top
/// `heavy` of them of mass `ratio` (the others mass 1), optionally between
/// two walls touching it. Checks the bounds of the module notes.
fn column(n: usize, r: f64, walls: bool, heavy: usize, ratio: f64) {
    let mut world = World::new(WorldSettings::default());
    add_ground(&mut world);
    if walls {
        let half_height = r * n as f64 + 1.0;
        wall(&mut world, -r - 0.5, half_height);
        wall(&mut world, r + 0.5, half_height);
    }
    let bodies: Vec<(BodyId, f64)> = (0..n)
        .map(|i| {
            let y = r + 2.0 * r * i as f64;
            let m = if i + heavy >= n { ratio } else { 1.0 };
            let id = world
                .add_body(
                    BodyDef::dynamic(Shape::circle(fx(r)))
                        .mass(fx(m))
                        .position(vec2(0.0, y)),
                )
                .expect("circle");
            (id, y)
        })
        .collect();
    let (mut sink, mut rise, mut moved_x) = (0.0f64, 0.0f64, false);
    let mut asleep_from = None;
    for t in 1..=6 * HZ {
        world.step();
        let mut asleep = true;
        for &(id, ideal) in &bodies {
            let b = world.body(id).unwrap();
            let dy = b.position().y.to_f64() - ideal;
            sink = sink.max(-dy);
            rise = rise.max(dy);
            moved_x |= b.position().x != Fx::ZERO;
            asleep &= !b.is_awake();
        }
        asleep_from = match (asleep, asleep_from) {
            (true, None) => Some(t),
            (true, from) => from,
            (false, _) => None,
        };
    }
    let bound = n as f64 * SLOP;
    println!(
        "circle column n {n} r {r} walls {walls} top {heavy} ×{ratio}: worst sink {sink:.3e} (bound {bound:.4}), rise {rise:.1e}, x moved {moved_x}, asleep from {asleep_from:?}"
    );
    assert!(sink <= bound + ROUND);
    assert!(rise <= ROUND);
    assert!(!moved_x);
    assert!(asleep_from.is_some_and(|t| t < 4 * HZ));
}

#[test]
fn circle_columns_rest_within_n_slop_without_drift_and_sleep() {
    for (n, r, walls) in [
        (10, 0.5, false),
        (30, 0.5, false),
        (10, 0.5, true),
        (30, 0.5, true),
        (10, 2.0, true),
        // Small circles: every circle lies within the 0.1 speculative
        // margin of several above it (rows that close cycles in the
        // contact graph); the bound is the same.
        (30, 0.05, true),
        (30, 0.02, true),
        (30, 0.05, false),
    ] {
        column(n, r, walls, 0, 1.0);
    }
}

#[test]
fn circle_columns_with_heavy_tops_rest_within_n_slop() {
    for (heavy, ratio) in [(1, 10.0), (1, 100.0), (1, 1000.0), (5, 100.0), (5, 1000.0)] {
        column(20, 0.5, true, heavy, ratio);
    }
}

/// `n` circles with radii in `[r_min, r_max)` at random places in a closed
/// box whose inside is [−5, 5] × [0, 20] (density 1).
fn closed_box(n: usize, r_min: f64, r_max: f64, seed: u64) {
    let mut world = World::new(WorldSettings::default());
    let fixed = |world: &mut World, half: (f64, f64), at: (f64, f64)| {
        world
            .add_body(BodyDef::fixed(Shape::aabb(vec2(half.0, half.1))).position(vec2(at.0, at.1)))
            .expect("wall");
    };
    fixed(&mut world, (6.0, 0.5), (0.0, -0.5));
    fixed(&mut world, (6.0, 0.5), (0.0, 20.5));
    fixed(&mut world, (0.5, 11.0), (-5.5, 10.0));
    fixed(&mut world, (0.5, 11.0), (5.5, 10.0));
    let mut rng = Rng(seed);
    let circles: Vec<(BodyId, f64)> = (0..n)
        .map(|_| {
            let r = rng.range(r_min, r_max);
            let x = rng.range(-5.0 + r, 5.0 - r);
            let y = rng.range(r, 20.0 - r);
            let id = world
                .add_body(BodyDef::dynamic(Shape::circle(fx(r))).position(vec2(x, y)))
                .expect("circle");
            (id, r)
        })
        .collect();
    let mut outside = 0.0f64;
    let mut asleep_from = None;
    for t in 1..=10 * HZ {
        world.step();
        let mut asleep = true;
        for &(id, r) in &circles {
            let b = world.body(id).unwrap();
            let (x, y) = b.position().to_f64();
            let past = [-5.0 + r - x, x - 5.0 + r, r - y, y - 20.0 + r];
            outside = past.into_iter().fold(outside, f64::max);
            asleep &= !b.is_awake();
        }
        asleep_from = match (asleep, asleep_from) {
            (true, None) => Some(t),
            (true, from) => from,
            (false, _) => None,
        };
    }
    println!(
        "{n} circles r {r_min}–{r_max} in a closed box: deepest past a wall {outside:.2e} (bound {:.0e}), asleep from tick {asleep_from:?}",
        10.0 * SLOP
    );
    assert!(outside <= 10.0 * SLOP);
    assert!(asleep_from.is_some());
}

#[test]
fn circles_dropped_into_a_closed_box_stay_inside_and_sleep() {
    closed_box(200, 0.2, 0.3, 1);
    // The larger pile runs in release (CI runs `cargo test --release`);
    // the debug profile is slow.
    if !cfg!(debug_assertions) {
        closed_box(500, 0.1, 0.2, 2);
    }
}
