//! `QueryIndex` (`World::query_index`) against the `World` query methods.
//!
//! The index must give *identical* answers: the same body, the same
//! `RayHit` bits, the same tie rule (equal distance: the smaller id), the
//! same orders. Checked here:
//!
//! * **Properties** (proptest): random worlds of circles and boxes (on a
//!   quarter-unit grid, so they overlap, touch and share edges exactly, or
//!   at arbitrary raw positions), of all three kinds, with bodies removed
//!   (ids with gaps) and re-added (reused slots, later generations),
//!   duplicated (two identical bodies at the same place: exact ties),
//!   optionally stepped a few times (arbitrary positions). Against each,
//!   random rays: origins on the grid, at raw positions, on box corners and
//!   edges and circle tangent points (exactly, or offset along an axis), at
//!   body centres (inside), far outside the world, at `MIN`/`MAX`;
//!   directions along the axes (rays running along faces), diagonal, aimed
//!   exactly at corners (grazing), raw, one-ulp components, zero; max
//!   distances negative, zero, small, large, `MAX`. Every one of
//!   `raycast`, `raycast_filtered`, `raycast_all`, `query_aabb`,
//!   `query_point` is compared, with random filters (kinds, `exclude` of a
//!   live or a removed body). On `Fx`, and (fewer cases) on `I48F16` and on
//!   the `f64` and `f32` reference types.
//! * **Hand-written cases**: an empty world, exact ties, an origin inside a
//!   body, grazing rays, far-away origins, filters, the order of
//!   `raycast_all`, and 2000 rays into the 5050-box pyramid of the bench.

use clockwork2d::prelude::*;
use clockwork2d_scene::builtin;
use fixed::types::I48F16;
use proptest::prelude::*;

// ---------------------------------------------------------------------------
// Random worlds and queries, described in `Fx` and converted to any scalar.
// ---------------------------------------------------------------------------

#[derive(Clone, Debug)]
struct BodySpec {
    kind: u8,
    circle: bool,
    half: (Fx, Fx),
    pos: (Fx, Fx),
}

#[derive(Clone, Debug)]
struct WorldSpec {
    bodies: Vec<BodySpec>,
    /// Indices (modulo the count) of bodies to remove after adding them all.
    remove: Vec<usize>,
    /// Bodies added after the removals (they reuse freed slots).
    extra: Vec<BodySpec>,
    /// Indices of bodies to add a second, identical copy of (exact ties).
    duplicate: Vec<usize>,
    steps: u8,
}

#[derive(Clone, Debug)]
enum PointSpec {
    /// Any point near the bodies.
    Free(Fx, Fx),
    /// A point of a live body's box (`k` picks one of the 9: corners, edge
    /// midpoints, centre; for a circle the edge midpoints are its tangent
    /// points), offset by `(dx, dy)` (often zero).
    Body(usize, u8, Fx, Fx),
    /// Far from the bodies: within ±2¹⁷ (still indexed) or up to ±2²⁰ (the
    /// index hands the query to the world).
    Far(Fx, Fx),
    /// A corner of the scalar's range.
    Extreme(u8),
}

#[derive(Clone, Debug)]
enum DirSpec {
    Axis(u8, Fx),
    Diagonal(u8),
    Free(Fx, Fx),
    /// Components of a few ulps.
    Tiny(i8, i8),
    Zero,
    /// Exactly towards a point (corners: grazing rays).
    Toward(PointSpec),
}

#[derive(Clone, Debug)]
enum DistSpec {
    Negative(Fx),
    Zero,
    Value(Fx),
    Large,
    Max,
}

#[derive(Clone, Debug)]
struct FilterSpec {
    fixed: bool,
    kinematic: bool,
    dynamic: bool,
    /// Index into every id ever issued (live or removed).
    exclude: Option<usize>,
}

#[derive(Clone, Debug)]
struct QuerySpec {
    origin: PointSpec,
    dir: DirSpec,
    dist: DistSpec,
    filter: FilterSpec,
    /// Area of the box query: centre and half extents (may be negative).
    area: (PointSpec, Fx, Fx),
    point: PointSpec,
}

