//! Closest point on a segment and the three contact tests.
//!
//! Three kinds of evidence:
//!
//! * **Exact integer oracles.** Test inputs are quantised to 1/1024, so
//!   every quantity the functions form is an integer in some power-of-two
//!   unit, and the ideal fixed-point answers (floor of a root, truncated
//!   quotient, rounded parameter) can be computed independently with `i128`
//!   / `u128` integer arithmetic. Where the implementation's documented bound
//!   is "exact" (or "the floor"), the test asserts bit equality.
//! * **Properties** (symmetry, unit normals, "moving `b` by
//!   `−separation·normal` makes the shapes touch", the closest point beats
//!   every sampled point) with tolerances derived in comments.
//! * **The `f64` reference** run of the same generic function, with the bound
//!   derived from the few rounded operations.
//!
//! Plus hand-computed cases, degenerate cases and inputs at (and beyond) the
//! documented world bounds; these run in debug and release, so they show
//! that the overflow behaviour is identical.
//!
//! Proptest case counts are set per block below (`CASES` = 2048 for every
//! property; the default would be 256).
#![allow(clippy::float_arithmetic, clippy::cast_precision_loss)]

use clockwork2d::geometry::*;
use clockwork2d::math::WORLD_LIMIT;
use clockwork2d::prelude::*;
use fixed::types::I48F16;
use proptest::prelude::*;

/// One `Fx` ulp, 2⁻³².
const ULP: f64 = 1.0 / 4_294_967_296.0;
/// Inputs are integers in units of 1/1024 (exact in `Fx`, `I48F16`, `f64`).
const UNIT: i64 = 1024;
/// `WORLD_LIMIT` in input units: 2¹⁵ · 2¹⁰ = 2²⁵.
const WORLD: i64 = (WORLD_LIMIT as i64) * UNIT;
/// Cases per proptest property.
const CASES: u32 = 2048;

// ---------------------------------------------------------------- helpers

/// `units / 1024` as `Fx`, exactly (raw bits `units · 2²²`).
fn q(units: i64) -> Fx {
    Fx::from_bits(units << 22)
}

fn v(x: i64, y: i64) -> Vec2 {
    Vec2::new(q(x), q(y))
}

fn f(x: Fx) -> f64 {
    x.to_num()
}

fn bits(x: Fx) -> i128 {
    i128::from(x.to_bits())
}

fn circle64(c: &Circle) -> Circle<f64> {
    Circle::new(c.center.cast(), c.radius.to_f64())
}

fn aabb64(b: &Aabb) -> Aabb<f64> {
    Aabb::new(b.center.cast(), b.half_extents.cast())
}

/// The raw bits of an `Fx` from an `i128`, asserting that it fits.
fn fx_from_bits(b: i128) -> Fx {
    Fx::from_bits(i64::try_from(b).expect("oracle value fits Fx"))
}

// ---------------------------------------------------------------- oracles

/// Ideal `Fx` distance and normal for an offset `d`: `(floor(|d|), trunc(d_i /
/// floor(|d|)))` on the 2⁻³² grid, in exact integer arithmetic (|d| bits ≤
/// 2⁴⁹ within the bounds, so `d²` sums stay below 2⁹⁹). `None` for `d = 0`.
fn oracle_normalize(dx: i128, dy: i128) -> Option<(i128, i128, i128)> {
    let l2 = u128::try_from(dx * dx + dy * dy).expect("a sum of squares");
    if l2 == 0 {
        return None;
    }
    let dist = i128::try_from(l2.isqrt()).expect("below 2^50");
    // i128 division truncates toward zero, as the fixed crate's does.
    Some((dist, (dx << 32) / dist, (dy << 32) / dist))
}

/// Exact oracle for `contact_circle_circle` on `Fx`.
fn oracle_circle_circle(a: &Circle, b: &Circle) -> Contact {
    let dx = bits(b.center.x) - bits(a.center.x);
    let dy = bits(b.center.y) - bits(a.center.y);
    let radii = bits(a.radius) + bits(b.radius);
    match oracle_normalize(dx, dy) {
        Some((dist, nx, ny)) => Contact {
            normal: Vec2::new(fx_from_bits(nx), fx_from_bits(ny)),
            separation: fx_from_bits(dist - radii),
        },
        None => Contact {
            normal: Vec2::Y,
            separation: fx_from_bits(-radii),
        },
    }
}

/// Exact oracle for `contact_circle_aabb` on `Fx` (the documented maths,
/// redone in integers).
fn oracle_circle_aabb(a: &Circle, b: &Aabb) -> Contact {
    let (hx, hy) = (bits(b.half_extents.x), bits(b.half_extents.y));
    let qx = bits(a.center.x) - bits(b.center.x);
    let qy = bits(a.center.y) - bits(b.center.y);
    let vx = qx - qx.clamp(-hx, hx);
    let vy = qy - qy.clamp(-hy, hy);
    let r = bits(a.radius);
    if let Some((dist, nx, ny)) = oracle_normalize(vx, vy) {
        return Contact {
            normal: Vec2::new(fx_from_bits(-nx), fx_from_bits(-ny)),
            separation: fx_from_bits(dist - r),
        };
    }
    let (ex, ey) = (hx - qx.abs(), hy - qy.abs());
    let into = |o: i128| if o > 0 { -1 } else { 1 };
    if ex < ey {
        Contact {
            normal: Vec2::new(Fx::from_num(into(qx)), Fx::ZERO),
            separation: fx_from_bits(-(ex + r)),
        }
    } else {
        Contact {
            normal: Vec2::new(Fx::ZERO, Fx::from_num(into(qy))),
            separation: fx_from_bits(-(ey + r)),
        }
    }
}

