//! The `bounds_extreme` scenario: bodies at the world bounds at max speed,
//! extreme masses and stiffness: saturation, clamping, freezing.

use super::*;

struct Bounds {
    b: Vec<BodyId>,
}

impl Script for Bounds {
    fn commands(&mut self, world: &World, observer: &mut Observer<'_>) -> Vec<Command> {
        let b = |i: usize| nth(&self.b, i);
        let max = <Fx as Scalar>::MAX;
        let min = <Fx as Scalar>::MIN;
        if world.tick() % 60 == 0 {
            // Rays across the whole world, and one of unbounded length.
            let rays = [
                (vi(-32768, -32600), vi(1, 0), n(1 << 16)),
                (vi(32768, 32768), vi(-1, -1), n(1 << 17)),
                (vi(0, 0), vi(0, -1), max),
                (vi(-32768, 32768), vi(32767, -1), max),
            ];
            for (origin, direction, length) in rays {
                let hit = world.raycast(origin, direction, length);
                observer.ray(hit.as_ref());
            }
        }
        match world.tick() {
            3 => vec![
                // Δv = 1000 · 1024 units/s on the 1/1024-mass body: refused.
                Command::ApplyImpulse {
                    body: b(5),
                    impulse: vi(1000, 0),
                },
                // The most negative impulses there are: refused, nothing overflows.
                Command::ApplyImpulse {
                    body: b(4),
                    impulse: vf(min, min),
                },
                // On the heaviest body the largest impulse is a change of
                // 2048 units/s: accepted, and saturates nothing.
                Command::ApplyImpulse {
                    body: b(4),
                    impulse: vf(max, n(0)),
                },
                Command::ApplyImpulse {
                    body: b(6),
                    impulse: vf(min, n(0)),
                },
            ],
            5 => vec![
                Command::SetVelocity {
                    body: b(7),
                    velocity: vi(0, 4097),
                },
                Command::SetVelocity {
                    body: b(1),
                    velocity: vi(4096, 0),
                },
            ],
            // b1 is frozen at x = +32768 by now.
            20 => vec![
                impulse_for(world, b(1), vi(-1, 0)),
                Command::SetVelocity {
                    body: b(1),
                    velocity: vi(-10, 0),
                },
                Command::SetPosition {
                    body: b(1),
                    position: vi(32767, 0),
                },
                Command::SetVelocity {
                    body: b(1),
                    velocity: vi(-4096, 0),
                },
            ],
            25 => vec![
                Command::SetPosition {
                    body: b(2),
                    position: vi(40000, 0),
                },
                Command::SetPosition {
                    body: b(2),
                    position: vf(max, min),
                },
                Command::Spawn(BodyDef::dynamic(Shape::circle(n(1))).position(vi(32769, 0))),
                Command::Spawn(BodyDef::dynamic(Shape::circle(n(1))).position(vi(32768, -32768))),
                Command::Spawn(BodyDef::dynamic(Shape::circle(n(1))).velocity(vi(4097, 0))),
                Command::Spawn(BodyDef::dynamic(Shape::circle(n(1))).mass(n(1 << 21))),
                Command::Spawn(BodyDef::dynamic(Shape::circle(n(1))).mass(r(1, 2048))),
            ],
            // The largest shape, heaviest mass, at max speed toward a corner.
            60 => vec![Command::Spawn(
                BodyDef::dynamic(Shape::circle(n(4096)))
                    .position(vi(28000, 28000))
                    .velocity(vi(4096, 4096))
                    .mass(n(1 << 20)),
            )],
            // A rope of the largest length between bodies half a world apart.
            120 => vec![Command::AddConstraint(Constraint::rope(
                Anchor::Body(b(1)),
                Anchor::Body(b(9)),
                n(32768),
            ))],
            300 => vec![Command::Despawn(b(2))],
            _ => Vec::new(),
        }
    }
}

pub(crate) fn bounds_extreme() -> Built {
    let mut world = World::new(WorldSettings::default());
    let heavy = n(1 << 20);
    let tiny = r(1, 1024);
    let defs = [
        // 0: the largest fixed box, near the bottom bound.
        BodyDef::fixed(Shape::aabb(vi(4096, 16))).position(vi(0, -32700)),
        // 1: at 4000 units/s toward x = +32768, 768 units away.
        BodyDef::dynamic(Shape::circle(r(1, 2)))
            .position(vi(32000, 0))
            .velocity(vi(4000, 0))
            .gravity_scale(n(0)),
        // 2: toward the bottom-left corner.
        BodyDef::dynamic(Shape::aabb(vi(1, 1)))
            .position(vi(-32000, -32000))
            .velocity(vi(-4000, -4000))
            .gravity_scale(n(0)),
        // 3: at max speed, 68 units under the top bound.
        BodyDef::dynamic(Shape::circle(n(1)))
            .position(vi(0, 32700))
            .velocity(vi(0, 4096)),
        // 4 and 5: the heaviest and the lightest body, head on at 8000.
        BodyDef::dynamic(Shape::aabb(vi(2, 2)))
            .position(vi(30000, 100))
            .velocity(vi(-4000, 0))
            .mass(heavy)
            .gravity_scale(n(0)),
        BodyDef::dynamic(Shape::circle(r(1, 4)))
            .position(vi(29000, 100))
            .velocity(vi(4000, 0))
            .mass(tiny)
            .gravity_scale(n(0)),
        // 6: 1000 g of gravity: clamped to max_speed, lands on body 0.
        BodyDef::dynamic(Shape::circle(n(1)))
            .position(vi(1000, 30000))
            .gravity_scale(n(1000)),
        // 7: a bullet at max speed between a wall and the open world.
        BodyDef::dynamic(Shape::circle(r(1, 10)))
            .position(vi(0, -32600))
            .velocity(vi(4096, 0))
            .bullet(true)
            .restitution(n(1))
            .gravity_scale(n(0)),
        BodyDef::fixed(Shape::aabb(vf(r(1, 10), n(100)))).position(vi(3000, -32600)),
        // 9: on the stiffest, most damped radial spring to the far corner.
        BodyDef::dynamic(Shape::circle(r(1, 2)))
            .position(vi(20000, 20000))
            .gravity_scale(n(0)),
        // 10 and 11: a 2^24 bendy spring between opposite corners.
        BodyDef::dynamic(Shape::circle(r(1, 2))).position(vi(-32000, 32000)),
        BodyDef::dynamic(Shape::circle(r(1, 2))).position(vi(32000, -32000)),
        // 12: hanging on a long rope from the top-right corner.
        BodyDef::dynamic(Shape::circle(r(1, 2))).position(vi(32000, 32000)),
    ];
    let mut b = Vec::new();
    for def in defs {
        b.push(world.add_body(def)?);
    }
    let k = n(1 << 24);
    world.add_constraint(Constraint::radial_spring(
        Anchor::Point(vi(-32768, -32768)),
        Anchor::Body(nth(&b, 9)),
        n(0),
        k,
        k,
    ))?;
    world.add_constraint(Constraint::bendy_spring(
        Anchor::Body(nth(&b, 10)),
        Anchor::Body(nth(&b, 11)),
        vf(k, k),
        n(0),
    ))?;
    world.add_constraint(Constraint::rope(
        Anchor::Point(vi(32768, 32768)),
        Anchor::Body(nth(&b, 12)),
        n(2000),
    ))?;
    Ok((world, Box::new(Bounds { b })))
}
