//! Narrow phase: candidate pairs → contact rows ([`NarrowPhase`]), with one
//! function per shape pair, chosen by the shapes.

use crate::geometry::{
    Aabb, Circle, Contact, Shape, Toi, contact_aabb_aabb, contact_aabb_circle, contact_circle_aabb,
    contact_circle_circle, toi_aabb_aabb, toi_circle_aabb, toi_circle_circle,
};
use crate::math::{Scalar, Vec2, WideScalar};

use super::CachedContact;
use super::NarrowScratch;
use super::box_corner::{box_contact, corner_apart, corner_impact};
use super::coincident::coincident_contact;
use super::confined_pair::confined_contact;
use super::covered_corner::covered_corner;
use super::deflected_sweep::{Side, deflected_impact, earlier_turn};
use super::face_past_walls::face_past_walls;
use super::grazing_miss::passes_within_slop;
use super::implied_rows::implied_rows;
use super::level_seam::level_seam;
use super::rope_turn::{rope_turn, rope_turned_contact};
use crate::dynamics::{Body, BodyKind};
use crate::solver::restitution::BounceCandidate;
use crate::solver::row::{ContactConstraint, effective_mass};

/// The contact between shape `a` at `pa` and shape `b` at `pb` (normal from
/// a to b).
#[inline]
pub(crate) fn contact_between<S: Scalar>(
    a: &Shape<S>,
    pa: Vec2<S>,
    b: &Shape<S>,
    pb: Vec2<S>,
) -> Contact<S> {
    match (*a, *b) {
        (Shape::Circle { radius: ra }, Shape::Circle { radius: rb }) => {
            contact_circle_circle(&Circle::new(pa, ra), &Circle::new(pb, rb))
        }
        (Shape::Circle { radius }, Shape::Aabb { half_extents }) => {
            contact_circle_aabb(&Circle::new(pa, radius), &Aabb::new(pb, half_extents))
        }
        (Shape::Aabb { half_extents }, Shape::Circle { radius }) => {
            contact_aabb_circle(&Aabb::new(pa, half_extents), &Circle::new(pb, radius))
        }
        (Shape::Aabb { half_extents: ha }, Shape::Aabb { half_extents: hb }) => {
            contact_aabb_aabb(&Aabb::new(pa, ha), &Aabb::new(pb, hb))
        }
    }
}

/// A slot meets something this substep (a row that closes within it).
const MEETS: u8 = 1;
/// A slot meets a body the solver cannot move.
const MEETS_IMMOVABLE: u8 = 2;
/// A slot of a pair the second look checks.
const WANTED: u8 = 4;
/// A circle with a row at the corner of an immovable box
/// (`collision::covered_corner`).
const COVERED: u8 = 8;
/// A movable body has a face row with an immovable body lying along −x
/// from it (`collision::confined_pair`); and along +x, −y, +y.
const WALL_NEG_X: u8 = 16;
/// See [`WALL_NEG_X`].
const WALL_POS_X: u8 = 32;
/// See [`WALL_NEG_X`].
const WALL_NEG_Y: u8 = 64;
/// See [`WALL_NEG_X`].
const WALL_POS_Y: u8 = 128;

/// The `WALL_*` bit of the axis direction `n`.
fn wall_bit<S: Scalar>(n: Vec2<S>) -> u8 {
    if n.x.is_negative() {
        WALL_NEG_X
    } else if n.x.is_positive() {
        WALL_POS_X
    } else if n.y.is_negative() {
        WALL_NEG_Y
    } else {
        WALL_POS_Y
    }
}

/// Time of impact of shape `a` at `pa` moving by `da` against shape `b` at
/// `pb` moving by `db` (normal from a to b).
#[inline]
pub(crate) fn shape_toi<S: Scalar>(
    a: &Shape<S>,
    pa: Vec2<S>,
    da: Vec2<S>,
    b: &Shape<S>,
    pb: Vec2<S>,
    db: Vec2<S>,
) -> Toi<S> {
    match (*a, *b) {
        (Shape::Circle { radius: ra }, Shape::Circle { radius: rb }) => {
            toi_circle_circle(&Circle::new(pa, ra), da, &Circle::new(pb, rb), db)
        }
        (Shape::Circle { radius }, Shape::Aabb { half_extents }) => toi_circle_aabb(
            &Circle::new(pa, radius),
            da,
            &Aabb::new(pb, half_extents),
            db,
        ),
        (Shape::Aabb { half_extents }, Shape::Circle { radius }) => {
            // Swap roles and flip the normal back to a → b.
            match toi_circle_aabb(
                &Circle::new(pb, radius),
                db,
                &Aabb::new(pa, half_extents),
                da,
            ) {
                Toi::Hit { t, normal } => Toi::Hit { t, normal: -normal },
                other => other,
            }
        }
        (Shape::Aabb { half_extents: ha }, Shape::Aabb { half_extents: hb }) => {
            toi_aabb_aabb(&Aabb::new(pa, ha), da, &Aabb::new(pb, hb), db)
        }
    }
}

/// Whether two circles are certainly too far apart to be in contact this
/// substep, decided without a square root (a cheap reject before
/// [`contact_between`], which normalises the centre offset).
///
/// The step keeps a pair when `s ≤ margin + max(0, −v_n)·h`, with
/// `s = |d| − (r_a + r_b)` and `v_n = Δv·n`. Since `|v_n| ≤ |Δv|₂ ≤
/// |Δv_x| + |Δv_y| = L₁`, the pair is dropped whenever
/// `|d| > R = r_a + r_b + margin + L₁·h + ε`, i.e. `|d|² > R²`, compared
/// exactly in the wide type. `ε` absorbs the rounding of the exact test, so
/// this never drops a pair that test would keep (the result is bit-identical
/// with or without the reject): the computed `|d|` is at most one ulp low;
/// the computed normal is off by at most `2 ulp/|d| + 2 ulp` relative, which
/// moves `v_n·h ≤ L₁·h < |d|` by at most `2 ulp + 2 ulp·R`; the dot product and
/// the products with `h` round by a few ulps more. `ε = 16 ulp + R/256`
/// covers all of it for every scalar with at least 9 fraction bits (and the
/// relative errors of the float references, near 2⁻²³).
#[inline]
pub(crate) fn circles_out_of_reach<S: Scalar>(
    radii: S,
    offset: Vec2<S>,
    relative_velocity: Vec2<S>,
    margin: S,
    h: S,
) -> bool {
    let speed_bound = relative_velocity.x.abs().add(relative_velocity.y.abs());
    let reach = radii.add(margin).add(speed_bound.mul(h));
    // R/256 as eight halvings (a shift for fixed point, no division).
    let reach_256th = (0..8).fold(reach, |r, _| r.half());
    let bound = reach.add(reach_256th).add(S::EPSILON.mul_int(16));
    offset.length_squared_wide() > bound.wide_mul(bound)
}

