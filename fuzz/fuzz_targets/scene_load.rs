//! `scene_load`: any text → `Scene::from_ron` → `Scene::build`.
//!
//! Never a panic; errors are typed. Limits are respected: a scene asking
//! for more than `MAX_SCENE_BODIES` bodies is refused with
//! `TooManyBodies` (before anything is allocated), and a built world has
//! exactly the bodies the scene announces, valid settings, a snapshot that
//! round-trips, and steps. A scene that builds also round-trips through
//! its RON text.
#![no_main]

use clockwork2d::prelude::{Fx, World};
use clockwork2d_fuzz::cost::step_within;
use clockwork2d_fuzz::roundtrip::assert_roundtrip;
use clockwork2d_scene::{MAX_SCENE_BODIES, Scene, SceneError};
use libfuzzer_sys::fuzz_target;

/// Scenes with more bodies than this are only checked for the refusal
/// above the limit (building a million bodies is bounded but slow).
const BUILD_BUDGET: u64 = 2_000;
/// Ticks a built world is stepped (within the budget).
const TICKS: u64 = 3;
/// Most pair-ticks spent stepping (`src/cost.rs`): a scene may place its
/// bodies on top of each other, and a step costs about 3 µs per touching
/// pair.
const STEP_BUDGET: u64 = 150_000;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let Ok(scene) = Scene::from_ron(text) else {
        return;
    };
    let count = scene.body_count();
    if count > MAX_SCENE_BODIES {
        match scene.build::<Fx>() {
            Err(SceneError::TooManyBodies(n)) => assert_eq!(n, count),
            other => panic!("a scene of {count} bodies was not refused: {other:?}"),
        }
        return;
    }
    if count > BUILD_BUDGET {
        return;
    }
    let Ok(mut world) = scene.build::<Fx>() else {
        return;
    };
    assert_eq!(world.body_count() as u64, count, "body count");
    assert!(world.settings().validate().is_ok(), "invalid settings");
    let again = Scene::from_ron(&scene.to_ron());
    assert!(
        again.as_ref() == Ok(&scene),
        "the scene does not round-trip through RON: {again:?}"
    );
    step_within(&mut world, TICKS, STEP_BUDGET, |_, _| {});
    let copy: World<Fx> = assert_roundtrip(&world, "built scene");
    drop(copy);
});
