//! The origin document's grapple-rope game: a player in an enclosed arena
//! aims, casts a ray to whatever is in the way, attaches an ideal rope at
//! the hit point, reels it in or out, swings, and lets go.
//!
//! Every control reaches the world as an engine command, applied before the
//! tick like a lockstep game's input: a sideways push is an
//! `ApplyImpulse`, a jump a `SetVelocity`, reeling a `RemoveConstraint` +
//! `AddConstraint` pair (a rope of the new length), firing an
//! `AddConstraint`. So a recorded session replays bit for bit.

use clockwork2d::geometry::Shape;
use clockwork2d::prelude::{
    Anchor, BodyDef, BodyId, BodyRayHit, Command, CommandOutcome, Constraint, ConstraintId, Fx,
    QueryFilter, Scalar, Vec2, World, WorldError, WorldSettings,
};

/// The arena's inside: x in `[-HALF_WIDTH, HALF_WIDTH]`, y in `[0, HEIGHT]`
/// (units).
pub const HALF_WIDTH: i32 = 15;
/// See [`HALF_WIDTH`].
pub const HEIGHT: i32 = 12;
/// The player's radius, 0.3 units (3/10).
const PLAYER_RADIUS: (i32, i32) = (3, 10);
/// Longest rope a shot can make (units): rays stop there.
const REACH: i32 = 30;
/// Shortest rope reeling can make (units).
const SHORTEST: (i32, i32) = (1, 2);
/// Rope length change per tick while reeling: 0.1 units, i.e. 6 units/s at
/// 60 ticks/s.
const REEL_PER_TICK: (i32, i32) = (1, 10);
/// Sideways velocity change per tick while pushing: 1/5 units/s, i.e. an
/// acceleration of 12 units/s² at 60 ticks/s (a bit more than gravity, so
/// pumping a swing works).
const PUSH_PER_TICK: (i32, i32) = (1, 5);
/// Pushing stops adding speed above this sideways speed (units/s).
const PUSH_TOP_SPEED: i32 = 8;
/// Vertical take-off speed of a jump (units/s): rises v²/2g = 2.45 units.
const JUMP_SPEED: i32 = 7;
/// A jump needs ground within this distance below the player's surface
/// (1/20 units): resting contact plus slop.
const GROUND_GAP: (i32, i32) = (1, 20);

fn ratio((n, d): (i32, i32)) -> Fx {
    Fx::from_ratio(n, d)
}

fn int(n: i32) -> Fx {
    Fx::from_int(n)
}

fn v(x: Fx, y: Fx) -> Vec2 {
    Vec2::new(x, y)
}

/// The keys held this tick.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Controls {
    /// Push left.
    pub left: bool,
    /// Push right.
    pub right: bool,
    /// Reel in while roped; jump while standing.
    pub up: bool,
    /// Reel out while roped.
    pub down: bool,
}

/// The rope the player hangs from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rope {
    /// The world's id of the rope constraint.
    pub id: ConstraintId,
    /// Where the ray hit (the fixed end).
    pub anchor: Vec2,
    /// Its current length.
    pub length: Fx,
}

/// The game's state next to its world: the player's body, the rope (if
/// any) and the keys held.
#[derive(Clone, Debug)]
pub struct GrappleGame {
    player: BodyId,
    rope: Option<Rope>,
    controls: Controls,
}

impl GrappleGame {
    /// The arena (walls, floating ledges to hook onto, a few crates and
    /// balls to knock about) and the player standing on the floor at the
    /// left.
    ///
    /// # Errors
    /// A [`WorldError`] cannot happen for these fixed numbers; it is passed
    /// on rather than unwrapped.
    pub fn arena() -> Result<(World, GrappleGame), WorldError> {
        let mut world: World = World::new(WorldSettings::default());
        let (w, h) = (int(HALF_WIDTH), int(HEIGHT));
        // Walls 1 unit thick (half thickness t); the side walls reach from
        // the floor's bottom to the ceiling's top: half height h/2 + 2t.
        let t = ratio((1, 2));
        let side = h.div(int(2)).add(t).add(t);
        let walls = [
            (v(w.add(t).add(t), t), v(Fx::ZERO, t.neg())),
            (v(w.add(t).add(t), t), v(Fx::ZERO, h.add(t))),
            (v(t, side), v(w.add(t).neg(), h.div(int(2)))),
            (v(t, side), v(w.add(t), h.div(int(2)))),
        ];
        // Ledges: (half extents, centre) in tenths of a unit.
        let ledges = [
            ((15, 2), (-80, 75)),
            ((20, 2), (0, 95)),
            ((10, 2), (80, 65)),
            ((5, 5), (30, 35)),
            ((5, 5), (-35, 45)),
        ];
        for (half, centre) in walls {
            world.add_body(BodyDef::fixed(Shape::aabb(half)).position(centre))?;
        }
        for ((hx, hy), (cx, cy)) in ledges {
            let half = v(ratio((hx, 10)), ratio((hy, 10)));
            let centre = v(ratio((cx, 10)), ratio((cy, 10)));
            world.add_body(BodyDef::fixed(Shape::aabb(half)).position(centre))?;
        }
        // A stack of three crates on the right and two balls in the middle.
        let crate_half = ratio((2, 5));
        for k in 0..3 {
            let y = crate_half.add(crate_half.add(crate_half).mul(int(k)));
            world.add_body(
                BodyDef::dynamic(Shape::aabb(v(crate_half, crate_half))).position(v(int(11), y)),
            )?;
        }
        for x in [-2, 2] {
            world.add_body(
                BodyDef::dynamic(Shape::circle(ratio((1, 2))))
                    .position(v(int(x), ratio((1, 2))))
                    .restitution(ratio((1, 2))),
            )?;
        }
        let radius = ratio(PLAYER_RADIUS);
        let player = world.add_body(
            BodyDef::dynamic(Shape::circle(radius))
                .mass(Fx::ONE)
                .position(v(int(-12), radius)),
        )?;
        Ok((
            world,
            GrappleGame {
                player,
                rope: None,
                controls: Controls::default(),
            },
        ))
    }

