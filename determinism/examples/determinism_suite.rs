//! `determinism_suite`: runs every scenario of
//! [`clockwork2d::determinism`] in one process and compares each with its
//! golden hashes, printing one table row per scene:
//! `target  profile  scene  ok|MISMATCH`. Exit 0 when every row is ok,
//! 1 on any mismatch, 2 for a usage or file error.
//!
//! ```text
//! determinism_suite [--label TARGET] [--scene NAME]... [--verbose]
//!                   [--write DIR] [--verify DIR]...
//! determinism_suite --print-golden | --update-golden | --list
//! ```
//!
//! * `--label TARGET`: the target name printed in the table (default: the
//!   architecture and OS this binary was built for).
//! * `--write DIR`: also writes, per scene, the recorded replay
//!   (`SCENE.replay`) and a snapshot at tick 300 (`SCENE.snapshot`), for
//!   another target to verify.
//! * `--verify DIR`: also verifies files written by `--write` (possibly on
//!   another architecture): the replay re-simulates to its hashes, those
//!   hashes are the goldens, the snapshot restores and continues to the
//!   golden hashes, and both files are byte for byte the ones this target
//!   writes.
//! * `--print-golden`: prints the Rust source of `determinism/src/golden.rs`
//!   for the current behaviour; `--update-golden` writes it there.
//!
//! It uses only the crate's normal dependencies, so it builds for every
//! target the cross-determinism script checks, and it uses no float
//! arithmetic.
#![forbid(unsafe_code)]
#![deny(clippy::float_arithmetic)]

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

use clockwork2d_determinism::{
    CHECKPOINT_EVERY, MISMATCH_ADVICE, SCENARIOS, Scenario, ScenarioRun, TICKS, UPDATE_COMMAND,
    check_golden, golden_source, verify_files,
};

/// Where `--update-golden` writes (the source tree this binary was built
/// from).
const GOLDEN_PATH: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/src/golden.rs");
/// The file in a `--write` directory naming the writer.
const WRITER_FILE: &str = "WRITER";

const USAGE: &str = "\
usage: determinism_suite [--label TARGET] [--scene NAME]... [--verbose]
                         [--write DIR] [--verify DIR]...
       determinism_suite --print-golden | --update-golden | --list";

#[derive(Default)]
struct Options {
    label: Option<String>,
    scenes: Vec<String>,
    verbose: bool,
    write: Option<PathBuf>,
    verify: Vec<PathBuf>,
    print_golden: bool,
    update_golden: bool,
    list: bool,
}

fn parse(args: impl Iterator<Item = String>) -> Result<Options, String> {
    let mut o = Options::default();
    let mut args = args.peekable();
    while let Some(arg) = args.next() {
        let mut value = |name: &str| {
            args.next()
                .ok_or_else(|| format!("{name} needs a value\n{USAGE}"))
        };
        match arg.as_str() {
            "--label" => o.label = Some(value("--label")?),
            "--scene" => o.scenes.push(value("--scene")?),
            "--write" => o.write = Some(PathBuf::from(value("--write")?)),
            "--verify" => o.verify.push(PathBuf::from(value("--verify")?)),
            "--verbose" | "-v" => o.verbose = true,
            "--print-golden" => o.print_golden = true,
            "--update-golden" => o.update_golden = true,
            "--list" => o.list = true,
            "--help" | "-h" => return Err(USAGE.to_owned()),
            other => return Err(format!("unknown argument {other:?}\n{USAGE}")),
        }
    }
    Ok(o)
}

fn default_label() -> String {
    let endian = if cfg!(target_endian = "big") {
        "BE"
    } else {
        "LE"
    };
    format!(
        "{}-{} ({endian}, {}-bit)",
        std::env::consts::ARCH,
        std::env::consts::OS,
        usize::BITS
    )
}

fn profile() -> &'static str {
    if cfg!(debug_assertions) {
        "debug"
    } else {
        "release"
    }
}

/// Prints one table row.
fn row(label: &str, scene: &str, status: &str, detail: &str) {
    println!(
        "{label:<32} {:<8} {scene:<44} {status:<9} {detail}",
        profile()
    );
}

