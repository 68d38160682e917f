//! Phases "solve velocities" and "solve positions": rows grouped by shared
//! bodies and warm-started, then velocity iterations (before integrating)
//! and position iterations (after), each group directly (block solve) or by
//! sequential impulses ([`crate::solver`]).

use super::constraints::relinearise_rope_rows;
use crate::math::{Scalar, Vec2};
use crate::solver::StepContext;
use crate::solver::block_solve::{BlockScratch, solve_group_positions, solve_group_velocities};
use crate::solver::row::{
    ContactConstraint, solve_friction_row, solve_position_row, solve_velocity_row, warm_start,
};
use crate::solver::row_groups::{GroupSolve, RowGroups};
use crate::solver::sparse_solve::{solve_sparse_positions, solve_sparse_velocities};
use crate::solver::tree_solve::{
    SideRows, TreeScratch, solve_tree_positions, solve_tree_velocities,
};
use crate::world::World;
use crate::world::WorldSettings;

impl<S: Scalar> World<S> {
    /// Rows grouped by shared bodies (chains, piles) and how each group is
    /// solved (`h`: the substep), then the warm start: last substep's
    /// impulses applied again.
    pub(super) fn group_and_warm_start(&mut self, h: S) {
        let context = &mut self.step_context;
        let slot_count = context.velocities.len();
        let (slop, gravity) = (self.settings.linear_slop, self.settings.gravity);
        // One substep of gravity: what resting bodies' velocities differ by
        // at most (L∞ norm of g times h).
        let rest_speed = gravity.x.abs().max(gravity.y.abs()).mul(h);
        let implied = &context.narrow_scratch.implied.implied;
        context.contact_groups.regroup(
            &context.constraints,
            0,
            implied,
            &context.velocities,
            slot_count,
            slop,
            gravity,
            &mut context.parents,
        );
        context.contact_groups.classify(
            &context.constraints,
            slot_count,
            0,
            &context.velocities,
            rest_speed,
        );
        context.joint_rows.clear();
        if !context.rope_rows.is_empty() {
            context.joint_rows.extend_from_slice(&context.rope_rows);
            context.joint_rows.extend_from_slice(&context.constraints);
            context.joint_groups.regroup(
                &context.joint_rows,
                context.rope_rows.len(),
                implied,
                &context.velocities,
                slot_count,
                slop,
                gravity,
                &mut context.parents,
            );
            context.joint_groups.classify(
                &context.joint_rows,
                slot_count,
                context.rope_rows.len(),
                &context.velocities,
                rest_speed,
            );
        }
        let row_count = context.joint_rows.len().max(context.constraints.len());
        context.tree.reserve(slot_count, row_count);
        self.remember_velocities_before_solve();
        let context = &mut self.step_context;
        warm_start(&context.rope_rows, &mut context.velocities);
        warm_start(&context.constraints, &mut context.velocities);
    }

