//! Ray casts: `Ray::new`, `ray_circle`, `ray_circle_roots`, `ray_aabb`.
//!
//! What is checked, on `Fx` unless stated:
//!
//! * **Hand-computed cases** (exact expectations where the answer is
//!   representable): head-on, oblique, tangent, just missing, max distance
//!   inclusive, origin inside / on the surface (the solid convention:
//!   distance 0, point = origin, normal = −direction), pointing away,
//!   axis-parallel rays (zero direction components), rays along a face
//!   line, the corner tie rule (y), one-ulp direction components.
//! * **Properties** (proptest), each on [`CASES`] random cases:
//!   - `ray_circle`: a hit is on the circle within [`TOL_SURFACE`], within
//!     `max_distance`, consistent with `origin + distance·direction`, with
//!     the outward unit normal, and no sampled point before it is inside
//!     the circle (beyond the tolerance); a miss really misses (the exact
//!     closest approach of the segment, computed in f64, and sampled points
//!     stay outside); an origin inside gives the solid-convention hit.
//!   - `ray_circle_roots`: both roots' points are on the circle; `None`
//!     only when the line's distance from the centre is at least `r`
//!     (within the tolerance); agreement with `ray_circle`.
//!   - `ray_aabb`: checked **bit for bit** against an independent exact
//!     oracle (rational slab test in `i128` on the raw bits): outcome, face,
//!     distance (= the truncated exact quotient), point exactly on the face;
//!     plus sampled points before the hit / along a miss are not inside.
//!   - `Ray::new`: the direction is unit within 1.25 ulps for any direction,
//!     from one ulp to `MAX`.
//!   - `Fx` against the `f64` run of the same code, with a stated bound.
//! * **Bounds**: coordinates at ±32 768, rays of length 2¹⁷ across the
//!   world, `max_distance` up to 2¹⁷ and `MAX`, one-ulp and `MIN`/`MAX`
//!   components: no panic, and (where the answer is exact) the exact
//!   answer, so debug and release are checked to agree bit for bit.
//! * The other scalars (`I48F16`, `f64`, `f32`) on the hand-computed cases.

use clockwork2d::geometry::*;
use clockwork2d::math::WORLD_LIMIT;
use clockwork2d::prelude::*;
use fixed::types::I48F16;
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;

mod common;
use common::fx_strategies::{positive, scaled};

/// Cases per property: 16× proptest's default of 256. One case is a few
/// hundred scalar operations plus 33 sampled points, so all the properties
/// of this file take well under a second, in release and in the debug test
/// profile (opt-level 1) alike. They have also been run with 200 000 cases
/// each.
const CASES: u32 = 4096;

/// One `Fx` ulp.
const ULP: f64 = 1.0 / 4_294_967_296.0;

/// How far a reported hit point may be from the circle, and how close a
/// miss may pass to it.
///
/// Derivation (see `sweep.rs`, `LineCircle`): after the Newton step on the
/// exact residual, the radial error is the residual's own rounding (the
/// length is rounded down, < 1 ulp), the step's rounding (about 1 ulp of
/// radial error) and forming the point (< 1 ulp per component, √2 ulps):
/// under 4 ulps. Where the step is skipped (grazing rays) the error it
/// would remove is below `r·2⁻¹⁴·⁵` ulps, under one ulp for these radii
/// (≤ 2¹²). A miss is decided on a discriminant whose error is under 3 ulps
/// of line-to-centre distance. The test allows 8 ulps (1.9e-9) for all of
/// these; the measured maximum, over 50 000 cases per property, is 4.2
/// ulps for hit points and roots, and misses pass at most 0.4 ulp inside. (The f64 evaluation here is exact to about 2⁻⁴⁰ for these
/// magnitudes.)
const TOL_SURFACE: f64 = 8.0 * ULP;

/// How far the reported point may be from `origin + distance·direction`
/// (per component): `o'` (≤ 1 ulp), `s'·d` (≤ 1 ulp) and the test's own
/// `distance·d` against the sum `s_f + s'` (≤ 1 ulp): 3 ulps; allow 4.
const TOL_ALONG: f64 = 4.0 * ULP;

// ---------------------------------------------------------------------------
// Helpers.
// ---------------------------------------------------------------------------

fn p64(p: Vec2) -> (f64, f64) {
    p.to_f64()
}

fn ray(o: Vec2, d: Vec2, max: f64) -> Ray {
    Ray::new(o, d, fx(max)).expect("valid ray")
}

/// The point `origin + s·direction` evaluated in f64 from the exact `Fx`
/// values (exact to about 2⁻³⁶ for `|s| ≤ 2¹⁷`).
fn along(r: &Ray, s: f64) -> (f64, f64) {
    let (ox, oy) = p64(r.origin);
    let (dx, dy) = p64(r.direction);
    (ox + s * dx, oy + s * dy)
}

fn dist(a: (f64, f64), b: (f64, f64)) -> f64 {
    (a.0 - b.0).hypot(a.1 - b.1)
}

/// The smallest distance from `c` to the segment `origin + s·direction`,
/// `s ∈ [0, max]`, in f64.
fn segment_distance(r: &Ray, max: f64, c: (f64, f64)) -> f64 {
    let (ox, oy) = p64(r.origin);
    let (dx, dy) = p64(r.direction);
    let dd = dx * dx + dy * dy;
    let s = (((c.0 - ox) * dx + (c.1 - oy) * dy) / dd).clamp(0.0, max);
    dist((ox + s * dx, oy + s * dy), c)
}

/// A coordinate anywhere in the world, ±2¹⁵ with all 32 fraction bits.
fn coord() -> impl Strategy<Value = Fx> {
    (-(1i64 << 47)..=(1i64 << 47)).prop_map(Fx::from_bits)
}

fn world_point() -> impl Strategy<Value = Vec2> {
    (coord(), coord()).prop_map(|(x, y)| Vec2::new(x, y))
}

fn clamp_world(p: Vec2) -> Vec2 {
    let l = Fx::from_num(WORLD_LIMIT);
    p.clamp(Vec2::new(-l, -l), Vec2::new(l, l))
}

