//! The origin document's three overlap tests, with closest points and
//! normals: circle–circle, box–box, and circle–box in both of its cases
//! (the circle's centre outside the box, and inside it).
//!
//! Four panels; in each, shape `a` (grey) stays put and shape `b` moves
//! around or through it. `b` is drawn orange while apart and red while
//! they overlap. The magenta segment joins the closest points the engine's
//! contact gives (its length is the gap, or the depth when they overlap),
//! and the green arrow is the contact normal, from `a` to `b`.
//!
//! `cargo run --release -p clockwork2d-render --example demo_overlap`
//! writes `docs/demos/overlap.gif` (or the path given as an argument).

mod support;

use std::f64::consts::TAU;

use clockwork2d::prelude::*;
use clockwork2d_render::{Colour, RenderError, View, contact_points, draw_contact, draw_shape};
use support::Demo;

/// Frames in one loop (the motion is periodic, so the GIF loops cleanly).
const FRAMES: u32 = 96;

/// One panel: a fixed shape, a moving one, and the moving one's path.
struct Panel {
    centre: (f64, f64),
    a: Shape,
    b: Shape,
    /// Offset of `b` from the panel centre at phase `t` in [0, 1).
    path: fn(f64) -> (f64, f64),
}

fn main() -> Result<(), RenderError> {
    let circle = |r: f64| Shape::circle(fx(r));
    let aabb = |w: f64, h: f64| Shape::aabb(Vec2::new(fx(w), fx(h)));
    // An orbit whose radius swings between 0.9 and 3.1: apart, grazing,
    // overlapping, and back. Two radius cycles per turn.
    let orbit = |t: f64| {
        let r = 2.0 + 1.1 * (2.0 * TAU * t).cos();
        (r * (TAU * t).cos(), r * (TAU * t).sin())
    };
    let panels = [
        Panel {
            centre: (-4.5, 3.5),
            a: circle(1.0),
            b: circle(0.7),
            path: orbit,
        },
        Panel {
            centre: (4.5, 3.5),
            a: aabb(1.2, 0.8),
            b: aabb(0.6, 0.5),
            path: orbit,
        },
        Panel {
            centre: (-4.5, -3.5),
            a: aabb(1.2, 0.8),
            b: circle(0.6),
            path: orbit,
        },
        // Centre inside: a small box's worth of path inside a large box,
        // passing near every face so the chosen face changes.
        Panel {
            centre: (4.5, -3.5),
            a: aabb(2.4, 1.6),
            b: circle(0.5),
            path: |t| (2.0 * (TAU * t).cos(), 1.3 * (2.0 * TAU * t).sin()),
        },
    ];
    let view = View::fit((-9.0, -7.0), (9.0, 7.0), 360, 280, 4);
    let mut demo = Demo::start("overlap", view, 5)?;
    for frame in 0..FRAMES {
        let t = f64::from(frame) / f64::from(FRAMES);
        let mut canvas = demo.canvas()?;
        for panel in &panels {
            let (cx, cy) = panel.centre;
            canvas.stroke_box(panel.centre, (4.3, 3.3), 1.0, Colour::Guide);
            let (dx, dy) = (panel.path)(t);
            let pa = Vec2::new(fx(cx), fx(cy));
            let pb = Vec2::new(fx(cx + dx), fx(cy + dy));
            let points = contact_points(&panel.a, pa, &panel.b, pb);
            let overlapping = points.contact.separation.is_negative();
            draw_shape(&mut canvas, &panel.a, pa.to_f64(), Colour::Fixed);
            let colour = if overlapping {
                Colour::Bullet
            } else {
                Colour::Awake
            };
            draw_shape(&mut canvas, &panel.b, pb.to_f64(), colour);
            draw_contact(&mut canvas, &points, 14.0);
        }
        demo.add(&canvas)?;
    }
    demo.finish()
}
