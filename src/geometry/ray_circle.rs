//! Ray against circle: [`ray_circle`] and [`ray_circle_roots`].
//!
//! # Maths
//!
//! A point of the ray is `p(t) = o + t·d` with `|d| = 1`. With
//! `m = o − c`, `|p(t) − c|² = r²` is
//!
//! ```text
//! t² + 2 b t + c' = 0,   b = m·d,   c' = m·m − r²
//! t = −b ± √(b² − c')
//! ```
//!
//! and `b² − c' = r² − (m × d)²` (Lagrange's identity with `|d| = 1`). The
//! implementation keeps `a = d·d` (a direction is unit only to within a few
//! ulps), solves from a point near the foot of the perpendicular from the
//! centre, and forms every square in the wide type, where `m·m` (up to 2³³
//! within the world bounds) is exact. The derivation and the error analysis
//! are next to the solver in `segment_cast/circle.rs`.
//!
//! The accuracy is stated on [`ray_circle`].

use super::Circle;
use super::ray::{Ray, RayHit, ray_hit_from_cast};
use super::segment_cast::{cast_circle, circle_roots};
use crate::math::Scalar;

/// Casts a ray against a solid circle: the first point within
/// `max_distance`, or `None`.
///
/// * Origin inside the circle or on it: a hit at distance 0 with
///   `point = origin` and `normal = -direction` (the solid convention, see
///   [`Ray`]).
/// * Origin outside, pointing away from the centre (or perpendicular to
///   it): `None`.
/// * Otherwise the nearer crossing, if the line crosses (a tangent line
///   touches at one point and counts as a hit) and it is within
///   `max_distance`. `normal` is the unit outward normal at the hit
///   (`(point − center) / r`).
///
/// A negative radius behaves as its absolute value.
///
/// # Accuracy (`Fx`, inputs within the world bounds)
///
/// * The hit point is within about 4 ulps (`1e-9`) of the circle, at any
///   distance and even for grazing rays (the quadratic is solved from a
///   point near the circle and refined by a Newton step on the exact
///   residual).
/// * The distance is as well conditioned as the geometry allows: a few ulps
///   for a head-on hit, growing like `r ulp / √(r² − h²)` as the ray's
///   distance `h` from the centre approaches `r` (a grazing ray).
///   Near-tangent rays may be hit in `Fx` and missed in `f64` or the other
///   way round; a miss passes at least `r − 3 ulps` from the centre.
///
/// ```
/// use clockwork2d::geometry::*;
/// use clockwork2d::prelude::*;
/// let circle = Circle::new(Vec2::new(fx(5.0), fx(0.0)), fx(1.0));
/// let ray = Ray::new(Vec2::ZERO, Vec2::new(fx(1.0), fx(0.0)), fx(10.0)).unwrap();
/// let hit = ray_circle(&ray, &circle).unwrap();
/// assert_eq!(hit.distance, fx(4.0));
/// assert_eq!(hit.normal, Vec2::new(fx(-1.0), fx(0.0)));
///
/// // Too short, or pointing away: no hit.
/// let short = Ray::new(Vec2::ZERO, Vec2::X, fx(3.5)).unwrap();
/// assert_eq!(ray_circle(&short, &circle), None);
/// let away = Ray::new(Vec2::ZERO, Vec2::new(fx(-1.0), fx(0.0)), fx(10.0)).unwrap();
/// assert_eq!(ray_circle(&away, &circle), None);
///
/// // Starting inside: distance 0, normal against the direction.
/// let inside = Ray::new(Vec2::new(fx(5.5), fx(0.0)), Vec2::Y, fx(10.0)).unwrap();
/// let hit = ray_circle(&inside, &circle).unwrap();
/// assert_eq!(hit.distance, fx(0.0));
/// assert_eq!(hit.normal, Vec2::new(fx(0.0), fx(-1.0)));
/// ```
#[must_use]
pub fn ray_circle<S: Scalar>(ray: &Ray<S>, circle: &Circle<S>) -> Option<RayHit<S>> {
    if ray.max_distance.is_negative() {
        return None;
    }
    let cast = cast_circle(
        ray.origin,
        ray.direction,
        ray.max_distance,
        circle.center,
        circle.radius,
    );
    ray_hit_from_cast(ray, cast)
}

/// Both distances `(t0, t1)`, `t0 ≤ t1`, at which the ray's **line** crosses
/// the circle, ignoring `max_distance` and the origin's side: negative
/// values are behind the origin, and an origin inside gives `t0 ≤ 0 ≤ t1`.
/// A tangent line gives `t0 == t1`. `None` when the line misses the circle
/// (or the ray's direction is zero).
///
/// Each root's point `origin + t·direction` is on the circle within the
/// accuracy stated on [`ray_circle`] (plus a few ulps for forming the
/// point), for far circles too.
///
/// ```
/// use clockwork2d::geometry::*;
/// use clockwork2d::prelude::*;
/// let circle = Circle::new(Vec2::new(fx(5.0), fx(0.0)), fx(1.0));
/// let ray = Ray::new(Vec2::ZERO, Vec2::X, fx(1.0)).unwrap();
/// assert_eq!(ray_circle_roots(&ray, &circle), Some((fx(4.0), fx(6.0))));
/// let up = Ray::new(Vec2::ZERO, Vec2::Y, fx(1.0)).unwrap();
/// assert_eq!(ray_circle_roots(&up, &circle), None);
/// ```
#[must_use]
pub fn ray_circle_roots<S: Scalar>(ray: &Ray<S>, circle: &Circle<S>) -> Option<(S, S)> {
    circle_roots(ray.origin, ray.direction, circle.center, circle.radius)
}
