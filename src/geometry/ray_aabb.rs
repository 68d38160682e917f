//! Ray against axis-aligned box: [`ray_aabb`].
//!
//! # Maths: the slab test, exact and division-free
//!
//! The box is the intersection of two slabs, `lo.x ≤ x ≤ hi.x` and
//! `lo.y ≤ y ≤ hi.y`. Along the ray `p(t) = o + t·d` the x slab holds for
//! `t ∈ [(near.x − o.x)/d.x, (far.x − o.x)/d.x]` (near/far chosen by the
//! sign of `d.x`), likewise y; the ray is in the box on the intersection of
//! the two intervals, and enters it at the larger of the two entry values.
//!
//! * A zero component (ray parallel to an axis) is never divided by: if the
//!   origin is within that slab (boundary included) the axis imposes no
//!   limit, otherwise the ray misses.
//! * The entry values are fractions `n / |d_i|`. Instead of dividing, they
//!   are compared by cross-multiplying in the wide type, where the
//!   products are exact (`Fx`, `I48F16`), and so are the tests "entry before
//!   the other exit" and "entry ≤ max_distance". Every decision is exact.
//! * The reported distance is then the single quotient `n / |d_k|`, taken
//!   only after the reach test proved it at most `max_distance`. So a tiny
//!   component (say one ulp) can never make the fixed-point division
//!   saturate into a wrong answer: a quotient that would have saturated
//!   belongs to a hit beyond `max_distance`, which was already rejected.
//!   The distance is truncated by less than one ulp.
//!
//! # Accuracy (`Fx`)
//!
//! The hit point is exactly on the entered face (its coordinate on the
//! entry axis is the face's; the other coordinate is rounded once and
//! clamped to the face). The distance is within one ulp of the exact
//! quotient for the given (rounded-to-unit) direction.

use super::Aabb;
use super::ray::{Ray, RayHit, ray_hit_from_cast};
use super::segment_cast::cast_box;
use crate::math::Scalar;

/// Casts a ray against a solid axis-aligned box: the first point within
/// `max_distance`, or `None`.
///
/// * Origin inside the box or on its boundary: a hit at distance 0 with
///   `point = origin` and `normal = -direction` (the solid convention, see
///   [`Ray`]).
/// * Otherwise the entry point, with `normal` the outward normal of the face
///   entered (`±X` or `±Y`). A ray entering **exactly through a corner**
///   (both entry distances equal) reports the **y** face, the geometry
///   module's tie rule.
/// * A ray running along a face line (e.g. at `y = hi.y`, direction `+X`)
///   touches the box: the closed box is hit at the first edge point, through
///   the x face.
///
/// A negative half extent behaves as its absolute value.
///
/// # Exactness
///
/// Every decision (hit or miss, which face, within `max_distance` or not)
/// is exact: the slab test compares its fractions by cross-multiplying in
/// the wide type and divides only once, for the reported distance, after
/// proving it at most `max_distance` (so a tiny direction component can
/// never make a saturated quotient look like a hit). A zero direction
/// component is never divided by. The distance is the exact quotient
/// truncated to an ulp, and the point lies exactly on the entered face.
///
/// ```
/// use clockwork2d::geometry::*;
/// use clockwork2d::prelude::*;
/// let b = Aabb::new(Vec2::new(fx(5.0), fx(0.0)), Vec2::new(fx(1.0), fx(2.0)));
/// let ray = Ray::new(Vec2::ZERO, Vec2::X, fx(10.0)).unwrap();
/// let hit = ray_aabb(&ray, &b).unwrap();
/// assert_eq!(hit.distance, fx(4.0));
/// assert_eq!(hit.point, Vec2::new(fx(4.0), fx(0.0)));
/// assert_eq!(hit.normal, Vec2::new(fx(-1.0), fx(0.0)));
///
/// // Exactly through the corner (4, -2): the y face is reported.
/// let diagonal = Ray::new(Vec2::new(fx(2.0), fx(-4.0)), Vec2::new(fx(1.0), fx(1.0)), fx(10.0)).unwrap();
/// assert_eq!(ray_aabb(&diagonal, &b).unwrap().normal, Vec2::new(fx(0.0), fx(-1.0)));
///
/// // Parallel to x, outside the y slab: a miss, with no division by zero.
/// let above = Ray::new(Vec2::new(fx(0.0), fx(3.0)), Vec2::X, fx(10.0)).unwrap();
/// assert_eq!(ray_aabb(&above, &b), None);
/// ```
#[must_use]
pub fn ray_aabb<S: Scalar>(ray: &Ray<S>, aabb: &Aabb<S>) -> Option<RayHit<S>> {
    if ray.max_distance.is_negative() {
        return None;
    }
    let cast = cast_box(
        ray.origin,
        ray.direction,
        ray.max_distance,
        aabb.center,
        aabb.half_extents,
    );
    ray_hit_from_cast(ray, cast)
}
