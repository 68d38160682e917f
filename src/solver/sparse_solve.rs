//! An exact solve for large contact groups of uneven masses: a sparse
//! `L·D·Lᵀ` of the group's effective-mass matrix in a fill-reducing order,
//! inside the block solver's active-set loop.
//!
//! # Why
//!
//! A cyclic contact group of uneven masses (a pile of light balls under
//! heavy ones) needs its normal rows solved together: sequential impulses
//! move the light bodies instead of the heavy ones and converge at about
//! `w_heavy/w_light` per sweep. Up to [`MAX_BLOCK`](super::block_solve::MAX_BLOCK)
//! rows the dense block solve does that (`O(r³)`). Above, the group was
//! solved on a few covering spanning trees one after another
//! ([`crate::solver::forest_cover`]), a block Gauss–Seidel that does not
//! converge at 1000:1: the velocity problem of a statically indeterminate
//! pile (an 8-row pile of balls: 94 rows, 72 velocity unknowns) is so ill
//! conditioned that projected Gauss–Seidel in f64 still left 0.002 units/s
//! after 16 384 sweeps, and such piles collapsed (thousands of times their
//! slop bound).
//!
//! # How
//!
//! With rows `i` (`J_i v = (v_b − v_a)·n_i`), `A = J·M⁻¹·Jᵀ` has
//! `A_ij ≠ 0` only when rows `i` and `j` share a movable body
//! ([`coupling`]): the row graph of a pile is a band a few rows of the
//! pile wide. The rows are put in reverse Cuthill–McKee order (a
//! breadth-first numbering from a peripheral row, neighbours by rising
//! degree, reversed), which keeps every row's nonzeros within a short
//! *profile* before the diagonal; `L·D·Lᵀ` fills only inside the profile
//! (George & Liu), so the factor is stored row by row from each row's
//! first nonzero (an envelope) and costs `Σ pᵢ²` for profile lengths `pᵢ`
//! (about `r·b²` for a band `b` wide), not `r³`.
//!
//! Fixed point. `A`'s diagonal spans the mass ratio (`w_a + w_b`: 2.5 for
//! two light balls of radius 0.5, 2.5e-3 for two ×1000 ones), and an
//! I32F32 ulp (2.3e-10) is then a coarse step of a heavy row's pivot: the
//! dense solve in place of the covering trees blew up on a ×1000 pile in
//! session 11. So the matrix is scaled to a unit diagonal first,
//! `Â = S·A·S` with `S = diag(√m_eff)` (`m_eff = 1/A_ii`), whose entries
//! are the cosines of the rows in the mass metric (`|Â_ij| ≤ 1`); the
//! solve is `Â·y = S·e`, `x = S·y`. A regularisation `ε = 2⁻¹⁶` on `Â`'s
//! diagonal keeps the factor defined for dependent rows (a statically
//! indeterminate pile has more rows than its bodies' degrees of freedom):
//! every pivot is then at least `ε` (≈ 6.6e4 ulps), and `|L_ij| ≤
//! 1/√ε = 256`. The products of the factor and the substitutions are
//! summed exactly in the wide type and rounded once.
//!
//! What the regularisation costs: the solve returns `(Â + ε)⁻¹·ê`, short
//! of an independent row's target by about `ε/(λ + ε)` of it along an
//! eigenvector of `Â` with eigenvalue `λ`; the dependent directions carry
//! no velocity error. `λ` is not always large beside `ε`: two columns of
//! ten light circles side by side, a ball 100× a circle arriving on one at
//! 50 units/s, were left 3 % short (the ball stopped only to 1.7 units/s
//! by the first solve: `λ ≈ 30 ε`). So each solve is refined: once the
//! active set holds, the rounds solve again for what the active rows
//! still lack (the target minus the velocity reached), with the same
//! factor, which shrinks the shortfall by `ε/(λ + ε)` per round, while
//! its largest value keeps halving. Without it the velocity sweeps left
//! 0.027 units/s in the columns and the bounce pass (two solves) launched
//! the ball at 49.955 instead of 50: a column left moving is not at rest
//! for the classification of the next step, which gave it sequential
//! impulses, and those could not take back the catch's warm-started
//! impulses after the ball had gone (a circle left at 858 units/s).
//!
//! Contradicting rows: rows of the active set can be one constraint with
//! targets that disagree. A ball 1 000× a circle at 1 000 units/s onto a
//! column of circles sees, within the speculative margin, every circle
//! below it and the ground: the rows ball–ground, ball–bottom circle and
//! bottom circle–ground are dependent (the first is the sum of the
//! others), with targets −15, −12 and 0 units/s. No impulse meets all
//! three; the regularised solve splits the difference (two rows short by
//! 1.5 units/s), and each round of refinement moves the impulses along
//! the dependent direction by the contradiction over `ε` (about 1e5 per
//! round), changing no velocity, until the ball–ground row (9e5) would
//! reach zero and leave the set, eight rounds on. The shortfall stops
//! halving at once, so the rounds stopped there: the columns were left
//! moving sideways at up to 11 units/s (the rows between them carry the
//! split), and the next step threw them at `max_speed`. So when the
//! refinement stalls, the row the further rounds would take to zero first
//! is released at once, if the geometric series of those rounds reaches
//! it (see the rounds below).
//!
//! The unilateral rows (contacts push, `λ ≥ 0`) take an active-set loop:
//! rows carrying impulse or short of their target start active; in each
//! round, when some active row's accumulated impulse would turn negative,
//! all such rows are released (zeroed) and the rest solved again;
//! otherwise the solution is applied, and the inactive rows it left short
//! of their target join the set for another round. At most [`MAX_ROUNDS`]
//! rounds; the rows the last applied solution did not hold take one
//! sequential impulse each ([`sequential_remainder`]). The block solve's
//! loop (releases only, 4 rounds) left rows that the solution drove into
//! their neighbours inactive, and the pile collapsed; with the rows joining
//! again, 16 rounds left the first substep of some ×10 000 piles (no warm
//! start yet) unsolved, 32 solve them. A primal loop (a partial step to
//! the first row reaching zero) and block principal pivoting (Júdice and
//! Pires, with Murty's single exchanges) needed hundreds of rounds on the
//! first substep of a 12-row pile. But the block exchanges can cycle: in
//! an even pile under a ball 100× lighter than its circles (a group of
//! uneven masses, but a statically indeterminate one of equal circles),
//! rows were released and taken in again in turn until every solve's
//! rounds ran out; so once a row released twice is short again, one row
//! changes per round (the shortest joins, the hardest pulling leaves),
//! with more rounds for small groups ([`MIN_ROUNDS`]).
//!
//! The rounds apply and take back impulses row by row, each application
//! rounded on its own; at the end the velocities are put back as they
//! were and each row's change of impulse applied once, so a row that ends
//! where it started leaves nothing (released rows at a slant left a few
//! ulps sideways, enough to turn a column of circles off the axis the
//! classification of the next step reads). Friction is taken by the caller before
//! the normal solve, as for the block solve (`world::step::solve`), so each
//! sweep ends with the normal rows exact.
//!
//! The factor depends only on the scaled matrix and which rows are active:
//! the sweeps of a substep whose active set did not change reuse it when
//! the matrix is bit for bit the one it was factored from (derived data: a
//! restored world recomputes it bit for bit).
//!
//! Cost bound: a group over [`MAX_SPARSE_ROWS`] rows, or whose profile
//! work `Σ pᵢ²` exceeds [`MAX_SPARSE_WORK`], is not planned here; it keeps
//! the covering trees ([`crate::solver::row_groups::RowGroups::classify`]).