    /// The player's body.
    #[must_use]
    pub fn player(&self) -> BodyId {
        self.player
    }

    /// The rope, while attached.
    #[must_use]
    pub fn rope(&self) -> Option<Rope> {
        self.rope
    }

    /// Sets the keys held from now on.
    pub fn set_controls(&mut self, controls: Controls) {
        self.controls = controls;
    }

    /// The ray from the player toward `target`, up to 30 units, ignoring
    /// the player itself: what a shot would hit. `None` when nothing is in
    /// reach or `target` is the player's centre (no direction).
    #[must_use]
    pub fn aim(&self, world: &World, target: Vec2) -> Option<BodyRayHit<Fx>> {
        let from = world.body(self.player)?.position();
        let direction = target - from;
        if direction == Vec2::ZERO {
            return None;
        }
        let filter = QueryFilter {
            exclude: Some(self.player),
            ..QueryFilter::default()
        };
        world.raycast_filtered(from, direction, int(REACH), &filter)
    }

    /// Shoots toward `target`: lets go of any rope, casts the ray and, on a
    /// hit, attaches a rope from the hit point to the player, as long as
    /// the distance (at least half a unit). Returns whether a rope was
    /// attached.
    ///
    /// # Errors
    /// A [`WorldError`] if the engine refuses the rope (it has no reason
    /// to for a hit inside the world).
    pub fn fire(&mut self, world: &mut World, target: Vec2) -> Result<bool, WorldError> {
        self.release(world)?;
        let Some(hit) = self.aim(world, target) else {
            return Ok(false);
        };
        let anchor = hit.hit.point;
        let length = Scalar::max(hit.hit.distance, ratio(SHORTEST));
        let id = world.apply(Command::AddConstraint(Constraint::rope(
            Anchor::Point(anchor),
            Anchor::Body(self.player),
            length,
        )))?;
        if let CommandOutcome::ConstraintAdded(id) = id {
            self.rope = Some(Rope { id, anchor, length });
        }
        Ok(self.rope.is_some())
    }

    /// Lets go of the rope. Returns whether there was one.
    ///
    /// # Errors
    /// A [`WorldError`] if the rope was already gone from the world (then
    /// the game forgets it too).
    pub fn release(&mut self, world: &mut World) -> Result<bool, WorldError> {
        match self.rope.take() {
            None => Ok(false),
            Some(rope) => world
                .apply(Command::RemoveConstraint(rope.id))
                .map(|_| true),
        }
    }

    /// This tick's commands from the keys held (see the module docs).
    #[must_use]
    pub fn commands(&self, world: &World) -> Vec<Command> {
        let mut out = Vec::new();
        let Some(body) = world.body(self.player) else {
            return out;
        };
        let velocity = body.velocity();
        let push = ratio(PUSH_PER_TICK);
        let top = int(PUSH_TOP_SPEED);
        let mut dv = Fx::ZERO;
        if self.controls.right && velocity.x < top {
            dv = dv.add(push);
        }
        if self.controls.left && velocity.x > top.neg() {
            dv = dv.sub(push);
        }
        if dv != Fx::ZERO {
            out.push(Command::ApplyImpulse {
                body: self.player,
                impulse: v(dv.mul(body.mass()), Fx::ZERO),
            });
        }
        match self.rope {
            Some(rope) => {
                let step = ratio(REEL_PER_TICK);
                let length = if self.controls.up && !self.controls.down {
                    Scalar::max(rope.length.sub(step), ratio(SHORTEST))
                } else if self.controls.down && !self.controls.up {
                    Scalar::min(rope.length.add(step), int(REACH))
                } else {
                    rope.length
                };
                if length != rope.length {
                    out.push(Command::RemoveConstraint(rope.id));
                    out.push(Command::AddConstraint(Constraint::rope(
                        Anchor::Point(rope.anchor),
                        Anchor::Body(self.player),
                        length,
                    )));
                }
            }
            None => {
                if self.controls.up && self.standing(world) {
                    out.push(Command::SetVelocity {
                        body: self.player,
                        velocity: v(velocity.x, int(JUMP_SPEED)),
                    });
                }
            }
        }
        out
    }

    /// Whether something is right under the player (a short ray down).
    fn standing(&self, world: &World) -> bool {
        let Some(body) = world.body(self.player) else {
            return false;
        };
        let filter = QueryFilter {
            exclude: Some(self.player),
            ..QueryFilter::default()
        };
        let reach = ratio(PLAYER_RADIUS).add(ratio(GROUND_GAP));
        world
            .raycast_filtered(body.position(), v(Fx::ZERO, Fx::ONE.neg()), reach, &filter)
            .is_some()
    }

    /// One tick: this tick's commands from the keys held, then the step.
    /// A reel replaces the rope; the game follows the new constraint's id.
    pub fn step(&mut self, world: &mut World) {
        let commands = self.commands(world);
        let results = world.step_with(&commands);
        for (command, result) in commands.iter().zip(&results) {
            if let (
                Command::AddConstraint(Constraint::Rope { max_length, .. }),
                Ok(CommandOutcome::ConstraintAdded(id)),
            ) = (command, result)
                && let Some(rope) = &mut self.rope
            {
                rope.id = *id;
                rope.length = *max_length;
            }
        }
    }
}
