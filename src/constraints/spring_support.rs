//! Contacts inside the spring solve: the rows that let a spring see the
//! bodies its ends rest on or carry (maths in [`crate::constraints`],
//! "Springs and contacts").
//!
//! The spring solve runs before the contact solve. Alone, it treats a body
//! that rests on the ground as free: a compressed spring standing on the
//! ground then computes its impulse for the effective mass `1/(w_a + w_b)`
//! of two free ends, while the ground holds the bottom end and the top body
//! really answers with `1/w_b`. The θ-method's stretch change `Δx_s` in the
//! spring's equation is then not the one the positions make, and the
//! energy balance gains the term `−k·θ_s·(Δx_assumed − Δx)·Δx`, of either
//! sign (a spring pair on the ground at ω·h = 1, g = 100 rose 6.9 % above
//! its start). So the sweeps also carry, as inequality rows on the same
//! position velocities, every contact row of the substep that reaches a
//! spring-moved body through contacts: the spring's impulse then sees the
//! ground holding, or the boxes riding on, its ends. Their impulses are
//! only the spring solve's view of the contacts: they are taken back out
//! of the position velocities when the sweeps end (exactly: each slot's
//! pushes are summed in [`SupportScratch::pushed`]), and the contact solve
//! then finds its own, warm started as always. The exception are the rows
//! solved with a stiff group (`held`, `spring_direct.rs`): their impulses
//! are final, their pushes stay ([`SupportScratch::kept`]), and the contact
//! solve leaves them (`world/step/constraints.rs`).

use crate::math::{Scalar, Vec2};

/// One contact row as the spring sweeps see it: the relative normal
/// position velocity `n·(p_b − p_a)` must not fall below `target`
/// (the contact row's own speculative or restitution bound), with a
/// pushing-only impulse `μ ≥ 0`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct SupportRow<S: Scalar> {
    /// Slot of the first body.
    pub(crate) a: u32,
    /// Slot of the second body.
    pub(crate) b: u32,
    /// Unit normal from `a` to `b`.
    pub(crate) normal: Vec2<S>,
    /// The lowest allowed `n·(p_b − p_a)`.
    pub(crate) target: S,
    /// `1 / (w_a + w_b)`.
    pub(crate) effective_mass: S,
    /// `w_a·n` and `w_b·n`: the position-velocity change per unit impulse
    /// (a contact moves the positions by all of its impulse, θ = 1).
    pub(crate) push: (Vec2<S>, Vec2<S>),
    /// The accumulated impulse `μ ≥ 0`.
    pub(crate) impulse: S,
    /// Solved with a stiff group's exact solve (`spring_direct.rs`): the
    /// sweeps leave it as it is.
    pub(crate) held: bool,
    /// The pair's Coulomb friction coefficient (the direct solve of stiff
    /// groups carries the friction impulse too, `spring_direct.rs`).
    pub(crate) friction: S,
    /// The pair touches (separation within the slop) at the substep's
    /// start: its ends take the contact solver's blend θ = 1.
    pub(crate) touching: bool,
    /// Index of the contact row (the substep's contact constraints).
    pub(crate) contact: u32,
    /// A held row's friction impulse (along `perp(n)`).
    pub(crate) tangent: S,
    /// The bounce of a contact that meets this substep fast enough to
    /// bounce (a bounce candidate), if it can meet within the substep.
    pub(crate) bounce: Option<SupportBounce<S>>,
    /// The bounce is solved here ([`SupportBounce`]): `target` is its end
    /// velocity, the impulse is capped, and its pushes are final.
    pub(crate) launched: bool,
}

/// A bounce solved inside the spring solve (see [`crate::constraints`],
/// "Springs and contacts", 4.): the row is driven to the bounce's end
/// velocity with an impulse of at most `cap`, and never below its
/// speculative target `floor`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct SupportBounce<S: Scalar> {
    /// The end velocity of the bounce (`restitution::bounce_end`).
    pub(crate) velocity: S,
    /// `(1 + e)·|u₀|·m`: the impulse of the impact itself, from the
    /// approach `u₀` before any spring acted.
    pub(crate) cap: S,
    /// When the pair meets within the substep (`s/|u₀|`): a body's
    /// earliest meeting bounces here.
    pub(crate) meets: S,
    /// The row's speculative target (no closing beyond the gap).
    pub(crate) floor: S,
}

