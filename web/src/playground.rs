//! [`Playground`]: the world the page shows, and what the page can do to
//! it.

use clockwork2d::geometry::Shape;
use clockwork2d::prelude::{BodyDef, Command, Fx, QueryFilter, Scalar, Vec2, World};
use clockwork2d_scene::{BUILTIN_SCENES, SceneError, builtin};
use wasm_bindgen::prelude::wasm_bindgen;

use crate::PlaygroundError;
use crate::determinism::hash_text;
use crate::draw;
use crate::edge::to_vec2;
use crate::grapple::{Controls, GrappleGame};

/// The name of the grapple game's arena in the page's scene list (not a
/// built-in scene of the library: it is a game, with a player and keys).
pub const GRAPPLE_SCENE: &str = "grapple";

/// Radius of a dropped ball and half size of a dropped box: 0.4 units.
const DROP_SIZE: (i32, i32) = (2, 5);

/// The built-in scenes' names, in the library's order, then
/// [`GRAPPLE_SCENE`].
#[wasm_bindgen(js_name = sceneNames)]
#[must_use]
pub fn scene_names() -> Vec<String> {
    BUILTIN_SCENES
        .iter()
        .map(|(name, _)| (*name).to_owned())
        .chain(core::iter::once(GRAPPLE_SCENE.to_owned()))
        .collect()
}

/// One world built from a built-in scene or the grapple arena.
#[wasm_bindgen]
pub struct Playground {
    scene: String,
    world: World,
    grapple: Option<GrappleGame>,
}

#[wasm_bindgen]
impl Playground {
    /// Builds the scene called `scene` (see [`scene_names`]).
    ///
    /// # Errors
    /// [`PlaygroundError::UnknownScene`] for another name.
    #[wasm_bindgen(constructor)]
    pub fn new(scene: &str) -> Result<Playground, PlaygroundError> {
        let (world, grapple) = if scene == GRAPPLE_SCENE {
            let (world, game) = GrappleGame::arena()?;
            (world, Some(game))
        } else {
            let built = builtin(scene).map_err(|e| match e {
                SceneError::Unknown(name) => PlaygroundError::UnknownScene(name),
                other => PlaygroundError::Scene(other),
            })?;
            (built.build()?, None)
        };
        Ok(Playground {
            scene: scene.to_owned(),
            world,
            grapple,
        })
    }

    /// The scene's name.
    #[must_use]
    pub fn scene(&self) -> String {
        self.scene.clone()
    }

    /// Advances one tick (in the grapple arena, the keys held first become
    /// this tick's commands).
    pub fn step(&mut self) {
        match &mut self.grapple {
            Some(game) => game.step(&mut self.world),
            None => self.world.step(),
        }
    }

    /// Ticks since the scene was built (saturating at `u32::MAX`, 2.2 years
    /// at 60 ticks/s).
    #[must_use]
    pub fn tick(&self) -> u32 {
        u32::try_from(self.world.tick()).unwrap_or(u32::MAX)
    }

    /// The state hash as the CLI prints it: `0x` and 16 hex digits.
    #[must_use]
    pub fn hash(&self) -> String {
        hash_text(self.world.state_hash())
    }

    /// Number of bodies.
    #[wasm_bindgen(js_name = bodyCount)]
    #[must_use]
    pub fn body_count(&self) -> u32 {
        u32::try_from(self.world.body_count()).unwrap_or(u32::MAX)
    }

    /// Number of constraints (springs and ropes).
    #[wasm_bindgen(js_name = constraintCount)]
    #[must_use]
    pub fn constraint_count(&self) -> u32 {
        u32::try_from(self.world.constraints().count()).unwrap_or(u32::MAX)
    }

    /// Drops a dynamic `"ball"` (radius 0.4) or `"box"` (0.8 × 0.8) with
    /// its centre at `(x, y)`, through a `Spawn` command. Returns the new
    /// body count.
    ///
    /// # Errors
    /// [`PlaygroundError::UnknownShape`], a number that is not finite or
    /// out of range, or the engine's refusal (outside the world bounds);
    /// the world is unchanged.
    #[wasm_bindgen(js_name = dropBody)]
    pub fn drop_body(&mut self, x: f64, y: f64, shape: &str) -> Result<u32, PlaygroundError> {
        let size = Fx::from_ratio(DROP_SIZE.0, DROP_SIZE.1);
        let shape = match shape {
            "ball" => Shape::circle(size),
            "box" => Shape::aabb(Vec2::new(size, size)),
            other => return Err(PlaygroundError::UnknownShape(other.to_owned())),
        };
        let position = to_vec2(x, y, "drop position")?;
        self.world
            .apply(Command::Spawn(BodyDef::dynamic(shape).position(position)))?;
        Ok(self.body_count())
    }

