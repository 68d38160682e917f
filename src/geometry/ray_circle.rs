//! PLACEHOLDER
use super::{Circle, Ray, RayHit};
use crate::math::Scalar;
/// x
pub fn ray_circle<S: Scalar>(_r: &Ray<S>, _c: &Circle<S>) -> Option<RayHit<S>> { todo!() }
/// x
pub fn ray_circle_roots<S: Scalar>(_r: &Ray<S>, _c: &Circle<S>) -> Option<(S, S)> { todo!() }
