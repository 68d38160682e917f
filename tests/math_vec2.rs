//! `Vec2`: exact dot/cross/length against `i128` arithmetic on the raw bits,
//! normalisation bounds, saturating operators, and agreement of the
//! fixed-point results with the `f64` reference run of the same code.
//!
//! Inputs come in two families: *world* vectors, whose components are within
//! ±[`WORLD_LIMIT`] = 2¹⁵ (endpoints included), where every wide product is
//! exact and nothing should saturate before narrowing; and *full-range*
//! vectors (any raw bits, including MIN/MAX), where the results must be the
//! saturated exact values. Every check runs for `I32F32` (= `Fx`) and
//! `I48F16`. Case counts: [`CASES`] (8192) per property, 32× proptest's
//! default of 256.

use clockwork2d::math::WORLD_LIMIT;
use clockwork2d::math::{Fx, Scalar, Vec2, fx, vec2};
use fixed::types::{I32F32, I48F16, I64F64};
use proptest::prelude::*;

mod common;
use common::raw_fixed::{Fixed, RAW_MAX, RAW_MIN, WideFixed, sat};

/// Cases per property (proptest's default is 256).
const CASES: u32 = 8192;

/// f64 unit roundoff, 2⁻⁵³.
const U: f64 = 1.0 / 9_007_199_254_740_992.0;

// ---------------------------------------------------------------------------
// Raw-bit access.
// ---------------------------------------------------------------------------

// `Fixed`, `WideFixed`, `sat`, `RAW_MIN`/`RAW_MAX`: tests/common/raw_fixed.rs.

fn vec<S: Fixed>((x, y): (i64, i64)) -> Vec2<S> {
    Vec2::new(S::from_raw(x), S::from_raw(y))
}

fn raw<S: Fixed>(v: Vec2<S>) -> (i128, i128) {
    (v.x.raw(), v.y.raw())
}

/// Exact `x² + y²` of raw components (2·FRAC fraction bits), unsaturated:
/// each square is ≤ 2¹²⁶, so the sum fits a `u128`.
fn raw_len_sq(x: i128, y: i128) -> u128 {
    x.unsigned_abs().pow(2) + y.unsigned_abs().pow(2)
}

/// The true length in units, as `f64` (relative error ≤ 2u).
fn true_len<S: Fixed>(v: Vec2<S>) -> f64 {
    let (x, y) = raw(v);
    // u128 → f64 rounds once (≤ u), sqrt rounds once and halves the first.
    (raw_len_sq(x, y) as f64).sqrt() / 2f64.powi(S::FRAC as i32)
}

// ---------------------------------------------------------------------------
// Strategies.
// ---------------------------------------------------------------------------

/// Raw bits with magnitude below 2^`bits` (log-uniform), plus the exact
/// endpoints ±2^`bits` when `endpoints` (a world coordinate may be exactly
/// ±WORLD_LIMIT).
fn raw_below(bits: u32, endpoints: bool) -> BoxedStrategy<i64> {
    let log_uniform = (1u32..=bits, any::<u64>(), any::<bool>()).prop_map(|(k, r, neg)| {
        let m = i64::try_from(r >> (64 - k)).expect("below 2^63");
        if neg { -m } else { m }
    });
    if !endpoints {
        return log_uniform.boxed();
    }
    let edge = 1i64 << bits;
    prop_oneof![
        6 => log_uniform,
        1 => prop_oneof![Just(edge), Just(-edge), Just(0)],
        1 => (0i64..1 << 10).prop_map(move |d| edge - d),
        1 => (0i64..1 << 10).prop_map(move |d| d - edge),
    ]
    .boxed()
}

/// Full-range raw bits: every magnitude plus the neighbourhoods of MIN/MAX.
fn raw_full() -> BoxedStrategy<i64> {
    prop_oneof![
        4 => raw_below(63, false),
        2 => any::<i64>(),
        1 => prop_oneof![Just(i64::MAX), Just(i64::MIN), Just(0), Just(1), Just(-1)],
        1 => (0i64..1 << 10).prop_map(|d| i64::MAX - d),
        1 => (0i64..1 << 10).prop_map(|d| i64::MIN + d),
    ]
    .boxed()
}

