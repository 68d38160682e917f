//! The grapple rope of the example game: ray cast, attach, swing within
//! the rope's length, release; and any input bytes are safe.

use clockwork2d::prelude::*;
use clockwork2d_ggrs::InputCommands;
use clockwork2d_ggrs::demo::{AIM_DIRECTIONS, DuelInput, DuelRules, arena};
use ggrs::InputStatus;

fn frame(world: &mut World, rules: &DuelRules, inputs: [DuelInput; 2]) {
    let mut commands = Vec::new();
    for (player, input) in inputs.iter().enumerate() {
        rules.commands(world, player, input, InputStatus::Confirmed, &mut commands);
    }
    for result in world.step_with(&commands) {
        result.unwrap();
    }
}

#[test]
fn the_grapple_attaches_to_the_ceiling_swings_within_its_length_and_releases() {
    let scene = arena().unwrap();
    let rules = DuelRules::new(scene.players);
    let mut world = scene.world;
    let player = scene.players[0];
    // Aim (-1, 4): up and to the left, from x = -8 on the floor: the ray
    // meets the ceiling's underside (y = 12) at x ≈ -10.9, before the wall.
    let aim = AIM_DIRECTIONS.iter().position(|&d| d == (-1, 4)).unwrap() as u8;
    let idle = DuelInput::default();
    for _ in 0..30 {
        frame(&mut world, &rules, [idle, idle]);
    }
    let from = world.body(player).unwrap().position();
    let fire = DuelInput {
        buttons: DuelInput::GRAPPLE,
        aim,
    };
    frame(&mut world, &rules, [fire, idle]);
    let rope = DuelRules::rope_of(&world, player).expect("the rope is attached");
    let Some(Constraint::Rope {
        a: Anchor::Point(anchor),
        max_length,
        ..
    }) = world.constraint(rope).copied()
    else {
        panic!("a rope from a point");
    };
    assert_eq!(anchor.y, fx(12.0));
    // The hit is on the aim line: (anchor - from) is parallel to (-1, 4),
    // and the rope is as long as the cast.
    let d = anchor - from;
    assert!((-d.x.to_f64() * 4.0 - d.y.to_f64()).abs() < 1e-6);
    assert!((d.length().to_f64() - max_length.to_f64()).abs() < 1e-6);
    // Swing: run right for two seconds holding the rope. An inextensible
    // rope keeps the player within its length (up to the solver's position
    // slop, a few thousandths of a unit; 0.02 allows for it).
    let swing = DuelInput {
        buttons: DuelInput::GRAPPLE | DuelInput::RIGHT,
        aim,
    };
    let mut farthest = 0.0f64;
    let mut moved = 0.0f64;
    for _ in 0..120 {
        frame(&mut world, &rules, [swing, idle]);
        let p = world.body(player).unwrap().position();
        farthest = farthest.max((anchor - p).length().to_f64());
        moved = moved.max((p - from).length().to_f64());
    }
    assert!(
        farthest <= max_length.to_f64() + 0.02,
        "{farthest} > {max_length:?}"
    );
    assert!(moved > 1.0, "the player moved at most {moved} units");
    // Release.
    frame(&mut world, &rules, [idle, idle]);
    assert_eq!(DuelRules::rope_of(&world, player), None);
}

/// Every button byte with every aim byte (remote peers can send anything):
/// the commands either apply or are refused; nothing panics and the
/// world stays valid (its snapshot restores, and restoring validates).
#[test]
fn every_input_value_is_safe() {
    let scene = arena().unwrap();
    let rules = DuelRules::new(scene.players);
    let mut world = scene.world;
    for buttons in 0..=255u8 {
        let input = DuelInput {
            buttons,
            aim: buttons.wrapping_mul(37),
        };
        let mut commands = Vec::new();
        for player in 0..3 {
            rules.commands(
                &world,
                player,
                &input,
                InputStatus::Predicted,
                &mut commands,
            );
        }
        world.step_with(&commands);
        let again: World = World::restore(&world.snapshot()).unwrap();
        assert_eq!(again.state_hash128(), world.state_hash128());
    }
}
