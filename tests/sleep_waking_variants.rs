//! Sleeping bodies wake whenever the world around them changes, and then
//! move as the physics says: a sleeping stack on a kinematic platform that
//! starts moving down or sideways, a sleeping stack whose fixed ground is
//! moved away, a sleeping box yanked by a rope, a sleeping floating box hit
//! by a slow ball, and a sleeping stack with a box taken out of its middle.
//!
//! Default settings (g = 10, 60 Hz, sleep after 0.5 s below 0.05 units/s).
//! Each scene first waits until its bodies are asleep (a precondition,
//! asserted). The bounds:
//!
//! * **Platform moving down at `v` = 2.** The stack must fall after it. A
//!   body released from rest catches up with a support receding at `v`
//!   after `v/g`, the gap then largest at `v²/(2g)` = 0.2; the engine's
//!   semi-implicit Euler gives, after `n` ticks, `v·n·h − g·h²·n(n+1)/2`,
//!   whose largest value is below that. So the bottom box is never more
//!   than 0.2 (+ slop) above the platform, and it rests on it at the end.
//! * **Platform moving sideways at `v` = 1.** Friction (μ = 0.6, both
//!   bodies' default, geometric mean 0.6) must carry the stack: each box
//!   reaches `v` after slipping at most `v²/(2μg)` = 0.083, plus one tick
//!   of `v·h` for the discrete start: 0.1.
//! * **Ground moved 10 down.** Nothing touches the boxes any more, so each
//!   falls freely: after `n` ticks `y₀ − g·h²·n(n+1)/2` exactly, to
//!   rounding (1e-6).
//! * **Rope yank.** A ball tied to a sleeping box by a slack rope of 3 is
//!   set moving away at 10 units/s: once taut, the rope may not be longer
//!   than 3 plus the ropes' settled allowance (slop + (1 − β)³·g·h² =
//!   1.22e-4, tests/rope_variants.rs), and the box must be dragged along
//!   (the rope's impulse, ~1.6 units/s, against friction μ·g = 6 carries
//!   it ~0.2; asserted: more than 0.1).
//! * **Slow ball into a sleeping floating box** (gravity off, 0.2
//!   units/s, e = 0, equal masses): momentum is kept to rounding and both
//!   end at 0.1.
//! * **Middle box removed from a sleeping stack of 10.** The five above
//!   fall by one box and rest on the four below within `depth · slop`.

use clockwork2d::prelude::*;

const H: f64 = 1.0 / 60.0;
const G: f64 = 10.0;
const SLOP: f64 = 1e-4;

fn position(world: &World, id: BodyId) -> (f64, f64) {
    world.body(id).unwrap().position().to_f64()
}

fn velocity(world: &World, id: BodyId) -> (f64, f64) {
    world.body(id).unwrap().velocity().to_f64()
}

fn all_asleep(world: &World, ids: &[BodyId]) -> bool {
    ids.iter().all(|&id| !world.body(id).unwrap().is_awake())
}

/// Steps until every body of `ids` sleeps (at most 300 ticks).
fn sleep(world: &mut World, ids: &[BodyId]) {
    for _ in 0..300 {
        world.step();
        if all_asleep(world, ids) {
            return;
        }
    }
    panic!("the scene did not fall asleep within 5 s");
}

/// `n` unit boxes stacked at x = 0 on a support whose top is y = 0.
fn column(world: &mut World, n: usize) -> Vec<BodyId> {
    (0..n)
        .map(|i| {
            world
                .add_body(
                    BodyDef::dynamic(Shape::aabb(vec2(0.5, 0.5)))
                        .position(vec2(0.0, 0.5 + i as f64)),
                )
                .expect("box")
        })
        .collect()
}

fn fixed_ground(world: &mut World) -> BodyId {
    world
        .add_body(BodyDef::fixed(Shape::aabb(vec2(50.0, 0.5))).position(vec2(0.0, -0.5)))
        .expect("ground")
}

