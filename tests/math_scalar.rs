//! The scalar overflow policy, wide products and roots, checked bit for bit
//! against reference arithmetic on the raw two's complement bits in `i128`.
//!
//! Every fixed-point expectation here is *exact* (an `assert_eq!` on raw
//! bits), so the same assertions pass in debug (overflow checks on) and in
//! release: the policy is "saturate", never "panic in debug, wrap in
//! release". The rounding modes the reference encodes are the ones the
//! `fixed` crate documents and the engine relies on:
//!
//! * `mul`, `narrow`, `half`, `mul_add_mul`: round toward −∞ (arithmetic
//!   shift of the exact product);
//! * `div`, `from_ratio`: truncate toward zero (`i128` division);
//! * `sqrt`, `sqrt_narrow`: round down (`isqrt` of the exact radicand);
//! * `from_f64`: round to nearest, ties to even.
//!
//! Every property runs for both fixed types, `I32F32` (= `Fx`) and
//! `I48F16`, on the same raw `i64` bits (both types store an `i64`).
//! Case counts: [`CASES`] (8192) per property, 32× proptest's default of 256;
//! each property is a few integer operations, so this is cheap even in debug.

use clockwork2d::math::WideFloat;
use clockwork2d::math::{Fx, Scalar, WideScalar, fx};
use fixed::types::{I32F32, I48F16, I64F64, I96F32};
use proptest::prelude::*;

mod common;
use common::raw_fixed::{Fixed, RAW_MAX, WideFixed, sat};

/// Cases per property (proptest's default is 256).
const CASES: u32 = 8192;

// ---------------------------------------------------------------------------
// Raw-bit access for the reference computations.
// ---------------------------------------------------------------------------

// `Fixed`, `WideFixed`, `sat`, `RAW_MIN`/`RAW_MAX`: tests/common/raw_fixed.rs.

/// Fraction bits dropped when narrowing `S::Wide` to `S`.
fn narrow_shift<S: Fixed>() -> u32 {
    <S::Wide as WideFixed>::FRAC - S::FRAC
}

/// floor(√v) for a nonnegative `i128`.
fn isqrt(v: i128) -> i128 {
    let v = u128::try_from(v).expect("nonnegative radicand");
    i128::try_from(v.isqrt()).expect("root of a u128 fits")
}

// ---------------------------------------------------------------------------
// Strategies.
// ---------------------------------------------------------------------------

/// Raw `i64` bits spread over every magnitude (log-uniform), plus the
/// boundary neighbourhoods where saturation happens, plus powers of two.
fn raw_bits() -> impl Strategy<Value = i64> {
    let log_uniform = (1u32..=63, any::<u64>(), any::<bool>()).prop_map(|(k, r, neg)| {
        let m = i64::try_from(r >> (64 - k)).expect("below 2^63");
        if neg { -m } else { m }
    });
    let pow2 = (0u32..63, any::<bool>()).prop_map(|(k, neg)| {
        let m = 1i64 << k;
        if neg { -m } else { m }
    });
    prop_oneof![
        4 => log_uniform,
        2 => any::<i64>(),
        1 => (0i64..1 << 12).prop_map(|d| i64::MAX - d),
        1 => (0i64..1 << 12).prop_map(|d| i64::MIN + d),
        1 => -(1i64 << 12)..(1i64 << 12),
        1 => pow2,
    ]
}

/// Raw wide (`i128`) bits: every magnitude, exact squares of narrow raw
/// values and their neighbours (where a root changes by one ulp), and the
/// extremes.
fn wide_bits() -> impl Strategy<Value = i128> {
    let log_uniform = (1u32..=127, any::<u128>(), any::<bool>()).prop_map(|(k, r, neg)| {
        let m = i128::try_from(r >> (128 - k)).expect("below 2^127");
        if neg { -m } else { m }
    });
    let near_square = (raw_bits(), -4i128..=4).prop_map(|(r, d)| {
        let r = i128::from(r);
        (r * r).saturating_add(d)
    });
    prop_oneof![
        4 => log_uniform,
        3 => near_square,
        1 => any::<i128>(),
        1 => (0i128..1 << 12).prop_map(|d| i128::MAX - d),
        1 => -(1i128 << 12)..(1i128 << 12),
    ]
}