/// A raw component pair within the world bounds for a type with `frac`
/// fraction bits (|c| ≤ 2^(15 + frac) raw).
fn world_pair(frac: u32) -> BoxedStrategy<(i64, i64)> {
    let bits = WORLD_LIMIT.trailing_zeros() + frac;
    (raw_below(bits, true), raw_below(bits, true)).boxed()
}

fn full_pair() -> BoxedStrategy<(i64, i64)> {
    (raw_full(), raw_full()).boxed()
}

/// Either family.
fn any_pair(frac: u32) -> BoxedStrategy<(i64, i64)> {
    prop_oneof![world_pair(frac), full_pair()].boxed()
}

/// Coordinates quantised to 16 fraction bits within the world (|c| < 2¹⁵):
/// k·2⁻¹⁶ with |k| < 2³¹ is exact in `Fx`, `I48F16` and `f64`.
fn quantised_pair() -> BoxedStrategy<(i64, i64)> {
    let k = prop_oneof![
        3 => raw_below(31, false),
        1 => raw_below(16, false),
    ];
    (k.clone(), k).boxed()
}

fn quantised<S: Fixed>((x, y): (i64, i64)) -> Vec2<S> {
    // Raw k at 16 fraction bits, shifted up to the type's FRAC (≥ 16).
    vec((x << (S::FRAC - 16), y << (S::FRAC - 16)))
}

// ---------------------------------------------------------------------------
// Exact products.
// ---------------------------------------------------------------------------

fn check_dot_cross<S: Fixed>(a: Vec2<S>, b: Vec2<S>, world: bool) {
    let ((ax, ay), (bx, by)) = (raw(a), raw(b));
    // Products ≤ 2¹²⁶; the wide type's raw range is all of i128, so the wide
    // sum saturates like i128::saturating_add (only MIN·MIN + MIN·MIN, at
    // 2¹²⁷, reaches it, and that is far beyond the narrow range anyway).
    let dot = (ax * bx).saturating_add(ay * by);
    let cross = (ax * by).saturating_sub(ay * bx);
    assert_eq!(a.dot_wide(b).raw(), dot, "{} dot_wide", S::NAME);
    assert_eq!(a.dot(b).raw(), sat(dot >> S::FRAC), "{} dot", S::NAME);
    assert_eq!(a.cross(b).raw(), sat(cross >> S::FRAC), "{} cross", S::NAME);
    assert_eq!(a.dot(b), b.dot(a), "{} dot commutes", S::NAME);
    if world {
        // Within the world the wide values are far from saturation:
        // |dot|, |cross| ≤ 2·(2¹⁵)² = 2³¹ units.
        let limit = 1i128 << (31 + 2 * S::FRAC);
        assert!(dot.abs() <= limit && cross.abs() <= limit);
        // Exact sums commute bit for bit.
        assert_eq!(b.dot_wide(a), a.dot_wide(b));
    }
    // perp().dot() is the cross product whenever −y does not saturate.
    if ay != RAW_MIN {
        assert_eq!(a.perp().dot(b), a.cross(b), "{} perp·b = a×b", S::NAME);
    }
    assert_eq!(raw(a.perp()), (sat(-ay), ax), "{} perp", S::NAME);
}

fn check_length<S: Fixed>(v: Vec2<S>) {
    let (x, y) = raw(v);
    let exact = raw_len_sq(x, y);
    // The wide squared length is exact unless it exceeds the wide range
    // (only possible for |v| ≥ 2^(63.5 − FRAC)… i.e. far outside the world).
    let wide = v.length_squared_wide().raw();
    assert_eq!(wide, i128::try_from(exact).unwrap_or(i128::MAX));
    assert_eq!(v.length_squared(), v.dot(v));
    assert_eq!(v.length_squared().raw(), sat(wide >> S::FRAC));
    // length = floor(√exact) in narrow ulps, saturated to MAX.
    let root = i128::try_from(exact.isqrt()).expect("fits");
    let len = v.length().raw();
    assert_eq!(len, root.min(RAW_MAX), "{} length of {v:?}", S::NAME);
    if root <= RAW_MAX {
        // Within one ulp, below: len ≤ |v| < len + ulp.
        let l = len.unsigned_abs();
        assert!(l * l <= exact && exact < (l + 1) * (l + 1));
    }
    // Symmetries that hold bit for bit.
    assert_eq!(Vec2::new(v.y, v.x).length(), v.length());
    if x != RAW_MIN && y != RAW_MIN {
        assert_eq!((-v).length(), v.length());
    }
}

