//! Phase "energy guard" (around the velocity iterations): a contact group
//! solved on covering trees, or a group holding ropes and contacts, never
//! leaves the solve with more kinetic energy than it came with, nor with
//! a body thrown through its neighbours.
//!
//! Why: a cyclic group of uneven masses above the block solver's size is
//! solved on a few spanning trees that together cover its rows, one after
//! another in every sweep, each tree exactly with the other trees'
//! impulses held (`RowGroups::classify`). That block Gauss–Seidel is not
//! a descent of anything and can run away: in a closed box of 200 bodies
//! at g 100 with every tenth 1000× heavier, a light box resting on the
//! floor left one velocity solve at 147 units/s and crossed 2.4 units of
//! the pile in one tick, through the bodies it had rows with.
//!
//! The bound it breaks. With every target `b ≤ 0` (a group holding a
//! bounce is solved by sequential impulses, `RowGroups::classify`) and no
//! moving immovable body, the solve's velocities are
//! `v = v₀ + M⁻¹·Jᵀ·λ`, `λ ≥ 0`, so
//!
//! ```text
//! ½·|v|²_M = ½·|v₀|²_M + f(λ) + λ·b,   f(λ) = ½·λᵀ·A·λ + λ·(J·v₀ − b),  A = J·M⁻¹·Jᵀ
//! ```
//!
//! `λ·b ≤ 0`, and sequential impulses started from `λ = 0` lower `f` with
//! every normal update (each is the exact minimum along its row with
//! `λ_i ≥ 0`), so `f ≤ f(0) = 0`: the energy never rises above its start
//! (the exact solution, the minimum of `f`, neither). Friction updates are
//! minima along their rows within the bound of the moment; a bound that
//! shrinks clamps an impulse, which bounds the friction's work by the
//! normal impulse it follows, and the engine's ordinary sweeps have always
//! lived with that.
//!
//! Two more bounds follow from the same solve: the exact solution holds
//! every row at its target, so no row closes beyond it, and the sweeps
//! that approach it move each body by the impulses of its own rows, which
//! hold it back. The scheme that ran away broke these far more plainly
//! than the energy (a light body's kinetic energy is small beside a heavy
//! pile's): the box above left at 147 units/s with bodies before the solve
//! at most about 20 (the heavy ones falling at g 100), and its row with the
//! body it crossed closed at 45 units/s where the target allowed none. So
//! a group is also caught when a body leaves faster than twice the fastest
//! body came in (`|v_x| + |v_y|`, no root), or a row closes beyond its
//! target by more than that (no row closed faster before:
//! `|n·(v_b − v_a)| ≤ |v_a| + |v_b|`). Both are far above what sweeps
//! that converge leave (a fraction of the approach speed), so a group
//! that meets them is not touched.
//!
//! What: before the warm start, the velocities of the groups solved on
//! covering trees are kept (`v₀`); after the sweeps each such group with
//! no moving immovable body is checked: `E = Σ m·|v|²` above
//! `E₀·(1 + 2⁻¹⁰)` (fixed-point rounding of the sums stays far below
//! that), or a body or a row past the speed bound above, and it is reset
//! to `v₀` with its impulses at zero and solved by sequential impulses
//! from there, as many sweeps as the velocity iterations. A group within
//! the bounds is left exactly as the trees solved it, so the scenes the
//! guard does not catch are bit-identical to the solve without it (the
//! shipped scenes and every golden).
//!
//! # Ropes and contacts
//!
//! A group holding ropes and contacts (`world::step::solve`, "Ropes and
//! contacts in one group") is solved on a spanning tree of its rows, the
//! rows off the tree by sequential impulses after it. Warm-started off
//! the tree, a row keeps last substep's impulse against everything the
//! exact solve does: a 10-link chain stacked upright and dropped, its end
//! 10⁴ times a link, lands on the pile its light links make above the
//! anchor; a contact between two links in that pile carried the end's
//! load (an impulse of 214 per tick). When the pile shifted, that contact
//! kept its 214 while the contacts around it lost theirs, the tree held it
//! with the slack rope between the same two links (a rope 0.08 slack and a
//! touching contact, each at 214, pulling and pushing one pair), the
//! rope's sideways stiffness was raised from that impulse, and the links
//! left the solve at 190 units/s: ropes 345 % long for the tick. With
//! twice the links or a 3·10⁴ end they reached `max_speed`, and a 20-link
//! chain at 10⁴ with two substeps stretched 3.6·10⁵ times its length.
//!
//! The bound is the same as above: rope rows are rows with `λ ≥ 0` and
//! targets ≤ 0 like contacts (a rope is the contact rule on its slack), a
//! rope's sideways row is a backward-Euler damper (it only takes energy),
//! so `½|v|²_M` of a converged solve never exceeds its start, and no row
//! of it closes beyond its target. The speed bound of the contact groups
//! is not used here: a rope levers a heavy body's motion into light links
//! legitimately (a ladder of ropes under a 100× body, released at rest,
//! swings light links faster than twice `g·h` in its first tick). A group
//! past the bound is solved again the same way, cold, from `v₀` (the warm
//! start was the fault); if that is still past it (3 substeps of 58 in a
//! family of 144 dropped chains), by sequential impulses from `v₀`, which
//! cannot be. The position pass and the rope settling rounds then hold
//! the ropes' lengths (`tests/chains_falling_onto_themselves.rs`: 9 of 210
//! chains came apart before, none now).

