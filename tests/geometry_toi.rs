//! Time of impact: `toi_circle_circle`, `toi_aabb_aabb`, `toi_circle_aabb`.
//!
//! What is checked, on `Fx` unless stated:
//!
//! * **Hand-computed cases**: head-on and oblique circles, a grazing
//!   contact and one ulp past it, contact exactly at `t = 1`, shapes moving
//!   apart, zero relative motion, a box landing on a box, boxes sliding
//!   with touching projections, corner-to-corner boxes (the y tie rule),
//!   axis-parallel motion, a circle on a box face, on a corner, on the
//!   face/corner boundary, starting inside the grown box's corner square,
//!   passing a corner; a thin fast bullet that would tunnel.
//! * **Properties** (proptest), [`CASES`] random cases per shape pair, with
//!   all three outcomes well represented:
//!   - `Overlapping` exactly when the shapes overlap or touch at `t = 0`,
//!     decided by an exact `i128` oracle on the raw bits;
//!   - a `Hit` at `t`: `t ∈ [0, 1]`, the shapes touch at `t` within
//!     [`tol`] (their signed separation, computed in f64 from the exact
//!     `Fx` inputs), no earlier time overlaps by more than `tol` (the
//!     separation is a convex function of time for these shapes, so its
//!     minimum over `[0, t]` is found by ternary search, and 32 sampled
//!     times are checked too), and the normal is the unit vector from `a`
//!     to `b` at contact (along the centres; a face axis; towards a corner);
//!   - a `Miss`: the minimum separation over the whole step (ternary search,
//!     plus 64 samples) is at least `-tol`.
//!   - `Fx` against the f64 run of the same code, with a stated bound.
//! * **Bounds**: positions at ±32 768, displacements across the whole
//!   world, extreme (`MIN`/`MAX`, one-ulp) inputs: no panic, and exact
//!   answers where they are exact (so debug and release agree bit for bit).
//! * The other scalars (`I48F16`, `f64`, `f32`) on hand-computed cases.

use clockwork2d::geometry::*;
use clockwork2d::math::WORLD_LIMIT;
use clockwork2d::prelude::*;
use fixed::types::I48F16;
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;

mod common;
use common::fx_strategies::{positive, scaled};

/// Cases per property and shape pair: 16× proptest's default of 256. Each
/// case is one query plus about 300 f64 separation evaluations; the whole
/// file runs in well under a second. (The properties have also been run
/// with 200 000 cases each.) With this generator about 20% of the cases are
/// hits, 45% misses and 35% overlapping, for each shape pair.
const CASES: u32 = 4096;

/// One `Fx` ulp.
const ULP: f64 = 1.0 / 4_294_967_296.0;

/// How far from touching the shapes may be at the reported `t`, and how far
/// they may overlap before it, for a relative displacement `d` (in units).
///
/// Derivation (`toi.rs`): `t` is truncated to 32 fraction bits, so the
/// relative position it stands for, `t·d`, is off by less than `|d|` ulps;
/// the cast's direction `u = d / L` has one component rounded (< 1 ulp),
/// which moves the path by at most `s·ulp ≤ L` ulps ≤ `|d|` ulps; the cast
/// itself is within 4 ulps of the shape (circle arcs, see the ray tests)
/// or exact on a face. So `(2|d| + 4)` ulps; the test allows
/// `(2|d| + 16)` ulps.
fn tol(d: (f64, f64)) -> f64 {
    (2.0 * d.0.hypot(d.1) + 16.0) * ULP
}

// ---------------------------------------------------------------------------
// Helpers and f64 geometry.
// ---------------------------------------------------------------------------

fn p64(p: Vec2) -> (f64, f64) {
    p.to_f64()
}

fn raw(x: Fx) -> i128 {
    i128::from(x.to_bits())
}

/// `p + t·d` in f64 (exact to about 2⁻⁴⁰ for these magnitudes).
fn at(p: Vec2, d: Vec2, t: f64) -> (f64, f64) {
    let (px, py) = p64(p);
    let (dx, dy) = p64(d);
    (px + t * dx, py + t * dy)
}

fn sub(a: (f64, f64), b: (f64, f64)) -> (f64, f64) {
    (a.0 - b.0, a.1 - b.1)
}

/// Signed separation of two circles.
fn sep_cc(ca: (f64, f64), ra: f64, cb: (f64, f64), rb: f64) -> f64 {
    let d = sub(cb, ca);
    d.0.hypot(d.1) - (ra + rb)
}

/// Signed separation of two boxes: the larger of the per-axis gaps
/// (positive: apart; zero: touching; negative: overlapping).
fn sep_bb(ca: (f64, f64), ha: (f64, f64), cb: (f64, f64), hb: (f64, f64)) -> f64 {
    let d = sub(cb, ca);
    (d.0.abs() - ha.0 - hb.0).max(d.1.abs() - ha.1 - hb.1)
}

