//! Numbers: the [`Scalar`] trait, the fixed-point default [`Fx`], wide
//! products and [`Vec2`].
//!
//! # World bounds
//!
//! With `Fx = I32F32` a coordinate can reach ±2³¹, but the engine needs
//! headroom for differences and products:
//!
//! * the difference of two in-bounds coordinates must fit: |Δ| ≤ 2·B;
//! * squared lengths and dot products are formed in `I64F64`, exact while
//!   below 2⁶³, i.e. for vectors up to 2^31.5 long;
//! * narrow products (`a.mul(b)`) appear only where one factor is a unit
//!   vector component, a dimensionless ratio, or a time step.
//!
//! The world therefore keeps every body inside ±[`WORLD_LIMIT`] = 2¹⁵ =
//! 32 768 units on each axis (documented in `WorldSettings`); within it the
//! squared distance between any two points, (2·2¹⁵)²·2 = 2³³, is exact in
//! the wide type and a ray of length up to 2¹⁷ stays inside the range.
//! Beyond the bounds, results saturate (defined, identical in debug and
//! release) rather than being exact.

mod fixed_impls;
mod float_impls;
mod isqrt;
mod scalar;
mod vec2;
mod wide;

pub use fixed_impls::{Fx, fx, vec2};
pub use scalar::Scalar;
pub use vec2::Vec2;
pub use wide::{WideFloat, WideScalar};

/// Half-extent of the documented world: every coordinate of every body is
/// kept within ±`WORLD_LIMIT` units (2¹⁵ = 32 768), which keeps all products
/// the engine forms exact in the wide type (see the module docs).
pub const WORLD_LIMIT: i32 = 1 << 15;
