//! [`Ray`] and [`RayHit`]: the input and output of the ray casts
//! ([`ray_circle`](super::ray_circle), [`ray_aabb`](super::ray_aabb)). The
//! conventions shared by every ray cast are documented on [`Ray`].

use serde::{Deserialize, Serialize};

use super::segment_cast::Cast;
use crate::math::Fx;
use crate::math::{Scalar, Vec2, WideScalar};

/// A ray: an origin, a unit direction and a maximum distance.
///
/// Build it with [`Ray::new`], which normalises the direction. The fields
/// are public for reading; a ray built by hand should keep `direction`
/// unit length (the casts measure distance in units of `|direction|`) and
/// `max_distance` non-negative (a negative one never hits anything).
///
/// # Conventions shared by every ray cast
///
/// * Shapes are **solid** and closed. A ray whose origin is inside a shape
///   or on its boundary hits it at distance 0: `point` is the origin and
///   `normal` is `-direction` (there is no surface crossing to take a normal
///   from; `-direction` is a unit vector that points back along the ray).
/// * A hit counts when its distance is at most `max_distance` (inclusive).
/// * A ray starting outside a shape and pointing away from it misses.
/// * Distances are measured in units of `|direction|`, which [`Ray::new`]
///   makes 1 within 1.21 ulps: a relative error of 2.8e-10 for `Fx`.
/// * Results are deterministic: the same inputs give the same bits on every
///   target (for the fixed-point scalars).
///
/// Documented range (`Fx`): coordinates within ±[`WORLD_LIMIT`] and
/// `max_distance ≤ 2¹⁷`, which keeps every hit point inside the scalar's
/// range; beyond it results saturate (defined and deterministic, not
/// accurate).
///
/// [`WORLD_LIMIT`]: crate::math::WORLD_LIMIT
///
/// ```
/// use clockwork2d::geometry::*;
/// use clockwork2d::math::*;
/// use clockwork2d::prelude::*;
/// let ray = Ray::new(Vec2::new(fx(0.0), fx(0.0)), Vec2::new(fx(3.0), fx(0.0)), fx(10.0)).unwrap();
/// assert_eq!(ray.direction, Vec2::new(fx(1.0), fx(0.0)));
/// assert_eq!(ray.point_at(fx(2.5)), Vec2::new(fx(2.5), fx(0.0)));
/// assert!(Ray::new(Vec2::<Fx>::ZERO, Vec2::ZERO, fx(1.0)).is_none());
/// assert!(Ray::new(Vec2::<Fx>::ZERO, Vec2::X, fx(-1.0)).is_none());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct Ray<S: Scalar = Fx> {
    /// Where the ray starts.
    pub origin: Vec2<S>,
    /// The direction, unit length.
    pub direction: Vec2<S>,
    /// The largest distance along `direction` at which a hit counts.
    pub max_distance: S,
}

impl<S: Scalar> Ray<S> {
    /// Creates a ray from a direction of any nonzero length.
    ///
    /// Returns `None` for a zero `direction` or a negative `max_distance`.
    ///
    /// Normalisation first divides the direction by its largest component
    /// magnitude (exact for that component, one rounding for the other),
    /// then by the length of the result, which is in `[1, √2]`; so tiny
    /// directions (even one ulp) are normalised as accurately as large
    /// ones. Every step rounds to nearest (decided exactly in the wide type
    /// for fixed point), and the result is symmetric under sign changes and
    /// swapping the axes (a diagonal input gives an exactly diagonal
    /// direction). Distances along the ray are measured in units of
    /// `|direction|`, so its length sets their relative accuracy: for `Fx`
    /// each component is off by at most half an ulp and the length by at
    /// most half an ulp in relative terms, so `| |direction|² − 1 | ≤
    /// (√2 + 1) ulp` and `| |direction| − 1 | ≤ 1.21 ulp` (2.8e-10: 4e-5 at
    /// 2¹⁷ units); the angle is within about 1.3 ulps of the input's.
    #[must_use]
    pub fn new(origin: Vec2<S>, direction: Vec2<S>, max_distance: S) -> Option<Self> {
        if max_distance.is_negative() {
            return None;
        }
        let scale = direction.x.abs().max(direction.y.abs());
        if !scale.is_positive() {
            return None;
        }
        // |component| ≤ scale, so both quotients are in [-1, 1], and the
        // larger one is exactly ±1.
        let w = Vec2::new(
            div_nearest(direction.x, scale),
            div_nearest(direction.y, scale),
        );
        let direction = unit_of_max_normed(w)?;
        Some(Ray {
            origin,
            direction,
            max_distance,
        })
    }

