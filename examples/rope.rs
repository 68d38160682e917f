//! A rope pendulum and a chain, printing positions every 30 ticks, then the
//! measured period of the pendulum (against 2π√(L/g) and the exact
//! large-amplitude period) and the largest stretch of each rope.
//!
//! The chain is released horizontal, so its end whips through the bottom;
//! the chain's max stretch is reached there (a known engine limitation of
//! ropes whose direction turns fast within a tick: see the ignored
//! horizontal-chain test in `tests/constraints_rope.rs`).
//!
//! Run with `cargo run --release --example rope`.

use std::f64::consts::PI;

use clockwork2d::prelude::*;

/// Pendulum: length 1, pivot (-2, 4), 20° amplitude.
const PIVOT: (f64, f64) = (-2.0, 4.0);
const LENGTH: f64 = 1.0;
const AMPLITUDE_DEG: f64 = 20.0;
/// Chain: 10 links of 0.15 (mass 0.2, radius 0.05) from (2, 4), started
/// horizontal.
const CHAIN_PIVOT: (f64, f64) = (2.0, 4.0);
const LINKS: usize = 10;
const SEGMENT: f64 = 0.15;

fn main() -> Result<(), WorldError> {
    let settings: WorldSettings = WorldSettings {
        sleep_enabled: false,
        ..WorldSettings::default()
    };
    let g = -settings.gravity.y.to_f64();
    let mut world = World::new(settings);

    let angle = AMPLITUDE_DEG.to_radians();
    let bob = world.add_body(
        BodyDef::dynamic(Shape::circle(fx(0.1)))
            .mass(fx(1.0))
            .position(vec2(
                PIVOT.0 + LENGTH * angle.sin(),
                PIVOT.1 - LENGTH * angle.cos(),
            )),
    )?;
    world.add_constraint(Constraint::rope(
        Anchor::Point(vec2(PIVOT.0, PIVOT.1)),
        Anchor::Body(bob),
        fx(LENGTH),
    ))?;

    let mut links = Vec::new();
    for i in 0..LINKS {
        let id = world.add_body(
            BodyDef::dynamic(Shape::circle(fx(0.05)))
                .mass(fx(0.2))
                .position(vec2(
                    CHAIN_PIVOT.0 + SEGMENT * (i + 1) as f64,
                    CHAIN_PIVOT.1,
                )),
        )?;
        let previous = match links.last() {
            Some(&p) => Anchor::Body(p),
            None => Anchor::Point(vec2(CHAIN_PIVOT.0, CHAIN_PIVOT.1)),
        };
        world.add_constraint(Constraint::rope(previous, Anchor::Body(id), fx(SEGMENT)))?;
        links.push(id);
    }

    let pos = |world: &World, id: BodyId| {
        world
            .body(id)
            .map_or((f64::NAN, f64::NAN), |b| b.position().to_f64())
    };
    println!(
        "{:>5} {:>6} | {:>8} {:>8} | {:>10} {:>10}",
        "tick", "time", "bob x", "bob y", "chain end x", "chain end y"
    );
    let ticks = 1200;
    let (mut crossings, mut previous_x) = (Vec::new(), pos(&world, bob).0 - PIVOT.0);
    let (mut bob_stretch, mut chain_stretch) = (0.0f64, 0.0f64);
    for tick in 0..=ticks {
        if tick % 30 == 0 {
            let (b, e) = (pos(&world, bob), pos(&world, links[LINKS - 1]));
            println!(
                "{:>5} {:>6.2} | {:>8.4} {:>8.4} | {:>10.4} {:>10.4}",
                tick,
                tick as f64 / 60.0,
                b.0,
                b.1,
                e.0,
                e.1
            );
        }
        if tick == ticks {
            break;
        }
        world.step();
        let b = pos(&world, bob);
        let x = b.0 - PIVOT.0;
        if previous_x < 0.0 && x >= 0.0 {
            crossings.push((tick as f64 + previous_x / (previous_x - x)) / 60.0);
        }
        previous_x = x;
        let d = (b.0 - PIVOT.0).hypot(b.1 - PIVOT.1);
        bob_stretch = bob_stretch.max((d - LENGTH) / LENGTH);
        let mut prev = CHAIN_PIVOT;
        for &id in &links {
            let p = pos(&world, id);
            chain_stretch =
                chain_stretch.max(((p.0 - prev.0).hypot(p.1 - prev.1) - SEGMENT) / SEGMENT);
            prev = p;
        }
    }
    let small = 2.0 * PI * (LENGTH / g).sqrt();
    // Exact period: T = 2π√(L/g) / AGM(1, cos(θ₀/2)).
    let (mut a, mut c) = (1.0f64, (angle / 2.0).cos());
    for _ in 0..8 {
        (a, c) = ((a + c) / 2.0, (a * c).sqrt());
    }
    let exact = small / a;
    if let (Some(first), Some(last)) = (crossings.first(), crossings.last())
        && crossings.len() > 1
    {
        let period = (last - first) / (crossings.len() - 1) as f64;
        println!(
            "pendulum period {period:.5} s over {} swings: 2π√(L/g) = {small:.5} ({:+.3} %), exact \
             for {AMPLITUDE_DEG}° = {exact:.5} ({:+.3} %)",
            crossings.len() - 1,
            100.0 * (period / small - 1.0),
            100.0 * (period / exact - 1.0)
        );
    }
    println!(
        "max stretch: pendulum rope {:.4} % of its length, chain {:.4} % of a segment",
        100.0 * bob_stretch,
        100.0 * chain_stretch
    );
    println!("state hash {:016x}", world.state_hash());
    Ok(())
}
