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
