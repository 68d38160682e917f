//! The exact (direct) spring solve for stiff spring networks: the θ-method
//! system of a connected group of springs, factored and solved in body
//! space, so that the step's energy bound of [`crate::constraints`]
//! ("Energy: never gained") holds for stiff lattices too (maths there,
//! "Stiff networks: the direct solve").
//!
//! # The system
//!
//! With `p` the bodies' position velocities, `T = Θ_b·M⁻¹` (per body
//! `θ_b·w_b`), and the rows' impulses `λ_s = t_s − g_s·(G·p)_s` (bendy:
//! per lane; `t_s = −h·k_s·x_s`, `g_s = h·(θ_s·h·k_s + c_s)`), the step
//! solves `T⁻¹·(p − v₀) = Gᵀ·λ(p)`, i.e. for `δ = p − v₀`
//!
//! ```text
//! (T⁻¹ + Gᵀ·D_g·G)·δ = Gᵀ·(t − D_g·G·v₀)
//! ```
//!
//! a weighted graph Laplacian plus the positive diagonal `m_b/θ_b`:
//! symmetric positive definite, every pivot of its `L·D·Lᵀ` factor at
//! least `m_b/θ_b ≥ 2⁻¹¹` (a Schur complement keeps the diagonal
//! dominance of the mass term). The two lanes of bendy springs are two
//! independent such systems (shared when `k_x = k_y`); a radial row couples
//! the lanes through `g_s·d̂_s·d̂_sᵀ` (`d̂_s` the unit pole at the substep's
//! start, the linearisation of `l' − l ≈ h·d̂·(p_b − p_a)`), and the
//! system is solved per body as a 2 × 2 block.
//!
//! # The solve
//!
//! Gauss–Seidel converges on such a system at a rate set by its condition
//! number, about `(ω·h)²·(size)²`: at ω·h = 50 the 8 capped sweeps leave
//! most of the impulse unsolved, and the unsolved part is stored as spring
//! energy (the residual term `Σ r_s·Δx_s/h` of the energy balance, of
//! order `½·(ω·h)²·r²`), which is how stiff lattices gained energy. Here
//! the matrix is factored once (envelope `L·D·Lᵀ` in a reverse
//! Cuthill–McKee order: a chain or tree has no fill, an `n × m` lattice a
//! band of about `min(n, m)`), and the step iterates
//!
//! ```text
//! δ ← δ + A⁻¹·R(δ),   R(δ) = Gᵀ·λ(v₀ + δ) − T⁻¹·δ
//! ```
//!
//! with the rows' own (nonlinear, for radial rows) impulse formulas in
//! `R`: for bendy rows the first pass is the exact solution and the second
//! an iterative refinement of its rounding; for radial rows the passes are
//! a Newton iteration with the start-of-substep Jacobian. The impulses
//! `λ(p)` of the final `p` are then applied through the rows' own pushes
//! (so momentum is exchanged exactly as the sweeps do), and the sweeps
//! of `spring_solve.rs` finish from there (contacts, nonlinearity).
//!
//! All products are summed exactly in the wide type and narrowed once per
//! entry. The factor depends only on the masses, blends, gains and
//! topology (bendy) — constant while a lattice swings — so it is kept and
//! reused while the matrix is bit-for-bit the same (derived data: a
//! restored world refactors and gets the same bits).

use super::spring_solve::{RadialRow, SpringRow, radial_geometry};
use crate::math::{Scalar, Vec2, WideScalar};

/// A row is stiff when `g·(θ_a·w_a + θ_b·w_b) ≥ 1` in a lane, i.e. its
/// inverse diagonal `1/(1 + g·(θ_a·w_a + θ_b·w_b))` is at most ½ (equal
/// masses: ω·h ≳ 1.65). Below, the sweeps converge in a few passes (the
/// coupling to the neighbours is at most about `g·θ·w` of each impulse);
/// from here on they cannot, and a group holding a stiff row takes the
/// direct solve.
const STIFF_INVERSE_DIAGONAL: (i32, i32) = (1, 2);