fn check_axis<S: Fixed>(c: i64) {
    // An axis-aligned vector has exactly |c| as its length (|MIN| saturates
    // to MAX in both), and normalises to exactly ±X / ±Y.
    let c = S::from_raw(c);
    for v in [Vec2::new(c, S::ZERO), Vec2::new(S::ZERO, c)] {
        assert_eq!(v.length(), c.abs(), "{} axis length", S::NAME);
        let Some(n) = v.try_normalize() else {
            assert_eq!(c, S::ZERO);
            continue;
        };
        let sign = c.signum();
        let expected = if v.y == S::ZERO {
            Vec2::new(sign, S::ZERO)
        } else {
            Vec2::new(S::ZERO, sign)
        };
        assert_eq!(n, expected, "{} axis normalize of {v:?}", S::NAME);
    }
}

// ---------------------------------------------------------------------------
// Normalisation.
// ---------------------------------------------------------------------------

/// Checks `try_normalize` against the bounds documented on it, derived
/// there: `len` is |v| rounded down by < 1 ulp and each quotient is
/// truncated toward zero by < 1 ulp, so
///
/// * |n| ∈ (1 − √2 ulp, 1 + ulp/(|v| − ulp)) and within 2 ulp/|v| + 2 ulp of 1;
/// * |v × n| / |v| = |v × t| / |v| ≤ |t| < √2 ulp (t = the truncations).
///
/// The measured quantities are exact `i128` values converted to `f64` once
/// (relative error ~1e-16, i.e. ≤ 1e-6 ulp for both types): a slack of
/// `1e-3 ulp` covers that and the 2⁻⁶²-relative shift of the halving path
/// for saturated lengths.
fn check_normalize<S: Fixed>(v: Vec2<S>) {
    let with_len = v.try_normalize_with_length();
    let Some(n) = v.try_normalize() else {
        assert_eq!(v, Vec2::ZERO, "{} None only for zero", S::NAME);
        assert_eq!(with_len, None);
        assert_eq!(v.normalize_or_zero(), Vec2::ZERO);
        return;
    };
    assert_eq!(with_len, Some((n, v.length())));
    assert_eq!(v.normalize_or_zero(), n);

    let ulp = S::EPSILON.to_f64();
    let slack = 1e-3 * ulp;
    let scale = 2f64.powi(S::FRAC as i32);
    let l = true_len(v);
    let (nx, ny) = raw(n);
    let norm = (raw_len_sq(nx, ny) as f64).sqrt() / scale;
    assert!(
        norm > 1.0 - 2f64.sqrt() * ulp - slack,
        "{} |n| = {norm} too short for {v:?}",
        S::NAME
    );
    assert!(
        (norm - 1.0).abs() <= 2.0 * ulp / l + 2.0 * ulp + slack,
        "{} |n| = {norm} outside the documented bound for |v| = {l}",
        S::NAME
    );
    if l > 2.0 * ulp {
        assert!(
            norm < 1.0 + ulp / (l - ulp) + slack,
            "{} |n| = {norm}",
            S::NAME
        );
    }
    if S::FRAC == 32 && l >= 1e-3 {
        assert!((norm - 1.0).abs() < 1e-6, "Fx: |n| = {norm}, |v| = {l}");
    }

    // Direction: the exact cross product v × n (raw, 2·FRAC fraction bits;
    // |v| ≤ 2⁶³·√2 raw and |n| ≤ 2^(FRAC+1), so it fits i128).
    let (x, y) = raw(v);
    let cross = x * ny - y * nx;
    let off = (cross as f64 / scale / scale).abs() / l;
    assert!(
        off <= 2f64.sqrt() * ulp + slack,
        "{} direction off by {off} for {v:?}",
        S::NAME
    );
    // Same half-plane, and no component changes sign.
    assert!(x * nx + y * ny > 0, "{} n points away from {v:?}", S::NAME);
    assert!(nx == 0 || nx.signum() == x.signum());
    assert!(ny == 0 || ny.signum() == y.signum());
}

