//! Raw-bit access to the fixed-point scalars and their wide types, for
//! reference computations in `i128` (the math tests check the engine's
//! arithmetic bit for bit against them).

use clockwork2d::math::{Scalar, WideScalar};
use fixed::types::{I32F32, I48F16, I64F64, I96F32};

/// A fixed-point scalar seen as raw bits with `FRAC` fraction bits.
pub trait Fixed: Scalar<Wide: WideFixed> {
    /// Fraction bits.
    const FRAC: u32;
    /// The raw two's complement value.
    fn raw(self) -> i128;
    /// The value with these raw bits.
    fn from_raw(bits: i64) -> Self;
}

/// A fixed-point wide type seen as raw `i128` bits with `FRAC` fraction bits.
pub trait WideFixed: WideScalar {
    /// Fraction bits.
    const FRAC: u32;
    /// The raw two's complement value.
    fn raw(self) -> i128;
    /// The value with these raw bits.
    fn from_raw(bits: i128) -> Self;
}

impl Fixed for I32F32 {
    const FRAC: u32 = 32;
    fn raw(self) -> i128 {
        self.to_bits().into()
    }
    fn from_raw(bits: i64) -> Self {
        Self::from_bits(bits)
    }
}

impl Fixed for I48F16 {
    const FRAC: u32 = 16;
    fn raw(self) -> i128 {
        self.to_bits().into()
    }
    fn from_raw(bits: i64) -> Self {
        Self::from_bits(bits)
    }
}

impl WideFixed for I64F64 {
    const FRAC: u32 = 64;
    fn raw(self) -> i128 {
        self.to_bits()
    }
    fn from_raw(bits: i128) -> Self {
        Self::from_bits(bits)
    }
}

impl WideFixed for I96F32 {
    const FRAC: u32 = 32;
    fn raw(self) -> i128 {
        self.to_bits()
    }
    fn from_raw(bits: i128) -> Self {
        Self::from_bits(bits)
    }
}

/// Raw bits of both narrow types' MIN and MAX (both store an `i64`).
pub const RAW_MIN: i128 = i64::MIN as i128;
/// See [`RAW_MIN`].
pub const RAW_MAX: i128 = i64::MAX as i128;

/// Clamps an exact raw result to the narrow range: the saturated value.
pub fn sat(v: i128) -> i128 {
    v.clamp(RAW_MIN, RAW_MAX)
}
