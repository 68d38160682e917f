//! The simultaneous spring solve: every spring row of a substep solved
//! together (Gauss–Seidel sweeps on the impulses, from zero, until they
//! settle), so that no spring sees velocities that others already changed
//! as if they were the start of the step. Maths in [`crate::constraints`]
//! ("Why springs are solved together").

use super::spring::theta_for;
use crate::math::{Scalar, Vec2};

/// Most sweeps of one spring solve. A resolved lattice (ω·h ≤ 0.3)
/// settles in 2–3 sweeps, ω·h = 1 in about 4 (the tolerance below); stiffer
/// springs are implicit Euler (θ = 1), whose damping absorbs what the capped
/// iteration leaves (measured: `tests/spring_lattice_energy.rs`).
pub(crate) const MAX_SPRING_SWEEPS: usize = 8;

/// The spring equations of one constraint: a bendy spring's two (one per
/// axis, independent lanes x and y), or a radial spring's one, along its
/// pole (lane x).
#[derive(Clone, Copy, Debug)]
pub(crate) struct SpringRow<S: Scalar> {
    /// Solver slot of the anchor `a` (the virtual ground for a point).
    pub(crate) a: u32,
    /// Solver slot of the anchor `b`.
    pub(crate) b: u32,
    /// The inverse masses `(w_a, w_b)` as the solver sees them.
    pub(crate) inverse_masses: (S, S),
    /// `None` for a bendy spring (lane x along X, lane y along Y); the unit
    /// axis `n` (from `a` to `b`) of a radial spring.
    pub(crate) axis: Option<Vec2<S>>,
    /// `−h·k·x` per lane, with `x` the stretch at the start of the substep.
    pub(crate) target: Vec2<S>,
    /// `g = h·(θ_s·h·k + c)` per lane: how the impulse answers the stretch
    /// rate.
    pub(crate) rate_gain: Vec2<S>,
    /// `1 / (1 + g·(θ_a·w_a + θ_b·w_b))` per lane (the divisor is ≥ 1).
    pub(crate) inverse_diagonal: Vec2<S>,
    /// `(θ_a·w_a, θ_b·w_b)`: the change of each end's position velocity per
    /// unit impulse.
    pub(crate) position_push: (S, S),
    /// The accumulated impulse `λ` per lane in this substep.
    pub(crate) impulse: Vec2<S>,
}

impl<S: Scalar> SpringRow<S> {
    /// The pushes and the inverse diagonals for the slot blends `θ_a`,
    /// `θ_b` (each in [½, 1]); the impulse starts at zero. `last` carries
    /// the previous row's `(g_x, g_y, θ_a·w_a + θ_b·w_b)` and inverse
    /// diagonals: rows of a lattice mostly share them, and a division is
    /// the costliest step here.
    pub(crate) fn finish(&mut self, theta_a: S, theta_b: S, last: &mut Option<InverseCache<S>>) {
        let (w_a, w_b) = self.inverse_masses;
        let (tw_a, tw_b) = (theta_a.mul(w_a), theta_b.mul(w_b));
        self.position_push = (tw_a, tw_b);
        let tw = tw_a.add(tw_b);
        let key = (self.rate_gain, tw);
        self.impulse = Vec2::ZERO;
        if let Some((cached, inverse)) = *last
            && cached == key
        {
            self.inverse_diagonal = inverse;
            return;
        }
        // 1 + g·(θ_a·w_a + θ_b·w_b) ≥ 1: all terms are non-negative, so the
        // division is defined and the result lies in (0, 1]. Equal lanes
        // (k_x = k_y) share one division.
        let inverse = |gain: S| S::ONE.div(S::ONE.add(gain.mul(tw)));
        let x = inverse(self.rate_gain.x);
        let y = if self.rate_gain.y == self.rate_gain.x {
            x
        } else {
            inverse(self.rate_gain.y)
        };
        self.inverse_diagonal = Vec2::new(x, y);
        *last = Some((key, self.inverse_diagonal));
    }
}

/// A row's `((g_x, g_y), θ_a·w_a + θ_b·w_b)` and its inverse diagonals.
pub(crate) type InverseCache<S> = ((Vec2<S>, S), Vec2<S>);

