//! The constraint phases of a substep: springs (forces → velocities) and
//! rope rows (solved with the contacts). Maths in [`crate::constraints`].
//!
//! Point anchors use a virtual "ground" slot at index `n` (one past the last
//! body) with zero velocity and zero inverse mass, so rope rows share the
//! contact solver's indexing without special cases.

use crate::constraints::spring_solve::{RadialRow, SpringScratch, solve_spring_rows};
use crate::constraints::spring_support::{SupportBounce, SupportRow, SupportScratch};
use crate::constraints::{Anchor, Constraint, constraint_body_pairs};
use crate::math::{Scalar, Vec2};
use crate::solver::restitution::bounce_end;
use crate::solver::row::{ContactConstraint, effective_mass};
use crate::world::World;

/// Where an anchor is this substep, how it moves, and which solver slot
/// carries its velocity.
#[derive(Clone, Copy)]
pub(super) struct AnchorState<S: Scalar> {
    pub(super) position: Vec2<S>,
    pub(super) velocity: Vec2<S>,
    pub(super) inverse_mass: S,
    pub(super) slot: u32,
}

impl<S: Scalar> World<S> {
    /// Index of the virtual ground slot used by point anchors.
    pub(crate) fn ground_slot(&self) -> u32 {
        u32::try_from(self.slots.len()).unwrap_or(u32::MAX)
    }

    pub(super) fn anchor_state(&self, anchor: &Anchor<S>) -> Option<AnchorState<S>> {
        match *anchor {
            Anchor::Point(p) => Some(AnchorState {
                position: p,
                velocity: Vec2::ZERO,
                inverse_mass: S::ZERO,
                slot: self.ground_slot(),
            }),
            Anchor::Body(id) | Anchor::BodyOffset(id, _) => {
                let index = self.live_index(id).ok()?;
                let body = self.slots[index].body.as_ref()?;
                Some(AnchorState {
                    position: body.position + anchor.local_point(),
                    velocity: *self.step_context.velocities.get(index)?,
                    inverse_mass: *self.step_context.inverse_masses.get(index)?,
                    slot: id.index(),
                })
            }
        }
    }

    /// Wakes a sleeping body joined by a constraint to an awake one, so a
    /// constraint never pulls against a frozen sleeper.
    pub(crate) fn wake_across_constraints(&mut self) {
        let mut to_wake = Vec::new();
        for (ia, ib) in constraint_body_pairs(&self.constraint_slots) {
            let (Some(ba), Some(bb)) = (self.body(ia), self.body(ib)) else {
                continue;
            };
            if ba.is_moving() && !bb.awake {
                to_wake.push(ib.index());
            }
            if bb.is_moving() && !ba.awake {
                to_wake.push(ia.index());
            }
        }
        for index in to_wake {
            self.wake_index(index);
        }
    }

