//! Resting scenes of boxes on the ground (stacks, pyramids, walls) and the
//! physical measures of how well they rest.
//!
//! Every box has an ideal resting height (faces exactly touching) and a
//! `depth`: the number of contacts in series between it and the ground.
//! A contact at rest may overlap by up to the linear slop (it is not
//! corrected below that), so a box `depth` contacts up may rest at most
//! `depth · slop` below its ideal height, and no contact pushes it above
//! (the faces touch or overlap). The measures are taken in f64 from the
//! engine's state only: positions, velocities, masses.

use clockwork2d::prelude::*;

use super::add_ground;

/// One dynamic axis-aligned box of a resting scene.
#[derive(Clone, Copy, Debug)]
pub struct RestingBox {
    /// Half extents (x, y).
    pub half: (f64, f64),
    /// Mass; `None` keeps the default density 1.
    pub mass: Option<f64>,
    /// Centre x where it is placed (and should stay).
    pub x: f64,
    /// Ideal resting centre y: every face it rests on exactly touching.
    pub rest_y: f64,
    /// Centre y where it is placed (above `rest_y` for a dropped scene).
    pub start_y: f64,
    /// Contacts in series from the ground up to this box.
    pub depth: usize,
}

impl RestingBox {
    /// A box placed at its resting height.
    pub fn at_rest(half: (f64, f64), x: f64, rest_y: f64, depth: usize) -> Self {
        RestingBox {
            half,
            mass: None,
            x,
            rest_y,
            start_y: rest_y,
            depth,
        }
    }

    /// The same box with the given mass.
    pub fn with_mass(self, mass: f64) -> Self {
        RestingBox {
            mass: Some(mass),
            ..self
        }
    }
}

/// A column of boxes given by their half extents and masses, bottom first,
/// centred on `x`, each resting on the one below; box `i` is placed `gap`
/// per contact above its resting height (`(i + 1) · gap`).
pub fn column(boxes: &[((f64, f64), Option<f64>)], x: f64, gap: f64) -> Vec<RestingBox> {
    let mut top = 0.0;
    boxes
        .iter()
        .enumerate()
        .map(|(i, &(half, mass))| {
            let rest_y = top + half.1;
            top += 2.0 * half.1;
            RestingBox {
                half,
                mass,
                x,
                rest_y,
                start_y: rest_y + gap * (i + 1) as f64,
                depth: i + 1,
            }
        })
        .collect()
}

/// What a resting run measured.
#[derive(Clone, Copy, Debug)]
pub struct RestingRun {
    /// Worst |y − rest_y| over the measured ticks, any box.
    pub worst_error: f64,
    /// Worst `|y − rest_y| − depth · slop` over the measured ticks (≤ 0:
    /// every box within its bound all the time).
    pub worst_excess: f64,
    /// |y − rest_y| of the worst box at the end.
    pub end_error: f64,
    /// Worst |x − x₀| over the whole run, any box.
    pub drift: f64,
    /// First tick from which every box stayed asleep to the end.
    pub asleep_from: Option<u64>,
    /// Largest rise of the total energy (kinetic + potential) above its
    /// value at the start, over the whole run (≤ 0: it never rose).
    pub energy_rise: f64,
    /// The total energy at the start (for relative tolerances).
    pub energy_start: f64,
}

/// Runs `boxes` on the ground for `ticks` ticks; heights are judged from
/// tick `judge_from` on (1: from the first step).
pub fn run_resting(
    boxes: &[RestingBox],
    settings: WorldSettings,
    ticks: u64,
    judge_from: u64,
) -> RestingRun {
    let slop = settings.linear_slop.to_f64();
    let (gx, gy) = settings.gravity.to_f64();
    let mut world: World = World::new(settings);
    add_ground(&mut world);
    let ids: Vec<BodyId> = boxes
        .iter()
        .map(|b| {
            let mut def = BodyDef::dynamic(Shape::aabb(vec2(b.half.0, b.half.1)))
                .position(vec2(b.x, b.start_y));
            if let Some(m) = b.mass {
                def = def.mass(fx(m));
            }
            world.add_body(def).expect("box inside the world")
        })
        .collect();
    let masses: Vec<f64> = ids
        .iter()
        .map(|&id| world.body(id).unwrap().mass().to_f64())
        .collect();
    // Potential energy −m·(g·p).
    let energy = |world: &World| -> f64 {
        ids.iter()
            .zip(&masses)
            .map(|(&id, &m)| {
                let body = world.body(id).unwrap();
                let (x, y) = body.position().to_f64();
                let (vx, vy) = body.velocity().to_f64();
                0.5 * m * (vx * vx + vy * vy) - m * (gx * x + gy * y)
            })
            .sum()
    };
    let energy_start = energy(&world);
    let mut run = RestingRun {
        worst_error: 0.0,
        worst_excess: f64::MIN,
        end_error: 0.0,
        drift: 0.0,
        asleep_from: None,
        energy_rise: f64::MIN,
        energy_start,
    };
    for t in 1..=ticks {
        world.step();
        let mut end_error: f64 = 0.0;
        for (&id, b) in ids.iter().zip(boxes) {
            let (x, y) = world.body(id).unwrap().position().to_f64();
            let error = (y - b.rest_y).abs();
            end_error = end_error.max(error);
            if t >= judge_from {
                run.worst_error = run.worst_error.max(error);
                run.worst_excess = run.worst_excess.max(error - b.depth as f64 * slop);
            }
            run.drift = run.drift.max((x - b.x).abs());
        }
        run.end_error = end_error;
        let asleep = ids.iter().all(|&id| !world.body(id).unwrap().is_awake());
        match (asleep, run.asleep_from) {
            (true, None) => run.asleep_from = Some(t),
            (false, _) => run.asleep_from = None,
            _ => {}
        }
        run.energy_rise = run.energy_rise.max(energy(&world) - energy_start);
    }
    run
}
