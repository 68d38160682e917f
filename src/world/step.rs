//! The step pipeline (DESIGN.md, "Pipeline of one step").
//!
//! Per tick: commands → per substep [gravity → broad phase → narrow phase
//! (waking what an awake body touches) → warm start → velocity iterations →
//! bullets' time of impact → integrate → position iterations → bounds] →
//! sleep → events.

use super::WorldSettings;
use super::step_constraints::relinearise_rope_rows;
use super::{Command, CommandOutcome, Event, World, WorldError};
use crate::collision::{CachedContact, NarrowPhase, Proxy, ProxyClass, shape_toi};
use crate::dynamics::{BodyId, BodyKind, islands};
use crate::geometry::Toi;
use crate::math::{Scalar, Vec2};
use crate::solver::StepContext;
use crate::solver::block_solve::BlockScratch;
use crate::solver::block_solve::{solve_group_positions, solve_group_velocities};
use crate::solver::row::{ContactConstraint, warm_start};
use crate::solver::row::{solve_friction_row, solve_position_row, solve_velocity_row};
use crate::solver::row_groups::RowGroups;

impl<S: Scalar> World<S> {
    /// Advances the world by one tick (`settings.dt` seconds).
    pub fn step(&mut self) {
        self.step_with(&[]);
    }

    /// Applies `commands` in order, then advances one tick. Returns one
    /// result per command; a refused command leaves the world unchanged and
    /// does not stop the others.
    pub fn step_with(
        &mut self,
        commands: &[Command<S>],
    ) -> Vec<Result<CommandOutcome, WorldError>> {
        self.events.clear();
        let results = commands.iter().map(|c| self.apply(c.clone())).collect();
        self.wake_across_constraints();
        let mut previous_touching = core::mem::take(&mut self.scratch.touching_before);
        previous_touching.clear();
        previous_touching.extend(
            self.contacts
                .iter()
                .filter(|c| c.touching)
                .map(|c| (c.a, c.b)),
        );
        let substeps = S::from_int(i32::try_from(self.settings.substeps).unwrap_or(1));
        // dt ∈ (0, 1] and substeps ∈ [1, 64] (validated), so both are exact
        // divisions by non-zero values.
        let h = self.settings.dt.div(substeps);
        let inverse_h = substeps.div(self.settings.dt);
        for _ in 0..self.settings.substeps {
            self.substep(h, inverse_h);
        }
        self.update_sleep();
        self.push_contact_events(&previous_touching);
        self.scratch.touching_before = previous_touching;
        self.events.sort_unstable();
        self.events.dedup();
        self.tick = self.tick.wrapping_add(1);
        results
    }

    fn substep(&mut self, h: S, inverse_h: S) {
        // Narrow phase may wake sleeping islands; their own contacts were not
        // paired (both asleep at broad-phase time), so the phase is redone.
        // Each pass wakes at least one island, so this ends.
        loop {
            self.load_scratch(h);
            self.apply_springs(h);
            self.build_proxies(h);
            let scratch = &mut self.scratch;
            scratch
                .broad_phase
                .find_pairs(&scratch.proxies, &mut scratch.pairs);
            let to_wake = self.build_constraints(h, inverse_h);
            if to_wake.is_empty() {
                break;
            }
            for index in to_wake {
                self.wake_index(index);
            }
        }
        self.build_rope_rows(h, inverse_h);
        let scratch = &mut self.scratch;
        let slot_count = scratch.velocities.len();
        scratch
            .rope_groups
            .regroup(&scratch.rope_rows, slot_count, &mut scratch.parents);
        scratch
            .contact_groups
            .regroup(&scratch.constraints, slot_count, &mut scratch.parents);
        scratch.rope_groups.classify(&scratch.rope_rows, true);
        scratch.contact_groups.classify(&scratch.constraints, false);
        warm_start(&scratch.rope_rows, &mut scratch.velocities);
        warm_start(&scratch.constraints, &mut scratch.velocities);
        for _ in 0..self.settings.velocity_iterations {
            let StepContext {
                rope_rows,
                rope_groups,
                constraints,
                contact_groups,
                velocities,
                rope_block,
                ..
            } = scratch;
            solve_group_list_velocities(rope_rows, rope_groups, velocities, rope_block);
            solve_group_list_velocities(constraints, contact_groups, velocities, rope_block);
        }
        self.integrate(h);
        let settings = &self.settings;
        let scratch = &mut self.scratch;
        for _ in 0..settings.position_iterations {
            let StepContext {
                rope_rows,
                rope_groups,
                rope_geometry,
                constraints,
                contact_groups,
                displacements,
                rope_block,
                ..
            } = scratch;
            relinearise_rope_rows(rope_rows, rope_geometry, displacements);
            solve_group_list_positions(rope_rows, rope_groups, displacements, settings, rope_block);
            solve_group_list_positions(
                constraints,
                contact_groups,
                displacements,
                settings,
                rope_block,
            );
        }
        self.write_back();
        self.update_contact_cache();
        self.store_rope_impulses();
    }

