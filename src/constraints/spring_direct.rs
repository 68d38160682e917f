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
//! the lanes through `g_s·n·nᵀ + γ_s·(I − n·nᵀ)` (`n` the unit direction of
//! its impulse, `γ_s` the sideways stiffness of its tension, see
//! [`radial_stiffness`]: the symmetric part of the row's Jacobian at the
//! current iterate), and the
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
//! a Newton iteration in its mixed form (the sideways stiffness taken from
//! the tension the step's linear model predicts, see
//! [`DirectScratch::solve`]): the factor of an earlier pass of the same
//! solve (never of an earlier step, unless the matrix is the same bit for
//! bit: a restored world must step identically) is used while each pass
//! on it shrinks the correction 4×, and a pass that
//! does not is undone and redone on the matrix at the current iterate (a
//! pole turning fast within the substep). A solve that still does not
//! converge is made energy-safe by [`DirectScratch::solve`]'s check (the
//! residual's work at most the body dissipation). The impulses
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
use super::spring_support::{SupportRow, SupportScratch};
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
/// Radial groups: Newton passes (the linearisation is refreshed where a
/// pass contracts by less than 4×).
const RADIAL_PASSES: usize = 16;
const PASS_TOLERANCE: i32 = 1 << 20;
/// Radial groups: Newton converges quadratically until the factor's
/// rounding takes over; a pass below 2⁻¹⁰ of the first that shrinks the
/// correction by less than 2× has reached that floor (at ω·h = 3000 about
/// 2⁻²¹ of the first pass), and more passes would only repeat it.
const STAGNATION_TOLERANCE: i32 = 1 << 10;

/// Most support (contact) rows solved with a direct group
/// ([`DirectScratch::couple_contacts`]: one factored solve each, and a
/// dense Delassus matrix); a group touching more keeps the sweeps' view of
/// its contacts.
const MAX_COUPLED_CONTACTS: usize = 256;
/// Projected Gauss–Seidel sweeps on the contacts' Delassus matrix, and the
/// stop: a sweep changing no impulse by more than 2⁻¹⁶ of the largest.
const CONTACT_SWEEPS: usize = 64;
const CONTACT_TOLERANCE: i32 = 1 << 16;
/// Rounds of (Newton passes, contact impulses) after the first.
const CONTACT_ROUNDS: usize = 4;

/// "No unknown" in the per-slot index (and "no contact" in
/// `DirectScratch::contact_partner`).
const NONE: u32 = u32::MAX;
/// "Contacts with more than two bodies" in
/// `DirectScratch::contact_partner`.
const MANY: u32 = u32::MAX - 1;

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
    /// Per slot: an end of a bounce launched in the spring solve
    /// (`SpringScratch::launch_bounces`); counts as a row of its group,
    /// so one stiff spring and a bounce are solved exactly together.
    pub(crate) launched_ends: Vec<bool>,
    /// Union–find parent per slot.
    parent: Vec<u32>,
    /// Per slot: the (up to two) bodies its support (contact) rows join it
    /// to, [`NONE`] where there are fewer, `[MANY; 2]` if more than two
    /// (see [`Self::find_stiff_groups`]), and whether it is the end of a
    /// support row that no impulse moves (a wall).
    contact_partner: Vec<[u32; 2]>,
    immovable: Vec<bool>,
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
    /// Per body unknown: `w_b` (the energy check's dissipation term).
    inverse_mass: Vec<S>,
    /// Per group: the energy check's state (see [`Self::keep_energy`]),
    /// the blend it took, and (per contact of [`Self::contacts`]) the safe
    /// point's contact impulses.
    blend: Vec<S>,
    taken_blend: Vec<S>,
    safe_impulses: Vec<S>,
    /// Per group: its mean position velocity, its safe point and its
    /// summed `m_b/θ_b` ([`Self::keep_energy`]).
    rigid: Vec<(Vec2<S>, Vec2<S>, S)>,
    /// Per movable body outside the direct groups that held contacts join
    /// to one free group: its slot, that group, and its position velocity
    /// at the group's safe point and at the Newton iterate
    /// ([`Self::find_outside_bodies`]).
    outside: Vec<(u32, u32, Vec2<S>, Vec2<S>)>,
    /// Per body unknown: the Newton iterate `p_N` and the safe point.
    newton: Vec<Vec2<S>>,
    safe: Vec<Vec2<S>>,
    /// The matrix being built, and the kept one with its factor.
    building: Envelope<S>,
    kept: Envelope<S>,
    kept_factor: Vec<S>,
    kept_valid: bool,
    /// Two lanes in one system (radial rows or unequal lane gains).
    coupled: bool,
    /// Per slot: the velocity gravity gave the body at the start of the
    /// substep (`h·g⃗` times its gravity scale; filled by the caller for
    /// scenes with radial springs, empty otherwise), for the energy check
    /// of [`Self::keep_energy`].
    pub(crate) kicks: Vec<Vec2<S>>,
    /// Per radial row (in radial order): the tension estimate the Newton
    /// matrix's sideways stiffness is built from (`None` before the first
    /// pass: the impulse at `p = v₀`), and per radial row the pass's
    /// linearisation `(λ(p), r̂')` at the iterate it started from.
    tension: Vec<Option<S>>,
    saved_tension: Vec<Option<S>>,
    linearisation: Vec<(S, Vec2<S>)>,
    /// The support (contact) rows that reach a direct body, each one's
    /// response `A⁻¹·T⁻¹·P_c` per body unknown (row-major, one block of
    /// `order.len()` per contact), their Delassus matrix (row-major) and
    /// impulses, and the start velocities with the contacts' pushes
    /// (see [`Self::couple_contacts`]).
    contacts: Vec<u32>,
    responses: Vec<Vec2<S>>,
    delassus: Vec<S>,
    impulses: Vec<S>,
    changes: Vec<S>,
    shifted: Vec<Vec2<S>>,
    /// Solve buffers.
    residual: Vec<Vec2<S>>,
    right: Vec<S>,
    wide: Vec<S::Wide>,
}

