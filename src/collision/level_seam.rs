//! Level seams: a body moving along a row of flush faces does not catch on
//! the corners between them.
//!
//! # Why
//!
//! A floor made of tiles has a seam wherever two tiles meet. A box sliding
//! on tile A towards tile B (tops flush) has, with B, a vertical gap of
//! about zero and a horizontal gap that the motion closes: the
//! separating-axis contact takes the axis of the larger gap, x, and its
//! speculative row stops the box at the seam — a ghost collision (a box at
//! 3 units/s over two flush fixed tiles stopped dead; over a row of
//! resting boxes it was slowed from 2 to 0.39). At the seam itself both
//! gaps are within the slop, and the corner rule
//! (`collision::box_corner`) takes the axis across gravity, x, again. A
//! circle meets B's corner, whose normal leans back from the vertical: the
//! row that stops its approach along that normal throws it up (a hop of
//! up to 1.96 units at 60 units/s).
//!
//! # The rule
//!
//! Along the axis `m` of the motion the body can only meet B's side face if
//! their extents on the other axis `o` overlap; when that overlap (or gap),
//! `g_o = |d_o| − (h_a,o + h_b,o)`, is within the slop — the depth a
//! resting contact may have — the bodies meet, if at all, on B's face
//! across `o` (its top, for a floor). So the contact is taken across `o`
//! with separation `g_o` (within ±slop: a row that neither pushes nor
//! lets the body sink) when all of:
//!
//! - the faces are level: `|g_o| ≤ slop`; or B's face lies lower, `g_o >
//!   slop` (a step down), and the body does not close on its plane faster
//!   than one substep of gravity from rest would, `c_o ≤ g_o + |g_o|·h²`
//!   (`c_o` the closing along `o` this substep). A body resting on A has
//!   exactly that closing before the solve (its velocity holds `g·h`,
//!   which A's row takes out); without this the time of impact of that
//!   unsupported motion hits B's side, and a box stepping down 0.001 was
//!   stopped dead. A body falling faster may really meet B's side and
//!   keeps its contact;
//! - the contact is not already across `o` (a box's x contact, a circle's
//!   corner contact);
//! - the pair moves along `m` by more than the slop this substep,
//!   `|Δ_m| > slop + |g_m|·h²` (`Δ` the relative displacement of the
//!   substep; a body resting on the other axis's faces sinks `|g|·h²` a
//!   substep before the solve, which is not a slide): a motion the slop
//!   cannot hold is not rest jitter. Bodies at rest corner
//!   to corner — diagonal neighbours in a wall — keep the corner rule's
//!   contact, which carries no weight. Moving apart counts too: a circle
//!   sunk up to the slop into A's top meets A's corner as it passes onto B,
//!   and that row, leaning forward, pushed it on (0.01 units/s became
//!   0.024);
//! - the contact would act this substep: its separation less the closing
//!   along its normal, `s + Δ·n`, is below the slop. Farther away the row
//!   does not bind, and taking the face's plane then would let a body glide
//!   over a hole towards a tile it has not reached. A circle leaving a
//!   ledge is held at the ledge's plane only while its corner contact is
//!   within the slop (its centre at most `√(2r·2·slop)` past the edge), a
//!   height error within the slop;
//! - only one axis qualifies (a body moving diagonally into a corner with
//!   both gaps within the slop is ambiguous: the contact is kept).
//!
//! A tile higher than the one the body rests on by more than the slop is a
//! wall (`|g_o| > slop`): the contact is kept and stops the body. A body
//! moving away (off a ledge) keeps its contact and falls. A body slower
//! than `slop/h` (0.006 units/s at 60 Hz) moves less than the slop per
//! substep, which the rule cannot tell from rest: it may stop at a seam.
//! Circle–circle pairs have no faces and are never changed.

use crate::geometry::Contact;
use crate::math::{Scalar, Vec2};

/// The contact of a pair at a level seam (module notes), or `None` when it
/// is not one. `contact` is the pair's contact (normal from `a` to `b`),
/// `offset` = `c_b − c_a`, `half_sum` the sum of the shapes' half extents
/// (a circle's are its radius), `relative_displacement` = `(v_b − v_a)·h`,
/// `sag` per axis the fall of one substep of gravity from rest, `|g|·h²`.
#[inline]
pub(crate) fn level_seam<S: Scalar>(
    contact: &Contact<S>,
    offset: Vec2<S>,
    half_sum: Vec2<S>,
    relative_displacement: Vec2<S>,
    sag: Vec2<S>,
    slop: S,
) -> Option<Contact<S>> {
    // Cheapest test first (most pairs, a resting pile's, fail it): moving
    // along some axis by more than slop + |g|·h² (see `moving` below).
    if relative_displacement.x.abs() <= slop.add(sag.x)
        && relative_displacement.y.abs() <= slop.add(sag.y)
    {
        return None;
    }
    // Active this substep: s − closing along n < slop.
    let closing_n = relative_displacement.dot(contact.normal).neg();
    if contact.separation.sub(closing_n) >= slop {
        return None;
    }
    let sign = |x: S| {
        if x.is_negative() {
            S::ONE.neg()
        } else {
            S::ONE
        }
    };
    // The face across y (motion along x), and across x (motion along y).
    let gap = Vec2::new(
        offset.x.abs().sub(half_sum.x),
        offset.y.abs().sub(half_sum.y),
    );
    let closing = Vec2::new(
        relative_displacement.x.mul(sign(offset.x)).neg(),
        relative_displacement.y.mul(sign(offset.y)).neg(),
    );
    // Level across an axis: within the slop, or apart by more (the next
    // tile lower: a step down) while closing on it by no more than the
    // gap plus one substep of gravity from rest (a supported body's
    // velocity before the solve holds that step, `g·h`, which its support
    // then takes out; a body falling faster may really meet the side).
    let level =
        |gap: S, closing: S, sag: S| gap >= slop.neg() && (gap <= slop || closing <= gap.add(sag));
    // Moving along an axis: beyond the slop and beyond one substep of
    // gravity from rest (a circle resting on a floor falls `|g|·h²` towards
    // the next tile each substep before the solve: that is no motion along
    // the wall of tiles beside it).
    let moving = |closing: S, sag: S| closing.abs() > slop.add(sag);
    let across_y =
        level(gap.y, closing.y, sag.y) && contact.normal.x != S::ZERO && moving(closing.x, sag.x);
    let across_x =
        level(gap.x, closing.x, sag.x) && contact.normal.y != S::ZERO && moving(closing.y, sag.y);
    match (across_y, across_x) {
        (true, false) => Some(Contact {
            normal: Vec2::new(S::ZERO, sign(offset.y)),
            separation: gap.y,
        }),
        (false, true) => Some(Contact {
            normal: Vec2::new(sign(offset.x), S::ZERO),
            separation: gap.x,
        }),
        _ => None,
    }
}