// ---------------------------------------------------------------------------
// Generic checks (trait methods only: on a concrete `I32F32` the `fixed`
// crate's inherent `abs`/`sqrt`/`min`/... would shadow them).
// ---------------------------------------------------------------------------

fn check_add_sub<S: Fixed>(a: i64, b: i64) {
    let (x, y) = (S::from_raw(a), S::from_raw(b));
    let (a, b) = (i128::from(a), i128::from(b));
    assert_eq!(x.add(y).raw(), sat(a + b), "{} add", S::NAME);
    assert_eq!(x.sub(y).raw(), sat(a - b), "{} sub", S::NAME);
}

fn check_mul<S: Fixed>(a: i64, b: i64) {
    let (x, y) = (S::from_raw(a), S::from_raw(b));
    let (a, b) = (i128::from(a), i128::from(b));
    // |a·b| ≤ 2^126 fits i128; `>>` on i128 is floor (toward −∞).
    assert_eq!(x.mul(y).raw(), sat((a * b) >> S::FRAC), "{} mul", S::NAME);
    assert_eq!(y.mul(x), x.mul(y), "{} mul commutes", S::NAME);
}

fn check_mul_int<S: Fixed>(a: i64, n: i32) {
    let x = S::from_raw(a);
    let expected = sat(i128::from(a) * i128::from(n));
    assert_eq!(x.mul_int(n).raw(), expected, "{} mul_int", S::NAME);
}

fn check_div<S: Fixed>(a: i64, b: i64) {
    let (x, y) = (S::from_raw(a), S::from_raw(b));
    if b == 0 {
        let expected = match a.signum() {
            1 => S::MAX,
            -1 => S::MIN,
            _ => S::ZERO,
        };
        assert_eq!(x.div(y), expected, "{} div by zero", S::NAME);
        assert_eq!(x.checked_div(y), None, "{} checked_div by zero", S::NAME);
        return;
    }
    // |a|·2^FRAC ≤ 2^95 fits i128; i128 `/` truncates toward zero.
    let exact = (i128::from(a) << S::FRAC) / i128::from(b);
    assert_eq!(x.div(y).raw(), sat(exact), "{} div", S::NAME);
    let checked = x.checked_div(y).map(S::raw);
    let expected = (sat(exact) == exact).then_some(exact);
    assert_eq!(checked, expected, "{} checked_div", S::NAME);
}

fn check_neg_abs_half<S: Fixed>(a: i64) {
    let x = S::from_raw(a);
    let a = i128::from(a);
    assert_eq!(x.neg().raw(), sat(-a), "{} neg", S::NAME);
    assert_eq!(x.abs().raw(), sat(a.abs()), "{} abs", S::NAME);
    // half() is an arithmetic shift: floor(a / 2), never overflows.
    let h = x.half().raw();
    assert_eq!(h, a.div_euclid(2), "{} half", S::NAME);
    assert!(2 * h == a || 2 * h == a - 1, "{} half", S::NAME);
}

fn check_sqrt<S: Fixed>(a: i64) {
    let x = S::from_raw(a);
    let r = x.sqrt().raw();
    if a <= 0 {
        assert_eq!(r, 0, "{} sqrt of non-positive", S::NAME);
        return;
    }
    // The root of a (FRAC fraction bits) has FRAC fraction bits: its raw
    // value is floor(√(a·2^FRAC)); a·2^FRAC < 2^95.
    let radicand = i128::from(a) << S::FRAC;
    assert_eq!(r, isqrt(radicand), "{} sqrt", S::NAME);
    // Equivalently (and what "exact to one ulp" means): r² ≤ x < (r + ulp)².
    assert!(r * r <= radicand && radicand < (r + 1) * (r + 1));
}

