//! [`SessionWorld`]: serves the save / load / advance requests of a GGRS
//! session against a [`World`].

use std::collections::BTreeMap;

use clockwork2d::prelude::{Command, Fx, Scalar, World, WorldError};
use clockwork2d::replay::{Recorder, Replay};
use ggrs::{Config, Frame, GgrsRequest, PlayerHandle};

use crate::error::SessionError;
use crate::input_commands::InputCommands;
use crate::rollback_state::RollbackState;

/// Frames of state hashes kept for [`SessionWorld::frame_hash`]: far more
/// than a prediction window (GGRS's default is 8) plus a desync-detection
/// interval, so the hash of any frame a peer can still report is there.
pub const HASH_HISTORY: usize = 1024;

/// Forensic copies of the world kept for [`SessionWorld::snapshot_at`], one
/// every `forensic_interval` frames. GGRS reports a desync for a frame that
/// is at most a few checksum intervals old (it sends one checksum per
/// interval once the frame is confirmed, and compares on the next
/// `advance_frame` after the peer's report arrives), so 16 intervals leave a
/// wide margin for latency and loss.
pub const FORENSIC_COPIES: usize = 16;

/// A command that [`World::apply`] refused during a frame.
#[derive(Clone, Debug, PartialEq)]
pub struct RefusedCommand {
    /// The frame being simulated (the state it starts from).
    pub frame: Frame,
    /// The player whose input produced it.
    pub player: PlayerHandle,
    /// Why the world refused it (the world is unchanged by it).
    pub error: WorldError,
}

/// What one batch of requests did.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct FrameReport {
    /// Save requests served.
    pub saves: u32,
    /// Load requests served (rollbacks).
    pub loads: u32,
    /// Frames simulated, re-simulations included.
    pub advances: u32,
    /// Commands the world refused (from any player, local or remote).
    pub refused: Vec<RefusedCommand>,
}

/// A [`World`] driven by GGRS requests.
///
/// * `SaveGameState` stores `St::save(&world)` with the checksum
///   [`World::state_hash128`] (computed once per state: the hash of the state
///   an advance produced is reused by the save of that frame; with
///   [`with_checksum_interval`](Self::with_checksum_interval), only on
///   checksum frames);
/// * `LoadGameState` restores the cell's state;
/// * `AdvanceFrame` asks the game's [`InputCommands`] for each player's
///   commands (players in handle order) and calls [`World::step_with`] with
///   all of them: refused commands leave the world unchanged and are listed in
///   the [`FrameReport`].
///
/// Frames are counted from the world the session started with: frame `f` is
/// the world at tick `start_tick + f`. Requests must be served in the order
/// GGRS gives them; a save or load for another frame is refused with
/// [`SessionError::FrameMismatch`].
///
/// Optional extras, for operating a session:
/// * state hashes of recent frames ([`frame_hash`](Self::frame_hash));
/// * forensic copies of the world every K frames, for the frame a desync
///   report names ([`snapshot_at`](Self::snapshot_at));
/// * a [`Replay`] of the confirmed frames ([`record_replay`](Self::record_replay),
///   [`confirm`](Self::confirm), [`finish_replay`](Self::finish_replay)).
#[derive(Debug)]
pub struct SessionWorld<M, S: Scalar = Fx, St = World<S>> {
    world: World<S>,
    game: M,
    start_tick: u64,
    frame: Frame,
    /// `state_hash128` of the current world, while the world is unchanged.
    current_hash: Option<u128>,
    frame_hashes: BTreeMap<Frame, u128>,
    checksum_interval: u32,
    forensic_interval: u32,
    forensic: BTreeMap<Frame, World<S>>,
    recorder: Option<Recorder<S>>,
    /// The next frame to hand to the recorder.
    next_recorded: Frame,
    /// Commands of simulated frames not yet recorded (the latest simulation
    /// of each frame: a re-simulation replaces them).
    pending_commands: BTreeMap<Frame, Vec<Command<S>>>,
    scratch: Vec<Command<S>>,
    owners: Vec<PlayerHandle>,
    _state: core::marker::PhantomData<fn() -> St>,
}