    /// Velocity iterations: with no rope active, over the contact groups;
    /// otherwise over the joint groups (`StepContext::joint_rows`: ropes,
    /// with their sideways stiffness [`rope_velocity_side_stiffness`],
    /// and contacts, a group holding every row that shares a body with
    /// another), after which the rows are copied back to the rope and
    /// contact rows.
    ///
    /// # Ropes and contacts in one group
    ///
    /// A chain draped over a fixed peg, a platform hung by ropes carrying a
    /// stack, boxes linked by ropes: the ropes and the contacts hold the
    /// same bodies, and each set is only right given the other. Solved as
    /// two groups one after the other in every sweep (ropes, then
    /// contacts), each undid part of the other, and the sweeps carried the
    /// correction across the boundary one row at a time: a 200-link chain
    /// over a peg stretched by hundreds of percent, a heavy stack on a
    /// rope-held platform sank. As one group, the exact tree (or block)
    /// solve takes both at once; its active set keeps contact impulses
    /// ≥ 0 and rope impulses ≥ 0 alike (a rope only pulls: its row is the
    /// contact rule on its slack).
    pub(super) fn solve_velocities(&mut self, h: S) {
        let context = &mut self.step_context;
        let slop = self.settings.linear_slop;
        if context.rope_rows.is_empty() {
            for _ in 0..self.settings.velocity_iterations {
                let StepContext {
                    constraints,
                    contact_groups,
                    velocities,
                    rope_block,
                    tree,
                    ..
                } = context;
                solve_group_list_velocities(
                    constraints,
                    contact_groups,
                    velocities,
                    slop,
                    None,
                    rope_block,
                    tree,
                );
            }
            self.guard_covering_tree_energy();
            return;
        }
        let ropes = context.rope_rows.len();
        rope_velocity_side_stiffness(
            &context.joint_rows[..ropes],
            &context.rope_geometry,
            h,
            &mut context.rope_velocity_side,
        );
        context.rope_side_impulse.clear();
        context.rope_side_impulse.resize(ropes, S::ZERO);
        context.rope_velocity_side_start.clear();
        context
            .rope_velocity_side_start
            .extend_from_slice(&context.rope_velocity_side);
        for iteration in 0..self.settings.velocity_iterations {
            if iteration > 0 {
                raise_rope_velocity_side_stiffness(
                    &context.joint_rows[..ropes],
                    &context.rope_geometry,
                    h,
                    &mut context.rope_velocity_side,
                );
            }
            let StepContext {
                joint_rows,
                joint_groups,
                rope_velocity_side,
                rope_side_impulse,
                velocities,
                rope_block,
                tree,
                ..
            } = context;
            let side = SideRows {
                stiffness: rope_velocity_side,
                accumulated: rope_side_impulse,
            };
            solve_group_list_velocities(
                joint_rows,
                joint_groups,
                velocities,
                slop,
                Some(side),
                rope_block,
                tree,
            );
        }
        self.guard_joint_groups(h);
        let context = &mut self.step_context;
        let (rope_part, contact_part) = context.joint_rows.split_at(ropes);
        context.rope_rows.copy_from_slice(rope_part);
        context.constraints.copy_from_slice(contact_part);
    }

    /// Position iterations: with no rope active, a pass over the contact
    /// groups; otherwise a pass over the joint groups
    /// ([`rope_position_pass`]: ropes re-linearised, with their sideways
    /// stiffness, and the contacts that share their bodies). Both move
    /// displacements only, so correcting penetration or stretch adds no
    /// energy.
    pub(super) fn solve_positions(&mut self, h: S) {
        let settings = &self.settings;
        let context = &mut self.step_context;
        if context.rope_rows.is_empty() {
            for _ in 0..settings.position_iterations {
                let StepContext {
                    constraints,
                    contact_groups,
                    displacements,
                    rope_block,
                    tree,
                    ..
                } = context;
                solve_group_list_positions(
                    constraints,
                    contact_groups,
                    displacements,
                    settings,
                    (&[], &[]),
                    false,
                    &mut (rope_block, tree),
                );
            }
            return;
        }
        rope_side_stiffness(
            &context.rope_rows,
            &context.rope_geometry,
            h,
            &mut context.rope_side_stiffness,
        );
        rope_correction_caps(&context.rope_geometry, &mut context.rope_correction_cap);
        for _ in 0..settings.position_iterations {
            rope_position_pass(context, settings, false);
        }
    }
}

