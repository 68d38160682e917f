//! A bullet's later impacts within one substep, reflected on its own
//! free-flight parabola with the energy that parabola holds.
//!
//! The first bounce of a substep is re-timed exactly
//! ([`crate::solver::restitution`]). The rebound sweep then follows the
//! rest of the motion along straight legs and reflects the body off what
//! it meets (`World::sweep_rebounds`). Under a constant acceleration `a`
//! (gravity) those legs are chords of parabolas, and the instant of an
//! impact along a chord is only known to `|a|·h²/(8·|u_n|)`: reflecting the
//! velocity the body has at a guessed instant hands back more (or less)
//! energy than the impact took, and a few impacts per step under gravity
//! pumped an elastic bullet by +0.2 % a minute.
//!
//! The reflection here is taken from the energy instead of the instant.
//! Along the integrator's parabola (velocity `u(τ) = v + a·(τ − h/2)` for
//! the stored mid-substep velocity `v`, see `restitution`) the
//! instantaneous energy per unit mass `E = ½|u|² − a·x` is constant. So:
//!
//! 1. `E` is read off the leg's predicted end (`x_end`, `u(h) = v + a·h/2`).
//! 2. At the impact point `p`, the component of `u` across `a` is the
//!    stored one (nothing accelerates it) and the component along `a` has
//!    the size `√(2(E + a·p) − u_⊥²)`; its sign is the chord's guess
//!    `v_a + |a|·(τ − h/2)` (it only matters where `u_a` is near zero,
//!    where it changes nothing).
//! 3. The normal part of that `u` is reflected with the restitution:
//!    `u' = u − (1+e)(u·n)·n`, and the energy after the impact is
//!    `E' = ½|u'|² − a·p` (`E' = E` for e = 1, less for e < 1).
//! 4. The velocity at the new predicted end `x'_end` follows from `E'`
//!    likewise (`u_⊥` of `u'`, `u_a` from the energy, sign from the
//!    chord), and `v' = u'(h) − a·h/2`.
//!
//! So the substep's shadow energy after any number of impacts is the one
//! before them, up to rounding (e = 1), or less (e < 1): the error of the
//! chord now only moves *where* the body is, never how much energy it has.
//! An end point higher than the energy can reach leaves `u_a = 0` there
//! (energy lost, never gained). Without acceleration this is the plain
//! reflection `v' = v − (1+e)(v·n)·n`, computed as such (bit-identical).

use crate::math::{Scalar, Vec2};

/// The body's motion for [`reflect_in_flight`]: its constant acceleration
/// and the substep.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Flight<S: Scalar> {
    /// The acceleration (gravity × gravity scale).
    pub(crate) accel: Vec2<S>,
    /// The substep `h`.
    pub(crate) h: S,
}

/// One impact of the reflection chain (module notes).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Impact<S: Scalar> {
    /// The leg's predicted end before the impact.
    pub(crate) end: Vec2<S>,
    /// Where the impact happens.
    pub(crate) point: Vec2<S>,
    /// The predicted end after it (the reflected rest of the leg).
    pub(crate) new_end: Vec2<S>,
    /// Unit normal from the body into the wall (at rest).
    pub(crate) normal: Vec2<S>,
    /// `1 + e`.
    pub(crate) e1: S,
    /// The chord's guess of the impact's instant within the substep.
    pub(crate) time: S,
}