/// A random direction: aimed at `target` from `origin` with a sideways
/// jitter of up to `2·size`, or any direction at all, or axis-parallel.
fn direction(origin: Vec2, target: Vec2, size: Fx, mode: u8, j: (f64, f64)) -> Vec2 {
    let aim = (target - origin).to_f64();
    let s = size.to_f64();
    match mode {
        0 | 1 => Vec2::from_f64(aim.0 + j.0 * s, aim.1 + j.1 * s),
        2 => Vec2::from_f64(j.0, j.1),
        3 => Vec2::new(if j.0 < 0.0 { -Fx::ONE } else { Fx::ONE }, Fx::ZERO),
        _ => Vec2::new(Fx::ZERO, if j.1 < 0.0 { -Fx::ONE } else { Fx::ONE }),
    }
}

/// `max_distance`: anywhere in `[0, 2^17]`, or scaled to the target's
/// distance (so that it sometimes cuts just before or after the hit).
fn max_distance(origin: Vec2, target: Vec2, mode: bool, f: f64) -> Fx {
    if mode {
        fx(f * 131_072.0)
    } else {
        fx(2.0 * f * dist(p64(origin), p64(target)))
    }
}

// ---------------------------------------------------------------------------
// ray_circle: generic checks.
// ---------------------------------------------------------------------------

fn check_ray_circle(r: &Ray, c: &Circle) -> Result<(), TestCaseError> {
    let hit = ray_circle(r, c);
    let centre = p64(c.center);
    let rad = c.radius.to_f64();
    let max = r.max_distance.to_f64();
    if c.contains_point(r.origin) {
        prop_assert_eq!(
            hit,
            Some(RayHit {
                distance: Fx::ZERO,
                point: r.origin,
                normal: -r.direction,
            })
        );
        return Ok(());
    }
    match hit {
        Some(h) => {
            let s = h.distance.to_f64();
            prop_assert!((0.0..=max).contains(&s), "distance {s} outside [0, {max}]");
            let p = p64(h.point);
            let off = (dist(p, centre) - rad).abs();
            let tol = TOL_SURFACE;
            prop_assert!(off <= tol, "point off the circle by {off:e}");
            let q = along(r, s);
            prop_assert!(
                (p.0 - q.0).abs() <= TOL_ALONG && (p.1 - q.1).abs() <= TOL_ALONG,
                "point {p:?} is not origin + distance·direction {q:?}"
            );
            // Outward unit normal: parallel to p − c. Normalising a vector
            // of length r costs about (2/r + 2) ulps; allow 8/r + 8.
            let (nx, ny) = p64(h.normal);
            let expect = ((p.0 - centre.0) / rad, (p.1 - centre.1) / rad);
            let tol_n = 8.0 * ULP / rad + 8.0 * ULP + tol / rad;
            prop_assert!(
                (nx - expect.0).abs() <= tol_n && (ny - expect.1).abs() <= tol_n,
                "normal {:?} vs {expect:?}",
                (nx, ny)
            );
            // Nothing earlier: 32 points before the hit are outside.
            for k in 0..32 {
                let sk = s * f64::from(k) / 32.0;
                let d = dist(along(r, sk), centre);
                prop_assert!(d >= rad - tol, "sample {k} inside: {d} < {rad}");
            }
            // Agreement with the roots (same solver): a hit that is not the
            // clamped "origin on the surface" case is the first root, bit
            // for bit.
            if h.distance > Fx::ZERO {
                let roots = ray_circle_roots(r, c);
                prop_assert_eq!(roots.map(|t| t.0), Some(h.distance));
            }
        }
        None => {
            // The exact closest approach of the segment stays outside (the
            // tolerance covers a grazing line whose discriminant rounds
            // below zero, and a hit rounded just past max_distance).
            let d = segment_distance(r, max, centre);
            prop_assert!(d >= rad - TOL_SURFACE, "missed but came within {d} < {rad}");
            for k in 0..=32 {
                let sk = max * f64::from(k) / 32.0;
                prop_assert!(dist(along(r, sk), centre) >= rad - TOL_SURFACE);
            }
        }
    }
    Ok(())
}

fn check_roots(r: &Ray, c: &Circle) -> Result<(), TestCaseError> {
    let centre = p64(c.center);
    let rad = c.radius.to_f64();
    match ray_circle_roots(r, c) {
        Some((t0, t1)) => {
            prop_assert!(t0 <= t1);
            for t in [t0, t1] {
                let p = along(r, t.to_f64());
                let off = (dist(p, centre) - rad).abs();
                // The surface tolerance plus the test's own o + t·d against
                // the solver's o' + s'·d (TOL_ALONG per component).
                let tol = TOL_SURFACE + 2.0 * TOL_ALONG;
                prop_assert!(off <= tol, "root off by {off:e}");
            }
            if c.contains_point(r.origin) {
                prop_assert!(t0 <= Fx::ZERO && t1 >= Fx::ZERO, "inside: {t0} {t1}");
            }
        }
        None => {
            // The line's distance from the centre is at least r.
            let (ox, oy) = p64(r.origin);
            let (dx, dy) = p64(r.direction);
            let h = ((centre.0 - ox) * dy - (centre.1 - oy) * dx).abs() / dx.hypot(dy);
            prop_assert!(h >= rad - TOL_SURFACE, "roots None but line at {h} < {rad}");
        }
    }
    Ok(())
}

// ---------------------------------------------------------------------------
// ray_aabb: an exact oracle on the raw bits.
// ---------------------------------------------------------------------------

/// The oracle's answer: the entered face and the exact entry parameter
/// `num / den` (a rational in real units: both raw values carry 2⁻³²).
#[derive(Debug, PartialEq)]
enum BoxOracle {
    Inside,
    Hit { x_face: bool, num: i128, den: i128 },
    Miss,
}

fn raw(x: Fx) -> i128 {
    i128::from(x.to_bits())
}

