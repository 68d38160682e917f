//! The game under GGRS's SyncTestSession: rollback of 7 frames and
//! re-simulation every frame gives the same checksums; a deliberately
//! non-deterministic step is caught.

use clockwork2d_ggrs::demo::{DuelRules, NondeterministicRules, arena, run_synctest};

/// The run: check distance 7, 10 000 frames, seeded random inputs
/// for both players. Every frame is simulated 8 times (once, then 7
/// re-simulations) once the session is past frame 7; frames 0 to 7 are
/// simulated once: 8 + 9 992 × 8 = 79 944 simulations.
#[test]
fn ten_thousand_frames_at_check_distance_seven_have_no_mismatch() {
    let scene = arena().unwrap();
    let rules = DuelRules::new(scene.players);
    let outcome = run_synctest(scene.world, rules, 10_000, 7, 20_261_123).unwrap();
    assert_eq!(outcome.mismatch, None);
    assert_eq!(outcome.frames, 10_000);
    assert_eq!(outcome.simulated, 8 + (10_000 - 8) * 8);
}

/// Other seeds, shorter: the inputs exercise the grapple (attach, swing,
/// release) differently each time.
#[test]
fn other_seeds_have_no_mismatch() {
    for seed in [1, 2, 3, 0xDEAD_BEEF] {
        let scene = arena().unwrap();
        let outcome =
            run_synctest(scene.world, DuelRules::new(scene.players), 600, 7, seed).unwrap();
        assert_eq!(outcome.mismatch, None, "seed {seed}");
    }
}

/// The negative control: a step whose impulse depends on how often it was
/// called differs between the first simulation and a re-simulation of the
/// same frame. GGRS must report the mismatch, within the first frames that
/// it checks (frame check_distance + 2 is the first whose re-simulations
/// are compared).
#[test]
fn a_nondeterministic_step_is_reported_as_a_mismatch() {
    let scene = arena().unwrap();
    let rules = NondeterministicRules::new(DuelRules::new(scene.players), scene.balls[0]);
    let outcome = run_synctest(scene.world, rules, 10_000, 7, 1).unwrap();
    let (at, frames) = outcome.mismatch.expect("the mismatch is reported");
    assert!(at <= 7 + 3, "reported late, at frame {at}");
    assert!(!frames.is_empty());
}
