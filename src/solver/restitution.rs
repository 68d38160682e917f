//! Restitution at the instant of contact, applied after the position
//! update.
//!
//! # The method
//!
//! The velocity solve treats a closing contact as purely speculative
//! (`v_n ≥ −s/h`): the pair closes its gap exactly by the end of the
//! substep and no more. A contact that met this substep fast enough to
//! bounce is then *re-timed* here, after the positions are integrated:
//!
//! 1. **When it met.** Within a substep every body follows the
//!    integrator's own free-flight path. Semi-implicit Euler
//!    (`v' = v + a·h`, `x' = x + v'·h`) puts successive positions exactly on
//!    a parabola of acceleration `a` whose velocity at the substep's start
//!    is `v' − a·h/2` (the chord velocity `v'` is the parabola's at
//!    mid-substep). Along the normal the gap is then
//!    `s(τ) = s₀ + u₀ τ + a_n τ²/2` with `u₀ = v_n − a_n·h/2`, `v_n` the
//!    relative normal velocity the solver started from and `a_n` the
//!    relative normal acceleration of gravity (zero between two bodies of
//!    the same gravity scale: the motion is then linear). Energy along the
//!    parabola gives the closing speed at contact exactly,
//!    `u_c = −√(u₀² − 2 a_n s₀)`, and the mean-velocity rule gives the
//!    instant, `τ = 2 s₀ / −(u₀ + u_c)` (exact for constant acceleration,
//!    and never a division by `a_n`).
//! 2. **The bounce.** At `τ` the normal velocity becomes `w = −e·u_c`
//!    (Newton's law with the speed *at the surface*), and the pair flies
//!    apart on the reflected parabola for the rest of the substep,
//!    `r = h − τ`: the end gap is `w·r + a_n r²/2` (never negative) and the
//!    end velocity, the parabola's at mid-substep, `w + a_n (h/2 − τ)`.
//! 3. **Applying it.** The difference between that end state and what the
//!    solver and the position pass left (relative normal velocity and
//!    gap) is applied along the normal as one impulse and one displacement,
//!    split by inverse mass (so momentum is conserved and a fixed body
//!    does not move). Only pushes are applied (a pair already separating
//!    faster is left alone). When several rows stopped one impact together
//!    (simultaneous contacts), each row's launch is scaled by the share of
//!    the approach it stopped, so sequential bounces never return more
//!    than the impacts took.
//!
//! The motion added in step 3 is then swept against the world like any
//! other motion (`World::sweep_rebounds`): a rebound cannot pass through
//! what lies behind the body.
//!
//! # Error bound
//!
//! For a body bouncing off a fixed body under gravity alone (the analysed
//! case) the bounce is exact in the integrator's own model: the samples
//! before and after lie on the two true parabolas, which meet at the
//! surface, and the launch speed is `e` times the speed at the surface;
//! what remains is fixed-point rounding (a few ulps in `τ`, `u_c` — the
//! square root is exact to an ulp) and the solver's residual in the
//! speculative gap, which is below the linear slop. With `e = 1` the
//! flight's energy is kept to rounding (tests: apex drift under 0.01 % in
//! a minute). When other forces act during the substep (springs, other
//! contacts), `a_n` ignores them and the instant is off by their share of
//! the substep's velocity change: first order in `h`, as for the rest of
//! the integrator. Between two dynamic bodies of equal gravity scale the
//! motion is linear and the method is exact. Several simultaneous contacts
//! on one body are re-timed one after the other (sequentially, like the
//! solver's rows); each is exact on its own.

use super::row::ContactConstraint;
use crate::math::{Scalar, Vec2, WideScalar};

/// A contact row that met this substep faster than the restitution
/// threshold: what the bounce needs besides the row.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct BounceCandidate<S: Scalar> {
    /// Index of the row in the substep's contact rows.
    pub(crate) row: u32,
    /// Relative normal velocity the solver started from (`v_n`, < 0).
    pub(crate) approach: S,
    /// Relative normal acceleration of gravity, `(a_b − a_a)·n`.
    pub(crate) accel_n: S,
    /// Combined restitution, > 0.
    pub(crate) restitution: S,
}