/// An independent slab test in exact rational arithmetic: each axis gives
/// the interval of `t` where the ray is between its two planes (or all `t`,
/// or none); intersect, keep `t ≥ 0` and `t ≤ max`; the entry axis is the
/// one with the later entry, y on an exact tie.
fn box_oracle(r: &Ray, b: &Aabb) -> BoxOracle {
    let (lo, hi) = (b.min(), b.max());
    let o = [raw(r.origin.x), raw(r.origin.y)];
    let d = [raw(r.direction.x), raw(r.direction.y)];
    let l = [raw(lo.x), raw(lo.y)];
    let h = [raw(hi.x), raw(hi.y)];
    if (0..2).all(|i| l[i] <= o[i] && o[i] <= h[i]) {
        return BoxOracle::Inside;
    }
    // Intervals as (enter_num, exit_num, den), den > 0; None = unbounded.
    let mut spans: [Option<(i128, i128, i128)>; 2] = [None, None];
    for i in 0..2 {
        if d[i] == 0 {
            if o[i] < l[i] || o[i] > h[i] {
                return BoxOracle::Miss;
            }
        } else if d[i] > 0 {
            spans[i] = Some((l[i] - o[i], h[i] - o[i], d[i]));
        } else {
            spans[i] = Some((o[i] - h[i], o[i] - l[i], -d[i]));
        }
    }
    // a/b < c/e with b, e > 0.
    let less = |a: i128, b: i128, c: i128, e: i128| a * e < c * b;
    let (k, (en, _, ed)) = match spans {
        [Some(x), Some(y)] => {
            if less(y.0, y.2, x.0, x.2) {
                (0, x)
            } else {
                (1, y)
            }
        }
        [Some(x), None] => (0, x),
        [None, Some(y)] => (1, y),
        [None, None] => unreachable!("outside the box means one slab is violated"),
    };
    for s in spans.iter().flatten() {
        // Exit before 0 or before the entry: miss.
        if s.1 < 0 || less(s.1, s.2, en, ed) {
            return BoxOracle::Miss;
        }
    }
    // en/ed ≤ max_raw / 2^32.
    if en * (1i128 << 32) > raw(r.max_distance) * ed {
        return BoxOracle::Miss;
    }
    assert!(en >= 0, "entry behind an outside origin");
    BoxOracle::Hit {
        x_face: k == 0,
        num: en,
        den: ed,
    }
}

/// `true` if `p` is inside the box by more than `tol` on both axes.
fn deep_inside(b: &Aabb, p: (f64, f64), tol: f64) -> bool {
    let (cx, cy) = p64(b.center);
    let (hx, hy) = p64(b.half_extents);
    (p.0 - cx).abs() < hx - tol && (p.1 - cy).abs() < hy - tol
}

fn check_ray_aabb(r: &Ray, b: &Aabb) -> Result<(), TestCaseError> {
    let hit = ray_aabb(r, b);
    let max = r.max_distance.to_f64();
    match box_oracle(r, b) {
        BoxOracle::Inside => {
            prop_assert_eq!(
                hit,
                Some(RayHit {
                    distance: Fx::ZERO,
                    point: r.origin,
                    normal: -r.direction,
                })
            );
        }
        BoxOracle::Miss => {
            prop_assert_eq!(hit, None);
            // Sampled points along the whole ray stay out (the oracle is
            // exact, so no tolerance is needed beyond f64 evaluation).
            for k in 0..=32 {
                let p = along(r, max * f64::from(k) / 32.0);
                prop_assert!(!deep_inside(b, p, 1e-9), "miss passes through {p:?}");
            }
        }
        BoxOracle::Hit { x_face, num, den } => {
            let Some(h) = hit else {
                return Err(TestCaseError::fail(format!(
                    "oracle hits, ray_aabb misses: {r:?} {b:?}"
                )));
            };
            // Distance: the exact quotient truncated to an ulp.
            prop_assert_eq!(raw(h.distance), (num << 32) / den);
            prop_assert!(h.distance <= r.max_distance);
            let (lo, hi) = (b.min(), b.max());
            let (dx, dy) = (r.direction.x, r.direction.y);
            // The entered face: its outward normal opposes the motion, and
            // the point is exactly on it, within its extent.
            if x_face {
                let face = if dx > Fx::ZERO { lo.x } else { hi.x };
                let sign = if dx > Fx::ZERO { -Fx::ONE } else { Fx::ONE };
                prop_assert_eq!(h.normal, Vec2::new(sign, Fx::ZERO));
                prop_assert_eq!(h.point.x, face);
                prop_assert!(lo.y <= h.point.y && h.point.y <= hi.y);
            } else {
                let face = if dy > Fx::ZERO { lo.y } else { hi.y };
                let sign = if dy > Fx::ZERO { -Fx::ONE } else { Fx::ONE };
                prop_assert_eq!(h.normal, Vec2::new(Fx::ZERO, sign));
                prop_assert_eq!(h.point.y, face);
                prop_assert!(lo.x <= h.point.x && h.point.x <= hi.x);
            }
            // The point is origin + t·direction for the exact t: the face
            // coordinate exactly; the other rounded once and clamped, and t
            // truncated (< 1 ulp · |d| ≤ 1 ulp): within 2 ulps.
            #[allow(clippy::cast_precision_loss)]
            let t = num as f64 / den as f64;
            let q = along(r, t);
            let p = p64(h.point);
            prop_assert!((p.0 - q.0).abs() <= 2.0 * ULP + t * 1e-15);
            prop_assert!((p.1 - q.1).abs() <= 2.0 * ULP + t * 1e-15);
            // Nothing earlier: 32 points before the hit are not inside.
            for k in 0..32 {
                let p = along(r, t * f64::from(k) / 32.0);
                prop_assert!(!deep_inside(b, p, 1e-9), "sample {k} inside before the hit");
            }
        }
    }
    Ok(())
}

// ---------------------------------------------------------------------------
// Strategies for whole cases.
// ---------------------------------------------------------------------------

/// A circle anywhere in the world, radius from 2⁻⁸ to 2¹², and a ray from a
/// point at distance 2⁻⁶..2¹⁴ (clamped to the world), mostly aimed at it.
fn circle_case() -> impl Strategy<Value = (Ray, Circle)> {
    (
        world_point(),
        (scaled(-6..15), scaled(-6..15)),
        positive(-8..12),
        0u8..6,
        (-2.0f64..2.0, -2.0f64..2.0),
        any::<bool>(),
        0.0f64..1.0,
    )
        .prop_filter_map("zero direction", |(c, (ox, oy), rad, mode, j, mm, f)| {
            let origin = clamp_world(c + Vec2::new(ox, oy));
            let dir = direction(origin, c, rad, mode, j);
            let r = Ray::new(origin, dir, max_distance(origin, c, mm, f))?;
            Some((r, Circle::new(c, rad)))
        })
}

