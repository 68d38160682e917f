//! The `commands_churn` scenario: spawn, despawn, impulse, velocity,
//! teleport, wake, constraints mid-run; refused commands.

use super::*;

struct Churn {
    ground: BodyId,
    bodies: Vec<BodyId>,
    spawned: Vec<BodyId>,
    constraints: Vec<ConstraintId>,
    kinematic: Option<BodyId>,
}

impl Script for Churn {
    fn commands(&mut self, world: &World, _observer: &mut Observer<'_>) -> Vec<Command> {
        let tick = world.tick();
        // The replay module's seeded input: impulses, spawns, despawns,
        // velocities, wakes and a stale despawn, on their own periods.
        let mut out = scripted_commands(world, 0x00C1_0C4B);
        let b = |i: usize| nth(&self.bodies, i);
        match tick {
            10 => {
                out.push(Command::AddConstraint(Constraint::rope(
                    Anchor::Body(b(0)),
                    Anchor::Body(b(1)),
                    n(2),
                )));
                out.push(Command::AddConstraint(Constraint::bendy_spring(
                    Anchor::Body(b(2)),
                    Anchor::Body(b(3)),
                    vi(40, 40),
                    r(1, 2),
                )));
            }
            // A body with a rope goes (the rope with it); its stale handle
            // is refused; the next spawn reuses its slot, one generation up.
            50 => out.push(Command::Despawn(b(0))),
            51 => {
                out.push(impulse_for(world, b(0), vi(1, 0)));
                out.push(Command::Spawn(
                    BodyDef::dynamic(Shape::aabb(vf(r(3, 10), r(3, 10)))).position(vi(-3, 7)),
                ));
            }
            100 => {
                out.push(Command::SetPosition {
                    body: b(4),
                    position: vi(3, 6),
                });
                out.push(Command::ApplyImpulse {
                    body: self.ground,
                    impulse: vi(1, 0),
                });
                out.push(Command::SetVelocity {
                    body: self.ground,
                    velocity: vi(1, 0),
                });
            }
            // Invalid definitions, each refused with its own error.
            150 => {
                out.push(Command::Spawn(BodyDef::dynamic(Shape::circle(n(0)))));
                out.push(Command::Spawn(
                    BodyDef::dynamic(Shape::circle(n(1))).restitution(n(2)),
                ));
                out.push(Command::Spawn(
                    BodyDef::dynamic(Shape::circle(n(1))).mass(n(0)),
                ));
                out.push(Command::Spawn(BodyDef::dynamic(Shape::circle(n(5000)))));
            }
            200 => {
                // A constraint attached to no body, and a rope of negative
                // length: both refused.
                out.push(Command::AddConstraint(Constraint::rope(
                    Anchor::Point(vi(0, 1)),
                    Anchor::Point(vi(0, 2)),
                    n(1),
                )));
                out.push(Command::AddConstraint(Constraint::rope(
                    Anchor::Point(vi(0, 1)),
                    Anchor::Body(self.spawned.first().copied().unwrap_or(b(5))),
                    n(-1),
                )));
                out.push(Command::RemoveConstraint(ConstraintId::from_parts(0, 9)));
                // The spring between 2 and 3 goes.
                if let Some(&id) = self.constraints.get(1) {
                    out.push(Command::RemoveConstraint(id));
                }
            }
            250 => out.push(Command::Spawn(
                BodyDef::kinematic(Shape::aabb(vf(r(3, 2), r(1, 4))))
                    .position(vi(-8, 3))
                    .velocity(vi(2, 0)),
            )),
            // A burst of spawns in one tick; three of them go the next tick.
            300 => {
                for i in 0..5 {
                    out.push(Command::Spawn(
                        BodyDef::dynamic(Shape::circle(r(1, 4))).position(vf(n(i - 2), n(9))),
                    ));
                }
            }
            301 => {
                for &id in self.spawned.iter().rev().take(3) {
                    out.push(Command::Despawn(id));
                }
            }
            350 => {
                if let Some(k) = self.kinematic {
                    out.push(Command::SetVelocity {
                        body: k,
                        velocity: vi(-2, 0),
                    });
                }
            }
            450 => {
                if let Some(k) = self.kinematic {
                    out.push(Command::Despawn(k));
                }
            }
            500 => {
                for (id, body) in world.bodies() {
                    if body.kind() == BodyKind::Dynamic {
                        out.push(Command::Wake(id));
                    }
                }
            }
            _ => {}
        }
        out
    }

    fn after_step(
        &mut self,
        world: &World,
        results: &[Result<CommandOutcome, WorldError>],
        _observer: &mut Observer<'_>,
    ) {
        let (bodies, constraints) = outcomes(results);
        if world.tick() == 251 {
            self.kinematic = bodies.iter().copied().find(|&id| {
                world
                    .body(id)
                    .is_some_and(|b| b.kind() == BodyKind::Kinematic)
            });
        }
        self.spawned.extend(bodies);
        self.constraints.extend(constraints);
    }
}

pub(crate) fn commands_churn() -> Built {
    let mut world = World::new(WorldSettings::default());
    let ground = world
        .add_body(BodyDef::fixed(Shape::aabb(vf(n(12), r(1, 2)))).position(vf(n(0), r(-1, 2))))?;
    for x in [-25, 25] {
        world
            .add_body(BodyDef::fixed(Shape::aabb(vf(r(1, 2), n(8)))).position(vf(r(x, 2), n(8))))?;
    }
    let mut bodies = Vec::new();
    for i in 0..12 {
        let x = r(i * 3 - 16, 2);
        let y = n(1 + (i % 3) * 2);
        let def = if i % 2 == 0 {
            BodyDef::dynamic(Shape::circle(r(3 + i % 3, 10)))
        } else {
            BodyDef::dynamic(Shape::aabb(vf(r(2 + i % 4, 10), r(3, 10))))
        };
        bodies.push(world.add_body(def.position(vf(x, y)).restitution(r(i % 4, 8)))?);
    }
    Ok((
        world,
        Box::new(Churn {
            ground,
            bodies,
            spawned: Vec::new(),
            constraints: Vec::new(),
            kinematic: None,
        }),
    ))
}
