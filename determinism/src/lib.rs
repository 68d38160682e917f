//! The determinism suite: named scenarios whose state hashes are committed
//! as golden constants, checked on every target CI builds for
//! (`scripts/cross-determinism.sh`: x86_64, i686, aarch64, s390x and
//! wasm32-wasip1, in debug and in release).
//!
//! Each [`Scenario`] builds a world (from a built-in scene or from code),
//! then plays a script for [`TICKS`] ticks: commands applied mid-run, ray
//! casts and queries. Every [`CHECKPOINT_EVERY`] ticks (and at tick 0) it
//! records a [`Checkpoint`]: the world's [`state_hash`](clockwork2d::prelude::World::state_hash)
//! and the digest of a [`Probe`] that folds everything observed besides the
//! state (ray-cast answers with their distance, point and normal bits,
//! query results, every command's outcome or refusal, every event).
//!
//! Together the scenarios use every feature: stacking and sleeping, the
//! pyramid, bullets with time of impact, bendy and radial springs, ropes and
//! a chain, ray casts and a scripted grapple, spawn / despawn / impulse and
//! the other commands mid-run (refused ones included), and bodies at the
//! world bounds with extreme velocities, masses and stiffnesses (the
//! saturation policy, `max_speed` clamping, freezing at the bounds).
//!
//! ```
//! use clockwork2d_determinism::{SCENARIOS, check_golden};
//! let scenario = SCENARIOS.iter().find(|s| s.name == "stack_sleep").unwrap();
//! let run = scenario.run().unwrap();
//! assert_eq!(run.checkpoints.len(), 11); // ticks 0, 60, ..., 600
//! assert!(check_golden(&run).is_ok());
//! ```
//!
//! # Updating the goldens
//!
//! A change that moves a golden hash is a behaviour change. After making
//! it on purpose, regenerate `determinism/src/golden.rs` with
//!
//! ```text
//! cargo run --release -p clockwork2d-determinism --example determinism_suite -- --update-golden
//! ```
//!
//! and name the change in CHANGELOG.md. A mismatch on one target only is
//! never a reason to regenerate: it is a determinism bug.

#![forbid(unsafe_code)]
#![deny(clippy::float_arithmetic)]

mod golden;
mod probe;
mod scenarios;

use core::fmt;
use std::collections::BTreeMap;
use std::fmt::Write as _;

pub use golden::GOLDEN;
pub use probe::{Probe, error_code, error_name};

use clockwork2d::replay::{Recorder, Replay};
use clockwork2d::snapshot::SnapshotError;
use clockwork2d::world::{Command, CommandOutcome, Event, World, WorldError};

/// Ticks every scenario runs.
pub const TICKS: u64 = 600;
/// Ticks between checkpoints.
pub const CHECKPOINT_EVERY: u64 = 60;
/// The tick at which [`ScenarioRun::snapshot`] is taken.
pub const SNAPSHOT_TICK: u64 = 300;
/// The command that regenerates the goldens (quoted in every mismatch
/// message).
pub const UPDATE_COMMAND: &str =
    "cargo run --release -p clockwork2d-determinism --example determinism_suite -- --update-golden";

/// Why a scenario could not be built or played.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SuiteError(pub String);

impl fmt::Display for SuiteError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for SuiteError {}

impl From<WorldError> for SuiteError {
    fn from(e: WorldError) -> Self {
        SuiteError(format!("world error while building a scenario: {e}"))
    }
}

impl From<clockwork2d_scene::SceneError> for SuiteError {
    fn from(e: clockwork2d_scene::SceneError) -> Self {
        SuiteError(format!("scene error while building a scenario: {e}"))
    }
}

impl From<SnapshotError> for SuiteError {
    fn from(e: SnapshotError) -> Self {
        SuiteError(format!("unreadable file: {e}"))
    }
}

/// One checkpoint: the tick, the state hash and the probe digest.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Checkpoint {
    /// World tick (after the step).
    pub tick: u64,
    /// [`World::state_hash`].
    pub state: u64,
    /// [`Probe::finish`]: everything observed besides the state, since
    /// tick 0.
    pub probe: u64,
}