// ---------------------------------------------------------------------------
// Operators and component-wise helpers.
// ---------------------------------------------------------------------------

fn check_ops<S: Fixed>(a: Vec2<S>, b: Vec2<S>, s: S) {
    let ((ax, ay), (bx, by), sr) = (raw(a), raw(b), s.raw());
    assert_eq!(raw(a + b), (sat(ax + bx), sat(ay + by)), "{} +", S::NAME);
    assert_eq!(raw(a - b), (sat(ax - bx), sat(ay - by)), "{} -", S::NAME);
    assert_eq!(raw(-a), (sat(-ax), sat(-ay)), "{} unary -", S::NAME);
    let scaled = (sat((ax * sr) >> S::FRAC), sat((ay * sr) >> S::FRAC));
    assert_eq!(raw(a * s), scaled, "{} * scalar", S::NAME);
    assert_eq!(a.scale(s), a * s);
    let elements = (sat((ax * bx) >> S::FRAC), sat((ay * by) >> S::FRAC));
    assert_eq!(raw(a.mul_elements(b)), elements, "{} mul_elements", S::NAME);
    let mut c = a;
    c += b;
    assert_eq!(c, a + b);
    c = a;
    c -= b;
    assert_eq!(c, a - b);

    assert_eq!(raw(a.min(b)), (ax.min(bx), ay.min(by)));
    assert_eq!(raw(a.max(b)), (ax.max(bx), ay.max(by)));
    assert_eq!(raw(a.abs()), (sat(ax.abs()), sat(ay.abs())));
    // clamp(low, high) per component; `low` wins where low > high.
    let (lo, hi) = (a.min(b), a.max(b));
    let probe = Vec2::new(s, s);
    let clamped = probe.clamp(lo, hi);
    assert_eq!(
        raw(clamped),
        (
            sr.clamp(ax.min(bx), ax.max(bx)),
            sr.clamp(ay.min(by), ay.max(by))
        )
    );
    assert_eq!(raw(probe.clamp(hi, lo)), (ax.max(bx), ay.max(by)));
    assert_eq!(a.distance(b), (b - a).length());
}

// ---------------------------------------------------------------------------
// Agreement with the f64 reference (item 4).
// ---------------------------------------------------------------------------