/// The point of box `(cb, hb)` closest to `p`.
fn closest_on_box(p: (f64, f64), cb: (f64, f64), hb: (f64, f64)) -> (f64, f64) {
    (
        p.0.clamp(cb.0 - hb.0, cb.0 + hb.0),
        p.1.clamp(cb.1 - hb.1, cb.1 + hb.1),
    )
}

/// Signed separation of a circle and a box: distance from the centre to the
/// box minus the radius (inside the box: minus the depth, minus the radius).
fn sep_cb(ca: (f64, f64), r: f64, cb: (f64, f64), hb: (f64, f64)) -> f64 {
    let q = sub(ca, cb);
    let o = (q.0.abs() - hb.0, q.1.abs() - hb.1);
    let outside = o.0.max(0.0).hypot(o.1.max(0.0));
    let inside = o.0.max(o.1).min(0.0);
    outside + inside - r
}

/// The minimum of a convex function on `[lo, hi]` (ternary search, 100
/// rounds: the bracket shrinks by (2/3)¹⁰⁰ ≈ 2.5e-18, then the ends are
/// checked too).
fn convex_min(f: impl Fn(f64) -> f64, lo: f64, hi: f64) -> f64 {
    let (mut a, mut b) = (lo, hi);
    for _ in 0..100 {
        let m1 = a + (b - a) / 3.0;
        let m2 = b - (b - a) / 3.0;
        if f(m1) <= f(m2) {
            b = m2;
        } else {
            a = m1;
        }
    }
    f(a).min(f(b)).min(f(lo)).min(f(hi))
}

/// The generic TOI checks, given the separation as a function of time, the
/// exact overlap oracle at `t = 0`, and how to check the normal.
fn check_toi(
    toi: Toi,
    overlap_at_0: bool,
    d: (f64, f64),
    sep: &dyn Fn(f64) -> f64,
    normal_ok: &dyn Fn(f64, (f64, f64)) -> Result<(), TestCaseError>,
) -> Result<(), TestCaseError> {
    let tol = tol(d);
    if overlap_at_0 {
        prop_assert_eq!(toi, Toi::Overlapping);
        return Ok(());
    }
    match toi {
        Toi::Overlapping => {
            return Err(TestCaseError::fail("Overlapping, but apart at t = 0"));
        }
        Toi::Hit { t, normal } => {
            let t = t.to_f64();
            prop_assert!((0.0..=1.0).contains(&t), "t = {t}");
            let s = sep(t);
            prop_assert!(s.abs() <= tol, "separation {s:e} at t = {t} (tol {tol:e})");
            let earliest = convex_min(sep, 0.0, t);
            prop_assert!(earliest >= -tol, "overlap {earliest:e} before t = {t}");
            for k in 0..32 {
                let tk = t * f64::from(k) / 32.0;
                prop_assert!(sep(tk) >= -tol, "sample {k} overlaps before t");
            }
            normal_ok(t, p64(normal))?;
        }
        Toi::Miss => {
            let least = convex_min(sep, 0.0, 1.0);
            prop_assert!(least >= -tol, "Miss, but the shapes overlap by {least:e}");
            for k in 0..=64 {
                prop_assert!(sep(f64::from(k) / 64.0) >= -tol);
            }
        }
    }
    Ok(())
}

// ---------------------------------------------------------------------------
// Exact overlap oracles at t = 0 (raw i128).
// ---------------------------------------------------------------------------

fn overlap_cc(a: &Circle, b: &Circle) -> bool {
    let (dx, dy) = (
        raw(b.center.x) - raw(a.center.x),
        raw(b.center.y) - raw(a.center.y),
    );
    let r = raw(a.radius) + raw(b.radius);
    dx * dx + dy * dy <= r * r
}

fn overlap_bb(a: &Aabb, b: &Aabb) -> bool {
    let (dx, dy) = (
        raw(b.center.x) - raw(a.center.x),
        raw(b.center.y) - raw(a.center.y),
    );
    dx.abs() <= raw(a.half_extents.x) + raw(b.half_extents.x)
        && dy.abs() <= raw(a.half_extents.y) + raw(b.half_extents.y)
}

fn overlap_cb(a: &Circle, b: &Aabb) -> bool {
    let ox = ((raw(a.center.x) - raw(b.center.x)).abs() - raw(b.half_extents.x)).max(0);
    let oy = ((raw(a.center.y) - raw(b.center.y)).abs() - raw(b.half_extents.y)).max(0);
    ox * ox + oy * oy <= raw(a.radius) * raw(a.radius)
}

// ---------------------------------------------------------------------------
// Per-pair checks.
// ---------------------------------------------------------------------------

fn rel(da: Vec2, db: Vec2) -> (f64, f64) {
    sub(p64(da), p64(db))
}

