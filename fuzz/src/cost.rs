//! What a step costs, so the targets that step a world built from bytes
//! (`snapshot_restore`, `replay_verify`, `scene_load`) can keep each input
//! within a time budget.
//!
//! # The cost model (measured)
//!
//! A step costs about `c·(bodies + touching pairs)`: every touching or
//! speculative pair is a contact row the solver visits on every
//! iteration (constraints add [`CONSTRAINT_COST`] pairs each). On the development machine, release build, default
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
//! counts, before every step, the pairs whose boxes (grown by the
//! speculative margin and one tick of motion) overlap, capped; after the
//! step the world's own `touching_pairs` gives the real count. Where a run
//! cannot be metered tick by tick (`Replay::verify` steps on its own),
//! [`most_pairs`] bounds every tick after the first.

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

/// What the next step of `world` costs by the model: its bodies and
/// constraints plus the pairs [`pairs_near`] finds with the velocities it
/// has now, counted up to `cap`.
///
/// The estimate is taken before every step, not carried over from the
/// pairs the last step reported: one step can multiply the pairs. A
/// restored snapshot whose cached warm-start impulse was 16 777 217
/// instead of 1.35 (`seeds/snapshot_restore/balls5000.tick90.warm-impulse.snap`)
/// throws a ball at 3 811 units/s in its first tick; the touching pairs of
/// the 5 004 bodies then go 5 105 → 21 074 → 788 522 → 5 452 454 in three
/// ticks (3.6 s and 32 s in a release build for the last two), while the
/// pairs near before each of those ticks, 138 709 and 2 229 722, already
/// show it.
///
/// Each constraint counts as [`CONSTRAINT_COST`] pairs.
#[must_use]
pub fn tick_cost(world: &World<Fx>, cap: u64) -> u64 {
    let constraints = (world.constraints().count() as u64).saturating_mul(CONSTRAINT_COST);
    (world.body_count() as u64)
        .saturating_add(constraints)
        .saturating_add(pairs_near(world, cap))
}

/// What one constraint costs a tick, in pairs. Measured on the costliest
/// kind, stiff springs, which are solved directly (a factorisation per
/// substep, more than linear in the group's size): a `springs_grid`
/// snapshot (1 025 bodies, 2 016 bendy springs) whose springs a fuzzer
/// input made stiff takes 100-210 ms a tick in a release build at load 8,
/// against about 3 µs per pair-tick: 35 000-70 000 pairs, 17-35 a spring.
/// Snapshots are at most the largest seed (libFuzzer's `-max_len`,
/// 316 KB), so no lattice is much larger than that one.
pub const CONSTRAINT_COST: u64 = 32;

/// The most pairs `bodies` bodies can form, `n(n − 1)/2`: a bound on one
/// tick's pairs that holds whatever the bodies' velocities become.
#[must_use]
pub fn most_pairs(bodies: u64) -> u64 {
    bodies.saturating_mul(bodies.saturating_sub(1)) / 2
}

/// Steps `world` up to `ticks` times, spending at most `budget` pair-ticks
/// (see the module notes); `each` runs after every step. Before every step
/// its cost is estimated by [`tick_cost`] and the stepping stops when that
/// would exceed what is left; a step is charged the larger of its estimate
/// and the pairs it reported touching. Returns the number of ticks stepped
/// (0 when even the first tick would exceed the budget).
pub fn step_within(
    world: &mut World<Fx>,
    ticks: u64,
    budget: u64,
    mut each: impl FnMut(&mut World<Fx>, u64),
) -> u64 {
    let bodies = world.body_count() as u64;
    let mut spent = 0u64;
    for tick in 1..=ticks {
        let left = budget.saturating_sub(spent);
        let estimate = tick_cost(world, left.saturating_add(1));
        if estimate > left {
            return tick - 1;
        }
        world.step();
        each(world, tick);
        let reported = bodies.saturating_add(world.touching_pairs().count() as u64);
        spent = spent.saturating_add(estimate.max(reported));
    }
    ticks
}