/// The narrow phase of one substep: the candidate pairs of the broad phase
/// become contact rows for the solver, warm-started from the contact cache.
/// Holds everything it reads besides the bodies.
pub(crate) struct NarrowPhase<'a, S: Scalar> {
    /// Candidate pairs, sorted by `(a, b)`.
    pub(crate) pairs: &'a [(u32, u32)],
    /// Velocity of each slot (gravity and springs applied).
    pub(crate) velocities: &'a [Vec2<S>],
    /// Inverse mass of each slot as the solver sees it.
    pub(crate) inverse_masses: &'a [S],
    /// Per slot, the turn of its velocity by stretched ropes (empty: none;
    /// `collision::rope_turn`).
    pub(crate) rope_turns: &'a [Vec2<S>],
    /// Last substep's contacts, sorted by `(a, b)`: the warm-start impulses.
    pub(crate) cache: &'a [CachedContact<S>],
    /// Gap within which a pair gets a (speculative) row.
    pub(crate) speculative_margin: S,
    /// Predicted gap at or below which a sleeping body is woken.
    pub(crate) linear_slop: S,
    /// Approach speed above which restitution applies.
    pub(crate) restitution_threshold: S,
    /// The world's gravity (for the bounce's relative acceleration).
    pub(crate) gravity: Vec2<S>,
    /// The substep `h`.
    pub(crate) h: S,
    /// `1/h`.
    pub(crate) inverse_h: S,
}

