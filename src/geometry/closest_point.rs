//! PLACEHOLDER (being written)
use crate::math::{Scalar, Vec2};
/// Closest point result.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SegmentPoint<S: Scalar> {
    /// Point.
    pub point: Vec2<S>,
    /// Parameter.
    pub t: S,
}
/// Closest point.
pub fn closest_point_on_segment<S: Scalar>(_a: Vec2<S>, _b: Vec2<S>, _p: Vec2<S>) -> SegmentPoint<S> {
    todo!()
}
