//! Heavy circles on light ones (issue 13): piles with cycles and uneven
//! masses, at the default settings.
//!
//! * A hexagonal pile of `k` rows of circles of radius `r` in a container
//!   exactly `2·k·r` wide (the packing is rigid: no circle can move without
//!   overlapping another or a wall), some of its circles `ratio` times
//!   heavier than the rest (the top row, the top three rows, the two
//!   middle rows, or every fifth circle), its circles created
//!   bottom row first or top row first (the order the solver meets the
//!   contacts in must not matter), under g = 10 or 100, at the origin or
//!   next to a corner of the world's bounds. Each circle rests on two
//!   below, along normals 60° from
//!   the horizontal; a contact at rest may overlap by up to the linear
//!   slop, which lowers the circle above by at most `slop / sin 60°`, so a
//!   circle in row `i` (0 at the bottom, on the ground) rests at most
//!   `(i + 1)·slop / sin 60°` below its ideal height. No contact pushes
//!   apart beyond touching, so none rises above it by more than the slop
//!   the walls' contacts may squeeze the bottom row by. Any two circles
//!   overlap by at most the slop (twice it for what the velocity
//!   iterations leave from one step to the next), and the pile sleeps.
//!   The masses change none of these bounds: a rigid packing holds any
//!   load, and the slop is what the solver allows at rest.
//!   Before the covering trees (`solver::forest_cover`) a top row 100×
//!   heavier sank 0.11 into the pile and 1000× fell through it (6.1).
//!   Before the block solve's groups took their friction first
//!   (`world::step::solve`), piles of 4–6 rows with ×1000 circles on top,
//!   in the middle or scattered sank up to 3 557 times the bound.
//!   Before the sparse exact solve (`solver::sparse_solve`), piles of 8
//!   rows and more (groups over 64 rows, then solved on covering spanning
//!   trees) with ×1000 circles collapsed (up to 6 818 times the bound),
//!   and so did 5-row piles with every fifth circle ×1000 created top row
//!   first (2 720 times) and most piles at ×10 000.
//!
//! Figures print with `--nocapture`.

use clockwork2d::prelude::*;

const HZ: u64 = 60;
const SLOP: f64 = 1e-4;
/// Fixed-point rounding allowance on a compared length: four I32F32 steps.
const ROUND: f64 = 1e-9;

fn fixed(world: &mut World, half: (f64, f64), at: (f64, f64), mu: Option<f64>) {
    let def = BodyDef::fixed(Shape::aabb(vec2(half.0, half.1))).position(vec2(at.0, at.1));
    let def = match mu {
        Some(mu) => def.friction(fx(mu)),
        None => def,
    };
    world.add_body(def).expect("fixed box");
}

/// The order the pile's circles are created in.
#[derive(Clone, Copy, Debug)]
enum Order {
    BottomRowFirst,
    TopRowFirst,
}

/// Which circles of the pile are heavy.
#[derive(Clone, Copy, Debug)]
enum Heavy {
    /// The top `n` rows.
    Top(usize),
    /// The two middle rows (`k/2 − 1` and `k/2`).
    Middle,
    /// Every fifth circle in creation order.
    EveryFifth,
}

/// One pile of the family in the module notes.
#[derive(Clone, Copy, Debug)]
struct Pile {
    k: usize,
    r: f64,
    ratio: f64,
    heavy: Heavy,
    order: Order,
    g: f64,
    /// Where the container's floor centre is.
    at: (f64, f64),
    /// Every body's friction coefficient (`None`: the default, 0.6).
    mu: Option<f64>,
}

/// A pile with its top `heavy_rows` rows heavy, under g = 10 at the origin.
fn heavy_topped_pile(k: usize, r: f64, ratio: f64, heavy_rows: usize, order: Order) {
    check_pile(Pile {
        k,
        r,
        ratio,
        heavy: Heavy::Top(heavy_rows),
        order,
        g: 10.0,
        at: (0.0, 0.0),
        mu: None,
    })
    .unwrap_or_else(|failure| panic!("{failure}"));
}

