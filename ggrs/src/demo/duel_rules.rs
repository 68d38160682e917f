//! [`DuelRules`]: the game's input → command mapping.

use std::sync::atomic::{AtomicU32, Ordering};

use clockwork2d::prelude::*;
use ggrs::{InputStatus, PlayerHandle};

use super::{AIM_DIRECTIONS, DuelInput};
use crate::InputCommands;

/// Sideways impulse per frame of a held move button (mass 1: 0.08 units/s
/// per frame, 4.8 units/s² at 60 Hz, about half of gravity).
fn move_impulse() -> Fx {
    fx(0.08)
}

/// Upward impulse of a jump (mass 1: 5 units/s, a jump of v²/2g ≈ 1.3
/// units).
fn jump_impulse() -> Fx {
    fx(5.0)
}

/// A jump is allowed only while the vertical speed is below this (standing,
/// or at the top of an arc): holding the button does not fly.
fn jump_speed_limit() -> Fx {
    fx(0.25)
}

/// Reach of the grapple (the arena's diagonal is about 34 units).
fn grapple_reach() -> Fx {
    fx(40.0)
}

/// A deliberate desynchronisation, for testing detection: on one peer, at
/// world tick `tick`, `body` receives an extra impulse.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DesyncInjection {
    /// The world tick at which the impulse is applied (frame = tick for a
    /// session started at tick 0).
    pub tick: u64,
    /// The body pushed.
    pub body: BodyId,
    /// The impulse.
    pub impulse: Vec2,
}

/// The rules: each player steers their ball (left, right, jump) and fires
/// a grapple rope.
///
/// The grapple is the origin document's rope: while the grapple button is
/// held and no rope is attached, a ray is cast from the player (ignoring the
/// player) in the aim direction; on a hit a rope of the hit distance is
/// attached from the hit point to the player, who then swings on it; when
/// the button is released the rope is removed. The rope is found again each
/// frame by looking in the world for the rope that holds the player, so the
/// world is the whole game state.
#[derive(Clone, Debug)]
pub struct DuelRules {
    /// The players' bodies, by handle.
    pub players: [BodyId; 2],
    /// A deliberate desynchronisation (only on one peer).
    pub inject: Option<DesyncInjection>,
}

impl DuelRules {
    /// Rules for these players, without injection.
    #[must_use]
    pub fn new(players: [BodyId; 2]) -> Self {
        DuelRules {
            players,
            inject: None,
        }
    }

    /// The rope that holds `player`, if one is attached.
    #[must_use]
    pub fn rope_of(world: &World, player: BodyId) -> Option<ConstraintId> {
        world.constraints().find_map(|(id, c)| match c {
            Constraint::Rope {
                b: Anchor::Body(b), ..
            } if *b == player => Some(id),
            _ => None,
        })
    }
}

impl InputCommands for DuelRules {
    type Input = DuelInput;

    fn commands(
        &self,
        world: &World,
        player: PlayerHandle,
        input: &DuelInput,
        _status: InputStatus,
        out: &mut Vec<Command>,
    ) {
        if let Some(inject) = self.inject
            && player == 0
            && world.tick() == inject.tick
        {
            out.push(Command::ApplyImpulse {
                body: inject.body,
                impulse: inject.impulse,
            });
        }
        // A handle beyond the two players (impossible in a two-player
        // session) maps to no commands rather than a panic.
        let Some(&body_id) = self.players.get(player) else {
            return;
        };
        // A player body that is gone (never, in this game) gives no
        // commands; every command below is still checked by the world.
        let Some(body) = world.body(body_id) else {
            return;
        };
        let mut push: Vec2 = Vec2::ZERO;
        if input.holds(DuelInput::LEFT) {
            push.x = push.x.sub(move_impulse());
        }
        if input.holds(DuelInput::RIGHT) {
            push.x = push.x.add(move_impulse());
        }
        if input.holds(DuelInput::JUMP) && body.velocity().y.abs() < jump_speed_limit() {
            push.y = jump_impulse();
        }
        if push != Vec2::ZERO {
            out.push(Command::ApplyImpulse {
                body: body_id,
                impulse: push,
            });
        }
        let rope = Self::rope_of(world, body_id);
        match (input.holds(DuelInput::GRAPPLE), rope) {
            (true, None) => {
                let (ax, ay) = AIM_DIRECTIONS[usize::from(input.aim) % AIM_DIRECTIONS.len()];
                let aim = Vec2::new(Fx::from_int(ax), Fx::from_int(ay));
                let filter = QueryFilter {
                    exclude: Some(body_id),
                    ..QueryFilter::default()
                };
                if let Some(hit) =
                    world.raycast_filtered(body.position(), aim, grapple_reach(), &filter)
                {
                    out.push(Command::AddConstraint(Constraint::rope(
                        Anchor::Point(hit.hit.point),
                        Anchor::Body(body_id),
                        hit.hit.distance,
                    )));
                }
            }
            (false, Some(rope)) => out.push(Command::RemoveConstraint(rope)),
            _ => {}
        }
    }
}

/// The negative control of the sync test: the duel rules plus an impulse
/// whose size depends on how many times the rules were called, so
/// re-simulating a frame gives another result. A sync test must report it.
#[derive(Debug)]
pub struct NondeterministicRules {
    /// The deterministic part.
    pub rules: DuelRules,
    /// The body that gets the varying impulse.
    pub body: BodyId,
    calls: AtomicU32,
}

impl NondeterministicRules {
    /// Wraps `rules`; `body` is pushed by a call-count-dependent impulse.
    #[must_use]
    pub fn new(rules: DuelRules, body: BodyId) -> Self {
        NondeterministicRules {
            rules,
            body,
            calls: AtomicU32::new(0),
        }
    }
}

impl InputCommands for NondeterministicRules {
    type Input = DuelInput;

    fn commands(
        &self,
        world: &World,
        player: PlayerHandle,
        input: &DuelInput,
        status: InputStatus,
        out: &mut Vec<Command>,
    ) {
        self.rules.commands(world, player, input, status, out);
        if player == 0 {
            let calls = self.calls.fetch_add(1, Ordering::Relaxed);
            // Modulo 11: with GGRS's 8 simulations per sync-test frame, a modulus
            // of 7 would give every simulation of a frame the same value.
            let k = i32::try_from(calls % 11).unwrap_or(0);
            out.push(Command::ApplyImpulse {
                body: self.body,
                impulse: Vec2::new(Fx::from_int(k).div(Fx::from_int(100)), Fx::ZERO),
            });
        }
    }
}
