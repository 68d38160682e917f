//! [`Scalar`] for the fixed-point types: `I32F32` (the default, [`Fx`]) and
//! `I48F16`.
//!
//! Every method maps to the `fixed` crate's `saturating_*` / `checked_*`
//! family, never to its operators (which panic in debug and wrap in release).

use fixed::types::{I32F32, I48F16, I64F64, I96F32};

use super::Vec2;
use super::scalar::Scalar;

/// The default scalar: 32 integer bits, 32 fraction bits.
///
/// Range ±2³¹ (about ±2.1e9), step 2⁻³² (about 2.3e-10). Products of two
/// coordinates are formed in `I64F64` (see [`Scalar::wide_mul`]).
pub type Fx = I32F32;

/// Converts a float literal to [`Fx`] (API edge only; rounds to nearest,
/// saturates, NaN becomes zero).
///
/// ```
/// use clockwork2d::prelude::*;
/// assert_eq!(fx(0.5), Fx::ONE.half());
/// assert_eq!(fx(f64::NAN), Fx::ZERO);
/// assert_eq!(fx(1e300), Fx::MAX);
/// ```
#[must_use]
pub fn fx(value: f64) -> Fx {
    Fx::from_f64(value)
}

/// A [`Vec2`] of [`Fx`] from two float literals, each converted like
/// [`fx`] (API edge only).
///
/// ```
/// use clockwork2d::prelude::*;
/// assert_eq!(vec2(1.5, -2.0), Vec2::new(fx(1.5), fx(-2.0)));
/// ```
#[must_use]
pub fn vec2(x: f64, y: f64) -> Vec2<Fx> {
    Vec2::new(fx(x), fx(y))
}