/// Runs dot, length and normalisation in `S` and in `f64` (the library's own
/// reference impl, same code path) on inputs that are exact in both, and
/// bounds the difference by the sum of the two error analyses:
///
/// * **dot**: `S` is the exact value floored (< 1 ulp below; for `Fx` it is
///   exact, since 16+16 fraction bits fit in 32). The `f64` run rounds each
///   product and the sum: error ≤ 2u(|p₁| + |p₂|) (first order; the 1.01
///   factor absorbs the u² terms). The `S` result (< 2³¹, ≤ 63 significant
///   bits) converts to `f64` with error ≤ u·|dot|.
/// * **length**: `S` is within [0, 1 ulp) below the true length (exact floor
///   of the exact root); `f64` rounds x², y², their sum (radicand ≤ 2u
///   relative, halved by the root) and the root: ≤ 2u·|v|. The `S` length
///   (< 2¹⁷, ≤ 49 significant bits) converts exactly.
/// * **normalise**: each `S` component is c/len truncated, len ∈ (|v| − ulp,
///   |v|], so it is within ulp·(1 + 1/len) of c/|v|; the `f64` component
///   c/|v|₆₄ is within 3u of it (length 2u, quotient u).
fn check_f64_agreement<S: Fixed>(q: (i64, i64), r: (i64, i64)) {
    let (a, b) = (quantised::<S>(q), quantised::<S>(r));
    let (af, bf): (Vec2<f64>, Vec2<f64>) = (a.cast(), b.cast());
    // The cast is exact for these inputs.
    assert_eq!(af.cast::<S>(), a);
    let ulp = S::EPSILON.to_f64();

    let (p1, p2) = (af.x * bf.x, af.y * bf.y);
    let dot_s = a.dot(b).to_f64();
    let dot_f = af.dot(bf);
    let bound = ulp + 2.0 * U * (p1.abs() + p2.abs()) * 1.01 + U * dot_s.abs();
    assert!(
        (dot_s - dot_f).abs() <= bound,
        "{} dot {dot_s} vs f64 {dot_f} (bound {bound})",
        S::NAME
    );
    if S::FRAC == 32 {
        // For Fx the quantised dot is exact, and f64 is within its own bound
        // of it.
        assert!((dot_s - dot_f).abs() <= bound - ulp);
    }

    let len_s = a.length().to_f64();
    let len_f = af.length();
    let bound = ulp + 2.0 * U * len_f * 1.01;
    assert!(
        (len_s - len_f).abs() <= bound,
        "{} length {len_s} vs f64 {len_f} (bound {bound})",
        S::NAME
    );
    // And the fixed length is never above the true one.
    assert!(len_s <= len_f * (1.0 + 2.02 * U));

    match (a.try_normalize(), af.try_normalize()) {
        (None, None) => assert_eq!(a, Vec2::ZERO),
        (Some(n), Some(nf)) => {
            let len = a.length().to_f64();
            let bound = ulp * (1.0 + 1.0 / len) + 3.03 * U;
            let (nx, ny) = n.to_f64();
            assert!(
                (nx - nf.x).abs() <= bound && (ny - nf.y).abs() <= bound,
                "{} normalize {n:?} vs f64 {nf:?} (bound {bound})",
                S::NAME
            );
            if len >= 1.0 {
                assert!(bound <= 2.0 * ulp + 3.03 * U);
            }
        }
        (s, f) => panic!("{} normalize disagrees on zero: {s:?} vs {f:?}", S::NAME),
    }
}

// ---------------------------------------------------------------------------
// Properties.
// ---------------------------------------------------------------------------

proptest! {
    #![proptest_config(ProptestConfig::with_cases(CASES))]

    #[test]
    fn dot_cross_exact_in_world(
        a in world_pair(32), b in world_pair(32),
        c in world_pair(16), d in world_pair(16),
    ) {
        check_dot_cross::<I32F32>(vec(a), vec(b), true);
        check_dot_cross::<I48F16>(vec(c), vec(d), true);
    }

    #[test]
    fn dot_cross_exact_then_saturated_full_range(a in full_pair(), b in full_pair()) {
        check_dot_cross::<I32F32>(vec(a), vec(b), false);
        check_dot_cross::<I48F16>(vec(a), vec(b), false);
    }

    #[test]
    fn length_is_floor_of_exact_length(a in any_pair(32), b in any_pair(16)) {
        check_length::<I32F32>(vec(a));
        check_length::<I48F16>(vec(b));
    }

    #[test]
    fn axis_vectors_are_exact(c in raw_full()) {
        check_axis::<I32F32>(c);
        check_axis::<I48F16>(c);
    }

    #[test]
    fn normalize_bounds_world(a in world_pair(32), b in world_pair(16)) {
        check_normalize::<I32F32>(vec(a));
        check_normalize::<I48F16>(vec(b));
    }

    #[test]
    fn normalize_bounds_full_range(a in full_pair()) {
        check_normalize::<I32F32>(vec(a));
        check_normalize::<I48F16>(vec(a));
    }

    #[test]
    fn normalize_tiny_vectors(x in -64i64..=64, y in -64i64..=64) {
        // A few ulps long: the rounding of the length dominates here.
        check_normalize::<I32F32>(vec((x, y)));
        check_normalize::<I48F16>(vec((x, y)));
    }

    #[test]
    fn operators_saturate(a in any_pair(32), b in any_pair(32), s in raw_full()) {
        check_ops::<I32F32>(vec(a), vec(b), I32F32::from_raw(s));
        check_ops::<I48F16>(vec(a), vec(b), I48F16::from_raw(s));
    }

    #[test]
    fn fixed_agrees_with_f64_reference(q in quantised_pair(), r in quantised_pair()) {
        check_f64_agreement::<I32F32>(q, r);
        check_f64_agreement::<I48F16>(q, r);
    }
}