fn check_cc(a: &Circle, da: Vec2, b: &Circle, db: Vec2) -> Result<(), TestCaseError> {
    let toi = toi_circle_circle(a, da, b, db);
    let (ra, rb) = (a.radius.to_f64(), b.radius.to_f64());
    let sep = |t: f64| sep_cc(at(a.center, da, t), ra, at(b.center, db, t), rb);
    let d = rel(da, db);
    let tol = tol(d);
    let normal_ok = |t: f64, n: (f64, f64)| {
        let c = sub(at(b.center, db, t), at(a.center, da, t));
        let len = c.0.hypot(c.1);
        // Position error tol over a lever of R = ra + rb, plus
        // normalisation (about 2 ulps / R + 2 ulps).
        let tn = (2.0 * tol + 8.0 * ULP) / len + 8.0 * ULP;
        prop_assert!(
            (n.0 - c.0 / len).abs() <= tn && (n.1 - c.1 / len).abs() <= tn,
            "normal {n:?} vs centres {c:?}"
        );
        Ok(())
    };
    check_toi(toi, overlap_cc(a, b), d, &sep, &normal_ok)
}

fn check_bb(a: &Aabb, da: Vec2, b: &Aabb, db: Vec2) -> Result<(), TestCaseError> {
    let toi = toi_aabb_aabb(a, da, b, db);
    let (ha, hb) = (p64(a.half_extents), p64(b.half_extents));
    let sep = |t: f64| sep_bb(at(a.center, da, t), ha, at(b.center, db, t), hb);
    let d = rel(da, db);
    let tol = tol(d);
    let normal_ok = |t: f64, n: (f64, f64)| {
        let c = sub(at(b.center, db, t), at(a.center, da, t));
        let gap = (c.0.abs() - ha.0 - hb.0, c.1.abs() - ha.1 - hb.1);
        // Exactly a unit axis; on that axis the boxes are touching and b
        // lies on the normal's side of a (up to the tolerance); the other
        // axis overlaps or touches.
        let (axis_gap, other_gap, along) = if n.0 == 0.0 && n.1.abs() == 1.0 {
            (gap.1, gap.0, c.1 * n.1)
        } else if n.1 == 0.0 && n.0.abs() == 1.0 {
            (gap.0, gap.1, c.0 * n.0)
        } else {
            return Err(TestCaseError::fail(format!("normal {n:?} is not an axis")));
        };
        prop_assert!(axis_gap.abs() <= tol, "normal axis gap {axis_gap:e}");
        prop_assert!(other_gap <= tol, "other axis gap {other_gap:e}");
        prop_assert!(along >= -tol, "normal points from b to a");
        Ok(())
    };
    check_toi(toi, overlap_bb(a, b), d, &sep, &normal_ok)
}

fn check_cb(a: &Circle, da: Vec2, b: &Aabb, db: Vec2) -> Result<(), TestCaseError> {
    let toi = toi_circle_aabb(a, da, b, db);
    let (r, hb) = (a.radius.to_f64(), p64(b.half_extents));
    let sep = |t: f64| sep_cb(at(a.center, da, t), r, at(b.center, db, t), hb);
    let d = rel(da, db);
    let tol = tol(d);
    let normal_ok = |t: f64, n: (f64, f64)| {
        let ca = at(a.center, da, t);
        let q = closest_on_box(ca, at(b.center, db, t), hb);
        let c = sub(q, ca);
        let len = c.0.hypot(c.1);
        let tn = (2.0 * tol + 8.0 * ULP) / len + 8.0 * ULP;
        prop_assert!(
            (n.0 - c.0 / len).abs() <= tn && (n.1 - c.1 / len).abs() <= tn,
            "normal {n:?} vs towards the box {c:?}"
        );
        Ok(())
    };
    check_toi(toi, overlap_cb(a, b), d, &sep, &normal_ok)
}

// ---------------------------------------------------------------------------
// Strategies.
// ---------------------------------------------------------------------------

fn scaled_vec(exps: core::ops::Range<i32>) -> impl Strategy<Value = Vec2> {
    (scaled(exps.clone()), scaled(exps)).prop_map(|(x, y)| Vec2::new(x, y))
}

fn world_point() -> impl Strategy<Value = Vec2> {
    let c = || (-(1i64 << 47)..=(1i64 << 47)).prop_map(Fx::from_bits);
    (c(), c()).prop_map(|(x, y)| Vec2::new(x, y))
}

fn clamp_world(p: Vec2) -> Vec2 {
    let l = Fx::from_num(WORLD_LIMIT);
    p.clamp(Vec2::new(-l, -l), Vec2::new(l, l))
}

/// Two centres (the second within 2⁻⁴..2¹¹ of the first) and two
/// displacements whose difference is mostly aimed from `a` to `b` (closing
/// 0..2.5 times the gap, with a sideways jitter of up to 2 sizes), else
/// random; one case in six moves along a single axis (a zero component).
fn motion(size: f64) -> impl Strategy<Value = (Vec2, Vec2, Vec2, Vec2)> {
    (
        world_point(),
        scaled_vec(-4..12),
        scaled_vec(-8..10),
        0u8..6,
        0.0f64..2.5,
        (-2.0f64..2.0, -2.0f64..2.0),
        scaled_vec(-6..12),
    )
        .prop_map(move |(ca, off, db, mode, k, j, random)| {
            let cb = clamp_world(ca + off);
            let gap = p64(cb - ca);
            let d = match mode {
                0..=2 => Vec2::from_f64(k * gap.0 + j.0 * size, k * gap.1 + j.1 * size),
                3 | 4 => random,
                _ => {
                    if j.0 < 0.0 {
                        Vec2::new(fx(k * gap.0), Fx::ZERO)
                    } else {
                        Vec2::new(Fx::ZERO, fx(k * gap.1))
                    }
                }
            };
            (ca, cb, db + d, db)
        })
}

