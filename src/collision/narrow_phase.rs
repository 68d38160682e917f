//! Narrow phase: one function per shape pair, chosen by the shapes.

use crate::geometry::{
    Aabb, Circle, Contact, Shape, Toi, contact_aabb_aabb, contact_aabb_circle, contact_circle_aabb,
    contact_circle_circle, toi_aabb_aabb, toi_circle_aabb, toi_circle_circle,
};
use crate::math::{Scalar, Vec2};

/// The contact between shape `a` at `pa` and shape `b` at `pb` (normal from
/// a to b).
#[inline]
pub(crate) fn contact_between<S: Scalar>(
    a: &Shape<S>,
    pa: Vec2<S>,
    b: &Shape<S>,
    pb: Vec2<S>,
) -> Contact<S> {
    match (*a, *b) {
        (Shape::Circle { radius: ra }, Shape::Circle { radius: rb }) => {
            contact_circle_circle(&Circle::new(pa, ra), &Circle::new(pb, rb))
        }
        (Shape::Circle { radius }, Shape::Aabb { half_extents }) => {
            contact_circle_aabb(&Circle::new(pa, radius), &Aabb::new(pb, half_extents))
        }
        (Shape::Aabb { half_extents }, Shape::Circle { radius }) => {
            contact_aabb_circle(&Aabb::new(pa, half_extents), &Circle::new(pb, radius))
        }
        (Shape::Aabb { half_extents: ha }, Shape::Aabb { half_extents: hb }) => {
            contact_aabb_aabb(&Aabb::new(pa, ha), &Aabb::new(pb, hb))
        }
    }
}

/// Time of impact of shape `a` at `pa` moving by `da` against shape `b` at
/// `pb` moving by `db` (normal from a to b).
#[inline]
pub(crate) fn shape_toi<S: Scalar>(
    a: &Shape<S>,
    pa: Vec2<S>,
    da: Vec2<S>,
    b: &Shape<S>,
    pb: Vec2<S>,
    db: Vec2<S>,
) -> Toi<S> {
    match (*a, *b) {
        (Shape::Circle { radius: ra }, Shape::Circle { radius: rb }) => {
            toi_circle_circle(&Circle::new(pa, ra), da, &Circle::new(pb, rb), db)
        }
        (Shape::Circle { radius }, Shape::Aabb { half_extents }) => toi_circle_aabb(
            &Circle::new(pa, radius),
            da,
            &Aabb::new(pb, half_extents),
            db,
        ),
        (Shape::Aabb { half_extents }, Shape::Circle { radius }) => {
            // Swap roles and flip the normal back to a → b.
            match toi_circle_aabb(
                &Circle::new(pb, radius),
                db,
                &Aabb::new(pa, half_extents),
                da,
            ) {
                Toi::Hit { t, normal } => Toi::Hit { t, normal: -normal },
                other => other,
            }
        }
        (Shape::Aabb { half_extents: ha }, Shape::Aabb { half_extents: hb }) => {
            toi_aabb_aabb(&Aabb::new(pa, ha), da, &Aabb::new(pb, hb), db)
        }
    }
}

/// Whether two circles are certainly too far apart to be in contact this
/// substep, decided without a square root (a cheap reject before
/// [`contact_between`], which normalises the centre offset).
///
/// The step keeps a pair when `s ≤ margin + max(0, −v_n)·h`, with
/// `s = |d| − (r_a + r_b)` and `v_n = Δv·n`. Since `|v_n| ≤ |Δv|₂ ≤
/// |Δv_x| + |Δv_y| = L₁`, the pair is dropped whenever
/// `|d| > R = r_a + r_b + margin + L₁·h + ε`, i.e. `|d|² > R²`, compared
/// exactly in the wide type. `ε` absorbs the rounding of the exact test, so
/// this never drops a pair that test would keep (the result is bit-identical
/// with or without the reject): the computed `|d|` is at most one ulp low;
/// the computed normal is off by at most `2 ulp/|d| + 2 ulp` relative, which
/// moves `v_n·h ≤ L₁·h < |d|` by at most `2 ulp + 2 ulp·R`; the dot product and
/// the products with `h` round by a few ulps more. `ε = 16 ulp + R/256`
/// covers all of it for every scalar with at least 9 fraction bits (and the
/// relative errors of the float references, near 2⁻²³).
#[inline]
pub(crate) fn circles_out_of_reach<S: Scalar>(
    radii: S,
    offset: Vec2<S>,
    relative_velocity: Vec2<S>,
    margin: S,
    h: S,
    one_256th: S,
) -> bool {
    let speed_bound = relative_velocity.x.abs().add(relative_velocity.y.abs());
    let reach = radii.add(margin).add(speed_bound.mul(h));
    let bound = reach.add(reach.mul(one_256th)).add(S::EPSILON.mul_int(16));
    offset.length_squared_wide() > bound.wide_mul(bound)
}
