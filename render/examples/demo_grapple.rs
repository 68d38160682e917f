//! The grapple game: aim, cast, attach, swing, release.
//!
//! A player (the orange ball) in a walled room jumps; while it rises, its
//! aim is drawn as a dashed line. At the top of the jump it casts a ray
//! along the aim (ignoring itself) to the room's walls; the ray and the hit
//! point are drawn. A rope is attached at the hit point with the hit
//! distance as its length, reeled in to 55 % of that at 6 units/s (each
//! tick the rope is replaced by a shorter one with a `RemoveConstraint` +
//! `AddConstraint` command pair), and the player swings on it. Then it lets
//! go, flies on, falls, and aims again. The trail shows the last two
//! seconds of the player's path.
//!
//! The same game, without pictures, is the root crate's `grapple` example.
//!
//! `cargo run --release -p clockwork2d-render --example demo_grapple`
//! writes `docs/demos/grapple.gif` (or the path given as an argument).

mod support;

use clockwork2d::prelude::*;
use clockwork2d_render::{Canvas, Colour, Layers, RenderError, View, draw_ray, draw_world};
use support::{Demo, Trail, v};

/// Inside of the room: x in [-10, 10], y in [0, 10].
const HALF_WIDTH: f64 = 10.0;
const HEIGHT: f64 = 10.0;
/// Scripted aims (any length) and the sideways speed of the jump before each.
const AIMS: [((f64, f64), f64); 3] = [((0.6, 1.0), 2.0), ((-0.8, 1.0), -2.0), ((0.9, 1.0), 3.0)];
const REEL_PER_TICK: f64 = 0.1;
const REEL_TO: f64 = 0.55;
const SWING_TICKS: u32 = 100;
const FALL_TICKS: u32 = 60;
/// How long the cast ray stays drawn after the cast.
const RAY_SHOWN_TICKS: u64 = 12;
const EVERY: u64 = 3;

struct Game {
    world: World,
    player: BodyId,
    demo: Demo,
    trail: Trail,
    /// The aim direction while aiming, drawn from the player.
    aim: Option<Vec2>,
    /// The last cast and the tick it was made.
    cast: Option<(Ray, Option<RayHit>, u64)>,
}

impl Game {
    /// Steps once (with `commands`), recording a frame every `EVERY` ticks.
    fn step(
        &mut self,
        commands: &[Command],
    ) -> Result<Vec<Result<CommandOutcome, WorldError>>, RenderError> {
        let results = self.world.step_with(commands);
        if let Some(b) = self.world.body(self.player) {
            self.trail.push(b.position().to_f64());
        }
        if self.world.tick().is_multiple_of(EVERY) {
            let mut canvas = self.demo.canvas()?;
            self.draw(&mut canvas);
            self.demo.add(&canvas)?;
        }
        Ok(results)
    }

    fn draw(&self, canvas: &mut Canvas) {
        self.trail.draw(canvas, Colour::Accent);
        draw_world(canvas, &self.world, &Layers::default());
        let from = self.world.body(self.player).map(|b| b.position().to_f64());
        if let (Some(d), Some(p)) = (self.aim, from) {
            let (dx, dy) = d.to_f64();
            let len = (dx * dx + dy * dy).sqrt();
            let end = (p.0 + 2.5 * dx / len, p.1 + 2.5 * dy / len);
            canvas.dashed_line(p, end, 1.5, 3.0, Colour::Accent);
        }
        if let Some((ray, hit, at)) = self.cast
            && self.world.tick() - at <= RAY_SHOWN_TICKS
        {
            draw_ray(canvas, &ray, hit.as_ref(), 10.0);
        }
    }
}

fn walls(world: &mut World) -> Result<(), WorldError> {
    let t = 0.5;
    for (half, centre) in [
        ((HALF_WIDTH + 2.0 * t, t), (0.0, -t)),
        ((HALF_WIDTH + 2.0 * t, t), (0.0, HEIGHT + t)),
        ((t, HEIGHT / 2.0 + t), (-HALF_WIDTH - t, HEIGHT / 2.0)),
        ((t, HEIGHT / 2.0 + t), (HALF_WIDTH + t, HEIGHT / 2.0)),
    ] {
        world.add_body(
            BodyDef::fixed(Shape::aabb(v(half.0, half.1))).position(v(centre.0, centre.1)),
        )?;
    }
    Ok(())
}

fn main() -> Result<(), RenderError> {
    let err = |e: WorldError| RenderError::Encode(e.to_string());
    let mut world = World::new(WorldSettings::default());
    walls(&mut world).map_err(err)?;
    let player = world
        .add_body(
            BodyDef::dynamic(Shape::circle(fx(0.3)))
                .mass(fx(1.0))
                .position(v(0.0, 0.3)),
        )
        .map_err(err)?;
    let view = View::fit((-11.0, -1.0), (11.0, 11.0), 330, 180, 2);
    let mut game = Game {
        world,
        player,
        demo: Demo::start("grapple", view, 5)?,
        trail: Trail::new(120),
        aim: None,
        cast: None,
    };
    let filter = QueryFilter {
        exclude: Some(player),
        ..QueryFilter::default()
    };
    for &((ax, ay), jump_x) in &AIMS {
        // Jump, aiming; wait for the top of the jump (at most one second).
        let aim = v(ax, ay);
        game.aim = Some(aim);
        game.step(&[Command::SetVelocity {
            body: player,
            velocity: v(jump_x, 7.0),
        }])?;
        for _ in 0..60 {
            if game
                .world
                .body(player)
                .is_some_and(|b| !b.velocity().y.is_positive())
            {
                break;
            }
            game.step(&[])?;
        }
        // Cast.
        let from = game.world.body(player).map_or(Vec2::ZERO, |b| b.position());
        let hit = game
            .world
            .raycast_filtered(from, aim, fx(100.0), &filter)
            .map(|h| h.hit);
        game.aim = None;
        if let Some(ray) = Ray::new(from, aim, fx(100.0)) {
            game.cast = Some((ray, hit, game.world.tick()));
        }
        let Some(hit) = hit else { continue };
        // Attach, and reel in.
        let attach = Anchor::Point(hit.point);
        let mut length = hit.distance.to_f64();
        let mut rope = game
            .world
            .add_constraint(Constraint::rope(attach, Anchor::Body(player), hit.distance))
            .map_err(err)?;
        let shortest = length * REEL_TO;
        while length > shortest {
            length = (length - REEL_PER_TICK).max(shortest);
            let results = game.step(&[
                Command::RemoveConstraint(rope),
                Command::AddConstraint(Constraint::rope(attach, Anchor::Body(player), fx(length))),
            ])?;
            match results.as_slice() {
                [Ok(_), Ok(CommandOutcome::ConstraintAdded(id))] => rope = *id,
                other => return Err(RenderError::Encode(format!("reeling failed: {other:?}"))),
            }
        }
        // Swing, release, fly and fall.
        for _ in 0..SWING_TICKS {
            game.step(&[])?;
        }
        game.world.remove_constraint(rope).map_err(err)?;
        for _ in 0..FALL_TICKS {
            game.step(&[])?;
        }
    }
    game.demo.finish()
}
