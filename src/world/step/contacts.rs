//! Phases "contacts after the position pass": bounding the position
//! corrections, keeping dynamic bodies out of immovable ones, the bounces
//! (re-timed to the instant of contact, [`crate::solver::restitution`]),
//! and sweeping the motion the bounces add.
//!
//! Order within a substep (see `step/mod.rs`): velocity solve → integrate →
//! [`World::remember_displacements`] → position pass →
//! [`World::bound_corrections`] → [`World::project_out_of_immovable`] →
//! [`World::bounce`] → [`World::sweep_rebounds`] → write back.

use super::solve::{rope_position_pass, rope_settle_side_stiffness};
use crate::collision::{Proxy, contact_between, shape_toi};
use crate::dynamics::BodyKind;
use crate::geometry::Toi;
use crate::math::{Scalar, Vec2};
use crate::solver::StepContext;
use crate::solver::flight_reflection::{Flight, Impact, reflect_in_flight};
use crate::solver::rebound_partners::collect_rebound_partners;
use crate::solver::restitution::{BounceSolver, apply_bounces};
use crate::solver::row::ContactConstraint;
use crate::world::{Slot, World, WorldSettings};

/// Most times of impact a bullet takes in one substep: the bounce found by
/// the contact solver, then up to `MAX_BULLET_IMPACTS − 1` more found by
/// sweeping its rebound. A bullet that reaches the cap stops at its last
/// impact for the rest of the substep (its velocity, already reflected,
/// is kept). 32 covers a bullet at the speed limit (4096 u/s, 68 units per
/// tick) between walls 2 units apart, or 1000 u/s between walls 0.55
/// apart, at 60 Hz.
pub const MAX_BULLET_IMPACTS: u32 = 32;

/// The most rounds of [`World::settle_ropes`] (rope lengths, then
/// immovable bodies) in one substep; rounds stop as soon as every rope is
/// within the slop.
const ROPE_SETTLE_MAX_PASSES: u32 = 32;

impl<S: Scalar> World<S> {
    /// Keeps the displacements before the position pass, for
    /// [`World::bound_corrections`].
    pub(super) fn remember_displacements(&mut self) {
        let StepContext {
            displacements,
            displacements_before_correction,
            ..
        } = &mut self.step_context;
        displacements_before_correction.clear();
        displacements_before_correction.extend_from_slice(displacements);
    }

    /// The bounces of this substep ([`crate::solver::restitution`]): the
    /// contacts that met fast enough leave it with `e` times their speed at
    /// the instant of contact; the bodies whose motion grew are listed for
    /// [`World::sweep_rebounds`].
    pub(super) fn bounce(&mut self, h: S) {
        let StepContext {
            constraints,
            contact_groups,
            bounce_candidates,
            bounce,
            velocities,
            displacements,
            rebounds,
            rope_block,
            tree,
            ..
        } = &mut self.step_context;
        rebounds.clear();
        // Each body is listed at most once per bounce group (twice per row
        // it bounces on in a large pile), and belongs to one group: room for
        // every slot keeps a step after the warm-up from allocating when
        // more bodies rebound than before.
        rebounds.reserve(velocities.len());
        let solver = BounceSolver {
            groups: contact_groups,
            sweeps: self.settings.velocity_iterations,
            slop: self.settings.linear_slop,
            block: rope_block,
            tree,
        };
        apply_bounces(
            constraints,
            bounce_candidates,
            h,
            solver,
            bounce,
            velocities,
            displacements,
            rebounds,
        );
    }

