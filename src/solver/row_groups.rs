//! Rows (contacts or ropes) grouped by the dynamic bodies they share, stored
//! flat so that regrouping every substep reuses the same two buffers and
//! allocates nothing once they have grown to the scene's size.

use core::ops::Range;

use crate::dynamics::islands;
use crate::math::{Scalar, Vec2};
use crate::solver::block_solve::MAX_BLOCK;
use crate::solver::forest_cover::{ForestCover, MAX_TREES};
use crate::solver::row::ContactConstraint;
use crate::solver::sparse_solve::{SparsePlanner, plan_sparse};
use crate::solver::tree_plan::{TreePlanner, TreeRow, plan_tree};
use crate::solver::tree_solve::MAX_LOOP_ROWS;

/// How a sweep solves one group's normal impulses.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum GroupSolve {
    /// Sequential impulses, row after row.
    Sequential,
    /// The dense block (LDLᵀ) solver: small groups with cycles.
    Block,
    /// The exact tree solve, with the plan at this range of
    /// [`RowGroups::plan`].
    Tree(Range<usize>),
    /// The exact tree solve on each of several spanning trees that
    /// together cover the group's rows ([`crate::solver::forest_cover`]),
    /// one after another: the plans at these ranges of
    /// [`RowGroups::plan`], listed at this range of
    /// [`RowGroups::trees`].
    Trees(Range<usize>),
    /// The exact sparse solve ([`crate::solver::sparse_solve`]) with the
    /// elimination order and profiles at this range of
    /// [`RowGroups::sparse`].
    Sparse(Range<usize>),
}

/// Groups of row indices, each sorted ascending, in the order of their first
/// row (deterministic). Group `g` is `rows[starts[g]..starts[g + 1]]`.
#[derive(Clone, Debug, Default)]
pub(crate) struct RowGroups {
    /// Row indices, group after group.
    rows: Vec<usize>,
    /// Start of each group in `rows`, plus one final entry `rows.len()`.
    starts: Vec<usize>,
    /// Per group: how the velocity and the position sweeps solve it. Decided
    /// once per substep by [`classify`](Self::classify): it depends only on
    /// the rows' masses and targets, which the sweeps do not change.
    modes: Vec<(GroupSolve, GroupSolve)>,
    /// The elimination plans of the tree groups, one after another.
    plans: Vec<TreeRow>,
    /// The plan ranges of the [`GroupSolve::Trees`] groups.
    trees: Vec<Range<usize>>,
    /// The covering of cyclic groups by spanning trees, and the rows it
    /// leaves uncovered.
    cover: ForestCover,
    /// Working memory of the tree planner.
    planner: TreePlanner,
    /// The sparse solve's elimination orders (group positions), one
    /// group after another.
    sparse_order: Vec<u32>,
    /// Per elimination index of [`sparse_order`](Self::sparse_order): the
    /// first column of its profile.
    sparse_first: Vec<u32>,
    /// Working memory of the sparse planner.
    sparse_planner: SparsePlanner,
    /// Group of each row while grouping (working memory).
    row_group: Vec<u32>,
    /// Group number of each union-find root while grouping (working memory).
    root_group: Vec<u32>,
    /// Per union-find root while grouping: which of [`TOUCHING_CYCLE`],
    /// [`APART_CYCLE`] and [`APART_EDGE`] its rows showed (working memory).
    root_flags: Vec<u8>,
    /// Per group: whether its dynamic bodies and rows carrying impulse or
    /// touching contain a cycle (a pyramid, a ball pile, two stacks side
    /// by side); cycles closed only by rows apart do not count.
    cyclic: Vec<bool>,
    /// Per group: [`TOUCHING_EDGE`] if a row touching or carrying impulse
    /// is on its spanning tree, [`GROUNDED`] if a row touches a body of
    /// infinite mass (what makes a resting structure, with
    /// [`resting_or_struck`]).
    support: Vec<u8>,
    /// Per row: whether it closed a cycle when the spanning trees were
    /// picked ([`regroup`](Self::regroup)); such rows are left out of the
    /// tree plans and solved by sequential impulses.
    off_tree: Vec<bool>,
    /// Per row: its [`tier`] while grouping (working memory).
    row_tier: Vec<u8>,
    /// The rows apart that meet within the substep, with when they meet
    /// (ordered bits), soonest first ([`regroup`](Self::regroup); working
    /// memory).
    meeting_rows: Vec<(u64, usize)>,
    /// Per row: how its normal lies against gravity ([`rise`]), which the
    /// covering's first tree reads ([`ForestCover::first_tree`]).
    row_rise: Vec<u8>,
    /// Per row: implied by two other rows of its group
    /// ([`regroup`](Self::regroup)'s `implied`; false for ropes). Such
    /// rows are in no spanning tree.
    row_implied: Vec<bool>,
}