// ---------------------------------------------------------------------------
// Hand-computed unit tests.
// ---------------------------------------------------------------------------

#[test]
fn three_four_five() {
    let a = vec2(3.0, 4.0);
    assert_eq!(a.length(), fx(5.0));
    assert_eq!(a.length_squared(), fx(25.0));
    assert_eq!(a.distance(Vec2::ZERO), fx(5.0));
    // 3/5 and 4/5 truncated toward zero: 0.6·2³² = 2 576 980 377.6,
    // 0.8·2³² = 3 435 973 836.8.
    let n = a.try_normalize().expect("nonzero");
    assert_eq!(
        (n.x.to_bits(), n.y.to_bits()),
        (2_576_980_377, 3_435_973_836)
    );
    assert_eq!(a.try_normalize_with_length(), Some((n, fx(5.0))));
    assert_eq!(a.dot(Vec2::X), fx(3.0));
    assert_eq!(a.cross(Vec2::X), fx(-4.0));
    assert_eq!(Vec2::<Fx>::X.cross(Vec2::Y), Fx::ONE);
    assert_eq!(a.perp(), vec2(-4.0, 3.0));
}

#[test]
fn world_limit_products() {
    let w = f64::from(WORLD_LIMIT);
    let corner = vec2(w, w);
    // |corner|² = 2³¹ is one ulp past Fx::MAX: narrow saturates, wide exact.
    assert_eq!(corner.length_squared(), Fx::MAX);
    assert_eq!(corner.length_squared_wide(), I64F64::from_num(1u64 << 31));
    assert_eq!(corner.dot(vec2(w, -w)), Fx::ZERO);
    assert_eq!(vec2(w, 0.0).cross(vec2(0.0, w)), fx(1_073_741_824.0)); // 2³⁰
    assert_eq!(corner.cross(vec2(-w, w)), Fx::MAX); // 2³¹ saturates
    assert_eq!(corner.cross(vec2(w, -w)), Fx::MIN); // −2³¹ is exactly MIN
    // Corner to corner across the world: |d|² = 2·(2¹⁶)² = 2³³, exact in the
    // wide type; |d| = 2¹⁶·√2 = 92 681.900 023 68…, floored to a 2⁻³² ulp.
    let d = corner - (-corner);
    assert_eq!(d, vec2(2.0 * w, 2.0 * w));
    assert_eq!(d.length_squared_wide(), I64F64::from_num(1u64 << 33));
    let expect = (1u128 << 97).isqrt(); // √(2³³·2⁶⁴) in raw 2⁻³² units
    assert_eq!(u128::try_from(d.length().to_bits()).ok(), Some(expect));
    assert!((d.length().to_f64() - 92_681.900_023_683).abs() < 1e-6);
    let n = d.try_normalize().expect("nonzero");
    assert_eq!(n.x, n.y);
    assert!((n.x.to_f64() - core::f64::consts::FRAC_1_SQRT_2).abs() < 1e-9);
}

#[test]
fn full_range_saturation() {
    let low = Vec2::new(Fx::MIN, Fx::MIN);
    let high = Vec2::new(Fx::MAX, Fx::MAX);
    // MIN·MIN + MIN·MIN = 2⁶³: saturates the wide type, then the narrow one.
    assert_eq!(low.dot(low), Fx::MAX);
    assert_eq!(low.length_squared_wide(), I64F64::MAX);
    assert_eq!(low.dot(high), Fx::MIN);
    assert_eq!(low.cross(high), Fx::ZERO); // MIN·MAX − MIN·MAX
    assert_eq!(low.length(), Fx::MAX);
    assert_eq!(high.length(), Fx::MAX);
    // Saturated length, still a unit vector (the halving path); before the
    // fix this returned about (−1, −1).
    let n = low.try_normalize().expect("nonzero");
    assert_eq!(n.x, n.y);
    assert!((n.x.to_f64() + core::f64::consts::FRAC_1_SQRT_2).abs() < 1e-9);
    let m = Vec2::new(Fx::MAX, Fx::from_bits(1))
        .try_normalize()
        .expect("nonzero");
    assert_eq!(m.x, Fx::ONE);
    // Operators saturate component-wise.
    let one = Vec2::new(Fx::ONE, Fx::ONE);
    assert_eq!(high + one, high);
    assert_eq!(low - one, low);
    assert_eq!(-low, high);
    assert_eq!(
        -high,
        Vec2::new(Fx::from_bits(-i64::MAX), Fx::from_bits(-i64::MAX))
    );
    assert_eq!(high * fx(2.0), high);
    assert_eq!(high * fx(-2.0), low);
    assert_eq!(low.abs(), high);
    assert_eq!(high.mul_elements(low), low);
}