/// Exact oracle for `closest_point_on_segment` on inputs in 1/1024 units:
/// returns the expected `t` bits (rounded to nearest, ties up) and, per
/// component, the exact point as a rational `(numerator, denominator)` in
/// units of 2⁻³², or `None` for the clamped cases (point = a or b exactly).
///
/// Magnitudes within the bounds: coordinates ≤ 2²⁵ units, `den = d·d ≤ 2⁵³`,
/// `num << 32 ≤ 2⁸⁵`, `d_i · num · 2²² ≤ 2¹⁰¹`: all fit `i128`.
fn oracle_segment(
    a: (i64, i64),
    b: (i64, i64),
    p: (i64, i64),
) -> (i128, Option<[(i128, i128); 2]>) {
    let d = (i128::from(b.0 - a.0), i128::from(b.1 - a.1));
    let w = (i128::from(p.0 - a.0), i128::from(p.1 - a.1));
    let den = d.0 * d.0 + d.1 * d.1;
    let num = w.0 * d.0 + w.1 * d.1;
    if den == 0 || num <= 0 {
        return (0, None);
    }
    if num >= den {
        return (1 << 32, None);
    }
    let scaled = num << 32;
    let t = scaled / den + i128::from(2 * (scaled % den) >= den);
    // point_i = a_i + d_i·num/den, with a_i in 2⁻³² units = a_i·2²².
    let comp = |a_i: i64, d_i: i128| {
        (
            i128::from(a_i) * (1 << 22) * den + d_i * num * (1 << 22),
            den,
        )
    };
    (t, Some([comp(a.0, d.0), comp(a.1, d.1)]))
}

// ---------------------------------------------------------------- strategies

/// A coordinate in ±2¹⁴ (so that centre + offset stays within ±2¹⁵), mixing
/// world-scale values with small ones near the origin (where zero offsets,
/// touching and coincident shapes actually occur).
fn coord() -> impl Strategy<Value = i64> {
    prop_oneof![-WORLD / 2..=WORLD / 2, -8 * UNIT..=8 * UNIT]
}

/// An offset in ±2¹⁴: world scale, body scale, sub-unit, or exactly zero.
fn offset() -> impl Strategy<Value = i64> {
    prop_oneof![
        -WORLD / 2..=WORLD / 2,
        -16 * UNIT..=16 * UNIT,
        -16i64..=16,
        Just(0i64),
    ]
}

/// A radius or half extent in (0, 4096].
fn extent() -> impl Strategy<Value = i64> {
    prop_oneof![1..=4096 * UNIT, 1..=4 * UNIT]
}

fn circle_pair() -> impl Strategy<Value = (Circle, Circle)> {
    (coord(), coord(), offset(), offset(), extent(), extent()).prop_map(|(x, y, dx, dy, ra, rb)| {
        (
            Circle::new(v(x, y), q(ra)),
            Circle::new(v(x + dx, y + dy), q(rb)),
        )
    })
}

fn aabb_pair() -> impl Strategy<Value = (Aabb, Aabb)> {
    (
        (coord(), coord(), offset(), offset()),
        (extent(), extent(), extent(), extent()),
    )
        .prop_map(|((x, y, dx, dy), (ax, ay, bx, by))| {
            (
                Aabb::new(v(x, y), v(ax, ay)),
                Aabb::new(v(x + dx, y + dy), v(bx, by)),
            )
        })
}

fn circle_aabb_pair() -> impl Strategy<Value = (Circle, Aabb)> {
    (
        (coord(), coord(), offset(), offset()),
        (extent(), extent(), extent()),
    )
        .prop_map(|((x, y, dx, dy), (r, hx, hy))| {
            (
                Circle::new(v(x + dx, y + dy), q(r)),
                Aabb::new(v(x, y), v(hx, hy)),
            )
        })
}

/// Segment `a → b` and query point `p`, in input units, all within ±2¹⁵.
#[allow(clippy::type_complexity)]
fn segment_query() -> impl Strategy<Value = ((i64, i64), (i64, i64), (i64, i64))> {
    (coord(), coord(), offset(), offset(), offset(), offset())
        .prop_map(|(x, y, dx, dy, px, py)| ((x, y), (x + dx, y + dy), (x + px, y + py)))
}

fn vq(p: (i64, i64)) -> Vec2 {
    v(p.0, p.1)
}

fn length64(v: Vec2<f64>) -> f64 {
    v.x.hypot(v.y)
}

// ---------------------------------------------------------------- closest point

