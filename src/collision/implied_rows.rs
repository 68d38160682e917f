//! A speculative row implied by two rows through a body lying between its
//! bodies is marked, so that the groups solved exactly leave it out.
//!
//! # Why
//!
//! The speculative margin (0.1) reaches through thin bodies: in a column of
//! boxes 0.02 thick each box has rows with the four boxes below it, and a
//! ball arriving at 200 units/s (3.3 units per substep) has rows with every
//! box of the column and with the ground. Those rows close cycles in the
//! contact graph, so the column's group is no tree: the exact tree solve
//! takes a spanning tree and the rows off it are solved by sequential
//! impulses in the same sweep, and at such an impact they fight the tree
//! (issue 13, F15: the ground row was left violated by 28.5 units/s; a
//! ball of the boxes' mass at 50 units/s pushed a box wholly into the one
//! below, 0.02 deep). The block solve fares no better: the rows are
//! linearly dependent (below), its matrix singular. Yet none of those rows
//! says anything the rows of the column do not.
//!
//! # The rule
//!
//! A row `A → C` along `n` with gap `s_AC` asks `(v_C − v_A)·n ≥ −s_AC/h`
//! (and the position pass, `(x_C − x_A)·n ≥ −s_AC` on displacements). Rows
//! `A → B` and `B → C` along the same `n` with gaps `s_AB`, `s_BC` give,
//! summed, `(v_C − v_A)·n ≥ −(s_AB + s_BC)/h`. When
//! `s_AB + s_BC ≤ s_AC` that is at least as strong: the row `A → C` is
//! implied in the solve's linear model, and leaving it out changes no
//! solution's admissible set. In a column, `s_AC = s_AB + t_B + s_BC` with
//! `t_B` the thickness of `B` along `n`. (Bodies do not rotate, so the
//! row's Jacobian is the sum of the other two: the three are dependent.)
//!
//! # Where it is left out
//!
//! Only where the rows `A → B` and `B → C` are solved exactly: then the
//! implied row holds whenever they do. The rows are all kept;
//! [`crate::solver::row_groups`] leaves the marked ones off the spanning
//! tree and out of the group's cycles, and a group that is a tree without
//! them takes the exact tree solve, the marked rows after it by sequential
//! impulses (which then find nothing to do). A cyclic group solved on
//! spanning trees leaves them out of every tree as well (one kept in let
//! the exact solve drop a row implying it as dependent). A group solved by
//! sequential impulses alone (a moving crowd of even masses) keeps
//! them as any other row: there the implying rows are only nearly solved
//! after the sweeps, and the implied row is the direct guard of `A`
//! against `C` (a box of a crowd against a wall, the projection out of
//! immovable bodies). Dropping the rows outright let boxes of crowds of
//! 200 end 0.05 past their walls.
//!
//! `B` must be movable: the three rows are then in one group (each joins
//! `B`'s), and the rows kept join `A` and `C` wherever a marked row did.
//!
//! Only speculative rows (gap above the slop) are left out, so no resting
//! contact, its warm start, friction or contact event changes, and only
//! when both implying rows have smaller gaps than the row itself
//! (`s_AB < s_AC`, `s_BC < s_AC`): every row left out is then implied by
//! rows of strictly smaller gap, which are kept or are themselves implied
//! by rows of smaller gap still, so the rows kept imply every row left out
//! (no two rows can be left out on each other's account). Axis normals
//! only (exactly equal normals; contacts of boxes and of circles over a
//! box's face).

use crate::math::{Scalar, Vec2};
use crate::solver::row::ContactConstraint;

/// The implied rows' working memory, kept in the narrow phase's scratch.
#[derive(Clone, Debug, Default)]
pub(crate) struct ImpliedScratch<S: Scalar> {
    /// Per slot: a movable end of a candidate row.
    marks: Vec<bool>,
    /// Candidate rows (speculative, axis normal).
    candidates: Vec<usize>,
    /// Axis rows at marked bodies, from the marked end: (body, other
    /// body, normal from body, gap), sorted by (body, other).
    adjacency: Vec<(u32, u32, Vec2<S>, S)>,
    /// Per row: whether two other rows imply it.
    pub(crate) implied: Vec<bool>,
}

