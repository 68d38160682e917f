//! Restitution at the instant of contact, applied after the position
//! update.
//!
//! # The method
//!
//! The velocity solve treats a closing contact as purely speculative
//! (`v_n ≥ −s/h`): the pair closes its gap exactly by the end of the
//! substep and no more. A contact that met this substep fast enough to
//! bounce is then *re-timed* here, after the positions are integrated:
//!
//! 1. **When it met.** Within a substep every body follows the
//!    integrator's own free-flight path. Semi-implicit Euler
//!    (`v' = v + a·h`, `x' = x + v'·h`) puts successive positions exactly on
//!    a parabola of acceleration `a` whose velocity at the substep's start
//!    is `v' − a·h/2` (the chord velocity `v'` is the parabola's at
//!    mid-substep). Along the normal the gap is then
//!    `s(τ) = s₀ + u₀ τ + a_n τ²/2` with `u₀ = v_n − a_n·h/2`, `v_n` the
//!    relative normal velocity the solver started from and `a_n` the
//!    relative normal acceleration of gravity (zero between two bodies of
//!    the same gravity scale: the motion is then linear). Energy along the
//!    parabola gives the closing speed at contact exactly,
//!    `u_c = −√(u₀² − 2 a_n s₀)`, and the mean-velocity rule gives the
//!    instant, `τ = 2 s₀ / −(u₀ + u_c)` (exact for constant acceleration,
//!    and never a division by `a_n`).
//! 2. **The bounce.** At `τ` the normal velocity becomes `w = −e·u_c`
//!    (Newton's law with the speed *at the surface*), and the pair flies
//!    apart on the reflected parabola for the rest of the substep,
//!    `r = h − τ`: the end gap is `w·r + a_n r²/2` (never negative) and the
//!    end velocity, the parabola's at mid-substep, `w + a_n (h/2 − τ)`.
//! 3. **Applying it.** The end velocity is a target for the pair's row,
//!    and every group of rows holding such a row is solved once more
//!    ([`apply_bounces`]): bouncing rows to their end velocity, rows
//!    touching at the end of the substep to "no closing", rows apart left
//!    out. The reaction of a bounce thus goes where the contacts carry it
//!    (a ball bouncing on a crate that rests on the ground meets, through
//!    the crate, the ground); momentum is conserved and a fixed body does
//!    not move. The velocity change of each body, times the flight after
//!    the impact, is its added displacement (for a pair alone: exactly the
//!    end gap). Only pushes start a bounce (a pair already separating
//!    faster is left alone). Several rows bouncing in one group
//!    (simultaneous contacts) take Newton's law together.
//!
//! Two kinds of group bounce row by row instead (each bouncing row's own
//! end velocity and end gap, one impulse and one displacement along its
//! normal split by inverse mass, the launch scaled by the share of the
//! approach the row stopped when several rows stopped one impact): a
//! group whose rows all hold an immovable body (nothing to transmit; each
//! wall keeps its own instant, which a common flight would not, so a body
//! meeting two walls in one substep leaves each exactly), and a large
//! group left to sequential impulses (an even-mass pile, whose sweeps
//! would cost as much as the velocity solve for every ball landing on
//! it: a bounce there is not transmitted through the pile).
//!
//! A body resting on another when it is hit (a crate on the ground) is
//! not in free flight: the acceleration of step 1 is its gravity less the
//! component its resting contacts hold ([`supported_accelerations`]), so
//! the bounce off a resting crate is re-timed exactly as off the ground.
//!
//! The motion added in step 3 is then swept against the world like any
//! other motion (`World::sweep_rebounds`): a rebound cannot pass through
//! what lies behind the body.
//!
//! # Error bound
//!
//! For a body bouncing off a fixed body under gravity alone (the analysed
//! case) the bounce is exact in the integrator's own model: the samples
//! before and after lie on the two true parabolas, which meet at the
//! surface, and the launch speed is `e` times the speed at the surface;
//! what remains is fixed-point rounding (a few ulps in `τ`, `u_c` — the
//! square root is exact to an ulp) and the solver's residual in the
//! speculative gap, which is below the linear slop. With `e = 1` the
//! flight's energy is kept to rounding (tests: apex drift under 0.01 % in
//! a minute). When other forces act during the substep (other contacts),
//! `a_n` ignores them and the instant is off by their share of the
//! substep's velocity change: first order in `h`, as for the rest of the
//! integrator. A bounce that reaches a spring-moved body is not re-timed
//! here: it is solved with the springs, which must see its motion
//! (`crate::constraints`, "Springs and contacts", 4.), and leaves the
//! candidates. Between two dynamic bodies of equal gravity scale the
//! motion is linear and the method is exact. A bounce through resting
//! contacts (a ball on a crate on the ground, a striker into a touching
//! row) is exact in the same sense: the touching contacts transmit it
//! rigidly (tests: `tests/contacts_bounce_transmitted.rs`, the crate's
//! rebound equals the ground's within the sampling error; a row leaves as
//! one body with the relative velocity `e·u`, energy kept for `e = 1`).