proptest! {
    // 2048 cases per property.
    #![proptest_config(ProptestConfig::with_cases(CASES))]

    /// `t` is exactly the rounded-to-nearest quotient (documented: ½ ulp);
    /// the point is within the documented 2 ulps + |d|·2⁻⁶⁴ per component of
    /// the exact rational point (|d| ≤ 2¹⁷ here: 2 + 2⁻¹⁵ ulps, tested as
    /// 2 + 2⁻¹⁴), and exactly `a`/`b` in the clamped cases.
    #[test]
    fn closest_point_matches_exact_oracle((a, b, p) in segment_query()) {
        let c = closest_point_on_segment(vq(a), vq(b), vq(p));
        let (t, exact) = oracle_segment(a, b, p);
        prop_assert_eq!(bits(c.t), t);
        match exact {
            None => prop_assert_eq!(c.point, if t == 0 { vq(a) } else { vq(b) }),
            Some(comps) => {
                for (got, (n, den)) in [c.point.x, c.point.y].into_iter().zip(comps) {
                    // |got − n/den| < (2 + 2⁻¹⁴) ulps ⇔ |got·den − n| < that·den.
                    prop_assert!((bits(got) * den - n).abs() < 2 * den + den / 16384,
                        "component {got} vs {}", n as f64 / den as f64 * ULP);
                }
            }
        }
    }

    /// `t ∈ [0, 1]`, and the point is no farther from `p` than any of 65
    /// sampled points of the segment (the ends and 63 interior points), up to
    /// the point's own error: each component within 2 ulps ⇒ within 2√2 ulps
    /// of the exact closest point, which is no farther than any sample; the
    /// f64 distances add < 2⁻⁵²·2¹⁸ = 0.25 ulp. Tolerance 3.5 ulps.
    #[test]
    fn closest_point_beats_samples((a, b, p) in segment_query()) {
        let c = closest_point_on_segment(vq(a), vq(b), vq(p));
        prop_assert!(c.t >= Fx::ZERO && c.t <= Fx::ONE);
        let (a64, b64, p64) = (vq(a).cast::<f64>(), vq(b).cast::<f64>(), vq(p).cast::<f64>());
        let got = length64(c.point.cast::<f64>() - p64);
        for i in 0..=64 {
            // a + (b − a)·i/64 is exact in f64 (multiples of 2⁻¹⁶ below 2¹⁷).
            let s = a64 + (b64 - a64) * (f64::from(i) / 64.0);
            prop_assert!(got <= length64(s - p64) + 3.5 * ULP, "sample {i} is closer");
        }
    }

    /// `Fx` against the `f64` run of the same function. For in-bounds inputs
    /// on the 1/1024 grid the f64 `w·d` and `d·d` are exact (integers below
    /// 2⁵³ in 2⁻²⁰ units), so f64's `t` is within 2⁻⁵³ of exact and its point
    /// within (|d| + 2|point|)·2⁻⁵³ < 2⁻³⁵ of exact; `Fx` is within 2⁻³³ (t)
    /// and 2 ulps (point). Bounds: t 2⁻³³ + 2⁻⁵², point 2.5 ulps.
    #[test]
    fn closest_point_agrees_with_f64((a, b, p) in segment_query()) {
        let c = closest_point_on_segment(vq(a), vq(b), vq(p));
        let r = closest_point_on_segment(vq(a).cast::<f64>(), vq(b).cast::<f64>(), vq(p).cast::<f64>());
        prop_assert!((f(c.t) - r.t).abs() <= ULP / 2.0 + f64::EPSILON);
        prop_assert!((f(c.point.x) - r.point.x).abs() <= 2.5 * ULP);
        prop_assert!((f(c.point.y) - r.point.y).abs() <= 2.5 * ULP);
    }

    /// A zero-length segment is the point `a` with `t = 0`, wherever `p` is.
    #[test]
    fn closest_point_zero_length(x in coord(), y in coord(), px in offset(), py in offset()) {
        let c = closest_point_on_segment(v(x, y), v(x, y), v(x + px, y + py));
        prop_assert_eq!(c, SegmentPoint { point: v(x, y), t: Fx::ZERO });
    }
}

#[test]
fn closest_point_hand_computed() {
    let (a, b) = (v(0, 0), v(4 * UNIT, 0));
    // Interior: foot of the perpendicular.
    let c = closest_point_on_segment(a, b, v(UNIT, 3 * UNIT));
    assert_eq!((c.t, c.point), (fx(0.25), v(UNIT, 0)));
    // Before a and after b: clamped, exactly the ends.
    let c = closest_point_on_segment(a, b, v(-UNIT, 5 * UNIT));
    assert_eq!((c.t, c.point), (Fx::ZERO, a));
    let c = closest_point_on_segment(a, b, v(7 * UNIT, -5 * UNIT));
    assert_eq!((c.t, c.point), (Fx::ONE, b));
    // Exactly at the perpendicular through an end: still that end.
    let c = closest_point_on_segment(a, b, v(4 * UNIT, 9 * UNIT));
    assert_eq!((c.t, c.point), (Fx::ONE, b));
    // A diagonal segment and t = 1/3 (not representable): t is rounded to
    // nearest, 1/3 = 0x5555_5555.55… ulps → 0x5555_5555; the point (1, 1)
    // comes out within 2 ulps (here 1 ulp below, from the floors).
    let c = closest_point_on_segment(v(0, 0), v(3 * UNIT, 3 * UNIT), v(2 * UNIT, 0));
    assert_eq!(c.t.to_bits(), 0x5555_5555);
    assert!((f(c.point.x) - 1.0).abs() <= 2.0 * ULP);
    assert!((f(c.point.y) - 1.0).abs() <= 2.0 * ULP);
    // A reversed segment gives 1 − t and the same point.
    let c = closest_point_on_segment(b, a, v(UNIT, 3 * UNIT));
    assert_eq!((c.t, c.point), (fx(0.75), v(UNIT, 0)));
    // A segment two ulps long: d·d = 2⁻⁶², still resolved exactly.
    let e = Fx::DELTA;
    let c = closest_point_on_segment(
        Vec2::ZERO,
        Vec2::new(e.mul_int(2), Fx::ZERO),
        Vec2::new(e, Fx::ONE),
    );
    assert_eq!((c.t, c.point), (fx(0.5), Vec2::new(e, Fx::ZERO)));
}

#[test]
fn closest_point_at_world_bounds() {
    let l = WORLD;
    // The world's diagonal; p at the opposite corner projects to its middle.
    let c = closest_point_on_segment(v(-l, -l), v(l, l), v(l, -l));
    assert_eq!((c.t, c.point), (fx(0.5), Vec2::ZERO));
    // Awkward in-bounds values, checked against the exact oracle.
    let (a, b, p) = ((-l, -l + 3), (l, l - 7), (l - 1, -l + 5));
    let c = closest_point_on_segment(vq(a), vq(b), vq(p));
    let (t, exact) = oracle_segment(a, b, p);
    assert_eq!(bits(c.t), t);
    let comps = exact.expect("interior");
    for (got, (n, den)) in [c.point.x, c.point.y].into_iter().zip(comps) {
        assert!((bits(got) * den - n).abs() < 2 * den + den / 16384);
    }
}

