//! A face hidden from the time of impact by the walls in front of it.
//!
//! The narrow phase asks a pair's exact time of impact whether the motion
//! of the substep really closes a speculative gap (`narrow_phase.rs`): a
//! miss drops the row, a hit at a corner re-aims it. That question is
//! asked of the straight motion, as if the pair were alone. When the
//! moving body meets another immovable body first, it does not go
//! straight on: it is reflected there, and the straight motion's answer
//! is wrong. Two shapes of this error, both in any closed room:
//!
//! * A bullet crossing a room's corner region (ceiling and side wall in
//!   one substep): the straight motion passes the ceiling's end beyond the
//!   side wall (a **miss**: no row, the ceiling impact is lost and the
//!   body is cut there by the bullet's time of impact, losing the rest of
//!   the substep), or passes the side wall's end inside the ceiling (a
//!   **corner hit** on the side wall's end, a point covered by the
//!   ceiling: the row takes an oblique normal, and the e = 1 bounce off it
//!   threw away up to 89 % of the energy).
//! * Under gravity, a lost impact loses time on one axis while gravity
//!   keeps acting on the other: a bullet frozen at the floor for the rest
//!   of a substep gains `g·(h − τ)·|v_y|` of energy there, and the pump
//!   ran every tick (+44 % in a minute).
//!
//! [`face_past_walls`] follows the moving body's straight motion through
//! its reflections off the other immovable partners (all of them fixed and
//! at rest, every reflecting face orthogonal to the pair's normal, so the
//! approach along that normal — and its time — is untouched by them, and
//! the pair's row along the start normal is exact for it) and reports
//! whether the reflected path reaches the pair's face. If so, the caller
//! keeps the row along the start normal with the start gap.

use crate::geometry::{Shape, Toi};
use crate::math::{Scalar, Vec2};

use super::narrow_phase::{contact_between, shape_toi};

/// Most reflections followed (as many as a bullet takes in a substep).
const MAX_REFLECTIONS: u32 = 32;

/// Whether `moving` at `at`, moving by `motion` this substep, reaches
/// `target` (at `target_at`, at rest) on its face of outward normal `−n`
/// (`n` from the moving body to the target, axis-aligned), once its motion
/// is reflected off the `walls` (shape, position and restitution; all at
/// rest and immovable, the target excluded) it meets before.
///
/// Every wall met before the target must be met on a face orthogonal to
/// `n` (`n_w·n = 0` exactly): such a reflection leaves the motion along
/// `n` unchanged. Anything else (a wall across `n`, an oblique normal)
/// answers `false`, as does a path that never reaches the target or
/// reaches it anywhere but on that face.
pub(crate) fn face_past_walls<'w, S: Scalar + 'w>(
    moving: &Shape<S>,
    at: Vec2<S>,
    motion: Vec2<S>,
    restitution: S,
    target: (&Shape<S>, Vec2<S>),
    n: Vec2<S>,
    walls: impl Iterator<Item = (&'w Shape<S>, Vec2<S>, S)> + Clone,
) -> bool {
    let (mut at, mut rest) = (at, motion);
    for _ in 0..MAX_REFLECTIONS {
        let target_hit = match shape_toi(moving, at, rest, target.0, target.1, Vec2::ZERO) {
            Toi::Hit { t, normal } => Some((t, normal)),
            _ => None,
        };
        // The earliest wall met (touching counts at t = 0 if the motion goes
        // into it).
        let mut earliest: Option<(S, Vec2<S>, S)> = None;
        for (shape, position, e) in walls.clone() {
            let hit = match shape_toi(moving, at, rest, shape, position, Vec2::ZERO) {
                Toi::Hit { t, normal } => Some((t, normal)),
                Toi::Overlapping => {
                    let normal = contact_between(moving, at, shape, position).normal;
                    rest.dot(normal).is_positive().then_some((S::ZERO, normal))
                }
                Toi::Miss => None,
            };
            if let Some((t, normal)) = hit
                && earliest.is_none_or(|(best, _, _)| t < best)
            {
                earliest = Some((t, normal, e));
            }
        }
        match (target_hit, earliest) {
            // The target first (or together with a wall): on its face?
            (Some((t, normal)), wall) if wall.is_none_or(|(tw, _, _)| t <= tw) => {
                return normal == n;
            }
            (_, None) => return false,
            (_, Some((t, normal, e))) => {
                if normal.dot(n) != S::ZERO {
                    return false;
                }
                let travelled = rest.scale(t);
                at += travelled;
                let remaining = rest - travelled;
                // Reflect the part of the remaining motion into the wall
                // with the pair's restitution (as the bounce will).
                let into = remaining.dot(normal);
                let e1 = S::ONE.add(restitution.max(e));
                rest = if into.is_positive() {
                    remaining - normal.scale(e1.mul(into))
                } else {
                    remaining
                };
            }
        }
    }
    false
}
