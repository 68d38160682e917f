//! A direct (block) solver for groups of ropes that share bodies: chains.
//!
//! Sequential impulses converge slowly on chains: each rope only "sees" its
//! neighbours through one Gauss–Seidel sweep, so a light link between a
//! fixed point and a heavy bob (mass ratio 100) keeps over 90 % of its error
//! after 8 iterations and the chain stretches by several percent. Ropes
//! that share a dynamic body are therefore solved together, exactly:
//!
//! With rows `i` (Jacobian `J_i v = (v_b − v_a)·n_i`), the effective-mass
//! matrix is `A_ij = Σ_k w_k (σ_ik n_i)·(σ_jk n_j)` over the bodies `k`
//! shared by rows `i` and `j` (σ = −1 for the `a` end, +1 for the `b` end,
//! `w` the inverse mass). The impulses `x` that bring every active row to
//! its target solve `A x = e`, `e_i = target_i − J_i v`. `A` is symmetric
//! positive definite for independent rows; a relative regularisation of
//! 2⁻¹⁶ on the diagonal keeps the fixed-point factorisation `A = L D Lᵀ`
//! (no square roots) well defined for dependent ones. Ropes can only pull:
//! rows whose accumulated impulse would become negative are released (set to
//! zero and removed) and the rest re-solved — a small active-set loop,
//! bounded to a few rounds.
//!
//! Groups larger than [`MAX_BLOCK`] rows fall back to sequential impulses
//! (cost O(r³) per solve would grow too fast).

use crate::math::{Scalar, Vec2};
use crate::solver::row::ContactConstraint;
use crate::solver::sparse_solve::SparseScratch;

/// Largest group solved directly.
pub(crate) const MAX_BLOCK: usize = 64;
/// Active-set rounds per solve.
const ROUNDS: usize = 4;

/// `A_ij` for rows `p` and `q` along directions `dp` and `dq` (each row's
/// normal, or for a rope's sideways row its normal turned a quarter).
pub(crate) fn coupling<S: Scalar>(
    (p, dp): (&ContactConstraint<S>, Vec2<S>),
    (q, dq): (&ContactConstraint<S>, Vec2<S>),
) -> S {
    let ends = |c: &ContactConstraint<S>| {
        [
            (c.a, c.inverse_mass_a, true),
            (c.b, c.inverse_mass_b, false),
        ]
    };
    let cos = dp.dot(dq);
    let mut sum = S::ZERO;
    for (sp, wp, neg_p) in ends(p) {
        if !wp.is_positive() {
            continue;
        }
        for (sq, _, neg_q) in ends(q) {
            if sp == sq {
                let term = wp.mul(cos);
                sum = if neg_p == neg_q {
                    sum.add(term)
                } else {
                    sum.sub(term)
                };
            }
        }
    }
    sum
}

/// Solves `A x = e` in place (`e` becomes `x`) for the dense symmetric `A`
/// (row-major, `m × m`) by `L D Lᵀ` with a relative diagonal regularisation.
fn solve_ldlt<S: Scalar>(a: &mut [S], e: &mut [S], m: usize) {
    // Regularise: A_ii (1 + 2^-16), and never below one ulp.
    for i in 0..m {
        let d = a[i * m + i];
        let bump = d.abs().mul(S::from_ratio(1, 65_536)).max(S::EPSILON);
        a[i * m + i] = d.add(bump);
    }
    // Factor in place: strict lower triangle holds L, diagonal holds D.
    for k in 0..m {
        let mut d = a[k * m + k];
        for p in 0..k {
            let l = a[k * m + p];
            d = d.sub(l.mul(l).mul(a[p * m + p]));
        }
        // Rounding can only make a pivot of an SPD matrix tiny, never
        // meaningfully negative; clamp so the division below is defined.
        let d = d.max(S::EPSILON);
        a[k * m + k] = d;
        for i in (k + 1)..m {
            let mut s = a[i * m + k];
            for p in 0..k {
                s = s.sub(a[i * m + p].mul(a[k * m + p]).mul(a[p * m + p]));
            }
            a[i * m + k] = s.div(d);
        }
    }
    // L y = e.
    for i in 0..m {
        let mut s = e[i];
        for p in 0..i {
            s = s.sub(a[i * m + p].mul(e[p]));
        }
        e[i] = s;
    }
    // D z = y.
    for i in 0..m {
        e[i] = e[i].div(a[i * m + i]);
    }
    // Lᵀ x = z.
    for i in (0..m).rev() {
        let mut s = e[i];
        for p in (i + 1)..m {
            s = s.sub(a[p * m + i].mul(e[p]));
        }
        e[i] = s;
    }
}

