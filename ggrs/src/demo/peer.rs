//! [`run_peer`]: one peer of a peer-to-peer session of the game.

use std::net::SocketAddr;
use std::path::PathBuf;
use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

use clockwork2d::prelude::*;
use clockwork2d::replay::Replay;
use ggrs::{
    DesyncDetection, Frame, GgrsError, GgrsEvent, PlayerHandle, PlayerType, SessionBuilder,
    SessionState,
};

use super::{DesyncInjection, DuelConfig, DuelInput, DuelRules, InputScript, arena};
use crate::net::{UdpTransport, WireTotals};
use crate::{SessionError, SessionWorld};

/// How to run one peer.
#[derive(Clone, Debug)]
pub struct PeerOptions {
    /// This peer's player handle (0 or 1); the remote has the other.
    pub handle: PlayerHandle,
    /// The remote peer's address.
    pub remote: SocketAddr,
    /// Frames to play (inputs are random until then, idle after).
    pub frames: Frame,
    /// GGRS's lockstep mode (`max_prediction = 0`) instead of rollback.
    pub lockstep: bool,
    /// Prediction window in rollback mode.
    pub max_prediction: usize,
    /// Local input delay in frames.
    pub input_delay: usize,
    /// Desync-detection interval in frames (0: off).
    pub desync_interval: u32,
    /// Perturb ball 0 on this peer at this frame (a deliberate desync).
    pub inject_desync: Option<Frame>,
    /// Seed of this peer's random inputs.
    pub seed: u64,
    /// Where to write the snapshot of a frame a desync report names.
    pub forensic_dir: Option<PathBuf>,
    /// Ticks between state hashes in the replay.
    pub replay_hash_interval: u32,
    /// GGRS disconnect timeout.
    pub disconnect_timeout: Duration,
    /// Give up (with [`PeerError::Timeout`]) after this long.
    pub timeout: Duration,
    /// Peers of the session that have finished (shared by peers run as
    /// threads): a finished peer keeps serving the session until every
    /// peer has finished, so the other still gets its inputs. Without it, a
    /// finished peer lingers for one second.
    pub finished_peers: Option<Arc<AtomicUsize>>,
    /// Leave the session abruptly at this frame (to test disconnects).
    pub quit_at: Option<Frame>,
}

impl PeerOptions {
    /// Defaults for player `handle` talking to `remote`: 3000 frames,
    /// rollback with a window of 8, input delay 2, desync detection every 10
    /// frames, hashes every 60 ticks in the replay, 2 s disconnect timeout,
    /// 120 s overall timeout.
    #[must_use]
    pub fn new(handle: PlayerHandle, remote: SocketAddr) -> Self {
        PeerOptions {
            handle,
            remote,
            frames: 3000,
            lockstep: false,
            max_prediction: 8,
            input_delay: 2,
            desync_interval: 10,
            inject_desync: None,
            seed: 1,
            forensic_dir: None,
            replay_hash_interval: 60,
            disconnect_timeout: Duration::from_secs(2),
            timeout: Duration::from_secs(120),
            finished_peers: None,
            quit_at: None,
        }
    }
}

/// A desync that GGRS reported to this peer.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DesyncReport {
    /// The frame whose checksums differ.
    pub frame: Frame,
    /// This peer's checksum of it.
    pub local_checksum: u128,
    /// The remote's.
    pub remote_checksum: u128,
    /// The frame this peer was at when the report arrived.
    pub detected_at: Frame,
    /// The snapshot of `frame` written for forensics, if kept.
    pub snapshot: Option<PathBuf>,
}

/// What one peer saw.
#[derive(Clone, Debug)]
pub struct PeerOutcome {
    /// The peer's handle.
    pub handle: PlayerHandle,
    /// Frames played (the `frames` option), all confirmed.
    pub frames: Frame,
    /// `state_hash128` of frame `frames` as finally simulated.
    pub final_hash: u128,
    /// Wall time from the start to the confirmation of the last frame.
    pub elapsed: Duration,
    /// Wall time spent synchronising before the first frame.
    pub sync_time: Duration,
    /// What the transport sent and received.
    pub wire: WireTotals,
    /// Frames this peer had advanced when the last frame was confirmed
    /// (the wire totals are up to then too).
    pub frames_at_finish: Frame,
    /// Desyncs GGRS reported.
    pub desyncs: Vec<DesyncReport>,
    /// Remotes that disconnected.
    pub disconnected: Vec<SocketAddr>,
    /// "Network interrupted" events.
    pub interruptions: u32,
    /// Rollbacks (load requests).
    pub rollbacks: u64,
    /// Frames simulated in all, re-simulations included.
    pub simulated: u64,
    /// Commands the world refused.
    pub refused: usize,
    /// The session's confirmed frames as a replay.
    pub replay: Replay,
    /// `state_hash128` of the replay recorder's world at its end.
    pub replay_final_hash: u128,
}