    /// Velocities (with gravity) and solver inverse masses for every slot.
    fn load_scratch(&mut self, h: S) {
        // One extra slot at the end: the virtual ground of point anchors.
        let n = self.slots.len() + 1;
        let scratch = &mut self.scratch;
        scratch.velocities.clear();
        scratch.velocities.resize(n, Vec2::ZERO);
        scratch.inverse_masses.clear();
        scratch.inverse_masses.resize(n, S::ZERO);
        scratch.displacements.clear();
        scratch.displacements.resize(n, Vec2::ZERO);
        let gravity_step = self.settings.gravity.scale(h);
        let max = self.settings.max_speed;
        let limit = Vec2::new(max, max);
        for (i, slot) in self.slots.iter().enumerate() {
            let Some(body) = &slot.body else { continue };
            if body.is_simulated_dynamic() {
                let v = body.velocity + gravity_step.scale(body.gravity_scale);
                scratch.velocities[i] = v.clamp(-limit, limit);
                scratch.inverse_masses[i] = body.inverse_mass;
            } else if body.is_moving() {
                scratch.velocities[i] = body.velocity;
            }
        }
    }

    /// Swept bounding boxes: the box now ∪ the box after moving `v·h`,
    /// grown by the speculative margin for bodies that move.
    fn build_proxies(&mut self, h: S) {
        let margin = self.settings.speculative_margin;
        let scratch = &mut self.scratch;
        scratch.proxies.clear();
        for (i, slot) in self.slots.iter().enumerate() {
            let Some(body) = &slot.body else { continue };
            if body.frozen {
                continue;
            }
            let velocity = scratch.velocities[i];
            let class = match body.kind {
                BodyKind::Dynamic if body.awake => ProxyClass::Dynamic,
                BodyKind::Dynamic => ProxyClass::Sleeping,
                BodyKind::Kinematic if velocity != Vec2::ZERO => ProxyClass::MovingKinematic,
                _ => ProxyClass::Still,
            };
            let now = body.aabb();
            let swept = if matches!(class, ProxyClass::Dynamic | ProxyClass::MovingKinematic) {
                let later = body
                    .shape
                    .bounding_aabb_at(body.position + velocity.scale(h));
                now.union(&later).expanded(margin)
            } else {
                now
            };
            let (lo, hi) = (swept.min(), swept.max());
            scratch.proxies.push(Proxy {
                min_x: lo.x,
                max_x: hi.x,
                min_y: lo.y,
                max_y: hi.y,
                index: u32::try_from(i).unwrap_or(u32::MAX),
                class: Some(class),
            });
        }
    }