use super::solve::{raise_rope_velocity_side_stiffness, solve_one_group_velocities};
use crate::math::{Scalar, Vec2, WideScalar};
use crate::solver::StepContext;
use crate::solver::row::{ContactConstraint, solve_velocity_row};
use crate::solver::row_groups::GroupSolve;
use crate::solver::tree_solve::SideRows;
use crate::world::{Slot, World};

/// Whether the joint-group guard checks `group` (rows ascending, the
/// `ropes` rope rows first): it holds ropes and contacts, and is solved
/// directly (a group holding a bounce is solved by sequential impulses and
/// may send a light body off at twice the speed of what struck it).
fn joint_group_is_guarded(group: &[usize], solve: &GroupSolve, ropes: usize) -> bool {
    !matches!(solve, GroupSolve::Sequential)
        && group.first().is_some_and(|&ri| ri < ropes)
        && group.last().is_some_and(|&ri| ri >= ropes)
}

impl<S: Scalar> World<S> {
    /// Keeps the velocities before the warm start (`v₀`) when a contact
    /// group is solved on covering trees; clears them otherwise.
    pub(super) fn remember_velocities_before_solve(&mut self) {
        let context = &mut self.step_context;
        context.velocities_before_solve.clear();
        // The guard runs on the contact groups, solved alone when no rope
        // is active (ropes join them into the joint groups).
        let ropes = context.rope_rows.len();
        let any = if ropes == 0 {
            context
                .contact_groups
                .iter_classified()
                .any(|(_, velocity, _)| {
                    matches!(velocity, GroupSolve::Trees(_) | GroupSolve::Sparse(_))
                })
        } else {
            context
                .joint_groups
                .iter_classified()
                .any(|(group, velocity, _)| joint_group_is_guarded(group, velocity, ropes))
        };
        if any {
            context
                .velocities_before_solve
                .extend_from_slice(&context.velocities);
        }
    }

    /// The guard (see the module docs): each covering-tree group that
    /// gained energy in the sweeps, or sent a body or a row past the speed
    /// bound, is solved again by sequential impulses from `v₀`.
    pub(super) fn guard_covering_tree_energy(&mut self) {
        if self.step_context.velocities_before_solve.is_empty() {
            return;
        }
        let iterations = self.settings.velocity_iterations;
        let StepContext {
            constraints,
            contact_groups,
            velocities,
            velocities_before_solve: before,
            energy_marks,
            ..
        } = &mut self.step_context;
        energy_marks.clear();
        energy_marks.resize(velocities.len(), u32::MAX);
        let slots = &self.slots;
        for (g, (group, velocity, _)) in contact_groups.iter_classified().enumerate() {
            if !matches!(velocity, GroupSolve::Trees(_) | GroupSolve::Sparse(_)) {
                continue;
            }
            let stamp = u32::try_from(g).unwrap_or(u32::MAX - 1);
            let motion = measure_group(
                constraints,
                group,
                slots,
                before,
                velocities,
                energy_marks,
                stamp,
            );
            if motion.pushed_by_motion {
                continue;
            }
            if !motion.gained_energy()
                && motion.fastest_after <= motion.speed_limit()
                && !motion.row_driven()
            {
                continue;
            }
            reset_group(constraints, group, velocities, before, 0, &mut []);
            for _ in 0..iterations {
                for &ri in group {
                    solve_velocity_row(&mut constraints[ri], velocities);
                }
            }
        }
    }