fn from_raw(raw: i64) -> Fx {
    Fx::from_bits(raw)
}

/// A coordinate: on the quarter-unit grid (exact shared edges) or raw.
fn coord(range: i32) -> impl Strategy<Value = Fx> {
    prop_oneof![
        3 => (-4 * range..=4 * range).prop_map(|q| Fx::from_num(q) / 4),
        2 => (-i64::from(range) << 32..=i64::from(range) << 32).prop_map(from_raw),
    ]
}

fn size() -> impl Strategy<Value = Fx> {
    prop_oneof![
        3 => (1..=8i32).prop_map(|q| Fx::from_num(q) / 4),
        1 => (1i64 << 28..=4i64 << 32).prop_map(from_raw),
    ]
}

fn body_spec() -> impl Strategy<Value = BodySpec> {
    (0..3u8, any::<bool>(), size(), size(), coord(10), coord(10)).prop_map(
        |(kind, circle, hx, hy, x, y)| BodySpec {
            kind,
            circle,
            half: (hx, hy),
            pos: (x, y),
        },
    )
}

fn world_spec(max_bodies: usize) -> impl Strategy<Value = WorldSpec> {
    (
        prop::collection::vec(body_spec(), 0..max_bodies),
        prop::collection::vec(any::<usize>(), 0..6),
        prop::collection::vec(body_spec(), 0..4),
        prop::collection::vec(any::<usize>(), 0..4),
        prop_oneof![3 => Just(0u8), 1 => 1..20u8],
    )
        .prop_map(|(bodies, remove, extra, duplicate, steps)| WorldSpec {
            bodies,
            remove,
            extra,
            duplicate,
            steps,
        })
}

fn point_spec() -> impl Strategy<Value = PointSpec> {
    let offset = prop_oneof![
        3 => Just(Fx::ZERO),
        1 => (-8..=8i32).prop_map(|q| Fx::from_num(q) / 4),
        1 => (-3i64..=3).prop_map(from_raw),
    ];
    prop_oneof![
        3 => (coord(14), coord(14)).prop_map(|(x, y)| PointSpec::Free(x, y)),
        4 => (any::<usize>(), 0..9u8, offset.clone(), offset)
            .prop_map(|(i, k, dx, dy)| PointSpec::Body(i, k, dx, dy)),
        // Up to 2¹⁷ (the index still answers; large margin) and beyond
        // (the index hands the query to the world).
        1 => prop_oneof![Just(1i64 << 49), Just(1i64 << 52)]
            .prop_flat_map(|r| (-r..=r, -r..=r))
            .prop_map(|(x, y)| PointSpec::Far(from_raw(x), from_raw(y))),
        1 => (0..4u8).prop_map(PointSpec::Extreme),
    ]
}

fn dir_spec() -> impl Strategy<Value = DirSpec> {
    prop_oneof![
        3 => (0..4u8, (1i64..=8i64 << 32).prop_map(from_raw)).prop_map(|(a, l)| DirSpec::Axis(a, l)),
        1 => (0..4u8).prop_map(DirSpec::Diagonal),
        2 => (coord(4), coord(4)).prop_map(|(x, y)| DirSpec::Free(x, y)),
        1 => (-3..=3i8, -3..=3i8).prop_map(|(x, y)| DirSpec::Tiny(x, y)),
        1 => Just(DirSpec::Zero),
        3 => point_spec().prop_map(DirSpec::Toward),
    ]
}

fn dist_spec() -> impl Strategy<Value = DistSpec> {
    prop_oneof![
        1 => (1i64..=4i64 << 32).prop_map(|r| DistSpec::Negative(from_raw(-r))),
        1 => Just(DistSpec::Zero),
        4 => (0i64..=40i64 << 32).prop_map(|r| DistSpec::Value(from_raw(r))),
        1 => Just(DistSpec::Large),
        2 => Just(DistSpec::Max),
    ]
}