    /// The narrow phase ([`NarrowPhase`]) into `scratch.constraints`;
    /// returns the sleeping bodies to wake (then the caller redoes it).
    fn build_constraints(&mut self, h: S, inverse_h: S) -> Vec<u32> {
        let settings = &self.settings;
        let StepContext {
            pairs,
            velocities,
            inverse_masses,
            constraints,
            ..
        } = &mut self.scratch;
        let narrow_phase = NarrowPhase {
            pairs,
            velocities,
            inverse_masses,
            cache: &self.contacts,
            speculative_margin: settings.speculative_margin,
            linear_slop: settings.linear_slop,
            restitution_threshold: settings.restitution_threshold,
            h,
            inverse_h,
        };
        let slots = &self.slots;
        narrow_phase.contact_rows(|i| slots[i as usize].body.as_ref(), constraints)
    }

    /// Displacements `v·h`; a bullet's is cut at its earliest time of impact
    /// against anything it was paired with, so it cannot pass through.
    fn integrate(&mut self, h: S) {
        let scratch = &mut self.scratch;
        let mut any_bullet = false;
        for (i, slot) in self.slots.iter().enumerate() {
            let Some(body) = &slot.body else { continue };
            if body.is_moving() {
                // x' = x + h·v' − h·(1−θ)·Δv_spring: springs get the θ-method
                // position rule (see crate::constraints).
                let lagging = scratch.spring_dv[i].scale(h);
                scratch.displacements[i] = scratch.velocities[i].scale(h) - lagging;
                any_bullet |= body.bullet && body.is_simulated_dynamic();
            }
        }
        // Most worlds have no bullet: skip the pass over every pair.
        if !any_bullet {
            return;
        }
        for &(a, b) in &scratch.pairs {
            for (bullet, other) in [(a, b), (b, a)] {
                let (Some(bb), Some(ob)) = (
                    self.slots[bullet as usize].body.as_ref(),
                    self.slots[other as usize].body.as_ref(),
                ) else {
                    continue;
                };
                if !bb.bullet || !bb.is_simulated_dynamic() {
                    continue;
                }
                let full = scratch.velocities[bullet as usize].scale(h);
                let other_motion = scratch.displacements[other as usize];
                if let Toi::Hit { t, .. } = shape_toi(
                    &bb.shape,
                    bb.position,
                    full,
                    &ob.shape,
                    ob.position,
                    other_motion,
                ) {
                    let cut = full.scale(t);
                    // Keep the shortest cut over all partners.
                    let current = scratch.displacements[bullet as usize];
                    if cut.length_squared_wide() < current.length_squared_wide() {
                        scratch.displacements[bullet as usize] = cut;
                    }
                }
            }
        }
    }

    /// Positions and velocities back into the bodies; bodies whose centre
    /// left the bounds are frozen.
    fn write_back(&mut self) {
        let bounds = self.settings.bounds;
        let (lo, hi) = (bounds.min(), bounds.max());
        for (i, slot) in self.slots.iter_mut().enumerate() {
            let Some(body) = slot.body.as_mut() else {
                continue;
            };
            if !body.is_moving() {
                continue;
            }
            body.position += self.scratch.displacements[i];
            if body.kind == BodyKind::Dynamic {
                body.velocity = self.scratch.velocities[i];
            }
            if !bounds.contains_point(body.position) {
                body.position = body.position.clamp(lo, hi);
                body.velocity = Vec2::ZERO;
                body.frozen = true;
                let id = BodyId::from_parts(u32::try_from(i).unwrap_or(u32::MAX), slot.generation);
                self.events.push(Event::Frozen(id));
            }
        }
    }

