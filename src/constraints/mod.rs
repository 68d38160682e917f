//! Constraints: bendy springs, radial springs and ropes.
//!
//! # Spring integration (θ-method between trapezoidal and implicit Euler)
//!
//! Springs are integrated on the relative coordinate `x` (stretch) and
//! velocity `v` along the spring's axis, with `W = w_a + w_b` the summed
//! inverse masses, by the θ-method:
//!
//! ```text
//! v' = v − h·W·(k·x_θ + c·v_θ),   x' = x + h·v_θ,
//! v_θ = (1−θ)·v + θ·v',            x_θ = x + θ·h·v_θ
//! ⇒ λ = (v' − v)/W = −(g·v + h·k·x) / (1 + W·θ·g),   g = h·(k·θ·h + c)
//! ```
//!
//! (the divisor is ≥ 1: never zero). The blend is
//! `θ = 1/2 + min(1/2, (ω·h)⁴/32)` with `(ω·h)² = k·W·h²`:
//!
//! * A resolved spring (`ω·h = 0.1`) is integrated by the trapezoidal rule
//!   (θ = 1/2 + 3e-6): the energy `k·x² + v²/W` is conserved up to a
//!   damping of ~6e-8 per step (amplitude −0.04 % after 100 periods), and
//!   the period error is `ω·h/(2·atan(ω·h/2)) − 1 ≈ (ω·h)²/12` = 0.08 %.
//!   Implicit Euler (θ = 1) would lose 27 % of the amplitude per period here.
//! * A stiff spring (`ω·h = 10`) is integrated by implicit Euler (θ = 1):
//!   unconditionally stable, and the mode the step cannot resolve is damped
//!   out within a few steps instead of ringing at the Nyquist rate. Explicit
//!   Euler explodes here (its amplification is √(1 + (ω·h)²) = 10 per step).
//! * For every θ ≥ 1/2 the scheme never gains energy, so the amplitude of a
//!   spring released from rest never exceeds its initial stretch.
//! * With damping `c = 2ζω/W`, the decay rate is second-order accurate
//!   while the spring is resolved.
//!
//! The engine integrates positions from end-of-step velocities
//! (`x' = x + h·v'`), so the `(1−θ)·Δv` share of the spring's velocity
//! change is recorded and `h` times it subtracted from the displacement.
//!
//! # Ropes
//!
//! A rope is an inequality row in the contact solver (same impulse loop, so
//! a rope and the ground act together): with `n` the unit vector from `a` to
//! `b`, slack `s = L - |d|`, and `v_n = (v_b - v_a)·n`, the row demands
//! `v_n ≤ s/h` with a pulling-only impulse (speculative, like contacts: the
//! rope becomes taut exactly at full length). Restitution `e` sets the
//! target `v_n ≤ -e·v_n0` when the rope snaps taut.

mod anchor;
mod constraint;
mod constraint_id;
pub(crate) mod spring;

use serde::{Deserialize, Serialize};

pub use anchor::Anchor;
pub use constraint::Constraint;
pub use constraint_id::{ConstraintId, ConstraintMarker};

use crate::dynamics::BodyId;
use crate::math::Scalar;

/// A constraint slot: generation counter and maybe a constraint with its
/// solver state.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) struct ConstraintSlot<S: Scalar> {
    pub(crate) generation: u32,
    pub(crate) entry: Option<ConstraintEntry<S>>,
}

/// A live constraint and the state the solver carries between steps.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub(crate) struct ConstraintEntry<S: Scalar> {
    pub(crate) constraint: Constraint<S>,
    /// A rope's accumulated impulse of the last substep (warm start); zero
    /// for springs and slack ropes.
    pub(crate) impulse: S,
}

/// The two bodies of every live constraint whose anchors are both on bodies,
/// in slot order (`(a, b)` as [`Constraint::anchors`] gives them).
/// Constraints with a point anchor join no two bodies and are skipped.
///
/// This is how the rest of the engine sees constraints as links between
/// bodies: waking across them, joining sleep islands, waking a woken body's
/// partners. The ids are not checked against the body slots; each caller
/// looks the bodies up with the rule it needs (a generation-checked lookup,
/// or the slot alone).
pub(crate) fn constraint_body_pairs<S: Scalar>(
    slots: &[ConstraintSlot<S>],
) -> impl Iterator<Item = (BodyId, BodyId)> + '_ {
    slots
        .iter()
        .filter_map(|slot| slot.entry.as_ref())
        .filter_map(|entry| {
            let (a, b) = entry.constraint.anchors();
            Some((a.body()?, b.body()?))
        })
}