fn is_axis<S: Scalar>(n: Vec2<S>) -> bool {
    n.x == S::ZERO || n.y == S::ZERO
}

/// Finds the rows of `rows` (sorted by pair `(a, b)`, `a < b`, as the
/// narrow phase makes them) that two other rows imply through a movable
/// body (module notes) and marks them in `scratch.implied` (one entry per
/// row). `movable` tells the bodies the solver moves (every row has at
/// least one).
pub(crate) fn implied_rows<S: Scalar>(
    rows: &[ContactConstraint<S>],
    slots: usize,
    movable: impl Fn(u32) -> bool,
    slop: S,
    scratch: &mut ImpliedScratch<S>,
) {
    let ImpliedScratch {
        marks,
        candidates,
        adjacency,
        implied: marked_rows,
    } = scratch;
    marked_rows.clear();
    marked_rows.resize(rows.len(), false);
    candidates.clear();
    for (index, row) in rows.iter().enumerate() {
        if row.separation > slop && is_axis(row.normal) {
            candidates.push(index);
        }
    }
    if candidates.is_empty() {
        return;
    }
    // Each candidate is walked from a movable end (its adjacency: a
    // handful of rows; a wall's would be hundreds); the other row is found
    // by the pair's place in `rows`.
    marks.clear();
    marks.resize(slots, false);
    for &index in candidates.iter() {
        let row = &rows[index];
        let end = if movable(row.a) { row.a } else { row.b };
        if let Some(m) = marks.get_mut(end as usize) {
            *m = true;
        }
    }
    let marked = |slot: u32| marks.get(slot as usize).copied().unwrap_or(false);
    adjacency.clear();
    for row in rows.iter() {
        if !is_axis(row.normal) {
            continue;
        }
        if marked(row.a) {
            adjacency.push((row.a, row.b, row.normal, row.separation));
        }
        if marked(row.b) {
            adjacency.push((row.b, row.a, -row.normal, row.separation));
        }
    }
    adjacency.sort_unstable_by_key(|e| (e.0, e.1));
    let adjacency = &*adjacency;
    let of = |slot: u32| {
        let first = adjacency.partition_point(|e| e.0 < slot);
        let end = first + adjacency[first..].partition_point(|e| e.0 == slot);
        &adjacency[first..end]
    };
    // The gap of the row from `x` to `y` along `n` (`None`: no such row).
    let row_gap = |x: u32, y: u32, n: Vec2<S>| {
        let key = (x.min(y), x.max(y));
        let at = rows.partition_point(|r| (r.a, r.b) < key);
        let r = rows.get(at).filter(|r| (r.a, r.b) == key)?;
        let along = if r.a == x { r.normal } else { -r.normal };
        (along == n).then_some(r.separation)
    };
    for &index in candidates.iter() {
        let row = &rows[index];
        let (a, c, n, gap) = (row.a, row.b, row.normal, row.separation);
        let fits = |s_ab: S, s_bc: S| s_ab < gap && s_bc < gap && s_ab.add(s_bc) <= gap;
        // `B` with rows `A → B` and `B → C` along `n`, both of gap below
        // `s_AC` and summing to at most it; walked from the movable end.
        let implied = if marked(a) {
            of(a).iter().any(|&(_, b, n_ab, s_ab)| {
                b != c
                    && n_ab == n
                    && movable(b)
                    && row_gap(b, c, n).is_some_and(|s_bc| fits(s_ab, s_bc))
            })
        } else {
            of(c).iter().any(|&(_, b, n_cb, s_bc)| {
                b != a
                    && n_cb == -n
                    && movable(b)
                    && row_gap(a, b, n).is_some_and(|s_ab| fits(s_ab, s_bc))
            })
        };
        marked_rows[index] = implied;
    }
}