    /// Limits each body's displacement by the position pass to half the
    /// speculative margin per axis (so under `margin/√2` in length).
    ///
    /// Why: a pair's row exists only if the bodies can come within the
    /// margin this substep; any body further away has no row, so nothing
    /// would stop a correction from pushing into it. A correction shorter
    /// than the margin cannot close a gap the row test left out (that gap
    /// exceeds `margin + max(0, −v_n)·h`, and the velocity motion closes at
    /// most `max(0, −v_n)·h` of it). Without the bound, a crowd spawned at
    /// one point receives hundreds of pushes per body per pass and flings
    /// bodies through walls. A deep overlap is therefore resolved at up to
    /// `margin/2` per axis and substep (3 units/s at the defaults).
    ///
    /// A body the pass moved by more than it may move while counting as
    /// resting (`sleep_linear_threshold·h` on an axis) is still being pushed
    /// out of an overlap: its sleep timer restarts, so a pile does not fall
    /// asleep half separated (position corrections leave velocities alone,
    /// so the velocity test alone would let it).
    pub(super) fn bound_corrections(&mut self, h: S) {
        let limit = self.settings.speculative_margin.half();
        let resting = self.settings.sleep_linear_threshold.mul(h);
        let (lo, hi) = (Vec2::new(limit.neg(), limit.neg()), Vec2::new(limit, limit));
        let StepContext {
            displacements,
            displacements_before_correction,
            ..
        } = &mut self.step_context;
        for ((d, before), slot) in displacements
            .iter_mut()
            .zip(displacements_before_correction.iter())
            .zip(self.slots.iter_mut())
        {
            let correction = *d - *before;
            if correction == Vec2::ZERO {
                continue;
            }
            let bounded = correction.clamp(lo, hi);
            if bounded != correction {
                *d = *before + bounded;
            }
            if (bounded.x.abs() > resting || bounded.y.abs() > resting)
                && let Some(body) = slot.body.as_mut()
            {
                body.sleep_time = S::ZERO;
            }
        }
    }

    /// No dynamic body ends a substep deeper than the linear slop in an
    /// immovable one (fixed, kinematic, asleep): each such row's remaining
    /// penetration is removed entirely from the movable body, along the
    /// row's normal. Two passes, so a body in a corner (two such rows) is
    /// out of both (axis-aligned walls: exact after the first pass unless
    /// the rows are not orthogonal).
    ///
    /// Crowd pressure acts through the dynamic–dynamic rows of the velocity
    /// and position passes, which may leave a body pushed into a wall; this
    /// is the last word, so no amount of pressure puts a body through.
    ///
    /// The projection keeps each body inside its broad-phase proxy (the
    /// region searched for its partners this substep: its box, swept by its
    /// motion, grown by the speculative margin). Beyond it the body has no
    /// rows, so a longer projection could put it anywhere, into bodies
    /// nothing here knows of: a body spawned coincident with two fixed
    /// circles was projected 7.6 units along both rows' normals into a box
    /// it had never been paired with, and fell asleep there. A projection
    /// that would leave the proxy stops at its edge; what is left of the
    /// overlap is resolved in the next substeps (by the position pass and
    /// this projection, each at least the margin per axis from a resting
    /// start), and the body is listed in `unresolved_overlaps` so it does
    /// not fall asleep this tick ([`World::update_sleep`]).
    pub(super) fn project_out_of_immovable(&mut self) {
        let slop = self.settings.linear_slop;
        let resting = self.resting_move();
        self.project_rows_out_of_immovable(slop, resting, 2);
    }

    /// `passes` passes of [`project_rows_out_of_immovable`] over this
    /// substep's rows, each body kept within its proxy.
    fn project_rows_out_of_immovable(&mut self, slop: S, resting: S, passes: u32) {
        let StepContext {
            constraints,
            displacements,
            proxies,
            unresolved_overlaps,
            ..
        } = &mut self.step_context;
        let reach = ProxyReach {
            proxies,
            slots: &self.slots,
        };
        for _ in 0..passes {
            project_rows_out_of_immovable(
                constraints,
                displacements,
                slop,
                resting,
                &reach,
                unresolved_overlaps,
            );
        }
    }

    /// The most a body may move on an axis in a substep while counting as
    /// resting: `sleep_linear_threshold · h` (as in
    /// [`World::bound_corrections`]).
    fn resting_move(&self) -> S {
        self.settings
            .sleep_linear_threshold
            .mul(self.substep_length())
    }

    /// The substep's length `h = dt / substeps`.
    fn substep_length(&self) -> S {
        let substeps = S::from_int(i32::try_from(self.settings.substeps).unwrap_or(1));
        self.settings.dt.div(substeps)
    }