    /// The point at `distance` along the ray: `origin + distance·direction`
    /// (saturating).
    #[inline]
    #[must_use]
    pub fn point_at(&self, distance: S) -> Vec2<S> {
        self.origin + self.direction.scale(distance)
    }
}

/// `n / l` rounded to the nearest representable value (ties away from
/// zero), for `l > 0`; sign-symmetric. For fixed point the truncated
/// quotient's remainder is exact in the wide type and decides the rounding;
/// for the float references the quotient is already correctly rounded and
/// the remainder test never fires.
fn div_nearest<S: Scalar>(n: S, l: S) -> S {
    let m = n.abs();
    let q = m.div(l);
    let rem = S::Wide::from_narrow(m).sub(q.wide_mul(l));
    // rem ∈ [0, l·ulp): round up when it is at least half an ulp of l.
    let q = if rem.add(rem) >= l.wide_mul(S::EPSILON) {
        q.add(S::EPSILON)
    } else {
        q
    };
    if n.is_negative() { q.neg() } else { q }
}

/// `w / |w|` for `w` with its largest component magnitude exactly 1 (so
/// `|w| ∈ [1, √2]`), every rounding to nearest: the length (the floored
/// root is bumped by one ulp when `(2·len + ulp)² ≤ 4·w·w`, exact in the
/// wide type) and each quotient. Symmetric under sign changes and under
/// swapping the axes.
fn unit_of_max_normed<S: Scalar>(w: Vec2<S>) -> Option<Vec2<S>> {
    let ww = w.length_squared_wide();
    let floor = ww.sqrt_narrow();
    if !floor.is_positive() {
        return None;
    }
    let up = floor.add(S::EPSILON);
    let twice_mid = floor.add(up);
    let ww2 = ww.add(ww);
    let len = if twice_mid.wide_mul(twice_mid) <= ww2.add(ww2) {
        up
    } else {
        floor
    };
    Some(Vec2::new(div_nearest(w.x, len), div_nearest(w.y, len)))
}

/// Where a ray hits a shape.
///
/// ```
/// use clockwork2d::geometry::*;
/// use clockwork2d::math::*;
/// use clockwork2d::prelude::*;
/// let ray = Ray::new(Vec2::new(fx(-5.0), fx(0.0)), Vec2::X, fx(100.0)).unwrap();
/// let hit = ray_circle(&ray, &Circle::new(Vec2::ZERO, fx(1.0))).unwrap();
/// assert_eq!(hit.distance, fx(4.0));
/// assert_eq!(hit.point, Vec2::new(fx(-1.0), fx(0.0)));
/// assert_eq!(hit.normal, Vec2::new(fx(-1.0), fx(0.0)));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct RayHit<S: Scalar = Fx> {
    /// Distance from the ray's origin along its direction, in
    /// `[0, max_distance]`.
    pub distance: S,
    /// The point hit, on the shape's surface (or the ray's origin, for a ray
    /// that starts inside).
    pub point: Vec2<S>,
    /// The unit outward surface normal at `point` (`-direction` for a ray
    /// that starts inside).
    pub normal: Vec2<S>,
}

/// Turns a cast result into the public ray answer (the solid convention for
/// an origin inside).
pub(super) fn ray_hit_from_cast<S: Scalar>(ray: &Ray<S>, cast: Cast<S>) -> Option<RayHit<S>> {
    match cast {
        Cast::Inside => Some(RayHit {
            distance: S::ZERO,
            point: ray.origin,
            normal: -ray.direction,
        }),
        Cast::Hit { s, point, normal } => Some(RayHit {
            distance: s,
            point,
            normal,
        }),
        Cast::Miss => None,
    }
}