impl RowGroups {
    /// Regroups `rows`: rows whose ends share a body with finite mass are in
    /// the same group. Linear time: a union-find over the `slot_count` body
    /// slots (`parents` is its working memory), then two passes over the
    /// rows (a counting sort by group keeps each group's rows ascending).
    ///
    /// The union-find also picks each group's spanning tree (Kruskal's
    /// rule: a row whose ends are already joined closes a cycle and is left
    /// *off the tree*), taking the rows in four tiers ([`tier`]): rows
    /// carrying impulse from the last substep (the load paths), rows
    /// touching within `slop` whose normal can carry weight (not
    /// perpendicular to `gravity`), the other rows touching (side by side),
    /// then rows apart (speculative). So a row that closes a cycle is one
    /// that carried no load, or is not touching, whenever such a choice
    /// exists: a box resting on a thin box also sees the box below that
    /// one within the speculative margin, and two stacks side by side touch
    /// each other along their sides; the spanning tree is then each stack's
    /// column of load-bearing contacts, solved exactly, and the rows off it
    /// are the ones sequential impulses handle well. Before the first
    /// substep of a resting scene no row carries impulse yet: the second
    /// tier still finds the columns (without it, side rows taken first
    /// made the tree, the columns' rows fell off it, and a wall of boxes
    /// 1e-5 apart sagged 0.0025 in its first step). Among the rows apart,
    /// those the `velocities` (one per slot; empty: none known) close
    /// beyond their target (`J·v < b`: they meet within the substep and
    /// will carry impulse) come first: a ball dropped onto three columns
    /// of boxes sees every box below it within the speculative margin,
    /// and taken in index order its row to the first column's bottom box
    /// (0.63 away at a slant, not closing within the substep) joined it to
    /// the tree while its row to the box it struck (0.37 apart, closing
    /// at 50 units/s against a target of −22) was left off the exact
    /// solve: the struck column sank 3.7e-3 into itself. The meeting rows
    /// are taken soonest first (least gap over closing speed): a ball
    /// arriving on the seam of two columns apart meets every box below it
    /// within the substep, and joins the tree by its rows to the two top
    /// boxes it lands on, not by those to the bottom boxes. Least gap
    /// alone is not when: a ball wider than the circles of a column, dropped
    /// onto it, sees the neighbouring column's top circle at a slant 0.29
    /// away along that row's normal, closing at 37 units/s, and the circle
    /// below 0.37 away, closing at 50; it meets the one below first, and the
    /// exact solve leaves the slanted row inactive. Taken nearest first,
    /// the slanted row joined the ball to the tree, the row below was left
    /// to sequential impulses, ball and circle were thrown sideways, and a
    /// circle sank 0.02 into the one below.
    ///
    /// `implied` (one entry per contact row, the rows after the `ropes`
    /// rope rows; empty: none) marks the rows two other rows imply through
    /// a movable body between ([`crate::collision`]'s implied rows). They
    /// are taken last and close no cycle that counts: a stack of thin
    /// boxes hit by a fast ball, whose rows reach through the boxes to
    /// every box below and to the ground, is still a tree. They are off
    /// every spanning tree (the rows with a body of infinite mass too,
    /// and in the trees covering a cyclic group,
    /// [`crate::solver::forest_cover`]), so an exact solve leaves them to
    /// the sequential update after it, which finds them satisfied; a
    /// group solved by sequential impulses alone solves them as any other
    /// row.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn regroup<S: Scalar>(
        &mut self,
        rows: &[ContactConstraint<S>],
        ropes: usize,
        implied: &[bool],
        velocities: &[Vec2<S>],
        slot_count: usize,
        slop: S,
        gravity: Vec2<S>,
        parents: &mut Vec<u32>,
    ) {
        let ropes = ropes.min(rows.len());
        // A marking of other rows (stale or absent) counts as none.
        let implied = if implied.len() == rows.len() - ropes {
            implied
        } else {
            &[]
        };
        let is_implied =
            |ri: usize| ri >= ropes && implied.get(ri - ropes).copied().unwrap_or(false);
        let any_implied = implied.iter().any(|&m| m);
        self.row_implied.clear();
        if any_implied {
            self.row_implied.extend((0..rows.len()).map(&is_implied));
        }
        islands::reset(parents, slot_count);
        self.root_flags.clear();
        self.root_flags.resize(slot_count, 0);
        self.off_tree.clear();
        self.off_tree.resize(rows.len(), false);
        self.row_tier.clear();
        // Across gravity: `n·g = 0`, read off one component when gravity
        // lies along an axis (the usual case; no product).
        let across_gravity = |n: Vec2<S>| {
            if gravity.x == S::ZERO {
                n.y == S::ZERO
            } else if gravity.y == S::ZERO {
                n.x == S::ZERO
            } else {
                n.dot(gravity) == S::ZERO
            }
        };
        // Rows apart that the velocities close beyond their target
        // (`J·v < b`: they meet within the substep and will carry
        // impulse) are taken before the other rows apart: listed here, and
        // marked [`MEETING`] in `row_tier` while the trees are picked.
        self.meeting_rows.clear();
        for (ri, row) in rows.iter().enumerate() {
            let mut t = tier(row, slop, across_gravity);
            if t == APART_TIER
                && let (Some(&va), Some(&vb)) = (
                    velocities.get(row.a as usize),
                    velocities.get(row.b as usize),
                )
                && let approach = (vb - va).dot(row.normal)
                && approach < row.target_velocity
            {
                t = MEETING;
                // When it meets: `t = d/c` for its gap `d > slop` and
                // closing speed `c = −J·v` (a speculative contact's target
                // is `−d/h`, so `c > d/h` and `t < h`), kept as the bits
                // of `t`, which order as `t` does while it is positive
                // (a row whose target is not `−d/h` gets some other
                // saturated or negative value: deterministic still).
                let when = row.separation.div(approach.neg()).to_hash_bits();
                self.meeting_rows.push((when, ri));
            }
            self.row_tier.push(t);
        }
        // Soonest first: the rows of one body that all meet within the
        // substep (a ball arriving on the seam of two columns, every box
        // below it within the margin) join it to the tree by the rows it
        // meets first, the ones that will carry its impact. Ties in index
        // order (a total order: deterministic without a stable sort).
        self.meeting_rows.sort_unstable();
        self.row_rise.clear();
        self.row_rise.extend(
            rows.iter()
                .map(|row| rise(row.normal, gravity, across_gravity(row.normal))),
        );
        // Join the two ends of every row that are both dynamic (the same
        // union as `islands::union`, lower root kept), tier by tier. A row
        // whose ends are already joined closes a cycle: it is off the
        // tree, and its group is cyclic (which spares `plan_tree` the
        // check; rows to fixed bodies never close one).
        for (pass, kind) in (0..2 * TIERS).map(|k| (k % TIERS, k / TIERS)) {
            let apart = pass == APART_TIER;
            let kind_rows = if kind == 0 {
                0..ropes
            } else {
                ropes..rows.len()
            };
            let meeting = if apart {
                self.meeting_rows.as_slice()
            } else {
                &[]
            };
            let listed = meeting
                .iter()
                .map(|&(_, ri)| ri)
                .filter(|ri| kind_rows.contains(ri));
            let scanned = (kind_rows.start..kind_rows.end).filter(|&ri| self.row_tier[ri] == pass);
            for ri in listed.chain(scanned) {
                if any_implied && is_implied(ri) {
                    continue;
                }
                let row = &rows[ri];
                let (ra, rb) = (islands::find(parents, row.a), islands::find(parents, row.b));
                if ra == rb {
                    self.root_flags[ra as usize] |=
                        if apart { APART_CYCLE } else { TOUCHING_CYCLE };
                    self.off_tree[ri] = true;
                } else {
                    let (keep, gone) = if ra < rb { (ra, rb) } else { (rb, ra) };
                    parents[gone as usize] = keep;
                    let flags = self.root_flags[gone as usize]
                        | if apart { APART_EDGE } else { TOUCHING_EDGE };
                    self.root_flags[keep as usize] |= flags;
                }
            }
        }
        for &(_, ri) in &self.meeting_rows {
            self.row_tier[ri] = APART_TIER;
        }
        // The implied rows between dynamic bodies, last: their ends are
        // joined by the rows implying them, so they close cycles, which do
        // not count (no flag).
        if any_implied {
            for (ri, (row, &t)) in rows.iter().zip(&self.row_tier).enumerate().skip(ropes) {
                if t == NO_TIER || !is_implied(ri) {
                    continue;
                }
                let (ra, rb) = (islands::find(parents, row.a), islands::find(parents, row.b));
                if ra == rb {
                    self.off_tree[ri] = true;
                } else {
                    let (keep, gone) = if ra < rb { (ra, rb) } else { (rb, ra) };
                    parents[gone as usize] = keep;
                    let flags = self.root_flags[gone as usize] | APART_EDGE;
                    self.root_flags[keep as usize] |= flags;
                }
            }
        }
        // Every slot at its root: the lookups below are one read each.
        islands::flatten(parents);
        // The group of a row is the root of its (first) dynamic end; groups
        // are numbered in the order their first row appears.
        self.root_group.clear();
        self.root_group.resize(slot_count, u32::MAX);
        self.row_group.clear();
        self.starts.clear();
        self.cyclic.clear();
        self.support.clear();
        for (row, &t) in rows.iter().zip(&self.row_tier) {
            let end = if row.inverse_mass_b.is_positive() {
                row.b
            } else {
                row.a
            };
            let root = parents.get(end as usize).copied().unwrap_or(end) as usize;
            let group = match self.root_group.get(root).copied() {
                Some(g) if g != u32::MAX => g,
                _ => {
                    let g = u32::try_from(self.starts.len()).unwrap_or(u32::MAX);
                    if let Some(slot) = self.root_group.get_mut(root) {
                        *slot = g;
                    }
                    self.starts.push(0);
                    let flags = self.root_flags.get(root).copied();
                    self.cyclic.push(flags.is_none_or(cyclic));
                    self.support.push(flags.map_or(0, |f| f & TOUCHING_EDGE));
                    g
                }
            };
            if t == NO_TIER
                && row.separation <= slop
                && let Some(f) = self.support.get_mut(group as usize)
            {
                *f |= GROUNDED;
            }
            self.row_group.push(group);
            if let Some(count) = self.starts.get_mut(group as usize) {
                *count += 1;
            }
        }
        // The implied rows with a body of infinite mass leave the spanning
        // tree too (the others are off it already): in a cyclic group as
        // well, where one that the exact solve took in (a box's row to the
        // ground through the box below it) made the row of the box below
        // dependent, which the solve then left out, so that the box could
        // sink by the implied row's gap into the box below.
        if any_implied {
            for (ri, &t) in self.row_tier.iter().enumerate() {
                if t == NO_TIER && is_implied(ri) {
                    self.off_tree[ri] = true;
                }
            }
        }
        // Counts → starts (exclusive prefix sums), then place the rows in
        // ascending order within their group.
        let mut next = 0;
        for entry in &mut self.starts {
            let count = *entry;
            *entry = next;
            next += count;
        }
        self.starts.push(next);
        self.rows.clear();
        self.rows.resize(rows.len(), 0);
        for (r, &g) in self.row_group.iter().enumerate() {
            let cursor = &mut self.starts[g as usize];
            self.rows[*cursor] = r;
            *cursor += 1;
        }
        // Each start was advanced by its group's size: it now holds the next
        // group's start. Shift them back by one place.
        for g in (1..self.starts.len()).rev() {
            self.starts[g] = self.starts[g - 1];
        }
        if let Some(first) = self.starts.first_mut() {
            *first = 0;
        }
    }

    /// The group of row `r` (as of the last regroup), if `r` is a row.
    pub(crate) fn group_of_row(&self, r: usize) -> Option<usize> {
        self.row_group.get(r).map(|&g| g as usize)
    }

    /// Group `g`'s rows and how the velocity sweeps solve it.
    pub(crate) fn group(&self, g: usize) -> Option<(&[usize], &GroupSolve)> {
        let (start, end) = (*self.starts.get(g)?, *self.starts.get(g + 1)?);
        Some((self.rows.get(start..end)?, &self.modes.get(g)?.0))
    }

    /// The groups in order, each a slice of row indices.
    pub(crate) fn iter(&self) -> impl Iterator<Item = &[usize]> {
        self.starts.windows(2).map(|w| &self.rows[w[0]..w[1]])
    }

    /// Decides, per group, how the sweeps solve it.
    ///
    /// * A group whose rows carrying impulse or touching form a tree (a
    ///   stack, a chain of ropes, a bob on the ground; also a stack of thin
    ///   boxes, where each box sees the one two below within the
    ///   speculative margin: that row is apart and off the tree) is solved
    ///   exactly in linear time by [`crate::solver::tree_solve`] when
    ///   it holds a rope (the rows below `rope_rows`: a rope group, with
    ///   any contacts its bodies have), when it has 3 rows or more, when its
    ///   masses are uneven, or when it has two rows that sequential
    ///   impulses converge on slowly ([`coupled_pair`]: a ball on a crate
    ///   on the ground); its rows off the tree take sequential impulses
    ///   after the exact solve in every sweep. Sequential impulses need
    ///   `O(n²)` sweeps to carry a correction along a chain of `n` rows,
    ///   which is what let a 30-box stack sag; two rows barely coupled (a
    ///   ball on the ground touching a wall) converge in a sweep or two and
    ///   skip the planning.
    /// * A group with a cycle among such rows and uneven masses (or ropes):
    ///   the dense block solver up to [`MAX_BLOCK`] rows; above, the exact
    ///   solve on each of a few spanning trees that together hold every
    ///   row ([`crate::solver::forest_cover`]; the first picked along the
    ///   load paths by [`RowGroups::regroup`]), one after another in every
    ///   sweep: each row is then solved exactly together with the load
    ///   path below it. One tree with the rows off it by sequential
    ///   impulses let a heavy top row sink through an 8-row pile of light
    ///   balls (×100: 3.4) and balls leave a closed box; a pyramid of heavy
    ///   boxes on light ones, which sequential impulses alone leave sagging
    ///   0.4 and awake, rests within the slop either way. Rope groups with at most
    ///   [`MAX_LOOP_ROWS`] rows off the tree (rings, ladders) keep one
    ///   spanning tree and take its solve at any size, with those rows
    ///   solved exactly together with the tree (`solver::tree_solve`, loop
    ///   closure).
    /// * A cyclic group of even masses that rests (a pyramid, a brick wall,
    ///   a wall of equal boxes: its touching rows join it, it touches a
    ///   body of infinite mass, and no two of its bodies approach or part
    ///   faster than one substep of gravity, [`resting_or_struck`]), or
    ///   rests but for one body striking it (two columns of thin boxes
    ///   side by side, a ball arriving on one of them) and for boxes
    ///   pressed together or parting along their faces (the columns in
    ///   the substeps after the impact), and has at most
    ///   [`CYCLIC_TREE_ROWS`] rows: the same spanning-tree solve. Sequential
    ///   impulses left a 10-row pyramid of equal boxes 0.0037 low (bound
    ///   10·slop = 0.001) and pass a load down `n` rows only in `O(n²)`
    ///   sweeps: a ball at 50 units/s pushed boxes of such a column wholly
    ///   into the ones below.
    /// * A cyclic group of even masses that rests on nothing (no row
    ///   touching joins it, or none touches a body of infinite mass),
    ///   struck by one body ([`resting_or_struck`]; some row closing faster
    ///   than `rest_speed` and beyond its target, [`impact_within`]): the
    ///   exact sparse solve ([`crate::solver::sparse_solve`]), if planned.
    ///   Its bodies may touch each other at a slant at rest relative to
    ///   each other (a row flush along the ball's flight).
    ///   A ball driving a row of free bodies of its mass along its flight
    ///   has rows with each of them (within the margin of its flight), and
    ///   they close cycles with the bodies' rows to each other; those rows
    ///   lie along one line, nearly dependent (the ball's row with the
    ///   second body says almost what its row with the first and the
    ///   first's with the second say), and the 8 sweeps of sequential
    ///   impulses did not converge on them: a ball at 2000 units/s into two
    ///   circles of its mass at a slant left the first closing on the
    ///   second at 23.4 units/s against the 3 units/s their 0.05 gap
    ///   allows, 0.18 inside it a tick later (issue 13). The sparse solve's
    ///   regularisation takes dependent rows. Crowds and piles struck by
    ///   many bodies at once, resting or not, keep the cheaper solves below.
    /// * The rest (cyclic groups of even masses in motion at a slant, such
    ///   as a ball pit being filled, or larger than [`CYCLIC_TREE_ROWS`]) take
    ///   sequential impulses, whose cost stays linear. The spanning-tree
    ///   solve's active-set rounds cost far more where contacts come and go
    ///   (a floor pile of the 5 000-ball pit, 1 400–2 900 rows in its first
    ///   second: +60 % instructions for the whole step) and on the largest
    ///   piles (a 5 000-box pyramid: 3.6 → 24 ms a step).
    ///
    /// The velocity sweeps leave bouncing groups (a restitution target
    /// above zero) to sequential impulses: solving simultaneous impacts
    /// exactly with restitution targets can create energy (three balls
    /// meeting at once), while the sequential order dissipates it; resting
    /// and speculative rows (targets ≤ 0) are where the exact solve pays
    /// off.
    pub(crate) fn classify<S: Scalar>(
        &mut self,
        rows: &[ContactConstraint<S>],
        slot_count: usize,
        rope_rows: usize,
        velocities: &[Vec2<S>],
        rest_speed: S,
    ) {
        self.modes.clear();
        self.plans.clear();
        self.trees.clear();
        self.sparse_order.clear();
        self.sparse_first.clear();
        self.cover.reset(rows.len(), slot_count);
        // The groups' row lists, out of `self` while the planners borrow it.
        let grouped = core::mem::take(&mut self.rows);
        for g in 0..self.cyclic.len() {
            let cyclic = self.cyclic[g];
            let supported = self.support[g] == TOUCHING_EDGE | GROUNDED;
            let group = &grouped[self.starts[g]..self.starts[g + 1]];
            // A group holding a rope (its rows ascend, ropes first) is
            // solved as a rope group, contacts and all.
            let always_direct = group.first().is_some_and(|&ri| ri < rope_rows);
            let position = if group.len() < 2 {
                GroupSolve::Sequential
            } else {
                let wanted = always_direct
                    || group.len() >= 3
                    || uneven_masses(rows, group)
                    || coupled_pair(rows, group);
                let direct = always_direct || uneven_masses(rows, group);
                // Rope loops that the tree solve closes exactly take it at
                // any size (the block solver leaves rings of light links
                // 0.16 % long for a second where the closed tree holds the
                // slop, at a fraction of its O(n³) cost).
                // Its contacts off the tree take sequential impulses.
                let closable = || {
                    always_direct
                        && group
                            .iter()
                            .filter(|&&ri| ri < rope_rows && self.off_tree[ri])
                            .count()
                            <= MAX_LOOP_ROWS
                };
                let block = cyclic && direct && group.len() <= MAX_BLOCK && !closable();
                let start = self.plans.len();
                let affordable = cyclic
                    && !direct
                    && supported
                    && group.len() <= CYCLIC_TREE_ROWS
                    && resting_or_struck(rows, group, velocities, rest_speed, &self.row_tier, true);
                // Contacts only: rope loops keep their one spanning tree
                // (the rope solves carry sideways rows the covering was
                // not measured with).
                // An even-mass cyclic group resting on nothing, struck by
                // one body (a ball driving a row of free bodies): the
                // exact sparse solve, else sequential impulses as before.
                let struck_free = cyclic
                    && !direct
                    && !always_direct
                    && !supported
                    && impact_within(rows, group, velocities, rest_speed)
                    && resting_or_struck(
                        rows,
                        group,
                        velocities,
                        rest_speed,
                        &self.row_tier,
                        false,
                    );
                if cyclic && (direct || struck_free) && !always_direct {
                    let at = self.sparse_order.len();
                    if plan_sparse(
                        rows,
                        group,
                        &mut self.sparse_planner,
                        &mut self.sparse_order,
                        &mut self.sparse_first,
                    ) {
                        GroupSolve::Sparse(at..self.sparse_order.len())
                    } else if block {
                        GroupSolve::Block
                    } else if struck_free {
                        GroupSolve::Sequential
                    } else {
                        self.plan_trees(rows, group, slot_count)
                    }
                } else if wanted
                    && (!cyclic || direct || affordable)
                    && !block
                    && plan_tree(
                        rows,
                        group,
                        &self.off_tree,
                        slot_count,
                        &mut self.planner,
                        &mut self.plans,
                    )
                {
                    GroupSolve::Tree(start..self.plans.len())
                } else if block {
                    GroupSolve::Block
                } else {
                    GroupSolve::Sequential
                }
            };
            let bouncing = position != GroupSolve::Sequential
                && group
                    .iter()
                    .any(|&ri| rows[ri].target_velocity.is_positive());
            let velocity = if bouncing {
                GroupSolve::Sequential
            } else {
                position.clone()
            };
            self.modes.push((velocity, position));
        }
        self.rows = grouped;
    }

    /// The groups with their decisions from the last
    /// [`classify`](Self::classify): `(rows, velocity_solve,
    /// position_solve)`.
    pub(crate) fn iter_classified(
        &self,
    ) -> impl Iterator<Item = (&[usize], &GroupSolve, &GroupSolve)> {
        self.iter()
            .zip(&self.modes)
            .map(|(group, (velocity, position))| (group, velocity, position))
    }

    /// The tree plan rows of a [`GroupSolve::Tree`] range.
    pub(crate) fn plan(&self, range: &Range<usize>) -> &[TreeRow] {
        &self.plans[range.clone()]
    }

    /// The elimination order and profile starts of a
    /// [`GroupSolve::Sparse`] range.
    pub(crate) fn sparse(&self, range: &Range<usize>) -> (&[u32], &[u32]) {
        (
            &self.sparse_order[range.clone()],
            &self.sparse_first[range.clone()],
        )
    }

    /// The plan ranges of a [`GroupSolve::Trees`] range.
    pub(crate) fn trees(&self, range: &Range<usize>) -> &[Range<usize>] {
        &self.trees[range.clone()]
    }

    /// Per row: whether it is in none of its group's trees (rows of a
    /// [`GroupSolve::Trees`] group left to sequential impulses).
    pub(crate) fn uncovered(&self) -> &[bool] {
        &self.cover.uncovered
    }

    /// Plans the spanning trees covering a cyclic `group`
    /// ([`crate::solver::forest_cover`]): first the one picked along the
    /// load paths, then up to [`MAX_TREES`] in all while rows remain
    /// uncovered. Sequential impulses if not even the first is a tree.
    fn plan_trees<S: Scalar>(
        &mut self,
        rows: &[ContactConstraint<S>],
        group: &[usize],
        slot_count: usize,
    ) -> GroupSolve {
        let first = self.trees.len();
        let start = self.plans.len();
        self.cover.first_tree(
            rows,
            group,
            &self.row_tier,
            &self.row_rise,
            &self.row_implied,
        );
        if !plan_tree(
            rows,
            group,
            &self.cover.off,
            slot_count,
            &mut self.planner,
            &mut self.plans,
        ) {
            return GroupSolve::Sequential;
        }
        self.trees.push(start..self.plans.len());
        self.cover.start(group);
        while self.trees.len() - first < MAX_TREES
            && self.cover.any_uncovered(group, &self.row_implied)
        {
            if self.cover.next_tree(rows, group, &self.row_implied) == 0 {
                break;
            }
            let start = self.plans.len();
            if !plan_tree(
                rows,
                group,
                &self.cover.off,
                slot_count,
                &mut self.planner,
                &mut self.plans,
            ) {
                break;
            }
            self.trees.push(start..self.plans.len());
        }
        GroupSolve::Trees(first..self.trees.len())
    }
}

