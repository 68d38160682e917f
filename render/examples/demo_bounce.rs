//! Balls bouncing with different restitution.
//!
//! Five balls are dropped from the same height (the faint line) onto the
//! ground, with restitution 0, 0.25, 0.5, 0.75 and 1 from left to right
//! (the ground's is 0; a contact uses the larger of the two). Each bounce
//! leaves at `e` times the impact speed, so it rises to `e²` of the height
//! it fell from: the faint marks show `e²·h` above the ground for each
//! ball, which its first bounce reaches. The trails show the last half
//! second of each path.
//!
//! `cargo run --release -p clockwork2d-render --example demo_bounce`
//! writes `docs/demos/bounce.gif` (or the path given as an argument).

mod support;

use clockwork2d::prelude::*;
use clockwork2d_render::{Colour, Layers, RenderError, View, draw_world};
use support::{Demo, Trail, v};

const TICKS: u64 = 360;
const EVERY: u64 = 2;
const RESTITUTION: [f64; 5] = [0.0, 0.25, 0.5, 0.75, 1.0];
const RADIUS: f64 = 0.3;
/// Drop height of the balls' bottoms above the ground.
const HEIGHT: f64 = 5.0;

fn main() -> Result<(), RenderError> {
    let err = |e: WorldError| RenderError::Encode(e.to_string());
    let mut world = World::new(WorldSettings::default());
    world
        .add_body(BodyDef::fixed(Shape::aabb(v(6.0, 0.5))).position(v(0.0, -0.5)))
        .map_err(err)?;
    let mut balls = Vec::new();
    for (i, &e) in RESTITUTION.iter().enumerate() {
        let x = -4.0 + 2.0 * i as f64;
        let id = world
            .add_body(
                BodyDef::dynamic(Shape::circle(fx(RADIUS)))
                    .position(v(x, HEIGHT + RADIUS))
                    .restitution(fx(e)),
            )
            .map_err(err)?;
        balls.push((id, x, e, Trail::new(30)));
    }
    let view = View::fit((-5.5, -0.8), (5.5, 6.0), 320, 200, 4);
    let mut demo = Demo::start("bounce", view, 3)?;
    for tick in 0..=TICKS {
        for (id, _, _, trail) in &mut balls {
            if let Some(b) = world.body(*id) {
                trail.push(b.position().to_f64());
            }
        }
        if tick % EVERY == 0 {
            let mut canvas = demo.canvas()?;
            canvas.line((-5.5, HEIGHT), (5.5, HEIGHT), 1.0, Colour::Guide);
            for (_, x, e, trail) in &balls {
                let top = e * e * HEIGHT;
                canvas.line((x - 0.5, top), (x + 0.5, top), 1.0, Colour::Guide);
                trail.draw(&mut canvas, Colour::Accent);
            }
            draw_world(&mut canvas, &world, &Layers::default());
            demo.add(&canvas)?;
        }
        world.step();
    }
    demo.finish()
}