/// A box anywhere in the world, half extents 2⁻⁸..2¹² per axis, and a ray
/// as for circles; one case in six starts exactly on a face line and runs
/// along it.
fn box_case() -> impl Strategy<Value = (Ray, Aabb)> {
    (
        world_point(),
        (positive(-8..12), positive(-8..12)),
        (scaled(-6..15), scaled(-6..15)),
        0u8..6,
        (-2.0f64..2.0, -2.0f64..2.0),
        any::<bool>(),
        0.0f64..1.0,
        0u8..6,
    )
        .prop_filter_map(
            "zero direction",
            |(c, (hx, hy), (ox, oy), mode, j, mm, f, face)| {
                let b = Aabb::new(c, Vec2::new(hx, hy));
                let mut origin = clamp_world(c + Vec2::new(ox, oy));
                let mut dir = direction(origin, c, Ord::max(hx, hy), mode, j);
                if face == 0 {
                    // Along the top or bottom face line.
                    origin.y = if j.1 < 0.0 { b.min().y } else { b.max().y };
                    dir = Vec2::new(if origin.x < c.x { Fx::ONE } else { -Fx::ONE }, Fx::ZERO);
                }
                let r = Ray::new(origin, dir, max_distance(origin, c, mm, f))?;
                Some((r, b))
            },
        )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(CASES))]

    #[test]
    fn prop_ray_circle((r, c) in circle_case()) {
        check_ray_circle(&r, &c)?;
    }

    #[test]
    fn prop_ray_circle_roots((r, c) in circle_case()) {
        check_roots(&r, &c)?;
    }

    /// Grazing rays: the line passes within `r·2⁻²⁰` of tangency (inside
    /// or outside), where the root is ill-conditioned and the solver's
    /// Newton step may be skipped; large radii (2⁶..2¹²) make any
    /// radius-proportional error visible. The hit point must still be on
    /// the circle within `TOL_SURFACE` and misses must not pass inside.
    #[test]
    fn prop_ray_circle_grazing(
        c in world_point(),
        rad in positive(6..12),
        (jx, jy) in (-1.0f64..1.0, -1.0f64..1.0),
        delta in -1.0f64..1.0,
        back in 1.0f64..8.0,
    ) {
        let Some(d) = Ray::new(Vec2::ZERO, Vec2::from_f64(jx, jy), Fx::ONE) else {
            return Ok(());
        };
        let (dx, dy) = p64(d.direction);
        let (cx, cy) = p64(c);
        let r = rad.to_f64();
        let h = r * (1.0 + delta / 1_048_576.0);
        // origin = c + h·perp(d) − back·r·d
        let o = Vec2::from_f64(cx - h * dy - back * r * dx, cy + h * dx - back * r * dy);
        let ray = Ray { origin: o, direction: d.direction, max_distance: fx(131_072.0) };
        check_ray_circle(&ray, &Circle::new(c, rad))?;
        check_roots(&ray, &Circle::new(c, rad))?;
    }

    #[test]
    fn prop_ray_aabb((r, b) in box_case()) {
        check_ray_aabb(&r, &b)?;
    }

    /// `Ray::new` normalises any nonzero direction to unit length within
    /// 1.25 ulps: the length of the max-normed vector (in [1, √2]) and each
    /// quotient are rounded to nearest (≤ ½ ulp each), so
    /// `| |d|² − 1 | ≤ (√2 + 1) ulp` and `| |d| − 1 | ≤ 1.21 ulp` (measured:
    /// 1.02). The angle moves by the max-norm quotient's rounding (½ ulp)
    /// and the final quotients' (½ ulp each): ≤ 1.3 ulps; the test allows 2.
    #[test]
    fn prop_ray_new_unit(x in any::<i64>(), y in any::<i64>(), shift in 0u32..63) {
        let d = Vec2::new(Fx::from_bits(x >> shift), Fx::from_bits(y >> shift));
        match Ray::new(Vec2::ZERO, d, Fx::ONE) {
            None => prop_assert_eq!(d, Vec2::ZERO),
            Some(r) => {
                let (dx, dy) = p64(r.direction);
                prop_assert!((dx.hypot(dy) - 1.0).abs() <= 1.25 * ULP);
                // Same direction: the cross product with the input is ~0.
                let (ix, iy) = p64(d);
                let cross = (dx * iy - dy * ix) / ix.hypot(iy);
                prop_assert!(cross.abs() <= 2.0 * ULP, "angle off by {cross:e}");
            }
        }
    }

    /// `Fx` against the f64 run of the same algorithm on the same inputs
    /// (the f64 ray is the `Fx` ray converted exactly, so both cast along
    /// the same direction). For rays that pass well inside the circle
    /// (`h ≤ 0.9 r`: `√(r² − h²) ≥ 0.43 r`, so the ill-conditioning factor
    /// `r / √disc` is at most 2.3), the `Fx` distance and point are within
    /// 16 ulps (3.7e-9) of the f64 ones: the `Fx` point is within 4 ulps of
    /// the circle (see `TOL_SURFACE`), which is at most 2.3·4 ulps along
    /// the ray, and the foot point's rounding shifts the line sideways by
    /// √2 ulps, which moves the hit by (h/√disc)·√2 ≤ 3 ulps. Measured (50 000
    /// cases): 6.3 ulps.
    #[test]
    fn prop_ray_circle_fx_vs_f64((r, c) in circle_case()) {
        let r64 = Ray::<f64> {
            origin: r.origin.cast(),
            direction: r.direction.cast(),
            max_distance: r.max_distance.to_f64(),
        };
        let c64 = Circle::<f64>::new(c.center.cast(), c.radius.to_f64());
        let (ox, oy) = p64(r.origin);
        let (dx, dy) = p64(r.direction);
        let (cx, cy) = p64(c.center);
        let h = ((cx - ox) * dy - (cy - oy) * dx).abs();
        let well_inside = h <= 0.9 * c.radius.to_f64();
        if let (Some(a), Some(b)) = (ray_circle(&r, &c), ray_circle(&r64, &c64)) {
            if well_inside {
                prop_assert!((a.distance.to_f64() - b.distance).abs() <= 16.0 * ULP);
                prop_assert!((a.point.x.to_f64() - b.point.x).abs() <= 16.0 * ULP);
                prop_assert!((a.point.y.to_f64() - b.point.y).abs() <= 16.0 * ULP);
            }
        } else if well_inside && c.radius > fx(1e-3) {
            // Well away from tangency both must agree on hit or miss,
            // unless the hit is within rounding of max_distance.
            let (a, b) = (ray_circle(&r, &c).is_some(), ray_circle(&r64, &c64).is_some());
            if a != b {
                let roots = ray_circle_roots(&r64, &c64).expect("well inside: line hits");
                let near_max = (roots.0 - r64.max_distance).abs() <= 16.0 * ULP;
                prop_assert!(near_max, "outcome differs: fx {a} f64 {b}");
            }
        }
    }
}

