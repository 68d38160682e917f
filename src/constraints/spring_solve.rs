//! The simultaneous spring solve: every spring row of a substep solved
//! together (Gauss–Seidel sweeps on the impulses, from each bendy spring's
//! free impulse, until they
//! settle), so that no spring sees velocities that others already changed
//! as if they were the start of the step. Maths in [`crate::constraints`]
//! ("Why springs are solved together").

use super::spring::theta_for;
use super::spring_direct::DirectScratch;
use super::spring_support::{SupportRow, SupportScratch};
use crate::math::{Scalar, Vec2};

/// Most sweeps of one spring solve. A resolved lattice (ω·h ≤ 0.3)
/// settles in 1–2 sweeps from its free impulses (the tolerance below); stiffer
/// springs are implicit Euler (θ = 1), whose damping absorbs what the capped
/// iteration leaves (measured: `tests/spring_lattice_energy.rs`).
pub(crate) const MAX_SPRING_SWEEPS: usize = 8;

/// The spring equations of one constraint: a bendy spring's two (one per
/// axis, independent lanes x and y), or a radial spring's one (lane x,
/// along a direction the sweeps re-evaluate; its geometry is the matching
/// [`RadialRow`]).
#[derive(Clone, Copy, Debug)]
pub(crate) struct SpringRow<S: Scalar> {
    /// Solver slot of the anchor `a` (the virtual ground for a point).
    pub(crate) a: u32,
    /// Solver slot of the anchor `b`.
    pub(crate) b: u32,
    /// The inverse masses `(w_a, w_b)` as the solver sees them.
    pub(crate) inverse_masses: (S, S),
    /// `false` for a bendy spring (lane x along X, lane y along Y), `true`
    /// for a radial one (the next [`RadialRow`] in order).
    pub(crate) radial: bool,
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
    /// the previous row's gains, inverse masses and blends with its pushes
    /// and inverse diagonals: rows of a lattice mostly share them, and a
    /// division is the costliest step here.
    pub(crate) fn finish(&mut self, theta_a: S, theta_b: S, last: &mut Option<InverseCache<S>>) {
        self.impulse = Vec2::ZERO;
        let key = (self.rate_gain, self.inverse_masses, theta_a, theta_b);
        if let Some((cached, (push, inverse))) = *last
            && cached == key
        {
            self.position_push = push;
            self.inverse_diagonal = inverse;
            return;
        }
        let (w_a, w_b) = self.inverse_masses;
        let (tw_a, tw_b) = (theta_a.mul(w_a), theta_b.mul(w_b));
        self.position_push = (tw_a, tw_b);
        let tw = tw_a.add(tw_b);
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
        *last = Some((key, (self.position_push, self.inverse_diagonal)));
    }

    /// Moves the ends' position velocities by an impulse change `change`
    /// (a vector per lane): `p_a −= θ_a·w_a·change`, `p_b += θ_b·w_b·change`.
    #[inline]
    pub(crate) fn push(&self, change: Vec2<S>, position_velocities: &mut [Vec2<S>]) {
        let (tw_a, tw_b) = self.position_push;
        let push_b = change.scale(tw_b);
        // Equal ends (equal masses and blends) share the product.
        let push_a = if tw_a == tw_b {
            push_b
        } else {
            change.scale(tw_a)
        };
        position_velocities[self.a as usize] -= push_a;
        position_velocities[self.b as usize] += push_b;
    }
}

/// A row's `((g_x, g_y), (w_a, w_b), θ_a, θ_b)` and its pushes
/// `(θ_a·w_a, θ_b·w_b)` and inverse diagonals.
pub(crate) type InverseCache<S> = ((Vec2<S>, (S, S), S, S), ((S, S), Vec2<S>));

/// What the radial lane of the sweeps needs beyond a [`SpringRow`]: the
/// geometry it re-linearises about in every sweep (the discrete gradient of
/// [`crate::constraints`], "Radial springs").
#[derive(Clone, Copy, Debug)]
pub(crate) struct RadialRow<S: Scalar> {
    /// `r = b − a` at the start of the substep.
    pub(crate) offset: Vec2<S>,
    /// `l = |r|`.
    pub(crate) length: S,
    /// `θ_s·h·k + c`: the impulse per unit of length change.
    pub(crate) gain_per_length: S,
    /// The impulse vector `λ·d` applied so far in this substep.
    pub(crate) applied: Vec2<S>,
}