use super::block_solve::{BlockScratch, MAX_BLOCK, solve_group_velocities};
use super::row::{ContactConstraint, solve_normal_row};
use super::row_groups::{GroupSolve, RowGroups};
use super::sparse_solve::solve_sparse_velocities;
use super::tree_solve::{TreeScratch, solve_tree_velocities};
use crate::math::{Scalar, Vec2, WideScalar};

/// A contact row that met this substep faster than the restitution
/// threshold: what the bounce needs besides the row.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct BounceCandidate<S: Scalar> {
    /// Index of the row in the substep's contact rows.
    pub(crate) row: u32,
    /// Relative normal velocity the solver started from (`v_n`, < 0).
    pub(crate) approach: S,
    /// Gravity's acceleration of body `a` (zero for a body gravity does
    /// not move).
    pub(crate) accel_a: Vec2<S>,
    /// Gravity's acceleration of body `b`.
    pub(crate) accel_b: Vec2<S>,
    /// Combined restitution, > 0.
    pub(crate) restitution: S,
}

/// A body a bounce moved: the start of its rebound motion, for the rebound
/// sweep (`World::sweep_rebounds`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Rebound<S: Scalar> {
    /// The body's slot.
    pub(crate) slot: u32,
    /// Its displacement before the bounce moved it (the rebound starts
    /// there).
    pub(crate) start: Vec2<S>,
    /// The instant of the bounce within the substep (`τ`, in `[0, h]`):
    /// the rebound motion covers `h − τ`.
    pub(crate) time: S,
    /// Its place in the list as pushed (set by the sweep, for its sort).
    pub(crate) order: u32,
}

/// The normal velocity and gap a bounce leaves at the end of the substep.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct BounceEnd<S: Scalar> {
    /// Relative normal velocity at the end (`w + a_n (h/2 − τ)`).
    pub(crate) velocity: S,
    /// Gap at the end (`w·r + a_n r²/2`, at least zero).
    pub(crate) gap: S,
    /// The launch speed `w = e·|u_c|`.
    pub(crate) launch: S,
}

/// Steps 1 and 2 of the module notes for a gap `s0` (negative values count
/// as touching), start velocity `approach` (`v_n`), acceleration `accel_n`
/// and restitution `e`, over a substep `h`. `None` when the pair would not
/// meet within the substep on its parabola (the linear prediction that
/// made it a candidate was off by the curvature).
pub(crate) fn bounce_end<S: Scalar>(
    s0: S,
    approach: S,
    accel_n: S,
    e: S,
    h: S,
) -> Option<BounceEnd<S>> {
    let s0 = s0.max(S::ZERO);
    // u₀ = v_n − a_n h/2: the relative normal velocity at the substep's start.
    let u0 = approach.sub(accel_n.mul(h).half());
    // u_c² = u₀² − 2 a_n s₀ (wide: exact products).
    let disc = u0.wide_mul(u0).sub(accel_n.mul_int(2).wide_mul(s0));
    if disc.is_negative() {
        return None;
    }
    let closing = disc.sqrt_narrow(); // −u_c ≥ 0
    let tau = if s0.is_positive() {
        // τ = 2 s₀ / (−u₀ − u_c) = 2 s₀ / (closing − u₀). The denominator is
        // positive whenever the pair meets: closing ≥ |u₀| when a_n ≤ 0;
        // when a_n > 0 meeting needs u₀ < 0. Refuse a τ beyond h without
        // dividing (2 s₀ > h·den ⇒ τ > h), which also covers den ≤ 0.
        let den = closing.sub(u0);
        let twice = s0.mul_int(2);
        if !den.is_positive() || S::Wide::from_narrow(twice) > h.wide_mul(den) {
            return None;
        }
        twice.div(den)
    } else {
        S::ZERO
    };
    // Launch speed w = e·|u_c|; the rest of the substep on the reflected
    // parabola.
    let launch = e.mul(closing);
    let rest = h.sub(tau);
    let gap = launch
        .mul(rest)
        .add(accel_n.mul(rest).mul(rest).half())
        .max(S::ZERO);
    let velocity = launch.add(accel_n.mul(h.half().sub(tau)));
    Some(BounceEnd {
        velocity,
        gap,
        launch,
    })
}