/// The golden checkpoints of one scenario.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct GoldenScenario {
    /// The scenario's name.
    pub name: &'static str,
    /// `(tick, state hash, probe digest)` at every checkpoint.
    pub checkpoints: &'static [(u64, u64, u64)],
}

/// What a scenario did, for checking that it still exercises its feature.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Coverage {
    /// Commands that took effect.
    pub applied: u32,
    /// Commands refused, by error name.
    pub refused: BTreeMap<&'static str, u32>,
    /// Events by kind ("began", "ended", "slept", "woke", "frozen").
    pub events: BTreeMap<&'static str, u32>,
    /// Ray casts that hit.
    pub ray_hits: u32,
    /// Ray casts that missed.
    pub ray_misses: u32,
    /// Largest number of live constraints seen after a step.
    pub max_constraints: u32,
    /// Largest number of live bodies seen after a step.
    pub max_bodies: u32,
}

impl Coverage {
    fn results(&mut self, results: &[Result<CommandOutcome, WorldError>]) {
        for r in results {
            match r {
                Ok(_) => self.applied += 1,
                Err(e) => *self.refused.entry(error_name(e)).or_default() += 1,
            }
        }
    }

    fn events(&mut self, events: &[Event]) {
        for e in events {
            let name = match e {
                Event::ContactEnded(..) => "ended",
                Event::ContactBegan(..) => "began",
                Event::Slept(_) => "slept",
                Event::Woke(_) => "woke",
                Event::Frozen(_) => "frozen",
            };
            *self.events.entry(name).or_default() += 1;
        }
    }

    /// Number of events of a kind ("began", "ended", "slept", "woke",
    /// "frozen").
    #[must_use]
    pub fn event_count(&self, kind: &str) -> u32 {
        self.events.get(kind).copied().unwrap_or(0)
    }

    /// Number of commands refused with the named error.
    #[must_use]
    pub fn refused_count(&self, error: &str) -> u32 {
        self.refused.get(error).copied().unwrap_or(0)
    }
}

/// Observations a script makes while it plays.
pub(crate) struct Observer<'a> {
    pub(crate) probe: &'a mut Probe,
    pub(crate) coverage: &'a mut Coverage,
}

impl Observer<'_> {
    /// Folds a ray answer and counts it.
    pub(crate) fn ray(
        &mut self,
        hit: Option<&clockwork2d::world::BodyRayHit<clockwork2d::prelude::Fx>>,
    ) {
        if hit.is_some() {
            self.coverage.ray_hits += 1;
        } else {
            self.coverage.ray_misses += 1;
        }
        self.probe.ray(hit);
    }
}

/// A scenario's script: the commands of each tick, and what it observes.
pub(crate) trait Script {
    /// The commands for the step from `world.tick()` to the next tick
    /// (queries made here are folded into the probe).
    fn commands(&mut self, world: &World, observer: &mut Observer<'_>) -> Vec<Command>;

    /// Called after each step with the commands' results.
    fn after_step(
        &mut self,
        _world: &World,
        _results: &[Result<CommandOutcome, WorldError>],
        _observer: &mut Observer<'_>,
    ) {
    }
}

/// What a scenario's builder returns: the world and its script.
pub(crate) type Built = Result<(World, Box<dyn Script>), SuiteError>;

/// A named scenario of the suite.
#[derive(Clone, Copy)]
pub struct Scenario {
    /// Short name (the golden key).
    pub name: &'static str,
    /// What it exercises.
    pub summary: &'static str,
    build: fn() -> Built,
}

impl fmt::Debug for Scenario {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Scenario")
            .field("name", &self.name)
            .field("summary", &self.summary)
            .finish_non_exhaustive()
    }
}