pub(crate) fn apply_impulse<S: Scalar>(
    row: &ContactConstraint<S>,
    amount: S,
    target: &mut [Vec2<S>],
) {
    let push = row.normal.scale(amount);
    if row.inverse_mass_a.is_positive() {
        target[row.a as usize] -= push.scale(row.inverse_mass_a);
    }
    if row.inverse_mass_b.is_positive() {
        target[row.b as usize] += push.scale(row.inverse_mass_b);
    }
}

/// Working memory of the block solver.
#[derive(Clone, Debug, Default)]
pub(crate) struct BlockScratch<S: Scalar> {
    matrix: Vec<S>,
    rhs: Vec<S>,
    /// The active rows (row indices).
    active: Vec<usize>,
    /// The rope rows' sideways rows in the solve: `(row index, g)`, after
    /// the active rows in the system (see [`solve_group_velocities`]).
    sides: Vec<(usize, S)>,
    /// The position impulse the position passes have applied to each row
    /// (by row index) since the rope settling rounds began; empty outside
    /// them (as the tree solve's `TreeScratch::applied`).
    pub(crate) applied: Vec<S>,
    /// Working memory of the sparse solve of large uneven groups.
    pub(crate) sparse: SparseScratch<S>,
}

impl<S: Scalar> BlockScratch<S> {
    /// The one block solve shared by the velocity and position passes:
    /// builds `A` over the active rows ([`coupling`]) and their sideways
    /// rows (direction `perp(n)`, with the compliance `1/g` on the
    /// diagonal), the right-hand side `e_i = rhs(row_i)` and
    /// `side_rhs(row, g)`, and solves `A x = e` (`x` is left in
    /// `self.rhs`, active rows first, then the sideways rows). `false` when
    /// no row is active (nothing built, nothing solved).
    fn solve_active(
        &mut self,
        rows: &[ContactConstraint<S>],
        mut rhs: impl FnMut(usize) -> S,
        mut side_rhs: impl FnMut(usize, S) -> S,
    ) -> bool {
        let hard = self.active.len();
        if hard == 0 {
            return false;
        }
        let m = hard + self.sides.len();
        self.rhs.clear();
        self.rhs.extend(self.active.iter().map(|&ri| rhs(ri)));
        self.rhs
            .extend(self.sides.iter().map(|&(ri, g)| side_rhs(ri, g)));
        self.matrix.clear();
        self.matrix.resize(m * m, S::ZERO);
        let entry = |k: usize| -> (&ContactConstraint<S>, Vec2<S>) {
            if k < hard {
                let row = &rows[self.active[k]];
                (row, row.normal)
            } else {
                let row = &rows[self.sides[k - hard].0];
                (row, row.normal.perp())
            }
        };
        for i in 0..m {
            for j in 0..m {
                self.matrix[i * m + j] = coupling(entry(i), entry(j));
            }
        }
        for (k, &(_, g)) in self.sides.iter().enumerate() {
            let d = (hard + k) * (m + 1);
            self.matrix[d] = self.matrix[d].add(S::ONE.div(g));
        }
        solve_ldlt(&mut self.matrix, &mut self.rhs, m);
        true
    }

    /// The sideways rows of the active rope rows: those with a sideways
    /// stiffness `g > 0` in `stiffness` (empty for contacts).
    fn collect_sides(&mut self, stiffness: &[S]) {
        self.sides.clear();
        for &ri in &self.active {
            if let Some(&g) = stiffness.get(ri)
                && g.is_positive()
            {
                self.sides.push((ri, g));
            }
        }
    }
}

/// A rope row's sideways impulse `y` along `perp(n)` applied to `target`.
fn apply_side_impulse<S: Scalar>(row: &ContactConstraint<S>, amount: S, target: &mut [Vec2<S>]) {
    let push = row.normal.perp().scale(amount);
    if row.inverse_mass_a.is_positive() {
        target[row.a as usize] -= push.scale(row.inverse_mass_a);
    }
    if row.inverse_mass_b.is_positive() {
        target[row.b as usize] += push.scale(row.inverse_mass_b);
    }
}