/// The most one position pass corrects each rope row: an eighth of the
/// rope's length (and never more than `max_correction`, which the pass
/// applies as well), into `out`.
///
/// Why: a pass is a Newton step on rows linearised at the current
/// displacements. A rope held at its length by the step (a neighbour of
/// the rope being shortened) is held only to first order: moving its end
/// by `δ` across it stretches it by `δ²/(2ℓ)`. A rope far longer than its
/// length (its anchor teleported, its bodies set apart) asks for a
/// correction many times `ℓ`; taken in one step, it moved a link of a
/// 0.1 chain across its neighbours by 0.2 per pass, stretching them 200 %,
/// and the chain never came back (700–1000 % for 10 s, whipping at
/// 15 units/s). With `δ ≤ ℓ/8` a neighbour is stretched at most `ℓ/128`
/// (0.8 %), which the next pass removes: the excess is taken out at up to
/// `ℓ/8` per pass and rope ([`World::settle_ropes`] takes up to 32 passes
/// a substep while a rope is still long). Ordinary corrections (a swing's
/// stretch, of the order of the slop) are far below the cap.
fn rope_correction_caps<S: Scalar>(geometry: &[(Vec2<S>, S)], out: &mut Vec<S>) {
    out.clear();
    out.extend(
        geometry
            .iter()
            .map(|&(_, length)| length.mul(S::from_ratio(1, 8))),
    );
}

/// Each rope row's sideways stiffness for the position passes,
/// `g = λ·h/ℓ` (`λ` the row's impulse from the velocity solve, `ℓ` the
/// rope's length), into `out`.
///
/// Why: the position pass is a Newton step of the projection onto the
/// ropes' lengths, `min ½|Δx|²_M` subject to `C(x) = 0`. Its exact matrix
/// is `M + Σ μ_r ∇²C_r`, where `μ_r ≈ T_r·h² = λ_r·h` is the rope's
/// multiplier and `∇²C_r = s sᵀ/ℓ` (`s ⊥` the rope) couples its two ends
/// sideways: a rope under tension resists turning. Gauss–Newton drops that
/// term; it is small against a body's mass when `T·h²/(m·ℓ) = (ω·h)²/2`
/// is small (`ω` the frequency at which a link swings sideways between
/// two taut ropes), but a light link under a heavy end's tension has
/// `(ω·h)²/2` of 10–100, and without the term the step moves it sideways
/// by `e/θ` (stretch `e`, kink angle `θ`) where `(e/θ)²/ℓ` is far beyond
/// `e`: the passes overshoot and the chain stretches from one tick to the
/// next. With it, the tree solve treats each rope as a hard row along its
/// direction and a spring of stiffness `g` across it
/// ([`crate::solver::tree_solve`]), and the passes converge.
fn rope_side_stiffness<S: Scalar>(
    rows: &[ContactConstraint<S>],
    geometry: &[(Vec2<S>, S)],
    h: S,
    out: &mut Vec<S>,
) {
    fill_side_stiffness(rows, geometry, h, out, |g, _| g);
}

/// Each rope row's sideways stiffness for the next rope settling round
/// (`World::settle_ropes`), `g = (λ·h + μ)/ℓ`, into `out`: `λ` the row's
/// impulse from the velocity solve, `μ` the position impulse the rounds so
/// far have applied to it (`applied`: what the tree solves and the block
/// solves summed, by row index), zero where `q = g·(w_a + w_b) < 1/4`
/// (as [`side_stiffness`]). With `μ = 0` it is [`rope_side_stiffness`],
/// bit for bit.
///
/// Why: the Hessian term `μ_r ∇²C_r` of the projection
/// ([`rope_side_stiffness`]) wants the projection's multiplier, the whole
/// position impulse the rope carries in the substep. `λ·h` is that while
/// the rope holds a load it already held; a rope that snaps taut within
/// the substep has almost none of it in `λ`. A short ring of ropes round
/// a 10⁴× body, hung from a point, folds as it falls: the heavy body is in
/// free fall until a light link swings into line between two ropes, so
/// the velocity solve leaves `λ·h ≈ 0.003` on the ropes that must then
/// lift it by about 2e-3 (a position impulse near 2). Without the term
/// each round moved the light link sideways by `e/θ` instead (stretch
/// `e`, kink `θ`), the rounds' reach (`rope_correction_caps`) shrank the
/// whole step to the link's eighth of a rope, and the heavy body rose
/// 2e-5 a round: after 32 rounds the ring stayed 1.1 % (3 ropes) to
/// 16.5 % (20 ropes) long. The multipliers of the rounds already taken
/// are the estimate a sequential quadratic programme uses for the next
/// one; the rounds then converge and every rope is within the slop at
/// every tick (`tests/constraints_rope_loops.rs`).
pub(super) fn rope_settle_side_stiffness<S: Scalar>(
    rows: &[ContactConstraint<S>],
    geometry: &[(Vec2<S>, S)],
    h: S,
    (applied_tree, applied_block): (&[S], &[S]),
    out: &mut [S],
) {
    for (ri, ((row, &(_, length)), stiffness)) in
        rows.iter().zip(geometry).zip(out.iter_mut()).enumerate()
    {
        let settled = applied_tree
            .get(ri)
            .copied()
            .unwrap_or(S::ZERO)
            .add(applied_block.get(ri).copied().unwrap_or(S::ZERO));
        if !settled.is_positive() {
            continue;
        }
        let carried = row.normal_impulse.max(S::ZERO).mul(h).add(settled);
        if !length.is_positive() {
            continue;
        }
        let g = carried.div(length);
        let q = g.mul(row.inverse_mass_a.add(row.inverse_mass_b));
        if q >= S::from_ratio(1, 4) {
            *stiffness = g;
        }
    }
}

