//! Whether a straight sweep that misses passes within the linear slop of
//! the other body: such a pair keeps its row, as a pair whose gap is
//! within the slop does (the narrow phase counts both as touching).
//!
//! Why: the narrow phase makes no row for a gap the straight motion would
//! close along the start normal but whose exact time of impact misses (a
//! ball passing a corner, or a gap, with clearance: the row would stop it
//! in mid-air). The straight motion is only the start of the substep's
//! path, though: the solve turns it by the rows and ropes the body meets,
//! and a turn of the order of the slop cannot be told from a miss by the
//! slop. A link of a chain sliding round a 0.2 peg, 1.7e-4 from it, slid
//! 1.85e-3 along it in a substep; its straight path missed the peg by
//! about 2e-6 (a tangent leaves a circle by `s²/(2ρ)`), the ropes' turn
//! predicted for the rerun (`collision::rope_turn`) pointed away from the
//! peg, the solve turned it in, and with no row it ended 7.4e-4 inside.
//! A path within the slop is a contact for the purposes of the solve: the
//! row with the start normal and gap lets the body slide past (the row
//! holds only the normal component, and the gap leaves it the clearance it
//! has), and stops it only where it would go in.
//!
//! Only pairs where a rope turns a body take the rule. The turns the rows
//! make are decided after the loop, from every meeting row
//! (`collision::deflected_sweep`), and are not guesses; the ropes' turn is
//! predicted from last substep's impulse and the stretch of the straight
//! motion, and can be wrong by the slop. Taken for every pair, the rule
//! added rows a crowd did not need (grazing neighbours in a room of 500
//! bodies at g 100, a third of them 1000×), changed how its groups were
//! solved, and left a body 1.1e-4 inside a wall, beyond the slop
//! (`tests/crowds_squeezed_by_heavy_bodies.rs`).

use super::narrow_phase::shape_toi;
use crate::geometry::{Shape, Toi};
use crate::math::{Scalar, Vec2};

/// `shape` grown by `by` on every side (a box per axis, so its corners
/// grow by up to `by·√2`: a path that close counts too, the safe side).
fn grown<S: Scalar>(shape: &Shape<S>, by: S) -> Shape<S> {
    match *shape {
        Shape::Circle { radius } => Shape::Circle {
            radius: radius.add(by),
        },
        Shape::Aabb { half_extents } => Shape::Aabb {
            half_extents: half_extents + Vec2::new(by, by),
        },
    }
}

/// Whether body `a` (shape, position, motion over the substep), grown by
/// `slop`, meets body `b` moving straight: the straight paths pass within
/// the slop of each other.
pub(crate) fn passes_within_slop<S: Scalar>(
    a: (&Shape<S>, Vec2<S>, Vec2<S>),
    b: (&Shape<S>, Vec2<S>, Vec2<S>),
    slop: S,
) -> bool {
    !matches!(
        shape_toi(&grown(a.0, slop), a.1, a.2, b.0, b.1, b.2),
        Toi::Miss
    )
}