impl<S: Scalar> NarrowPhase<'_, S> {
    /// Writes one contact row per pair that is or may come into contact
    /// within the substep into `rows` (cleared first), merge-joining the
    /// cache for warm starting (both lists are sorted by pair). `body(i)`
    /// is the body of slot `i`.
    ///
    /// Rows that close this substep faster than the restitution threshold
    /// with a positive restitution go to `bounces` too (cleared first): the
    /// solve treats every row as speculative only, and the bounce is
    /// re-timed to the instant of contact after the position update
    /// ([`crate::solver::restitution`]).
    ///
    /// Returns the sleeping bodies an awake body touches (sorted, without
    /// repeats), to be woken; when it is not empty the rows are incomplete
    /// and the caller redoes the phase after waking them.
    pub(crate) fn contact_rows<'b>(
        &self,
        body: impl Fn(u32) -> Option<&'b Body<S>>,
        rows: &mut Vec<ContactConstraint<S>>,
        bounces: &mut Vec<BounceCandidate<S>>,
        scratch: &mut NarrowScratch<S>,
    ) -> Vec<u32>
    where
        S: 'b,
    {
        let NarrowPhase {
            pairs,
            velocities,
            inverse_masses,
            rope_turns,
            cache,
            speculative_margin,
            linear_slop,
            restitution_threshold: _,
            gravity,
            h,
            inverse_h: _,
        } = *self;
        rows.clear();
        bounces.clear();
        let mut to_wake = Vec::new();
        let mut cache = cache.iter().peekable();
        // The last inverse-mass sum and its reciprocal: piles of equal
        // masses need one division, not one per pair (same value).
        let mut last_mass = (S::ZERO, S::ZERO);
        // The pairs whose straight sweep is re-checked after the loop
        // against the rows that meet (`collision::deflected_sweep`):
        // misses (no row yet) and hits (a row at `rows[i]`, hit at
        // fraction `t`).
        scratch.missed.clear();
        scratch.hits.clear();
        scratch.straight_misses = 0;
        // Per slot: whether it meets anything this substep (`MEETS`), an
        // immovable body (`MEETS_IMMOVABLE`): only such a body can be
        // turned (`collision::deflected_sweep`).
        scratch.flags.clear();
        scratch.flags.resize(velocities.len(), 0);
        // One substep of the world's gravity from rest, per axis (`|g|·h²`,
        // the level seams' allowance, `collision::level_seam`).
        let h2 = h.mul(h);
        let sag = Vec2::new(gravity.x.abs().mul(h2), gravity.y.abs().mul(h2));
        for &(a, b) in pairs {
            let (Some(body_a), Some(body_b)) = (body(a), body(b)) else {
                continue;
            };
            // Most broad-phase pairs of a ball pit are diagonal neighbours
            // out of reach: reject them before the square root.
            if let (Shape::Circle { radius: ra }, Shape::Circle { radius: rb }) =
                (body_a.shape, body_b.shape)
                && circles_out_of_reach(
                    ra.add(rb),
                    body_b.position - body_a.position,
                    velocities[b as usize] - velocities[a as usize],
                    speculative_margin,
                    h,
                )
            {
                continue;
            }
            let is_box_pair = matches!(
                (body_a.shape, body_b.shape),
                (Shape::Aabb { .. }, Shape::Aabb { .. })
            );
            // Same centre: the geometry has no normal; take the pair's own
            // spread direction (see `collision::coincident`).
            let mut contact = if body_a.position == body_b.position {
                coincident_contact(a, &body_a.shape, b, &body_b.shape)
            } else if let (Shape::Aabb { half_extents: ha }, Shape::Aabb { half_extents: hb }) =
                (body_a.shape, body_b.shape)
            {
                // Boxes: a corner touch does not carry weight.
                box_contact(
                    &Aabb::new(body_a.position, ha),
                    &Aabb::new(body_b.position, hb),
                    gravity,
                    linear_slop,
                )
            } else {
                contact_between(
                    &body_a.shape,
                    body_a.position,
                    &body_b.shape,
                    body_b.position,
                )
            };
            let (va, vb) = (velocities[a as usize], velocities[b as usize]);
            let mut on_seam = false;
            // A body moving along flush faces meets the next one's face,
            // not its corner (`collision::level_seam`). Circle pairs have
            // no faces.
            if !matches!(
                (body_a.shape, body_b.shape),
                (Shape::Circle { .. }, Shape::Circle { .. })
            ) && let Some(seam) = level_seam(
                &contact,
                body_b.position - body_a.position,
                body_a.shape.half_extents() + body_b.shape.half_extents(),
                (vb - va).scale(h),
                sag,
                linear_slop,
            ) {
                contact = seam;
                on_seam = true;
            }
            if is_box_pair
                && corner_apart(
                    &Aabb::new(body_a.position, body_a.shape.half_extents()),
                    &Aabb::new(body_b.position, body_b.shape.half_extents()),
                    (vb - va).scale(h),
                    &contact,
                    gravity,
                    linear_slop,
                )
            {
                // A corner over a corner carries no weight
                // (`collision::box_corner`).
                continue;
            }
            let mut vn = (vb - va).dot(contact.normal);
            // Keep the contact if the gap can close within this substep
            // (plus the margin): s ≤ margin + max(0, -v_n)·h.
            let reach = speculative_margin.add(vn.neg().max(S::ZERO).mul(h));
            if contact.separation > reach {
                continue;
            }
            // A gap the current motion would close along the start normal
            // (an active speculative row): ask the exact time of impact
            // whether it really closes. A miss (passing a corner or a gap
            // with clearance) makes no row: it would stop or deflect a body
            // that never touches (a ghost hit). A hit re-aims the row at
            // the impact: its normal, and the gap along it that the motion
            // closes, `s' = −t·(Δv·n')·h`, so the row lets the pair move
            // exactly to the impact. Gaps within the slop count as
            // touching and are left alone.
            // (Not at a level seam: the motion there holds a gravity step
            // the support below takes out, and its time of impact would
            // hit the side face the seam rule has just ruled out.)
            let mut hit_at = None;
            if !on_seam && contact.separation > linear_slop && vn.neg().mul(h) > contact.separation
            {
                let toi = shape_toi(
                    &body_a.shape,
                    body_a.position,
                    va.scale(h),
                    &body_b.shape,
                    body_b.position,
                    vb.scale(h),
                );
                // A miss or a corner hit of a face contact may only be the
                // straight motion's answer: reflected off the walls it meets
                // first, the body may still reach the face
                // (`collision::face_past_walls`). Then the row along the
                // start normal, with the start gap, is the exact one.
                let face_lost = match toi {
                    Toi::Miss => true,
                    Toi::Hit { normal, .. } => normal != contact.normal,
                    Toi::Overlapping => false,
                };
                let toi =
                    if face_lost && self.face_reached_past_walls(&body, (a, b), contact.normal) {
                        Toi::Overlapping
                    } else {
                        toi
                    };
                match toi {
                    // A miss is a clearance only if neither body is turned
                    // into the other by something it meets first: decided
                    // after the loop, when every meeting row is known
                    // (`collision::deflected_sweep`).
                    // A body a stretched rope turns may meet the other after
                    // all (`collision::rope_turn`): the row is aimed at the
                    // turned motion's impact.
                    Toi::Miss => match rope_turned_contact(
                        (&body_a.shape, body_a.position, va),
                        (&body_b.shape, body_b.position, vb),
                        (rope_turn(rope_turns, a), rope_turn(rope_turns, b)),
                        h,
                    ) {
                        Some(turned) => {
                            vn = (vb - va).dot(turned.normal);
                            contact = turned;
                        }
                        // A rope-turned path within the slop keeps the start
                        // row (`collision::grazing_miss`).
                        None if (rope_turn(rope_turns, a) != Vec2::ZERO
                            || rope_turn(rope_turns, b) != Vec2::ZERO)
                            && passes_within_slop(
                                (&body_a.shape, body_a.position, va.scale(h)),
                                (&body_b.shape, body_b.position, vb.scale(h)),
                                linear_slop,
                            ) => {}
                        None => {
                            scratch.straight_misses += 1;
                            scratch.missed.push((a, b));
                            continue;
                        }
                    },
                    Toi::Hit { t, normal }
                        if is_box_pair
                            && corner_impact(
                                &Aabb::new(body_a.position, body_a.shape.half_extents()),
                                &Aabb::new(body_b.position, body_b.shape.half_extents()),
                                (vb - va).scale(h),
                                t,
                                normal,
                                gravity,
                                linear_slop,
                            ) =>
                    {
                        // A corner meeting along the weight axis carries no
                        // weight (`collision::box_corner`).
                        continue;
                    }
                    Toi::Hit { t, normal } => {
                        // Re-aimed at the impact (and re-checked after the
                        // loop for an earlier turn of either body,
                        // `collision::deflected_sweep`).
                        vn = (vb - va).dot(normal);
                        contact.normal = normal;
                        contact.separation = t.mul(vn.mul(h)).neg().max(S::ZERO);
                        hit_at = Some(t);
                    }
                    Toi::Overlapping => {}
                }
            }
            let asleep_a = body_a.kind == BodyKind::Dynamic && !body_a.awake;
            let asleep_b = body_b.kind == BodyKind::Dynamic && !body_b.awake;
            // Wake a sleeper only if the pair touches or will touch within
            // this substep at the current approach speed: a resting awake
            // body a hair away from a sleeping pile must not wake it.
            let predicted = contact.separation.add(vn.min(S::ZERO).mul(h));
            if (asleep_a || asleep_b) && predicted <= linear_slop {
                if asleep_a {
                    to_wake.push(a);
                }
                if asleep_b {
                    to_wake.push(b);
                }
            }
            if !to_wake.is_empty() {
                continue;
            }
            let (wa, wb) = (inverse_masses[a as usize], inverse_masses[b as usize]);
            let sum = wa.add(wb);
            if !sum.is_positive() {
                continue;
            }
            // Skip cache entries of pairs that are gone, pick this pair's.
            while cache.peek().is_some_and(|c| (c.a, c.b) < (a, b)) {
                cache.next();
            }
            // Warm start only contacts that touch: a speculative row's
            // impulse of the last substep (a bounce, a catch) says nothing
            // about this one, and re-applied it can drive the body the
            // wrong way (into what is behind it).
            let (normal_impulse, tangent_impulse) = match cache.peek() {
                Some(c) if (c.a, c.b) == (a, b) && contact.separation <= linear_slop => {
                    (c.normal_impulse, c.tangent_impulse)
                }
                _ => (S::ZERO, S::ZERO),
            };
            if sum != last_mass.0 {
                last_mass = (sum, effective_mass(wa, wb));
            }
            let (constraint, bounce) = self.row(
                (a, body_a),
                (b, body_b),
                contact,
                vn,
                (normal_impulse, tangent_impulse),
                last_mass.1,
            );
            if let Some(mut bounce) = bounce {
                bounce.row = u32::try_from(rows.len()).unwrap_or(u32::MAX);
                bounces.push(bounce);
            }
            if vn.is_negative() && vn.neg().mul(h) >= contact.separation {
                let flag = |w: S| MEETS | if w.is_positive() { 0 } else { MEETS_IMMOVABLE };
                scratch.flags[a as usize] |= flag(wb);
                scratch.flags[b as usize] |= flag(wa);
            }
            if let Some(t) = hit_at {
                scratch.hits.push((rows.len(), t));
            }
            // A face row of a movable body with an immovable one: the side
            // it lies on (`collision::confined_pair`).
            if wa.is_positive() != wb.is_positive()
                && (contact.normal.x == S::ZERO || contact.normal.y == S::ZERO)
            {
                let (slot, n) = if wa.is_positive() {
                    (a, contact.normal)
                } else {
                    (b, -contact.normal)
                };
                scratch.flags[slot as usize] |= wall_bit(n);
            }
            rows.push(constraint);
        }
        if to_wake.is_empty() && !(scratch.missed.is_empty() && scratch.hits.is_empty()) {
            self.turned_rows(&body, scratch, rows, bounces, &mut to_wake);
        }
        if to_wake.is_empty() {
            self.covered_corners(&body, scratch, rows, bounces);
            self.confined_pairs(&body, scratch, rows, bounces);
            self.mark_implied_rows(scratch, rows);
        }
        to_wake.sort_unstable();
        to_wake.dedup();
        to_wake
    }

    /// The row of the pair `(a, b)` with `contact` and normal velocity
    /// `vn`, warm-started with `warm`, and its bounce if it bounces (its
    /// `row` index left for the caller to set).
    #[inline(always)]
    fn row(
        &self,
        (a, body_a): (u32, &Body<S>),
        (b, body_b): (u32, &Body<S>),
        contact: Contact<S>,
        vn: S,
        warm: (S, S),
        effective: S,
    ) -> (ContactConstraint<S>, Option<BounceCandidate<S>>) {
        let (h, inverse_h, gravity) = (self.h, self.inverse_h, self.gravity);
        let (wa, wb) = (
            self.inverse_masses[a as usize],
            self.inverse_masses[b as usize],
        );
        // Geometric mean of the frictions (exact, and sqrt-free, when
        // they are equal, which is the common case).
        let friction = if body_a.friction == body_b.friction {
            body_a.friction
        } else {
            body_a.friction.mul(body_b.friction).sqrt()
        };
        let restitution = body_a.restitution.max(body_b.restitution);
        let mut constraint = ContactConstraint::new(
            a,
            b,
            contact.normal,
            contact.separation,
            (wa, wb),
            effective,
            friction,
            warm,
        );
        // Speculative only in the solve; the bounce comes after the
        // position update.
        constraint.prepare_target(vn, S::ZERO, self.restitution_threshold, h, inverse_h);
        // A candidate for a bounce: an approach faster than the threshold,
        // with a positive restitution, that may meet within the substep.
        let bounce = (restitution.is_positive() && vn < self.restitution_threshold.neg())
            .then(|| {
                // Gravity acts on awake dynamic bodies only (scaled).
                let accel = |body: &Body<S>| {
                    if body.is_simulated_dynamic() {
                        gravity.scale(body.gravity_scale)
                    } else {
                        Vec2::ZERO
                    }
                };
                let (accel_a, accel_b) = (accel(body_a), accel(body_b));
                // May the pair meet within the substep? `−v_n·h ≥ s` along
                // the velocities after gravity, plus the part of the gravity
                // step a contact may hold back (a crate resting on the
                // ground falls `g·h²` less than its velocity says, see
                // `restitution::supported_accelerations`): at most
                // `(|a_a|₁ + |a_b|₁)·h²`. The exact test is the bounce's own
                // (`restitution::bounce_end`), after the solve.
                let held = accel_a
                    .x
                    .abs()
                    .add(accel_a.y.abs())
                    .add(accel_b.x.abs())
                    .add(accel_b.y.abs())
                    .mul(h)
                    .mul(h);
                let meets = vn.neg().mul(h).add(held) >= contact.separation;
                meets.then_some(BounceCandidate {
                    row: 0,
                    approach: vn,
                    accel_a,
                    accel_b,
                    restitution,
                })
            })
            .flatten();
        (constraint, bounce)
    }

    /// The second look at the pairs whose straight sweep was not the whole
    /// story (`collision::deflected_sweep`), once every row that meets is
    /// known: a straight hit `(row, t)` is re-aimed at the impact of the
    /// turned motion when an immovable body turns one of the pair earlier;
    /// a straight miss `(a, b)` whose body is turned into the other gets
    /// its row after all (inserted in pair order; the bounces' row indices
    /// follow). Sleepers such a row reaches go to `to_wake`.
    #[allow(clippy::too_many_arguments)]
    fn turned_rows<'b>(
        &self,
        body: &impl Fn(u32) -> Option<&'b Body<S>>,
        scratch: &mut NarrowScratch<S>,
        rows: &mut Vec<ContactConstraint<S>>,
        bounces: &mut Vec<BounceCandidate<S>>,
        to_wake: &mut Vec<u32>,
    ) where
        S: 'b,
    {
        let (h, slop) = (self.h, self.linear_slop);
        // Only a pair with a body that meets something (an immovable body,
        // for a hit) can be turned; mark those bodies (`WANTED`).
        let NarrowScratch {
            flags,
            missed,
            hits,
            meeting,
            restored,
            moved,
            new_bounces,
            spare_rows,
            ..
        } = scratch;
        let flag = |slot: u32| flags.get(slot as usize).copied().unwrap_or(0);
        hits.retain(|&(index, _)| {
            rows.get(index)
                .is_some_and(|r| (flag(r.a) | flag(r.b)) & MEETS_IMMOVABLE != 0)
        });
        missed.retain(|&(a, b)| (flag(a) | flag(b)) & MEETS != 0);
        if hits.is_empty() && missed.is_empty() {
            return;
        }
        for slot in missed
            .iter()
            .flat_map(|&(a, b)| [a, b])
            .chain(hits.iter().flat_map(|&(i, _)| [rows[i].a, rows[i].b]))
        {
            if let Some(f) = flags.get_mut(slot as usize) {
                *f |= WANTED;
            }
        }
        let wanted = |slot: u32| flags.get(slot as usize).is_some_and(|f| f & WANTED != 0);
        // Who meets whom this substep (for the wanted bodies): the rows
        // that close within it.
        meeting.reset(self.velocities.len());
        for row in rows.iter() {
            let (want_a, want_b) = (wanted(row.a), wanted(row.b));
            if !(want_a || want_b) {
                continue;
            }
            let (Some(&va), Some(&vb)) = (
                self.velocities.get(row.a as usize),
                self.velocities.get(row.b as usize),
            ) else {
                continue;
            };
            let vn = (vb - va).dot(row.normal);
            if vn.is_negative() && vn.neg().mul(h) >= row.separation {
                meeting.link(row, (want_a, want_b));
            }
        }
        let meeting = &meeting;
        let side = |slot: u32| {
            Some(Side {
                slot,
                body: body(slot)?,
                velocity: *self.velocities.get(slot as usize)?,
                inverse_mass: *self.inverse_masses.get(slot as usize)?,
            })
        };
        let row_of = |a: Side<'b, S>, b: Side<'b, S>, contact: Contact<S>, warm| {
            let vn = (b.velocity - a.velocity).dot(contact.normal);
            let effective = effective_mass(a.inverse_mass, b.inverse_mass);
            self.row(
                (a.slot, a.body),
                (b.slot, b.body),
                contact,
                vn,
                warm,
                effective,
            )
        };
        for &(index, t) in hits.iter() {
            let Some(row) = rows.get(index) else { continue };
            let (Some(a), Some(b)) = (side(row.a), side(row.b)) else {
                continue;
            };
            let Some(turned) =
                earlier_turn(a, b, t, meeting, self.inverse_masses, self.velocities, h)
            else {
                continue;
            };
            let row = &rows[index];
            // A row that now touches keeps the warm start it was given.
            let warm = if turned.separation <= slop {
                (row.normal_impulse, row.tangent_impulse)
            } else {
                (S::ZERO, S::ZERO)
            };
            self.replace_row(index, (a, b), turned, warm, rows, bounces);
        }
        restored.clear();
        for &(a, b) in missed.iter() {
            let (Some(side_a), Some(side_b)) = (side(a), side(b)) else {
                continue;
            };
            let Some(turned) = deflected_impact(side_a, side_b, meeting, self.velocities, h) else {
                continue;
            };
            for s in [side_a, side_b] {
                if s.body.kind == BodyKind::Dynamic && !s.body.awake {
                    to_wake.push(s.slot);
                }
            }
            restored.push(row_of(side_a, side_b, turned, (S::ZERO, S::ZERO)));
        }
        if restored.is_empty() || !to_wake.is_empty() {
            return;
        }
        // Merge the restored rows (in pair order) into the rows (in pair
        // order); `moved[i]` is old row `i`'s new index.
        spare_rows.clear();
        core::mem::swap(rows, spare_rows);
        moved.clear();
        new_bounces.clear();
        let mut restored = restored.drain(..).peekable();
        let mut place =
            |rows: &mut Vec<ContactConstraint<S>>,
             (constraint, bounce): (ContactConstraint<S>, Option<BounceCandidate<S>>)| {
                if let Some(mut bounce) = bounce {
                    bounce.row = u32::try_from(rows.len()).unwrap_or(u32::MAX);
                    new_bounces.push(bounce);
                }
                rows.push(constraint);
            };
        for row in spare_rows.drain(..) {
            while let Some(next) = restored.next_if(|(r, _)| (r.a, r.b) < (row.a, row.b)) {
                place(rows, next);
            }
            moved.push(u32::try_from(rows.len()).unwrap_or(u32::MAX));
            rows.push(row);
        }
        for next in restored {
            place(rows, next);
        }
        for bounce in bounces.iter_mut() {
            if let Some(&to) = moved.get(bounce.row as usize) {
                bounce.row = to;
            }
        }
        bounces.append(new_bounces);
        bounces.sort_unstable_by_key(|c| c.row);
    }
}

