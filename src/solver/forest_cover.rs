//! Covering the rows of a cyclic group with a few spanning trees, so that
//! every row is solved exactly in some tree (a block Gauss–Seidel whose
//! blocks are whole load paths down to the fixed bodies).
//!
//! # Why
//!
//! A pile with cycles (balls in a container, a pyramid) has no tree solve.
//! Taking one spanning tree and leaving the rows off it to sequential
//! impulses fails when the masses are uneven: a heavy ball resting on two
//! light ones has one support on the tree and the other off it, and the
//! off-tree row's impulse `λ = e/(w_heavy + w_light)` moves mostly the
//! *light* body, into the bodies below it; the next exact solve pushes
//! it back. Each sweep removes only about `w_heavy/w_light` of the heavy
//! body's error (1/100 at a 1:100 ratio), so a heavy top row sank through
//! an 8-row pile of light balls and the pile never slept.
//!
//! With several spanning trees that together contain every row, each row
//! is solved exactly *with the whole load path below it*: in the tree that
//! holds the heavy ball's second support, the light ball under it is
//! itself held exactly by its own supports down to the ground and walls.
//! What one tree's solve does to the rows of another is then a matter of
//! the angle between their normals, not of the masses: for a body held by
//! two rigid supports the alternation is a projection onto one support
//! plane and then the other, which shrinks the error by `cos²θ` per sweep
//! (`θ` the angle between the normals, 60° in a hexagonal packing: 1/4).
//!
//! # How many trees
//!
//! Rows to fixed bodies never close a cycle and are in every tree, except
//! rows implied by two others through a movable body
//! ([`crate::collision`]'s implied rows), which are in none: one kept
//! made a row implying it dependent in the exact solve, which then left it
//! out (a box of a thin column sank wholly into the box below). The
//! first tree is the one [`crate::solver::row_groups::RowGroups::regroup`]
//! picked along the load paths; each next one is Kruskal's rule over the
//! rows not yet covered first, then the covered ones (loaded first). A
//! planar contact graph (discs, non-rotating boxes) is the union of three
//! forests (Nash-Williams; arboricity ≤ 3), and greedy covering takes a few
//! more at worst: rows left uncovered after [`MAX_TREES`] trees take
//! sequential impulses.

use crate::math::Scalar;
use crate::solver::row::ContactConstraint;
use crate::solver::row_groups::{ACROSS, APART_TIER, NO_TIER, OBLIQUE, RISE_B};

/// Most spanning trees built for one group.
pub(crate) const MAX_TREES: usize = 4;

/// Working memory of the covering and its result: which rows are in no
/// tree.
#[derive(Clone, Debug, Default)]
pub(crate) struct ForestCover {
    /// Union-find over body slots; every slot is its own root between uses.
    parents: Vec<u32>,
    /// Per body slot: held up by a row of the tree being picked
    /// ([`first_tree`](Self::first_tree)); false between uses.
    supported: Vec<bool>,
    /// Per row: off the tree built last ([`next_tree`](Self::next_tree)).
    pub(crate) off: Vec<bool>,
    /// Per row: in none of the trees built so far for its group (entries
    /// of rows in other groups are stale). The solves give these rows
    /// sequential impulses.
    pub(crate) uncovered: Vec<bool>,
}

impl ForestCover {
    /// Sizes the buffers for `rows` rows and `slots` slots. Nothing is
    /// cleared: [`start`](Self::start) and [`next_tree`](Self::next_tree)
    /// write every entry of their group before it is read, and the solves
    /// read them for the groups covered here only.
    pub(crate) fn reset(&mut self, rows: usize, slots: usize) {
        if self.off.len() < rows {
            self.off.resize(rows, false);
            self.uncovered.resize(rows, false);
        }
        let have = self.parents.len();
        if have < slots {
            self.parents
                .extend((have..slots).map(|i| u32::try_from(i).unwrap_or(u32::MAX)));
        }
    }

