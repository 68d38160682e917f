//! An exact, linear-time solve for groups of rows whose bodies form a tree:
//! stacks (a chain in the contact graph), chains of ropes, a rope's bob
//! resting on the ground, a box on two boxes that do not touch each other.
//!
//! # Why
//!
//! Sequential impulses (Gauss–Seidel) carry a correction one row per sweep,
//! so on a chain of `n` rows the slowest mode converges like
//! `1 − O(1/n²)` per sweep: a 30-box stack keeps most of its error after 8
//! iterations, and a light rope link between a fixed point and a heavy bob
//! keeps most of it after any affordable number. A direct solve has no such
//! limit. A dense factorisation costs `O(n³)`; a tree needs none of that.
//!
//! # The maths
//!
//! Rows `r` join a *parent* body `p` and, unless the other end is fixed or
//! still, a *child* body `g` (the tree is rooted at a body; every body but
//! the root has exactly one parent row). `J_r v = (v_b − v_a)·n_r`; an
//! impulse `λ` on the row changes `v_b` by `w_b n λ` and `v_a` by
//! `−w_a n λ`. We want the impulses that make every row exact:
//! `J_r (v + Δv) = target_r`.
//!
//! Eliminate rows from the leaves up. Each body `k` carries what its
//! already-eliminated subtree makes of it: an effective *mobility* `K_k`
//! (a symmetric 2×2 matrix, first `w_k I`) and a *drift* `u_k` (the velocity
//! change the subtree's rows cause when nothing else acts), so that an
//! extra impulse `f` on `k` gives `Δv_k = u_k + K_k f`. For row `r`
//! (`σ_p = ±1` the sign of the parent end, `σ_g = −σ_p`), with `g`'s
//! subtree already folded into `(K_g, u_g)`:
//!
//! ```text
//! d  = nᵀ (K_p + K_g) n                       (the row's effective inverse mass)
//! λ⁰ = (target − J_r(v + u)) / d              (its impulse if p felt nothing else)
//! λ  = λ⁰ − a·f_p,   a = σ_p K_p n / d         (f_p: what later rows push on p)
//! u_p ← u_p + σ_p K_p n λ⁰,   K_p ← K_p − (K_p n)(K_p n)ᵀ / d.
//! ```
//!
//! The back pass runs in the reverse order: at the root nothing else
//! pushes (`f = 0`); each row's `λ` follows from the push `f_p` of the rows
//! after it, and adds `σ_p n λ` to `f_p` and starts `f_g = σ_g n λ`. Every
//! row is touched twice with 2×2 arithmetic: `O(n)` and no fill-in (this is
//! block Gaussian elimination of `[M Jᵀ; J 0]` in a leaves-first order, which
//! on a tree creates no new non-zeros).
//!
//! `K_p` stays positive definite while the rows are independent (`d` is at
//! least `nᵀ K_p n`, so the update keeps a positive remainder along `n`). A
//! row that depends on those already folded (a body squeezed between two
//! fixed walls along one normal) has `d ≈ 0`: it is left out of the exact
//! solve (its impulse is 0 here) and the caller treats it by sequential
//! impulses.
//!
//! # Ropes: a sideways stiffness on the edge
//!
//! A rope row may carry a sideways stiffness `g` (set by the caller; 0 for
//! contacts): the edge is then the hard row along `n` and a soft row along
//! `s = perp(n)` with impulse `λ_s = −g·(s·Δv_rel)` (compliance `1/g`),
//! the implicit form of the rope's geometric stiffness `T/ℓ·s sᵀ` (a rope
//! under tension `T` resists turning; `world::step::solve` has the
//! physics). Both rows join the same two bodies, so the edge is eliminated
//! as one 2×2 block: with `R = [nᵀ; sᵀ]` and `K = K_p + K_g`,
//!
//! ```text
//! D  = R K Rᵀ + diag(0, 1/g)
//!    ⇒ D⁻¹ = [[1 + g·c, −g·b], [−g·b, g·a]] / (a(1 + g·c) − g·b²),
//!       a = nᵀKn, b = nᵀKs, c = sᵀKs      (no 1/g: g may be tiny)
//! μ⁰ = D⁻¹ e,   G = σ_p D⁻¹ Qᵀ,   Q = [K_p n, K_p s]
//! u_p ← u_p + σ_p Q μ⁰,   K_p ← K_p − Q D⁻¹ Qᵀ,   μ = μ⁰ − G f_p.
//! ```
//!
//! With `g = 0` this is the scalar row above. `D` is positive definite
//! whenever `a > 0` (its determinant is `(a·c − b²) + a/g > 0`), so the
//! same skip rule applies to `a` and to the determinant's numerator.
//!
//! Rounding: every quantity is a product of a few inverse masses and unit
//! normals; `d` is bounded below by the skip rule (2⁻¹⁶ of the body's own
//! inverse mass), so `λ⁰ = e/d` never amplifies the residual by more than
//! `2¹⁶ / w`, and all products saturate.