use crate::math::{Scalar, Vec2, WideScalar};
use crate::solver::block_solve::{apply_impulse, coupling, sequential_remainder};
use crate::solver::row::ContactConstraint;

/// Largest profile work `Σ pᵢ²` (about the multiply-adds of one
/// factorisation) planned for one group: 4.2e6, a band of about 90 rows
/// over 500 rows.
pub(crate) const MAX_SPARSE_WORK: usize = 1 << 22;
/// Largest group planned here (rows). A 12-row pile of balls has 212.
/// Crowds of bodies in motion (a closed box of 200 bodies at g 100, every
/// tenth ×1000: 500–930 rows, profile work up to 1.7e6) took the solve
/// first: every active-set round a refactorisation, rounds running out
/// while contacts came and went, and the crowd ended 0.33 deep in itself
/// (0.005–0.034 on the covering trees); they keep the covering trees.
pub(crate) const MAX_SPARSE_ROWS: usize = 256;
/// Active-set rounds per solve: at least [`MIN_ROUNDS`], and up to
/// [`MAX_ROUNDS`] while their factorisations' work stays within
/// [`ROUND_WORK`] multiply-adds. The first substep of a pile with no warm
/// start needs up to about 30 (a ×10 000 pile); an even pile under a light
/// ball, whose set cycles until it turns to single exchanges (see
/// [`solve_sparse_velocities`]), up to 65 for a 95-row group.
const MIN_ROUNDS: usize = 32;
/// See [`MIN_ROUNDS`].
const MAX_ROUNDS: usize = 128;
/// See [`MIN_ROUNDS`]: 2²⁵ multiply-adds, 128 rounds of a group whose
/// profile work is 2¹⁸ (a 212-row pile's is about 1.2e5).
const ROUND_WORK: usize = 1 << 25;

