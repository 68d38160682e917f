//! PLACEHOLDER
use crate::math::{Scalar, Vec2};
/// A ray.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray<S: Scalar> {
    /// Origin.
    pub origin: Vec2<S>,
    /// Unit direction.
    pub direction: Vec2<S>,
    /// Max distance.
    pub max_distance: S,
}
impl<S: Scalar> Ray<S> {
    /// New; None for zero direction or negative max distance.
    pub fn new(origin: Vec2<S>, direction: Vec2<S>, max_distance: S) -> Option<Self> {
        let direction = direction.try_normalize()?;
        if max_distance.is_negative() { return None; }
        Some(Ray { origin, direction, max_distance })
    }
}
/// A hit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RayHit<S: Scalar> {
    /// Distance.
    pub distance: S,
    /// Point.
    pub point: Vec2<S>,
    /// Normal.
    pub normal: Vec2<S>,
}
