//! Agreement of the ray casts and time-of-impact queries: the same generic
//! function run with `S = Fx` and `S = f64` on the same inputs.
//!
//! Inputs are drawn by the seeded [`Rng`] and quantised to 1/1024, so they
//! are exact in both types: the differences come only from the queries
//! (including `Ray::new`'s normalisation, which each type does itself).
//! The ray rows are end to end: each type normalises the direction itself,
//! and a direction rounded by an ulp (2⁻³² rad) moves a hit thousands of
//! units away sideways by ~1e-6, which a grazing incidence turns into a
//! much larger shift along the surface; so a third row runs the f64 cast
//! along the `Fx` ray's exact direction, which measures the cast alone.
//! Errors are compared only where both types report a hit; cases where one
//! type hits and the other does not (or, for TOI, where the outcomes
//! `Hit` / `Overlapping` / `Miss` differ) are counted as outcome
//! mismatches. Those are expected only for near-tangent or near-limit cases
//! (a ray grazing a circle, a hit within rounding of `max_distance`, a
//! contact within rounding of `t = 1`).
//!
//! Scenes: a shape anywhere in the world (±30 000), the ray origin or the
//! other shape at an offset of scale 2^k, k = 0..13 uniformly (so from
//! touching distance to a quarter of the world), sizes up to 64 units,
//! motions mostly aimed at the target with a sideways jitter.

use clockwork2d::geometry::*;
use clockwork2d::prelude::Fx;
use clockwork2d::prelude::*;

use super::rng::Rng;

/// Cases per query.
const CASES: u32 = 100_000;

/// Error statistics of one output.
#[derive(Default)]
struct Stats {
    both_hit: u32,
    mismatches: u32,
    max: f64,
    sum: f64,
}

impl Stats {
    fn add(&mut self, err: f64) {
        self.both_hit += 1;
        self.max = self.max.max(err);
        self.sum += err;
    }

    fn row(&self, query: &str) {
        let mean = if self.both_hit > 0 {
            self.sum / f64::from(self.both_hit)
        } else {
            0.0
        };
        println!(
            "| {query} | {CASES} ({} both hit, {} outcome mismatches) | {:.2e} | {:.2e} |",
            self.both_hit, self.mismatches, self.max, mean
        );
    }
}

/// A ray case: origin, unnormalised direction, max distance, and a target
/// (centre and size) to cast against.
struct RayCase {
    origin: (f64, f64),
    direction: (f64, f64),
    max_distance: f64,
    center: (f64, f64),
    size: (f64, f64),
}

/// A TOI case: two centres, two sizes (radius or half extents), two
/// displacements.
struct ToiCase {
    ca: (f64, f64),
    cb: (f64, f64),
    sa: (f64, f64),
    sb: (f64, f64),
    da: (f64, f64),
    db: (f64, f64),
}

/// An offset scale 2^k, k uniform in 0..=13.
fn scale(rng: &mut Rng) -> f64 {
    let k = rng.next_u64() % 14;
    f64::from(1u32 << k)
}

fn ray_case(rng: &mut Rng) -> RayCase {
    let center = (
        rng.range(-30_000.0, 30_000.0),
        rng.range(-30_000.0, 30_000.0),
    );
    let s = scale(rng);
    let origin = (center.0 + rng.range(-s, s), center.1 + rng.range(-s, s));
    let size = (rng.range(0.01, 64.0), rng.range(0.01, 64.0));
    let j = size.0.max(size.1);
    let direction = (
        center.0 - origin.0 + rng.range(-1.5, 1.5) * j,
        center.1 - origin.1 + rng.range(-1.5, 1.5) * j,
    );
    // Quantise the jittered direction again (products of two quantised
    // values are not multiples of 1/1024 in general).
    let q = |x: f64| (x * 1024.0).round() / 1024.0;
    let reach = (center.0 - origin.0).hypot(center.1 - origin.1) + 2.0 * j;
    RayCase {
        origin,
        direction: (q(direction.0), q(direction.1)),
        max_distance: rng.range(0.0, 1.5 * reach),
        center,
        size,
    }
}

fn toi_case(rng: &mut Rng) -> ToiCase {
    let q = |x: f64| (x * 1024.0).round() / 1024.0;
    let ca = (
        rng.range(-30_000.0, 30_000.0),
        rng.range(-30_000.0, 30_000.0),
    );
    let s = scale(rng);
    let cb = (ca.0 + rng.range(-s, s), ca.1 + rng.range(-s, s));
    let sa = (rng.range(0.01, 64.0), rng.range(0.01, 64.0));
    let sb = (rng.range(0.01, 64.0), rng.range(0.01, 64.0));
    let k = rng.range(0.0, 2.0);
    let j = sa.0.max(sb.0);
    let rel = (
        q(k * (cb.0 - ca.0) + rng.range(-1.5, 1.5) * j),
        q(k * (cb.1 - ca.1) + rng.range(-1.5, 1.5) * j),
    );
    let db = (rng.range(-16.0, 16.0), rng.range(-16.0, 16.0));
    ToiCase {
        ca,
        cb,
        sa,
        sb,
        da: (db.0 + rel.0, db.1 + rel.1),
        db,
    }
}

fn vec<S: Scalar>(p: (f64, f64)) -> Vec2<S> {
    Vec2::from_f64(p.0, p.1)
}

fn make_ray<S: Scalar>(c: &RayCase) -> Option<Ray<S>> {
    Ray::new(vec(c.origin), vec(c.direction), S::from_f64(c.max_distance))
}