// ---------------------------------------------------------------------------
// Hand-computed cases: ray_circle.
// ---------------------------------------------------------------------------

#[test]
fn circle_head_on_exact() {
    let c = Circle::new(vec2(10.0, 0.0), fx(2.0));
    let h = ray_circle(&ray(vec2(0.0, 0.0), vec2(1.0, 0.0), 100.0), &c).unwrap();
    assert_eq!(h.distance, fx(8.0));
    assert_eq!(h.point, vec2(8.0, 0.0));
    assert_eq!(h.normal, vec2(-1.0, 0.0));
    // Coming down onto the top.
    let h = ray_circle(&ray(vec2(10.0, 7.0), vec2(0.0, -3.0), 100.0), &c).unwrap();
    assert_eq!(
        (h.distance, h.point, h.normal),
        (fx(5.0), vec2(10.0, 2.0), vec2(0.0, 1.0))
    );
}

#[test]
fn circle_oblique_3_4_5() {
    // Ray from the origin along (3, 4)/5 towards the circle at (6, 8) of
    // radius 5: |m| = 10, so the hit is at distance 5, the point (3, 4),
    // the normal (−0.6, −0.8).
    let h = ray_circle(
        &ray(vec2(0.0, 0.0), vec2(3.0, 4.0), 100.0),
        &Circle::new(vec2(6.0, 8.0), fx(5.0)),
    )
    .unwrap();
    assert!((h.distance.to_f64() - 5.0).abs() < 8.0 * ULP);
    assert!(dist(p64(h.point), (3.0, 4.0)) < 8.0 * ULP);
    assert!(dist(p64(h.normal), (-0.6, -0.8)) < 8.0 * ULP);
}

#[test]
fn circle_off_axis() {
    // Ray along +x at height 0.6 against the unit circle: enters at
    // x = −0.8, so from x = −10 the distance is 9.2, normal (−0.8, 0.6).
    let r = ray(vec2(-10.0, 0.6), vec2(1.0, 0.0), 100.0);
    let h = ray_circle(&r, &Circle::new(vec2(0.0, 0.0), fx(1.0))).unwrap();
    // 0.6 is not exact in Fx (error < 2⁻³³): the hit moves by about
    // (0.6/0.8)·2⁻³³ plus the solver's few ulps.
    assert!((h.distance.to_f64() - 9.2).abs() < 8.0 * ULP);
    assert!(dist(p64(h.normal), (-0.8, 0.6)) < 8.0 * ULP);
}

#[test]
fn circle_tangent_and_just_missing() {
    let c = Circle::new(vec2(0.0, 0.0), fx(1.0));
    // Tangent at (0, 1): a hit (the closed circle is touched), exactly.
    let h = ray_circle(&ray(vec2(-5.0, 1.0), vec2(1.0, 0.0), 100.0), &c).unwrap();
    assert_eq!(
        (h.distance, h.point, h.normal),
        (fx(5.0), vec2(0.0, 1.0), vec2(0.0, 1.0))
    );
    assert_eq!(
        ray_circle_roots(&ray(vec2(-5.0, 1.0), vec2(1.0, 0.0), 1.0), &c),
        Some((fx(5.0), fx(5.0)))
    );
    // One ulp higher: the line misses.
    let above = Vec2::new(fx(-5.0), Fx::ONE + Fx::DELTA);
    assert_eq!(ray_circle(&ray(above, vec2(1.0, 0.0), 100.0), &c), None);
    assert_eq!(
        ray_circle_roots(&ray(above, vec2(1.0, 0.0), 100.0), &c),
        None
    );
}

#[test]
fn circle_max_distance_is_inclusive() {
    let c = Circle::new(vec2(10.0, 0.0), fx(2.0));
    assert!(ray_circle(&ray(vec2(0.0, 0.0), vec2(1.0, 0.0), 8.0), &c).is_some());
    let short = Ray::new(vec2(0.0, 0.0), vec2(1.0, 0.0), fx(8.0) - Fx::DELTA).unwrap();
    assert_eq!(ray_circle(&short, &c), None);
    // A zero max distance from outside: nothing.
    assert_eq!(
        ray_circle(&ray(vec2(0.0, 0.0), vec2(1.0, 0.0), 0.0), &c),
        None
    );
}

#[test]
fn circle_inside_and_on_surface_is_solid() {
    let c = Circle::new(vec2(0.0, 0.0), fx(1.0));
    for (o, d) in [
        (vec2(0.0, 0.0), vec2(1.0, 0.0)),   // centre
        (vec2(0.5, 0.25), vec2(-1.0, 2.0)), // inside
        (vec2(1.0, 0.0), vec2(1.0, 0.0)),   // on the surface, leaving
        (vec2(0.0, -1.0), vec2(0.0, 1.0)),  // on the surface, entering
    ] {
        let r = ray(o, d, 5.0);
        let h = ray_circle(&r, &c).unwrap();
        assert_eq!((h.distance, h.point, h.normal), (Fx::ZERO, o, -r.direction));
    }
    // Roots from inside straddle the origin.
    let (t0, t1) = ray_circle_roots(&ray(vec2(0.5, 0.0), vec2(1.0, 0.0), 1.0), &c).unwrap();
    assert_eq!((t0, t1), (fx(-1.5), fx(0.5)));
}

