//! Adding and removing bodies, with full validation first.

use super::{Slot, World, WorldError};
use crate::dynamics::{Body, BodyDef, BodyId, BodyKind, MassSpec, NO_ISLAND};
use crate::geometry::Shape;
use crate::math::{Scalar, Vec2};

/// Largest radius or half extent accepted (units). Keeps every shape's
/// bounding box, and the sums of two, far inside the number range.
pub(crate) const MAX_SHAPE_SIZE: i32 = 4096;
/// A dynamic body's mass is at least `1 / MIN_MASS_RECIPROCAL` = 2⁻¹⁰ (its
/// inverse then keeps at least 12 significant bits in I32F32: 2⁻²⁰ / 2⁻³²)
/// and at most [`MAX_MASS`] = 2²⁰ (mass × speed stays in range). The error
/// message ([`WorldError::MassOutOfRange`]) states the same range.
pub(crate) const MIN_MASS_RECIPROCAL: i32 = 1 << 10;
/// See [`MIN_MASS_RECIPROCAL`].
pub(crate) const MAX_MASS: i32 = 1 << 20;
/// Largest number of slots (2³¹): ids stay far from `u32` overflow.
const MAX_SLOTS: usize = 1 << 31;

impl<S: Scalar> World<S> {
    /// Adds a body.
    ///
    /// # Errors
    /// A [`WorldError`] if the definition is invalid (non-positive size or
    /// mass, material out of range, position outside the bounds, speed above
    /// `max_speed`). The world is then unchanged.
    pub fn add_body(&mut self, def: BodyDef<S>) -> Result<BodyId, WorldError> {
        let body = self.validate_def(&def)?;
        if self.free_list.is_empty() && self.slots.len() >= MAX_SLOTS {
            return Err(WorldError::TooManyBodies);
        }
        let index = match self.free_list.pop() {
            Some(index) => {
                let slot = &mut self.slots[index as usize];
                slot.body = Some(body);
                index
            }
            None => {
                let index =
                    u32::try_from(self.slots.len()).map_err(|_| WorldError::TooManyBodies)?;
                self.slots.push(Slot {
                    generation: 0,
                    body: Some(body),
                });
                index
            }
        };
        self.wake_sleepers_overlapping(index);
        Ok(self.id_of(index))
    }

    /// Removes a body. Bodies that touched it are woken (so a stack whose
    /// support is removed falls).
    ///
    /// # Errors
    /// [`WorldError::UnknownBody`] for a stale or unknown id (the world is
    /// then unchanged).
    pub fn remove_body(&mut self, id: BodyId) -> Result<Body<S>, WorldError> {
        let index = self.live_index(id)?;
        let index_u32 = id.index();
        // Wake everything that touched it, then forget its contacts (the
        // slot may be reused by a new body, which must not inherit them).
        self.wake_neighbours(index_u32);
        // Constraints attached to the body go with it (their bodies woken).
        self.wake_constraint_partners(index_u32);
        self.remove_constraints_of(index_u32);
        self.wake_index(index_u32);
        self.contacts
            .retain(|c| c.a != index_u32 && c.b != index_u32);
        let slot = &mut self.slots[index];
        let body = slot.body.take().ok_or(WorldError::UnknownBody(id))?;
        slot.generation = slot.generation.wrapping_add(1);
        self.free_list.push(index_u32);
        Ok(body)
    }