    /// The last word on positions when ropes are active: each rope that a
    /// bound correction, a projection out of an immovable body or a rebound
    /// left longer than its length is pulled back (exactly, to the slop, at
    /// most an eighth of its length per pass: `rope_correction_caps` in
    /// `step/solve.rs`), then the bodies are projected out of immovable
    /// ones again; rounds until every rope is within the slop, at most
    /// [`ROPE_SETTLE_MAX_PASSES`].
    ///
    /// Why: the position pass solves ropes and contacts together, but what
    /// comes after it moves bodies without looking at ropes. The bound on
    /// corrections ([`World::bound_corrections`]) caps a rope's pull like a
    /// contact's push (a rope reeled in by 0.1 per tick was followed at
    /// 0.05 per axis and fell behind without limit), and the projection
    /// out of immovable bodies and the rebound move a body along a contact
    /// normal, which may point away from the anchor. A pull along the rope
    /// cannot fling a crowd (it acts on the rope's two bodies only), so it
    /// needs no crowd bound; the cap per pass keeps a rope made much
    /// shorter than its bodies' distance from dragging them across the
    /// world in one substep, and the linearised passes from overshooting
    /// (it pulls at up to `ROPE_SETTLE_MAX_PASSES · ℓ/8`, 4ℓ, per substep
    /// on top of the position pass: a chain of 0.1 links lying on the
    /// ground whose anchor is teleported 8 units up is taut again within
    /// half a second).
    ///
    /// Rounds end when every rope is within the slop: most substeps need
    /// one round (a swinging chain's stretch is of the order of the slop),
    /// fewer than the four rounds this took before; a rope far too long
    /// takes more, up to the cap.
    ///
    /// Rope and immovable bodies alternate (projections onto a disc and a
    /// half-plane): when a body on a taut rope is pressed into a fixed body
    /// both hold to rounding after the first round unless the rope pulls
    /// into the surface, and each round shrinks what is left. When no
    /// position honours both (a rope that passes through a fixed body and
    /// is shorter than the way around it: ropes do not wrap), the fixed
    /// body wins and the rope stays long by the overlap (and the rounds
    /// run to the cap every substep while it does).
    ///
    /// Each round's pass solves the rope groups with the contacts in them
    /// (`StepContext::joint_rows`): a chain draped over a fixed peg is
    /// pulled to its length while its links' rows with the peg hold, in
    /// one exact solve, instead of the rope pass pulling the links into
    /// the peg and the projection pushing them back out round after round
    /// (a 200-link chain over a box peg stayed 386 % long after 32 rounds).
    /// Contacts off a group's spanning tree (links of a folded chain
    /// touching each other) are not corrected in the rounds: taken by
    /// sequential corrections after the exact pass they undid part of it
    /// every round (a 50-link chain round a box stayed 13 % long); the
    /// position iterations of the next substep take them.
    ///
    /// From the second round on, each rope's sideways stiffness counts the
    /// position impulse the rounds have applied to it
    /// ([`rope_settle_side_stiffness`] in `step/solve.rs`): the multiplier
    /// of the projection is what the rounds have found, not only the
    /// velocity solve's impulse, which is nearly nothing on a rope that
    /// snapped taut in the substep.
    pub(super) fn settle_ropes(&mut self) {
        if self.step_context.rope_rows.is_empty() {
            return;
        }
        let slop = self.settings.linear_slop;
        let resting = self.resting_move();
        // The rounds aim 2⁻¹⁰ of the slop inside it (1e-7 at the
        // defaults) and stop once every rope is within the slop: each
        // round is a Newton step on rows re-linearised at the current
        // displacements, so what it leaves beyond its aim is its
        // second-order residual `δ²/(2ℓ)` for a correction `δ`, below the
        // margin once `δ` is of the order of the slop, and one round
        // usually ends them. Below the slop, a round that does not shrink
        // the worst excess has met the fixed-point floor (a displacement
        // is an impulse of whole ulps times the inverse mass: 3e-8 for a
        // link of mass 0.008) and ends them too; above it, the worst
        // excess may grow for a round while a long rope's correction moves
        // to its neighbours.
        let settings = WorldSettings {
            position_correction: S::ONE,
            linear_slop: slop.sub(slop.mul(S::from_ratio(1, 1024))),
            ..self.settings
        };
        // A round that does not shrink the worst excess once it is within
        // the slop is undone, so the rounds end where they stood best: near
        // a resting loop's floor a linearised round can move links sideways
        // far more than the correction it asks for, and its second-order
        // stretch is then larger than what it removed (a ring of 100 equal
        // links at rest: 5.6e-9 beyond the slop before a round, 1.1e-7
        // after; stopping after it kept the worse state).
        let mut previous = S::MAX;
        let ropes = self.step_context.rope_rows.len();
        let h = self.substep_length();
        for applied in [
            &mut self.step_context.tree.applied,
            &mut self.step_context.rope_block.applied,
        ] {
            applied.clear();
            applied.resize(ropes, S::ZERO);
        }
        for pass in 0..=ROPE_SETTLE_MAX_PASSES {
            if pass > 0 {
                let context = &mut self.step_context;
                rope_settle_side_stiffness(
                    &context.joint_rows[..ropes],
                    &context.rope_geometry,
                    h,
                    (&context.tree.applied, &context.rope_block.applied),
                    &mut context.rope_side_stiffness,
                );
            }
            let worst = worst_rope_excess(&self.step_context, slop);
            if !worst.is_positive() {
                break;
            }
            let context = &mut self.step_context;
            if worst <= slop && worst >= previous {
                // `previous <= slop`: its displacements were kept.
                context
                    .displacements
                    .copy_from_slice(&context.settled_displacements);
                break;
            }
            if pass == ROPE_SETTLE_MAX_PASSES {
                break;
            }
            previous = worst;
            if worst <= slop {
                context.settled_displacements.clear();
                context
                    .settled_displacements
                    .extend_from_slice(&context.displacements);
            }
            rope_position_pass(context, &settings, true);
            self.project_rows_out_of_immovable(slop, resting, 1);
        }
        // Outside the rounds the passes sum nothing.
        self.step_context.tree.applied.clear();
        self.step_context.rope_block.applied.clear();
    }

