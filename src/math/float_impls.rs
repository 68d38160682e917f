//! [`Scalar`] for `f64` and `f32`: **reference types only**.
//!
//! They run the same algorithm as the fixed-point types so that the error of
//! fixed point can be measured on one code path. They are not used for
//! lockstep: float results can differ across targets and compiler settings.
//! Their "saturation" is IEEE behaviour (overflow to infinity); only the
//! zero-divisor and negative-root cases are given the same defined results as
//! the fixed types.
#![allow(clippy::float_arithmetic)]

use super::scalar::Scalar;
use super::wide::WideFloat;

macro_rules! impl_scalar_float {
    ($t:ty, $name:literal, $id:literal, $bits:expr) => {
        impl Scalar for $t {
            type Wide = WideFloat<$t>;
            const ZERO: Self = 0.0;
            const ONE: Self = 1.0;
            const MAX: Self = <$t>::MAX;
            const MIN: Self = <$t>::MIN;
            const EPSILON: Self = <$t>::EPSILON;
            const NAME: &'static str = $name;
            const ID: u8 = $id;
            const IS_REFERENCE: bool = true;

            #[inline]
            #[allow(clippy::cast_possible_truncation)]
            fn from_f64(value: f64) -> Self {
                if value.is_nan() { 0.0 } else { value as $t }
            }
            #[inline]
            fn to_f64(self) -> f64 {
                f64::from(self)
            }
            #[inline]
            #[allow(clippy::cast_possible_truncation, clippy::cast_lossless)]
            fn from_int(value: i32) -> Self {
                value as $t
            }
            #[inline]
            fn to_hash_bits(self) -> u64 {
                let bits: fn($t) -> u64 = $bits;
                bits(self)
            }
            #[inline]
            fn add(self, rhs: Self) -> Self {
                self + rhs
            }
            #[inline]
            fn sub(self, rhs: Self) -> Self {
                self - rhs
            }
            #[inline]
            fn mul(self, rhs: Self) -> Self {
                self * rhs
            }
            #[inline]
            fn div(self, rhs: Self) -> Self {
                if rhs == 0.0 {
                    if self > 0.0 {
                        <$t>::MAX
                    } else if self < 0.0 {
                        <$t>::MIN
                    } else {
                        0.0
                    }
                } else {
                    self / rhs
                }
            }
            #[inline]
            fn checked_div(self, rhs: Self) -> Option<Self> {
                if rhs == 0.0 { None } else { Some(self / rhs) }
            }
            #[inline]
            fn neg(self) -> Self {
                -self
            }
            #[inline]
            fn abs(self) -> Self {
                <$t>::abs(self)
            }
            #[inline]
            fn sqrt(self) -> Self {
                if self > 0.0 { <$t>::sqrt(self) } else { 0.0 }
            }
            #[inline]
            fn wide_mul(self, rhs: Self) -> WideFloat<$t> {
                WideFloat(f64::from(self) * f64::from(rhs), core::marker::PhantomData)
            }
            #[inline]
            #[allow(clippy::cast_possible_truncation, clippy::cast_lossless)]
            fn mul_int(self, rhs: i32) -> Self {
                self * (rhs as $t)
            }
            #[inline]
            fn half(self) -> Self {
                self * 0.5
            }
        }
    };
}

impl_scalar_float!(f64, "f64", 100, |v: f64| v.to_bits());
impl_scalar_float!(f32, "f32", 101, |v: f32| u64::from(v.to_bits()));
