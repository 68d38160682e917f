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

/// Largest group solved directly.
pub(crate) const MAX_BLOCK: usize = 64;
/// Active-set rounds per solve.
const ROUNDS: usize = 4;

/// `A_ij` for rows `p` and `q`.
fn coupling<S: Scalar>(p: &ContactConstraint<S>, q: &ContactConstraint<S>) -> S {
    let ends = |c: &ContactConstraint<S>| {
        [
            (c.a, c.inverse_mass_a, true),
            (c.b, c.inverse_mass_b, false),
        ]
    };
    let cos = p.normal.dot(q.normal);
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

fn apply_impulse<S: Scalar>(row: &ContactConstraint<S>, amount: S, target: &mut [Vec2<S>]) {
    let push = row.normal.scale(amount);
    if row.inverse_mass_a.is_positive() {
        target[row.a as usize] -= push.scale(row.inverse_mass_a);
    }
    if row.inverse_mass_b.is_positive() {
        target[row.b as usize] += push.scale(row.inverse_mass_b);
    }
}

/// Working memory for the block solves.
#[derive(Clone, Debug, Default)]
pub(crate) struct BlockScratch<S: Scalar> {
    matrix: Vec<S>,
    rhs: Vec<S>,
    active: Vec<usize>,
}

impl<S: Scalar> BlockScratch<S> {
    /// The one block solve shared by the velocity and position passes:
    /// builds `A` over the active rows ([`coupling`]) and the right-hand side
    /// `e_i = rhs(row_i)`, and solves `A x = e` (`x` is left in `self.rhs`,
    /// in the order of `self.active`). `false` when no row is active
    /// (nothing built, nothing solved).
    fn solve_active(
        &mut self,
        rows: &[ContactConstraint<S>],
        mut rhs: impl FnMut(&ContactConstraint<S>) -> S,
    ) -> bool {
        let m = self.active.len();
        if m == 0 {
            return false;
        }
        self.rhs.clear();
        self.rhs
            .extend(self.active.iter().map(|&ri| rhs(&rows[ri])));
        self.matrix.clear();
        self.matrix.resize(m * m, S::ZERO);
        for (i, &ri) in self.active.iter().enumerate() {
            let row = &rows[ri];
            for (j, &rj) in self.active.iter().enumerate() {
                self.matrix[i * m + j] = coupling(row, &rows[rj]);
            }
        }
        solve_ldlt(&mut self.matrix, &mut self.rhs, m);
        true
    }
}

/// One exact velocity solve of each group (groups of one, and groups above
/// [`MAX_BLOCK`], take the sequential-impulse path in the caller).
pub(crate) fn solve_group_velocities<S: Scalar>(
    rows: &mut [ContactConstraint<S>],
    group: &[usize],
    velocities: &mut [Vec2<S>],
    work: &mut BlockScratch<S>,
) {
    work.active.clear();
    work.active.extend_from_slice(group);
    for _ in 0..ROUNDS {
        // e_i = target_i − J_i v: the velocity change row i still needs.
        let solved = work.solve_active(rows, |row| {
            let vn = (velocities[row.b as usize] - velocities[row.a as usize]).dot(row.normal);
            row.target_velocity.sub(vn)
        });
        if !solved {
            return;
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
            return;
        }
        for &ri in &released {
            let old = rows[ri].normal_impulse;
            rows[ri].normal_impulse = S::ZERO;
            let row = rows[ri];
            apply_impulse(&row, old.neg(), velocities);
        }
        work.active.retain(|ri| !released.contains(ri));
    }
}

/// One exact position-correction solve of a group: stretched rows (beyond
/// the slop) are pulled back by the fraction `beta`, at most `max_correction`.
pub(crate) fn solve_group_positions<S: Scalar>(
    rows: &[ContactConstraint<S>],
    group: &[usize],
    displacements: &mut [Vec2<S>],
    slop: S,
    beta: S,
    max_correction: S,
    work: &mut BlockScratch<S>,
) {
    let correction_of = |row: &ContactConstraint<S>, d: &[Vec2<S>]| {
        let separation = row
            .separation
            .add((d[row.b as usize] - d[row.a as usize]).dot(row.normal));
        beta.mul(separation.add(slop))
            .clamp(max_correction.neg(), S::ZERO)
    };
    work.active.clear();
    work.active.extend(
        group
            .iter()
            .copied()
            .filter(|&ri| correction_of(&rows[ri], displacements).is_negative()),
    );
    for _ in 0..ROUNDS {
        // e_i = −correction_i: the stretch row i must take back.
        let solved = work.solve_active(rows, |row| correction_of(row, displacements).neg());
        if !solved {
            return;
        }
        if work.rhs.iter().all(|x| !x.is_negative()) {
            for (i, &ri) in work.active.iter().enumerate() {
                apply_impulse(&rows[ri], work.rhs[i], displacements);
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
