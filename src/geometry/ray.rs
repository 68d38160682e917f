//! [`Ray`] and [`RayHit`]: the input and output of the ray casts
//! ([`ray_circle`](super::ray_circle), [`ray_aabb`](super::ray_aabb)).
//!
//! # Conventions shared by every ray cast
//!
//! * Shapes are **solid** and closed. A ray whose origin is inside a shape
//!   or on its boundary hits it at distance 0: `point` is the origin and
//!   `normal` is `-direction` (there is no surface crossing to take a normal
//!   from; `-direction` is a unit vector that points back along the ray).
//! * A hit counts when its distance is at most `max_distance` (inclusive).
//! * A ray starting outside a shape and pointing away from it misses.
//! * Results are deterministic: the same inputs give the same bits on every
//!   target (for the fixed-point scalars).

use serde::{Deserialize, Serialize};

use super::sweep::Cast;
use crate::Fx;
use crate::math::{Scalar, Vec2, WideScalar};

/// A ray: an origin, a unit direction and a maximum distance.
///
/// Build it with [`Ray::new`], which normalises the direction. The fields
/// are public for reading; a ray built by hand should keep `direction`
/// unit length (the casts measure distance in units of `|direction|`) and
/// `max_distance` non-negative (a negative one never hits anything).
///
/// Documented range (`Fx`): coordinates within ±[`WORLD_LIMIT`] and
/// `max_distance ≤ 2¹⁷`, which keeps every hit point inside the scalar's
/// range; beyond it results saturate (defined and deterministic, not
/// accurate).
///
/// [`WORLD_LIMIT`]: crate::math::WORLD_LIMIT
///
/// ```
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
    /// ones. Of the quotients and their neighbours one ulp away, the pair
    /// whose squared length is closest to 1 (decided exactly in the wide
    /// type) is kept: distances along the ray are measured in units of
    /// `|direction|`, so this is what sets their relative accuracy. For
    /// `Fx` the result's length is within about one ulp (2.3e-10) of 1 (a
    /// relative distance error of at most 2.3e-10: 3e-5 at 2¹⁷ units) and
    /// its angle within about 3 ulps of the input's.
    #[must_use]
    pub fn new(origin: Vec2<S>, direction: Vec2<S>, max_distance: S) -> Option<Self> {
        if max_distance.is_negative() {
            return None;
        }
        let scale = direction.x.abs().max(direction.y.abs());
        if !scale.is_positive() {
            return None;
        }
        // |component| ≤ scale, so both quotients are in [-1, 1].
        let w = Vec2::new(direction.x.div(scale), direction.y.div(scale));
        let direction = closest_to_unit(w.try_normalize()?);
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

/// Of `u` and its eight neighbours (each component moved by -1, 0 or +1
/// ulp), the one whose squared length is closest to 1, compared exactly in
/// the wide type (the first in a fixed order on ties, `u` itself first).
///
/// The unit circle passes within about half an ulp of `u` (its components
/// are truncated quotients by a length rounded down, each off by less than
/// an ulp), so one of the nine is within `ulp/√2` of it: its squared length
/// is within `√2 ulp` of 1, its length within `ulp/√2`, and its angle moves
/// by at most √2 ulps.
fn closest_to_unit<S: Scalar>(u: Vec2<S>) -> Vec2<S> {
    let one = S::ONE.wide_mul(S::ONE);
    let error = |v: Vec2<S>| {
        let e = v.length_squared_wide().sub(one);
        if e.is_negative() { S::Wide::ZERO.sub(e) } else { e }
    };
    let steps = [S::ZERO, S::EPSILON.neg(), S::EPSILON];
    let mut best = u;
    let mut best_error = error(u);
    for dx in steps {
        for dy in steps {
            let candidate = Vec2::new(u.x.add(dx), u.y.add(dy));
            let e = error(candidate);
            if e < best_error {
                best = candidate;
                best_error = e;
            }
        }
    }
    best
}

/// Where a ray hits a shape.
///
/// ```
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