mod loop_closure;

use crate::math::{Scalar, Vec2};
use crate::solver::row::{ContactConstraint, solve_position_row};
use crate::solver::tree_plan::{NO_CHILD, TreeRow};
pub(crate) use loop_closure::MAX_LOOP_ROWS;
use loop_closure::{LoopScratch, solve_closed_tree};

/// A symmetric 2×2 matrix.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct Sym2<S: Scalar> {
    xx: S,
    xy: S,
    yy: S,
}

impl<S: Scalar> Sym2<S> {
    fn scalar(w: S) -> Self {
        Sym2 {
            xx: w,
            xy: S::ZERO,
            yy: w,
        }
    }

    fn times(&self, n: Vec2<S>) -> Vec2<S> {
        Vec2::new(
            S::mul_add_mul(self.xx, n.x, self.xy, n.y),
            S::mul_add_mul(self.xy, n.x, self.yy, n.y),
        )
    }
}

/// Working memory of the tree solves, indexed by slot or by row; it grows
/// to the scene's size once and is reused.
#[derive(Clone, Debug, Default)]
pub(crate) struct TreeScratch<S: Scalar> {
    /// `K_k` per slot.
    mobility: Vec<Sym2<S>>,
    /// `u_k` per slot.
    drift: Vec<Vec2<S>>,
    /// `f_k` per slot (back pass).
    load: Vec<Vec2<S>>,
    /// Per slot: how far one rope group's position pass may move the body
    /// ([`trust_scale`]).
    reach: Vec<S>,
    /// `λ⁰` per row.
    free: Vec<S>,
    /// `a` per row.
    gain: Vec<Vec2<S>>,
    /// The sideways part of `λ⁰` per row (edges with a sideways stiffness).
    free_side: Vec<S>,
    /// The sideways part of `a` per row.
    gain_side: Vec<Vec2<S>>,
    /// The sideways stiffness `g` per row (0: none); see [`solve_tree`].
    pub(crate) side_stiffness: Vec<S>,
    /// The solved sideways impulse per row.
    pub(crate) side_value: Vec<S>,
    /// The position impulse the position passes have applied to each row
    /// (by row index) since the rope settling rounds began; empty outside
    /// them, and then nothing is summed (`World::settle_ropes` in
    /// `world/step/contacts.rs` reads it for the ropes' sideways stiffness).
    pub(crate) applied: Vec<S>,
    /// The residual `target − J v` per row on entry, the solved impulse
    /// per row on exit (0 for rows left out).
    pub(crate) value: Vec<S>,
    /// Whether each row takes part in the solve.
    pub(crate) active: Vec<bool>,
    /// Rows of the current group left out because they depend on others.
    pub(crate) dependent: Vec<usize>,
    /// Per row: whether it is in `dependent` (so the callers look it up
    /// in constant time: a pyramid's spanning tree has a dependent row for
    /// every box that rests on two grounded ones).
    is_dependent: Vec<bool>,
    /// Whether each row of the current group is in its tree plan (rows
    /// off the spanning tree are not: sequential impulses solve them, or
    /// [`loop_closure`] with the tree).
    in_plan: Vec<bool>,
    /// Working memory of the loop closure ([`loop_closure`]).
    loops: LoopScratch<S>,
}

impl<S: Scalar> TreeScratch<S> {
    /// A body before any row is folded into it: mobility `w·I`, no drift,
    /// no load.
    fn reset_body(&mut self, slot: u32, inverse_mass: S) {
        let k = slot as usize;
        self.mobility[k] = Sym2::scalar(inverse_mass);
        self.drift[k] = Vec2::ZERO;
        self.load[k] = Vec2::ZERO;
    }

    /// Lists row `r` as left out of the exact solve (it depends on the
    /// rows solved).
    fn mark_dependent(&mut self, r: usize) {
        if !self.is_dependent[r] {
            self.dependent.push(r);
            self.is_dependent[r] = true;
        }
    }

    /// Sizes the per-slot and per-row arrays.
    pub(crate) fn reserve(&mut self, slots: usize, rows: usize) {
        if self.mobility.len() < slots {
            self.mobility.resize(slots, Sym2::default());
            self.drift.resize(slots, Vec2::ZERO);
            self.load.resize(slots, Vec2::ZERO);
            self.reach.resize(slots, S::ZERO);
        }
        if self.free.len() < rows {
            self.free.resize(rows, S::ZERO);
            self.gain.resize(rows, Vec2::ZERO);
            self.free_side.resize(rows, S::ZERO);
            self.gain_side.resize(rows, Vec2::ZERO);
            self.side_stiffness.resize(rows, S::ZERO);
            self.side_value.resize(rows, S::ZERO);
            self.value.resize(rows, S::ZERO);
            self.active.resize(rows, false);
            self.in_plan.resize(rows, false);
            self.is_dependent.resize(rows, false);
        }
    }
}