fn check_order<S: Fixed>(a: i64, b: i64, c: i64) {
    let (x, y, z) = (S::from_raw(a), S::from_raw(b), S::from_raw(c));
    assert_eq!(x.min(y).raw(), i128::from(a.min(b)));
    assert_eq!(x.max(y).raw(), i128::from(a.max(b)));
    // clamp(low, high): `low` wins when low > high (documented), otherwise
    // the usual clamp.
    let expected = if b > c { b } else { a.clamp(b, c) };
    assert_eq!(x.clamp(y, z).raw(), i128::from(expected));
    assert_eq!(x.signum().raw(), i128::from(a.signum()) << S::FRAC);
    assert_eq!(x.is_negative(), a < 0);
    assert_eq!(x.is_positive(), a > 0);
    assert_eq!(x.to_hash_bits(), a as u64);
}

fn check_mul_add_mul<S: Fixed>(a: i64, b: i64, c: i64, d: i64) {
    let [x, y, z, w] = [a, b, c, d].map(S::from_raw);
    let [a, b, c, d] = [a, b, c, d].map(i128::from);
    // Each product ≤ 2^126; the wide type is the whole i128, so the wide
    // sum saturates exactly like i128::saturating_add (and anything beyond
    // i128 is far beyond the narrow range anyway).
    let sum = (a * b).saturating_add(c * d);
    let diff = (a * b).saturating_sub(c * d);
    assert_eq!(
        S::mul_add_mul(x, y, z, w).raw(),
        sat(sum >> S::FRAC),
        "{} mul_add_mul",
        S::NAME
    );
    assert_eq!(
        S::mul_sub_mul(x, y, z, w).raw(),
        sat(diff >> S::FRAC),
        "{} mul_sub_mul",
        S::NAME
    );
}

fn check_from_ratio<S: Fixed>(n: i32, d: i32) {
    let r = S::from_ratio(n, d);
    if d == 0 {
        let expected = match n.signum() {
            1 => S::MAX,
            -1 => S::MIN,
            _ => S::ZERO,
        };
        assert_eq!(r, expected, "{} from_ratio(_, 0)", S::NAME);
        return;
    }
    // Exact quotient truncated toward zero; only −2^31 / −1 = 2^31 can
    // leave I32F32's range (and saturates to MAX).
    let exact = (i128::from(n) << S::FRAC) / i128::from(d);
    assert_eq!(r.raw(), sat(exact), "{} from_ratio", S::NAME);
}

fn check_from_int<S: Fixed>(n: i32) {
    // Both types hold every i32 exactly.
    assert_eq!(S::from_int(n).raw(), i128::from(n) << S::FRAC);
}

fn check_from_f64_exact<S: Fixed>(a: i64) {
    // A raw value with at most 53 significant bits is exactly an f64, and
    // converting it back is exact (no rounding, no saturation).
    let x = S::from_raw(a);
    let f = x.to_f64();
    if a.unsigned_abs() < 1 << 53 {
        assert_eq!(S::from_f64(f), x, "{} f64 round trip", S::NAME);
    }
    // Wider raw values (|a| < 2^63) are rounded to nearest by to_f64: off by
    // at most half an f64 ulp, 2^(62 − 52) / 2 = 2^9 raw (or they round up
    // to ±2^63 and saturate back to the extreme, even closer).
    let back = S::from_f64(f);
    let err = (back.raw() - i128::from(a)).abs();
    assert!(err <= 1 << 9, "{} to_f64/from_f64 drift {err}", S::NAME);
}

fn check_wide<S: Fixed>(a: i64, b: i64) {
    let (x, y) = (S::from_raw(a), S::from_raw(b));
    let p = i128::from(a) * i128::from(b);
    // The wide product is exact: FRAC + FRAC fraction bits is the wide
    // type's FRAC for both pairs (32+32 = 64, 16+16 = 32).
    assert_eq!(x.wide_mul(y).raw(), p, "{} wide_mul", S::NAME);
    assert_eq!(
        <S::Wide as WideScalar>::from_narrow(x).raw(),
        i128::from(a) << narrow_shift::<S>(),
        "{} from_narrow",
        S::NAME
    );
    // Narrowing the exact product is the saturating floor of it, i.e. mul.
    assert_eq!(
        x.wide_mul(y).narrow(),
        x.mul(y),
        "{} narrow(wide_mul)",
        S::NAME
    );
}