    /// Checks a definition and builds the body it describes.
    pub(crate) fn validate_def(&self, def: &BodyDef<S>) -> Result<Body<S>, WorldError> {
        let max_size = S::from_int(MAX_SHAPE_SIZE);
        match def.shape {
            Shape::Circle { radius } => {
                if !radius.is_positive() {
                    return Err(WorldError::NonPositiveSize);
                }
                if radius > max_size {
                    return Err(WorldError::ShapeTooLarge);
                }
            }
            Shape::Aabb { half_extents } => {
                if !half_extents.x.is_positive() || !half_extents.y.is_positive() {
                    return Err(WorldError::NonPositiveSize);
                }
                if half_extents.x > max_size || half_extents.y > max_size {
                    return Err(WorldError::ShapeTooLarge);
                }
            }
        }
        self.check_in_bounds(def.position)?;
        self.check_speed(def.velocity)?;
        if def.restitution.is_negative() || def.restitution > S::ONE {
            return Err(WorldError::MaterialOutOfRange {
                field: "restitution",
            });
        }
        let thousand = S::from_int(1000);
        if def.friction.is_negative() || def.friction > thousand {
            return Err(WorldError::MaterialOutOfRange { field: "friction" });
        }
        if def.gravity_scale.abs() > thousand {
            return Err(WorldError::MaterialOutOfRange {
                field: "gravity_scale",
            });
        }
        // One rule for every kind: the mass specification must be positive,
        // even where it is not used (fixed and kinematic bodies have infinite
        // mass), so a definition is valid or not whatever its kind.
        let spec = match def.mass {
            MassSpec::Density(value) | MassSpec::Mass(value) => value,
        };
        if !spec.is_positive() {
            return Err(WorldError::NonPositiveMass);
        }
        let (mass, inverse_mass) = if def.kind == BodyKind::Dynamic {
            let mass = match def.mass {
                MassSpec::Density(density) => density.mul(def.shape.area()),
                MassSpec::Mass(mass) => mass,
            };
            // Mass in [2^-10, 2^20] (see `MIN_MASS_RECIPROCAL`).
            if mass < S::from_ratio(1, MIN_MASS_RECIPROCAL) || mass > S::from_int(MAX_MASS) {
                return Err(WorldError::MassOutOfRange);
            }
            (mass, S::ONE.div(mass))
        } else {
            (S::ZERO, S::ZERO)
        };
        let velocity = if def.kind == BodyKind::Fixed {
            Vec2::ZERO
        } else {
            def.velocity
        };
        Ok(Body {
            kind: def.kind,
            shape: def.shape,
            position: def.position,
            velocity,
            mass,
            inverse_mass,
            restitution: def.restitution,
            friction: def.friction,
            gravity_scale: def.gravity_scale,
            bullet: def.bullet && def.kind == BodyKind::Dynamic,
            awake: def.kind != BodyKind::Fixed,
            frozen: false,
            sleep_time: S::ZERO,
            island: NO_ISLAND,
        })
    }

    pub(crate) fn check_in_bounds(&self, position: Vec2<S>) -> Result<(), WorldError> {
        if self.settings.bounds.contains_point(position) {
            Ok(())
        } else {
            Err(WorldError::OutOfBounds)
        }
    }

    pub(crate) fn check_speed(&self, velocity: Vec2<S>) -> Result<(), WorldError> {
        let max = self.settings.max_speed;
        if velocity.x.abs() > max || velocity.y.abs() > max {
            Err(WorldError::SpeedTooLarge)
        } else {
            Ok(())
        }
    }

    /// Wakes every body that was in contact with the body in slot `index`
    /// during the last step.
    pub(crate) fn wake_neighbours(&mut self, index: u32) {
        let neighbours: Vec<u32> = self
            .contacts
            .iter()
            .filter_map(|c| {
                if c.a == index {
                    Some(c.b)
                } else if c.b == index {
                    Some(c.a)
                } else {
                    None
                }
            })
            .collect();
        for n in neighbours {
            self.wake_index(n);
        }
    }

    /// Wakes every sleeping island with a member whose bounding box overlaps
    /// or touches that of the body in slot `index` (just spawned or
    /// teleported). A sleeping body takes no part in the step, so a body
    /// that appears on top of it would otherwise stay inside it until
    /// something else woke it: a fixed body spawned over a sleeping ball
    /// held it overlapped for good (found by the `world_commands` fuzz
    /// target).
    pub(crate) fn wake_sleepers_overlapping(&mut self, index: u32) {
        let Some(Some(body)) = self.slots.get(index as usize).map(|s| s.body.as_ref()) else {
            return;
        };
        let reach = body.aabb();
        let touched: Vec<u32> = self
            .sleeping_islands
            .values()
            .filter_map(|members| {
                members.iter().copied().find(|&m| {
                    m != index
                        && self
                            .slots
                            .get(m as usize)
                            .and_then(|s| s.body.as_ref())
                            .is_some_and(|b| b.aabb().overlaps(&reach))
                })
            })
            .collect();
        for m in touched {
            self.wake_index(m);
        }
    }

    /// Wakes the body in slot `index` and, if it sleeps, its whole island.
    pub(crate) fn wake_index(&mut self, index: u32) {
        let Some(Some(body)) = self.slots.get(index as usize).map(|s| s.body.as_ref()) else {
            return;
        };
        if body.kind == BodyKind::Fixed || body.frozen {
            return;
        }
        if body.awake {
            if let Some(b) = self.slots[index as usize].body.as_mut() {
                b.sleep_time = S::ZERO;
            }
            return;
        }
        let key = body.island;
        let members = self
            .sleeping_islands
            .remove(&key)
            .unwrap_or_else(|| vec![index]);
        for m in members {
            if let Some(b) = self.slots.get_mut(m as usize).and_then(|s| s.body.as_mut())
                && !b.awake
                && b.kind != BodyKind::Fixed
            {
                b.awake = true;
                b.sleep_time = S::ZERO;
                b.island = NO_ISLAND;
                self.events.push(super::Event::Woke(BodyId::from_parts(
                    m,
                    self.slots[m as usize].generation,
                )));
            }
        }
    }
}
