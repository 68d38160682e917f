//! Whether a pair whose straight sweep misses meets after all, because a
//! stretched rope turns one of its bodies into the other.
//!
//! The narrow phase drops a closing speculative row when the exact time of
//! impact along the pair's straight motion misses (a body passing a corner
//! with clearance must not be stopped in mid-air). A body on a rope the
//! straight motion would stretch does not move straight: the rope's row
//! takes the stretch out along the rope within the same substep. A link of
//! a chain sliding round a peg is the common case: its straight motion
//! leaves the peg's outline by `s²/(2ρ)` (slide `s`, radius of curvature
//! `ρ`), the sweep misses, and the ropes then pull it round and into the
//! peg with no row to hold it.
//!
//! The turned motion: each body's velocity plus the turn its stretched
//! ropes give it (`world::step::rope_turns`), over the whole substep (the
//! rope acts from the start: its stretch is there from the first instant
//! of the straight motion). A hit at fraction `t` with normal `n'` makes
//! the row, re-aimed as a straight hit is (`s' = −t·(Δv'·n')·h`, `Δv'` the
//! turned relative velocity): the solve lets the pair close at most `s'`
//! along `n'`, so the pair stops touching. A miss of the turned motion too
//! is a clearance (and goes on to `collision::deflected_sweep`).

use super::narrow_phase::shape_toi;
use crate::geometry::{Contact, Shape, Toi};
use crate::math::{Scalar, Vec2};

/// The turn of slot `slot`'s velocity by stretched ropes (zero when no
/// rope is stretched, `turns` empty).
pub(crate) fn rope_turn<S: Scalar>(turns: &[Vec2<S>], slot: u32) -> Vec2<S> {
    turns.get(slot as usize).copied().unwrap_or(Vec2::ZERO)
}

/// The row of a pair whose straight sweep misses, when the motion turned
/// by the ropes (`turns`, per body) hits: its normal at the impact and the
/// gap the turned motion closes up to it. `None` when no rope turns either
/// body or the turned motion misses too. Each side is (shape, position,
/// velocity).
pub(crate) fn rope_turned_contact<S: Scalar>(
    a: (&Shape<S>, Vec2<S>, Vec2<S>),
    b: (&Shape<S>, Vec2<S>, Vec2<S>),
    turns: (Vec2<S>, Vec2<S>),
    h: S,
) -> Option<Contact<S>> {
    if turns.0 == Vec2::ZERO && turns.1 == Vec2::ZERO {
        return None;
    }
    let (va, vb) = (a.2 + turns.0, b.2 + turns.1);
    match shape_toi(a.0, a.1, va.scale(h), b.0, b.1, vb.scale(h)) {
        Toi::Hit { t, normal } => Some(Contact {
            normal,
            separation: t.mul((vb - va).dot(normal).mul(h)).neg().max(S::ZERO),
        }),
        Toi::Overlapping | Toi::Miss => None,
    }
}