fn cc_case() -> impl Strategy<Value = (Circle, Vec2, Circle, Vec2)> {
    (positive(-6..9), positive(-6..9)).prop_flat_map(|(ra, rb)| {
        motion((ra + rb).to_f64())
            .prop_map(move |(ca, cb, da, db)| (Circle::new(ca, ra), da, Circle::new(cb, rb), db))
    })
}

fn bb_case() -> impl Strategy<Value = (Aabb, Vec2, Aabb, Vec2)> {
    (
        positive(-6..9),
        positive(-6..9),
        positive(-6..9),
        positive(-6..9),
    )
        .prop_flat_map(|(ax, ay, bx, by)| {
            motion((ax + bx).to_f64()).prop_map(move |(ca, cb, da, db)| {
                (
                    Aabb::new(ca, Vec2::new(ax, ay)),
                    da,
                    Aabb::new(cb, Vec2::new(bx, by)),
                    db,
                )
            })
        })
}

fn cb_case() -> impl Strategy<Value = (Circle, Vec2, Aabb, Vec2)> {
    (positive(-6..9), positive(-6..9), positive(-6..9)).prop_flat_map(|(r, bx, by)| {
        motion((r + bx).to_f64()).prop_map(move |(ca, cb, da, db)| {
            (Circle::new(ca, r), da, Aabb::new(cb, Vec2::new(bx, by)), db)
        })
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(CASES))]

    #[test]
    fn prop_toi_circle_circle((a, da, b, db) in cc_case()) {
        check_cc(&a, da, &b, db)?;
    }

    #[test]
    fn prop_toi_aabb_aabb((a, da, b, db) in bb_case()) {
        check_bb(&a, da, &b, db)?;
    }

    #[test]
    fn prop_toi_circle_aabb((a, da, b, db) in cb_case()) {
        check_cb(&a, da, &b, db)?;
    }

    /// `Fx` against the f64 run of the same code on the same (exactly
    /// converted) inputs, circle–circle, for contacts that are not
    /// grazing (the f64 normal's component along the motion is at least
    /// 0.5: the motion is within 60° of head-on, so `t` is at most twice as
    /// sensitive as the contact position). The `Fx` `t` is then within
    /// `2·tol(d)/|d|` of the f64 one: both touch within `tol` and the
    /// separation changes at least `|d|/2` per unit of `t`.
    #[test]
    fn prop_toi_fx_vs_f64((a, da, b, db) in cc_case()) {
        let c64 = |c: &Circle| Circle::<f64>::new(c.center.cast(), c.radius.to_f64());
        let fx_toi = toi_circle_circle(&a, da, &b, db);
        let f_toi = toi_circle_circle(&c64(&a), da.cast(), &c64(&b), db.cast());
        if let (Toi::Hit { t, .. }, Toi::Hit { t: t64, normal: n64 }) = (fx_toi, f_toi) {
            let d = rel(da, db);
            let len = d.0.hypot(d.1);
            let head_on = (n64.x * d.0 + n64.y * d.1) / len;
            if head_on >= 0.5 {
                let bound = 2.0 * tol(d) / len + ULP;
                prop_assert!((t.to_f64() - t64).abs() <= bound, "t {t} vs {t64}");
            }
        }
    }
}

// ---------------------------------------------------------------------------
// Hand-computed cases.
// ---------------------------------------------------------------------------

fn hit(toi: Toi) -> (f64, (f64, f64)) {
    match toi {
        Toi::Hit { t, normal } => (t.to_f64(), p64(normal)),
        other => panic!("expected a hit, got {other:?}"),
    }
}

#[test]
fn circles_head_on_and_oblique() {
    let a = Circle::new(vec2(0.0, 0.0), fx(1.0));
    let b = Circle::new(vec2(5.0, 0.0), fx(1.0));
    assert_eq!(
        toi_circle_circle(&a, vec2(2.0, 0.0), &b, vec2(-2.0, 0.0)),
        Toi::Hit {
            t: fx(0.75),
            normal: vec2(1.0, 0.0)
        }
    );
    // b at (5, 1.5), a moving by (10, 0): |(5 − 10t, 1.5)| = 2 at
    // t = (5 − √1.75)/10, normal (√1.75, 1.5)/2.
    let b = Circle::new(vec2(5.0, 1.5), fx(1.0));
    let (t, n) = hit(toi_circle_circle(&a, vec2(10.0, 0.0), &b, vec2(0.0, 0.0)));
    assert!((t - (5.0 - 1.75f64.sqrt()) / 10.0).abs() < 1e-9, "{t}");
    assert!((n.0 - 1.75f64.sqrt() / 2.0).abs() < 1e-9 && (n.1 - 0.75).abs() < 1e-9);
    check_cc(&a, vec2(10.0, 0.0), &b, vec2(0.0, 0.0)).unwrap();
}