fn check_wide_ops<S: Fixed>(u: i128, v: i128) {
    let (p, q) = (
        <S::Wide as WideFixed>::from_raw(u),
        <S::Wide as WideFixed>::from_raw(v),
    );
    assert_eq!(p.add(q).raw(), u.saturating_add(v), "{} wide add", S::NAME);
    assert_eq!(p.sub(q).raw(), u.saturating_sub(v), "{} wide sub", S::NAME);
    assert_eq!(p.is_negative(), u < 0);
    // narrow: drop the extra fraction bits rounding toward −∞, saturate.
    let narrowed = p.narrow().raw();
    assert_eq!(
        narrowed,
        sat(u >> narrow_shift::<S>()),
        "{} narrow",
        S::NAME
    );
}

fn check_sqrt_narrow<S: Fixed>(u: i128) {
    let p = <S::Wide as WideFixed>::from_raw(u);
    let r = p.sqrt_narrow().raw();
    if u <= 0 {
        assert_eq!(r, 0, "{} sqrt_narrow of non-positive", S::NAME);
        return;
    }
    // Wide raw u has 2·FRAC fraction bits, so floor(√u) is the root's raw
    // value with FRAC fraction bits: the true root rounded down to a narrow
    // ulp, saturated to MAX once it reaches 2^(63 − FRAC).
    let root = isqrt(u);
    assert_eq!(r, root.min(RAW_MAX), "{} sqrt_narrow({u})", S::NAME);
    // Within one narrow ulp: r² ≤ u < (r + 1)² whenever not saturated.
    if root <= RAW_MAX {
        assert!(
            r * r <= u && u < (r + 1) * (r + 1),
            "{} sqrt_narrow",
            S::NAME
        );
    }
    // A nonzero radicand always has a nonzero root (1 ulp² ↦ 1 ulp).
    assert!(r >= 1);
}

// ---------------------------------------------------------------------------
// Properties.
// ---------------------------------------------------------------------------