/// Largest resting cyclic group of even masses given the spanning-tree
/// solve ([`RowGroups::classify`]): a 20 × 20 wall of boxes has 1 502 rows,
/// a 30-row pyramid 1 335; the 5 050-box benchmark pyramid (about 15 000
/// rows) stays on sequential impulses, whose cost it was tuned for.
const CYCLIC_TREE_ROWS: usize = 4096;

/// The coupling `ρ` above which a group of two rows takes the exact solve
/// ([`coupled_pair`]): 3/10, so that the 8 default sweeps leave at most
/// `0.3⁸ ≈ 6.6e-5` of an impact to the other row. A chain of three equal
/// free bodies (`ρ = 1/4`, `1.5e-5` left) stays with sequential impulses;
/// a chain of equal bodies ending on a fixed one (`ρ = 1/2`) does not.
const PAIR_COUPLING: (i32, i32) = (3, 10);

/// Tiers in which [`RowGroups::regroup`] takes the rows.
pub(crate) const TIERS: u8 = 4;
/// The tier of the rows apart.
pub(crate) const APART_TIER: u8 = 3;
/// The tier of a row with a body of infinite mass (never joins two).
pub(crate) const NO_TIER: u8 = u8::MAX;
/// A row apart that meets within the substep, while
/// [`RowGroups::regroup`] picks the trees (it is [`APART_TIER`] after).
const MEETING: u8 = TIERS;

