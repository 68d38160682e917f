//! The `springs` scenario: bendy and radial springs, soft to 10^6 stiff;
//! body-to-body springs added and removed.

use super::*;

struct Springs {
    bodies: Vec<BodyId>,
    added: Vec<ConstraintId>,
}

impl Script for Springs {
    fn commands(&mut self, world: &World, _observer: &mut Observer<'_>) -> Vec<Command> {
        let b = |i: usize| nth(&self.bodies, i);
        match world.tick() {
            // A radial spring between the two free balls, off-centre anchors.
            120 => vec![Command::AddConstraint(Constraint::radial_spring(
                Anchor::BodyOffset(b(0), vf(r(1, 10), n(0))),
                Anchor::BodyOffset(b(1), vf(r(-1, 10), n(0))),
                n(4),
                n(30),
                r(1, 5),
            ))],
            // A bendy spring between two hanging boxes, with a rest offset.
            240 => vec![Command::AddConstraint(
                Constraint::bendy_spring(
                    Anchor::Body(b(2)),
                    Anchor::Body(b(3)),
                    vi(80, 120),
                    r(1, 2),
                )
                .with_rest_offset(vf(r(12, 5), n(0))),
            )],
            360 => self
                .added
                .first()
                .map(|&id| vec![Command::RemoveConstraint(id)])
                .unwrap_or_default(),
            // A kick to the box on the 10^6 spring.
            420 => vec![impulse_for(world, b(7), vi(0, 50))],
            // The box on the 5000 spring is let go (constraint slot 6 of the
            // scene) and falls to the ground.
            480 => vec![Command::RemoveConstraint(ConstraintId::from_parts(6, 0))],
            // The stiffest spring accepted (2^24), undamped, on another box.
            500 => vec![Command::AddConstraint(Constraint::radial_spring(
                Anchor::Point(vf(r(-6, 5), n(5))),
                Anchor::Body(b(4)),
                n(1),
                n(1 << 24),
                n(0),
            ))],
            _ => Vec::new(),
        }
    }

    fn after_step(
        &mut self,
        _world: &World,
        results: &[Result<CommandOutcome, WorldError>],
        _observer: &mut Observer<'_>,
    ) {
        self.added.extend(outcomes(results).1);
    }
}

pub(crate) fn springs() -> Built {
    let world: World = builtin("springs")?.build()?;
    let bodies = ids_of(&world, BodyKind::Dynamic);
    Ok((
        world,
        Box::new(Springs {
            bodies,
            added: Vec::new(),
        }),
    ))
}
