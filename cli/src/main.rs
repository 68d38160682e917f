//! The `clockwork2d` command-line tool.
//!
//! `clockwork2d run [SCENE] [--ticks N] [--hash-every K]` runs a built-in
//! scene (by name) or a scene file (by path), printing the state hash every
//! K ticks and a final line with the body count and the time per step.
//! With no arguments it runs the built-in default scene.
//!
//! Replays and snapshots:
//!
//! * `clockwork2d record SCENE --ticks N [--inputs FILE] [--seed S]
//!   [--hash-every K] -o OUT` records a replay (with a seeded scripted
//!   input when no input file is given);
//! * `clockwork2d verify FILE` re-simulates a replay: exit 0 and
//!   `ok: N ticks, final hash 0x…`, exit 1 and `diverged at tick T: …`,
//!   exit 2 and a one-line reason for a file it cannot read;
//! * `clockwork2d info FILE` prints a snapshot's or replay's header and a
//!   summary;
//! * `clockwork2d diff A B` lists the differences between two snapshots
//!   (exit 0 identical, 1 different, 2 unreadable).
//!
//! Pictures: `clockwork2d render SCENE --ticks N [--every K] [--width W]
//! [--height H] -o OUT.gif|OUT.png` simulates a scene and writes a GIF
//! (a frame every K ticks) or a PNG of the last tick, with a progress bar;
//! exit 2 and a one-line reason for a bad argument.
#![forbid(unsafe_code)]

mod inputs;
mod render_command;

use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::{Duration, Instant};

use clap::{Parser, Subcommand};
use clockwork2d::diff::diff_worlds;
use clockwork2d::dynamics::BodyKind;
use clockwork2d::prelude::{Command, Fx, Scalar, World};
use clockwork2d::replay::{MAX_CHECKPOINTS, MAX_REPLAY_TICKS, Recorder, Replay};
use clockwork2d::snapshot::{FileHeader, FileKind, SnapshotError};
use clockwork2d_scene::{
    BUILTIN_SCENES, DEFAULT_SCENE, Scene, SceneError, builtin, scripted_commands,
};
use fixed::types::I48F16;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use inputs::parse_inputs;

#[derive(Parser)]
#[command(
    name = "clockwork2d",
    version,
    about = "A deterministic 2D physics engine"
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Cmd>,
}

#[derive(Subcommand)]
enum Cmd {
    /// Runs a scene and prints state hashes.
    Run {
        /// A built-in scene name or a path to a .ron scene file.
        #[arg(default_value = DEFAULT_SCENE)]
        scene: String,
        /// Ticks to simulate.
        #[arg(long, default_value_t = 600)]
        ticks: u64,
        /// Print the hash every K ticks (0: only the final line).
        #[arg(long, default_value_t = 60)]
        hash_every: u64,
    },
    /// Lists the built-in scenes.
    Scenes,
    /// Records a replay of a scene.
    Record {
        /// A built-in scene name or a path to a .ron scene file.
        scene: String,
        /// Ticks to record.
        #[arg(long)]
        ticks: u64,
        /// A RON list of (tick, [commands]); without it, a seeded scripted
        /// input (impulses, spawns, despawns) is used.
        #[arg(long)]
        inputs: Option<PathBuf>,
        /// Seed of the scripted input.
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// Record the state hash every K ticks.
        #[arg(long, default_value_t = 1)]
        hash_every: u32,
        /// The replay file to write.
        #[arg(short, long)]
        output: PathBuf,
    },
    /// Re-simulates a replay and checks its recorded state hashes (exit 0
    /// ok, 1 diverged, 2 unreadable).
    Verify {
        /// A replay file (a snapshot file is checked for validity).
        file: PathBuf,
    },
    /// Prints a snapshot's or replay's header and a summary.
    Info {
        /// A snapshot or replay file.
        file: PathBuf,
    },
    /// Lists the differences between two snapshots (exit 0 identical, 1
    /// different, 2 unreadable).
    Diff {
        /// Snapshot A.
        a: PathBuf,
        /// Snapshot B.
        b: PathBuf,
        /// Most differences to print.
        #[arg(long, default_value_t = 100)]
        limit: usize,
    },
    /// Simulates a scene and draws it: a GIF (one frame every K ticks) or
    /// a PNG of the last tick, chosen by the output's extension.
    Render {
        /// A built-in scene name or a path to a .ron scene file.
        scene: String,
        /// Ticks to simulate.
        #[arg(long, default_value_t = 300)]
        ticks: u64,
        /// A GIF frame every K ticks (1 or more).
        #[arg(long, default_value_t = 2, value_parser = clap::value_parser!(u64).range(1..))]
        every: u64,
        /// Picture width in pixels (1 to 4096).
        #[arg(long, default_value_t = 480, value_parser = clap::value_parser!(u32).range(1..=4096))]
        width: u32,
        /// Picture height in pixels (1 to 4096).
        #[arg(long, default_value_t = 320, value_parser = clap::value_parser!(u32).range(1..=4096))]
        height: u32,
        /// The picture to write: OUT.gif or OUT.png.
        #[arg(short, long)]
        output: PathBuf,
    },
}

