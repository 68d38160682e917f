//! Contacts of two boxes whose overlap is a corner: the normal that does not
//! carry weight.
//!
//! # Why
//!
//! The separating-axis contact of two boxes ([`contact_aabb_aabb`]) takes
//! the axis of the larger gap. When the boxes meet corner to corner — in a
//! wall of equal boxes, each box and its diagonal neighbour touch at one
//! point, both gaps about zero — that choice turns on differences far below
//! the slop: at the start the gaps tie and the tie goes to the vertical
//! axis, so each box rests partly on the corners of its diagonal
//! neighbours; as soon as a row sinks by a fraction of the slop, the
//! vertical overlap becomes the larger penetration and the contact turns
//! horizontal, the load it carried drops onto the rest, and the wall sinks
//! (a 3 × 10 wall 0.0049, a 20 × 20 wall 0.082, bounds 10·slop = 0.001 and
//! 20·slop = 0.002).
//!
//! # The rule
//!
//! A support needs a patch of shared face: a box rests on another where
//! their faces overlap. Along a corner contact that patch is the overlap of
//! the boxes' projections on the other axis, `−g_other`, and when it is
//! within the slop the touch is a corner, not a face. So when gravity is
//! along one axis (the weight axis), a contact along that axis whose gap
//! is within the slop (`g_weight ≤ slop`) and whose patch is within the
//! slop (`g_other ≥ −slop`) is taken along the other axis instead, with
//! `g_other` as its separation: corners never carry weight, and the choice
//! is the same on both sides of the tie, so it does not flip while the
//! pile settles. The wall rests on its columns, each a stack.
//!
//! The same holds at an impact: boxes falling row on row meet their
//! diagonal neighbours corner to corner too, and the time-of-impact row
//! that would catch such a corner along the weight axis is dropped
//! ([`corner_impact`]) when the boxes' patch at the moment of impact is
//! within the slop; the row of the face below catches the box, and once
//! touching, the corner gets its row across gravity by the rule above.
//! (Kept, it carried the impact along the weight axis for one substep and
//! its impulse then warm-started the corner's row across gravity, pushing
//! the columns apart: a 5 × 10 wall dropped row on row from 0.01 sagged
//! 0.002 and spread 7e-4.)
//!
//! The separation stays exact and conservative: `g_other ≤ g_weight` (the
//! separating-axis contact chose the larger gap), so the row holds the
//! boxes apart on the other axis by no less than before, and a box that
//! truly rests on another (patch wider than the slop) keeps its vertical
//! contact. A box balanced on a corner within the slop slides off it,
//! which is the same ambiguity the slop already allows. Without gravity,
//! or with gravity off the axes, no axis carries weight more than the
//! other and the separating-axis contact is kept as it is.

use crate::geometry::{Aabb, Contact};
use crate::math::{Scalar, Vec2};

/// The contact between boxes `a` and `b` (normal from `a` to `b`): the
/// separating-axis contact, except that a corner touch along the axis of
/// `gravity` is taken along the other axis (module notes).
#[inline]
pub(crate) fn box_contact<S: Scalar>(
    a: &Aabb<S>,
    b: &Aabb<S>,
    gravity: Vec2<S>,
    slop: S,
) -> Contact<S> {
    // The gaps of `contact_aabb_aabb`, computed here once for both the
    // separating-axis choice (larger gap, ties to y) and the corner test.
    let d = b.center - a.center;
    let gap_x = d.x.abs().sub(a.half_extents.x.add(b.half_extents.x));
    let gap_y = d.y.abs().sub(a.half_extents.y.add(b.half_extents.y));
    let mut along_x = gap_x > gap_y;
    let corner = gap_x <= slop && gap_y <= slop && gap_x >= slop.neg() && gap_y >= slop.neg();
    if corner {
        // Within the slop on both axes, the chosen axis's gap is at most
        // slop and the other's patch at most slop: take the axis across
        // gravity when gravity lies along an axis.
        if gravity.x == S::ZERO && gravity.y != S::ZERO {
            along_x = true;
        } else if gravity.y == S::ZERO && gravity.x != S::ZERO {
            along_x = false;
        }
    }
    let sign = |offset: S| {
        if offset.is_negative() {
            S::ONE.neg()
        } else {
            S::ONE
        }
    };
    if along_x {
        Contact {
            normal: Vec2::new(sign(d.x), S::ZERO),
            separation: gap_x,
        }
    } else {
        Contact {
            normal: Vec2::new(S::ZERO, sign(d.y)),
            separation: gap_y,
        }
    }
}