proptest! {
    #![proptest_config(ProptestConfig::with_cases(CASES))]

    #[test]
    fn add_sub_saturate_like_i128(a in raw_bits(), b in raw_bits()) {
        check_add_sub::<I32F32>(a, b);
        check_add_sub::<I48F16>(a, b);
    }

    #[test]
    fn mul_saturates_and_rounds_down(a in raw_bits(), b in raw_bits()) {
        check_mul::<I32F32>(a, b);
        check_mul::<I48F16>(a, b);
    }

    #[test]
    fn mul_int_saturates(a in raw_bits(), n in any::<i32>()) {
        check_mul_int::<I32F32>(a, n);
        check_mul_int::<I48F16>(a, n);
    }

    #[test]
    fn div_truncates_saturates_and_defines_zero(
        a in raw_bits(),
        b in prop_oneof![4 => raw_bits(), 1 => Just(0i64)],
    ) {
        check_div::<I32F32>(a, b);
        check_div::<I48F16>(a, b);
    }

    #[test]
    fn neg_abs_half(a in raw_bits()) {
        check_neg_abs_half::<I32F32>(a);
        check_neg_abs_half::<I48F16>(a);
    }

    #[test]
    fn sqrt_is_floor_of_exact_root(a in raw_bits()) {
        check_sqrt::<I32F32>(a);
        check_sqrt::<I48F16>(a);
    }

    #[test]
    fn min_max_clamp_signum_hash(a in raw_bits(), b in raw_bits(), c in raw_bits()) {
        check_order::<I32F32>(a, b, c);
        check_order::<I48F16>(a, b, c);
    }

    #[test]
    fn mul_add_mul_is_one_exact_sum_then_saturate(
        a in raw_bits(), b in raw_bits(), c in raw_bits(), d in raw_bits(),
    ) {
        check_mul_add_mul::<I32F32>(a, b, c, d);
        check_mul_add_mul::<I48F16>(a, b, c, d);
    }

    #[test]
    fn from_ratio_truncates_and_defines_zero(
        n in any::<i32>(),
        d in prop_oneof![4 => any::<i32>(), 1 => Just(0i32), 1 => -3i32..=3],
    ) {
        check_from_ratio::<I32F32>(n, d);
        check_from_ratio::<I48F16>(n, d);
    }

    #[test]
    fn from_int_is_exact(n in any::<i32>()) {
        check_from_int::<I32F32>(n);
        check_from_int::<I48F16>(n);
    }

    #[test]
    fn from_f64_round_trips(a in raw_bits()) {
        check_from_f64_exact::<I32F32>(a);
        check_from_f64_exact::<I48F16>(a);
    }

    #[test]
    fn from_f64_saturates_out_of_range(m in 1.0f64..1e300, neg in any::<bool>()) {
        // Anything at or beyond 2^31 (Fx) / 2^47 (I48F16) in magnitude
        // saturates; below −2^31 saturates to MIN.
        let big = if neg { -(m + 2f64.powi(47)) } else { m + 2f64.powi(47) };
        let (fx_sat, i48_sat) = if neg {
            (Fx::MIN, <I48F16 as Scalar>::MIN)
        } else {
            (Fx::MAX, <I48F16 as Scalar>::MAX)
        };
        prop_assert_eq!(<Fx as Scalar>::from_f64(big), fx_sat);
        prop_assert_eq!(<I48F16 as Scalar>::from_f64(big), i48_sat);
    }

    #[test]
    fn wide_mul_is_exact(a in raw_bits(), b in raw_bits()) {
        check_wide::<I32F32>(a, b);
        check_wide::<I48F16>(a, b);
    }

    #[test]
    fn wide_add_sub_narrow_saturate(u in wide_bits(), v in wide_bits()) {
        check_wide_ops::<I32F32>(u, v);
        check_wide_ops::<I48F16>(u, v);
    }

    #[test]
    fn sqrt_narrow_is_floor_of_exact_root(u in wide_bits()) {
        check_sqrt_narrow::<I32F32>(u);
        check_sqrt_narrow::<I48F16>(u);
    }

    #[test]
    fn sqrt_narrow_of_exact_square_is_exact(a in raw_bits()) {
        // √(x²) = |x| exactly, saturating only at |MIN| = 2^(63−FRAC).
        // (This caught the fast path that narrowed x² before the root:
        // (1 + ulp)² gave 1.)
        for s in [a, a.saturating_add(1), a.saturating_sub(1)] {
            let x = Fx::from_bits(s);
            prop_assert_eq!(x.wide_mul(x).sqrt_narrow(), Scalar::abs(x));
            let y = I48F16::from_bits(s);
            prop_assert_eq!(y.wide_mul(y).sqrt_narrow(), Scalar::abs(y));
        }
    }

    #[test]
    fn float_references_define_zero_division_and_negative_roots(
        x in -1e30f64..1e30,
        small in -1e30f32..1e30,
    ) {
        check_float_reference::<f64>(x);
        check_float_reference::<f32>(small);
        check_float_reference::<f64>(f64::from(small));
    }
}

// ---------------------------------------------------------------------------
// The f64/f32 references (item 5).
// ---------------------------------------------------------------------------

/// The float references share the fixed types' defined results for a zero
/// divisor and a negative radicand (their other overflow is IEEE).
fn check_float_reference<S: Scalar + Into<f64>>(x: S) {
    let v: f64 = x.into();
    let by_zero = x.div(S::ZERO);
    let expected = if v > 0.0 {
        S::MAX
    } else if v < 0.0 {
        S::MIN
    } else {
        S::ZERO
    };
    assert_eq!(by_zero, expected, "{} div by zero", S::NAME);
    assert_eq!(x.div(S::ZERO.neg()), expected, "{} div by −0", S::NAME);
    assert_eq!(x.checked_div(S::ZERO), None, "{} checked_div(0)", S::NAME);
    assert_eq!(
        x.checked_div(S::ZERO.neg()),
        None,
        "{} checked_div(−0)",
        S::NAME
    );
    let r: f64 = x.sqrt().into();
    if v <= 0.0 {
        assert_eq!(r.to_bits(), 0, "{} sqrt of non-positive is +0", S::NAME);
    } else {
        assert!(r > 0.0 && (r * r - v).abs() <= v * 1e-6);
    }
    // x·|x| is x² for x > 0 and −x² (a negative radicand) for x < 0.
    let w = x.wide_mul(x.abs());
    let wr: f64 = w.sqrt_narrow().into();
    if v <= 0.0 {
        assert_eq!(wr.to_bits(), 0, "{} sqrt_narrow of non-positive", S::NAME);
    } else {
        assert!((wr - v).abs() <= v * 1e-6, "{} sqrt_narrow", S::NAME);
    }
    assert!(S::IS_REFERENCE, "{} is a reference type", S::NAME);
}

