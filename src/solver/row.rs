//! Sequential impulses for contacts, with warm starting, speculative
//! contacts, restitution, Coulomb friction, and a separate position pass.
//!
//! # The model (no rotation, one point per pair)
//!
//! With bodies that cannot rotate, a contact's Jacobian is just `±n`, so the
//! effective mass along the normal and along the tangent is the same scalar
//! `m = 1 / (w_a + w_b)` (`w` = inverse mass) and the contact point does not
//! matter. For relative normal velocity `v_n = (v_b - v_a)·n`:
//!
//! * **Speculative:** with a gap `s > 0` the constraint is `v_n ≥ -s / h`: the
//!   bodies may close the gap exactly within the step but not more. The
//!   impact happens "the instant before it hits", with no later push-back.
//! * **Touching/penetrating** (`s ≤ 0`): `v_n ≥ 0`. Penetration is removed
//!   by the position pass, which moves bodies without touching velocities,
//!   so correcting it adds no energy.
//! * **Restitution:** if the pair approached faster than the threshold at
//!   the start of the step and will meet within it (`-v_n0·h ≥ s`), the
//!   target becomes `v_n ≥ -e·v_n0`.
//! * **Friction:** `v_t = (v_b - v_a)·t` with `t = perp(n)`, accumulated
//!   impulse clamped to `|λ_t| ≤ μ λ_n`.
//!
//! Each impulse is accumulated and clamped (`λ_n ≥ 0`), so iterating converges
//! to the projected solution; the accumulated impulses of the previous step
//! warm-start the next, which is what lets stacks settle in few iterations.

use crate::math::{Scalar, Vec2};

/// One contact prepared for the solver.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct ContactConstraint<S: Scalar> {
    pub(crate) a: u32,
    pub(crate) b: u32,
    /// Unit normal from a to b.
    pub(crate) normal: Vec2<S>,
    /// Separation at the start of the substep.
    pub(crate) separation: S,
    /// Inverse masses as the solver sees them.
    pub(crate) inverse_mass_a: S,
    pub(crate) inverse_mass_b: S,
    /// `1 / (w_a + w_b)`.
    pub(crate) effective_mass: S,
    pub(crate) friction: S,
    /// The lowest allowed relative normal velocity (speculative bound or
    /// restitution target).
    pub(crate) target_velocity: S,
    pub(crate) normal_impulse: S,
    pub(crate) tangent_impulse: S,
    /// `w_a·n` and `w_b·n`, precomputed: the velocity change per unit of
    /// normal impulse (and, turned a quarter, of friction impulse).
    pub(crate) push_a: Vec2<S>,
    pub(crate) push_b: Vec2<S>,
}

impl<S: Scalar> ContactConstraint<S> {
    /// A row between slots `a` and `b` with normal `normal` (from a to b),
    /// separation, inverse masses `(w_a, w_b)` with `w_a + w_b > 0`, their
    /// [`effective_mass`] (passed in so that the narrow phase can reuse it
    /// across the many pairs of equal masses), friction and warm-start
    /// impulses `(normal, tangent)`; the target is set by
    /// [`prepare_target`](Self::prepare_target).
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn new(
        a: u32,
        b: u32,
        normal: Vec2<S>,
        separation: S,
        (inverse_mass_a, inverse_mass_b): (S, S),
        effective_mass: S,
        friction: S,
        (normal_impulse, tangent_impulse): (S, S),
    ) -> Self {
        let push_a = normal.scale(inverse_mass_a);
        let push_b = if inverse_mass_b == inverse_mass_a {
            push_a
        } else {
            normal.scale(inverse_mass_b)
        };
        ContactConstraint {
            a,
            b,
            normal,
            separation,
            inverse_mass_a,
            inverse_mass_b,
            effective_mass,
            friction,
            target_velocity: S::ZERO,
            normal_impulse,
            tangent_impulse,
            push_a,
            push_b,
        }
    }

