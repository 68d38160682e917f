//! [`Vec2`]: a 2D vector over any [`Scalar`].
//!
//! The operators (`+`, `-`, unary `-`, `* scalar`) are implemented through the
//! scalar's saturating methods, so vector code reads naturally and still has
//! the one overflow policy. Dot products, cross products and squared lengths
//! are computed exactly in the wide type and saturated once.

use core::ops::{Add, AddAssign, Mul, Neg, Sub, SubAssign};

use serde::{Deserialize, Serialize};

use super::scalar::Scalar;
use super::wide::WideScalar;
use crate::math::Fx;

/// A 2D vector (or point) with components of scalar type `S`.
///
/// ```
/// use clockwork2d::prelude::*;
/// let a = Vec2::new(fx(3.0), fx(4.0));
/// assert_eq!(a.length(), fx(5.0));
/// assert_eq!(a.dot(Vec2::new(fx(1.0), fx(0.0))), fx(3.0));
/// assert_eq!(a + a, Vec2::new(fx(6.0), fx(8.0)));
/// ```
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct Vec2<S: Scalar = Fx> {
    /// Horizontal component (positive to the right).
    pub x: S,
    /// Vertical component (positive up).
    pub y: S,
}

impl<S: Scalar> Vec2<S> {
    /// The zero vector.
    pub const ZERO: Self = Vec2 {
        x: S::ZERO,
        y: S::ZERO,
    };
    /// The unit vector along +x.
    pub const X: Self = Vec2 {
        x: S::ONE,
        y: S::ZERO,
    };
    /// The unit vector along +y.
    pub const Y: Self = Vec2 {
        x: S::ZERO,
        y: S::ONE,
    };

    /// Creates a vector.
    #[inline]
    #[must_use]
    pub const fn new(x: S, y: S) -> Self {
        Vec2 { x, y }
    }

    /// Creates a vector from float literals (API edge only).
    #[inline]
    #[must_use]
    pub fn from_f64(x: f64, y: f64) -> Self {
        Vec2::new(S::from_f64(x), S::from_f64(y))
    }

    /// Both components as `f64` (reports and rendering only).
    #[inline]
    #[must_use]
    pub fn to_f64(self) -> (f64, f64) {
        (self.x.to_f64(), self.y.to_f64())
    }

    /// Multiplies both components by `factor` (saturating).
    #[inline]
    #[must_use]
    pub fn scale(self, factor: S) -> Self {
        Vec2::new(self.x.mul(factor), self.y.mul(factor))
    }

    /// Component-wise product.
    #[inline]
    #[must_use]
    pub fn mul_elements(self, other: Self) -> Self {
        Vec2::new(self.x.mul(other.x), self.y.mul(other.y))
    }

    /// Dot product, exact in the wide type then saturated.
    #[inline]
    #[must_use]
    pub fn dot(self, other: Self) -> S {
        S::mul_add_mul(self.x, other.x, self.y, other.y)
    }

    /// Dot product in the wide type (exact; never saturates within the
    /// world bounds).
    #[inline]
    #[must_use]
    pub fn dot_wide(self, other: Self) -> S::Wide {
        self.x.wide_mul(other.x).add(self.y.wide_mul(other.y))
    }

    /// The 2D cross product (perp-dot) `self.x * other.y - self.y * other.x`:
    /// positive when `other` is counter-clockwise from `self`.
    #[inline]
    #[must_use]
    pub fn cross(self, other: Self) -> S {
        S::mul_sub_mul(self.x, other.y, self.y, other.x)
    }

    /// The vector rotated a quarter turn counter-clockwise: `(-y, x)`.
    #[inline]
    #[must_use]
    pub fn perp(self) -> Self {
        Vec2::new(self.y.neg(), self.x)
    }

    /// Squared length, saturated to the scalar's range. For `Fx` this is
    /// the exact square rounded down to one ulp while the length is below
    /// 46 340; use
    /// [`length_squared_wide`](Self::length_squared_wide) beyond.
    #[inline]
    #[must_use]
    pub fn length_squared(self) -> S {
        self.dot(self)
    }

    /// Squared length in the wide type (exact within the world bounds).
    #[inline]
    #[must_use]
    pub fn length_squared_wide(self) -> S::Wide {
        self.dot_wide(self)
    }

    /// Length. For fixed point, the exact length rounded down to one ulp for
    /// any vector whose length fits the scalar (the square is formed exactly
    /// in the wide type); longer vectors (beyond 2³¹ for `Fx`) give `MAX`.
    #[inline]
    #[must_use]
    pub fn length(self) -> S {
        self.length_squared_wide().sqrt_narrow()
    }

