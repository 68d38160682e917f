//! Contact between a circle and an axis-aligned box, in both orders.
//!
//! # The maths
//!
//! Work in the box's frame: `q = c − c_box` is the circle's centre relative
//! to the box centre, `h` the half extents. Clamping `q` to `[−h, h]` gives
//! the point of the box closest to the centre, and `v = q − clamp(q)` the
//! vector from that point to the centre.
//!
//! * **Centre outside the box** (`v ≠ 0`): the distance from the box to the
//!   centre is `|v|`, so `separation = |v| − r`, and the normal from the
//!   circle to the box is `−v/|v|`. In the face regions (`v` along an axis,
//!   the common case) both are exact and need no square root; in the corner
//!   regions one `try_normalize_with_length` gives both.
//! * **Centre inside the box or on its boundary** (`v = 0`): the circle
//!   leaves through the face nearest its centre. With the depths
//!   `e_x = h_x − |q_x|` and `e_y = h_y − |q_y|` (both `≥ 0`), the smaller
//!   one wins (ties: y), `separation = −(e + r)`, and the normal points from
//!   the circle into the box, i.e. away from that face: `−sign(q)` on that
//!   axis. A centre exactly on an edge has `e = 0`, giving `separation = −r`
//!   and the face normal — the limit of the outside case, so the result is
//!   continuous across the boundary (at a corner the tie picks the y face).
//!
//! # Degenerate cases (API decision)
//!
//! A zero offset on the chosen axis (`q_x = 0` or `q_y = 0`, e.g. the
//! circle's centre at the box's centre) gives the **positive** axis as the
//! circle→box normal: the circle is pushed out through the box's negative
//! face. For a square box (or any box whose smaller depth at the centre is
//! along y) a centred circle therefore gets `+Y`, the engine-wide convention;
//! for a box narrower than it is tall the least-penetration axis is x and the
//! normal is `+X`.
//!
//! [`contact_aabb_circle`] is defined as the flipped result, so the *physical*
//! answer (which way each body is pushed) never depends on the argument
//! order; seen from the box, the centred case's normal is therefore `−Y`.
//!
//! # Accuracy (for `Fx`, inputs inside ±`WORLD_LIMIT`)
//!
//! `q`, the clamp and `v` are exact. Inside and in the face regions the
//! whole result is exact. In the corner regions, as for two circles:
//! `|v|` is rounded down by less than 1 ulp (so is the separation), and each
//! normal component is within `ulp·(1 + 1/|v|)` of `v_i/|v|`.

use super::{Aabb, Circle, Contact};
use crate::math::{Scalar, Vec2};

/// The contact between circle `a` and box `b`: unit normal from the circle
/// towards the box and the signed distance between their surfaces (negative
/// when they overlap).
///
/// Handles the centre outside the box (distance to the nearest point of the
/// box, minus the radius) and inside it (least-penetration face: separation
/// `−(distance to that face + radius)`). A zero offset on the chosen axis
/// gives the positive axis: a circle centred on a square box gets `+Y`. See
/// the module notes in `src/geometry/contact_circle_aabb.rs` for the derivation, accuracy and degenerate cases.
///
/// ```
/// use clockwork2d::geometry::*;
/// use clockwork2d::math::*;
/// use clockwork2d::prelude::*;
/// let ground = Aabb::new(Vec2::new(fx(0.0), fx(0.0)), Vec2::new(fx(10.0), fx(1.0)));
/// // A ball of radius 0.5 whose centre is 1.25 above the box: a gap of 0.75 ...
/// let ball = Circle::new(Vec2::new(fx(3.0), fx(2.25)), fx(0.5));
/// let c = contact_circle_aabb(&ball, &ground);
/// assert_eq!((c.normal, c.separation), (-Vec2::Y, fx(0.75)));
/// // ... and a ball whose centre is 0.25 inside the top face.
/// let ball = Circle::new(Vec2::new(fx(3.0), fx(0.75)), fx(0.5));
/// let c = contact_circle_aabb(&ball, &ground);
/// assert_eq!((c.normal, c.separation), (-Vec2::Y, fx(-0.75)));
/// ```
#[must_use]
pub fn contact_circle_aabb<S: Scalar>(a: &Circle<S>, b: &Aabb<S>) -> Contact<S> {
    let h = b.half_extents;
    let q = a.center - b.center;
    let v = q - q.clamp(-h, h);

    if let Some((outward, distance)) = box_to_centre(v) {
        // `outward` points from the box to the circle; the contact normal
        // goes from the circle (a) to the box (b).
        return Contact {
            normal: -outward,
            separation: distance.sub(a.radius),
        };
    }

    // Centre inside or on the boundary: leave through the nearest face.
    let depth_x = h.x.sub(q.x.abs());
    let depth_y = h.y.sub(q.y.abs());
    if depth_x < depth_y {
        Contact {
            normal: Vec2::new(into_box(q.x), S::ZERO),
            separation: depth_x.add(a.radius).neg(),
        }
    } else {
        Contact {
            normal: Vec2::new(S::ZERO, into_box(q.y)),
            separation: depth_y.add(a.radius).neg(),
        }
    }
}

