//! The `clockwork2d` command-line tool.
//!
//! `clockwork2d run [SCENE] [--ticks N] [--hash-every K]` runs a built-in
//! scene (by name) or a scene file (by path), printing the state hash every
//! K ticks and a final line with the body count and the time per step.
//! With no arguments it runs the built-in default scene.
#![forbid(unsafe_code)]

use std::path::Path;
use std::process::ExitCode;
use std::time::Instant;

use clap::{Parser, Subcommand};
use clockwork2d::World;
use clockwork2d::scene::{BUILTIN_SCENES, DEFAULT_SCENE, Scene, SceneError, builtin};

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
    let result = match cli.command.unwrap_or(Cmd::Run {
        scene: DEFAULT_SCENE.to_owned(),
        ticks: 600,
        hash_every: 60,
    }) {
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
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
    }
}