    /// Springs: every spring row of the substep solved together by the
    /// θ-method (see [`crate::constraints`], "Why springs are solved
    /// together"): rows built here, θ per row and per slot, Gauss–Seidel
    /// sweeps in `constraints::spring_solve`, and the `(1 − θ_b)·Δv` share
    /// the positions do not follow recorded in `spring_dv`.
    pub(crate) fn apply_springs(&mut self, h: S) {
        let n = self.slots.len();
        let mut scratch = core::mem::take(&mut self.step_context.springs);
        scratch.begin(n + 1);
        let mut any = false;
        for ci in 0..self.constraint_slots.len() {
            let Some(constraint) = self.constraint_slots[ci]
                .entry
                .as_ref()
                .map(|e| e.constraint)
            else {
                continue;
            };
            let (a, b) = constraint.anchors();
            let (Some(sa), Some(sb)) = (self.anchor_state(&a), self.anchor_state(&b)) else {
                continue;
            };
            let w = sa.inverse_mass.add(sb.inverse_mass);
            if !w.is_positive() {
                continue;
            }
            any = true;
            let ends = ((sa.slot, sb.slot), (sa.inverse_mass, sb.inverse_mass));
            match constraint {
                Constraint::BendySpring {
                    rest_offset,
                    stiffness,
                    damping,
                    ..
                } => {
                    let stretch = sb.position - sa.position - rest_offset;
                    scratch.push_row(ends, false, stretch, (stiffness, damping), h);
                }
                Constraint::RadialSpring {
                    rest_length,
                    stiffness,
                    damping,
                    ..
                } => {
                    let offset = sb.position - sa.position;
                    let length = offset.length();
                    let stretch = length.sub(rest_length);
                    // The direction is found in the sweeps (the midpoint
                    // discrete gradient, `constraints`, "Radial springs").
                    let theta = scratch.push_row(
                        ends,
                        true,
                        Vec2::new(stretch, S::ZERO),
                        (Vec2::new(stiffness, stiffness), damping),
                        h,
                    );
                    scratch.radial.push(RadialRow {
                        offset,
                        length,
                        gain_per_length: theta.mul(h).mul(stiffness).add(damping),
                        applied: Vec2::ZERO,
                    });
                }
                Constraint::Rope { .. } => continue,
            }
        }
        if any {
            self.gather_supports(&mut scratch, h);
        }
        // The gravity kick inside each slot's velocity, for the direct
        // solve's energy check (radial groups only).
        let kicks = &mut scratch.direct.kicks;
        kicks.clear();
        if !scratch.radial.is_empty() {
            let gravity_step = self.settings.gravity.scale(h);
            kicks.resize(n + 1, Vec2::ZERO);
            for (kick, slot) in kicks.iter_mut().zip(&self.slots) {
                if let Some(body) = &slot.body
                    && body.is_simulated_dynamic()
                {
                    *kick = gravity_step.scale(body.gravity_scale);
                }
            }
        }
        let context = &mut self.step_context;
        context.spring_dv.clear();
        context.spring_dv.resize(n + 1, Vec2::ZERO);
        if !any {
            scratch.supports.rows.clear();
            self.step_context.springs = scratch;
            return;
        }
        // A body in contact follows the contact solver's position rule:
        // θ_b = 1 (see `constraints`, "Springs and contacts"). Only pairs
        // touching now: a pair merely within the speculative margin
        // (neighbours of a folding lattice) mostly takes no impulse, and
        // θ_b = 1 would damp its springs by ½·m·|Δv|² per step for
        // nothing.
        let contacted = &mut scratch.supports.contacted;
        contacted.clear();
        contacted.resize(n + 1, false);
        for contact in scratch.supports.rows.iter().filter(|c| c.touching) {
            for slot in [contact.a, contact.b] {
                if let Some(theta) = scratch.body_theta.get_mut(slot as usize) {
                    *theta = S::ONE;
                    contacted[slot as usize] = true;
                }
            }
        }
        scratch.finish_rows();
        scratch.position_velocities.clear();
        scratch
            .position_velocities
            .extend_from_slice(&context.velocities);
        solve_spring_rows(
            &mut scratch.rows,
            &mut scratch.radial,
            &mut scratch.supports,
            &mut scratch.direct,
            (&context.velocities, &mut scratch.position_velocities),
            h,
        );
        // A spring-moved body with θ_b < 1 that a contact pushes this
        // substep, though not touching yet (a speculative row: a folding
        // chain's links closing on each other, a body flung at a wall),
        // would carry the lag of `constraints`, "Springs and contacts"
        // (1.), whose cross term has either sign (20 links with a 100× end
        // at ω·h = 1: +1.7 J; a pair at ω·h = 1 driven at a wall 0.6 away:
        // +0.19 J of 5): the sweeps' support rows, and the velocities the
        // bodies end with, tell which contacts act; their spring-moved
        // ends take θ_b = 1. The bounces that meet are launched (4.), and
        // the springs are solved again.
        let raised = scratch.raise_bound_ends(&context.velocities);
        if scratch.launch_bounces() | raised {
            scratch.finish_rows();
            scratch.position_velocities.clear();
            scratch
                .position_velocities
                .extend_from_slice(&context.velocities);
            scratch.supports.clear_impulses();
            for geometry in scratch.radial.iter_mut() {
                geometry.applied = Vec2::ZERO;
            }
            solve_spring_rows(
                &mut scratch.rows,
                &mut scratch.radial,
                &mut scratch.supports,
                &mut scratch.direct,
                (&context.velocities, &mut scratch.position_velocities),
                h,
            );
        }
        // A held row's push on a body no spring moves is a contact impulse,
        // which moves the position by all of it (θ = 1): with the blend ½
        // of a free body, v = v₀ + (p − v₀)/θ_b would double it.
        scratch.hold_unsprung_ends();
        // Velocities: v = v₀ + Δv with θ_b·Δv = p − v₀ (θ_b ∈ [½, 1], so
        // the division is defined); positions follow p, so v − p is the
        // share (1 − θ_b)·Δv they do not see.
        // Bodies mostly share a few blends: the last inverse is reused.
        let mut last_inverse = (S::ONE.half(), S::from_int(2));
        for (i, &p) in scratch.position_velocities.iter().enumerate() {
            let v0 = context.velocities[i];
            if p == v0 {
                continue;
            }
            let theta = scratch.body_theta[i];
            if theta != last_inverse.0 {
                last_inverse = (theta, S::ONE.div(theta));
            }
            let inverse_theta = last_inverse.1;
            let v = v0 + (p - v0).scale(inverse_theta);
            context.velocities[i] = v;
            context.spring_dv[i] = v - p;
        }
        // A launched bounce is final like a held row (below), and the
        // bounce after the position update leaves it.
        let mut any_launched = false;
        for row in scratch.supports.rows.iter_mut().filter(|row| row.launched) {
            row.held = true;
            any_launched = true;
        }
        if any_launched {
            let rows = &scratch.supports.rows;
            context.bounce_candidates.retain(|candidate| {
                rows.binary_search_by_key(&candidate.row, |row| row.contact)
                    .map_or(true, |i| !rows[i].launched)
            });
        }
        // The contacts solved with a stiff group (held rows) are final:
        // their impulses are in the velocities (the support rows' pushes
        // kept), and the contact solve, which would answer with the mass of
        // the struck body alone, leaves them: each such row asks no more
        // than the relative normal velocity it has now, and starts from
        // no impulse (its impulses are added back after the velocity
        // solve, for the contact cache, the bounces and the events).
        for row in scratch.supports.rows.iter().filter(|row| row.held) {
            let Some(c) = context.constraints.get_mut(row.contact as usize) else {
                continue;
            };
            let (va, vb) = (
                context.velocities[c.a as usize],
                context.velocities[c.b as usize],
            );
            c.target_velocity = c.target_velocity.min((vb - va).dot(c.normal));
            c.normal_impulse = S::ZERO;
            c.tangent_impulse = S::ZERO;
        }
        context.springs = scratch;
    }