/// The tier in which [`RowGroups::regroup`] takes a row: 0 carrying
/// impulse, 1 touching within `slop` along a normal that can carry weight
/// (`n·g ≠ 0`), 2 touching along a normal across gravity
/// (`across_gravity`), 3 apart; [`NO_TIER`] for a row to a body of
/// infinite mass.
#[inline]
fn tier<S: Scalar>(
    row: &ContactConstraint<S>,
    slop: S,
    across_gravity: impl Fn(Vec2<S>) -> bool,
) -> u8 {
    if !(row.inverse_mass_a.is_positive() && row.inverse_mass_b.is_positive()) {
        NO_TIER
    } else if row.normal_impulse.is_positive() {
        0
    } else if row.separation > slop {
        APART_TIER
    } else if across_gravity(row.normal) {
        2
    } else {
        1
    }
}

/// [`rise`]: the row's `b` end is the upper one (the normal, from `a` to
/// `b`, points against gravity); otherwise `a` is, unless [`ACROSS`].
pub(crate) const RISE_B: u8 = 1;
/// [`rise`]: the normal is across gravity (`n·g = 0`: side by side), or
/// there is no gravity; neither end holds the other up.
pub(crate) const ACROSS: u8 = 2;
/// [`rise`]: the normal is neither along nor across gravity (a ball on two
/// balls below: its supports push their bodies apart sideways).
pub(crate) const OBLIQUE: u8 = 4;

