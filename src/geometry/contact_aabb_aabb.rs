//! Contact between two axis-aligned boxes (separating-axis test).
//!
//! # The maths
//!
//! Two axis-aligned boxes have two candidate separating axes, x and y. With
//! `d = c_b − c_a` and half extents `h_a`, `h_b`, the signed gap between the
//! boxes' projections on each axis is
//!
//! ```text
//!     g_x = |d_x| − (h_a.x + h_b.x),     g_y = |d_y| − (h_a.y + h_b.y)
//! ```
//!
//! (negative = the projections overlap by `−g`). The separating-axis theorem
//! says the boxes overlap iff both are `≤ 0`, and the contact is on the axis
//! with the **largest** gap: when overlapping that is the axis of least
//! penetration (the shortest way out); when apart, the axis of greatest
//! separation. The separation is that gap, `max(g_x, g_y)`, and the normal is
//! `±X` or `±Y`, pointing from `a` towards `b` (the sign of `d` on that axis).
//!
//! # Separation when apart on both axes (API decision)
//!
//! When `g_x > 0` and `g_y > 0` the boxes are apart diagonally; the true
//! (Euclidean) distance between them is the corner-to-corner distance
//! `√(g_x² + g_y²)`. This function returns the SAT value `max(g_x, g_y)`
//! instead, with an axis normal:
//!
//! * it is a **lower bound** on the true gap (`max(g_x, g_y) ≤ √(g_x²+g_y²)`),
//!   so a speculative contact built from it is conservative: it can only
//!   start acting early, never let the boxes pass into each other;
//! * it keeps the normal on an axis, which is what a box resting near the
//!   seam between two boxes needs (a diagonal corner normal there would give
//!   the classic "ghost bump");
//! * it needs no square root, and is exact (see below).
//!
//! The price: for diagonally separated boxes, moving `b` by
//! `−separation · normal` closes the gap on the chosen axis only (the boxes'
//! projections then touch on it, and the other axis's gap remains). Whenever
//! the projections overlap on the other axis (always, for touching or
//! penetrating boxes) the moved boxes touch exactly.
//!
//! # Ties and degenerate cases
//!
//! * `g_x == g_y` picks the y axis (the engine-wide convention).
//! * A zero offset on the chosen axis gives the positive axis (`+X` or `+Y`);
//!   in particular coincident centres give `+Y` unless the x gap is larger.
//!   Such a configuration is symmetric, and both orders return the same
//!   normal.
//!
//! # Accuracy and symmetry
//!
//! Only additions, subtractions and an absolute value: the result is
//! **exact** for any boxes inside the world bounds (for `Fx`: the sums stay
//! far below 2³¹), so `Fx` agrees bit for bit with the `f64` reference on
//! inputs exact in both. Beyond the bounds each operation saturates
//! (defined, identical in debug and release). Swapping `a` and `b` negates
//! `d` exactly, so the contact is exactly flipped (except for the zero-offset
//! case above).

use super::{Aabb, Contact};
use crate::math::{Scalar, Vec2};

/// The contact between boxes `a` and `b`: an axis normal (`±X` or `±Y`) from
/// `a` towards `b` and the signed separating-axis gap (negative = penetration
/// depth along that axis).
///
/// When the boxes are apart on both axes the separation is the larger axis
/// gap, a conservative lower bound on the Euclidean gap (see the
/// module notes in `src/geometry/contact_aabb_aabb.rs` for why). Equal gaps pick the y axis; a zero centre
/// offset on the chosen axis gives the positive axis.
///
/// ```
/// use clockwork2d::geometry::*;
/// use clockwork2d::prelude::*;
/// let a = Aabb::new(Vec2::new(fx(0.0), fx(0.0)), Vec2::new(fx(2.0), fx(1.0)));
/// // Resting on top of `a`, sunk in by 0.25.
/// let b = Aabb::new(Vec2::new(fx(1.0), fx(1.75)), Vec2::new(fx(1.0), fx(1.0)));
/// let c = contact_aabb_aabb(&a, &b);
/// assert_eq!((c.normal, c.separation), (Vec2::Y, fx(-0.25)));
/// // Seen from `b`: same separation, opposite normal.
/// assert_eq!(contact_aabb_aabb(&b, &a), c.flipped());
/// ```
#[must_use]
pub fn contact_aabb_aabb<S: Scalar>(a: &Aabb<S>, b: &Aabb<S>) -> Contact<S> {
    let d = b.center - a.center;
    let gap_x = d.x.abs().sub(a.half_extents.x.add(b.half_extents.x));
    let gap_y = d.y.abs().sub(a.half_extents.y.add(b.half_extents.y));
    // Largest gap wins; ties go to y.
    if gap_x > gap_y {
        Contact {
            normal: Vec2::new(axis_sign(d.x), S::ZERO),
            separation: gap_x,
        }
    } else {
        Contact {
            normal: Vec2::new(S::ZERO, axis_sign(d.y)),
            separation: gap_y,
        }
    }
}

/// `−1` for a negative offset, `+1` otherwise (zero maps to the positive
/// axis, the documented tie-break).
#[inline]
fn axis_sign<S: Scalar>(offset: S) -> S {
    if offset.is_negative() {
        S::ONE.neg()
    } else {
        S::ONE
    }
}