/// The largest envelope (stored matrix entries) the direct solve takes on:
/// 2²² entries (32 MiB of matrix and factor for `I32F32`). A 256 × 256 bendy
/// lattice needs 2²⁴; such groups keep the sweeps.
const MAX_ENVELOPE: usize = 1 << 22;

/// Most passes of `δ ← δ + A⁻¹·R(δ)`. Linear (bendy-only) groups are exact
/// after one up to the factor's rounding; the next passes refine it (the
/// factor's entries carry an absolute rounding of about `ulp·g` against a
/// mass term `m/θ` that may be 10⁶ times smaller, so a pass contracts the
/// error by about 10⁻² at ω·h = 1000). Radial groups converge linearly at
/// a rate of about the pole's turn in the substep (`h·|v⊥|/l`). The passes
/// stop once one moves no velocity by more than [`PASS_TOLERANCE`]⁻¹ of
/// the first pass's largest move.
const LINEAR_PASSES: usize = 8;
const RADIAL_PASSES: usize = 8;
const PASS_TOLERANCE: i32 = 1 << 20;

/// "No unknown" in the per-slot index.
const NONE: u32 = u32::MAX;

/// A symmetric matrix stored by rows from each row's first nonzero column
/// to the diagonal, and its `L·D·Lᵀ` factor in the same shape.
#[derive(Clone, Debug, Default, PartialEq)]
struct Envelope<S: Scalar> {
    /// Row `i`'s first stored column.
    first: Vec<u32>,
    /// Where row `i` starts in `matrix` (length `n + 1`).
    offset: Vec<u32>,
    /// The entries `A_ij`, `first[i] ≤ j ≤ i`.
    matrix: Vec<S>,
}

impl<S: Scalar> Envelope<S> {
    fn len(&self) -> usize {
        self.first.len()
    }

    fn index(&self, row: usize, column: usize) -> usize {
        self.offset[row] as usize + (column - self.first[row] as usize)
    }

    /// Adds `value` to `A_uv` (and so to `A_vu`).
    fn add(&mut self, u: usize, v: usize, value: S) {
        let (row, column) = if u >= v { (u, v) } else { (v, u) };
        let i = self.index(row, column);
        self.matrix[i] = self.matrix[i].add(value);
    }
}

/// The `L·D·Lᵀ` factor: unit-lower `L` below the diagonal, `D` on it.
/// `None` when a pivot is not positive (cannot happen for the systems
/// built here, which are positive definite with pivots ≥ 2⁻¹¹; kept as a
/// guard against rounding at the ends of the number range).
fn factor<S: Scalar>(envelope: &Envelope<S>, out: &mut Vec<S>) -> bool {
    out.clear();
    out.extend_from_slice(&envelope.matrix);
    let n = envelope.len();
    for i in 0..n {
        let first_i = envelope.first[i] as usize;
        let row_i = envelope.offset[i] as usize;
        // u_ij = A_ij − Σ_k u_ik·L_jk (k from the later of the two rows'
        // first columns to j − 1), summed exactly; u_ij = L_ij·d_j.
        for j in first_i..i {
            let first_j = envelope.first[j] as usize;
            let row_j = envelope.offset[j] as usize;
            let start = first_i.max(first_j);
            let mut sum = S::Wide::from_narrow(out[row_i + (j - first_i)]);
            for k in start..j {
                sum = sum.sub(out[row_i + (k - first_i)].wide_mul(out[row_j + (k - first_j)]));
            }
            out[row_i + (j - first_i)] = sum.narrow();
        }
        // L_ij = u_ij / d_j, and d_i = A_ii − Σ_j u_ij·L_ij.
        let mut pivot = S::Wide::from_narrow(out[row_i + (i - first_i)]);
        for j in first_i..i {
            let d_j = out[envelope.offset[j] as usize + (j - envelope.first[j] as usize)];
            let u = out[row_i + (j - first_i)];
            let l = u.div(d_j);
            pivot = pivot.sub(u.wide_mul(l));
            out[row_i + (j - first_i)] = l;
        }
        let pivot = pivot.narrow();
        if !pivot.is_positive() {
            return false;
        }
        out[row_i + (i - first_i)] = pivot;
    }
    true
}