/// The hexagonal pile of the module notes: `Err` with the figures when
/// it breaks a bound.
fn check_pile(pile: Pile) -> Result<(), String> {
    let Pile {
        k,
        r,
        ratio,
        heavy,
        order,
        g,
        at,
        mu,
    } = pile;
    let friction = |def: BodyDef| match mu {
        Some(mu) => def.friction(fx(mu)),
        None => def,
    };
    let mut world = World::new(WorldSettings {
        gravity: vec2(0.0, -g),
        ..WorldSettings::default()
    });
    fixed(&mut world, (50.0, 0.5), (at.0, at.1 - 0.5), mu);
    let half_width = k as f64 * r;
    let wall_height = 2.0 * r * k as f64;
    fixed(
        &mut world,
        (0.5, wall_height),
        (at.0 - half_width - 0.5, at.1 + wall_height),
        mu,
    );
    fixed(
        &mut world,
        (0.5, wall_height),
        (at.0 + half_width + 0.5, at.1 + wall_height),
        mu,
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
            let is_heavy = match heavy {
                Heavy::Top(rows) => row + rows >= k,
                Heavy::Middle => row + 1 == k / 2 || row == k / 2,
                Heavy::EveryFifth => circles.len() % 5 == 0,
            };
            let mass = if is_heavy { ratio } else { 1.0 };
            let id = world
                .add_body(friction(
                    BodyDef::dynamic(Shape::circle(fx(r)))
                        .mass(fx(mass))
                        .position(vec2(at.0 + x, at.1 + y)),
                ))
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
            .map(|&(id, _, _)| {
                let (x, y) = world.body(id).unwrap().position().to_f64();
                (x - at.0, y - at.1)
            })
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
    let figures = format!(
        "pile k {k} r {r} {heavy:?} ×{ratio}, {order:?}, g {g}, at {at:?}, μ {mu:?}: worst sink {worst_sink:.3} of its bound, rise {rise:.1e}, overlap {overlap:.1e}, asleep from tick {asleep_from:?}"
    );
    println!("{figures}");
    let rests = worst_sink <= 1.0 + ROUND
        && rise <= SLOP + ROUND
        && overlap <= 2.0 * SLOP + ROUND
        && asleep_from.is_some_and(|t| t < 4 * HZ);
    if rests { Ok(()) } else { Err(figures) }
}

/// Checks every pile, then fails listing those that broke a bound.
fn check_piles(piles: impl IntoIterator<Item = Pile>) {
    let mut count = 0;
    let failures: Vec<String> = piles
        .into_iter()
        .inspect(|_| count += 1)
        .filter_map(|pile| check_pile(pile).err())
        .collect();
    println!("{} of {count} piles broke a bound", failures.len());
    assert!(failures.is_empty(), "{}", failures.join("\n"));
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

/// Piles of 4–6 rows (groups of up to 64 rows) with heavy circles on
/// top, in the middle or scattered, ×10 to ×10 000, both creation orders,
/// g = 10 and 100, at the origin and beside the world's corner
/// (−32 700, −32 700), radius 0.5 and 0.25, friction 0.6 and 0.3. Debug
/// runs take every 7th pile (the test profile is slow).
#[test]
fn heavy_circles_anywhere_in_small_piles_rest() {
    let step = if cfg!(debug_assertions) { 7 } else { 1 };
    check_piles(small_piles().into_iter().step_by(step));
}

/// Piles of 8, 10 and 12 rows (groups of 94 to 212 rows: the sparse exact
/// solve) with heavy circles on top, in the middle or scattered, ×100 to
/// ×10 000, both creation orders, g = 10 and 100; the heaviest beside the
/// world's corner and at friction 0.3. Debug runs take every 11th pile.
#[test]
fn heavy_circles_anywhere_in_large_piles_rest() {
    let step = if cfg!(debug_assertions) { 11 } else { 1 };
    check_piles(large_piles().into_iter().step_by(step));
}

/// The large-pile family of [`heavy_circles_anywhere_in_large_piles_rest`].
fn large_piles() -> Vec<Pile> {
    use Order::{BottomRowFirst, TopRowFirst};
    let layouts = [
        Heavy::Top(1),
        Heavy::Top(3),
        Heavy::Middle,
        Heavy::EveryFifth,
    ];
    let mut piles = Vec::new();
    for k in [8, 10, 12] {
        for heavy in layouts {
            for ratio in [100.0, 1000.0, 10_000.0] {
                for order in [BottomRowFirst, TopRowFirst] {
                    for g in [10.0, 100.0] {
                        piles.push(Pile {
                            k,
                            r: 0.5,
                            ratio,
                            heavy,
                            order,
                            g,
                            at: (0.0, 0.0),
                            mu: None,
                        });
                    }
                }
            }
        }
    }
    // Beside the world's corner, and at friction 0.3: ×1000 and ×10 000.
    for k in [8, 12] {
        for heavy in layouts {
            for ratio in [1000.0, 10_000.0] {
                for order in [BottomRowFirst, TopRowFirst] {
                    for (at, mu) in [((-32_700.0, -32_700.0), None), ((0.0, 0.0), Some(0.3))] {
                        piles.push(Pile {
                            k,
                            r: 0.5,
                            ratio,
                            heavy,
                            order,
                            g: 10.0,
                            at,
                            mu,
                        });
                    }
                }
            }
        }
    }
    piles
}

/// The small-pile family of [`heavy_circles_anywhere_in_small_piles_rest`].
fn small_piles() -> Vec<Pile> {
    use Order::{BottomRowFirst, TopRowFirst};
    let mut piles = Vec::new();
    for k in [4, 5, 6] {
        for heavy in [
            Heavy::Top(1),
            Heavy::Top(3),
            Heavy::Middle,
            Heavy::EveryFifth,
        ] {
            for ratio in [10.0, 100.0, 1000.0, 10_000.0] {
                for order in [BottomRowFirst, TopRowFirst] {
                    for g in [10.0, 100.0] {
                        piles.push(Pile {
                            k,
                            r: 0.5,
                            ratio,
                            heavy,
                            order,
                            g,
                            at: (0.0, 0.0),
                            mu: None,
                        });
                    }
                }
            }
        }
    }
    // Beside the world's corner, smaller, and at friction 0.3: ×1000.
    for k in [4, 5, 6] {
        for heavy in [
            Heavy::Top(1),
            Heavy::Top(3),
            Heavy::Middle,
            Heavy::EveryFifth,
        ] {
            for (r, at, mu) in [
                (0.5, (-32_700.0, -32_700.0), None),
                (0.25, (0.0, 0.0), None),
                (0.5, (0.0, 0.0), Some(0.3)),
            ] {
                for order in [BottomRowFirst, TopRowFirst] {
                    piles.push(Pile {
                        k,
                        r,
                        ratio: 1000.0,
                        heavy,
                        order,
                        g: 10.0,
                        at,
                        mu,
                    });
                }
            }
        }
    }
    piles
}