#[test]
fn circle_pointing_away_or_behind() {
    let c = Circle::new(vec2(10.0, 0.0), fx(2.0));
    assert_eq!(
        ray_circle(&ray(vec2(0.0, 0.0), vec2(-1.0, 0.0), 100.0), &c),
        None
    );
    // Perpendicular at the closest point (m·d = 0): moving away.
    assert_eq!(
        ray_circle(&ray(vec2(10.0, 5.0), vec2(1.0, 0.0), 100.0), &c),
        None
    );
    // Behind: the roots are negative.
    let (t0, t1) = ray_circle_roots(&ray(vec2(20.0, 0.0), vec2(1.0, 0.0), 1.0), &c).unwrap();
    assert_eq!((t0, t1), (fx(-12.0), fx(-8.0)));
}

#[test]
fn circle_long_ray_across_the_world() {
    // From the left edge of the world to a small circle at the right edge,
    // 65 534 units away: exact, because the direction is exactly +x.
    let c = Circle::new(vec2(32_767.0, 0.0), fx(0.5));
    let r = ray(vec2(-32_768.0, 0.0), vec2(1.0, 0.0), 131_072.0);
    assert_eq!(ray_circle_roots(&r, &c), Some((fx(65_534.5), fx(65_535.5))));
    let h = ray_circle(&r, &c).unwrap();
    assert_eq!((h.distance, h.point), (fx(65_534.5), vec2(32_766.5, 0.0)));
    // Diagonally across the whole world (|m| = 2^16·√2 ≈ 92 682, m·m =
    // 2^33 beyond the narrow range: formed in the wide type).
    let c = Circle::new(vec2(32_767.0, 32_767.0), fx(1.0));
    let r = ray(vec2(-32_768.0, -32_768.0), vec2(1.0, 1.0), 131_072.0);
    check_ray_circle(&r, &c).unwrap();
    let h = ray_circle(&r, &c).unwrap();
    let expect = 65_535.0 * 2f64.sqrt() - 1.0;
    // The direction (1,1)/√2 is rounded (< 2 ulps per component), which at
    // 92 680 units moves the hit by up to 2¹⁷·2⁻³¹ = 6e-5 along the ray.
    assert!(
        (h.distance.to_f64() - expect).abs() < 1e-4,
        "{}",
        h.distance
    );
}

// ---------------------------------------------------------------------------
// Hand-computed cases: ray_aabb.
// ---------------------------------------------------------------------------

fn unit_box() -> Aabb {
    Aabb::new(vec2(0.0, 0.0), vec2(1.0, 1.0))
}

#[test]
fn aabb_each_face() {
    let b = Aabb::new(vec2(0.0, 0.0), vec2(2.0, 1.0));
    for (o, d, dist_, point, normal) in [
        (
            vec2(-5.0, 0.5),
            vec2(1.0, 0.0),
            3.0,
            vec2(-2.0, 0.5),
            vec2(-1.0, 0.0),
        ),
        (
            vec2(5.0, -0.5),
            vec2(-1.0, 0.0),
            3.0,
            vec2(2.0, -0.5),
            vec2(1.0, 0.0),
        ),
        (
            vec2(1.5, -4.0),
            vec2(0.0, 1.0),
            3.0,
            vec2(1.5, -1.0),
            vec2(0.0, -1.0),
        ),
        (
            vec2(-1.5, 4.0),
            vec2(0.0, -1.0),
            3.0,
            vec2(-1.5, 1.0),
            vec2(0.0, 1.0),
        ),
    ] {
        let r = ray(o, d, 10.0);
        let h = ray_aabb(&r, &b).unwrap();
        assert_eq!((h.distance, h.point, h.normal), (fx(dist_), point, normal));
        check_ray_aabb(&r, &b).unwrap();
    }
}

#[test]
fn aabb_oblique() {
    // From (−4, −1) (on the bottom face's line, left of the box) along
    // (3, 4)/5: in the y slab for t ∈ [0, 2.5], in the x slab for
    // t ∈ [5, 8.33]: the intervals are disjoint, a miss (passing above the
    // box's top-left corner).
    let r = ray(vec2(-4.0, -1.0), vec2(3.0, 4.0), 10.0);
    assert_eq!(ray_aabb(&r, &unit_box()), None);
    check_ray_aabb(&r, &unit_box()).unwrap();
    // From (−3, −1.5) along (4, 3)/5: reaches x = −1 at t = 2.5 (y = 0):
    // the left face.
    let r = ray(vec2(-3.0, -1.5), vec2(4.0, 3.0), 10.0);
    let h = ray_aabb(&r, &unit_box()).unwrap();
    assert!((h.distance.to_f64() - 2.5).abs() < 4.0 * ULP);
    assert_eq!(h.normal, vec2(-1.0, 0.0));
    assert_eq!(h.point.x, fx(-1.0));
    assert!(h.point.y.to_f64().abs() < 4.0 * ULP);
    check_ray_aabb(&r, &unit_box()).unwrap();
}

#[test]
fn aabb_corner_tie_picks_y() {
    // Exactly through the corner (−1, −1) from (−3, −3): y face.
    let r = ray(vec2(-3.0, -3.0), vec2(1.0, 1.0), 10.0);
    let h = ray_aabb(&r, &unit_box()).unwrap();
    assert_eq!(h.normal, vec2(0.0, -1.0));
    assert_eq!(h.point, vec2(-1.0, -1.0));
    // Through (1, 1) from (3, 3): y face, normal +Y.
    let h = ray_aabb(&ray(vec2(3.0, 3.0), vec2(-1.0, -1.0), 10.0), &unit_box()).unwrap();
    assert_eq!((h.normal, h.point), (vec2(0.0, 1.0), vec2(1.0, 1.0)));
    // One ulp to the side, the x face wins: from (−3 − ulp, −3) the x entry
    // comes later.
    let r = ray(
        Vec2::new(fx(-3.0) - Fx::DELTA, fx(-3.0)),
        vec2(1.0, 1.0),
        10.0,
    );
    assert_eq!(ray_aabb(&r, &unit_box()).unwrap().normal, vec2(-1.0, 0.0));
}