    /// The guard of groups holding ropes and contacts (module notes,
    /// "Ropes and contacts"): a group whose solve gained kinetic energy,
    /// or left a row closing far beyond its target, is solved again the
    /// same way from `v₀`, cold (every impulse of the group at zero, its
    /// ropes' sideways stiffness as it was before the iterations raised
    /// it); if that is still past the bounds, by sequential impulses from
    /// `v₀` (`h`: the substep).
    pub(super) fn guard_joint_groups(&mut self, h: S) {
        if self.step_context.velocities_before_solve.is_empty() {
            return;
        }
        let (iterations, slop) = (self.settings.velocity_iterations, self.settings.linear_slop);
        let StepContext {
            joint_rows,
            joint_groups,
            velocities,
            velocities_before_solve: before,
            energy_marks,
            rope_rows,
            rope_geometry,
            rope_velocity_side,
            rope_velocity_side_start,
            rope_side_impulse,
            rope_block,
            tree,
            ..
        } = &mut self.step_context;
        energy_marks.clear();
        energy_marks.resize(velocities.len(), u32::MAX);
        let slots = &self.slots;
        let ropes = rope_rows.len();
        let mut stamp = 0u32;
        // The contact guard's speed bound on bodies is not used here (module
        // notes, "Ropes and contacts").
        let mut past_bounds = |rows: &[ContactConstraint<S>],
                               group: &[usize],
                               velocities: &[Vec2<S>]| {
            stamp = stamp.wrapping_add(1);
            let motion = measure_group(rows, group, slots, before, velocities, energy_marks, stamp);
            motion.gained_energy() || motion.row_driven()
        };
        for (group, solve, _) in joint_groups.iter_classified() {
            if !joint_group_is_guarded(group, solve, ropes)
                || !past_bounds(joint_rows, group, velocities)
            {
                continue;
            }
            reset_group(
                joint_rows,
                group,
                velocities,
                before,
                ropes,
                rope_side_impulse,
            );
            for &ri in group.iter().take_while(|&&ri| ri < ropes) {
                rope_velocity_side[ri] = rope_velocity_side_start[ri];
            }
            for iteration in 0..iterations {
                if iteration > 0 {
                    raise_rope_velocity_side_stiffness(
                        &joint_rows[..ropes],
                        rope_geometry,
                        h,
                        rope_velocity_side,
                    );
                }
                let side = SideRows {
                    stiffness: rope_velocity_side,
                    accumulated: rope_side_impulse,
                };
                solve_one_group_velocities(
                    joint_rows,
                    joint_groups,
                    (group, solve),
                    velocities,
                    slop,
                    Some(side),
                    rope_block,
                    tree,
                );
            }
            if !past_bounds(joint_rows, group, velocities) {
                continue;
            }
            reset_group(
                joint_rows,
                group,
                velocities,
                before,
                ropes,
                rope_side_impulse,
            );
            for _ in 0..iterations {
                for &ri in group {
                    solve_velocity_row(&mut joint_rows[ri], velocities);
                }
            }
        }
    }
}

/// What the guards measure of one group after its solve, in one pass
/// over its rows (module notes: the bounds a converged solve meets).
struct GroupMotion<S: Scalar> {
    /// `Σ m·|v₀|²` over the group's movable bodies, before the warm start.
    energy_before: S::Wide,
    /// `Σ m·|v|²` after the solve.
    energy_after: S::Wide,
    /// The fastest movable body before the solve, `|v_x| + |v_y|` (≥ |v|).
    fastest_before: S,
    /// The fastest movable body after it, measured the same way.
    fastest_after: S,
    /// The most any row closes beyond its target, `max(b − n·(v_b − v_a))`
    /// (`S::MIN` for an empty group).
    deepest_overshoot: S,
    /// Whether an immovable body of the group moves (it can feed energy in).
    pushed_by_motion: bool,
}