    /// The new cache: this substep's contacts, plus the remembered contacts
    /// of pairs that were not simulated (both asleep or still), so a sleeping
    /// stack keeps its warm-start impulses and does not report its contacts
    /// as ended.
    fn update_contact_cache(&mut self) {
        let slop = self.settings.linear_slop;
        let mut fresh = core::mem::take(&mut self.scratch.contacts_next);
        fresh.clear();
        // Whether each slot moved this substep, read from a dense array
        // rather than from the bodies (two random body reads per contact).
        let mut moving = core::mem::take(&mut self.scratch.moving);
        moving.clear();
        moving.extend(
            self.slots
                .iter()
                .map(|slot| slot.body.as_ref().is_some_and(|b| b.is_moving())),
        );
        let scratch = &self.scratch;
        let active = |index: u32| moving.get(index as usize).copied().unwrap_or(false);
        // Merge (both sorted by pair): the remembered contacts of pairs that
        // were not simulated, and this substep's contacts.
        let mut kept = self
            .contacts
            .iter()
            .filter(|c| !active(c.a) && !active(c.b))
            .peekable();
        for c in &scratch.constraints {
            // A pair can be both: a body frozen at the bounds during this
            // substep is no longer active, yet its contact was simulated.
            // The fresh entry wins; the remembered one is dropped.
            while let Some(k) = kept.next_if(|k| (k.a, k.b) <= (c.a, c.b)) {
                if (k.a, k.b) != (c.a, c.b) {
                    fresh.push(*k);
                }
            }
            let motion = scratch.displacements[c.b as usize] - scratch.displacements[c.a as usize];
            let separation = c.separation.add(motion.dot(c.normal));
            fresh.push(CachedContact {
                a: c.a,
                b: c.b,
                normal_impulse: c.normal_impulse,
                tangent_impulse: c.tangent_impulse,
                // Touching: within the slop at the end of the substep, or
                // pushed apart this substep (a speculative bounce exchanges
                // impulse a hair before the surfaces meet).
                touching: separation <= slop || c.normal_impulse.is_positive(),
            });
        }
        fresh.extend(kept.copied());
        self.scratch.moving = moving;
        // Double buffer: the old cache becomes next substep's scratch.
        self.scratch.contacts_next = core::mem::replace(&mut self.contacts, fresh);
    }

    /// Sleep timers, islands, and putting resting islands to sleep.
    fn update_sleep(&mut self) {
        let settings = &self.settings;
        if !settings.sleep_enabled {
            return;
        }
        let threshold_sq = settings
            .sleep_linear_threshold
            .wide_mul(settings.sleep_linear_threshold);
        for slot in &mut self.slots {
            let Some(body) = slot.body.as_mut() else {
                continue;
            };
            if !body.is_simulated_dynamic() {
                continue;
            }
            if body.velocity.length_squared_wide() <= threshold_sq {
                body.sleep_time = body.sleep_time.add(settings.dt);
            } else {
                body.sleep_time = S::ZERO;
            }
        }
        let n = self.slots.len();
        let parents = &mut self.scratch.parents;
        islands::reset(parents, n);
        for c in &self.contacts {
            if !(c.touching || c.normal_impulse.is_positive()) {
                continue;
            }
            let (Some(ba), Some(bb)) = (
                self.slots[c.a as usize].body.as_ref(),
                self.slots[c.b as usize].body.as_ref(),
            ) else {
                continue;
            };
            let (da, db) = (ba.is_simulated_dynamic(), bb.is_simulated_dynamic());
            if da && db {
                islands::union(parents, c.a, c.b);
            }
        }
        // Constraints join islands like touching contacts.
        for entry in self
            .constraint_slots
            .iter()
            .filter_map(|s| s.entry.as_ref())
        {
            let (a, b) = entry.constraint.anchors();
            let (Some(ia), Some(ib)) = (a.body(), b.body()) else {
                continue;
            };
            let both = [ia, ib].iter().all(|id| {
                self.slots
                    .get(id.index() as usize)
                    .and_then(|s| s.body.as_ref())
                    .is_some_and(|b| b.is_simulated_dynamic())
            });
            if both {
                islands::union(parents, ia.index(), ib.index());
            }
        }
        // A body touched by a moving kinematic body may not sleep.
        for c in &self.contacts {
            for (me, other) in [(c.a, c.b), (c.b, c.a)] {
                let moving_kinematic = self.slots[other as usize]
                    .body
                    .as_ref()
                    .is_some_and(|o| o.kind == BodyKind::Kinematic && o.velocity != Vec2::ZERO);
                if moving_kinematic && let Some(body) = self.slots[me as usize].body.as_mut() {
                    body.sleep_time = S::ZERO;
                }
            }
        }
        // The island's readiness is its least-rested member.
        let mut island_time = core::mem::take(&mut self.scratch.island_time);
        island_time.clear();
        island_time.resize(n, S::MAX);
        for i in 0..n {
            let Some(body) = self.slots[i].body.as_ref() else {
                continue;
            };
            if !body.is_simulated_dynamic() {
                continue;
            }
            let root = islands::find(parents, u32::try_from(i).unwrap_or(u32::MAX)) as usize;
            island_time[root] = island_time[root].min(body.sleep_time);
        }
        for i in 0..n {
            let Some(body) = self.slots[i].body.as_mut() else {
                continue;
            };
            if !body.is_simulated_dynamic() {
                continue;
            }
            let index = u32::try_from(i).unwrap_or(u32::MAX);
            let root = islands::find(parents, index);
            if island_time[root as usize] < settings.time_to_sleep {
                continue;
            }
            body.awake = false;
            body.velocity = Vec2::ZERO;
            body.island = root;
            self.sleeping_islands.entry(root).or_default().push(index);
            self.events.push(Event::Slept(BodyId::from_parts(
                index,
                self.slots[i].generation,
            )));
        }
        self.scratch.island_time = island_time;
    }

