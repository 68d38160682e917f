//! Found by the `geometry_differential` fuzz target (its first runs): two
//! inputs where `Fx` answered differently from what the target then
//! expected. Neither is an engine bug; both are behaviour the geometry
//! module documents and the target now checks with the right bound. They
//! are kept here so `cargo test` holds the engine to that behaviour.
//!
//! 1. `toi_normal_of_a_tiny_minkowski_circle`: the minimised input was a
//!    circle of radius 1 ulp at (30, 0) moving by (110, 0) onto a circle of
//!    radius ~111 ulps at (110.4296875, −1 ulp). The normal at the hit,
//!    (1, −0.00893), is 4e-5 off unit length: it is the cast's hit point
//!    minus the centre over the Minkowski radius `R` (112 ulps), and the
//!    point is rounded to the ulp grid, so the normal is only as good as
//!    `(hit-point error + 2 ulps) / R` — the same `ulp·(1 + 1/L)` behaviour
//!    as `contact_circle_circle`'s normal. For `R ≥ 1` it is unit within a
//!    few ulps.
//! 2. `ray_from_half_an_ulp_outside_hits_at_zero_with_the_surface_normal`:
//!    a ray from (1, 0), half an ulp outside the unit circle centred at
//!    (0, −2⁻¹⁶), heading in: the entry is less than an ulp away, so the
//!    hit is at distance 0 and its point is the origin — but it is a hit
//!    from outside, with the surface's normal, not the "origin inside"
//!    convention (normal = −direction).
//!
//! # Bounds used (from `src/geometry/toi.rs` and `fuzz/src/geometry_check.rs`)
//! At a TOI hit the shapes are within `B = (2.5|d| + 4)` ulps of touching
//! (`|d|` the relative displacement in units); the normal is the hit point
//! minus the centre over `R`, so each component and the length are within
//! `2(B + 2 ulps)/R + 8 ulps` of the true unit normal.

use clockwork2d::geometry::{Circle, Ray, Toi, ray_circle, toi_circle_circle};
use clockwork2d::prelude::*;

const ULP: f64 = 1.0 / 4_294_967_296.0;

fn raw(bits: i64) -> Fx {
    Fx::from_bits(bits)
}

#[test]
fn toi_normal_of_a_tiny_minkowski_circle() {
    let mover = Circle::new(Vec2::new(fx(30.0), fx(0.0)), raw(1));
    let motion = Vec2::new(fx(110.0), fx(0.0));
    let target_center = Vec2::new(fx(110.4296875), raw(-1));
    // Radii from one ulp to one unit (the fuzz input had 111 ulps).
    for radius_bits in [1i64, 2, 3, 10, 111, 1_000, 1 << 20, 1 << 32] {
        let target = Circle::new(target_center, raw(radius_bits));
        let Toi::Hit { t, normal } = toi_circle_circle(&mover, motion, &target, Vec2::ZERO) else {
            panic!("radius {radius_bits} ulps: the mover must hit the target");
        };
        let big_r = (radius_bits + 1) as f64 * ULP;
        let bound = (2.5 * 110.0 + 4.0) * ULP;
        let tol = 2.0 * (bound + 2.0 * ULP) / big_r + 8.0 * ULP;
        // The true normal at the reported t: from the mover's centre to the
        // target's.
        let t = t.to_f64();
        let (gx, gy) = (
            target_center.x.to_f64() - (30.0 + 110.0 * t),
            target_center.y.to_f64(),
        );
        let len = gx.hypot(gy);
        let (nx, ny) = (normal.x.to_f64(), normal.y.to_f64());
        assert!(
            (len - big_r).abs() <= bound,
            "radius {radius_bits}: centres {len} apart at t, R = {big_r}"
        );
        assert!(
            (nx - gx / len).abs() <= tol && (ny - gy / len).abs() <= tol,
            "radius {radius_bits}: normal ({nx}, {ny}) vs ({}, {}) beyond {tol}",
            gx / len,
            gy / len
        );
        assert!(
            (nx.hypot(ny) - 1.0).abs() <= tol,
            "radius {radius_bits}: |normal| = {}",
            nx.hypot(ny)
        );
        if radius_bits >= 1 << 32 {
            // A unit radius: unit within a few ulps.
            assert!(
                (nx.hypot(ny) - 1.0).abs() <= 1e-9,
                "R = 1: |normal| {nx} {ny}"
            );
        }
    }
}

#[test]
fn ray_from_half_an_ulp_outside_hits_at_zero_with_the_surface_normal() {
    // |origin − centre|² = 1 + 2⁻³²: outside by about half an ulp.
    let circle = Circle::new(Vec2::new(fx(0.0), raw(-(1 << 16))), fx(1.0));
    let direction = Vec2::new(fx(-1.0), fx(1.0));
    let ray = Ray::new(Vec2::new(fx(1.0), fx(0.0)), direction, fx(1.0)).unwrap();
    assert!(!circle.contains_point(ray.origin), "the origin is outside");
    let hit = ray_circle(&ray, &circle).expect("heading into the circle");
    assert_eq!(hit.distance, Fx::ZERO, "entry below one ulp away");
    assert_eq!(hit.point, ray.origin);
    // The outward normal at (1, 0) of this circle: (1, 2⁻¹⁶)/|…|, not the
    // inside convention −direction = (0.707, −0.707).
    assert_ne!(hit.normal, -ray.direction);
    let (nx, ny) = (hit.normal.x.to_f64(), hit.normal.y.to_f64());
    let len = 1.0f64.hypot(1.0 / 65_536.0);
    assert!((nx - 1.0 / len).abs() <= 1e-8, "normal x {nx}");
    assert!((ny - 1.0 / 65_536.0 / len).abs() <= 1e-8, "normal y {ny}");

    // The same ray starting one ulp further in (inside or on the circle)
    // gets the inside convention.
    let inside = Ray::new(Vec2::new(raw((1 << 32) - 1), fx(0.0)), direction, fx(1.0)).unwrap();
    let hit = ray_circle(&inside, &circle).unwrap();
    assert_eq!(
        (hit.distance, hit.point, hit.normal),
        (Fx::ZERO, inside.origin, -inside.direction)
    );
}
