//! # clockwork2d-render
//!
//! Pictures of [clockwork2d] worlds: bodies (sleeping ones
//! drawn differently), contacts with their closest points and normals,
//! springs, ropes, rays and hits, drawn with `tiny-skia` and written as a
//! PNG (one picture) or a small animated GIF.
//!
//! Rendering is at the edge of the engine: it reads a world's fixed-point
//! state, converts it to `f64`/`f32` and draws. Nothing here feeds back into
//! a simulation, so floats are fine here and the engine's determinism does
//! not depend on this crate.
//!
//! ```
//! use clockwork2d::prelude::*;
//! use clockwork2d_render::{Canvas, Colour, Layers, draw_world, view_of_world};
//!
//! let mut world = World::new(WorldSettings::default());
//! world.add_body(BodyDef::fixed(Shape::aabb(Vec2::new(fx(4.0), fx(0.5))))).unwrap();
//! let ball = world
//!     .add_body(BodyDef::dynamic(Shape::circle(fx(0.5))).position(Vec2::new(fx(0.0), fx(2.0))))
//!     .unwrap();
//! let mut canvas = Canvas::new(view_of_world(&world, 160, 120).unwrap()).unwrap();
//! draw_world(&mut canvas, &world, &Layers::default());
//! let centre = world.body(ball).unwrap().position().to_f64();
//! assert_eq!(canvas.colour_at_world(centre), Some(Colour::Awake));
//! ```
#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod body_drawing;
mod canvas;
mod constraint_drawing;
mod contact_drawing;
mod contact_points;
mod error;
mod gif_recorder;
mod output_format;
mod palette;
mod png_output;
mod ray_drawing;
mod render_run;
mod view;
mod world_drawing;

pub use body_drawing::{body_colour, draw_body, draw_shape};
pub use canvas::{Canvas, MAX_SIDE};
pub use constraint_drawing::{anchor_position, draw_constraint};
pub use contact_drawing::draw_contact;
pub use contact_points::{ContactPoints, contact_points};
pub use error::RenderError;
pub use gif_recorder::{GifRecorder, UNCHANGED, gif_global_palette};
pub use output_format::OutputFormat;
pub use palette::Colour;
pub use png_output::write_png;
pub use ray_drawing::draw_ray;
pub use render_run::{RenderOptions, RenderSummary, render_run};
pub use view::View;
pub use world_drawing::{Layers, MIN_CONTACT_BODY_PX, draw_world, view_of_world, world_extent};