/// A spring's `(k, w_a + w_b, c)` and its blends and rate gains
/// `(θ_x, θ_y, g_x, g_y)`.
type BlendCache<S> = ((Vec2<S>, S, S), (S, S, S, S));

/// Working memory of the spring solve (derived; never part of the state).
#[derive(Clone, Debug, Default)]
pub(crate) struct SpringScratch<S: Scalar> {
    /// The rows of this substep, in constraint-slot order.
    pub(crate) rows: Vec<SpringRow<S>>,
    /// Radial rows whose axis waits for the slots' blends: (row index,
    /// offset b − a, relative velocity).
    pub(crate) pending_radial: Vec<(usize, Vec2<S>, Vec2<S>)>,
    /// Each slot's blend θ_b: the largest θ_s of the rows that move it (½
    /// for a slot no spring moves).
    pub(crate) body_theta: Vec<S>,
    /// Each slot's position velocity `p = v₀ + θ_b·Δv`: the velocity its
    /// position follows this substep.
    pub(crate) position_velocities: Vec<Vec2<S>>,
    /// The last spring's blends (springs of a lattice mostly share them).
    last_blend: Option<BlendCache<S>>,
}

impl<S: Scalar> SpringScratch<S> {
    /// Empties the scratch for a substep with `slots` slots (blends ½).
    pub(crate) fn begin(&mut self, slots: usize) {
        self.rows.clear();
        self.pending_radial.clear();
        self.body_theta.clear();
        self.body_theta.resize(slots, S::ONE.half());
        self.last_blend = None;
    }

    /// Adds a row between the `ends` (slots, inverse masses; `w_a + w_b >
    /// 0`) with per-lane stretch, stiffness and damping `c`: a bendy
    /// spring's (`axis` `None`) or a radial spring's (lane x; its axis is
    /// set before [`SpringRow::finish`]). Raises the blend θ_b of each
    /// moving end to the row's θ_s (see [`theta_for`]).
    pub(crate) fn push_row(
        &mut self,
        ends: ((u32, u32), (S, S)),
        axis: Option<Vec2<S>>,
        stretch: Vec2<S>,
        (stiffness, damping): (Vec2<S>, S),
        h: S,
    ) {
        let (slots, inverse_masses) = ends;
        let w = inverse_masses.0.add(inverse_masses.1);
        let key = (stiffness, w, damping);
        let (theta_x, theta_y, gain_x, gain_y) = match self.last_blend {
            Some((cached, blend)) if cached == key => blend,
            _ => {
                let theta_x = theta_for(stiffness.x, w, h);
                let theta_y = if stiffness.y == stiffness.x {
                    theta_x
                } else {
                    theta_for(stiffness.y, w, h)
                };
                let gain = |k: S, t: S| h.mul(k.mul(t).mul(h).add(damping));
                let gain_x = gain(stiffness.x, theta_x);
                let gain_y = if stiffness.y == stiffness.x {
                    gain_x
                } else {
                    gain(stiffness.y, theta_y)
                };
                let blend = (theta_x, theta_y, gain_x, gain_y);
                self.last_blend = Some((key, blend));
                blend
            }
        };
        let theta = theta_x.max(theta_y);
        for (slot, w) in [(slots.0, inverse_masses.0), (slots.1, inverse_masses.1)] {
            if w.is_positive()
                && let Some(t) = self.body_theta.get_mut(slot as usize)
            {
                *t = (*t).max(theta);
            }
        }
        self.rows.push(SpringRow {
            a: slots.0,
            b: slots.1,
            inverse_masses,
            axis,
            target: -stretch.mul_elements(stiffness).scale(h),
            rate_gain: Vec2::new(gain_x, gain_y),
            inverse_diagonal: Vec2::new(S::ONE, S::ONE),
            position_push: (S::ZERO, S::ZERO),
            impulse: Vec2::ZERO,
        });
    }
}