/// Solves the active rows of one tree exactly: on entry `work.value[r]` is
/// the residual `target_r − J_r v` of each active row; on exit
/// `work.value[r]` is the
/// impulse that makes every active row exact, and `work.dependent` lists the
/// active rows left out (impulse 0). Nothing is applied.
pub(crate) fn solve_tree<S: Scalar>(
    rows: &[ContactConstraint<S>],
    plan: &[TreeRow],
    work: &mut TreeScratch<S>,
) {
    for &r in &work.dependent {
        work.is_dependent[r] = false;
    }
    work.dependent.clear();
    // Reset the bodies of the tree: each appears as a parent or a child.
    for t in plan {
        let r = &rows[t.row];
        let (w_parent, w_child) = if t.parent_is_b {
            (r.inverse_mass_b, r.inverse_mass_a)
        } else {
            (r.inverse_mass_a, r.inverse_mass_b)
        };
        work.reset_body(t.parent, w_parent);
        if t.child != NO_CHILD {
            work.reset_body(t.child, w_child);
        }
    }
    // Forward: fold each row into its parent, leaves first.
    for t in plan {
        if !work.active[t.row] {
            continue;
        }
        let r = &rows[t.row];
        let n = r.normal;
        let p = t.parent as usize;
        let k_p = work.mobility[p];
        let kn = k_p.times(n);
        let own = n.dot(kn);
        let child_part = if t.child == NO_CHILD {
            S::ZERO
        } else {
            n.dot(work.mobility[t.child as usize].times(n))
        };
        let d = own.add(child_part);
        // Skip rule: a pivot below 2⁻¹⁶ of the parent's own inverse mass
        // means the row depends on rows already folded (see module docs).
        let w_parent = if t.parent_is_b {
            r.inverse_mass_b
        } else {
            r.inverse_mass_a
        };
        let floor = w_parent.mul(S::from_ratio(1, 65_536)).max(S::EPSILON);
        if d <= floor {
            work.dependent.push(t.row);
            work.is_dependent[t.row] = true;
            work.free[t.row] = S::ZERO;
            work.gain[t.row] = Vec2::ZERO;
            work.free_side[t.row] = S::ZERO;
            work.gain_side[t.row] = Vec2::ZERO;
            continue;
        }
        // Residual at the predicted velocities: the entry residual minus
        // what the subtrees' drifts already do along this row.
        let (ub, ua) = if t.parent_is_b {
            (work.drift[p], child_drift(work, t))
        } else {
            (child_drift(work, t), work.drift[p])
        };
        let residual = work.value[t.row].sub((ub - ua).dot(n));
        let g = work.side_stiffness[t.row];
        if !g.is_positive() {
            let free = residual.div(d);
            let signed_kn = if t.parent_is_b { kn } else { -kn };
            work.free[t.row] = free;
            work.free_side[t.row] = S::ZERO;
            work.gain[t.row] = Vec2::new(signed_kn.x.div(d), signed_kn.y.div(d));
            work.gain_side[t.row] = Vec2::ZERO;
            work.drift[p] += signed_kn.scale(free);
            // K_p − (K_p n)(K_p n)ᵀ / d, with (K_p n)/d computed once.
            let q = Vec2::new(kn.x.div(d), kn.y.div(d));
            work.mobility[p] = Sym2 {
                xx: k_p.xx.sub(kn.x.mul(q.x)),
                xy: k_p.xy.sub(kn.x.mul(q.y)),
                yy: k_p.yy.sub(kn.y.mul(q.y)),
            };
            continue;
        }
        // An edge with a sideways stiffness g along s = perp(n) (see
        // `solve_tree`): rows (n, s), D = R K Rᵀ + diag(0, 1/g) with
        // K = K_p + K_g, written without 1/g:
        //   D⁻¹ = [[1 + g·c, −g·b], [−g·b, g·a]] / (a(1 + g·c) − g·b²),
        //   a = nᵀKn, b = nᵀKs, c = sᵀKs.
        let side = n.perp();
        let k_sum = match t.child {
            NO_CHILD => k_p,
            child => {
                let k_g = work.mobility[child as usize];
                Sym2 {
                    xx: k_p.xx.add(k_g.xx),
                    xy: k_p.xy.add(k_g.xy),
                    yy: k_p.yy.add(k_g.yy),
                }
            }
        };
        let (a, b, c) = (d, n.dot(k_sum.times(side)), side.dot(k_sum.times(side)));
        let one_gc = S::ONE.add(g.mul(c));
        let (gb, ga) = (g.mul(b), g.mul(a));
        let den = a.mul(one_gc).sub(gb.mul(b));
        if den <= floor {
            work.dependent.push(t.row);
            work.is_dependent[t.row] = true;
            work.free[t.row] = S::ZERO;
            work.gain[t.row] = Vec2::ZERO;
            work.free_side[t.row] = S::ZERO;
            work.gain_side[t.row] = Vec2::ZERO;
            continue;
        }
        let residual_side = work.side_value[t.row].sub((ub - ua).dot(side));
        // μ⁰ = D⁻¹ e.
        let free = one_gc.mul(residual).sub(gb.mul(residual_side)).div(den);
        let free_side = ga.mul(residual_side).sub(gb.mul(residual)).div(den);
        let ks = k_p.times(side);
        let sign = |v: Vec2<S>| if t.parent_is_b { v } else { -v };
        // Gains G = σ D⁻¹ Qᵀ with Q = [K_p n, K_p s].
        let gain_n = Vec2::new(
            one_gc.mul(kn.x).sub(gb.mul(ks.x)).div(den),
            one_gc.mul(kn.y).sub(gb.mul(ks.y)).div(den),
        );
        let gain_s = Vec2::new(
            ga.mul(ks.x).sub(gb.mul(kn.x)).div(den),
            ga.mul(ks.y).sub(gb.mul(kn.y)).div(den),
        );
        work.free[t.row] = free;
        work.free_side[t.row] = free_side;
        work.gain[t.row] = sign(gain_n);
        work.gain_side[t.row] = sign(gain_s);
        work.drift[p] += sign(kn.scale(free) + ks.scale(free_side));
        // K_p − Q D⁻¹ Qᵀ = K_p − kn·gain_nᵀ − ks·gain_sᵀ (symmetric).
        work.mobility[p] = Sym2 {
            xx: k_p.xx.sub(kn.x.mul(gain_n.x)).sub(ks.x.mul(gain_s.x)),
            xy: k_p.xy.sub(kn.x.mul(gain_n.y)).sub(ks.x.mul(gain_s.y)),
            yy: k_p.yy.sub(kn.y.mul(gain_n.y)).sub(ks.y.mul(gain_s.y)),
        };
    }
    // Back pass: the root feels nothing else; each row's impulse follows
    // from what the rows after it push on its parent.
    for t in plan.iter().rev() {
        if !work.active[t.row] {
            continue;
        }
        let p = t.parent as usize;
        let lambda = work.free[t.row].sub(work.gain[t.row].dot(work.load[p]));
        let n = rows[t.row].normal;
        // A row without a sideways stiffness has no sideways impulse
        // (its free part and gain are zero): skip the products.
        let push = if work.side_stiffness[t.row].is_positive() {
            let lambda_side = work.free_side[t.row].sub(work.gain_side[t.row].dot(work.load[p]));
            work.side_value[t.row] = lambda_side;
            n.scale(lambda) + n.perp().scale(lambda_side)
        } else {
            work.side_value[t.row] = S::ZERO;
            n.scale(lambda)
        };
        if t.parent_is_b {
            work.load[p] += push;
        } else {
            work.load[p] -= push;
        }
        if t.child != NO_CHILD {
            work.load[t.child as usize] = if t.parent_is_b { -push } else { push };
        }
        work.value[t.row] = lambda;
    }
    for &r in &work.dependent {
        work.value[r] = S::ZERO;
        work.side_value[r] = S::ZERO;
    }
}