/// Far beyond the bounds (the whole `Fx` range): `d = MAX − MIN` saturates
/// to `MAX` per component, so the segment is effectively `MIN → MIN + MAX`;
/// `t` stays in `[0, 1]` and the result is the same in debug and release.
/// The values are defined, not meaningful.
#[test]
fn closest_point_beyond_bounds_is_defined() {
    let (lo, hi) = (Vec2::new(Fx::MIN, Fx::MIN), Vec2::new(Fx::MAX, Fx::MAX));
    let c = closest_point_on_segment(lo, hi, Vec2::new(Fx::MAX, Fx::MIN));
    // w = (MAX, 0), d = (MAX, MAX): t = ½ exactly; point = MIN + MAX/2
    // = −2³⁰ − 2⁻³³, floored to −2³⁰ − 1 ulp.
    assert_eq!(c.t, fx(0.5));
    let expected = Fx::from_num(-(1i64 << 30)).sub(Fx::DELTA);
    assert_eq!(c.point, Vec2::new(expected, expected));
    let c = closest_point_on_segment(lo, hi, hi);
    assert_eq!((c.t, c.point), (Fx::ONE, hi));
}

// ---------------------------------------------------------------- circle–circle

proptest! {
    // 2048 cases per property.
    #![proptest_config(ProptestConfig::with_cases(CASES))]

    /// Bit-exact against the integer oracle: distance = floor(|d|) on the ulp
    /// grid (so separation within 1 ulp, rounded down), normal = d/distance
    /// truncated toward zero.
    #[test]
    fn circle_circle_matches_exact_oracle((a, b) in circle_pair()) {
        prop_assert_eq!(contact_circle_circle(&a, &b), oracle_circle_circle(&a, &b));
    }

    /// Swapping the circles gives exactly the flipped contact (d negates
    /// exactly, |d| is unchanged, division truncates toward zero); coincident
    /// centres give +Y both ways.
    #[test]
    fn circle_circle_symmetric((a, b) in circle_pair()) {
        let (ab, ba) = (contact_circle_circle(&a, &b), contact_circle_circle(&b, &a));
        if a.center == b.center {
            prop_assert_eq!(ab.normal, Vec2::Y);
            prop_assert_eq!(ba, ab);
        } else {
            prop_assert_eq!(ba, ab.flipped());
        }
    }

    /// Unit normal: each component is within ulp·(1 + 1/L) of the exact one
    /// (module docs), so | |n| − 1 | ≤ √2·ulp·(1 + 1/L) (+ f64 rounding).
    /// Touch: moving b by −sep·n (each product floored, < 1 ulp) leaves the
    /// pair at separation 0 up to: the 1-ulp floor of the old distance, the
    /// normal error times the lever |sep| (√2·ulp·(1 + 1/L)·|sep|), the
    /// products' √2 ulps and the new distance's 1-ulp floor:
    /// ulp·(4 + 1.5·|sep|·(1 + 1/L)).
    #[test]
    fn circle_circle_unit_normal_and_touch((a, b) in circle_pair()) {
        let c = contact_circle_circle(&a, &b);
        let l = length64((b.center - a.center).cast::<f64>());
        let lever = if l > 0.0 { 1.0 + 1.0 / l } else { 0.0 };
        let n = c.normal.cast::<f64>();
        prop_assert!((length64(n) - 1.0).abs() <= 1.5 * ULP * lever + 1e-15);
        let moved = Circle::new(b.center - c.normal.scale(c.separation), b.radius);
        let after = contact_circle_circle(&a, &moved).separation;
        prop_assert!(f(after).abs() <= ULP * (4.0 + 1.5 * f(c.separation).abs() * lever),
            "after = {after}");
    }

    /// `Fx` against the `f64` run of the same function. f64's L² is exact
    /// (integers below 2⁵³ in 2⁻²⁰ units), its root within 2⁻⁵³·2¹⁷ = 2⁻³⁶;
    /// `Fx` is within 1 ulp (separation) and ulp·(1 + 1/L) (normal).
    #[test]
    fn circle_circle_agrees_with_f64((a, b) in circle_pair()) {
        let c = contact_circle_circle(&a, &b);
        let r = contact_circle_circle(&circle64(&a), &circle64(&b));
        let l = length64((b.center - a.center).cast::<f64>());
        let lever = if l > 0.0 { 1.0 + 1.0 / l } else { 0.0 };
        prop_assert!((f(c.separation) - r.separation).abs() <= ULP + 2f64.powi(-35));
        prop_assert!((f(c.normal.x) - r.normal.x).abs() <= ULP * lever + 1e-15);
        prop_assert!((f(c.normal.y) - r.normal.y).abs() <= ULP * lever + 1e-15);
    }
}

#[test]
fn circle_circle_hand_computed() {
    let a = Circle::new(v(0, 0), q(UNIT));
    // 3-4-5: gap 5 − 3 = 2, normal (0.6, 0.8) truncated.
    let c = contact_circle_circle(&a, &Circle::new(v(3 * UNIT, 4 * UNIT), q(2 * UNIT)));
    assert_eq!(c.separation, fx(2.0));
    assert_eq!(c.normal.x.to_bits(), (3i64 << 32) / 5);
    assert_eq!(c.normal.y.to_bits(), (4i64 << 32) / 5);
    // Axis-aligned overlap: exact normal, penetration 0.5.
    let c = contact_circle_circle(&a, &Circle::new(v(-UNIT - UNIT / 2, 0), q(UNIT)));
    assert_eq!((c.normal, c.separation), (-Vec2::X, fx(-0.5)));
    // Exactly touching.
    let c = contact_circle_circle(&a, &Circle::new(v(0, 3 * UNIT), q(2 * UNIT)));
    assert_eq!((c.normal, c.separation), (Vec2::Y, Fx::ZERO));
}

