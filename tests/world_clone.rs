//! `World::clone` and `World::clone_from` copy the state but not the step's
//! working memory: a clone, and a world overwritten with `clone_from`
//! (whatever it held before), continue bit-identically to the original and
//! to a restored snapshot of it, step after step.

use clockwork2d::prelude::*;
use clockwork2d_scene::BUILTIN_SCENES;
use clockwork2d_scene::Scene;

fn scene(name: &str, ticks: u32) -> World {
    let text = BUILTIN_SCENES
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, t)| *t)
        .unwrap();
    let mut world: World = Scene::from_ron(text).unwrap().build().unwrap();
    for _ in 0..ticks {
        world.step();
    }
    world
}

#[test]
fn clones_and_clone_from_targets_continue_like_the_original() {
    for (name, other) in [
        ("pyramid", "balls"),
        ("balls", "pyramid"),
        ("rope", "mixed"),
    ] {
        // Mid-contact: 40 ticks in, with a warm contact cache.
        let mut original = scene(name, 40);
        let mut clone = original.clone();
        // A target with other bodies, other contacts and a broad-phase order
        // of its own from 25 steps.
        let mut target = scene(other, 25);
        target.clone_from(&original);
        let mut restored: World = World::restore(&original.snapshot()).unwrap();
        for tick in 0..120 {
            let expected = original.state_hash128();
            assert_eq!(
                clone.state_hash128(),
                expected,
                "{name}: clone at tick {tick}"
            );
            assert_eq!(
                target.state_hash128(),
                expected,
                "{name}: clone_from at tick {tick}"
            );
            assert_eq!(
                restored.state_hash128(),
                expected,
                "{name}: restored at tick {tick}"
            );
            original.step();
            clone.step();
            target.step();
            restored.step();
        }
    }
}

/// Loading a saved world into a world that has run ahead (what a rollback
/// does) and re-simulating gives the states of the first run.
#[test]
fn clone_from_an_earlier_state_resimulates_the_same_states() {
    let mut world = scene("mixed", 10);
    let saved = world.clone();
    let mut first_run = Vec::new();
    for _ in 0..30 {
        world.step();
        first_run.push(world.state_hash128());
    }
    world.clone_from(&saved);
    for (tick, expected) in first_run.iter().enumerate() {
        world.step();
        assert_eq!(world.state_hash128(), *expected, "tick {tick}");
    }
}