#[test]
fn circles_grazing_and_just_missing() {
    let a = Circle::new(vec2(0.0, 0.0), fx(1.0));
    // Tangent path: touches at t = 1/2 exactly, normal +Y.
    let b = Circle::new(vec2(5.0, 2.0), fx(1.0));
    assert_eq!(
        toi_circle_circle(&a, vec2(10.0, 0.0), &b, Vec2::ZERO),
        Toi::Hit {
            t: fx(0.5),
            normal: vec2(0.0, 1.0)
        }
    );
    // One ulp further: never touches.
    let b = Circle::new(Vec2::new(fx(5.0), fx(2.0) + Fx::DELTA), fx(1.0));
    assert_eq!(
        toi_circle_circle(&a, vec2(10.0, 0.0), &b, Vec2::ZERO),
        Toi::Miss
    );
}

#[test]
fn circles_step_limits_and_motion() {
    let a = Circle::new(vec2(0.0, 0.0), fx(1.0));
    let b = Circle::new(vec2(5.0, 0.0), fx(1.0));
    // Gap 3 closed exactly at the end of the step: t = 1.
    assert_eq!(
        toi_circle_circle(&a, vec2(3.0, 0.0), &b, Vec2::ZERO),
        Toi::Hit {
            t: fx(1.0),
            normal: vec2(1.0, 0.0)
        }
    );
    // One ulp short: a miss.
    let short = Vec2::new(fx(3.0) - Fx::DELTA, fx(0.0));
    assert_eq!(toi_circle_circle(&a, short, &b, Vec2::ZERO), Toi::Miss);
    // Moving apart, moving together in parallel (zero relative motion):
    // a miss, and no division by zero.
    assert_eq!(
        toi_circle_circle(&a, vec2(-1.0, 0.0), &b, vec2(1.0, 0.0)),
        Toi::Miss
    );
    assert_eq!(
        toi_circle_circle(&a, vec2(7.0, 3.0), &b, vec2(7.0, 3.0)),
        Toi::Miss
    );
    assert_eq!(toi_circle_circle(&a, Vec2::ZERO, &b, Vec2::ZERO), Toi::Miss);
    // Chased from behind: b moves away slower than a follows.
    assert_eq!(
        toi_circle_circle(&a, vec2(5.0, 0.0), &b, vec2(2.0, 0.0)),
        Toi::Hit {
            t: fx(1.0),
            normal: vec2(1.0, 0.0)
        }
    );
    // Touching or overlapping at t = 0: Overlapping, whatever the motion.
    let touching = Circle::new(vec2(2.0, 0.0), fx(1.0));
    for d in [Vec2::ZERO, vec2(-5.0, 0.0), vec2(5.0, 0.0)] {
        assert_eq!(
            toi_circle_circle(&a, d, &touching, Vec2::ZERO),
            Toi::Overlapping
        );
    }
}

#[test]
fn boxes_landing_sliding_and_corner_tie() {
    let a = Aabb::new(vec2(0.0, 0.0), vec2(1.0, 1.0));
    let ground = Aabb::new(vec2(0.0, -5.0), vec2(2.0, 1.0));
    assert_eq!(
        toi_aabb_aabb(&a, vec2(0.0, -6.0), &ground, Vec2::ZERO),
        Toi::Hit {
            t: fx(0.5),
            normal: vec2(0.0, -1.0)
        }
    );
    // y projections exactly touching (closed), x gap 2, moving +x by 4:
    // touches at t = 1/2 through the x faces.
    let a = Aabb::new(vec2(-5.0, 2.0), vec2(1.0, 1.0));
    let b = Aabb::new(vec2(0.0, 0.0), vec2(2.0, 1.0));
    assert_eq!(
        toi_aabb_aabb(&a, vec2(4.0, 0.0), &b, Vec2::ZERO),
        Toi::Hit {
            t: fx(0.5),
            normal: vec2(1.0, 0.0)
        }
    );
    // y projections one ulp apart: a miss.
    let a2 = Aabb::new(Vec2::new(fx(-5.0), fx(2.0) + Fx::DELTA), vec2(1.0, 1.0));
    assert_eq!(
        toi_aabb_aabb(&a2, vec2(4.0, 0.0), &b, Vec2::ZERO),
        Toi::Miss
    );
    // Corner to corner: both axes close at t = 1/2: the y axis is
    // reported (b is above a: +Y).
    let a = Aabb::new(vec2(-3.0, -3.0), vec2(1.0, 1.0));
    let b = Aabb::new(vec2(0.0, 0.0), vec2(1.0, 1.0));
    assert_eq!(
        toi_aabb_aabb(&a, vec2(2.0, 2.0), &b, Vec2::ZERO),
        Toi::Hit {
            t: fx(0.5),
            normal: vec2(0.0, 1.0)
        }
    );
    // Same, b moving instead of a.
    assert_eq!(
        toi_aabb_aabb(&a, Vec2::ZERO, &b, vec2(-2.0, -2.0)),
        Toi::Hit {
            t: fx(0.5),
            normal: vec2(0.0, 1.0)
        }
    );
}