macro_rules! impl_scalar_fixed {
    ($t:ty, $wide:ty, $name:literal, $id:literal, $frac:literal) => {
        impl Scalar for $t {
            type Wide = $wide;
            const ZERO: Self = <$t>::ZERO;
            const ONE: Self = <$t>::ONE;
            const MAX: Self = <$t>::MAX;
            const MIN: Self = <$t>::MIN;
            const EPSILON: Self = <$t>::DELTA;
            const NAME: &'static str = $name;
            const ID: u8 = $id;
            const IS_REFERENCE: bool = false;

            #[inline]
            fn from_f64(value: f64) -> Self {
                if value.is_nan() {
                    return <$t>::ZERO;
                }
                // Rounds to nearest, ties to even (the `fixed` crate's rule
                // for float sources); out-of-range values saturate.
                <$t>::saturating_from_num(value)
            }
            #[inline]
            fn to_f64(self) -> f64 {
                self.to_num::<f64>()
            }
            #[inline]
            fn from_int(value: i32) -> Self {
                <$t>::saturating_from_num(value)
            }
            #[inline]
            fn to_hash_bits(self) -> u64 {
                // Two's complement bits of the raw i64 value.
                self.to_bits() as u64
            }
            #[inline]
            fn add(self, rhs: Self) -> Self {
                self.saturating_add(rhs)
            }
            #[inline]
            fn sub(self, rhs: Self) -> Self {
                // The same result as `saturating_sub`, in the form the
                // compiler gives `saturating_add` (one instruction shorter
                // on x86-64 than its own lowering of the subtraction): on
                // overflow the wrapped difference has the wrong sign, so
                // the bound is MAX when it is negative and MIN otherwise,
                // i.e. `(wrapped >> 63) ^ MIN` on the raw bits.
                let (wrapped, overflow) = self.to_bits().overflowing_sub(rhs.to_bits());
                if overflow {
                    <$t>::from_bits((wrapped >> 63) ^ i64::MIN)
                } else {
                    <$t>::from_bits(wrapped)
                }
            }
            #[inline]
            fn mul(self, rhs: Self) -> Self {
                // The exact product of two i64 raw values always fits i128
                // (one 64×64→128 machine multiply); shifting by the fraction
                // bits rounds toward −∞ exactly like the `fixed` crate's
                // `saturating_mul`, then the result is clamped. Bit-identical
                // to `saturating_mul`, but without its general 128-bit path.
                let product = i128::from(self.to_bits()) * i128::from(rhs.to_bits());
                <$t>::from_bits(super::wide::shift_saturate::<$frac>(product))
            }
            #[inline]
            fn div(self, rhs: Self) -> Self {
                if rhs == <$t>::ZERO {
                    if self > <$t>::ZERO {
                        <$t>::MAX
                    } else if self < <$t>::ZERO {
                        <$t>::MIN
                    } else {
                        <$t>::ZERO
                    }
                } else {
                    let (n, d) = (self.to_bits(), rhs.to_bits());
                    let magnitude = n.unsigned_abs();
                    if magnitude < 1u64 << (63 - $frac) {
                        // |n|·2^f < 2^63 fits a u64, so the quotient is one
                        // machine division instead of a 128-bit one
                        // (normals, effective masses: small numerators).
                        // Unsigned division truncates; applying the sign
                        // afterwards truncates toward zero, as the `fixed`
                        // crate does. |q| ≤ |n|·2^f < 2^63: no overflow.
                        let q = ((magnitude << $frac) / d.unsigned_abs()) as i64;
                        <$t>::from_bits(if (n < 0) == (d < 0) { q } else { -q })
                    } else {
                        self.saturating_div(rhs)
                    }
                }
            }
            #[inline]
            fn checked_div(self, rhs: Self) -> Option<Self> {
                <$t>::checked_div(self, rhs)
            }
            #[inline]
            fn neg(self) -> Self {
                self.saturating_neg()
            }
            #[inline]
            fn abs(self) -> Self {
                self.saturating_abs()
            }
            #[inline]
            fn sqrt(self) -> Self {
                if self <= <$t>::ZERO {
                    <$t>::ZERO
                } else {
                    // The root of a positive value below 2^k never overflows
                    // (sqrt(x) < x for x > 1, and < 1 otherwise); use the
                    // overflowing form so even that cannot reach a debug panic.
                    self.overflowing_sqrt().0
                }
            }
            #[inline]
            fn mul_add_mul(a: Self, b: Self, c: Self, d: Self) -> Self {
                // The same exact wide sum as the default method (the wide
                // type's raw bits are the raw product, with twice the
                // fraction bits), with the saturation moved off the hot
                // path: the sum of two products of i64 values overflows
                // i128 only when both are (−2⁶³)² = 2¹²⁶.
                let p = i128::from(a.to_bits()) * i128::from(b.to_bits());
                let q = i128::from(c.to_bits()) * i128::from(d.to_bits());
                match p.checked_add(q) {
                    Some(sum) => <$t>::from_bits(super::wide::shift_saturate::<$frac>(sum)),
                    None => <$t>::MAX,
                }
            }
            #[inline]
            fn mul_sub_mul(a: Self, b: Self, c: Self, d: Self) -> Self {
                // As `mul_add_mul`. A product of i64 values lies in
                // [−2¹²⁶ + 2⁶³, 2¹²⁶], so |p − q| ≤ 2¹²⁷ − 2⁶³ always fits;
                // the overflow arms only keep the function total.
                let p = i128::from(a.to_bits()) * i128::from(b.to_bits());
                let q = i128::from(c.to_bits()) * i128::from(d.to_bits());
                match p.checked_sub(q) {
                    Some(difference) => {
                        <$t>::from_bits(super::wide::shift_saturate::<$frac>(difference))
                    }
                    None if p > 0 => <$t>::MAX,
                    None => <$t>::MIN,
                }
            }
            #[inline]
            fn wide_mul(self, rhs: Self) -> $wide {
                <$t>::wide_mul(self, rhs)
            }
            #[inline]
            fn mul_int(self, rhs: i32) -> Self {
                self.saturating_mul_int(i64::from(rhs))
            }
            #[inline]
            fn half(self) -> Self {
                // Arithmetic shift: exact except for the lowest bit, which is
                // rounded toward negative infinity. Never overflows.
                <$t>::from_bits(self.to_bits() >> 1)
            }
        }
    };
}

impl_scalar_fixed!(I32F32, I64F64, "I32F32", 1, 32);
impl_scalar_fixed!(I48F16, I96F32, "I48F16", 2, 16);