/// A spring's `(k, w_a + w_b, c)` and its blends, rate gains and stretch
/// gains `(θ_x, θ_y, g_x, g_y, −h·k)`.
type BlendCache<S> = ((Vec2<S>, S, S), (S, S, S, S, Vec2<S>));

/// Working memory of the spring solve (derived; never part of the state).
#[derive(Clone, Debug, Default)]
pub(crate) struct SpringScratch<S: Scalar> {
    /// The rows of this substep, in constraint-slot order.
    pub(crate) rows: Vec<SpringRow<S>>,
    /// The radial rows' geometry, in row order (blends and lags are set
    /// once every slot's θ is known).
    pub(crate) radial: Vec<RadialRow<S>>,
    /// Each slot's blend θ_b: the largest θ_s of the rows that move it (½
    /// for a slot no spring moves).
    pub(crate) body_theta: Vec<S>,
    /// Each slot's position velocity `p = v₀ + θ_b·Δv`: the velocity its
    /// position follows this substep.
    pub(crate) position_velocities: Vec<Vec2<S>>,
    /// The contact rows the sweeps carry (`spring_support.rs`).
    pub(crate) supports: SupportScratch<S>,
    /// The direct solve of stiff groups and its kept factor
    /// (`spring_direct.rs`).
    pub(crate) direct: DirectScratch<S>,
    /// The last spring's blends (springs of a lattice mostly share them).
    last_blend: Option<BlendCache<S>>,
    /// Per slot: a spring row moves it (working memory).
    spring_moved: Vec<bool>,
    /// Per slot: its earliest bounce's meeting (working memory).
    first_meet: Vec<S>,
    /// The slots raised to θ_b = 1 (working memory).
    raised: Vec<usize>,
}

impl<S: Scalar> SpringScratch<S> {
    /// Finishes every row with its slots' blends (pushes and inverse
    /// diagonals; the impulses start at zero).
    pub(crate) fn finish_rows(&mut self) {
        let mut last_inverse = None;
        for row in &mut self.rows {
            let (t_a, t_b) = (
                self.body_theta[row.a as usize],
                self.body_theta[row.b as usize],
            );
            row.finish(t_a, t_b, &mut last_inverse);
        }
    }

    /// Launches the bounces the first solve found (see
    /// [`crate::constraints`], "Springs and contacts", 4.): a support row
    /// that carries a bounce and pushed in that solve (the pair meets),
    /// and is the earliest meeting of each of its two bodies (a row behind
    /// another, which the sweeps may leave a remnant of impulse, does not
    /// bounce), now targets the bounce's end velocity; its two ends take
    /// θ_b = 1 and count as a row of their group for the direct solve.
    /// Returns whether any was launched.
    pub(crate) fn launch_bounces(&mut self) -> bool {
        let rows = &mut self.supports.rows;
        self.direct.launched_ends.clear();
        if rows.iter().all(|row| row.bounce.is_none()) {
            return false;
        }
        let never = S::from_int(1 << 20);
        let first = &mut self.first_meet;
        first.clear();
        first.resize(self.body_theta.len(), never);
        let pushed = |row: &SupportRow<S>| row.impulse.is_positive();
        for row in rows.iter().filter(|row| pushed(row)) {
            if let Some(bounce) = row.bounce {
                for slot in [row.a as usize, row.b as usize] {
                    first[slot] = first[slot].min(bounce.meets);
                }
            }
        }
        let ends = &mut self.direct.launched_ends;
        ends.clear();
        ends.resize(self.body_theta.len(), false);
        let mut any = false;
        for row in rows.iter_mut() {
            let Some(mut bounce) = row.bounce else {
                continue;
            };
            let (a, b) = (row.a as usize, row.b as usize);
            if !pushed(row) || bounce.meets > first[a] || bounce.meets > first[b] {
                continue;
            }
            bounce.floor = row.target;
            row.bounce = Some(bounce);
            row.target = row.target.max(bounce.velocity);
            row.launched = true;
            for slot in [a, b] {
                self.body_theta[slot] = S::ONE;
                ends[slot] = true;
            }
            any = true;
        }
        any
    }