    /// Sweeps the motion each bounce added against the bouncing body's
    /// broad-phase partners and, when the rebound leaves its proxy, the
    /// bodies beyond it that it reaches ([`World::find_rebound_escapes`])
    /// (at their end-of-substep positions), so a
    /// rebound cannot pass through what is behind it.
    ///
    /// A body that is not a bullet stops at the first thing its rebound
    /// meets (the next substep's contact handles that impact). A bullet
    /// bounces off immovable bodies (fixed, kinematic) within the substep,
    /// with the pair's restitution, and sweeps on, up to
    /// [`MAX_BULLET_IMPACTS`] impacts in all; it stops at a dynamic body
    /// (whose response needs the solver) or at the cap.
    ///
    /// A partner the body already touches where its rebound starts is an
    /// obstacle at once if the rebound goes into it (along the pair's
    /// contact normal), and none if it leaves it (the body it bounced off).
    ///
    /// Under gravity a bullet's reflection off a wall at rest is taken on
    /// its own free-flight parabola, from the energy the flight holds
    /// ([`crate::solver::flight_reflection`]): reflecting the stored
    /// (mid-substep) velocity instead is off by `(1 + e)·a_n·(τ − h/2)` at an
    /// impact at instant `τ`, energy gained at every floor impact late in
    /// a substep (up to `g·h·|v_n|` per bounce). The instant `τ`, needed
    /// only for the sign of the velocity along gravity, runs linearly along
    /// the rebound from the bounce's instant to `h`.
    pub(super) fn sweep_rebounds(&mut self, h: S) {
        if self.step_context.rebounds.is_empty() {
            return;
        }
        let context = &mut self.step_context;
        // One sweep per body: keep each slot's first bounce (its earliest
        // displacement is the start of its rebound), at the earliest
        // instant of its bounces. Listed in push order within a slot (an
        // unstable sort needs no buffer; a stable one of thousands of
        // rebounding bodies allocated every step).
        for (k, rebound) in context.rebounds.iter_mut().enumerate() {
            rebound.order = u32::try_from(k).unwrap_or(u32::MAX);
        }
        context.rebounds.sort_unstable_by_key(|r| (r.slot, r.order));
        context.rebounds.dedup_by(|later, first| {
            let same = later.slot == first.slot;
            if same {
                first.time = first.time.min(later.time);
            }
            same
        });
        let gravity = self.settings.gravity;
        collect_rebound_partners(
            &context.pairs,
            &context.rebounds,
            context.velocities.len(),
            &mut context.rebound_partners,
        );
        self.find_rebound_escapes();
        let context = &mut self.step_context;
        for (k, rebound) in context.rebounds.iter().enumerate() {
            let (slot, before) = (rebound.slot, rebound.start);
            let Some(body) = self.slots[slot as usize].body.as_ref() else {
                continue;
            };
            let bullet = body.bullet && body.is_simulated_dynamic();
            let accel = if body.is_simulated_dynamic() {
                gravity.scale(body.gravity_scale)
            } else {
                Vec2::ZERO
            };
            let mut time = rebound.time;
            let cap = if bullet { MAX_BULLET_IMPACTS - 1 } else { 1 };
            // The broad-phase partners, then those beyond the proxy that
            // the rebound reaches (`step/rebound_escape.rs`).
            let beyond = {
                let escapes = &context.rebound_escape_pairs;
                let from = escapes.partition_point(|&(s, _)| s < slot);
                let to = escapes.partition_point(|&(s, _)| s <= slot);
                &escapes[from..to]
            };
            let partners = context
                .rebound_partners
                .of(k)
                .iter()
                .copied()
                .chain(beyond.iter().map(|&(_, other)| other));
            let index = slot as usize;
            let mut at = body.position + before;
            let mut rest = context.displacements[index] - before;
            let mut velocity = context.velocities[index];
            for impact in 0..cap {
                let mut earliest: Option<(S, Vec2<S>, u32)> = None;
                for other in partners.clone() {
                    let Some(ob) = self.slots[other as usize].body.as_ref() else {
                        continue;
                    };
                    let other_at = ob.position + context.displacements[other as usize];
                    let hit =
                        match shape_toi(&body.shape, at, rest, &ob.shape, other_at, Vec2::ZERO) {
                            Toi::Hit { t, normal } => Some((t, normal)),
                            // Touching at the start: an obstacle at t = 0 if the
                            // motion goes into it, none if it leaves it.
                            Toi::Overlapping => {
                                let normal =
                                    contact_between(&body.shape, at, &ob.shape, other_at).normal;
                                rest.dot(normal).is_positive().then_some((S::ZERO, normal))
                            }
                            Toi::Miss => None,
                        };
                    if let Some((t, normal)) = hit
                        && earliest.is_none_or(|(best, _, _)| t < best)
                    {
                        earliest = Some((t, normal, other));
                    }
                }
                let Some((t, normal, other)) = earliest else {
                    break;
                };
                let travelled = rest.scale(t);
                at += travelled;
                let remaining = rest - travelled;
                let immovable = !context.inverse_masses[other as usize].is_positive();
                if !bullet || !immovable || impact + 1 == cap {
                    rest = Vec2::ZERO;
                    break;
                }
                let Some(ob) = self.slots[other as usize].body.as_ref() else {
                    rest = Vec2::ZERO;
                    break;
                };
                // Reflect off the immovable partner (normal from the bullet
                // to it): relative approach v_n = (v_o − u(τ))·n < 0 becomes
                // −e·v_n, i.e. v += (1 + e)·v_n·n; the remaining motion's
                // component into the partner is reflected the same way.
                let e1 = S::ONE.add(body.restitution.max(ob.restitution));
                time = time.add(t.mul(h.sub(time)));
                let into = remaining.dot(normal);
                let reflected = if into.is_positive() {
                    remaining - normal.scale(e1.mul(into))
                } else {
                    remaining
                };
                let other_velocity = context.velocities[other as usize];
                if other_velocity == Vec2::ZERO {
                    // A wall at rest: the reflection on the flight's parabola,
                    // with its energy (`solver::flight_reflection`).
                    velocity = reflect_in_flight(
                        velocity,
                        Flight { accel, h },
                        Impact {
                            end: at + remaining,
                            point: at,
                            new_end: at + reflected,
                            normal,
                            e1,
                            time,
                        },
                    );
                } else {
                    let vn = (other_velocity - velocity).dot(normal);
                    if vn.is_negative() {
                        velocity += normal.scale(e1.mul(vn));
                    }
                }
                rest = reflected;
            }
            at += rest;
            context.displacements[index] = at - body.position;
            context.velocities[index] = velocity;
        }
    }
}

