//! World ray casts agree with exact geometry: 2000 random rays (origins
//! anywhere in an 80 × 80 area, any direction, direction lengths 0.001 to
//! 100) into 40 random fixed circles (r 0.05–2) and boxes (half extents
//! 0.01–2), in a world at the origin and in two at the corners of the
//! world's bounds (±32 000, where every coordinate uses the top bits of the
//! fixed-point range).
//!
//! The reference is computed in f64 from the bodies' own stored positions
//! and sizes: a circle by the quadratic `|o + t·u − c|² = r²`, a box by the
//! slab method, a ray starting inside a shape at distance 0 (the crate's
//! documented rule). The nearest hit within `max_distance` must be the same
//! body, at the same distance.
//!
//! Tolerance: the engine works in I32F32 (resolution `q = 2⁻³²` ≈ 2.3e-10
//! absolute, whatever the magnitude). It normalises the direction (a unit
//! vector good to a few ulps, so a point `t` along the ray is off by
//! ~`t·4q`, under 1e-7 for `t` ≤ 200) and solves the same quadratic or
//! slabs with a few roundings each: 1e-6 on the distance is generous and
//! still 1000× smaller than the smallest shape. Rays that the reference
//! finds ambiguous under such rounding are left out of the comparison:
//! within 1e-6 of tangent to a circle (the discriminant's square root
//! amplifies rounding there), within 1e-6 of a box's corner or of grazing
//! a box's face, or with two bodies' hit distances within 1e-6 of each
//! other (either may be the first). The count left out is printed; it is
//! a handful of 6000.
//!
//! Run with `--nocapture` to see the figures.

use clockwork2d::prelude::*;

mod common;
use common::split_mix::SplitMix;

const TOLERANCE: f64 = 1e-6;
const MAX_DISTANCE: f64 = 200.0;

/// A shape as the reference sees it: centre and either a radius or half
/// extents.
#[derive(Clone, Copy)]
enum Solid {
    Circle { c: (f64, f64), r: f64 },
    Box { c: (f64, f64), h: (f64, f64) },
}

/// The reference hit distance of the ray `o + t·u` (`u` unit) with a
/// solid, and whether the answer is ambiguous under rounding.
fn reference(solid: Solid, o: (f64, f64), u: (f64, f64)) -> (Option<f64>, bool) {
    match solid {
        Solid::Circle { c, r } => {
            let f = (o.0 - c.0, o.1 - c.1);
            let b = f.0 * u.0 + f.1 * u.1;
            let k = f.0 * f.0 + f.1 * f.1 - r * r;
            if k <= 0.0 {
                // Inside (or on) the circle: distance 0; on the rim is ambiguous.
                return (Some(0.0), k > -2.0 * r * TOLERANCE);
            }
            let disc = b * b - k;
            // Distance of the line from the centre is √(r² − disc); the ray
            // is near tangent when that is within the tolerance of r.
            let near_tangent = disc.abs() < 2.0 * r * TOLERANCE;
            if disc < 0.0 {
                return (None, near_tangent);
            }
            let t = -b - disc.sqrt();
            if t >= 0.0 {
                (Some(t), near_tangent)
            } else {
                (None, near_tangent)
            }
        }
        Solid::Box { c, h } => {
            let (mut t0, mut t1) = (0.0f64, f64::MAX);
            let mut ambiguous = false;
            for (o, u, lo, hi) in [
                (o.0, u.0, c.0 - h.0, c.0 + h.0),
                (o.1, u.1, c.1 - h.1, c.1 + h.1),
            ] {
                if u.abs() < 1e-12 {
                    ambiguous |= (o - lo).abs() < TOLERANCE || (o - hi).abs() < TOLERANCE;
                    if o < lo || o > hi {
                        return (None, ambiguous);
                    }
                } else {
                    let (a, b) = ((lo - o) / u, (hi - o) / u);
                    t0 = t0.max(a.min(b));
                    t1 = t1.min(a.max(b));
                }
            }
            // Entering and leaving the slabs at nearly the same distance:
            // the ray passes within the tolerance of a corner.
            ambiguous |= (t1 - t0).abs() < TOLERANCE * 4.0;
            if t0 <= t1 {
                (Some(t0), ambiguous)
            } else {
                (None, ambiguous)
            }
        }
    }
}