    /// Raises to θ_b = 1 every spring-moved end with θ_b < 1 of a support
    /// row (a contact) that the last solve pushed, or whose end velocities
    /// `v₀ + (p − v₀)/θ_b` close it beyond its target (the contact solve
    /// will push it): such an end would carry the lag of
    /// [`crate::constraints`], "Springs and contacts", 1. Held rows (solved
    /// with a stiff group) too: their push is final and sits in `p`, so at
    /// θ_b = ½ the velocity took it twice while the other end took it once
    /// (a pusher at ω·h = 1 on a radial spring, thrown at 50 units/s at a
    /// middle body touching a third: Σ m·v fell from −5 to −3.8 in the
    /// tick of the strike). Returns whether any was raised.
    pub(crate) fn raise_bound_ends(&mut self, velocities: &[Vec2<S>]) -> bool {
        if self.supports.rows.is_empty() {
            return false;
        }
        self.mark_spring_moved();
        let moved = &self.spring_moved;
        let (theta, p) = (&self.body_theta, &self.position_velocities);
        let lagging = |slot: usize| moved[slot] && theta[slot] < S::ONE;
        // The velocity a slot ends the substep with: v₀ + Δv, θ_b·Δv = p − v₀.
        let end = |slot: usize| {
            let (v, q) = (velocities[slot], p[slot]);
            if q == v {
                v
            } else {
                v + (q - v).scale(S::ONE.div(theta[slot]))
            }
        };
        let raised = &mut self.raised;
        raised.clear();
        for row in &self.supports.rows {
            let (a, b) = (row.a as usize, row.b as usize);
            if !lagging(a) && !lagging(b) {
                continue;
            }
            if row.impulse == S::ZERO && (end(b) - end(a)).dot(row.normal) >= row.target {
                continue;
            }
            raised.extend([a, b].into_iter().filter(|&slot| lagging(slot)));
        }
        for &slot in raised.iter() {
            self.body_theta[slot] = S::ONE;
        }
        !raised.is_empty()
    }

    /// Marks in `spring_moved`, per slot, whether a spring row moves it
    /// (a movable end of a row this substep).
    fn mark_spring_moved(&mut self) {
        let moved = &mut self.spring_moved;
        moved.clear();
        moved.resize(self.body_theta.len(), false);
        for row in &self.rows {
            for (slot, w) in [(row.a, row.inverse_masses.0), (row.b, row.inverse_masses.1)] {
                if w.is_positive() {
                    moved[slot as usize] = true;
                }
            }
        }
    }

    /// Gives every end of a held or launched support row that no spring
    /// moves the blend θ_b = 1: its position velocity `p` then carries the
    /// row's final push as the contact solver moves a body (all of the
    /// impulse), and the velocity `v = v₀ + (p − v₀)/θ_b` takes it once.
    /// At the free body's θ_b = ½ the push was taken twice: a stiff
    /// chain (ω·h 3 to 100) striking a free ball at rest gave the ball
    /// twice the impulse the chain lost, and Σ m·v rose by up to the
    /// chain's whole momentum in the tick of the strike.
    pub(crate) fn hold_unsprung_ends(&mut self) {
        if !self
            .supports
            .rows
            .iter()
            .any(|row| row.held || row.launched)
        {
            return;
        }
        self.mark_spring_moved();
        let moved = &self.spring_moved;
        for row in self
            .supports
            .rows
            .iter()
            .filter(|row| row.held || row.launched)
        {
            for slot in [row.a as usize, row.b as usize] {
                if !moved[slot] {
                    self.body_theta[slot] = S::ONE;
                }
            }
        }
    }

    /// Empties the scratch for a substep with `slots` slots (blends ½).
    pub(crate) fn begin(&mut self, slots: usize) {
        self.rows.clear();
        self.radial.clear();
        self.body_theta.clear();
        self.body_theta.resize(slots, S::ONE.half());
        self.last_blend = None;
        self.direct.launched_ends.clear();
    }

