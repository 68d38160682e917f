//! The step pipeline, top to bottom (ARCHITECTURE.md, "The step pipeline").
//!
//! [`World::step_with`] is one tick and [`World::substep`] one substep; each
//! phase is a method in the file named after it:
//!
//! | phase | file |
//! |---|---|
//! | apply this tick's commands | `world/command_apply.rs` |
//! | wake across constraints | [`constraints`] |
//! | per substep: forces → velocities (gravity) | [`velocities`] |
//! | springs | [`constraints`] |
//! | broad phase (proxies, candidate pairs) | [`broad_phase`] |
//! | narrow phase (pairs → contact rows, waking sleepers; run again with the ropes' turns of the bodies' paths when a straight sweep missed) | [`narrow_phase`], [`rope_turns`] |
//! | rope rows | [`constraints`] |
//! | grouping, warm start, velocity iterations (contacts solved with a stiff spring group left alone, their impulses added back after; covering-tree groups that run away solved again by sequential impulses) | [`solve`], [`constraints`], [`energy_guard`] |
//! | integrate (bullets' time of impact; punched bodies stopped at immovable ones they have no row with and where they meet movable ones they have no row with, their followers held behind them) | [`integrate`], [`punched_motion`], [`punched_followers`] |
//! | position iterations | [`solve`] |
//! | bound corrections, out of immovable bodies (punched bodies again), bounces, rebound sweep (beyond the proxies too), ropes settled | [`contacts`], [`punched_motion`], [`rebound_escape`] |
//! | write back (bounds: freeze) | [`integrate`] |
//! | contact cache, rope impulses | [`contact_cache`], [`constraints`] |
//! | per tick: sleep | [`sleep`] |
//! | contact events | [`events`] |
//!
//! The phases share the step context ([`crate::solver::StepContext`],
//! `World::step_context`): derived buffers, never part of the state.

mod broad_phase;
mod constraints;
mod contact_cache;
pub(crate) mod contacts;
mod energy_guard;
mod events;
mod integrate;
mod narrow_phase;
mod punched_followers;
mod punched_motion;
mod rebound_escape;
mod rope_turns;
mod sleep;
mod solve;
mod velocities;

use super::{Command, CommandOutcome, World, WorldError};
use crate::math::Scalar;

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
        self.step_context.unresolved_overlaps.clear();
        let mut previous_touching = core::mem::take(&mut self.step_context.touching_before);
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
        self.step_context.touching_before = previous_touching;
        self.events.sort_unstable();
        self.events.dedup();
        self.tick = self.tick.wrapping_add(1);
        results
    }

    /// One substep of length `h` (`inverse_h` = 1/h).
    fn substep(&mut self, h: S, inverse_h: S) {
        // Narrow phase may wake sleeping islands; their own contacts were not
        // paired (both asleep at broad-phase time), so the phase is redone.
        // Each pass wakes at least one island, so this ends.
        loop {
            self.load_step_context(h);
            self.build_proxies(h);
            self.find_pairs();
            let to_wake = self.build_constraints(h, inverse_h);
            if to_wake.is_empty() {
                break;
            }
            for index in to_wake {
                self.wake_index(index);
            }
        }
        self.remember_predicted_velocities();
        self.apply_springs(h);
        self.build_rope_rows(h, inverse_h);
        self.group_and_warm_start(h);
        self.solve_velocities(h);
        self.add_held_contact_impulses();
        self.integrate(h);
        self.remember_displacements();
        self.solve_positions(h);
        self.bound_corrections(h);
        self.project_out_of_immovable();
        self.cut_punched_at_immovable_partners(false);
        self.bounce(h);
        self.sweep_rebounds(h);
        self.settle_ropes();
        self.write_back();
        self.update_contact_cache();
        self.store_rope_impulses();
    }
}