/// Marks which rows of `group` are in `plan` (`work.in_plan`).
fn mark_plan<S: Scalar>(group: &[usize], plan: &[TreeRow], work: &mut TreeScratch<S>) {
    for &ri in group {
        work.in_plan[ri] = false;
    }
    for t in plan {
        work.in_plan[t.row] = true;
    }
}

/// Which of a rope group's rows off its spanning tree (the plan marked in
/// `work.in_plan`) are solved exactly with the tree ([`loop_closure`]):
/// the rows below the index returned. All of them (`usize::MAX`) when
/// there are 1..=[`MAX_LOOP_ROWS`]; else its rope rows (those below
/// `ropes`, the rope rows coming first) when they are that many; else
/// none (0, also for a group without ropes, `ropes` 0).
///
/// The callers close the loops of rope groups only (those are the groups
/// passed a sideways stiffness): a cyclic contact group above the block
/// solver's size is a pile with a row off the tree for nearly every body,
/// far beyond what `k + 2` tree solves per sweep can afford. For the same
/// reason a rope group's contacts off the tree (links of a folded ring
/// touching each other) are not closed: they take sequential impulses.
fn closes_loops<S: Scalar>(group: &[usize], ropes: usize, work: &TreeScratch<S>) -> usize {
    let off = |below: usize| {
        group
            .iter()
            .filter(|&&ri| ri < below && !work.in_plan[ri])
            .count()
    };
    if ropes == 0 {
        0
    } else if (1..=MAX_LOOP_ROWS).contains(&off(usize::MAX)) {
        usize::MAX
    } else if (1..=MAX_LOOP_ROWS).contains(&off(ropes)) {
        ropes
    } else {
        0
    }
}

