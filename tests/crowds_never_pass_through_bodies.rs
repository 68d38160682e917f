//! No body of a heavy crowd passes through another in one tick (issue 13,
//! heavy crowds).
//!
//! A closed box of bodies of random sizes (circles, or circles and boxes),
//! every 10th 100× or 1000× denser than the rest, falls into a pile under
//! g = 10 or 100. Big cyclic groups of uneven masses are solved on a few
//! covering spanning trees in turn (`RowGroups::classify`), a scheme that
//! can run away: a light box resting on the floor under the pile left one
//! velocity solve at 147 units/s and crossed 2.4 units of the pile in one
//! tick, through five bodies it had rows with (g 100, seed 1, tick 364).
//!
//! The physics: bodies are impenetrable, so a body's centre never goes in
//! one tick from one side of another body to the other through it. The
//! check: for each pair `(A, B)` whose boxes (a circle's bounding box) are
//! apart by more than `CLEAR` at both ends of a tick (so no overlap the
//! position pass is still correcting counts), `A`'s centre must not pass
//! within half of the combined half extents of `B`'s centre on both axes
//! at any point of the straight segment between its two positions while
//! `B` stays put (a `B` moving less than `STILL`). A body going round `B`
//! in a curve within a tick is possible but can never come that close
//! (its path would have to dip halfway into `B`), and a body moving
//! straight across `B`'s middle has passed through it. The segment is
//! the least a body's path can be: the test cannot see a path that passed
//! through and came back, so it cannot report a crossing that did not
//! happen.
//!
//! Not asserted here: the overlaps of the heaviest piles at g 100 (up to
//! 0.2, open in issue 13) — the pairs they concern are excluded by `CLEAR`.

mod common;
use clockwork2d::prelude::*;
use common::add_closed_room;
use common::split_mix::SplitMix;

/// How far apart two bodies' boxes must be at both ends of a tick for the
/// pair to be checked: well clear of the slop (1e-4) and of the overlaps
/// a sinking heavy pile still has.
const CLEAR: f64 = 1e-3;
/// The most `B` may move in the tick for the pair to be checked.
const STILL: f64 = 0.05;
/// Ticks per crowd (8 s; 3 s in debug, the test profile is slow).
const TICKS: usize = if cfg!(debug_assertions) { 180 } else { 480 };

#[derive(Clone, Copy, Debug)]
struct Crowd {
    count: usize,
    ratio: f64,
    g: f64,
    seed: u64,
    boxes: bool,
}

/// Half extents of a body's bounding box.
fn half_extents(shape: Shape) -> (f64, f64) {
    match shape {
        Shape::Circle { radius } => (radius.to_f64(), radius.to_f64()),
        Shape::Aabb { half_extents } => half_extents.to_f64(),
    }
}

/// Whether the segment `p0 → p1` passes within `(hx, hy)` of `q` on both
/// axes (a segment against a box, by clipping `t ∈ [0, 1]` per axis).
fn segment_enters(p0: (f64, f64), p1: (f64, f64), q: (f64, f64), (hx, hy): (f64, f64)) -> bool {
    let (mut low, mut high) = (0.0f64, 1.0f64);
    for (start, end, centre, half) in [(p0.0, p1.0, q.0, hx), (p0.1, p1.1, q.1, hy)] {
        let d = end - start;
        let (a, b) = (centre - half - start, centre + half - start);
        if d == 0.0 {
            if a > 0.0 || b < 0.0 {
                return false;
            }
            continue;
        }
        let (t0, t1) = if d > 0.0 {
            (a / d, b / d)
        } else {
            (b / d, a / d)
        };
        low = low.max(t0);
        high = high.min(t1);
    }
    low <= high
}

/// Runs one crowd; returns the crossings seen (tick, body, other).
fn crossings(crowd: Crowd) -> Vec<(usize, usize, usize)> {
    let mut world = World::new(WorldSettings {
        gravity: vec2(0.0, -crowd.g),
        ..WorldSettings::default()
    });
    let (hw, hh, wall) = (4.0, 8.0, 0.1);
    add_closed_room(&mut world, (0.0, 0.0), (hw, hh), wall);
    let mut rng = SplitMix(crowd.seed);
    let mut bodies = Vec::new();
    for k in 0..crowd.count {
        let x = -hw + 0.25 + 0.5 * (k % 16) as f64;
        let y = -hh + 0.25 + 0.5 * (k / 16) as f64;
        let s = rng.range(0.1, 0.24);
        let shape = if crowd.boxes && rng.unit() < 0.5 {
            Shape::aabb(vec2(s, rng.range(0.1, 0.24)))
        } else {
            Shape::circle(fx(s))
        };
        let mut def = BodyDef::dynamic(shape).position(vec2(x, y));
        if k % 10 == 0 {
            def = def.density(fx(crowd.ratio));
        }
        bodies.push(world.add_body(def).expect("body"));
    }
    let halves: Vec<(f64, f64)> = bodies
        .iter()
        .map(|&id| half_extents(world.body(id).expect("body").shape()))
        .collect();
    let positions = |world: &World| -> Vec<(f64, f64)> {
        bodies
            .iter()
            .map(|&id| world.body(id).expect("body").position().to_f64())
            .collect()
    };
    // Boxes apart by more than CLEAR.
    let apart = |p: (f64, f64), q: (f64, f64), h: (f64, f64)| {
        (p.0 - q.0).abs() - h.0 > CLEAR || (p.1 - q.1).abs() - h.1 > CLEAR
    };
    let mut found = Vec::new();
    let mut before = positions(&world);
    for tick in 1..=TICKS {
        world.step();
        let after = positions(&world);
        for a in 0..bodies.len() {
            for b in 0..bodies.len() {
                if a == b {
                    continue;
                }
                let (b0, b1) = (before[b], after[b]);
                if (b1.0 - b0.0).hypot(b1.1 - b0.1) > STILL {
                    continue;
                }
                let h = (halves[a].0 + halves[b].0, halves[a].1 + halves[b].1);
                if !(apart(before[a], b0, h) && apart(after[a], b1, h)) {
                    continue;
                }
                if segment_enters(before[a], after[a], b1, (h.0 / 2.0, h.1 / 2.0)) {
                    found.push((tick, a, b));
                }
            }
        }
        before = after;
    }
    found
}

/// Crowds of 200 in a closed 8 × 16 box, every 10th body 100× or 1000×
/// denser, g 10 and 100, circles or circles and boxes, four seeds.
#[test]
fn no_body_of_a_heavy_crowd_passes_through_another() {
    let mut failures = Vec::new();
    for seed in 1..=4 {
        for ratio in [100.0, 1000.0] {
            for g in [10.0, 100.0] {
                for boxes in [false, true] {
                    let crowd = Crowd {
                        count: 200,
                        ratio,
                        g,
                        seed,
                        boxes,
                    };
                    let found = crossings(crowd);
                    println!("{crowd:?}: {} crossings {:?}", found.len(), found.first());
                    if !found.is_empty() {
                        failures.push((crowd, found.len(), found[0]));
                    }
                }
            }
        }
    }
    assert!(
        failures.is_empty(),
        "{} crowds with a body through another: {failures:?}",
        failures.len()
    );
}
