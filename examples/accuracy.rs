//! The speed-against-error report: one command, a Markdown table and an SVG
//! plot.
//!
//! ```sh
//! cargo run --release --example accuracy            # writes docs/report/
//! cargo run --release --example accuracy -- OUT_DIR # writes OUT_DIR/
//! ```
//!
//! The engine is generic over its scalar, so the *same* code path runs with
//! each number type: `I32F32` (the default `Fx`), `I48F16`, and the `f64` and
//! `f32` references. For every scalar and a grid of solver settings
//! (velocity iterations 4/8/16 × substeps 1/2/4; 8 × 1 is the default) it
//! runs small scenes with known answers and measures:
//!
//! * **projectile**: a body thrown at (3, 12) units/s under g = 10, 2.4 s;
//!   the largest distance from the analytic parabola at the tick times.
//!   Mostly the integrator's O(h) error (positions from end-of-step
//!   velocities: ½·g·h·t), which substeps shrink.
//! * **spring**: a unit mass on an undamped bendy spring (k = 4π², period
//!   1 s), released 1 unit from rest, 10 s; the relative error of the
//!   period (from zero crossings) and of the amplitude in the last period.
//! * **rope pendulum**: a bob on a rope of length 1 started at 30°, 10 s;
//!   the relative period error against the exact large-angle period
//!   `2π√(L/g) / AGM(1, cos(θ₀/2))`, and the largest stretch of the rope
//!   (`|bob − pivot| − L`).
//! * **pyramid**: the 20-row pyramid (`scenes/pyramid.ron`, 210 boxes),
//!   sleeping off, 500 steps; the sag of the top box and the maximum
//!   penetration between any two bodies (geometric, from positions, every
//!   10 steps). Its time per step is the speed figure of a setting.
//! * **geometry against f64**: 3 000 random time-of-impact queries (circle
//!   and box pairs) and 3 000 random ray casts, their inputs rounded to the
//!   scalar, then answered in the scalar and in `f64` *from the same rounded
//!   inputs*: so the error is the algorithm's arithmetic, not the rounding
//!   of the inputs. TOI error is `|Δt|·|d|` (the contact position error, in
//!   units); ray error is the hit distance error. Queries where the two
//!   disagree on hit/miss (grazing cases) are counted separately.
//!
//! Times are taken from the simulation path only (each `step()` call; the
//! median over the run, then the smaller of two rounds) on a possibly busy
//! machine: treat them as ±20 %. The tick clock is the
//! nominal one, `k / 60` s; `I48F16` cannot hold 1/60 exactly (its dt is
//! 0.0166626, 0.024 % short), and that shows in its errors, as it would in a
//! game.
#![allow(clippy::float_arithmetic)]
#![allow(clippy::cast_precision_loss)]

#[path = "support/penetration.rs"]
mod penetration;

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;

use clockwork2d::geometry::*;
use clockwork2d::prelude::*;
use clockwork2d_scene::builtin;
use fixed::types::I48F16;
use penetration::{Piece, PieceShape, max_penetration};
use plotters::element::Circle as Dot;
use plotters::prelude::{
    BLACK, ChartBuilder, Color, Cross, IntoDrawingArea, IntoLogRange, RGBColor, SVGBackend,
    SeriesLabelPosition, TriangleMarker, WHITE,
};

/// `(velocity iterations, substeps)`.
const SETTINGS: [(u32, u32); 9] = [
    (4, 1),
    (8, 1),
    (16, 1),
    (4, 2),
    (8, 2),
    (16, 2),
    (4, 4),
    (8, 4),
    (16, 4),
];
/// Nominal tick length (s).
const DT: f64 = 1.0 / 60.0;
/// Random geometry queries per kind.
const QUERIES: usize = 1_000;
/// Rounds of the whole measurement; each time is the minimum over rounds.
const ROUNDS: usize = 2;

/// What one (scalar, setting) run measured.
#[derive(Clone, Debug)]
struct Row {
    scalar: &'static str,
    iterations: u32,
    substeps: u32,
    ns_pyramid: f64,
    ns_projectile: f64,
    ns_spring: f64,
    ns_pendulum: f64,
    projectile: f64,
    spring_period: f64,
    spring_amplitude: f64,
    pendulum_period: f64,
    rope_stretch: f64,
    sag: f64,
    penetration: f64,
}

