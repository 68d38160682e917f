//! Writes the committed seed corpora under `fuzz/seeds/<target>/`:
//!
//! * `snapshot_restore`: a snapshot of every built-in scene at tick 0 and
//!   mid-simulation (contacts cached, bodies asleep);
//! * `replay_verify`: the golden replays of `tests/data/` and a short
//!   replay of every other built-in scene with the seeded scripted input.
//!
//! Run from the repository root:
//! `cargo run --manifest-path fuzz/Cargo.toml --example make_seeds`.

use std::fs;
use std::path::{Path, PathBuf};

use clockwork2d::prelude::{Fx, World};
use clockwork2d::replay::Recorder;
use clockwork2d_scene::{BUILTIN_SCENES, builtin, scripted_commands};

/// Ticks of the mid-simulation snapshot and of the short replays.
const TICKS: u64 = 90;

fn main() {
    let fuzz = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let root = fuzz.parent().expect("fuzz/ has a parent").to_path_buf();
    let seeds = fuzz.join("seeds");
    let snapshots = dir(&seeds.join("snapshot_restore"));
    let replays = dir(&seeds.join("replay_verify"));
    for (name, _) in BUILTIN_SCENES {
        let scene = builtin(name).expect("built-in scenes parse");
        let mut world: World<Fx> = scene.build().expect("built-in scenes build");
        write(
            &snapshots.join(format!("{name}.tick0.snap")),
            &world.snapshot(),
        );
        for _ in 0..TICKS {
            world.step();
        }
        write(
            &snapshots.join(format!("{name}.tick{TICKS}.snap")),
            &world.snapshot(),
        );

        // Scenes with a golden replay get that one (copied below).
        if root.join(format!("tests/data/{name}.replay")).exists() {
            continue;
        }
        let world: World<Fx> = scene.build().expect("built-in scenes build");
        let mut recorder = Recorder::new(world, 10);
        for _ in 0..TICKS {
            let commands = scripted_commands(recorder.world(), 2024);
            recorder.step_with(&commands);
        }
        write(
            &replays.join(format!("{name}.scripted.replay")),
            &recorder.finish().to_bytes(),
        );
    }
    for entry in fs::read_dir(root.join("tests/data")).expect("tests/data exists") {
        let path = entry.expect("readable directory").path();
        if path.extension().is_some_and(|e| e == "replay") {
            let name = path.file_name().expect("a file name");
            write(
                &replays.join(name),
                &fs::read(&path).expect("readable replay"),
            );
        }
    }
}

fn dir(path: &Path) -> PathBuf {
    fs::create_dir_all(path).expect("can create the seed directory");
    path.to_path_buf()
}

fn write(path: &Path, bytes: &[u8]) {
    fs::write(path, bytes).expect("can write a seed");
    println!("{} ({} bytes)", path.display(), bytes.len());
}
