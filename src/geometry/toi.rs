//! Time of impact (TOI) of two shapes moving linearly over one step:
//! [`toi_circle_circle`], [`toi_aabb_aabb`], [`toi_circle_aabb`].
//!
//! # Maths
//!
//! Shape `a` moves by `da` and shape `b` by `db` during the step (linear
//! motion, no rotation), both at constant velocity, for the fraction
//! `t ∈ [0, 1]` of the step. In `b`'s frame, `a`'s centre moves by the
//! relative displacement `d = da − db`, and `a` touches `b` exactly when
//! `a`'s centre is on the boundary of the Minkowski sum of `b` and `a`
//! (both shapes are centrally symmetric, so the sum with `−a` is the sum
//! with `a`), centred on `b`'s centre:
//!
//! * circle + circle: a circle of radius `ra + rb`;
//! * box + box: a box of half extents `ha + hb`;
//! * circle + box: the box grown by `r` — four faces pushed out by `r` and
//!   four quarter circles of radius `r` around the box's corners (a
//!   "rounded box"); faces and corners are both handled exactly.
//!
//! So the TOI is a ray cast of `a`'s centre along `d` against that shape,
//! and is analytic (no iteration). The cast is done with the direction
//! `u = d / L`, `L = max(|d.x|, |d.y|)` (the max-norm: no square root, one
//! component of `u` is exactly ±1, `|u| ∈ [1, √2]`), out to the parameter
//! `L`; a hit at parameter `s ≤ L` is at `t = s / L`, a division taken only
//! when `L > 0` and whose quotient is at most 1. Zero relative motion
//! (`L = 0`) is never divided by: the answer is then `Overlapping` or
//! `Miss`.
//!
//! The outcomes, the normal conventions and the accuracy are documented on
//! [`Toi`].

use super::segment_cast::{Cast, cast_box, cast_circle, cast_rounded_box};
use super::{Aabb, Circle};
use crate::math::Fx;
use crate::math::{Scalar, Vec2};

/// The outcome of a time-of-impact query.
///
/// The queries take each shape's displacement over the step (`da`, `db`,
/// linear motion) and work with the relative displacement `d = da − db`,
/// cast along the direction `u = d / L`, `L = max(|d.x|, |d.y|)` (see
/// `toi.rs` for the maths).
///
/// # Outcomes and conventions
///
/// * [`Toi::Overlapping`]: the shapes overlap **or touch** at `t = 0` (the
///   shapes are closed), whatever the motion; the contact solver handles
///   it. Decided exactly.
/// * [`Toi::Hit`]: the first `t` at which they touch, with the unit normal
///   **from `a` to `b`** at that moment (the geometry module's contact
///   convention).
///   - Circle–circle: along the line of centres.
///   - Box–box: the axis of the faces that meet, `±X` or `±Y`. When both
///     axes meet at the same instant (corner against corner), the **y**
///     axis (the module's tie rule). The tie is decided exactly for `u`,
///     which is exact when `|d.x| = |d.y|` or when the smaller component
///     over the larger is representable; otherwise `u` is rounded by an ulp
///     and so is the order of two almost simultaneous contacts.
///   - Circle–box: a face normal `±X`/`±Y` when the circle meets a face,
///     and the unit vector from the circle's centre to the box's corner when
///     it meets a corner (at the face/corner boundary the two agree).
/// * [`Toi::Miss`]: they do not touch during the step (`t ∈ [0, 1]`),
///   including shapes moving apart or side by side and zero relative
///   motion.
/// * Grazing contact (touching at a single instant without overlapping)
///   counts as a hit, and so does contact exactly at `t = 1`.
///
/// # Accuracy (`Fx`, inputs within the world bounds)
///
/// `t` has 32 fraction bits, so the relative position it stands for,
/// `t·d`, is resolved to about `|d|·2⁻³²`; rounding `u` adds at most
/// `L·2⁻³²`; the cast itself is within 4 ulps of the shape. The shapes'
/// separation at the reported `t` is therefore within about `(2|d| + 4)`
/// ulps of zero (`|d|` in units): for a displacement of 100 units, about
/// 5e-8. Near-grazing contacts have an ill-conditioned `t` (as in the ray
/// casts), but the contact position stays within that bound.
///
/// A normal from a circle (circle–circle, or a circle at a box's corner)
/// is the cast's hit point minus the centre over the Minkowski radius `R`
/// (`ra + rb`, or the circle's radius): the point is off by the bound
/// above plus an ulp per component, so the normal's direction and length
/// are within about `(bound + 2 ulps) / R` — a few ulps for `R ≥ 1`, but
/// only roughly unit when `R` is a few ulps (like the contact normals'
/// `ulp·(1 + 1/L)`).
///
/// ```
/// use clockwork2d::geometry::*;
/// use clockwork2d::prelude::*;
/// let a = Circle::new(Vec2::ZERO, fx(1.0));
/// let b = Circle::new(Vec2::new(fx(10.0), fx(0.0)), fx(1.0));
/// let toi = toi_circle_circle(&a, Vec2::new(fx(16.0), fx(0.0)), &b, Vec2::ZERO);
/// assert_eq!(toi, Toi::Hit { t: fx(0.5), normal: Vec2::X });
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Toi<S: Scalar = Fx> {
    /// The shapes first touch at fraction `t` of the step.
    Hit {
        /// Fraction of the step, in `[0, 1]`.
        t: S,
        /// Unit normal from `a` to `b` at the moment of contact.
        normal: Vec2<S>,
    },
    /// The shapes already overlap or touch at `t = 0`.
    Overlapping,
    /// The shapes do not touch during the step.
    Miss,
}