/// One row's bounce, found by [`apply_bounces`]: what the bounce solve
/// drives the row to.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Launch<S: Scalar> {
    /// Relative normal velocity the row must leave with (step 2's end
    /// velocity).
    velocity: S,
    /// Rest of the substep the bodies fly after the impact, as the ratio
    /// of the end gap's change to the end velocity's change (`≈ h − τ`,
    /// within `[0, h]`): the displacement a velocity change adds.
    flight: S,
    /// The end gap (step 2), for the row-by-row bounce of large groups.
    gap: S,
    /// The launch speed `w`, likewise.
    launch: S,
    /// The approach `|v_n|` the re-timing started from, likewise.
    approach: S,
}

/// Working memory of [`apply_bounces`], reused from substep to substep.
///
/// The per-row and per-slot maps hold [`NONE`] everywhere between calls:
/// a call sets only its candidates' entries and resets them before it
/// returns, so a substep costs what its candidates and their groups hold,
/// not what the scene holds.
#[derive(Clone, Debug, Default)]
pub(crate) struct BounceScratch<S: Scalar> {
    /// The launches found this substep (indexed by `row_launch`).
    launches: Vec<Launch<S>>,
    /// Per contact row: its index in `launches`, [`MARKED`] for a
    /// candidate that did not launch, else [`NONE`].
    row_launch: Vec<u32>,
    /// The accelerations bouncing bodies have before their impacts
    /// (gravity, less what resting contacts hold), indexed by `slot_accel`.
    accels: Vec<Vec2<S>>,
    /// Per slot: its index in `accels` if it bounces, else [`NONE`].
    slot_accel: Vec<u32>,
    /// A group's movable bodies (slot, velocity before the bounce solve),
    /// sorted by slot, each once.
    before: Vec<(u32, Vec2<S>)>,
    /// A group's rows' normal impulses and targets before the bounce solve.
    saved: Vec<(S, S)>,
    /// A group's rows that take part in the bounce solve.
    participants: Vec<usize>,
    /// The groups holding a candidate row, ascending.
    groups: Vec<usize>,
}

/// No entry in a [`BounceScratch`] map.
const NONE: u32 = u32::MAX;
/// A candidate row that has no launch (yet): never a support.
const MARKED: u32 = u32::MAX - 1;

impl<S: Scalar> BounceScratch<S> {
    /// Row `ri`'s launch, if it bounces this substep.
    fn launch(&self, ri: usize) -> Option<Launch<S>> {
        let k = *self.row_launch.get(ri)?;
        self.launches.get(k as usize).copied()
    }

    /// Slot `slot`'s acceleration before its impact (zero unless it
    /// bounces).
    fn accel(&self, slot: u32) -> Option<Vec2<S>> {
        let k = *self.slot_accel.get(slot as usize)?;
        self.accels.get(k as usize).copied()
    }

    /// Puts the per-row and per-slot maps back to [`NONE`] (only the
    /// entries the candidates set).
    fn reset(&mut self, rows: &[ContactConstraint<S>], candidates: &[BounceCandidate<S>]) {
        for candidate in candidates {
            if let Some(entry) = self.row_launch.get_mut(candidate.row as usize) {
                *entry = NONE;
            }
            if let Some(c) = rows.get(candidate.row as usize) {
                for slot in [c.a, c.b] {
                    if let Some(entry) = self.slot_accel.get_mut(slot as usize) {
                        *entry = NONE;
                    }
                }
            }
        }
        self.launches.clear();
        self.accels.clear();
    }
}

/// Grows `map` to `len` entries of [`NONE`] (with room for twice as many,
/// so a scene growing after the warm-up does not allocate at every step).
fn grow_map(map: &mut Vec<u32>, len: usize) {
    if map.len() < len {
        map.reserve(len.saturating_mul(2).saturating_sub(map.len()));
        map.resize(len, NONE);
    }
}

/// How the bounce solve treats a group: how the sweeps solve it and how
/// many sweeps they take (see [`apply_bounces`]).
pub(crate) struct BounceSolver<'a, S: Scalar> {
    /// The contact groups, classified for this substep.
    pub(crate) groups: &'a RowGroups,
    /// Sweeps over a group solved by sequential impulses (the world's
    /// velocity iterations; the exact solves need one).
    pub(crate) sweeps: u32,
    /// The linear slop (the tree solve's touching test).
    pub(crate) slop: S,
    /// Block solver memory.
    pub(crate) block: &'a mut BlockScratch<S>,
    /// Tree solver memory.
    pub(crate) tree: &'a mut TreeScratch<S>,
}