/// Working memory of [`plan_sparse`].
#[derive(Clone, Debug, Default)]
pub(crate) struct SparsePlanner {
    /// `(body slot, group position)` of every movable end.
    ends: Vec<(u32, u32)>,
    /// Neighbour pairs `(p, q)` (rows sharing a movable body), then CSR.
    pairs: Vec<(u32, u32)>,
    /// CSR start of each position's neighbours (length `n + 1`).
    start: Vec<u32>,
    /// CSR neighbours, each list sorted by (degree, position).
    neighbours: Vec<u32>,
    /// Per position: visited by the breadth-first search.
    visited: Vec<bool>,
    /// Breadth-first order.
    queue: Vec<u32>,
    /// Per position: its index in the elimination order.
    index_of: Vec<u32>,
}

impl SparsePlanner {
    fn degree(&self, p: u32) -> u32 {
        self.start[p as usize + 1] - self.start[p as usize]
    }

    /// Breadth-first numbering from `root` (appended to `queue`; neighbours
    /// in their sorted order); returns where the last level starts.
    fn breadth_first(&mut self, root: u32) -> usize {
        let mut head = self.queue.len();
        self.visited[root as usize] = true;
        self.queue.push(root);
        let mut level_start = head;
        let mut level_end = self.queue.len();
        while head < self.queue.len() {
            if head == level_end {
                level_start = level_end;
                level_end = self.queue.len();
            }
            let p = self.queue[head] as usize;
            head += 1;
            for k in self.start[p]..self.start[p + 1] {
                let q = self.neighbours[k as usize];
                if !self.visited[q as usize] {
                    self.visited[q as usize] = true;
                    self.queue.push(q);
                }
            }
        }
        level_start
    }
}

