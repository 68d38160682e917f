//! PLACEHOLDER
use super::{Aabb, Circle};
use crate::math::{Scalar, Vec2};
/// Outcome.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Toi<S: Scalar> {
    /// Hit at fraction t of the step with normal from a to b.
    Hit {
        /// Fraction of the step in [0, 1].
        t: S,
        /// Unit normal from a to b at the moment of contact.
        normal: Vec2<S>,
    },
    /// Already overlapping at t = 0.
    Overlapping,
    /// No contact within the step.
    Miss,
}
/// x
pub fn toi_circle_circle<S: Scalar>(_a: &Circle<S>, _da: Vec2<S>, _b: &Circle<S>, _db: Vec2<S>) -> Toi<S> { todo!() }
/// x
pub fn toi_aabb_aabb<S: Scalar>(_a: &Aabb<S>, _da: Vec2<S>, _b: &Aabb<S>, _db: Vec2<S>) -> Toi<S> { todo!() }
/// x
pub fn toi_circle_aabb<S: Scalar>(_a: &Circle<S>, _da: Vec2<S>, _b: &Aabb<S>, _db: Vec2<S>) -> Toi<S> { todo!() }
