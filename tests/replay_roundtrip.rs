//! Recording, storing, reading and verifying replays; divergences name the
//! tick, both hashes and the parts that differ.

use clockwork2d::prelude::*;
use clockwork2d::replay::{Checkpoint, Recorder, Replay};
use clockwork2d::snapshot::{FileKind, SnapshotError};
use clockwork2d_scene::builtin;
use clockwork2d_scene::scripted_commands;

fn record(scene: &str, ticks: u64, k: u32, seed: u64) -> (Replay, World) {
    let world: World = builtin(scene).unwrap().build().unwrap();
    let mut recorder = Recorder::new(world, k);
    for _ in 0..ticks {
        let commands = scripted_commands(recorder.world(), seed);
        recorder.step_with(&commands);
    }
    recorder.finish_with_world()
}

#[test]
fn a_recording_verifies_and_round_trips_exactly() {
    let (replay, end) = record("mixed", 200, 7, 9);
    assert_eq!(replay.ticks(), 200);
    assert_eq!(replay.final_tick(), 200);
    assert_eq!(replay.final_hash(), end.state_hash());
    // Checkpoints at 0, 7, ..., 196 and the final 200.
    let ticks: Vec<u64> = replay.checkpoints().iter().map(|c| c.tick).collect();
    assert_eq!(ticks.first(), Some(&0));
    assert_eq!(ticks.get(1), Some(&7));
    assert_eq!(ticks.last(), Some(&200));
    assert_eq!(ticks.len(), 200 / 7 + 2);
    assert!(replay.commands().len() > 10);

    let bytes = replay.to_bytes();
    assert_eq!(&bytes[..8], b"CW2DRPLY");
    let read: Replay = Replay::from_bytes(&bytes).unwrap();
    assert_eq!(read.to_bytes(), bytes, "re-encoding must be byte-identical");
    assert_eq!(read.hash_interval(), 7);
    assert_eq!(read.crate_version(), env!("CARGO_PKG_VERSION"));
    let report = read.verify().unwrap();
    assert_eq!(report.ticks, 200);
    assert_eq!(report.final_tick, 200);
    assert_eq!(report.final_hash, end.state_hash());
    assert_eq!(report.final_hash128, end.state_hash128());
    assert_eq!(report.checkpoints, ticks.len());
}

#[test]
fn a_recording_can_start_mid_game() {
    let mut world: World = builtin("stack").unwrap().build().unwrap();
    for _ in 0..77 {
        world.step();
    }
    let mut recorder = Recorder::new(world, 10);
    for _ in 0..45 {
        let commands = scripted_commands(recorder.world(), 1);
        recorder.step_with(&commands);
    }
    let replay = recorder.finish();
    assert_eq!(replay.initial().tick(), 77);
    assert_eq!(replay.final_tick(), 122);
    let read: Replay = Replay::from_bytes(&replay.to_bytes()).unwrap();
    assert_eq!(read.verify().unwrap().final_tick, 122);
}

#[test]
fn refused_commands_are_recorded_and_refused_again() {
    let world: World = builtin("stack").unwrap().build().unwrap();
    let mut recorder = Recorder::new(world, 1);
    let ghost = BodyId::from_parts(999, 3);
    let results = recorder.step_with(&[Command::Despawn(ghost), Command::Wake(ghost)]);
    assert!(results.iter().all(Result::is_err));
    recorder.step();
    let replay = recorder.finish();
    assert_eq!(replay.commands().len(), 2);
    assert!(replay.verify().is_ok());
}

#[test]
fn dropped_inputs_diverge_at_the_next_checkpoint_and_name_the_part() {
    let (replay, _) = record("stack", 120, 10, 4);
    // Drop the first impulse (applied at tick 7): the state differs from
    // tick 8, so the first failing checkpoint is tick 10.
    let mut commands = replay.commands().to_vec();
    let first = commands
        .iter()
        .position(|(_, c)| matches!(c, Command::ApplyImpulse { .. }))
        .unwrap();
    let dropped_at = commands[first].0;
    assert_eq!(dropped_at, 7);
    commands.remove(first);
    let tampered = Replay::from_parts(
        replay.initial().clone(),
        replay.hash_interval(),
        replay.ticks(),
        commands,
        replay.checkpoints().to_vec(),
    )
    .unwrap();
    let d = tampered.verify().unwrap_err();
    assert_eq!(d.tick, 10);
    assert_eq!(d.expected, replay.checkpoints()[1].hash);
    assert_ne!(d.actual, d.expected);
    assert!(d.parts.contains(&"bodies"), "{:?}", d.parts);
    assert!(!d.parts.contains(&"world"), "{:?}", d.parts);
    let text = d.to_string();
    assert!(
        text.starts_with("diverged at tick 10: state hash 0x"),
        "{text}"
    );
    assert!(text.contains("parts that differ: bodies"), "{text}");
    // Through bytes too.
    let read: Replay = Replay::from_bytes(&tampered.to_bytes()).unwrap();
    assert_eq!(read.verify().unwrap_err(), d);
}