/// Solves `L·D·Lᵀ·x = b` in place (`b` becomes `x`); `wide` is scratch.
fn solve_factored<S: Scalar>(
    envelope: &Envelope<S>,
    factor: &[S],
    b: &mut [S],
    wide: &mut Vec<S::Wide>,
) {
    let n = envelope.len();
    // Forward: y_i = b_i − Σ_j L_ij·y_j, then z_i = y_i / d_i.
    for i in 0..n {
        let first = envelope.first[i] as usize;
        let row = envelope.offset[i] as usize;
        let mut sum = S::Wide::from_narrow(b[i]);
        for j in first..i {
            sum = sum.sub(factor[row + (j - first)].wide_mul(b[j]));
        }
        b[i] = sum.narrow();
    }
    for i in 0..n {
        let d = factor[envelope.index(i, i)];
        b[i] = b[i].div(d);
    }
    // Backward: x_j = z_j − Σ_{i>j} L_ij·x_i, by rows of L (columns of
    // Lᵀ), each x_j's sum kept exact until x_j is final.
    wide.clear();
    wide.extend(b.iter().map(|&z| S::Wide::from_narrow(z)));
    for i in (0..n).rev() {
        let x_i = wide[i].narrow();
        b[i] = x_i;
        let first = envelope.first[i] as usize;
        let row = envelope.offset[i] as usize;
        for j in first..i {
            wide[j] = wide[j].sub(factor[row + (j - first)].wide_mul(x_i));
        }
    }
}

/// Working memory and the kept factor of the direct solve (derived data,
/// never part of the world state).
#[derive(Clone, Debug)]
pub(crate) struct DirectScratch<S: Scalar> {
    /// Per row: solved here (its impulse is set and pushed).
    pub(crate) direct: Vec<bool>,
    /// Union–find parent per slot.
    parent: Vec<u32>,
    /// Per root slot: the group holds a stiff row / its row count.
    stiff: Vec<bool>,
    rows_in: Vec<u32>,
    /// Per slot: its body index in the elimination order, or [`NONE`].
    local: Vec<u32>,
    /// The slots of the unknowns, in elimination order.
    order: Vec<u32>,
    /// Neighbour lists (compressed rows over slots) and the search queue.
    start: Vec<u32>,
    neighbours: Vec<u32>,
    fill: Vec<u32>,
    queue: Vec<u32>,
    group: Vec<u32>,
    /// Where each group starts in `order` (and one past the last), and
    /// per group: a row of it ends on an immovable anchor.
    group_start: Vec<u32>,
    anchored: Vec<bool>,
    /// Per body unknown: `θ_b·w_b` and its inverse `m_b/θ_b`.
    position_push: Vec<S>,
    mass: Vec<S>,
    /// The matrix being built, and the kept one with its factor.
    building: Envelope<S>,
    kept: Envelope<S>,
    kept_factor: Vec<S>,
    kept_valid: bool,
    /// Two lanes in one system (radial rows or unequal lane gains).
    coupled: bool,
    /// Solve buffers.
    residual: Vec<Vec2<S>>,
    right: Vec<S>,
    wide: Vec<S::Wide>,
}

impl<S: Scalar> Default for DirectScratch<S> {
    fn default() -> Self {
        DirectScratch {
            direct: Vec::new(),
            parent: Vec::new(),
            stiff: Vec::new(),
            rows_in: Vec::new(),
            local: Vec::new(),
            order: Vec::new(),
            start: Vec::new(),
            neighbours: Vec::new(),
            fill: Vec::new(),
            queue: Vec::new(),
            group: Vec::new(),
            group_start: Vec::new(),
            anchored: Vec::new(),
            position_push: Vec::new(),
            mass: Vec::new(),
            building: Envelope::default(),
            kept: Envelope::default(),
            kept_factor: Vec::new(),
            kept_valid: false,
            coupled: false,
            residual: Vec::new(),
            right: Vec::new(),
            wide: Vec::new(),
        }
    }
}

/// The root of `slot`'s set (path halving).
fn find(parent: &mut [u32], mut slot: u32) -> u32 {
    while parent[slot as usize] != slot {
        let up = parent[parent[slot as usize] as usize];
        parent[slot as usize] = up;
        slot = up;
    }
    slot
}

