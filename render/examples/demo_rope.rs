//! The rope: a real rope and the mirror rule.
//!
//! Two balls hang from hooks on ropes of length 3, each held 2.5 to the
//! side of its hook at the hook's height, so the rope starts slack (drawn
//! sagging, pale). Released, each falls freely until its rope is taut
//! (drawn straight, dark). Then:
//!
//! * left, a real rope (restitution 0): the velocity along the rope is
//!   removed and the ball swings on as a pendulum;
//! * right, the mirror rule (restitution 1): the velocity along the rope is
//!   reflected, so the ball bounces back inward and the rope goes slack
//!   again, over and over.
//!
//! The trails show the last second of each path.
//!
//! `cargo run --release -p clockwork2d-render --example demo_rope`
//! writes `docs/demos/rope.gif` (or the path given as an argument).

mod support;

use clockwork2d::prelude::*;
use clockwork2d_render::{Colour, Layers, RenderError, View, draw_world};
use support::{Demo, Trail, v};

const TICKS: u64 = 420;
const EVERY: u64 = 3;

fn main() -> Result<(), RenderError> {
    let err = |e: WorldError| RenderError::Encode(e.to_string());
    let mut world = World::new(WorldSettings::default());
    let mut balls = Vec::new();
    for (hook_x, restitution) in [(-3.5, 0.0), (3.5, 1.0)] {
        let hook = v(hook_x, 5.0);
        let ball = world
            .add_body(
                BodyDef::dynamic(Shape::circle(fx(0.25)))
                    .mass(fx(1.0))
                    .position(v(hook_x - 2.5, 5.0)),
            )
            .map_err(err)?;
        world
            .add_constraint(
                Constraint::rope(Anchor::Point(hook), Anchor::Body(ball), fx(3.0))
                    .with_restitution(fx(restitution)),
            )
            .map_err(err)?;
        balls.push((ball, hook.to_f64(), Trail::new(60)));
    }
    let view = View::fit((-7.0, 1.6), (7.0, 5.4), 360, 110, 6);
    let mut demo = Demo::start("rope", view, 5)?;
    for tick in 0..=TICKS {
        for (ball, _, trail) in &mut balls {
            if let Some(b) = world.body(*ball) {
                trail.push(b.position().to_f64());
            }
        }
        if tick % EVERY == 0 {
            let mut canvas = demo.canvas()?;
            for (_, hook, trail) in &balls {
                // The lowest point the rope's full length reaches.
                let low = (hook.0, hook.1 - 3.0);
                canvas.line(
                    (low.0 - 0.4, low.1),
                    (low.0 + 0.4, low.1),
                    1.0,
                    Colour::Guide,
                );
                trail.draw(&mut canvas, Colour::Accent);
            }
            draw_world(&mut canvas, &world, &Layers::default());
            demo.add(&canvas)?;
        }
        world.step();
    }
    demo.finish()
}