/// Applies the bounces of this substep (step 3 of the module notes) to the
/// velocities and displacements, and reports every slot whose
/// displacement a bounce changed (`rebounds`: the slot and the
/// displacement it had before), for the rebound sweep.
///
/// # The bounce solve
///
/// The bounce of a pair is a velocity target, not an impulse of its own:
/// each group of rows (bodies joined by contacts) that holds a bouncing
/// row is solved once more, with the bouncing rows driven to their end
/// velocities `w + a_n (h/2 − τ)` and every other row to its speculative
/// bound (`v_n ≥ −s/h` at the current gap `s`, so a touching row does not
/// close), accumulated impulses ≥ 0, by the group's own solver (tree,
/// block or sequential impulses, as the velocity solve chose). So the
/// bounce's reaction goes where the contacts carry it: a ball bouncing on
/// a crate that rests on the ground leaves with `e·|u_c|` as from the
/// ground itself (the crate's row into the ground holds, the crate does
/// not move), whatever the crate's mass and however many crates the stack
/// has; a striker into a row of touching bodies leaves with the relative
/// velocity `e·u` to the row, which moves on as one body. Momentum is
/// kept (internal impulses; fixed bodies take the rest).
///
/// Energy: with one bouncing row in a group, the solve is Newton's law at
/// that row with the other rows as (unilateral) rigid links: a collision
/// along one direction with the group's effective mass, which returns
/// `e²` of the energy the impact took, never more. Several bouncing rows
/// solved together follow Newton's law at each (a ball on the seam of two
/// crates, in a corner); such simultaneous impacts of several free bodies
/// are not bounded in general (tests: the billiards crowd, the seam).
///
/// The displacement a bounce adds is the velocity change times the
/// flight after the impact (`≈ h − τ`; in a group, that of its earliest
/// impact), which for a single pair is exactly step 2's end gap.
///
/// The rows' accumulated impulses and targets are restored afterwards:
/// the contact cache warm-starts the next substep from the velocity
/// solve's impulses, as without a bounce.
#[allow(clippy::too_many_arguments)]
pub(crate) fn apply_bounces<S: Scalar>(
    rows: &mut [ContactConstraint<S>],
    candidates: &[BounceCandidate<S>],
    h: S,
    solver: BounceSolver<'_, S>,
    scratch: &mut BounceScratch<S>,
    velocities: &mut [Vec2<S>],
    displacements: &mut [Vec2<S>],
    rebounds: &mut Vec<Rebound<S>>,
) {
    // Grow the working memory with the scene, bounce or not, with the
    // same headroom as the rows' own buffers (twice the need), so a first
    // bounce after the warm-up allocates nothing.
    let (row_room, slot_room) = (rows.len().saturating_mul(2), velocities.len());
    grow_map(&mut scratch.row_launch, rows.len());
    grow_map(&mut scratch.slot_accel, velocities.len());
    scratch.participants.reserve(row_room);
    scratch.launches.reserve(row_room);
    scratch.saved.reserve(row_room);
    scratch.accels.reserve(slot_room);
    scratch.before.reserve(slot_room);
    if candidates.is_empty() {
        return;
    }
    // Only the groups holding a candidate are visited (a pile of thousands
    // of rows with one ball landing on it costs that ball's group).
    let mut group_list = core::mem::take(&mut scratch.groups);
    group_list.clear();
    group_list.extend(
        candidates
            .iter()
            .filter_map(|c| solver.groups.group_of_row(c.row as usize)),
    );
    group_list.sort_unstable();
    group_list.dedup();
    supported_accelerations(
        rows,
        candidates,
        solver.slop,
        displacements,
        (solver.groups, &group_list),
        scratch,
    );
    let mut any = false;
    for candidate in candidates {
        let Some(c) = rows.get(candidate.row as usize) else {
            continue;
        };
        // The row did nothing (the pair was already slowing or separating
        // without it): no contact happened, no bounce.
        if !c.normal_impulse.is_positive() {
            continue;
        }
        // Accelerations with the held parts taken out, and the approach
        // without the gravity step those parts did not take (a resting
        // crate's velocity before the solve is −g·h, its motion none).
        let accel = |slot: u32| scratch.accel(slot).unwrap_or(Vec2::ZERO);
        let (accel_a, accel_b) = (accel(c.a), accel(c.b));
        let accel_n = (accel_b - accel_a).dot(c.normal);
        let held = ((accel_b - candidate.accel_b) - (accel_a - candidate.accel_a)).dot(c.normal);
        let approach = candidate.approach.add(held.mul(h));
        let Some(end) = bounce_end(c.separation, approach, accel_n, candidate.restitution, h)
        else {
            continue;
        };
        let (ia, ib) = (c.a as usize, c.b as usize);
        let vn_now = (velocities[ib] - velocities[ia]).dot(c.normal);
        let dv = end.velocity.sub(vn_now);
        // Only pushes: a pair already separating faster is left alone.
        if !dv.is_positive() {
            continue;
        }
        let gap_now = c
            .separation
            .add((displacements[ib] - displacements[ia]).dot(c.normal));
        let ds = end.gap.sub(gap_now).max(S::ZERO);
        // flight = ds/dv within [0, h] (no division when it would exceed h).
        let flight = if ds >= dv.mul(h) { h } else { ds.div(dv) };
        let index = u32::try_from(scratch.launches.len()).unwrap_or(NONE);
        scratch.launches.push(Launch {
            velocity: end.velocity,
            flight,
            gap: end.gap,
            launch: end.launch,
            approach: approach.neg(),
        });
        scratch.row_launch[candidate.row as usize] = index;
        any = true;
    }
    if any {
        solve_bounce_groups(
            rows,
            h,
            solver,
            &group_list,
            scratch,
            velocities,
            displacements,
            rebounds,
        );
    }
    scratch.reset(rows, candidates);
    scratch.groups = group_list;
}