/// Plans the sparse solve of `group` (rows sharing movable bodies): its
/// positions in reverse Cuthill–McKee order appended to `order`, and per
/// elimination index the first column of its profile appended to `first`.
/// `false` (nothing appended) for a group over [`MAX_SPARSE_ROWS`] rows or
/// whose profile work exceeds [`MAX_SPARSE_WORK`].
pub(crate) fn plan_sparse<S: Scalar>(
    rows: &[ContactConstraint<S>],
    group: &[usize],
    planner: &mut SparsePlanner,
    order: &mut Vec<u32>,
    first: &mut Vec<u32>,
) -> bool {
    let n = group.len();
    let Ok(n32) = u32::try_from(n) else {
        return false;
    };
    if n > MAX_SPARSE_ROWS {
        return false;
    }
    planner.ends.clear();
    for (p, &ri) in (0..n32).zip(group) {
        let row = &rows[ri];
        if row.inverse_mass_a.is_positive() {
            planner.ends.push((row.a, p));
        }
        if row.inverse_mass_b.is_positive() {
            planner.ends.push((row.b, p));
        }
    }
    planner.ends.sort_unstable();
    // Rows sharing a body are neighbours.
    planner.pairs.clear();
    let mut i = 0;
    while i < planner.ends.len() {
        let slot = planner.ends[i].0;
        let mut j = i;
        while j < planner.ends.len() && planner.ends[j].0 == slot {
            j += 1;
        }
        for a in i..j {
            for b in i..j {
                let (p, q) = (planner.ends[a].1, planner.ends[b].1);
                if p != q {
                    planner.pairs.push((p, q));
                }
            }
        }
        i = j;
    }
    planner.pairs.sort_unstable();
    planner.pairs.dedup();
    planner.start.clear();
    planner.start.resize(n + 1, 0);
    for &(p, _) in &planner.pairs {
        planner.start[p as usize + 1] += 1;
    }
    for p in 0..n {
        planner.start[p + 1] += planner.start[p];
    }
    planner.neighbours.clear();
    planner
        .neighbours
        .extend(planner.pairs.iter().map(|&(_, q)| q));
    // Neighbours by rising degree, then position (Cuthill–McKee).
    let mut neighbours = core::mem::take(&mut planner.neighbours);
    for p in 0..n {
        let (s, e) = (planner.start[p] as usize, planner.start[p + 1] as usize);
        neighbours[s..e].sort_unstable_by_key(|&q| (planner.degree(q), q));
    }
    planner.neighbours = neighbours;
    // A peripheral root: from the row of least degree, the row of least
    // degree in the last level of its breadth-first search (one step of
    // George and Liu's search).
    planner.queue.clear();
    planner.visited.clear();
    planner.visited.resize(n, false);
    let mut rest = 0u32;
    while (rest as usize) < n {
        // The next unvisited component (a group is connected; kept general).
        let seed = (rest..n32)
            .filter(|&p| !planner.visited[p as usize])
            .min_by_key(|&p| (planner.degree(p), p));
        let Some(seed) = seed else { break };
        let mark = planner.queue.len();
        let last = planner.breadth_first(seed);
        let root = planner.queue[last..]
            .iter()
            .copied()
            .min_by_key(|&p| (planner.degree(p), p))
            .unwrap_or(seed);
        for k in mark..planner.queue.len() {
            let p = planner.queue[k] as usize;
            planner.visited[p] = false;
        }
        planner.queue.truncate(mark);
        planner.breadth_first(root);
        while (rest as usize) < n && planner.visited[rest as usize] {
            rest += 1;
        }
    }
    // Reverse Cuthill–McKee.
    planner.queue.reverse();
    planner.index_of.clear();
    planner.index_of.resize(n, 0);
    for (k, &p) in (0..n32).zip(&planner.queue) {
        planner.index_of[p as usize] = k;
    }
    let base = first.len();
    let mut work = 0usize;
    for (k, &p) in (0..n32).zip(&planner.queue) {
        let (s, e) = (
            planner.start[p as usize] as usize,
            planner.start[p as usize + 1] as usize,
        );
        let f = planner.neighbours[s..e]
            .iter()
            .map(|&q| planner.index_of[q as usize])
            .min()
            .unwrap_or(k)
            .min(k);
        let profile = (k - f + 1) as usize;
        work = work.saturating_add(profile * profile);
        first.push(f);
    }
    if work > MAX_SPARSE_WORK {
        first.truncate(base);
        return false;
    }
    order.extend_from_slice(&planner.queue);
    true
}

/// A contact group as [`plan_sparse`] ordered it: the group (indices
/// into the rows), its elimination order (positions in the group) and the
/// first index of each elimination row's profile.
#[derive(Clone, Copy)]
struct SparsePlan<'a> {
    group: &'a [usize],
    order: &'a [u32],
    first: &'a [u32],
}

impl SparsePlan<'_> {
    /// The row index of elimination index `k`.
    fn row(&self, k: usize) -> usize {
        self.group[self.order[k] as usize]
    }

    /// `(elimination index, row index)` in elimination order.
    fn rows(&self) -> impl Iterator<Item = (usize, usize)> + '_ {
        self.order
            .iter()
            .enumerate()
            .map(|(k, &p)| (k, self.group[p as usize]))
    }
}

/// Working memory of the sparse solve, and its last factor.
#[derive(Clone, Debug)]
pub(crate) struct SparseScratch<S: Scalar> {
    /// Start of each elimination index's row in the envelope (`n + 1`).
    offset: Vec<usize>,
    /// `√m_eff` per elimination index.
    scale: Vec<S>,
    /// Per elimination index: in the active set.
    active: Vec<bool>,
    /// The scaled matrix of the active rows, row by row over each profile
    /// (diagonal last).
    matrix: Vec<S>,
    /// The matrix and profile the factor below was computed from.
    source: Vec<S>,
    source_first: Vec<u32>,
    /// `L` (strictly lower, over each profile) and `D` (diagonal slots).
    factor: Vec<S>,
    /// One row's `L_kj·D_j` while factoring.
    temp: Vec<S>,
    /// Right-hand side, then solution (scaled).
    rhs: Vec<S>,
    /// Wide accumulators of the back substitution.
    acc: Vec<S::Wide>,
    /// The active rows' indices, ascending (for the sequential remainder).
    active_rows: Vec<usize>,
    /// Per elimination index: solved by the last solution applied.
    solved: Vec<bool>,
    /// Rows released since then, with their impulses.
    released: Vec<(usize, S)>,
    /// Per group position: the row's accumulated impulse when the solve
    /// started.
    start_impulse: Vec<S>,
    /// The group's movable bodies' velocities when the solve started
    /// (`(slot, velocity)`, a body once per row end).
    start_velocity: Vec<(u32, Vec2<S>)>,
    /// Per elimination index: how often released in this solve.
    was_released: Vec<u8>,
    /// The profile work `Σ pᵢ²` of the group prepared last.
    work: usize,
}

