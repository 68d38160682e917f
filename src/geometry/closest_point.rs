//! The closest point on a line segment to a given point.
//!
//! # The formula
//!
//! With `d = b - a` and `w = p - a`, the point of the infinite line through
//! `a` and `b` nearest to `p` is `a + t·d` with
//!
//! ```text
//!     t = (w·d) / (d·d)            (the origin document's x = ((p-a)·(b-a)) / |b-a|²)
//! ```
//!
//! and the nearest point of the *segment* is obtained by clamping `t` to
//! `[0, 1]` (the squared distance `|w - t·d|²` is a convex parabola in `t`).
//!
//! # Dividing wide by wide without overflow or floats
//!
//! `w·d` and `d·d` are formed exactly in the wide type (`I64F64` for `Fx`):
//! within the world bounds `|d|, |w| ≤ 2¹⁶·√2`, so both are below 2³⁴, far from
//! the wide range, but `d·d` can exceed the *narrow* range (2³¹) and, for a
//! short segment, be far below one narrow ulp (a segment of length 2⁻²⁰ has
//! `d·d = 2⁻⁴⁰`). Narrowing either operand before dividing would lose all
//! precision in one of those regimes.
//!
//! The clamps are decided exactly on the wide values (`w·d ≤ 0` gives
//! `t = 0`, `w·d ≥ d·d` gives `t = 1`), so a division is only needed for
//! `0 < w·d < d·d`, where the quotient lies in `(0, 1)`. There it is computed
//! by **restoring binary long division** in the wide type: keep a remainder
//! `r < d·d`; for each quotient bit, double `r` (no overflow: `2r < 2·d·d`,
//! below 2³⁵), and if `r ≥ d·d` subtract `d·d` and set the bit. This uses only
//! addition, subtraction and comparison, is exact, has no magnitude-dependent
//! branches to get wrong, and behaves identically on every target. (Beyond
//! the world bounds the doubling may saturate; the invariant `r < d·d` still
//! holds, so `t` stays in `[0, 1]`, merely inexact — defined, never a panic.)
//!
//! # Accuracy (for `Fx`, inputs inside ±`WORLD_LIMIT`)
//!
//! * **`t`**: the first pass gives the quotient truncated to the scalar's ulp
//!   (32 bits for `Fx`); a second pass gives the next 32 bits, used to round
//!   `t` to nearest. So `|t − t*| ≤ ½ ulp` (2⁻³³ ≈ 1.2e-10), and `t` is
//!   exactly 0 or 1 whenever the exact `t*` is clamped.
//! * **`point`**: `a + t·d` with a rounded `t` would be off by up to
//!   `|d|·½ ulp` (1.5e-5 for a segment spanning the world). Instead each
//!   component is `a + d·t_hi + (d·t_lo)·ulp`, where `t_hi` (truncated
//!   quotient) and `t_lo` (the next 32 bits, as a fraction) come from the two
//!   passes: `a + d·t_hi` is exact in the wide type and the correction term is
//!   below `|d|·ulp` in magnitude, so it is formed in the narrow type to within
//!   one ulp. Each component is therefore within **2 ulps** of the exact
//!   closest point (≈ 4.7e-10), independent of the segment's length: below
//!   one ulp for the correction term's rounding, below one for the final
//!   narrowing (both round toward −∞), plus `|d|·2⁻⁶⁴` from the quotient bits
//!   that were not computed (at most 2⁻¹⁵ ulp inside the bounds; strictly,
//!   the bound is `2 ulp + |d|·2⁻⁶⁴`). The result is then clamped to the segment's
//!   bounding box, which can only move it toward the exact point.
//!
//! For `I48F16` the same holds with its ulp (2⁻¹⁶) and 16-bit passes; for the
//! float reference types the passes stop at `EPSILON` (2⁻⁵² for `f64`).
//!
//! # Cost
//!
//! Two passes of `frac_bits` iterations (64 in all for `Fx`), each a wide
//! double, compare, select and subtract with no data-dependent branch; no
//! hardware division, no square root. Measured at roughly 200 ns for `Fx`
//! (about four times a `Vec2::length`): fine off the hot path. Should it
//! become hot, a quotient primitive on `WideScalar` (exact `I64F64`
//! division narrowed once) would replace the first pass.

use serde::{Deserialize, Serialize};

use crate::math::Fx;
use crate::math::{Scalar, Vec2, WideScalar};

/// The point of a segment nearest to a query point, with its parameter.
///
/// `point` is `a + t·(b - a)` for the segment `a → b` (see
/// [`closest_point_on_segment`] for the accuracy of each field).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct SegmentPoint<S: Scalar = Fx> {
    /// The closest point of the segment.
    pub point: Vec2<S>,
    /// Its parameter along the segment, in `[0, 1]`: 0 at `a`, 1 at `b`.
    pub t: S,
}

