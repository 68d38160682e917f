//! Shared internals of the ray casts ([`ray_circle`](super::ray_circle),
//! [`ray_aabb`](super::ray_aabb)) and the time-of-impact queries
//! ([`toi`](super::toi)): a parametric segment
//!
//! ```text
//! P(s) = origin + s·dir,   0 ≤ s ≤ s_max
//! ```
//!
//! cast against a solid circle, a solid box and a solid rounded box (a box
//! grown by a radius, with round corners: the Minkowski sum of a box and a
//! circle).
//!
//! `dir` need not be a unit vector: `s` is measured in units of `|dir|`.
//! The precision statements assume `|dir|` between 1/2 and 2 (a ray's unit
//! direction, or a displacement divided by its max-norm, whose length is in
//! `[1, √2]`). A zero `dir` is allowed and never divides by zero: the cast
//! then only reports whether `origin` is inside.
//!
//! Every shape is closed: a point on the boundary is inside (the same rule
//! as [`Circle::contains_point`](super::Circle::contains_point) and
//! [`Aabb::contains_point`](super::Aabb::contains_point)).
//!
//! Error bounds below are for `Fx` (`I32F32`, one ulp `u = 2⁻³²`) with all
//! inputs inside the world bounds (coordinates within ±2¹⁵, `s_max ≤ 2¹⁷`).
//! Outside those bounds every operation still saturates to a defined,
//! deterministic result; it is just no longer accurate.
//!
//! # Where each solid is
//!
//! * `circle.rs`: [`cast_circle`] and [`circle_roots`], on the line–circle
//!   quadratic in its stable form (the discriminant by Lagrange's identity,
//!   the roots solved again from the foot of the perpendicular, one guarded
//!   Newton step), the only cast whose answer is rounded beyond one ulp.
//! * `aabb.rs`: [`cast_box`], the slab test made exact by cross
//!   multiplication in the wide type; the one division is the reported `s`.
//! * `rounded_aabb.rs`: [`cast_rounded_box`], the Minkowski sum of a box and
//!   a circle, as a cast against the grown box and, in a corner, against the
//!   corner's circle (both of the above).
//!
//! All three answer with [`Cast`] (inside, first hit with point and outward
//! normal, or miss), so the ray casts and times of impact built on them
//! share one set of outcomes.

mod aabb;
mod circle;
mod rounded_aabb;

use crate::math::{Scalar, Vec2};

pub(crate) use aabb::cast_box;
pub(crate) use circle::{cast_circle, circle_roots};
pub(crate) use rounded_aabb::cast_rounded_box;

/// The outcome of a cast.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Cast<S: Scalar> {
    /// `origin` is inside the shape or on its boundary.
    Inside,
    /// The first point of the segment on the shape's boundary.
    Hit {
        /// The parameter, in `[0, s_max]`.
        s: S,
        /// The point on the boundary (close to `origin + s·dir`, see the
        /// function docs for which one is exact).
        point: Vec2<S>,
        /// The unit outward normal of the shape at `point`.
        normal: Vec2<S>,
    },
    /// The segment never touches the shape.
    Miss,
}
