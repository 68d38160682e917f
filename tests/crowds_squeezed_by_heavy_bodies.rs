//! Heavy bodies never squeeze light ones out of a closed room (issue 13,
//! N7), over a family of rooms: interior sizes 3 × 6 to 20 × 14, walls
//! 0.02, 0.1 and 2 thick, g = 10 and 100, heavy bodies 1–1000× the density
//! of the rest (every 10th, every 3rd, or the whole upper half of the
//! crowd: heavy bodies on top press the light ones into the floor and
//! walls), crowds of 40–500 circles and boxes of random sizes, rooms at
//! the origin and at a corner of the world's bounds.
//!
//! The physics: the walls are fixed, so no pressure of the crowd can move
//! them, and a body can only reach past a wall's inner face by as much as
//! a resting contact may overlap: the linear slop (the position pass
//! corrects any overlap beyond it, and the projection out of immovable
//! bodies removes what is left at the end of every substep). The bound
//! is therefore the slop, at every tick, plus the rounding of the centres
//! and sizes read back (2⁻³² each, `ROUNDING`). Rounding in the solver
//! itself does not add to it: the projection is the substep's last word
//! on positions.
//!
//! The hard case: a light body wedged between heavy ones leaves the
//! velocity solve at hundreds of units/s (the wedge turns the heavy
//! bodies' approach into a squirt, and the sweeps stop before the light
//! body's rows agree), far beyond the motion its contacts were looked for
//! at; it had no row, often no pair, with the wall it then crossed, and
//! walls even 2 thick were passed (up to 18 562 units outside, frozen at
//! the world's bound).
//!
//! Debug runs (the test profile is slow) check every 4th room over fewer
//! ticks; run with `--release --nocapture` for all rooms and the figures.

mod common;
use clockwork2d::prelude::*;
use common::add_closed_room;
use common::split_mix::SplitMix;

const SLOP: f64 = 1e-4;
/// Rounding of the stored centres and half extents read back as f64.
const ROUNDING: f64 = 1e-9;
/// 4 s of falling, piling and squeezing (2 s in debug): the crowds are
/// piled within about 1.5 s (a fall of at most 28 under g = 10).
const TICKS: usize = if cfg!(debug_assertions) { 120 } else { 240 };

/// Which bodies of the crowd are heavy.
#[derive(Clone, Copy, Debug)]
enum Heavy {
    EveryTenth,
    EveryThird,
    UpperHalf,
}

/// One room of the family.
#[derive(Clone, Copy, Debug)]
struct Room {
    centre: (f64, f64),
    /// Interior half width and half height.
    half: (f64, f64),
    wall: f64,
    g: f64,
    /// Density of the heavy bodies (the rest have density 1).
    ratio: f64,
    heavy: Heavy,
    bodies: usize,
    seed: u64,
}

/// The family: every combination is not needed (each room takes 0.5–2 s in
/// release), so each parameter cycles with its own period (3, 3, 2, 4, 3,
/// 5, …), co-prime enough that the 36 rooms mix them all.
fn rooms() -> Vec<Room> {
    let halves = [(1.5, 3.0), (4.0, 8.0), (10.0, 7.0)];
    let walls = [0.02, 0.1, 2.0];
    let gs = [100.0, 10.0];
    let ratios = [1000.0, 100.0, 10.0, 1.0];
    let heavies = [Heavy::EveryTenth, Heavy::UpperHalf, Heavy::EveryThird];
    (0..36u64)
        .map(|k| {
            let i = k as usize;
            let half = halves[i % 3];
            // Fill 40–85 % of the room's grid cells (0.5 apart), at most 500.
            let cells = ((2.0 * half.0) / 0.5) as usize * ((2.0 * half.1) / 0.5) as usize;
            let fill = [0.85, 0.4, 0.6, 0.7, 0.5][i % 5];
            let bodies = ((cells as f64 * fill) as usize).clamp(40, 500);
            let centre = if i % 7 == 6 {
                (32_700.0 - 30.0, -32_700.0 + 30.0)
            } else {
                (0.0, 0.0)
            };
            Room {
                centre,
                half,
                wall: walls[(i / 3) % 3],
                g: gs[i % 2],
                ratio: ratios[(i / 2) % 4],
                heavy: heavies[(i / 4) % 3],
                bodies,
                seed: 100 + k,
            }
        })
        .collect()
}

/// The room's walls and its crowd on a grid (cells 0.5 apart, bodies at
/// most 0.48 across: no overlap at the start), filled from the floor up.
fn build(room: &Room) -> (World, Vec<BodyId>) {
    let mut world = World::new(WorldSettings {
        gravity: vec2(0.0, -room.g),
        ..WorldSettings::default()
    });
    let (hw, hh) = room.half;
    add_closed_room(&mut world, room.centre, (hw, hh), room.wall);
    let columns = ((2.0 * hw) / 0.5) as usize;
    let mut rng = SplitMix(room.seed);
    let bodies = (0..room.bodies)
        .map(|k| {
            let x = -hw + 0.25 + 0.5 * (k % columns) as f64;
            let y = -hh + 0.25 + 0.5 * (k / columns) as f64;
            let size = rng.range(0.05, 0.24);
            let shape = if rng.unit() < 0.5 {
                Shape::circle(fx(size))
            } else {
                Shape::aabb(vec2(size, rng.range(0.05, 0.24)))
            };
            let heavy = match room.heavy {
                Heavy::EveryTenth => k % 10 == 0,
                Heavy::EveryThird => k % 3 == 0,
                Heavy::UpperHalf => 2 * k >= room.bodies,
            };
            let mut def =
                BodyDef::dynamic(shape).position(vec2(room.centre.0 + x, room.centre.1 + y));
            if heavy && room.ratio > 1.0 {
                def = def.density(fx(room.ratio));
            }
            world.add_body(def).expect("body")
        })
        .collect();
    (world, bodies)
}

/// How far any body reaches past the room's inner faces (negative: inside).
fn worst_reach(world: &World, bodies: &[BodyId], room: &Room) -> f64 {
    bodies
        .iter()
        .map(|&id| {
            let b = world.body(id).unwrap();
            let (x, y) = b.position().to_f64();
            let (ex, ey) = match b.shape() {
                Shape::Circle { radius } => (radius.to_f64(), radius.to_f64()),
                Shape::Aabb { half_extents } => half_extents.to_f64(),
            };
            ((x - room.centre.0).abs() + ex - room.half.0)
                .max((y - room.centre.1).abs() + ey - room.half.1)
        })
        .fold(f64::MIN, f64::max)
}

#[test]
fn heavy_crowds_never_squeeze_a_body_through_a_wall() {
    let rooms = rooms();
    let step = if cfg!(debug_assertions) { 4 } else { 1 };
    let mut failures = Vec::new();
    for room in rooms.iter().step_by(step) {
        let (mut world, bodies) = build(room);
        let mut worst = f64::MIN;
        let mut first_out = None;
        for tick in 1..=TICKS {
            world.step();
            let reach = worst_reach(&world, &bodies, room);
            worst = worst.max(reach);
            if reach > SLOP + ROUNDING && first_out.is_none() {
                first_out = Some(tick);
            }
        }
        println!(
            "{room:?}: worst reach past a wall {worst:.3e} (bound {SLOP}){}",
            first_out.map_or(String::new(), |t| format!(", first past at tick {t}"))
        );
        if let Some(tick) = first_out {
            failures.push(format!(
                "{room:?}: {worst} past a wall (first at tick {tick})"
            ));
        }
    }
    assert!(
        failures.is_empty(),
        "bodies squeezed out:\n{}",
        failures.join("\n")
    );
}