    /// Adds the held contact rows' impulses (solved with their stiff group
    /// in [`World::apply_springs`]) to what the contact solve gave them.
    pub(crate) fn add_held_contact_impulses(&mut self) {
        let context = &mut self.step_context;
        for row in context.springs.supports.rows.iter().filter(|row| row.held) {
            if let Some(c) = context.constraints.get_mut(row.contact as usize) {
                c.normal_impulse = c.normal_impulse.add(row.impulse);
                c.tangent_impulse = c.tangent_impulse.add(row.tangent);
            }
        }
    }

    /// The substep's contact rows that reach a spring-moved body through
    /// contacts (breadth first over dynamic bodies; an immovable body ends
    /// a path), as support rows of the spring sweeps (`spring_support.rs`),
    /// each bounce candidate among them with its bounce (`constraints`,
    /// "Springs and contacts", 4.).
    fn gather_supports(&self, scratch: &mut SpringScratch<S>, h: S) {
        let context = &self.step_context;
        let supports = &mut scratch.supports;
        let slots = context.velocities.len();
        supports.rows.clear();
        supports.pushed.clear();
        supports.pushed.resize(slots, Vec2::ZERO);
        supports.kept.clear();
        supports.kept.resize(slots, Vec2::ZERO);
        supports.reached.clear();
        supports.reached.resize(slots, false);
        let contacts = &context.constraints;
        let slop = self.settings.linear_slop;
        if contacts.is_empty() {
            return;
        }
        let moving = |slot: u32| {
            context
                .inverse_masses
                .get(slot as usize)
                .is_some_and(|w| w.is_positive())
        };
        let SupportScratch {
            ref mut rows,
            ref mut reached,
            ref mut start,
            ref mut fill,
            ref mut incident,
            ref mut taken,
            ref mut frontier,
            ..
        } = *supports;
        frontier.clear();
        for row in &scratch.rows {
            for (slot, w) in [(row.a, row.inverse_masses.0), (row.b, row.inverse_masses.1)] {
                if w.is_positive() && !reached[slot as usize] {
                    reached[slot as usize] = true;
                    frontier.push(slot);
                }
            }
        }
        // Each slot's contact rows (compressed sparse rows): counts, then
        // offsets, then the row indices.
        start.clear();
        start.resize(slots + 1, 0);
        for c in contacts {
            start[c.a as usize + 1] += 1;
            start[c.b as usize + 1] += 1;
        }
        for i in 0..slots {
            start[i + 1] += start[i];
        }
        fill.clear();
        fill.extend_from_slice(start.as_slice());
        incident.clear();
        incident.resize(start[slots] as usize, 0);
        for (index, c) in contacts.iter().enumerate() {
            for slot in [c.a, c.b] {
                incident[fill[slot as usize] as usize] = index as u32;
                fill[slot as usize] += 1;
            }
        }
        taken.clear();
        taken.resize(contacts.len(), false);
        while let Some(slot) = frontier.pop() {
            let range = start[slot as usize] as usize..start[slot as usize + 1] as usize;
            for &index in &incident[range] {
                if core::mem::replace(&mut taken[index as usize], true) {
                    continue;
                }
                let c = &contacts[index as usize];
                let other = if c.a == slot { c.b } else { c.a };
                if moving(other) && !reached[other as usize] {
                    reached[other as usize] = true;
                    frontier.push(other);
                }
            }
        }
        // In contact-row order (deterministic, whatever the search order).
        for (index, (c, _)) in contacts
            .iter()
            .zip(taken.iter())
            .enumerate()
            .filter(|(_, (_, t))| **t)
        {
            rows.push(SupportRow {
                a: c.a,
                b: c.b,
                normal: c.normal,
                target: c.target_velocity,
                effective_mass: c.effective_mass,
                push: (c.push_a, c.push_b),
                impulse: S::ZERO,
                held: false,
                friction: c.friction,
                touching: c.separation <= slop,
                contact: index as u32,
                tangent: S::ZERO,
                bounce: None,
                launched: false,
            });
        }
        // The bounce candidates among them (both lists are in contact-row
        // order): the end velocity of the re-timed bounce
        // (`solver::restitution`) and the impulse of the impact itself.
        for candidate in &context.bounce_candidates {
            let Ok(i) = rows.binary_search_by_key(&candidate.row, |row| row.contact) else {
                continue;
            };
            let c = &contacts[candidate.row as usize];
            let accel_n = (candidate.accel_b - candidate.accel_a).dot(c.normal);
            let approach = candidate.approach;
            let Some(end) = bounce_end(c.separation, approach, accel_n, candidate.restitution, h)
            else {
                continue;
            };
            rows[i].bounce = Some(SupportBounce {
                velocity: end.velocity,
                cap: S::ONE
                    .add(candidate.restitution)
                    .mul(approach.neg())
                    .mul(c.effective_mass),
                meets: c.separation.max(S::ZERO).div(approach.neg()),
                floor: rows[i].target,
            });
        }
    }

