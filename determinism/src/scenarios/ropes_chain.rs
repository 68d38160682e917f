//! The `ropes_chain` scenario: rope pendulum, 10-link chain, bouncy rope; a
//! link despawned, a rope added.

use super::*;

struct Ropes {
    bodies: Vec<BodyId>,
}

impl Script for Ropes {
    fn commands(&mut self, world: &World, _observer: &mut Observer<'_>) -> Vec<Command> {
        // Dynamic bodies: 0 pendulum bob, 1 heavy ball, 2..=11 chain links.
        let b = |i: usize| nth(&self.bodies, i);
        match world.tick() {
            150 => vec![Command::SetVelocity {
                body: b(11),
                velocity: vi(0, 6),
            }],
            // A middle link goes, and its two ropes with it: the chain splits.
            300 => vec![Command::Despawn(b(6))],
            // A bouncy rope between the pendulum bob and the heavy ball.
            400 => vec![Command::AddConstraint(
                Constraint::rope(Anchor::Body(b(0)), Anchor::Body(b(1)), n(14))
                    .with_restitution(r(1, 2)),
            )],
            // The fallen end of the chain is hoisted by a short rope.
            450 => vec![Command::AddConstraint(Constraint::rope(
                Anchor::Point(vi(-2, 10)),
                Anchor::BodyOffset(b(11), vf(r(1, 20), n(0))),
                n(3),
            ))],
            _ => Vec::new(),
        }
    }
}

pub(crate) fn ropes_chain() -> Built {
    let world: World = builtin("rope")?.build()?;
    let bodies = ids_of(&world, BodyKind::Dynamic);
    Ok((world, Box::new(Ropes { bodies })))
}
