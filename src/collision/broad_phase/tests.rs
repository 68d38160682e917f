//! Tests of the broad phase against a brute-force reference.
//!
//! The reference is the definition in the module docs, pair by pair
//! (O(n²)); the original single sweep is a second reference. The phase is
//! called repeatedly on one [`BroadPhase`] with changing sets, so the kept
//! x order (moves, appearing and disappearing proxies, class changes) is
//! exercised, for every scalar type.

use fixed::types::I48F16;
use proptest::prelude::*;

use super::bands::MAX_BANDS;
use super::item::order_key;
use super::*;
use crate::math::{Fx, WORLD_LIMIT};

/// The pair set by definition: for each two classed proxies, the later in
/// `(min_x, index)` order must start within the earlier's x range, the y
/// ranges must overlap and the classes pair.
fn brute_force<S: Scalar>(proxies: &[Proxy<S>]) -> Vec<(u32, u32)> {
    let mut pairs = Vec::new();
    for (i, p) in proxies.iter().enumerate() {
        for q in &proxies[i + 1..] {
            let (Some(pc), Some(qc)) = (p.class, q.class) else {
                continue;
            };
            let q_first = q.min_x < p.min_x || (q.min_x == p.min_x && q.index < p.index);
            let (first, second) = if q_first { (q, p) } else { (p, q) };
            if second.min_x <= first.max_x
                && second.min_y <= first.max_y
                && first.min_y <= second.max_y
                && pc.pairs_with(qc)
            {
                pairs.push((p.index.min(q.index), p.index.max(q.index)));
            }
        }
    }
    pairs.sort_unstable();
    pairs
}

/// The broad phase as it was before bands: one sweep over all proxies.
fn original_find_pairs<S: Scalar>(proxies: &mut [Proxy<S>], pairs: &mut Vec<(u32, u32)>) {
    pairs.clear();
    proxies.sort_unstable_by(|p, q| {
        p.min_x
            .partial_cmp(&q.min_x)
            .unwrap_or(core::cmp::Ordering::Equal)
            .then(p.index.cmp(&q.index))
    });
    for (i, p) in proxies.iter().enumerate() {
        let Some(pc) = p.class else { continue };
        for q in &proxies[i + 1..] {
            if q.min_x > p.max_x {
                break;
            }
            let Some(qc) = q.class else { continue };
            if !pc.pairs_with(qc) || q.min_y > p.max_y || p.min_y > q.max_y {
                continue;
            }
            let pair = if p.index < q.index {
                (p.index, q.index)
            } else {
                (q.index, p.index)
            };
            pairs.push(pair);
        }
    }
    pairs.sort_unstable();
}

/// Runs `find_pairs` on `bp` and checks it against both references and
/// the memory bounds.
fn check<S: Scalar>(bp: &mut BroadPhase, proxies: &[Proxy<S>]) -> Result<(), TestCaseError> {
    let mut pairs = vec![(7, 7)];
    bp.find_pairs(proxies, &mut pairs);
    let expected = brute_force(proxies);
    prop_assert_eq!(&pairs, &expected);
    let mut original = Vec::new();
    original_find_pairs(&mut proxies.to_vec(), &mut original);
    prop_assert_eq!(&pairs, &original);
    // Bounded memory: fewer than 4 copies per proxy, at most MAX_BANDS.
    if !bp.band_start.is_empty() && !pairs.is_empty() {
        let copies = bp.band_start.last().copied().unwrap_or(0);
        prop_assert!(copies < 4 * bp.items.len().max(1), "{copies} copies");
        prop_assert!(bp.band_start.len() - 1 <= MAX_BANDS);
    }
    Ok(())
}

/// One proxy in test units: coordinates in 1/64, `i32::MIN` / `i32::MAX`
/// standing for the scalar's extremes.
#[derive(Clone, Copy, Debug)]
struct Spec {
    x: i32,
    y: i32,
    width: i32,
    height: i32,
    /// 0..4: a class code; 4: no class.
    class: u8,
}

