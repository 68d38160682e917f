//! A stack coming to rest and falling asleep, then woken.
//!
//! Two towers of boxes are dropped onto the ground with small sideways
//! offsets. They settle; once an island has been slow for `time_to_sleep`
//! (0.5 s) its bodies sleep and are drawn blue with an inner outline.
//! Contact points and normals are drawn for every touching pair. At 4 s a
//! heavy ball is thrown in from the left: the bodies it disturbs wake
//! (orange), tumble, and go back to sleep.
//!
//! `cargo run --release -p clockwork2d-render --example demo_stack`
//! writes `docs/demos/stack.gif` (or the path given as an argument).

mod support;

use clockwork2d::prelude::*;
use clockwork2d_render::{Layers, RenderError, View, draw_world};
use support::{Demo, v};

const TICKS: u64 = 540;
const EVERY: u64 = 3;
const THROW_AT: u64 = 240;

fn main() -> Result<(), RenderError> {
    let mut world = World::new(WorldSettings::default());
    let err = |e: WorldError| RenderError::Encode(e.to_string());
    world
        .add_body(BodyDef::fixed(Shape::aabb(v(9.0, 0.5))).position(v(0.0, -0.5)))
        .map_err(err)?;
    // Towers: boxes of 1×0.8 (left) and 0.8×0.8 (right), 0.05 apart, each
    // shifted sideways by a few hundredths (a stack that needs friction).
    let wobble = [0.0, 0.06, -0.04, 0.03, -0.07, 0.05, -0.02];
    for (i, dx) in wobble.iter().enumerate() {
        let y = 0.45 + 0.85 * i as f64;
        world
            .add_body(BodyDef::dynamic(Shape::aabb(v(0.5, 0.4))).position(v(-3.0 + dx, y)))
            .map_err(err)?;
        world
            .add_body(BodyDef::dynamic(Shape::aabb(v(0.4, 0.4))).position(v(3.0 - dx, y)))
            .map_err(err)?;
    }
    let view = View::fit((-7.0, -1.0), (7.0, 6.5), 360, 192, 4);
    let mut demo = Demo::start("stack", view, 6)?;
    let layers = Layers::default();
    for tick in 0..=TICKS {
        if tick == THROW_AT {
            world
                .add_body(
                    BodyDef::dynamic(Shape::circle(fx(0.35)))
                        .position(v(-6.5, 6.0))
                        .velocity(v(14.0, -1.0))
                        .density(fx(4.0)),
                )
                .map_err(err)?;
        }
        if tick % EVERY == 0 {
            let mut canvas = demo.canvas()?;
            draw_world(&mut canvas, &world, &layers);
            canvas.progress_bar(
                tick as f64 / TICKS as f64,
                clockwork2d_render::Colour::Guide,
            );
            demo.add(&canvas)?;
        }
        world.step();
    }
    demo.finish()
}