/// Geometry errors of one scalar against f64.
#[derive(Clone, Debug)]
struct GeometryRow {
    scalar: &'static str,
    ns_toi: f64,
    toi_error: f64,
    toi_mismatches: usize,
    ns_ray: f64,
    ray_error: f64,
    ray_mismatches: usize,
}

fn settings<S: Scalar>(iterations: u32, substeps: u32) -> WorldSettings<S> {
    WorldSettings {
        velocity_iterations: iterations,
        substeps,
        sleep_enabled: false,
        ..WorldSettings::default()
    }
}

fn v<S: Scalar>(x: f64, y: f64) -> Vec2<S> {
    Vec2::from_f64(x, y)
}

/// Steps `world` `steps` times, calling `observe` after each step (not
/// timed); returns the median ns per step (the median, because other
/// processes on a shared machine add rare long outliers to a mean).
fn run<S: Scalar>(
    world: &mut World<S>,
    steps: usize,
    mut observe: impl FnMut(usize, &World<S>),
) -> f64 {
    let mut times = Vec::with_capacity(steps);
    for k in 1..=steps {
        let start = Instant::now();
        world.step();
        times.push(start.elapsed().as_secs_f64() * 1e9);
        observe(k, world);
    }
    times.sort_by(f64::total_cmp);
    times[times.len() / 2]
}

/// Times (s) at which the sampled signal `x[k]` (at `k·DT`) changes sign,
/// linearly interpolated.
fn zero_crossings(x: &[f64]) -> Vec<f64> {
    x.windows(2)
        .enumerate()
        .filter(|(_, w)| (w[0] < 0.0) != (w[1] < 0.0))
        .map(|(k, w)| (k as f64 + w[0] / (w[0] - w[1])) * DT)
        .collect()
}

/// The period from the zero crossings (two per period).
fn period(x: &[f64]) -> f64 {
    let c = zero_crossings(x);
    assert!(c.len() >= 3, "too few zero crossings to measure a period");
    2.0 * (c[c.len() - 1] - c[0]) / (c.len() - 1) as f64
}

fn projectile<S: Scalar>(iterations: u32, substeps: u32) -> (f64, f64) {
    let mut world = World::<S>::new_generic(settings(iterations, substeps));
    let (v0x, v0y, g) = (3.0, 12.0, -10.0);
    let id = world
        .add_body(
            BodyDef::dynamic(Shape::circle(S::from_f64(0.1)))
                .position(v(0.0, 0.0))
                .velocity(v(v0x, v0y)),
        )
        .expect("projectile");
    let mut worst: f64 = 0.0;
    let ns = run(&mut world, 144, |k, w| {
        let t = k as f64 * DT;
        let (x, y) = w.body(id).expect("body").position().to_f64();
        let (ex, ey) = (v0x * t, v0y * t + 0.5 * g * t * t);
        worst = worst.max((x - ex).hypot(y - ey));
    });
    (ns, worst)
}

/// `(ns/step, period error, amplitude error)`, both relative.
fn spring<S: Scalar>(iterations: u32, substeps: u32) -> (f64, f64, f64) {
    let mut world = World::<S>::new_generic(settings(iterations, substeps));
    let k = S::from_f64(4.0 * std::f64::consts::PI * std::f64::consts::PI);
    let id = world
        .add_body(
            BodyDef::dynamic(Shape::circle(S::from_f64(0.1)))
                .position(v(1.0, 0.0))
                .mass(S::ONE)
                .gravity_scale(S::ZERO),
        )
        .expect("spring body");
    world
        .add_constraint(Constraint::bendy_spring(
            Anchor::Point(Vec2::ZERO),
            Anchor::Body(id),
            Vec2::new(k, k),
            S::ZERO,
        ))
        .expect("spring");
    let mut x = vec![1.0];
    let ns = run(&mut world, 600, |_, w| {
        x.push(w.body(id).expect("body").position().to_f64().0);
    });
    let exact = 2.0 * std::f64::consts::PI / k.to_f64().sqrt();
    let last_period = x.len() - (exact / DT).ceil() as usize;
    let amplitude = peak(&x[last_period..]);
    (
        ns,
        (period(&x) / exact - 1.0).abs(),
        (amplitude - 1.0).abs(),
    )
}