/// A rope row's sideways stiffness `g = λ·h/ℓ` and `q = g·(w_a + w_b)`
/// (≈ `(ω·h)²/2` of its ends' sideways swing), or `None` when the row
/// carries no tension or `q < 1/4`.
///
/// Below `q = 1/4` the term `μ∇²C` is under an eighth of the mass term:
/// Gauss–Newton converges without it and the velocity iterations resolve
/// the swing (`φ(q) < 1/256`), so the row keeps the cheaper scalar
/// elimination (ordinary pendulums and chains of equal links: a 20-link
/// chain of equal links has `q ≈ 0.44` at its top rope only).
fn side_stiffness<S: Scalar>(row: &ContactConstraint<S>, length: S, h: S) -> Option<(S, S)> {
    if !(row.normal_impulse.is_positive() && length.is_positive()) {
        return None;
    }
    let g = row.normal_impulse.mul(h).div(length);
    let q = g.mul(row.inverse_mass_a.add(row.inverse_mass_b));
    (q >= S::from_ratio(1, 4)).then_some((g, q))
}

/// Each rope row's sideways stiffness for the velocity iterations, into
/// `out`: `g·φ(q)` with `g = λ·h/ℓ` as in [`rope_side_stiffness`] (`λ`
/// the warm-start impulse, last substep's tension times `h`),
/// `q = g·(w_a + w_b)` (≈ `(ω·h)²/2` of the ends' sideways swing) and
/// `φ(q) = min(1, q²/16)`.
///
/// Why: the velocity iterations hold each rope along its direction at the
/// start of the substep, i.e. they treat the turning of the rope's tension
/// explicitly; for a light link between two taut ropes that is stable
/// only while `ω·h < 2`, and a heavy end (100×, 1000×) puts light links
/// far beyond it. The sideways row `λ_s = −g·(s·v_rel)` at the substep's
/// end velocities is that turning taken implicitly (backward Euler on
/// the geometric stiffness `T/ℓ·s sᵀ`), stable at any `ω·h`. Backward
/// Euler also damps: `φ` keeps it small where the step resolves the
/// swing and full where it cannot (`q ≥ 4`); below `q = 1/4` it is off
/// ([`side_stiffness`]; a 1-unit pendulum at 60 Hz has `q ≈ 0.003`).
fn rope_velocity_side_stiffness<S: Scalar>(
    rows: &[ContactConstraint<S>],
    geometry: &[(Vec2<S>, S)],
    h: S,
    out: &mut Vec<S>,
) {
    fill_side_stiffness(rows, geometry, h, out, velocity_side_stiffness);
}

