//! A world in steady state allocates nothing per step.
//!
//! How it is checked: `allocation-counter` replaces the global allocator in
//! this test binary with one that counts, per thread, every allocation and
//! reallocation made while a closure runs. Each built-in scene is stepped
//! until its working buffers have grown to the scene's size (the warm-up),
//! then the next ticks are stepped inside `measure` and the count must be
//! exactly zero. The scenes cover every pipeline stage: contacts with warm
//! starting (stack, pyramids, ball pits), bullets with time of impact,
//! sleeping and waking, springs, ropes and rope chains (block solver), and
//! contact events.

use clockwork2d::prelude::*;
use clockwork2d_scene::{BUILTIN_SCENES, builtin};

/// Ticks before measuring: long enough for every scene's contact count to
/// reach its peak (piles have landed, stacks have settled or slept).
const WARM_UP_TICKS: u32 = 600;
/// Ticks measured after the warm-up.
const MEASURED_TICKS: u32 = 120;

#[test]
fn every_builtin_scene_steps_without_allocating_after_warm_up() {
    for (name, _) in BUILTIN_SCENES {
        let mut world: World<Fx> = builtin(name)
            .and_then(|scene| scene.build())
            .unwrap_or_else(|e| panic!("scene {name}: {e}"));
        for _ in 0..WARM_UP_TICKS {
            world.step();
        }
        let info = allocation_counter::measure(|| {
            for _ in 0..MEASURED_TICKS {
                world.step();
            }
        });
        assert_eq!(
            info.count_total, 0,
            "scene {name}: {} allocations ({} bytes) in {MEASURED_TICKS} ticks after warm-up",
            info.count_total, info.bytes_total
        );
    }
}

#[test]
fn the_counter_sees_allocations_made_inside_a_step() {
    // The check above is only meaningful if allocations during a step are
    // counted: adding a body through a command grows the body storage.
    let mut world: World<Fx> = World::new(WorldSettings::default());
    let info = allocation_counter::measure(|| {
        world.step_with(&[Command::Spawn(BodyDef::dynamic(Shape::Circle {
            radius: fx(0.5),
        }))]);
    });
    assert!(info.count_total > 0, "the counting allocator saw nothing");
}