impl<S: Scalar> DirectScratch<S> {
    /// Solves every group of rows joined through moving bodies that holds
    /// a stiff row (and more than one row) exactly, sets those rows'
    /// impulses and pushes them onto `position_velocities` (which hold `v₀`
    /// on entry), and marks them in [`Self::direct`]. Returns `true` if it
    /// solved any row.
    pub(crate) fn solve(
        &mut self,
        rows: &mut [SpringRow<S>],
        radial: &mut [RadialRow<S>],
        velocities: &[Vec2<S>],
        position_velocities: &mut [Vec2<S>],
        h: S,
    ) -> bool {
        self.direct.clear();
        self.direct.resize(rows.len(), false);
        let slots = position_velocities.len();
        if !self.find_stiff_groups(rows, slots) {
            return false;
        }
        if !self.order_unknowns(rows, slots) {
            self.direct.iter_mut().for_each(|d| *d = false);
            return false;
        }
        self.collect_masses(rows);
        self.coupled = rows
            .iter()
            .zip(&self.direct)
            .any(|(row, &d)| d && (row.radial || row.rate_gain.x != row.rate_gain.y));
        let lanes = if self.coupled { 2 } else { 1 };
        if !self.build_matrix(rows, radial, lanes) {
            self.direct.iter_mut().for_each(|d| *d = false);
            return false;
        }
        if !(self.kept_valid && self.building == self.kept) {
            core::mem::swap(&mut self.building, &mut self.kept);
            self.kept_valid = factor(&self.kept, &mut self.kept_factor);
        }
        if !self.kept_valid {
            self.direct.iter_mut().for_each(|d| *d = false);
            return false;
        }
        let any_radial = rows.iter().zip(&self.direct).any(|(r, &d)| d && r.radial);
        let passes = if any_radial {
            RADIAL_PASSES
        } else {
            LINEAR_PASSES
        };
        let mut first = S::ZERO;
        for pass in 0..passes {
            let largest = self.correct(rows, radial, velocities, position_velocities, h);
            if pass == 0 {
                first = largest;
            } else if largest <= first.mul(S::from_ratio(1, PASS_TOLERANCE)) {
                break;
            }
        }
        self.keep_momentum(rows, velocities, position_velocities);
        self.apply(rows, radial, position_velocities, h);
        true
    }

    /// Union–find over the rows' moving ends; marks the rows of groups
    /// with a stiff row and at least two rows. Returns whether any.
    fn find_stiff_groups(&mut self, rows: &[SpringRow<S>], slots: usize) -> bool {
        let stiff_limit = S::from_ratio(STIFF_INVERSE_DIAGONAL.0, STIFF_INVERSE_DIAGONAL.1);
        let is_stiff =
            |row: &SpringRow<S>| row.inverse_diagonal.x.min(row.inverse_diagonal.y) <= stiff_limit;
        if !rows.iter().any(is_stiff) {
            return false;
        }
        self.parent.clear();
        self.parent.extend(0..slots as u32);
        for row in rows {
            if row.inverse_masses.0.is_positive() && row.inverse_masses.1.is_positive() {
                let (ra, rb) = (find(&mut self.parent, row.a), find(&mut self.parent, row.b));
                // The smaller slot is the root (deterministic).
                let (low, high) = if ra < rb { (ra, rb) } else { (rb, ra) };
                self.parent[high as usize] = low;
            }
        }
        self.stiff.clear();
        self.stiff.resize(slots, false);
        self.rows_in.clear();
        self.rows_in.resize(slots, 0);
        for row in rows.iter() {
            let root = find(&mut self.parent, moving_end(row));
            self.rows_in[root as usize] += 1;
            if is_stiff(row) {
                self.stiff[root as usize] = true;
            }
        }
        let mut any = false;
        for (i, row) in rows.iter().enumerate() {
            let root = find(&mut self.parent, moving_end(row)) as usize;
            if self.stiff[root] && self.rows_in[root] >= 2 {
                self.direct[i] = true;
                any = true;
            }
        }
        any
    }