#[test]
fn float_reference_special_values() {
    // NaN converts to zero; infinities and huge values are kept (IEEE is
    // the references' "saturation").
    assert_eq!(<f64 as Scalar>::from_f64(f64::NAN).to_bits(), 0);
    assert_eq!(<f32 as Scalar>::from_f64(f64::NAN).to_bits(), 0);
    assert_eq!(<f32 as Scalar>::from_f64(1e300), f32::INFINITY);
    assert_eq!(<f64 as Scalar>::sqrt(f64::NEG_INFINITY), 0.0);
    assert_eq!(<f64 as Scalar>::sqrt(-0.0).to_bits(), 0);
    assert_eq!(<f32 as Scalar>::sqrt(-f32::MIN_POSITIVE), 0.0);
    assert_eq!(<f64 as Scalar>::from_ratio(3, 0), f64::MAX);
    assert_eq!(<f64 as Scalar>::from_ratio(-3, 0), f64::MIN);
    assert_eq!(<f64 as Scalar>::from_ratio(0, 0), 0.0);
    assert_eq!(<f32 as Scalar>::from_ratio(1, 4), 0.25);
    let negative: WideFloat<f64> = Scalar::wide_mul(-2.0f64, 3.0);
    assert_eq!(negative.sqrt_narrow(), 0.0);
    assert_eq!(<f64 as Scalar>::half(3.0), 1.5);
    assert_eq!(<f32 as Scalar>::mul_int(1.5, -4), -6.0);
    assert_eq!(
        (f64::ID, f32::ID, f64::NAME, f32::NAME),
        (100, 101, "f64", "f32")
    );
}

// ---------------------------------------------------------------------------
// Hand-computed unit tests.
// ---------------------------------------------------------------------------

#[test]
fn constants_are_the_raw_extremes() {
    assert_eq!(<Fx as Scalar>::MAX.to_bits(), i64::MAX);
    assert_eq!(<Fx as Scalar>::MIN.to_bits(), i64::MIN);
    assert_eq!(<Fx as Scalar>::EPSILON.to_bits(), 1);
    assert_eq!(<Fx as Scalar>::ONE.to_bits(), 1 << 32);
    assert_eq!(<I48F16 as Scalar>::ONE.to_bits(), 1 << 16);
    assert_eq!(<I48F16 as Scalar>::EPSILON.to_bits(), 1);
    assert_eq!((<Fx as Scalar>::NAME, <Fx as Scalar>::ID), ("I32F32", 1));
    assert_eq!(
        (<I48F16 as Scalar>::NAME, <I48F16 as Scalar>::ID),
        ("I48F16", 2)
    );
    assert_eq!(
        (
            <Fx as Scalar>::IS_REFERENCE,
            <I48F16 as Scalar>::IS_REFERENCE
        ),
        (false, false)
    );
}