/// The largest |x| of a sampled oscillation, refined by a parabola through
/// the largest sample and its neighbours: the raw sample can miss the crest
/// by up to half a step in time, an error of (ω·h/2)²/2 (1.4e-3 for the
/// spring here), far above what is being measured.
fn peak(x: &[f64]) -> f64 {
    let a: Vec<f64> = x.iter().map(|v| v.abs()).collect();
    let k = (1..a.len() - 1)
        .max_by(|&i, &j| a[i].total_cmp(&a[j]))
        .expect("at least three samples");
    let (l, c, r) = (a[k - 1], a[k], a[k + 1]);
    let curvature = l - 2.0 * c + r;
    if curvature >= 0.0 {
        return c;
    }
    // Vertex of the parabola through (−1, l), (0, c), (1, r).
    c - (r - l) * (r - l) / (8.0 * curvature)
}

/// Arithmetic-geometric mean.
fn agm(mut a: f64, mut b: f64) -> f64 {
    while (a - b).abs() > 1e-15 * a {
        (a, b) = (0.5 * (a + b), (a * b).sqrt());
    }
    a
}

/// `(ns/step, period error (relative), largest stretch (units))`.
fn pendulum<S: Scalar>(iterations: u32, substeps: u32) -> (f64, f64, f64) {
    let mut world = World::<S>::new_generic(settings(iterations, substeps));
    let theta0 = 30f64.to_radians();
    let start = v::<S>(theta0.sin(), -theta0.cos());
    let id = world
        .add_body(BodyDef::dynamic(Shape::circle(S::from_f64(0.05))).position(start))
        .expect("bob");
    let length = S::ONE;
    world
        .add_constraint(Constraint::rope(
            Anchor::Point(Vec2::ZERO),
            Anchor::Body(id),
            length,
        ))
        .expect("rope");
    let (x0, y0) = start.to_f64();
    let mut x = vec![x0];
    let mut stretch: f64 = 0.0;
    let ns = run(&mut world, 600, |_, w| {
        let (px, py) = w.body(id).expect("body").position().to_f64();
        x.push(px);
        stretch = stretch.max(px.hypot(py) - length.to_f64());
    });
    // The exact period for the amplitude actually simulated (the rounded
    // start position).
    let amplitude = x0.atan2(-y0);
    let exact = 2.0 * std::f64::consts::PI * (length.to_f64() / 10.0).sqrt()
        / agm(1.0, (amplitude / 2.0).cos());
    (ns, (period(&x) / exact - 1.0).abs(), stretch)
}

fn pieces<S: Scalar>(world: &World<S>) -> Vec<Piece> {
    world
        .bodies()
        .map(|(_, b)| {
            let (x, y) = b.position().to_f64();
            let shape = match b.shape() {
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
                dynamic: b.kind() == BodyKind::Dynamic,
            }
        })
        .collect()
}

/// `(ns/step, top-box sag, max penetration)` on the 20-row pyramid.
fn pyramid<S: Scalar>(iterations: u32, substeps: u32) -> (f64, f64, f64) {
    let mut scene = builtin("pyramid").expect("built-in pyramid");
    scene.settings.sleep_enabled = Some(false);
    scene.settings.velocity_iterations = Some(iterations);
    scene.settings.substeps = Some(substeps);
    let mut world = scene.build::<S>().expect("pyramid builds");
    // The generator builds rows bottom-up: the top box is the last body.
    let top = |w: &World<S>| w.bodies().last().expect("bodies").1.position().y.to_f64();
    let y0 = top(&world);
    let mut worst: f64 = 0.0;
    let ns = run(&mut world, 500, |k, w| {
        if k % 10 == 0 {
            worst = worst.max(max_penetration(&pieces(w)));
        }
    });
    (ns, y0 - top(&world), worst)
}

fn dynamics_row<S: Scalar>(iterations: u32, substeps: u32) -> Row {
    let (ns_projectile, projectile) = projectile::<S>(iterations, substeps);
    let (ns_spring, spring_period, spring_amplitude) = spring::<S>(iterations, substeps);
    let (ns_pendulum, pendulum_period, rope_stretch) = pendulum::<S>(iterations, substeps);
    let (ns_pyramid, sag, penetration) = pyramid::<S>(iterations, substeps);
    Row {
        scalar: S::NAME,
        iterations,
        substeps,
        ns_pyramid,
        ns_projectile,
        ns_spring,
        ns_pendulum,
        projectile,
        spring_period,
        spring_amplitude,
        pendulum_period,
        rope_stretch,
        sag,
        penetration,
    }
}

