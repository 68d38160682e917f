//! Closing a tree group's loops exactly: the rows off its spanning tree
//! (a ring of ropes has one) solved together with the tree by a Schur
//! complement.
//!
//! # Why
//!
//! A cyclic group above [`crate::solver::block_solve::MAX_BLOCK`] rows is
//! solved on a spanning tree, and the rows off it used to take sequential
//! impulses after each exact tree solve: a block Gauss–Seidel between the
//! tree and the off-tree rows. Round a loop that converges like a chain
//! does under plain iteration: the tree moves the whole ring to honour
//! its rows, the off-tree row then pulls its two ends (light links) and
//! the next tree solve spreads that back. A ring of 64 light ropes hung
//! from a point with a 100× body stretched 24.7 %, 100 ropes with a 1000×
//! body 65 %.
//!
//! # The maths
//!
//! Split the impulses into tree rows `T` and off-tree rows `O` (`k` of
//! them). With `A = J W Jᵀ` (plus the tree's soft sideways rows) and the
//! residuals `e`:
//!
//! ```text
//! [A_TT A_TO] [λ_T]   [e_T]
//! [A_OT A_OO] [λ_O] = [e_O]
//! ```
//!
//! The tree solve applies `A_TT⁻¹` in linear time. Eliminating `λ_T`:
//!
//! ```text
//! S λ_O = e_O − A_OT A_TT⁻¹ e_T,   S = A_OO − A_OT A_TT⁻¹ A_TO   (k × k)
//! λ_T = A_TT⁻¹ (e_T − A_TO λ_O)
//! ```
//!
//! Column `j` of `S` is what row `i` sees of a unit impulse on off-tree row
//! `j` once the tree has answered it (the tree's rows held exact): apply
//! the unit impulse, tree-solve the residual it causes (`−J_T W J_jᵀ`),
//! and read `J_i` of the sum. So the whole solve is `k + 2` tree solves
//! (`e_T` alone, one per column, the final one) and a dense `k × k`
//! elimination: `O(k·n + k³)` against the dense block solver's `O(n³)`.
//!
//! `S` is the effective inverse mass of the off-tree rows with the tree
//! held: symmetric positive definite when the rows are independent. An
//! off-tree row that depends on the tree and the rows before it (a rope
//! doubling a tree rope) has a pivot near zero: it is left out (impulse 0,
//! listed as dependent, so the callers give it sequential impulses), by the
//! tree solve's rule, a pivot below 2⁻¹⁶ of the row's own inverse mass.
//!
//! Rounding: every column is a tree solve (bounded as in the parent
//! module) followed by products of inverse masses and unit normals; the
//! pivots are bounded below by the skip rule, so `λ_O` amplifies its
//! residual by at most `2¹⁶ / (w_a + w_b)`.

use super::{TreeScratch, apply, apply_side, solve_tree};
use crate::math::{Scalar, Vec2};
use crate::solver::row::ContactConstraint;
use crate::solver::tree_plan::TreeRow;

/// Most rows off the spanning tree a group may have for its loops to be
/// closed exactly (`k + 2` tree solves per solve; a ring has one, a
/// ladder of `r` rungs `r − 1`). Groups with more keep sequential impulses
/// for their off-tree rows.
pub(crate) const MAX_LOOP_ROWS: usize = 32;

/// Working memory of [`solve_closed_tree`]; grows once and is reused.
#[derive(Clone, Debug, Default)]
pub(crate) struct LoopScratch<S: Scalar> {
    /// The off-tree rows taking part in the current solve.
    off: Vec<usize>,
    /// Their residuals, then their impulses.
    rhs: Vec<S>,
    /// The Schur complement `S`, `k × k` row-major.
    schur: Vec<S>,
    /// The tree's residuals on entry (along `n`, sideways), by plan
    /// position.
    saved: Vec<(S, S)>,
    /// A velocity (or displacement) change per slot; all zero between
    /// uses.
    change: Vec<Vec2<S>>,
    /// Per off-tree row: whether the dense solve kept it.
    kept: Vec<bool>,
    /// Per off-tree row: the pivot at or below which it is left out.
    floor: Vec<S>,
}