    /// Changes the velocity of the dynamic body under `(x, y)` by
    /// `(dvx, dvy)` units/s, through an `ApplyImpulse` command of
    /// `mass · dv`. Returns whether a dynamic body was there (the first in
    /// id order when several overlap).
    ///
    /// # Errors
    /// A number that is not finite or out of range, or the engine's refusal
    /// (an impulse beyond its limits); the world is unchanged.
    pub fn push(&mut self, x: f64, y: f64, dvx: f64, dvy: f64) -> Result<bool, PlaygroundError> {
        let point = to_vec2(x, y, "push position")?;
        let dv = to_vec2(dvx, dvy, "velocity change")?;
        let filter = QueryFilter {
            fixed: false,
            kinematic: false,
            ..QueryFilter::default()
        };
        let Some(&body) = self.world.query_point(point, &filter).first() else {
            return Ok(false);
        };
        let mass = self.world.body(body).map_or(Fx::ZERO, |b| b.mass());
        self.world.apply(Command::ApplyImpulse {
            body,
            impulse: dv.scale(mass),
        })?;
        Ok(true)
    }

    /// Every body, [`BODY_STRIDE`](crate::BODY_STRIDE) numbers each (a
    /// `Float32Array` in the page).
    #[must_use]
    pub fn bodies(&self) -> Vec<f32> {
        draw::bodies(&self.world)
    }

    /// Every constraint, [`CONSTRAINT_STRIDE`](crate::CONSTRAINT_STRIDE)
    /// numbers each.
    #[must_use]
    pub fn constraints(&self) -> Vec<f32> {
        draw::constraints(&self.world)
    }

    /// The centres of every touching pair, 4 numbers each.
    #[must_use]
    pub fn contacts(&self) -> Vec<f32> {
        draw::contacts(&self.world)
    }

    /// Whether this is the grapple arena.
    #[wasm_bindgen(js_name = isGrapple)]
    #[must_use]
    pub fn is_grapple(&self) -> bool {
        self.grapple.is_some()
    }

    /// Grapple: where a shot toward `(x, y)` would hit, `[x, y]`, or an
    /// empty list when nothing is within reach.
    ///
    /// # Errors
    /// [`PlaygroundError::NotGrapple`] outside the arena; a number that is
    /// not finite or out of range.
    pub fn aim(&self, x: f64, y: f64) -> Result<Vec<f32>, PlaygroundError> {
        let game = self.grapple.as_ref().ok_or(PlaygroundError::NotGrapple)?;
        let target = to_vec2(x, y, "aim")?;
        Ok(game.aim(&self.world, target).map_or_else(Vec::new, |hit| {
            let p = hit.hit.point;
            vec![p.x.to_num::<f32>(), p.y.to_num::<f32>()]
        }))
    }

    /// Grapple: shoots toward `(x, y)` and attaches a rope at the hit.
    /// Returns whether a rope was attached.
    ///
    /// # Errors
    /// As [`aim`](Self::aim), or the engine's refusal of the rope.
    pub fn fire(&mut self, x: f64, y: f64) -> Result<bool, PlaygroundError> {
        let target = to_vec2(x, y, "aim")?;
        let game = self.grapple.as_mut().ok_or(PlaygroundError::NotGrapple)?;
        Ok(game.fire(&mut self.world, target)?)
    }

    /// Grapple: lets go of the rope. Returns whether there was one.
    ///
    /// # Errors
    /// [`PlaygroundError::NotGrapple`] outside the arena.
    pub fn release(&mut self) -> Result<bool, PlaygroundError> {
        let game = self.grapple.as_mut().ok_or(PlaygroundError::NotGrapple)?;
        Ok(game.release(&mut self.world)?)
    }

    /// Grapple: the keys held from the next tick on (left/right push, up
    /// reels in or jumps, down reels out).
    ///
    /// # Errors
    /// [`PlaygroundError::NotGrapple`] outside the arena.
    #[wasm_bindgen(js_name = setControls)]
    pub fn set_controls(
        &mut self,
        left: bool,
        right: bool,
        up: bool,
        down: bool,
    ) -> Result<(), PlaygroundError> {
        let game = self.grapple.as_mut().ok_or(PlaygroundError::NotGrapple)?;
        game.set_controls(Controls {
            left,
            right,
            up,
            down,
        });
        Ok(())
    }

    /// Grapple: `[player_x, player_y]`, then `[anchor_x, anchor_y, length]`
    /// while roped; empty outside the arena.
    #[wasm_bindgen(js_name = grappleState)]
    #[must_use]
    pub fn grapple_state(&self) -> Vec<f32> {
        let Some(game) = &self.grapple else {
            return Vec::new();
        };
        let mut out = Vec::with_capacity(5);
        if let Some(body) = self.world.body(game.player()) {
            let p = body.position();
            out.extend_from_slice(&[p.x.to_num::<f32>(), p.y.to_num::<f32>()]);
        }
        if let Some(rope) = game.rope() {
            out.extend_from_slice(&[
                rope.anchor.x.to_num::<f32>(),
                rope.anchor.y.to_num::<f32>(),
                rope.length.to_num::<f32>(),
            ]);
        }
        out
    }
}

impl Playground {
    /// The world (for native callers and tests).
    #[must_use]
    pub fn world(&self) -> &World {
        &self.world
    }

    /// The grapple game, in the grapple arena.
    #[must_use]
    pub fn grapple(&self) -> Option<&GrappleGame> {
        self.grapple.as_ref()
    }
}