/// Every scenario of the suite, in the order of the golden table.
pub const SCENARIOS: &[Scenario] = &[
    Scenario {
        name: "stack_sleep",
        summary: "10-box stack settles and sleeps; a dropped ball and a wake command wake it",
        build: scenarios::stack_sleep,
    },
    Scenario {
        name: "pyramid",
        summary: "the 20-row pyramid (210 boxes) settles and sleeps; a ball knocks its top",
        build: scenarios::pyramid,
    },
    Scenario {
        name: "bullets_toi",
        summary: "bullets at 700-3000 units/s against thin walls (exact time of impact)",
        build: scenarios::bullets_toi,
    },
    Scenario {
        name: "springs",
        summary: "bendy and radial springs, soft to 10^6 stiff; body-to-body springs added and removed",
        build: scenarios::springs,
    },
    Scenario {
        name: "ropes_chain",
        summary: "rope pendulum, 10-link chain, bouncy rope; a link despawned, a rope added",
        build: scenarios::ropes_chain,
    },
    Scenario {
        name: "grapple_rays",
        summary: "scripted grapple (ray cast, attach rope, swing, release) and ray / box / point queries",
        build: scenarios::grapple_rays,
    },
    Scenario {
        name: "commands_churn",
        summary: "spawn, despawn, impulse, velocity, teleport, wake, constraints mid-run; refused commands",
        build: scenarios::commands_churn,
    },
    Scenario {
        name: "bounds_extreme",
        summary: "bodies at the world bounds at max speed, extreme masses and stiffness: saturation, clamping, freezing",
        build: scenarios::bounds_extreme,
    },
];

/// The result of playing one scenario.
#[derive(Clone, Debug)]
pub struct ScenarioRun {
    /// The scenario's name.
    pub name: &'static str,
    /// Checkpoints at tick 0 and every [`CHECKPOINT_EVERY`] ticks.
    pub checkpoints: Vec<Checkpoint>,
    /// What the scenario exercised.
    pub coverage: Coverage,
    /// The recorded replay (initial snapshot, every command, state hashes
    /// every [`CHECKPOINT_EVERY`] ticks).
    pub replay: Replay,
    /// A snapshot taken at [`SNAPSHOT_TICK`].
    pub snapshot: Vec<u8>,
}

impl Scenario {
    /// Builds the scenario's world and plays its script for [`TICKS`]
    /// ticks.
    ///
    /// # Errors
    /// A [`SuiteError`] if the world cannot be built (a scene that no longer
    /// parses, a body the world refuses).
    pub fn run(&self) -> Result<ScenarioRun, SuiteError> {
        let (world, mut script) = (self.build)()?;
        let mut probe = Probe::default();
        let mut coverage = Coverage::default();
        let hash_interval = u32::try_from(CHECKPOINT_EVERY).unwrap_or(60);
        let mut recorder = Recorder::new(world, hash_interval);
        let mut checkpoints = vec![Checkpoint {
            tick: recorder.world().tick(),
            state: recorder.world().state_hash(),
            probe: probe.finish(),
        }];
        let mut snapshot = Vec::new();
        for _ in 0..TICKS {
            let commands = {
                let mut observer = Observer {
                    probe: &mut probe,
                    coverage: &mut coverage,
                };
                script.commands(recorder.world(), &mut observer)
            };
            let results = recorder.step_with(&commands);
            let world = recorder.world();
            for r in &results {
                probe.result(r);
            }
            coverage.results(&results);
            probe.events(world.events());
            coverage.events(world.events());
            coverage.max_bodies = coverage
                .max_bodies
                .max(u32::try_from(world.body_count()).unwrap_or(u32::MAX));
            coverage.max_constraints = coverage
                .max_constraints
                .max(u32::try_from(world.constraints().count()).unwrap_or(u32::MAX));
            let mut observer = Observer {
                probe: &mut probe,
                coverage: &mut coverage,
            };
            script.after_step(world, &results, &mut observer);
            let tick = world.tick();
            if tick % CHECKPOINT_EVERY == 0 {
                checkpoints.push(Checkpoint {
                    tick,
                    state: world.state_hash(),
                    probe: probe.finish(),
                });
            }
            if tick == SNAPSHOT_TICK {
                snapshot = world.snapshot();
            }
        }
        Ok(ScenarioRun {
            name: self.name,
            checkpoints,
            coverage,
            replay: recorder.finish(),
            snapshot,
        })
    }
}

/// The scenario called `name`.
#[must_use]
pub fn scenario(name: &str) -> Option<&'static Scenario> {
    SCENARIOS.iter().find(|s| s.name == name)
}

