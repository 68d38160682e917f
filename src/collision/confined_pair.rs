//! A deep overlap of two boxes (or circles) that immovable bodies keep from separating
//! along its shortest way out is separated along the other axis.
//!
//! # Why
//!
//! The contact of two overlapping boxes is along the axis of least
//! penetration (`geometry::contact_aabb_aabb`): the shortest way out when
//! both boxes are free to move. Two unit boxes spawned at one point in a
//! pit exactly one box wide take a horizontal row (their centres coincide,
//! `collision::coincident` picks an axis; or one is a hair to the side):
//! every position pass pushes them apart sideways, the walls push them
//! straight back, the row stays horizontal, and the pair never separates
//! (overlap 1.0 for ever). The same holds for any pair squeezed between
//! immovable bodies across its normal.
//!
//! # The rule
//!
//! A row of two movable boxes `a`, `b` along the axis normal `n` (from `a`
//! to `b`) overlapping by `o > 2·slop` needs `a` to move by `σ_a` along `−n`
//! and `b` by `σ_b` along `+n` with `σ_a + σ_b = o`. An immovable body with
//! an axis face row across `n` in front of `a` (normal from `a` to it equal
//! to `−n`, gap `g_a`) lets `a` move at most `g_a` that way, and likewise
//! `g_b` for `b` along `+n` (the least gap over such rows). When both are
//! bounded and `g_a + g_b < o − slop`, the overlap cannot be undone along
//! `n` at all: rigid bodies there must separate along the other axis `p`,
//! where the boxes overlap by `o_p = (h_a + h_b)·p − |d·p|`. The row is
//! taken along `±p` (the sign of `d·p`; at `d·p = 0`, the side with more
//! room, `+p` on a tie) with separation `−o_p`, unless `p` is blocked
//! worse (its own shortfall `o_p − (g'_a + g'_b)` at least `n`'s).
//!
//! Two circles (radii summing to `R`) whose row is along an axis (their
//! centres level across it, as walls leave them) are the same case: at the
//! offset `d·n` along `n` they overlap along `p` within
//! `√(R² − (d·n)²)` of each other, so `o_p = √(R² − (d·n)²) − |d·p|`.
//!
//! Only rows more than twice the slop deep are looked at (a resting
//! contact is about one slop deep; the position pass leaves some a few
//! ulps beyond it), and only face rows of immovable bodies
//! count as walls: a tilted corner row does not bound a motion along an
//! axis. Both boxes being movable, the swap changes which way the
//! position pass pushes; nothing is pushed into the walls, whose own rows
//! hold as before.

use crate::geometry::Contact;
use crate::math::{Scalar, Vec2};

/// The contact along the other axis `p` for a deep row of two boxes or two
/// circles (centre offset `d` = b − a, row `contact` along an axis from
/// `a` to `b`, `reach_p` the distance along `p` within which the shapes
/// overlap at their offset along the normal) when the immovable bodies' rows keep the pair
/// from separating along the row's normal (module notes); `None` when the
/// row can be undone along its normal, or the other axis is blocked
/// worse. `room(on_b, dir)` is the least gap of the face rows between body
/// `b` (`on_b`) or `a` and immovable bodies lying along `dir` from it,
/// `None` when there is none.
pub(crate) fn confined_contact<S: Scalar>(
    d: Vec2<S>,
    reach_p: S,
    contact: &Contact<S>,
    room: impl Fn(bool, Vec2<S>) -> Option<S>,
    slop: S,
) -> Option<Contact<S>> {
    let n = contact.normal;
    let overlap = contact.separation.neg();
    // Room to undo the overlap by moving `a` along `−dir` and `b` along
    // `dir`: `None` when either side is unbounded.
    let both = |dir: Vec2<S>| Some(room(false, -dir)?.add(room(true, dir)?));
    let along_n = both(n)?;
    if along_n >= overlap.sub(slop) {
        return None;
    }
    let shortfall_n = overlap.sub(along_n);
    // The other axis (the normal is `±X` or `±Y`).
    let p = if n.x == S::ZERO {
        Vec2::new(S::ONE, S::ZERO)
    } else {
        Vec2::new(S::ZERO, S::ONE)
    };
    let across = d.dot(p);
    let overlap_p = reach_p.sub(across.abs());
    let dir = if across.is_positive() {
        p
    } else if across.is_negative() {
        -p
    } else {
        // Coincident along `p`: the side with more room (unbounded first).
        match (both(p), both(-p)) {
            (Some(plus), Some(minus)) if minus > plus => -p,
            (Some(_), None) => -p,
            _ => p,
        }
    };
    if let Some(along_p) = both(dir)
        && overlap_p.sub(along_p) >= shortfall_n
    {
        return None;
    }
    Some(Contact {
        normal: dir,
        separation: overlap_p.neg(),
    })
}

