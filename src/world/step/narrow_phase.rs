//! Phase "narrow phase": candidate pairs → contact rows
//! ([`crate::collision::NarrowPhase`]), waking sleepers an awake body touches.

use crate::collision::NarrowPhase;
use crate::math::Scalar;
use crate::solver::StepContext;
use crate::world::World;

impl<S: Scalar> World<S> {
    /// The narrow phase ([`NarrowPhase`]) into `context.constraints`;
    /// returns the sleeping bodies to wake (then the caller redoes it).
    ///
    /// The ropes' turns of the bodies' paths (`collision::rope_turn`)
    /// matter only to a pair whose straight sweep misses, so the narrow
    /// phase runs first without them, and only if some sweep missed and a
    /// rope turns some body is it run again with the turns: a rope world
    /// pays for them in the substeps where a sweep misses, not in every
    /// one (the rows come out as if the turns had been known from the
    /// start: without a miss they change nothing).
    pub(super) fn build_constraints(&mut self, h: S, inverse_h: S) -> Vec<u32> {
        self.step_context.rope_turns.clear();
        let to_wake = self.run_narrow_phase(h, inverse_h);
        if !to_wake.is_empty() || self.step_context.narrow_scratch.straight_misses == 0 {
            return to_wake;
        }
        self.find_rope_turns(h, inverse_h);
        if self.step_context.rope_turns.is_empty() {
            return to_wake;
        }
        self.run_narrow_phase(h, inverse_h)
    }

    /// One run of the narrow phase with the current `rope_turns`.
    fn run_narrow_phase(&mut self, h: S, inverse_h: S) -> Vec<u32> {
        let settings = &self.settings;
        let StepContext {
            pairs,
            velocities,
            inverse_masses,
            constraints,
            bounce_candidates,
            narrow_scratch,
            rope_turns,
            ..
        } = &mut self.step_context;
        let narrow_phase = NarrowPhase {
            pairs,
            velocities,
            inverse_masses,
            rope_turns,
            cache: &self.contacts,
            speculative_margin: settings.speculative_margin,
            linear_slop: settings.linear_slop,
            restitution_threshold: settings.restitution_threshold,
            gravity: settings.gravity,
            h,
            inverse_h,
        };
        let slots = &self.slots;
        narrow_phase.contact_rows(
            |i| slots[i as usize].body.as_ref(),
            constraints,
            bounce_candidates,
            narrow_scratch,
        )
    }
}