    /// Orders the moving bodies of the direct rows (reverse Cuthill–McKee
    /// per group: breadth first from a body of least degree, neighbours by
    /// degree then slot, reversed) and sizes the envelope. Returns `false`
    /// if the envelope would exceed [`MAX_ENVELOPE`].
    fn order_unknowns(&mut self, rows: &[SpringRow<S>], slots: usize) -> bool {
        // Neighbour lists over slots (compressed rows).
        self.start.clear();
        self.start.resize(slots + 1, 0);
        self.local.clear();
        self.local.resize(slots, NONE);
        let moving_pairs = rows
            .iter()
            .zip(&self.direct)
            .filter(|(row, d)| {
                **d && row.inverse_masses.0.is_positive() && row.inverse_masses.1.is_positive()
            })
            .map(|(row, _)| (row.a, row.b));
        for (a, b) in moving_pairs.clone() {
            self.start[a as usize + 1] += 1;
            self.start[b as usize + 1] += 1;
        }
        for i in 0..slots {
            self.start[i + 1] += self.start[i];
        }
        self.fill.clear();
        self.fill.extend_from_slice(&self.start[..slots]);
        self.neighbours.clear();
        self.neighbours.resize(self.start[slots] as usize, 0);
        for (a, b) in moving_pairs {
            self.neighbours[self.fill[a as usize] as usize] = b;
            self.fill[a as usize] += 1;
            self.neighbours[self.fill[b as usize] as usize] = a;
            self.fill[b as usize] += 1;
        }
        let degree = |start: &[u32], slot: u32| start[slot as usize + 1] - start[slot as usize];
        // Sort each neighbour list by (degree, slot).
        for slot in 0..slots {
            let range = self.start[slot] as usize..self.start[slot + 1] as usize;
            let start = &self.start;
            self.neighbours[range].sort_unstable_by_key(|&s| (degree(start, s), s));
        }
        // The moving ends of direct rows, in slot order, are the bodies.
        let mut is_body = core::mem::take(&mut self.fill);
        is_body.clear();
        is_body.resize(slots, 0);
        for (row, _) in rows.iter().zip(&self.direct).filter(|(_, d)| **d) {
            for (slot, w) in [(row.a, row.inverse_masses.0), (row.b, row.inverse_masses.1)] {
                if w.is_positive() {
                    is_body[slot as usize] = 1;
                }
            }
        }
        self.order.clear();
        self.group_start.clear();
        for seed in 0..slots as u32 {
            if is_body[seed as usize] != 1 {
                continue;
            }
            // The group: breadth first from the seed (marks 2).
            self.group.clear();
            self.group.push(seed);
            is_body[seed as usize] = 2;
            let mut head = 0;
            while head < self.group.len() {
                let slot = self.group[head];
                head += 1;
                let range =
                    self.start[slot as usize] as usize..self.start[slot as usize + 1] as usize;
                for &next in &self.neighbours[range] {
                    if is_body[next as usize] == 1 {
                        is_body[next as usize] = 2;
                        self.group.push(next);
                    }
                }
            }
            // A body of least degree (smallest slot on ties) starts.
            let root = self
                .group
                .iter()
                .copied()
                .min_by_key(|&s| (degree(&self.start, s), s))
                .unwrap_or(seed);
            let begin = self.order.len();
            self.queue.clear();
            self.queue.push(root);
            is_body[root as usize] = 3;
            let mut head = 0;
            while head < self.queue.len() {
                let slot = self.queue[head];
                head += 1;
                self.order.push(slot);
                let range =
                    self.start[slot as usize] as usize..self.start[slot as usize + 1] as usize;
                for &next in &self.neighbours[range] {
                    if is_body[next as usize] == 2 {
                        is_body[next as usize] = 3;
                        self.queue.push(next);
                    }
                }
            }
            self.order[begin..].reverse();
            self.group_start.push(begin as u32);
        }
        self.fill = is_body;
        self.group_start.push(self.order.len() as u32);
        for (index, &slot) in self.order.iter().enumerate() {
            self.local[slot as usize] = index as u32;
        }
        // Envelope: each body's first column is its earliest neighbour.
        let lanes = 2; // sized for the coupled case; trimmed in build_matrix
        let mut entries = 0usize;
        for (index, &slot) in self.order.iter().enumerate() {
            let range = self.start[slot as usize] as usize..self.start[slot as usize + 1] as usize;
            let first = self.neighbours[range]
                .iter()
                .map(|&s| self.local[s as usize] as usize)
                .fold(index, usize::min);
            entries += lanes * lanes * (index - first) + lanes * (lanes + 1) / 2;
            if entries > MAX_ENVELOPE {
                return false;
            }
        }
        true
    }

