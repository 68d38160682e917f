//! clockwork2d against rapier2d on the same scenes, in the same process.
//!
//! ```sh
//! cargo run --release --example peer_comparison
//! ```
//!
//! For each benchmark scene (`large_pyramid`: Box2D's 5050-box pyramid;
//! `balls5000`: 5000 circles in a walled box) the clockwork2d world is built
//! from the built-in scene file, and the rapier2d world is built **from the
//! clockwork2d world's bodies** (same shapes, positions, initial velocities,
//! masses, friction, restitution), so both engines start from the same
//! state. Then each engine is stepped 500 times (interleaved in blocks, see
//! below), and reports the time per step and the accuracy side:
//!
//! * **sag**: how far the top box of the pyramid has sunk after 500 steps
//!   (a rigid pyramid would not sink at all; all of it is solver error:
//!   penetration plus slip);
//! * **max penetration**: the deepest overlap of any two bodies, measured
//!   geometrically from positions (the same code for both engines), sampled
//!   every 10 steps outside the timed region (the maximum is usually a
//!   transient of the first impacts), and after the last step (**final**,
//!   the settled pile);
//! * **escaped** (ball pit): balls whose centre ended outside the walls.
//!
//! # Matching the two engines
//!
//! * Same gravity (0, -10), dt = 1/60, sleeping off (rapier:
//!   `can_sleep(false)` on every body), CCD off (rapier's default; no body
//!   here is a bullet in clockwork2d either).
//! * Rotations locked on every rapier body (`lock_rotations()`):
//!   clockwork2d models no rotation, so this is the same model. Balls
//!   included, otherwise rapier's balls would roll and carry angular terms.
//! * Same friction and restitution, combined by the same rules: clockwork2d
//!   combines friction by the geometric mean and restitution by the maximum,
//!   so the rapier colliders use `CoefficientCombineRule::GeometricMean` and
//!   `Max`. Masses equal (rapier density = clockwork mass / area).
//! * Solver iterations. clockwork2d runs, per step, `velocity_iterations`
//!   (8) sequential-impulse sweeps and `position_iterations` (3)
//!   position-correction sweeps, in one substep. rapier2d's solver (TGS-soft)
//!   instead runs `num_solver_iterations` substeps, each with
//!   `num_internal_pgs_iterations` biased sweeps and
//!   `num_internal_stabilization_iterations` unbiased sweeps. No setting
//!   makes the two the same algorithm, so three rapier configurations are
//!   timed:
//!   - **rapier 8 iterations** (the headline): `num_solver_iterations = 8`,
//!     the knob rapier calls "solver iterations" set to clockwork2d's
//!     velocity iteration count (8 substeps × (1 biased + 1 relax sweep):
//!     16 sweeps and 8 integrations per step);
//!   - **rapier 1×(8+3) sweeps**: one substep with 8 biased and 3 unbiased
//!     sweeps, the same number of sweeps per step as clockwork2d's 8 + 3
//!     (rapier is not tuned for this; it shows the cost per sweep);
//!   - **rapier default**: `IntegrationParameters::default()` (4 iterations),
//!     what a user gets out of the box.
//!
//! # Timing on a shared machine
//!
//! All four worlds exist at once and are stepped in turn, 10 steps each
//! (clockwork2d, rapier ×3, clockwork2d, …), so background load hits them
//! alike. The headline figure is the thread's CPU time per step (Linux:
//! `/proc/thread-self/schedstat`), which does not count time other
//! processes held the core; the wall-clock median per step is printed next
//! to it. Penetration is measured between blocks, untimed.
#![allow(clippy::float_arithmetic)]
#![allow(clippy::cast_precision_loss)]

#[path = "support/cpu_time.rs"]
mod cpu_time;
#[path = "support/penetration.rs"]
mod penetration;

use std::time::Instant;

use clockwork2d::prelude::*;
use clockwork2d_scene::builtin;
use cpu_time::thread_cpu_ns;
use penetration::{Piece, PieceShape, max_penetration};
use rapier2d::prelude as rp;