#[test]
fn boxes_axis_parallel_zero_components() {
    let b = Aabb::new(vec2(0.0, 0.0), vec2(1.0, 1.0));
    // Moving along y only, x projections overlapping: a hit.
    let a = Aabb::new(vec2(1.5, 5.0), vec2(1.0, 1.0));
    assert_eq!(
        toi_aabb_aabb(&a, vec2(0.0, -4.0), &b, Vec2::ZERO),
        Toi::Hit {
            t: fx(0.75),
            normal: vec2(0.0, -1.0)
        }
    );
    // x projections apart: a miss, never divided by the zero x motion.
    let a = Aabb::new(vec2(3.5, 5.0), vec2(1.0, 1.0));
    assert_eq!(
        toi_aabb_aabb(&a, vec2(0.0, -40.0), &b, Vec2::ZERO),
        Toi::Miss
    );
    // Overlapping stays overlapping.
    let a = Aabb::new(vec2(1.5, 1.5), vec2(1.0, 1.0));
    assert_eq!(
        toi_aabb_aabb(&a, vec2(0.0, -4.0), &b, Vec2::ZERO),
        Toi::Overlapping
    );
}

#[test]
fn circle_box_faces_corners_and_boundary() {
    let b = Aabb::new(vec2(0.0, 0.0), vec2(1.0, 1.0));
    // Face.
    let a = Circle::new(vec2(4.0, 0.5), fx(1.0));
    assert_eq!(
        toi_circle_aabb(&a, vec2(-4.0, 0.0), &b, Vec2::ZERO),
        Toi::Hit {
            t: fx(0.5),
            normal: vec2(-1.0, 0.0)
        }
    );
    // Face/corner boundary: the centre moves down along x = 1 (the face's
    // end): touches when the centre is at y = 2, t = 3/8, face normal.
    let a = Circle::new(vec2(1.0, 5.0), fx(1.0));
    assert_eq!(
        toi_circle_aabb(&a, vec2(0.0, -8.0), &b, Vec2::ZERO),
        Toi::Hit {
            t: fx(0.375),
            normal: vec2(0.0, -1.0)
        }
    );
    // Corner: along the diagonal onto (1, 1): touches when the centre is 1
    // from the corner, t = (3 − √½)/4; the normal points at the corner.
    let a = Circle::new(vec2(4.0, 4.0), fx(1.0));
    let (t, n) = hit(toi_circle_aabb(&a, vec2(-4.0, -4.0), &b, Vec2::ZERO));
    assert!((t - (3.0 - 0.5f64.sqrt()) / 4.0).abs() < 1e-9);
    assert!((n.0 + 0.5f64.sqrt()).abs() < 1e-9 && (n.1 + 0.5f64.sqrt()).abs() < 1e-9);
    // Passing the corner at height 1.9: the corner arc (not the grown
    // box's corner) is hit, at x = 1 + √(1 − 0.81).
    let a = Circle::new(vec2(3.0, 1.9), fx(1.0));
    let (t, n) = hit(toi_circle_aabb(&a, vec2(-6.0, 0.0), &b, Vec2::ZERO));
    let x = 1.0 + 0.19f64.sqrt();
    assert!((t - (3.0 - x) / 6.0).abs() < 1e-9, "{t}");
    assert!(
        (n.0 + 0.19f64.sqrt()).abs() < 1e-9 && (n.1 + 0.9).abs() < 1e-9,
        "{n:?}"
    );
    check_cb(&a, vec2(-6.0, 0.0), &b, Vec2::ZERO).unwrap();
    // Passing above the corner arc (height 2.5 > 2): a miss, although the
    // path crosses the grown box's corner square.
    let a = Circle::new(vec2(3.0, 2.5), fx(1.0));
    assert_eq!(
        toi_circle_aabb(&a, vec2(-6.0, 0.5), &b, Vec2::ZERO),
        Toi::Miss
    );
    assert_eq!(
        toi_circle_aabb(
            &Circle::new(vec2(3.0, 2.0) + Vec2::new(Fx::ZERO, Fx::DELTA), fx(1.0)),
            vec2(-6.0, 0.0),
            &b,
            Vec2::ZERO
        ),
        Toi::Miss
    );
}