#[test]
fn aabb_axis_parallel_zero_components() {
    let b = unit_box();
    // Inside the y slab (boundary included), moving along x: hit.
    for y in [-1.0, -0.5, 0.0, 1.0] {
        let h = ray_aabb(&ray(vec2(-3.0, y), vec2(1.0, 0.0), 10.0), &b).unwrap();
        assert_eq!(
            (h.distance, h.point, h.normal),
            (fx(2.0), vec2(-1.0, y), vec2(-1.0, 0.0))
        );
    }
    // Outside the slab by one ulp: miss, no division by zero anywhere.
    let r = ray(
        Vec2::new(fx(-3.0), Fx::ONE + Fx::DELTA),
        vec2(1.0, 0.0),
        10.0,
    );
    assert_eq!(ray_aabb(&r, &b), None);
    // Vertical rays.
    let h = ray_aabb(&ray(vec2(0.25, 7.0), vec2(0.0, -2.0), 10.0), &b).unwrap();
    assert_eq!(
        (h.distance, h.point, h.normal),
        (fx(6.0), vec2(0.25, 1.0), vec2(0.0, 1.0))
    );
    assert_eq!(
        ray_aabb(&ray(vec2(1.5, 7.0), vec2(0.0, -1.0), 10.0), &b),
        None
    );
}

#[test]
fn aabb_along_a_face_line() {
    // Running along the top face line y = 1 from outside: touches the
    // closed box at its corner, through the x face.
    let h = ray_aabb(&ray(vec2(-5.0, 1.0), vec2(1.0, 0.0), 10.0), &unit_box()).unwrap();
    assert_eq!(
        (h.distance, h.point, h.normal),
        (fx(4.0), vec2(-1.0, 1.0), vec2(-1.0, 0.0))
    );
    // Starting on the face and running along it: inside (solid convention).
    let r = ray(vec2(0.0, 1.0), vec2(1.0, 0.0), 10.0);
    let h = ray_aabb(&r, &unit_box()).unwrap();
    assert_eq!(
        (h.distance, h.point, h.normal),
        (Fx::ZERO, vec2(0.0, 1.0), vec2(-1.0, 0.0))
    );
}

#[test]
fn aabb_inside_pointing_away_and_limits() {
    let b = unit_box();
    let r = ray(vec2(0.5, 0.5), vec2(0.0, 1.0), 10.0);
    assert_eq!(ray_aabb(&r, &b).unwrap().distance, Fx::ZERO);
    assert_eq!(ray_aabb(&r, &b).unwrap().normal, vec2(0.0, -1.0));
    assert_eq!(
        ray_aabb(&ray(vec2(3.0, 0.0), vec2(1.0, 0.0), 10.0), &b),
        None
    );
    // max_distance inclusive.
    assert!(ray_aabb(&ray(vec2(3.0, 0.0), vec2(-1.0, 0.0), 2.0), &b).is_some());
    let short = Ray::new(vec2(3.0, 0.0), vec2(-1.0, 0.0), fx(2.0) - Fx::DELTA).unwrap();
    assert_eq!(ray_aabb(&short, &b), None);
}

#[test]
fn aabb_one_ulp_direction_component() {
    // A direction with a one-ulp y component: the y slab is reached only
    // after 2³² units, far beyond any max_distance; the quotient that would
    // saturate is never formed (the reach test rejects it first).
    let b = Aabb::new(vec2(0.0, 1.5), vec2(10_000.0, 0.5));
    let r = Ray {
        origin: vec2(0.0, 0.0),
        direction: Vec2::new(Fx::ONE, Fx::DELTA),
        max_distance: Fx::MAX,
    };
    assert_eq!(ray_aabb(&r, &b), None);
    // Same with the box placed where the ray does reach it: at x ≥ 2³¹ the
    // ray leaves the representable range, so only boxes before it count.
    // A box straddling y = 0: entered through its x face at distance 5.
    let b = Aabb::new(vec2(10.0, 0.0), vec2(5.0, 1.0));
    let h = ray_aabb(&r, &b).unwrap();
    assert_eq!((h.distance, h.normal), (fx(5.0), vec2(-1.0, 0.0)));
    check_ray_aabb(&r, &b).unwrap();
    // Built by Ray::new, a one-ulp direction is normalised exactly.
    let r = Ray::new(vec2(0.0, 0.0), Vec2::new(Fx::DELTA, Fx::ZERO), fx(10.0)).unwrap();
    assert_eq!(r.direction, vec2(1.0, 0.0));
}

// ---------------------------------------------------------------------------
// Bounds: no panic, exact answers where they are exact.
// ---------------------------------------------------------------------------

#[test]
fn bounds_world_corners_and_long_rays() {
    let l = 32_768.0;
    // Box at the far corner, ray from the opposite corner along the
    // diagonal: enters exactly through the box's corner (tie → y face).
    let b = Aabb::new(vec2(l - 1.0, l - 1.0), vec2(1.0, 1.0));
    let r = ray(vec2(-l, -l), vec2(1.0, 1.0), 131_072.0);
    let h = ray_aabb(&r, &b).unwrap();
    assert_eq!(
        (h.point, h.normal),
        (vec2(l - 2.0, l - 2.0), vec2(0.0, -1.0))
    );
    check_ray_aabb(&r, &b).unwrap();
    // Along the bottom edge of the world, exactly.
    let b = Aabb::new(vec2(l - 0.5, -l + 0.5), vec2(0.5, 0.5));
    let r = ray(vec2(-l, -l), vec2(1.0, 0.0), 131_072.0);
    let h = ray_aabb(&r, &b).unwrap();
    assert_eq!(
        (h.distance, h.point, h.normal),
        (fx(65_535.0), vec2(l - 1.0, -l), vec2(-1.0, 0.0))
    );
    // The same ray against a circle in the far corner.
    let c = Circle::new(vec2(l - 1.0, -l + 1.0), fx(1.0));
    let h = ray_circle(&r, &c).unwrap();
    assert_eq!(
        (h.distance, h.point, h.normal),
        (fx(65_535.0), vec2(l - 1.0, -l), vec2(0.0, -1.0))
    );
}

