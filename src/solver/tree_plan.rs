//! Finding the tree solve's elimination order: whether a group's dynamic
//! bodies and rows form a tree, and if so its rows leaves first
//! ([`plan_tree`]), which [`crate::solver::tree_solve`] folds in that order.

use crate::math::Scalar;
use crate::solver::row::ContactConstraint;

/// Marks a row whose other end is not a dynamic body of the group.
pub(crate) const NO_CHILD: u32 = u32::MAX;

/// One row of a tree plan, in elimination (leaves-first) order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct TreeRow {
    /// Index of the row in the row list.
    pub(crate) row: usize,
    /// Slot of the end nearer the root (always dynamic).
    pub(crate) parent: u32,
    /// Slot of the other end when it is a dynamic body of the group, else
    /// [`NO_CHILD`].
    pub(crate) child: u32,
    /// Whether the parent is the row's `b` end (σ_p = +1).
    pub(crate) parent_is_b: bool,
}

/// Working memory of [`plan_tree`] (adjacency lists and marks per slot).
#[derive(Clone, Debug, Default)]
pub(crate) struct TreePlanner {
    /// First incidence of each slot (`2·position + end`), or `u32::MAX`.
    head: Vec<u32>,
    /// Next incidence of the same slot, per incidence.
    next: Vec<u32>,
    /// Whether each slot has been reached by the search.
    seen: Vec<bool>,
    /// Whether each row (by position in the group) has been placed.
    placed: Vec<bool>,
    /// Bodies in the order the search reached them.
    queue: Vec<u32>,
}

const NONE: u32 = u32::MAX;

/// The dynamic slot at end `end` (0 = a, 1 = b) of a row, if dynamic.
fn dynamic_end<S: Scalar>(row: &ContactConstraint<S>, end: u32) -> Option<u32> {
    if end == 0 {
        row.inverse_mass_a.is_positive().then_some(row.a)
    } else {
        row.inverse_mass_b.is_positive().then_some(row.b)
    }
}

/// Appends to `out` the elimination plan of `group` (leaves first) and
/// returns true when the group's dynamic bodies and rows, without the rows
/// marked in `off_tree` (indexed by row), form a tree; on a cycle it
/// returns false and leaves `out` as it was. The rows off the tree are not
/// in the plan: the solves treat them by sequential impulses. Linear in the
/// group's size: a breadth-first search from the first tree row's dynamic
/// end builds the parent links, and the rows listed in the reverse of the
/// search order have every child body's rows before the body's own parent
/// row.
pub(crate) fn plan_tree<S: Scalar>(
    rows: &[ContactConstraint<S>],
    group: &[usize],
    off_tree: &[bool],
    slot_count: usize,
    planner: &mut TreePlanner,
    out: &mut Vec<TreeRow>,
) -> bool {
    if planner.head.len() < slot_count {
        planner.head.resize(slot_count, NONE);
        planner.seen.resize(slot_count, false);
    }
    planner.next.clear();
    planner.next.resize(2 * group.len(), NONE);
    planner.placed.clear();
    planner.placed.resize(group.len(), false);
    for (position, &ri) in group.iter().enumerate() {
        if off_tree.get(ri).copied().unwrap_or(false) {
            // Not part of the tree: counts as placed, never linked.
            planner.placed[position] = true;
            continue;
        }
        for end in 0..2 {
            if let Some(k) = dynamic_end(&rows[ri], end) {
                let incidence = u32::try_from(2 * position).unwrap_or(NONE) + end;
                planner.next[incidence as usize] = planner.head[k as usize];
                planner.head[k as usize] = incidence;
            }
        }
    }
    let start = out.len();
    planner.queue.clear();
    let is_tree = 'search: {
        let Some(&first) = group
            .iter()
            .find(|&&ri| !off_tree.get(ri).copied().unwrap_or(false))
        else {
            break 'search true;
        };
        let Some(root) = dynamic_end(&rows[first], 1).or(dynamic_end(&rows[first], 0)) else {
            break 'search false;
        };
        planner.seen[root as usize] = true;
        planner.queue.push(root);
        let mut cursor = 0;
        while let Some(&body) = planner.queue.get(cursor) {
            cursor += 1;
            let mut incidence = planner.head[body as usize];
            while incidence != NONE {
                let position = (incidence / 2) as usize;
                let end = incidence % 2;
                incidence = planner.next[incidence as usize];
                if planner.placed[position] {
                    continue;
                }
                planner.placed[position] = true;
                let ri = group[position];
                let child = match dynamic_end(&rows[ri], 1 - end) {
                    Some(g) if planner.seen[g as usize] => break 'search false,
                    Some(g) => {
                        planner.seen[g as usize] = true;
                        planner.queue.push(g);
                        g
                    }
                    None => NO_CHILD,
                };
                out.push(TreeRow {
                    row: ri,
                    parent: body,
                    child,
                    parent_is_b: end == 1,
                });
            }
        }
        // Every row is reached from the root when the group is connected
        // (groups are built that way); anything left means it is not.
        planner.placed.iter().all(|&p| p)
    };
    // Clear the per-slot marks of this group only.
    for &ri in group {
        for end in 0..2 {
            if let Some(k) = dynamic_end(&rows[ri], end) {
                planner.head[k as usize] = NONE;
                planner.seen[k as usize] = false;
            }
        }
    }
    if is_tree {
        out[start..].reverse();
    } else {
        out.truncate(start);
    }
    is_tree
}