fn load(scene: &str) -> Result<Scene, SceneError> {
    match builtin(scene) {
        Ok(s) => Ok(s),
        Err(SceneError::Unknown(_)) if Path::new(scene).exists() => {
            Scene::from_file(Path::new(scene))
        }
        Err(e) => Err(e),
    }
}

fn run(scene: &str, ticks: u64, hash_every: u64) -> Result<(), SceneError> {
    let scene = load(scene)?;
    let mut world: World = scene.build()?;
    let mut stepping = std::time::Duration::ZERO;
    for _ in 0..ticks {
        let start = Instant::now();
        world.step();
        stepping += start.elapsed();
        let t = world.tick();
        if hash_every > 0 && t % hash_every == 0 {
            println!("tick {t} hash 0x{:016x}", world.state_hash());
        }
    }
    #[allow(clippy::cast_precision_loss)]
    let ms_per_step = if ticks == 0 {
        0.0
    } else {
        stepping.as_secs_f64() * 1000.0 / ticks as f64
    };
    println!(
        "final tick {} hash 0x{:016x} bodies {} ms_per_step {:.4}",
        world.tick(),
        world.state_hash(),
        world.body_count(),
        ms_per_step
    );
    Ok(())
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let command = cli.command.unwrap_or(Cmd::Run {
        scene: DEFAULT_SCENE.to_owned(),
        ticks: 600,
        hash_every: 60,
    });
    let command = match command {
        Cmd::Record {
            scene,
            ticks,
            inputs,
            seed,
            hash_every,
            output,
        } => return record(&scene, ticks, inputs.as_deref(), seed, hash_every, &output),
        Cmd::Verify { file } => return verify(&file),
        Cmd::Info { file } => return info(&file),
        Cmd::Diff { a, b, limit } => return diff(&a, &b, limit),
        Cmd::Render {
            scene,
            ticks,
            every,
            width,
            height,
            output,
        } => {
            let options = clockwork2d_render::RenderOptions {
                ticks,
                every,
                width,
                height,
                ..clockwork2d_render::RenderOptions::default()
            };
            return render_command::render(&scene, &options, &output);
        }
        other => other,
    };
    let result = match command {
        Cmd::Run {
            scene,
            ticks,
            hash_every,
        } => run(&scene, ticks, hash_every),
        Cmd::Scenes => {
            for (name, _) in BUILTIN_SCENES {
                println!("{name}");
            }
            Ok(())
        }
        // Handled above.
        Cmd::Record { .. }
        | Cmd::Verify { .. }
        | Cmd::Info { .. }
        | Cmd::Diff { .. }
        | Cmd::Render { .. } => Ok(()),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}

/// Prints a one-line error and gives exit code 2.
fn fail(message: impl std::fmt::Display) -> ExitCode {
    eprintln!("error: {message}");
    ExitCode::from(2)
}

fn read_file(path: &Path) -> Result<Vec<u8>, String> {
    std::fs::read(path).map_err(|e| format!("cannot read {}: {e}", path.display()))
}

/// Reads a snapshot or replay file and its header (the frame check that
/// `verify`, `info` and `diff` all start with); the error names the file.
fn read_with_header(path: &Path) -> Result<(Vec<u8>, FileHeader), String> {
    let bytes = read_file(path)?;
    let header = FileHeader::read(&bytes).map_err(|e| format!("{}: {e}", path.display()))?;
    Ok((bytes, header))
}

fn record(
    scene_name: &str,
    ticks: u64,
    inputs: Option<&Path>,
    seed: u64,
    hash_every: u32,
    output: &Path,
) -> ExitCode {
    // A recording the reader would refuse is refused up front.
    let checkpoints = (ticks / u64::from(hash_every.max(1))).saturating_add(2);
    if ticks > MAX_REPLAY_TICKS || checkpoints > MAX_CHECKPOINTS as u64 {
        return fail(format!(
            "a replay holds at most {MAX_REPLAY_TICKS} ticks and {MAX_CHECKPOINTS} checkpoints \
             (use a larger --hash-every)"
        ));
    }
    let world: World = match load(scene_name).and_then(|s| s.build()) {
        Ok(w) => w,
        Err(e) => return fail(e),
    };
    let inputs = match inputs {
        None => None,
        Some(path) => {
            let text = match std::fs::read_to_string(path) {
                Ok(t) => t,
                Err(e) => return fail(format!("cannot read {}: {e}", path.display())),
            };
            match parse_inputs::<Fx>(&text) {
                Ok(list) => Some(list),
                Err(e) => return fail(format!("{}: {e}", path.display())),
            }
        }
    };
    let start = world.tick();
    let mut recorder = Recorder::new(world, hash_every);
    let mut next = 0;
    let mut batch: Vec<Command> = Vec::new();
    for _ in 0..ticks {
        batch.clear();
        match &inputs {
            None => batch.extend(scripted_commands(recorder.world(), seed)),
            Some(list) => {
                let offset = recorder.world().tick().wrapping_sub(start);
                while let Some((t, commands)) = list.get(next)
                    && *t <= offset
                {
                    // Entries for ticks already past (duplicates sorted
                    // together) are applied now, in file order.
                    batch.extend(commands.iter().cloned());
                    next += 1;
                }
            }
        }
        recorder.step_with(&batch);
    }
    if let Some(list) = &inputs
        && next < list.len()
    {
        eprintln!(
            "warning: {} input entries are after tick {ticks} and were not used",
            list.len() - next
        );
    }
    let replay = recorder.finish();
    let bytes = replay.to_bytes();
    if let Err(e) = std::fs::write(output, &bytes) {
        return fail(format!("cannot write {}: {e}", output.display()));
    }
    println!(
        "recorded {ticks} ticks of {scene_name} to {}: {} bytes, {} checkpoints, final hash 0x{:016x}",
        output.display(),
        bytes.len(),
        replay.checkpoints().len(),
        replay.final_hash()
    );
    ExitCode::SUCCESS
}

/// Runs `$body` with `$S` bound to the scalar type of id `$id`, or
/// evaluates `$unknown` for an id this build does not know.
macro_rules! with_scalar {
    ($id:expr, $S:ident => $body:expr, _ => $unknown:expr) => {
        match $id {
            id if id == <Fx as Scalar>::ID => {
                type $S = Fx;
                $body
            }
            id if id == <I48F16 as Scalar>::ID => {
                type $S = I48F16;
                $body
            }
            id if id == <f64 as Scalar>::ID => {
                type $S = f64;
                $body
            }
            id if id == <f32 as Scalar>::ID => {
                type $S = f32;
                $body
            }
            _ => $unknown,
        }
    };
}

fn verify(path: &Path) -> ExitCode {
    let (bytes, header) = match read_with_header(path) {
        Ok(read) => read,
        Err(e) => return fail(e),
    };
    with_scalar!(header.scalar_id, S => verify_as::<S>(path, &bytes, header.kind),
        _ => fail(format!("{}: unknown scalar id {}", path.display(), header.scalar_id)))
}

fn verify_as<S: Scalar>(path: &Path, bytes: &[u8], kind: FileKind) -> ExitCode {
    if kind == FileKind::Snapshot {
        return match World::<S>::restore(bytes) {
            Ok(w) => {
                println!(
                    "ok: snapshot at tick {}, hash 0x{:016x}",
                    w.tick(),
                    w.state_hash()
                );
                ExitCode::SUCCESS
            }
            Err(e) => fail(format!("{}: {e}", path.display())),
        };
    }
    let replay = match Replay::<S>::from_bytes(bytes) {
        Ok(r) => r,
        Err(e) => return fail(format!("{}: {e}", path.display())),
    };
    // The bar appears only once a verify has taken a second, and never
    // when the output goes to a file or a pipe.
    let interactive = std::io::stdout().is_terminal() && std::io::stderr().is_terminal();
    let bar = ProgressBar::with_draw_target(Some(replay.ticks()), ProgressDrawTarget::hidden());
    if let Ok(style) =
        ProgressStyle::with_template("verifying {bar:40} {pos}/{len} ticks ({per_sec}, eta {eta})")
    {
        bar.set_style(style);
    }
    let started = Instant::now();
    let mut shown = false;
    let result = replay.verify_with_progress(|done, total| {
        if done % 32 != 0 && done != total {
            return;
        }
        if !shown && interactive && started.elapsed() > Duration::from_secs(1) {
            bar.set_draw_target(ProgressDrawTarget::stderr());
            shown = true;
        }
        bar.set_position(done);
    });
    bar.finish_and_clear();
    match result {
        Ok(report) => {
            println!(
                "ok: {} ticks, final hash 0x{:016x}",
                report.ticks, report.final_hash
            );
            ExitCode::SUCCESS
        }
        Err(divergence) => {
            println!("{divergence}");
            ExitCode::from(1)
        }
    }
}

fn info(path: &Path) -> ExitCode {
    let (bytes, header) = match read_with_header(path) {
        Ok(read) => read,
        Err(e) => return fail(e),
    };
    println!("clockwork2d {}: {}", header.kind, path.display());
    println!("  format version  {}", header.format_version);
    println!("  written by      clockwork2d {}", header.crate_version);
    println!(
        "  scalar          {} (id {})",
        header.scalar_name, header.scalar_id
    );
    println!("  file size       {} bytes", bytes.len());
    println!("  payload         {} bytes", header.payload_len);
    if let Some(k) = header.hash_interval {
        println!("  hash interval   {k} ticks");
    }
    let result = with_scalar!(header.scalar_id, S => info_as::<S>(&bytes, header.kind),
        _ => Err(SnapshotError::BadHeader { reason: "unknown scalar id" }));
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => fail(format!("{}: {e}", path.display())),
    }
}