    /// Distance between two points.
    #[inline]
    #[must_use]
    pub fn distance(self, other: Self) -> S {
        (other - self).length()
    }

    /// The unit vector in this direction, or `None` for the zero vector.
    ///
    /// Accuracy (fixed point): each component is `c / len`, where `len` is
    /// `|v|` rounded down by less than one ulp, truncated toward zero by
    /// less than one ulp. So the result's length is in
    /// `(1 − √2 ulp, 1 + ulp / (|v| − ulp))`, within `2 ulp / |v| + 2 ulp`
    /// of 1 (for `Fx` and `|v| ≥ 1e-3`, better than 1e-6), and its direction
    /// is off by at most about `√2 ulp` (its cross product with `v / |v|`).
    /// This holds for every nonzero vector, including those whose length
    /// saturates.
    #[inline]
    #[must_use]
    pub fn try_normalize(self) -> Option<Self> {
        self.try_normalize_with_length().map(|(unit, _)| unit)
    }

    /// The unit vector in this direction, or zero for the zero vector.
    #[inline]
    #[must_use]
    pub fn normalize_or_zero(self) -> Self {
        self.try_normalize().unwrap_or(Self::ZERO)
    }

    /// The unit vector and the length, or `None` for the zero vector.
    ///
    /// The length saturates like [`length`](Self::length); the unit vector
    /// has the accuracy documented on [`try_normalize`](Self::try_normalize).
    #[inline]
    #[must_use]
    pub fn try_normalize_with_length(self) -> Option<(Self, S)> {
        let len = self.length();
        if len <= S::ZERO {
            return None;
        }
        if len == S::MAX {
            // The length saturated (|v| ≥ 2³¹ for `Fx`, far outside the
            // world): dividing by the clamped length would give a vector up
            // to √2 long. Halving both components brings |v| below 2^30.5;
            // the dropped lowest bits are a relative change near 2⁻⁶².
            let half = Vec2::new(self.x.half(), self.y.half());
            let half_len = half.length();
            return Some((Vec2::new(half.x.div(half_len), half.y.div(half_len)), len));
        }
        // |c| <= len, so each quotient is in [-1, 1] and cannot overflow.
        Some((Vec2::new(self.x.div(len), self.y.div(len)), len))
    }

    /// Component-wise minimum.
    #[inline]
    #[must_use]
    pub fn min(self, other: Self) -> Self {
        Vec2::new(self.x.min(other.x), self.y.min(other.y))
    }

    /// Component-wise maximum.
    #[inline]
    #[must_use]
    pub fn max(self, other: Self) -> Self {
        Vec2::new(self.x.max(other.x), self.y.max(other.y))
    }

    /// Component-wise absolute value (saturating).
    #[inline]
    #[must_use]
    pub fn abs(self) -> Self {
        Vec2::new(self.x.abs(), self.y.abs())
    }

    /// Component-wise clamp to `[low, high]`.
    #[inline]
    #[must_use]
    pub fn clamp(self, low: Self, high: Self) -> Self {
        Vec2::new(self.x.clamp(low.x, high.x), self.y.clamp(low.y, high.y))
    }

    /// Converts to another scalar type through `f64` (reports and error
    /// measurement only).
    #[inline]
    #[must_use]
    pub fn cast<T: Scalar>(self) -> Vec2<T> {
        Vec2::new(T::from_f64(self.x.to_f64()), T::from_f64(self.y.to_f64()))
    }
}

impl<S: Scalar> Add for Vec2<S> {
    type Output = Self;
    #[inline]
    fn add(self, rhs: Self) -> Self {
        Vec2::new(self.x.add(rhs.x), self.y.add(rhs.y))
    }
}

impl<S: Scalar> Sub for Vec2<S> {
    type Output = Self;
    #[inline]
    fn sub(self, rhs: Self) -> Self {
        Vec2::new(self.x.sub(rhs.x), self.y.sub(rhs.y))
    }
}

impl<S: Scalar> AddAssign for Vec2<S> {
    #[inline]
    fn add_assign(&mut self, rhs: Self) {
        *self = *self + rhs;
    }
}

impl<S: Scalar> SubAssign for Vec2<S> {
    #[inline]
    fn sub_assign(&mut self, rhs: Self) {
        *self = *self - rhs;
    }
}

impl<S: Scalar> Neg for Vec2<S> {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        Vec2::new(self.x.neg(), self.y.neg())
    }
}

impl<S: Scalar> Mul<S> for Vec2<S> {
    type Output = Self;
    #[inline]
    fn mul(self, rhs: S) -> Self {
        self.scale(rhs)
    }
}
