//! Phase "punched motion", step 3: the bodies following a body the cut
//! stopped are held behind it (`step/punched_motion.rs` is the cut).
//!
//! Why: the velocity solve sets a body's velocity from its rows assuming
//! each partner moves by `v·h`; a partner stopped at an obstacle short of
//! that leaves the follower's motion unchecked. A ball at 50 units/s
//! pushing a box 100× lighter towards a wall 0.3 away: the solve sent both
//! at 49.7 units/s (0.83 in the tick), the box was stopped at the wall, and
//! the ball ended 0.265 inside it; with a box of its own mass at 300
//! units/s, 0.45 inside, and the projection out of the box then pushed it
//! out on the wall's side. The position pass cannot repair this: it
//! corrects at most `margin/2` per axis and substep
//! ([`World::bound_corrections`]).
//!
//! What: the follower's displacement `d` is scaled, never pushed: its
//! approach to the other end along the row's normal `n`, `g` (`d_a·n` when
//! it is the row's body a, `−d_b·n` when b), is cut by the row's deficit,
//! `d ← d·(1 − deficit/g)`. A row is linear in the displacement and holds
//! at `d` (the solve) and at 0 (where the body starts), so every other row
//! of the follower (its floor, a wall beside it) still holds at any `λ·d`,
//! `λ ∈ [0, 1]`. A push back along the row's normal does not: a first
//! version did that, and in a heavy crowd it moved a light circle back
//! along a diagonal contact normal (0.8, 0.6) by 0.64, which took 0.38 off
//! its height, through the floor it had a row with (and nothing after
//! repairs that: the position pass corrects at most `margin/2` per axis;
//! `crowds_stay_inside` and `crowds_squeezed_by_heavy_bodies` failed, up to
//! 506 units past a wall). The held body keeps its velocity: the next
//! substep's rows (the follower closing on the stopped body, that one
//! touching the wall) stop or bounce it as any impact into a body resting
//! on a wall.

use crate::math::{Scalar, Vec2};
use crate::solver::row::ContactConstraint;
#[cfg(doc)]
use crate::world::World;

/// The most passes of [`hold_followers_behind`] over the rows: each pass
/// holds at least the next body of every chain behind a cut body (more when
/// the rows come in chain order), so 8 passes hold chains of 8 followers;
/// a longer chain's further bodies are left to the position pass (each
/// such row was closed by at most the cut).
const HOLD_MAX_PASSES: u32 = 8;

/// Bodies following a cut body are held behind it: each row between two
/// movable bodies, at least one of them ranked, that the cuts (or a body
/// held here) closed beyond where it stood before, `s < min(s₀, 0)` (`s₀`
/// the row's separation at the displacements before the cuts, `s` at the
/// current ones), shortens the follower's displacement along its own path
/// until `s = min(s₀, 0)` (or to nothing), and ranks it one above the
/// other end, so that its own followers are held behind it in the next
/// passes (at most [`HOLD_MAX_PASSES`]). The follower is the end that
/// approaches the other along the row's normal when only one does (only it
/// closes the row); when both do, the end of higher rank or the unranked
/// one (cut bodies are 1), and of two ends of the same rank, the one
/// approaching the other the faster (two boxes of a row both cut at the
/// wall: the one behind passed through the other to reach it).
///
/// The ranks alone do not say who follows: a row of 4 boxes 100× lighter
/// than a ball at 300 units/s, 0.3 from a wall, was cut at the wall box by
/// box (all ranked 1, each reaching it through the ones ahead), the second
/// box was then stopped short by its meeting with the last one, and the
/// third, held behind the last one (rank 2), counted as the second's
/// follower; it moved away from the second, so the row was left 0.31
/// closed.
pub(super) fn hold_followers_behind<S: Scalar>(
    constraints: &[ContactConstraint<S>],
    links: &mut Vec<u32>,
    displacements: &mut [Vec2<S>],
    uncut: &[Vec2<S>],
    rank: &mut [u32],
) {
    // The rows between two movable bodies, once (the passes read only
    // these, and most of them only for the ranks of their ends).
    links.clear();
    links.extend(
        constraints
            .iter()
            .enumerate()
            .filter(|(_, c)| c.inverse_mass_a.is_positive() && c.inverse_mass_b.is_positive())
            .map(|(k, _)| u32::try_from(k).unwrap_or(u32::MAX)),
    );
    for _ in 0..HOLD_MAX_PASSES {
        let mut held = false;
        for &k in links.iter() {
            let c = &constraints[k as usize];
            let (a, b) = (c.a as usize, c.b as usize);
            let (rank_a, rank_b) = (rank[a], rank[b]);
            if rank_a == 0 && rank_b == 0 {
                continue;
            }
            let before = c.separation.add((uncut[b] - uncut[a]).dot(c.normal));
            let now = c
                .separation
                .add((displacements[b] - displacements[a]).dot(c.normal));
            let deficit = before.min(S::ZERO).sub(now);
            if !deficit.is_positive() {
                continue;
            }
            // The follower: the end of higher rank, or the unranked one.
            // Its displacement is scaled down along its own path, never
            // pushed sideways or back: its approach to the other end along
            // the normal, `g` (`−d_b·n` for b, `d_a·n` for a), is cut by
            // the deficit, `d ← d·(1 − deficit/g)`, or to nothing.
            let (along_a, along_b) = (
                displacements[a].dot(c.normal),
                displacements[b].dot(c.normal),
            );
            let (a_approaches, b_approaches) = (along_a.is_positive(), along_b.is_negative());
            // A row is closed only by an end approaching the other: when
            // only one does, it follows, whatever the ranks.
            let b_follows = if a_approaches != b_approaches {
                b_approaches
            } else if rank_a == rank_b {
                along_b.neg() > along_a
            } else {
                rank_a != 0 && (rank_b == 0 || rank_b > rank_a)
            };
            let follower = if b_follows { b } else { a };
            let approach = if b_follows { along_b.neg() } else { along_a };
            if !approach.is_positive() {
                continue;
            }
            displacements[follower] = if deficit < approach {
                let keep = approach.sub(deficit).div(approach);
                displacements[follower].scale(keep)
            } else {
                Vec2::ZERO
            };
            rank[follower] = if b_follows { rank_a + 1 } else { rank_b + 1 };
            held = true;
        }
        if !held {
            break;
        }
    }
}