#[test]
fn circle_box_starting_in_the_corner_square() {
    // The centre starts inside the grown box (within 1 of both faces'
    // lines) but 0.9·√2 > 1 from the corner: not overlapping. Moving
    // towards the corner by (−0.5, −0.5): touches when 1 from it, after
    // travelling 0.9 − √½ per axis: t = (0.9 − √½)/0.5.
    let b = Aabb::new(vec2(0.0, 0.0), vec2(1.0, 1.0));
    let a = Circle::new(vec2(1.9, 1.9), fx(1.0));
    let (t, n) = hit(toi_circle_aabb(&a, vec2(-0.5, -0.5), &b, Vec2::ZERO));
    assert!((t - (0.9 - 0.5f64.sqrt()) / 0.5).abs() < 1e-9, "{t}");
    assert!((n.0 + 0.5f64.sqrt()).abs() < 1e-9 && (n.1 + 0.5f64.sqrt()).abs() < 1e-9);
    // Moving away from the corner from there: a miss.
    assert_eq!(
        toi_circle_aabb(&a, vec2(0.5, 0.1), &b, Vec2::ZERO),
        Toi::Miss
    );
}

#[test]
fn bullet_through_thin_wall() {
    // A 0.1-radius bullet moving 20 units in one step against a wall 0.1
    // thick: sampling the step's ends would tunnel; the TOI does not.
    let bullet = Circle::new(vec2(-10.0, 0.3), fx(0.1));
    let wall = Aabb::new(vec2(0.0, 0.0), vec2(0.05, 5.0));
    let (t, n) = hit(toi_circle_aabb(&bullet, vec2(20.0, 0.0), &wall, Vec2::ZERO));
    assert!((t - (10.0 - 0.15) / 20.0).abs() < 1e-9);
    assert_eq!(n, (1.0, 0.0));
    let box_bullet = Aabb::new(vec2(-10.0, 0.3), vec2(0.1, 0.1));
    assert_eq!(
        toi_aabb_aabb(&box_bullet, vec2(20.0, 0.0), &wall, Vec2::ZERO),
        Toi::Hit {
            t: fx(0.4925),
            normal: vec2(1.0, 0.0)
        }
    );
}

// ---------------------------------------------------------------------------
// Bounds.
// ---------------------------------------------------------------------------

#[test]
fn bounds_across_the_world() {
    let l = 32_768.0;
    // From one edge of the world to the other in one step (65 534 units).
    let a = Circle::new(vec2(-l + 1.0, 0.0), fx(1.0));
    let b = Circle::new(vec2(l - 1.0, 0.0), fx(1.0));
    // The direction is exactly +x, so the cast is exact: s = 65 532, and
    // t = 65 532 / 65 534 truncated to 32 fraction bits.
    let Toi::Hit { t, normal } = toi_circle_circle(&a, vec2(2.0 * l - 2.0, 0.0), &b, Vec2::ZERO)
    else {
        panic!("expected a hit");
    };
    assert_eq!(raw(t), (65_532i128 << 32) / 65_534);
    assert_eq!(normal, vec2(1.0, 0.0));
    let a = Aabb::new(vec2(-l + 1.0, -l + 1.0), vec2(1.0, 1.0));
    let b = Aabb::new(vec2(l - 1.0, l - 1.0), vec2(1.0, 1.0));
    // Diagonal, corner to corner: exact tie, y axis.
    let (t, n) = hit(toi_aabb_aabb(&a, vec2(2.0 * l, 2.0 * l), &b, Vec2::ZERO));
    assert!((t - (2.0 * l - 4.0) / (2.0 * l)).abs() <= ULP);
    assert_eq!(n, (0.0, 1.0));
    check_bb(&a, vec2(2.0 * l, 2.0 * l), &b, Vec2::ZERO).unwrap();
    let c = Circle::new(vec2(-l + 1.0, -l + 1.0), fx(1.0));
    check_cb(&c, vec2(2.0 * l, 2.0 * l - 0.5), &b, Vec2::ZERO).unwrap();
    check_cb(&c, vec2(2.0 * l - 3.0, 2.0 * l), &b, vec2(-1.0, 0.0)).unwrap();
}

/// Extreme inputs (`MIN`/`MAX`, one ulp, far outside the world): results
/// saturate but never panic (debug builds check every overflow), and the
/// same call gives the same answer twice; a hit's `t` is in `[0, 1]`.
#[test]
fn bounds_extreme_inputs_do_not_panic() {
    let vals = [
        Fx::MIN,
        fx(-32_768.0),
        -Fx::DELTA,
        Fx::ZERO,
        Fx::DELTA,
        fx(0.75),
        fx(32_768.0),
        Fx::MAX,
    ];
    let sizes = [Fx::ZERO, Fx::DELTA, Fx::ONE, fx(32_768.0), Fx::MAX];
    let mut count = 0u32;
    for &x in &vals {
        for &y in &vals {
            for &dx in &vals {
                for &dy in &vals {
                    for &s in &sizes {
                        let ca = Vec2::new(x, y);
                        let cb = Vec2::new(dy, x);
                        let da = Vec2::new(dx, dy);
                        let db = Vec2::new(y, dx);
                        let (c1, c2) = (Circle::new(ca, s), Circle::new(cb, s));
                        let (b1, b2) = (
                            Aabb::new(ca, Vec2::new(s, s)),
                            Aabb::new(cb, Vec2::new(s, Fx::ONE)),
                        );
                        let r = [
                            toi_circle_circle(&c1, da, &c2, db),
                            toi_aabb_aabb(&b1, da, &b2, db),
                            toi_circle_aabb(&c1, da, &b2, db),
                        ];
                        let again = [
                            toi_circle_circle(&c1, da, &c2, db),
                            toi_aabb_aabb(&b1, da, &b2, db),
                            toi_circle_aabb(&c1, da, &b2, db),
                        ];
                        assert_eq!(r, again);
                        for toi in r {
                            if let Toi::Hit { t, .. } = toi {
                                assert!(t >= Fx::ZERO && t <= Fx::ONE);
                            }
                        }
                        count += 1;
                    }
                }
            }
        }
    }
    assert_eq!(count, 8 * 8 * 8 * 8 * 5);
}