/// Steps per run (the issue's "after 500 steps").
const STEPS: usize = 500;
/// Steps per timed block; penetration is sampled after each block (not
/// timed).
const SAMPLE_EVERY: usize = 10;

/// One body of the scene, read from the clockwork2d world, in `f64`.
#[derive(Clone, Copy)]
struct BodyInit {
    piece: Piece,
    vx: f64,
    vy: f64,
    mass: f64,
    friction: f64,
    restitution: f64,
}

fn piece_of(body: &Body) -> Piece {
    let (x, y) = body.position().to_f64();
    let shape = match body.shape() {
        Shape::Circle { radius } => PieceShape::Circle(radius.to_f64()),
        Shape::Aabb { half_extents } => {
            let (hx, hy) = half_extents.to_f64();
            PieceShape::Box(hx, hy)
        }
    };
    Piece {
        x,
        y,
        shape,
        dynamic: body.kind() == BodyKind::Dynamic,
    }
}

fn inits(world: &World) -> Vec<BodyInit> {
    world
        .bodies()
        .map(|(_, b)| {
            let (vx, vy) = b.velocity().to_f64();
            BodyInit {
                piece: piece_of(b),
                vx,
                vy,
                mass: b.mass().to_f64(),
                friction: b.friction().to_f64(),
                restitution: b.restitution().to_f64(),
            }
        })
        .collect()
}

/// One engine under test, stepped in blocks alternately with the others.
trait Engine {
    fn label(&self) -> String;
    fn step(&mut self);
    /// Every body as a [`Piece`], in the scene's body order.
    fn pieces(&self) -> Vec<Piece>;
}

struct Clockwork(World);

impl Engine for Clockwork {
    fn label(&self) -> String {
        let s = self.0.settings();
        format!(
            "clockwork2d I32F32, {} vel + {} pos iterations",
            s.velocity_iterations, s.position_iterations
        )
    }
    fn step(&mut self) {
        self.0.step();
    }
    fn pieces(&self) -> Vec<Piece> {
        self.0.bodies().map(|(_, b)| piece_of(b)).collect()
    }
}

struct Rapier {
    label: &'static str,
    world: rp::PhysicsWorld,
    handles: Vec<rp::RigidBodyHandle>,
    /// The scene's bodies (shapes and kinds of the pieces).
    bodies: Vec<BodyInit>,
}

impl Engine for Rapier {
    fn label(&self) -> String {
        self.label.to_owned()
    }
    fn step(&mut self) {
        self.world.step();
    }
    fn pieces(&self) -> Vec<Piece> {
        self.handles
            .iter()
            .zip(&self.bodies)
            .map(|(&h, b)| {
                let t = self.world.bodies[h].translation();
                Piece {
                    x: f64::from(t.x),
                    y: f64::from(t.y),
                    ..b.piece
                }
            })
            .collect()
    }
}

/// What one engine measured.
struct Run {
    label: String,
    /// Per-step wall times, ms.
    wall: Vec<f64>,
    /// Thread CPU time over all timed blocks, ns (if the platform has it).
    cpu_ns: Option<u64>,
    /// Top box's drop after the run (the pyramid only).
    sag: Option<f64>,
    max_penetration: f64,
    /// Deepest overlap after the last step (the settled state, where the
    /// maximum above is usually from the first impacts).
    final_penetration: f64,
    /// Dynamic bodies whose centre ended outside the walls (the ball pit
    /// only): bodies that tunnelled.
    escaped: Option<usize>,
}

impl Run {
    fn wall_median(&self) -> f64 {
        let mut t = self.wall.clone();
        t.sort_by(f64::total_cmp);
        t[t.len() / 2]
    }
    /// CPU ms per step if known, else the wall-clock median.
    fn ms_per_step(&self) -> f64 {
        self.cpu_ns.map_or_else(
            || self.wall_median(),
            |ns| ns as f64 / 1e6 / self.wall.len() as f64,
        )
    }
}