/// How a row's normal `n` lies against `gravity`: [`RISE_B`], [`ACROSS`]
/// and [`OBLIQUE`] flags (`across` is `n·g = 0`, computed by the caller).
/// Read off one component when gravity lies along an axis (no product).
#[inline]
fn rise<S: Scalar>(n: Vec2<S>, gravity: Vec2<S>, across: bool) -> u8 {
    if across || gravity == Vec2::new(S::ZERO, S::ZERO) {
        return ACROSS;
    }
    let (along, up_b) = if gravity.x == S::ZERO {
        (n.x == S::ZERO, (n.y > S::ZERO) == (gravity.y < S::ZERO))
    } else if gravity.y == S::ZERO {
        (n.y == S::ZERO, (n.x > S::ZERO) == (gravity.x < S::ZERO))
    } else {
        (n.cross(gravity) == S::ZERO, n.dot(gravity).is_negative())
    };
    (if up_b { RISE_B } else { 0 }) | if along { 0 } else { OBLIQUE }
}

/// A cycle closed by a row carrying impulse or touching.
const TOUCHING_CYCLE: u8 = 1;
/// A cycle closed by a row apart (a speculative contact, a slack rope).
const APART_CYCLE: u8 = 2;
/// A row apart joining two parts of the group (an edge of its spanning
/// tree).
const APART_EDGE: u8 = 4;
/// A row carrying impulse or touching joining two parts of the group.
const TOUCHING_EDGE: u8 = 8;
/// A row touching a body of infinite mass (the group rests on something).
const GROUNDED: u8 = 16;

