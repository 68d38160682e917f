//! The `bullets_toi` scenario: bullets at 700-3000 units/s against thin walls
//! (exact time of impact).

use super::*;

struct Bullets {
    bullets: Vec<BodyId>,
}

impl Script for Bullets {
    fn commands(&mut self, world: &World, observer: &mut Observer<'_>) -> Vec<Command> {
        let tick = world.tick();
        if tick % 60 == 30 {
            // Where is the first bullet's next wall? (ray along its path)
            if let Some(b) = world.body(nth(&self.bullets, 0)) {
                let filter = QueryFilter {
                    exclude: Some(nth(&self.bullets, 0)),
                    ..QueryFilter::default()
                };
                let hit = world.raycast_filtered(b.position(), b.velocity(), n(100), &filter);
                observer.ray(hit.as_ref());
            }
        }
        let bullet = |shape: Shape<Fx>, position: Vec2<Fx>, velocity: Vec2<Fx>| {
            Command::Spawn(
                BodyDef::dynamic(shape)
                    .position(position)
                    .velocity(velocity)
                    .bullet(true)
                    .restitution(n(1))
                    .friction(n(0)),
            )
        };
        match tick {
            // 33 units per tick against 0.1-thick walls 40 apart (one
            // impact per tick at most).
            100 => vec![bullet(
                Shape::circle(r(1, 20)),
                vf(n(-19), r(1, 2)),
                vi(2000, 0),
            )],
            200 => vec![Command::SetVelocity {
                body: nth(&self.bullets, 0),
                velocity: vi(-1500, 30),
            }],
            // A box bullet (time of impact of a box, i.e. a rounded-box sweep).
            300 => vec![bullet(
                Shape::aabb(vf(r(1, 20), r(1, 20))),
                vf(n(15), r(-3, 2)),
                vi(-3000, 1),
            )],
            // A fast body that is not a bullet (speculative contacts only).
            400 => vec![Command::Spawn(
                BodyDef::dynamic(Shape::circle(r(1, 5)))
                    .position(vi(0, 2))
                    .velocity(vi(900, 0))
                    .restitution(r(1, 2)),
            )],
            _ => Vec::new(),
        }
    }
}

pub(crate) fn bullets_toi() -> Built {
    let world: World = builtin("bullets")?.build()?;
    let bullets = world
        .bodies()
        .filter(|(_, b)| b.is_bullet())
        .map(|(id, _)| id)
        .collect();
    Ok((world, Box::new(Bullets { bullets })))
}