fn scalar<S: Scalar>(value: i32) -> S {
    match value {
        i32::MIN => S::MIN,
        i32::MAX => S::MAX,
        _ => S::from_ratio(value, 64),
    }
}

fn class_of(code: u8) -> Option<ProxyClass> {
    ProxyClass::ALL.get(usize::from(code)).copied()
}

fn proxy<S: Scalar>(spec: &Spec, index: u32) -> Proxy<S> {
    let far = |start: i32, size: i32| match size {
        i32::MAX => S::MAX,
        _ => scalar(start.saturating_add(size).clamp(i32::MIN + 1, i32::MAX - 1)),
    };
    Proxy {
        min_x: scalar(spec.x),
        max_x: far(spec.x, spec.width),
        min_y: scalar(spec.y),
        max_y: far(spec.y, spec.height),
        index,
        class: class_of(spec.class),
    }
}

/// A coordinate: mostly a crowded small area (many ties and identical
/// boxes), some far apart (up to ±2¹⁵ units and beyond), some saturated.
fn coordinate() -> impl Strategy<Value = i32> {
    prop_oneof![
        6 => -64i32..64,
        2 => -(WORLD_LIMIT * 64)..(WORLD_LIMIT * 64),
        1 => prop_oneof![
            Just(-WORLD_LIMIT * 64),
            Just(WORLD_LIMIT * 64),
            Just(i32::MIN),
            Just(i32::MAX),
        ],
    ]
}

/// A size: mostly small, some large, some zero or inverted (min > max),
/// some reaching the scalar's maximum.
fn size() -> impl Strategy<Value = i32> {
    prop_oneof![
        6 => 0i32..48,
        2 => 0i32..4000,
        1 => Just(0),
        1 => -48i32..0,
        1 => Just(i32::MAX),
    ]
}

fn spec() -> impl Strategy<Value = Spec> {
    (coordinate(), coordinate(), size(), size(), 0u8..5).prop_map(|(x, y, width, height, class)| {
        Spec {
            x,
            y,
            width,
            height,
            class,
        }
    })
}

/// A change of one proxy between two calls: a small move `(dx, dy)`, an
/// operation (0: absent this call, 1: takes the class code, else
/// unchanged) and a class code.
type Change = (i32, i32, u8, u8);

fn change() -> impl Strategy<Value = Change> {
    (-6i32..6, -6i32..6, 0u8..12, 0u8..5)
}

/// Calls one broad phase on a sequence of sets derived from `base` by
/// `rounds` of changes; slot indices are `position · stride + offset`, in
/// increasing or decreasing input order.
fn run_sequence<S: Scalar>(
    base: &[Spec],
    rounds: &[Vec<Change>],
    stride: u32,
    reversed: bool,
) -> Result<(), TestCaseError> {
    let mut bp = BroadPhase::default();
    let mut specs = base.to_vec();
    let index_of = |i: usize| (i as u32).wrapping_mul(stride).wrapping_add(stride / 2);
    let all: Vec<Proxy<S>> = specs
        .iter()
        .enumerate()
        .map(|(i, s)| proxy(s, index_of(i)))
        .collect();
    check(&mut bp, &all)?;
    for round in rounds {
        let mut proxies = Vec::new();
        for (i, (spec, &(dx, dy, op, class))) in specs.iter_mut().zip(round).enumerate() {
            if !matches!(spec.x, i32::MIN | i32::MAX) {
                spec.x = spec.x.saturating_add(dx).clamp(i32::MIN + 1, i32::MAX - 1);
            }
            if !matches!(spec.y, i32::MIN | i32::MAX) {
                spec.y = spec.y.saturating_add(dy).clamp(i32::MIN + 1, i32::MAX - 1);
            }
            match op {
                0 => continue,
                1 => spec.class = class,
                _ => {}
            }
            proxies.push(proxy::<S>(spec, index_of(i)));
        }
        if reversed {
            proxies.reverse();
        }
        check(&mut bp, &proxies)?;
    }
    Ok(())
}

