//! PLACEHOLDER
use super::{Aabb, Ray, RayHit};
use crate::math::Scalar;
/// x
pub fn ray_aabb<S: Scalar>(_r: &Ray<S>, _c: &Aabb<S>) -> Option<RayHit<S>> { todo!() }
