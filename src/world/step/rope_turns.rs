//! Phase "rope turns" (within the narrow phase, when a straight sweep
//! missed): how much each body's velocity is turned by its ropes, so the
//! narrow phase does not take a straight sweep's miss for a clearance when
//! a rope bends the body's path into what it misses
//! (`collision::rope_turn`).
//!
//! Why: a chain draped over a peg slides round it. Each link's straight
//! motion over a substep leaves the peg's outline (a tangent departs from a
//! circle of radius `ρ` by `s²/(2ρ)` over a slide `s`), so the exact time of
//! impact with the peg misses and the narrow phase made no row; the ropes
//! then pulled the link round, into the peg, with nothing to hold it (a
//! link of a 20-link chain with ends 1000× its mass, 3e-4 from the peg,
//! ended 1.1e-2 inside it).
//!
//! What: each rope acts on its two bodies along its direction `u` (from
//! `a` to `b`, at the ends' straight positions after the substep) with
//! what it held last substep, the impulse `λ` the warm start applies first
//! (the tension of a loaded chain: most of a draped link's turn), and with
//! what its row will take out of the excess the straight motion makes,
//! `e = |d + Δv·h| − L` (`d` the anchor offset `b − a`, `Δv = v_b − v_a`,
//! `L` the rope's length), shared by inverse mass. So `a` is turned by
//! `+(w_a·λ + (w_a/(w_a + w_b))·(e/h))·u` and `b` by
//! `−(w_b·λ + (w_b/(w_a + w_b))·(e/h))·u`; a body on several ropes adds
//! their turns. That is the turn each rope gives acting alone; the solve
//! shares pulls between neighbours, so the sum predicts the path's bend,
//! not its exact value, and the narrow phase uses it only to decide
//! whether a straight miss is a miss (and where the turned motion meets).
//! A slack rope with no impulse turns nothing, and a world without ropes
//! pays one pass over its constraints.

use crate::constraints::Constraint;
use crate::math::{Scalar, Vec2};
use crate::world::World;

impl<S: Scalar> World<S> {
    /// Fills `rope_turns` (one velocity change per slot) with the turns of
    /// the ropes that the straight motion stretches; leaves it empty when
    /// no rope does.
    pub(super) fn find_rope_turns(&mut self, h: S, inverse_h: S) {
        self.step_context.rope_turns.clear();
        for ci in 0..self.constraint_slots.len() {
            let Some(entry) = self.constraint_slots[ci].entry.as_ref() else {
                continue;
            };
            let Constraint::Rope {
                a, b, max_length, ..
            } = entry.constraint
            else {
                continue;
            };
            let (Some(sa), Some(sb)) = (self.anchor_state(&a), self.anchor_state(&b)) else {
                continue;
            };
            let w = sa.inverse_mass.add(sb.inverse_mass);
            if !w.is_positive() {
                continue;
            }
            let reached = sb.position - sa.position + (sb.velocity - sa.velocity).scale(h);
            let Some((direction, length)) = reached.try_normalize_with_length() else {
                continue;
            };
            // The excess the straight motion makes, as a velocity along
            // the rope, and last substep's impulse (the tension the warm
            // start applies first).
            let excess = length.sub(max_length).max(S::ZERO);
            let warm = entry.impulse.max(S::ZERO);
            if !(excess.is_positive() || warm.is_positive()) {
                continue;
            }
            let speed = excess.mul(inverse_h);
            let turns = &mut self.step_context.rope_turns;
            if turns.is_empty() {
                turns.resize(self.step_context.velocities.len(), Vec2::ZERO);
            }
            for (state, sign) in [(&sa, S::ONE), (&sb, S::ONE.neg())] {
                if !state.inverse_mass.is_positive() {
                    continue;
                }
                let share = speed
                    .mul(state.inverse_mass)
                    .div(w)
                    .add(warm.mul(state.inverse_mass))
                    .mul(sign);
                if let Some(turn) = turns.get_mut(state.slot as usize) {
                    *turn += direction.scale(share);
                }
            }
        }
    }
}