fn filter_spec() -> impl Strategy<Value = FilterSpec> {
    prop_oneof![
        2 => Just(FilterSpec { fixed: true, kinematic: true, dynamic: true, exclude: None }),
        3 => (any::<bool>(), any::<bool>(), any::<bool>(), prop::option::of(any::<usize>()))
            .prop_map(|(fixed, kinematic, dynamic, exclude)| FilterSpec {
                fixed,
                kinematic,
                dynamic,
                exclude,
            }),
    ]
}

fn query_spec() -> impl Strategy<Value = QuerySpec> {
    (
        point_spec(),
        dir_spec(),
        dist_spec(),
        filter_spec(),
        (point_spec(), coord(6), coord(6)),
        point_spec(),
    )
        .prop_map(|(origin, dir, dist, filter, area, point)| QuerySpec {
            origin,
            dir,
            dist,
            filter,
            area,
            point,
        })
}

fn conv<S: Scalar>(x: Fx) -> S {
    S::from_f64(x.to_f64())
}

fn def<S: Scalar>(spec: &BodySpec) -> BodyDef<S> {
    let shape = if spec.circle {
        Shape::circle(conv(spec.half.0))
    } else {
        Shape::aabb(Vec2::new(conv(spec.half.0), conv(spec.half.1)))
    };
    let def = match spec.kind {
        0 => BodyDef::fixed(shape),
        1 => BodyDef::kinematic(shape),
        _ => BodyDef::dynamic(shape),
    };
    def.position(Vec2::new(conv(spec.pos.0), conv(spec.pos.1)))
}

/// Builds the world; returns it with every id ever issued.
fn build_world<S: Scalar>(spec: &WorldSpec) -> (World<S>, Vec<BodyId>) {
    let mut world = World::new_generic(WorldSettings::default());
    let mut ids = Vec::new();
    for b in &spec.bodies {
        if let Ok(id) = world.add_body(def(b)) {
            ids.push(id);
        }
    }
    let first: Vec<BodyId> = ids.clone();
    for &d in &spec.duplicate {
        if let Some(b) = spec.bodies.get(d % spec.bodies.len().max(1))
            && let Ok(id) = world.add_body(def(b))
        {
            ids.push(id);
        }
    }
    for &r in &spec.remove {
        if !first.is_empty() {
            let _ = world.remove_body(first[r % first.len()]);
        }
    }
    for b in &spec.extra {
        if let Ok(id) = world.add_body(def(b)) {
            ids.push(id);
        }
    }
    for _ in 0..spec.steps {
        world.step();
    }
    (world, ids)
}

fn resolve_point<S: Scalar>(world: &World<S>, spec: &PointSpec) -> Vec2<S> {
    match *spec {
        PointSpec::Free(x, y) | PointSpec::Far(x, y) => Vec2::new(conv(x), conv(y)),
        PointSpec::Body(i, k, dx, dy) => {
            let bodies: Vec<&Body<S>> = world.bodies().map(|(_, b)| b).collect();
            let Some(body) = bodies.get(i % bodies.len().max(1)) else {
                return Vec2::new(conv(dx), conv(dy));
            };
            let c = body.position();
            let h = body.shape().half_extents();
            let pick = |s: u8, c: S, h: S| match s {
                0 => c.sub(h),
                1 => c,
                _ => c.add(h),
            };
            Vec2::new(
                pick(k % 3, c.x, h.x).add(conv(dx)),
                pick(k / 3, c.y, h.y).add(conv(dy)),
            )
        }
        PointSpec::Extreme(k) => {
            let pick = |b: bool| if b { S::MAX } else { S::MIN };
            Vec2::new(pick(k & 1 != 0), pick(k & 2 != 0))
        }
    }
}