impl<S: Scalar> Default for SparseScratch<S> {
    fn default() -> Self {
        SparseScratch {
            offset: Vec::new(),
            scale: Vec::new(),
            active: Vec::new(),
            matrix: Vec::new(),
            source: Vec::new(),
            source_first: Vec::new(),
            factor: Vec::new(),
            temp: Vec::new(),
            rhs: Vec::new(),
            acc: Vec::new(),
            active_rows: Vec::new(),
            solved: Vec::new(),
            released: Vec::new(),
            start_impulse: Vec::new(),
            start_velocity: Vec::new(),
            was_released: Vec::new(),
            work: 0,
        }
    }
}

impl<S: Scalar> SparseScratch<S> {
    /// Takes the row at elimination index `k` (group row `ri`) out of the
    /// active set: its accumulated impulse is taken back out of its
    /// bodies' velocities and kept in `released` (put back if the rounds
    /// run out before a solution is applied), and the release is counted
    /// (a row released twice marks the active set as cycling).
    fn release(
        &mut self,
        k: usize,
        row: &mut ContactConstraint<S>,
        ri: usize,
        velocities: &mut [Vec2<S>],
    ) {
        self.was_released[k] = self.was_released[k].saturating_add(1);
        self.active[k] = false;
        let old = row.normal_impulse;
        self.released.push((ri, old));
        row.normal_impulse = S::ZERO;
        apply_impulse(row, old.neg(), velocities);
    }

    /// Offsets and scales for a group in this order.
    fn prepare(&mut self, rows: &[ContactConstraint<S>], plan: SparsePlan) {
        let n = plan.order.len();
        self.offset.clear();
        let mut at = 0;
        self.work = 0;
        for (k, &f) in plan.first.iter().enumerate() {
            self.offset.push(at);
            let profile = k - f as usize + 1;
            at += profile;
            self.work += profile * profile;
        }
        self.offset.push(at);
        self.scale.clear();
        self.scale
            .extend(plan.rows().map(|(_, ri)| rows[ri].effective_mass.sqrt()));
        self.active.clear();
        self.active.resize(n, false);
    }

    /// Builds `Â` over the active rows (inactive rows: unit diagonal, no
    /// coupling), and factors it unless it is the matrix factored last.
    /// (Index loops: each reads several arrays at shifted offsets.)
    #[allow(clippy::needless_range_loop)]
    fn build_and_factor(&mut self, rows: &[ContactConstraint<S>], plan: SparsePlan) {
        let (n, first) = (plan.order.len(), plan.first);
        let epsilon = S::from_ratio(1, 65_536);
        self.matrix.clear();
        self.matrix.resize(self.offset[n], S::ZERO);
        for k in 0..n {
            let o = self.offset[k];
            let f = first[k] as usize;
            if !self.active[k] {
                self.matrix[o + k - f] = S::ONE;
                continue;
            }
            let rk = &rows[plan.row(k)];
            let sk = self.scale[k];
            for j in f..k {
                if !self.active[j] {
                    continue;
                }
                let rj = &rows[plan.row(j)];
                let a = coupling((rk, rk.normal), (rj, rj.normal));
                if a != S::ZERO {
                    self.matrix[o + j - f] = a.mul(sk).mul(self.scale[j]);
                }
            }
            let d = coupling((rk, rk.normal), (rk, rk.normal));
            self.matrix[o + k - f] = d.mul(sk).mul(sk).add(epsilon);
        }
        if self.source == self.matrix && self.source_first == first {
            return;
        }
        self.factor.clear();
        self.factor.resize(self.offset[n], S::ZERO);
        for k in 0..n {
            let o = self.offset[k];
            let fk = first[k] as usize;
            self.temp.clear();
            // t_j = A_kj − Σ_p t_p·L_jp over the profiles' overlap.
            for j in fk..k {
                let fj = first[j] as usize;
                let oj = self.offset[j];
                let mut s = S::Wide::from_narrow(self.matrix[o + j - fk]);
                for p in fk.max(fj)..j {
                    s = s.sub(self.temp[p - fk].wide_mul(self.factor[oj + p - fj]));
                }
                self.temp.push(s.narrow());
            }
            // L_kj = t_j / D_j, D_k = A_kk − Σ_j t_j·L_kj.
            let mut d = S::Wide::from_narrow(self.matrix[o + k - fk]);
            for j in fk..k {
                let t = self.temp[j - fk];
                if t == S::ZERO {
                    continue;
                }
                let dj = self.factor[self.offset[j] + j - first[j] as usize];
                let l = t.div(dj);
                d = d.sub(t.wide_mul(l));
                self.factor[o + j - fk] = l;
            }
            // Rounding can take a pivot of the regularised matrix (≥ ε)
            // only slightly lower; half of ε keeps the division defined
            // and `L` bounded.
            self.factor[o + k - fk] = d.narrow().max(epsilon.half());
        }
        core::mem::swap(&mut self.source, &mut self.matrix);
        self.source_first.clear();
        self.source_first.extend_from_slice(first);
    }