/// A body a bounce moved: the start of its rebound motion, for the rebound
/// sweep (`World::sweep_rebounds`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Rebound<S: Scalar> {
    /// The body's slot.
    pub(crate) slot: u32,
    /// Its displacement before the bounce moved it (the rebound starts
    /// there).
    pub(crate) start: Vec2<S>,
    /// The instant of the bounce within the substep (`τ`, in `[0, h]`):
    /// the rebound motion covers `h − τ`.
    pub(crate) time: S,
}

/// The normal velocity and gap a bounce leaves at the end of the substep.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct BounceEnd<S: Scalar> {
    /// Relative normal velocity at the end (`w + a_n (h/2 − τ)`).
    pub(crate) velocity: S,
    /// Gap at the end (`w·r + a_n r²/2`, at least zero).
    pub(crate) gap: S,
    /// The launch speed `w = e·|u_c|`.
    pub(crate) launch: S,
    /// The instant of contact `τ` within the substep.
    pub(crate) time: S,
}

/// Steps 1 and 2 of the module notes for a gap `s0` (negative values count
/// as touching), start velocity `approach` (`v_n`), acceleration `accel_n`
/// and restitution `e`, over a substep `h`. `None` when the pair would not
/// meet within the substep on its parabola (the linear prediction that
/// made it a candidate was off by the curvature).
pub(crate) fn bounce_end<S: Scalar>(
    s0: S,
    approach: S,
    accel_n: S,
    e: S,
    h: S,
) -> Option<BounceEnd<S>> {
    let s0 = s0.max(S::ZERO);
    // u₀ = v_n − a_n h/2: the relative normal velocity at the substep's start.
    let u0 = approach.sub(accel_n.mul(h).half());
    // u_c² = u₀² − 2 a_n s₀ (wide: exact products).
    let disc = u0.wide_mul(u0).sub(accel_n.mul_int(2).wide_mul(s0));
    if disc.is_negative() {
        return None;
    }
    let closing = disc.sqrt_narrow(); // −u_c ≥ 0
    let tau = if s0.is_positive() {
        // τ = 2 s₀ / (−u₀ − u_c) = 2 s₀ / (closing − u₀). The denominator is
        // positive whenever the pair meets: closing ≥ |u₀| when a_n ≤ 0;
        // when a_n > 0 meeting needs u₀ < 0. Refuse a τ beyond h without
        // dividing (2 s₀ > h·den ⇒ τ > h), which also covers den ≤ 0.
        let den = closing.sub(u0);
        let twice = s0.mul_int(2);
        if !den.is_positive() || S::Wide::from_narrow(twice) > h.wide_mul(den) {
            return None;
        }
        twice.div(den)
    } else {
        S::ZERO
    };
    // Launch speed w = e·|u_c|; the rest of the substep on the reflected
    // parabola.
    let launch = e.mul(closing);
    let rest = h.sub(tau);
    let gap = launch
        .mul(rest)
        .add(accel_n.mul(rest).mul(rest).half())
        .max(S::ZERO);
    let velocity = launch.add(accel_n.mul(h.half().sub(tau)));
    Some(BounceEnd {
        velocity,
        gap,
        launch,
        time: tau,
    })
}

