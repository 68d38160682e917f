//! Whether a pair whose straight sweep misses meets after all, because one
//! body is turned by something else it hits first in the same substep.
//!
//! # Why
//!
//! The narrow phase drops a closing speculative row when the exact time of
//! impact along the pair's straight motion misses (the body passes a corner
//! with clearance: a row would stop it in mid-air). That straight motion is
//! only the body's real path if nothing else stops it first. A small ball
//! thrown down into the corner of a wall standing flush on a floor sweeps
//! *under* the wall's bottom corner, through the floor: the wall pair
//! misses, its row is dropped, the floor row then turns the ball's motion
//! horizontal, and nothing holds it back from the wall — it slides along
//! the seam through the wall. A miss whose path runs through another body is
//! not a clearance.
//!
//! # The turned path
//!
//! The second look runs after every row of the substep is made, so it knows
//! every row each body meets (a row that closes within the substep,
//! touching rows included) as the solver will take it: its normal `n₁`
//! (from `X` to the partner `Z`) and gap `s₁` — a row re-aimed at an
//! impact, or taken on a level seam's face, turns the body the way the
//! solve will. `X` is taken to move straight until the row closes,
//! `t₁ = s₁ / (−(v_Z − v_X)·n₁·h)`, and then with its velocity along `n₁`
//! matched to `Z`'s: `v_X' = v_X + ((v_Z − v_X)·n₁)·n₁` — what a contact does
//! to a body meeting something immovable. The pair is swept again from the
//! positions at `t₁` over the rest of the substep, `Y` moving straight. A
//! hit at fraction `t₂` of that rest, normal `n₂`, makes the row: along
//! `n₂`, with the gap the turned motion closes up to the impact,
//! `s' = −h·(t₁·(Δv·n₂) + t₂·(1 − t₁)·(Δv'·n₂))` (`Δv = v_b − v_a` before,
//! `Δv'` after the turn), the same re-aim as a straight hit
//! (`s' = −t·(Δv·n')·h`). The solver's row then lets the pair close at most
//! `s'` along `n₂` this substep: the body stops at the wall.
//!
//! A miss tries every row `X` meets (a movable `Z` turns it less than
//! assumed, so trying every turn keeps at least every row the real motion
//! needs; the first hit, in a fixed order, wins). A straight hit is re-aimed
//! only for the earliest turn by an immovable body before it (exact: see
//! [`earlier_turn`]).
//!
//! # Beside `face_past_walls`
//!
//! `collision::face_past_walls` asks the same question ("does the body
//! reach this face after all?") of the other motion the engine gives a body
//! in a substep: the *bounce*, its path reflected with restitution off fixed
//! walls at rest orthogonal to the face (as many reflections as a bullet
//! takes). It answers in the loop, for face contacts only, and keeps the
//! row along the start normal. This module answers for the solve's own
//! motion, the turn (velocity along the row matched to the partner's, the
//! slide a contact gives) by any row the body meets — movable partners,
//! oblique normals, re-aimed rows — and also re-aims straight hits. A row
//! either of them finds is kept: the solve and the bounce that follows it
//! both move the body in the same substep, so a face either path reaches
//! must be held. (On the room family of `tests/bounces_in_rooms_energy.rs`
//! the turn alone already keeps every row the reflections keep; the
//! reflections stay for what one turn cannot follow, several bounces in a
//! substep.)

use crate::dynamics::Body;
use crate::geometry::{Contact, Toi};
use crate::math::{Scalar, Vec2};
use crate::solver::row::ContactConstraint;

use super::narrow_phase::{contact_between, shape_toi};

/// The rows each body meets this substep (rows that close within it,
/// touching rows included), as the solver will take them: partner, normal
/// (from the body to the partner) and gap. Lists threaded through one
/// array, built from the rows (`O(1)` per row) only for the bodies of the
/// pairs looked at again.
#[derive(Clone, Debug, Default)]
pub(crate) struct MeetingRows<S: Scalar> {
    /// Per slot: the index of its last entry, `u32::MAX` for none.
    first: Vec<u32>,
    /// Entries: `(partner, normal, gap, previous entry of the same slot)`.
    entries: Vec<(u32, Vec2<S>, S, u32)>,
}