#[test]
fn ray_casts_match_exact_geometry_near_the_origin_and_at_the_bounds() {
    let mut rng = SplitMix(7);
    let (mut cast, mut compared, mut hits, mut worst) = (0usize, 0usize, 0usize, 0.0f64);
    for (cx, cy) in [(0.0, 0.0), (32_000.0, -32_000.0), (-32_700.0, 32_700.0)] {
        let mut world = World::new(WorldSettings::default());
        let mut solids: Vec<(BodyId, Solid)> = Vec::new();
        for _ in 0..40 {
            let at = vec2(cx + rng.range(-20.0, 20.0), cy + rng.range(-20.0, 20.0));
            let shape = if rng.unit() < 0.5 {
                Shape::circle(fx(rng.range(0.05, 2.0)))
            } else {
                Shape::aabb(vec2(rng.range(0.01, 2.0), rng.range(0.01, 2.0)))
            };
            let id = world
                .add_body(BodyDef::fixed(shape).position(at))
                .expect("shape inside the world");
            // The reference uses what the world stores (literals rounded to Fx).
            let body = world.body(id).unwrap();
            let c = body.position().to_f64();
            let solid = match body.shape() {
                Shape::Circle { radius } => Solid::Circle {
                    c,
                    r: radius.to_f64(),
                },
                Shape::Aabb { half_extents } => Solid::Box {
                    c,
                    h: half_extents.to_f64(),
                },
            };
            solids.push((id, solid));
        }
        for _ in 0..2000 {
            let origin = vec2(cx + rng.range(-40.0, 40.0), cy + rng.range(-40.0, 40.0));
            let angle = rng.range(0.0, std::f64::consts::TAU);
            let length = rng.range(0.001, 100.0);
            let direction = vec2(length * angle.cos(), length * angle.sin());
            let o = origin.to_f64();
            let d = direction.to_f64();
            let norm = d.0.hypot(d.1);
            let u = (d.0 / norm, d.1 / norm);
            cast += 1;
            // Reference: every hit within the range, sorted.
            let mut ambiguous = false;
            let mut found: Vec<(f64, BodyId)> = Vec::new();
            for &(id, solid) in &solids {
                let (t, amb) = reference(solid, o, u);
                ambiguous |= amb;
                if let Some(t) = t {
                    ambiguous |= (t - MAX_DISTANCE).abs() < TOLERANCE;
                    if t <= MAX_DISTANCE {
                        found.push((t, id));
                    }
                }
            }
            found.sort_by(|a, b| a.0.total_cmp(&b.0));
            if found.len() > 1 && found[1].0 - found[0].0 < TOLERANCE {
                ambiguous = true;
            }
            if ambiguous {
                continue;
            }
            compared += 1;
            let got = world.raycast(origin, direction, fx(MAX_DISTANCE));
            match (found.first(), got) {
                (None, None) => {}
                (Some(&(t, id)), Some(hit)) => {
                    hits += 1;
                    let err = (hit.hit.distance.to_f64() - t).abs();
                    worst = worst.max(err);
                    assert_eq!(hit.body, id, "ray from {o:?} along {d:?}: a different body");
                    assert!(
                        err <= TOLERANCE,
                        "ray from {o:?} along {d:?}: distance {} against {t}",
                        hit.hit.distance.to_f64()
                    );
                }
                (expected, got) => panic!(
                    "ray from {o:?} along {d:?}: reference {expected:?}, world {:?}",
                    got.map(|h| h.hit.distance.to_f64())
                ),
            }
        }
    }
    println!(
        "rays: {cast} cast, {compared} compared ({} ambiguous left out), {hits} hits, worst distance error {worst:.3e}",
        cast - compared
    );
    assert!(compared * 100 >= cast * 95, "too many rays left out");
}