/// The point of the segment `a → b` closest to `p`.
///
/// Implements the origin document's `t = ((p-a)·(b-a)) / |b-a|²`, clamped to
/// `[0, 1]`, with `point = a + t·(b-a)`:
///
/// * `t = 0` and `point = a` (exactly) if the projection of `p` falls before
///   `a`, or if the segment has zero length (`a == b`);
/// * `t = 1` and `point = b` (exactly) if it falls after `b`;
/// * otherwise, for `Fx` inside the world bounds, `t` is within ½ ulp and each
///   component of `point` within 2 ulps of the exact values (derivation in the
///   module notes in `src/geometry/closest_point.rs`).
///
/// Never divides by zero, never panics; inputs beyond the world bounds give a
/// defined (saturated) result with `t` in `[0, 1]`.
///
/// ```
/// use clockwork2d::geometry::*;
/// use clockwork2d::math::*;
/// use clockwork2d::prelude::*;
/// let a = Vec2::new(fx(0.0), fx(0.0));
/// let b = Vec2::new(fx(4.0), fx(0.0));
/// let c = closest_point_on_segment(a, b, Vec2::new(fx(1.0), fx(3.0)));
/// assert_eq!(c.t, fx(0.25));
/// assert_eq!(c.point, Vec2::new(fx(1.0), fx(0.0)));
/// // Beyond an end: clamped to it.
/// let c = closest_point_on_segment(a, b, Vec2::new(fx(9.0), fx(-1.0)));
/// assert_eq!((c.t, c.point), (fx(1.0), b));
/// // A zero-length segment is its own closest point.
/// let c = closest_point_on_segment(a, a, Vec2::new(fx(9.0), fx(-1.0)));
/// assert_eq!((c.t, c.point), (fx(0.0), a));
/// ```
#[must_use]
pub fn closest_point_on_segment<S: Scalar>(a: Vec2<S>, b: Vec2<S>, p: Vec2<S>) -> SegmentPoint<S> {
    let d = b - a;
    let w = p - a;
    // Both exact in the wide type within the world bounds.
    let den = d.length_squared_wide();
    let num = w.dot_wide(d);

    // `den <= 0` only for a zero-length segment (for the float references,
    // also when |d|² underflows): the whole segment is `a`.
    if den <= S::Wide::ZERO || num <= S::Wide::ZERO {
        return SegmentPoint {
            point: a,
            t: S::ZERO,
        };
    }
    if num >= den {
        return SegmentPoint {
            point: b,
            t: S::ONE,
        };
    }

    // 0 < num < den: t* = num/den in (0, 1).
    // t* = t_hi + t_lo·ulp + (tail < ulp²), with t_hi, t_lo in [0, 1).
    let (t_hi, rem) = quotient_fraction::<S>(num, den);
    let (t_lo, _) = quotient_fraction::<S>(rem, den);

    // Round t to nearest: t_lo ≥ ½ means the discarded part is ≥ ½ ulp.
    // t_hi ≤ 1 − ulp, so the increment cannot exceed 1.
    let t = if t_lo >= S::ONE.half() {
        t_hi.add(S::EPSILON)
    } else {
        t_hi
    };

    let point = Vec2::new(
        lerp_component(a.x, d.x, t_hi, t_lo),
        lerp_component(a.y, d.y, t_hi, t_lo),
    );
    // The exact point lies in the segment's bounding box; clamping to it
    // removes any rounding overshoot past an end and never increases the
    // error.
    let point = point.clamp(a.min(b), a.max(b));
    SegmentPoint { point, t }
}

/// `a + d·(t_hi + t_lo·ulp)` for one component, with `a + d·t_hi` exact in the
/// wide type and the small correction `d·t_lo·ulp` (|·| < |d|·ulp) formed in
/// the narrow type; one narrowing at the end.
#[inline]
fn lerp_component<S: Scalar>(a: S, d: S, t_hi: S, t_lo: S) -> S {
    let correction = d.mul(t_lo).mul(S::EPSILON);
    S::Wide::from_narrow(a)
        .add(d.wide_mul(t_hi))
        .add(S::Wide::from_narrow(correction))
        .narrow()
}

/// Restoring long division for `0 ≤ rem < den`: returns `q` = the fraction
/// `rem/den` truncated to the scalar's `EPSILON` (bits ½, ¼, …, `EPSILON`),
/// and the final remainder `rem'` with `rem/den = q + (rem'/den)·EPSILON`,
/// `0 ≤ rem' < den`.
///
/// Invariant: `0 ≤ r < den` before each step, so `2r < 2·den` and after the
/// conditional subtraction again `0 ≤ r < den`. If the doubling saturates
/// (only for `den` beyond half the wide range, far outside the world bounds),
/// `MAX − den < den` still keeps the invariant, so the result stays in
/// `[0, 1)`.
///
/// Iterations: the number of fraction bits (32 for `Fx`, 16 for `I48F16`,
/// 52 for `f64`, 23 for `f32`). `step` is a power of two from ½ down to
/// `EPSILON`, both exact in every scalar; halving reaches `EPSILON` exactly,
/// and the `<=` test ends the loop even if it did not.
#[inline]
fn quotient_fraction<S: Scalar>(rem: S::Wide, den: S::Wide) -> (S, S::Wide) {
    let mut r = rem;
    let mut q = S::ZERO;
    let mut step = S::ONE.half();
    loop {
        r = r.add(r);
        // Written as selects rather than a branch: the quotient bits are
        // unpredictable, and a mispredicted branch per bit would dominate.
        let take = r >= den;
        r = r.sub(if take { den } else { S::Wide::ZERO });
        q = q.add(if take { step } else { S::ZERO });
        if step <= S::EPSILON {
            return (q, r);
        }
        step = step.half();
    }
}