fn resolve_ray<S: Scalar>(world: &World<S>, q: &QuerySpec) -> (Vec2<S>, Vec2<S>, S) {
    let origin = resolve_point(world, &q.origin);
    let dir = match &q.dir {
        DirSpec::Axis(a, l) => {
            let l: S = conv(*l);
            match a {
                0 => Vec2::new(l, S::ZERO),
                1 => Vec2::new(l.neg(), S::ZERO),
                2 => Vec2::new(S::ZERO, l),
                _ => Vec2::new(S::ZERO, l.neg()),
            }
        }
        DirSpec::Diagonal(k) => {
            let x = if k & 1 != 0 { S::ONE } else { S::ONE.neg() };
            let y = if k & 2 != 0 { S::ONE } else { S::ONE.neg() };
            Vec2::new(x, y)
        }
        DirSpec::Free(x, y) => Vec2::new(conv(*x), conv(*y)),
        DirSpec::Tiny(x, y) => Vec2::new(
            S::EPSILON.mul_int(i32::from(*x)),
            S::EPSILON.mul_int(i32::from(*y)),
        ),
        DirSpec::Zero => Vec2::ZERO,
        DirSpec::Toward(p) => resolve_point(world, p) - origin,
    };
    let dist = match q.dist {
        DistSpec::Negative(d) | DistSpec::Value(d) => conv(d),
        DistSpec::Zero => S::ZERO,
        DistSpec::Large => S::from_int(1 << 17),
        DistSpec::Max => S::MAX,
    };
    (origin, dir, dist)
}

fn resolve_filter(spec: &FilterSpec, ids: &[BodyId]) -> QueryFilter {
    QueryFilter {
        fixed: spec.fixed,
        kinematic: spec.kinematic,
        dynamic: spec.dynamic,
        exclude: spec
            .exclude
            .and_then(|i| ids.get(i % ids.len().max(1)).copied()),
    }
}

/// Equal, or printed identically: the `f64` reference type at `±MAX`
/// coordinates produces NaN distances (on both sides), and NaN ≠ NaN.
macro_rules! prop_assert_same {
    ($index:expr, $world:expr) => {
        prop_assert_same!($index, $world, "")
    };
    ($index:expr, $world:expr, $($msg:tt)+) => {{
        let (index, world) = ($index, $world);
        prop_assert!(
            index == world || format!("{index:?}") == format!("{world:?}"),
            "index {:?} != world {:?}: {}",
            index,
            world,
            format!($($msg)+)
        );
    }};
}

/// Every query of `q`, through the index and through the world: equal.
fn check_query<S: Scalar>(
    world: &World<S>,
    index: &QueryIndex<'_, S>,
    ids: &[BodyId],
    q: &QuerySpec,
) -> Result<(), TestCaseError> {
    let (origin, dir, dist) = resolve_ray(world, q);
    let filter = resolve_filter(&q.filter, ids);
    prop_assert_same!(
        index.raycast(origin, dir, dist),
        world.raycast(origin, dir, dist),
        "raycast {:?} {:?} {:?}",
        origin,
        dir,
        dist
    );
    prop_assert_same!(
        index.raycast_filtered(origin, dir, dist, &filter),
        world.raycast_filtered(origin, dir, dist, &filter),
        "raycast_filtered {:?} {:?} {:?} {:?}",
        origin,
        dir,
        dist,
        filter
    );
    prop_assert_same!(
        index.raycast_all(origin, dir, dist, &filter),
        world.raycast_all(origin, dir, dist, &filter),
        "raycast_all {:?} {:?} {:?} {:?}",
        origin,
        dir,
        dist,
        filter
    );
    let centre = resolve_point(world, &q.area.0);
    let area = Aabb::new(centre, Vec2::new(conv(q.area.1), conv(q.area.2)));
    prop_assert_same!(
        index.query_aabb(&area, &filter),
        world.query_aabb(&area, &filter),
        "query_aabb {:?}",
        area
    );
    let point = resolve_point(world, &q.point);
    prop_assert_same!(
        index.query_point(point, &filter),
        world.query_point(point, &filter),
        "query_point {:?}",
        point
    );
    // The same point as a query area of size zero, and the ray's origin.
    let dot = Aabb::new(point, Vec2::ZERO);
    prop_assert_same!(
        index.query_aabb(&dot, &filter),
        world.query_aabb(&dot, &filter)
    );
    prop_assert_same!(
        index.query_point(origin, &filter),
        world.query_point(origin, &filter)
    );
    Ok(())
}