/// Whether a group with these flags counts as cyclic for
/// [`RowGroups::classify`]: a cycle among rows carrying impulse or
/// touching, or a cycle closed by a row apart in a group whose spanning
/// tree also runs through rows apart (a cloud of falling bodies seeing
/// each other within the speculative margin: its rows are all apart, and
/// an exact solve of them buys nothing for its cost). A resting group
/// whose cycles are closed only by rows apart (a stack of thin boxes, each
/// within the speculative margin of the box two below) is not: its
/// touching rows span it as a tree.
fn cyclic(flags: u8) -> bool {
    flags & TOUCHING_CYCLE != 0 || flags & (APART_CYCLE | APART_EDGE) == APART_CYCLE | APART_EDGE
}

/// Whether a group rests, or rests but for one body striking it and for
/// bodies pressed together along faces: the spanning-tree solve of an
/// even-mass cyclic group ([`RowGroups::classify`]).
///
/// *Resting*: no two of its dynamic bodies approach or part along a row
/// faster than `rest_speed` (one substep of gravity, `|g|·h`: bodies
/// resting on each other share the velocity gravity gave them), and every
/// such row touching or carrying impulse (`tiers`: not [`APART_TIER`]) is
/// along an axis (faces of boxes). With oblique rows touching (a pile of
/// circles) the alternation of the exact tree solve and the rows off the
/// tree did not settle: a 500-circle pile in a closed box never slept in
/// 10 s (it sleeps on sequential impulses). A slow row apart carries
/// nothing and may lie at any angle (a ball resting on a seam sees the
/// boxes below through the seam at a slant).
///
/// *Struck*: the rows faster than `rest_speed` that lie at a slant all
/// hold one body (the striker), and the others are as above. Two columns
/// of thin boxes side by side, a ball arriving at 50–1000 units/s on one
/// of them or on the seam (issue 13): the rows between the columns close
/// cycles, and sequential impulses, which carry an impact down a chain of
/// `n` rows only in `O(n²)` sweeps, left boxes wholly inside the ones
/// below (0.02 deep) and up to 16 units through the ground. The exact
/// solve stops the ball on the column as on the ground. Groups struck by
/// several bodies at once (a pile being filled, the 5 000-ball pit) keep
/// sequential impulses, whose cost stays linear.
///
/// Fast rows along an axis (faces of boxes pressed together or parting)
/// may be any number: an impact passed down a column of boxes leaves the
/// rows of the column closing or opening faster than `rest_speed` for a
/// substep or two. A ball 100× a box at 1 000 units/s, e = 1, on columns
/// of 3 boxes side by side: its bounce drove the boxes of the struck
/// column into each other and the ground at 3–9 units/s, and with the
/// column on sequential impulses the impact's impulses, warm-started into
/// the next substep after the ball had left, were carried back up the
/// column only a row per sweep: the boxes left at `max_speed` (+0.65 of
/// the ball's energy). The exact solve's active set releases them at once.
///
/// A row apart whose gap the current velocities do not close beyond its
/// target within the substep (`J·v ≥ b`) cannot carry impulse there, and
/// is not counted at any speed or slant. A ball 100× a circle bouncing
/// (e = 1) on two columns of 3 circles: after the bounce the struck column
/// moved down at 0.44 units/s (over `|g|·h`) and parted from the next
/// column's circles at a slant, 0.02 apart; counted as fast rows at a
/// slant holding several bodies, they left the group on sequential
/// impulses, which could not take the catch's impulse, warm-started into
/// the next substep, back out of the column in 8 sweeps: the bottom circle
/// left at 465 units/s.
///
/// "Along an axis" is within 2^-10 of it ([`near_axis`]).
///
/// `supported` says which group is asked about:
///
/// * `true`, a group resting on a body of infinite mass, for the
///   spanning-tree solve: rows apart that the velocities do not close
///   within the substep (`J·v ≥ b`) do not count (they carry no impulse),
///   and a slow row touching at a slant makes the group neither resting
///   nor struck (the pile of circles above).
/// * `false`, a group resting on nothing, for the exact sparse solve
///   ([`RowGroups::classify`]): rows apart count as any row (bodies flying
///   past each other at a slant are a crowd in motion, not one body
///   striking the rest, and keep sequential impulses; counted out, groups
///   of balls passing each other in mid-air in the 5 000-ball pit took the
///   sparse solve: +17 % instructions for the pit's second), and slow rows
///   touching at a slant count for nothing: bodies flush with each other
///   in a free row at a slant touch at rest relative to each other when
///   the ball strikes the first, and those rows are the nearly dependent
///   ones that sequential impulses do not converge on (the pile's reason
///   above is about the tree solve's alternation, not the sparse solve's).
///   Counting them, a ball of a circle's mass at 2 000 units/s into two
///   circles flush along its flight at 0.2 rad (e = 0) left the group on
///   sequential impulses, whose 8 sweeps ended with the ball at 1 059
///   units/s behind circles at 460 (the back one) and 441 units/s: a tick
///   later the circles were 0.23 inside each other and the ball 0.15
///   inside the back one (issue 13). The exact solve moves all three on
///   together.
fn resting_or_struck<S: Scalar>(
    rows: &[ContactConstraint<S>],
    group: &[usize],
    velocities: &[Vec2<S>],
    rest_speed: S,
    tiers: &[u8],
    supported: bool,
) -> bool {
    // The striker's candidates: the ends of the first fast row, narrowed
    // by each fast row after it.
    let mut striker: Option<[Option<u32>; 2]> = None;
    for &ri in group {
        let row = &rows[ri];
        if !(row.inverse_mass_a.is_positive() && row.inverse_mass_b.is_positive()) {
            continue;
        }
        let approach = (velocities[row.b as usize] - velocities[row.a as usize]).dot(row.normal);
        if supported && tiers[ri] == APART_TIER && approach >= row.target_velocity {
            continue;
        }
        let speed = approach.abs();
        let axis = near_axis(row.normal);
        if speed <= rest_speed {
            if supported && !axis && tiers[ri] != APART_TIER {
                return false;
            }
            continue;
        }
        // Pressed together or parting along a face: any number.
        if axis {
            continue;
        }
        let ends = [Some(row.a), Some(row.b)];
        let kept = match striker {
            None => ends,
            Some(candidates) => candidates.map(|c| c.filter(|slot| ends.contains(&Some(*slot)))),
        };
        if kept == [None, None] {
            return false;
        }
        striker = Some(kept);
    }
    true
}