/// One exact solve of the active rows: the tree alone, or with its active
/// rows off the tree when `closing` ([`loop_closure`]).
fn solve_rows<S: Scalar>(
    rows: &[ContactConstraint<S>],
    group: &[usize],
    plan: &[TreeRow],
    closing: bool,
    work: &mut TreeScratch<S>,
) {
    if closing {
        work.collect_loop_rows(group);
        solve_closed_tree(rows, plan, work);
    } else {
        solve_tree(rows, plan, work);
    }
}

/// The drift of a row's child (zero for a fixed or still other end).
fn child_drift<S: Scalar>(work: &TreeScratch<S>, t: &TreeRow) -> Vec2<S> {
    if t.child == NO_CHILD {
        Vec2::ZERO
    } else {
        work.drift[t.child as usize]
    }
}

/// Applies impulse `amount` of row `row` to `target` (velocities or
/// displacements).
fn apply<S: Scalar>(row: &ContactConstraint<S>, amount: S, target: &mut [Vec2<S>]) {
    if row.inverse_mass_a.is_positive() {
        target[row.a as usize] -= row.push_a.scale(amount);
    }
    if row.inverse_mass_b.is_positive() {
        target[row.b as usize] += row.push_b.scale(amount);
    }
}

/// The sideways stiffness of rope rows in a velocity solve and the
/// sideways impulse each has received this substep (see
/// `world::step::solve`).
pub(crate) struct SideRows<'a, S: Scalar> {
    /// `g` per row (0: none).
    pub(crate) stiffness: &'a [S],
    /// The accumulated sideways impulse per row.
    pub(crate) accumulated: &'a mut [S],
}

/// Applies sideways impulse `amount` of row `row` (along `perp(n)`) to
/// `target`.
fn apply_side<S: Scalar>(row: &ContactConstraint<S>, amount: S, target: &mut [Vec2<S>]) {
    if amount == S::ZERO {
        return;
    }
    let side = row.normal.perp();
    if row.inverse_mass_a.is_positive() {
        target[row.a as usize] -= side.scale(row.inverse_mass_a.mul(amount));
    }
    if row.inverse_mass_b.is_positive() {
        target[row.b as usize] += side.scale(row.inverse_mass_b.mul(amount));
    }
}

/// Active-set rounds per solve: each round releases the rows that would
/// have to pull (a contact) or push (a rope); what is still unsettled after
/// the last round is left to the sequential pass and the next iteration.
const ROUNDS: usize = 4;

/// Whether a rope group (`ropes`: one entry per rope row, the rope rows
/// first) holds contacts too: its last row is not a rope.
fn holds_contacts<S>(group: &[usize], ropes: &[S]) -> bool {
    !ropes.is_empty() && group.last().is_some_and(|&ri| ri >= ropes.len())
}

/// Active-set rounds per solve of a group holding ropes and contacts. A chain lying on
/// a peg or a face and pulled off it lets go of its contacts one after
/// another: each round's solve makes the next link's contact pull once the
/// one before is released (a 50-link chain sliding off a box peg released
/// one row per round for 4 rounds in every sweep, so no solution was ever
/// applied, and the chain stretched 26 %). The rounds stop as soon as no
/// row is released, so a group that settles in one or two rounds costs
/// no more.
const ROPE_ROUNDS: usize = 16;

