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
use crate::solver::tree_solve::{TreeScratch, solve_tree_positions, solve_tree_velocities};
use crate::world::World;
use crate::world::WorldSettings;

impl<S: Scalar> World<S> {
    /// Rows grouped by shared bodies (chains, piles) and how each group is
    /// solved, then the warm start: last substep's impulses applied again.
    pub(super) fn group_and_warm_start(&mut self) {
        let context = &mut self.step_context;
        let slot_count = context.velocities.len();
        context
            .rope_groups
            .regroup(&context.rope_rows, slot_count, &mut context.parents);
        context
            .contact_groups
            .regroup(&context.constraints, slot_count, &mut context.parents);
        context
            .rope_groups
            .classify(&context.rope_rows, slot_count, true);
        context
            .contact_groups
            .classify(&context.constraints, slot_count, false);
        let row_count = context.rope_rows.len().max(context.constraints.len());
        context.tree.reserve(slot_count, row_count);
        warm_start(&context.rope_rows, &mut context.velocities);
        warm_start(&context.constraints, &mut context.velocities);
    }

    /// Velocity iterations over rope rows, then contact rows.
    pub(super) fn solve_velocities(&mut self) {
        let context = &mut self.step_context;
        for _ in 0..self.settings.velocity_iterations {
            let StepContext {
                rope_rows,
                rope_groups,
                constraints,
                contact_groups,
                velocities,
                rope_block,
                tree,
                ..
            } = context;
            let slop = self.settings.linear_slop;
            solve_group_list_velocities(rope_rows, rope_groups, velocities, slop, rope_block, tree);
            solve_group_list_velocities(
                constraints,
                contact_groups,
                velocities,
                slop,
                rope_block,
                tree,
            );
        }
    }

    /// Position iterations (ropes re-linearised each time), moving
    /// displacements only, so correcting penetration adds no energy.
    pub(super) fn solve_positions(&mut self) {
        let settings = &self.settings;
        let context = &mut self.step_context;
        for _ in 0..settings.position_iterations {
            let StepContext {
                rope_rows,
                rope_groups,
                rope_geometry,
                constraints,
                contact_groups,
                displacements,
                rope_block,
                tree,
                ..
            } = context;
            relinearise_rope_rows(rope_rows, rope_geometry, displacements);
            let mut work = (rope_block, tree);
            solve_group_list_positions(rope_rows, rope_groups, displacements, settings, &mut work);
            solve_group_list_positions(
                constraints,
                contact_groups,
                displacements,
                settings,
                &mut work,
            );
        }
    }
}

/// One velocity pass over grouped rows (ropes or contacts), each group the
/// way [`RowGroups::classify`] decided: directly (the tree or block solver
/// for the normal impulses, then friction by sequential impulses) or by
/// sequential impulses.
fn solve_group_list_velocities<S: Scalar>(
    rows: &mut [ContactConstraint<S>],
    groups: &RowGroups,
    velocities: &mut [Vec2<S>],
    slop: S,
    block: &mut BlockScratch<S>,
    tree: &mut TreeScratch<S>,
) {
    for (group, solve, _) in groups.iter_classified() {
        match solve {
            GroupSolve::Sequential => {
                for &ri in group {
                    solve_velocity_row(&mut rows[ri], velocities);
                }
                continue;
            }
            GroupSolve::Block => solve_group_velocities(rows, group, velocities, block),
            GroupSolve::Tree(range) => {
                solve_tree_velocities(rows, group, groups.plan(range), velocities, slop, tree);
            }
        }
        for &ri in group {
            solve_friction_row(&mut rows[ri], velocities);
        }
    }
}

/// One position pass over grouped rows (same split as the velocities).
pub(super) fn solve_group_list_positions<S: Scalar>(
    rows: &[ContactConstraint<S>],
    groups: &RowGroups,
    displacements: &mut [Vec2<S>],
    settings: &WorldSettings<S>,
    (block, tree): &mut (&mut BlockScratch<S>, &mut TreeScratch<S>),
) {
    let (slop, beta, max) = (
        settings.linear_slop,
        settings.position_correction,
        settings.max_correction,
    );
    for (group, _, solve) in groups.iter_classified() {
        match solve {
            GroupSolve::Sequential => {
                for &ri in group {
                    solve_position_row(&rows[ri], displacements, slop, beta, max);
                }
            }
            GroupSolve::Block => {
                solve_group_positions(rows, group, displacements, slop, beta, max, block);
            }
            GroupSolve::Tree(range) => solve_tree_positions(
                rows,
                group,
                groups.plan(range),
                displacements,
                slop,
                beta,
                max,
                tree,
            ),
        }
    }
}