fn sequence_strategy() -> impl Strategy<Value = (Vec<Spec>, Vec<Vec<Change>>)> {
    proptest::collection::vec(spec(), 0..150).prop_flat_map(|base| {
        let n = base.len();
        (
            Just(base),
            proptest::collection::vec(proptest::collection::vec(change(), n), 1..5),
        )
    })
}

fn stride() -> impl Strategy<Value = u32> {
    prop_oneof![Just(1u32), Just(3), Just(1000), Just(u32::MAX / 200)]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    #[test]
    fn fx_matches_the_reference_over_changing_sets(
        (base, rounds) in sequence_strategy(),
        stride in stride(),
        reversed in any::<bool>(),
    ) {
        run_sequence::<Fx>(&base, &rounds, stride, reversed)?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    #[test]
    fn i48f16_matches_the_reference_over_changing_sets(
        (base, rounds) in sequence_strategy(),
        stride in stride(),
        reversed in any::<bool>(),
    ) {
        run_sequence::<I48F16>(&base, &rounds, stride, reversed)?;
    }

    #[test]
    fn f64_matches_the_reference_over_changing_sets(
        (base, rounds) in sequence_strategy(),
        stride in stride(),
        reversed in any::<bool>(),
    ) {
        run_sequence::<f64>(&base, &rounds, stride, reversed)?;
    }

    #[test]
    fn f32_matches_the_reference_over_changing_sets(
        (base, rounds) in sequence_strategy(),
        stride in stride(),
        reversed in any::<bool>(),
    ) {
        run_sequence::<f32>(&base, &rounds, stride, reversed)?;
    }

    /// A pile: many small boxes, slowly moving, all of one class mix; the
    /// case the kept x order and the bands are made for.
    #[test]
    fn piles_match_the_reference(
        cells in proptest::collection::vec((0i32..1200, 0i32..400, 16i32..40, 0u8..5), 1..400),
        moves in proptest::collection::vec(proptest::collection::vec(-4i32..4, 400), 1..4),
    ) {
        let base: Vec<Spec> = cells
            .iter()
            .map(|&(x, y, size, class)| Spec { x, y, width: size, height: size, class })
            .collect();
        let rounds: Vec<Vec<Change>> = moves
            .iter()
            .map(|m| m.iter().take(base.len()).map(|&d| (d, -d.abs(), 5, 0)).collect())
            .collect();
        run_sequence::<Fx>(&base, &rounds, 1, false)?;
    }

    /// `order_key` orders like the scalar, for every scalar type.
    #[test]
    fn order_keys_are_monotone(a in any::<i64>(), b in any::<i64>(), x in -1e30f64..1e30, y in -1e30f64..1e30) {
        let (fa, fb) = (Fx::from_bits(a), Fx::from_bits(b));
        prop_assert_eq!(order_key(fa).cmp(&order_key(fb)), fa.cmp(&fb));
        let (ia, ib) = (I48F16::from_bits(a), I48F16::from_bits(b));
        prop_assert_eq!(order_key(ia).cmp(&order_key(ib)), ia.cmp(&ib));
        prop_assert_eq!(Some(order_key(x).cmp(&order_key(y))), x.partial_cmp(&y));
        let (sx, sy) = (<f32 as Scalar>::from_f64(x), <f32 as Scalar>::from_f64(y));
        prop_assert_eq!(Some(order_key(sx).cmp(&order_key(sy))), sx.partial_cmp(&sy));
    }
}

#[test]
fn float_zeros_share_a_key() {
    assert_eq!(order_key(-0.0f64), order_key(0.0f64));
    assert_eq!(order_key(-0.0f32), order_key(0.0f32));
    assert!(order_key(-f64::MIN_POSITIVE) < order_key(0.0f64));
    assert!(order_key(f32::MIN) < order_key(f32::MAX));
}

#[test]
fn pair_table_is_pairs_with() {
    for a in ProxyClass::ALL {
        for b in ProxyClass::ALL {
            let bit = (PAIR_TABLE >> (4 * a.code() + b.code())) & 1 != 0;
            assert_eq!(bit, a.pairs_with(b), "{a:?} {b:?}");
        }
    }
}

fn fx_proxy(min: (i32, i32), max: (i32, i32), index: u32) -> Proxy<Fx> {
    Proxy {
        min_x: Fx::from_num(min.0),
        max_x: Fx::from_num(max.0),
        min_y: Fx::from_num(min.1),
        max_y: Fx::from_num(max.1),
        index,
        class: Some(ProxyClass::Dynamic),
    }
}

fn assert_matches(bp: &mut BroadPhase, proxies: &[Proxy<Fx>]) {
    if let Err(e) = check(bp, proxies) {
        panic!("{e}");
    }
}

#[test]
fn everything_in_one_spot_pairs_everything() {
    let proxies: Vec<_> = (0..300).map(|i| fx_proxy((0, 0), (1, 1), i)).collect();
    let mut bp = BroadPhase::default();
    let mut pairs = Vec::new();
    bp.find_pairs(&proxies, &mut pairs);
    assert_eq!(pairs.len(), 300 * 299 / 2);
    assert_matches(&mut bp, &proxies);
}

#[test]
fn a_ground_spanning_the_world_and_tall_walls() {
    let limit = WORLD_LIMIT;
    let mut proxies = vec![
        fx_proxy((-limit, -limit), (limit, -limit + 1), 0),
        fx_proxy((-limit, -limit), (-limit + 1, limit), 1),
        fx_proxy((limit - 1, -limit), (limit, limit), 2),
    ];
    for i in 0..2000 {
        let x = (i * 37) % 4000 - 2000;
        let y = -limit + (i * 13) % 300;
        proxies.push(fx_proxy((x, y), (x + 1, y + 1), 3 + i as u32));
    }
    // Many proxies as tall as the world: the band height grows so that the
    // copies stay below 4n.
    for i in 0..500 {
        proxies.push(fx_proxy((i, -limit), (i, limit), 5000 + i as u32));
    }
    let mut bp = BroadPhase::default();
    assert_matches(&mut bp, &proxies);
    assert_matches(&mut bp, &proxies);
}

#[test]
fn saturated_and_far_apart_coordinates() {
    let extreme = |min_x, max_x, min_y, max_y, index| Proxy {
        min_x,
        max_x,
        min_y,
        max_y,
        index,
        class: Some(ProxyClass::Dynamic),
    };
    let proxies = vec![
        extreme(Fx::MIN, Fx::MAX, Fx::MIN, Fx::MAX, 0),
        extreme(Fx::MIN, Fx::MIN, Fx::MIN, Fx::MIN, 1),
        extreme(Fx::MAX, Fx::MAX, Fx::MAX, Fx::MAX, 2),
        extreme(Fx::MAX, Fx::MIN, Fx::MAX, Fx::MIN, 3),
        extreme(Fx::ZERO, Fx::ZERO, Fx::MIN, Fx::MAX, 4),
        extreme(Fx::MIN, Fx::ZERO, Fx::ZERO, Fx::ZERO, u32::MAX),
    ];
    let mut bp = BroadPhase::default();
    assert_matches(&mut bp, &proxies);
    // Tiny boxes spread over the whole range: the band count is capped.
    let spread: Vec<_> = (0..3000)
        .map(|i| {
            let y = Fx::from_bits((i64::from(i) - 1500) << 51);
            extreme(Fx::ZERO, Fx::ONE, y, y, i)
        })
        .collect();
    assert_matches(&mut bp, &spread);
    assert!(bp.band_start.len() - 1 <= MAX_BANDS);
}

#[test]
fn a_reversed_crowd_falls_back_to_a_full_sort() {
    // After a call, every proxy jumps past every other: the insertion sort
    // gives up and the full sort gives the same pairs.
    let mut proxies: Vec<_> = (0..1000)
        .map(|i| fx_proxy((i, i % 7), (i + 2, i % 7 + 1), i as u32))
        .collect();
    let mut bp = BroadPhase::default();
    assert_matches(&mut bp, &proxies);
    for p in &mut proxies {
        let x = 1000 - p.min_x.to_num::<i32>();
        p.min_x = Fx::from_num(x);
        p.max_x = Fx::from_num(x + 2);
    }
    assert_matches(&mut bp, &proxies);
    // And back, with half the proxies gone and new ones in a new range.
    proxies.retain(|p| p.index % 2 == 0);
    proxies.extend((0..300).map(|i| fx_proxy((i, 0), (i + 1, 3), 2000 + i as u32)));
    assert_matches(&mut bp, &proxies);
}

#[test]
fn nothing_to_pair_when_nothing_moves() {
    let mut proxies: Vec<_> = (0..50).map(|i| fx_proxy((0, 0), (1, 1), i)).collect();
    for (i, p) in proxies.iter_mut().enumerate() {
        p.class = Some(if i % 2 == 0 {
            ProxyClass::Still
        } else {
            ProxyClass::Sleeping
        });
    }
    let mut bp = BroadPhase::default();
    let mut pairs = vec![(1, 2)];
    bp.find_pairs(&proxies, &mut pairs);
    assert!(pairs.is_empty());
    proxies[3].class = Some(ProxyClass::MovingKinematic);
    assert_matches(&mut bp, &proxies);
}

#[test]
fn scene_proxies_match_the_original() {
    // Real proxies (a falling pile of circles with scattered velocities in
    // a closed box, like the `balls5000` scene), called on the step's own
    // broad phase, whose x order has been kept over the ticks.
    use crate::dynamics::BodyDef;
    use crate::geometry::Shape;
    use crate::math::Vec2;
    let v = |x: f64, y: f64| Vec2::new(crate::math::fx(x), crate::math::fx(y));
    let mut world: crate::world::World<Fx> =
        crate::world::World::new(crate::world::WorldSettings::default());
    for (centre, half) in [
        (v(0.0, -0.5), v(41.0, 1.0)),
        (v(0.0, 40.5), v(41.0, 1.0)),
        (v(-40.5, 20.0), v(1.0, 21.0)),
        (v(40.5, 20.0), v(1.0, 21.0)),
    ] {
        world
            .add_body(BodyDef::fixed(Shape::aabb(half)).position(centre))
            .unwrap_or_else(|e| panic!("{e}"));
    }
    let mut state = 5000_u64;
    let mut speed = || {
        // SplitMix64 step, mapped to -5..5 in steps of 1/64.
        state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        let steps = i32::try_from((z ^ (z >> 31)) % 641).unwrap_or(0) - 320;
        Fx::from_num(steps) / 64
    };
    for row in 0..50_u8 {
        for column in 0..100_u8 {
            let position = v(
                -37.125 + 0.75 * f64::from(column),
                0.5 + 0.75 * f64::from(row),
            );
            let velocity = Vec2::new(speed(), speed());
            world
                .add_body(
                    BodyDef::dynamic(Shape::circle(crate::math::fx(0.25)))
                        .position(position)
                        .velocity(velocity),
                )
                .unwrap_or_else(|e| panic!("{e}"));
        }
    }
    for _ in 0..40 {
        world.step();
    }
    let proxies = world.step_context.proxies.clone();
    assert_matches(&mut world.step_context.broad_phase, &proxies);
}

#[test]
fn repeated_slot_indices_do_not_panic() {
    // Outside the contract (slot indices are distinct), but no input may
    // crash the phase, also on the next calls with a history.
    let proxies: Vec<_> = (0..40u32)
        .map(|i| fx_proxy((i as i32 % 5, 0), (i as i32 % 5 + 2, 1), i % 3))
        .collect();
    let mut bp = BroadPhase::default();
    let mut pairs = Vec::new();
    for _ in 0..3 {
        bp.find_pairs(&proxies, &mut pairs);
        assert!(pairs.iter().all(|&(a, b)| a <= b));
    }
    let distinct: Vec<_> = (0..40u32)
        .map(|i| fx_proxy((i as i32 % 5, 0), (i as i32 % 5 + 2, 1), i))
        .collect();
    assert_matches(&mut bp, &distinct);
}