    /// Rope rows for this substep: a rope is active when it is taut or can
    /// become taut within the substep (plus the speculative margin).
    pub(crate) fn build_rope_rows(&mut self, h: S, inverse_h: S) {
        self.step_context.rope_rows.clear();
        self.step_context.rope_slots.clear();
        self.step_context.rope_geometry.clear();
        let margin = self.settings.speculative_margin;
        let threshold = self.settings.restitution_threshold;
        for ci in 0..self.constraint_slots.len() {
            let Some(entry) = self.constraint_slots[ci].entry.as_ref() else {
                continue;
            };
            let Constraint::Rope {
                a,
                b,
                max_length,
                restitution,
            } = entry.constraint
            else {
                continue;
            };
            let warm = entry.impulse;
            let (Some(sa), Some(sb)) = (self.anchor_state(&a), self.anchor_state(&b)) else {
                continue;
            };
            let w = sa.inverse_mass.add(sb.inverse_mass);
            if !w.is_positive() {
                continue;
            }
            let (direction, length) = (sb.position - sa.position)
                .try_normalize_with_length()
                .unwrap_or((Vec2::Y, S::ZERO));
            // The row's "normal" points from b back to a, so that the
            // contact rule v ≥ -s/h with s = slack reads v_n ≤ s/h.
            let normal = -direction;
            let slack = max_length.sub(length);
            let vn = (sb.velocity - sa.velocity).dot(normal);
            let reach = margin.add(vn.neg().max(S::ZERO).mul(h));
            if slack > reach {
                continue;
            }
            let mut row = ContactConstraint::new(
                sa.slot,
                sb.slot,
                normal,
                slack,
                (sa.inverse_mass, sb.inverse_mass),
                effective_mass(sa.inverse_mass, sb.inverse_mass),
                S::ZERO,
                (warm, S::ZERO),
            );
            row.prepare_target(vn, restitution, threshold, h, inverse_h);
            self.step_context.rope_rows.push(row);
            self.step_context
                .rope_slots
                .push(u32::try_from(ci).unwrap_or(u32::MAX));
            self.step_context
                .rope_geometry
                .push((sb.position - sa.position, max_length));
        }
    }

