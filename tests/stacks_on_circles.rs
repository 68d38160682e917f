//! Tall stacks on round or uneven foundations rest within `depth · slop`
//! at default settings: columns of 30–100 boxes of random sizes (half
//! widths 0.2–1.5, half heights 0.1–1.0) on the ground, and columns of
//! unit boxes standing on one dynamic circle, on a fixed circle, on a
//! circle 100× lighter than a box, and on two circles held in a slot.
//!
//! The physics: every box, and every circle under them, has an ideal
//! resting height (faces touching, a box's bottom face on the circle's top
//! point) and a `depth`, the number of contacts in series between it and
//! the ground. A resting contact may overlap by up to the linear slop (it is
//! not corrected below that), so a body may rest at most `depth · slop`
//! below its ideal height, at every tick; no contact pushes it above. A
//! box centred on a circle touches it at the circle's top point, where the
//! normal is vertical, so nothing pushes sideways: the x drift must be
//! exactly 0 (the scenes are mirror-symmetric about x = 0 or, for the
//! slot, held by walls). The rest criterion: asleep within 4 s.
//! A dropped stack (gaps of 0.05 per contact) is judged from its second
//! second on, after the fall; its energy may only fall.
//!
//! Run with `--nocapture` to see the table.

use clockwork2d::prelude::*;

mod common;
use common::split_mix::SplitMix;

const SLOP: f64 = 1e-4;
/// 10 s at 60 Hz in release; 4 s (the sleep deadline) in debug.
const TICKS: u64 = if cfg!(debug_assertions) { 240 } else { 600 };
/// The deadline for falling asleep, in ticks (4 s).
const ASLEEP_BY: u64 = 240;

/// What stands under the column.
#[derive(Clone, Copy, Debug)]
enum Base {
    Ground,
    /// A dynamic circle r 0.5 (mass π/4) on the ground.
    Circle,
    /// A dynamic circle r 0.5 of mass 0.01 (100× lighter than a unit box).
    LightCircle,
    /// A fixed circle r 0.5 standing on the ground.
    FixedCircle,
    /// Two dynamic circles r 0.5 side by side in a slot 2 wide; the boxes
    /// are 2 wide and rest on both circles' top points.
    TwoCirclesInSlot,
}

/// One body of the scene: id, x, ideal y, depth.
type Placed = (BodyId, f64, f64, usize);

fn fixed_box(world: &mut World, half: (f64, f64), at: (f64, f64)) {
    world
        .add_body(BodyDef::fixed(Shape::aabb(vec2(half.0, half.1))).position(vec2(at.0, at.1)))
        .expect("fixed box");
}

/// Builds the base; returns the bodies it adds (to be judged too), the
/// height of its top and the depth of a box resting on it.
fn build_base(world: &mut World, base: Base) -> (Vec<Placed>, f64, usize) {
    fixed_box(world, (50.0, 0.5), (0.0, -0.5));
    let circle = |world: &mut World, x: f64, mass: Option<f64>| {
        let mut def = BodyDef::dynamic(Shape::circle(fx(0.5))).position(vec2(x, 0.5));
        if let Some(m) = mass {
            def = def.mass(fx(m));
        }
        world.add_body(def).expect("circle")
    };
    match base {
        Base::Ground => (Vec::new(), 0.0, 0),
        Base::Circle => (vec![(circle(world, 0.0, None), 0.0, 0.5, 1)], 1.0, 1),
        Base::LightCircle => (vec![(circle(world, 0.0, Some(0.01)), 0.0, 0.5, 1)], 1.0, 1),
        Base::FixedCircle => {
            world
                .add_body(BodyDef::fixed(Shape::circle(fx(0.5))).position(vec2(0.0, 0.5)))
                .expect("fixed circle");
            (Vec::new(), 1.0, 0)
        }
        Base::TwoCirclesInSlot => {
            fixed_box(world, (0.5, 0.6), (-1.5, 0.6));
            fixed_box(world, (0.5, 0.6), (1.5, 0.6));
            let placed = [-0.5, 0.5]
                .iter()
                .map(|&x| (circle(world, x, None), x, 0.5, 1))
                .collect();
            (placed, 1.0, 1)
        }
    }
}

