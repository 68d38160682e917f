//! The clockwork2d web playground: the engine compiled to
//! `wasm32-unknown-unknown` with `wasm-bindgen`, driven by `web/www/`.
//!
//! The page (`web/www/index.html` + `app.js`) owns the canvas, the mouse and
//! the keyboard; this crate owns the world. Every interaction reaches the
//! world as an engine [`Command`](clockwork2d::prelude::Command) or a query, exactly
//! as a game would send it:
//!
//! * [`Playground`]: one world built from a built-in scene (or the grapple
//!   arena), stepped, clicked and dragged, read back as flat draw lists;
//! * [`GrappleGame`](grapple::GrappleGame): the origin document's rope game
//!   (aim, ray cast, attach a rope, reel, swing, release);
//! * [`determinism_hash`]: the fixed input script the page's determinism
//!   panel replays, compared there with the hash the native CLI computed at
//!   build time.
//!
//! Everything here also compiles natively (`cargo test` runs its tests on
//! the host). Floats appear only at the edge: numbers coming from the page
//! are converted once to `Fx` (and refused when not finite or out of
//! range), and positions go back to the page as `f32` for drawing. No float
//! arithmetic happens here (the lint below).
#![forbid(unsafe_code)]
#![deny(clippy::float_arithmetic)]

mod determinism;
mod draw;
mod edge;
pub mod grapple;
mod playground;

pub use determinism::determinism_hash;
pub use draw::{BODY_STRIDE, CONSTRAINT_STRIDE};
pub use edge::PlaygroundError;
pub use playground::{GRAPPLE_SCENE, Playground, scene_names};