/// Runs a cast of `a`'s centre along the relative displacement `d`, with
/// `cast(dir, s_max)` casting from `a`'s centre against the Minkowski shape.
fn toi_from_cast<S: Scalar>(d: Vec2<S>, cast: impl FnOnce(Vec2<S>, S) -> Cast<S>) -> Toi<S> {
    let len = d.x.abs().max(d.y.abs());
    // u = d / L: |d.x|, |d.y| ≤ L, so both quotients are in [-1, 1]. For a
    // zero displacement the cast gets a zero direction and a zero range, and
    // only reports whether the shapes overlap.
    let (dir, s_max) = if len.is_positive() {
        (Vec2::new(d.x.div(len), d.y.div(len)), len)
    } else {
        (Vec2::ZERO, S::ZERO)
    };
    match cast(dir, s_max) {
        Cast::Inside => Toi::Overlapping,
        Cast::Miss => Toi::Miss,
        Cast::Hit { s, normal, .. } => {
            // 0 ≤ s ≤ s_max = L, so s / L is in [0, 1]; the clamp only
            // guards the float references' rounding. A zero L cannot hit
            // (the cast with a zero direction cannot), but is defined.
            let t = if len.is_positive() {
                s.div(len).clamp(S::ZERO, S::ONE)
            } else {
                S::ZERO
            };
            // The cast's normal points out of b's Minkowski shape, towards
            // a; the contact normal points from a to b.
            Toi::Hit { t, normal: -normal }
        }
    }
}

/// Time of impact of two moving circles.
///
/// `da` and `db` are the circles' displacements over the step. The
/// relative motion of `a`'s centre is cast against the circle of radius
/// `ra + rb` around `b`'s centre. The normal at a hit is the unit vector
/// from `a`'s centre to `b`'s centre at that moment. See the
/// outcomes and the accuracy on [`Toi`].
///
/// ```
/// use clockwork2d::geometry::*;
/// use clockwork2d::prelude::*;
/// let a = Circle::new(Vec2::ZERO, fx(1.0));
/// let b = Circle::new(Vec2::new(fx(5.0), fx(0.0)), fx(1.0));
/// // Both move towards each other by 2: the gap of 3 closes at t = 3/4.
/// let toi = toi_circle_circle(&a, Vec2::new(fx(2.0), fx(0.0)), &b, Vec2::new(fx(-2.0), fx(0.0)));
/// assert_eq!(toi, Toi::Hit { t: fx(0.75), normal: Vec2::X });
/// // Touching already: overlapping, whatever the motion.
/// let c = Circle::new(Vec2::new(fx(2.0), fx(0.0)), fx(1.0));
/// assert_eq!(toi_circle_circle(&a, Vec2::ZERO, &c, Vec2::ZERO), Toi::Overlapping);
/// // Moving apart: a miss.
/// assert_eq!(toi_circle_circle(&a, Vec2::new(fx(-1.0), fx(0.0)), &b, Vec2::ZERO), Toi::Miss);
/// ```
#[must_use]
pub fn toi_circle_circle<S: Scalar>(
    a: &Circle<S>,
    da: Vec2<S>,
    b: &Circle<S>,
    db: Vec2<S>,
) -> Toi<S> {
    let radius = a.radius.abs().add(b.radius.abs());
    toi_from_cast(da - db, |dir, s_max| {
        cast_circle(a.center, dir, s_max, b.center, radius)
    })
}

