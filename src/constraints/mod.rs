//! Constraints: bendy springs, radial springs and ropes.
//!
//! # Spring integration (trapezoidal, "implicit midpoint")
//!
//! Springs are integrated with the trapezoidal rule on the relative
//! coordinate `x` (stretch) and velocity `v` along the spring's axis, with
//! `W = w_a + w_b` the summed inverse masses:
//!
//! ```text
//! v' = v + h·W·(-k·(x + x')/2 - c·(v + v')/2)
//! x' = x + h·(v + v')/2
//! ```
//!
//! Solved for the impulse `λ = (v' - v)/W` on `b` (and `-λ` on `a`):
//!
//! ```text
//! g = h·(k·h/4 + c/2)
//! λ = -(2·g·v + h·k·x) / (1 + W·g)          (the divisor is ≥ 1: never zero)
//! ```
//!
//! Why this one: for an undamped spring the trapezoidal map conserves
//! `k·x² + v²/W` exactly (its eigenvalues lie on the unit circle for every
//! `ω·h`), so a stiff spring (`ω·h = 10`) can never gain energy or grow its
//! amplitude — explicit Euler explodes there. Unlike implicit Euler, it
//! has no numerical damping, so a resolved spring (`ω·h = 0.1`) keeps its
//! amplitude; its period error is `1 - ω·h / (2·atan(ω·h/2)) ≈ (ω·h)²/12`
//! = 0.08 % at `ω·h = 0.1`. With damping `c = 2ζω/W` the decay rate is also
//! second-order accurate.
//!
//! The engine integrates positions from end-of-step velocities
//! (`x' = x + h·v'`), so to get `x + h·(v + v')/2` the spring's velocity
//! change `Δv` is also recorded and `-h·Δv/2` is added to the displacement.
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
pub(crate) mod rope_block;
pub(crate) mod spring;

use serde::{Deserialize, Serialize};

pub use anchor::Anchor;
pub use constraint::Constraint;
pub use constraint_id::ConstraintId;

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