/// The bounce solve of every group in `group_list` holding a launch (see
/// [`apply_bounces`]).
#[allow(clippy::too_many_arguments)]
fn solve_bounce_groups<S: Scalar>(
    rows: &mut [ContactConstraint<S>],
    h: S,
    solver: BounceSolver<'_, S>,
    group_list: &[usize],
    scratch: &mut BounceScratch<S>,
    velocities: &mut [Vec2<S>],
    displacements: &mut [Vec2<S>],
    rebounds: &mut Vec<Rebound<S>>,
) {
    let BounceSolver {
        groups,
        sweeps,
        slop,
        block,
        tree,
    } = solver;
    // A target below any relative normal velocity (speeds are bounded by
    // the world's speed limit, 4096): a row apart never pushes.
    let free = S::from_int(-(1 << 16));
    for &g in group_list {
        let Some((group, solve)) = groups.group(g) else {
            continue;
        };
        let mut bouncing = false;
        let mut flight = S::ZERO;
        // A group whose rows all hold an immovable body (a body against
        // walls) has nothing to transmit.
        let mut against_walls = true;
        for &ri in group {
            if let Some(launch) = scratch.launch(ri) {
                bouncing = true;
                flight = flight.max(launch.flight);
            }
            let row = &rows[ri];
            if row.inverse_mass_a.is_positive() && row.inverse_mass_b.is_positive() {
                against_walls = false;
            }
        }
        if !bouncing {
            continue;
        }
        // Each bouncing row bounces on its own (`bounce_row`) in two kinds
        // of group. Against walls: the row's own end gap is exact per wall
        // (several walls in one substep, a room's corner, each keep their
        // own instant; the group's common flight would not). And a large
        // group left to sequential impulses (an even-mass pile): the sweeps
        // a whole pile would take for every ball landing on it cost as
        // much as the velocity solve.
        if against_walls || large_sequential(group, solve) {
            for &ri in group {
                if let Some(launch) = scratch.launch(ri) {
                    bounce_row(&rows[ri], launch, h, velocities, displacements, rebounds);
                }
            }
            continue;
        }
        // Targets: bouncing rows their end velocity; rows touching at the
        // end of the substep must not close (v_n ≥ 0); rows apart take no
        // part (impulse zero for the solve, a target no velocity reaches):
        // what a rebound meets beyond a gap is the rebound sweep's and the
        // next substep's business.
        scratch.saved.clear();
        scratch.participants.clear();
        for &ri in group {
            let launch = scratch.launch(ri);
            let row = &mut rows[ri];
            scratch
                .saved
                .push((row.normal_impulse, row.target_velocity));
            row.target_velocity = match launch {
                Some(launch) => launch.velocity,
                None => {
                    let gap = row.separation.add(
                        (displacements[row.b as usize] - displacements[row.a as usize])
                            .dot(row.normal),
                    );
                    if gap <= slop {
                        S::ZERO
                    } else {
                        row.normal_impulse = S::ZERO;
                        free
                    }
                }
            };
            if row.target_velocity != free {
                scratch.participants.push(ri);
            }
        }
        // The participants' movable bodies, each once; a body in two
        // participating rows is where a bounce is transmitted.
        scratch.before.clear();
        for &ri in &scratch.participants {
            let row = &rows[ri];
            push_movable(&mut scratch.before, row, velocities);
        }
        scratch.before.sort_unstable_by_key(|&(slot, _)| slot);
        let shared = scratch.before.windows(2).any(|w| w[0].0 == w[1].0);
        if !shared {
            // No body in two participating rows: each row is a pair alone,
            // and one row solve is exact for it (as the group's solve would
            // be). The shift takes the group's flight, as below.
            for &ri in &scratch.participants {
                let row = &mut rows[ri];
                let (ia, ib) = (row.a as usize, row.b as usize);
                let (va, vb) = (velocities[ia], velocities[ib]);
                solve_normal_row(row, velocities);
                let time = h.sub(flight);
                for (slot, v0) in [(row.a, va), (row.b, vb)] {
                    let i = slot as usize;
                    let change = velocities[i] - v0;
                    if change != Vec2::ZERO {
                        shift_body(
                            slot,
                            change.scale(flight),
                            time,
                            slop,
                            displacements,
                            rebounds,
                        );
                    }
                }
            }
            restore_rows(rows, group, &scratch.saved);
            continue;
        }
        // The group's own solver, except that groups the velocity solve
        // leaves to sequential impulses (even masses) take the exact block
        // solve when small: sequential impulses halve a bounce's error per
        // sweep through a crate on the ground (its reaction bounces between
        // the two rows), and the bounce must be exact.
        //
        // Groups the velocity solve takes by the sparse solve take it here
        // too, at any size: its refinement takes out what the
        // regularisation leaves, and the block solve's sweeps do not. A
        // heavy ball on a column of light circles on the ground is nearly
        // statically indeterminate (the ball's row, the column's and the
        // ground's carry one force; the scaled matrix's least eigenvalue
        // is about the ball's share of the inverse masses, λ), and the
        // block solve left the bounce short by `ε/(λ + ε)` of it: a ball
        // 100× a circle at 1 000 units/s left two columns of 3 at 991
        // units/s and the struck column moving down at 3, 6 and 9 units/s
        // (`tests/impacts_on_columns_side_by_side.rs`).
        match solve {
            _ if scratch.participants.len() <= MAX_BLOCK
                && matches!(solve, GroupSolve::Sequential | GroupSolve::Block) =>
            {
                // The block solve regularises its diagonal by 2⁻¹⁶; sweeps
                // of sequential impulses from its answer take that error
                // out (a single row is exact after one).
                solve_group_velocities(rows, &scratch.participants, velocities, None, block);
                // Until a sweep changes no impulse (the answer is then a
                // fixed point of the sweeps).
                for _ in 0..sweeps.max(1) {
                    let mut changed = false;
                    for &ri in &scratch.participants {
                        let old = rows[ri].normal_impulse;
                        solve_normal_row(&mut rows[ri], velocities);
                        changed |= rows[ri].normal_impulse != old;
                    }
                    if !changed {
                        break;
                    }
                }
            }
            GroupSolve::Tree(_) | GroupSolve::Trees(_) | GroupSolve::Sparse(_) => {
                // The tree solves take the whole group: every movable body
                // of it is watched for a change.
                for &ri in group {
                    push_movable(&mut scratch.before, &rows[ri], velocities);
                }
                scratch.before.sort_unstable_by_key(|&(slot, _)| slot);
                scratch.before.dedup_by_key(|&mut (slot, _)| slot);
                // Exact on the tree in one sweep; a second for the rows
                // off it (sequential impulses within the sweep). Several
                // covering trees: each in turn, as the velocity solve does.
                for _ in 0..sweeps.clamp(1, 2) {
                    match solve {
                        GroupSolve::Tree(range) => solve_tree_velocities(
                            rows,
                            group,
                            groups.plan(range),
                            velocities,
                            slop,
                            None,
                            None,
                            tree,
                        ),
                        GroupSolve::Trees(range) => {
                            for plan in groups.trees(range) {
                                solve_tree_velocities(
                                    rows,
                                    group,
                                    groups.plan(plan),
                                    velocities,
                                    slop,
                                    None,
                                    Some(groups.uncovered()),
                                    tree,
                                );
                            }
                        }
                        GroupSolve::Sparse(range) => solve_sparse_velocities(
                            rows,
                            group,
                            groups.sparse(range),
                            velocities,
                            &mut block.sparse,
                        ),
                        _ => {}
                    }
                }
            }
            _ => {
                for _ in 0..sweeps.max(1) {
                    for &ri in &scratch.participants {
                        solve_normal_row(&mut rows[ri], velocities);
                    }
                }
            }
        }
        restore_rows(rows, group, &scratch.saved);
        // Each body's velocity change gives the displacement it adds over
        // the flight (the group's earliest impact's).
        scratch.before.dedup_by_key(|&mut (slot, _)| slot);
        for &(slot, v0) in &scratch.before {
            let change = velocities[slot as usize] - v0;
            if change != Vec2::ZERO {
                shift_body(
                    slot,
                    change.scale(flight),
                    h.sub(flight),
                    slop,
                    displacements,
                    rebounds,
                );
            }
        }
    }
}