#[test]
fn circle_circle_coincident_centres_give_plus_y() {
    let a = Circle::new(v(5 * UNIT, -7 * UNIT), q(UNIT));
    let b = Circle::new(v(5 * UNIT, -7 * UNIT), q(3 * UNIT));
    for c in [contact_circle_circle(&a, &b), contact_circle_circle(&b, &a)] {
        assert_eq!((c.normal, c.separation), (Vec2::Y, fx(-4.0)));
    }
}

#[test]
fn circle_circle_at_world_bounds() {
    let l = WORLD;
    // Opposite world corners, radii 4000: exact oracle values (distance
    // 65536·√2 floored), no overflow anywhere.
    let a = Circle::new(v(-l, -l), q(4000 * UNIT));
    let b = Circle::new(v(l, l), q(4000 * UNIT));
    let c = contact_circle_circle(&a, &b);
    assert_eq!(c, oracle_circle_circle(&a, &b));
    assert!((f(c.separation) - (65536.0 * 2f64.sqrt() - 8000.0)).abs() < 2.0 * ULP);
    // Along an edge: exact.
    let b = Circle::new(v(l, -l), q(4000 * UNIT));
    assert_eq!(
        contact_circle_circle(&a, &b),
        Contact {
            normal: Vec2::X,
            separation: fx(57_536.0)
        }
    );
}

/// Beyond the bounds, everything saturates (centre difference to `Fx::MAX`,
/// the distance to `Fx::MAX`, the radii sum to `Fx::MAX`): a defined, if
/// meaningless, answer, the same in debug and release. The normal is still
/// a unit vector: `Vec2::try_normalize_with_length` handles saturated
/// lengths.
#[test]
fn circle_circle_beyond_bounds_is_defined() {
    let a = Circle::new(Vec2::new(Fx::MIN, Fx::MIN), Fx::MAX);
    let b = Circle::new(Vec2::new(Fx::MAX, Fx::MAX), Fx::MAX);
    let c = contact_circle_circle(&a, &b);
    let diagonal = Vec2::new(Fx::MAX, Fx::MAX)
        .try_normalize()
        .expect("nonzero");
    assert_eq!(
        c,
        Contact {
            normal: diagonal,
            separation: Fx::ZERO
        }
    );
    assert!((f(c.normal.x) - 0.5f64.sqrt()).abs() < 2.0 * ULP);
}

// ---------------------------------------------------------------- aabb–aabb

/// The two signed axis gaps, computed independently in integers.
fn gaps(a: &Aabb, b: &Aabb) -> (i128, i128) {
    let gx = (bits(b.center.x) - bits(a.center.x)).abs()
        - bits(a.half_extents.x)
        - bits(b.half_extents.x);
    let gy = (bits(b.center.y) - bits(a.center.y)).abs()
        - bits(a.half_extents.y)
        - bits(b.half_extents.y);
    (gx, gy)
}

proptest! {
    // 2048 cases per property.
    #![proptest_config(ProptestConfig::with_cases(CASES))]

    /// Exact: separation = max gap (ties: y), axis normal towards b; the sign
    /// of the separation agrees with `Aabb::overlaps`.
    #[test]
    fn aabb_aabb_is_exact_sat((a, b) in aabb_pair()) {
        let c = contact_aabb_aabb(&a, &b);
        let (gx, gy) = gaps(&a, &b);
        let sign = |d: Fx| if d < Fx::ZERO { -Fx::ONE } else { Fx::ONE };
        let d = b.center - a.center;
        let expected = if gx > gy {
            Contact { normal: Vec2::new(sign(d.x), Fx::ZERO), separation: fx_from_bits(gx) }
        } else {
            Contact { normal: Vec2::new(Fx::ZERO, sign(d.y)), separation: fx_from_bits(gy) }
        };
        prop_assert_eq!(c, expected);
        prop_assert_eq!(c.separation <= Fx::ZERO, a.overlaps(&b));
    }

    /// Swapping gives exactly the flipped contact, unless the offset on the
    /// chosen axis is zero (then both orders give the positive axis).
    #[test]
    fn aabb_aabb_symmetric((a, b) in aabb_pair()) {
        let (ab, ba) = (contact_aabb_aabb(&a, &b), contact_aabb_aabb(&b, &a));
        prop_assert_eq!(ba.separation, ab.separation);
        let offset_on_axis = (b.center - a.center).dot(ab.normal);
        if offset_on_axis == Fx::ZERO {
            prop_assert_eq!(ba.normal, ab.normal);
        } else {
            prop_assert_eq!(ba.normal, -ab.normal);
        }
    }

    /// The normal is exactly a unit axis. Moving b by −sep·n (exact: n is an
    /// axis) closes the gap on the chosen axis exactly; the moved boxes touch
    /// (separation exactly 0) whenever the other axis's projections overlap,
    /// and otherwise are apart by exactly the other axis's gap (the
    /// documented SAT choice for diagonally separated boxes).
    #[test]
    fn aabb_aabb_unit_normal_and_touch((a, b) in aabb_pair()) {
        let c = contact_aabb_aabb(&a, &b);
        prop_assert!(c.normal.abs() == Vec2::X || c.normal.abs() == Vec2::Y);
        let moved = Aabb::new(b.center - c.normal.scale(c.separation), b.half_extents);
        let (gx, gy) = gaps(&a, &b);
        let other = if c.normal.x == Fx::ZERO { gx } else { gy };
        let after = contact_aabb_aabb(&a, &moved);
        prop_assert_eq!(bits(after.separation), other.max(0));
        let (mx, my) = gaps(&a, &moved);
        prop_assert_eq!(if c.normal.x == Fx::ZERO { my } else { mx }, 0);
    }

    /// Only exact operations: `Fx` and `f64` agree bit for bit.
    #[test]
    fn aabb_aabb_agrees_with_f64((a, b) in aabb_pair()) {
        let c = contact_aabb_aabb(&a, &b);
        let r = contact_aabb_aabb(&aabb64(&a), &aabb64(&b));
        prop_assert_eq!(c.normal.cast::<f64>(), r.normal);
        prop_assert_eq!(f(c.separation), r.separation);
    }
}

