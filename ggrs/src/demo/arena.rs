//! The arena of the example game.

use clockwork2d::prelude::*;

/// The arena and the ids the rules need.
#[derive(Clone, Debug)]
pub struct Arena {
    /// The world at frame 0.
    pub world: World,
    /// The players' bodies, by player handle.
    pub players: [BodyId; 2],
    /// The loose balls.
    pub balls: Vec<BodyId>,
    /// The box hanging from the ceiling on a spring.
    pub spring_box: BodyId,
}

/// Builds the arena: walls and ceiling (what the ropes hook on), a stack of
/// five boxes in the middle, six balls, a box hanging on a radial spring
/// from the ceiling, and the two players on either side.
///
/// # Errors
/// A [`WorldError`] if a body is refused (it never is: every value is a
/// valid constant; the error is passed on rather than unwrapped).
pub fn arena() -> Result<Arena, WorldError> {
    let mut world = World::new(WorldSettings::default());
    // Walls 1 unit thick around the inside x ∈ [-12, 12], y ∈ [0, 12]:
    // (half extents, centre) of floor, ceiling, left and right wall.
    for (half, centre) in [
        ((13.0, 0.5), (0.0, -0.5)),
        ((13.0, 0.5), (0.0, 12.5)),
        ((0.5, 6.5), (-12.5, 6.0)),
        ((0.5, 6.5), (12.5, 6.0)),
    ] {
        world.add_body(
            BodyDef::fixed(Shape::aabb(vec2(half.0, half.1))).position(vec2(centre.0, centre.1)),
        )?;
    }
    for level in 0..5 {
        world.add_body(
            BodyDef::dynamic(Shape::aabb(vec2(0.5, 0.5)))
                .position(Vec2::new(Fx::ZERO, fx(0.5).add(Fx::from_int(level))))
                .friction(fx(0.6)),
        )?;
    }
    let mut balls = Vec::new();
    for i in 0..6 {
        let ball = world.add_body(
            BodyDef::dynamic(Shape::circle(fx(0.35)))
                .position(Vec2::new(
                    fx(-7.5).add(Fx::from_int(3 * i)),
                    Fx::from_int(3 + i % 2),
                ))
                .restitution(fx(0.4)),
        )?;
        balls.push(ball);
    }
    let spring_box = world.add_body(
        BodyDef::dynamic(Shape::aabb(vec2(0.4, 0.4)))
            .position(vec2(5.0, 8.0))
            .mass(fx(1.0)),
    )?;
    world.add_constraint(Constraint::radial_spring(
        Anchor::Point(vec2(5.0, 12.0)),
        Anchor::Body(spring_box),
        fx(3.0),
        fx(60.0),
        fx(2.0),
    ))?;
    let mut players = [BodyId::from_parts(0, 0); 2];
    for (player, x) in players.iter_mut().zip([-8.0, 8.0]) {
        *player = world.add_body(
            BodyDef::dynamic(Shape::circle(fx(0.4)))
                .position(vec2(x, 0.4))
                .mass(fx(1.0))
                .friction(fx(0.3)),
        )?;
    }
    Ok(Arena {
        world,
        players,
        balls,
        spring_box,
    })
}
