//! The [`Scalar`] trait: the one place where simulation arithmetic happens.
//!
//! # Overflow policy
//!
//! Every operation **saturates**: a result that does not fit is clamped to
//! [`Scalar::MAX`] or [`Scalar::MIN`]. This is the same in debug and release
//! builds (the `fixed` crate's `+`/`*` operators panic in debug and wrap in
//! release; the engine never uses them). Saturation was chosen over wrapping
//! because a saturated position stays on the same side of the world and is
//! caught by the world-bounds check, while a wrapped one teleports.
//!
//! Defined results for the two operations that have none in mathematics:
//!
//! * `x.div(0)` is `MAX` for `x > 0`, `MIN` for `x < 0` and `0` for `x == 0`
//!   (the limit from the positive side, with 0/0 taken as 0). Engine code
//!   never relies on it: it checks divisors first. It exists so that no
//!   input, however hostile, can reach a panic.
//! * `x.sqrt()` of a negative `x` is `0`.
//!
//! # Wide products
//!
//! A product of two coordinates can exceed the scalar's range (for `I32F32`,
//! 46 341² > 2³¹). [`Scalar::wide_mul`] returns the exact product in the
//! double-width type [`Scalar::Wide`] (`I64F64` for `I32F32`); sums of such
//! products (dot products, squared lengths, discriminants) are formed there
//! and narrowed once, with saturation, at the end.

use core::fmt::Debug;

use serde::Serialize;
use serde::de::DeserializeOwned;

use super::wide::WideScalar;

/// A number type the engine can simulate with.
///
/// Implemented for [`crate::math::Fx`] (`I32F32`, the default), `I48F16` (large,
/// coarse worlds), and for `f64` and `f32` as *reference* types used only to
/// measure error (floats are not bit-identical across targets in general and
/// must not be used for lockstep).
///
/// All arithmetic methods saturate; see the module notes in `src/math/scalar.rs`.
///
/// ```
/// use clockwork2d::prelude::*;
/// let a = fx(1.5);
/// assert_eq!(a.add(fx(2.0)), fx(3.5));
/// assert_eq!(Fx::MAX.add(Fx::ONE), Fx::MAX); // saturates, debug and release alike
/// assert_eq!(fx(1.0).div(Fx::ZERO), Fx::MAX); // defined, never a panic
/// ```
pub trait Scalar:
    Copy
    + Debug
    + Default
    + PartialEq
    + PartialOrd
    + Send
    + Sync
    + Serialize
    + DeserializeOwned
    + 'static
{
    /// The double-width type that holds exact products of two scalars.
    type Wide: WideScalar<Narrow = Self>;

    /// Zero.
    const ZERO: Self;
    /// One.
    const ONE: Self;
    /// The largest representable value.
    const MAX: Self;
    /// The smallest (most negative) representable value.
    const MIN: Self;
    /// The smallest positive step (one ulp for fixed point).
    const EPSILON: Self;
    /// A short stable name (`"I32F32"`, `"I48F16"`, `"f64"`, `"f32"`), used in
    /// reports and in file headers.
    const NAME: &'static str;
    /// A stable numeric id for file headers; never reused.
    const ID: u8;
    /// `true` for the float reference types, which are not bit-identical
    /// across targets and exist only to measure error.
    const IS_REFERENCE: bool;

    /// Converts a float literal (edge of the API only). Saturates to the
    /// range; NaN becomes zero. Rounds to the nearest representable value.
    fn from_f64(value: f64) -> Self;
    /// Converts to `f64`, for reports and rendering (edge of the API only).
    fn to_f64(self) -> f64;
    /// Converts an integer, saturating to the range.
    fn from_int(value: i32) -> Self;
    /// `numerator / denominator` computed exactly-then-rounded in the scalar
    /// (no float on the way; truncated toward zero for fixed point). A zero
    /// denominator gives the defined division result (see module docs).
    fn from_ratio(numerator: i32, denominator: i32) -> Self {
        Self::from_int(numerator).div(Self::from_int(denominator))
    }
    /// Canonical bits for hashing: the two's complement raw value for fixed
    /// point (sign-extended to 64 bits), the IEEE bits for floats.
    fn to_hash_bits(self) -> u64;

    /// Saturating addition.
    fn add(self, rhs: Self) -> Self;
    /// Saturating subtraction.
    fn sub(self, rhs: Self) -> Self;
    /// Saturating multiplication. For fixed point the exact product is
    /// rounded toward negative infinity.
    fn mul(self, rhs: Self) -> Self;
    /// Saturating division with a defined result for a zero divisor. For
    /// fixed point the exact quotient is truncated toward zero.
    fn div(self, rhs: Self) -> Self;
    /// Division, or `None` for a zero divisor or (fixed point) an
    /// overflowing quotient.
    fn checked_div(self, rhs: Self) -> Option<Self>;
    /// Saturating negation (`MIN.neg()` is `MAX` for fixed point).
    fn neg(self) -> Self;
    /// Saturating absolute value.
    fn abs(self) -> Self;
    /// Square root; zero for negative input. Exact to one ulp for fixed point.
    fn sqrt(self) -> Self;
    /// The exact product in the double-width type.
    fn wide_mul(self, rhs: Self) -> Self::Wide;
    /// Multiplication by an integer, saturating.
    fn mul_int(self, rhs: i32) -> Self;
    /// Halving (exact for fixed point apart from the last bit, which is
    /// rounded toward negative infinity).
    fn half(self) -> Self;

    /// `true` if strictly below zero.
    #[inline]
    fn is_negative(self) -> bool {
        self < Self::ZERO
    }
    /// `true` if strictly above zero.
    #[inline]
    fn is_positive(self) -> bool {
        self > Self::ZERO
    }
    /// The smaller of two values (`self` on ties).
    #[inline]
    fn min(self, other: Self) -> Self {
        if other < self { other } else { self }
    }
    /// The larger of two values (`self` on ties).
    #[inline]
    fn max(self, other: Self) -> Self {
        if other > self { other } else { self }
    }
    /// Clamps to `[low, high]`. If `low > high`, the result is `low`.
    #[inline]
    fn clamp(self, low: Self, high: Self) -> Self {
        self.min(high).max(low)
    }
    /// -1, 0 or 1.
    #[inline]
    fn signum(self) -> Self {
        if self > Self::ZERO {
            Self::ONE
        } else if self < Self::ZERO {
            Self::ONE.neg()
        } else {
            Self::ZERO
        }
    }
    /// `a*b + c*d` computed exactly in the wide type and saturated once.
    #[inline]
    fn mul_add_mul(a: Self, b: Self, c: Self, d: Self) -> Self {
        a.wide_mul(b).add(c.wide_mul(d)).narrow()
    }
    /// `a*b - c*d` computed exactly in the wide type and saturated once.
    #[inline]
    fn mul_sub_mul(a: Self, b: Self, c: Self, d: Self) -> Self {
        a.wide_mul(b).sub(c.wide_mul(d)).narrow()
    }
}
