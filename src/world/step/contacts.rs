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
use crate::geometry::{Shape, Toi};
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

/// The most passes of [`World::sweep_rebounds`]: the first sweeps every
/// rebound, each further one the rebounds whose rebounding partners the
/// pass before shortened (a partner swept later and stopped short can
/// otherwise be passed). Each pass only shortens rebounds along their own
/// paths, so the passes end; a row of 8 bodies stopped one behind the
/// other takes 8.
const REBOUND_SWEEP_MAX_PASSES: u32 = 8;

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
    /// A partner that rebounds too is not standing at its end meanwhile: it
    /// moves along its own rebound, at the same share of it (the rebounds
    /// of a substep are swept over one parameter, their share done), until
    /// its own sweep stopped it, and stands there after ([`meeting`]). Swept
    /// against the end of a partner launched with it, a box of a row
    /// struck at e = 1 "met" the box ahead where that one's end lay across
    /// its path, stopped there, and ended 0.018 inside it (two boxes of the
    /// projectile's mass at 50 units/s; up to 0.5 with boxes 100× lighter).
    /// A partner swept later can still be stopped short of where the body
    /// was swept against, so the rebounds whose rebounding partners a pass
    /// stopped are swept again (bodies that are no bullets, along their
    /// whole rebound, keeping the least share any pass left them), at most
    /// [`REBOUND_SWEEP_MAX_PASSES`] passes; each pass only shortens.
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
        let count = context.rebounds.len();
        context.rebound_shortened.clear();
        context.rebound_shortened.resize(count, false);
        context.rebound_shortening.clear();
        context.rebound_shortening.resize(count, false);
        context.rebound_dirty.clear();
        context.rebound_dirty.resize(count, false);
        context.rebound_reach.clear();
        context.rebound_reach.resize(count, S::ONE);
        context.rebound_full.clear();
        context.rebound_full.extend(
            context
                .rebounds
                .iter()
                .map(|r| context.displacements[r.slot as usize] - r.start),
        );
        for pass in 0..REBOUND_SWEEP_MAX_PASSES {
            let mut any_shortened = false;
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
                // After the first pass, only a body that is no bullet and has
                // a rebounding partner the last pass shortened is swept
                // again, and only against those partners: its share is the
                // least of every meeting found, and the others' meetings are
                // unchanged.
                if pass > 0 && (bullet || !context.rebound_dirty[k]) {
                    continue;
                }
                let index = slot as usize;
                let mut at = body.position + before;
                // A body that is no bullet is swept along its whole rebound
                // motion (its parameter is its partners'), and keeps the
                // least share any pass left it.
                let mut rest = if bullet {
                    context.displacements[index] - before
                } else {
                    context.rebound_full[k]
                };
                let mut velocity = context.velocities[index];
                // The share of the rebound motion done (the partners that
                // rebound too are at the same share of theirs).
                let mut done = S::ZERO;
                for impact in 0..cap {
                    let mut earliest: Option<(S, Vec2<S>, u32)> = None;
                    let swept = SweptBox::of(&body.shape, at, rest);
                    for other in partners.clone() {
                        let Some(ob) = self.slots[other as usize].body.as_ref() else {
                            continue;
                        };
                        let rebounding = context
                            .rebound_partners
                            .rebound_of(other)
                            .filter(|_| !(ob.bullet && ob.is_simulated_dynamic()));
                        if pass > 0 && !rebounding.is_some_and(|j| context.rebound_shortened[j]) {
                            continue;
                        }
                        let partner = match rebounding {
                            Some(j) => PartnerPath {
                                base: ob.position + context.rebounds[j].start,
                                motion: context.rebound_full[j],
                                reach: context.rebound_reach[j],
                            },
                            None => PartnerPath {
                                base: ob.position + context.displacements[other as usize],
                                motion: Vec2::ZERO,
                                reach: S::ZERO,
                            },
                        };
                        if swept.apart(&ob.shape, partner) {
                            continue;
                        }
                        let hit = meeting(&body.shape, at, rest, done, &ob.shape, partner);
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
                    done = done.add(t.mul(S::ONE.sub(done)));
                    let remaining = rest - travelled;
                    let immovable = !context.inverse_masses[other as usize].is_positive();
                    if !bullet || !immovable || impact + 1 == cap {
                        rest = Vec2::ZERO;
                        if !bullet {
                            // The rebound stops at `t` of its whole motion,
                            // or where a pass before stopped it.
                            let reach = &mut context.rebound_reach[k];
                            *reach = (*reach).min(t);
                        }
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
                let displacement = if bullet {
                    at - body.position
                } else {
                    before + context.rebound_full[k].scale(context.rebound_reach[k])
                };
                if displacement != context.displacements[index] {
                    context.rebound_shortening[k] = true;
                    any_shortened = true;
                }
                context.displacements[index] = displacement;
                context.velocities[index] = velocity;
            }
            if !any_shortened {
                break;
            }
            // The bodies to sweep again: the rebounding partners of those
            // shortened (broad-phase partners are mutual; a partner beyond
            // a proxy is listed under the rebound that reached it).
            context.rebound_dirty.fill(false);
            for (j, _) in context
                .rebound_shortening
                .iter()
                .enumerate()
                .filter(|(_, shortened)| **shortened)
            {
                for &other in context.rebound_partners.of(j) {
                    if let Some(i) = context.rebound_partners.rebound_of(other) {
                        context.rebound_dirty[i] = true;
                    }
                }
                let slot = context.rebounds[j].slot;
                for &(from, _) in context
                    .rebound_escape_pairs
                    .iter()
                    .filter(|&&(_, other)| other == slot)
                {
                    if let Some(i) = context.rebound_partners.rebound_of(from) {
                        context.rebound_dirty[i] = true;
                    }
                }
            }
            core::mem::swap(
                &mut context.rebound_shortened,
                &mut context.rebound_shortening,
            );
            context.rebound_shortening.fill(false);
        }
    }
}

