//! Walls and pyramids of boxes at default settings (issue 13): columns of
//! equal boxes side by side and touching, columns a hair apart, brick
//! walls (rows offset by half a box), pyramids of equal boxes, walls of
//! flat and of tall boxes, walls of alternating masses, a wall dropped from
//! a gap, and a wall lying sideways under sideways gravity.
//!
//! The physics: a box `n` contacts above the ground (the ground, then the
//! `n − 1` boxes it rests on, row by row) sits at its ideal height minus
//! the overlap the solver leaves in each contact, at most one linear slop
//! (`WorldSettings::linear_slop`, 1e-4) each: `|y − y_ideal| ≤ n · slop` at
//! every tick. It holds however the load spreads over the contacts of a
//! row (a brick rests on two, a box of a wall touches its neighbours), as
//! it is a statement about contact geometry, not about loads. Diagonal
//! neighbours of a wall touch corner to corner; a corner is no face to
//! rest on, and whichever way the solver treats it, the bound above stands.
//!
//! Nothing pushes a box sideways: the walls and pyramids are symmetric
//! under their loads, every net horizontal force is zero, so x may move
//! only within the overlap a side contact may keep, one slop. With
//! restitution 0 nothing adds energy, so the total energy (kinetic +
//! potential, from positions, velocities, masses) never rises above its
//! start (tolerance: f64 rounding of the sum, 1e-12 of it). The walls come
//! to rest, so they fall asleep (the time to sleep is 0.5 s; 2 s allowed).
//!
//! Each case runs 10 s; every case is asleep by about 0.6 s, so the debug
//! profile runs the file in about a second. Figures are printed with
//! `cargo test --release --test solver_walls -- --nocapture`.
mod common;

use clockwork2d::prelude::*;
use common::resting::{RestingBox, RestingRun, run_resting};

const HZ: u64 = 60;
/// Run length: 10 s.
const TICKS: u64 = 10 * HZ;
/// Fixed-point rounding allowed past `n · slop`: positions are multiples
/// of 2⁻³² (2.3e-10) and a contact resting at the edge of the slop is
/// judged on that grid, so a box may sit a few steps past its bound (one
/// was seen); four steps.
const ROUND: f64 = 1e-9;
/// Relative f64 rounding allowed on the energy sum.
const ENERGY_ROUNDING: f64 = 1e-12;

fn slop() -> f64 {
    WorldSettings::<Fx>::default().linear_slop.to_f64()
}

/// The checks of every case: within `n · slop` from `judge_from` on, x
/// within one slop, energy never above the start, asleep by `asleep_by`.
#[track_caller]
fn assert_rests(name: &str, r: &RestingRun, asleep_by: u64) {
    println!(
        "{name:44} worst {:.6} (excess over n·slop {:+.6}) end {:.6} drift {:.2e} asleep from {:?} energy rise {:+.3e}",
        r.worst_error, r.worst_excess, r.end_error, r.drift, r.asleep_from, r.energy_rise
    );
    assert!(
        r.worst_excess <= ROUND,
        "{name}: a box left its n·slop band by {}",
        r.worst_excess
    );
    assert!(r.drift <= slop(), "{name}: x drift {}", r.drift);
    assert!(
        r.energy_rise <= ENERGY_ROUNDING * r.energy_start.abs().max(1.0),
        "{name}: energy rose by {}",
        r.energy_rise
    );
    assert!(
        r.asleep_from.is_some_and(|t| t <= asleep_by),
        "{name}: asleep from {:?}, wanted by tick {asleep_by}",
        r.asleep_from
    );
}

/// `cols × rows` boxes of half extents `half`, columns `2·half.0 + gap`
/// apart, every other row shifted by half a box when `brick`; box `(c, r)`
/// is `r + 1` contacts above the ground. Masses: `mass(r)` per row.
fn wall(
    cols: usize,
    rows: usize,
    half: (f64, f64),
    gap: f64,
    brick: bool,
    mass: impl Fn(usize) -> Option<f64>,
) -> Vec<RestingBox> {
    let mut boxes = vec![];
    for r in 0..rows {
        for c in 0..cols {
            let shift = if brick && r % 2 == 1 { half.0 } else { 0.0 };
            let x = c as f64 * (2.0 * half.0 + gap) + shift;
            let b = RestingBox::at_rest(half, x, half.1 * (2 * r + 1) as f64, r + 1);
            boxes.push(match mass(r) {
                Some(m) => b.with_mass(m),
                None => b,
            });
        }
    }
    boxes
}