    /// `θ_b·w_b` and `m_b/θ_b` per body unknown (from the rows' pushes).
    fn collect_masses(&mut self, rows: &[SpringRow<S>]) {
        let n = self.order.len();
        self.position_push.clear();
        self.position_push.resize(n, S::ZERO);
        for (row, _) in rows.iter().zip(&self.direct).filter(|(_, d)| **d) {
            for (slot, push) in [(row.a, row.position_push.0), (row.b, row.position_push.1)] {
                let local = self.local[slot as usize];
                if local != NONE {
                    self.position_push[local as usize] = push;
                }
            }
        }
        self.mass.clear();
        let mut last = (S::ZERO, S::ZERO);
        for &push in &self.position_push {
            if push != last.0 {
                // θ_b·w_b ≥ ½·2⁻²⁰ > 0 for a moving body.
                last = (push, S::ONE.div(push));
            }
            self.mass.push(last.1);
        }
    }

    /// Builds `T⁻¹ + Gᵀ·D_g·G` in the envelope (one unknown per body, or
    /// two, interleaved x/y, when `lanes` is 2).
    fn build_matrix(
        &mut self,
        rows: &[SpringRow<S>],
        radial: &[RadialRow<S>],
        lanes: usize,
    ) -> bool {
        let n = self.order.len();
        let env = &mut self.building;
        env.first.clear();
        env.offset.clear();
        env.offset.push(0);
        for (index, &slot) in self.order.iter().enumerate() {
            let range = self.start[slot as usize] as usize..self.start[slot as usize + 1] as usize;
            let first = self.neighbours[range]
                .iter()
                .map(|&s| self.local[s as usize] as usize)
                .fold(index, usize::min);
            for lane in 0..lanes {
                let unknown = index * lanes + lane;
                env.first.push((first * lanes) as u32);
                let last = *env.offset.last().unwrap_or(&0);
                env.offset.push(last + (unknown - first * lanes + 1) as u32);
            }
        }
        let total = *env.offset.last().unwrap_or(&0) as usize;
        if total > MAX_ENVELOPE {
            return false;
        }
        env.matrix.clear();
        env.matrix.resize(total, S::ZERO);
        for body in 0..n {
            for lane in 0..lanes {
                let u = body * lanes + lane;
                env.add(u, u, self.mass[body]);
            }
        }
        let mut radial_rows = radial.iter();
        for (row, &direct) in rows.iter().zip(&self.direct) {
            let geometry = if row.radial { radial_rows.next() } else { None };
            if !direct {
                continue;
            }
            let ends = [self.local[row.a as usize], self.local[row.b as usize]];
            // The row's lane coupling: diag(g_x, g_y) for a bendy row,
            // g·d̂·d̂ᵀ for a radial one (d̂ the unit pole at the start).
            let block = match geometry {
                Some(geometry) => {
                    let g = row.rate_gain.x;
                    let d = geometry.offset.try_normalize().unwrap_or(Vec2::Y);
                    let gx = d.scale(g);
                    [
                        [gx.x.mul(d.x), gx.x.mul(d.y)],
                        [gx.x.mul(d.y), gx.y.mul(d.y)],
                    ]
                }
                None => [[row.rate_gain.x, S::ZERO], [S::ZERO, row.rate_gain.y]],
            };
            for (i, &ei) in ends.iter().enumerate() {
                if ei == NONE {
                    continue;
                }
                for (j, &ej) in ends.iter().enumerate() {
                    if ej == NONE || ej > ei {
                        continue;
                    }
                    // +block on the diagonal blocks, −block between.
                    let negative = i != j;
                    for (li, block_row) in block.iter().enumerate().take(lanes) {
                        for (lj, &value) in block_row.iter().enumerate().take(lanes) {
                            let u = ei as usize * lanes + li;
                            let v = ej as usize * lanes + lj;
                            if ei == ej && v > u {
                                continue;
                            }
                            env.add(u, v, if negative { value.neg() } else { value });
                        }
                    }
                }
            }
        }
        true
    }

