//! Phase "narrow phase": candidate pairs → contact rows
//! ([`crate::collision::NarrowPhase`]), waking sleepers an awake body touches.

use crate::collision::NarrowPhase;
use crate::math::Scalar;
use crate::solver::StepContext;
use crate::world::World;

impl<S: Scalar> World<S> {
    /// The narrow phase ([`NarrowPhase`]) into `context.constraints`;
    /// returns the sleeping bodies to wake (then the caller redoes it).
    pub(super) fn build_constraints(&mut self, h: S, inverse_h: S) -> Vec<u32> {
        let settings = &self.settings;
        let StepContext {
            pairs,
            velocities,
            inverse_masses,
            constraints,
            bounce_candidates,
            narrow_scratch,
            ..
        } = &mut self.step_context;
        let narrow_phase = NarrowPhase {
            pairs,
            velocities,
            inverse_masses,
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
