//! The `clockwork2d` replay and snapshot subcommands: outputs and exit
//! codes (0 ok, 1 diverged / different, 2 unreadable), and `run` /
//! `scenes` unchanged.

use std::path::PathBuf;
use std::process::{Command as Process, Output};

use clockwork2d::prelude::*;
use clockwork2d::replay::{Recorder, Replay};
use clockwork2d_scene::builtin;

fn cli(args: &[&str]) -> Output {
    Process::new(env!("CARGO_BIN_EXE_clockwork2d"))
        .args(args)
        .output()
        .expect("run clockwork2d")
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// A fresh scratch directory for one test.
fn scratch(test: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("cw2d-cli-{}-{test}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn s(p: &std::path::Path) -> &str {
    p.to_str().unwrap()
}

#[test]
fn record_then_verify_then_info() {
    let dir = scratch("record");
    let out = dir.join("stack.replay");
    let o = cli(&[
        "record",
        "stack",
        "--ticks",
        "120",
        "--hash-every",
        "10",
        "-o",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stdout(&o).starts_with("recorded 120 ticks of stack to "),
        "{}",
        stdout(&o)
    );

    let o = cli(&["verify", s(&out)]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let line = stdout(&o);
    assert!(line.starts_with("ok: 120 ticks, final hash 0x"), "{line}");
    // The hash printed is the replay's.
    let replay: Replay = Replay::from_bytes(&std::fs::read(&out).unwrap()).unwrap();
    assert!(line.contains(&format!("0x{:016x}", replay.final_hash())));
    // No progress bar when not on a terminal.
    assert!(stderr(&o).is_empty(), "{}", stderr(&o));

    let o = cli(&["info", s(&out)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = stdout(&o);
    for needle in [
        "clockwork2d replay",
        "scalar          I32F32 (id 1)",
        "hash interval   10 ticks",
        "ticks           120 (tick 0 to 120)",
        "checkpoints     13",
        "state hash      0x",
    ] {
        assert!(text.contains(needle), "missing {needle:?} in\n{text}");
    }
}

#[test]
fn record_with_an_input_file() {
    let dir = scratch("inputs");
    let inputs = dir.join("inputs.ron");
    std::fs::write(
        &inputs,
        r#"[
            (5, [Spawn((kind: Dynamic, shape: Circle(radius: 0.4), position: (3.0, 12.0)))]),
            (20, [Impulse(body: (11, 0), impulse: (1.0, 2.0)), Wake((3, 0))]),
            (40, [Despawn((11, 0)), Despawn((11, 0))]),
        ]"#,
    )
    .unwrap();
    let out = dir.join("in.replay");
    let o = cli(&[
        "record",
        "stack",
        "--ticks",
        "60",
        "--inputs",
        s(&inputs),
        "-o",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let replay: Replay = Replay::from_bytes(&std::fs::read(&out).unwrap()).unwrap();
    let ticks: Vec<u64> = replay.commands().iter().map(|(t, _)| *t).collect();
    assert_eq!(ticks, vec![5, 20, 20, 40, 40]);
    assert_eq!(cli(&["verify", s(&out)]).status.code(), Some(0));

    // A bad input file is a one-line error, exit 2.
    std::fs::write(&inputs, "[(1, [Explode])]").unwrap();
    let o = cli(&[
        "record",
        "stack",
        "--ticks",
        "5",
        "--inputs",
        s(&inputs),
        "-o",
        s(&out),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(stderr(&o).lines().count(), 1, "{}", stderr(&o));
}

#[test]
fn a_diverging_replay_exits_1() {
    let dir = scratch("diverge");
    let world: World = builtin("stack").unwrap().build().unwrap();
    let mut recorder = Recorder::new(world, 5);
    for _ in 0..30 {
        recorder.step();
    }
    let good = recorder.finish();
    // Same checkpoints, but an extra impulse at tick 12.
    let body = good.initial().bodies().nth(4).unwrap().0;
    let bad = Replay::from_parts(
        good.initial().clone(),
        5,
        30,
        vec![(
            12,
            Command::ApplyImpulse {
                body,
                impulse: Vec2::new(fx(2.0), fx(0.0)),
            },
        )],
        good.checkpoints().to_vec(),
    )
    .unwrap();
    let path = dir.join("bad.replay");
    std::fs::write(&path, bad.to_bytes()).unwrap();
    let o = cli(&["verify", s(&path)]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let line = stdout(&o);
    assert!(line.starts_with("diverged at tick 15: "), "{line}");
    assert!(line.contains("bodies"), "{line}");
}

#[test]
fn unreadable_files_exit_2_with_one_line() {
    let dir = scratch("unreadable");
    let garbage = dir.join("garbage.replay");
    std::fs::write(&garbage, b"not a replay at all").unwrap();
    let truncated = dir.join("truncated.replay");
    let mut recorder = Recorder::new(builtin("stack").unwrap().build::<Fx>().unwrap(), 5);
    recorder.step();
    let bytes = recorder.finish().to_bytes();
    std::fs::write(&truncated, &bytes[..bytes.len() - 3]).unwrap();
    let missing = dir.join("missing.replay");
    for path in [&garbage, &truncated, &missing] {
        for command in ["verify", "info"] {
            let o = cli(&[command, s(path)]);
            assert_eq!(o.status.code(), Some(2), "{command} {}", path.display());
            let err = stderr(&o);
            assert_eq!(err.lines().count(), 1, "{err}");
            assert!(err.starts_with("error: "), "{err}");
        }
    }
    let o = cli(&["verify", s(&truncated)]);
    assert!(stderr(&o).contains("truncated"), "{}", stderr(&o));
}

#[test]
fn verify_and_info_accept_snapshots() {
    let dir = scratch("snapshot");
    let mut world: World = builtin("pyramid").unwrap().build().unwrap();
    for _ in 0..20 {
        world.step();
    }
    let path = dir.join("p.snapshot");
    std::fs::write(&path, world.snapshot()).unwrap();
    let o = cli(&["verify", s(&path)]);
    assert_eq!(o.status.code(), Some(0));
    assert_eq!(
        stdout(&o).trim(),
        format!(
            "ok: snapshot at tick 20, hash 0x{:016x}",
            world.state_hash()
        )
    );
    let o = cli(&["info", s(&path)]);
    assert!(o.status.success());
    assert!(
        stdout(&o).contains("clockwork2d snapshot"),
        "{}",
        stdout(&o)
    );
    assert!(stdout(&o).contains("tick            20"), "{}", stdout(&o));
}

#[test]
fn diff_lists_differences_in_words() {
    let dir = scratch("diff");
    let mut world: World = builtin("stack").unwrap().build().unwrap();
    for _ in 0..10 {
        world.step();
    }
    let a = dir.join("a.snapshot");
    std::fs::write(&a, world.snapshot()).unwrap();
    world.step();
    let b = dir.join("b.snapshot");
    std::fs::write(&b, world.snapshot()).unwrap();

    let o = cli(&["diff", s(&a), s(&a)]);
    assert_eq!(o.status.code(), Some(0));
    assert!(
        stdout(&o).starts_with("identical: tick 10, state hash 0x"),
        "{}",
        stdout(&o)
    );

    let o = cli(&["diff", s(&a), s(&b), "--limit", "5"]);
    assert_eq!(o.status.code(), Some(1));
    let text = stdout(&o);
    let lines: Vec<&str> = text.lines().collect();
    assert!(
        lines[0].contains("differences (A tick 10, B tick 11"),
        "{text}"
    );
    assert_eq!(lines[1], "world: tick 10 vs 11");
    // Which body field differs first between two ticks depends on the
    // physics (a stack at rest changes only its sleep timers; a falling one
    // its positions), so the test checks the form the command promises:
    // the part, the body with its generation, the field, then both values
    // in hex with their decimal reading.
    let body_line = lines[2];
    let rest = body_line
        .strip_prefix("bodies: body ")
        .unwrap_or_else(|| panic!("not a body difference: {text}"));
    let (index, rest) = rest.split_once(" (gen ").expect("generation named");
    assert!(index.parse::<u32>().is_ok(), "{text}");
    let (generation, rest) = rest.split_once(") ").expect("generation closed");
    assert!(generation.parse::<u32>().is_ok(), "{text}");
    let (field, values) = rest.split_once(' ').expect("field then values");
    assert!(
        !field.is_empty()
            && field
                .chars()
                .all(|c| c.is_ascii_lowercase() || c == '_' || c == '.'),
        "field {field:?} in {text}"
    );
    let (before, after) = values.split_once(" vs ").expect("A vs B");
    for value in [before, after] {
        assert!(
            value.starts_with("0x") && value.contains(" (") && value.ends_with(')'),
            "value {value:?} in {text}"
        );
    }
    assert_ne!(before, after, "{text}");
    assert!(text.contains("... and "), "{text}");

    let o = cli(&["diff", s(&a), "/nonexistent/file"]);
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn run_and_scenes_are_unchanged() {
    let o = cli(&["scenes"]);
    assert!(o.status.success());
    assert!(stdout(&o).lines().any(|l| l == "stack"));
    let o = cli(&["run", "stack", "--ticks", "60", "--hash-every", "30"]);
    assert!(o.status.success());
    let text = stdout(&o);
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 3, "{text}");
    assert!(lines[0].starts_with("tick 30 hash 0x"), "{text}");
    assert!(lines[1].starts_with("tick 60 hash 0x"), "{text}");
    assert!(lines[2].starts_with("final tick 60 hash 0x"), "{text}");
    assert!(lines[2].contains(" bodies 11 ms_per_step "), "{text}");
}