#[test]
fn aabb_aabb_hand_computed() {
    let a = Aabb::new(v(0, 0), v(UNIT, UNIT));
    let bx = |x: i64, y: i64| Aabb::new(v(x, y), v(UNIT, UNIT));
    // Side by side, overlapping by 0.5 in x: −X normal from a to the left box.
    let c = contact_aabb_aabb(&a, &bx(-3 * UNIT / 2, UNIT / 4));
    assert_eq!((c.normal, c.separation), (-Vec2::X, fx(-0.5)));
    // Apart on both axes (gaps 1 and 2): the larger gap, along y.
    let c = contact_aabb_aabb(&a, &bx(3 * UNIT, 4 * UNIT));
    assert_eq!((c.normal, c.separation), (Vec2::Y, fx(2.0)));
    // Equal gaps: y wins.
    let c = contact_aabb_aabb(&a, &bx(3 * UNIT, -3 * UNIT));
    assert_eq!((c.normal, c.separation), (-Vec2::Y, fx(1.0)));
    // Equal penetration: y wins.
    let c = contact_aabb_aabb(&a, &bx(UNIT, UNIT));
    assert_eq!((c.normal, c.separation), (Vec2::Y, fx(-1.0)));
    // Touching at a corner.
    let c = contact_aabb_aabb(&a, &bx(2 * UNIT, 2 * UNIT));
    assert_eq!((c.normal, c.separation), (Vec2::Y, Fx::ZERO));
}

#[test]
fn aabb_aabb_coincident_centres() {
    // Square (or wide) boxes: +Y, both orders.
    let a = Aabb::new(v(UNIT, UNIT), v(UNIT, UNIT));
    let b = Aabb::new(v(UNIT, UNIT), v(2 * UNIT, UNIT));
    for c in [contact_aabb_aabb(&a, &b), contact_aabb_aabb(&b, &a)] {
        assert_eq!((c.normal, c.separation), (Vec2::Y, fx(-2.0)));
    }
    // Tall boxes: x is the axis of least penetration; zero offset → +X.
    let a = Aabb::new(v(0, 0), v(UNIT, 3 * UNIT));
    let c = contact_aabb_aabb(&a, &a);
    assert_eq!((c.normal, c.separation), (Vec2::X, fx(-2.0)));
}

#[test]
fn aabb_aabb_at_world_bounds() {
    let l = WORLD;
    let a = Aabb::new(v(-l, 0), v(4000 * UNIT, 4000 * UNIT));
    let b = Aabb::new(v(l, 0), v(4000 * UNIT, 4000 * UNIT));
    assert_eq!(
        contact_aabb_aabb(&a, &b),
        Contact {
            normal: Vec2::X,
            separation: fx(57_536.0)
        }
    );
    assert_eq!(
        contact_aabb_aabb(&b, &a),
        Contact {
            normal: -Vec2::X,
            separation: fx(57_536.0)
        }
    );
    // Beyond: the offset saturates to MAX and the half-extent sum to MAX.
    let a = Aabb::new(Vec2::new(Fx::MIN, Fx::MIN), Vec2::new(Fx::MAX, Fx::ONE));
    let b = Aabb::new(Vec2::new(Fx::MAX, Fx::MIN), Vec2::new(Fx::MAX, Fx::ONE));
    let c = contact_aabb_aabb(&a, &b);
    assert_eq!(
        c,
        Contact {
            normal: Vec2::X,
            separation: Fx::ZERO
        }
    );
}

// ---------------------------------------------------------------- circle–aabb

/// Signed distance from a point to a box, the textbook formula in f64 (an
/// oracle independent of the implementation's case split).
fn box_sdf(p: Vec2<f64>, b: &Aabb<f64>) -> f64 {
    let dx = (p.x - b.center.x).abs() - b.half_extents.x;
    let dy = (p.y - b.center.y).abs() - b.half_extents.y;
    if dx > 0.0 || dy > 0.0 {
        dx.max(0.0).hypot(dy.max(0.0))
    } else {
        dx.max(dy)
    }
}