/// Raises each rope row's velocity sideways stiffness in `out` to what its
/// impulse accumulated so far this substep gives
/// ([`rope_velocity_side_stiffness`], never lowered), before each velocity
/// iteration after the first.
///
/// Why: the stiffness is built from the warm-start impulse, last substep's
/// tension. A rope that snaps taut this substep has almost none: a short
/// ring of light links round a very heavy body (10 links, body 10⁴× a
/// link) falls for a few ticks while the circle folds into two strands,
/// then the heavy body jerks the links with no sideways stiffness at all,
/// the velocity sweeps treat the turning of that sudden tension
/// explicitly (unstable far beyond `ω·h = 2`) and the links whipped: the
/// ring gained 2272 J and stretched 194 %. Taken from the tension the
/// sweeps have found so far, the jerk's turning is implicit from the
/// second sweep on. Only raised, so a sweep that releases a rope (its
/// impulse back to zero) does not switch its stiffness off and on.
pub(super) fn raise_rope_velocity_side_stiffness<S: Scalar>(
    rows: &[ContactConstraint<S>],
    geometry: &[(Vec2<S>, S)],
    h: S,
    out: &mut [S],
) {
    for ((row, &(_, length)), stiffness) in rows.iter().zip(geometry).zip(out.iter_mut()) {
        if let Some((g, q)) = side_stiffness(row, length, h) {
            *stiffness = (*stiffness).max(velocity_side_stiffness(g, q));
        }
    }
}

/// `g·φ(q)`, `φ(q) = min(1, q²/16)` ([`rope_velocity_side_stiffness`]).
fn velocity_side_stiffness<S: Scalar>(g: S, q: S) -> S {
    let q = q.min(S::from_int(4));
    let phi = q.mul(q).mul(S::from_ratio(1, 16)).min(S::ONE);
    g.mul(phi)
}

/// Writes one stiffness per rope row into `out`: `stiffness(g, q)` of the
/// row's [`side_stiffness`], or zero where it has none.
fn fill_side_stiffness<S: Scalar>(
    rows: &[ContactConstraint<S>],
    geometry: &[(Vec2<S>, S)],
    h: S,
    out: &mut Vec<S>,
    stiffness: impl Fn(S, S) -> S,
) {
    out.clear();
    out.extend(rows.iter().zip(geometry).map(|(row, &(_, length))| {
        side_stiffness(row, length, h).map_or(S::ZERO, |(g, q)| stiffness(g, q))
    }));
}

/// One position pass over the joint rows (ropes, and the contacts in
/// their groups; every contact when any rope is active, see
/// `StepContext::joint_rows`): the rope rows re-linearised at the current
/// displacements (so the pass sees each rope's true length and direction:
/// a Newton step of the projection onto the ropes' lengths), then every
/// group solved like the position iterations solve contacts, with each
/// rope's sideways stiffness ([`rope_side_stiffness`]) in the tree solve.
///
/// Reads the context's joint rows and groups, rope geometry (each row's
/// anchor offset at the start of the substep and length) and sideways
/// stiffness, and moves its displacements.
pub(super) fn rope_position_pass<S: Scalar>(
    context: &mut StepContext<S>,
    settings: &WorldSettings<S>,
    settling: bool,
) {
    let StepContext {
        rope_rows,
        joint_rows,
        joint_groups,
        rope_geometry,
        rope_side_stiffness,
        rope_correction_cap,
        displacements,
        rope_block,
        tree,
        ..
    } = context;
    let ropes = rope_rows.len();
    relinearise_rope_rows(&mut joint_rows[..ropes], rope_geometry, displacements);
    solve_group_list_positions(
        joint_rows,
        joint_groups,
        displacements,
        settings,
        (rope_side_stiffness, rope_correction_cap),
        settling,
        &mut (rope_block, tree),
    );
}

