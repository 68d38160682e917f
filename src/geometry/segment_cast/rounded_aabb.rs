//! A segment cast against a solid rounded box (a box grown by a radius),
//! built on the box and circle casts (see the [module notes](super)).

use super::{Cast, cast_box, cast_circle};
use crate::math::{Scalar, Vec2};

/// Casts the segment against the solid rounded box: the box `(center,
/// half)` grown by `radius` (`|half|`, `|radius|` are used), i.e. the set of
/// points within `radius` of the box. It is the Minkowski sum used for a
/// moving circle against a box: four flat faces pushed out by `radius` and
/// four quarter circles of radius `radius` around the box's corners.
///
/// # Method
///
/// 1. Inside test, exact: with `q = |origin − center|` per axis, the
///    distance to the box is `|(max(q.x − h.x, 0), max(q.y − h.y, 0))|`,
///    compared squared with `r²` in the wide type.
/// 2. Cast against the box grown by `r` on each axis (it contains the
///    rounded box, so a miss there is a miss). If the entry point is within
///    the inner box's extent on the other axis, it is on a flat face: done.
/// 3. Otherwise the entry point is in a corner square `[h, h + r]²` (up to
///    signs), and the answer is the cast against that corner's circle: from
///    inside the corner square the segment can only leave it through the
///    two outer sides (leaving the grown box for good, as it is convex) or
///    through the two inner sides, which lie inside the corner circle; so
///    it either hits that circle first or misses the rounded box.
///
///    If the origin itself is inside the grown box but outside the rounded
///    box, it is in a corner square, and step 3 applies from there.
/// 4. The inner sides of a corner square touch the corner circle only at
///    its two tangent points `(h.x + r, h.y)` and `(h.x, h.y + r)`. A
///    segment through (or an ulp beside) a tangent point, running almost
///    along the face beyond it, grazes the circle: in exact arithmetic it
///    touches it, but the circle cast's rounding (a few ulps, see
///    `circle.rs`) may call it a miss, and the segment then runs on inside
///    the face region, `s_max·|dir_face|` deep by its end (a fuzzed TOI went
///    6e-5 into a box this way). So a corner miss is checked against the
///    two flat slabs whose union with the four circles is the rounded box,
///    the box grown by `r` on x only and on y only, with the exact box
///    cast: the first entry of either is the answer (they cannot contain
///    the origin: step 1 is exact and would have said inside).
///
/// At the face/corner boundary both answers agree (the circle's normal
/// there is the face normal), so classifying a point one ulp off that
/// boundary changes the result by rounding only.
#[must_use]
pub(crate) fn cast_rounded_box<S: Scalar>(
    origin: Vec2<S>,
    dir: Vec2<S>,
    s_max: S,
    center: Vec2<S>,
    half: Vec2<S>,
    radius: S,
) -> Cast<S> {
    let half = half.abs();
    let radius = radius.abs();
    let q = (origin - center).abs();
    let outside = Vec2::new(q.x.sub(half.x).max(S::ZERO), q.y.sub(half.y).max(S::ZERO));
    if outside.length_squared_wide() <= radius.wide_mul(radius) {
        return Cast::Inside;
    }
    let grown = half + Vec2::new(radius, radius);
    // The corner of the inner box on the side of `p`.
    let corner_near = |p: Vec2<S>| {
        let rel = p - center;
        Vec2::new(
            if rel.x.is_negative() {
                center.x.sub(half.x)
            } else {
                center.x.add(half.x)
            },
            if rel.y.is_negative() {
                center.y.sub(half.y)
            } else {
                center.y.add(half.y)
            },
        )
    };
    // Step 3, with step 4 when the corner's circle is missed.
    let corner_or_faces = |corner: Vec2<S>| match cast_circle(origin, dir, s_max, corner, radius) {
        Cast::Miss => cast_face_slabs(origin, dir, s_max, center, half, radius),
        found => found,
    };
    let hit = match cast_box(origin, dir, s_max, center, grown) {
        Cast::Miss => return Cast::Miss,
        // Inside the grown box but not the rounded box: in a corner square.
        Cast::Inside => return corner_or_faces(corner_near(origin)),
        Cast::Hit { s, point, normal } => (s, point, normal),
    };
    let (_, point, normal) = hit;
    let rel = point - center;
    // The coordinate along the face (the axis the normal is not on).
    let on_face = if normal.x == S::ZERO {
        rel.x.abs() <= half.x
    } else {
        rel.y.abs() <= half.y
    };
    if on_face {
        return Cast::Hit {
            s: hit.0,
            point,
            normal,
        };
    }
    corner_or_faces(corner_near(point))
}

/// The first entry of the segment into the two flat slabs of the rounded
/// box: the box grown by `radius` along x only and along y only (step 4 of
/// [`cast_rounded_box`]). Both casts are exact in their decisions; the
/// earlier entry wins (on a tie, the y slab, the module's tie rule).
fn cast_face_slabs<S: Scalar>(
    origin: Vec2<S>,
    dir: Vec2<S>,
    s_max: S,
    center: Vec2<S>,
    half: Vec2<S>,
    radius: S,
) -> Cast<S> {
    // The slab's flat-face normal on the entry point's side.
    let with_face_normal = |found: Cast<S>, on_x: bool| match found {
        Cast::Hit { s, point, .. } => {
            let rel = point - center;
            let side = |v: S| {
                if v.is_negative() {
                    S::ONE.neg()
                } else {
                    S::ONE
                }
            };
            let normal = if on_x {
                Vec2::new(side(rel.x), S::ZERO)
            } else {
                Vec2::new(S::ZERO, side(rel.y))
            };
            Cast::Hit { s, point, normal }
        }
        other => other,
    };
    let x_slab = Vec2::new(half.x.add(radius), half.y);
    let y_slab = Vec2::new(half.x, half.y.add(radius));
    let along_x = with_face_normal(cast_box(origin, dir, s_max, center, x_slab), true);
    let along_y = with_face_normal(cast_box(origin, dir, s_max, center, y_slab), false);
    match (along_x, along_y) {
        // Not reached when the origin is outside the rounded box (step 1
        // is exact); kept consistent rather than unreachable.
        (Cast::Inside, _) | (_, Cast::Inside) => Cast::Inside,
        (Cast::Miss, other) | (other, Cast::Miss) => other,
        (Cast::Hit { s: sx, .. }, Cast::Hit { s: sy, .. }) => {
            if sx < sy {
                along_x
            } else {
                along_y
            }
        }
    }
}
