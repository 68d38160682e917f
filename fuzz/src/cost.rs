//! What a step costs, so the targets that step a world built from bytes
//! (`snapshot_restore`, `replay_verify`, `scene_load`) can keep each input
//! within a time budget.
//!
//! # The cost model (measured)
//!
//! A step costs about `c·(bodies + touching pairs)`: every touching or
//! speculative pair is a contact row the solver visits on every
//! iteration. On the development machine, release build, default
//! settings (8 velocity and 3 position iterations), `c` is 2-3 µs per
//! pair per tick: `large_pyramid` (5 051 bodies, 14 950 pairs) 2.1 µs;
//! the same pyramid with every box 13.8 units wide (173 090 pairs, the
//! slow input the fuzzer found: one shared shape in the snapshot changed
//! from 0.5 to 6.89) 3.0 µs; 250, 500 and 1 000 coincident boxes (31 125,
//! 124 750 and 499 500 pairs) 1.5, 3.0 and 2.9 µs. So such a world is
//! legitimate and just expensive: the pairs are bounded by `n(n − 1)/2`
//! for `n` bodies, and `n` by the snapshot's size. The same world can be
//! built through the API (`add_body` accepts overlapping bodies).
//!
//! The targets therefore budget **pair-ticks**, not ticks: [`pairs_near`]
//! counts, before the first step, the pairs whose boxes (grown by the
//! speculative margin and one tick of motion) overlap, capped; after each
//! step the world's own `touching_pairs` gives the real count.

use clockwork2d::prelude::{BodyKind, Fx, Scalar, World};

/// Counts the pairs of bodies, at least one of them dynamic, whose bounding
/// boxes grown by the speculative margin and one tick of motion
/// (`|v|₁·dt`) overlap, stopping at `cap`. A sweep along x over the boxes
/// sorted by their left edge: `O(n log n + min(pairs, cap))`.
#[must_use]
pub fn pairs_near(world: &World<Fx>, cap: u64) -> u64 {
    let settings = world.settings();
    let dt = settings.dt.abs();
    let margin = settings.speculative_margin.abs();
    let mut boxes: Vec<(Fx, Fx, Fx, Fx, bool)> = world
        .bodies()
        .map(|(_, body)| {
            let v = body.velocity();
            let grow = margin.add(v.x.abs().add(v.y.abs()).mul(dt));
            let b = body.aabb().expanded(grow);
            let (lo, hi) = (b.min(), b.max());
            (lo.x, hi.x, lo.y, hi.y, body.kind() == BodyKind::Dynamic)
        })
        .collect();
    boxes.sort_by_key(|a| a.0);
    let mut count = 0u64;
    for (i, a) in boxes.iter().enumerate() {
        for b in &boxes[i + 1..] {
            if b.0 > a.1 {
                break;
            }
            if (a.4 || b.4) && b.2 <= a.3 && a.2 <= b.3 {
                count += 1;
                if count >= cap {
                    return cap;
                }
            }
        }
    }
    count
}

/// Steps `world` up to `ticks` times, spending at most `budget` pair-ticks
/// (bodies + touching pairs per tick, see the module notes); `each` runs
/// after every step. Returns the number of ticks stepped (0 when even the
/// first tick would exceed the budget by the estimate of [`pairs_near`]).
pub fn step_within(
    world: &mut World<Fx>,
    ticks: u64,
    budget: u64,
    mut each: impl FnMut(&mut World<Fx>, u64),
) -> u64 {
    let bodies = world.body_count() as u64;
    let mut spent = 0u64;
    let mut next = bodies.saturating_add(pairs_near(world, budget.saturating_add(1)));
    for tick in 1..=ticks {
        if spent.saturating_add(next) > budget {
            return tick - 1;
        }
        world.step();
        each(world, tick);
        let pairs = world.touching_pairs().count() as u64;
        next = bodies.saturating_add(pairs);
        spent = spent.saturating_add(next);
    }
    ticks
}