impl<S: Scalar> Default for DirectScratch<S> {
    fn default() -> Self {
        DirectScratch {
            launched_ends: Vec::new(),
            direct: Vec::new(),
            parent: Vec::new(),
            contact_partner: Vec::new(),
            immovable: Vec::new(),
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
            inverse_mass: Vec::new(),
            blend: Vec::new(),
            taken_blend: Vec::new(),
            safe_impulses: Vec::new(),
            rigid: Vec::new(),
            outside: Vec::new(),
            newton: Vec::new(),
            safe: Vec::new(),
            building: Envelope::default(),
            kept: Envelope::default(),
            kept_factor: Vec::new(),
            kept_valid: false,
            coupled: false,
            kicks: Vec::new(),
            tension: Vec::new(),
            saved_tension: Vec::new(),
            linearisation: Vec::new(),
            contacts: Vec::new(),
            responses: Vec::new(),
            delassus: Vec::new(),
            impulses: Vec::new(),
            changes: Vec::new(),
            shifted: Vec::new(),
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
        supports: &mut SupportScratch<S>,
        (velocities, position_velocities): (&[Vec2<S>], &mut [Vec2<S>]),
        h: S,
        every_group: bool,
    ) -> bool {
        self.direct.clear();
        self.direct.resize(rows.len(), false);
        let slots = position_velocities.len();
        if !self.find_stiff_groups(rows, &supports.rows, slots, every_group) {
            return false;
        }
        if !self.order_unknowns(rows, slots) {
            self.direct.iter_mut().for_each(|d| *d = false);
            return false;
        }
        self.collect_masses(rows);
        self.tension.clear();
        self.tension.resize(radial.len(), None);
        self.linearisation.clear();
        self.linearisation
            .resize(radial.len(), (S::ZERO, Vec2::ZERO));
        self.coupled = rows
            .iter()
            .zip(&self.direct)
            .any(|(row, &d)| d && (row.radial || row.rate_gain.x != row.rate_gain.y));
        let lanes = if self.coupled { 2 } else { 1 };
        if !self.build_matrix(rows, radial, lanes, (position_velocities, h)) {
            self.direct.iter_mut().for_each(|d| *d = false);
            return false;
        }
        let any_radial = rows.iter().zip(&self.direct).any(|(r, &d)| d && r.radial);
        // Every solve starts on the factor of its own first matrix (built
        // at `p = v₀`): a factor kept from an earlier solve is reused only
        // when the matrix is the same bit for bit (derived data that a
        // restored world recomputes identically; a radial group whose
        // poles turned between steps has another matrix and refactors).
        // Later passes of this solve run on it as a chord (modified
        // Newton) iteration until one does not contract 4× (below).
        if !(self.kept_valid && self.building == self.kept) {
            core::mem::swap(&mut self.building, &mut self.kept);
            self.kept_valid = factor(&self.kept, &mut self.kept_factor);
        }
        if !self.kept_valid {
            self.direct.iter_mut().for_each(|d| *d = false);
            return false;
        }
        self.iterate(
            rows,
            radial,
            (velocities, position_velocities),
            (h, lanes, any_radial),
            false,
        );
        let mut shifted = core::mem::take(&mut self.shifted);
        let coupled = self.couple_contacts(supports, velocities, position_velocities, &mut shifted);
        let mut settled = true;
        if coupled {
            settled = false;
            // The contacts' impulses are now fixed loads: the exact
            // (Newton) solve again from the linear prediction, on the
            // same factor (a chord iteration while it contracts); the
            // contacts then see the nonlinear answer, until their
            // impulses settle.
            for _ in 0..CONTACT_ROUNDS {
                if any_radial {
                    // The passes on the matrix where the contacts' linear
                    // increments put the group: they turn its poles, and a
                    // very stiff pole's curvature over that turn is an
                    // impulse far larger than the contacts' (3 links of
                    // 0.003 at ω·h = 1000 resting on the ground: λ ≈ 1
                    // against a contact impulse of 7·10⁻⁴), which the
                    // factor of the poles before the turn projected into
                    // the soft sideways motions (a first pass of 2.5 u/s,
                    // then 7·10⁴: the rounds never settled).
                    if !self.refactor_at(rows, radial, lanes, (position_velocities, h)) {
                        break;
                    }
                }
                self.iterate(
                    rows,
                    radial,
                    (&shifted, position_velocities),
                    (h, lanes, any_radial),
                    true,
                );
                if any_radial {
                    // The contacts' next increments on the group's
                    // linearisation here (an impact turns and loads the
                    // poles: the start's matrix then misjudges the
                    // response, and the rounds overshoot).
                    if !self.refactor_at(rows, radial, lanes, (position_velocities, h)) {
                        break;
                    }
                    self.contact_responses(supports);
                }
                let total = self.impulses.iter().fold(S::ZERO, |m, x| m.max(x.abs()));
                let change = self.solve_contacts(supports, position_velocities, &mut shifted);
                if change <= total.mul(S::from_ratio(1, CONTACT_TOLERANCE)) {
                    settled = true;
                    break;
                }
            }
            self.iterate(
                rows,
                radial,
                (&shifted, position_velocities),
                (h, lanes, any_radial),
                true,
            );
            self.keep_momentum(rows, &shifted, position_velocities);
            // The contacts' impulses count in the group's energy balance
            // like any impulse no spring row accounts for (the residual
            // `ρ` of [`Self::keep_energy`], taken against the start `v₀`
            // without them), and they are final: the contact solve leaves
            // these rows alone (`world/step/constraints.rs`). Rounds that
            // did not settle (an impact that turns and loads the poles
            // faster than the linearisations follow) leave a residual
            // doing work, which [`Self::keep_energy`] takes out like any
            // other. (Dropping such a solution and solving the group
            // without its contacts, as before, left the contact solve to
            // stop the struck body alone against the stiff group: a
            // 2-link chain of 0.001 at ω·h = 300 striking the ground
            // gained 0.17 J, 28× its energy, in that substep.)
        }
        if !coupled {
            self.keep_momentum(rows, velocities, position_velocities);
        }
        if any_radial || coupled {
            let held = coupled.then_some(&mut *supports);
            self.keep_energy(
                rows,
                radial,
                (held, settled),
                velocities,
                position_velocities,
                h,
            );
        }
        self.apply(rows, radial, position_velocities, h);
        self.shifted = shifted;
        true
    }

    /// The passes `p ← p + A⁻¹·R(p)` from `p` (see the module docs) with
    /// `velocities` as `v₀`; `stale`: the kept factor is from an earlier
    /// iterate (a chord iteration, redone on a fresh matrix where a pass
    /// does not contract 4×).
    fn iterate(
        &mut self,
        rows: &[SpringRow<S>],
        radial: &[RadialRow<S>],
        (velocities, position_velocities): (&[Vec2<S>], &mut [Vec2<S>]),
        (h, lanes, any_radial): (S, usize, bool),
        stale: bool,
    ) {
        let mut stale = stale && any_radial;
        let passes = if any_radial {
            RADIAL_PASSES
        } else {
            LINEAR_PASSES
        };
        let mut first = S::ZERO;
        let mut previous = S::ZERO;
        let mut relinearise = false;
        for pass in 0..passes {
            if relinearise {
                // Newton: the matrix at the current iterate.
                if !self.refactor_at(rows, radial, lanes, (position_velocities, h)) {
                    break;
                }
                stale = false;
            }
            if stale {
                self.save_iterate(position_velocities);
            }
            let largest = self.correct(rows, radial, velocities, position_velocities, h);
            if pass == 0 {
                first = largest;
            } else if largest <= first.mul(S::from_ratio(1, PASS_TOLERANCE))
                || (any_radial
                    && largest > previous.half()
                    && (!stale || largest <= first.mul(S::from_ratio(1, STAGNATION_TOLERANCE))))
            {
                // Converged; or the correction stopped shrinking at the
                // factor's rounding, or on a matrix built at this iterate
                // (Newton itself stalls: [`Self::keep_energy`] takes over).
                break;
            }
            if stale && pass > 0 && largest > previous.mul(S::from_ratio(1, 4)) {
                // A pass on a matrix from an earlier iterate that did not
                // contract the correction 4× (the poles turned within the
                // substep): undone, and redone with the matrix here.
                self.restore_iterate(position_velocities);
                relinearise = true;
                continue;
            }
            relinearise = false;
            stale = any_radial;
            previous = largest;
        }
    }

    /// Solves the support (contact) rows that reach a direct body together
    /// with the group's exact solve, so that neither the springs nor the
    /// contacts answer with the wrong effective mass. Returns whether any
    /// contact pushes (then `shifted` is `v₀` plus the contacts' pushes,
    /// `p` the group's linear response to them, and the support rows carry
    /// their impulses; their pushes are kept, see
    /// [`SupportScratch::take_back`]).
    ///
    /// Why: a contact impulse `μ` on a body of a stiff group is carried by
    /// the whole group (the springs answer within the substep), while the
    /// sweeps' contact row answers with the mass of its two bodies alone and
    /// the spring rows, one at a time, pass the push on at a rate set by the
    /// group's stiffness and size. Capped at 8 sweeps, a group at ω·h = 30
    /// left spring rows unsolved by most of the push, stored as spring energy
    /// `½·(ω·h)²·r²/W`: a 20-link chain folding onto itself gained 2.6 J of
    /// its 1.25 J in one step (the direct solve had left 3e-8 J).
    ///
    /// How: a contact's impulse moves its ends' position velocities by
    /// `P_c = w·n` per unit, as in the sweeps (`spring_support.rs`), i.e.
    /// shifts the direct system's start velocity `v₀` by `P_c`, so the
    /// group answers with `A⁻¹·T⁻¹·P_c` (`T⁻¹·P_c = n/θ_b` on a direct body;
    /// a body outside the direct groups moves by `P_c` itself). With the
    /// responses, the contacts' Delassus matrix `C_cd = n_c·(δp_d(b_c) −
    /// δp_d(a_c))` (`J·A⁻¹·Θ⁻¹·Jᵀ` on the direct bodies: symmetric positive
    /// semi-definite where the contacted bodies share θ_b = 1, as touching
    /// ones do; its diagonal is positive) gives the linear complementarity
    /// problem `n_c·(p_b − p_a) + Σ_d C_cd·μ_d ≥ target_c ⊥ μ_c ≥ 0`, with
    /// each friction impulse in `|τ_c| ≤ f_c·μ_c` against its sliding rate,
    /// solved by projected Gauss–Seidel on the small dense matrix (64
    /// sweeps at most). The nonlinearity of the radial rows is taken up by
    /// the Newton passes with `v₀ + P(μ)` as the start and a few rounds of
    /// contact increments, each on the matrix at the iterate ([`Self::solve`]),
    /// whose result goes through the energy check of [`Self::keep_energy`]
    /// with the contacts' impulses counted in the residual. The contact
    /// impulses found here are final (the contact solve leaves these rows,
    /// `world/step/constraints.rs`). A group reached by more than
    /// [`MAX_COUPLED_CONTACTS`] contact rows keeps the sweeps' view of its
    /// contacts.
    fn couple_contacts(
        &mut self,
        supports: &mut SupportScratch<S>,
        velocities: &[Vec2<S>],
        p: &mut [Vec2<S>],
        shifted: &mut Vec<Vec2<S>>,
    ) -> bool {
        if supports.rows.is_empty() || !self.kept_valid {
            return false;
        }
        let _n = 0;
        self.contacts.clear();
        for (index, row) in supports.rows.iter().enumerate() {
            if self.local[row.a as usize] != NONE || self.local[row.b as usize] != NONE {
                self.contacts.push(index as u32);
            }
        }
        let count = self.contacts.len();
        if count == 0 || count > MAX_COUPLED_CONTACTS {
            return false;
        }
        self.contact_responses(supports);
        let unknowns = 2 * count;
        self.impulses.clear();
        self.impulses.resize(unknowns, S::ZERO);
        shifted.clear();
        shifted.extend_from_slice(velocities);
        self.solve_contacts(supports, p, shifted) > S::ZERO
    }

    /// The responses `δp_j` of the group to a unit of each contact
    /// unknown on the kept factor, and their Delassus matrix (see
    /// [`Self::couple_contacts`]).
    fn contact_responses(&mut self, supports: &SupportScratch<S>) {
        let n = self.order.len();
        let count = self.contacts.len();
        // Unknown `2·k` is contact k's normal impulse, `2·k + 1` its
        // friction impulse (along perp(n), as the contact solve applies
        // it); a unit of either moves the ends by `w·dir`.
        let unknowns = 2 * count;
        let direction = |row: &SupportRow<S>, j: usize| {
            if j.is_multiple_of(2) {
                (row.normal, row.push)
            } else {
                (row.normal.perp(), (row.push.0.perp(), row.push.1.perp()))
            }
        };
        // The responses δp_j on the direct unknowns.
        let mut rhs = core::mem::take(&mut self.residual);
        self.responses.clear();
        for j in 0..unknowns {
            let row = supports.rows[self.contacts[j / 2] as usize];
            let (_, push) = direction(&row, j);
            rhs.clear();
            rhs.resize(n, Vec2::ZERO);
            for (slot, push, on_a) in [(row.a, push.0, true), (row.b, push.1, false)] {
                let local = self.local[slot as usize];
                if local != NONE {
                    let force = push.scale(self.mass[local as usize]);
                    rhs[local as usize] = if on_a {
                        rhs[local as usize] - force
                    } else {
                        rhs[local as usize] + force
                    };
                }
            }
            self.solve_unknowns(&mut rhs);
            self.responses.extend_from_slice(&rhs);
        }
        self.residual = rhs;
        // δp_j at a slot: the group's response, or the push itself on a
        // body outside the direct groups.
        let response = |this: &Self, j: usize, slot: u32| -> Vec2<S> {
            let local = this.local[slot as usize];
            if local != NONE {
                return this.responses[j * n + local as usize];
            }
            let row = &supports.rows[this.contacts[j / 2] as usize];
            let (_, push) = direction(row, j);
            let mut v = Vec2::ZERO;
            if slot == row.a {
                v -= push.0;
            }
            if slot == row.b {
                v += push.1;
            }
            v
        };
        self.delassus.clear();
        for i in 0..unknowns {
            let row = &supports.rows[self.contacts[i / 2] as usize];
            let (dir, _) = direction(row, i);
            for j in 0..unknowns {
                let moved = response(self, j, row.b) - response(self, j, row.a);
                self.delassus.push(moved.dot(dir));
            }
        }
    }

    /// Projected block Gauss–Seidel on the contacts' Delassus matrix from
    /// the current impulses and `p` (per contact its normal and friction
    /// impulses together, in the friction cone: [`contact_block`]), and
    /// the changes applied: the pushes (as the sweeps make them), the
    /// shifted start, and the group's linear response. Returns the largest
    /// change of an impulse.
    fn solve_contacts(
        &mut self,
        supports: &mut SupportScratch<S>,
        p: &mut [Vec2<S>],
        shifted: &mut [Vec2<S>],
    ) -> S {
        let n = self.order.len();
        let unknowns = self.impulses.len();
        self.changes.clear();
        self.changes.resize(unknowns, S::ZERO);
        for _ in 0..CONTACT_SWEEPS {
            let mut largest = S::ZERO;
            let mut total = S::ZERO;
            for k in 0..unknowns / 2 {
                let row = &supports.rows[self.contacts[k] as usize];
                let (jn, jt) = (2 * k, 2 * k + 1);
                let entry = |i: usize, j: usize| self.delassus[i * unknowns + j];
                let relative = p[row.b as usize] - p[row.a as usize];
                let mut rate_n = S::Wide::from_narrow(relative.dot(row.normal));
                let mut rate_t = S::Wide::from_narrow(relative.dot(row.normal.perp()));
                for (m, &change) in self.changes.iter().enumerate() {
                    rate_n = rate_n.add(entry(jn, m).wide_mul(change));
                    rate_t = rate_t.add(entry(jt, m).wide_mul(change));
                }
                let old = (
                    self.impulses[jn].add(self.changes[jn]),
                    self.impulses[jt].add(self.changes[jt]),
                );
                let new = contact_block(
                    (entry(jn, jn), entry(jn, jt), entry(jt, jn), entry(jt, jt)),
                    (row.target.sub(rate_n.narrow()), rate_t.narrow().neg()),
                    old,
                    row.friction,
                );
                self.changes[jn] = new.0.sub(self.impulses[jn]);
                self.changes[jt] = new.1.sub(self.impulses[jt]);
                largest = largest
                    .max(new.0.sub(old.0).abs())
                    .max(new.1.sub(old.1).abs());
                total = total.max(new.0.abs()).max(new.1.abs());
            }
            if largest <= total.mul(S::from_ratio(1, CONTACT_TOLERANCE)) {
                break;
            }
        }
        let mut largest = S::ZERO;
        for (k, &index) in self.contacts.iter().enumerate() {
            let (dn, dt) = (self.changes[2 * k], self.changes[2 * k + 1]);
            largest = largest.max(dn.abs()).max(dt.abs());
            self.impulses[2 * k] = self.impulses[2 * k].add(dn);
            self.impulses[2 * k + 1] = self.impulses[2 * k + 1].add(dt);
            let row = &mut supports.rows[index as usize];
            row.impulse = self.impulses[2 * k];
            row.tangent = self.impulses[2 * k + 1];
            row.held = true;
            if dn == S::ZERO && dt == S::ZERO {
                continue;
            }
            let along = |push: Vec2<S>| {
                Vec2::new(
                    S::mul_sub_mul(push.x, dn, push.y, dt),
                    S::mul_add_mul(push.y, dn, push.x, dt),
                )
            };
            let (push_a, push_b) = (along(row.push.0), along(row.push.1));
            let (a, b) = (row.a as usize, row.b as usize);
            supports.pushed[a] -= push_a;
            supports.pushed[b] += push_b;
            supports.kept[a] -= push_a;
            supports.kept[b] += push_b;
            shifted[a] -= push_a;
            shifted[b] += push_b;
            if self.local[a] == NONE {
                p[a] -= push_a;
            }
            if self.local[b] == NONE {
                p[b] += push_b;
            }
        }
        if largest == S::ZERO {
            return largest;
        }
        for (body, &slot) in self.order.iter().enumerate() {
            let mut sum_x = S::Wide::ZERO;
            let mut sum_y = S::Wide::ZERO;
            for (j, &x) in self.changes.iter().enumerate() {
                let r = self.responses[j * n + body];
                sum_x = sum_x.add(r.x.wide_mul(x));
                sum_y = sum_y.add(r.y.wide_mul(x));
            }
            p[slot as usize] += Vec2::new(sum_x.narrow(), sum_y.narrow());
        }
        largest
    }

    /// Solves `A·x = b` on the kept factor, in place, per body unknown.
    fn solve_unknowns(&mut self, b: &mut [Vec2<S>]) {
        if self.coupled {
            self.right.clear();
            for r in b.iter() {
                self.right.push(r.x);
                self.right.push(r.y);
            }
            solve_factored(
                &self.kept,
                &self.kept_factor,
                &mut self.right,
                &mut self.wide,
            );
            for (body, v) in b.iter_mut().enumerate() {
                *v = Vec2::new(self.right[2 * body], self.right[2 * body + 1]);
            }
        } else {
            for lane in 0..2 {
                self.right.clear();
                self.right
                    .extend(b.iter().map(|r| if lane == 0 { r.x } else { r.y }));
                solve_factored(
                    &self.kept,
                    &self.kept_factor,
                    &mut self.right,
                    &mut self.wide,
                );
                for (v, &x) in b.iter_mut().zip(&self.right) {
                    if lane == 0 {
                        v.x = x;
                    } else {
                        v.y = x;
                    }
                }
            }
        }
    }

    /// Keeps the current iterate (the order's position velocities and the
    /// radial rows' tension estimates) to undo a pass.
    fn save_iterate(&mut self, p: &[Vec2<S>]) {
        self.newton.clear();
        self.newton
            .extend(self.order.iter().map(|&slot| p[slot as usize]));
        self.saved_tension.clear();
        self.saved_tension.extend_from_slice(&self.tension);
    }

    /// Puts back what [`Self::save_iterate`] kept.
    fn restore_iterate(&mut self, p: &mut [Vec2<S>]) {
        for (&slot, &saved) in self.order.iter().zip(&self.newton) {
            p[slot as usize] = saved;
        }
        core::mem::swap(&mut self.tension, &mut self.saved_tension);
    }

    /// Whether solving every group of two or more rows (and every lone
    /// radial row, see [`Self::find_stiff_groups`]) exactly would take
    /// more rows than [`Self::direct`] marks now (the marks are then those
    /// of every group).
    pub(crate) fn would_take_more(
        &mut self,
        rows: &[SpringRow<S>],
        supports: &[SupportRow<S>],
        slots: usize,
    ) -> bool {
        let before = self.direct.iter().filter(|d| **d).count();
        self.direct.clear();
        self.direct.resize(rows.len(), false);
        self.find_stiff_groups(rows, supports, slots, true)
            && self.direct.iter().filter(|d| **d).count() > before
    }

    /// Union–find over the rows' moving ends; marks the rows of groups
    /// with a stiff row and at least two rows (`every`: of every group of
    /// two or more rows, and every lone radial row that no contact joins
    /// to a third body). Returns whether any.
    ///
    /// A lone bendy row is exact in the first sweep; a lone radial row is
    /// not when its pole turns far within the substep: the sweeps then
    /// re-linearise along the discrete gradient `d = (r + r')/(l + l')`,
    /// whose length falls with the turn (`cos(φ/2)` at constant length),
    /// and 8 of them stop far from the row's equation. A pusher on a
    /// radial spring at ω·h = 100 thrown past the body it holds (0.5 rad
    /// off the pole at 50 units/s, a turn of 1.3 rad in the substep) kept
    /// λ = −3.3 where its equation asked about −2.4·10³: the pusher flew
    /// on, the spring ended 0.08 long, and stored 6.1·10³ J of the pair's
    /// 125 J. So the restart of unsettled sweeps solves it exactly too
    /// (Newton, with the energy safeguard of [`Self::keep_energy`]).
    /// Only where every contact that reaches it is solved with it
    /// ([`Self::contacts_only_between`]): no wall on its ends, and a third
    /// body they touch has no contact beyond the row's two ends. The
    /// contacts solved with a stiff group are final and the sweeps leave
    /// them, so a further contact of the third body, solved after them,
    /// pushes it back into the group unopposed (a middle body pushed into
    /// the struck one as that bounced off a wall: +18 J of 5), and a wall
    /// on an end meets bodies the exact spring flings at it (open, issue
    /// 13); such a row keeps the sweeps' view of its contacts.
    fn find_stiff_groups(
        &mut self,
        rows: &[SpringRow<S>],
        supports: &[SupportRow<S>],
        slots: usize,
        every: bool,
    ) -> bool {
        let stiff_limit = S::from_ratio(STIFF_INVERSE_DIAGONAL.0, STIFF_INVERSE_DIAGONAL.1);
        let is_stiff = |row: &SpringRow<S>| {
            every || row.inverse_diagonal.x.min(row.inverse_diagonal.y) <= stiff_limit
        };
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
        // A launched bounce's end counts as a row: against one stiff
        // spring the sweeps would play the bounce and the spring off each
        // other along nearly the same line (a pusher on a stiff radial
        // spring thrown into a wall: rows 0.1 rad apart), and 8 sweeps
        // leave the spring stretched far beyond its equation.
        for (slot, _) in self
            .launched_ends
            .iter()
            .enumerate()
            .take(slots)
            .filter(|(_, launched)| **launched)
        {
            let root = find(&mut self.parent, slot as u32) as usize;
            self.rows_in[root] += 1;
        }
        if every {
            self.find_contact_partners(supports, slots);
        }
        let mut any = false;
        for (i, row) in rows.iter().enumerate() {
            let root = find(&mut self.parent, moving_end(row)) as usize;
            let lone_radial = every && row.radial && self.contacts_only_between(row);
            if self.stiff[root] && (self.rows_in[root] >= 2 || lone_radial) {
                self.direct[i] = true;
                any = true;
            }
        }
        any
    }

    /// Each slot's [`Self::contact_partner`] over the support rows.
    fn find_contact_partners(&mut self, supports: &[SupportRow<S>], slots: usize) {
        let partner = &mut self.contact_partner;
        partner.clear();
        partner.resize(slots, [NONE; 2]);
        let immovable = &mut self.immovable;
        immovable.clear();
        immovable.resize(slots, false);
        let mut meet = |slot: u32, other: u32| {
            let Some(p) = partner.get_mut(slot as usize) else {
                return;
            };
            if p[0] == NONE || p[0] == other {
                p[0] = other;
            } else if p[1] == NONE || p[1] == other {
                p[1] = other;
            } else {
                *p = [MANY; 2];
            }
        };
        for row in supports {
            meet(row.a, row.b);
            meet(row.b, row.a);
            for (slot, push) in [(row.a, row.push.0), (row.b, row.push.1)] {
                if push == Vec2::ZERO
                    && let Some(fixed) = immovable.get_mut(slot as usize)
                {
                    *fixed = true;
                }
            }
        }
    }

    /// Whether the contacts that reach a lone radial `row` are all solved
    /// with it ([`Self::contact_partner`] is set): besides each other, its
    /// ends touch only movable third bodies whose own contacts are all with
    /// the row's two ends.
    fn contacts_only_between(&self, row: &SpringRow<S>) -> bool {
        let partners = |slot: u32| {
            self.contact_partner
                .get(slot as usize)
                .copied()
                .unwrap_or([NONE; 2])
        };
        let ends = [row.a, row.b];
        let only_ends = |q: u32| q == NONE || ends.contains(&q);
        ends.iter().all(|&end| {
            partners(end).iter().all(|&q| {
                if only_ends(q) {
                    return true;
                }
                if q == MANY || self.immovable.get(q as usize).is_none_or(|&fixed| fixed) {
                    return false;
                }
                let outer = partners(q);
                outer[0] != MANY && outer.iter().all(|&r| only_ends(r))
            })
        })
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
        self.inverse_mass.clear();
        self.inverse_mass.resize(n, S::ZERO);
        for (row, _) in rows.iter().zip(&self.direct).filter(|(_, d)| **d) {
            for (slot, push, w) in [
                (row.a, row.position_push.0, row.inverse_masses.0),
                (row.b, row.position_push.1, row.inverse_masses.1),
            ] {
                let local = self.local[slot as usize];
                if local != NONE {
                    self.position_push[local as usize] = push;
                    self.inverse_mass[local as usize] = w;
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

    /// The kept factor rebuilt at the iterate `p`: the matrix there
    /// ([`Self::build_matrix`]) becomes the kept one, factored. `false` when
    /// it cannot be built or factored (the callers then stop their passes;
    /// `kept_valid` says whether the kept factor may still be used).
    fn refactor_at(
        &mut self,
        rows: &[SpringRow<S>],
        radial: &[RadialRow<S>],
        lanes: usize,
        (p, h): (&[Vec2<S>], S),
    ) -> bool {
        if !self.build_matrix(rows, radial, lanes, (p, h)) {
            return false;
        }
        core::mem::swap(&mut self.building, &mut self.kept);
        self.kept_valid = factor(&self.kept, &mut self.kept_factor);
        self.kept_valid
    }

    /// Builds `T⁻¹ + Gᵀ·D_g·G` in the envelope (one unknown per body, or
    /// two, interleaved x/y, when `lanes` is 2).
    fn build_matrix(
        &mut self,
        rows: &[SpringRow<S>],
        radial: &[RadialRow<S>],
        lanes: usize,
        (p, h): (&[Vec2<S>], S),
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
        let mut radial_rows = radial.iter().zip(&self.tension);
        for (row, &direct) in rows.iter().zip(&self.direct) {
            let geometry = if row.radial { radial_rows.next() } else { None };
            if !direct {
                continue;
            }
            let ends = [self.local[row.a as usize], self.local[row.b as usize]];
            // The row's lane coupling: diag(g_x, g_y) for a bendy row,
            // g·d̂·d̂ᵀ for a radial one (d̂ the unit pole at the start).
            let block = match geometry {
                Some((geometry, &tension)) => {
                    let (g, d, across) = radial_stiffness(row, geometry, tension, p, h);
                    // g·n·nᵀ + γ·(I − n·nᵀ) = (g − γ)·n·nᵀ + γ·I.
                    let gd = d.scale(g.sub(across));
                    [
                        [gd.x.mul(d.x).add(across), gd.x.mul(d.y)],
                        [gd.x.mul(d.y), gd.y.mul(d.y).add(across)],
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

    /// `R(p) = Gᵀ·λ(p) − T⁻¹·(p − v₀)` per body unknown into `residual`
    /// (and each direct radial row's linearisation at `p`).
    fn compute_residual(
        &mut self,
        rows: &[SpringRow<S>],
        radial: &[RadialRow<S>],
        velocities: &[Vec2<S>],
        p: &[Vec2<S>],
        h: S,
    ) {
        let n = self.order.len();
        self.residual.clear();
        self.residual.resize(n, Vec2::ZERO);
        let mut radial_rows = radial.iter().zip(self.linearisation.iter_mut());
        for (row, &direct) in rows.iter().zip(&self.direct) {
            let geometry = if row.radial { radial_rows.next() } else { None };
            if !direct {
                continue;
            }
            let (impulse, lambda) = Self::row_impulse(row, geometry.as_ref().map(|g| g.0), p, h);
            if let Some((geometry, linearisation)) = geometry {
                let end = geometry.offset + (p[row.b as usize] - p[row.a as usize]).scale(h);
                *linearisation = (lambda, end.try_normalize().unwrap_or(Vec2::ZERO));
            }
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
        self.compute_residual(rows, radial, velocities, p, h);
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
        self.linearised_tension(rows, radial, h);
        largest
    }

    /// The tension each direct radial row's linearisation predicts at the
    /// new iterate, `λ(p) − (g/h)·h·r̂'·(δp_b − δp_a)` (the pass's steps
    /// `δp` are in `right`, per unknown): the impulse of the Newton step's
    /// own linear model, which the next matrix's sideways stiffness is
    /// built from. Evaluating the tension at the new iterate instead
    /// (`λ(p + δp)`) takes in `(g/h)` times the length's curvature over
    /// the step, `|h·δp⊥|²/(2·l)`: at ω·h = 3000 an impulse 10⁴ times the
    /// true one after the first pass on a kicked 200-body chain, whose
    /// sideways stiffness then froze or released the chain's turn and the
    /// passes diverged (10⁹ × the energy in one tick). This is the
    /// mixed (impulse and velocity) form of Newton's method, whose
    /// convergence does not degrade with the stiffness.
    fn linearised_tension(&mut self, rows: &[SpringRow<S>], radial: &[RadialRow<S>], h: S) {
        let lanes = if self.coupled { 2 } else { 1 };
        let step = |local: u32| -> Vec2<S> {
            if local == NONE || lanes != 2 {
                return Vec2::ZERO;
            }
            let i = 2 * local as usize;
            Vec2::new(self.right[i], self.right[i + 1])
        };
        let mut radial_rows = radial.iter().zip(&self.linearisation);
        let mut updates = core::mem::take(&mut self.tension);
        let mut index = 0usize;
        for (row, &direct) in rows.iter().zip(&self.direct) {
            if !row.radial {
                continue;
            }
            let Some((geometry, &(lambda, unit))) = radial_rows.next() else {
                break;
            };
            if direct {
                let moved = step(self.local[row.b as usize]) - step(self.local[row.a as usize]);
                updates[index] =
                    Some(lambda.sub(geometry.gain_per_length.mul(h.mul(unit.dot(moved)))));
            }
            index += 1;
        }
        self.tension = updates;
    }

    /// The energy safeguard of the radial Newton solve, which may stop short
    /// of convergence (a whip or a fast turn of a very stiff group within
    /// [`RADIAL_PASSES`], or the factor's rounding): the step is kept where
    /// it cannot gain energy, and is otherwise pulled back towards a point
    /// that provably does not. Run after every radial solve (one residual
    /// evaluation; a converged solve passes at once).
    ///
    /// Every row's equation holds exactly at any `p` ([`Self::apply`] sets
    /// `λ = λ(p)`); what an unconverged `p` leaves is the body residual
    /// `ρ_b = (m_b/θ_b)·(p_b − v₀_b) − (Gᵀ·λ(p))_b`, an impulse no row
    /// accounts for. Repeating the balance of [`crate::constraints`]
    /// ("Energy: never gained"; `M·Δv = Gᵀ·λ + ρ`, `v₀ + ½·Δv + (θ_b −
    /// ½)·Δv = p`) gives
    ///
    /// ```text
    /// ΔE = −Σ_b (θ_b − ½)·m_b·|Δv_b|² − Σ_s ((θ_s − ½)·k_s + c_s/h)·Δx_s² + Σ_b ρ_b·p_b
    /// ```
    ///
    /// so the step gains nothing while the residual's work
    /// `W = Σ_b ρ_b·p_b` is at most the body dissipation
    /// `D = Σ_b (θ_b − ½)·m_b·|Δv_b|²`. Under gravity (a kick `h·g⃗_b`
    /// inside `v₀`) the invariant is `E_θ = E + Σ_b (1 − θ_b)·h·m_b·g⃗_b·v_b`
    /// (`crate::constraints`, "Radial springs") and the body term becomes
    /// `(θ_b − ½)·m_b·|Δv_b + h·g⃗_b|²` (the balance with the kick's terms
    /// collected, `ρ` entering as above), so `D` is taken as that:
    /// `(m_b/θ_b)·(1 − 1/(2·θ_b))·|p_b − v₀_b + θ_b·h·g⃗_b|²`. A group that fails
    /// this is moved along `p(α) = p_s + α·(p_N − p_s)`, α = ½, ¼, … 2⁻¹⁰,
    /// then 0, to the first α that passes. The safe point `p_s` has no
    /// internal motion: every body at the group's mean `c` (weights
    /// `m_b/θ_b`, so `Σ_b (m_b/θ_b)·(c − v₀_b) = 0`) for a free group, at
    /// rest for one hung on immovable anchors. There `Σ_b ρ_b = 0` (internal
    /// impulses cancel in pairs) gives `W = c·Σ_b ρ_b = 0` for a free
    /// group, and `p = 0` gives `W = 0` for an anchored one: `ΔE ≤ 0` at
    /// α = 0 whatever the rows do. The price where it acts is damping: at
    /// α = 0 the group's internal motion of the substep is taken out.
    ///
    /// A free group whose contacts were solved with it (`held`: they are
    /// final, [`Self::couple_contacts`]) takes as its safe point the rigid
    /// translation `c` that its contacts allow ([`Self::rigid_safe_points`]:
    /// with immovable bodies, and with movable ones outside the groups,
    /// which then move too, [`Self::find_outside_bodies`]) instead of its
    /// mean: at the mean, a
    /// body striking the ground kept moving into it at the group's
    /// velocity past its final contact rows, and the position pass then
    /// pushed it out alone against the stiff group, which stored the push
    /// as spring energy (a thrown 3-link chain of 0.1 at ω·h = 100 gained
    /// 429 J in the tick it struck). There `Σ_b ρ_b = Σ_k μ_k·J_k` (the
    /// contacts' impulses, everything else internal), so `W = c·Σ_b ρ_b =
    /// Σ_k μ_k·(J_k·c)`, each contact's impulse times its rate: at most 0
    /// where the impulses are complementary to rates bounded below by
    /// `min(target, 0)` (a pushing impulse only where the rate is that
    /// bound; up to the contact sweeps' tolerance, and a kinematic partner
    /// pushing does its own work `μ_k·n_k·v_k`). A blend passes only where
    /// it also meets these contacts ([`Self::reopen_entering`]).
    fn keep_energy(
        &mut self,
        rows: &[SpringRow<S>],
        radial: &[RadialRow<S>],
        (mut held, settled): (Option<&mut SupportScratch<S>>, bool),
        velocities: &[Vec2<S>],
        p: &mut [Vec2<S>],
        h: S,
    ) {
        let groups = self.group_start.len().saturating_sub(1);
        // Which groups are anchored (as in `keep_momentum`).
        self.anchored.clear();
        self.anchored.resize(groups, false);
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
        // Each group's mean (rest if anchored) and summed mass `m_b/θ_b`.
        self.rigid.clear();
        for group in 0..groups {
            let range = self.group_start[group] as usize..self.group_start[group + 1] as usize;
            let (mut sum_x, mut sum_y, mut total) = (S::Wide::ZERO, S::Wide::ZERO, S::Wide::ZERO);
            for body in range {
                let v = velocities[self.order[body] as usize];
                sum_x = sum_x.add(self.mass[body].wide_mul(v.x));
                sum_y = sum_y.add(self.mass[body].wide_mul(v.y));
                total = total.add(S::Wide::from_narrow(self.mass[body]));
            }
            let total = total.narrow();
            let mean = if self.anchored[group] || !total.is_positive() {
                Vec2::ZERO
            } else {
                Vec2::new(sum_x.narrow().div(total), sum_y.narrow().div(total))
            };
            self.rigid.push((mean, mean, total));
        }
        self.outside.clear();
        if let Some(supports) = held.as_deref() {
            self.find_outside_bodies(supports, p);
        }
        if let Some(supports) = held.as_deref_mut() {
            self.rigid_safe_points(supports, p);
        }
        // The Newton iterate and each group's safe point.
        self.newton.clear();
        self.safe.clear();
        for group in 0..groups {
            let range = self.group_start[group] as usize..self.group_start[group + 1] as usize;
            for body in range {
                self.newton.push(p[self.order[body] as usize]);
                self.safe.push(self.rigid[group].1);
            }
        }
        // Per group: pending (nonzero) until a blend passes, and the blend
        // taken.
        self.blend.clear();
        self.blend.resize(groups, S::ONE);
        self.taken_blend.clear();
        self.taken_blend.resize(groups, S::ONE);
        let mut exponent = 0;
        loop {
            let mut failing = self.failing_groups(rows, radial, velocities, p, h);
            if (exponent > 0 || !settled)
                && let Some(supports) = held.as_deref()
            {
                failing += self.reopen_entering(supports, p);
            }
            if failing == 0 {
                break;
            }
            exponent += 1;
            // 2⁻¹⁰ and then the safe point itself.
            let alpha = if exponent > 10 {
                S::ZERO
            } else {
                S::from_ratio(1, 1 << exponent)
            };
            for group in 0..groups {
                if self.blend[group] == S::ZERO {
                    continue;
                }
                self.blend[group] = alpha;
                self.taken_blend[group] = alpha;
                let range = self.group_start[group] as usize..self.group_start[group + 1] as usize;
                for body in range {
                    let (newton, safe) = (self.newton[body], self.safe[body]);
                    p[self.order[body] as usize] = safe + (newton - safe).scale(alpha);
                }
                for &(slot, g, safe, newton) in &self.outside {
                    if g as usize == group {
                        p[slot as usize] = safe + (newton - safe).scale(alpha);
                    }
                }
            }
            if alpha == S::ZERO {
                break;
            }
        }
        if let Some(supports) = held {
            self.blend_held_impulses(supports);
        }
    }

    /// A blend between a group's Newton iterate and its rigid safe point
    /// passes only where it meets the group's contacts with immovable
    /// bodies as well as the safe point does: `n·(p_b − p_a) ≥ min(target,
    /// rate at the safe point)` for each (the rate is linear along the
    /// blend, so a small enough blend always does). Otherwise the struck
    /// body enters the ground, its final contact rows let it, and the
    /// position pass then pushes it out alone against the stiff group,
    /// which stores the push as spring energy (`½·k·depth²`: a thrown chain
    /// of 0.1 with a 100 end at ω·h = 100 gained 774 J where a blend of
    /// 1/16 passed the energy check with its light middle body still
    /// entering the ground at 1.6 units/s). Reopens every accepted group
    /// that does not; returns how many.
    fn reopen_entering(&mut self, supports: &SupportScratch<S>, p: &[Vec2<S>]) -> usize {
        let mut reopened = 0;
        for k in 0..self.contacts.len() {
            let row = &supports.rows[self.contacts[k] as usize];
            let Some((group, sign)) = self.rigid_contact(row) else {
                continue;
            };
            if self.blend[group] != S::ZERO {
                continue;
            }
            let (end, other) = if sign.is_positive() {
                (row.b, row.a)
            } else {
                (row.a, row.b)
            };
            let other = p[other as usize];
            let rate = row.normal.dot(p[end as usize] - other).mul(sign);
            let safe = row.normal.dot(self.rigid[group].1 - other).mul(sign);
            if rate < row.target.min(safe) {
                self.blend[group] = self.taken_blend[group];
                reopened += 1;
            }
        }
        reopened
    }

    /// Per free group, the rigid translation `c` (every body at the same
    /// position velocity) nearest its mean (in the metric `Σ_b m_b/θ_b`)
    /// that its held contacts with immovable bodies allow: `J_k·c ≥
    /// min(target_k, 0)` for each such contact `k` (`J_k` its normal as the
    /// group's end sees it), normal impulses only, by projected
    /// Gauss–Seidel on `c` itself (a unit impulse moves `c` by `n/M`); into
    /// `rigid[group].1`, the contacts' impulses into `safe_impulses`. A
    /// flat ground is met in one sweep. Anchored groups keep rest, which
    /// meets every such bound (`J_k·0 = 0`). A held contact with a movable
    /// body outside the groups ([`Self::outside`]) is solved between `c`
    /// and that body's own position velocity `u` (`J_k·(c − u) ≥
    /// min(target_k, 0)`, effective mass `1/(1/M + w_o)`, equal and
    /// opposite impulses: Σ m·v is kept at the safe point and, linear in
    /// the blend, at every blend). Without it a blend of a middle body
    /// held by a stiff radial spring passed the energy check while closing
    /// on the body it touched at 19 units/s against a bound of 1.2: the
    /// two passed through each other within the tick, punched motion cut
    /// them apart and the spring kept the solve's velocities (+7.2 J of
    /// 125). The pair's energy at the safe point changes by
    /// `μ·u_s − ½·μ²·(1/M + w_o)`, at most 0 where the impulse is
    /// complementary to the rate `u_s ≤ 0`.
    fn rigid_safe_points(&mut self, supports: &SupportScratch<S>, p: &[Vec2<S>]) {
        let count = self.contacts.len();
        self.safe_impulses.clear();
        self.safe_impulses.resize(count, S::ZERO);
        for _ in 0..CONTACT_SWEEPS {
            let (mut largest, mut total) = (S::ZERO, S::ZERO);
            for k in 0..count {
                let row = &supports.rows[self.contacts[k] as usize];
                // The contact's other end: a movable body outside the
                // groups (its velocity at the safe point so far, moved by
                // the impulse, and its push `w_o` along the normal) or an
                // immovable one (its velocity, which no impulse moves).
                let (group, sign, other, outside) = if !self.outside.is_empty()
                    && let Some((group, sign, o)) = self.outside_contact(row)
                    && let Some(e) = self.outside.iter().position(|e| e.0 == o)
                {
                    let w_o = if o == row.a { row.push.0 } else { row.push.1 }.dot(row.normal);
                    (group, sign, self.outside[e].2, Some((e, w_o)))
                } else if let Some((group, sign)) = self.rigid_contact(row) {
                    let other = if sign.is_positive() {
                        p[row.a as usize]
                    } else {
                        p[row.b as usize]
                    };
                    (group, sign, other, None)
                } else {
                    continue;
                };
                let (_, c, mass) = self.rigid[group];
                // n·(p_b − p_a) with the group's end at c.
                let rate = row.normal.dot(c - other).mul(sign);
                // The pair's effective mass: M against an immovable end,
                // 1/(1/M + w_o) against an outside body.
                let effective = match outside {
                    Some((_, w_o)) => S::ONE.div(S::ONE.div(mass).add(w_o)),
                    None => mass,
                };
                let old = self.safe_impulses[k];
                let new = old
                    .add(row.target.min(S::ZERO).sub(rate).mul(effective))
                    .max(S::ZERO);
                if new == old {
                    continue;
                }
                self.safe_impulses[k] = new;
                let d = new.sub(old).mul(sign);
                self.rigid[group].1 = c + row.normal.scale(d.div(mass));
                if let Some((e, w_o)) = outside {
                    self.outside[e].2 = other - row.normal.scale(d.mul(w_o));
                }
                largest = largest.max(new.sub(old).abs());
                total = total.max(new);
            }
            if largest <= total.mul(S::from_ratio(1, CONTACT_TOLERANCE)) {
                break;
            }
        }
    }

    /// Where [`Self::find_outside_bodies`] does not solve them at the safe
    /// point, moves each free group's mean (the safe point of
    /// [`Self::keep_energy`]) by the impulses of its held contacts with
    /// movable bodies outside the direct groups: those bodies keep the
    /// contacts' final pushes whatever blend the group takes, so the group
    /// must keep them too, or Σ m·v changes by the pushes the blend drops
    /// (a pusher on a stiff radial spring, ω·h = 100, thrown at 300
    /// units/s at a middle body touching a third: the third body left at
    /// −199 units/s with its push, the group fell back to its mean
    /// before the push, and Σ m·v went from −30 to −49.8). Along the blend
    /// Σ m·v is then linear between two points that both keep it. At the
    /// safe point a pair's energy changes by `μ·u_s − ½·μ²/m_o` (`u_s` the
    /// row's opening rate there, `m_o` the outside body's mass) where the
    /// outside body gained `½·μ²/m_o` from nothing before.
    fn carry_outside_pushes(&mut self, supports: &SupportScratch<S>) {
        for &index in &self.contacts {
            let row = &supports.rows[index as usize];
            let (a, b) = (self.local[row.a as usize], self.local[row.b as usize]);
            let (local, sign, other_push) = match (a == NONE, b == NONE) {
                (true, false) => (b, S::ONE, row.push.0),
                (false, true) => (a, S::ONE.neg(), row.push.1),
                _ => continue,
            };
            if other_push == Vec2::ZERO {
                continue;
            }
            let group = self.group_start.partition_point(|&start| start <= local) - 1;
            let (mean, _, total) = self.rigid[group];
            if self.anchored[group] || !total.is_positive() {
                continue;
            }
            let n = row.normal;
            let impulse = Vec2::new(
                S::mul_sub_mul(n.x, row.impulse, n.y, row.tangent),
                S::mul_add_mul(n.y, row.impulse, n.x, row.tangent),
            );
            let shift = Vec2::new(impulse.x.div(total), impulse.y.div(total)).scale(sign);
            self.rigid[group] = (mean + shift, mean + shift, total);
        }
    }

    /// The movable bodies outside the direct groups that held contacts
    /// join to a free group ([`Self::outside`]), for the safe point of
    /// [`Self::keep_energy`]: each keeps its position velocity at the
    /// Newton iterate (with the contacts' final pushes) and starts the safe
    /// point's contact solve from it without them ([`Self::rigid_safe_points`]
    /// then treats it as a free body of its own mass). Where a body is
    /// joined to two groups, or a held contact is a launched bounce, the
    /// safe points instead carry the Newton pushes
    /// ([`Self::carry_outside_pushes`]): a bounce's end velocity is not a
    /// bound a rigid translation meets, and such a safe point left a
    /// pusher and the body it strikes at a wall moving on into it, which
    /// the bounce pass then threw back at 300 units/s (+5.8·10³ J of
    /// 4.5·10³ at ω·h = 10).
    fn find_outside_bodies(&mut self, supports: &SupportScratch<S>, p: &[Vec2<S>]) {
        for &index in &self.contacts {
            let row = &supports.rows[index as usize];
            let Some((group, _, o)) = self.outside_contact(row) else {
                continue;
            };
            let along = |push: Vec2<S>| {
                Vec2::new(
                    S::mul_sub_mul(push.x, row.impulse, push.y, row.tangent),
                    S::mul_add_mul(push.y, row.impulse, push.x, row.tangent),
                )
            };
            let pushed = if o == row.a {
                Vec2::ZERO - along(row.push.0)
            } else {
                along(row.push.1)
            };
            match self.outside.iter_mut().find(|e| e.0 == o) {
                Some(e) => {
                    if e.1 != group as u32 {
                        e.1 = NONE;
                    }
                    e.2 -= pushed;
                }
                None => self
                    .outside
                    .push((o, group as u32, p[o as usize] - pushed, p[o as usize])),
            }
        }
        let launched = self
            .contacts
            .iter()
            .any(|&index| supports.rows[index as usize].launched);
        if launched || self.outside.iter().any(|e| e.1 == NONE) {
            self.outside.clear();
            self.carry_outside_pushes(supports);
        }
    }

    /// The free group, side (`+1`: the group's end is `b`) and outside
    /// slot of a held contact between a direct body and a movable body
    /// outside the direct groups.
    fn outside_contact(&self, row: &SupportRow<S>) -> Option<(usize, S, u32)> {
        let (a, b) = (self.local[row.a as usize], self.local[row.b as usize]);
        let (local, sign, other_push, o) = match (a == NONE, b == NONE) {
            (true, false) => (b, S::ONE, row.push.0, row.a),
            (false, true) => (a, S::ONE.neg(), row.push.1, row.b),
            _ => return None,
        };
        if other_push == Vec2::ZERO {
            return None;
        }
        let group = self.group_start.partition_point(|&start| start <= local) - 1;
        (!self.anchored[group] && self.rigid[group].2.is_positive()).then_some((group, sign, o))
    }

    /// The free group and side (`+1`: the group's end is `b`) of a held
    /// contact with one end on a direct body and the other on an immovable
    /// one (no push): the contacts of [`Self::rigid_safe_points`].
    fn rigid_contact(&self, row: &SupportRow<S>) -> Option<(usize, S)> {
        let (a, b) = (self.local[row.a as usize], self.local[row.b as usize]);
        let (local, sign, other_push) = match (a == NONE, b == NONE) {
            (true, false) => (b, S::ONE, row.push.0),
            (false, true) => (a, S::ONE.neg(), row.push.1),
            _ => return None,
        };
        if other_push != Vec2::ZERO {
            return None;
        }
        let group = self.group_start.partition_point(|&start| start <= local) - 1;
        (!self.anchored[group] && self.rigid[group].2.is_positive()).then_some((group, sign))
    }

    /// The held contacts of [`Self::rigid_safe_points`] report the impulses
    /// of the blend their group took, `μ_s + α·(μ_N − μ_s)` (friction
    /// `α·τ_N`), for the contact cache, the bounces and the events.
    fn blend_held_impulses(&mut self, supports: &mut SupportScratch<S>) {
        for k in 0..self.contacts.len() {
            let index = self.contacts[k] as usize;
            let group = if let Some((group, _)) = self.rigid_contact(&supports.rows[index]) {
                group
            } else if !self.outside.is_empty()
                && let Some((group, _, _)) = self.outside_contact(&supports.rows[index])
            {
                group
            } else {
                continue;
            };
            let alpha = self.taken_blend[group];
            if alpha == S::ONE {
                continue;
            }
            let safe = self.safe_impulses[k];
            let row = &mut supports.rows[index];
            row.impulse = safe.add(row.impulse.sub(safe).mul(alpha));
            row.tangent = row.tangent.mul(alpha);
        }
    }

    /// Marks (with a zero blend) every group whose residual's work is at
    /// most its body dissipation at the current `p` (see
    /// [`Self::keep_energy`]); returns how many groups still fail.
    fn failing_groups(
        &mut self,
        rows: &[SpringRow<S>],
        radial: &[RadialRow<S>],
        velocities: &[Vec2<S>],
        p: &[Vec2<S>],
        h: S,
    ) -> usize {
        self.compute_residual(rows, radial, velocities, p, h);
        let groups = self.group_start.len().saturating_sub(1);
        let mut failing = 0;
        for group in 0..groups {
            if self.blend[group] == S::ZERO {
                continue;
            }
            let range = self.group_start[group] as usize..self.group_start[group + 1] as usize;
            // W = Σ ρ·p with ρ = −R; D as in `keep_energy`.
            let (mut work, mut dissipation) = (S::Wide::ZERO, S::Wide::ZERO);
            for body in range {
                let slot = self.order[body] as usize;
                let (pb, r) = (p[slot], self.residual[body]);
                work = work.sub(r.x.wide_mul(pb.x)).sub(r.y.wide_mul(pb.y));
                // θ_b·(Δv_b + h·g⃗_b) = p_b − v₀_b + θ_b·h·g⃗_b.
                let theta = self.position_push[body].div(self.inverse_mass[body]);
                let kick = self.kicks.get(slot).copied().unwrap_or(Vec2::ZERO);
                let moved = pb - velocities[slot] + kick.scale(theta);
                // (θ_b − ½)·m_b/θ_b² = (m_b/θ_b)·(1 − w_b·(m_b/θ_b)/2) ≥ 0
                // (w_b·m_b/θ_b = 1/θ_b ≤ 2).
                let weight = self.mass[body]
                    .mul(S::ONE.sub(self.inverse_mass[body].mul(self.mass[body]).half()));
                // (saturating: a saturated product only makes D smaller,
                // the check stricter)
                dissipation = dissipation
                    .add(weight.mul(moved.x).wide_mul(moved.x))
                    .add(weight.mul(moved.y).wide_mul(moved.y));
            }
            if work <= dissipation {
                self.blend[group] = S::ZERO;
            } else {
                failing += 1;
            }
        }
        failing
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

/// One contact's normal and friction impulses `(μ, τ)` from `old`, with
/// the other contacts held: the 2 × 2 block `C` of its Delassus matrix
/// (`(C_nn, C_nt, C_tn, C_tt)`) and the rates still wanted, `want =
/// (target − v_n, −v_t)` at `old`. Sticking if the block's solution lies
/// in the cone `|τ| ≤ f·μ`; else sliding with `τ = s·f·μ` (`s` the sign the
/// sticking impulse asked for) and `μ` from the normal equation; `μ ≥ 0`.
///
/// Why a block: a body held by a stiff group moves along nearly one line
/// (a pendulum's rod: normal and friction impulses both move it along the
/// tangent of its circle), so its 2 × 2 block is nearly singular and a
/// scalar projected Gauss–Seidel, friction then normal, crawled: after
/// its sweeps a heavy link on the ground at ω·h = 3 kept a friction
/// impulse 3.8× its cone (13.1 against 1.5 × 2.3), the springs were solved
/// for that hold, the contact solve (which keeps the cone) gave less, and
/// the chain gained 6.3 J in a step.
fn contact_block<S: Scalar>(
    (c_nn, c_nt, c_tn, c_tt): (S, S, S, S),
    (want_n, want_t): (S, S),
    (mu, tau): (S, S),
    friction: S,
) -> (S, S) {
    if !c_nn.is_positive() {
        return (mu, tau);
    }
    // Sticking: C·(dμ, dτ) = want.
    let det = S::mul_sub_mul(c_nn, c_tt, c_nt, c_tn);
    if det.is_positive() && c_tt.is_positive() {
        let d_mu = S::mul_sub_mul(want_n, c_tt, c_nt, want_t).div(det);
        let d_tau = S::mul_sub_mul(c_nn, want_t, c_tn, want_n).div(det);
        let (new_mu, new_tau) = (mu.add(d_mu), tau.add(d_tau));
        if !new_mu.is_negative() && new_tau.abs() <= friction.mul(new_mu) {
            return (new_mu, new_tau);
        }
        if new_mu.is_positive() && !friction.is_positive() {
            // Frictionless: the normal row alone (below).
        } else if new_mu.is_positive() || new_tau != S::ZERO {
            // Sliding, τ = s·f·μ: C_nn·(μ − μ₀) + C_nt·(s·f·μ − τ₀) = want_n.
            let s = if new_tau.is_negative() {
                S::ONE.neg()
            } else {
                S::ONE
            };
            let slope = c_nn.add(c_nt.mul(friction).mul(s));
            if slope.is_positive() {
                let right = want_n.add(c_nn.mul(mu)).add(c_nt.mul(tau));
                let new_mu = right.div(slope).max(S::ZERO);
                return (new_mu, friction.mul(new_mu).mul(s));
            }
        }
    }
    // The normal row alone, friction in the cone of the new normal.
    let new_mu = mu.add(want_n.div(c_nn)).max(S::ZERO);
    let limit = friction.mul(new_mu);
    let new_tau = if c_tt.is_positive() {
        tau.add(want_t.div(c_tt))
    } else {
        tau
    };
    (new_mu, new_tau.clamp(limit.neg(), limit))
}

/// A radial row's linearisation at the position velocities `p`: its gain
/// `g` along the unit pole `n` (the direction of `d`), and the transverse
/// stiffness of its tension, `γ = max(0, −λ)·h/(l + l')`.
///
/// The row's impulse is `J = λ·d` with `d = (r + r')/(l + l')`, so
/// `∂J/∂p_b = −g·d·r̂'ᵀ + λ·h·(I − d·r̂'ᵀ)/(l + l')`: the first term is the
/// spring's own stiffness along the pole, the second the turn of `d` with
/// the end (a taut string's sideways stiffness, `T/l` per unit length).
/// The Newton matrix takes the symmetric part `g·n·nᵀ + γ·(I − n·nᵀ)`
/// (`d ≈ r̂' ≈ n` to the pole's turn in the substep); under compression
/// `γ` would be negative and is left out, so the matrix stays positive
/// definite. Without `γ` the sideways motion of a light body between two
/// taut springs is solved by a fixed-point iteration whose rate is about
/// `θ·w·γ` relative to the mass term: at `(ω·h)² ·strain ≳ 1` that
/// diverges (two springs from a fixed point with a 100× end at ω·h = 3
/// reached the world's bound in 28 ticks).
fn radial_stiffness<S: Scalar>(
    row: &SpringRow<S>,
    geometry: &RadialRow<S>,
    tension: Option<S>,
    p: &[Vec2<S>],
    h: S,
) -> (S, Vec2<S>, S) {
    let (p_a, p_b) = (p[row.a as usize], p[row.b as usize]);
    let (end_length, direction) = radial_geometry(geometry, (p_a, p_b), h);
    let lambda = tension.unwrap_or_else(|| {
        row.target.x.sub(
            geometry
                .gain_per_length
                .mul(end_length.sub(geometry.length)),
        )
    });
    let unit = direction
        .try_normalize()
        .or_else(|| geometry.offset.try_normalize())
        .unwrap_or(Vec2::Y);
    let scale = geometry.length.add(end_length);
    let across = if lambda.is_negative() && scale.is_positive() {
        lambda.neg().mul(h).div(scale)
    } else {
        S::ZERO
    };
    (row.rate_gain.x, unit, across)
}

/// A moving end of a row (`w_a + w_b > 0`, so one is).
fn moving_end<S: Scalar>(row: &SpringRow<S>) -> u32 {
    if row.inverse_masses.1.is_positive() {
        row.b
    } else {
        row.a
    }
}
