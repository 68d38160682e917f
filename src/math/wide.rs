//! Double-width intermediates for products of scalars.
//!
//! `I32F32 × I32F32` is exact in `I64F64`, `I48F16 × I48F16` in `I96F32`.
//! Sums of a few such products (a dot product, a squared length, a ray
//! discriminant) stay exact there as long as they are below 2⁶³ (resp. 2⁹⁵),
//! which the documented world bounds guarantee with a wide margin.

use core::fmt::Debug;

use fixed::types::{I64F64, I96F32};

use super::scalar::Scalar;

/// A double-width value: the exact product of two [`Scalar`]s.
///
/// All operations saturate, like the narrow ones.
pub trait WideScalar: Copy + Debug + PartialEq + PartialOrd + Send + Sync {
    /// The narrow scalar this is the wide form of.
    type Narrow: Scalar;
    /// Zero.
    const ZERO: Self;

    /// Saturating addition.
    fn add(self, rhs: Self) -> Self;
    /// Saturating subtraction.
    fn sub(self, rhs: Self) -> Self;
    /// Widens a narrow value (exact).
    fn from_narrow(value: Self::Narrow) -> Self;
    /// Narrows with saturation; the low fraction bits are rounded toward
    /// negative infinity.
    fn narrow(self) -> Self::Narrow;
    /// Square root, narrowed with saturation; zero for negative input.
    ///
    /// For fixed point the result is the true root rounded down to a narrow
    /// ulp (`r ≤ √x < r + ulp`, so a nonzero value, even one wide ulp, has a
    /// nonzero root); it saturates to the narrow `MAX` once `√x` is past the
    /// narrow range (`x ≥ 2⁶²` for `I64F64`, `x ≥ 2⁹⁴` for `I96F32`).
    fn sqrt_narrow(self) -> Self::Narrow;
    /// `true` if strictly below zero.
    #[inline]
    fn is_negative(self) -> bool {
        self < Self::ZERO
    }
}

/// `value >> SHIFT` (an arithmetic shift: rounded toward −∞) clamped to
/// the `i64` range, for `SHIFT` in `1..64`. Within the world bounds
/// products and sums never leave that range, so the test is one
/// predictable branch and the clamp sits on a cold path (same result as a
/// plain clamp of the shifted value).
///
/// The test reads only the high word `h = ⌊value / 2⁶⁴⌋`: the shifted
/// value fits `i64` iff `−2^(63+SHIFT) ≤ value < 2^(63+SHIFT)`, and since
/// those bounds are multiples of 2⁶⁴ that is `−2^(SHIFT−1) ≤ h <
/// 2^(SHIFT−1)`, i.e. `h` equals its own low `SHIFT` bits sign-extended
/// (two instructions for `SHIFT = 32`, where testing the shifted value's
/// round trip took five). Out of range, the shifted value has the sign of
/// `value`.
#[inline(always)]
pub(crate) fn shift_saturate<const SHIFT: u32>(value: i128) -> i64 {
    let high = (value >> 64) as i64;
    let spare = 64 - SHIFT;
    if (high << spare) >> spare == high {
        // Fits: the low 64 bits of the shifted value are all of it.
        (value >> SHIFT) as i64
    } else {
        saturate_out_of_range(value)
    }
}

/// The cold half of [`shift_saturate`]: the shifted value is outside the
/// `i64` range, on the side of `value`'s sign.
#[cold]
#[inline(never)]
fn saturate_out_of_range(value: i128) -> i64 {
    if value < 0 { i64::MIN } else { i64::MAX }
}