/// The golden checkpoints of the scenario called `name`.
#[must_use]
pub fn golden(name: &str) -> Option<&'static GoldenScenario> {
    GOLDEN.iter().find(|g| g.name == name)
}

/// How a run differs from its goldens.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Mismatch {
    /// The golden table has no entry for the scenario.
    NoGolden {
        /// The scenario.
        name: String,
    },
    /// A different number of checkpoints (or at different ticks).
    Shape {
        /// The scenario.
        name: String,
        /// Golden checkpoint ticks.
        expected: Vec<u64>,
        /// Actual checkpoint ticks.
        actual: Vec<u64>,
    },
    /// The first checkpoint whose state hash or probe digest differs.
    Hash {
        /// The scenario.
        name: String,
        /// The tick.
        tick: u64,
        /// Golden state hash.
        expected_state: u64,
        /// Actual state hash.
        actual_state: u64,
        /// Golden probe digest.
        expected_probe: u64,
        /// Actual probe digest.
        actual_probe: u64,
    },
}

impl fmt::Display for Mismatch {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Mismatch::NoGolden { name } => write!(f, "{name}: no golden checkpoints")?,
            Mismatch::Shape {
                name,
                expected,
                actual,
            } => write!(
                f,
                "{name}: checkpoints at ticks {actual:?}, golden has {expected:?}"
            )?,
            Mismatch::Hash {
                name,
                tick,
                expected_state,
                actual_state,
                expected_probe,
                actual_probe,
            } => {
                write!(f, "{name}: first difference at tick {tick}:")?;
                if expected_state != actual_state {
                    write!(
                        f,
                        " state hash {actual_state:#018x}, golden {expected_state:#018x};"
                    )?;
                }
                if expected_probe != actual_probe {
                    write!(
                        f,
                        " probe (rays, queries, command results, events) {actual_probe:#018x}, \
                         golden {expected_probe:#018x};"
                    )?;
                }
            }
        }
        Ok(())
    }
}

/// What to do about a mismatch (printed after the table).
pub const MISMATCH_ADVICE: &str = "\
A golden hash moved. If it moved on one target or profile only, that is a \
determinism bug: do not update the goldens. If the behaviour change is \
intended, regenerate determinism/src/golden.rs with
    cargo run --release -p clockwork2d-determinism --example determinism_suite -- --update-golden
then rerun scripts/cross-determinism.sh, and name the behaviour change in \
CHANGELOG.md (every change that moves a golden hash is listed there).";

/// Compares a run with its goldens.
///
/// # Errors
/// The first [`Mismatch`].
pub fn check_golden(run: &ScenarioRun) -> Result<(), Mismatch> {
    let Some(golden) = golden(run.name) else {
        return Err(Mismatch::NoGolden {
            name: run.name.to_owned(),
        });
    };
    check_checkpoints(run.name, &run.checkpoints, golden)
}

fn check_checkpoints(
    name: &str,
    checkpoints: &[Checkpoint],
    golden: &GoldenScenario,
) -> Result<(), Mismatch> {
    let expected: Vec<u64> = golden.checkpoints.iter().map(|c| c.0).collect();
    let actual: Vec<u64> = checkpoints.iter().map(|c| c.tick).collect();
    if expected != actual {
        return Err(Mismatch::Shape {
            name: name.to_owned(),
            expected,
            actual,
        });
    }
    for (c, &(tick, state, probe)) in checkpoints.iter().zip(golden.checkpoints) {
        if c.state != state || c.probe != probe {
            return Err(Mismatch::Hash {
                name: name.to_owned(),
                tick,
                expected_state: state,
                actual_state: c.state,
                expected_probe: probe,
                actual_probe: c.probe,
            });
        }
    }
    Ok(())
}