fn check_world<S: Scalar>(spec: &WorldSpec, queries: &[QuerySpec]) -> Result<(), TestCaseError> {
    let (world, ids) = build_world::<S>(spec);
    let index = world.query_index();
    for q in queries {
        check_query(&world, &index, &ids, q)?;
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 1024, ..ProptestConfig::default() })]

    /// Small and medium worlds (trees up to depth 4), `Fx`.
    #[test]
    fn index_matches_world_fx(
        spec in world_spec(48),
        queries in prop::collection::vec(query_spec(), 1..40),
    ) {
        check_world::<Fx>(&spec, &queries)?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, ..ProptestConfig::default() })]

    /// Larger worlds (deeper trees, many overlaps), `Fx`.
    #[test]
    fn index_matches_world_fx_large(
        spec in world_spec(400),
        queries in prop::collection::vec(query_spec(), 50..100),
    ) {
        check_world::<Fx>(&spec, &queries)?;
    }

    /// The other fixed-point scalar.
    #[test]
    fn index_matches_world_i48f16(
        spec in world_spec(64),
        queries in prop::collection::vec(query_spec(), 1..40),
    ) {
        check_world::<I48F16>(&spec, &queries)?;
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    /// The `f64` reference type (relative rounding, covered by the margin).
    #[test]
    fn index_matches_world_f64(
        spec in world_spec(64),
        queries in prop::collection::vec(query_spec(), 1..40),
    ) {
        check_world::<f64>(&spec, &queries)?;
    }

    /// The `f32` reference type (coarser still: an ulp of 2⁻⁶ at 2¹⁷).
    #[test]
    fn index_matches_world_f32(
        spec in world_spec(64),
        queries in prop::collection::vec(query_spec(), 1..40),
    ) {
        check_world::<f32>(&spec, &queries)?;
    }
}

// ---------------------------------------------------------------------------
// Hand-written cases.
// ---------------------------------------------------------------------------

fn square(world: &mut World, kind: BodyKind, at: Vec2) -> BodyId {
    let shape = Shape::aabb(vec2(0.5, 0.5));
    let def = match kind {
        BodyKind::Fixed => BodyDef::fixed(shape),
        BodyKind::Kinematic => BodyDef::kinematic(shape),
        BodyKind::Dynamic => BodyDef::dynamic(shape),
    };
    world.add_body(def.position(at)).unwrap()
}

/// Asserts every query of one ray (and its origin as a point) agrees.
fn assert_same(world: &World, origin: Vec2, dir: Vec2, dist: Fx, filter: &QueryFilter) {
    let index = world.query_index();
    assert_eq!(
        index.raycast(origin, dir, dist),
        world.raycast(origin, dir, dist)
    );
    assert_eq!(
        index.raycast_filtered(origin, dir, dist, filter),
        world.raycast_filtered(origin, dir, dist, filter)
    );
    assert_eq!(
        index.raycast_all(origin, dir, dist, filter),
        world.raycast_all(origin, dir, dist, filter)
    );
    assert_eq!(
        index.query_point(origin, filter),
        world.query_point(origin, filter)
    );
}

#[test]
fn empty_world_answers_nothing() {
    let world = World::new(WorldSettings::default());
    let index = world.query_index();
    let all = QueryFilter::default();
    assert_eq!(index.raycast(Vec2::ZERO, Vec2::X, Fx::MAX), None);
    assert!(
        index
            .raycast_all(Vec2::ZERO, Vec2::X, Fx::MAX, &all)
            .is_empty()
    );
    let area = Aabb::new(Vec2::ZERO, vec2(100.0, 100.0));
    assert!(index.query_aabb(&area, &all).is_empty());
    assert!(index.query_point(Vec2::ZERO, &all).is_empty());
}

