//! Phase "forces → velocities": each slot's velocity for the substep with
//! gravity applied, and the inverse mass the solver sees (springs follow
//! in [`constraints`](super::constraints)).

use crate::math::{Scalar, Vec2};
use crate::world::World;

impl<S: Scalar> World<S> {
    /// Velocities (with gravity) and solver inverse masses for every slot.
    pub(super) fn load_step_context(&mut self, h: S) {
        // One extra slot at the end: the virtual ground of point anchors.
        let n = self.slots.len() + 1;
        let context = &mut self.step_context;
        context.velocities.clear();
        context.velocities.resize(n, Vec2::ZERO);
        context.inverse_masses.clear();
        context.inverse_masses.resize(n, S::ZERO);
        context.displacements.clear();
        context.displacements.resize(n, Vec2::ZERO);
        let gravity_step = self.settings.gravity.scale(h);
        let max = self.settings.max_speed;
        let limit = Vec2::new(max, max);
        for (i, slot) in self.slots.iter().enumerate() {
            let Some(body) = &slot.body else { continue };
            if body.is_simulated_dynamic() {
                let v = body.velocity + gravity_step.scale(body.gravity_scale);
                context.velocities[i] = v.clamp(-limit, limit);
                context.inverse_masses[i] = body.inverse_mass;
            } else if body.is_moving() {
                context.velocities[i] = body.velocity;
            }
        }
    }
}
