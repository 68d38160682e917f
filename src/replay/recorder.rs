//! [`Recorder`]: wraps a world while it plays and records a [`Replay`].

use super::{Checkpoint, Replay};
use crate::math::Fx;
use crate::math::Scalar;
use crate::world::{Command, CommandOutcome, World, WorldError};

/// Records a session: the initial state, every command, and a checkpoint
/// (state hash with part digests) every `hash_interval` ticks.
///
/// The recorder owns the world; read it with [`Recorder::world`] and
/// advance it only through [`Recorder::step_with`] / [`Recorder::step`], so
/// that nothing escapes the record.
#[derive(Clone, Debug)]
pub struct Recorder<S: Scalar = Fx> {
    world: World<S>,
    initial: World<S>,
    hash_interval: u32,
    ticks: u64,
    commands: Vec<(u64, Command<S>)>,
    checkpoints: Vec<Checkpoint>,
}

impl<S: Scalar> Recorder<S> {
    /// Starts recording from `world`'s current state, with a checkpoint
    /// every `hash_interval` ticks (0 is taken as 1).
    #[must_use]
    pub fn new(world: World<S>, hash_interval: u32) -> Self {
        let checkpoints = vec![Checkpoint::of(&world)];
        Recorder {
            initial: world.clone(),
            world,
            hash_interval: hash_interval.max(1),
            ticks: 0,
            commands: Vec::new(),
            checkpoints,
        }
    }

    /// The world being recorded.
    #[must_use]
    pub fn world(&self) -> &World<S> {
        &self.world
    }

    /// Ticks recorded so far.
    #[must_use]
    pub fn ticks(&self) -> u64 {
        self.ticks
    }

    /// Applies `commands` and steps the world (as [`World::step_with`]),
    /// recording both. Refused commands are recorded too: they are refused
    /// again, identically, on replay.
    pub fn step_with(
        &mut self,
        commands: &[Command<S>],
    ) -> Vec<Result<CommandOutcome, WorldError>> {
        let tick = self.world.tick();
        self.commands
            .extend(commands.iter().map(|c| (tick, c.clone())));
        let results = self.world.step_with(commands);
        self.ticks += 1;
        if self.ticks.is_multiple_of(u64::from(self.hash_interval)) {
            self.checkpoints.push(Checkpoint::of(&self.world));
        }
        results
    }

    /// Steps the world with no commands.
    pub fn step(&mut self) {
        self.step_with(&[]);
    }

    /// Ends the recording (adding a checkpoint for the final tick if it is
    /// not on the interval) and returns the replay and nothing else; use
    /// [`Recorder::finish_with_world`] to keep playing.
    #[must_use]
    pub fn finish(self) -> Replay<S> {
        self.finish_with_world().0
    }

    /// As [`Recorder::finish`], also giving the world back.
    #[must_use]
    pub fn finish_with_world(mut self) -> (Replay<S>, World<S>) {
        if !self.ticks.is_multiple_of(u64::from(self.hash_interval)) {
            self.checkpoints.push(Checkpoint::of(&self.world));
        }
        let replay = Replay {
            crate_version: env!("CARGO_PKG_VERSION").to_owned(),
            hash_interval: self.hash_interval,
            initial: self.initial,
            ticks: self.ticks,
            commands: self.commands,
            checkpoints: self.checkpoints,
        };
        (replay, self.world)
    }
}