/// One exact velocity solve of a tree group's normal impulses, with the
/// accumulated impulses kept non-negative (active set), followed by a
/// sequential-impulse update of the rows the exact solve left out (idle
/// rows that may have become violated, dependent rows, rows off the
/// spanning tree of a cyclic group). Friction is the
/// caller's.
///
/// `off_plan`: which rows of the group that are not in `plan` take the
/// sequential update (`None`: all of them; a group covered by several
/// trees passes the rows in none, [`crate::solver::forest_cover`]).
#[allow(clippy::too_many_arguments)]
pub(crate) fn solve_tree_velocities<S: Scalar>(
    rows: &mut [ContactConstraint<S>],
    group: &[usize],
    plan: &[TreeRow],
    velocities: &mut [Vec2<S>],
    slop: S,
    side: Option<SideRows<'_, S>>,
    off_plan: Option<&[bool]>,
    work: &mut TreeScratch<S>,
) {
    let shortfall = |row: &ContactConstraint<S>, v: &[Vec2<S>]| {
        row.target_velocity
            .sub((v[row.b as usize] - v[row.a as usize]).dot(row.normal))
    };
    // Rows carrying impulse, touching (separation within the slop: a taut
    // rope, a resting contact) or at or beyond their target take part; idle
    // rows that are strictly satisfied and apart (a speculative contact not
    // closing) stay out.
    //
    // Why touching rows start in the set: a rope whose slack rounds to a
    // few ulps above zero has a speculative target a few ulps below zero
    // and is strictly satisfied while the chain below it falls as one
    // piece; left out, it joins only after the round that lets the links
    // above it hold and the links below it fall, one such row per round.
    // In a hanging chain of 80 links enough rows round that way to
    // outlast the rounds, and the bottom links fell freely for a tick
    // (0.73–2.02 % stretch). A touching row that should not hold is
    // released by the first round (its impulse would pull).
    mark_plan(group, plan, work);
    // The count of rows off the tree in `closes_loops` holds for a group
    // solved on one tree only (`off_plan` not given).
    // Off-tree rows closed exactly with the tree: those below `closing`
    // ([`closes_loops`]); the others take sequential impulses.
    let closing = match side.as_ref() {
        Some(sr) if off_plan.is_none() => closes_loops(group, sr.stiffness.len(), work),
        _ => 0,
    };
    for &ri in group {
        let row = &rows[ri];
        work.side_stiffness[ri] = side
            .as_ref()
            .filter(|_| work.in_plan[ri])
            .and_then(|sr| sr.stiffness.get(ri).copied())
            .unwrap_or(S::ZERO);
        work.side_value[ri] = S::ZERO;
        work.active[ri] = (work.in_plan[ri] || ri < closing)
            && (row.normal_impulse.is_positive()
                || row.separation <= slop
                || !shortfall(row, velocities).is_negative());
    }
    let rounds = match side.as_ref() {
        Some(sr) if holds_contacts(group, sr.stiffness) => ROPE_ROUNDS,
        _ => ROUNDS,
    };
    let mut side = side;
    for _ in 0..rounds {
        for &ri in group {
            if work.active[ri] {
                work.value[ri] = shortfall(&rows[ri], velocities);
                let g = work.side_stiffness[ri];
                if let Some(sr) = side.as_ref()
                    && g.is_positive()
                {
                    // λ_s = −g·(s·v_rel) at the end: residual
                    // −s·v_rel − (impulse so far)/g.
                    let row = &rows[ri];
                    let v_rel = velocities[row.b as usize] - velocities[row.a as usize];
                    work.side_value[ri] = v_rel
                        .dot(row.normal.perp())
                        .add(sr.accumulated[ri].div(g))
                        .neg();
                }
            }
        }
        solve_rows(rows, group, plan, closing > 0, work);
        let mut released = false;
        for &ri in group {
            if work.active[ri] && rows[ri].normal_impulse.add(work.value[ri]).is_negative() {
                // Let go of it: its accumulated impulse is taken back.
                let old = rows[ri].normal_impulse;
                rows[ri].normal_impulse = S::ZERO;
                apply(&rows[ri], old.neg(), velocities);
                work.active[ri] = false;
                released = true;
            }
        }
        if released {
            continue;
        }
        for &ri in group {
            if work.active[ri] {
                let x = work.value[ri];
                rows[ri].normal_impulse = rows[ri].normal_impulse.add(x);
                apply(&rows[ri], x, velocities);
                if let Some(sr) = side.as_mut()
                    && work.side_stiffness[ri].is_positive()
                {
                    let y = work.side_value[ri];
                    sr.accumulated[ri] = sr.accumulated[ri].add(y);
                    apply_side(&rows[ri], y, velocities);
                }
            }
        }
        // Rows left out that the solution now violates join the next round.
        let mut joined = false;
        for &ri in group {
            if (work.in_plan[ri] || ri < closing)
                && !work.active[ri]
                && shortfall(&rows[ri], velocities).is_positive()
            {
                work.active[ri] = true;
                joined = true;
            }
        }
        if !joined {
            break;
        }
    }
    for &ri in group {
        let row = &mut rows[ri];
        let missing = if work.in_plan[ri] || ri < closing {
            !work.active[ri] || work.is_dependent[ri]
        } else {
            off_plan.is_none_or(|rest| rest[ri])
        };
        if !missing {
            continue;
        }
        let old = row.normal_impulse;
        let lambda = shortfall(row, velocities).mul(row.effective_mass);
        row.normal_impulse = old.add(lambda).max(S::ZERO);
        let dn = row.normal_impulse.sub(old);
        if dn != S::ZERO {
            apply(row, dn, velocities);
        }
    }
}