/// Whether a time-of-impact hit of boxes `a` and `b` at fraction `t` of
/// the substep, along `normal`, is a corner meeting along the weight axis
/// (module notes): gravity lies along one axis, `normal` along it, and the
/// boxes' gap on the other axis at the moment of impact,
/// `|d + t·Δ| − (h_a + h_b)` with `Δ` the relative displacement of the
/// substep, is at least `−slop` (a patch of at most the slop).
#[inline]
pub(crate) fn corner_impact<S: Scalar>(
    a: &Aabb<S>,
    b: &Aabb<S>,
    relative_displacement: Vec2<S>,
    t: S,
    normal: Vec2<S>,
    gravity: Vec2<S>,
    slop: S,
) -> bool {
    let d = b.center - a.center;
    let (offset, motion, half_sum) = if gravity.x == S::ZERO && gravity.y != S::ZERO {
        if normal.y == S::ZERO {
            return false;
        }
        (
            d.x,
            relative_displacement.x,
            a.half_extents.x.add(b.half_extents.x),
        )
    } else if gravity.y == S::ZERO && gravity.x != S::ZERO {
        if normal.x == S::ZERO {
            return false;
        }
        (
            d.y,
            relative_displacement.y,
            a.half_extents.y.add(b.half_extents.y),
        )
    } else {
        return false;
    };
    offset.add(t.mul(motion)).abs().sub(half_sum) >= slop.neg()
}

/// Whether the separating-axis contact of boxes `a` and `b` (normal
/// `normal`, gap `separation`) is a speculative row at a corner along the
/// weight axis: apart along the axis of `gravity` by more than the slop,
/// while on the other axis the boxes' patch is within the slop
/// (`−slop ≤ g_other ≤ slop`) at the start of the substep and still at
/// least `−slop` after the relative displacement of the substep, on the
/// same side. Such a row would catch a corner on a corner (module notes);
/// it is left out, and the face below catches the box.
#[inline]
pub(crate) fn corner_apart<S: Scalar>(
    a: &Aabb<S>,
    b: &Aabb<S>,
    relative_displacement: Vec2<S>,
    contact: &Contact<S>,
    gravity: Vec2<S>,
    slop: S,
) -> bool {
    if contact.separation <= slop {
        return false;
    }
    let d = b.center - a.center;
    let (offset, motion, half_sum) = if gravity.x == S::ZERO && gravity.y != S::ZERO {
        if contact.normal.y == S::ZERO {
            return false;
        }
        (
            d.x,
            relative_displacement.x,
            a.half_extents.x.add(b.half_extents.x),
        )
    } else if gravity.y == S::ZERO && gravity.x != S::ZERO {
        if contact.normal.x == S::ZERO {
            return false;
        }
        (
            d.y,
            relative_displacement.y,
            a.half_extents.y.add(b.half_extents.y),
        )
    } else {
        return false;
    };
    let start = offset.abs().sub(half_sum);
    let end_offset = offset.add(motion);
    let same_side = end_offset.is_negative() == offset.is_negative();
    start <= slop
        && start >= slop.neg()
        && same_side
        && end_offset.abs().sub(half_sum) >= slop.neg()
}

#[cfg(test)]
#[allow(clippy::float_arithmetic)] // test inputs are built in f64
mod tests {
    use super::*;
    use crate::geometry::contact_aabb_aabb;
    use crate::math::Fx;

    fn boxed(x: f64, y: f64) -> Aabb<Fx> {
        Aabb::new(
            Vec2::new(Fx::from_f64(x), Fx::from_f64(y)),
            Vec2::new(Fx::from_f64(0.5), Fx::from_f64(0.5)),
        )
    }

    fn down() -> Vec2<Fx> {
        Vec2::new(Fx::ZERO, Fx::from_int(-10))
    }

    fn slop() -> Fx {
        Fx::from_f64(1e-4)
    }

    /// Diagonal neighbours of a wall, exactly touching and with the upper
    /// one sunk by less or more than the slop: always the horizontal axis.
    #[test]
    fn a_corner_touch_under_vertical_gravity_is_horizontal_on_both_sides_of_the_tie() {
        for sink in [0.0, 5e-5, 1e-3] {
            let c = box_contact(&boxed(0.0, 0.0), &boxed(1.0, 1.0 - sink), down(), slop());
            assert_eq!(c.normal, Vec2::X, "sink {sink}");
            assert_eq!(c.separation, Fx::ZERO);
            // Seen from the other box: the same contact flipped.
            let back = box_contact(&boxed(1.0, 1.0 - sink), &boxed(0.0, 0.0), down(), slop());
            assert_eq!(back, c.flipped());
        }
    }

