//! The spring blend: where the θ-method sits between trapezoidal and
//! implicit Euler for one spring (derivation here and in the module docs of
//! [`crate::constraints`]).

use crate::math::Scalar;

/// The blend `θ ∈ [1/2, 1]` of the θ-method for a spring whose (ω·h)² is
/// `q = k·W·h²`: `θ = 1/2 + min(1/2, q⁴/512)`, i.e. `ε = θ − 1/2 = (ω·h)⁸/512`.
///
/// At `θ = 1/2` (trapezoidal) the springs keep their energy exactly; the
/// extra `ε` damps a mode of frequency Ω by `2ε·(Ω·h)²` of its energy per
/// step. The blend is chosen so that a resolved lattice keeps its energy
/// over a minute: at ω·h = 0.3 (q = 0.09), ε = 1.3e-7, and a square
/// lattice's highest mode has (Ω·h)² ≤ 4q = 0.36 (four springs per body, a
/// Gershgorin bound), so the loss over 3600 steps is at most
/// 3600 · 2 · 1.3e-7 · 0.36 = 3.3e-4 of the energy (the bound is
/// 1 %). At ω·h ≥ 2 (q ≥ 4) the scheme is implicit Euler, which damps a
/// mode the time step cannot resolve within a few steps instead of letting
/// it ring at the Nyquist rate; between, ε grows steeply (ω·h = 1: 0.002;
/// 1.5: 0.05). For every θ ≥ 1/2 the method never gains energy.
#[inline]
pub(crate) fn theta_for<S: Scalar>(k: S, w: S, h: S) -> S {
    let q = k.mul(w).mul(h).mul(h);
    let half = S::ONE.half();
    // q ≥ 4 already means ε ≥ 1/2; cap q before raising it so nothing
    // saturates (4⁴ = 256).
    let q = q.min(S::from_int(4));
    let q2 = q.mul(q);
    // q⁴ ≥ 0, so dividing by 512 (truncation) equals nine exact halvings
    // (each rounds toward −∞): the same bits without a division.
    let mut epsilon = q2.mul(q2);
    for _ in 0..9 {
        epsilon = epsilon.half();
    }
    half.add(epsilon.min(half))
}

#[cfg(test)]
mod theta_tests {
    use super::*;

    #[test]
    #[allow(clippy::float_arithmetic)]
    fn theta_is_trapezoidal_when_resolved_and_implicit_euler_when_not() {
        let h = 1.0 / 60.0;
        // ω·h = 0.3: q = 0.09, ε = 0.09⁴/512 = 1.28e-7.
        let resolved = theta_for(324.0, 1.0, h);
        assert!((resolved - 0.5 - 0.09f64.powi(4) / 512.0).abs() < 1e-12);
        // ω·h = 2 and 10: implicit Euler.
        assert!((theta_for(14_400.0, 1.0, h) - 1.0).abs() < 1e-12);
        assert!((theta_for(360_000.0, 1.0, h) - 1.0).abs() < 1e-12);
        // Monotone in the stiffness.
        let mut last = 0.5;
        for k in [1.0, 100.0, 1000.0, 3600.0, 8100.0, 14_000.0] {
            let t = theta_for(k, 1.0, h);
            assert!(t >= last, "θ({k}) = {t} < {last}");
            last = t;
        }
    }
}