    /// Stores the ropes' accumulated impulses for warm starting (zero for
    /// ropes that were slack this substep).
    pub(crate) fn store_rope_impulses(&mut self) {
        for slot in &mut self.constraint_slots {
            if let Some(entry) = slot.entry.as_mut() {
                entry.impulse = S::ZERO;
            }
        }
        for (row, &ci) in self
            .step_context
            .rope_rows
            .iter()
            .zip(&self.step_context.rope_slots)
        {
            if let Some(entry) = self
                .constraint_slots
                .get_mut(ci as usize)
                .and_then(|s| s.entry.as_mut())
            {
                entry.impulse = row.normal_impulse;
            }
        }
    }
}

/// Re-linearises every rope row about the current displacements, so that
/// the position iterations see the rope's true length.
///
/// The rows are built with the direction at the start of the substep, and
/// the linear estimate `s + (Δb − Δa)·n` misses the second-order stretch
/// `(v_t·h)²/(2ℓ)` of fast sideways motion (a whipping chain end). Here the
/// current offset `d = d0 + Δb − Δa` gives the exact slack `L − |d|` and
/// direction, and the row's separation is re-based so that its linear
/// estimate is exact at the current displacements: a non-linear
/// Gauss–Seidel on positions.
pub(crate) fn relinearise_rope_rows<S: Scalar>(
    rows: &mut [ContactConstraint<S>],
    geometry: &[(Vec2<S>, S)],
    displacements: &[Vec2<S>],
) {
    for (row, &(start_offset, max_length)) in rows.iter_mut().zip(geometry) {
        let moved = displacements[row.b as usize] - displacements[row.a as usize];
        let Some((direction, length)) = (start_offset + moved).try_normalize_with_length() else {
            continue;
        };
        row.normal = -direction;
        // The tree solve applies impulses through the push vectors.
        row.push_a = row.normal.scale(row.inverse_mass_a);
        row.push_b = row.normal.scale(row.inverse_mass_b);
        row.separation = max_length.sub(length).sub(moved.dot(row.normal));
    }
}