/// Applies the bounces of this substep (step 3 of the module notes) to the
/// velocities and displacements, and reports every slot whose
/// displacement grew (`rebounds`: the slot and the displacement it had
/// before), for the rebound sweep.
pub(crate) fn apply_bounces<S: Scalar>(
    rows: &[ContactConstraint<S>],
    candidates: &[BounceCandidate<S>],
    h: S,
    velocities: &mut [Vec2<S>],
    displacements: &mut [Vec2<S>],
    rebounds: &mut Vec<Rebound<S>>,
) {
    for candidate in candidates {
        let Some(c) = rows.get(candidate.row as usize) else {
            continue;
        };
        // The row did nothing (the pair was already slowing or separating
        // without it): no contact happened, no bounce.
        if !c.normal_impulse.is_positive() {
            continue;
        }
        let Some(end) = bounce_end(
            c.separation,
            candidate.approach,
            candidate.accel_n,
            candidate.restitution,
            h,
        ) else {
            continue;
        };
        let (ia, ib) = (c.a as usize, c.b as usize);
        let vn_now = (velocities[ib] - velocities[ia]).dot(c.normal);
        // The share of the approach this row stopped: its impulse changed
        // the relative normal velocity by λ·(w_a + w_b), and what is still
        // closing, max(0, −v_n), it would stop too. Alone on the pair that
        // is all of the approach |v_n0| (share 1); when other rows took part
        // of the impact (several simultaneous contacts on a body) the
        // launch is scaled by the share, so the sequential bounces cannot
        // hand back more than each row took (no energy gain).
        let approach = candidate.approach.neg();
        let stopped = c
            .normal_impulse
            .mul(c.inverse_mass_a.add(c.inverse_mass_b))
            .add(vn_now.neg().max(S::ZERO));
        let end_velocity = if stopped >= approach {
            end.velocity
        } else {
            // approach > stopped ≥ 0, so the share is in [0, 1).
            let share = stopped.div(approach);
            end.velocity.sub(end.launch.mul(S::ONE.sub(share)))
        };
        let dv = end_velocity.sub(vn_now);
        if !dv.is_positive() {
            continue;
        }
        let gap_now = c
            .separation
            .add((displacements[ib] - displacements[ia]).dot(c.normal));
        let ds = end.gap.sub(gap_now).max(S::ZERO);
        // Impulse and displacement "impulse": P = Δ·m, body change w·n·P.
        let impulse = dv.mul(c.effective_mass);
        let shift = ds.mul(c.effective_mass);
        if c.inverse_mass_a.is_positive() {
            if shift != S::ZERO {
                rebounds.push(Rebound {
                    slot: c.a,
                    start: displacements[ia],
                    time: end.time,
                });
            }
            velocities[ia] -= c.push_a.scale(impulse);
            displacements[ia] -= c.push_a.scale(shift);
        }
        if c.inverse_mass_b.is_positive() {
            if shift != S::ZERO {
                rebounds.push(Rebound {
                    slot: c.b,
                    start: displacements[ib],
                    time: end.time,
                });
            }
            velocities[ib] += c.push_b.scale(impulse);
            displacements[ib] += c.push_b.scale(shift);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::math::Fx;

    fn f(x: f64) -> Fx {
        Fx::from_f64(x)
    }

    /// A ball falling under g = 10 onto the ground: the end state is the
    /// one of the two exact parabolas meeting at the surface.
    #[test]
    fn bounce_under_gravity_matches_the_parabolas() {
        let h = 1.0 / 60.0;
        for (s0, v1, e) in [(0.05, -6.0, 1.0), (0.001, -3.0, 0.5), (0.09, -10.0, 0.8)] {
            let end = bounce_end(f(s0), f(v1), f(-10.0), f(e), f(h)).unwrap();
            // Reference in f64.
            let u0: f64 = v1 + 10.0 * h / 2.0;
            let uc = -(u0 * u0 + 2.0 * 10.0 * s0).sqrt();
            let tau = 2.0 * s0 / -(u0 + uc);
            // The incoming parabola is at the surface at τ.
            assert!((s0 + u0 * tau - 5.0 * tau * tau).abs() < 1e-9);
            let w = -e * uc;
            let r = h - tau;
            let gap = w * r - 5.0 * r * r;
            let vel = w - 10.0 * (h / 2.0 - tau);
            assert!((end.gap.to_f64() - gap).abs() < 1e-7, "{end:?} vs {gap}");
            assert!(
                (end.velocity.to_f64() - vel).abs() < 1e-7,
                "{end:?} vs {vel}"
            );
        }
    }

    /// Without relative acceleration the motion is linear: τ = s₀/|v|,
    /// end gap e·|v|·(h − τ).
    #[test]
    fn bounce_without_gravity_is_linear() {
        let end = bounce_end(f(0.25), f(-30.0), Fx::ZERO, f(1.0), f(0.05)).unwrap();
        assert!((end.velocity.to_f64() - 30.0).abs() < 1e-7);
        assert!((end.gap.to_f64() - 30.0 * (0.05 - 0.25 / 30.0)).abs() < 1e-7);
    }

    /// A pair decelerating towards each other that stops short does not
    /// bounce.
    #[test]
    fn no_bounce_when_the_parabola_stops_short() {
        // u₀ = −1.5, u₀² − 2·50·0.1 < 0.
        assert_eq!(bounce_end(f(0.1), f(-1.0), f(50.0), f(1.0), f(0.02)), None);
    }
}