/// Whether some row of `group` between two movable bodies closes faster
/// than `rest_speed` and beyond its target (`J·v < b`: it will carry
/// impulse in this solve), so the group is being struck, not resting or
/// flying apart ([`RowGroups::classify`]).
fn impact_within<S: Scalar>(
    rows: &[ContactConstraint<S>],
    group: &[usize],
    velocities: &[Vec2<S>],
    rest_speed: S,
) -> bool {
    group.iter().any(|&ri| {
        let row = &rows[ri];
        if !(row.inverse_mass_a.is_positive() && row.inverse_mass_b.is_positive()) {
            return false;
        }
        let approach = (velocities[row.b as usize] - velocities[row.a as usize]).dot(row.normal);
        approach < row.target_velocity && approach.neg() > rest_speed
    })
}

/// Whether a row's normal lies along an axis for [`resting_or_struck`]:
/// its other component is at most 2^-10 (the normal's angle to the axis
/// under 0.06°; the weight passed along the row pushes sideways by under
/// 0.1 % of it). Circles stacked in columns touching side by side lie
/// exactly along the axes until an impact shifts them sideways by about
/// 1e-6 (5e-5 of a 0.02 diameter): read exactly, their rows were then
/// at a slant, the group kept sequential impulses after the impact, and
/// the circles sank up to 5e-3 into the ones below, or (the impact's
/// impulses warm-started into them) went through the ground (60 of 144
/// throws, issue 13). A pile of circles lies at slants of 30° and more,
/// far outside this.
#[inline]
fn near_axis<S: Scalar>(n: Vec2<S>) -> bool {
    let near = S::from_ratio(1, 1024);
    n.x.abs() <= near || n.y.abs() <= near
}

/// Whether the dynamic bodies of a group differ in inverse mass by 4× or
/// more. Sequential impulses converge at a rate of about
/// `1 − w_min/(w_min + w_max)` per sweep, so groups of equal masses (stacks,
/// ball piles) converge well with them and skip the cost of the direct
/// solve, while a heavy body on a light one (1:100) needs it. Ropes are
/// always solved directly: a chain converges slowly even with equal masses.
fn uneven_masses<S: Scalar>(rows: &[ContactConstraint<S>], group: &[usize]) -> bool {
    let mut low = S::MAX;
    let mut high = S::ZERO;
    for &ri in group {
        for w in [rows[ri].inverse_mass_a, rows[ri].inverse_mass_b] {
            if w.is_positive() {
                low = low.min(w);
                high = high.max(w);
            }
        }
    }
    high >= low.mul_int(4)
}

