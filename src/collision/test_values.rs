//! Inputs of the collision unit tests, written as `f64` literals and
//! converted once (test code only: the simulation path has no float).

use crate::math::{Fx, Scalar, Vec2};

/// `(x, y)` as a fixed-point vector.
pub(super) fn v(x: f64, y: f64) -> Vec2<Fx> {
    Vec2::new(Fx::from_f64(x), Fx::from_f64(y))
}

/// The default linear slop, 1e-4 units.
pub(super) fn slop() -> Fx {
    Fx::from_f64(1e-4)
}