/// The contact between box `a` and circle `b`: exactly
/// `contact_circle_aabb(b, a).flipped()` (same separation, normal from the
/// box towards the circle).
///
/// Being the flip, the push each body receives does not depend on the order
/// of the arguments; a circle centred on a square box gives `−Y` here (the
/// box goes down, the circle up, as with [`contact_circle_aabb`]).
///
/// ```
/// use clockwork2d::geometry::*;
/// use clockwork2d::math::*;
/// use clockwork2d::prelude::*;
/// let ground = Aabb::new(Vec2::new(fx(0.0), fx(0.0)), Vec2::new(fx(10.0), fx(1.0)));
/// let ball = Circle::new(Vec2::new(fx(3.0), fx(0.75)), fx(0.5));
/// let c = contact_aabb_circle(&ground, &ball);
/// assert_eq!((c.normal, c.separation), (Vec2::Y, fx(-0.75)));
/// ```
#[must_use]
pub fn contact_aabb_circle<S: Scalar>(a: &Aabb<S>, b: &Circle<S>) -> Contact<S> {
    contact_circle_aabb(b, a).flipped()
}

/// For `v` = circle centre minus nearest box point: the unit direction from
/// the box to the centre and the distance, or `None` if the centre is inside
/// or on the box (`v = 0`).
///
/// Axis-aligned `v` (the face regions) is handled exactly without a square
/// root; otherwise one normalisation. (For fixed point a non-zero `v` always
/// has a positive length, since `|v|² ≥ ulp²` is exact in the wide type; only
/// a float reference whose `|v|²` underflows could get `None` for `v ≠ 0`;
/// it then falls through to the inside case, whose depths are then
/// vanishingly small negative numbers — still a defined result.)
#[inline]
fn box_to_centre<S: Scalar>(v: Vec2<S>) -> Option<(Vec2<S>, S)> {
    if v.y == S::ZERO {
        if v.x == S::ZERO {
            return None;
        }
        return Some((Vec2::new(v.x.signum(), S::ZERO), v.x.abs()));
    }
    if v.x == S::ZERO {
        return Some((Vec2::new(S::ZERO, v.y.signum()), v.y.abs()));
    }
    v.try_normalize_with_length()
}

/// The circle→box normal component on an axis for a centre offset `q_i`
/// inside the box: `−1` when the centre is on the positive side (it leaves
/// through the positive face), `+1` otherwise (zero offset: the positive
/// axis, the documented tie-break).
#[inline]
fn into_box<S: Scalar>(offset: S) -> S {
    if offset.is_positive() {
        S::ONE.neg()
    } else {
        S::ONE
    }
}
