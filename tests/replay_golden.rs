//! Golden replays: one small replay per scene family under `tests/data/`,
//! recorded from the built-in scene with the seeded scripted input. Each
//! must decode, re-simulate to its recorded hashes, and end on the golden
//! hash below, on every machine.
//!
//! A change that moves these hashes is a behaviour change. If it is
//! intended, regenerate the files and the constants with the one command
//! in [`REGENERATE`] and name the change in CHANGELOG.md.

use std::path::PathBuf;

use clockwork2d::prelude::*;
use clockwork2d::replay::{Recorder, Replay};
use clockwork2d_scene::builtin;
use clockwork2d_scene::scripted_commands;

/// The command that rewrites `tests/data/*.replay` and the constants below.
const REGENERATE: &str =
    "cargo test --release --test replay_golden -- --ignored --exact regenerate_golden_replays";

/// `(scene, ticks, hash interval)` of each golden replay; the scripted
/// input uses seed [`SEED`]. The ball pit is shortened: it is the largest.
const RECORDINGS: &[(&str, u64, u32)] = &[
    ("stack", 300, 10),
    ("pyramid", 300, 10),
    ("balls", 90, 10),
    ("bullets", 240, 10),
    ("mixed", 300, 10),
];
const SEED: u64 = 2024;

// BEGIN GOLDEN (written by regenerate_golden_replays)
const GOLDEN: &[(&str, u64)] = &[
    ("stack", 0x7eaf53db48b4e049),
    ("pyramid", 0x51e16126bf3937b2),
    ("balls", 0x732c296e039b7086),
    ("bullets", 0xe2394485569ea57a),
    ("mixed", 0xf79fa3168975e253),
];
// END GOLDEN

fn data_path(scene: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(format!("{scene}.replay"))
}

#[track_caller]
fn fail(scene: &str, what: &str) -> ! {
    panic!(
        "golden replay tests/data/{scene}.replay: {what}\n\
         If this behaviour change is intended, regenerate the golden replays and \
         their hashes with\n    {REGENERATE}\n\
         and name the change in CHANGELOG.md (a change that moves a golden hash is \
         a behaviour change)."
    )
}

#[test]
fn golden_replays_verify_to_their_golden_hashes() {
    for (scene, ticks, _) in RECORDINGS {
        let Some(&(_, golden)) = GOLDEN.iter().find(|(n, _)| n == scene) else {
            fail(scene, "no golden hash recorded");
        };
        let bytes = std::fs::read(data_path(scene))
            .unwrap_or_else(|e| fail(scene, &format!("cannot read: {e}")));
        let replay: Replay = Replay::from_bytes(&bytes)
            .unwrap_or_else(|e| fail(scene, &format!("does not decode: {e}")));
        assert_eq!(replay.ticks(), *ticks);
        let report = replay
            .verify()
            .unwrap_or_else(|d| fail(scene, &d.to_string()));
        if report.final_hash != golden {
            fail(
                scene,
                &format!(
                    "final hash 0x{:016x}, golden 0x{golden:016x}",
                    report.final_hash
                ),
            );
        }
        // The recorded start is still what the scene builds.
        let built: World = builtin(scene).unwrap().build().unwrap();
        if built.state_hash() != replay.initial().state_hash() {
            fail(scene, "the scene now builds a different initial world");
        }
    }
}

fn record(scene: &str, ticks: u64, k: u32) -> Replay {
    let world: World = builtin(scene).unwrap().build().unwrap();
    let mut recorder = Recorder::new(world, k);
    for _ in 0..ticks {
        let commands = scripted_commands(recorder.world(), SEED);
        recorder.step_with(&commands);
    }
    recorder.finish()
}

/// Rewrites `tests/data/*.replay` and the `GOLDEN` table in this file.
#[test]
#[ignore = "regenerates the golden files; run explicitly"]
fn regenerate_golden_replays() {
    let mut table = String::from("const GOLDEN: &[(&str, u64)] = &[\n");
    for (scene, ticks, k) in RECORDINGS {
        let replay = record(scene, *ticks, *k);
        replay.verify().expect("a fresh recording verifies");
        std::fs::write(data_path(scene), replay.to_bytes()).expect("write the replay");
        table.push_str(&format!(
            "    (\"{scene}\", 0x{:016x}),\n",
            replay.final_hash()
        ));
    }
    table.push_str("];\n");
    let source = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/replay_golden.rs");
    let text = std::fs::read_to_string(&source).expect("read this test's source");
    let begin = text.find("// BEGIN GOLDEN").expect("BEGIN marker");
    let start = text[begin..]
        .find('\n')
        .map(|i| begin + i + 1)
        .expect("marker line");
    let end = text.find("// END GOLDEN").expect("END marker");
    let updated = format!("{}{}{}", &text[..start], table, &text[end..]);
    std::fs::write(&source, updated).expect("write this test's source");
    println!("{table}");
}