fn info_as<S: Scalar>(bytes: &[u8], kind: FileKind) -> Result<(), SnapshotError> {
    let world = match kind {
        FileKind::Snapshot => World::<S>::restore(bytes)?,
        FileKind::Replay => {
            let replay = Replay::<S>::from_bytes(bytes)?;
            println!(
                "  ticks           {} (tick {} to {})",
                replay.ticks(),
                replay.initial().tick(),
                replay.final_tick()
            );
            println!("  commands        {}", replay.commands().len());
            println!("  checkpoints     {}", replay.checkpoints().len());
            println!(
                "  final hash      0x{:016x} (recorded)",
                replay.final_hash()
            );
            println!("  initial world:");
            replay.initial().clone()
        }
    };
    summarize(&world);
    Ok(())
}

fn summarize<S: Scalar>(world: &World<S>) {
    let count = |kind: BodyKind| world.bodies().filter(|(_, b)| b.kind() == kind).count();
    let asleep = world
        .bodies()
        .filter(|(_, b)| b.kind() == BodyKind::Dynamic && !b.is_awake())
        .count();
    let frozen = world.bodies().filter(|(_, b)| b.is_frozen()).count();
    println!("  tick            {}", world.tick());
    println!(
        "  bodies          {} live: {} dynamic ({asleep} asleep, {frozen} frozen), {} kinematic, {} fixed",
        world.body_count(),
        count(BodyKind::Dynamic),
        count(BodyKind::Kinematic),
        count(BodyKind::Fixed)
    );
    println!("  touching pairs  {}", world.touching_pairs().count());
    println!("  constraints     {}", world.constraints().count());
    println!("  last events     {}", world.events().len());
    println!("  state hash      0x{:016x}", world.state_hash());
    println!("  state hash128   0x{:032x}", world.state_hash128());
    let parts: Vec<String> = world
        .state_digest()
        .parts()
        .iter()
        .map(|(name, d)| format!("{name} 0x{d:016x}"))
        .collect();
    println!("  parts           {}", parts.join(", "));
}