/// Whether a group of two rows is one that sequential impulses leave
/// short after a sweep's worth of iterations: its rows are coupled by more
/// than [`PAIR_COUPLING`].
///
/// Gauss–Seidel on two rows `p`, `q` (Jacobians `J_p`, `J_q`, inverse mass
/// matrix `W`) takes out a factor `ρ = (J_p·W·J_qᵀ)² / ((J_p·W·J_pᵀ)(J_q·W·J_qᵀ))`
/// of the error per sweep, the squared cosine of the rows in the mass
/// metric. Bodies do not rotate, so `J_p·W·J_qᵀ = (n_p·n_q)·Σ ±w` over the
/// movable bodies the rows share (`+` where it is the same end of both),
/// and `J·W·Jᵀ = w_a + w_b = 1/m_eff`. A ball `M` on a crate `m` on the
/// ground: `ρ = M/(M + m)`, 1/2 for equal masses, 0.66 and 0.80 for crates
/// of half and a quarter of the ball (masses within 4×, so not
/// [`uneven_masses`]): 8 sweeps left 0.4 %, 3.6 % and 16 % of the impact,
/// and the crate sank 7.3e-4 and 3.9e-3 into the ground, the ball's
/// rebound rising by as much (issue 13, F1); a ball pushing an equal box
/// into a wall at 300 units/s ended 1.5e-3 inside the box (N7). Those
/// chains take the exact tree solve.
fn coupled_pair<S: Scalar>(rows: &[ContactConstraint<S>], group: &[usize]) -> bool {
    let &[i, j] = group else {
        return false;
    };
    let (p, q) = (&rows[i], &rows[j]);
    let mut shared = S::ZERO;
    for (slot, w, end) in [(p.a, p.inverse_mass_a, 0), (p.b, p.inverse_mass_b, 1)] {
        if !w.is_positive() {
            continue;
        }
        for (other, other_end) in [(q.a, 0), (q.b, 1)] {
            if slot == other {
                shared = if end == other_end {
                    shared.add(w)
                } else {
                    shared.sub(w)
                };
            }
        }
    }
    // d·m_p and d·m_q are each at most 1 in magnitude (|n_p·n_q| ≤ 1, the
    // shared w at most each row's w_a + w_b): no overflow.
    let d = shared.mul(p.normal.dot(q.normal));
    let rho = d.mul(p.effective_mass).mul(d.mul(q.effective_mass));
    rho > S::from_ratio(PAIR_COUPLING.0, PAIR_COUPLING.1)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::{Fx, Vec2};

    fn row(a: u32, b: u32, wa: i32, wb: i32) -> ContactConstraint<Fx> {
        ContactConstraint::new(
            a,
            b,
            Vec2::Y,
            Fx::ZERO,
            (Fx::from_int(wa), Fx::from_int(wb)),
            Fx::ONE,
            Fx::ZERO,
            (Fx::ZERO, Fx::ZERO),
        )
    }

    fn grouped(rows: &[ContactConstraint<Fx>], slots: usize) -> Vec<Vec<usize>> {
        let mut groups = RowGroups::default();
        let mut parents = Vec::new();
        groups.regroup(rows, 0, &[], &[], slots, Fx::ZERO, Vec2::ZERO, &mut parents);
        groups.iter().map(<[usize]>::to_vec).collect()
    }

    #[test]
    fn rows_sharing_a_dynamic_body_are_grouped_in_first_row_order() {
        // Slot 0 is fixed (w = 0): rows touching only it through one dynamic
        // body do not join each other through it.
        let rows = [
            row(0, 3, 0, 1), // group A (body 3)
            row(1, 2, 1, 1), // group B (bodies 1, 2)
            row(0, 4, 0, 1), // group C (body 4): shares only the fixed body
            row(2, 5, 1, 1), // group B
            row(3, 4, 1, 1), // joins A and C: both become one group
        ];
        assert_eq!(grouped(&rows, 6), vec![vec![0, 2, 4], vec![1, 3]]);
    }

    #[test]
    fn a_group_with_a_cycle_among_dynamic_bodies_is_marked_cyclic() {
        let mut groups = RowGroups::default();
        let mut parents = Vec::new();
        // Group of bodies 1-2-3 closed into a triangle; group of 4-5 hung
        // from fixed body 0 twice (rows to a fixed body close no cycle);
        // two rows between 6 and 7 (two ropes on one pair) are a cycle.
        let rows = [
            row(1, 2, 1, 1),
            row(0, 4, 0, 1),
            row(2, 3, 1, 1),
            row(0, 5, 0, 1),
            row(6, 7, 1, 1),
            row(3, 1, 1, 1),
            row(4, 5, 1, 1),
            row(6, 7, 1, 1),
        ];
        groups.regroup(&rows, 0, &[], &[], 8, Fx::ZERO, Vec2::ZERO, &mut parents);
        assert_eq!(groups.iter().count(), 3);
        assert_eq!(groups.cyclic, vec![true, false, true]);
        let trees = |groups: &RowGroups| -> Vec<bool> {
            groups
                .iter_classified()
                .map(|(_, _, p)| matches!(p, GroupSolve::Tree(_)))
                .collect()
        };
        // Contacts: the cycles (even masses, not resting on anything) are
        // not solved on a tree.
        groups.classify(&rows, 8, 0, &[Vec2::ZERO; 8], Fx::ZERO);
        assert_eq!(trees(&groups), vec![false, true, false]);
        // Ropes: a group with few rows off its spanning tree takes the
        // tree solve, which closes its loops exactly.
        groups.classify(&rows, 8, rows.len(), &[Vec2::ZERO; 8], Fx::ZERO);
        assert_eq!(trees(&groups), vec![true, true, true]);
    }

    #[test]
    fn regrouping_reuses_buffers_and_forgets_old_groups() {
        let mut groups = RowGroups::default();
        let mut parents = Vec::new();
        let first = [row(0, 1, 1, 1), row(2, 3, 1, 1), row(1, 2, 1, 1)];
        groups.regroup(&first, 0, &[], &[], 4, Fx::ZERO, Vec2::ZERO, &mut parents);
        assert_eq!(groups.iter().count(), 1);
        let second = [row(0, 1, 1, 1), row(2, 3, 1, 1)];
        groups.regroup(&second, 0, &[], &[], 4, Fx::ZERO, Vec2::ZERO, &mut parents);
        let got: Vec<Vec<usize>> = groups.iter().map(<[usize]>::to_vec).collect();
        assert_eq!(got, vec![vec![0], vec![1]]);
        groups.regroup::<Fx>(&[], 0, &[], &[], 4, Fx::ZERO, Vec2::ZERO, &mut parents);
        assert_eq!(groups.iter().count(), 0);
    }
}
