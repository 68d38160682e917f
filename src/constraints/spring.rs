//! The trapezoidal spring impulse (derivation in the module docs of
//! [`crate::constraints`]).

use crate::math::Scalar;

/// The impulse on `b` along the spring axis for stretch `x`, relative
/// velocity `v`, summed inverse mass `w`, stiffness `k`, damping `c` and
/// time step `h`: `λ = -(2·g·v + h·k·x) / (1 + w·g)`, `g = h·(k·h/4 + c/2)`.
///
/// The divisor is at least 1 (all terms are non-negative), so the division
/// is always defined; every product saturates.
#[inline]
pub(crate) fn trapezoidal_impulse<S: Scalar>(x: S, v: S, w: S, k: S, c: S, h: S) -> S {
    let kh = k.mul(h);
    let g = h.mul(kh.half().half().add(c.half()));
    let numerator = g.mul_int(2).mul(v).add(kh.mul(x));
    let divisor = S::ONE.add(w.mul(g));
    numerator.div(divisor).neg()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An undamped unit-mass spring stepped with this impulse and the
    /// half-step position rule conserves k·x² + v² to rounding, even at
    /// ω·h = 10 (checked in f64, the reference scalar).
    #[test]
    #[allow(clippy::float_arithmetic)]
    fn undamped_energy_is_conserved_at_omega_h_10() {
        let h = 1.0 / 60.0;
        let omega = 10.0 / h;
        let k = omega * omega;
        let (mut x, mut v) = (1.0f64, 0.0f64);
        let e0 = k * x * x + v * v;
        for _ in 0..10_000 {
            let lambda = trapezoidal_impulse(x, v, 1.0, k, 0.0, h);
            let v_new = v + lambda;
            x += h * (v + v_new) / 2.0;
            v = v_new;
            let e = k * x * x + v * v;
            assert!(e <= e0 * (1.0 + 1e-9), "energy grew: {e} > {e0}");
            assert!(x.abs() <= 1.0 + 1e-9);
        }
    }
}
