//! Variants of resting stacks at default settings (issue 13): thin boxes,
//! mixed heights, mass ratios up to 10 000, boxes dropped from gaps,
//! widths from 0.1 to 10, and pyramids whose top half is heavy.
//!
//! The physics: a box resting on `n` contacts in series (the ground and the
//! `n − 1` boxes below it) sits at its ideal height minus the overlap the
//! solver leaves in each contact. A resting contact is not corrected while
//! its overlap is within the linear slop (`WorldSettings::linear_slop`,
//! 1e-4), so each contact may leave at most one slop and the box may sit at
//! most `n · slop` below its ideal height; nothing pushes it above (that
//! would need the faces apart, and a gap has no force). So every box is
//! held to `|y − y_ideal| ≤ n · slop` at every tick, whatever the masses:
//! the bound is a statement about contact geometry, not about loads.
//!
//! No horizontal force acts on a centred column (every normal is vertical
//! and nothing slides), so x stays exactly where it was placed. A resting
//! or falling stack with restitution 0 only loses energy, so the total
//! energy (kinetic + potential, computed here from positions, velocities
//! and masses) never rises above its start; the tolerance is f64 rounding
//! of that sum (1e-12 of it). The stacks come to rest, so they fall asleep
//! within a few seconds of settling (the time to sleep is 0.5 s).
//!
//! Each case runs 10 s (every case is asleep by 1.6 s, so the debug
//! profile runs it in well under a second). Figures are printed with
//! `cargo test --release --test solver_stack_variants -- --nocapture`.
mod common;

use clockwork2d::prelude::*;
use common::resting::{RestingBox, RestingRun, column, run_resting};

const HZ: u64 = 60;
/// Run length: 10 s in release, 4 s in the debug profile.
const TICKS: u64 = if cfg!(debug_assertions) {
    4 * HZ
} else {
    10 * HZ
};

/// Fixed-point rounding allowed past `n · slop`: positions are multiples
/// of 2⁻³² (2.3e-10) and a contact resting at the edge of the slop is
/// judged on that grid, so a box may sit a few steps past its bound (one
/// was seen); four steps.
const ROUND: f64 = 1e-9;
/// Relative f64 rounding allowed on the energy sum.
const ENERGY_ROUNDING: f64 = 1e-12;

fn print(name: &str, r: &RestingRun) {
    println!(
        "{name:42} worst {:.6} (excess over n·slop {:+.6}) end {:.6} drift {:.2e} asleep from {:?} energy rise {:+.3e}",
        r.worst_error, r.worst_excess, r.end_error, r.drift, r.asleep_from, r.energy_rise
    );
}