/// Why a peer stopped early.
#[derive(Clone, Debug, PartialEq)]
pub enum PeerError {
    /// The session did not confirm all frames in time.
    Timeout {
        /// The frame reached.
        frame: Frame,
        /// Frames recorded as confirmed.
        confirmed: Frame,
    },
    /// The peer left on purpose ([`PeerOptions::quit_at`]).
    Quit {
        /// The frame it left at.
        frame: Frame,
    },
    /// A request could not be served, or GGRS refused a call.
    Session(SessionError),
    /// Writing a forensic snapshot failed, or building the scene.
    Io(String),
}

impl core::fmt::Display for PeerError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            PeerError::Timeout { frame, confirmed } => write!(
                f,
                "timed out at frame {frame} with {confirmed} frames confirmed: is the other \
                 peer running, and reachable?"
            ),
            PeerError::Quit { frame } => write!(f, "left the session at frame {frame}"),
            PeerError::Session(e) => write!(f, "{e}"),
            PeerError::Io(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for PeerError {}

impl From<SessionError> for PeerError {
    fn from(e: SessionError) -> Self {
        PeerError::Session(e)
    }
}

fn ggrs_error(e: &GgrsError) -> PeerError {
    PeerError::Session(SessionError::Session(e.to_string()))
}

/// Runs one peer of the game over `transport` until all `frames` frames
/// are confirmed (and, with [`PeerOptions::finished_peers`], until every
/// peer is done), then returns what it saw. Garbage datagrams, lost
/// packets and a disconnecting remote are counted and reported, never a
/// panic.
///
/// # Errors
/// [`PeerError`]: a timeout, a deliberate quit, a request that cannot be
/// served, or a forensic snapshot that cannot be written.
pub fn run_peer(options: &PeerOptions, transport: UdpTransport) -> Result<PeerOutcome, PeerError> {
    let start = Instant::now();
    let arena = arena().map_err(|e| PeerError::Io(e.to_string()))?;
    let mut rules = DuelRules::new(arena.players);
    if let Some(frame) = options.inject_desync {
        rules.inject = Some(DesyncInjection {
            tick: u64::try_from(frame).unwrap_or(0),
            body: arena.balls[0],
            impulse: Vec2::new(fx(0.5), fx(0.0)),
        });
    }
    let counters = transport.counters();
    let max_prediction = if options.lockstep {
        0
    } else {
        options.max_prediction
    };
    let detection = if options.desync_interval == 0 {
        DesyncDetection::Off
    } else {
        DesyncDetection::On {
            interval: options.desync_interval,
        }
    };
    let remote_handle = 1 - options.handle.min(1);
    let mut session = SessionBuilder::<DuelConfig>::new()
        .with_num_players(2)
        .and_then(|b| {
            b.with_max_prediction_window(max_prediction)
                .with_input_delay(options.input_delay)
                .with_desync_detection_mode(detection)
                .with_disconnect_timeout(options.disconnect_timeout)
                .with_disconnect_notify_delay(options.disconnect_timeout / 2)
                .add_player(PlayerType::Local, options.handle)
        })
        .and_then(|b| b.add_player(PlayerType::Remote(options.remote), remote_handle))
        .and_then(|b| b.start_p2p_session(transport))
        .map_err(|e| ggrs_error(&e))?;
    // Checksums only where GGRS sends them (multiples of the detection
    // interval), and at the last frame, whose hash is the result.
    let checksum_interval = gcd(
        options.desync_interval.max(1),
        options.frames.unsigned_abs(),
    );
    let mut game: SessionWorld<DuelRules> = SessionWorld::new(arena.world, rules)
        .with_checksum_interval(checksum_interval)
        .with_forensics(options.desync_interval)
        .record_replay(options.replay_hash_interval);
    let mut script = InputScript::new(options.seed);
    let inputs: Vec<DuelInput> = (0..options.frames).map(|_| script.next_input()).collect();

    let mut desyncs = Vec::new();
    let mut disconnected = Vec::new();
    let mut interruptions = 0u32;
    let (mut rollbacks, mut simulated, mut refused) = (0u64, 0u64, 0usize);
    let mut sync_time = None;
    let mut finish: Option<(u128, Duration, WireTotals, Frame)> = None;
    let mut finished_at = None;
    loop {
        if start.elapsed() > options.timeout {
            return Err(PeerError::Timeout {
                frame: game.frame(),
                confirmed: game.recorded_frames(),
            });
        }
        if options.quit_at.is_some_and(|q| game.frame() >= q) {
            return Err(PeerError::Quit {
                frame: game.frame(),
            });
        }
        session.poll_remote_clients();
        for event in session.events() {
            match event {
                GgrsEvent::DesyncDetected {
                    frame,
                    local_checksum,
                    remote_checksum,
                    ..
                } => {
                    // GGRS sends each checksum report once: over a lossy
                    // link each peer may be told about different frames. On
                    // the first report a peer writes every frame it keeps up
                    // to the reported one, so both peers have the earliest
                    // frame either was told about.
                    if desyncs.is_empty() {
                        let earlier: Vec<Frame> =
                            game.forensic_frames().filter(|&f| f < frame).collect();
                        for f in earlier {
                            write_forensic(options, &game, f)?;
                        }
                    }
                    desyncs.push(DesyncReport {
                        frame,
                        local_checksum,
                        remote_checksum,
                        detected_at: game.frame(),
                        snapshot: write_forensic(options, &game, frame)?,
                    });
                }
                GgrsEvent::Disconnected { addr } => disconnected.push(addr),
                GgrsEvent::NetworkInterrupted { .. } => interruptions += 1,
                _ => {}
            }
        }
        if finish.is_some() {
            let everyone_done = match &options.finished_peers {
                Some(done) => done.load(Ordering::SeqCst) >= 2,
                None => finished_at.is_some_and(|t: Instant| t.elapsed() > Duration::from_secs(1)),
            };
            if everyone_done || !disconnected.is_empty() {
                break;
            }
        }
        if session.current_state() != SessionState::Running {
            std::thread::sleep(Duration::from_millis(1));
            continue;
        }
        if sync_time.is_none() {
            sync_time = Some(start.elapsed());
        }
        let input = usize::try_from(session.current_frame())
            .ok()
            .and_then(|f| inputs.get(f))
            .copied()
            .unwrap_or_default();
        session
            .add_local_input(options.handle, input)
            .map_err(|e| ggrs_error(&e))?;
        match session.advance_frame() {
            Ok(requests) => {
                let stalled = requests.is_empty();
                let report = game.handle_requests(requests)?;
                rollbacks += u64::from(report.loads);
                simulated += u64::from(report.advances);
                refused += report.refused.len();
                // Read right after serving the requests, before any new
                // poll: every frame up to it was simulated with confirmed
                // inputs.
                game.confirm(session.confirmed_frame().min(options.frames - 1));
                if stalled {
                    std::thread::sleep(Duration::from_micros(200));
                }
            }
            Err(GgrsError::PredictionThreshold | GgrsError::NotSynchronized) => {
                std::thread::sleep(Duration::from_micros(200));
            }
            Err(e) => return Err(ggrs_error(&e)),
        }
        if finish.is_none() && game.recorded_frames() >= options.frames {
            let hash = game
                .frame_hash(options.frames)
                .ok_or_else(|| PeerError::Io("the final frame's hash was not kept".to_owned()))?;
            finish = Some((hash, start.elapsed(), counters.totals(), game.frame()));
            finished_at = Some(Instant::now());
            if let Some(done) = &options.finished_peers {
                done.fetch_add(1, Ordering::SeqCst);
            }
        }
    }
    let Some((final_hash, elapsed, wire, frames_at_finish)) = finish else {
        return Err(PeerError::Io(
            "the session ended before it finished".to_owned(),
        ));
    };
    let Some((replay, replay_world)) = game.finish_replay() else {
        return Err(PeerError::Io("no replay was recorded".to_owned()));
    };
    Ok(PeerOutcome {
        handle: options.handle,
        frames: options.frames,
        final_hash,
        elapsed,
        sync_time: sync_time.unwrap_or_default(),
        wire,
        frames_at_finish,
        desyncs,
        disconnected,
        interruptions,
        rollbacks,
        simulated,
        refused,
        replay_final_hash: replay_world.state_hash128(),
        replay,
    })
}

/// Writes the snapshot of `frame` (as this peer simulated it) for a desync
/// report, if a directory is given and the frame is still kept.
fn write_forensic(
    options: &PeerOptions,
    game: &SessionWorld<DuelRules>,
    frame: Frame,
) -> Result<Option<PathBuf>, PeerError> {
    let Some(dir) = &options.forensic_dir else {
        return Ok(None);
    };
    let Some(bytes) = game.snapshot_at(frame) else {
        return Ok(None);
    };
    let path = dir.join(format!("desync-frame{frame}-peer{}.snap", options.handle));
    std::fs::write(&path, bytes)
        .map_err(|e| PeerError::Io(format!("cannot write {}: {e}", path.display())))?;
    Ok(Some(path))
}

/// Greatest common divisor (Euclid); `gcd(a, 0) = a`.
fn gcd(mut a: u32, mut b: u32) -> u32 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}