fn main() -> ExitCode {
    let options = match parse(std::env::args().skip(1)) {
        Ok(o) => o,
        Err(message) => {
            eprintln!("{message}");
            return ExitCode::from(2);
        }
    };
    if options.list {
        for s in SCENARIOS {
            println!("{:<16} {}", s.name, s.summary);
        }
        return ExitCode::SUCCESS;
    }
    if options.print_golden || options.update_golden {
        return golden(&options);
    }
    let selected: Vec<&Scenario> = if options.scenes.is_empty() {
        SCENARIOS.iter().collect()
    } else {
        let mut chosen = Vec::new();
        for name in &options.scenes {
            match SCENARIOS.iter().find(|s| s.name == name) {
                Some(s) => chosen.push(s),
                None => {
                    eprintln!("unknown scene {name:?} (see --list)");
                    return ExitCode::from(2);
                }
            }
        }
        chosen
    };
    let label = options.label.clone().unwrap_or_else(default_label);
    println!(
        "# determinism suite: {label}, {}, {} scenes, {TICKS} ticks each, checkpoint every {CHECKPOINT_EVERY}",
        profile(),
        selected.len()
    );
    println!(
        "{:<32} {:<8} {:<44} {:<9} detail",
        "# target", "profile", "scene", "result"
    );
    let mut failures = Vec::new();
    let mut usage_error = false;
    let mut passed = 0u32;
    let mut runs: Vec<ScenarioRun> = Vec::new();
    for scenario in &selected {
        let start = Instant::now();
        let run = match scenario.run() {
            Ok(run) => run,
            Err(e) => {
                row(
                    &label,
                    scenario.name,
                    "MISMATCH",
                    &format!("cannot run: {e}"),
                );
                failures.push(format!("{}: cannot run: {e}", scenario.name));
                continue;
            }
        };
        let ms = start.elapsed().as_millis();
        let last = run.checkpoints.last().map_or(0, |c| c.state);
        match check_golden(&run) {
            Ok(()) => {
                passed += 1;
                row(
                    &label,
                    scenario.name,
                    "ok",
                    &format!("final {last:#018x}, {ms} ms"),
                );
            }
            Err(m) => {
                row(
                    &label,
                    scenario.name,
                    "MISMATCH",
                    &format!("final {last:#018x}, {ms} ms"),
                );
                failures.push(m.to_string());
            }
        }
        if options.verbose {
            println!("#   coverage: {:?}", run.coverage);
        }
        if let Some(dir) = &options.write
            && let Err(e) = write_files(dir, &label, &run)
        {
            eprintln!("cannot write {}: {e}", dir.display());
            usage_error = true;
        }
        runs.push(run);
    }
    for dir in &options.verify {
        let writer = std::fs::read_to_string(dir.join(WRITER_FILE))
            .map(|s| s.trim().to_owned())
            .unwrap_or_else(|_| dir.display().to_string());
        for scenario in &selected {
            let name = format!("{} <- files of {writer}", scenario.name);
            match read_pair(dir, scenario.name) {
                Err(e) => {
                    row(&label, &name, "MISMATCH", &e);
                    failures.push(format!("{name}: {e}"));
                }
                Ok((replay, snapshot)) => match verify_files(scenario.name, &replay, &snapshot) {
                    Ok(n) => {
                        // The files this target writes are the same bytes.
                        let ours = runs.iter().find(|r| r.name == scenario.name);
                        let same = ours.is_some_and(|r| {
                            r.snapshot == snapshot && r.replay.to_bytes() == replay
                        });
                        if same {
                            passed += 1;
                            row(
                                &label,
                                &name,
                                "ok",
                                &format!("replay + snapshot verify ({n} checkpoints), same bytes"),
                            );
                        } else {
                            row(&label, &name, "MISMATCH", "see below");
                            failures.push(format!(
                                "{name}: the files verify, but this target writes different bytes"
                            ));
                        }
                    }
                    Err(e) => {
                        row(&label, &name, "MISMATCH", "see below");
                        failures.push(e.to_string());
                    }
                },
            }
        }
    }
    let failed = failures.len();
    for f in &failures {
        println!("# MISMATCH {f}");
    }
    println!("# {label} {}: {passed} passed, {failed} failed", profile());
    if failed > 0 {
        for line in MISMATCH_ADVICE.lines() {
            println!("# {line}");
        }
        return ExitCode::from(1);
    }
    if usage_error {
        return ExitCode::from(2);
    }
    ExitCode::SUCCESS
}

/// `--print-golden` / `--update-golden`.
fn golden(options: &Options) -> ExitCode {
    let mut runs: Vec<ScenarioRun> = Vec::new();
    for s in SCENARIOS {
        match s.run() {
            Ok(run) => runs.push(run),
            Err(e) => {
                eprintln!("{}: cannot run: {e}", s.name);
                return ExitCode::from(2);
            }
        }
    }
    let source = golden_source(&runs);
    if options.print_golden {
        print!("{source}");
    }
    if options.update_golden {
        let moved: Vec<&str> = runs
            .iter()
            .filter(|r| check_golden(r).is_err())
            .map(|r| r.name)
            .collect();
        if let Err(e) = std::fs::write(GOLDEN_PATH, &source) {
            eprintln!("cannot write {GOLDEN_PATH}: {e}");
            return ExitCode::from(2);
        }
        eprintln!("wrote {GOLDEN_PATH}");
        if moved.is_empty() {
            eprintln!("no golden hash moved");
        } else {
            eprintln!(
                "golden hashes moved for: {}. Name this behaviour change in CHANGELOG.md, \
                 and run scripts/cross-determinism.sh to check that every target agrees \
                 (a target that disagrees is a determinism bug, not a reason to run \
                 `{UPDATE_COMMAND}` again).",
                moved.join(", ")
            );
        }
    }
    ExitCode::SUCCESS
}

fn write_files(dir: &Path, label: &str, run: &ScenarioRun) -> std::io::Result<()> {
    std::fs::create_dir_all(dir)?;
    std::fs::write(dir.join(WRITER_FILE), format!("{label}/{}\n", profile()))?;
    std::fs::write(
        dir.join(format!("{}.replay", run.name)),
        run.replay.to_bytes(),
    )?;
    std::fs::write(dir.join(format!("{}.snapshot", run.name)), &run.snapshot)?;
    Ok(())
}

fn read_pair(dir: &Path, name: &str) -> Result<(Vec<u8>, Vec<u8>), String> {
    let read = |file: String| {
        let path = dir.join(&file);
        std::fs::read(&path).map_err(|e| format!("cannot read {}: {e}", path.display()))
    };
    Ok((
        read(format!("{name}.replay"))?,
        read(format!("{name}.snapshot"))?,
    ))
}