/// Gauss–Seidel sweeps over `rows` on the slots' position velocities `p`
/// (they start at the substep's velocities `v₀`): each lane `s` of a row
/// solves its own equation
///
/// ```text
/// λ_s = −(h·k·x_s + g_s·ṽ_s),   ṽ_s = n·(p_b − p_a)   (the stretch rate
/// the positions will see, with every impulse so far included)
/// ```
///
/// for its `λ_s` with the others held, i.e. adds
/// `δ = r_s / (1 + g_s·(θ_a·w_a + θ_b·w_b))`, `r_s = −(h·k·x_s + g_s·ṽ_s) − λ_s`,
/// and moves `p_a` by `−θ_a·w_a·δ·n`, `p_b` by `θ_b·w_b·δ·n`. The system is
/// `(h²·K·Θ_s)⁻¹`-symmetrisable to `(h²·K·Θ_s)⁻¹ + G·Θ_b·M⁻¹·Gᵀ`,
/// symmetric positive definite, so the sweeps converge. They stop when
/// the largest change of a sweep is at most 2⁻⁸ of the largest impulse
/// after the first sweep (or after [`MAX_SPRING_SWEEPS`]); 2⁻¹⁰ and 2⁻¹³
/// gave the same energy figures on the lattice tests, one and two sweeps
/// dearer. Stopping one
/// sweep earlier on a geometric extrapolation of the changes still to come
/// was tried: a 32 × 32 lattice at ω·h = 0.3 then rose to 1.013 × its
/// energy over 60 s. The velocities follow from
/// `v = v₀ + (p − v₀)/θ_b` (the caller's job). Returns the number of
/// sweeps made.
pub(crate) fn solve_spring_rows<S: Scalar>(
    rows: &mut [SpringRow<S>],
    position_velocities: &mut [Vec2<S>],
) -> usize {
    // The impulses' scale, from the first sweep (later sweeps change them
    // by the coupling between springs, a small fraction while the sweeps
    // converge).
    let mut threshold = S::ZERO;
    for sweep in 1..=MAX_SPRING_SWEEPS {
        let mut largest_change = S::ZERO;
        for row in rows.iter_mut() {
            let (a, b) = (row.a as usize, row.b as usize);
            let relative = position_velocities[b] - position_velocities[a];
            let (tw_a, tw_b) = row.position_push;
            // The change of each end's position velocity per unit of the
            // impulse change (a vector per lane).
            let (change, size) = match row.axis {
                None => {
                    // Two independent lanes along X and Y.
                    let residual = row.target - row.rate_gain.mul_elements(relative) - row.impulse;
                    let change = residual.mul_elements(row.inverse_diagonal);
                    row.impulse += change;
                    (change, change.x.abs().max(change.y.abs()))
                }
                Some(axis) => {
                    let rate = axis.dot(relative);
                    let residual = row
                        .target
                        .x
                        .sub(row.rate_gain.x.mul(rate))
                        .sub(row.impulse.x);
                    let change = residual.mul(row.inverse_diagonal.x);
                    row.impulse.x = row.impulse.x.add(change);
                    (axis.scale(change), change.abs())
                }
            };
            let push_b = change.scale(tw_b);
            // Equal ends (equal masses and blends) share the product.
            let push_a = if tw_a == tw_b {
                push_b
            } else {
                change.scale(tw_a)
            };
            position_velocities[a] -= push_a;
            position_velocities[b] += push_b;
            largest_change = largest_change.max(size);
        }
        if sweep == 1 {
            let largest_impulse = rows.iter().fold(S::ZERO, |m, row| {
                m.max(row.impulse.x.abs()).max(row.impulse.y.abs())
            });
            threshold = largest_impulse.mul(S::from_ratio(1, 256));
        }
        if largest_change <= threshold {
            return sweep;
        }
    }
    MAX_SPRING_SWEEPS
}

#[cfg(test)]
#[allow(clippy::float_arithmetic)]
mod tests {
    use super::*;

    /// Finishes every row with the slots' blends.
    fn finish_all(scratch: &mut SpringScratch<f64>) {
        let thetas = scratch.body_theta.clone();
        let mut last = None;
        for row in &mut scratch.rows {
            row.finish(thetas[row.a as usize], thetas[row.b as usize], &mut last);
        }
    }