/// SplitMix64 → uniform floats: the same query sets for every scalar.
struct Rng(u64);

impl Rng {
    fn unit(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    }
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
}

/// A query's inputs, already rounded to the scalar and read back as f64 (so
/// both sides of the comparison see the same numbers).
#[derive(Clone, Copy)]
struct Case {
    /// Shape a: circle (radius in `ha.0`) or box (half extents `ha`).
    a_circle: bool,
    a: (f64, f64),
    ha: (f64, f64),
    da: (f64, f64),
    /// Shape b: circle or box.
    b_circle: bool,
    b: (f64, f64),
    hb: (f64, f64),
    db: (f64, f64),
}

fn rounded<S: Scalar>(x: f64) -> f64 {
    S::from_f64(x).to_f64()
}

fn rounded2<S: Scalar>((x, y): (f64, f64)) -> (f64, f64) {
    (rounded::<S>(x), rounded::<S>(y))
}

/// Pairs on a collision course (b placed near a's path), a third of each
/// kind: circle–circle, box–box, circle–box.
fn cases<S: Scalar>() -> Vec<Case> {
    let mut rng = Rng(2024);
    (0..QUERIES * 3)
        .map(|i| {
            let (a_circle, b_circle) = [(true, true), (false, false), (true, false)][i % 3];
            let size = |rng: &mut Rng, circle: bool| {
                let x = rng.range(0.05, 2.0);
                if circle {
                    (x, x)
                } else {
                    (x, rng.range(0.05, 2.0))
                }
            };
            let ha = size(&mut rng, a_circle);
            let hb = size(&mut rng, b_circle);
            let a = (rng.range(-100.0, 100.0), rng.range(-100.0, 100.0));
            let da = (rng.range(-30.0, 30.0), rng.range(-30.0, 30.0));
            let along = rng.unit();
            let b = (
                a.0 + along * da.0 + rng.range(-3.0, 3.0),
                a.1 + along * da.1 + rng.range(-3.0, 3.0),
            );
            let db = (rng.range(-2.0, 2.0), rng.range(-2.0, 2.0));
            Case {
                a_circle,
                a: rounded2::<S>(a),
                ha: rounded2::<S>(ha),
                da: rounded2::<S>(da),
                b_circle,
                b: rounded2::<S>(b),
                hb: rounded2::<S>(hb),
                db: rounded2::<S>(db),
            }
        })
        .collect()
}

fn toi_of<T: Scalar>(c: &Case) -> Toi<T> {
    let p = |(x, y): (f64, f64)| Vec2::<T>::from_f64(x, y);
    let circle = |centre, h: (f64, f64)| Circle::new(p(centre), T::from_f64(h.0));
    let aabb = |centre, h| Aabb::new(p(centre), p(h));
    match (c.a_circle, c.b_circle) {
        (true, true) => toi_circle_circle(&circle(c.a, c.ha), p(c.da), &circle(c.b, c.hb), p(c.db)),
        (false, false) => toi_aabb_aabb(&aabb(c.a, c.ha), p(c.da), &aabb(c.b, c.hb), p(c.db)),
        _ => toi_circle_aabb(&circle(c.a, c.ha), p(c.da), &aabb(c.b, c.hb), p(c.db)),
    }
}

/// The ray of a case: from a's centre along da, out to |da|·1.5, against b.
fn ray_of<T: Scalar>(c: &Case) -> Option<RayHit<T>> {
    let p = |(x, y): (f64, f64)| Vec2::<T>::from_f64(x, y);
    let reach = T::from_f64(1.5 * c.da.0.hypot(c.da.1));
    let ray = Ray::new(p(c.a), p(c.da), reach)?;
    if c.b_circle {
        ray_circle(&ray, &Circle::new(p(c.b), T::from_f64(c.hb.0)))
    } else {
        ray_aabb(&ray, &Aabb::new(p(c.b), p(c.hb)))
    }
}