/// The scene-specific accuracy measures, from the final positions.
struct Measure {
    /// Index (in body order) of the pyramid's top box and its start height.
    top: Option<(usize, f64)>,
    /// Inner region of the ball pit (|x| ≤ hx, 0 ≤ y ≤ h).
    region: Option<(f64, f64)>,
}

impl Measure {
    fn sag(&self, pieces: &[Piece]) -> Option<f64> {
        self.top.map(|(i, y0)| y0 - pieces[i].y)
    }
    fn escaped(&self, pieces: &[Piece]) -> Option<usize> {
        self.region.map(|(hx, h)| {
            pieces
                .iter()
                .filter(|p| p.dynamic && (p.x.abs() > hx || p.y < 0.0 || p.y > h))
                .count()
        })
    }
}

/// Steps every engine `STEPS` times, in blocks of `SAMPLE_EVERY` steps
/// taken in turn (engine 1, engine 2, …, engine 1, …), so that all of
/// them run under the same background load; penetration is measured
/// between blocks, outside the timed region.
fn race(engines: &mut [Box<dyn Engine>], measure: &Measure) -> Vec<Run> {
    let mut wall: Vec<Vec<f64>> = engines.iter().map(|_| Vec::with_capacity(STEPS)).collect();
    let mut cpu: Vec<Option<u64>> = engines.iter().map(|_| Some(0)).collect();
    let mut worst = vec![0.0_f64; engines.len()];
    for _ in 0..STEPS / SAMPLE_EVERY {
        for (i, engine) in engines.iter_mut().enumerate() {
            let cpu_start = thread_cpu_ns();
            for _ in 0..SAMPLE_EVERY {
                let start = Instant::now();
                engine.step();
                wall[i].push(start.elapsed().as_secs_f64() * 1e3);
            }
            cpu[i] = match (cpu[i], cpu_start, thread_cpu_ns()) {
                (Some(total), Some(a), Some(b)) => Some(total + b.saturating_sub(a)),
                _ => None,
            };
            worst[i] = worst[i].max(max_penetration(&engine.pieces()));
        }
    }
    engines
        .iter()
        .zip(wall)
        .zip(cpu)
        .zip(worst)
        .map(|(((engine, wall), cpu_ns), worst)| {
            let last = engine.pieces();
            Run {
                label: engine.label(),
                wall,
                cpu_ns,
                sag: measure.sag(&last),
                max_penetration: worst,
                final_penetration: max_penetration(&last),
                escaped: measure.escaped(&last),
            }
        })
        .collect()
}

/// A rapier2d solver configuration (see the module docs).
struct RapierConfig {
    label: &'static str,
    solver_iterations: usize,
    pgs_iterations: usize,
    stabilization_iterations: usize,
}

const RAPIER_CONFIGS: &[RapierConfig] = &[
    RapierConfig {
        label: "rapier2d 0.36 f32, 8 iterations",
        solver_iterations: 8,
        pgs_iterations: 1,
        stabilization_iterations: 1,
    },
    RapierConfig {
        label: "rapier2d 0.36 f32, 1 substep × (8 + 3) sweeps",
        solver_iterations: 1,
        pgs_iterations: 8,
        stabilization_iterations: 3,
    },
    RapierConfig {
        label: "rapier2d 0.36 f32, default (4 iterations)",
        solver_iterations: 4,
        pgs_iterations: 1,
        stabilization_iterations: 1,
    },
];