    /// The impulse vector of a direct row at the position velocities `p`
    /// (bendy: per lane; radial: `λ·d` and `λ`).
    fn row_impulse(
        row: &SpringRow<S>,
        geometry: Option<&RadialRow<S>>,
        p: &[Vec2<S>],
        h: S,
    ) -> (Vec2<S>, S) {
        let (p_a, p_b) = (p[row.a as usize], p[row.b as usize]);
        match geometry {
            Some(geometry) => {
                let (end_length, direction) = radial_geometry(geometry, (p_a, p_b), h);
                let lambda = row.target.x.sub(
                    geometry
                        .gain_per_length
                        .mul(end_length.sub(geometry.length)),
                );
                (direction.scale(lambda), lambda)
            }
            None => {
                let lambda = row.target - row.rate_gain.mul_elements(p_b - p_a);
                (lambda, S::ZERO)
            }
        }
    }

    /// One pass `p ← p + A⁻¹·R(p)`; returns its largest velocity change.
    fn correct(
        &mut self,
        rows: &[SpringRow<S>],
        radial: &[RadialRow<S>],
        velocities: &[Vec2<S>],
        p: &mut [Vec2<S>],
        h: S,
    ) -> S {
        let n = self.order.len();
        self.residual.clear();
        self.residual.resize(n, Vec2::ZERO);
        let mut radial_rows = radial.iter();
        for (row, &direct) in rows.iter().zip(&self.direct) {
            let geometry = if row.radial { radial_rows.next() } else { None };
            if !direct {
                continue;
            }
            let (impulse, _) = Self::row_impulse(row, geometry, p, h);
            let (a, b) = (self.local[row.a as usize], self.local[row.b as usize]);
            if a != NONE {
                self.residual[a as usize] -= impulse;
            }
            if b != NONE {
                self.residual[b as usize] += impulse;
            }
        }
        for (body, &slot) in self.order.iter().enumerate() {
            let moved = p[slot as usize] - velocities[slot as usize];
            self.residual[body] -= moved.scale(self.mass[body]);
        }
        let mut largest = S::ZERO;
        if self.coupled {
            self.right.clear();
            for r in &self.residual {
                self.right.push(r.x);
                self.right.push(r.y);
            }
            solve_factored(
                &self.kept,
                &self.kept_factor,
                &mut self.right,
                &mut self.wide,
            );
            for (body, &slot) in self.order.iter().enumerate() {
                let step = Vec2::new(self.right[2 * body], self.right[2 * body + 1]);
                p[slot as usize] += step;
            }
            largest = self.right.iter().fold(largest, |m, d| m.max(d.abs()));
        } else {
            for lane in 0..2 {
                self.right.clear();
                self.right.extend(
                    self.residual
                        .iter()
                        .map(|r| if lane == 0 { r.x } else { r.y }),
                );
                solve_factored(
                    &self.kept,
                    &self.kept_factor,
                    &mut self.right,
                    &mut self.wide,
                );
                for (body, &slot) in self.order.iter().enumerate() {
                    let v = &mut p[slot as usize];
                    if lane == 0 {
                        v.x = v.x.add(self.right[body]);
                    } else {
                        v.y = v.y.add(self.right[body]);
                    }
                }
                largest = self.right.iter().fold(largest, |m, d| m.max(d.abs()));
            }
        }
        largest
    }