/// Inputs far outside the documented bounds (`MIN`/`MAX` coordinates,
/// radii and half extents, one-ulp and huge directions): results saturate
/// but there is no panic (in debug, every overflow check is live), and the
/// same call gives the same answer twice.
#[test]
fn bounds_extreme_inputs_do_not_panic() {
    let vals = [
        Fx::MIN,
        Fx::MIN + Fx::DELTA,
        fx(-32_768.0),
        -Fx::DELTA,
        Fx::ZERO,
        Fx::DELTA,
        fx(0.5),
        fx(32_768.0),
        fx(131_072.0),
        Fx::MAX,
    ];
    let mut count = 0u32;
    for &ox in &vals {
        for &oy in &vals {
            for &dx in &vals {
                for &dy in &[Fx::MIN, -Fx::DELTA, Fx::ZERO, Fx::DELTA, Fx::MAX] {
                    for &size in &[Fx::DELTA, Fx::ONE, fx(32_768.0), Fx::MAX] {
                        for &max in &[Fx::ZERO, fx(131_072.0), Fx::MAX] {
                            let Some(r) = Ray::new(Vec2::new(ox, oy), Vec2::new(dx, dy), max)
                            else {
                                continue;
                            };
                            let c = Circle::new(Vec2::new(dy, ox), size);
                            let b = Aabb::new(Vec2::new(oy, dx), Vec2::new(size, size));
                            let a = (
                                ray_circle(&r, &c),
                                ray_circle_roots(&r, &c),
                                ray_aabb(&r, &b),
                            );
                            let again = (
                                ray_circle(&r, &c),
                                ray_circle_roots(&r, &c),
                                ray_aabb(&r, &b),
                            );
                            assert_eq!(a, again);
                            if let Some(h) = a.2 {
                                assert!(h.distance >= Fx::ZERO && h.distance <= max);
                            }
                            if let Some(h) = a.0 {
                                assert!(h.distance >= Fx::ZERO && h.distance <= max);
                            }
                            count += 1;
                        }
                    }
                }
            }
        }
    }
    assert!(count > 10_000, "{count} cases");
}

/// Random rays across the world with the largest `max_distance` (2¹⁷) and
/// random shapes near the world's edges: all properties hold there too.
#[test]
fn bounds_random_edge_cases() {
    let mut runner = proptest::test_runner::TestRunner::new(ProptestConfig::with_cases(CASES));
    let edge = prop_oneof![Just(-32_768.0f64), Just(32_768.0), -32_768.0f64..32_768.0];
    let case = (
        edge.clone(),
        edge.clone(),
        edge.clone(),
        edge,
        positive(-4..14),
        0.0f64..1.0,
    );
    runner
        .run(&case, |(ox, oy, cx, cy, size, f)| {
            let o = vec2(ox, oy);
            let c = vec2(cx, cy);
            let Some(r) = Ray::new(o, c - o + vec2(f, 1.0 - f), fx(131_072.0)) else {
                return Ok(());
            };
            check_ray_circle(&r, &Circle::new(c, size))?;
            check_roots(&r, &Circle::new(c, size))?;
            check_ray_aabb(&r, &Aabb::new(c, Vec2::new(size, size.mul(fx(f + 0.5)))))
        })
        .unwrap();
}

// ---------------------------------------------------------------------------
// The other scalars.
// ---------------------------------------------------------------------------

fn generic_cases<S: Scalar>(tol: f64) {
    let v = |x: f64, y: f64| Vec2::<S>::from_f64(x, y);
    let r = |o, d, m: f64| Ray::new(o, d, S::from_f64(m)).unwrap();
    let close = |a: S, b: f64| (a.to_f64() - b).abs() <= tol;
    // Head-on circle.
    let h = ray_circle(
        &r(v(0.0, 0.0), v(2.0, 0.0), 100.0),
        &Circle::new(v(10.0, 0.0), S::from_f64(2.0)),
    )
    .unwrap();
    assert!(
        close(h.distance, 8.0) && close(h.normal.x, -1.0),
        "{} {h:?}",
        S::NAME
    );
    // Oblique 3-4-5.
    let h = ray_circle(
        &r(v(0.0, 0.0), v(3.0, 4.0), 100.0),
        &Circle::new(v(6.0, 8.0), S::from_f64(5.0)),
    )
    .unwrap();
    assert!(
        close(h.distance, 5.0) && close(h.point.x, 3.0) && close(h.normal.y, -0.8),
        "{} {h:?}",
        S::NAME
    );
    // Roots.
    let (t0, t1) = ray_circle_roots(
        &r(v(0.5, 0.0), v(1.0, 0.0), 1.0),
        &Circle::new(v(0.0, 0.0), S::ONE),
    )
    .unwrap();
    assert!(close(t0, -1.5) && close(t1, 0.5), "{}", S::NAME);
    // Inside.
    let h = ray_circle(
        &r(v(0.1, 0.0), v(0.0, 1.0), 1.0),
        &Circle::new(v(0.0, 0.0), S::ONE),
    )
    .unwrap();
    assert!(h.distance == S::ZERO && close(h.normal.y, -1.0));
    // Boxes: a face, the corner tie, a parallel miss.
    let b = Aabb::new(v(0.0, 0.0), v(1.0, 1.0));
    let h = ray_aabb(&r(v(-3.0, 0.5), v(1.0, 0.0), 10.0), &b).unwrap();
    assert!(
        close(h.distance, 2.0) && close(h.normal.x, -1.0),
        "{} {h:?}",
        S::NAME
    );
    let h = ray_aabb(&r(v(-3.0, -3.0), v(1.0, 1.0), 10.0), &b).unwrap();
    assert!(close(h.normal.y, -1.0), "{} {h:?}", S::NAME);
    assert_eq!(ray_aabb(&r(v(-3.0, 1.5), v(1.0, 0.0), 10.0), &b), None);
}

#[test]
fn other_scalars() {
    generic_cases::<I48F16>(4.0 / 65_536.0);
    generic_cases::<f64>(1e-12);
    generic_cases::<f32>(1e-5);
}
