//! The two shapes: [`Circle`] and the axis-aligned box [`Aabb`].
//!
//! Boxes never rotate (the engine has no angular terms), so an axis-aligned
//! box is both a collision shape and a bounding box.

use serde::{Deserialize, Serialize};

use crate::math::Fx;
use crate::math::{Scalar, Vec2};

/// A circle: centre and radius.
///
/// ```
/// use clockwork2d::prelude::*;
/// let c = Circle::new(Vec2::new(fx(1.0), fx(2.0)), fx(0.5));
/// assert!(c.contains_point(Vec2::new(fx(1.25), fx(2.0))));
/// assert_eq!(c.bounding_aabb().half_extents, Vec2::new(fx(0.5), fx(0.5)));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct Circle<S: Scalar = Fx> {
    /// Centre.
    pub center: Vec2<S>,
    /// Radius (the engine requires it to be positive).
    pub radius: S,
}

impl<S: Scalar> Circle<S> {
    /// Creates a circle.
    #[inline]
    #[must_use]
    pub const fn new(center: Vec2<S>, radius: S) -> Self {
        Circle { center, radius }
    }

    /// The smallest axis-aligned box containing the circle.
    #[inline]
    #[must_use]
    pub fn bounding_aabb(&self) -> Aabb<S> {
        Aabb::new(self.center, Vec2::new(self.radius, self.radius))
    }

    /// `true` if `point` is inside or on the circle. Exact: the squared
    /// distance and squared radius are compared in the wide type.
    #[inline]
    #[must_use]
    pub fn contains_point(&self, point: Vec2<S>) -> bool {
        (point - self.center).length_squared_wide() <= self.radius.wide_mul(self.radius)
    }
}

/// An axis-aligned box: centre and half extents.
///
/// ```
/// use clockwork2d::prelude::*;
/// let b = Aabb::new(Vec2::new(fx(0.0), fx(0.0)), Vec2::new(fx(2.0), fx(1.0)));
/// assert_eq!(b.min(), Vec2::new(fx(-2.0), fx(-1.0)));
/// assert!(b.contains_point(Vec2::new(fx(2.0), fx(0.0))));
/// assert!(!b.contains_point(Vec2::new(fx(0.0), fx(1.5))));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct Aabb<S: Scalar = Fx> {
    /// Centre.
    pub center: Vec2<S>,
    /// Half the width and half the height (the engine requires both to be
    /// positive for a body's shape; bounding boxes may be degenerate).
    pub half_extents: Vec2<S>,
}

impl<S: Scalar> Aabb<S> {
    /// Creates a box from its centre and half extents.
    #[inline]
    #[must_use]
    pub const fn new(center: Vec2<S>, half_extents: Vec2<S>) -> Self {
        Aabb {
            center,
            half_extents,
        }
    }

    /// Creates the box spanning two corners (in any order).
    #[inline]
    #[must_use]
    pub fn from_corners(a: Vec2<S>, b: Vec2<S>) -> Self {
        let lo = a.min(b);
        let hi = a.max(b);
        let half = Vec2::new(hi.x.sub(lo.x).half(), hi.y.sub(lo.y).half());
        Aabb::new(lo + half, half)
    }

    /// The lower-left corner.
    #[inline]
    #[must_use]
    pub fn min(&self) -> Vec2<S> {
        self.center - self.half_extents
    }

    /// The upper-right corner.
    #[inline]
    #[must_use]
    pub fn max(&self) -> Vec2<S> {
        self.center + self.half_extents
    }

    /// The box itself (a box is its own bounding box).
    #[inline]
    #[must_use]
    pub fn bounding_aabb(&self) -> Aabb<S> {
        *self
    }

    /// `true` if `point` is inside or on the boundary.
    #[inline]
    #[must_use]
    pub fn contains_point(&self, point: Vec2<S>) -> bool {
        let d = (point - self.center).abs();
        d.x <= self.half_extents.x && d.y <= self.half_extents.y
    }

    /// `true` if the boxes overlap or touch.
    #[inline]
    #[must_use]
    pub fn overlaps(&self, other: &Aabb<S>) -> bool {
        let (a0, a1, b0, b1) = (self.min(), self.max(), other.min(), other.max());
        a0.x <= b1.x && b0.x <= a1.x && a0.y <= b1.y && b0.y <= a1.y
    }

    /// The smallest box containing both.
    #[inline]
    #[must_use]
    pub fn union(&self, other: &Aabb<S>) -> Aabb<S> {
        Aabb::from_corners(self.min().min(other.min()), self.max().max(other.max()))
    }

    /// The box grown by `margin` on every side.
    #[inline]
    #[must_use]
    pub fn expanded(&self, margin: S) -> Aabb<S> {
        Aabb::new(self.center, self.half_extents + Vec2::new(margin, margin))
    }
}

/// A collision shape: a circle or an axis-aligned box, in local coordinates
/// (centred on the body's position).
///
/// ```
/// use clockwork2d::prelude::*;
/// let s = Shape::circle(fx(0.5));
/// assert_eq!(s.half_extents(), Vec2::new(fx(0.5), fx(0.5)));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub enum Shape<S: Scalar = Fx> {
    /// A circle of the given radius.
    Circle {
        /// Radius.
        radius: S,
    },
    /// An axis-aligned box of the given half extents.
    Aabb {
        /// Half width and half height.
        half_extents: Vec2<S>,
    },
}

impl<S: Scalar> Shape<S> {
    /// A circle of radius `radius`.
    #[inline]
    #[must_use]
    pub const fn circle(radius: S) -> Self {
        Shape::Circle { radius }
    }

    /// An axis-aligned box of half extents `half_extents`.
    #[inline]
    #[must_use]
    pub const fn aabb(half_extents: Vec2<S>) -> Self {
        Shape::Aabb { half_extents }
    }

    /// The half extents of the shape's bounding box.
    #[inline]
    #[must_use]
    pub fn half_extents(&self) -> Vec2<S> {
        match *self {
            Shape::Circle { radius } => Vec2::new(radius, radius),
            Shape::Aabb { half_extents } => half_extents,
        }
    }

    /// The bounding box of the shape placed at `position`.
    #[inline]
    #[must_use]
    pub fn bounding_aabb_at(&self, position: Vec2<S>) -> Aabb<S> {
        Aabb::new(position, self.half_extents())
    }

    /// The area, used to derive mass from density (`π r²` uses a fixed
    /// rational approximation of π: 355/113, relative error 8.5e-8).
    #[must_use]
    pub fn area(&self) -> S {
        match *self {
            Shape::Circle { radius } => radius.mul(radius).mul(S::from_ratio(355, 113)),
            Shape::Aabb { half_extents } => half_extents.x.mul(half_extents.y).mul_int(4),
        }
    }
}