fn geometry_row<S: Scalar>() -> GeometryRow {
    let cases = cases::<S>();
    // Time the scalar's queries: the fastest of 5 passes (a pass takes a
    // millisecond or less, so one preemption would swamp a single one).
    let fastest = |pass: &dyn Fn()| {
        (0..5)
            .map(|_| {
                let start = Instant::now();
                pass();
                start.elapsed().as_secs_f64() * 1e9 / cases.len() as f64
            })
            .fold(f64::MAX, f64::min)
    };
    let ns_toi = fastest(&|| {
        std::hint::black_box(cases.iter().map(toi_of::<S>).collect::<Vec<_>>());
    });
    let ns_ray = fastest(&|| {
        std::hint::black_box(cases.iter().map(ray_of::<S>).collect::<Vec<_>>());
    });
    let tois: Vec<Toi<S>> = cases.iter().map(toi_of::<S>).collect();
    let rays: Vec<Option<RayHit<S>>> = cases.iter().map(ray_of::<S>).collect();

    let (mut toi_error, mut toi_mismatches): (f64, usize) = (0.0, 0);
    let (mut ray_error, mut ray_mismatches): (f64, usize) = (0.0, 0);
    for ((c, toi), ray) in cases.iter().zip(&tois).zip(&rays) {
        let d = (c.da.0 - c.db.0).hypot(c.da.1 - c.db.1);
        match (toi, toi_of::<f64>(c)) {
            (Toi::Hit { t, .. }, Toi::Hit { t: t64, .. }) => {
                toi_error = toi_error.max((t.to_f64() - t64).abs() * d);
            }
            (Toi::Overlapping, Toi::Overlapping) | (Toi::Miss, Toi::Miss) => {}
            _ => toi_mismatches += 1,
        }
        match (ray, ray_of::<f64>(c)) {
            (Some(h), Some(h64)) => {
                ray_error = ray_error.max((h.distance.to_f64() - h64.distance).abs());
            }
            (None, None) => {}
            _ => ray_mismatches += 1,
        }
    }
    GeometryRow {
        scalar: S::NAME,
        ns_toi,
        toi_error,
        toi_mismatches,
        ns_ray,
        ray_error,
        ray_mismatches,
    }
}

fn scalar_rows<S: Scalar>(rows: &mut Vec<Row>, geometry: &mut Vec<GeometryRow>) {
    for (iterations, substeps) in SETTINGS {
        let row = dynamics_row::<S>(iterations, substeps);
        eprintln!(
            "{:>7} it {:>2} sub {}: pyramid {:>9.0} ns/step",
            row.scalar, row.iterations, row.substeps, row.ns_pyramid
        );
        rows.push(row);
    }
    geometry.push(geometry_row::<S>());
}

fn sci(x: f64) -> String {
    if x == 0.0 {
        "0".to_owned()
    } else {
        format!("{x:.2e}")
    }
}

fn machine() -> String {
    std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split(':').nth(1))
                .map(|m| m.trim().to_owned())
        })
        .unwrap_or_else(|| "unknown CPU".to_owned())
}