/// The relative velocity (displacement) of a row's ends in `change`, read
/// along `n` and sideways.
fn relative<S: Scalar>(row: &ContactConstraint<S>, change: &[Vec2<S>]) -> Vec2<S> {
    let at = |slot: u32| change.get(slot as usize).copied().unwrap_or(Vec2::ZERO);
    at(row.b) - at(row.a)
}

impl<S: Scalar> TreeScratch<S> {
    /// Sets the off-tree rows of the next [`solve_closed_tree`]: the rows
    /// of `group` not in the plan that are active.
    pub(crate) fn collect_loop_rows(&mut self, group: &[usize]) {
        self.loops.off.clear();
        for &ri in group {
            if !self.in_plan[ri] && self.active[ri] {
                self.loops.off.push(ri);
            }
        }
    }

    /// Adds the impulses the last tree solve found (its active rows, with
    /// their sideways parts) to `loops.change`.
    fn add_tree_impulses(&mut self, rows: &[ContactConstraint<S>], plan: &[TreeRow]) {
        for t in plan {
            if self.active[t.row] {
                let row = &rows[t.row];
                apply(row, self.value[t.row], &mut self.loops.change);
                if self.side_stiffness[t.row].is_positive() {
                    apply_side(row, self.side_value[t.row], &mut self.loops.change);
                }
            }
        }
    }

    /// Zeroes `loops.change` on every body of the plan and the off-tree
    /// rows.
    fn clear_change(&mut self, rows: &[ContactConstraint<S>], plan: &[TreeRow]) {
        let change = &mut self.loops.change;
        let rows_touched = plan
            .iter()
            .map(|t| t.row)
            .chain(self.loops.off.iter().copied());
        for ri in rows_touched {
            for slot in [rows[ri].a, rows[ri].b] {
                if let Some(v) = change.get_mut(slot as usize) {
                    *v = Vec2::ZERO;
                }
            }
        }
    }

    /// Sets the residual of every active tree row to `base` (by plan
    /// position: the saved entry residuals, or zero) minus what
    /// `loops.change` does along the row and sideways.
    fn set_tree_residuals(
        &mut self,
        rows: &[ContactConstraint<S>],
        plan: &[TreeRow],
        base: impl Fn(&[(S, S)], usize) -> (S, S),
    ) {
        for (position, t) in plan.iter().enumerate() {
            if !self.active[t.row] {
                continue;
            }
            let row = &rows[t.row];
            let rel = relative(row, &self.loops.change);
            let (along, side) = base(&self.loops.saved, position);
            self.value[t.row] = along.sub(rel.dot(row.normal));
            self.side_value[t.row] = side.sub(rel.dot(row.normal.perp()));
        }
    }
}

