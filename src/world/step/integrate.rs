//! Phase "integrate": displacements `v·h` (a bullet's cut at its time of
//! impact), then positions and velocities written back to the bodies, with
//! bodies that left the world bounds frozen.

use crate::collision::shape_toi;
use crate::dynamics::{BodyId, BodyKind};
use crate::geometry::Toi;
use crate::math::{Scalar, Vec2};
use crate::world::Event;
use crate::world::World;

impl<S: Scalar> World<S> {
    /// Displacements `v·h`; a bullet's is cut at its earliest time of impact
    /// against anything it was paired with, so it cannot pass through.
    pub(super) fn integrate(&mut self, h: S) {
        let context = &mut self.step_context;
        let mut any_bullet = false;
        for (i, slot) in self.slots.iter().enumerate() {
            let Some(body) = &slot.body else { continue };
            if body.is_moving() {
                // x' = x + h·v' − h·(1−θ)·Δv_spring: springs get the θ-method
                // position rule (see crate::constraints).
                let lagging = context.spring_dv[i].scale(h);
                context.displacements[i] = context.velocities[i].scale(h) - lagging;
                any_bullet |= body.bullet && body.is_simulated_dynamic();
            }
        }
        self.cut_punched_motion(h);
        let context = &mut self.step_context;
        // Most worlds have no bullet: skip the pass over every pair.
        if !any_bullet {
            return;
        }
        for &(a, b) in &context.pairs {
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
                let full = context.velocities[bullet as usize].scale(h);
                let other_motion = context.displacements[other as usize];
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
                    let current = context.displacements[bullet as usize];
                    if cut.length_squared_wide() < current.length_squared_wide() {
                        context.displacements[bullet as usize] = cut;
                    }
                }
            }
        }
    }

    /// Positions and velocities back into the bodies; bodies whose centre
    /// left the bounds are frozen.
    ///
    /// A velocity is stored clamped per axis to `max_speed`, as the setting
    /// promises of every body between steps: the solve can leave a body
    /// faster (a heavy body at `max_speed` striking a light one with
    /// restitution 1 throws it at twice that; a restored snapshot's cached
    /// warm-start impulse is any non-negative number), and the loading of the
    /// next step clamps only after adding gravity.
    pub(super) fn write_back(&mut self) {
        let bounds = self.settings.bounds;
        let (lo, hi) = (bounds.min(), bounds.max());
        let max = self.settings.max_speed;
        let limit = Vec2::new(max, max);
        for (i, slot) in self.slots.iter_mut().enumerate() {
            let Some(body) = slot.body.as_mut() else {
                continue;
            };
            if !body.is_moving() {
                continue;
            }
            body.position += self.step_context.displacements[i];
            if body.kind == BodyKind::Dynamic {
                body.velocity = self.step_context.velocities[i].clamp(-limit, limit);
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
}
