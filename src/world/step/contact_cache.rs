//! Phase "contact cache": this substep's contacts (impulses for the next
//! warm start) merged with the remembered contacts of pairs that did not move.

use crate::collision::CachedContact;
use crate::math::Scalar;
use crate::world::World;

impl<S: Scalar> World<S> {
    /// The new cache: this substep's contacts, plus the remembered contacts
    /// of pairs that were not simulated (both asleep or still), so a sleeping
    /// stack keeps its warm-start impulses and does not report its contacts
    /// as ended.
    pub(super) fn update_contact_cache(&mut self) {
        let slop = self.settings.linear_slop;
        let mut fresh = core::mem::take(&mut self.step_context.contacts_next);
        fresh.clear();
        // Whether each slot moved this substep, read from a dense array
        // rather than from the bodies (two random body reads per contact).
        let mut moving = core::mem::take(&mut self.step_context.moving);
        moving.clear();
        moving.extend(
            self.slots
                .iter()
                .map(|slot| slot.body.as_ref().is_some_and(|b| b.is_moving())),
        );
        let context = &self.step_context;
        let active = |index: u32| moving.get(index as usize).copied().unwrap_or(false);
        // Merge (both sorted by pair): the remembered contacts of pairs that
        // were not simulated, and this substep's contacts.
        let mut kept = self
            .contacts
            .iter()
            .filter(|c| !active(c.a) && !active(c.b))
            .peekable();
        for c in &context.constraints {
            // A pair can be both: a body frozen at the bounds during this
            // substep is no longer active, yet its contact was simulated.
            // The fresh entry wins; the remembered one is dropped.
            while let Some(k) = kept.next_if(|k| (k.a, k.b) <= (c.a, c.b)) {
                if (k.a, k.b) != (c.a, c.b) {
                    fresh.push(*k);
                }
            }
            let motion = context.displacements[c.b as usize] - context.displacements[c.a as usize];
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
        self.step_context.moving = moving;
        // Double buffer: the old cache becomes next substep's spare buffer.
        self.step_context.contacts_next = core::mem::replace(&mut self.contacts, fresh);
    }
}