/// Where a rebound's partner is along the sweep's parameter `s ∈ [0, 1]`
/// (the share of the rebound motion done): `base + motion·min(s, reach)`.
/// A partner that rebounds too moves along its own rebound motion until it
/// was stopped (`reach`, the share it kept) and stands there after; any
/// other stands at its end (`motion` zero).
#[derive(Clone, Copy)]
struct PartnerPath<S: Scalar> {
    base: Vec2<S>,
    motion: Vec2<S>,
    reach: S,
}

/// The box a body sweeps moving from `at` by `rest`, grown by its shape's
/// half extents and a margin: a cheap reject before [`meeting`], which
/// casts (most broad-phase partners of a rebound lie beside its short
/// motion).
///
/// It never drops a meeting: at any parameter the body is within
/// `[min(at, at + rest), max(at, at + rest)]` and the partner within
/// `[min(base, end), max(base, end)]`, `end = base + motion·reach` (each
/// piece of [`meeting`] runs between points of those segments), so on an
/// axis where the grown ranges are apart by `g` the shapes are apart by `g`
/// at every parameter. The casts are exact but for their direction
/// `u = d/L`, rounded by an ulp a component, so the point cast to lies
/// within `L·ulp + 4 ulps` of the exact one (`geometry::toi`), and the
/// pieces' starts are rounded by an ulp or two: the margin
/// `64 ulps + |rest|₁/256 + |motion|₁/256` covers it all for any scalar with
/// at least 9 fraction bits (the result is bit-identical with or without
/// the reject).
#[derive(Clone, Copy)]
struct SweptBox<S: Scalar> {
    lo: Vec2<S>,
    hi: Vec2<S>,
}

/// `|v|₁/256` as eight halvings (a shift for fixed point, no division).
fn l1_256th<S: Scalar>(v: Vec2<S>) -> S {
    (0..8).fold(v.x.abs().add(v.y.abs()), |r, _| r.half())
}