macro_rules! impl_wide_fixed {
    ($wide:ty, $narrow:ty, $shift:literal) => {
        impl WideScalar for $wide {
            type Narrow = $narrow;
            const ZERO: Self = <$wide>::ZERO;

            #[inline]
            fn add(self, rhs: Self) -> Self {
                self.saturating_add(rhs)
            }
            #[inline]
            fn sub(self, rhs: Self) -> Self {
                self.saturating_sub(rhs)
            }
            #[inline]
            fn from_narrow(value: $narrow) -> Self {
                <$wide>::from_num(value)
            }
            #[inline]
            fn narrow(self) -> $narrow {
                // Drop the extra fraction bits with an arithmetic shift
                // (rounding toward negative infinity, like the `fixed`
                // crate's conversions), then clamp to the narrow range.
                <$narrow>::from_bits(shift_saturate::<$shift>(self.to_bits()))
            }
            #[inline]
            fn sqrt_narrow(self) -> $narrow {
                // The wide type has exactly twice the narrow type's fraction
                // bits (64 vs 32, or 32 vs 16). With W the wide raw bits and
                // f the narrow fraction bits, w = W / 2^(2f), so the narrow
                // root's raw bits are
                //   R = floor(sqrt(W / 2^(2f)) · 2^f) = floor(sqrt(W)) = isqrt(W):
                // one exact integer square root, correctly rounded down
                // (within one narrow ulp of the true root), no float.
                let bits = self.to_bits();
                if bits <= 0 {
                    return <$narrow>::ZERO;
                }
                let w = bits.unsigned_abs();
                let root: u128 = match u64::try_from(w) {
                    // Most squared lengths in a world fit 64 bits; the u64
                    // root (one division, `math::isqrt`) is several times
                    // cheaper than the u128 one.
                    Ok(small) => u128::from(super::isqrt::isqrt_u64(small)),
                    Err(_) => w.isqrt(),
                };
                // Saturate: only roots of values above the narrow range's
                // square (2^62 for I32F32) can exceed it.
                <$narrow>::from_bits(i64::try_from(root).unwrap_or(i64::MAX))
            }
        }
    };
}

impl_wide_fixed!(I64F64, fixed::types::I32F32, 32);
impl_wide_fixed!(I96F32, fixed::types::I48F16, 16);

/// The wide type of the float references is `f64` for both: `f32` products
/// are exact in `f64`, and `f64` has no wider hardware type (it is a
/// reference, so plain `f64` rounding is what we want to compare against).
macro_rules! impl_wide_float {
    ($narrow:ty) => {
        #[allow(clippy::float_arithmetic)]
        impl WideScalar for WideFloat<$narrow> {
            type Narrow = $narrow;
            const ZERO: Self = WideFloat(0.0, core::marker::PhantomData);

            #[inline]
            fn add(self, rhs: Self) -> Self {
                WideFloat(self.0 + rhs.0, core::marker::PhantomData)
            }
            #[inline]
            fn sub(self, rhs: Self) -> Self {
                WideFloat(self.0 - rhs.0, core::marker::PhantomData)
            }
            #[inline]
            fn from_narrow(value: $narrow) -> Self {
                WideFloat(f64::from(value), core::marker::PhantomData)
            }
            #[inline]
            #[allow(clippy::cast_possible_truncation)]
            fn narrow(self) -> $narrow {
                self.0 as $narrow
            }
            #[inline]
            #[allow(clippy::cast_possible_truncation)]
            fn sqrt_narrow(self) -> $narrow {
                if self.0 > 0.0 {
                    self.0.sqrt() as $narrow
                } else {
                    0.0
                }
            }
        }
    };
}

/// The wide form of a float reference scalar: an `f64` tagged with the
/// narrow type it came from.
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd)]
pub struct WideFloat<T>(pub f64, pub core::marker::PhantomData<T>);

impl_wide_float!(f64);
impl_wide_float!(f32);

#[cfg(test)]
mod tests {
    use super::shift_saturate;
    use proptest::prelude::*;

    /// The plain definition: shift, then clamp to the `i64` range.
    fn reference(value: i128, shift: u32) -> i64 {
        let shifted = value >> shift;
        i64::try_from(shifted).unwrap_or(if shifted < 0 { i64::MIN } else { i64::MAX })
    }

    fn check(value: i128) {
        assert_eq!(
            shift_saturate::<32>(value),
            reference(value, 32),
            "{value:#x} >> 32"
        );
        assert_eq!(
            shift_saturate::<16>(value),
            reference(value, 16),
            "{value:#x} >> 16"
        );
    }

    /// The edges of the fitting range for both shifts, one off either side,
    /// and the ends of `i128`.
    #[test]
    fn edges_match_shift_then_clamp() {
        for shift in [16u32, 32] {
            let top = 1i128 << (63 + shift);
            for edge in [top, -top, 0, 1i128 << 64, -(1i128 << 64)] {
                for delta in -2i128..=2 {
                    check(edge + delta);
                }
            }
        }
        check(i128::MAX);
        check(i128::MIN);
        check(i128::MIN + 1);
    }

    proptest! {
        #[test]
        fn random_values_match_shift_then_clamp(high in any::<i64>(), low in any::<u64>(), scale in 0u32..64) {
            // Values of every magnitude: a random high word shifted down.
            let value = ((i128::from(high) << 64) | i128::from(low)) >> scale;
            check(value);
        }
    }
}