#[test]
fn overflow_edges_by_hand() {
    let (max, min, one) = (Fx::MAX, Fx::MIN, Fx::ONE);
    assert_eq!(max.add(one), max);
    assert_eq!(min.sub(one), min);
    assert_eq!(Scalar::neg(min), max);
    assert_eq!(Scalar::abs(min), max);
    assert_eq!(Scalar::neg(max).to_bits(), -i64::MAX);
    // 46 341² = 2 147 488 281 > 2^31 − 1: saturates; 46 340² fits.
    assert_eq!(fx(46_341.0).mul(fx(46_341.0)), max);
    assert_eq!(fx(46_341.0).mul(fx(-46_341.0)), min);
    assert_eq!(fx(46_340.0).mul(fx(46_340.0)), fx(2_147_395_600.0));
    assert_eq!(min.mul_int(-1), max);
    assert_eq!(fx(2.5).mul_int(3), fx(7.5));
    assert_eq!(fx(1.0).mul_int(i32::MIN), fx(-2_147_483_648.0));
    // Products round toward −∞: (−1 ulp)·½ = −1 ulp, (+1 ulp)·½ = 0.
    let half = fx(0.5);
    assert_eq!(Fx::from_bits(-1).mul(half).to_bits(), -1);
    assert_eq!(Fx::from_bits(1).mul(half).to_bits(), 0);
    // Quotients truncate toward zero: ±7 ulp / 2 = ±3 ulp.
    assert_eq!(Fx::from_bits(7).div(fx(2.0)).to_bits(), 3);
    assert_eq!(Fx::from_bits(-7).div(fx(2.0)).to_bits(), -3);
    assert_eq!(min.div(fx(-1.0)), max);
    assert_eq!(min.checked_div(fx(-1.0)), None);
    assert_eq!(fx(1.0).checked_div(fx(4.0)), Some(fx(0.25)));
    assert_eq!(fx(3.0).div(Fx::ZERO), max);
    assert_eq!(fx(-3.0).div(Fx::ZERO), min);
    assert_eq!(Fx::ZERO.div(Fx::ZERO), Fx::ZERO);
    assert_eq!(Fx::ZERO.checked_div(Fx::ZERO), None);
    assert_eq!(Fx::from_bits(-3).half().to_bits(), -2);
    assert_eq!(min.half().to_bits(), i64::MIN / 2);
    assert_eq!(max.half().to_bits(), i64::MAX / 2);
}

#[test]
fn sqrt_by_hand() {
    assert_eq!(Scalar::sqrt(fx(-4.0)), Fx::ZERO);
    assert_eq!(Scalar::sqrt(Fx::MIN), Fx::ZERO);
    assert_eq!(Scalar::sqrt(fx(6.25)), fx(2.5));
    assert_eq!(Scalar::sqrt(Fx::from_bits(1)).to_bits(), 1 << 16); // √2⁻³² = 2⁻¹⁶
    // √MAX: the raw root is floor(√((2^63 − 1)·2^32)).
    let expect = isqrt((i128::from(i64::MAX)) << 32);
    assert_eq!(i128::from(Scalar::sqrt(Fx::MAX).to_bits()), expect);
    assert_eq!(Scalar::sqrt(<I48F16 as Scalar>::from_int(-1)), I48F16::ZERO);
    assert_eq!(Scalar::sqrt(I48F16::from_num(144)), I48F16::from_num(12));
}

#[test]
fn sqrt_narrow_by_hand() {
    let wide = |bits: i128| I64F64::from_bits(bits);
    // One wide ulp (2^-64) is a squared length of one narrow ulp: root 2^-32.
    assert_eq!(wide(1).sqrt_narrow().to_bits(), 1);
    assert_eq!(wide(3).sqrt_narrow().to_bits(), 1); // √3 ulp² = 1.73 ulp
    assert_eq!(wide(4).sqrt_narrow().to_bits(), 2);
    assert_eq!(I96F32::from_bits(1).sqrt_narrow().to_bits(), 1);
    // (1 + ulp)² = 1 + 2^-31 + 2^-64: the root is exactly 1 + ulp. The old
    // fast path narrowed first (dropping 2^-64) and returned 1.
    let f = Fx::from_bits((1 << 32) + 1);
    assert_eq!(f.wide_mul(f).sqrt_narrow(), f);
    let g = I48F16::from_bits((1 << 16) + 1);
    assert_eq!(g.wide_mul(g).sqrt_narrow(), g);
    // Above the narrow MAX but below 2^62: exact (2^40 ↦ 2^20).
    assert_eq!(I64F64::from_num(1u64 << 40).sqrt_narrow(), fx(1_048_576.0));
    // Just below 2^62: floor(√(2^62 − 2^-64)) = MAX (2^31 − 2^-32).
    assert_eq!(wide((1 << 126) - 1).sqrt_narrow(), Fx::MAX);
    // From 2^62 on, the root is ≥ 2^31 and saturates to MAX.
    assert_eq!(wide(1 << 126).sqrt_narrow(), Fx::MAX);
    assert_eq!(I64F64::MAX.sqrt_narrow(), Fx::MAX);
    assert_eq!(I96F32::MAX.sqrt_narrow(), <I48F16 as Scalar>::MAX);
    assert_eq!(wide(-1).sqrt_narrow(), Fx::ZERO);
    assert_eq!(I64F64::MIN.sqrt_narrow(), Fx::ZERO);
    assert_eq!(I64F64::ZERO.sqrt_narrow(), Fx::ZERO);
}