impl<S: Scalar> MeetingRows<S> {
    /// No rows yet, for `slot_count` slots (the buffers kept).
    pub(crate) fn reset(&mut self, slot_count: usize) {
        self.first.clear();
        self.first.resize(slot_count, u32::MAX);
        self.entries.clear();
    }

    /// Records the meeting row `row` (in the lists of the sides `keep`
    /// selects: `(a, b)`).
    pub(crate) fn link(&mut self, row: &ContactConstraint<S>, keep: (bool, bool)) {
        let sides = [
            (row.a, row.b, row.normal, keep.0),
            (row.b, row.a, -row.normal, keep.1),
        ];
        for (i, other, normal, kept) in sides {
            if !kept {
                continue;
            }
            if let Some(head) = self.first.get_mut(i as usize) {
                let entry = u32::try_from(self.entries.len()).unwrap_or(u32::MAX);
                self.entries.push((other, normal, row.separation, *head));
                *head = entry;
            }
        }
    }

    /// The rows slot `i` meets (latest first): partner, normal from `i` to
    /// it, gap.
    fn of(&self, i: u32) -> impl Iterator<Item = (u32, Vec2<S>, S)> + '_ {
        let mut at = self.first.get(i as usize).copied().unwrap_or(u32::MAX);
        core::iter::from_fn(move || {
            let &(other, normal, gap, previous) = self.entries.get(at as usize)?;
            at = previous;
            Some((other, normal, gap))
        })
    }
}

/// One body of a pair: its slot, body, velocity and inverse mass.
#[derive(Clone, Copy)]
pub(crate) struct Side<'b, S: Scalar> {
    pub(crate) slot: u32,
    pub(crate) body: &'b Body<S>,
    pub(crate) velocity: Vec2<S>,
    pub(crate) inverse_mass: S,
}

/// The row (normal from `a` to `b`, gap) of the pair `(a, b)` whose straight
/// sweep over the substep `h` missed, if one of its bodies, turned by a
/// partner it hits first (see the module notes), meets the other this
/// substep; `None` when it is a clearance. Every partner's turn is tried
/// (the first that hits wins): a movable partner turns the body less than
/// assumed, so trying them all keeps every row the real motion may need.
pub(crate) fn deflected_impact<'b, S: Scalar + 'b>(
    a: Side<'b, S>,
    b: Side<'b, S>,
    partners: &MeetingRows<S>,
    velocities: &[Vec2<S>],
    h: S,
) -> Option<Contact<S>> {
    for turned_is_a in [true, false] {
        let (turned, other) = if turned_is_a { (a, b) } else { (b, a) };
        // Only a body the solver moves can be turned.
        if !turned.inverse_mass.is_positive() {
            continue;
        }
        for (z, normal, gap) in partners.of(turned.slot) {
            if z == other.slot {
                continue;
            }
            let Some(&vz) = velocities.get(z as usize) else {
                continue;
            };
            if let Some((t1, turned_velocity)) = turn(turned.velocity, vz, normal, gap, h)
                && let Some(contact) = sweep_turned(a, b, turned_is_a, t1, turned_velocity, h)
            {
                return Some(contact);
            }
        }
    }
    None
}