/// The largest excess of an active rope over its length plus the slop,
/// `|d| − L − slop`, at the current displacements (negative when every
/// rope is within the slop).
fn worst_rope_excess<S: Scalar>(context: &StepContext<S>, slop: S) -> S {
    let mut worst = S::MIN;
    for (row, &(start_offset, max_length)) in context.rope_rows.iter().zip(&context.rope_geometry) {
        let moved = context.displacements[row.b as usize] - context.displacements[row.a as usize];
        worst = worst.max((start_offset + moved).length().sub(max_length).sub(slop));
    }
    worst
}

/// The displacements each body may end a substep with: those keeping its
/// box within its broad-phase proxy (see
/// [`World::project_out_of_immovable`]).
struct ProxyReach<'a, S: Scalar> {
    /// This substep's proxies, in slot order (`build_proxies` pushes them
    /// so; bodies without a proxy are skipped).
    proxies: &'a [Proxy<S>],
    slots: &'a [Slot<S>],
}

impl<S: Scalar> ProxyReach<'_, S> {
    /// Whether the body in `slot` is a sleeping dynamic body (immovable
    /// this substep only).
    fn asleep(&self, slot: usize) -> bool {
        self.slots
            .get(slot)
            .and_then(|s| s.body.as_ref())
            .is_some_and(|b| b.kind == BodyKind::Dynamic && !b.awake)
    }

    /// The lowest and highest displacement (per axis) of the body in
    /// `slot` that keep its box, from where it started the substep, inside
    /// its proxy; `None` for a slot without a proxy (frozen, empty).
    fn range(&self, slot: usize) -> Option<(Vec2<S>, Vec2<S>)> {
        let index = u32::try_from(slot).ok()?;
        let at = self
            .proxies
            .binary_search_by_key(&index, |p| p.index)
            .ok()?;
        let proxy = &self.proxies[at];
        let now = self.slots.get(slot)?.body.as_ref()?.aabb();
        let (lo, hi) = (now.min(), now.max());
        Some((
            Vec2::new(proxy.min_x.sub(lo.x), proxy.min_y.sub(lo.y)),
            Vec2::new(proxy.max_x.sub(hi.x), proxy.max_y.sub(hi.y)),
        ))
    }
}

