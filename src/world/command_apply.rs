//! Applying [`Command`]s: validate fully, then mutate.

use super::{Command, CommandOutcome, World, WorldError};
use crate::dynamics::BodyKind;
use crate::math::Scalar;

impl<S: Scalar> World<S> {
    /// Applies one command now. On error the world is unchanged.
    ///
    /// # Errors
    /// The [`WorldError`] explaining why the command was refused.
    pub fn apply(&mut self, command: Command<S>) -> Result<CommandOutcome, WorldError> {
        match command {
            Command::Spawn(def) => self.add_body(def).map(CommandOutcome::Spawned),
            Command::Despawn(id) => self.remove_body(id).map(|_| CommandOutcome::Applied),
            Command::ApplyImpulse { body, impulse } => {
                let index = self.live_index(body)?;
                let b = self.slots[index]
                    .body
                    .as_ref()
                    .ok_or(WorldError::UnknownBody(body))?;
                if b.kind != BodyKind::Dynamic {
                    return Err(WorldError::NotDynamic(body));
                }
                if b.frozen {
                    return Err(WorldError::OutOfBounds);
                }
                // Δv = J / m = J · (1/m).
                let dv = impulse.scale(b.inverse_mass);
                let velocity = b.velocity + dv;
                self.check_speed(velocity)?;
                self.set_velocity_unchecked(index, velocity);
                Ok(CommandOutcome::Applied)
            }
            Command::SetVelocity { body, velocity } => {
                let index = self.live_index(body)?;
                let b = self.slots[index]
                    .body
                    .as_ref()
                    .ok_or(WorldError::UnknownBody(body))?;
                if b.kind == BodyKind::Fixed {
                    return Err(WorldError::FixedBody(body));
                }
                if b.frozen {
                    return Err(WorldError::OutOfBounds);
                }
                self.check_speed(velocity)?;
                self.set_velocity_unchecked(index, velocity);
                Ok(CommandOutcome::Applied)
            }
            Command::SetPosition { body, position } => {
                let index = self.live_index(body)?;
                self.check_in_bounds(position)?;
                let index_u32 = body.index();
                // Wake what touched it at its old place (it may have been a
                // support), then move it and wake it and whatever sleeps
                // where it lands.
                self.wake_neighbours(index_u32);
                if let Some(b) = self.slots[index].body.as_mut() {
                    b.position = position;
                    b.frozen = false;
                }
                self.wake_index(index_u32);
                self.wake_sleepers_overlapping(index_u32);
                Ok(CommandOutcome::Applied)
            }
            Command::AddConstraint(constraint) => self
                .add_constraint(constraint)
                .map(CommandOutcome::ConstraintAdded),
            Command::RemoveConstraint(id) => {
                self.remove_constraint(id).map(|_| CommandOutcome::Applied)
            }
            Command::Wake(body) => {
                let index = self.live_index(body)?;
                self.wake_index(u32::try_from(index).map_err(|_| WorldError::UnknownBody(body))?);
                Ok(CommandOutcome::Applied)
            }
        }
    }

    fn set_velocity_unchecked(&mut self, index: usize, velocity: crate::math::Vec2<S>) {
        if let Some(b) = self.slots[index].body.as_mut() {
            b.velocity = velocity;
        }
        if let Ok(index) = u32::try_from(index) {
            self.wake_index(index);
        }
    }
}