    /// Adds a row between the `ends` (slots, inverse masses; `w_a + w_b >
    /// 0`) with per-lane stretch, stiffness and damping `c`: a bendy
    /// spring's (`radial` false) or a radial spring's (lane x; the caller
    /// pushes its [`RadialRow`]). Raises the blend θ_b of each
    /// moving end to the row's θ_s (see [`theta_for`]) and returns lane x's
    /// θ_s.
    pub(crate) fn push_row(
        &mut self,
        ends: ((u32, u32), (S, S)),
        radial: bool,
        stretch: Vec2<S>,
        (stiffness, damping): (Vec2<S>, S),
        h: S,
    ) -> S {
        let (slots, inverse_masses) = ends;
        let w = inverse_masses.0.add(inverse_masses.1);
        let key = (stiffness, w, damping);
        let (theta_x, theta_y, gain_x, gain_y, stretch_gain) = match self.last_blend {
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
                // The impulse per unit stretch, −h·k (one product per
                // distinct spring instead of two per row).
                let stretch_gain = -stiffness.scale(h);
                let blend = (theta_x, theta_y, gain_x, gain_y, stretch_gain);
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
            radial,
            target: stretch.mul_elements(stretch_gain),
            rate_gain: Vec2::new(gain_x, gain_y),
            inverse_diagonal: Vec2::new(S::ONE, S::ONE),
            position_push: (S::ZERO, S::ZERO),
            impulse: Vec2::ZERO,
        });
        theta_x
    }
}

/// The smallest inverse diagonal `1 / (1 + g·(θ_a·w_a + θ_b·w_b))` of a
/// lane that starts from its free impulse: `g·(θ_a·w_a + θ_b·w_b) ≤ 1/4`
/// (ω·h up to about 1 for equal masses).
const RESOLVED_INVERSE_DIAGONAL: (i32, i32) = (4, 5);