impl<S: Scalar> NarrowPhase<'_, S> {
    /// Replaces row `index`, of the pair `(a, b)`, by the row of `contact`
    /// warm-started with `warm`, and its bounce (kept sorted by row).
    fn replace_row(
        &self,
        index: usize,
        (a, b): (Side<'_, S>, Side<'_, S>),
        contact: Contact<S>,
        warm: (S, S),
        rows: &mut [ContactConstraint<S>],
        bounces: &mut Vec<BounceCandidate<S>>,
    ) {
        let vn = (b.velocity - a.velocity).dot(contact.normal);
        let effective = effective_mass(a.inverse_mass, b.inverse_mass);
        let (constraint, bounce) = self.row(
            (a.slot, a.body),
            (b.slot, b.body),
            contact,
            vn,
            warm,
            effective,
        );
        rows[index] = constraint;
        let row_id = u32::try_from(index).unwrap_or(u32::MAX);
        let at = bounces.partition_point(|c| c.row < row_id);
        let had = bounces.get(at).is_some_and(|c| c.row == row_id);
        match (bounce, had) {
            (Some(mut bounce), true) => {
                bounce.row = row_id;
                bounces[at] = bounce;
            }
            (Some(mut bounce), false) => {
                bounce.row = row_id;
                bounces.insert(at, bounce);
            }
            (None, true) => {
                bounces.remove(at);
            }
            (None, false) => {}
        }
    }

    /// Rows of a circle at the corner of an immovable box that lies on
    /// (or behind) the face of another immovable box the circle has a face
    /// row with are taken along that face's normal
    /// (`collision::covered_corner`): flush tiles make one flat face.
    fn covered_corners<'b>(
        &self,
        body: &impl Fn(u32) -> Option<&'b Body<S>>,
        scratch: &mut NarrowScratch<S>,
        rows: &mut [ContactConstraint<S>],
        bounces: &mut Vec<BounceCandidate<S>>,
    ) where
        S: 'b,
    {
        let NarrowScratch {
            flags,
            corners,
            faces,
            ..
        } = scratch;
        let immovable = |i: u32| {
            self.inverse_masses
                .get(i as usize)
                .is_some_and(|w| !w.is_positive())
        };
        let is_box = |i: u32| body(i).is_some_and(|b| matches!(b.shape, Shape::Aabb { .. }));
        let is_circle = |i: u32| body(i).is_some_and(|b| matches!(b.shape, Shape::Circle { .. }));
        // The candidates: oblique rows between a circle and an immovable
        // box (the cheap tests first: most oblique rows are between two
        // movable bodies).
        corners.clear();
        for (index, row) in rows.iter().enumerate() {
            if row.normal.x == S::ZERO || row.normal.y == S::ZERO {
                continue;
            }
            let circle = match (immovable(row.a), immovable(row.b)) {
                (false, true) => row.a,
                (true, false) => row.b,
                _ => continue,
            };
            let corner_box = if circle == row.a { row.b } else { row.a };
            if is_circle(circle) && is_box(corner_box) {
                corners.push((circle, corner_box, index));
                if let Some(f) = flags.get_mut(circle as usize) {
                    *f |= COVERED;
                }
            }
        }
        if corners.is_empty() {
            return;
        }
        // The face rows of those circles with immovable boxes: (circle,
        // box, normal from the circle to the box), sorted by circle.
        faces.clear();
        let covered = |i: u32| flags.get(i as usize).is_some_and(|f| f & COVERED != 0);
        for row in rows.iter() {
            if row.normal.x != S::ZERO && row.normal.y != S::ZERO {
                continue;
            }
            let (circle, face_box, normal) = if covered(row.a) && immovable(row.b) {
                (row.a, row.b, row.normal)
            } else if covered(row.b) && immovable(row.a) {
                (row.b, row.a, -row.normal)
            } else {
                continue;
            };
            if is_box(face_box) {
                faces.push((circle, face_box, normal));
            }
        }
        faces.sort_unstable_by_key(|f| (f.0, f.1));
        let aabb = |b: &Body<S>| Aabb::new(b.position, b.shape.half_extents());
        for &(circle, corner_box, index) in corners.iter() {
            let (Some(c), Some(a)) = (body(circle), body(corner_box)) else {
                continue;
            };
            let Shape::Circle { radius } = c.shape else {
                continue;
            };
            let velocity = |i: u32| self.velocities.get(i as usize).copied();
            let first = faces.partition_point(|f| f.0 < circle);
            let covering = faces[first..]
                .iter()
                .take_while(|f| f.0 == circle)
                .filter(|f| f.1 != corner_box && velocity(f.1) == velocity(corner_box))
                .find_map(|&(_, face_box, normal)| {
                    covered_corner(
                        c.position,
                        radius,
                        &aabb(a),
                        &aabb(body(face_box)?),
                        normal,
                        self.linear_slop,
                    )
                });
            let Some(mut contact) = covering else {
                continue;
            };
            let row = &rows[index];
            // The row's normal runs from `row.a` to `row.b`.
            if row.a != circle {
                contact.normal = -contact.normal;
            }
            let side = |slot: u32| {
                Some(Side {
                    slot,
                    body: body(slot)?,
                    velocity: *self.velocities.get(slot as usize)?,
                    inverse_mass: *self.inverse_masses.get(slot as usize)?,
                })
            };
            let (Some(sa), Some(sb)) = (side(row.a), side(row.b)) else {
                continue;
            };
            let warm = (row.normal_impulse, row.tangent_impulse);
            self.replace_row(index, (sa, sb), contact, warm, rows, bounces);
        }
    }

    /// Marks the speculative rows two other rows imply through a movable
    /// body between (`collision::implied_rows`) in the scratch's
    /// `implied.implied`, one entry per row; the grouping reads them.
    fn mark_implied_rows(&self, scratch: &mut NarrowScratch<S>, rows: &[ContactConstraint<S>]) {
        let movable = |i: u32| {
            self.inverse_masses
                .get(i as usize)
                .is_some_and(|w| w.is_positive())
        };
        implied_rows(
            rows,
            self.velocities.len(),
            movable,
            self.linear_slop,
            &mut scratch.implied,
        );
    }

    /// Rows of two movable boxes (or circles) more than the slop deep whose overlap
    /// the immovable bodies' face rows keep from being undone along the
    /// row's normal are taken along the other axis
    /// (`collision::confined_pair`).
    #[inline(never)]
    fn confined_pairs<'b>(
        &self,
        body: &impl Fn(u32) -> Option<&'b Body<S>>,
        scratch: &mut NarrowScratch<S>,
        rows: &mut [ContactConstraint<S>],
        bounces: &mut Vec<BounceCandidate<S>>,
    ) where
        S: 'b,
    {
        let slop = self.linear_slop;
        let movable = |i: u32| {
            self.inverse_masses
                .get(i as usize)
                .is_some_and(|w| w.is_positive())
        };
        let same_kind = |a: u32, b: u32| match (body(a), body(b)) {
            (Some(x), Some(y)) => matches!(
                (x.shape, y.shape),
                (Shape::Aabb { .. }, Shape::Aabb { .. })
                    | (Shape::Circle { .. }, Shape::Circle { .. })
            ),
            _ => false,
        };
        let NarrowScratch {
            flags,
            confined,
            walls,
            ..
        } = scratch;
        // The candidates: rows more than twice the slop deep (resting rows
        // sit about one slop deep, some a few ulps more) along an axis,
        // whose bodies each have an immovable body's face row in front of
        // them (the `WALL_*` bits set in the loop, movable bodies only);
        // the cheap test first: deep rows are common in piles, walls on
        // both sides of them are not.
        let deep = slop.add(slop).neg();
        let has = |slot: u32, n: Vec2<S>| {
            flags
                .get(slot as usize)
                .is_some_and(|f| f & wall_bit(n) != 0)
        };
        confined.clear();
        for (index, row) in rows.iter().enumerate() {
            if row.separation < deep
                && (row.normal.x == S::ZERO || row.normal.y == S::ZERO)
                && has(row.a, -row.normal)
                && has(row.b, row.normal)
                && same_kind(row.a, row.b)
            {
                confined.push(index);
            }
        }
        if confined.is_empty() {
            return;
        }
        let face = |row: &ContactConstraint<S>| {
            if row.normal.x != S::ZERO && row.normal.y != S::ZERO {
                return None;
            }
            match (movable(row.a), movable(row.b)) {
                (true, false) => Some((row.a, row.normal)),
                (false, true) => Some((row.b, -row.normal)),
                _ => None,
            }
        };
        // The face rows with immovable bodies: (movable body, normal from
        // it to the immovable body, gap), sorted by body.
        walls.clear();
        walls.extend(rows.iter().filter_map(|row| {
            let (slot, n) = face(row)?;
            Some((slot, n, row.separation))
        }));
        walls.sort_unstable_by_key(|w| w.0);
        let walls = &*walls;
        let room = |slot: u32, dir: Vec2<S>| {
            let first = walls.partition_point(|w| w.0 < slot);
            walls[first..]
                .iter()
                .take_while(|w| w.0 == slot)
                .filter(|w| w.1 == dir)
                .map(|w| w.2)
                .reduce(|x, y| x.min(y))
        };
        for &index in confined.iter() {
            let row = &rows[index];
            let (Some(ba), Some(bb)) = (body(row.a), body(row.b)) else {
                continue;
            };
            let contact = Contact {
                normal: row.normal,
                separation: row.separation,
            };
            let (a, b) = (row.a, row.b);
            let d = bb.position - ba.position;
            // How far apart across the normal the shapes still overlap.
            let reach = match (ba.shape, bb.shape) {
                (Shape::Circle { radius: ra }, Shape::Circle { radius: rb }) => {
                    let (sum, along) = (ra.add(rb), d.dot(row.normal));
                    // (negative under the root: zero, `sqrt_narrow`'s rule)
                    sum.wide_mul(sum).sub(along.wide_mul(along)).sqrt_narrow()
                }
                _ => {
                    let extents = ba.shape.half_extents() + bb.shape.half_extents();
                    if row.normal.x == S::ZERO {
                        extents.x
                    } else {
                        extents.y
                    }
                }
            };
            let Some(turned) = confined_contact(
                d,
                reach,
                &contact,
                |on_b, dir| room(if on_b { b } else { a }, dir),
                slop,
            ) else {
                continue;
            };
            let side = |slot: u32| {
                Some(Side {
                    slot,
                    body: body(slot)?,
                    velocity: *self.velocities.get(slot as usize)?,
                    inverse_mass: *self.inverse_masses.get(slot as usize)?,
                })
            };
            let (Some(sa), Some(sb)) = (side(a), side(b)) else {
                continue;
            };
            self.replace_row(index, (sa, sb), turned, (S::ZERO, S::ZERO), rows, bounces);
        }
    }
}

