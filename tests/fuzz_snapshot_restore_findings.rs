//! Findings of the `snapshot_restore` fuzz target (`fuzz/`), as tests that
//! run without cargo-fuzz. The inputs are the committed seeds they became.

use clockwork2d::prelude::*;

/// `balls5000` at tick 90 with one cached warm-start impulse raised from
/// 1.35 to 16 777 217.35 (one byte of the snapshot; checksum repaired). A
/// contact cache holds any non-negative impulse, so restore accepts it;
/// the warm start throws one ball at 3 811 units/s in the first tick, and
/// the crowd it strikes comes out of the second tick's solve at up to
/// 28 616 units/s. `max_speed` (4 096 here) is the largest speed a body
/// may have between steps, so after every tick every velocity component
/// is within it.
#[test]
fn a_restored_warm_start_impulse_of_any_size_leaves_every_body_within_max_speed() {
    let bytes = include_bytes!("../fuzz/seeds/snapshot_restore/balls5000.tick90.warm-impulse.snap");
    let mut world = World::<Fx>::restore(bytes).expect("a valid snapshot");
    let max = world.settings().max_speed;
    // Two ticks: the second is where the solve exceeds the limit (the
    // third would cost seconds: the flying balls' swept boxes overlap
    // hundreds of thousands of pairs).
    for tick in 1..=2 {
        world.step();
        for (id, body) in world.bodies() {
            let v = body.velocity();
            assert!(
                v.x.abs() <= max && v.y.abs() <= max,
                "{id:?} left tick {tick} at {v:?}, above max_speed {max}"
            );
        }
    }
}

/// A snapshot (a fuzzer's mutation, checksum repaired) whose sleeping box
/// moves at 10 625 570 units/s, `max_speed` being 4 096. A sleeping body
/// is never written back, so the step never clamped it and it left every
/// tick above the limit. No world the engine makes holds such a body
/// (`add_body` and the velocity commands refuse it, write-back clamps
/// every awake body, a body falls asleep at rest), so restore refuses it
/// with a reason a person can act on.
#[test]
fn a_restored_body_above_max_speed_is_refused() {
    let bytes =
        include_bytes!("../fuzz/seeds/snapshot_restore/mixed.sleeping-box-above-max-speed.snap");
    let error = World::<Fx>::restore(bytes).expect_err("a body above max_speed");
    let reason = error.to_string();
    assert!(
        reason.contains("velocity above max_speed"),
        "unexpected reason: {reason}"
    );
}