/// One exact position-correction solve of a tree group: every row
/// penetrated (or stretched) beyond the slop is corrected by the fraction
/// `beta` of its excess, at most `max_correction` (and at most its entry
/// in `row_caps`, where it has one), all at once; rows that would have to
/// pull are released and the rest re-solved. Rows not in `plan` take
/// sequential corrections after it, those marked in `off_plan` when given
/// (as in [`solve_tree_velocities`]) and only those below
/// `off_tree_below` (the rope settling rounds pass the number of rope
/// rows: see `World::settle_ropes`).
///
/// Rows left out (apart) that the applied correction pushes in or
/// stretches beyond the slop join a further round, which holds the rows
/// already corrected where they are and corrects the newcomers. Without
/// it, a rope slack by a little more than the slop next to a stretched one
/// took the whole correction as new stretch, and the stretch walked down
/// the chain one rope per pass: a 50-link chain with a 1000× body in the
/// middle, released horizontal, kept 3.8 % after the settling passes.
#[allow(clippy::too_many_arguments)]
pub(crate) fn solve_tree_positions<S: Scalar>(
    rows: &[ContactConstraint<S>],
    group: &[usize],
    plan: &[TreeRow],
    displacements: &mut [Vec2<S>],
    slop: S,
    beta: S,
    max_correction: S,
    side_stiffness: &[S],
    row_caps: &[S],
    off_plan: Option<&[bool]>,
    off_tree_below: usize,
    work: &mut TreeScratch<S>,
) {
    // The correction each row asks for (≤ 0), from the current separation.
    let correction = |ri: usize, d: &[Vec2<S>]| {
        let row = &rows[ri];
        let cap = row_caps
            .get(ri)
            .map_or(max_correction, |&c| c.min(max_correction));
        let separation = row
            .separation
            .add((d[row.b as usize] - d[row.a as usize]).dot(row.normal));
        if !separation.add(slop).is_negative() {
            return S::ZERO;
        }
        beta.mul(separation.add(slop)).clamp(cap.neg(), S::ZERO)
    };
    // Rows beyond the slop are corrected; rows touching (within the slop)
    // are held where they are, so a correction does not stretch or push
    // into the rows next to it (released if holding would pull); rows
    // apart stay out.
    mark_plan(group, plan, work);
    // As in `solve_tree_velocities`: the rope rows off the tree (below
    // `closing`) closed exactly with it.
    let closing = if off_plan.is_none() {
        closes_loops(group, side_stiffness.len(), work)
    } else {
        0
    };
    let mut any = false;
    for &ri in group {
        let row = &rows[ri];
        if !(work.in_plan[ri] || ri < closing) {
            work.active[ri] = false;
            continue;
        }
        let c = correction(ri, displacements);
        any |= c.is_negative();
        let separation = row
            .separation
            .add((displacements[row.b as usize] - displacements[row.a as usize]).dot(row.normal));
        work.active[ri] = c.is_negative() || separation <= slop;
        work.value[ri] = c.neg();
        work.side_stiffness[ri] = if work.in_plan[ri] {
            side_stiffness.get(ri).copied().unwrap_or(S::ZERO)
        } else {
            S::ZERO
        };
        work.side_value[ri] = S::ZERO;
    }
    if any {
        // A group covered by several trees (`off_plan` given) lets no row
        // join a further round: the next tree's exact pass, in the same
        // sweep, corrects what this one pushed in.
        let join = off_plan.is_none();
        // Rope groups: more rounds, and each pass kept within the reach
        // of its linearisation (`trust_scale`).
        let (rounds, reach) = if holds_contacts(group, side_stiffness) {
            (ROPE_ROUNDS, Some((row_caps, max_correction)))
        } else {
            (ROUNDS, None)
        };
        solve_tree_position_rounds(
            rows,
            group,
            (plan, closing),
            displacements,
            (slop, join, rounds),
            work,
            (correction, reach),
        );
        // Rows the exact pass left out as dependent (their pivot vanished:
        // two boxes spawned at one point on the ground, the pair's row
        // vertical and both boxes held by the ground's rows) take a
        // sequential correction, as the velocity solve's missing rows do;
        // left alone, nothing ever pushed such a pair apart (issue 13).
        for &ri in group {
            if work.in_plan[ri] && work.is_dependent[ri] {
                let cap = row_caps
                    .get(ri)
                    .map_or(max_correction, |&c| c.min(max_correction));
                solve_position_row(&rows[ri], displacements, slop, beta, cap);
            }
        }
    }
    // Rows off the spanning tree: sequential position corrections, after
    // the exact pass (the next iteration's exact pass sees what they moved).
    for &ri in group {
        if !work.in_plan[ri] && ri < off_tree_below && off_plan.is_none_or(|rest| rest[ri]) {
            let cap = row_caps
                .get(ri)
                .map_or(max_correction, |&c| c.min(max_correction));
            solve_position_row(&rows[ri], displacements, slop, beta, cap);
        }
    }
}