/// The `Fx` ray converted exactly to f64: the f64 cast then runs along the
/// very same (rounded) direction, which isolates the cast's arithmetic from
/// the normalisation in `Ray::new`.
fn fx_ray_in_f64(c: &RayCase) -> Option<Ray<f64>> {
    let r = make_ray::<Fx>(c)?;
    Some(Ray {
        origin: r.origin.cast(),
        direction: r.direction.cast(),
        max_distance: r.max_distance.to_f64(),
    })
}

/// `ray_circle`: distance and point, as f64.
fn ray_circle_on<S: Scalar>(ray: Option<Ray<S>>, c: &RayCase) -> Option<(f64, (f64, f64))> {
    let hit = ray_circle(&ray?, &Circle::new(vec(c.center), S::from_f64(c.size.0)))?;
    Some((hit.distance.to_f64(), hit.point.to_f64()))
}

/// `ray_aabb`: distance and point, as f64.
fn ray_aabb_on<S: Scalar>(ray: Option<Ray<S>>, c: &RayCase) -> Option<(f64, (f64, f64))> {
    let hit = ray_aabb(&ray?, &Aabb::new(vec(c.center), vec(c.size)))?;
    Some((hit.distance.to_f64(), hit.point.to_f64()))
}

/// A TOI outcome as (kind, t): kind 0 = hit, 1 = overlapping, 2 = miss.
fn outcome<S: Scalar>(toi: Toi<S>) -> (u8, f64) {
    match toi {
        Toi::Hit { t, .. } => (0, t.to_f64()),
        Toi::Overlapping => (1, 0.0),
        Toi::Miss => (2, 0.0),
    }
}

fn toi_cc_case<S: Scalar>(c: &ToiCase) -> (u8, f64) {
    let a = Circle::new(vec::<S>(c.ca), S::from_f64(c.sa.0));
    let b = Circle::new(vec::<S>(c.cb), S::from_f64(c.sb.0));
    outcome(toi_circle_circle(&a, vec(c.da), &b, vec(c.db)))
}

fn toi_bb_case<S: Scalar>(c: &ToiCase) -> (u8, f64) {
    let a = Aabb::new(vec::<S>(c.ca), vec(c.sa));
    let b = Aabb::new(vec::<S>(c.cb), vec(c.sb));
    outcome(toi_aabb_aabb(&a, vec(c.da), &b, vec(c.db)))
}

fn toi_cb_case<S: Scalar>(c: &ToiCase) -> (u8, f64) {
    let a = Circle::new(vec::<S>(c.ca), S::from_f64(c.sa.0));
    let b = Aabb::new(vec::<S>(c.cb), vec(c.sb));
    outcome(toi_circle_aabb(&a, vec(c.da), &b, vec(c.db)))
}

/// One ray query's answers: `Fx`, f64, and f64 along the `Fx` direction.
type RayAnswers = [Option<(f64, (f64, f64))>; 3];

/// Runs one ray query over `CASES` cases and prints its rows: distance and
/// point (end to end, each type normalising the direction itself), and the
/// distance with the f64 cast run along the `Fx` ray's direction.
fn ray_rows(name: &str, seed: u64, query: fn(&RayCase) -> RayAnswers) {
    let mut rng = Rng(seed);
    let (mut distance, mut point, mut same) =
        (Stats::default(), Stats::default(), Stats::default());
    for _ in 0..CASES {
        let case = ray_case(&mut rng);
        let [a, b, c] = query(&case);
        match (a, b) {
            (Some((d0, p0)), Some((d1, p1))) => {
                distance.add((d0 - d1).abs());
                point.add((p0.0 - p1.0).hypot(p0.1 - p1.1));
            }
            (None, None) => {}
            _ => {
                distance.mismatches += 1;
                point.mismatches += 1;
            }
        }
        match (a, c) {
            (Some((d0, _)), Some((d1, _))) => same.add((d0 - d1).abs()),
            (None, None) => {}
            _ => same.mismatches += 1,
        }
    }
    distance.row(&format!("{name} distance"));
    point.row(&format!("{name} point"));
    same.row(&format!("{name} distance, f64 along the Fx direction"));
}

/// Runs one TOI query over `CASES` cases and prints its `t` row.
fn toi_row(name: &str, seed: u64, query: fn(&ToiCase) -> [(u8, f64); 2]) {
    let mut rng = Rng(seed);
    let mut t = Stats::default();
    for _ in 0..CASES {
        let case = toi_case(&mut rng);
        let [(k0, t0), (k1, t1)] = query(&case);
        if k0 != k1 {
            t.mismatches += 1;
        } else if k0 == 0 {
            t.add((t0 - t1).abs());
        }
    }
    t.row(&format!("{name} t"));
}

/// Prints the rows of the ray and TOI queries.
pub fn report() {
    ray_rows("ray_circle", 0x5241_5943, |c| {
        [
            ray_circle_on(make_ray::<Fx>(c), c),
            ray_circle_on(make_ray::<f64>(c), c),
            ray_circle_on(fx_ray_in_f64(c), c),
        ]
    });
    ray_rows("ray_aabb", 0x5241_5942, |c| {
        [
            ray_aabb_on(make_ray::<Fx>(c), c),
            ray_aabb_on(make_ray::<f64>(c), c),
            ray_aabb_on(fx_ray_in_f64(c), c),
        ]
    });
    toi_row("toi_circle_circle", 0x544F_4943, |c| {
        [toi_cc_case::<Fx>(c), toi_cc_case::<f64>(c)]
    });
    toi_row("toi_aabb_aabb", 0x544F_4942, |c| {
        [toi_bb_case::<Fx>(c), toi_bb_case::<f64>(c)]
    });
    toi_row("toi_circle_aabb", 0x544F_4941, |c| {
        [toi_cb_case::<Fx>(c), toi_cb_case::<f64>(c)]
    });
}