impl<S: Scalar> NarrowPhase<'_, S> {
    /// Whether the pair `(a, b)` — one body movable, the other immovable
    /// and at rest, in contact along the axis-aligned `normal` (a to b) —
    /// meets on that face once the movable body's motion is reflected off
    /// its other immovable partners at rest
    /// ([`face_past_walls`]). Only asked when the pair's own time of
    /// impact missed the face (rare: fast motion past a face's end), so
    /// the partners are found by a scan of the pairs.
    fn face_reached_past_walls<'b>(
        &self,
        body: &impl Fn(u32) -> Option<&'b Body<S>>,
        (a, b): (u32, u32),
        normal: Vec2<S>,
    ) -> bool
    where
        S: 'b,
    {
        let immovable = |i: u32| {
            !self.inverse_masses[i as usize].is_positive()
                && self.velocities[i as usize] == Vec2::ZERO
        };
        let (moving, target, n) = match (immovable(a), immovable(b)) {
            (false, true) => (a, b, normal),
            (true, false) => (b, a, -normal),
            _ => return false,
        };
        if normal.x != S::ZERO && normal.y != S::ZERO {
            return false;
        }
        let (Some(mover), Some(face)) = (body(moving), body(target)) else {
            return false;
        };
        let walls = self.pairs.iter().filter_map(|&(p, q)| {
            let other = match (p == moving, q == moving) {
                (true, _) => q,
                (_, true) => p,
                _ => return None,
            };
            if other == target || !immovable(other) {
                return None;
            }
            body(other).map(|w| (&w.shape, w.position, w.restitution))
        });
        face_past_walls(
            &mover.shape,
            mover.position,
            self.velocities[moving as usize].scale(self.h),
            mover.restitution,
            (&face.shape, face.position),
            n,
            walls,
        )
    }
}