#[test]
fn a_different_initial_world_diverges_at_the_first_tick() {
    let (replay, _) = record("stack", 30, 10, 4);
    let mut other = replay.initial().clone();
    let id = other.bodies().nth(3).unwrap().0;
    other
        .apply(Command::SetPosition {
            body: id,
            position: Vec2::new(fx(7.0), fx(9.0)),
        })
        .unwrap();
    let tampered = Replay::from_parts(
        other,
        10,
        30,
        replay.commands().to_vec(),
        replay.checkpoints().to_vec(),
    )
    .unwrap();
    let d = tampered.verify().unwrap_err();
    assert_eq!(d.tick, 0);
    assert_eq!(d.parts, vec!["bodies"]);
}

#[test]
fn inconsistent_tables_are_refused() {
    let (replay, _) = record("stack", 30, 10, 4);
    let parts = |ticks: u64, checkpoints: Vec<Checkpoint>, commands| {
        Replay::from_parts(replay.initial().clone(), 10, ticks, commands, checkpoints)
    };
    let good = replay.checkpoints().to_vec();
    let commands = replay.commands().to_vec();
    assert!(parts(30, good.clone(), commands.clone()).is_ok());
    // A missing checkpoint.
    let mut missing = good.clone();
    missing.remove(1);
    assert!(matches!(
        parts(30, missing, commands.clone()),
        Err(SnapshotError::Invalid(s)) if s.part == "replay"
    ));
    // A tick count that does not match the checkpoints.
    assert!(parts(31, good.clone(), commands.clone()).is_err());
    // A command after the end.
    let mut late = commands.clone();
    late.push((30, Command::Wake(BodyId::from_parts(1, 0))));
    assert!(parts(30, good.clone(), late).is_err());
    // Commands out of order.
    let mut shuffled = commands.clone();
    shuffled.push((0, Command::Wake(BodyId::from_parts(1, 0))));
    assert!(parts(30, good.clone(), shuffled).is_err());
    // Interval 0.
    assert!(Replay::from_parts(replay.initial().clone(), 0, 30, commands, good).is_err());
}

#[test]
fn a_snapshot_is_not_a_replay() {
    let world: World = builtin("stack").unwrap().build().unwrap();
    let e = Replay::<Fx>::from_bytes(&world.snapshot()).unwrap_err();
    assert_eq!(
        e,
        SnapshotError::WrongMagic {
            expected: FileKind::Replay,
            found: Some(FileKind::Snapshot)
        }
    );
}

#[test]
fn replay_framing_errors_are_typed() {
    let (replay, _) = record("stack", 20, 5, 4);
    let bytes = replay.to_bytes();
    for n in 0..bytes.len() {
        assert!(
            matches!(
                Replay::<Fx>::from_bytes(&bytes[..n]),
                Err(SnapshotError::Truncated { .. })
            ),
            "length {n}"
        );
    }
    let mut flipped = bytes.clone();
    let middle = bytes.len() / 2;
    flipped[middle] ^= 1;
    assert!(matches!(
        Replay::<Fx>::from_bytes(&flipped),
        Err(SnapshotError::BadChecksum { .. })
    ));
    let mut longer = bytes;
    longer.push(7);
    assert_eq!(
        Replay::<Fx>::from_bytes(&longer).unwrap_err(),
        SnapshotError::TrailingBytes { extra: 1 }
    );
}

#[test]
fn state_hash128_tracks_the_state() {
    let (_, a) = record("stack", 50, 10, 4);
    let (_, b) = record("stack", 50, 10, 4);
    let (_, c) = record("stack", 51, 10, 4);
    assert_eq!(a.state_hash128(), b.state_hash128());
    assert_ne!(a.state_hash128(), c.state_hash128());
    // Not a widening of the 64-bit hash.
    assert_ne!(a.state_hash128() as u64, a.state_hash());
    assert_ne!((a.state_hash128() >> 64) as u64, a.state_hash());
}