fn kinematic_platform(world: &mut World) -> BodyId {
    world
        .add_body(BodyDef::kinematic(Shape::aabb(vec2(20.0, 0.25))).position(vec2(0.0, -0.25)))
        .expect("platform")
}

#[test]
fn a_stack_falls_after_its_platform_when_it_sinks() {
    let mut world = World::new(WorldSettings::default());
    let platform = kinematic_platform(&mut world);
    let stack = column(&mut world, 5);
    sleep(&mut world, &stack);
    world
        .apply(Command::SetVelocity {
            body: platform,
            velocity: vec2(0.0, -2.0),
        })
        .unwrap();
    let bound = 2.0 * 2.0 / (2.0 * G) + SLOP;
    let mut worst_gap = f64::MIN;
    for _ in 0..120 {
        world.step();
        let gap = (position(&world, stack[0]).1 - 0.5) - (position(&world, platform).1 + 0.25);
        worst_gap = worst_gap.max(gap);
    }
    let end_gap = (position(&world, stack[0]).1 - 0.5) - (position(&world, platform).1 + 0.25);
    println!(
        "platform sinking at 2: worst gap {worst_gap:.5} (bound v^2/2g {bound:.5}), gap after 2 s {end_gap:.6}"
    );
    assert!(
        worst_gap <= bound,
        "the stack hung in the air: gap {worst_gap}"
    );
    assert!(
        end_gap.abs() <= SLOP,
        "the stack does not rest on the platform: gap {end_gap}"
    );
    assert!(stack.iter().all(|&id| world.body(id).unwrap().is_awake()));
}

#[test]
fn a_stack_is_carried_by_its_platform_when_it_slides() {
    let mut world = World::new(WorldSettings::default());
    let platform = kinematic_platform(&mut world);
    let stack = column(&mut world, 5);
    sleep(&mut world, &stack);
    world
        .apply(Command::SetVelocity {
            body: platform,
            velocity: vec2(1.0, 0.0),
        })
        .unwrap();
    for _ in 0..120 {
        world.step();
    }
    let bound = 1.0 / (2.0 * 0.6 * G) + 1.0 * H;
    let platform_x = position(&world, platform).0;
    let worst_slip = stack
        .iter()
        .map(|&id| platform_x - position(&world, id).0)
        .fold(f64::MIN, f64::max);
    println!(
        "platform sliding at 1: after 2 s platform x {platform_x:.4}, worst slip {worst_slip:.4} (bound {bound:.4}), top box vx {:.4}",
        velocity(&world, stack[4]).0
    );
    assert!(
        worst_slip <= bound && worst_slip >= 0.0,
        "slip {worst_slip}"
    );
    for &id in &stack {
        assert!(
            (velocity(&world, id).0 - 1.0).abs() < 1e-6,
            "a box does not move with the platform"
        );
    }
}

#[test]
fn a_stack_falls_freely_when_its_ground_is_moved_away() {
    let mut world = World::new(WorldSettings::default());
    let ground = fixed_ground(&mut world);
    let stack = column(&mut world, 5);
    sleep(&mut world, &stack);
    let start: Vec<f64> = stack.iter().map(|&id| position(&world, id).1).collect();
    world
        .apply(Command::SetPosition {
            body: ground,
            position: vec2(0.0, -10.5),
        })
        .unwrap();
    let mut worst = 0.0f64;
    for n in 1..=60u32 {
        world.step();
        let fall = G * H * H * f64::from(n * (n + 1)) / 2.0;
        for (&id, &y0) in stack.iter().zip(&start) {
            worst = worst.max((position(&world, id).1 - (y0 - fall)).abs());
        }
    }
    println!("ground moved away: worst departure from free fall over 1 s {worst:.3e}");
    assert!(worst <= 1e-6, "the boxes do not fall freely: {worst}");
}