#[cfg(test)]
#[allow(clippy::float_arithmetic)] // test inputs are built in f64
mod tests {
    use super::*;
    use crate::math::Fx;
    use fixed::types::I48F16;
    use proptest::prelude::*;

    /// The step's exact keep test (see `World::build_constraints`): keep the
    /// pair when `s ≤ margin + max(0, −v_n)·h`.
    fn exact_keeps<S: Scalar>(
        ra: S,
        rb: S,
        pa: Vec2<S>,
        pb: Vec2<S>,
        dv: Vec2<S>,
        margin: S,
        h: S,
    ) -> bool {
        let contact = contact_between(
            &Shape::Circle { radius: ra },
            pa,
            &Shape::Circle { radius: rb },
            pb,
        );
        let vn = dv.dot(contact.normal);
        let reach = margin.add(vn.neg().max(S::ZERO).mul(h));
        contact.separation <= reach
    }

    fn check<S: Scalar>(values: [f64; 9]) {
        let [ra, rb, ax, ay, bx, by, vx, vy, hh] = values.map(S::from_f64);
        let margin = S::from_f64(0.1);
        let h = hh.abs();
        let (pa, pb, dv) = (Vec2::new(ax, ay), Vec2::new(bx, by), Vec2::new(vx, vy));
        if circles_out_of_reach(ra.add(rb), pb - pa, dv, margin, h) {
            assert!(
                !exact_keeps(ra, rb, pa, pb, dv, margin, h),
                "{}: rejected a pair the exact test keeps: {values:?}",
                S::NAME
            );
        }
    }