/// The mid-substep velocity after the impact, from the one before
/// (`velocity`); unchanged if the body is not moving into the wall.
pub(crate) fn reflect_in_flight<S: Scalar>(
    velocity: Vec2<S>,
    flight: Flight<S>,
    impact: Impact<S>,
) -> Vec2<S> {
    let Flight { accel, h } = flight;
    let n = impact.normal;
    let Some((along, g)) = accel.try_normalize_with_length() else {
        // The wall's relative approach v_n = (0 − v)·n < 0 becomes −e·v_n.
        let vn = (Vec2::ZERO - velocity).dot(n);
        return if vn.is_negative() {
            velocity + n.scale(impact.e1.mul(vn))
        } else {
            velocity
        };
    };
    let across = along.perp();
    // Twice the energy per unit mass, from the leg's predicted end.
    let u_end = velocity + accel.scale(h.half());
    let twice_energy = u_end.dot(u_end).sub(accel.dot(impact.end).mul_int(2));
    // The velocity at the impact: across from the stored one, along from
    // the energy with the chord's sign.
    let u_across = velocity.dot(across);
    let guess = velocity.dot(along).add(g.mul(impact.time.sub(h.half())));
    let u = from_energy(
        twice_energy,
        accel,
        impact.point,
        u_across,
        guess,
        along,
        across,
    );
    let un = u.dot(n);
    if !un.is_positive() {
        return velocity;
    }
    let reflected = u - n.scale(impact.e1.mul(un));
    let twice_after = reflected
        .dot(reflected)
        .sub(accel.dot(impact.point).mul_int(2));
    let guess_end = reflected.dot(along).add(g.mul(h.sub(impact.time)));
    let u_new_end = from_energy(
        twice_after,
        accel,
        impact.new_end,
        reflected.dot(across),
        guess_end,
        along,
        across,
    );
    u_new_end - accel.scale(h.half())
}

/// The velocity at `point` of a flight holding `twice_energy` (`|u|² −
/// 2a·x`), with `u_across` across the acceleration and the sign of `guess`
/// along it (zero along it when the energy does not reach `point`).
fn from_energy<S: Scalar>(
    twice_energy: S,
    accel: Vec2<S>,
    point: Vec2<S>,
    u_across: S,
    guess: S,
    along: Vec2<S>,
    across: Vec2<S>,
) -> Vec2<S> {
    let square = twice_energy
        .add(accel.dot(point).mul_int(2))
        .sub(u_across.mul(u_across))
        .max(S::ZERO);
    let size = square.sqrt();
    let u_along = if guess.is_negative() {
        size.neg()
    } else {
        size
    };
    along.scale(u_along) + across.scale(u_across)
}

#[cfg(test)]
#[allow(clippy::float_arithmetic)] // test inputs and references in f64
mod tests {
    use super::*;
    use crate::math::Fx;

    fn v(x: f64, y: f64) -> Vec2<Fx> {
        Vec2::new(Fx::from_f64(x), Fx::from_f64(y))
    }

    /// Twice the instantaneous energy at the end of the substep, in f64.
    fn twice_energy(velocity: Vec2<Fx>, end: Vec2<Fx>, g: f64, h: f64) -> f64 {
        let (vx, vy) = velocity.to_f64();
        let uy = vy - g * h / 2.0;
        vx * vx + uy * uy + 2.0 * g * end.to_f64().1
    }

    /// e = 1 off a floor under gravity: the energy at the new end is the
    /// one at the old end, whatever the guessed instant.
    #[test]
    fn elastic_floor_impact_keeps_the_energy() {
        let h = 1.0 / 60.0;
        let flight = Flight {
            accel: v(0.0, -10.0),
            h: Fx::from_f64(h),
        };
        for time in [0.0, 0.3 * h, h] {
            let velocity = v(300.0, -400.0);
            let end = v(1.0, -0.5);
            let point = v(0.8, 0.0);
            let new_end = v(1.0, 0.5);
            let after = reflect_in_flight(
                velocity,
                flight,
                Impact {
                    end,
                    point,
                    new_end,
                    normal: v(0.0, -1.0),
                    e1: Fx::from_f64(2.0),
                    time: Fx::from_f64(time),
                },
            );
            let before = twice_energy(velocity, end, 10.0, h);
            let now = twice_energy(after, new_end, 10.0, h);
            assert!((now - before).abs() < 1e-4, "{before} -> {now}");
            assert!(after.to_f64().1 > 0.0, "{after:?}");
            assert_eq!(after.x, velocity.x);
        }
    }

    /// Without gravity it is the plain reflection.
    #[test]
    fn without_gravity_the_plain_reflection() {
        let flight = Flight {
            accel: Vec2::ZERO,
            h: Fx::from_f64(0.01),
        };
        let after = reflect_in_flight(
            v(3.0, -4.0),
            flight,
            Impact {
                end: v(0.0, 0.0),
                point: v(0.0, 0.0),
                new_end: v(0.0, 0.0),
                normal: v(0.0, -1.0),
                e1: Fx::from_f64(1.5),
                time: Fx::ZERO,
            },
        );
        assert_eq!(after, v(3.0, 2.0));
    }
}
