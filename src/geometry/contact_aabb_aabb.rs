//! PLACEHOLDER
use super::{Aabb, Contact};
use crate::math::Scalar;
/// x
pub fn contact_aabb_aabb<S: Scalar>(_a: &Aabb<S>, _b: &Aabb<S>) -> Contact<S> { todo!() }