#[test]
fn a_rope_yanks_a_sleeping_box() {
    let mut world = World::new(WorldSettings::default());
    fixed_ground(&mut world);
    let crate_box = world
        .add_body(BodyDef::dynamic(Shape::aabb(vec2(0.5, 0.5))).position(vec2(0.0, 0.5)))
        .unwrap();
    let ball = world
        .add_body(BodyDef::dynamic(Shape::circle(fx(0.25))).position(vec2(2.0, 0.25)))
        .unwrap();
    world
        .add_constraint(Constraint::rope(
            Anchor::Body(crate_box),
            Anchor::Body(ball),
            fx(3.0),
        ))
        .unwrap();
    sleep(&mut world, &[crate_box, ball]);
    world
        .apply(Command::SetVelocity {
            body: ball,
            velocity: vec2(10.0, 0.0),
        })
        .unwrap();
    let allowance = SLOP + 0.2f64.powi(3) * G * H * H;
    let mut longest = 0.0f64;
    for _ in 0..120 {
        world.step();
        let (a, b) = (position(&world, crate_box), position(&world, ball));
        longest = longest.max((b.0 - a.0).hypot(b.1 - a.1));
    }
    let moved = position(&world, crate_box).0;
    println!(
        "rope yank: longest rope {longest:.6} (max 3 + {allowance:.2e}), box dragged {moved:.4}"
    );
    assert!(
        longest <= 3.0 + allowance,
        "the rope stretched to {longest}"
    );
    assert!(moved > 0.1, "the sleeping box was not dragged ({moved})");
}

#[test]
fn a_slow_ball_wakes_a_floating_sleeper_and_shares_its_momentum() {
    let mut world = World::new(WorldSettings {
        gravity: Vec2::ZERO,
        ..WorldSettings::default()
    });
    let floating = world
        .add_body(BodyDef::dynamic(Shape::aabb(vec2(0.5, 0.5))))
        .unwrap();
    sleep(&mut world, &[floating]);
    let ball = world
        .add_body(
            BodyDef::dynamic(Shape::circle(fx(0.5)))
                .mass(fx(1.0))
                .position(vec2(-1.5, 0.0))
                .velocity(vec2(0.2, 0.0)),
        )
        .unwrap();
    // The ball closes the gap of 0.5 in 2.5 s; run 4 s.
    for _ in 0..240 {
        world.step();
    }
    let (vb, vf) = (velocity(&world, ball), velocity(&world, floating));
    println!(
        "slow ball into a sleeper: ball {vb:?}, box {vf:?}, momentum {:.9}",
        vb.0 + vf.0
    );
    assert!((vb.0 + vf.0 - 0.2).abs() < 1e-8, "momentum not kept");
    assert!(
        (vf.0 - 0.1).abs() < 1e-6 && (vb.0 - 0.1).abs() < 1e-6,
        "not a perfectly inelastic share"
    );
}

#[test]
fn boxes_above_a_removed_box_fall_and_rest_on_the_rest() {
    let mut world = World::new(WorldSettings::default());
    fixed_ground(&mut world);
    let stack = column(&mut world, 10);
    sleep(&mut world, &stack);
    world.remove_body(stack[4]).unwrap();
    for _ in 0..180 {
        world.step();
    }
    let mut worst_excess = f64::MIN;
    for (i, &id) in stack.iter().enumerate() {
        if i == 4 {
            continue;
        }
        let (depth, ideal) = if i < 4 {
            (i + 1, 0.5 + i as f64)
        } else {
            (i, 0.5 + (i - 1) as f64)
        };
        let (x, y) = position(&world, id);
        assert_eq!(x, 0.0, "box {i} moved sideways");
        worst_excess = worst_excess.max((y - ideal).abs() - depth as f64 * SLOP);
    }
    println!(
        "middle box removed: worst |y - ideal| - depth*slop {worst_excess:.6}, asleep again {}",
        all_asleep(&world, &stack[5..])
    );
    assert!(
        worst_excess <= 0.0,
        "a box rests {worst_excess} beyond depth*slop"
    );
}