    /// Picks the first spanning tree of `group` along its load paths (its
    /// rows off it marked in [`off`](Self::off)): Kruskal's rule over the
    /// rows in this order —
    ///
    /// 1. rows carrying impulse from the last substep whose normal can
    ///    carry weight, then such rows touching within the slop (`tiers`
    ///    from [`RowGroups::regroup`](crate::solver::row_groups::RowGroups::regroup)),
    ///    each taken only as the *first* support of the body it holds up
    ///    when its normal is oblique (`rises`, [`OBLIQUE`]);
    /// 2. rows side by side (across gravity), carrying impulse first;
    /// 3. the second oblique supports left out in 1;
    /// 4. rows apart.
    ///
    /// Why one oblique support per body: a ball resting on two balls below
    /// pushes them apart sideways. A tree holding both supports of every
    /// ball of a row, and not the side rows between the balls below,
    /// is a zigzag the tree solve can flatten like an accordion: before
    /// any row carried impulse (the first substep), an 8-row pile of balls
    /// in an exact-width container took this tree, its bottom row spread
    /// 4.6e-4 in one step (one step of gravity was 0.003) and the pile
    /// ended at its slop bound. With one support per ball and the side rows
    /// below it tied, each ball hangs on a path straight down to the
    /// ground, which is how the load goes: 2.4e-6 in that step. Supports
    /// along gravity (a brick on two bricks) push nothing apart and are all
    /// taken in 1. Rows to bodies of infinite mass are in every tree; one
    /// that holds its body up counts as its first support. Rows marked in
    /// `implied` (per row; empty: none) are in no tree (module notes).
    pub(crate) fn first_tree<S: Scalar>(
        &mut self,
        rows: &[ContactConstraint<S>],
        group: &[usize],
        tiers: &[u8],
        rises: &[u8],
        implied: &[bool],
    ) {
        if self.supported.len() < self.parents.len() {
            self.supported.resize(self.parents.len(), false);
        }
        // The body a row holds up, if it holds one up.
        let upper = |ri: usize| {
            let (row, rise) = (&rows[ri], rises[ri]);
            if rise & ACROSS != 0 {
                None
            } else if rise & RISE_B != 0 {
                row.inverse_mass_b.is_positive().then_some(row.b)
            } else {
                row.inverse_mass_a.is_positive().then_some(row.a)
            }
        };
        let implied = |ri: usize| implied.get(ri).copied().unwrap_or(false);
        for &ri in group {
            if implied(ri) {
                // Implied by rows of the group: in no tree (left to the
                // sequential update after the exact solves).
                self.off[ri] = true;
                self.uncovered[ri] = false;
                continue;
            }
            if tiers[ri] == NO_TIER {
                self.off[ri] = false;
                if let Some(body) = upper(ri) {
                    self.supported[body as usize] = true;
                }
            }
        }
        // Passes: 0 loaded supports, 1 touching supports, 2 loaded side
        // rows, 3 touching side rows, 4 second oblique supports, 5 apart.
        let pass_of = |ri: usize| match (tiers[ri], rises[ri] & ACROSS != 0) {
            _ if implied(ri) => None,
            (NO_TIER, _) => None,
            (0, false) => Some(0),
            (0, true) => Some(2),
            (1, _) => Some(1),
            (t, _) if t == APART_TIER => Some(5),
            _ => Some(3),
        };
        for pass in 0..6 {
            for &ri in group {
                let own = pass_of(ri);
                let deferred = pass == 4 && matches!(own, Some(0 | 1)) && self.deferred(ri);
                if own != Some(pass) && !deferred {
                    continue;
                }
                let holds = if pass < 2 { upper(ri) } else { None };
                if let Some(body) = holds
                    && rises[ri] & OBLIQUE != 0
                    && self.supported[body as usize]
                {
                    // A second oblique support: pass 4.
                    self.off[ri] = true;
                    self.mark_deferred(ri, true);
                    continue;
                }
                self.mark_deferred(ri, false);
                let row = &rows[ri];
                let (ra, rb) = (self.find(row.a), self.find(row.b));
                if ra == rb {
                    self.off[ri] = true;
                } else {
                    self.off[ri] = false;
                    self.parents[ra.max(rb) as usize] = ra.min(rb);
                    if let Some(body) = holds {
                        self.supported[body as usize] = true;
                    }
                }
            }
        }
        self.release(rows, group);
    }

