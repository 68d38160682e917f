//! PLACEHOLDER
use super::{Aabb, Circle, Contact};
use crate::math::Scalar;
/// x
pub fn contact_circle_aabb<S: Scalar>(_a: &Circle<S>, _b: &Aabb<S>) -> Contact<S> { todo!() }
/// x
pub fn contact_aabb_circle<S: Scalar>(_a: &Aabb<S>, _b: &Circle<S>) -> Contact<S> { todo!() }