#[cfg(test)]
#[allow(clippy::float_arithmetic)] // test inputs are built in f64
mod tests {
    use super::*;
    use crate::collision::test_values::v;
    use crate::math::Fx;

    fn contact(n: Vec2<Fx>, s: f64) -> Contact<Fx> {
        Contact {
            normal: n,
            separation: Fx::from_f64(s),
        }
    }

    const SLOP: f64 = 1e-4;

    /// Walls touching both boxes across x: a side-by-side overlap cannot be
    /// undone along x, so the row turns vertical (b, the upper or the
    /// tie's, goes up).
    #[test]
    fn a_pair_between_walls_turns_to_the_free_axis() {
        let walls = |_: bool, dir: Vec2<Fx>| (dir.y == Fx::ZERO).then_some(Fx::ZERO);
        let c = confined_contact(
            v(0.0, 0.0),
            Fx::ONE,
            &contact(Vec2::new(Fx::ONE, Fx::ZERO), -1.0),
            walls,
            Fx::from_f64(SLOP),
        )
        .expect("confined");
        assert_eq!(c.normal, v(0.0, 1.0));
        assert_eq!(c.separation, Fx::from_f64(-1.0));
        // b a little below a: b goes down.
        let c = confined_contact(
            v(0.0, -0.25),
            Fx::ONE,
            &contact(Vec2::new(Fx::ONE, Fx::ZERO), -1.0),
            walls,
            Fx::from_f64(SLOP),
        )
        .expect("confined");
        assert_eq!(c.normal, v(0.0, -1.0));
        assert_eq!(c.separation, Fx::from_f64(-0.75));
    }

    /// Room enough along the normal, or a side with no wall, keeps the row.
    #[test]
    fn room_along_the_normal_keeps_the_row() {
        let n = Vec2::new(Fx::ONE, Fx::ZERO);
        let roomy = |_: bool, dir: Vec2<Fx>| (dir.y == Fx::ZERO).then_some(Fx::from_f64(0.5));
        assert!(
            confined_contact(
                v(0.0, 0.0),
                Fx::ONE,
                &contact(n, -1.0),
                roomy,
                Fx::from_f64(SLOP)
            )
            .is_none()
        );
        let one_side = |on_b: bool, dir: Vec2<Fx>| (on_b && dir.y == Fx::ZERO).then_some(Fx::ZERO);
        assert!(
            confined_contact(
                v(0.0, 0.0),
                Fx::ONE,
                &contact(n, -1.0),
                one_side,
                Fx::from_f64(SLOP)
            )
            .is_none()
        );
    }

    /// Walls on every side: the other axis is no better, the row stays.
    #[test]
    fn a_pair_boxed_in_on_both_axes_keeps_its_row() {
        let boxed = |_: bool, _: Vec2<Fx>| Some(Fx::ZERO);
        assert!(
            confined_contact(
                v(0.0, 0.0),
                Fx::ONE,
                &contact(Vec2::new(Fx::ONE, Fx::ZERO), -1.0),
                boxed,
                Fx::from_f64(SLOP)
            )
            .is_none()
        );
    }
}