/// Whether a group is a large one the velocity solve leaves to
/// sequential impulses (an even-mass pile): its bounces are row by row.
fn large_sequential(group: &[usize], solve: &GroupSolve) -> bool {
    matches!(solve, GroupSolve::Sequential) && group.len() > MAX_BLOCK
}

/// Lists the movable bodies of `row` with their velocities.
fn push_movable<S: Scalar>(
    list: &mut Vec<(u32, Vec2<S>)>,
    row: &ContactConstraint<S>,
    velocities: &[Vec2<S>],
) {
    if row.inverse_mass_a.is_positive() {
        list.push((row.a, velocities[row.a as usize]));
    }
    if row.inverse_mass_b.is_positive() {
        list.push((row.b, velocities[row.b as usize]));
    }
}

/// Puts the rows' accumulated impulses and targets back as the velocity
/// solve left them (the contact cache warm-starts from them).
fn restore_rows<S: Scalar>(rows: &mut [ContactConstraint<S>], group: &[usize], saved: &[(S, S)]) {
    for (&ri, &(impulse, target)) in group.iter().zip(saved) {
        let row = &mut rows[ri];
        row.normal_impulse = impulse;
        row.target_velocity = target;
    }
}

/// Adds a bounce's displacement `shift` to a body; a shift beyond the
/// slop is listed for the rebound sweep (a rebound must not pass through
/// what lies behind; within the slop, an overlap it could make is one the
/// slop allows), from the bounce's instant `time`.
fn shift_body<S: Scalar>(
    slot: u32,
    shift: Vec2<S>,
    time: S,
    slop: S,
    displacements: &mut [Vec2<S>],
    rebounds: &mut Vec<Rebound<S>>,
) {
    let i = slot as usize;
    if shift.x.abs() > slop || shift.y.abs() > slop {
        rebounds.push(Rebound {
            slot,
            start: displacements[i],
            time,
            order: 0,
        });
    }
    displacements[i] += shift;
}