    /// Contact begin/end events by comparing the touching pairs before and
    /// after the tick (both sorted).
    fn push_contact_events(&mut self, before: &[(u32, u32)]) {
        let mut after = self
            .contacts
            .iter()
            .filter(|c| c.touching)
            .map(|c| (c.a, c.b))
            .peekable();
        let mut before = before.iter().copied().peekable();
        loop {
            let event = match (before.peek().copied(), after.peek().copied()) {
                (Some(x), Some(y)) if x == y => {
                    before.next();
                    after.next();
                    continue;
                }
                (Some(x), Some(y)) if x < y => {
                    before.next();
                    Event::ContactEnded(self.id_of(x.0), self.id_of(x.1))
                }
                (Some(x), None) => {
                    before.next();
                    Event::ContactEnded(self.id_of(x.0), self.id_of(x.1))
                }
                (_, Some(y)) => {
                    after.next();
                    Event::ContactBegan(self.id_of(y.0), self.id_of(y.1))
                }
                (None, None) => break,
            };
            self.events.push(event);
        }
    }
}

/// One velocity pass over grouped rows (ropes or contacts), each group the
/// way [`RowGroups::classify`] decided: directly (the block solver for the
/// normal impulses, then friction by sequential impulses) or by sequential
/// impulses.
fn solve_group_list_velocities<S: Scalar>(
    rows: &mut [ContactConstraint<S>],
    groups: &RowGroups,
    velocities: &mut [Vec2<S>],
    block: &mut BlockScratch<S>,
) {
    for (group, direct, _) in groups.iter_classified() {
        if direct {
            solve_group_velocities(rows, group, velocities, block);
            for &ri in group {
                solve_friction_row(&mut rows[ri], velocities);
            }
        } else {
            for &ri in group {
                solve_velocity_row(&mut rows[ri], velocities);
            }
        }
    }
}

/// One position pass over grouped rows (same split as the velocities).
fn solve_group_list_positions<S: Scalar>(
    rows: &[ContactConstraint<S>],
    groups: &RowGroups,
    displacements: &mut [Vec2<S>],
    settings: &WorldSettings<S>,
    block: &mut BlockScratch<S>,
) {
    let (slop, beta, max) = (
        settings.linear_slop,
        settings.position_correction,
        settings.max_correction,
    );
    for (group, _, direct) in groups.iter_classified() {
        if direct {
            solve_group_positions(rows, group, displacements, slop, beta, max, block);
        } else {
            for &ri in group {
                solve_position_row(&rows[ri], displacements, slop, beta, max);
            }
        }
    }
}