/// One velocity pass over grouped rows (ropes or contacts), each group the
/// way [`RowGroups::classify`] decided: directly (the tree or block solver
/// for the normal impulses, then friction by sequential impulses; contact
/// groups of the block solver take their friction first) or by sequential
/// impulses.
fn solve_group_list_velocities<S: Scalar>(
    rows: &mut [ContactConstraint<S>],
    groups: &RowGroups,
    velocities: &mut [Vec2<S>],
    slop: S,
    mut side: Option<SideRows<'_, S>>,
    block: &mut BlockScratch<S>,
    tree: &mut TreeScratch<S>,
) {
    for (group, solve, _) in groups.iter_classified() {
        let side = side.as_mut().map(|sr| SideRows {
            stiffness: sr.stiffness,
            accumulated: &mut *sr.accumulated,
        });
        solve_one_group_velocities(
            rows,
            groups,
            (group, solve),
            velocities,
            slop,
            side,
            block,
            tree,
        );
    }
}

/// One velocity pass over one group of `groups` (see
/// [`solve_group_list_velocities`]).
#[allow(clippy::too_many_arguments)]
#[inline]
pub(super) fn solve_one_group_velocities<S: Scalar>(
    rows: &mut [ContactConstraint<S>],
    groups: &RowGroups,
    (group, solve): (&[usize], &GroupSolve),
    velocities: &mut [Vec2<S>],
    slop: S,
    side: Option<SideRows<'_, S>>,
    block: &mut BlockScratch<S>,
    tree: &mut TreeScratch<S>,
) {
    // The rope rows come first: a group holds a rope when its first row is
    // one. A group of contacts alone is solved as a contact group.
    let ropes = side.as_ref().map_or(0, |sr| sr.stiffness.len());
    let holds_rope = group.first().is_some_and(|&ri| ri < ropes);
    let mut side = side.filter(|_| holds_rope);
    match solve {
        GroupSolve::Sequential => {
            match contiguous(group) {
                Some(run) => {
                    for row in &mut rows[run] {
                        solve_velocity_row(row, velocities);
                    }
                }
                None => {
                    for &ri in group {
                        solve_velocity_row(&mut rows[ri], velocities);
                    }
                }
            }
            return;
        }
        GroupSolve::Block if side.is_none() => {
            // Contacts: friction first, so that every sweep ends with
            // the exact normal solve. Under heavy bodies the friction
            // rows carry impulses of hundreds (μ·λ of a 1000× load);
            // solved after the exact solve, they moved the light
            // bodies by the friction's share in every sweep, and the
            // sweep ended with the normal rows violated by it: a
            // hexagonal pile of 4–6 rows of light circles with heavy
            // (×1000) top, middle or scattered circles sank through
            // itself (up to 3 557 times the slop bound at the default
            // 8 iterations); with the exact solve ending the sweep it
            // rests within the slop (tests/heavy_circle_piles.rs).
            for &ri in group {
                solve_friction_row(&mut rows[ri], velocities);
            }
            solve_group_velocities(rows, group, velocities, None, block);
            return;
        }
        GroupSolve::Sparse(range) => {
            // Friction first, as for the block solve above.
            for &ri in group {
                solve_friction_row(&mut rows[ri], velocities);
            }
            solve_sparse_velocities(
                rows,
                group,
                groups.sparse(range),
                velocities,
                &mut block.sparse,
            );
            return;
        }
        GroupSolve::Block => {
            let side = side.as_mut().map(|sr| (sr.stiffness, &mut *sr.accumulated));
            solve_group_velocities(rows, group, velocities, side, block);
        }
        GroupSolve::Tree(range) => {
            let side = side.as_mut().map(|sr| SideRows {
                stiffness: sr.stiffness,
                accumulated: &mut *sr.accumulated,
            });
            solve_tree_velocities(
                rows,
                group,
                groups.plan(range),
                velocities,
                slop,
                side,
                None,
                tree,
            );
        }
        GroupSolve::Trees(range) => {
            for plan in groups.trees(range) {
                let side = side.as_mut().map(|sr| SideRows {
                    stiffness: sr.stiffness,
                    accumulated: &mut *sr.accumulated,
                });
                solve_tree_velocities(
                    rows,
                    group,
                    groups.plan(plan),
                    velocities,
                    slop,
                    side,
                    Some(groups.uncovered()),
                    tree,
                );
            }
        }
    }
    for &ri in group {
        solve_friction_row(&mut rows[ri], velocities);
    }
}