fn markdown(rows: &[Row], geometry: &[GeometryRow]) -> String {
    let mut md = String::new();
    let cores = std::thread::available_parallelism().map_or(0, std::num::NonZero::get);
    let _ = writeln!(md, "# Speed against error\n");
    let _ = writeln!(
        md,
        "Generated by `cargo run --release --example accuracy` on {} ({cores} cores, \
         shared with other work: times ±20 %). Every scene uses the same engine code; only \
         the scalar and the solver settings change. Sleeping is off. See \
         `examples/accuracy.rs` for the exact scenes.\n",
        machine()
    );
    let _ = writeln!(md, "## Dynamics\n");
    let _ = writeln!(
        md,
        "* **ns/step**: the 20-row pyramid (210 boxes), median of 500 steps (the smaller of two rounds).\n\
         * **projectile**: largest distance from the analytic parabola over 2.4 s (units).\n\
         * **spring T / A**: relative error of the period and of the amplitude after 10 periods \
           (unit mass, k = 4π², undamped).\n\
         * **pendulum T**: relative period error of a 1-unit rope pendulum started at 30°, \
           against the exact large-angle period; **rope stretch**: largest `|bob − pivot| − L` (units).\n\
         * **sag**: how far the pyramid's top box sank in 500 steps; **penetration**: deepest \
           overlap of any two bodies, sampled every 10 steps (units).\n"
    );
    let _ = writeln!(
        md,
        "| scalar | iterations | substeps | ns/step | projectile | spring T | spring A | pendulum T | rope stretch | sag | penetration |"
    );
    let _ = writeln!(
        md,
        "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
    );
    for r in rows {
        let default = if (r.iterations, r.substeps) == (8, 1) {
            " (default)"
        } else {
            ""
        };
        let _ = writeln!(
            md,
            "| {} | {}{} | {} | {:.0} | {} | {} | {} | {} | {} | {} | {} |",
            r.scalar,
            r.iterations,
            default,
            r.substeps,
            r.ns_pyramid,
            sci(r.projectile),
            sci(r.spring_period),
            sci(r.spring_amplitude),
            sci(r.pendulum_period),
            sci(r.rope_stretch),
            sci(r.sag),
            sci(r.penetration),
        );
    }
    let _ = writeln!(md, "\n## Geometry against f64\n");
    let _ = writeln!(
        md,
        "{} random queries of each kind (time of impact of moving circle/box pairs; ray casts \
         against circles and boxes), inputs rounded to the scalar, answered in the scalar and in \
         f64 from the same rounded inputs; times are the fastest of 5 passes. **TOI error**: largest `|Δt|·|d|`, the error of the \
         contact position (units); **ray error**: largest error of the hit distance (units); \
         **mismatches**: queries where the two disagree on hit/miss/overlap (grazing cases).\n",
        3 * QUERIES
    );
    let _ = writeln!(
        md,
        "| scalar | ns/TOI | TOI error | TOI mismatches | ns/ray | ray error | ray mismatches |"
    );
    let _ = writeln!(md, "|---|---:|---:|---:|---:|---:|---:|");
    for g in geometry {
        let _ = writeln!(
            md,
            "| {} | {:.0} | {} | {} | {:.0} | {} | {} |",
            g.scalar,
            g.ns_toi,
            sci(g.toi_error),
            g.toi_mismatches,
            g.ns_ray,
            sci(g.ray_error),
            g.ray_mismatches
        );
    }
    let _ = writeln!(
        md,
        "\n## Other scenes' time per step\n\n\
         The tiny scenes above cost little; their ns/step (medians) show the fixed cost of a step \
         per scalar at the default settings (8 iterations, 1 substep):\n"
    );
    let _ = writeln!(
        md,
        "| scalar | projectile (1 body) | spring (1 body) | pendulum (1 body, 1 rope) | pyramid (210 boxes) |"
    );
    let _ = writeln!(md, "|---|---:|---:|---:|---:|");
    for r in rows.iter().filter(|r| (r.iterations, r.substeps) == (8, 1)) {
        let _ = writeln!(
            md,
            "| {} | {:.0} | {:.0} | {:.0} | {:.0} |",
            r.scalar, r.ns_projectile, r.ns_spring, r.ns_pendulum, r.ns_pyramid
        );
    }
    let _ = writeln!(
        md,
        "\n![error against time per step](accuracy.svg)\n\n\
         The plot shows each error against the pyramid's time per step: one colour per scalar, \
         one marker per substep count (circle 1, triangle 2, cross 4), more iterations further \
         right. Errors below 1e-12 (exact zeros included) are drawn at 1e-12."
    );
    md
}