    /// Solves `L·D·Lᵀ·y = rhs` in place (`rhs` becomes `y`).
    #[allow(clippy::needless_range_loop)]
    fn substitute(&mut self, first: &[u32]) {
        let n = self.rhs.len();
        for k in 0..n {
            let o = self.offset[k];
            let f = first[k] as usize;
            let mut s = S::Wide::from_narrow(self.rhs[k]);
            for j in f..k {
                s = s.sub(self.factor[o + j - f].wide_mul(self.rhs[j]));
            }
            self.rhs[k] = s.narrow();
        }
        for k in 0..n {
            let f = first[k] as usize;
            self.rhs[k] = self.rhs[k].div(self.factor[self.offset[k] + k - f]);
        }
        self.acc.clear();
        self.acc
            .extend(self.rhs.iter().map(|&v| S::Wide::from_narrow(v)));
        for k in (0..n).rev() {
            let x = self.acc[k].narrow();
            self.rhs[k] = x;
            if x == S::ZERO {
                continue;
            }
            let o = self.offset[k];
            let f = first[k] as usize;
            for j in f..k {
                let l = self.factor[o + j - f];
                self.acc[j] = self.acc[j].sub(l.wide_mul(x));
            }
        }
    }

    /// One exact solve over the active rows: `Â·y = S·e` with `e_k =
    /// rhs(row)` for active rows (0 for the others), `x = S·y` left in
    /// `self.rhs` (elimination order). `false` when no row is active.
    fn solve_active(
        &mut self,
        rows: &[ContactConstraint<S>],
        plan: SparsePlan,
        mut rhs: impl FnMut(&ContactConstraint<S>) -> S,
    ) -> bool {
        if !self.active.iter().any(|&a| a) {
            return false;
        }
        self.build_and_factor(rows, plan);
        self.rhs.clear();
        for (k, ri) in plan.rows() {
            let e = if self.active[k] {
                rhs(&rows[ri]).mul(self.scale[k])
            } else {
                S::ZERO
            };
            self.rhs.push(e);
        }
        self.substitute(plan.first);
        for (x, &s) in self.rhs.iter_mut().zip(&self.scale) {
            *x = x.mul(s);
        }
        true
    }
}