#[test]
fn exact_ties_go_to_the_smaller_id_whatever_the_tree_order() {
    let mut world = World::new(WorldSettings::default());
    // Fill slots 0..8, free slot 2, and reuse it: the re-added body has the
    // smaller index (and a later generation) than the others at its place.
    let mut ids: Vec<BodyId> = (0..8)
        .map(|i| square(&mut world, BodyKind::Fixed, vec2(f64::from(i) * 3.0, 0.0)))
        .collect();
    world.remove_body(ids[2]).unwrap();
    let twin_late = square(&mut world, BodyKind::Dynamic, vec2(21.0, 0.0));
    assert_eq!(twin_late.index(), 2);
    ids[2] = twin_late;
    // Slot 7 also holds a square at x = 21: an exact tie at distance 20.5.
    let index = world.query_index();
    let hit = index.raycast(vec2(0.0, 5.0), vec2(0.0, -1.0), fx(10.0));
    assert_eq!(
        hit,
        world.raycast(vec2(0.0, 5.0), vec2(0.0, -1.0), fx(10.0))
    );
    let hit = index
        .raycast(vec2(30.0, 0.0), vec2(-1.0, 0.0), fx(100.0))
        .unwrap();
    assert_eq!(hit.body, twin_late);
    assert_eq!(hit.hit.distance, fx(8.5));
    assert_eq!(
        Some(hit),
        world.raycast(vec2(30.0, 0.0), vec2(-1.0, 0.0), fx(100.0))
    );
    let all = index.raycast_all(
        vec2(30.0, 0.0),
        vec2(-1.0, 0.0),
        fx(100.0),
        &QueryFilter::default(),
    );
    assert_eq!(all[0].body, twin_late);
    assert_eq!(all[1].body, ids[7]);
    assert_eq!(all[0].hit.distance, all[1].hit.distance);
    assert_eq!(
        all,
        world.raycast_all(
            vec2(30.0, 0.0),
            vec2(-1.0, 0.0),
            fx(100.0),
            &QueryFilter::default()
        )
    );
}

#[test]
fn origin_inside_grazing_rays_and_corners_agree() {
    let mut world = World::new(WorldSettings::default());
    let a = square(&mut world, BodyKind::Fixed, vec2(0.0, 0.0));
    let _b = square(&mut world, BodyKind::Kinematic, vec2(1.0, 0.0)); // shares an edge
    let c = world
        .add_body(BodyDef::dynamic(Shape::circle(fx(0.5))).position(vec2(0.0, 3.0)))
        .unwrap();
    let all = QueryFilter::default();
    // Inside: distance 0, normal against the direction.
    let hit = world
        .query_index()
        .raycast(vec2(0.1, 0.1), Vec2::X, fx(5.0))
        .unwrap();
    assert_eq!(hit.body, a);
    assert_eq!(hit.hit.distance, Fx::ZERO);
    // Along the top faces (y = 0.5), along the shared edge, through corners,
    // tangent to the circle, towards the circle's bounding-box corner.
    let cases = [
        (vec2(-3.0, 0.5), Vec2::X),
        (vec2(0.5, -3.0), Vec2::Y),
        (vec2(-1.5, -1.5), vec2(1.0, 1.0)),
        (vec2(-2.0, 1.5), vec2(1.5, -1.0)),
        (vec2(-3.0, 3.5), Vec2::X),
        (vec2(0.5, -5.0), Vec2::Y),
        (vec2(-3.0, 0.0), vec2(2.5, 3.5)),
        (vec2(0.5, 0.5), vec2(-1.0, 1.0)),
        (vec2(0.0, 3.0), vec2(0.0, -1.0)),
    ];
    for (origin, dir) in cases {
        for dist in [Fx::ZERO, fx(0.5), fx(3.0), fx(10.0), Fx::MAX] {
            assert_same(&world, origin, dir, dist, &all);
        }
    }
    let circle_top = world
        .query_index()
        .raycast(vec2(-3.0, 3.5), Vec2::X, fx(10.0))
        .unwrap();
    assert_eq!(circle_top.body, c);
}