    /// Sets the velocity target from the separation, the approach speed
    /// at the start of the substep and the restitution.
    pub(crate) fn prepare_target(
        &mut self,
        relative_normal_velocity: S,
        restitution: S,
        restitution_threshold: S,
        h: S,
        inverse_h: S,
    ) {
        // Speculative bound: v_n ≥ -max(s, 0)/h.
        let speculative = if self.separation.is_positive() {
            self.separation.mul(inverse_h).neg()
        } else {
            S::ZERO
        };
        let approaching_fast = relative_normal_velocity < restitution_threshold.neg();
        // Will the gap close within this substep? -v_n0·h ≥ s.
        let meets = relative_normal_velocity.neg().mul(h) >= self.separation;
        self.target_velocity = if restitution.is_positive() && approaching_fast && meets {
            speculative.max(restitution.mul(relative_normal_velocity).neg())
        } else {
            speculative
        };
    }
}

/// `1 / (w_a + w_b)`, the effective mass of a row along any direction.
/// The caller guarantees a positive sum: no division by zero.
#[inline]
pub(crate) fn effective_mass<S: Scalar>(inverse_mass_a: S, inverse_mass_b: S) -> S {
    S::ONE.div(inverse_mass_a.add(inverse_mass_b))
}

/// Applies the warm-start impulses.
pub(crate) fn warm_start<S: Scalar>(
    constraints: &[ContactConstraint<S>],
    velocities: &mut [Vec2<S>],
) {
    for c in constraints {
        apply_row(c, c.normal_impulse, c.tangent_impulse, velocities);
    }
}

/// Applies normal impulse `dn` and friction impulse `dt` (along
/// `perp(n)`): `Δv_b = w_b·(n·dn + perp(n)·dt)`, `Δv_a = −w_a·(…)`.
///
/// Always inlined: it runs once per row and sweep (~20 million times in
/// 300 ticks of `balls5000`), and as a call it cost a fifth of its own
/// work in saving and restoring registers.
#[inline(always)]
fn apply_row<S: Scalar>(c: &ContactConstraint<S>, dn: S, dt: S, velocities: &mut [Vec2<S>]) {
    // w·(n·dn + perp(n)·dt) = (p.x·dn − p.y·dt, p.y·dn + p.x·dt) for p = w·n,
    // each component one exact two-product sum, rounded once.
    let delta = |p: Vec2<S>| {
        Vec2::new(
            S::mul_sub_mul(p.x, dn, p.y, dt),
            S::mul_add_mul(p.y, dn, p.x, dt),
        )
    };
    match (
        c.inverse_mass_a.is_positive(),
        c.inverse_mass_b.is_positive(),
    ) {
        (true, true) => {
            let change_a = delta(c.push_a);
            // Equal masses (a ball pit, a stack of equal boxes) give equal
            // push vectors, hence the same change: compute it once.
            let change_b = if c.push_b == c.push_a {
                change_a
            } else {
                delta(c.push_b)
            };
            velocities[c.a as usize] -= change_a;
            velocities[c.b as usize] += change_b;
        }
        (true, false) => velocities[c.a as usize] -= delta(c.push_a),
        (false, true) => velocities[c.b as usize] += delta(c.push_b),
        (false, false) => {}
    }
}

/// The friction half of [`solve_velocity_row`] (used after a block solve of
/// the normal impulses).
#[inline]
pub(crate) fn solve_friction_row<S: Scalar>(
    c: &mut ContactConstraint<S>,
    velocities: &mut [Vec2<S>],
) {
    let limit = c.friction.mul(c.normal_impulse);
    let old_t = c.tangent_impulse;
    if limit == S::ZERO && old_t == S::ZERO {
        return;
    }
    let relative = velocities[c.b as usize] - velocities[c.a as usize];
    let vt = c.normal.cross(relative);
    c.tangent_impulse = old_t
        .sub(vt.mul(c.effective_mass))
        .clamp(limit.neg(), limit);
    let dt = c.tangent_impulse.sub(old_t);
    if dt != S::ZERO {
        apply_row(c, S::ZERO, dt, velocities);
    }
}

