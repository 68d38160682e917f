//! Constraints: bendy springs, radial springs and ropes.
//!
//! # Spring integration (θ-method between trapezoidal and implicit Euler)
//!
//! Each spring (each axis of a bendy spring; a radial spring along its
//! pole) has a stretch `x_s`, stiffness `k_s`, damping `c_s`, and
//! `ω_s² = k_s·W_s` with `W_s = w_a + w_b` the summed inverse masses. A
//! substep of length `h` gives every spring an impulse `λ_s` and every body
//! a velocity change `Δv = M⁻¹·Gᵀ·λ` (`G` maps body velocities to stretch
//! rates), and moves each body by `Δq_b = h·(v_b + θ_b·Δv_b)`. The
//! impulses solve, all together,
//!
//! ```text
//! λ_s = −h·k_s·(x_s + θ_s·Δx_s) − c_s·Δx_s,    Δx_s = (G·Δq)_s
//! ```
//!
//! (the force evaluated a fraction θ_s into the step). For one spring
//! between two bodies with θ_b = θ_s this is the classic θ-method
//! `λ = −(g·v + h·k·x) / (1 + W·θ·g)`, `g = h·(k·θ·h + c)`.
//!
//! ## Energy: never gained
//!
//! With `E = ½·vᵀ·M·v + ½·Σ_s k_s·x_s²` (linear springs), write
//! `v̄ = v + ½·Δv`, `x̄ = x + ½·Δx`; then `ΔE = v̄ᵀ·M·Δv + x̄ᵀ·K·Δx`. From the
//! equation above, `k_s·x̄_s = −λ_s/h − (θ_s − ½)·k_s·Δx_s − c_s·Δx_s/h`, and
//! `Δx = h·G·(v + Θ_b·Δv)`, `Gᵀ·λ = M·Δv`, so
//!
//! ```text
//! ΔE = −Σ_b (θ_b − ½)·m_b·|Δv_b|² − Σ_s ((θ_s − ½)·k_s + c_s/h)·Δx_s² ≤ 0
//! ```
//!
//! for any blends θ_s, θ_b ≥ ½, at any step size: the trapezoidal rule
//! (all θ = ½, c = 0) conserves the energy exactly, and a larger θ damps.
//!
//! ## Why springs are solved together
//!
//! The proof needs every λ_s to see the others: the `Δx_s` in a spring's
//! equation is the stretch change the positions will really make, with
//! every impulse on its two bodies included. Applying springs one after
//! another, each treating the velocities the earlier ones already changed
//! as the start of the step (as this engine did before: a spring's rate
//! term saw the full earlier Δv where the positions follow only θ of it),
//! is a different map whose energy balance has an extra term of either
//! sign: 32 × 32 lattices of light bodies at ω·h ≈ 1 gained energy
//! without bound. So the step builds one row per spring and
//! solves the system above by Gauss–Seidel sweeps (`spring_solve.rs`), a
//! resolved bendy spring starting from its free impulse
//! `−h·k_s·x_s − g_s·ṽ_s` (exact inside a uniformly loaded lattice), the
//! others from 0: in the symmetrised form `(h²·K·Θ_s)⁻¹ + G·Θ_b·M⁻¹·Gᵀ`
//! (positive definite) the sweeps converge, and they stop when a sweep's
//! largest change is ≤ 2⁻⁹ of the largest impulse, or after 8 sweeps. A
//! single spring, or springs that share no body, are exact in the first.
//! The remaining residual `r` adds `Σ_s r_s·Δx_s/h` to ΔE; measured on
//! lattices, chains, uneven masses and ω·h from 0.1 to 10
//! (`tests/spring_lattice_energy.rs`), the energy never rose above
//! 1.0002 × its start.
//!
//! ## Stiff networks: the direct solve
//!
//! The residual term is harmless only while the sweeps converge. For a
//! stiff spring (θ = 1) a stretch-rate residual `r_v` really moves the
//! positions, so the network stores `½·k·h²·r_v² = ½·(ω·h)²·r_v²/W` of
//! spring energy: at ω·h = 100 a residual of 1 % of the kick is already
//! about the whole energy. Gauss–Seidel needs a number of sweeps that
//! grows with `(ω·h)²` and the network's size for the smooth modes; capped
//! at 8, a 32 × 32 bendy lattice at ω·h = 50 / 100 rose to 2.5 / 10 × its
//! energy in its first tick, a braced radial one at ω·h = 20 / 100 to
//! 1.13 / 26 ×. So every group of springs joined through moving bodies
//! that holds a stiff row (`g·(θ_a·w_a + θ_b·w_b) ≥ 1`, ω·h ≳ 1.65 for equal
//! masses) and more than one row is solved exactly first, and so is a
//! lone radial row whose sweeps do not settle (a pole turning far within
//! the substep) when every contact that reaches it is solved with it (no
//! wall, no third body with contacts of its own beyond the row's ends:
//! `spring_direct.rs`): the system above in body space,
//!
//! ```text
//! (M·Θ_b⁻¹ + Gᵀ·D_g·G)·(p − v₀) = Gᵀ·(t − D_g·G·v₀),   D_g = diag(g_s),
//! ```
//!
//! symmetric positive definite (a weighted graph Laplacian plus the mass
//! diagonal), factored as `L·D·Lᵀ` in fixed point (envelope storage in a
//! reverse Cuthill–McKee order; the factor is kept while the matrix is
//! unchanged, as it is for a swinging bendy lattice) and solved with
//! iterative refinement against the rows' own impulse formulas (for
//! radial rows a Newton iteration whose matrix carries the tension's
//! sideways stiffness, and whose residual, where it does not converge, is
//! kept from doing more work than the step dissipates).
//! The exact solution has `r = 0`, so the bound above holds; what is left
//! is rounding. Two details keep that rounding from being amplified by
//! `(ω·h)²`: the body velocities are the solved `p` (the impulses are
//! recomputed from it as bookkeeping, not pushed back onto `v₀`, which
//! would move each body by `θ_b·w_b` times the solve's residual), and the
//! refinement runs until a pass moves nothing by more than 2⁻²⁰ of the
//! first (the factor's entries carry an absolute rounding of about
//! `ulp·g`, against a mass term up to 10⁶ times smaller). Measured: 32 × 32
//! bendy and braced radial lattices, 200-body chains, every third body
//! 100× heavier, an anchored edge, ω·h from 20 to 3000 (the lightest mass
//! and nearly the stiffest spring the engine accepts): never above
//! 1.000000 × the start energy (`tests/spring_lattice_energy.rs`). The
//! sweeps then run as before (contacts, radial nonlinearity) from a point
//! where every direct row's equation already holds.
//!
//! ## Springs and contacts
//!
//! The contact solve integrates positions from end-of-step velocities
//! (θ = 1 for every contact impulse) and runs after the springs. Two things
//! broke the balance above for springs that stand on or carry something
//! (a spring pair standing on the ground, ω·h = 1: +4.7 % energy, g = 100:
//! +47 %, the bottom body hopping off the ground):
//!
//! 1. **The lag.** A body's position follows `v₀ + θ_b·Δv_s` of its spring
//!    impulse, and the engine stores `(1 − θ_b)·Δv_s` as a lag subtracted
//!    from `h·v'` at integration. When a contact then cancels the spring's
//!    push into the ground (`v' = 0`), the displacement is
//!    `−h·(1 − θ_b)·Δv_s`: the body is lifted *out of* the ground by half
//!    the spring push (`θ_b = ½`), every step the spring is loaded. In the
//!    balance this is the cross term `−θ_b·Δv_sᵀ·M·Δv_c` of the two
//!    impulses followed by different fractions, positive when the contact
//!    opposes the spring. Cure: a body that touches another (a contact row of the substep
//!    within the slop) takes `θ_b = 1` (the proof above holds for every
//!    `θ_b ≥ ½`), so spring and contact impulses move it alike and the lag
//!    is zero. The price is the body term `−½·m_b·|Δv_b|²`: nothing for a
//!    body a contact holds still, an `O((ω·h)²)` damping per step for a
//!    body that rides a spring with its load. A contact that is not
//!    touching yet acts too when the spring drives a body into it within
//!    the substep (a pair at ω·h = 1 driven at a wall 0.6 away: the
//!    contact clamped the end velocity of a body whose position, lagging,
//!    would never have reached the wall: +0.19 J of 5): so after a first
//!    solve every spring-moved end of a contact row that the sweeps pushed,
//!    or that the end velocities `v₀ + (p − v₀)/θ_b` close beyond its
//!    target, takes `θ_b = 1` too, and the springs are solved again.
//!    Rows that take no impulse leave their bodies' blends alone (a folding
//!    lattice's neighbours within the margin).
//! 2. **The effective mass.** A spring solved alone treats the body on the
//!    ground as free: its impulse is computed for the stretch change of two
//!    free ends while the ground holds one, so the `Δx_s` in its equation
//!    is not the one the positions make, and the balance gains
//!    `−k_s·θ_s·(Δx_assumed − Δx)·Δx`: with `λ ≈ −h·k·x` about
//!    `½·θ_s·θ_a·k²·h²·w_a·Δ(x²)` per step, a rise of `θ_s·θ_a·(ω·h)²·w_a/W`
//!    of the spring's energy whenever it compresses (measured +6.9 % at
//!    ω·h = 1, g = 100). Cure: the spring solve runs after the narrow phase
//!    and its sweeps carry, as inequality rows on the same position
//!    velocities, every contact row that reaches a spring-moved body
//!    through contacts (`spring_support.rs`): the springs then see the
//!    ground hold and the boxes ride, i.e. they solve the coupled system.
//!    Those contact impulses are taken back out afterwards (the contact
//!    solve finds its own, warm started).
//! 3. **Stiff groups.** Against a group solved exactly (below), the sweeps'
//!    contact rows answer with the mass of their two bodies alone while
//!    the group answers as one, and 8 sweeps leave most of a contact's
//!    push unsolved in the spring rows (a folding 20-link chain at
//!    ω·h = 30: +2.6 J of spring energy in a substep); friction, applied
//!    later by the contact solve to one body, does the same. So the
//!    contact rows that reach such a group, normal and friction impulses,
//!    are solved with it through the group's factor
//!    (`spring_direct.rs`, `couple_contacts`), and the sweeps leave them.
//!    Their impulses are final: they are not taken back (an end no spring
//!    moves then takes θ_b = 1, so its velocity gets the push once, as a
//!    contact gives it), and the contact solve leaves those rows (each
//!    asks no more than the normal velocity it has after the spring solve,
//!    from no warm start). Handed back to
//!    the contact solve, a strike was answered by the struck body alone
//!    while the group's springs did not move within the substep, and the
//!    spring stored `½·(ω·h)²·|Δv|²/W` of the contact's velocity change
//!    `Δv`: 20 links of 0.001 at ω·h = 300 striking the ground gained 12 J
//!    (their whole energy is 0.42 J). Where the coupled rounds do not
//!    settle (an impact that turns and loads the poles faster than the
//!    Newton linearisations follow), the result keeps its contacts and
//!    goes through the same energy safeguard as any unconverged direct
//!    solve (the contacts' impulses counted in its residual), which pulls
//!    it back towards rest until it gains nothing.
//! 4. **Bounces.** A contact with restitution is re-timed after the
//!    position update (`solver::restitution`): driven from the approach
//!    `u₀` the narrow phase saw, before the springs, to `e·|u₀|`, and the
//!    rebound moved along its flight. Between sprung bodies that wipes the
//!    spring's velocity change along the normal and moves the ends apart
//!    where the spring's impulse had them close: a pair at ω·h = 1 thrown
//!    together at 50 units/s came apart with its kinetic energy kept and
//!    its spring stretched 0.43 (+17 J of 125), and at ω·h = 100 the
//!    spring stores `½·(ω·h)²·|Δx/h|²/W`, thousands of times the energy.
//!    So a bounce that reaches a spring-moved body through contacts is
//!    solved with the springs: the candidate rows the first solve pushed
//!    (the pair meets), each its bodies' earliest meeting, are driven to
//!    the bounce's end velocity in the second solve, their ends at
//!    `θ_b = 1`, and their impulses are final (as a stiff group's held
//!    contacts). The balance then reads, with every contact impulse moving
//!    its bodies by `h·Δv_c` and seen by the springs,
//!
//!    ```text
//!    ΔE = (the springs' dissipation above) + ½·|v₀ + Δv_c|²_M − ½·|v₀|²_M,
//!    ```
//!
//!    the contacts' work as if they acted on `v₀` alone. For one row that
//!    is `½·μ·((u₀ + c)² − u₀²)`: no gain while its velocity change
//!    `c ≤ 2·|u₀|`. A bounce that a spring pulls the pair into needs
//!    `c = (1 + e)·|u₀| + |a|` to leave at `e·|u₀|` (`a` the spring's
//!    part), which gains; so the row's impulse is capped at the impact's
//!    own, `(1 + e)·|u₀|·m`, where the term is `½·μ·(e² − 1)·u₀² ≤ 0`, and
//!    it never lets the pair close beyond the gap whatever the cap. One
//!    stiff spring and a bounce row meet along nearly one line (a pusher
//!    on a stiff radial spring thrown into a wall), where the sweeps stall
//!    and leave the spring stretched far beyond its equation, so a
//!    launched bounce counts as a row of its group for the direct solve.
//!    The price: such a bounce turns at the substep's start, from where
//!    the pair was (up to `|u₀|·h` early), not at the re-timed instant.
//!
//! **Gravity.** Gravity is a kick before the drift (`v += h·g`, then the
//! positions follow the kicked velocity), the symplectic Euler step for a
//! constant force, whose exact invariant is not `E` but
//! `E_h = E + ½·h·Σ_b m_b·g·v_b`: in free fall `ΔE = −½·m·|g|²·h²` per step
//! while `Δ(½·h·m·g·v) = +½·m·|g|²·h²`. Repeating the balance above with
//! the kick inside `v₀` gives, with springs,
//! `ΔE_h = (dissipation above) − Σ_b (θ_b − ½)·h·m_b·g·Δv_{s,b}`: exactly
//! conserved by the trapezoidal rule, and the extra term is the blend's
//! (zero to `(ω·h)⁸/512` where the step resolves the spring). The measured
//! `E` itself oscillates about `E_h` by `½·h·m·|g|·|v|` (1.4 % for the
//! pair at g = 100), which is the gravity integrator's, not the springs'.
//!
//! ## The blend
//!
//! `θ_s = 1/2 + min(1/2, (ω_s·h)⁸/512)`, and each body takes the largest
//! θ_s of its springs (θ_b = ½ for a body no spring moves). A mode of
//! frequency Ω loses `2·(θ − ½)·(Ω·h)²` of its energy per step (the two
//! damping terms above, each ≈ (Ω·h)²·E averaged over a period):
//!
//! * A resolved spring (ω·h = 0.3) is integrated by the trapezoidal rule to
//!   θ − ½ = 1.3e-7. In a square lattice a body has four springs, so the
//!   highest mode has (Ω·h)² ≤ 4·(ω·h)² = 0.36 (Gershgorin), and even that
//!   mode keeps all but 3600 · 2 · 1.3e-7 · 0.36 = 3.3e-4 of its energy
//!   over a minute. The period error of the trapezoidal rule is
//!   `ω·h/(2·atan(ω·h/2)) − 1 ≈ (ω·h)²/12` (0.08 % at ω·h = 0.1).
//! * A stiff spring (ω·h ≥ 2) is integrated by implicit Euler (θ = 1):
//!   unconditionally stable, and the mode the step cannot resolve is damped
//!   within a few steps instead of ringing at the Nyquist rate. Explicit
//!   Euler explodes here (its amplification is √(1 + (ω·h)²) per step).
//! * Between, the damping grows steeply: θ − ½ = 0.002 at ω·h = 1, 0.05
//!   at 1.5.
//! * With damping `c = 2ζω/W`, the decay rate is second-order accurate
//!   while the spring is resolved.
//!
//! The engine integrates positions from end-of-step velocities
//! (`x' = x + h·v'`), so the `(1 − θ_b)·Δv` share of each body's velocity
//! change is recorded and `h` times it subtracted from the displacement.
//!
//! ## Radial springs: a discrete gradient
//!
//! A radial spring's energy `½·k·(|r| − L)²` (`r = q_b − q_a`) is not
//! quadratic in the positions, so no fixed axis and linear stretch can
//! carry the proof above: the free sideways motion of a pole changes its
//! length by `|Δr⊥|²/(2·|r|)` at second order, and an axis fixed before the
//! step misses how the body turns within it. Instead each radial row uses
//! the *true* length change and a direction that makes the impulse's work
//! equal to it, the midpoint discrete gradient (after Gonzalez). With
//! `Δq_b = h·p_b` the displacements, `r' = r + Δq_b − Δq_a`, `l = |r|`,
//! `l' = |r'|`, `x = l − L` and `Δx = l' − l`:
//!
//! ```text
//! λ = −h·k·(x + θ_s·Δx) − c·Δx,      J = λ·d on b (−J on a),
//! d = (r + r')/(l + l'),             d·(r' − r) = (l'² − l²)/(l + l') = Δx.
//! ```
//!
//! `d` and `Δx` depend on where the solve puts the bodies, so the sweeps
//! re-evaluate them from the current position velocities at every visit of
//! the row (`spring_solve.rs`; the first visit sees `p = v₀`), and the
//! direct solve iterates Newton on them (`spring_direct.rs`).
//!
//! **Energy.** The kinetic part of the balance gains `λ·d·Δr/h` per row
//! and the spring part changes by `k·(x + ½·Δx)·Δx`; since `d·Δr = Δx`
//! exactly, `ΔE` is the expression of "Energy: never gained" with no
//! other term: never a gain, at any blends, stiffness, masses or geometry.
//! With gravity (below) the invariant of a body with blend θ_b is
//! `E + (1 − θ_b)·h·m_b·g⃗·v_b`, which changes by
//! `−(θ_b − ½)·m_b·|Δv_s,b + h·g⃗|²` (complete the square in the balance of
//! **Gravity**): `E_h` for a resolved spring, `E` for a stiff one.
//!
//! The direction used before, `u/ℓ` with `u = r + (1 − θ_b)·Δq_b −
//! (1 − θ_a)·Δq_a` (through the points the θ position rule turns the
//! bodies about, which kept the angular momentum exactly), left the work
//! defect `−(θ − ½)·λ·(|Δr|² − Δx²)/(h·ℓ)`: a gain under tension for
//! θ > ½, which the θ damping of a lone body absorbs but a light body
//! between two taut springs does not (its two pulls nearly cancel, so its
//! `|Δv|` and damping are small, while both springs' defects add). At
//! θ = 1 the direction was the start pole: the sideways stiffness of the
//! tension, `T·(1/l₁ + 1/l₂)/m`, was integrated explicitly, and two
//! springs from a fixed point with a 100× end at ω·h = 3 reached the
//! world's bound in 28 ticks (+3.5e12 J); 20 equal links at ω·h = 3 rose
//! 3.6 J (`tests/radial_chains_under_gravity.rs`).
//!
//! **Angular momentum.** For any body, `q'×v' − q×v =
//! (q + (1 − θ_b)·Δq_b) × Δv_b` under `Δq = h·(v + θ_b·Δv)`, so a row
//! between ends of blend θ changes `Σ_b m_b·q_b×v_b` by
//! `(r + (1 − θ)·Δr) × λ·(2·r + Δr)/(l + l') = (2θ − 1)·λ·(r × Δr)/(l + l')`:
//! zero for a resolved spring (θ − ½ = (ω·h)⁸/512: kept to rounding, 1e-7
//! relative in 10 s), and for a stiff one the torque of the implicit step,
//! which under tension slows the pair's turn (measured on a spinning
//! dumbbell, `tests/radial_spring_conservation.rs`). No direction does
//! both at θ > ½: keeping the momentum needs `J ∥ r + (1 − θ)·Δr`, and in a
//! turn at constant length (`Δx = 0`) that impulse does the work
//! `λ·(1 − 2θ)·|Δr|²/(2·ℓ·h)` ≠ 0 (positive under tension). The energy
//! bound is what the engine promises.
//!
//! **A circular orbit is a steady state** of the θ = ½ step: a body at
//! radius R with tangential speed v turns by φ per step with chord
//! `2·R·sin(φ/2) = h·v·cos(φ/2)` (positions follow the mean velocity), i.e.
//! `tan(φ/2) = v·h/(2·R)`; the impulse, along the mid-angle radius with
//! size `h·k·(R − L)·|d|`, `|d| = cos(φ/2)`, turns the velocity by
//! `2·m·v·sin(φ/2)` exactly when `k·(R − L) = m·v²/R`, the continuous
//! orbit's condition. So radius and speed are kept and only the phase lags,
//! `φ = 2·atan(Ω·h/2)` against `Ω·h`. (The fixed axis used before drifted
//! the radius by 1.4e-4 of itself in 10 s at Ω·h = 0.05.)
//!
//! Cost: per radial row and sweep, one square root (the length `l'`), one
//! division (`1/ℓ`) and about a dozen products; bendy rows are untouched.
//!
//! Lattices of radial springs: a square lattice of central springs has no
//! shear stiffness, its cells fold freely, and a kicked one folds until
//! bodies touch; the energy such a lattice loses goes into those
//! (inelastic) contacts, not the springs (measured, booked per tick in
//! `tests/spring_lattice_energy.rs`).
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
pub(crate) mod spring_direct;
pub(crate) mod spring_solve;
pub(crate) mod spring_support;

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