impl<M, S, St> SessionWorld<M, S, St>
where
    S: Scalar,
    M: InputCommands<S>,
    St: RollbackState<S>,
{
    /// A session world starting from `world` (frame 0 is its current tick).
    #[must_use]
    pub fn new(world: World<S>, game: M) -> Self {
        SessionWorld {
            start_tick: world.tick(),
            world,
            game,
            frame: 0,
            current_hash: None,
            frame_hashes: BTreeMap::new(),
            checksum_interval: 1,
            forensic_interval: 0,
            forensic: BTreeMap::new(),
            recorder: None,
            next_recorded: 0,
            pending_commands: BTreeMap::new(),
            scratch: Vec::new(),
            owners: Vec::new(),
            _state: core::marker::PhantomData,
        }
    }

    /// Keeps a copy of the world every `interval` frames (the last
    /// [`FORENSIC_COPIES`] of them) so that [`snapshot_at`](Self::snapshot_at)
    /// can write the state of a frame a desync report names. Use the
    /// session's desync-detection interval. 0 turns it off.
    #[must_use]
    pub fn with_forensics(mut self, interval: u32) -> Self {
        self.forensic_interval = interval;
        self
    }

    /// Computes the checksum (and keeps the frame hash) only for frames
    /// that are multiples of `interval` (default 1: every frame, as a sync
    /// test needs). In a P2P session GGRS sends the checksums of multiples
    /// of its desync-detection interval only, so with that interval the
    /// other saves skip the hash, which costs about a third of a step
    /// (see the rollback-cost report). 0 is taken as 1.
    #[must_use]
    pub fn with_checksum_interval(mut self, interval: u32) -> Self {
        self.checksum_interval = interval.max(1);
        self
    }

    fn is_checksum_frame(&self, frame: Frame) -> bool {
        frame % i32::try_from(self.checksum_interval).unwrap_or(i32::MAX) == 0
    }

    /// Records the confirmed frames as a [`Replay`] with a state hash every
    /// `hash_interval` ticks. The recorder re-simulates each frame once it is
    /// confirmed (one extra step per frame), so the replay holds exactly the
    /// commands that every peer applied.
    #[must_use]
    pub fn record_replay(mut self, hash_interval: u32) -> Self {
        self.recorder = Some(Recorder::new(self.world.clone(), hash_interval));
        self
    }

    /// The world as it is now.
    #[must_use]
    pub fn world(&self) -> &World<S> {
        &self.world
    }

    /// The game's input → command mapping.
    #[must_use]
    pub fn game(&self) -> &M {
        &self.game
    }

    /// The frame the world is at.
    #[must_use]
    pub fn frame(&self) -> Frame {
        self.frame
    }

    /// The checksum GGRS is given for the current state
    /// ([`World::state_hash128`]).
    pub fn checksum(&mut self) -> u128 {
        *self
            .current_hash
            .get_or_insert_with(|| self.world.state_hash128())
    }

    /// The state hash of `frame` as last simulated (within the last
    /// [`HASH_HISTORY`] checksum frames; only frames that are multiples of
    /// the checksum interval; frame 0 only once a save has hashed it).
    #[must_use]
    pub fn frame_hash(&self, frame: Frame) -> Option<u128> {
        self.frame_hashes.get(&frame).copied()
    }

    /// The snapshot bytes of `frame` as last simulated, if a forensic copy
    /// of it is kept (see [`with_forensics`](Self::with_forensics)).
    #[must_use]
    pub fn snapshot_at(&self, frame: Frame) -> Option<Vec<u8>> {
        if frame == self.frame {
            return Some(self.world.snapshot());
        }
        self.forensic.get(&frame).map(World::snapshot)
    }

    /// The frames whose forensic copies are kept, oldest first.
    pub fn forensic_frames(&self) -> impl Iterator<Item = Frame> + '_ {
        self.forensic.keys().copied()
    }

    /// Serves one batch of GGRS requests, in order.
    ///
    /// # Errors
    /// The first [`SessionError`]; the requests after it are not served.
    pub fn handle_requests<C>(
        &mut self,
        requests: Vec<GgrsRequest<C>>,
    ) -> Result<FrameReport, SessionError>
    where
        C: Config<Input = M::Input, State = St>,
    {
        let mut report = FrameReport::default();
        for request in requests {
            match request {
                GgrsRequest::SaveGameState { cell, frame } => {
                    if frame != self.frame {
                        return Err(SessionError::FrameMismatch {
                            request: "save",
                            requested: frame,
                            actual: self.frame,
                        });
                    }
                    let checksum = self.is_checksum_frame(frame).then(|| {
                        let checksum = self.checksum();
                        self.frame_hashes.insert(frame, checksum);
                        checksum
                    });
                    cell.save(frame, Some(St::save(&self.world)), checksum);
                    report.saves += 1;
                }
                GgrsRequest::LoadGameState { cell, frame } => {
                    self.load(&cell, frame)?;
                    report.loads += 1;
                }
                GgrsRequest::AdvanceFrame { inputs } => {
                    self.advance(&inputs, &mut report.refused);
                    report.advances += 1;
                }
            }
        }
        Ok(report)
    }

    fn load(&mut self, cell: &ggrs::GameStateCell<St>, frame: Frame) -> Result<(), SessionError> {
        let Some(state) = cell.data() else {
            return Err(SessionError::EmptyCell { frame });
        };
        // Load into a copy first only when the state could fail to load:
        // `World` never fails, snapshot bytes are checked before anything
        // is replaced (restore_into leaves the world unchanged on error).
        state.load(&mut self.world).map_err(SessionError::Load)?;
        let loaded = self.frame_of_tick(self.world.tick());
        if loaded != frame {
            return Err(SessionError::FrameMismatch {
                request: "load",
                requested: frame,
                actual: loaded,
            });
        }
        self.frame = frame;
        self.current_hash = None;
        Ok(())
    }

    fn frame_of_tick(&self, tick: u64) -> Frame {
        let offset = tick.wrapping_sub(self.start_tick);
        Frame::try_from(offset).unwrap_or(Frame::MAX)
    }

    fn advance(
        &mut self,
        inputs: &[(M::Input, ggrs::InputStatus)],
        refused: &mut Vec<RefusedCommand>,
    ) {
        let mut commands = core::mem::take(&mut self.scratch);
        commands.clear();
        self.owners.clear();
        for (player, (input, status)) in inputs.iter().enumerate() {
            let before = commands.len();
            self.game
                .commands(&self.world, player, input, *status, &mut commands);
            self.owners
                .extend(core::iter::repeat_n(player, commands.len() - before));
        }
        let results = self.world.step_with(&commands);
        for (result, &player) in results.into_iter().zip(&self.owners) {
            if let Err(error) = result {
                refused.push(RefusedCommand {
                    frame: self.frame,
                    player,
                    error,
                });
            }
        }
        if self.recorder.is_some() {
            self.pending_commands.insert(self.frame, commands.clone());
        }
        self.scratch = commands;
        self.frame = self.frame.saturating_add(1);
        self.current_hash = None;
        if self.is_checksum_frame(self.frame) {
            let hash = self.checksum();
            self.frame_hashes.insert(self.frame, hash);
            while self.frame_hashes.len() > HASH_HISTORY {
                self.frame_hashes.pop_first();
            }
        }
        if self.forensic_interval > 0
            && self.frame % i32::try_from(self.forensic_interval).unwrap_or(i32::MAX) == 0
        {
            self.forensic.insert(self.frame, self.world.clone());
            while self.forensic.len() > FORENSIC_COPIES {
                self.forensic.pop_first();
            }
        }
    }

    /// Hands the frames up to `confirmed` (inclusive) to the replay
    /// recorder. Call it right after serving the requests of an
    /// `advance_frame`, with the session's `confirmed_frame()` read before
    /// polling again: then every frame up to it was simulated with the
    /// confirmed inputs. Frames not simulated yet wait for a later call.
    pub fn confirm(&mut self, confirmed: Frame) {
        let Some(recorder) = self.recorder.as_mut() else {
            return;
        };
        while self.next_recorded <= confirmed && self.next_recorded < self.frame {
            let Some(commands) = self.pending_commands.remove(&self.next_recorded) else {
                break;
            };
            recorder.step_with(&commands);
            self.next_recorded += 1;
        }
    }

    /// Frames handed to the replay recorder so far.
    #[must_use]
    pub fn recorded_frames(&self) -> Frame {
        self.next_recorded
    }

    /// The replay of the confirmed frames, and the world at its end (`None`
    /// without [`record_replay`](Self::record_replay)).
    #[must_use]
    pub fn finish_replay(&mut self) -> Option<(Replay<S>, World<S>)> {
        let recorder = self.recorder.take()?;
        self.pending_commands.clear();
        Some(recorder.finish_with_world())
    }
}