/// Solves the active rows of a tree group and its active off-tree rows
/// (set by [`TreeScratch::collect_loop_rows`]) exactly: like
/// [`solve_tree`], `work.value[r]` holds each active row's residual on
/// entry (tree and off-tree rows; `work.side_value` the tree rows'
/// sideways residuals) and its impulse on exit; off-tree rows the dense
/// solve leaves out get 0 and join `work.dependent`. Nothing is applied.
pub(crate) fn solve_closed_tree<S: Scalar>(
    rows: &[ContactConstraint<S>],
    plan: &[TreeRow],
    work: &mut TreeScratch<S>,
) {
    let k = work.loops.off.len();
    if k == 0 {
        solve_tree(rows, plan, work);
        return;
    }
    let slots = plan
        .iter()
        .map(|t| t.row)
        .chain(work.loops.off.iter().copied())
        .flat_map(|ri| [rows[ri].a, rows[ri].b])
        .map(|slot| slot as usize + 1)
        .max()
        .unwrap_or(0);
    if work.loops.change.len() < slots {
        work.loops.change.resize(slots, Vec2::ZERO);
    }
    // Entry residuals: the tree's (kept for the final solve) and the
    // off-tree rows'.
    work.loops.saved.clear();
    for t in plan {
        let saved = (work.value[t.row], work.side_value[t.row]);
        work.loops.saved.push(saved);
    }
    work.loops.rhs.clear();
    for i in 0..k {
        let residual = work.value[work.loops.off[i]];
        work.loops.rhs.push(residual);
    }
    // e_O − A_OT A_TT⁻¹ e_T: the tree alone, then what its impulses do to
    // the off-tree rows.
    solve_tree(rows, plan, work);
    work.add_tree_impulses(rows, plan);
    for i in 0..k {
        let row = &rows[work.loops.off[i]];
        let seen = relative(row, &work.loops.change).dot(row.normal);
        work.loops.rhs[i] = work.loops.rhs[i].sub(seen);
    }
    work.clear_change(rows, plan);
    // S column by column: a unit impulse on off-tree row j, the tree's
    // answer to it, and what the off-tree rows see of both.
    work.loops.schur.clear();
    work.loops.schur.resize(k * k, S::ZERO);
    for j in 0..k {
        apply(&rows[work.loops.off[j]], S::ONE, &mut work.loops.change);
        work.set_tree_residuals(rows, plan, |_, _| (S::ZERO, S::ZERO));
        solve_tree(rows, plan, work);
        work.add_tree_impulses(rows, plan);
        for i in 0..k {
            let row = &rows[work.loops.off[i]];
            work.loops.schur[i * k + j] = relative(row, &work.loops.change).dot(row.normal);
        }
        work.clear_change(rows, plan);
    }
    let LoopScratch {
        off,
        schur,
        rhs,
        kept,
        floor,
        ..
    } = &mut work.loops;
    floor.clear();
    floor.extend(off.iter().map(|&ri| {
        let row = &rows[ri];
        row.inverse_mass_a
            .add(row.inverse_mass_b)
            .mul(S::from_ratio(1, 65_536))
            .max(S::EPSILON)
    }));
    eliminate(schur, rhs, kept, floor, k);
    // The tree again, with the off-tree impulses applied: residuals
    // e_T − A_TO λ_O.
    for j in 0..k {
        if work.loops.kept[j] {
            let amount = work.loops.rhs[j];
            apply(&rows[work.loops.off[j]], amount, &mut work.loops.change);
        }
    }
    work.set_tree_residuals(rows, plan, |saved, position| saved[position]);
    work.clear_change(rows, plan);
    solve_tree(rows, plan, work);
    for j in 0..k {
        let ri = work.loops.off[j];
        if work.loops.kept[j] {
            work.value[ri] = work.loops.rhs[j];
        } else {
            work.value[ri] = S::ZERO;
            work.mark_dependent(ri);
        }
        work.side_value[ri] = S::ZERO;
    }
}

/// Solves `a x = b` in place (`b` becomes `x`) for the `m × m` matrix `a`
/// (row-major) by Gaussian elimination in the given order; an unknown
/// whose pivot is at or below its `floor` is left out (`kept[i]` false,
/// `x_i = 0`): its row depends on the ones before it.
fn eliminate<S: Scalar>(a: &mut [S], b: &mut [S], kept: &mut Vec<bool>, floor: &[S], m: usize) {
    kept.clear();
    kept.resize(m, true);
    for p in 0..m {
        let pivot = a[p * m + p];
        if pivot <= floor[p] {
            kept[p] = false;
            b[p] = S::ZERO;
            continue;
        }
        for i in (p + 1)..m {
            let factor = a[i * m + p].div(pivot);
            if factor == S::ZERO {
                continue;
            }
            for j in (p + 1)..m {
                a[i * m + j] = a[i * m + j].sub(factor.mul(a[p * m + j]));
            }
            b[i] = b[i].sub(factor.mul(b[p]));
        }
    }
    for p in (0..m).rev() {
        if !kept[p] {
            continue;
        }
        let mut s = b[p];
        for j in (p + 1)..m {
            if kept[j] {
                s = s.sub(a[p * m + j].mul(b[j]));
            }
        }
        b[p] = s.div(a[p * m + p]);
    }
}