/// Time of impact of two moving axis-aligned boxes.
///
/// `da` and `db` are the boxes' displacements over the step. The relative
/// motion of `a`'s centre is cast against the box of half extents
/// `ha + hb` around `b`'s centre with the exact slab test of
/// [`ray_aabb`](super::ray_aabb). The normal is `±X` or `±Y`, from `a` to
/// `b`; when the boxes meet corner to corner (both axes close at the same
/// instant), it is the **y** axis. See [`Toi`].
///
/// ```
/// use clockwork2d::geometry::*;
/// use clockwork2d::prelude::*;
/// let a = Aabb::new(Vec2::ZERO, Vec2::new(fx(1.0), fx(1.0)));
/// let b = Aabb::new(Vec2::new(fx(0.0), fx(-5.0)), Vec2::new(fx(2.0), fx(1.0)));
/// // a falls by 6 onto b: the gap of 3 closes at t = 1/2, normal -Y.
/// let toi = toi_aabb_aabb(&a, Vec2::new(fx(0.0), fx(-6.0)), &b, Vec2::ZERO);
/// assert_eq!(toi, Toi::Hit { t: fx(0.5), normal: Vec2::new(fx(0.0), fx(-1.0)) });
/// ```
#[must_use]
pub fn toi_aabb_aabb<S: Scalar>(a: &Aabb<S>, da: Vec2<S>, b: &Aabb<S>, db: Vec2<S>) -> Toi<S> {
    let half = a.half_extents.abs() + b.half_extents.abs();
    toi_from_cast(da - db, |dir, s_max| {
        cast_box(a.center, dir, s_max, b.center, half)
    })
}

/// Time of impact of a moving circle `a` and a moving axis-aligned box `b`.
///
/// `da` and `db` are the displacements over the step. The relative motion
/// of the circle's centre is cast against the box grown by the radius, with
/// round corners (faces and corner arcs handled exactly). The normal points
/// from the circle to the box: `±X`/`±Y` when the circle meets a face, the
/// unit vector from the circle's centre to the box's corner when it meets a
/// corner. For a box moving against a circle, swap the arguments and negate
/// the normal. See [`Toi`].
///
/// ```
/// use clockwork2d::geometry::*;
/// use clockwork2d::prelude::*;
/// let b = Aabb::new(Vec2::ZERO, Vec2::new(fx(1.0), fx(1.0)));
/// // A circle of radius 1 moving left onto the box's right face.
/// let a = Circle::new(Vec2::new(fx(4.0), fx(0.5)), fx(1.0));
/// let toi = toi_circle_aabb(&a, Vec2::new(fx(-4.0), fx(0.0)), &b, Vec2::ZERO);
/// assert_eq!(toi, Toi::Hit { t: fx(0.5), normal: Vec2::new(fx(-1.0), fx(0.0)) });
/// // Diagonally onto the corner (1, 1): touches when the centre is at
/// // distance 1 from the corner; the normal points at the corner.
/// let c = Circle::new(Vec2::new(fx(4.0), fx(4.0)), fx(1.0));
/// match toi_circle_aabb(&c, Vec2::new(fx(-4.0), fx(-4.0)), &b, Vec2::ZERO) {
///     Toi::Hit { t, normal } => {
///         assert!((t.to_f64() - (3.0 - 0.5f64.sqrt()) / 4.0).abs() < 1e-9);
///         assert!((normal.x.to_f64() + 0.5f64.sqrt()).abs() < 1e-9);
///     }
///     other => panic!("{other:?}"),
/// }
/// ```
#[must_use]
pub fn toi_circle_aabb<S: Scalar>(a: &Circle<S>, da: Vec2<S>, b: &Aabb<S>, db: Vec2<S>) -> Toi<S> {
    toi_from_cast(da - db, |dir, s_max| {
        cast_rounded_box(a.center, dir, s_max, b.center, b.half_extents, a.radius)
    })
}