/// One row's bounce on its own, for a row of a large group left to
/// sequential impulses: the pair's relative normal velocity is raised to
/// the end velocity and its gap to the end gap (step 2) by one impulse
/// and one displacement along the normal, split by inverse mass. When
/// the row stopped only part of the approach (other rows took the rest:
/// simultaneous contacts), the launch is scaled by the share it stopped,
/// so row-by-row bounces never return more than the impacts took.
fn bounce_row<S: Scalar>(
    c: &ContactConstraint<S>,
    launch: Launch<S>,
    h: S,
    velocities: &mut [Vec2<S>],
    displacements: &mut [Vec2<S>],
    rebounds: &mut Vec<Rebound<S>>,
) {
    let (ia, ib) = (c.a as usize, c.b as usize);
    let vn_now = (velocities[ib] - velocities[ia]).dot(c.normal);
    // The share of the approach this row stopped: its impulse changed the
    // relative normal velocity by λ·(w_a + w_b), and what is still
    // closing, max(0, −v_n), it would stop too.
    let stopped = c
        .normal_impulse
        .mul(c.inverse_mass_a.add(c.inverse_mass_b))
        .add(vn_now.neg().max(S::ZERO));
    let end_velocity = if stopped >= launch.approach || !launch.approach.is_positive() {
        launch.velocity
    } else {
        let share = stopped.div(launch.approach);
        launch.velocity.sub(launch.launch.mul(S::ONE.sub(share)))
    };
    let dv = end_velocity.sub(vn_now);
    if !dv.is_positive() {
        return;
    }
    let gap_now = c
        .separation
        .add((displacements[ib] - displacements[ia]).dot(c.normal));
    let ds = launch.gap.sub(gap_now).max(S::ZERO);
    // Impulse and displacement "impulse": P = Δ·m, body change w·n·P.
    let impulse = dv.mul(c.effective_mass);
    let shift = ds.mul(c.effective_mass);
    let time = h.sub(launch.flight);
    if c.inverse_mass_a.is_positive() {
        if shift != S::ZERO {
            rebounds.push(Rebound {
                slot: c.a,
                start: displacements[ia],
                time,
                order: 0,
            });
        }
        velocities[ia] -= c.push_a.scale(impulse);
        displacements[ia] -= c.push_a.scale(shift);
    }
    if c.inverse_mass_b.is_positive() {
        if shift != S::ZERO {
            rebounds.push(Rebound {
                slot: c.b,
                start: displacements[ib],
                time,
                order: 0,
            });
        }
        velocities[ib] += c.push_b.scale(impulse);
        displacements[ib] += c.push_b.scale(shift);
    }
}