/// The row of the pair `(a, b)` whose straight sweep hits at fraction `t`,
/// if one of its bodies is first turned (earlier than `t`) by a partner the
/// solver cannot move (`inverse_masses` zero: fixed or kinematic, whose
/// turn is exact) and the turned motion hits too: the row is then aimed at
/// that impact instead. The straight hit of a ball thrown low into a floor
/// corner is the wall's bottom corner, under which the ball would pass; the
/// floor turns it first, and it meets the wall's face. Aimed at the corner,
/// the row would stop the ball short and, being oblique to the floor's row,
/// press it into the floor. `None` keeps the straight hit (no earlier
/// immovable turn, or the turned motion misses: a movable `Y` may still be
/// met along the straight path, so the row stays).
pub(crate) fn earlier_turn<'b, S: Scalar + 'b>(
    a: Side<'b, S>,
    b: Side<'b, S>,
    t: S,
    partners: &MeetingRows<S>,
    inverse_masses: &[S],
    velocities: &[Vec2<S>],
    h: S,
) -> Option<Contact<S>> {
    // The earliest turn of either body (ties: the first found).
    let mut earliest: Option<(S, bool, Vec2<S>)> = None;
    for turned_is_a in [true, false] {
        let (turned, other) = if turned_is_a { (a, b) } else { (b, a) };
        if !turned.inverse_mass.is_positive() {
            continue;
        }
        for (z, normal, gap) in partners.of(turned.slot) {
            if z == other.slot
                || inverse_masses
                    .get(z as usize)
                    .is_none_or(|w| w.is_positive())
            {
                continue;
            }
            let Some(&vz) = velocities.get(z as usize) else {
                continue;
            };
            if let Some((t1, turned_velocity)) = turn(turned.velocity, vz, normal, gap, h)
                && t1 < t
                && earliest.is_none_or(|(first, _, _)| t1 < first)
            {
                earliest = Some((t1, turned_is_a, turned_velocity));
            }
        }
    }
    let (t1, turned_is_a, turned_velocity) = earliest?;
    sweep_turned(a, b, turned_is_a, t1, turned_velocity, h)
}

/// The pair `(a, b)` swept from the positions at fraction `t1` over the
/// rest of the substep, the turned body with `turned_velocity`, the other
/// straight on: the row aimed at the impact (module notes), `None` on a
/// miss.
fn sweep_turned<S: Scalar>(
    a: Side<'_, S>,
    b: Side<'_, S>,
    turned_is_a: bool,
    t1: S,
    turned_velocity: Vec2<S>,
    h: S,
) -> Option<Contact<S>> {
    let rest = S::ONE.sub(t1);
    let (va_turned, vb_turned) = if turned_is_a {
        (turned_velocity, b.velocity)
    } else {
        (a.velocity, turned_velocity)
    };
    let at_turn = |side: Side<'_, S>| side.body.position + side.velocity.scale(h.mul(t1));
    match shape_toi(
        &a.body.shape,
        at_turn(a),
        va_turned.scale(h.mul(rest)),
        &b.body.shape,
        at_turn(b),
        vb_turned.scale(h.mul(rest)),
    ) {
        Toi::Miss => None,
        Toi::Hit { t, normal } => {
            let before = t1.mul((b.velocity - a.velocity).dot(normal));
            let after = t.mul(rest).mul((vb_turned - va_turned).dot(normal));
            let separation = h.mul(before.add(after)).neg().max(S::ZERO);
            Some(Contact { normal, separation })
        }
        // Touching where the turn begins (the straight sweep found no
        // contact before: within rounding): the start geometry's row.
        Toi::Overlapping => Some(contact_between(
            &a.body.shape,
            a.body.position,
            &b.body.shape,
            b.body.position,
        )),
    }
}

/// When a body of velocity `vx` meets a partner of velocity `vz` through a
/// row of normal `normal` (from the body to the partner) and gap `gap` —
/// the fraction `t₁ = gap / (−(v_z − v_x)·n·h)` of the substep — and its
/// velocity after, matched along the normal to the partner's (`None` if the
/// row does not close). The row as the solver takes it, not the bare
/// geometry: a row the narrow phase re-aimed or took on a level seam turns
/// the body the way the solve will.
fn turn<S: Scalar>(
    vx: Vec2<S>,
    vz: Vec2<S>,
    normal: Vec2<S>,
    gap: S,
    h: S,
) -> Option<(S, Vec2<S>)> {
    let closing = (vz - vx).dot(normal);
    if !closing.is_negative() {
        return None;
    }
    // The row meets: `0 < gap ≤ −closing·h`, so `t₁ ∈ (0, 1]`.
    let travel = closing.neg().mul(h);
    let t1 = if gap.is_positive() && travel.is_positive() {
        gap.div(travel).min(S::ONE)
    } else {
        S::ZERO
    };
    Some((t1, vx + normal.scale(closing)))
}
