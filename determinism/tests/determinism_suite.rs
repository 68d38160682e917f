//! The determinism suite as a normal test (issue 6): every scenario of
//! `clockwork2d::determinism` reproduces its golden hashes, still exercises
//! the feature it is there for, and its replay and snapshot files verify.
//!
//! `cargo test` runs this natively in debug (overflow checks on) and
//! `cargo test --release` in release; `scripts/cross-determinism.sh` runs
//! the same scenarios on i686, aarch64, s390x and wasm32 through the
//! `determinism_suite` binary.

use std::sync::OnceLock;

use clockwork2d_determinism::{
    MISMATCH_ADVICE, SCENARIOS, ScenarioRun, TICKS, check_golden, golden, golden_source,
    verify_files,
};

/// Every scenario, run once for all the tests of this file.
fn runs() -> &'static [ScenarioRun] {
    static RUNS: OnceLock<Vec<ScenarioRun>> = OnceLock::new();
    RUNS.get_or_init(|| {
        SCENARIOS
            .iter()
            .map(|s| {
                s.run()
                    .unwrap_or_else(|e| panic!("{}: cannot run: {e}", s.name))
            })
            .collect()
    })
}

fn run(name: &str) -> &'static ScenarioRun {
    runs()
        .iter()
        .find(|r| r.name == name)
        .unwrap_or_else(|| panic!("no scenario {name}"))
}

#[test]
fn every_scenario_reproduces_its_golden_hashes() {
    let failures: Vec<String> = runs()
        .iter()
        .filter_map(|r| check_golden(r).err().map(|m| m.to_string()))
        .collect();
    assert!(
        failures.is_empty(),
        "determinism suite mismatch:\n  {}\n{MISMATCH_ADVICE}",
        failures.join("\n  ")
    );
}

#[test]
fn the_suite_has_six_or_more_scenarios_of_600_ticks_with_a_checkpoint_every_60() {
    assert!(SCENARIOS.len() >= 6);
    const { assert!(TICKS >= 600) };
    for r in runs() {
        let ticks: Vec<u64> = r.checkpoints.iter().map(|c| c.tick).collect();
        let expected: Vec<u64> = (0..=TICKS / 60).map(|i| i * 60).collect();
        assert_eq!(ticks, expected, "{}", r.name);
        assert!(golden(r.name).is_some(), "{} has no golden entry", r.name);
    }
}

#[test]
fn the_golden_file_is_what_print_golden_prints() {
    // The goldens are exactly the generated source: regenerating with no
    // behaviour change is a no-op (so a hand edit is caught here).
    let source = golden_source(runs());
    let committed = include_str!("../src/golden.rs");
    if check_golden_all() {
        assert_eq!(source, committed);
    }
}

fn check_golden_all() -> bool {
    runs().iter().all(|r| check_golden(r).is_ok())
}

/// Each scenario still does what it is in the suite for (a change that made
/// a scenario stop exercising its feature would keep the hashes stable but
/// lose coverage).
#[test]
fn every_scenario_exercises_its_feature() {
    let stack = &run("stack_sleep").coverage;
    assert!(stack.event_count("slept") >= 10, "{stack:?}");
    assert!(stack.event_count("woke") >= 10, "{stack:?}");

    let pyramid = &run("pyramid").coverage;
    assert!(pyramid.max_bodies >= 211, "{pyramid:?}");
    assert!(pyramid.event_count("slept") >= 210, "{pyramid:?}");

    let bullets = &run("bullets_toi").coverage;
    assert!(bullets.event_count("began") >= 3, "{bullets:?}");

    let springs = &run("springs").coverage;
    assert!(springs.max_constraints >= 9, "{springs:?}");
    assert!(springs.refused.is_empty(), "{springs:?}");

    let ropes = &run("ropes_chain").coverage;
    assert!(ropes.max_constraints >= 12, "{ropes:?}");
    assert!(ropes.refused.is_empty(), "{ropes:?}");

    let grapple = &run("grapple_rays").coverage;
    assert!(
        grapple.ray_hits >= 100 && grapple.ray_misses >= 10,
        "{grapple:?}"
    );
    // Four throws: rope added, swing, rope removed, fling.
    assert_eq!(grapple.applied, 16, "{grapple:?}");
    assert_eq!(grapple.max_constraints, 1, "{grapple:?}");

    let churn = &run("commands_churn").coverage;
    for error in [
        "UnknownBody",
        "NotDynamic",
        "FixedBody",
        "NonPositiveSize",
        "MaterialOutOfRange",
        "NonPositiveMass",
        "ShapeTooLarge",
        "InvalidConstraint",
        "UnknownConstraint",
    ] {
        assert!(churn.refused_count(error) >= 1, "{error}: {churn:?}");
    }
    assert!(churn.applied >= 50, "{churn:?}");

    let bounds = &run("bounds_extreme").coverage;
    assert!(bounds.event_count("frozen") >= 4, "{bounds:?}");
    assert!(bounds.refused_count("SpeedTooLarge") >= 3, "{bounds:?}");
    assert!(bounds.refused_count("OutOfBounds") >= 3, "{bounds:?}");
    assert!(bounds.refused_count("MassOutOfRange") >= 2, "{bounds:?}");
    assert!(bounds.ray_hits >= 10, "{bounds:?}");
}

#[test]
fn replay_and_snapshot_files_verify() {
    for r in runs() {
        let replay = r.replay.to_bytes();
        let compared = verify_files(r.name, &replay, &r.snapshot).unwrap_or_else(|e| panic!("{e}"));
        assert!(compared >= 11 + 6, "{}: {compared} checkpoints", r.name);
    }
}

#[test]
fn damaged_files_are_refused_not_a_panic() {
    let r = run("springs");
    let replay = r.replay.to_bytes();
    let mut bad_snapshot = r.snapshot.clone();
    if let Some(byte) = bad_snapshot.get_mut(40) {
        *byte ^= 0x10;
    }
    assert!(verify_files(r.name, &replay, &bad_snapshot).is_err());
    assert!(verify_files(r.name, &replay[..replay.len() / 2], &r.snapshot).is_err());
    // Files of another scenario do not match this one's goldens.
    let other = run("pyramid");
    assert!(verify_files(r.name, &other.replay.to_bytes(), &other.snapshot).is_err());
    assert!(verify_files("no_such_scene", &replay, &r.snapshot).is_err());
}
