//! Heavy circles on light ones (issue 13): piles with cycles and uneven
//! masses, at the default settings.
//!
//! * A hexagonal pile of `k` rows of circles of radius `r` in a container
//!   exactly `2·k·r` wide (the packing is rigid: no circle can move without
//!   overlapping another or a wall), its top row `ratio` times heavier
//!   than the rest, its circles created
//!   bottom row first or top row first (the order the solver meets the
//!   contacts in must not matter). Each circle rests on two below, along normals 60° from
//!   the horizontal; a contact at rest may overlap by up to the linear
//!   slop, which lowers the circle above by at most `slop / sin 60°`, so a
//!   circle in row `i` (0 at the bottom, on the ground) rests at most
//!   `(i + 1)·slop / sin 60°` below its ideal height. No contact pushes
//!   apart beyond touching, so none rises above it by more than the slop
//!   the walls' contacts may squeeze the bottom row by. Any two circles
//!   overlap by at most the slop (twice it for what the velocity
//!   iterations leave from one step to the next), and the pile sleeps.
//!   Before the covering trees (`solver::forest_cover`) a top row 100×
//!   heavier sank 0.11 into the pile and 1000× fell through it (6.1).
//!
//! Figures print with `--nocapture`.

use clockwork2d::prelude::*;

mod common;
use common::add_ground;

const HZ: u64 = 60;
const SLOP: f64 = 1e-4;
/// Fixed-point rounding allowance on a compared length: four I32F32 steps.
const ROUND: f64 = 1e-9;

fn fixed(world: &mut World, half: (f64, f64), at: (f64, f64)) {
    world
        .add_body(BodyDef::fixed(Shape::aabb(vec2(half.0, half.1))).position(vec2(at.0, at.1)))
        .expect("fixed box");
}

/// The order the pile's circles are created in.
#[derive(Clone, Copy, Debug)]
enum Order {
    BottomRowFirst,
    TopRowFirst,
}

/// The hexagonal pile of the module notes; checks its bounds.
fn heavy_topped_pile(k: usize, r: f64, ratio: f64, heavy_rows: usize, order: Order) {
    let mut world = World::new(WorldSettings::default());
    add_ground(&mut world);
    let half_width = k as f64 * r;
    let wall_height = 2.0 * r * k as f64;
    fixed(
        &mut world,
        (0.5, wall_height),
        (-half_width - 0.5, wall_height),
    );
    fixed(
        &mut world,
        (0.5, wall_height),
        (half_width + 0.5, wall_height),
    );
    let row_height = 3f64.sqrt() * r;
    let mut circles = Vec::new();
    for nth in 0..k {
        let row = match order {
            Order::BottomRowFirst => nth,
            Order::TopRowFirst => k - 1 - nth,
        };
        for j in 0..k - row {
            let x = -half_width + r * (1 + row + 2 * j) as f64;
            let y = r + row_height * row as f64;
            let mass = if row + heavy_rows >= k { ratio } else { 1.0 };
            let id = world
                .add_body(
                    BodyDef::dynamic(Shape::circle(fx(r)))
                        .mass(fx(mass))
                        .position(vec2(x, y)),
                )
                .expect("circle");
            circles.push((id, row, y));
        }
    }
    let sin60 = 3f64.sqrt() / 2.0;
    let (mut worst_sink, mut rise, mut overlap) = (0.0f64, 0.0f64, 0.0f64);
    let mut asleep_from = None;
    for t in 1..=5 * HZ {
        world.step();
        let mut asleep = true;
        let positions: Vec<(f64, f64)> = circles
            .iter()
            .map(|&(id, _, _)| world.body(id).unwrap().position().to_f64())
            .collect();
        for (&(id, row, ideal), &(_, y)) in circles.iter().zip(&positions) {
            let bound = (row + 1) as f64 * SLOP / sin60;
            worst_sink = worst_sink.max((ideal - y) / bound);
            rise = rise.max(y - ideal);
            asleep &= !world.body(id).unwrap().is_awake();
        }
        for (i, a) in positions.iter().enumerate() {
            for b in &positions[i + 1..] {
                overlap = overlap.max(2.0 * r - (a.0 - b.0).hypot(a.1 - b.1));
            }
        }
        asleep_from = match (asleep, asleep_from) {
            (true, None) => Some(t),
            (true, from) => from,
            (false, _) => None,
        };
    }
    println!(
        "pile k {k} r {r} top {heavy_rows} row(s) ×{ratio}, {order:?}: worst sink {worst_sink:.3} of its bound, rise {rise:.1e}, overlap {overlap:.1e}, asleep from tick {asleep_from:?}"
    );
    assert!(worst_sink <= 1.0 + ROUND, "sank {worst_sink} of the bound");
    assert!(rise <= SLOP + ROUND, "rose {rise}");
    assert!(overlap <= 2.0 * SLOP + ROUND, "overlap {overlap}");
    assert!(
        asleep_from.is_some_and(|t| t < 4 * HZ),
        "asleep {asleep_from:?}"
    );
}

#[test]
fn a_heavy_top_row_rests_on_a_pile_of_light_circles() {
    use Order::{BottomRowFirst, TopRowFirst};
    for (k, r, ratio, heavy_rows, order) in [
        (8, 0.5, 10.0, 1, BottomRowFirst),
        (8, 0.5, 100.0, 1, BottomRowFirst),
        (8, 0.5, 1000.0, 1, BottomRowFirst),
        (8, 0.25, 1000.0, 1, BottomRowFirst),
        (12, 0.5, 1000.0, 1, BottomRowFirst),
        (8, 0.5, 10.0, 1, TopRowFirst),
        (8, 0.5, 1000.0, 1, TopRowFirst),
        (12, 0.5, 1000.0, 1, TopRowFirst),
    ] {
        heavy_topped_pile(k, r, ratio, heavy_rows, order);
    }
}