/// One exact velocity solve of a contact `group` planned by
/// [`plan_sparse`] (`order`, `first`), friction left to the caller.
pub(crate) fn solve_sparse_velocities<S: Scalar>(
    rows: &mut [ContactConstraint<S>],
    group: &[usize],
    (order, first): (&[u32], &[u32]),
    velocities: &mut [Vec2<S>],
    work: &mut SparseScratch<S>,
) {
    let plan = SparsePlan {
        group,
        order,
        first,
    };
    work.prepare(rows, plan);
    // The impulses and velocities at the start, for the single application
    // of the impulse changes at the end (below).
    work.start_impulse.clear();
    work.start_impulse
        .extend(group.iter().map(|&ri| rows[ri].normal_impulse));
    work.start_velocity.clear();
    for &ri in group {
        let row = &rows[ri];
        for (slot, w) in [(row.a, row.inverse_mass_a), (row.b, row.inverse_mass_b)] {
            if w.is_positive() {
                work.start_velocity.push((slot, velocities[slot as usize]));
            }
        }
    }
    let normal_velocity = |row: &ContactConstraint<S>, v: &[Vec2<S>]| {
        (v[row.b as usize] - v[row.a as usize]).dot(row.normal)
    };
    // Rows carrying impulse or short of their target start active (as in
    // the block solve).
    for (k, ri) in plan.rows() {
        let row = &rows[ri];
        work.active[k] = row.normal_impulse.is_positive()
            || !row.separation.is_positive()
            || normal_velocity(row, velocities) < row.target_velocity;
    }
    // Rows short of their target by more than this after a solution join
    // the active set (rounding leaves rows within it).
    let tolerance = S::from_ratio(1, 1 << 20);
    // Whether a solution was applied, and which rows it solved.
    let mut applied = false;
    // The releases since the last solution applied (row, impulse), undone
    // when the rounds run out before another is: a release alone leaves
    // the bodies its row held unsupported.
    work.released.clear();
    let mut finished = false;
    // The largest shortfall of an active row after the last solution
    // applied (refinement below).
    let mut last_residual = S::MAX;
    // Whether a row released in this solve was short again (single
    // exchanges from then on, below).
    let mut cycling = false;
    work.was_released.clear();
    work.was_released.resize(order.len(), 0);
    let rounds = (ROUND_WORK / work.work.max(1)).clamp(MIN_ROUNDS, MAX_ROUNDS);
    for _ in 0..rounds {
        let solved = work.solve_active(rows, plan, |row| {
            row.target_velocity.sub(normal_velocity(row, velocities))
        });
        if !solved {
            finished = true;
            break;
        }
        // Rows that would pull leave the set (their impulse zeroed), and
        // the rest is solved again; once the set cycles (below), only the
        // row that would pull hardest.
        let mut pull = (S::ZERO, usize::MAX);
        for (k, ri) in plan.rows() {
            let total = rows[ri].normal_impulse.add(work.rhs[k]);
            if work.active[k] && total < pull.0 {
                pull = (total, k);
            }
        }
        let mut released = false;
        for (k, ri) in plan.rows() {
            if work.active[k]
                && rows[ri].normal_impulse.add(work.rhs[k]).is_negative()
                && (!cycling || k == pull.1)
            {
                released = true;
                work.release(k, &mut rows[ri], ri, velocities);
            }
        }
        if released {
            last_residual = S::MAX;
            continue;
        }
        for (k, ri) in plan.rows() {
            if !work.active[k] {
                continue;
            }
            let x = work.rhs[k];
            rows[ri].normal_impulse = rows[ri].normal_impulse.add(x);
            let row = rows[ri];
            apply_impulse(&row, x, velocities);
        }
        applied = true;
        work.released.clear();
        work.solved.clear();
        work.solved.extend_from_slice(&work.active);
        // Iterative refinement (module notes): another round on what the
        // active rows still lack, with the same factor, while the largest
        // shortfall keeps halving (one that stops shrinking is a target
        // the other rows contradict: no round mends it). The rows off the
        // set see the active rows' shortfall too (a dependent row of a
        // pile is short by what its neighbours lack): while what they lack
        // is within four times the active rows' shortfall, refinement
        // comes first (taken in while the regularisation's shortfall
        // lasted, such rows were released and joined again in turn).
        let mut residual = S::ZERO;
        for (k, ri) in plan.rows() {
            if work.active[k] {
                let row = &rows[ri];
                residual = residual.max(
                    row.target_velocity
                        .sub(normal_velocity(row, velocities))
                        .abs(),
                );
            }
        }
        // The rows off the set short of their target: the shortest, and
        // whether one released twice in this solve is among them: the set
        // then cycles (rows of a statically
        // indeterminate pile taken in and released in turn: an even pile
        // under a ball 100× lighter than its circles never settled in 32
        // rounds, the last solution held some rows while others closed at
        // 0.3 units/s, and the pile sank 5–18 times its resting bound):
        // from then on one row changes per round, the shortest joining and
        // the hardest pulling leaving (single exchanges, as in Murty's
        // method).
        let mut short = (tolerance, usize::MAX);
        for (k, ri) in plan.rows() {
            let row = &rows[ri];
            let lack = row.target_velocity.sub(normal_velocity(row, velocities));
            if !work.active[k] && lack > tolerance {
                cycling |= work.was_released[k] >= 2;
                if lack > short.0 {
                    short = (lack, k);
                }
            }
        }
        let far_short = short.1 != usize::MAX && short.0 > residual.mul_int(4);
        let mut again = !far_short && residual > tolerance && residual < last_residual.half();
        let previous = last_residual;
        last_residual = residual;
        if !again && !far_short && previous != S::MAX && residual > tolerance {
            // The refinement stalls (module notes, "contradicting rows"):
            // each further round would move the impulses by `x` times the
            // shortfall's ratio `q = residual/previous` again (a geometric
            // series, `x·q/(1 − q)` in all), and a row it takes to zero
            // leaves the set then. The row that gets there first is
            // released now if the series reaches it: `imp ≤ |x|·q/(1 − q)`,
            // i.e. `imp·(previous − residual) ≤ |x|·residual` (always when
            // the shortfall does not shrink at all: a contradiction).
            let mut first = (S::MAX, usize::MAX);
            for (k, ri) in plan.rows() {
                let x = work.rhs[k];
                if work.active[k] && x.is_negative() {
                    let rounds = rows[ri].normal_impulse.div(x.neg());
                    if rounds < first.0 {
                        first = (rounds, k);
                    }
                }
            }
            let k = first.1;
            if k != usize::MAX
                && rows[plan.row(k)]
                    .normal_impulse
                    .wide_mul(previous.sub(residual))
                    <= work.rhs[k].neg().wide_mul(residual)
            {
                let ri = plan.row(k);
                work.release(k, &mut rows[ri], ri, velocities);
                last_residual = S::MAX;
                continue;
            }
        }
        if !again {
            // Rows the solution left short join the set for the next
            // round (a new set: its refinement starts afresh).
            for (k, ri) in plan.rows() {
                let row = &rows[ri];
                if !work.active[k]
                    && row.target_velocity.sub(normal_velocity(row, velocities)) > tolerance
                    && (!cycling || k == short.1)
                {
                    work.active[k] = true;
                    again = true;
                    last_residual = S::MAX;
                }
            }
        }
        if !again {
            finished = true;
            break;
        }
    }
    if !finished {
        for &(ri, old) in work.released.iter().rev() {
            rows[ri].normal_impulse = old;
        }
    }
    // The velocities as they were when the solve started.
    for &(slot, v) in &work.start_velocity {
        velocities[slot as usize] = v;
    }
    // The rounds applied and took back impulses row by row (a release
    // takes back everything its row received, each application rounded on
    // its own): rows that end where they started would leave a few ulps in
    // their bodies, and a released row at a slant would set a column of
    // circles aside by them (the group, then no longer along the axis, left
    // the exact solve in the next step: see `row_groups::resting_or_struck`).
    // So every row's change of impulse is applied once, in group order, to
    // the velocities the solve started from.
    for (&ri, &before) in group.iter().zip(&work.start_impulse) {
        let change = rows[ri].normal_impulse.sub(before);
        if change != S::ZERO {
            let row = rows[ri];
            apply_impulse(&row, change, velocities);
        }
    }
    work.active_rows.clear();
    for (k, ri) in plan.rows() {
        if applied && work.solved[k] {
            work.active_rows.push(ri);
        }
    }
    work.active_rows.sort_unstable();
    sequential_remainder(rows, group, velocities, applied, &work.active_rows, 0);
}