/// Each bouncing body's acceleration before its impact, into
/// `scratch.accels` (indexed by `scratch.slot_accel`; bodies that do not
/// bounce have none); marks the candidate rows ([`MARKED`]).
///
/// The re-timing (step 1 of the module notes) follows each body on its
/// free-flight parabola up to the impact. A body resting on another (a
/// crate on the ground) is not in free flight: the contact below it holds
/// it, so along that contact's normal it does not accelerate. So each
/// touching row (within the slop at the end of the substep) that carries
/// a push and does not bounce itself removes from each of its bodies'
/// gravity the component into the row (`a −= n·(n·a)` when `n·a` points
/// into the surface): a crate on flat ground has no acceleration, a box
/// on a slope keeps the part along the slope. A ball bouncing off a
/// resting crate is then re-timed exactly as off the ground itself.
fn supported_accelerations<S: Scalar>(
    rows: &[ContactConstraint<S>],
    candidates: &[BounceCandidate<S>],
    slop: S,
    displacements: &[Vec2<S>],
    (groups, group_list): (&RowGroups, &[usize]),
    scratch: &mut BounceScratch<S>,
) {
    scratch.launches.clear();
    scratch.accels.clear();
    // Mark the bouncing rows so they are not taken as supports.
    for candidate in candidates {
        let Some(c) = rows.get(candidate.row as usize) else {
            continue;
        };
        scratch.row_launch[candidate.row as usize] = MARKED;
        for (slot, accel) in [(c.a, candidate.accel_a), (c.b, candidate.accel_b)] {
            let entry = &mut scratch.slot_accel[slot as usize];
            if *entry == NONE {
                *entry = u32::try_from(scratch.accels.len()).unwrap_or(NONE);
                scratch.accels.push(accel);
            }
        }
    }
    // A body's rows are all in its group: the candidates' groups hold
    // every support of a bouncing body.
    // Large piles left to sequential impulses bounce row by row from free
    // flight (see [`apply_bounces`]) and are not scanned.
    let group_rows = group_list
        .iter()
        .filter_map(|&g| groups.group(g))
        .filter(|&(group, solve)| !large_sequential(group, solve))
        .flat_map(|(group, _)| group.iter().copied());
    for ri in group_rows {
        let row = &rows[ri];
        let (ka, kb) = (
            scratch.slot_accel[row.a as usize],
            scratch.slot_accel[row.b as usize],
        );
        if scratch.row_launch[ri] != NONE
            || !row.normal_impulse.is_positive()
            || (ka == NONE && kb == NONE)
        {
            continue;
        }
        let gap = row
            .separation
            .add((displacements[row.b as usize] - displacements[row.a as usize]).dot(row.normal));
        if gap > slop {
            continue;
        }
        // The row pushes b along +n and a along −n.
        for (k, n) in [(ka, -row.normal), (kb, row.normal)] {
            if let Some(a) = scratch.accels.get_mut(k as usize) {
                let into = a.dot(n);
                if into.is_negative() {
                    *a -= n.scale(into);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Fx;

    fn f(x: f64) -> Fx {
        Fx::from_f64(x)
    }

    /// A ball falling under g = 10 onto the ground: the end state is the
    /// one of the two exact parabolas meeting at the surface.
    #[test]
    fn bounce_under_gravity_matches_the_parabolas() {
        let h = 1.0 / 60.0;
        for (s0, v1, e) in [(0.05, -6.0, 1.0), (0.001, -3.0, 0.5), (0.09, -10.0, 0.8)] {
            let end = bounce_end(f(s0), f(v1), f(-10.0), f(e), f(h)).unwrap();
            // Reference in f64.
            let u0: f64 = v1 + 10.0 * h / 2.0;
            let uc = -(u0 * u0 + 2.0 * 10.0 * s0).sqrt();
            let tau = 2.0 * s0 / -(u0 + uc);
            // The incoming parabola is at the surface at τ.
            assert!((s0 + u0 * tau - 5.0 * tau * tau).abs() < 1e-9);
            let w = -e * uc;
            let r = h - tau;
            let gap = w * r - 5.0 * r * r;
            let vel = w - 10.0 * (h / 2.0 - tau);
            assert!((end.gap.to_f64() - gap).abs() < 1e-7, "{end:?} vs {gap}");
            assert!(
                (end.velocity.to_f64() - vel).abs() < 1e-7,
                "{end:?} vs {vel}"
            );
        }
    }

    /// Without relative acceleration the motion is linear: τ = s₀/|v|,
    /// end gap e·|v|·(h − τ).
    #[test]
    fn bounce_without_gravity_is_linear() {
        let end = bounce_end(f(0.25), f(-30.0), Fx::ZERO, f(1.0), f(0.05)).unwrap();
        assert!((end.velocity.to_f64() - 30.0).abs() < 1e-7);
        assert!((end.gap.to_f64() - 30.0 * (0.05 - 0.25 / 30.0)).abs() < 1e-7);
    }

    /// A pair decelerating towards each other that stops short does not
    /// bounce.
    #[test]
    fn no_bounce_when_the_parabola_stops_short() {
        // u₀ = −1.5, u₀² − 2·50·0.1 < 0.
        assert_eq!(bounce_end(f(0.1), f(-1.0), f(50.0), f(1.0), f(0.02)), None);
    }
}
