//! Agreement of the closest-point and contact queries: the same generic
//! function run with `S = Fx` and with `S = f64`, on seeded random inputs
//! quantised to 1/1024 (exact in both types, so the difference comes only
//! from the queries' own rounding).
//!
//! Inputs (magnitudes ≤ 1000, the scale of a typical scene):
//!
//! * segments: `a`, `b`, `p` uniform in ±1000 on each axis;
//! * pairs of shapes: the first centre uniform in ±1000, the second at an
//!   offset uniform in ±20, radii and half extents uniform in [0.01, 10),
//!   so that touching, overlapping and separated pairs all occur.
//!
//! Each row reports one output; for vectors (points, normals) the error of a
//! case is the larger of the two component errors.

use clockwork2d::geometry::*;
use clockwork2d::prelude::*;

use super::rng::Rng;

/// Cases per query.
const CASES: usize = 100_000;

/// Running max and mean of absolute errors.
#[derive(Default)]
struct Stats {
    max: f64,
    sum: f64,
    count: usize,
}

impl Stats {
    fn scalar(&mut self, fixed: Fx, reference: f64) {
        self.push((fixed.to_f64() - reference).abs());
    }

    fn vector(&mut self, fixed: Vec2, reference: Vec2<f64>) {
        let (x, y) = fixed.to_f64();
        self.push((x - reference.x).abs().max((y - reference.y).abs()));
    }

    fn push(&mut self, err: f64) {
        self.max = self.max.max(err);
        self.sum += err;
        self.count += 1;
    }

    #[allow(clippy::cast_precision_loss)]
    fn row(&self, query: &str) {
        let mean = if self.count == 0 {
            0.0
        } else {
            self.sum / self.count as f64
        };
        println!(
            "| {query} | {} | {:.3e} | {:.3e} |",
            self.count, self.max, mean
        );
    }
}

fn point(rng: &mut Rng, half: f64) -> Vec2<f64> {
    Vec2::new(rng.range(-half, half), rng.range(-half, half))
}

/// Quantised inputs are exact in `Fx`, so this conversion is exact.
fn fixed(v: Vec2<f64>) -> Vec2 {
    v.cast()
}

fn circle(rng: &mut Rng, center: Vec2<f64>) -> Circle<f64> {
    Circle::new(center, rng.range(0.01, 10.0))
}

fn aabb(rng: &mut Rng, center: Vec2<f64>) -> Aabb<f64> {
    Aabb::new(
        center,
        Vec2::new(rng.range(0.01, 10.0), rng.range(0.01, 10.0)),
    )
}

fn circle_fx(c: &Circle<f64>) -> Circle {
    Circle::new(fixed(c.center), Fx::from_f64(c.radius))
}

fn aabb_fx(b: &Aabb<f64>) -> Aabb {
    Aabb::new(fixed(b.center), fixed(b.half_extents))
}

/// A pair of centres: one in ±1000, the other within ±20 of it.
fn centres(rng: &mut Rng) -> (Vec2<f64>, Vec2<f64>) {
    let a = point(rng, 1000.0);
    let b = a + point(rng, 20.0);
    (a, b)
}

/// Prints the table rows for the four queries.
pub fn report() {
    let mut rng = Rng(0xC0DE_C0DE_0000_0001);

    let (mut t, mut pt) = (Stats::default(), Stats::default());
    for _ in 0..CASES {
        let (a, b, p) = (
            point(&mut rng, 1000.0),
            point(&mut rng, 1000.0),
            point(&mut rng, 1000.0),
        );
        let r = closest_point_on_segment(a, b, p);
        let c = closest_point_on_segment(fixed(a), fixed(b), fixed(p));
        t.scalar(c.t, r.t);
        pt.vector(c.point, r.point);
    }
    t.row("closest_point_on_segment: t");
    pt.row("closest_point_on_segment: point");

    let (mut sep, mut nrm) = (Stats::default(), Stats::default());
    for _ in 0..CASES {
        let (ca, cb) = centres(&mut rng);
        let (a, b) = (circle(&mut rng, ca), circle(&mut rng, cb));
        let r = contact_circle_circle(&a, &b);
        let c = contact_circle_circle(&circle_fx(&a), &circle_fx(&b));
        sep.scalar(c.separation, r.separation);
        nrm.vector(c.normal, r.normal);
    }
    sep.row("contact_circle_circle: separation");
    nrm.row("contact_circle_circle: normal");

    let (mut sep, mut nrm) = (Stats::default(), Stats::default());
    for _ in 0..CASES {
        let (ca, cb) = centres(&mut rng);
        let (a, b) = (aabb(&mut rng, ca), aabb(&mut rng, cb));
        let r = contact_aabb_aabb(&a, &b);
        let c = contact_aabb_aabb(&aabb_fx(&a), &aabb_fx(&b));
        sep.scalar(c.separation, r.separation);
        nrm.vector(c.normal, r.normal);
    }
    sep.row("contact_aabb_aabb: separation");
    nrm.row("contact_aabb_aabb: normal");

    let (mut sep, mut nrm) = (Stats::default(), Stats::default());
    for _ in 0..CASES {
        let (ca, cb) = centres(&mut rng);
        let (a, b) = (circle(&mut rng, ca), aabb(&mut rng, cb));
        let r = contact_circle_aabb(&a, &b);
        let c = contact_circle_aabb(&circle_fx(&a), &aabb_fx(&b));
        sep.scalar(c.separation, r.separation);
        nrm.vector(c.normal, r.normal);
    }
    sep.row("contact_circle_aabb: separation");
    nrm.row("contact_circle_aabb: normal");
}