#[test]
fn tiny_vectors() {
    let e = Fx::from_bits(1);
    // One ulp long: the squared length (one wide ulp) has a nonzero root.
    let a = Vec2::new(e, Fx::ZERO);
    assert_eq!(a.length(), e);
    assert_eq!(a.try_normalize(), Some(Vec2::X));
    // (ulp, ulp): √2 ulp floors to 1 ulp, so the quotients are exactly 1:
    // |n| = √2, the documented worst case (within 2 ulp/|v| + 2 ulp of 1).
    let b = Vec2::new(e, e);
    assert_eq!(b.length(), e);
    assert_eq!(b.try_normalize(), Some(Vec2::new(Fx::ONE, Fx::ONE)));
    assert_eq!(Vec2::<Fx>::ZERO.try_normalize(), None);
    assert_eq!(Vec2::<Fx>::ZERO.normalize_or_zero(), Vec2::ZERO);
    assert_eq!(Vec2::<Fx>::ZERO.try_normalize_with_length(), None);
    assert_eq!(Vec2::<Fx>::ZERO.length(), Fx::ZERO);
}

#[test]
fn component_helpers() {
    let a = vec2(1.0, -2.0);
    let b = vec2(-3.0, 4.0);
    assert_eq!(a.min(b), vec2(-3.0, -2.0));
    assert_eq!(a.max(b), vec2(1.0, 4.0));
    assert_eq!(b.abs(), vec2(3.0, 4.0));
    assert_eq!(
        vec2(5.0, -5.0).clamp(vec2(-1.0, -1.0), vec2(1.0, 1.0)),
        vec2(1.0, -1.0)
    );
    // low > high: low wins.
    assert_eq!(
        vec2(0.0, 0.0).clamp(vec2(2.0, 2.0), vec2(1.0, 1.0)),
        vec2(2.0, 2.0)
    );
    assert_eq!(a + b, vec2(-2.0, 2.0));
    assert_eq!(a - b, vec2(4.0, -6.0));
    assert_eq!(a * fx(0.5), vec2(0.5, -1.0));
    assert_eq!(a.mul_elements(b), vec2(-3.0, -8.0));
    assert_eq!(Vec2::<Fx>::default(), Vec2::ZERO);
    assert_eq!(
        (Vec2::<Fx>::X, Vec2::<Fx>::Y),
        (vec2(1.0, 0.0), vec2(0.0, 1.0))
    );
    assert_eq!(a.to_f64(), (1.0, -2.0));
    assert_eq!(a.cast::<f64>(), Vec2::new(1.0, -2.0));
    assert_eq!(Vec2::<f64>::new(1.0, -2.0).cast::<Fx>(), a);
}

#[test]
fn f64_reference_vectors() {
    // The reference type runs the same code; zero normalises to None and
    // the defined results hold.
    let z = Vec2::<f64>::ZERO;
    assert_eq!(z.try_normalize(), None);
    assert_eq!(z.length(), 0.0);
    let a = Vec2::<f64>::new(3.0, 4.0);
    assert_eq!(a.length(), 5.0);
    assert_eq!(a.try_normalize(), Some(Vec2::new(0.6, 0.8)));
    assert_eq!(a.cross(Vec2::X), -4.0);
    let f = Vec2::<f32>::new(3.0, 4.0);
    assert_eq!(f.length(), 5.0);
    assert_eq!(f.dot(f), 25.0);
}
