//! Phase "sleep" (once per tick): islands of slow bodies fall asleep.

use crate::constraints::constraint_body_pairs;
use crate::dynamics::{BodyId, BodyKind, islands};
use crate::math::{Scalar, Vec2};
use crate::world::{Event, World};

impl<S: Scalar> World<S> {
    /// Sleep timers, islands, and putting resting islands to sleep.
    pub(super) fn update_sleep(&mut self) {
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
        let parents = &mut self.step_context.parents;
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
        for (ia, ib) in constraint_body_pairs(&self.constraint_slots) {
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
        let mut island_time = core::mem::take(&mut self.step_context.island_time);
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
        // A body still deeper than the slop in an immovable one (its
        // projection out stopped at its proxy's edge: `step/contacts.rs`)
        // is being pushed out, however slow it is: its island stays awake,
        // even with `time_to_sleep` 0 (hence below any valid time, ≥ 0).
        for &index in &self.step_context.unresolved_overlaps {
            if let Some(body) = self.slots[index as usize].body.as_mut() {
                body.sleep_time = S::ZERO;
            }
            let root = islands::find(parents, index) as usize;
            island_time[root] = S::MIN;
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
        self.step_context.island_time = island_time;
    }
}