/// Random cases at the world's edges with displacements up to the world's
/// width: every property holds there too.
#[test]
fn bounds_random_edge_cases() {
    let mut runner = proptest::test_runner::TestRunner::new(ProptestConfig::with_cases(CASES));
    let edge = || prop_oneof![Just(-32_768.0f64), Just(32_768.0), -32_768.0f64..32_768.0];
    let case = (
        edge(),
        edge(),
        edge(),
        edge(),
        positive(-4..10),
        positive(-4..10),
        0.0f64..2.0,
    );
    runner
        .run(&case, |(ax, ay, bx, by, s1, s2, k)| {
            let (ca, cb) = (vec2(ax, ay), vec2(bx, by));
            let d = Vec2::from_f64(k * (bx - ax), k * (by - ay));
            check_cc(&Circle::new(ca, s1), d, &Circle::new(cb, s2), Vec2::ZERO)?;
            check_bb(
                &Aabb::new(ca, Vec2::new(s1, s2)),
                d,
                &Aabb::new(cb, Vec2::new(s2, s1)),
                Vec2::ZERO,
            )?;
            check_cb(
                &Circle::new(ca, s1),
                d,
                &Aabb::new(cb, Vec2::new(s2, s1)),
                Vec2::ZERO,
            )
        })
        .unwrap();
}

// ---------------------------------------------------------------------------
// The other scalars.
// ---------------------------------------------------------------------------

fn generic_cases<S: Scalar>(tol: f64) {
    let v = |x: f64, y: f64| Vec2::<S>::from_f64(x, y);
    let s = S::from_f64;
    let expect = |toi: Toi<S>, t: f64, n: (f64, f64)| match toi {
        Toi::Hit { t: got, normal } => {
            let (nx, ny) = normal.to_f64();
            assert!(
                (got.to_f64() - t).abs() <= tol
                    && (nx - n.0).abs() <= tol
                    && (ny - n.1).abs() <= tol,
                "{}: {toi:?}, expected t = {t} n = {n:?}",
                S::NAME
            );
        }
        other => panic!("{}: expected a hit, got {other:?}", S::NAME),
    };
    let a = Circle::new(v(0.0, 0.0), s(1.0));
    expect(
        toi_circle_circle(
            &a,
            v(2.0, 0.0),
            &Circle::new(v(5.0, 0.0), s(1.0)),
            v(-2.0, 0.0),
        ),
        0.75,
        (1.0, 0.0),
    );
    let b = Aabb::new(v(0.0, 0.0), v(1.0, 1.0));
    expect(
        toi_aabb_aabb(
            &Aabb::new(v(-3.0, -3.0), v(1.0, 1.0)),
            v(2.0, 2.0),
            &b,
            v(0.0, 0.0),
        ),
        0.5,
        (0.0, 1.0),
    );
    expect(
        toi_circle_aabb(
            &Circle::new(v(4.0, 0.5), s(1.0)),
            v(-4.0, 0.0),
            &b,
            v(0.0, 0.0),
        ),
        0.5,
        (-1.0, 0.0),
    );
    let h = 0.5f64.sqrt();
    expect(
        toi_circle_aabb(
            &Circle::new(v(4.0, 4.0), s(1.0)),
            v(-4.0, -4.0),
            &b,
            v(0.0, 0.0),
        ),
        (3.0 - h) / 4.0,
        (-h, -h),
    );
    assert_eq!(
        toi_circle_circle(
            &a,
            v(0.0, 0.0),
            &Circle::new(v(1.5, 0.0), s(1.0)),
            v(0.0, 0.0)
        ),
        Toi::Overlapping
    );
    assert_eq!(
        toi_aabb_aabb(
            &Aabb::new(v(3.5, 0.0), v(1.0, 1.0)),
            v(0.0, 5.0),
            &b,
            v(0.0, 0.0)
        ),
        Toi::Miss
    );
}

#[test]
fn other_scalars() {
    generic_cases::<I48F16>(8.0 / 65_536.0);
    generic_cases::<f64>(1e-12);
    generic_cases::<f32>(1e-5);
}