/// One sequential-impulse update of one row: friction (bounded by the
/// normal impulse of the last pass), then the normal impulse.
///
/// A friction impulse changes the relative velocity only along `perp(n)`
/// (both bodies' changes are multiples of `perp(n)`), so the normal
/// velocity is read once, before either update.
///
/// Never inlined: inlined into the sweep over groups (which also holds
/// the block and tree solves) it shared that function's registers and
/// spilled its values to the stack on every row; as a function of its own
/// it keeps them in registers. The call costs a few more instructions
/// (callgrind: `balls5000` 300 ticks +1.9 % with the position row below)
/// but ~10 % less time for the whole step.
#[inline(never)]
pub(crate) fn solve_velocity_row<S: Scalar>(
    c: &mut ContactConstraint<S>,
    velocities: &mut [Vec2<S>],
) {
    let relative = velocities[c.b as usize] - velocities[c.a as usize];
    let vn = relative.dot(c.normal);

    let limit = c.friction.mul(c.normal_impulse);
    let old_t = c.tangent_impulse;
    let dt = if limit == S::ZERO && old_t == S::ZERO {
        S::ZERO
    } else {
        // v_t = relative · perp(n) = n × relative.
        let vt = c.normal.cross(relative);
        c.tangent_impulse = old_t
            .sub(vt.mul(c.effective_mass))
            .clamp(limit.neg(), limit);
        c.tangent_impulse.sub(old_t)
    };

    // Normal: drive v_n to at least the target, accumulated λ ≥ 0.
    let old_n = c.normal_impulse;
    let shortfall = c.target_velocity.sub(vn);
    // An idle row (no accumulated impulse, already at or above its target:
    // a speculative contact that is not closing) stays idle: λ = shortfall·m
    // ≤ 0 (the product rounds toward −∞ but cannot turn positive) and the
    // clamp keeps the impulse at zero. Skip the product; same bits.
    let dn = if old_n == S::ZERO && !shortfall.is_positive() {
        S::ZERO
    } else {
        let lambda = shortfall.mul(c.effective_mass);
        c.normal_impulse = old_n.add(lambda).max(S::ZERO);
        c.normal_impulse.sub(old_n)
    };
    if dn != S::ZERO || dt != S::ZERO {
        apply_row(c, dn, dt, velocities);
    }
}

/// The normal half of [`solve_velocity_row`] (the bounce solve,
/// [`crate::solver::restitution`], moves normal impulses only).
#[inline]
pub(crate) fn solve_normal_row<S: Scalar>(
    c: &mut ContactConstraint<S>,
    velocities: &mut [Vec2<S>],
) {
    let vn = (velocities[c.b as usize] - velocities[c.a as usize]).dot(c.normal);
    let old_n = c.normal_impulse;
    let shortfall = c.target_velocity.sub(vn);
    if old_n == S::ZERO && !shortfall.is_positive() {
        return;
    }
    c.normal_impulse = old_n.add(shortfall.mul(c.effective_mass)).max(S::ZERO);
    let dn = c.normal_impulse.sub(old_n);
    if dn != S::ZERO {
        apply_row(c, dn, S::ZERO, velocities);
    }
}

/// Position correction of one row on the substep's displacements.
///
/// The current separation is `s = s0 + (Δb - Δa)·n` (exact for translation
/// with a fixed normal). Penetration beyond the slop is reduced by the
/// fraction `beta`, at most `max_correction` per pass; the correction moves
/// positions only, so it cannot add kinetic energy.
///
/// Never inlined, for the same reason as [`solve_velocity_row`].
#[inline(never)]
pub(crate) fn solve_position_row<S: Scalar>(
    c: &ContactConstraint<S>,
    displacements: &mut [Vec2<S>],
    slop: S,
    beta: S,
    max_correction: S,
) {
    let (ia, ib) = (c.a as usize, c.b as usize);
    let separation = c
        .separation
        .add((displacements[ib] - displacements[ia]).dot(c.normal));
    // Within the slop (or apart): β·C ≥ 0 clamps to zero below, so skip the
    // product (β > 0 and rounding toward −∞ keeps a non-negative product
    // non-negative). Same bits, one multiply less for most rows.
    if !separation.add(slop).is_negative() {
        return;
    }
    // C ≤ 0 is the penetration beyond the slop, scaled and bounded.
    let correction = beta
        .mul(separation.add(slop))
        .clamp(max_correction.neg(), S::ZERO);
    if correction == S::ZERO {
        return;
    }
    let impulse = correction.neg().mul(c.effective_mass);
    let push = c.normal.scale(impulse);
    if c.inverse_mass_a.is_positive() {
        displacements[ia] -= push.scale(c.inverse_mass_a);
    }
    if c.inverse_mass_b.is_positive() {
        displacements[ib] += push.scale(c.inverse_mass_b);
    }
}
