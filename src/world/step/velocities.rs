//! Phase "forces → velocities": each slot's velocity for the substep with
//! gravity applied, and the inverse mass the solver sees (springs follow
//! in [`constraints`](super::constraints)).

use crate::math::{Scalar, Vec2};
use crate::world::World;

impl<S: Scalar> World<S> {
    /// Velocities (with gravity) and solver inverse masses for every slot.
    pub(super) fn load_scratch(&mut self, h: S) {
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
}