    fn inputs() -> impl Strategy<Value = [f64; 9]> {
        // Radii from tiny to large, positions within the world bounds (often
        // near contact: the reject's edge), velocities up to the default
        // speed limit, substeps from 1/64 to one second.
        let radius = prop_oneof![0.0001f64..0.01, 0.01f64..2.0, 2.0f64..500.0];
        let coordinate = prop_oneof![-4.0f64..4.0, -32_000.0f64..32_000.0];
        let speed = prop_oneof![-10.0f64..10.0, -4096.0f64..4096.0];
        let h = prop_oneof![Just(1.0 / 60.0), 1.0f64 / 64.0..1.0];
        (
            radius.clone(),
            radius,
            coordinate.clone(),
            coordinate.clone(),
            -3.0f64..3.0,
            -3.0f64..3.0,
            speed.clone(),
            speed,
            h,
        )
            .prop_map(|(ra, rb, ax, ay, dx, dy, vx, vy, h)| {
                [ra, rb, ax, ay, ax + dx, ay + dy, vx, vy, h]
            })
    }

    /// Pairs on the edge of the keep test: closing along the centre line at
    /// speed `v`, centres `r_a + r_b + margin + v·h + δ` apart with δ a few
    /// hundred ulps either way, along axis and diagonal directions — where
    /// the reject's bound `L₁ ≥ |v_n|` is tight (axes) or loose (diagonals).
    fn edge_inputs() -> impl Strategy<Value = [f64; 9]> {
        let direction = prop_oneof![
            Just((1.0f64, 0.0f64)),
            Just((0.0, 1.0)),
            Just((0.6, 0.8)),
            Just((0.8, -0.6)),
            Just((
                std::f64::consts::FRAC_1_SQRT_2,
                std::f64::consts::FRAC_1_SQRT_2
            )),
            Just((-5.0 / 13.0, 12.0 / 13.0)),
        ];
        (
            0.01f64..2.0,
            0.01f64..2.0,
            -1000.0f64..1000.0,
            -1000.0f64..1000.0,
            direction,
            0.0f64..200.0,
            -300i32..300,
            prop_oneof![Just(1.0 / 60.0), 1.0f64 / 64.0..0.5],
        )
            .prop_map(|(ra, rb, ax, ay, (ux, uy), v, ulps, h)| {
                let gap = ra + rb + 0.1 + v * h + f64::from(ulps) * 2f64.powi(-32);
                [
                    ra,
                    rb,
                    ax,
                    ay,
                    ax + ux * gap,
                    ay + uy * gap,
                    -ux * v,
                    -uy * v,
                    h,
                ]
            })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(4096))]

        /// The same on the edge of the keep test.
        #[test]
        fn reject_never_drops_a_kept_pair_on_the_edge(values in edge_inputs()) {
            check::<Fx>(values);
            check::<I48F16>(values);
            check::<f64>(values);
            check::<f32>(values);
        }

        /// The square-root-free reject only drops pairs the exact test
        /// drops (so the step's result is the same with or without it).
        #[test]
        fn reject_never_drops_a_kept_pair(values in inputs()) {
            check::<Fx>(values);
            check::<I48F16>(values);
            check::<f64>(values);
            check::<f32>(values);
        }
    }

    #[test]
    fn reject_drops_far_pairs_and_keeps_touching_ones() {
        let (radii, margin, h) = (Fx::ONE, Fx::from_f64(0.1), Fx::from_f64(1.0 / 60.0));
        let far = Vec2::new(Fx::from_int(2), Fx::ZERO);
        let touching = Vec2::new(Fx::ONE, Fx::ZERO);
        assert!(circles_out_of_reach(radii, far, Vec2::ZERO, margin, h,));
        assert!(!circles_out_of_reach(
            radii,
            touching,
            Vec2::ZERO,
            margin,
            h,
        ));
        // Closing fast enough to cover the gap within the substep: kept.
        let closing = Vec2::new(Fx::from_int(-60), Fx::ZERO);
        assert!(!circles_out_of_reach(radii, far, closing, margin, h));
    }
}