/// The rows of `group` (ascending row indices, no repeats) as one range
/// when they are consecutive: a pile that is one group holds every row, and
/// a sweep then walks the rows in place instead of through the index list
/// (the same rows in the same order, without an index load, bounds check
/// and address computation per row).
fn contiguous(group: &[usize]) -> Option<core::ops::Range<usize>> {
    let (&first, &last) = (group.first()?, group.last()?);
    (last - first + 1 == group.len()).then_some(first..last + 1)
}

/// One position pass over grouped rows (same split as the velocities);
/// `settling` for the rope settling rounds: groups without a rope are
/// left alone, and contacts off a group's spanning tree are not corrected.
fn solve_group_list_positions<S: Scalar>(
    rows: &[ContactConstraint<S>],
    groups: &RowGroups,
    displacements: &mut [Vec2<S>],
    settings: &WorldSettings<S>,
    (rope_side_stiffness, rope_caps): (&[S], &[S]),
    settling: bool,
    (block, tree): &mut (&mut BlockScratch<S>, &mut TreeScratch<S>),
) {
    let (slop, beta, max) = (
        settings.linear_slop,
        settings.position_correction,
        settings.max_correction,
    );
    // The rope rows come first (one stiffness per rope row): a group holds
    // a rope when its first row is one.
    let ropes = rope_side_stiffness.len();
    // The settling rounds correct no contact between two moving bodies
    // off the spanning tree (see `World::settle_ropes`).
    let off_tree_below = if settling { ropes } else { usize::MAX };
    for (group, _, solve) in groups.iter_classified() {
        let holds_rope = group.first().is_some_and(|&ri| ri < ropes);
        if settling && !holds_rope {
            continue;
        }
        let (side_stiffness, row_caps) = if holds_rope {
            (rope_side_stiffness, rope_caps)
        } else {
            (&[][..], &[][..])
        };
        match solve {
            GroupSolve::Sequential => match contiguous(group) {
                Some(run) => {
                    for row in &rows[run] {
                        solve_position_row(row, displacements, slop, beta, max);
                    }
                }
                None => {
                    for &ri in group {
                        solve_position_row(&rows[ri], displacements, slop, beta, max);
                    }
                }
            },
            GroupSolve::Block => {
                solve_group_positions(
                    rows,
                    group,
                    displacements,
                    (slop, beta, max),
                    side_stiffness,
                    row_caps,
                    block,
                );
            }
            GroupSolve::Sparse(range) => solve_sparse_positions(
                rows,
                group,
                groups.sparse(range),
                displacements,
                (slop, beta, max),
                &mut block.sparse,
            ),
            GroupSolve::Tree(range) => solve_tree_positions(
                rows,
                group,
                groups.plan(range),
                displacements,
                slop,
                beta,
                max,
                side_stiffness,
                row_caps,
                None,
                off_tree_below,
                tree,
            ),
            // The position pass solves the first (load-path) tree exactly
            // and the rows off it by sequential corrections, as for one
            // spanning tree: correcting on every covering tree moved a
            // ring of 40 ropes round a 1000× body by 0.17 % in its last
            // second (the velocity sweeps carry the heavy loads).
            GroupSolve::Trees(range) => {
                if let Some(first) = groups.trees(range).first() {
                    solve_tree_positions(
                        rows,
                        group,
                        groups.plan(first),
                        displacements,
                        slop,
                        beta,
                        max,
                        side_stiffness,
                        row_caps,
                        None,
                        off_tree_below,
                        tree,
                    );
                }
            }
        }
    }
}
