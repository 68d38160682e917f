//! PLACEHOLDER
use super::{Circle, Contact};
use crate::math::Scalar;
/// x
pub fn contact_circle_circle<S: Scalar>(_a: &Circle<S>, _b: &Circle<S>) -> Contact<S> { todo!() }
