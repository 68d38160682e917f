//! Phase "energy guard" (around the velocity iterations): a contact group
//! solved on covering trees never leaves the solve with more kinetic
//! energy than it came with, nor with a body thrown through its
//! neighbours.
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

use crate::math::{Scalar, Vec2, WideScalar};
use crate::solver::StepContext;
use crate::solver::row::solve_velocity_row;
use crate::solver::row_groups::GroupSolve;
use crate::world::World;

impl<S: Scalar> World<S> {
    /// Keeps the velocities before the warm start (`v₀`) when a contact
    /// group is solved on covering trees; clears them otherwise.
    pub(super) fn remember_velocities_before_solve(&mut self) {
        let context = &mut self.step_context;
        context.velocities_before_solve.clear();
        // The guard runs on the contact groups, solved alone when no rope
        // is active (ropes join them into the joint groups).
        let any = context.rope_rows.is_empty()
            && context
                .contact_groups
                .iter_classified()
                .any(|(_, velocity, _)| {
                    matches!(velocity, GroupSolve::Trees(_) | GroupSolve::Sparse(_))
                });
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
            let (mut start, mut end) = (S::Wide::ZERO, S::Wide::ZERO);
            // The fastest body before the solve, `|v_x| + |v_y|` (≥ |v|).
            let mut fastest = S::ZERO;
            // The fastest body after it.
            let mut fastest_after = S::ZERO;
            let mut pushed_by_motion = false;
            for &ri in group {
                let row = &constraints[ri];
                for (slot, inverse_mass) in [
                    (row.a as usize, row.inverse_mass_a),
                    (row.b as usize, row.inverse_mass_b),
                ] {
                    if !inverse_mass.is_positive() {
                        // An immovable body that moves can feed the group.
                        pushed_by_motion |= before[slot] != Vec2::ZERO;
                        continue;
                    }
                    if energy_marks[slot] == stamp {
                        continue;
                    }
                    energy_marks[slot] = stamp;
                    let Some(body) = slots[slot].body.as_ref() else {
                        continue;
                    };
                    let (v0, v) = (before[slot], velocities[slot]);
                    fastest = fastest.max(v0.x.abs().add(v0.y.abs()));
                    fastest_after = fastest_after.max(v.x.abs().add(v.y.abs()));
                    start = start.add(body.mass.wide_mul(v0.dot(v0)));
                    end = end.add(body.mass.wide_mul(v.dot(v)));
                }
            }
            if pushed_by_motion {
                continue;
            }
            let allowance = start.narrow().mul(S::from_ratio(1, 1024));
            let gained = end > start.add(S::Wide::from_narrow(allowance));
            let limit = fastest.add(fastest);
            // No row closed faster than `2·fastest` before the solve
            // (`|n·(v_b − v_a)| ≤ |v_a| + |v_b|`); one left closing that
            // much beyond its target was driven, not held.
            let driven = || {
                group.iter().any(|&ri| {
                    let row = &constraints[ri];
                    let vn =
                        (velocities[row.b as usize] - velocities[row.a as usize]).dot(row.normal);
                    row.target_velocity.sub(vn) > limit
                })
            };
            if !gained && fastest_after <= limit && !driven() {
                continue;
            }
            for &ri in group {
                let row = &mut constraints[ri];
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
            }
            for _ in 0..iterations {
                for &ri in group {
                    solve_velocity_row(&mut constraints[ri], velocities);
                }
            }
        }
    }
}