/// One exact position-correction solve of a contact `group` planned by
/// [`plan_sparse`]: rows stretched beyond the slop are pulled back by the
/// fraction `beta`, at most `max_correction`, as the block solve's
/// position pass does.
pub(crate) fn solve_sparse_positions<S: Scalar>(
    rows: &[ContactConstraint<S>],
    group: &[usize],
    (order, first): (&[u32], &[u32]),
    displacements: &mut [Vec2<S>],
    (slop, beta, max_correction): (S, S, S),
    work: &mut SparseScratch<S>,
) {
    let plan = SparsePlan {
        group,
        order,
        first,
    };
    work.prepare(rows, plan);
    let correction_of = |row: &ContactConstraint<S>, d: &[Vec2<S>]| {
        let separation = row
            .separation
            .add((d[row.b as usize] - d[row.a as usize]).dot(row.normal));
        beta.mul(separation.add(slop))
            .clamp(max_correction.neg(), S::ZERO)
    };
    for (k, ri) in plan.rows() {
        work.active[k] = correction_of(&rows[ri], displacements).is_negative();
    }
    for _ in 0..MIN_ROUNDS {
        let solved = work.solve_active(rows, plan, |row| correction_of(row, displacements).neg());
        if !solved {
            return;
        }
        let mut dropped = false;
        for k in 0..order.len() {
            if work.active[k] && work.rhs[k].is_negative() {
                work.active[k] = false;
                dropped = true;
            }
        }
        if !dropped {
            for (k, ri) in plan.rows() {
                if work.active[k] {
                    apply_impulse(&rows[ri], work.rhs[k], displacements);
                }
            }
            return;
        }
    }
}