fn build_rapier(bodies: &[BodyInit], config: &RapierConfig) -> Rapier {
    let mut world = rp::PhysicsWorld::new();
    world.gravity = rp::Vector::new(0.0, -10.0);
    let params = &mut world.integration_parameters;
    params.dt = 1.0 / 60.0;
    params.num_solver_iterations = config.solver_iterations;
    params.num_internal_pgs_iterations = config.pgs_iterations;
    params.num_internal_stabilization_iterations = config.stabilization_iterations;
    let handles = bodies
        .iter()
        .map(|b| {
            let p = &b.piece;
            let translation = rp::Vector::new(p.x as f32, p.y as f32);
            let body = if p.dynamic {
                rp::RigidBodyBuilder::dynamic()
                    .translation(translation)
                    .linvel(rp::Vector::new(b.vx as f32, b.vy as f32))
                    .lock_rotations()
                    .can_sleep(false)
            } else {
                rp::RigidBodyBuilder::fixed().translation(translation)
            };
            let (collider, area) = match p.shape {
                PieceShape::Circle(r) => (
                    rp::ColliderBuilder::ball(r as f32),
                    std::f64::consts::PI * r * r,
                ),
                PieceShape::Box(hx, hy) => (
                    rp::ColliderBuilder::cuboid(hx as f32, hy as f32),
                    4.0 * hx * hy,
                ),
            };
            let density = if p.dynamic { b.mass / area } else { 1.0 };
            let collider = collider
                .density(density as f32)
                .friction(b.friction as f32)
                .friction_combine_rule(rp::CoefficientCombineRule::GeometricMean)
                .restitution(b.restitution as f32)
                .restitution_combine_rule(rp::CoefficientCombineRule::Max);
            world.insert(body, collider).0
        })
        .collect();
    Rapier {
        label: config.label,
        world,
        handles,
        bodies: bodies.to_vec(),
    }
}

fn scene_world(name: &str) -> World {
    builtin(name)
        .and_then(|s| s.build())
        .unwrap_or_else(|e| panic!("built-in scene {name}: {e}"))
}

fn report(scene: &str, bodies: usize, runs: &[Run]) {
    println!("\n## {scene} ({bodies} bodies, {STEPS} steps)\n");
    println!(
        "| engine | ms/step (CPU) | ms/step (wall, median) | clockwork2d ÷ engine | top-box sag | max penetration | final penetration | escaped |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---:|");
    let base = runs[0].ms_per_step();
    for r in runs {
        let opt = |v: Option<f64>| v.map_or("–".to_owned(), |v| format!("{v:.4}"));
        println!(
            "| {} | {:.2} | {:.2} | {:.2} | {} | {:.4} | {:.4} | {} |",
            r.label,
            r.ms_per_step(),
            r.wall_median(),
            base / r.ms_per_step(),
            opt(r.sag),
            r.max_penetration,
            r.final_penetration,
            r.escaped.map_or("–".to_owned(), |n| n.to_string()),
        );
    }
}

fn engines(world: World, bodies: &[BodyInit]) -> Vec<Box<dyn Engine>> {
    let mut engines: Vec<Box<dyn Engine>> = vec![Box::new(Clockwork(world))];
    for config in RAPIER_CONFIGS {
        engines.push(Box::new(build_rapier(bodies, config)));
    }
    engines
}

fn main() {
    println!("# clockwork2d vs rapier2d (same process, interleaved)");
    let cpu = if thread_cpu_ns().is_some() {
        "thread CPU time (excludes time other processes held the core), mean over the run"
    } else {
        "not available on this platform: the wall-clock median is used"
    };
    println!(
        "\nms/step (CPU): {cpu}. clockwork2d ÷ engine: ratio of the CPU ms/step, below 1 means \
         clockwork2d is faster. Sag and penetration in units (boxes are 1 unit, balls 0.5 across)."
    );

    // The pyramid: the top box is the last body (the pyramid generator
    // builds the rows bottom-up).
    let world = scene_world("large_pyramid");
    let bodies = inits(&world);
    let top = bodies.len() - 1;
    let measure = Measure {
        top: Some((top, bodies[top].piece.y)),
        region: None,
    };
    let runs = race(&mut engines(world, &bodies), &measure);
    report("large_pyramid", bodies.len(), &runs);

    // The ball pit: the walls enclose |x| ≤ 40, 0 ≤ y ≤ 40 (balls5000.ron).
    let world = scene_world("balls5000");
    let bodies = inits(&world);
    let measure = Measure {
        top: None,
        region: Some((40.0, 40.0)),
    };
    let runs = race(&mut engines(world, &bodies), &measure);
    report("balls5000", bodies.len(), &runs);
}
