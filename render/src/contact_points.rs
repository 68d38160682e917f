//! [`ContactPoints`]: the engine's contact between two placed shapes, plus
//! the closest points on each surface, for drawing.

use clockwork2d::geometry::{
    Aabb, Circle, Contact, Shape, contact_aabb_aabb, contact_aabb_circle, contact_circle_aabb,
    contact_circle_circle,
};
use clockwork2d::math::Vec2;
use clockwork2d::prelude::Scalar;

/// A contact as the engine computes it, and where it touches each shape.
///
/// `contact` is the engine's own (fixed-point) answer; the points are
/// derived from it at the edge, in `f64`, only to draw them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactPoints<S: Scalar> {
    /// The engine's contact: unit normal from `a` to `b` and signed
    /// separation (negative = penetration).
    pub contact: Contact<S>,
    /// The point of `a`'s surface nearest to `b` along the normal (for a
    /// penetrating pair, the deepest point of `a` inside `b`).
    pub on_a: (f64, f64),
    /// The matching point of `b`'s surface.
    pub on_b: (f64, f64),
}

/// The contact between `shape_a` at `position_a` and `shape_b` at
/// `position_b`, with its closest points.
///
/// The contact is the engine's (`contact_circle_circle`,
/// `contact_circle_aabb` in both cases, `contact_aabb_aabb`, chosen by the
/// shapes). The points follow from the normal `n` and separation `s`:
///
/// * a circle's point is its support point along the normal: `c + r·n` for
///   `a`, `c − r·n` for `b`;
/// * between a circle and a box the box's point is the circle's point moved
///   by `s·n` (outside the box: the point of the box nearest the centre;
///   centre inside: the point of the nearest face);
/// * between two boxes each point is on the box's face across the normal,
///   at the middle of the overlap of the two boxes along that face (or at
///   the nearer corners when they do not overlap along it).
#[must_use]
pub fn contact_points<S: Scalar>(
    shape_a: &Shape<S>,
    position_a: Vec2<S>,
    shape_b: &Shape<S>,
    position_b: Vec2<S>,
) -> ContactPoints<S> {
    let (ca, cb) = (position_a.to_f64(), position_b.to_f64());
    match (*shape_a, *shape_b) {
        (Shape::Circle { radius: ra }, Shape::Circle { radius: rb }) => {
            let contact =
                contact_circle_circle(&Circle::new(position_a, ra), &Circle::new(position_b, rb));
            let n = contact.normal.to_f64();
            ContactPoints {
                contact,
                on_a: along(ca, n, ra.to_f64()),
                on_b: along(cb, n, -rb.to_f64()),
            }
        }
        (Shape::Circle { radius }, Shape::Aabb { half_extents }) => {
            let contact = contact_circle_aabb(
                &Circle::new(position_a, radius),
                &Aabb::new(position_b, half_extents),
            );
            let n = contact.normal.to_f64();
            let on_a = along(ca, n, radius.to_f64());
            ContactPoints {
                contact,
                on_a,
                on_b: along(on_a, n, contact.separation.to_f64()),
            }
        }
        (Shape::Aabb { half_extents }, Shape::Circle { radius }) => {
            let contact = contact_aabb_circle(
                &Aabb::new(position_a, half_extents),
                &Circle::new(position_b, radius),
            );
            let n = contact.normal.to_f64();
            let on_b = along(cb, n, -radius.to_f64());
            ContactPoints {
                contact,
                on_a: along(on_b, n, -contact.separation.to_f64()),
                on_b,
            }
        }
        (Shape::Aabb { half_extents: ha }, Shape::Aabb { half_extents: hb }) => {
            let contact = contact_aabb_aabb(&Aabb::new(position_a, ha), &Aabb::new(position_b, hb));
            let n = contact.normal.to_f64();
            let (ha, hb) = (ha.to_f64(), hb.to_f64());
            let (on_a, on_b) = if n.0 == 0.0 {
                // Normal along y: faces at y = c ± h.y, points along x.
                let (xa, xb) = facing_coordinates((ca.0, ha.0), (cb.0, hb.0));
                ((xa, ca.1 + n.1 * ha.1), (xb, cb.1 - n.1 * hb.1))
            } else {
                let (ya, yb) = facing_coordinates((ca.1, ha.1), (cb.1, hb.1));
                ((ca.0 + n.0 * ha.0, ya), (cb.0 - n.0 * hb.0, yb))
            };
            ContactPoints {
                contact,
                on_a,
                on_b,
            }
        }
    }
}

/// `p + t·n`.
fn along(p: (f64, f64), n: (f64, f64), t: f64) -> (f64, f64) {
    (p.0 + t * n.0, p.1 + t * n.1)
}

/// Two intervals `centre ± half` on the tangent axis: the middle of their
/// overlap for both, or each interval's end nearest the other when apart.
fn facing_coordinates(a: (f64, f64), b: (f64, f64)) -> (f64, f64) {
    let (a_lo, a_hi) = (a.0 - a.1, a.0 + a.1);
    let (b_lo, b_hi) = (b.0 - b.1, b.0 + b.1);
    let (lo, hi) = (a_lo.max(b_lo), a_hi.min(b_hi));
    if lo <= hi {
        let mid = (lo + hi) / 2.0;
        (mid, mid)
    } else if a_hi < b_lo {
        (a_hi, b_lo)
    } else {
        (a_lo, b_hi)
    }
}