/// One exact velocity solve of each group (groups of one, and groups above
/// [`MAX_BLOCK`], take the sequential-impulse path in the caller).
///
/// Rope rows with a sideways stiffness `g` (`side`: `g` per row and the
/// sideways impulse each has received this substep; `None` for contacts)
/// add a soft row along `perp(n)` with compliance `1/g` and target
/// `λ_s = −g·(s·v_rel)` at the end velocities, as in the tree solve
/// (`solver::tree_solve`, "Ropes: a sideways stiffness on the edge"):
/// without it a closed loop of light links round a heavy body turned its
/// ropes explicitly and blew up (a ring of 20 with a 1000× body: 38 000 %).
pub(crate) fn solve_group_velocities<S: Scalar>(
    rows: &mut [ContactConstraint<S>],
    group: &[usize],
    velocities: &mut [Vec2<S>],
    mut side: Option<(&[S], &mut [S])>,
    work: &mut BlockScratch<S>,
) {
    // The rows below `ropes` are ropes (the rope rows come first, and a
    // rope group may hold contacts too); without `side`, every row is a
    // contact.
    let ropes = side.as_ref().map_or(0, |(stiffness, _)| stiffness.len());
    work.active.clear();
    // Ropes start active. Contacts: a row carrying no impulse whose
    // target the bodies already meet (`J v ≥ target`: a speculative row of
    // bodies still apart, a touching row not pressed) needs no impulse;
    // starting with it active makes the equality solve pull on it and a
    // round release it again, and a group with more such rows than rounds
    // never got a solution applied (below).
    work.active.extend(group.iter().copied().filter(|&ri| {
        let row = &rows[ri];
        let vn = (velocities[row.b as usize] - velocities[row.a as usize]).dot(row.normal);
        ri < ropes || row.normal_impulse.is_positive() || vn < row.target_velocity
    }));
    let mut applied = false;
    for _ in 0..ROUNDS {
        match side.as_ref() {
            Some((stiffness, _)) => work.collect_sides(stiffness),
            None => work.sides.clear(),
        }
        let accumulated: &[S] = side.as_ref().map_or(&[], |(_, a)| &**a);
        // e_i = target_i − J_i v: the velocity change row i still needs;
        // sideways: −s·v_rel − (impulse so far)/g.
        let solved = work.solve_active(
            rows,
            |ri| {
                let row = &rows[ri];
                let vn = (velocities[row.b as usize] - velocities[row.a as usize]).dot(row.normal);
                row.target_velocity.sub(vn)
            },
            |ri, g| {
                let row = &rows[ri];
                let v_rel = velocities[row.b as usize] - velocities[row.a as usize];
                let so_far = accumulated.get(ri).copied().unwrap_or(S::ZERO);
                v_rel.dot(row.normal.perp()).add(so_far.div(g)).neg()
            },
        );
        if !solved {
            break;
        }
        // Release rows that would push (their accumulated impulse would
        // turn negative): zero them, and re-solve the others.
        let mut released = Vec::new();
        for (i, &ri) in work.active.iter().enumerate() {
            if rows[ri].normal_impulse.add(work.rhs[i]).is_negative() {
                released.push(ri);
            }
        }
        if released.is_empty() {
            for (i, &ri) in work.active.iter().enumerate() {
                let x = work.rhs[i];
                rows[ri].normal_impulse = rows[ri].normal_impulse.add(x);
                let row = rows[ri];
                apply_impulse(&row, x, velocities);
            }
            let hard = work.active.len();
            for (k, &(ri, _)) in work.sides.iter().enumerate() {
                let y = work.rhs[hard + k];
                if let Some((_, accumulated)) = side.as_mut() {
                    accumulated[ri] = accumulated[ri].add(y);
                }
                apply_side_impulse(&rows[ri], y, velocities);
            }
            applied = true;
            break;
        }
        for &ri in &released {
            let old = rows[ri].normal_impulse;
            rows[ri].normal_impulse = S::ZERO;
            let row = rows[ri];
            apply_impulse(&row, old.neg(), velocities);
        }
        work.active.retain(|ri| !released.contains(ri));
    }
    if group.last().is_some_and(|&ri| ri >= ropes) {
        sequential_remainder(rows, group, velocities, applied, &work.active, ropes);
    }
}