fn equal(_: usize) -> Option<f64> {
    None
}

/// A pyramid of `rows` rows of unit boxes, `spacing` apart in a row.
fn pyramid(rows: usize, spacing: f64) -> Vec<RestingBox> {
    let mut boxes = vec![];
    for r in 0..rows {
        let count = rows - r;
        for j in 0..count {
            let x = (j as f64 - (count as f64 - 1.0) / 2.0) * spacing;
            boxes.push(RestingBox::at_rest((0.5, 0.5), x, 0.5 + r as f64, r + 1));
        }
    }
    boxes
}

fn rest(boxes: &[RestingBox]) -> RestingRun {
    run_resting(boxes, WorldSettings::default(), TICKS, 1)
}

/// Columns of unit boxes side by side, exactly touching: every box touches
/// its diagonal neighbours corner to corner.
#[test]
fn walls_of_equal_boxes_rest_within_n_slop() {
    for (cols, rows) in [(2, 10), (3, 10), (10, 10), (5, 20), (20, 20), (3, 30)] {
        let boxes = wall(cols, rows, (0.5, 0.5), 0.0, false, equal);
        assert_rests(&format!("wall {cols}x{rows}"), &rest(&boxes), 2 * HZ);
    }
}

/// Columns a hair apart: within the slop (they count as touching) and
/// beyond it.
#[test]
fn columns_with_tiny_side_gaps_rest_within_n_slop() {
    for gap in [1e-6, 1e-5, 5e-5, 1e-4, 2e-4, 1e-3, 0.01] {
        let boxes = wall(3, 10, (0.5, 0.5), gap, false, equal);
        assert_rests(&format!("3x10 columns {gap} apart"), &rest(&boxes), 2 * HZ);
    }
}

/// Brick walls: each box rests on two, half on each.
#[test]
fn brick_walls_rest_within_n_slop() {
    for (cols, rows, half) in [
        (5, 10, (0.5, 0.25)),
        (10, 20, (0.5, 0.5)),
        (4, 30, (1.0, 0.1)),
    ] {
        let boxes = wall(cols, rows, half, 0.0, true, equal);
        let name = format!(
            "brick wall {cols}x{rows} of {}x{}",
            2.0 * half.0,
            2.0 * half.1
        );
        assert_rests(&name, &rest(&boxes), 2 * HZ);
    }
}

/// Pyramids of equal boxes, the boxes of a row touching or apart.
#[test]
fn pyramids_of_equal_boxes_rest_within_n_slop() {
    for rows in [5, 10, 20, 30] {
        for spacing in [1.0, 1.05] {
            let name = format!("pyramid {rows} rows, spacing {spacing}");
            assert_rests(&name, &rest(&pyramid(rows, spacing)), 2 * HZ);
        }
    }
}

/// Walls of flat boxes (10 × 1 wide-to-high) and of tall ones (1 × 10), and
/// walls whose rows alternate light and 100× heavy boxes.
#[test]
fn walls_of_other_shapes_and_masses_rest_within_n_slop() {
    let flat = wall(5, 20, (1.0, 0.1), 0.0, false, equal);
    assert_rests("wall 5x20 of flat boxes 2x0.2", &rest(&flat), 2 * HZ);
    let tall = wall(10, 5, (0.1, 1.0), 0.0, false, equal);
    assert_rests("wall 10x5 of tall boxes 0.2x2", &rest(&tall), 2 * HZ);
    for (cols, rows) in [(2, 10), (5, 10), (10, 20)] {
        let heavy = |r: usize| Some(if r % 2 == 1 { 100.0 } else { 1.0 });
        let boxes = wall(cols, rows, (0.5, 0.5), 0.0, false, heavy);
        assert_rests(
            &format!("wall {cols}x{rows}, rows x1/x100"),
            &rest(&boxes),
            2 * HZ,
        );
    }
}