/// Runs one column; returns (worst excess over depth·slop, worst drift,
/// asleep-from tick, worst energy rise).
fn run_column(
    base: Base,
    n: usize,
    random_seed: Option<u64>,
    gap: f64,
) -> (f64, f64, Option<u64>, f64) {
    let mut world = World::new(WorldSettings::default());
    let (mut placed, mut top, mut depth) = build_base(&mut world, base);
    let mut sizes = random_seed.map(SplitMix);
    for i in 0..n {
        let (hx, hy) = match sizes.as_mut() {
            Some(r) => (r.range(0.2, 1.5), r.range(0.1, 1.0)),
            None => (0.5, 0.5),
        };
        let hx = if matches!(base, Base::TwoCirclesInSlot) {
            1.0
        } else {
            hx
        };
        let rest_y = top + hy;
        let id = world
            .add_body(
                BodyDef::dynamic(Shape::aabb(vec2(hx, hy)))
                    .position(vec2(0.0, rest_y + gap * (i + 1) as f64)),
            )
            .expect("box");
        depth += 1;
        placed.push((id, 0.0, rest_y, depth));
        top += 2.0 * hy;
    }
    let energy = |world: &World| -> f64 {
        placed
            .iter()
            .map(|&(id, _, _, _)| {
                let b = world.body(id).unwrap();
                let (vx, vy) = b.velocity().to_f64();
                let m = b.mass().to_f64();
                0.5 * m * (vx * vx + vy * vy) + 10.0 * m * b.position().to_f64().1
            })
            .sum()
    };
    let e0 = energy(&world);
    let judge_from = if gap > 0.0 { 61 } else { 1 };
    let (mut excess, mut drift, mut asleep_from, mut rise) = (f64::MIN, 0.0f64, None, f64::MIN);
    for tick in 1..=TICKS {
        world.step();
        let mut all_asleep = true;
        for &(id, x, y, d) in &placed {
            let b = world.body(id).unwrap();
            let (px, py) = b.position().to_f64();
            if tick >= judge_from {
                excess = excess.max((py - y).abs() - d as f64 * SLOP);
            }
            drift = drift.max((px - x).abs());
            all_asleep &= !b.is_awake();
        }
        rise = rise.max(energy(&world) - e0);
        match (all_asleep, asleep_from) {
            (true, None) => asleep_from = Some(tick),
            (false, _) => asleep_from = None,
            _ => {}
        }
    }
    (excess, drift, asleep_from, rise)
}

#[test]
fn stacks_on_circles_and_of_mixed_sizes_rest_within_depth_times_slop() {
    let cases: &[(Base, usize, Option<u64>, f64)] = &[
        (Base::Ground, 30, Some(1), 0.0),
        (Base::Ground, 50, Some(2), 0.0),
        (Base::Ground, 100, Some(3), 0.0),
        (Base::Ground, 50, Some(4), 0.05),
        (Base::Circle, 30, None, 0.0),
        (Base::Circle, 50, None, 0.0),
        (Base::Circle, 100, None, 0.0),
        (Base::Circle, 30, Some(5), 0.0),
        (Base::Circle, 30, None, 0.05),
        (Base::LightCircle, 30, None, 0.0),
        (Base::FixedCircle, 30, None, 0.0),
        (Base::TwoCirclesInSlot, 30, None, 0.0),
        (Base::TwoCirclesInSlot, 50, Some(6), 0.0),
    ];
    for &(base, n, seed, gap) in cases {
        let (excess, drift, asleep_from, rise) = run_column(base, n, seed, gap);
        let label = format!(
            "{n} {} boxes on {base:?}, gap {gap}",
            if seed.is_some() { "random" } else { "unit" }
        );
        println!(
            "{label}: worst |y - ideal| - depth*slop {excess:.6}, drift {drift:e}, asleep from tick {asleep_from:?}, energy rise {rise:.3e}"
        );
        assert!(
            excess <= 0.0,
            "{label}: a body sank {excess} beyond depth*slop"
        );
        assert_eq!(drift, 0.0, "{label}: the column moved sideways");
        assert!(
            asleep_from.is_some_and(|t| t <= ASLEEP_BY),
            "{label}: not asleep by 4 s ({asleep_from:?})"
        );
        // Energy may only fall; rounding of the f64 sum of up to 100 terms
        // of size ~10·m·y is far below 1e-6.
        assert!(rise <= 1e-6, "{label}: energy rose by {rise}");
    }
}