impl<S: Scalar> SweptBox<S> {
    /// The grown box of a body of `shape` moving from `at` by `rest`.
    fn of(shape: &Shape<S>, at: Vec2<S>, rest: Vec2<S>) -> Self {
        let to = at + rest;
        let margin = l1_256th(rest).add(S::EPSILON.mul_int(64));
        let grow = shape.half_extents() + Vec2::new(margin, margin);
        let lo = Vec2::new(at.x.min(to.x), at.y.min(to.y)) - grow;
        let hi = Vec2::new(at.x.max(to.x), at.y.max(to.y)) + grow;
        Self { lo, hi }
    }

    /// Whether a partner of `other` on `path` is certainly never met.
    #[inline]
    fn apart(&self, other: &Shape<S>, path: PartnerPath<S>) -> bool {
        let hb = other.half_extents();
        let (mut lo, mut hi) = (path.base - hb, path.base + hb);
        if path.motion != Vec2::ZERO {
            let end = path.base + path.motion.scale(path.reach);
            let margin = l1_256th(path.motion);
            let grow = Vec2::new(margin, margin);
            lo = Vec2::new(lo.x.min(end.x.sub(hb.x)), lo.y.min(end.y.sub(hb.y))) - grow;
            hi = Vec2::new(hi.x.max(end.x.add(hb.x)), hi.y.max(end.y.add(hb.y))) + grow;
        }
        lo.x > self.hi.x || lo.y > self.hi.y || self.lo.x > hi.x || self.lo.y > hi.y
    }
}

/// Where a body moving from `at` by `rest` over `s ∈ [done, 1]` first meets
/// a partner on `path`: the share of `rest` travelled and the contact
/// normal (from the body to the partner). Two pieces: while the partner
/// still moves (`s` up to its reach), both move; after, it stands at its
/// end. Touching where a piece starts is a meeting at once if the motion
/// goes into the partner, none if it leaves it.
fn meeting<S: Scalar>(
    shape: &Shape<S>,
    at: Vec2<S>,
    rest: Vec2<S>,
    done: S,
    other: &Shape<S>,
    path: PartnerPath<S>,
) -> Option<(S, Vec2<S>)> {
    let first = |from: Vec2<S>, by: Vec2<S>, other_from: Vec2<S>, other_by: Vec2<S>| match shape_toi(
        shape, from, by, other, other_from, other_by,
    ) {
        Toi::Hit { t, normal } => Some((t, normal)),
        Toi::Overlapping => {
            let normal = contact_between(shape, from, other, other_from).normal;
            (by - other_by)
                .dot(normal)
                .is_positive()
                .then_some((S::ZERO, normal))
        }
        Toi::Miss => None,
    };
    // The common cases in one piece: a partner standing at its end, and one
    // whose whole rebound is ahead as the body's is.
    if path.motion == Vec2::ZERO {
        return first(at, rest, path.base, Vec2::ZERO);
    }
    if done == S::ZERO && path.reach >= S::ONE {
        return first(at, rest, path.base, path.motion);
    }
    // The share of `rest` made while the partner moves.
    let span = S::ONE.sub(done);
    let moving = if path.reach <= done || !span.is_positive() {
        S::ZERO
    } else if done == S::ZERO {
        path.reach
    } else {
        path.reach.sub(done).div(span).min(S::ONE)
    };
    if moving.is_positive() {
        let other_from = path.base + path.motion.scale(done);
        let other_by = path.motion.scale(path.reach.sub(done));
        if let Some((t, normal)) = first(at, rest.scale(moving), other_from, other_by) {
            return Some((t.mul(moving), normal));
        }
        // A partner moving to the end of the parameter: no second piece.
        if moving >= S::ONE {
            return None;
        }
    }
    let made = rest.scale(moving);
    let end = path.base + path.motion.scale(path.reach);
    first(at + made, rest - made, end, Vec2::ZERO)
        .map(|(t, normal)| (moving.add(t.mul(S::ONE.sub(moving))), normal))
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