#[test]
fn far_origins_zero_directions_and_bad_distances_agree() {
    let mut world = World::new(WorldSettings::default());
    square(&mut world, BodyKind::Fixed, vec2(0.0, 0.0));
    world
        .add_body(BodyDef::dynamic(Shape::circle(fx(2.0))).position(vec2(10.0, 0.0)))
        .unwrap();
    let all = QueryFilter::default();
    let far = vec2(-1_000_000.0, 0.0);
    let index = world.query_index();
    let hit = index.raycast(far, Vec2::X, Fx::MAX).unwrap();
    assert_eq!(Some(hit), world.raycast(far, Vec2::X, Fx::MAX));
    for (origin, dir, dist) in [
        (far, Vec2::X, Fx::MAX),
        (Vec2::new(Fx::MIN, Fx::MIN), vec2(1.0, 1.0), Fx::MAX),
        (Vec2::new(Fx::MAX, Fx::ZERO), vec2(-1.0, 0.0), Fx::MAX),
        (vec2(-5.0, 0.0), Vec2::ZERO, fx(10.0)),
        (vec2(-5.0, 0.0), Vec2::X, fx(-1.0)),
        (vec2(-5.0, 0.0), Vec2::X, Fx::ZERO),
        (vec2(-0.5, 0.0), Vec2::X, Fx::ZERO),
        (vec2(-5.0, 0.0), Vec2::new(Fx::DELTA, Fx::ZERO), fx(4.5)),
        (vec2(-5.0, 0.0), Vec2::new(Fx::DELTA, Fx::DELTA), Fx::MAX),
    ] {
        assert_same(&world, origin, dir, dist, &all);
    }
}

#[test]
fn filters_agree() {
    let mut world = World::new(WorldSettings::default());
    let kinds = [BodyKind::Fixed, BodyKind::Kinematic, BodyKind::Dynamic];
    let mut ids = Vec::new();
    for i in 0..30 {
        ids.push(square(
            &mut world,
            kinds[i % 3],
            vec2(i as f64 * 0.75, (i % 4) as f64 * 0.25),
        ));
    }
    world.remove_body(ids[4]).unwrap();
    let index = world.query_index();
    for bits in 0..8u8 {
        for exclude in [None, Some(ids[0]), Some(ids[1]), Some(ids[4])] {
            let filter = QueryFilter {
                fixed: bits & 1 != 0,
                kinematic: bits & 2 != 0,
                dynamic: bits & 4 != 0,
                exclude,
            };
            let (o, d) = (vec2(-2.0, 0.1), Vec2::X);
            assert_eq!(
                index.raycast_filtered(o, d, fx(100.0), &filter),
                world.raycast_filtered(o, d, fx(100.0), &filter)
            );
            assert_eq!(
                index.raycast_all(o, d, fx(100.0), &filter),
                world.raycast_all(o, d, fx(100.0), &filter)
            );
            let area = Aabb::new(vec2(10.0, 0.0), vec2(5.0, 1.0));
            assert_eq!(
                index.query_aabb(&area, &filter),
                world.query_aabb(&area, &filter)
            );
            assert_eq!(
                index.query_point(vec2(3.0, 0.25), &filter),
                world.query_point(vec2(3.0, 0.25), &filter)
            );
        }
    }
}

/// The bench's workload: rays from a circle around the 5050-box pyramid,
/// aimed into it; plus the same after the pile has been stepped a while.
#[test]
fn pyramid_rays_agree() {
    let mut world: World = builtin("large_pyramid").unwrap().build().unwrap();
    let mut state = 7u64;
    let mut next = move || {
        state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    };
    for round in 0..2 {
        let index = world.query_index();
        let mut hits = 0;
        for _ in 0..1000 {
            // Raw fixed-point coordinates: origin within ±160, target in the
            // pyramid's box (x in ±50, y in 0..100).
            let r = |n: u64, span: i64| Fx::from_bits((n % (2 * span as u64)) as i64 - span);
            let origin = Vec2::new(r(next(), 160 << 32), r(next(), 160 << 32));
            let target = Vec2::new(r(next(), 50 << 32), r(next(), 50 << 32) + fx(50.0));
            let dir = target - origin;
            let got = index.raycast(origin, dir, fx(300.0));
            assert_eq!(got, world.raycast(origin, dir, fx(300.0)), "round {round}");
            hits += usize::from(got.is_some());
            let area = Aabb::new(target, vec2(1.5, 0.75));
            let all = QueryFilter::default();
            assert_eq!(index.query_aabb(&area, &all), world.query_aabb(&area, &all));
            assert_eq!(
                index.query_point(target, &all),
                world.query_point(target, &all)
            );
        }
        assert!(hits > 900, "{hits}");
        drop(index);
        for _ in 0..30 {
            world.step();
        }
    }
}