/// Starts every resolved lane of a bendy row from its *free* impulse
/// `λ⁰_s = −h·k·x_s − g_s·ṽ⁰_s` (`ṽ⁰_s` the stretch rate at the substep's
/// velocities `v₀`) and moves the ends' position velocities by it; stiffer
/// lanes and radial rows (re-linearised in every sweep) start from zero.
///
/// The exact impulse is `λ_s = λ⁰_s − g_s·n·(Δp_b − Δp_a)`, with `Δp` the
/// pushes of all impulses (this lane's own included) on its two ends. A
/// spring inside a uniformly loaded chain or lattice (a hanging cloth, a
/// stretched chain) has its ends pulled on the far side by the same
/// tension, so those pushes cancel and `λ⁰` is the answer up to the load's
/// gradient; elsewhere the start is off by the mobility term, at most about
/// `g·(θ_a·w_a + θ_b·w_b)` (≤ 1/4 here) of the neighbouring impulses.
/// Starting from zero instead is off by the whole impulse: the springs
/// bench lattice (ω·h = 0.56) needed three sweeps from zero and needs one
/// or two from here. The start's error is proportional to impulses, not to
/// the stretch rate, so what the sweeps leave of it is no viscous bias:
/// starting from `−h·k·x` alone (without the rate term) made a 32 × 32
/// lattice at ω·h = 0.3 lose 2.3 % of its energy in 60 s. A stiff lane
/// (the mobility term dominates) starts from zero: starting 200-spring
/// chains at ω·h = 10 from `−h·k·x` made them gain energy without bound,
/// because the capped sweeps then overshoot instead of under-solving.
fn start_from_free_impulses<S: Scalar>(
    rows: &mut [SpringRow<S>],
    direct: &[bool],
    velocities: &[Vec2<S>],
    position_velocities: &mut [Vec2<S>],
) {
    let resolved = S::from_ratio(RESOLVED_INVERSE_DIAGONAL.0, RESOLVED_INVERSE_DIAGONAL.1);
    let start = |free: S, inverse_diagonal: S| {
        if inverse_diagonal >= resolved {
            free
        } else {
            S::ZERO
        }
    };
    for (row, _) in rows
        .iter_mut()
        .zip(direct.iter().chain(core::iter::repeat(&false)))
        .filter(|(row, direct)| !row.radial && !**direct)
    {
        let relative = velocities[row.b as usize] - velocities[row.a as usize];
        let free = row.target - row.rate_gain.mul_elements(relative);
        row.impulse = Vec2::new(
            start(free.x, row.inverse_diagonal.x),
            start(free.y, row.inverse_diagonal.y),
        );
        row.push(row.impulse, position_velocities);
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
/// (a radial row: its own equation re-linearised where the ends now are,
/// see [`radial_lane`]) for its `λ_s` with the others held, i.e. adds
/// `δ = r_s / (1 + g_s·(θ_a·w_a + θ_b·w_b))`, `r_s = −(h·k·x_s + g_s·ṽ_s) − λ_s`,
/// and moves `p_a` by `−θ_a·w_a·δ·n`, `p_b` by `θ_b·w_b·δ·n`. The system is
/// `(h²·K·Θ_s)⁻¹`-symmetrisable to `(h²·K·Θ_s)⁻¹ + G·Θ_b·M⁻¹·Gᵀ`,
/// symmetric positive definite, so the sweeps converge. They start from
/// the free impulses ([`start_from_free_impulses`]) and stop when the
/// largest change of a sweep is at most 2⁻⁹ of the largest impulse after
/// the first sweep (or after [`MAX_SPRING_SWEEPS`]), the first sweep
/// included: its change is the start's error. Measured on
/// `tests/spring_lattice_energy.rs`: from zero, 2⁻⁸, 2⁻¹⁰ and 2⁻¹³ gave
/// the same energy figures; from the free impulses, 2⁻⁸ with at least two
/// sweeps and 2⁻⁹ from one sweep on both keep every bound. Stopping one
/// sweep earlier on a geometric extrapolation of the changes still to come
/// was tried (from zero): a 32 × 32 lattice at ω·h = 0.3 then rose to
/// 1.013 × its energy over 60 s. The velocities follow from
/// `v = v₀ + (p − v₀)/θ_b` (the caller's job). Sweeps that do not settle
/// within [`MAX_SPRING_SWEEPS`] (a chain of light links with a heavy end
/// near the stiffness limit: 20 links, end 100×, ω·h = 1 gained 83 J that
/// way) leave a residual whose work enters the energy balance, so the
/// substep then starts over with every group of two or more rows, and
/// every lone radial row whose contacts are all solved with it (a pole
/// turning fast: `DirectScratch::find_stiff_groups`), solved exactly
/// (`spring_direct.rs`). Returns the number of sweeps made.
pub(crate) fn solve_spring_rows<S: Scalar>(
    rows: &mut [SpringRow<S>],
    radial: &mut [RadialRow<S>],
    supports: &mut SupportScratch<S>,
    direct: &mut DirectScratch<S>,
    (velocities, position_velocities): (&[Vec2<S>], &mut [Vec2<S>]),
    h: S,
) -> usize {
    let solved = direct.solve(
        rows,
        radial,
        supports,
        (velocities, position_velocities),
        h,
        false,
    );
    let (sweeps, converged) = sweep_until_settled(
        rows,
        radial,
        supports,
        (solved, direct),
        (velocities, position_velocities),
        h,
    );
    if converged || !direct.would_take_more(rows, &supports.rows, position_velocities.len()) {
        return sweeps;
    }
    // The sweeps did not settle (a chain of uneven masses, a long group
    // near the stiffness limit, a lone radial spring turning fast): their
    // residual would enter the energy balance, so the step starts over
    // with every group of two or more rows (and every lone radial row
    // whose contacts are all solved with it) solved exactly.
    restart(rows, radial, supports, (velocities, position_velocities));
    let solved = direct.solve(
        rows,
        radial,
        supports,
        (velocities, position_velocities),
        h,
        true,
    );
    let (more, _) = sweep_until_settled(
        rows,
        radial,
        supports,
        (solved, direct),
        (velocities, position_velocities),
        h,
    );
    sweeps + more
}

/// Clears every impulse of the substep and puts the position velocities
/// back at `v₀`.
fn restart<S: Scalar>(
    rows: &mut [SpringRow<S>],
    radial: &mut [RadialRow<S>],
    supports: &mut SupportScratch<S>,
    (velocities, position_velocities): (&[Vec2<S>], &mut [Vec2<S>]),
) {
    for row in rows.iter_mut() {
        row.impulse = Vec2::ZERO;
    }
    for geometry in radial.iter_mut() {
        geometry.applied = Vec2::ZERO;
    }
    supports.clear_impulses();
    position_velocities.copy_from_slice(velocities);
}

/// The sweeps of [`solve_spring_rows`] from the direct solution (if
/// `solved`) and the free impulses; returns the sweeps made and whether
/// they settled.
fn sweep_until_settled<S: Scalar>(
    rows: &mut [SpringRow<S>],
    radial: &mut [RadialRow<S>],
    supports: &mut SupportScratch<S>,
    (solved, direct): (bool, &mut DirectScratch<S>),
    (velocities, position_velocities): (&[Vec2<S>], &mut [Vec2<S>]),
    h: S,
) -> (usize, bool) {
    // The impulses' scale, from the first sweep (later sweeps change them
    // by the coupling between springs, a small fraction while the sweeps
    // converge). 2⁻⁹ = 1/512.
    let mut threshold = S::ZERO;
    if !solved {
        direct.direct.clear();
    }
    start_from_free_impulses(rows, &direct.direct, velocities, position_velocities);
    for sweep in 1..=MAX_SPRING_SWEEPS {
        // Scenes without radial springs get a sweep with no radial branch
        // (the bendy lattices' cost is the sweep's inner loop).
        let largest_change = if radial.is_empty() {
            sweep_rows::<S, false>(rows, radial, position_velocities, h)
        } else {
            sweep_rows::<S, true>(rows, radial, position_velocities, h)
        };
        let largest_change = if supports.rows.is_empty() {
            largest_change
        } else {
            largest_change.max(supports.sweep(position_velocities))
        };
        if sweep == 1 {
            let largest_impulse = rows.iter().fold(S::ZERO, |m, row| {
                m.max(row.impulse.x.abs()).max(row.impulse.y.abs())
            });
            threshold = largest_impulse.mul(S::from_ratio(1, 512));
        }
        if largest_change <= threshold {
            supports.take_back(position_velocities);
            return (sweep, true);
        }
    }
    supports.take_back(position_velocities);
    (MAX_SPRING_SWEEPS, false)
}

/// One Gauss–Seidel sweep over the rows (see [`solve_spring_rows`]);
/// `RADIAL` false skips the radial lane (no row is radial). Returns the
/// sweep's largest impulse change.
fn sweep_rows<S: Scalar, const RADIAL: bool>(
    rows: &mut [SpringRow<S>],
    radial: &mut [RadialRow<S>],
    position_velocities: &mut [Vec2<S>],
    h: S,
) -> S {
    let mut largest_change = S::ZERO;
    let mut radial_rows = radial.iter_mut();
    for row in rows.iter_mut() {
        let (a, b) = (row.a as usize, row.b as usize);
        let (tw_a, tw_b) = row.position_push;
        // The change of the impulse (a vector: per lane for a bendy row,
        // λ·d for a radial one).
        let change = if RADIAL && row.radial {
            let Some(geometry) = radial_rows.next() else {
                continue;
            };
            radial_lane(
                row,
                geometry,
                (position_velocities[a], position_velocities[b]),
                h,
            )
        } else {
            // Two independent lanes along X and Y.
            let relative = position_velocities[b] - position_velocities[a];
            let residual = row.target - row.rate_gain.mul_elements(relative) - row.impulse;
            let change = residual.mul_elements(row.inverse_diagonal);
            row.impulse += change;
            change
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
        largest_change = largest_change.max(change.x.abs().max(change.y.abs()));
    }
    largest_change
}

/// Where the position velocities `(p_a, p_b)` put a radial row's ends:
/// the end length `l' = |r'|`, `r' = r + h·(p_b − p_a)`, and the impulse
/// direction `d = (r + r') / (l + l')`, the midpoint discrete gradient of
/// [`crate::constraints`] ("Radial springs"): `d·(r' − r) = l' − l`
/// exactly, and `|d| ≤ 1`.
pub(crate) fn radial_geometry<S: Scalar>(
    geometry: &RadialRow<S>,
    (p_a, p_b): (Vec2<S>, Vec2<S>),
    h: S,
) -> (S, Vec2<S>) {
    let end = geometry.offset + (p_b - p_a).scale(h);
    let end_length = end.length();
    let scale = geometry.length.add(end_length);
    let sum = geometry.offset + end;
    let direction = if scale.is_positive() {
        let d = sum.scale(S::ONE.div(scale));
        // |d| ≤ 1 up to rounding; only a scale so small that its inverse
        // saturates gives more, and then the unit sum is the sane direction.
        if d.x.abs().max(d.y.abs()) <= S::from_int(2) {
            d
        } else {
            sum.try_normalize().unwrap_or(Vec2::Y)
        }
    } else {
        // Both ends on the pivot (and at rest): pushed along +Y, the
        // geometry module's convention for coincident points.
        Vec2::Y
    };
    (end_length, direction)
}

/// One Gauss–Seidel update of a radial row, re-linearised about where the
/// ends' position velocities `(p_a, p_b)` now put them (the discrete
/// gradient of [`crate::constraints`], "Radial springs"): with
/// `r' = r + h·(p_b − p_a)` and `l' = |r'|`, the row solves
/// `λ = −h·k·(x + θ_s·(l' − l)) − c·(l' − l)` along
/// `d = (r + (1 − θ_b)·h·p_b − (1 − θ_a)·h·p_a) / (θ̄·l + (1 − θ̄)·l')`.
/// Returns the change of the impulse vector `λ·d` (already stored).
fn radial_lane<S: Scalar>(
    row: &mut SpringRow<S>,
    geometry: &mut RadialRow<S>,
    ends: (Vec2<S>, Vec2<S>),
    h: S,
) -> Vec2<S> {
    let (end_length, direction) = radial_geometry(geometry, ends, h);
    let residual = row
        .target
        .x
        .sub(
            geometry
                .gain_per_length
                .mul(end_length.sub(geometry.length)),
        )
        .sub(row.impulse.x);
    row.impulse.x = row.impulse.x.add(residual.mul(row.inverse_diagonal.x));
    let applied = direction.scale(row.impulse.x);
    let change = applied - geometry.applied;
    geometry.applied = applied;
    change
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
                false,
                Vec2::new(x, 0.0),
                (Vec2::new(k, k), 0.0),
                h,
            );
            finish_all(&mut scratch);
            let mut p = vec![Vec2::new(v, 0.0), Vec2::ZERO];
            assert!(
                solve_spring_rows(
                    &mut scratch.rows,
                    &mut [],
                    &mut SupportScratch::default(),
                    &mut DirectScratch::default(),
                    (&p.clone(), &mut p),
                    h
                ) <= 2
            );
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
        scratch.push_row(
            ((2, 0), (0.0, 1.0)),
            false,
            Vec2::new(x1, 0.0),
            stiffness,
            h,
        );
        scratch.push_row(
            ((0, 1), (1.0, 1.0)),
            false,
            Vec2::new(x2, 0.0),
            stiffness,
            h,
        );
        finish_all(&mut scratch);
        // Both bodies carry the larger blend (the 0→1 spring's).
        let theta = scratch.body_theta[0];
        assert_eq!(theta, scratch.body_theta[1]);
        let (t1, t2) = (theta_for(k, 1.0, h), theta_for(k, 2.0, h));
        let mut p = vec![Vec2::new(v0, 0.0), Vec2::new(v1, 0.0), Vec2::ZERO];
        solve_spring_rows(
            &mut scratch.rows,
            &mut [],
            &mut SupportScratch::default(),
            &mut DirectScratch::default(),
            (&p.clone(), &mut p),
            h,
        );
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