fn diff(a: &Path, b: &Path, limit: usize) -> ExitCode {
    let ((bytes_a, header), bytes_b) = match (read_with_header(a), read_file(b)) {
        (Ok(x), Ok(y)) => (x, y),
        (Err(e), _) | (_, Err(e)) => return fail(e),
    };
    with_scalar!(header.scalar_id, S => diff_as::<S>(a, &bytes_a, b, &bytes_b, limit),
        _ => fail(format!("{}: unknown scalar id {}", a.display(), header.scalar_id)))
}

fn diff_as<S: Scalar>(
    a: &Path,
    bytes_a: &[u8],
    b: &Path,
    bytes_b: &[u8],
    limit: usize,
) -> ExitCode {
    let wa = match World::<S>::restore(bytes_a) {
        Ok(w) => w,
        Err(e) => return fail(format!("{}: {e}", a.display())),
    };
    let wb = match World::<S>::restore(bytes_b) {
        Ok(w) => w,
        Err(e) => return fail(format!("{}: {e}", b.display())),
    };
    let differences = diff_worlds(&wa, &wb);
    if differences.is_empty() {
        println!(
            "identical: tick {}, state hash 0x{:016x}",
            wa.tick(),
            wa.state_hash()
        );
        return ExitCode::SUCCESS;
    }
    let parts = wa.state_digest().differing_parts(&wb.state_digest());
    println!(
        "{} differences (A tick {}, B tick {}; parts that differ: {})",
        differences.len(),
        wa.tick(),
        wb.tick(),
        if parts.is_empty() {
            "events only".to_owned()
        } else {
            parts.join(", ")
        }
    );
    for d in differences.iter().take(limit) {
        println!("{d}");
    }
    if differences.len() > limit {
        println!("... and {} more", differences.len() - limit);
    }
    ExitCode::from(1)
}
