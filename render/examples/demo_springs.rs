//! The bendy spring and the rotational (radial) spring.
//!
//! Left: a "bendy" spring, one spring per axis pulling the box toward the
//! anchor's rest point (the ring), stiffer along y than along x (k_y = 4
//! k_x, so it oscillates twice as fast vertically): released off to the
//! side, the box traces a Lissajous figure, slowly shrinking with the
//! damping.
//!
//! Right: the rotational spring, a pole on a pivot with a spring along it:
//! it pushes and pulls only along the pivot→ball line, so the ball swings
//! freely around the pivot under gravity while the pole stretches and
//! shortens.
//!
//! The trails show the last two seconds of each path.
//!
//! `cargo run --release -p clockwork2d-render --example demo_springs`
//! writes `docs/demos/springs.gif` (or the path given as an argument).

mod support;

use clockwork2d::prelude::*;
use clockwork2d_render::{Colour, Layers, RenderError, View, draw_world};
use support::{Demo, Trail, v};

const TICKS: u64 = 420;
const EVERY: u64 = 3;

fn main() -> Result<(), RenderError> {
    let err = |e: WorldError| RenderError::Encode(e.to_string());
    // Gravity only shifts the bendy spring's rest point down by
    // m·g/k_y = 0.25, so both demos share one world with default gravity.
    let mut world = World::new(WorldSettings::default());
    let anchor = v(-4.0, 3.0);
    let block = world
        .add_body(
            BodyDef::dynamic(Shape::aabb(v(0.3, 0.3)))
                .mass(fx(1.0))
                .position(v(-1.5, 4.5)),
        )
        .map_err(err)?;
    world
        .add_constraint(Constraint::bendy_spring(
            Anchor::Point(anchor),
            Anchor::Body(block),
            v(10.0, 40.0),
            fx(0.15),
        ))
        .map_err(err)?;
    let pivot = v(4.0, 3.0);
    let ball = world
        .add_body(
            BodyDef::dynamic(Shape::circle(fx(0.3)))
                .mass(fx(1.0))
                .position(v(6.5, 3.0)),
        )
        .map_err(err)?;
    world
        .add_constraint(Constraint::radial_spring(
            Anchor::Point(pivot),
            Anchor::Body(ball),
            fx(2.0),
            fx(30.0),
            fx(0.1),
        ))
        .map_err(err)?;
    let view = View::fit((-7.0, -0.5), (7.0, 6.5), 360, 180, 4);
    let mut demo = Demo::start("springs", view, 5)?;
    let (mut block_trail, mut ball_trail) = (Trail::new(120), Trail::new(120));
    for tick in 0..=TICKS {
        if let (Some(a), Some(b)) = (world.body(block), world.body(ball)) {
            block_trail.push(a.position().to_f64());
            ball_trail.push(b.position().to_f64());
        }
        if tick % EVERY == 0 {
            let mut canvas = demo.canvas()?;
            block_trail.draw(&mut canvas, Colour::Accent);
            ball_trail.draw(&mut canvas, Colour::Accent);
            // The circle the pole's rest length sweeps, for reference.
            canvas.stroke_circle(pivot.to_f64(), 2.0, 1.0, Colour::Guide);
            draw_world(&mut canvas, &world, &Layers::default());
            demo.add(&canvas)?;
        }
        world.step();
    }
    demo.finish()
}