proptest! {
    // 2048 cases per property.
    #![proptest_config(ProptestConfig::with_cases(CASES))]

    /// Bit-exact against the integer oracle of the documented maths.
    #[test]
    fn circle_aabb_matches_exact_oracle((a, b) in circle_aabb_pair()) {
        prop_assert_eq!(contact_circle_aabb(&a, &b), oracle_circle_aabb(&a, &b));
    }

    /// Against the textbook signed distance (f64): outside, `Fx` rounds the
    /// distance down by < 1 ulp and f64's hypot adds ≤ 2⁻⁵²·2¹⁷; inside it is
    /// exact. Bound ulp + 2⁻³⁴.
    #[test]
    fn circle_aabb_matches_sdf((a, b) in circle_aabb_pair()) {
        let c = contact_circle_aabb(&a, &b);
        let expected = box_sdf(a.center.cast(), &aabb64(&b)) - f(a.radius);
        prop_assert!((f(c.separation) - expected).abs() <= ULP + 2f64.powi(-34));
    }

    /// `contact_aabb_circle` is exactly the flip of `contact_circle_aabb`.
    #[test]
    fn circle_aabb_symmetric((a, b) in circle_aabb_pair()) {
        prop_assert_eq!(contact_aabb_circle(&b, &a), contact_circle_aabb(&a, &b).flipped());
    }

    /// Unit normal (exact in the face regions and inside; in the corner
    /// regions as for two circles, with L = |v| ≥ 2⁻¹⁰ here). Touch: moving
    /// the box by −sep·n brings the pair to separation 0 within the
    /// circle–circle bound (the box's signed distance is 1-Lipschitz, so the
    /// same displacement-error argument holds); exactly 0 when n is an axis.
    #[test]
    fn circle_aabb_unit_normal_and_touch((a, b) in circle_aabb_pair()) {
        let c = contact_circle_aabb(&a, &b);
        let axis = c.normal.abs() == Vec2::X || c.normal.abs() == Vec2::Y;
        let lever = 1.0 + 1024.0;
        let n = length64(c.normal.cast::<f64>());
        prop_assert!((n - 1.0).abs() <= 1.5 * ULP * lever);
        let moved = Aabb::new(b.center - c.normal.scale(c.separation), b.half_extents);
        let after = contact_circle_aabb(&a, &moved).separation;
        if axis {
            prop_assert_eq!(after, Fx::ZERO);
        } else {
            prop_assert!(f(after).abs() <= ULP * (4.0 + 1.5 * f(c.separation).abs() * lever));
        }
    }

    /// `Fx` against the `f64` run: identical case split (exact comparisons),
    /// then as for two circles.
    #[test]
    fn circle_aabb_agrees_with_f64((a, b) in circle_aabb_pair()) {
        let c = contact_circle_aabb(&a, &b);
        let r = contact_circle_aabb(&circle64(&a), &aabb64(&b));
        prop_assert!((f(c.separation) - r.separation).abs() <= ULP + 2f64.powi(-35));
        prop_assert!((f(c.normal.x) - r.normal.x).abs() <= ULP * 1025.0);
        prop_assert!((f(c.normal.y) - r.normal.y).abs() <= ULP * 1025.0);
    }
}

#[test]
fn circle_aabb_hand_computed() {
    let b = Aabb::new(v(0, 0), v(2 * UNIT, UNIT));
    let at = |x: i64, y: i64, r: i64| contact_circle_aabb(&Circle::new(v(x, y), q(r)), &b);
    // Above the top face, gap 0.5: normal −Y (from circle down to box).
    assert_eq!(
        at(UNIT, 2 * UNIT, UNIT / 2),
        Contact {
            normal: -Vec2::Y,
            separation: fx(0.5)
        }
    );
    // Corner region: v = (3, 4), distance 5.
    let c = at(5 * UNIT, 5 * UNIT, UNIT);
    assert_eq!(c.separation, fx(4.0));
    assert_eq!(c.normal.x.to_bits(), -((3i64 << 32) / 5));
    assert_eq!(c.normal.y.to_bits(), -((4i64 << 32) / 5));
    // Centre exactly on the right edge: depth 0 → separation −r, face normal.
    assert_eq!(
        at(2 * UNIT, UNIT / 2, UNIT / 2),
        Contact {
            normal: -Vec2::X,
            separation: fx(-0.5)
        }
    );
    // Exactly on the bottom edge.
    assert_eq!(
        at(UNIT, -UNIT, UNIT / 2),
        Contact {
            normal: Vec2::Y,
            separation: fx(-0.5)
        }
    );
    // Exactly on a corner: equal depths (0), the y face.
    assert_eq!(
        at(2 * UNIT, UNIT, UNIT / 2),
        Contact {
            normal: -Vec2::Y,
            separation: fx(-0.5)
        }
    );
    assert_eq!(
        at(-2 * UNIT, -UNIT, UNIT / 2),
        Contact {
            normal: Vec2::Y,
            separation: fx(-0.5)
        }
    );
    // Inside, nearest face is x (depth 0.5 < 0.75): −(0.5 + 0.5).
    assert_eq!(
        at(3 * UNIT / 2, UNIT / 4, UNIT / 2),
        Contact {
            normal: -Vec2::X,
            separation: fx(-1.0)
        }
    );
    // Inside, left half: pushed out through −X, so the normal is +X.
    assert_eq!(
        at(-7 * UNIT / 4, -UNIT / 2, UNIT / 2),
        Contact {
            normal: Vec2::X,
            separation: fx(-0.75)
        }
    );
    // Inside, nearest face is y.
    assert_eq!(
        at(UNIT / 2, -3 * UNIT / 4, UNIT / 2),
        Contact {
            normal: Vec2::Y,
            separation: fx(-0.75)
        }
    );
}

#[test]
fn circle_aabb_centre_at_box_centre() {
    // Square box: +Y from the circle (the engine-wide convention) and −Y
    // from the box (the flip; the same physical push either way).
    let sq = Aabb::new(v(3 * UNIT, 3 * UNIT), v(UNIT, UNIT));
    let ball = Circle::new(v(3 * UNIT, 3 * UNIT), q(UNIT / 4));
    let c = contact_circle_aabb(&ball, &sq);
    assert_eq!(
        c,
        Contact {
            normal: Vec2::Y,
            separation: fx(-1.25)
        }
    );
    assert_eq!(
        contact_aabb_circle(&sq, &ball),
        Contact {
            normal: -Vec2::Y,
            separation: fx(-1.25)
        }
    );
    // Wide box: y is the least-penetration axis, +Y.
    let wide = Aabb::new(v(3 * UNIT, 3 * UNIT), v(4 * UNIT, UNIT));
    assert_eq!(contact_circle_aabb(&ball, &wide).normal, Vec2::Y);
    // Tall box: x is the least-penetration axis, zero offset → +X.
    let tall = Aabb::new(v(3 * UNIT, 3 * UNIT), v(UNIT, 4 * UNIT));
    assert_eq!(
        contact_circle_aabb(&ball, &tall),
        Contact {
            normal: Vec2::X,
            separation: fx(-1.25)
        }
    );
}