/// A 5 × 10 wall whose boxes start 0.01 per contact above their resting
/// heights: they fall and land row on row. Heights are judged once the top
/// row has landed: it falls 0.1, which takes `sqrt(2 · 0.1 / g)` = 0.14 s,
/// plus 0.5 s to settle.
#[test]
fn a_wall_dropped_from_a_gap_settles_within_n_slop() {
    let gap = 0.01;
    let mut boxes = wall(5, 10, (0.5, 0.5), 0.0, false, equal);
    for b in &mut boxes {
        b.start_y = b.rest_y + gap * b.depth as f64;
    }
    let fall: f64 = (2.0 * 10.0 * gap / 10.0).sqrt();
    let judge_from = ((fall + 0.5) * HZ as f64).ceil() as u64;
    let r = run_resting(&boxes, WorldSettings::default(), TICKS, judge_from);
    assert_rests("wall 5x10 dropped from gaps 0.01", &r, judge_from + 2 * HZ);
}

/// The same physics turned a quarter: gravity along −x, a fixed wall whose
/// face is the line x = 0, and a 4 × 10 wall of unit boxes lying against
/// it (rows along x). Box `r` of a row is `r + 1` contacts from the fixed
/// wall: `|x − x_ideal| ≤ (r + 1) · slop`, y within one slop, energy never
/// above the start, asleep by 2 s.
#[test]
fn a_wall_under_sideways_gravity_rests_within_n_slop() {
    let settings = WorldSettings {
        gravity: vec2(-10.0, 0.0),
        ..WorldSettings::default()
    };
    let mut world: World = World::new(settings);
    world
        .add_body(BodyDef::fixed(Shape::aabb(vec2(0.5, 50.0))).position(vec2(-0.5, 0.0)))
        .unwrap();
    let (layers, columns) = (10, 4);
    let mut boxes = vec![];
    for r in 0..layers {
        for c in 0..columns {
            let (x, y) = (0.5 + r as f64, c as f64);
            let id = world
                .add_body(BodyDef::dynamic(Shape::aabb(vec2(0.5, 0.5))).position(vec2(x, y)))
                .unwrap();
            boxes.push((id, x, y, r + 1));
        }
    }
    let energy = |world: &World| -> f64 {
        boxes
            .iter()
            .map(|&(id, ..)| {
                let body = world.body(id).unwrap();
                let (x, _) = body.position().to_f64();
                let (vx, vy) = body.velocity().to_f64();
                let m = body.mass().to_f64();
                0.5 * m * (vx * vx + vy * vy) + m * 10.0 * x
            })
            .sum()
    };
    let e0 = energy(&world);
    let (mut worst_excess, mut drift, mut rise) = (f64::MIN, 0.0f64, f64::MIN);
    let mut asleep_from = None;
    for t in 1..=TICKS {
        world.step();
        for &(id, x, y, depth) in &boxes {
            let (px, py) = world.body(id).unwrap().position().to_f64();
            worst_excess = worst_excess.max((px - x).abs() - depth as f64 * slop());
            drift = drift.max((py - y).abs());
        }
        rise = rise.max(energy(&world) - e0);
        let asleep = boxes
            .iter()
            .all(|&(id, ..)| !world.body(id).unwrap().is_awake());
        match (asleep, asleep_from) {
            (true, None) => asleep_from = Some(t),
            (false, _) => asleep_from = None,
            _ => {}
        }
    }
    println!(
        "sideways wall 4x10: excess over n·slop {worst_excess:+.6}, y drift {drift:.2e}, energy rise {rise:+.3e}, asleep from {asleep_from:?}"
    );
    assert!(
        worst_excess <= 0.0,
        "a box left its n·slop band by {worst_excess}"
    );
    assert!(drift <= slop(), "y drift {drift}");
    assert!(
        rise <= ENERGY_ROUNDING * e0.abs().max(1.0),
        "energy rose by {rise}"
    );
    assert!(
        asleep_from.is_some_and(|t| t <= 2 * HZ),
        "asleep from {asleep_from:?}"
    );
}