impl<S: Scalar> GroupMotion<S> {
    /// The energy bound: no more than `E₀·(1 + 2⁻¹⁰)` (the fixed-point
    /// rounding of the sums stays far below the allowance).
    fn gained_energy(&self) -> bool {
        let allowance = self.energy_before.narrow().mul(S::from_ratio(1, 1024));
        self.energy_after > self.energy_before.add(S::Wide::from_narrow(allowance))
    }

    /// Twice the fastest body before the solve: no row closed faster than
    /// `2·fastest` then (`|n·(v_b − v_a)| ≤ |v_a| + |v_b|`).
    fn speed_limit(&self) -> S {
        self.fastest_before.add(self.fastest_before)
    }

    /// Whether a row was left closing beyond its target by more than the
    /// speed limit: driven, not held.
    fn row_driven(&self) -> bool {
        self.deepest_overshoot > self.speed_limit()
    }
}

/// Measures `group` (rows of `rows`) for the guards: every movable body is
/// counted once, marked in `marks` with `stamp` (a stamp no other group of
/// this pass uses).
fn measure_group<S: Scalar>(
    rows: &[ContactConstraint<S>],
    group: &[usize],
    slots: &[Slot<S>],
    before: &[Vec2<S>],
    velocities: &[Vec2<S>],
    marks: &mut [u32],
    stamp: u32,
) -> GroupMotion<S> {
    let mut motion = GroupMotion {
        energy_before: S::Wide::ZERO,
        energy_after: S::Wide::ZERO,
        fastest_before: S::ZERO,
        fastest_after: S::ZERO,
        deepest_overshoot: S::MIN,
        pushed_by_motion: false,
    };
    for &ri in group {
        let row = &rows[ri];
        let vn = (velocities[row.b as usize] - velocities[row.a as usize]).dot(row.normal);
        motion.deepest_overshoot = motion.deepest_overshoot.max(row.target_velocity.sub(vn));
        for (slot, inverse_mass) in [
            (row.a as usize, row.inverse_mass_a),
            (row.b as usize, row.inverse_mass_b),
        ] {
            if !inverse_mass.is_positive() {
                motion.pushed_by_motion |= before[slot] != Vec2::ZERO;
                continue;
            }
            if marks[slot] == stamp {
                continue;
            }
            marks[slot] = stamp;
            let Some(body) = slots[slot].body.as_ref() else {
                continue;
            };
            let (v0, v) = (before[slot], velocities[slot]);
            motion.fastest_before = motion.fastest_before.max(v0.x.abs().add(v0.y.abs()));
            motion.fastest_after = motion.fastest_after.max(v.x.abs().add(v.y.abs()));
            motion.energy_before = motion.energy_before.add(body.mass.wide_mul(v0.dot(v0)));
            motion.energy_after = motion.energy_after.add(body.mass.wide_mul(v.dot(v)));
        }
    }
    motion
}

/// Puts `group`'s movable bodies back to their velocities `before` the
/// solve, and every impulse of its rows (normal, friction, a rope's
/// sideways impulse) to zero.
fn reset_group<S: Scalar>(
    rows: &mut [ContactConstraint<S>],
    group: &[usize],
    velocities: &mut [Vec2<S>],
    before: &[Vec2<S>],
    ropes: usize,
    rope_side_impulse: &mut [S],
) {
    for &ri in group {
        let row = &mut rows[ri];
        row.normal_impulse = S::ZERO;
        row.tangent_impulse = S::ZERO;
        for (slot, inverse_mass) in [
            (row.a as usize, row.inverse_mass_a),
            (row.b as usize, row.inverse_mass_b),
        ] {
            if inverse_mass.is_positive() {
                velocities[slot] = before[slot];
            }
        }
        if ri < ropes {
            rope_side_impulse[ri] = S::ZERO;
        }
    }
}