    /// Starts covering `group`, whose first tree
    /// ([`first_tree`](Self::first_tree)) left out the rows now marked in
    /// [`off`](Self::off).
    pub(crate) fn start(&mut self, group: &[usize]) {
        for &ri in group {
            self.uncovered[ri] = self.off[ri];
        }
    }

    /// Whether some row of `group` is in no tree yet, the rows marked in
    /// `implied` aside (they are in none, by design).
    pub(crate) fn any_uncovered(&self, group: &[usize], implied: &[bool]) -> bool {
        group
            .iter()
            .any(|&ri| self.uncovered[ri] && !implied.get(ri).copied().unwrap_or(false))
    }

    /// Picks the next spanning tree of `group` (its rows off it marked in
    /// [`off`](Self::off)), taking the uncovered rows first, and marks the
    /// rows it covers; returns how many rows it newly covers. Rows marked
    /// in `implied` stay off it and uncovered.
    pub(crate) fn next_tree<S: Scalar>(
        &mut self,
        rows: &[ContactConstraint<S>],
        group: &[usize],
        implied: &[bool],
    ) -> usize {
        let implied = |ri: usize| implied.get(ri).copied().unwrap_or(false);
        // Tiers: 0 uncovered, 1 covered and loaded, 2 the rest.
        let tier = |ri: usize, uncovered: &[bool]| {
            if uncovered[ri] {
                0
            } else if rows[ri].normal_impulse.is_positive() {
                1
            } else {
                2
            }
        };
        for pass in 0..3 {
            for &ri in group {
                if tier(ri, &self.uncovered) != pass {
                    continue;
                }
                let row = &rows[ri];
                if implied(ri) {
                    self.off[ri] = true;
                    continue;
                }
                if !(row.inverse_mass_a.is_positive() && row.inverse_mass_b.is_positive()) {
                    // A row to a fixed body closes no cycle.
                    self.off[ri] = false;
                    continue;
                }
                let (ra, rb) = (self.find(row.a), self.find(row.b));
                if ra == rb {
                    self.off[ri] = true;
                } else {
                    self.off[ri] = false;
                    self.parents[ra.max(rb) as usize] = ra.min(rb);
                }
            }
        }
        self.release(rows, group);
        let mut newly = 0;
        for &ri in group {
            if self.uncovered[ri] && !self.off[ri] {
                self.uncovered[ri] = false;
                newly += 1;
            }
        }
        newly
    }

    /// Every slot of `group` back to its own root and unsupported, ready
    /// for the next tree or group.
    fn release<S: Scalar>(&mut self, rows: &[ContactConstraint<S>], group: &[usize]) {
        for &ri in group {
            for slot in [rows[ri].a, rows[ri].b] {
                if let Some(parent) = self.parents.get_mut(slot as usize) {
                    *parent = slot;
                }
                if let Some(flag) = self.supported.get_mut(slot as usize) {
                    *flag = false;
                }
            }
        }
    }

    /// Whether [`first_tree`](Self::first_tree) left row `ri` for its
    /// pass of second oblique supports.
    fn deferred(&self, ri: usize) -> bool {
        self.uncovered[ri]
    }

    /// Marks row `ri` as left for the pass of second oblique supports
    /// (kept in [`uncovered`](Self::uncovered), which
    /// [`start`](Self::start) overwrites afterwards).
    fn mark_deferred(&mut self, ri: usize, deferred: bool) {
        self.uncovered[ri] = deferred;
    }

    /// The root of `slot` (path halving).
    fn find(&mut self, slot: u32) -> u32 {
        let mut node = slot;
        loop {
            let parent = self.parents[node as usize];
            if parent == node {
                return node;
            }
            let grandparent = self.parents[parent as usize];
            self.parents[node as usize] = grandparent;
            node = grandparent;
        }
    }
}