    /// An undamped unit-mass spring stepped by the solve and the θ position
    /// rule never gains energy (k·x² + v²), even at ω·h = 10, and a lone
    /// row is solved exactly by its first sweep (the second sees no change).
    #[test]
    fn lone_spring_never_gains_energy_at_omega_h_10() {
        let h = 1.0 / 60.0;
        let k = (10.0f64 / h).powi(2);
        let (mut x, mut v) = (1.0f64, 0.0f64);
        let e0 = k * x * x + v * v;
        for _ in 0..10_000 {
            let mut scratch = SpringScratch {
                body_theta: vec![0.5, 0.5],
                ..SpringScratch::default()
            };
            scratch.push_row(
                ((1, 0), (0.0, 1.0)),
                None,
                Vec2::new(x, 0.0),
                (Vec2::new(k, k), 0.0),
                h,
            );
            finish_all(&mut scratch);
            let mut p = vec![Vec2::new(v, 0.0), Vec2::ZERO];
            assert!(solve_spring_rows(&mut scratch.rows, &mut p) <= 2);
            let theta = scratch.body_theta[0];
            x += h * p[0].x;
            v += (p[0].x - v) / theta;
            let e = k * x * x + v * v;
            assert!(e <= e0 * (1.0 + 1e-9), "energy grew: {e} > {e0}");
        }
    }

    /// Two bodies in a chain (ground – 0 – 1, unit masses, equal springs
    /// along x): the sweeps reach the simultaneous solution of the 2 × 2
    /// θ-method system, computed here by Cramer's rule.
    #[test]
    fn sweeps_reach_the_simultaneous_solution_of_a_two_spring_chain() {
        let h = 1.0 / 60.0;
        let k = 900.0; // ω·h = 0.5 for one spring of two unit masses
        let (x1, x2) = (0.3, -0.2); // stretches: ground→0 and 0→1
        let (v0, v1) = (0.5, -1.0);
        let mut scratch = SpringScratch {
            body_theta: vec![0.5; 3],
            ..SpringScratch::default()
        };
        let stiffness = (Vec2::new(k, k), 0.0);
        scratch.push_row(((2, 0), (0.0, 1.0)), None, Vec2::new(x1, 0.0), stiffness, h);
        scratch.push_row(((0, 1), (1.0, 1.0)), None, Vec2::new(x2, 0.0), stiffness, h);
        finish_all(&mut scratch);
        // Both bodies carry the larger blend (the 0→1 spring's).
        let theta = scratch.body_theta[0];
        assert_eq!(theta, scratch.body_theta[1]);
        let (t1, t2) = (theta_for(k, 1.0, h), theta_for(k, 2.0, h));
        let mut p = vec![Vec2::new(v0, 0.0), Vec2::new(v1, 0.0), Vec2::ZERO];
        solve_spring_rows(&mut scratch.rows, &mut p);
        // λ_s = −h·k·(x_s + θ_s·h·ṽ_s) with ṽ_1 = v0 + θ·(λ1 − λ2),
        // ṽ_2 = (v1 − v0) + θ·(2·λ2 − λ1) (unit masses):
        // [1 + g1·θ, −g1·θ; −g2·θ, 1 + 2·g2·θ]·λ = −h·k·[x1 + θ1·h·v0; x2 + θ2·h·(v1 − v0)],
        // with g_s = θ_s·h²·k.
        let (g1, g2) = (t1 * h * h * k, t2 * h * h * k);
        let (a11, a12) = (1.0 + g1 * theta, -g1 * theta);
        let (a21, a22) = (-g2 * theta, 1.0 + 2.0 * g2 * theta);
        let b1 = -h * k * (x1 + t1 * h * v0);
        let b2 = -h * k * (x2 + t2 * h * (v1 - v0));
        let det = a11 * a22 - a12 * a21;
        let l1 = (b1 * a22 - a12 * b2) / det;
        let l2 = (a11 * b2 - a21 * b1) / det;
        let (s1, s2) = (scratch.rows[0].impulse.x, scratch.rows[1].impulse.x);
        assert!((s1 - l1).abs() < 1e-3 * l1.abs(), "{s1} vs {l1}");
        assert!((s2 - l2).abs() < 1e-3 * l2.abs(), "{s2} vs {l2}");
        // Positions follow θ of the velocity change the impulses make.
        assert!((p[0].x - (v0 + theta * (s1 - s2))).abs() < 1e-12);
        assert!((p[1].x - (v1 + theta * s2)).abs() < 1e-12);
    }
}