#[cfg(test)]
#[allow(clippy::float_arithmetic)] // test inputs are built in f64
mod tests {
    use super::*;
    use crate::collision::box_corner::box_contact;
    use crate::collision::test_values::{slop, v};
    use crate::geometry::{Aabb, Circle, contact_circle_aabb};
    use crate::math::Fx;

    /// One substep of g = 10 from rest at 60 Hz.
    fn sag() -> Vec2<Fx> {
        v(0.0, 10.0 / 3600.0)
    }

    /// A unit box resting on a floor at `x` moving by `dx` this substep,
    /// against the tile of half width 1 whose left face is at 0 and top at
    /// `tile_top`: the separating-axis contact and the level seam's.
    fn box_at_seam(x: f64, tile_top: f64, dx: f64) -> (Contact<Fx>, Option<Contact<Fx>>) {
        let (a, b) = (
            Aabb::new(v(x, 0.5), v(0.5, 0.5)),
            Aabb::new(v(1.0, tile_top - 0.5), v(1.0, 0.5)),
        );
        // As the narrow phase: with the corner rule, under gravity −y.
        let c = box_contact(&a, &b, v(0.0, -10.0), slop());
        let seam = level_seam(
            &c,
            b.center - a.center,
            v(1.5, 1.0),
            v(-dx, 0.0),
            sag(),
            slop(),
        );
        (c, seam)
    }

    /// Approaching a flush tile (gap 0.02, closing 0.05 this substep), at
    /// the seam, and over it: the tile's top, separation its top's height
    /// difference.
    #[test]
    fn a_box_closing_on_a_flush_tile_meets_its_top() {
        for (x, top) in [(-0.52, 0.0), (-0.5, 0.0), (-0.5, 5e-5), (-0.5, -5e-5)] {
            // A tile lower within the slop already gives the top's contact.
            let (sat, seam) = box_at_seam(x, top, 0.05);
            let c = seam.unwrap_or(sat);
            // Normal from the box (a) down to the tile (b).
            assert_eq!(c.normal, Vec2::new(Fx::ZERO, Fx::ONE.neg()));
            assert!((c.separation.to_f64() + top).abs() < 1e-9, "{c:?}");
        }
    }

    /// Not a level seam: a tile higher by more than the slop (a wall), a
    /// box at rest or slower than the slop per substep (a wall's diagonal
    /// neighbours), a box moving away (off a ledge), a tile farther than
    /// the substep's motion.
    #[test]
    fn walls_rest_departures_and_far_tiles_keep_their_contact() {
        for (x, top, dx) in [
            (-0.5, 2e-4, 0.05),
            (-0.5, 0.0, 0.0),
            (-0.5, 0.0, 0.5e-4),
            (-0.5, 0.0, -0.05),
            (-0.6, 0.0, 0.05),
        ] {
            let (sat, seam) = box_at_seam(x, top, dx);
            assert_eq!(seam, None, "x {x} top {top} dx {dx}");
            assert_eq!(sat.normal, Vec2::X, "x {x} top {top} dx {dx}");
        }
    }

    /// A circle of radius 0.5 on the floor, its centre 0.01 short of the
    /// tile's corner, closing 0.05: its corner contact becomes the top's.
    #[test]
    fn a_circle_closing_on_a_flush_tile_meets_its_top() {
        let ball = Circle::new(v(-0.01, 0.5), Fx::from_f64(0.5));
        let tile = Aabb::new(v(1.0, -0.5), v(1.0, 0.5));
        let c = contact_circle_aabb(&ball, &tile);
        assert!(c.normal.x != Fx::ZERO && c.normal.y != Fx::ZERO, "a corner");
        let seam = level_seam(
            &c,
            tile.center - ball.center,
            v(1.5, 1.0),
            v(-0.05, 0.0),
            sag(),
            slop(),
        );
        assert_eq!(
            seam,
            Some(Contact {
                normal: Vec2::new(Fx::ZERO, Fx::ONE.neg()),
                separation: Fx::ZERO
            })
        );
    }
}
