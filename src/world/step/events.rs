//! Phase "events" (once per tick): contact begin/end from the touching
//! pairs before and after the tick.

use crate::math::Scalar;
use crate::world::Event;
use crate::world::World;

impl<S: Scalar> World<S> {
    /// Contact begin/end events by comparing the touching pairs before and
    /// after the tick (both sorted).
    pub(super) fn push_contact_events(&mut self, before: &[(u32, u32)]) {
        let mut after = self
            .contacts
            .iter()
            .filter(|c| c.touching)
            .map(|c| (c.a, c.b))
            .peekable();
        let mut before = before.iter().copied().peekable();
        loop {
            let event = match (before.peek().copied(), after.peek().copied()) {
                (Some(x), Some(y)) if x == y => {
                    before.next();
                    after.next();
                    continue;
                }
                (Some(x), Some(y)) if x < y => {
                    before.next();
                    Event::ContactEnded(self.id_of(x.0), self.id_of(x.1))
                }
                (Some(x), None) => {
                    before.next();
                    Event::ContactEnded(self.id_of(x.0), self.id_of(x.1))
                }
                (_, Some(y)) => {
                    after.next();
                    Event::ContactBegan(self.id_of(y.0), self.id_of(y.1))
                }
                (None, None) => break,
            };
            self.events.push(event);
        }
    }
}