/// The support rows of a substep and what they pushed.
#[derive(Clone, Debug, Default)]
pub(crate) struct SupportScratch<S: Scalar> {
    /// The rows, in contact-row order.
    pub(crate) rows: Vec<SupportRow<S>>,
    /// Each slot's summed support pushes (to take them back out).
    pub(crate) pushed: Vec<Vec2<S>>,
    /// Per slot: reached from a spring-moved body through contacts.
    pub(crate) reached: Vec<bool>,
    /// Each slot's summed pushes of the held rows: kept when the others
    /// are taken back (a stiff group's contacts are final, see
    /// [`crate::constraints`], "Springs and contacts").
    pub(crate) kept: Vec<Vec2<S>>,
    /// Per slot: an end of a support row (its blend is θ = 1).
    pub(crate) contacted: Vec<bool>,
    /// The search's buffers (kept to step without allocating): each
    /// slot's first incident contact row, the fill cursors, the incident
    /// rows, the rows taken and the slots still to visit.
    pub(crate) start: Vec<u32>,
    pub(crate) fill: Vec<u32>,
    pub(crate) incident: Vec<u32>,
    pub(crate) taken: Vec<bool>,
    pub(crate) frontier: Vec<u32>,
}

impl<S: Scalar> SupportScratch<S> {
    /// One projected Gauss–Seidel sweep over the rows; returns the largest
    /// impulse change.
    pub(crate) fn sweep(&mut self, position_velocities: &mut [Vec2<S>]) -> S {
        let mut largest = S::ZERO;
        for row in self.rows.iter_mut().filter(|row| !row.held) {
            let (a, b) = (row.a as usize, row.b as usize);
            let relative = position_velocities[b] - position_velocities[a];
            let wanted = row
                .target
                .sub(relative.dot(row.normal))
                .mul(row.effective_mass);
            // μ stays ≥ 0: the new impulse is max(0, μ + wanted).
            let mut change = wanted.max(row.impulse.neg());
            if row.launched
                && let Some(bounce) = row.bounce
            {
                // A launched bounce: at most the impact's impulse, but
                // never closing beyond the gap whatever the cap.
                let floor = bounce
                    .floor
                    .sub(relative.dot(row.normal))
                    .mul(row.effective_mass)
                    .max(row.impulse.neg());
                change = change.min(bounce.cap.sub(row.impulse)).max(floor);
            }
            if change == S::ZERO {
                continue;
            }
            row.impulse = row.impulse.add(change);
            let (push_a, push_b) = (row.push.0.scale(change), row.push.1.scale(change));
            position_velocities[a] -= push_a;
            position_velocities[b] += push_b;
            self.pushed[a] -= push_a;
            self.pushed[b] += push_b;
            if row.launched {
                self.kept[a] -= push_a;
                self.kept[b] += push_b;
            }
            largest = largest.max(change.abs());
        }
        largest
    }

    /// Takes every support push but the held rows' back out of the
    /// position velocities, bit for bit (the same sums were added; sums of
    /// fixed-point values are exact).
    pub(crate) fn take_back(&self, position_velocities: &mut [Vec2<S>]) {
        for ((p, pushed), kept) in position_velocities
            .iter_mut()
            .zip(&self.pushed)
            .zip(&self.kept)
        {
            *p -= *pushed - *kept;
        }
    }

    /// Clears every row's impulse and every push (launched bounces stay
    /// launched).
    pub(crate) fn clear_impulses(&mut self) {
        for row in self.rows.iter_mut() {
            row.impulse = S::ZERO;
            row.tangent = S::ZERO;
            row.held = false;
        }
        self.pushed.iter_mut().for_each(|p| *p = Vec2::ZERO);
        self.kept.iter_mut().for_each(|p| *p = Vec2::ZERO);
    }
}
