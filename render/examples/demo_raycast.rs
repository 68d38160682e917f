//! Ray casts against circles and boxes, with bullets.
//!
//! A turret (bottom left) sweeps a fan of seven rays across a field of
//! fixed circles and boxes and a few loose ones. Each ray is drawn to its
//! first hit (`World::raycast_all`, skipping bullets), with the hit point and the surface normal
//! there; a ray that hits nothing within its range is dashed.
//!
//! Every third of a second the turret also fires a bullet along its middle
//! ray at 45 units/s: 0.75 units per step, more than the 0.2-unit thickness
//! of the thin plates. Bullets use exact time of impact, so they hit the
//! plates and bounce instead of tunnelling through. The trails show each
//! bullet's last third of a second.
//!
//! `cargo run --release -p clockwork2d-render --example demo_raycast`
//! writes `docs/demos/raycast.gif` (or the path given as an argument).

mod support;

use clockwork2d::prelude::*;
use clockwork2d_render::{Colour, Layers, RenderError, View, draw_ray, draw_world};
use support::{Demo, Trail, v};

const TICKS: u64 = 300;
const EVERY: u64 = 3;
const FIRE_EVERY: u64 = 20;
/// A bullet is removed this many ticks after it is fired.
const BULLET_LIFE: u64 = 100;
const RAYS: usize = 7;
const RANGE: f64 = 14.0;

fn main() -> Result<(), RenderError> {
    let err = |e: WorldError| RenderError::Encode(e.to_string());
    let mut world = World::new(WorldSettings::default());
    let fixed = |world: &mut World, shape: Shape, x: f64, y: f64| {
        world.add_body(BodyDef::fixed(shape).position(v(x, y)))
    };
    fixed(&mut world, Shape::aabb(v(9.0, 0.5)), 0.0, -0.5).map_err(err)?;
    fixed(&mut world, Shape::circle(fx(0.8)), 1.0, 4.5).map_err(err)?;
    fixed(&mut world, Shape::circle(fx(0.5)), -1.5, 6.5).map_err(err)?;
    fixed(&mut world, Shape::circle(fx(1.1)), 5.5, 6.8).map_err(err)?;
    fixed(&mut world, Shape::aabb(v(1.0, 0.6)), 4.0, 2.5).map_err(err)?;
    // Thin plates: a bullet moves 0.75 per step, 3.75 plate thicknesses.
    fixed(&mut world, Shape::aabb(v(0.1, 2.0)), 8.0, 4.0).map_err(err)?;
    fixed(&mut world, Shape::aabb(v(2.0, 0.1)), -3.0, 8.5).map_err(err)?;
    for (i, x) in [1.5, 2.5].iter().enumerate() {
        world
            .add_body(
                BodyDef::dynamic(Shape::aabb(v(0.4, 0.4))).position(v(*x, 0.4 + 0.85 * i as f64)),
            )
            .map_err(err)?;
    }
    world
        .add_body(BodyDef::dynamic(Shape::circle(fx(0.45))).position(v(6.0, 0.45)))
        .map_err(err)?;

    let turret = v(-7.5, 1.0);
    let view = View::fit((-8.5, -0.2), (8.5, 9.0), 320, 180, 4);
    let mut demo = Demo::start("raycast", view, 5)?;
    let mut bullets: Vec<(BodyId, u64, Trail)> = Vec::new();
    for tick in 0..=TICKS {
        // The fan's middle direction sweeps between 15° and 75° and back.
        let phase = tick as f64 / TICKS as f64 * std::f64::consts::TAU;
        let middle = (45.0 - 30.0 * phase.cos()).to_radians();
        let direction = |k: usize| {
            let a = middle + (k as f64 - (RAYS / 2) as f64) * 4f64.to_radians();
            v(a.cos(), a.sin())
        };
        if tick % FIRE_EVERY == 0 && tick + 60 < TICKS {
            let d = direction(RAYS / 2);
            let speed = fx(45.0);
            let bullet = world
                .add_body(
                    BodyDef::dynamic(Shape::circle(fx(0.12)))
                        .bullet(true)
                        .restitution(fx(0.6))
                        .gravity_scale(fx(0.3))
                        .position(turret)
                        .velocity(Vec2::new(d.x * speed, d.y * speed)),
                )
                .map_err(err)?;
            bullets.push((bullet, tick, Trail::new(20)));
        }
        bullets.retain(|(id, fired, _)| {
            let keep = tick - fired < BULLET_LIFE;
            if !keep {
                let _ = world.remove_body(*id);
            }
            keep
        });
        for (id, _, trail) in &mut bullets {
            if let Some(b) = world.body(*id) {
                trail.push(b.position().to_f64());
            }
        }
        if tick % EVERY == 0 {
            let mut canvas = demo.canvas()?;
            for (_, _, trail) in &bullets {
                trail.draw(&mut canvas, Colour::Accent);
            }
            draw_world(&mut canvas, &world, &Layers::default());
            for k in 0..RAYS {
                let d = direction(k);
                // The first hit on anything but a bullet (the rays show the
                // scene; the bullets fly through them).
                let hit = world
                    .raycast_all(turret, d, fx(RANGE), &QueryFilter::default())
                    .into_iter()
                    .find(|h| world.body(h.body).is_some_and(|b| !b.is_bullet()))
                    .map(|h| h.hit);
                if let Some(ray) = Ray::new(turret, d, fx(RANGE)) {
                    draw_ray(&mut canvas, &ray, hit.as_ref(), 8.0);
                }
            }
            canvas.dot(turret.to_f64(), 4.0, Colour::Ink);
            demo.add(&canvas)?;
        }
        world.step();
    }
    demo.finish()
}