/// The contact rows of `group` (those from `ropes` on) the rounds of
/// [`solve_group_velocities`] did not solve take one sequential impulse
/// each (accumulated impulse kept ≥ 0): rows left out or released, and
/// every row when no round's solution was applied (`applied` false;
/// `active` the rows still in the set, ascending as `group`). Why: every round may release rows (each
/// release changes which others must pull), and when the rounds ran out
/// the group got only the releases: a column of 19 bodies in a crowd of
/// 300 kept its rows unsolved in every sweep, gravity piled up in its
/// velocities (3 units/s) while the position pass alone held it, and it
/// never slept.
pub(crate) fn sequential_remainder<S: Scalar>(
    rows: &mut [ContactConstraint<S>],
    group: &[usize],
    velocities: &mut [Vec2<S>],
    applied: bool,
    active: &[usize],
    ropes: usize,
) {
    let mut next_active = active.iter().copied().peekable();
    for &ri in group {
        let solved = applied && next_active.peek() == Some(&ri);
        if next_active.peek() == Some(&ri) {
            next_active.next();
        }
        if solved || ri < ropes {
            continue;
        }
        let row = &mut rows[ri];
        let vn = (velocities[row.b as usize] - velocities[row.a as usize]).dot(row.normal);
        let old = row.normal_impulse;
        let lambda = row.target_velocity.sub(vn).mul(row.effective_mass);
        row.normal_impulse = old.add(lambda).max(S::ZERO);
        let dn = row.normal_impulse.sub(old);
        if dn != S::ZERO {
            let row = *row;
            apply_impulse(&row, dn, velocities);
        }
    }
}

/// One exact position-correction solve of a group: stretched rows (beyond
/// the slop) are pulled back by the fraction `beta`, at most `max_correction`
/// (and at most the row's entry in `row_caps`, where it has one); rope rows
/// with a sideways stiffness in `side_stiffness` resist turning, as in the
/// tree solve.
#[allow(clippy::too_many_arguments)]
pub(crate) fn solve_group_positions<S: Scalar>(
    rows: &[ContactConstraint<S>],
    group: &[usize],
    displacements: &mut [Vec2<S>],
    (slop, beta, max_correction): (S, S, S),
    side_stiffness: &[S],
    row_caps: &[S],
    work: &mut BlockScratch<S>,
) {
    let correction_of = |ri: usize, d: &[Vec2<S>]| {
        let row = &rows[ri];
        let cap = row_caps
            .get(ri)
            .map_or(max_correction, |&c| c.min(max_correction));
        let separation = row
            .separation
            .add((d[row.b as usize] - d[row.a as usize]).dot(row.normal));
        beta.mul(separation.add(slop)).clamp(cap.neg(), S::ZERO)
    };
    work.active.clear();
    work.active.extend(
        group
            .iter()
            .copied()
            .filter(|&ri| correction_of(ri, displacements).is_negative()),
    );
    for _ in 0..ROUNDS {
        work.collect_sides(side_stiffness);
        // e_i = −correction_i: the stretch row i must take back; the
        // sideways rows hold what they have (right-hand side 0).
        let solved = work.solve_active(
            rows,
            |ri| correction_of(ri, displacements).neg(),
            |_, _| S::ZERO,
        );
        if !solved {
            return;
        }
        let hard = work.active.len();
        if work.rhs[..hard].iter().all(|x| !x.is_negative()) {
            for (i, &ri) in work.active.iter().enumerate() {
                apply_impulse(&rows[ri], work.rhs[i], displacements);
                if let Some(sum) = work.applied.get_mut(ri) {
                    *sum = sum.add(work.rhs[i]);
                }
            }
            for (k, &(ri, _)) in work.sides.iter().enumerate() {
                apply_side_impulse(&rows[ri], work.rhs[hard + k], displacements);
            }
            return;
        }
        // A row that would have to push is not stretched enough to matter
        // once its neighbours move: drop it and solve the rest.
        let keep: Vec<usize> = work
            .active
            .iter()
            .zip(&work.rhs)
            .filter(|(_, x)| !x.is_negative())
            .map(|(&ri, _)| ri)
            .collect();
        work.active = keep;
    }
}