/// The fraction of one rope group's position solution (`work.value`,
/// `work.side_value` of its active rows) that keeps every body within the
/// reach of the pass's linearisation: a body with ropes moves at most the
/// smallest cap of its ropes (`caps`, an eighth of each rope's length, see
/// `world::step::solve`), any other at most `most` (`max_correction`),
/// per axis. 1 when the solution stays within it; otherwise the whole
/// solution is scaled down alike (a damped Newton step: every row's
/// correction keeps its share).
///
/// Why: ropes and contacts solved in one group meet in rows that are
/// almost parallel. A rope pulling a body straight into the fixed box it
/// stands on cannot be shortened except sideways: a rope stretched by 1.3
/// from an anchor under the box, 5° off the contact's normal, asked for a
/// correction of 0.25 (its cap) and the exact solve moved the body 2.8
/// sideways per pass (0.25/sin 5°), round the box and under it. The
/// linearisation holds only for moves of about the cap: the pass is
/// damped to it, and the next pass looks again.
fn trust_scale<S: Scalar>(
    rows: &[ContactConstraint<S>],
    group: &[usize],
    caps: &[S],
    most: S,
    work: &mut TreeScratch<S>,
) -> S {
    for &ri in group {
        let row = &rows[ri];
        for slot in [row.a, row.b] {
            work.drift[slot as usize] = Vec2::ZERO;
            work.reach[slot as usize] = most;
        }
    }
    for &ri in group {
        let row = &rows[ri];
        if let Some(&cap) = caps.get(ri) {
            for slot in [row.a, row.b] {
                let reach = &mut work.reach[slot as usize];
                *reach = (*reach).min(cap);
            }
        }
        if work.active[ri] {
            apply(row, work.value[ri], &mut work.drift);
            apply_side(row, work.side_value[ri], &mut work.drift);
        }
    }
    let mut scale = S::ONE;
    for &ri in group {
        let row = &rows[ri];
        for slot in [row.a, row.b] {
            let moved = work.drift[slot as usize];
            let far = moved.x.abs().max(moved.y.abs());
            let reach = work.reach[slot as usize];
            if far > reach {
                scale = scale.min(reach.div(far));
            }
        }
    }
    scale
}

/// The active-set rounds of [`solve_tree_positions`]: `work` holds the
/// active rows and their corrections on entry.
fn solve_tree_position_rounds<S: Scalar>(
    rows: &[ContactConstraint<S>],
    group: &[usize],
    (plan, closing): (&[TreeRow], usize),
    displacements: &mut [Vec2<S>],
    (slop, join, rounds): (S, bool, usize),
    work: &mut TreeScratch<S>,
    (correction, reach): (impl Fn(usize, &[Vec2<S>]) -> S, Option<(&[S], S)>),
) {
    for _ in 0..rounds {
        solve_rows(rows, group, plan, closing > 0, work);
        let mut released = false;
        for &ri in group {
            if work.active[ri] && work.value[ri].is_negative() {
                work.active[ri] = false;
                released = true;
            }
        }
        if !released {
            let scale = reach.map_or(S::ONE, |(caps, most)| {
                trust_scale(rows, group, caps, most, work)
            });
            for &ri in group {
                if work.active[ri] {
                    let (value, side) = if scale == S::ONE {
                        (work.value[ri], work.side_value[ri])
                    } else {
                        (work.value[ri].mul(scale), work.side_value[ri].mul(scale))
                    };
                    apply(&rows[ri], value, displacements);
                    apply_side(&rows[ri], side, displacements);
                    if let Some(sum) = work.applied.get_mut(ri) {
                        *sum = sum.add(value);
                    }
                }
            }
            // Rows left out that the correction stretched (or pushed in)
            // beyond the slop join the next round; the rows corrected are
            // held where they are now (their fraction beta is taken).
            let mut joined = false;
            for &ri in group {
                if join
                    && (work.in_plan[ri] || ri < closing)
                    && !work.active[ri]
                    && correction(ri, displacements).is_negative()
                {
                    joined = true;
                }
            }
            if !joined {
                return;
            }
            for &ri in group.iter().filter(|&&ri| work.in_plan[ri] || ri < closing) {
                let row = &rows[ri];
                let separation = row.separation.add(
                    (displacements[row.b as usize] - displacements[row.a as usize]).dot(row.normal),
                );
                let c = correction(ri, displacements);
                if work.active[ri] {
                    work.value[ri] = S::ZERO;
                } else {
                    work.active[ri] = c.is_negative() || separation <= slop;
                    work.value[ri] = c.neg();
                }
                work.side_value[ri] = S::ZERO;
            }
            continue;
        }
        // Residuals again (the solve overwrote them), for the rows kept.
        for &ri in group {
            if work.active[ri] {
                work.value[ri] = correction(ri, displacements).neg();
                work.side_value[ri] = S::ZERO;
            }
        }
    }
}
