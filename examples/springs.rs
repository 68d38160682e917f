//! A bendy spring and a radial ("rotational") spring side by side, under
//! gravity, printing their positions every 30 ticks (half a second).
//!
//! * Bendy spring: two independent springs, one per axis, pulling the body
//!   toward the anchor plus a rest offset. Stiffness (20, 40), so the two
//!   axes oscillate at different frequencies; it settles where gravity and
//!   the y spring balance: `anchor + offset − (0, m·g/k_y)`.
//! * Radial spring: a pole on a pivot with a spring along it; the body
//!   swings freely around the pivot while the pole stretches and shrinks.
//!
//! Run with `cargo run --release --example springs`.

use clockwork2d::prelude::*;

fn main() -> Result<(), WorldError> {
    let mut world = World::new(WorldSettings::default());
    let ball = |world: &mut World, x: f64, y: f64| {
        world.add_body(
            BodyDef::dynamic(Shape::circle(fx(0.25)))
                .mass(fx(1.0))
                .position(vec2(x, y)),
        )
    };

    // Bendy: anchor (-3, 5), rest offset (0, -1), started 1 unit to the right.
    let (anchor, offset, k, c) = ((-3.0, 5.0), (0.0, -1.0), (20.0, 40.0), 0.5);
    let bendy = ball(&mut world, anchor.0 + offset.0 + 1.0, anchor.1 + offset.1)?;
    world.add_constraint(
        Constraint::bendy_spring(
            Anchor::Point(vec2(anchor.0, anchor.1)),
            Anchor::Body(bendy),
            vec2(k.0, k.1),
            fx(c),
        )
        .with_rest_offset(vec2(offset.0, offset.1)),
    )?;

    // Radial: pivot (3, 5), rest length 1.5, released from the horizontal.
    let (pivot, rest, k_radial, c_radial) = ((3.0, 5.0), 1.5, 40.0, 0.5);
    let radial = ball(&mut world, pivot.0 + rest, pivot.1)?;
    world.add_constraint(Constraint::radial_spring(
        Anchor::Point(vec2(pivot.0, pivot.1)),
        Anchor::Body(radial),
        fx(rest),
        fx(k_radial),
        fx(c_radial),
    ))?;

    println!(
        "{:>5} {:>6} | {:>9} {:>9} | {:>9} {:>9} {:>9}",
        "tick", "time", "bendy x", "bendy y", "radial x", "radial y", "pole"
    );
    let row = |world: &World| {
        let b = world.body(bendy).map(|b| b.position().to_f64());
        let r = world.body(radial).map(|b| b.position().to_f64());
        if let (Some(b), Some(r)) = (b, r) {
            let pole = (r.0 - pivot.0).hypot(r.1 - pivot.1);
            println!(
                "{:>5} {:>6.2} | {:>9.4} {:>9.4} | {:>9.4} {:>9.4} {:>9.4}",
                world.tick(),
                world.tick() as f64 / 60.0,
                b.0,
                b.1,
                r.0,
                r.1,
                pole
            );
        }
    };
    row(&world);
    for _ in 0..20 {
        for _ in 0..30 {
            world.step();
        }
        row(&world);
    }
    let g = 10.0;
    println!(
        "bendy equilibrium (anchor + offset − m·g/k_y): ({:.4}, {:.4}); radial pole at rest \
         when hanging: {:.4} (rest + m·g/k)",
        anchor.0 + offset.0,
        anchor.1 + offset.1 - g / k.1,
        rest + g / k_radial
    );
    println!("state hash {:016x}", world.state_hash());
    Ok(())
}
