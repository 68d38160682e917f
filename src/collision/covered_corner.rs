//! A box corner lying on another box's face is no corner: a circle meets
//! the face's plane there.
//!
//! # Why
//!
//! Two flush floor tiles A and B make one flat floor. A circle over B,
//! its centre a little way `dx` from the seam, has with A a corner contact
//! (A's top corner at the seam is the point of A nearest its centre) whose
//! normal leans `atan(dx/r)` from the vertical, with a gap of only about
//! `dx²/2r` more than B's. Falling onto the floor, the circle closes on
//! that corner within the substep, so its row acts with B's face row: the
//! solve and the bounce push along the tilted normal, and a ball dropped
//! 0.001–0.02 beside the seam left sideways at 0.025–0.5 units/s and
//! short of its apex (1.80 of 2.0). `collision::level_seam` takes the face
//! for a body moving *along* the tiles; this is the landing, across them.
//!
//! # The rule
//!
//! The circle (centre `c`, radius `r`) also has a face row with a box B
//! along an axis normal `n` (from the circle to B), and B holds it on the
//! near side of B's face plane `x·n = p_B`. Let `x·n = p_A` be A's face
//! across `n` nearer the circle, and `δ = p_A − p_B`. When `δ ≥ 0` (A's
//! face on or behind B's plane: flush tiles, or A lower, a step down) all
//! of A lies behind B's plane, and for any point `X` of A and any centre on
//! the near side, `|X − c| ≥ (X − c)·n ≥ (p_A − c·n)`: a circle B's row
//! keeps off B's plane cannot reach A at all, and A's row along the tilted
//! normal is one the real motion never needs. It is taken along `n`
//! instead, with the circle's gap to A's plane, `s = p_A − c·n − r`: a row
//! B's own (at least as tight) already implies, which neither tilts the
//! bounce nor lets the circle into A (its distance to A is at least `s`).
//! A face up to the slop in front of B's plane (`−slop ≤ δ < 0`) counts as
//! flush (a level within the slop, as `collision::level_seam`): the row
//! along `n` then holds the circle off A's plane.
//!
//! The condition is on the whole box, not only its corner: a wall standing
//! on a floor has its bottom corner on the floor's plane, but the wall
//! rises in front of it; its face across the floor's normal (its top) is
//! far in front of the floor, and its row is kept (a ball thrown along the
//! floor into it must be stopped).
//!
//! A box reaching farther in front of the plane (A higher by more than the
//! slop: a step up) has a real corner the circle can hit, and a corner with no
//! face row of another box beside it (a lone tile's edge) is one too: both
//! keep their tilted rows. Only immovable boxes moving together (A and B
//! with equal velocities, in practice fixed tiles) qualify: the argument
//! needs the plane and the box fixed relative to each other over the
//! substep.

use crate::geometry::{Aabb, Contact};
use crate::math::{Scalar, Vec2};

/// The contact of a circle (centre `center`, radius `radius`) with box
/// `corner_box` taken along `normal` — the axis normal (from the circle to
/// `face_box`) of the circle's face contact with `face_box` — when all of
/// `corner_box` lies on or behind `face_box`'s face across `normal`, to
/// within `slop` (module notes); `None` when it reaches farther in front
/// (a real corner, or a wall standing on that face).
pub(crate) fn covered_corner<S: Scalar>(
    center: Vec2<S>,
    radius: S,
    corner_box: &Aabb<S>,
    face_box: &Aabb<S>,
    normal: Vec2<S>,
    slop: S,
) -> Option<Contact<S>> {
    // A box's face across `normal` nearer the circle: `x·n = p`, with `n`
    // an axis (`|n| = 1`), `p = c·n − |h·n|`.
    let near_face = |b: &Aabb<S>| b.center.dot(normal).sub(b.half_extents.dot(normal).abs());
    let behind = near_face(corner_box).sub(near_face(face_box));
    if behind < slop.neg() {
        return None;
    }
    Some(Contact {
        normal,
        separation: near_face(corner_box).sub(center.dot(normal)).sub(radius),
    })
}

#[cfg(test)]
#[allow(clippy::float_arithmetic)] // test inputs are built in f64
mod tests {
    use super::*;
    use crate::collision::test_values::{slop, v};
    use crate::math::Fx;

    /// Tiles of half width 1 with their tops at 0 (B) and `a_top` (A, to
    /// the left of the seam at x = 0); a circle r 0.25 at (dx, 0.25 + gap).
    fn at_seam(a_top: f64, dx: f64, gap: f64) -> Option<Contact<Fx>> {
        let a = Aabb::new(v(-1.0, a_top - 0.5), v(1.0, 0.5));
        let b = Aabb::new(v(1.0, -0.5), v(1.0, 0.5));
        covered_corner(
            v(dx, 0.25 + gap),
            Fx::from_f64(0.25),
            &a,
            &b,
            v(0.0, -1.0),
            slop(),
        )
    }

    /// Flush, a step down, a corner within the slop above: B's plane
    /// through the corner, gap from the circle to it.
    #[test]
    fn a_corner_on_or_behind_the_face_is_taken_along_its_normal() {
        for (a_top, dx, gap) in [
            (0.0, 0.001, 0.0),
            (0.0, 0.02, 0.01),
            (-0.01, 0.1, 0.003),
            (5e-5, 0.005, 0.0),
        ] {
            let c = at_seam(a_top, dx, gap).expect("covered");
            assert_eq!(c.normal, v(0.0, -1.0));
            assert!(
                (c.separation.to_f64() - (gap - a_top)).abs() < 1e-9,
                "{c:?}"
            );
        }
    }

    /// A step up by more than the slop is a real corner; a wall standing
    /// on the floor (bottom corner on the floor's plane) is kept too.
    #[test]
    fn a_box_in_front_of_the_face_is_kept() {
        assert!(at_seam(0.01, 0.02, 0.0).is_none());
        assert!(at_seam(2e-4, 0.02, 0.0).is_none());
        let wall = Aabb::new(v(-0.5, 1.0), v(0.5, 1.0));
        let floor = Aabb::new(v(1.0, -0.5), v(1.0, 0.5));
        let c = covered_corner(
            v(0.1, -0.05),
            Fx::from_f64(0.25),
            &wall,
            &floor,
            v(0.0, -1.0),
            slop(),
        );
        assert!(c.is_none(), "{c:?}");
    }
}