    /// A box resting on another with a face patch wider than the slop keeps
    /// its vertical contact; a patch within the slop is a corner.
    #[test]
    fn a_face_patch_wider_than_the_slop_carries_weight() {
        let c = box_contact(&boxed(0.0, 0.0), &boxed(0.999, 1.0), down(), slop());
        assert_eq!((c.normal, c.separation), (Vec2::Y, Fx::ZERO));
        let c = box_contact(&boxed(0.0, 0.0), &boxed(0.99995, 1.0), down(), slop());
        assert_eq!(c.normal, Vec2::X);
        assert!(c.separation < Fx::ZERO && c.separation >= slop().neg());
    }

    /// Falling onto the corner of a diagonal neighbour: dropped; onto a
    /// face patch wider than the slop, or sideways into a face: kept.
    #[test]
    fn only_corner_impacts_along_the_weight_axis_are_dropped() {
        let fall = Vec2::new(Fx::ZERO, Fx::from_f64(-0.02));
        let (t, up) = (Fx::from_f64(0.5), Vec2::Y);
        let lower = boxed(0.0, 0.0);
        assert!(corner_impact(
            &lower,
            &boxed(1.0, 1.01),
            fall,
            t,
            up,
            down(),
            slop()
        ));
        assert!(!corner_impact(
            &lower,
            &boxed(0.999, 1.01),
            fall,
            t,
            up,
            down(),
            slop()
        ));
        // Sliding right into the lower box's corner while falling: the
        // patch at impact (x offset 1.0 − 0.5·0.004) is wider than the slop.
        let slide = Vec2::new(Fx::from_f64(-0.004), Fx::from_f64(-0.02));
        assert!(!corner_impact(
            &lower,
            &boxed(1.0, 1.01),
            slide,
            t,
            up,
            down(),
            slop()
        ));
        let sideways = Vec2::new(Fx::from_f64(-0.02), Fx::ZERO);
        assert!(!corner_impact(
            &lower,
            &boxed(1.01, 1.0),
            sideways,
            t,
            Vec2::X,
            down(),
            slop()
        ));
        assert!(!corner_impact(
            &lower,
            &boxed(1.0, 1.01),
            fall,
            t,
            up,
            Vec2::ZERO,
            slop()
        ));
    }

    /// A diagonal neighbour falling row on row: its speculative corner row
    /// is left out; a box above a face patch wider than the slop, or one
    /// whose motion closes the patch, keeps its row.
    #[test]
    fn speculative_corner_rows_along_the_weight_axis_are_left_out() {
        let still = Vec2::ZERO;
        let lower = boxed(0.0, 0.0);
        let upper = boxed(1.0, 1.01);
        let c = contact_aabb_aabb(&lower, &upper);
        assert!(corner_apart(&lower, &upper, still, &c, down(), slop()));
        let face = boxed(0.99, 1.01);
        let c = contact_aabb_aabb(&lower, &face);
        assert!(!corner_apart(&lower, &face, still, &c, down(), slop()));
        let closing = Vec2::new(Fx::from_f64(-0.01), Fx::from_f64(-0.02));
        let c = contact_aabb_aabb(&lower, &upper);
        assert!(!corner_apart(&lower, &upper, closing, &c, down(), slop()));
        assert!(!corner_apart(&lower, &upper, still, &c, Vec2::ZERO, slop()));
    }

    /// Apart along the weight axis by more than the slop (a speculative
    /// row), without gravity, or under sideways gravity: the separating-axis
    /// contact.
    #[test]
    fn other_cases_keep_the_separating_axis_contact() {
        let (a, b) = (boxed(0.0, 0.0), boxed(1.0, 1.01));
        assert_eq!(
            box_contact(&a, &b, down(), slop()),
            contact_aabb_aabb(&a, &b)
        );
        let b = boxed(1.0, 1.0);
        assert_eq!(
            box_contact(&a, &b, Vec2::ZERO, slop()),
            contact_aabb_aabb(&a, &b)
        );
        let diagonal = Vec2::new(Fx::from_int(3), Fx::from_int(-4));
        assert_eq!(
            box_contact(&a, &b, diagonal, slop()),
            contact_aabb_aabb(&a, &b)
        );
        // Gravity along x: the weight axis is x, a corner touch is vertical.
        let sideways = Vec2::new(Fx::from_int(-10), Fx::ZERO);
        let c = box_contact(&boxed(0.0, 0.0), &boxed(1.0 - 5e-5, 1.0), sideways, slop());
        assert_eq!((c.normal, c.separation), (Vec2::Y, Fx::ZERO));
    }
}