#[test]
fn from_f64_by_hand() {
    let ulp = 2f64.powi(-32);
    assert_eq!(fx(f64::NAN), Fx::ZERO);
    assert_eq!(fx(-f64::NAN), Fx::ZERO);
    assert_eq!(fx(f64::INFINITY), Fx::MAX);
    assert_eq!(fx(f64::NEG_INFINITY), Fx::MIN);
    assert_eq!(fx(1e300), Fx::MAX);
    assert_eq!(fx(-1e300), Fx::MIN);
    assert_eq!(fx(f64::MAX), Fx::MAX);
    // 2^31 is one ulp past MAX; −2^31 is exactly MIN.
    assert_eq!(fx(2_147_483_648.0), Fx::MAX);
    assert_eq!(fx(-2_147_483_648.0), Fx::MIN);
    assert_eq!(fx(-2_147_483_649.0), Fx::MIN);
    // Nearest, ties to even.
    assert_eq!(fx(0.5 * ulp).to_bits(), 0);
    assert_eq!(fx(1.5 * ulp).to_bits(), 2);
    assert_eq!(fx(2.5 * ulp).to_bits(), 2);
    assert_eq!(fx(3.5 * ulp).to_bits(), 4);
    assert_eq!(fx(-2.5 * ulp).to_bits(), -2);
    assert_eq!(fx(0.6 * ulp).to_bits(), 1);
    assert_eq!(fx(f64::MIN_POSITIVE).to_bits(), 0);
    assert_eq!(fx(-0.0).to_bits(), 0);
    assert_eq!(<I48F16 as Scalar>::from_f64(f64::NAN), I48F16::ZERO);
    assert_eq!(<I48F16 as Scalar>::from_f64(1e20), <I48F16 as Scalar>::MAX);
    assert_eq!(<I48F16 as Scalar>::from_f64(-1e20), <I48F16 as Scalar>::MIN);
    assert_eq!(<I48F16 as Scalar>::from_f64(0.75), I48F16::from_num(0.75));
}

#[test]
fn from_ratio_by_hand() {
    assert_eq!(Fx::from_ratio(1, 3).to_bits(), 0x5555_5555); // ⅓ truncated
    assert_eq!(Fx::from_ratio(-1, 3).to_bits(), -0x5555_5555);
    assert_eq!(Fx::from_ratio(2, 3).to_bits(), 0xAAAA_AAAA);
    assert_eq!(Fx::from_ratio(1, 60), Fx::ONE.div(fx(60.0)));
    assert_eq!(Fx::from_ratio(7, 0), Fx::MAX);
    assert_eq!(Fx::from_ratio(-7, 0), Fx::MIN);
    assert_eq!(Fx::from_ratio(0, 0), Fx::ZERO);
    assert_eq!(Fx::from_ratio(i32::MIN, -1), Fx::MAX);
    assert_eq!(Fx::from_ratio(i32::MIN, 1), Fx::MIN);
    assert_eq!(
        I48F16::from_ratio(i32::MIN, -1),
        I48F16::from_num(1u64 << 31)
    );
}