/// The Rust source of `determinism/src/golden.rs` for these runs
/// (rustfmt-clean).
#[must_use]
pub fn golden_source(runs: &[ScenarioRun]) -> String {
    let mut s = String::new();
    s.push_str(
        "//! Golden checkpoints of the determinism suite. Generated: do not edit by hand.\n\
         //!\n\
         //! Regenerate with\n\
         //! `cargo run --release -p clockwork2d-determinism --example determinism_suite -- --update-golden`\n\
         //! and name the behaviour change in CHANGELOG.md.\n\
         \n\
         use super::GoldenScenario;\n\
         \n\
         /// `(tick, state hash, probe digest)` of every scenario at every checkpoint.\n\
         pub const GOLDEN: &[GoldenScenario] = &[\n",
    );
    for run in runs {
        let _ = writeln!(s, "    GoldenScenario {{");
        let _ = writeln!(s, "        name: {:?},", run.name);
        let _ = writeln!(s, "        checkpoints: &[");
        for c in &run.checkpoints {
            let _ = writeln!(
                s,
                "            ({}, {:#018x}, {:#018x}),",
                c.tick, c.state, c.probe
            );
        }
        let _ = writeln!(s, "        ],");
        let _ = writeln!(s, "    }},");
    }
    s.push_str("];\n");
    s
}

/// Why files written by another target did not verify.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct VerifyFailure(pub String);

impl fmt::Display for VerifyFailure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

/// Checks a scenario's replay and mid-run snapshot written elsewhere
/// (possibly on another architecture):
///
/// 1. the replay decodes and [`Replay::verify`] re-simulates it to its
///    recorded hashes;
/// 2. the recorded state hashes equal this scenario's golden state hashes
///    (so the writer was right too);
/// 3. the snapshot restores to the golden state hash at
///    [`SNAPSHOT_TICK`], and stepping it with the replay's commands gives
///    the golden state hash at every later checkpoint.
///
/// Returns the number of checkpoints compared.
///
/// # Errors
/// A [`VerifyFailure`] saying which check failed.
pub fn verify_files(
    name: &str,
    replay_bytes: &[u8],
    snapshot_bytes: &[u8],
) -> Result<usize, VerifyFailure> {
    let fail = |what: String| Err(VerifyFailure(format!("{name}: {what}")));
    let Some(golden) = golden(name) else {
        return fail("no golden checkpoints".to_owned());
    };
    let replay: Replay = match Replay::from_bytes(replay_bytes) {
        Ok(r) => r,
        Err(e) => return fail(format!("replay refused: {e}")),
    };
    let report = match replay.verify() {
        Ok(r) => r,
        Err(d) => return fail(format!("replay does not verify: {d}")),
    };
    let recorded: Vec<(u64, u64)> = replay
        .checkpoints()
        .iter()
        .map(|c| (c.tick, c.hash))
        .collect();
    let expected: Vec<(u64, u64)> = golden.checkpoints.iter().map(|c| (c.0, c.1)).collect();
    if recorded != expected {
        return fail(format!(
            "the replay's recorded hashes differ from the goldens (recorded {recorded:x?}, golden {expected:x?})"
        ));
    }
    let mut world = match World::<clockwork2d::prelude::Fx>::restore(snapshot_bytes) {
        Ok(w) => w,
        Err(e) => return fail(format!("snapshot refused: {e}")),
    };
    let mut compared = report.checkpoints;
    let start = world.tick();
    let mut goldens = golden.checkpoints.iter().filter(|c| c.0 >= start);
    let mut commands = replay.commands().iter().peekable();
    let mut batch = Vec::new();
    loop {
        if world.tick() % CHECKPOINT_EVERY == 0 {
            let Some(&(tick, state, _)) = goldens.next() else {
                return fail(format!(
                    "snapshot at tick {} is past the goldens",
                    world.tick()
                ));
            };
            if tick != world.tick() || state != world.state_hash() {
                return fail(format!(
                    "snapshot continuation at tick {}: state hash {:#018x}, golden {state:#018x} (tick {tick})",
                    world.tick(),
                    world.state_hash()
                ));
            }
            compared += 1;
        }
        if world.tick() >= replay.final_tick() {
            break;
        }
        batch.clear();
        while let Some((t, c)) = commands.peek() {
            if *t < world.tick() {
                commands.next();
            } else if *t == world.tick() {
                batch.push(c.clone());
                commands.next();
            } else {
                break;
            }
        }
        world.step_with(&batch);
    }
    Ok(compared)
}
