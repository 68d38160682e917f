//! The spring impulse: a θ-method between trapezoidal and implicit Euler
//! (derivation here and in the module docs of [`crate::constraints`]).

use crate::math::Scalar;

/// The blend `θ ∈ [1/2, 1]` of the θ-method for a spring whose (ω·h)² is
/// `q = k·W·h²`: `θ = 1/2 + min(1/2, q²/32)`.
///
/// At `θ = 1/2` (trapezoidal) a resolved spring keeps its energy exactly;
/// the extra `ε = q²/32 = (ω·h)⁴/32` adds a numerical damping of about
/// `2ε(ω·h)²` per step — 6e-8 at ω·h = 0.1, i.e. 0.04 % of amplitude after
/// 100 periods — while at ω·h ≥ 2 the scheme is implicit Euler, which damps
/// a mode the time step cannot resolve within a few steps instead of letting
/// it ring at the Nyquist rate forever. For every θ ≥ 1/2 the method never
/// gains energy.
#[inline]
pub(crate) fn theta_for<S: Scalar>(k: S, w: S, h: S) -> S {
    let q = k.mul(w).mul(h).mul(h);
    let half = S::ONE.half();
    // q ≥ 2 already means ε ≥ 1/8; cap q before squaring so nothing saturates.
    let q = q.min(S::from_int(4));
    // q² ≥ 0, so dividing by 32 (truncation) equals five exact halvings
    // (each rounds toward −∞): the same bits without a division.
    let epsilon = q.mul(q).half().half().half().half().half().min(half);
    half.add(epsilon)
}

/// The impulse on `b` along the spring axis for stretch `x`, relative
/// velocity `v`, summed inverse mass `w`, stiffness `k`, damping `c`, time
/// step `h` and blend `θ` (see [`theta_for`]), from the θ-method
///
/// ```text
/// v' = v − h·W·(k·x_θ + c·v_θ),  x' = x + h·v_θ,
/// x_θ = x + θ·h·v_θ,  v_θ = (1−θ)·v + θ·v'
/// ⇒ λ = (v' − v)/W = −(g·v + h·k·x) / (1 + W·θ·g),   g = h·(k·θ·h + c).
/// ```
///
/// The divisor is at least 1 (all terms are non-negative), so the division
/// is always defined; every product saturates. The caller moves the body by
/// `h·v' − h·(1−θ)·Δv` so that the position follows `x' = x + h·v_θ`.
#[inline]
pub(crate) fn spring_impulse<S: Scalar>(x: S, v: S, w: S, k: S, c: S, h: S, theta: S) -> S {
    let g = h.mul(k.mul(theta).mul(h).add(c));
    let numerator = g.mul(v).add(k.mul(h).mul(x));
    let divisor = S::ONE.add(w.mul(theta).mul(g));
    numerator.div(divisor).neg()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An undamped unit-mass spring stepped with this impulse and the θ
    /// position rule never gains energy (k·x² + v²), even at ω·h = 10
    /// (checked in f64, the reference scalar).
    #[test]
    #[allow(clippy::float_arithmetic)]
    fn undamped_energy_is_conserved_at_omega_h_10() {
        let h = 1.0 / 60.0;
        let omega = 10.0 / h;
        let k = omega * omega;
        let (mut x, mut v) = (1.0f64, 0.0f64);
        let e0 = k * x * x + v * v;
        for _ in 0..10_000 {
            let theta = theta_for(k, 1.0, h);
            let lambda = spring_impulse(x, v, 1.0, k, 0.0, h, theta);
            let v_new = v + lambda;
            x += h * ((1.0 - theta) * v + theta * v_new);
            v = v_new;
            let e = k * x * x + v * v;
            assert!(e <= e0 * (1.0 + 1e-9), "energy grew: {e} > {e0}");
            assert!(x.abs() <= 1.0 + 1e-9);
        }
    }
}

#[cfg(test)]
mod theta_tests {
    use super::*;

    #[test]
    #[allow(clippy::float_arithmetic)]
    fn theta_is_trapezoidal_when_resolved_and_implicit_euler_when_not() {
        let h = 1.0 / 60.0;
        // ω·h = 0.1: q = 0.01, ε = 1e-4/32.
        let resolved = theta_for(36.0 * 1.0, 1.0, h);
        assert!((resolved - 0.5).abs() < 1e-5);
        // ω·h = 10: implicit Euler.
        let stiff = theta_for(360_000.0, 1.0, h);
        assert!((stiff - 1.0).abs() < 1e-12);
    }
}