/// One panel per error measure, x = pyramid µs/step, y = error, both log;
/// colour = scalar, marker = substeps (the iteration count moves a point
/// along x).
fn plot(rows: &[Row], path: &Path) -> Result<(), Box<dyn std::error::Error>> {
    const FLOOR: f64 = 1e-12;
    type Measure = (&'static str, fn(&Row) -> f64);
    let measures: [Measure; 6] = [
        ("projectile error (units)", |r| r.projectile),
        ("spring period error (relative)", |r| r.spring_period),
        ("pendulum period error (relative)", |r| r.pendulum_period),
        ("rope stretch (units)", |r| r.rope_stretch),
        ("pyramid sag (units)", |r| r.sag),
        ("max penetration (units)", |r| r.penetration),
    ];
    let colours = [
        ("I32F32", RGBColor(0x1f, 0x77, 0xb4)),
        ("I48F16", RGBColor(0xd6, 0x27, 0x28)),
        ("f64", RGBColor(0x2c, 0xa0, 0x2c)),
        ("f32", RGBColor(0xff, 0x7f, 0x0e)),
    ];
    let us = |r: &Row| r.ns_pyramid / 1e3;
    let (xmin, xmax) = rows.iter().fold((f64::MAX, f64::MIN), |(lo, hi), r| {
        (lo.min(us(r)), hi.max(us(r)))
    });
    let root = SVGBackend::new(path, (1500, 900)).into_drawing_area();
    root.fill(&WHITE)?;
    let root = root.titled(
        "clockwork2d: error against time per step. Colour: scalar. Marker: \u{25cf} 1 substep, \
         \u{25b2} 2 substeps, \u{2715} 4 substeps; more iterations = further right.",
        ("sans-serif", 18),
    )?;
    let panels = root.split_evenly((2, 3));
    for ((title, measure), area) in measures.iter().zip(panels.iter()) {
        let value = |r: &Row| measure(r).abs().max(FLOOR);
        let (ymin, ymax) = rows.iter().fold((f64::MAX, f64::MIN), |(lo, hi), r| {
            (lo.min(value(r)), hi.max(value(r)))
        });
        let mut chart = ChartBuilder::on(area)
            .caption(*title, ("sans-serif", 16))
            .margin(10)
            .x_label_area_size(35)
            .y_label_area_size(60)
            .build_cartesian_2d(
                (xmin / 1.2..xmax * 1.2).log_scale(),
                // Headroom above the points for the legend.
                (ymin / 3.0..ymax * 30.0).log_scale(),
            )?;
        chart
            .configure_mesh()
            .x_desc("time per step, 20-row pyramid (\u{b5}s)")
            .x_labels(8)
            .y_labels(6)
            .x_label_formatter(&|x| format!("{x:.0}"))
            .y_label_formatter(&|y| format!("{y:.0e}"))
            .draw()?;
        for &(scalar, colour) in &colours {
            let mine = || rows.iter().filter(move |r| r.scalar == scalar);
            let at = |r: &Row| (us(r), value(r));
            chart
                .draw_series(
                    mine()
                        .filter(|r| r.substeps == 1)
                        .map(|r| Dot::new(at(r), 4, colour.filled())),
                )?
                .label(scalar)
                .legend(move |(x, y)| Dot::new((x + 8, y), 4, colour.filled()));
            chart.draw_series(
                mine()
                    .filter(|r| r.substeps == 2)
                    .map(|r| TriangleMarker::new(at(r), 5, colour.filled())),
            )?;
            chart.draw_series(
                mine()
                    .filter(|r| r.substeps >= 4)
                    .map(|r| Cross::new(at(r), 4, colour.stroke_width(2))),
            )?;
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .position(SeriesLabelPosition::UpperRight)
            .draw()?;
    }
    root.present()?;
    Ok(())
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let out: PathBuf = std::env::args()
        .nth(1)
        .map_or_else(|| PathBuf::from("docs/report"), PathBuf::from);
    std::fs::create_dir_all(&out)?;
    let started = Instant::now();
    // Two rounds over every scalar, keeping each time's minimum: a burst of
    // background work during one configuration then costs it nothing. The
    // errors are the same in both rounds (the simulation is deterministic).
    let mut rounds = Vec::new();
    for _ in 0..ROUNDS {
        let (mut rows, mut geometry) = (Vec::new(), Vec::new());
        scalar_rows::<Fx>(&mut rows, &mut geometry);
        scalar_rows::<I48F16>(&mut rows, &mut geometry);
        scalar_rows::<f64>(&mut rows, &mut geometry);
        scalar_rows::<f32>(&mut rows, &mut geometry);
        rounds.push((rows, geometry));
    }
    let (mut rows, mut geometry) = rounds.pop().expect("at least one round");
    for (earlier_rows, earlier_geometry) in &rounds {
        for (r, e) in rows.iter_mut().zip(earlier_rows) {
            r.ns_pyramid = r.ns_pyramid.min(e.ns_pyramid);
            r.ns_projectile = r.ns_projectile.min(e.ns_projectile);
            r.ns_spring = r.ns_spring.min(e.ns_spring);
            r.ns_pendulum = r.ns_pendulum.min(e.ns_pendulum);
        }
        for (g, e) in geometry.iter_mut().zip(earlier_geometry) {
            g.ns_toi = g.ns_toi.min(e.ns_toi);
            g.ns_ray = g.ns_ray.min(e.ns_ray);
        }
    }
    let md = markdown(&rows, &geometry);
    std::fs::write(out.join("accuracy.md"), &md)?;
    plot(&rows, &out.join("accuracy.svg"))?;
    println!("{md}");
    eprintln!(
        "wrote {} and {} in {:.1} s",
        out.join("accuracy.md").display(),
        out.join("accuracy.svg").display(),
        started.elapsed().as_secs_f64()
    );
    Ok(())
}