#[test]
fn circle_aabb_at_world_bounds() {
    let l = WORLD;
    // Corner region across the whole world: exact oracle values.
    let ball = Circle::new(v(-l, -l), q(3000 * UNIT));
    let bx = Aabb::new(v(l, l), v(1000 * UNIT, 2000 * UNIT));
    let c = contact_circle_aabb(&ball, &bx);
    assert_eq!(c, oracle_circle_aabb(&ball, &bx));
    let expected = (64_536.0f64).hypot(63_536.0) - 3000.0;
    assert!((f(c.separation) - expected).abs() < 2.0 * ULP);
    // Face region: exact.
    let ball = Circle::new(v(-l, l), q(3000 * UNIT));
    assert_eq!(
        contact_circle_aabb(&ball, &bx),
        Contact {
            normal: Vec2::X,
            separation: fx(61_536.0)
        }
    );
    // Beyond: the offset q = MIN − MAX saturates to MIN = −2³¹, v = MIN + 1
    // (face region), distance 2³¹ − 1, separation (2³¹ − 1) − MAX = −(1 − ulp).
    let ball = Circle::new(Vec2::new(Fx::MIN, Fx::ZERO), Fx::MAX);
    let bx = Aabb::new(Vec2::new(Fx::MAX, Fx::ZERO), Vec2::new(Fx::ONE, Fx::ONE));
    let c = contact_circle_aabb(&ball, &bx);
    assert_eq!(
        c,
        Contact {
            normal: Vec2::X,
            separation: Fx::DELTA.sub(Fx::ONE)
        }
    );
}

// ---------------------------------------------------------------- other scalars

/// The same generic functions on `I48F16` (ulp 2⁻¹⁶) and `f32` agree with
/// `f64` within bounds scaled to their precision: I48F16 as derived above
/// with its ulp (separation 1 ulp, normal ulp·(1 + 1/L), point 2 ulps,
/// t ½ ulp); f32 (relative 2⁻²⁴, magnitudes ≤ 32 here) within 1e-4.
#[test]
fn other_scalars_agree_with_f64() {
    let u48 = 2f64.powi(-16);
    let mut seed = 0x1234_5678_9abc_def0u64;
    let mut next = |range: i64| {
        seed = seed
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        ((seed >> 33) as i64).rem_euclid(2 * range + 1) - range
    };
    for _ in 0..2000 {
        let p: Vec<f64> = (0..8)
            .map(|_| next(8 * UNIT) as f64 / UNIT as f64)
            .collect();
        let r = (next(4 * UNIT).abs() + 1) as f64 / UNIT as f64;
        let a64 = Circle::new(Vec2::new(p[0], p[1]), r);
        let b64 = Circle::new(Vec2::new(p[2], p[3]), r);
        let reference = contact_circle_circle(&a64, &b64);
        let l = length64(b64.center - a64.center);
        let lever = if l > 0.0 { 1.0 + 1.0 / l } else { 0.0 };

        let c48 = contact_circle_circle(
            &Circle::new(a64.center.cast::<I48F16>(), I48F16::from_f64(r)),
            &Circle::new(b64.center.cast::<I48F16>(), I48F16::from_f64(r)),
        );
        assert!((c48.separation.to_f64() - reference.separation).abs() <= u48 + 1e-12);
        assert!((c48.normal.x.to_f64() - reference.normal.x).abs() <= u48 * lever + 1e-12);
        assert!((c48.normal.y.to_f64() - reference.normal.y).abs() <= u48 * lever + 1e-12);

        let c32 = contact_circle_circle(
            &Circle::new(a64.center.cast::<f32>(), r as f32),
            &Circle::new(b64.center.cast::<f32>(), r as f32),
        );
        assert!((f64::from(c32.separation) - reference.separation).abs() <= 1e-4);

        let (sa, sb, sp) = (
            Vec2::new(p[4], p[5]),
            Vec2::new(p[6], p[7]),
            Vec2::new(p[0], p[1]),
        );
        let seg = closest_point_on_segment(sa, sb, sp);
        let s48 = closest_point_on_segment(sa.cast::<I48F16>(), sb.cast(), sp.cast());
        assert!((s48.t.to_f64() - seg.t).abs() <= u48 / 2.0 + 1e-12);
        assert!((s48.point.x.to_f64() - seg.point.x).abs() <= 2.0 * u48 + 1e-12);
        assert!((s48.point.y.to_f64() - seg.point.y).abs() <= 2.0 * u48 + 1e-12);
        let s32 = closest_point_on_segment(sa.cast::<f32>(), sb.cast(), sp.cast());
        assert!((f64::from(s32.t) - seg.t).abs() <= 1e-4);

        let box64 = Aabb::new(Vec2::new(p[4], p[5]), Vec2::new(r, r * 0.5));
        let box48 = Aabb::new(box64.center.cast::<I48F16>(), box64.half_extents.cast());
        let ca = contact_circle_aabb(&a64, &box64);
        let ca48 = contact_circle_aabb(
            &Circle::new(a64.center.cast::<I48F16>(), I48F16::from_f64(r)),
            &box48,
        );
        assert!((ca48.separation.to_f64() - ca.separation).abs() <= u48 + 1e-12);
        let bb = contact_aabb_aabb(&box64, &a64.bounding_aabb());
        let bb48 = contact_aabb_aabb(
            &box48,
            &Circle::new(a64.center.cast::<I48F16>(), I48F16::from_f64(r)).bounding_aabb(),
        );
        assert_eq!(bb48.separation.to_f64(), bb.separation);
    }
}