    /// Gives every free group (no row on an immovable anchor) back its
    /// linear momentum exactly. The internal impulses cancel in pairs, so
    /// the step must leave `Σ_b (m_b/θ_b)·(p_b − v₀_b)` (the momentum the
    /// velocities `v = v₀ + (p − v₀)/θ_b` change by) at zero; the solve
    /// leaves its final residual there, and fixed-point products round
    /// toward −∞, so that drift has a sign (a free 32 × 32 lattice at
    /// ω·h = 10 lost 0.6 % of its centre-of-mass energy in 10 s). A
    /// uniform shift `c` of the group's `p` changes no internal stretch rate
    /// (exact fixed-point differences) and removes the defect up to one
    /// rounding of `c`.
    fn keep_momentum(&mut self, rows: &[SpringRow<S>], velocities: &[Vec2<S>], p: &mut [Vec2<S>]) {
        let groups = self.group_start.len().saturating_sub(1);
        self.anchored.clear();
        self.anchored.resize(groups, false);
        // The group of each body (groups are contiguous in `order`).
        for (row, _) in rows.iter().zip(&self.direct).filter(|(_, d)| **d) {
            if row.inverse_masses.0.is_positive() && row.inverse_masses.1.is_positive() {
                continue;
            }
            let local = self.local[moving_end(row) as usize];
            if local == NONE {
                continue;
            }
            let group = self.group_start.partition_point(|&start| start <= local) - 1;
            self.anchored[group] = true;
        }
        for group in 0..groups {
            if self.anchored[group] {
                continue;
            }
            let range = self.group_start[group] as usize..self.group_start[group + 1] as usize;
            let (mut defect_x, mut defect_y, mut total) =
                (S::Wide::ZERO, S::Wide::ZERO, S::Wide::ZERO);
            for body in range.clone() {
                let slot = self.order[body] as usize;
                let moved = p[slot] - velocities[slot];
                let mass = self.mass[body];
                defect_x = defect_x.add(mass.wide_mul(moved.x));
                defect_y = defect_y.add(mass.wide_mul(moved.y));
                total = total.add(S::Wide::from_narrow(mass));
            }
            let total = total.narrow();
            if !total.is_positive() {
                continue;
            }
            // c = −D/Σm rounded to the nearest step (a truncated quotient
            // leaves a remainder of D's sign every substep: a drift).
            let nearest = |defect: S::Wide| {
                let quotient = defect.narrow().div(total);
                let remainder = defect.sub(quotient.wide_mul(total)).narrow();
                let half_step = total.mul(S::EPSILON).half();
                let quotient = if remainder > half_step {
                    quotient.add(S::EPSILON)
                } else if remainder < half_step.neg() {
                    quotient.sub(S::EPSILON)
                } else {
                    quotient
                };
                quotient.neg()
            };
            let shift = Vec2::new(nearest(defect_x), nearest(defect_y));
            for body in range {
                p[self.order[body] as usize] += shift;
            }
        }
    }

    /// Sets the direct rows' impulses from the solved `p` (the sweeps'
    /// bookkeeping: each row's own equation then holds exactly at `p`, so
    /// a sweep finds nothing to change). `p` itself is kept: pushing the
    /// impulses back onto `v₀` would move each body by `θ_b·w_b` times the
    /// solve's rounding residual, which a stiff spring turns into stored
    /// energy of order `½·(ω·h)²·(θ·w·residual)²/W`.
    fn apply(
        &mut self,
        rows: &mut [SpringRow<S>],
        radial: &mut [RadialRow<S>],
        p: &[Vec2<S>],
        h: S,
    ) {
        let mut radial_rows = radial.iter_mut();
        for (row, &direct) in rows.iter_mut().zip(&self.direct) {
            let geometry = if row.radial { radial_rows.next() } else { None };
            if !direct {
                continue;
            }
            let (impulse, lambda) = Self::row_impulse(row, geometry.as_deref(), p, h);
            match geometry {
                Some(geometry) => {
                    row.impulse = Vec2::new(lambda, S::ZERO);
                    geometry.applied = impulse;
                }
                None => row.impulse = impulse,
            }
        }
    }
}

/// A moving end of a row (`w_a + w_b > 0`, so one is).
fn moving_end<S: Scalar>(row: &SpringRow<S>) -> u32 {
    if row.inverse_masses.1.is_positive() {
        row.b
    } else {
        row.a
    }
}