/// The checks every resting case must pass: within `n · slop` from
/// `judge_from` on, never an x drift, energy never above the start, asleep
/// by `asleep_by` ticks and staying so.
#[track_caller]
fn assert_rests(name: &str, r: &RestingRun, max_drift: f64, asleep_by: u64) {
    print(name, r);
    assert!(
        r.worst_excess <= ROUND,
        "{name}: a box left its n·slop band by {}",
        r.worst_excess
    );
    assert!(r.drift <= max_drift, "{name}: x drift {}", r.drift);
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

fn unit_masses(masses: &[f64]) -> Vec<((f64, f64), Option<f64>)> {
    masses.iter().map(|&m| ((0.5, 0.5), Some(m))).collect()
}

fn default_rest(boxes: &[RestingBox]) -> RestingRun {
    run_resting(boxes, WorldSettings::default(), TICKS, 1)
}

/// Thin boxes (height 0.02 to 0.2): the box two above lies within the
/// speculative margin through a thin box, which must not make the stack
/// solve worse than a stack of cubes.
#[test]
fn thin_box_stacks_rest_within_n_slop() {
    for hh in [0.01, 0.02, 0.05, 0.1] {
        let boxes = column(&vec![((0.5, hh), None); 10], 0.0, 0.0);
        assert_rests(
            &format!("10 boxes of height {}", 2.0 * hh),
            &default_rest(&boxes),
            0.0,
            2 * HZ,
        );
    }
    let heights = [0.05, 0.5, 0.02, 1.0, 0.1, 0.05, 2.0, 0.05];
    let boxes: Vec<_> = heights.iter().map(|&hh| ((0.5, hh), None)).collect();
    assert_rests(
        "mixed heights 0.04..4",
        &default_rest(&column(&boxes, 0.0, 0.0)),
        0.0,
        2 * HZ,
    );
    let boxes: Vec<_> = (0..20)
        .map(|i| ((0.5, if i % 2 == 0 { 0.02 } else { 0.5 }), None))
        .collect();
    assert_rests(
        "20 alternating heights 0.04 / 1",
        &default_rest(&column(&boxes, 0.0, 0.0)),
        0.0,
        2 * HZ,
    );
}

/// Mass ratios: heavy boxes on light ones and the reverse, alternating,
/// one very heavy box on a tall stack.
#[test]
fn mass_ratio_stacks_rest_within_n_slop() {
    for ratio in [10.0, 100.0, 1000.0] {
        let top_heavy: Vec<f64> = (0..10).map(|i| if i >= 5 { ratio } else { 1.0 }).collect();
        let bottom_heavy: Vec<f64> = (0..10).map(|i| if i < 5 { ratio } else { 1.0 }).collect();
        let alternating: Vec<f64> = (0..20)
            .map(|i| if i % 2 == 1 { ratio } else { 1.0 })
            .collect();
        let heavy_top: Vec<f64> = (0..30).map(|i| if i == 29 { ratio } else { 1.0 }).collect();
        for (what, masses) in [
            ("10, top 5 heavy", top_heavy),
            ("10, bottom 5 heavy", bottom_heavy),
            ("20 alternating", alternating),
            ("30, heavy top", heavy_top),
            ("2, heavy top", vec![1.0, ratio]),
        ] {
            let boxes = column(&unit_masses(&masses), 0.0, 0.0);
            assert_rests(
                &format!("{what} x{ratio}"),
                &default_rest(&boxes),
                0.0,
                2 * HZ,
            );
        }
    }
    let heavy_top: Vec<f64> = (0..30)
        .map(|i| if i == 29 { 10_000.0 } else { 1.0 })
        .collect();
    let boxes = column(&unit_masses(&heavy_top), 0.0, 0.0);
    assert_rests("30, heavy top x10000", &default_rest(&boxes), 0.0, 2 * HZ);
}

/// The heavy stack is no worse at other substep and iteration counts.
#[test]
fn heavy_top_stack_rests_at_other_substeps_and_iterations() {
    let heavy_top: Vec<f64> = (0..30)
        .map(|i| if i == 29 { 1000.0 } else { 1.0 })
        .collect();
    let boxes = column(&unit_masses(&heavy_top), 0.0, 0.0);
    let d = WorldSettings::default;
    let settings = [
        ("substeps 2", WorldSettings { substeps: 2, ..d() }),
        ("substeps 4", WorldSettings { substeps: 4, ..d() }),
        (
            "position iterations 1",
            WorldSettings {
                position_iterations: 1,
                ..d()
            },
        ),
        (
            "position iterations 10",
            WorldSettings {
                position_iterations: 10,
                ..d()
            },
        ),
        (
            "velocity iterations 4",
            WorldSettings {
                velocity_iterations: 4,
                ..d()
            },
        ),
        (
            "velocity iterations 32",
            WorldSettings {
                velocity_iterations: 32,
                ..d()
            },
        ),
    ];
    for (what, s) in settings {
        let r = run_resting(&boxes, s, TICKS, 1);
        assert_rests(&format!("30, heavy top x1000, {what}"), &r, 0.0, 2 * HZ);
    }
}

/// 30 cubes, each placed `gap` per contact above its resting height: they
/// fall, land one on another and settle. Heights are judged once the top
/// box has had time to land: it falls `30 · gap`, which takes
/// `sqrt(2 · 30 · gap / g)` (1.1 s at gap 0.2), and 0.5 s more to settle.
#[test]
fn stacks_dropped_from_gaps_settle_within_n_slop() {
    let g = 10.0;
    for gap in [1e-6, 1e-4, 1e-3, 0.01, 0.05, 0.2] {
        let boxes = column(&vec![((0.5, 0.5), None); 30], 0.0, gap);
        let fall: f64 = (2.0 * 30.0 * gap / g).sqrt();
        let judge_from = ((fall + 0.5) * HZ as f64).ceil() as u64;
        let r = run_resting(&boxes, WorldSettings::default(), TICKS, judge_from);
        assert_rests(
            &format!("30 cubes dropped from gaps {gap}"),
            &r,
            0.0,
            judge_from + 2 * HZ,
        );
    }
}

/// Widths from 0.1 to 10 in one column, at equal masses and at density 1
/// (mass ratio 100 between the widest and the narrowest).
#[test]
fn stacks_of_mixed_widths_rest_within_n_slop() {
    let half_widths = [0.05, 5.0, 0.05, 0.5, 5.0, 0.1, 2.0, 0.05, 1.0, 0.3];
    let equal: Vec<_> = half_widths
        .iter()
        .map(|&hw| ((hw, 0.5), Some(1.0)))
        .collect();
    let density: Vec<_> = half_widths.iter().map(|&hw| ((hw, 0.5), None)).collect();
    assert_rests(
        "widths 0.1..10, mass 1",
        &default_rest(&column(&equal, 0.0, 0.0)),
        0.0,
        2 * HZ,
    );
    assert_rests(
        "widths 0.1..10, density 1",
        &default_rest(&column(&density, 0.0, 0.0)),
        0.0,
        2 * HZ,
    );
}

/// A 10-row pyramid of unit boxes whose top five rows are `ratio` times
/// heavier: each box rests on two, and a box of row r is r + 1 contacts
/// above the ground. Boxes of a row touch sideways (spacing 1) or stand
/// 0.05 apart; either way every load is vertical and no net horizontal
/// force acts, so a box may move sideways only within the overlap a side
/// contact may keep, one slop.
#[test]
fn pyramids_with_a_heavy_top_half_rest_within_n_slop() {
    for (ratio, spacing) in [(10.0, 1.0), (100.0, 1.0), (10.0, 1.05), (100.0, 1.05)] {
        let rows = 10;
        let mut boxes = vec![];
        for r in 0..rows {
            let count = rows - r;
            for j in 0..count {
                let x = (j as f64 - (count as f64 - 1.0) / 2.0) * spacing;
                let b = RestingBox::at_rest((0.5, 0.5), x, 0.5 + r as f64, r + 1);
                boxes.push(if r >= rows / 2 { b.with_mass(ratio) } else { b });
            }
        }
        let slop = WorldSettings::<Fx>::default().linear_slop.to_f64();
        assert_rests(
            &format!("pyramid 10 rows, spacing {spacing}, top half x{ratio}"),
            &default_rest(&boxes),
            slop,
            2 * HZ,
        );
    }
}