/// One pass of [`World::project_out_of_immovable`]: every row between a
/// movable and an immovable body that is deeper than the slop moves the
/// movable body out along the row's normal, to the slop, as far as its
/// proxy allows (`reach`). A body stopped short, or moved by more than it
/// may move while counting as resting (`resting` on an axis), is added to
/// `unresolved`: the row's separation is linear in the displacement, so a
/// body moved far along a normal taken where it started (coincident
/// centres) can still be deep by the true geometry, which only the next
/// substep's rows see; it may not fall asleep before they do.
fn project_rows_out_of_immovable<S: Scalar>(
    constraints: &[ContactConstraint<S>],
    displacements: &mut [Vec2<S>],
    slop: S,
    resting: S,
    reach: &ProxyReach<'_, S>,
    unresolved: &mut Vec<u32>,
) {
    // Rows to sleeping bodies first, rows to fixed and kinematic bodies
    // last: the last row a body is projected along is the one it ends
    // within the slop of, and only fixed walls must never be crossed (a
    // sleeper is woken by the contact in the next substeps). A light body
    // wedged at 5° between the floor and a sleeping body ended 1.9e-9
    // beyond the slop in the floor when the sleeper's row came last.
    for sleepers in [true, false] {
        project_rows_pass(
            constraints,
            displacements,
            slop,
            resting,
            reach,
            unresolved,
            sleepers,
        );
    }
}

/// The rows of [`project_rows_out_of_immovable`] whose immovable end is a
/// sleeping body (`sleepers`) or a fixed or kinematic one (`!sleepers`).
fn project_rows_pass<S: Scalar>(
    constraints: &[ContactConstraint<S>],
    displacements: &mut [Vec2<S>],
    slop: S,
    resting: S,
    reach: &ProxyReach<'_, S>,
    unresolved: &mut Vec<u32>,
    sleepers: bool,
) {
    for c in constraints {
        let (ia, ib) = (c.a as usize, c.b as usize);
        let (movable_a, movable_b) = (
            c.inverse_mass_a.is_positive(),
            c.inverse_mass_b.is_positive(),
        );
        if movable_a == movable_b || reach.asleep(if movable_a { ib } else { ia }) != sleepers {
            continue;
        }
        let separation = c
            .separation
            .add((displacements[ib] - displacements[ia]).dot(c.normal));
        // Depth beyond the slop: −slop − s > 0.
        let deficit = slop.neg().sub(separation);
        if !deficit.is_positive() {
            continue;
        }
        let push = c.normal.scale(deficit);
        let (slot, wanted) = if movable_a {
            (ia, displacements[ia] - push)
        } else {
            (ib, displacements[ib] + push)
        };
        let current = displacements[slot];
        let bounded = match reach.range(slot) {
            // A displacement already outside the range (none is, as the
            // passes before stay within the proxy) is not pulled back.
            Some((lo, hi)) => wanted.clamp(lo.min(current), hi.max(current)),
            None => wanted,
        };
        let moved = bounded - current;
        if bounded != wanted || moved.x.abs() > resting || moved.y.abs() > resting {
            let index = if movable_a { c.a } else { c.b };
            if !unresolved.contains(&index) {
                unresolved.push(index);
            }
        }
        displacements[slot] = bounded;
    }
}
