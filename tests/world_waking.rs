//! Waking (issue 3): a ball dropped on a sleeping stack wakes it; removing
//! the bottom box of a sleeping stack makes the rest fall.
//!
//! Default settings (g = 10, 60 Hz, time to sleep 0.5 s). A 5-box stack
//! settles and sleeps well within 240 ticks (the 10-box stack of
//! `world_stacking` sleeps by tick ~90); the tests first wait for that.

mod common;

use clockwork2d::prelude::*;
use common::{add_ground, add_stack, y_of};

/// Builds a 5-box stack (starting 0.05 apart) and steps until every box
/// sleeps (at most 240 ticks).
fn sleeping_stack() -> (World, Vec<BodyId>) {
    let mut world = World::new(WorldSettings::default());
    add_ground(&mut world);
    let ids = add_stack(&mut world, 5, 0.05);
    for _ in 0..240 {
        world.step();
        if ids.iter().all(|&id| !world.body(id).unwrap().is_awake()) {
            println!("waking: 5-box stack asleep at tick {}", world.tick());
            return (world, ids);
        }
    }
    panic!("the stack did not sleep within 240 ticks");
}

fn woke_in(events: &[Event], id: BodyId) -> bool {
    events.contains(&Event::Woke(id))
}

#[test]
fn a_ball_dropped_on_a_sleeping_stack_wakes_it() {
    let (mut world, stack) = sleeping_stack();
    // The top box's top face is at y = 5; the ball (radius 0.25) starts with
    // its bottom 1 unit above it and falls 1 unit in sqrt(2/10) = 0.45 s,
    // i.e. ~27 ticks; it is awake (just added), the stack is not.
    let ball = world
        .add_body(BodyDef::dynamic(Shape::circle(fx(0.25))).position(vec2(0.0, 6.25)))
        .unwrap();
    let dropped_at = world.tick();
    let mut woke_at = vec![None; stack.len()];
    for _ in 0..60 {
        world.step();
        for (k, &id) in stack.iter().enumerate() {
            if woke_at[k].is_none() && woke_in(world.events(), id) {
                woke_at[k] = Some(world.tick());
                // The event and the state agree in the step that reports it.
                assert!(
                    world.body(id).unwrap().is_awake(),
                    "box {k}: Woke event but asleep"
                );
            }
        }
        if woke_at.iter().all(Option::is_some) {
            break;
        }
    }
    println!("waking: ball contact woke the stack at ticks {woke_at:?}");
    for (k, tick) in woke_at.iter().enumerate() {
        let tick = tick.unwrap_or_else(|| panic!("box {k} never got a Woke event"));
        // After k ticks the ball has fallen g·h²·k(k+1)/2 = k(k+1)/720
        // (symplectic Euler) and moves at g·h·k = k/6. A sleeper is woken in
        // the step where the pair touches or will touch at the current
        // approach speed: gap - v·h ≤ slop, i.e. at the start of step k
        // 1 - (k-1)k/720 - k/360 ≤ 1e-4, first true at k = 27. (Waking as
        // soon as the pair is within the speculative margin would give
        // k = 25.) Allow 24..=30.
        let n = tick - dropped_at;
        assert!(
            (24..=30).contains(&n),
            "box {k} woke {n} ticks after the drop"
        );
    }
    // The whole island woke in the same step.
    assert!(
        woke_at.windows(2).all(|w| w[0] == w[1]),
        "the island woke piecemeal: {woke_at:?}"
    );
    assert!(
        world.body(ball).unwrap().position().y.to_f64() > 5.0,
        "the ball went into the stack"
    );
}

/// Removes the bottom box (through `remove`) and checks the rest fall.
fn remove_bottom_and_watch(remove: impl FnOnce(&mut World, BodyId) -> Vec<Event>) {
    let (mut world, stack) = sleeping_stack();
    let before: Vec<f64> = stack.iter().map(|&id| y_of(&world, id)).collect();
    let events = remove(&mut world, stack[0]);
    assert!(
        world.body(stack[0]).is_none(),
        "the bottom box is still there"
    );
    for (k, &id) in stack.iter().enumerate().skip(1) {
        assert!(
            world.body(id).unwrap().is_awake(),
            "box {k} still asleep after its support went"
        );
        assert!(
            woke_in(&events, id),
            "no Woke event for box {k}: {events:?}"
        );
    }
    // Three ticks of free fall with symplectic Euler: the drop after n ticks
    // is g·h²·n(n+1)/2 = 10/3600 · 6 = 0.0167. The boxes all fall together
    // (zero relative velocity), so nothing should hold them; warm-start
    // impulses of the old contacts between them are undone by the clamped
    // accumulated impulse. Each must have dropped at least half of that.
    let free_fall = 10.0 / 3600.0 * 6.0;
    let mut y_prev = before.clone();
    for tick in 1..=3 {
        world.step();
        for (k, &id) in stack.iter().enumerate().skip(1) {
            let y = y_of(&world, id);
            assert!(
                y < y_prev[k],
                "box {k} did not move down at tick {tick} ({y} >= {})",
                y_prev[k]
            );
            y_prev[k] = y;
        }
    }
    let drops: Vec<f64> = stack
        .iter()
        .enumerate()
        .skip(1)
        .map(|(k, &id)| before[k] - y_of(&world, id))
        .collect();
    println!(
        "waking: after removing the bottom box, drops over 3 ticks {drops:?} (free fall {free_fall:.6})"
    );
    for (k, d) in drops.iter().enumerate() {
        assert!(*d > free_fall / 2.0, "box {} dropped only {d}", k + 1);
    }
}

#[test]
fn removing_the_bottom_box_of_a_sleeping_stack_makes_the_rest_fall() {
    remove_bottom_and_watch(|world, bottom| {
        world.remove_body(bottom).unwrap();
        world.events().to_vec()
    });
}

#[test]
fn despawning_the_bottom_box_by_command_makes_the_rest_fall() {
    // Through `step_with`, the Woke events are part of that tick's events.
    remove_bottom_and_watch(|world, bottom| {
        let results = world.step_with(&[Command::Despawn(bottom)]);
        assert_eq!(results, vec![Ok(CommandOutcome::Applied)]);
        world.events().to_vec()
    });
}
