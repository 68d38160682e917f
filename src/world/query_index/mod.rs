//! [`QueryIndex`]: a bounding-volume tree over a borrowed [`World`], for
//! many ray casts and box / point queries per tick.
//!
//! # When to use it
//!
//! The [`World`] query methods test every body: O(n) per query and nothing to
//! set up, the right choice for a handful of queries. [`World::query_index`]
//! costs O(n log n) once (for the 5050-box `large_pyramid`, about 0.6 ms,
//! the time of about a thousand rays) and then answers each query in about O(log n) node tests plus
//! the shape tests of the few bodies near the ray, box or point. Build one
//! when a tick asks more than a few dozen queries of the same world state
//! (AI sight lines, a spray of bullets, a query per body), use it, drop it.
//!
//! ```
//! use clockwork2d::geometry::*;
//! use clockwork2d::prelude::*;
//! let mut world = World::new(WorldSettings::default());
//! let ground = world.add_body(BodyDef::fixed(Shape::aabb(Vec2::new(fx(20.0), fx(0.5))))
//!     .position(Vec2::new(fx(0.0), fx(-0.5)))).unwrap();
//! let mut guards = Vec::new();
//! for i in -5..5 {
//!     let at = Vec2::new(fx(f64::from(3 * i)), fx(0.5));
//!     guards.push(world.add_body(BodyDef::dynamic(Shape::circle(fx(0.5))).position(at)).unwrap());
//! }
//! for _tick in 0..3 {
//!     world.step();
//!     // Once per tick: build, ask every guard's question, drop.
//!     let index = world.query_index();
//!     for &guard in &guards {
//!         let eye = world.body(guard).unwrap().position();
//!         let not_me = QueryFilter { exclude: Some(guard), ..QueryFilter::default() };
//!         let down = index.raycast_filtered(eye, Vec2::new(fx(0.0), fx(-1.0)), fx(10.0), &not_me);
//!         assert_eq!(down.map(|h| h.body), Some(ground));
//!     }
//! } // `index` is gone before the next `step`, as the borrow checker requires
//! ```
//!
//! # Why it cannot go stale
//!
//! The index borrows the world (`&World`), so while it lives the borrow
//! checker forbids every mutation (`step`, commands, `add_body`, ...). It is
//! always built from, and queried against, exactly the state it describes.
//!
//! # Identical answers
//!
//! Every answer is the [`World`] method's, bit for bit: the same body, the
//! same [`RayHit`](crate::geometry::RayHit) (it is computed by the same
//! `ray_circle` / `ray_aabb` call on the same ray), the same tie rule (on
//! equal distance the smaller id wins), the same orders. The tree only
//! decides which bodies are *tested*; it must never skip a body the world
//! would report, and it never does, by the following argument (`Fx` and
//! `I48F16`; see [`QueryIndex`] for the float reference types).
//!
//! * **Leaf boxes** contain every point a body's query can report: for a box
//!   body the closed box `center ± |half|` computed exactly as `ray_aabb`
//!   computes it, for a circle `center ± |r|`; both also contain the body's
//!   [`aabb`](crate::dynamics::Body::aabb) as `query_aabb` compares it. Node boxes
//!   are unions of their children's.
//! * **Node test for rays** (`RaySetup::may_hit`): the exact slab test of the
//!   box *grown by a margin* `m` against the segment `[0, bound]` of the ray.
//!   Every decision is made without division, by cross-multiplying in the
//!   wide type, where the products are exact (as in `ray_aabb`). The margin
//!   covers circle hits, which are not exact: a reported circle hit at
//!   distance `s` has `origin + s·direction` within a few ulps of the circle
//!   (`ray_circle`'s accuracy statement: the point is within ~4 ulps of the
//!   circle and within ~3 ulps of `origin + s·direction`; a clamped `s = 0`
//!   hit has the origin within a few ulps of the circle), so within the
//!   grown leaf box; `m` is at least 64 ulps, and more for far-away
//!   coordinates. Box hits are exact and need no margin.
//! * **Pruning by the best hit so far**: a reported distance `d` is never
//!   below `floor(t)`, where `t` is the exact parameter at which the ray
//!   enters the grown box (for a box body `d = floor(t_body)` with `t_body ≥
//!   t`; for a circle the point at `s = d` is in the grown box, so `t ≤ d`
//!   and `floor(t) ≤ d`). So a node is skipped only when `floor(t) > best`,
//!   tested exactly as `enter < (best + ulp)·speed`: a node whose entry
//!   *equals* the best distance is still visited, as it may hold an equal
//!   hit with a smaller id.
//! * **No saturation**: the argument needs exact arithmetic, so the index is
//!   used only when every leaf box and the query's origin or point lie within
//!   ±2¹⁷ (validated worlds are within ±(2¹⁵ + 4096)). Anything else (a ray
//!   from far outside the world, a world with out-of-range coordinates) is
//!   answered by the [`World`] method itself: slower, still identical.
//!
//! Box queries need no margin at all: a body passes `query_aabb` on
//! comparisons of its box corners with the area's, and its leaf box (and so
//! every ancestor) encloses those corners, so the node comparisons pass by
//! transitivity.
//!
//! # The tree
//!
//! A static binary tree over the live bodies, built top-down by median
//! splits: each node's bodies are split at the median of their box centres
//! along the axis where those centres spread most, ties broken by id, so the
//! tree is a pure function of the world state (deterministic, though the
//! answers would be identical for any tree). Leaves hold up to four
//! bodies; the depth is at most ⌈log₂ n⌉. Each node also keeps
//! the set of body kinds below it, so a filtered query skips subtrees of
//! rejected kinds.
//!
//! Closest-hit traversal goes depth first, nearer child first (the child on
//! the side the ray comes from along the split axis), and re-tests each
//! node against the best distance found so far when it is taken off the
//! stack, so once a near hit is found most of the tree is never opened.

use core::cmp::Ordering;

mod tree;

use super::World;
use super::queries::{BodyRayHit, QueryFilter, ray_shape, shape_contains_point, sort_hits};
use crate::dynamics::BodyId;
use crate::geometry::{Aabb, Ray};
use crate::math::Fx;
use crate::math::{Scalar, Vec2};
use tree::{
    Entry, Item, MARGIN_FACTOR, Node, RaySetup, SAFE_COORDINATE, build, kind_mask, leaf_bounds,
};

/// A spatial index over a borrowed [`World`], answering the world's queries
/// ([`raycast`](Self::raycast), [`raycast_filtered`](Self::raycast_filtered),
/// [`raycast_all`](Self::raycast_all), [`query_aabb`](Self::query_aabb),
/// [`query_point`](Self::query_point)) with identical results, bit for bit,
/// in about O(log n) each instead of O(n).
///
/// Build it with [`World::query_index`] (O(n log n)) when a tick needs many
/// queries; for one or two, the [`World`] methods are cheaper (no build).
/// It borrows the world, so the world cannot change while it lives: it can
/// never be out of date. See the module notes in `src/world/query_index.rs` for the design and the
/// argument that it never misses a body.
///
/// For the float reference scalars (`f64`, `f32`) the grown boxes' margin is
/// relative to the coordinates (64 ε per unit of the largest coordinate
/// involved), far above their rounding, so the answers agree there too; the
/// exactness argument proper is for the fixed-point scalars.
///
/// ```
/// use clockwork2d::geometry::*;
/// use clockwork2d::prelude::*;
/// let mut world = World::new(WorldSettings::default());
/// for i in 0..10 {
///     world.add_body(BodyDef::fixed(Shape::aabb(Vec2::new(fx(0.5), fx(0.5))))
///         .position(Vec2::new(fx(f64::from(2 * i)), fx(0.0)))).unwrap();
/// }
/// let index = world.query_index();
/// // Many rays against one state: each is a tree walk, not a scan.
/// for k in 0..20 {
///     let origin = Vec2::new(fx(f64::from(k)), fx(5.0));
///     let down = Vec2::new(fx(0.0), fx(-1.0));
///     assert_eq!(index.raycast(origin, down, fx(10.0)), world.raycast(origin, down, fx(10.0)));
/// }
/// drop(index);
/// world.step(); // the index is gone, the world can change again
/// ```
#[derive(Clone, Debug)]
pub struct QueryIndex<'w, S: Scalar = Fx> {
    world: &'w World<S>,
    /// The live bodies, permuted into tree order (each leaf's in id order).
    entries: Vec<Entry<S>>,
    /// The tree in depth-first order; node 0 is the root. Empty for an empty
    /// world, and when `indexed` is false.
    nodes: Vec<Node<S>>,
    /// The largest coordinate magnitude of any leaf box (sizes the margin).
    extent: S,
    /// `false` when some body's box is beyond the safe range: every query is
    /// then answered by the world's own method.
    indexed: bool,
}

impl<S: Scalar> World<S> {
    /// Builds a [`QueryIndex`] over the current state: O(n log n) time, O(n)
    /// memory. Worth it when a tick asks many queries; for one or two, call
    /// the world's methods directly.
    ///
    /// ```
    /// use clockwork2d::geometry::*;
    /// use clockwork2d::prelude::*;
    /// let mut world = World::new(WorldSettings::default());
    /// let ball = world.add_body(BodyDef::dynamic(Shape::circle(fx(1.0)))
    ///     .position(Vec2::new(fx(5.0), fx(0.0)))).unwrap();
    /// let index = world.query_index();
    /// let hit = index.raycast(Vec2::ZERO, Vec2::new(fx(1.0), fx(0.0)), fx(100.0)).unwrap();
    /// assert_eq!(hit.body, ball);
    /// assert_eq!(hit.hit.distance, fx(4.0));
    /// ```
    #[must_use]
    pub fn query_index(&self) -> QueryIndex<'_, S> {
        QueryIndex::new(self)
    }
}

impl<'w, S: Scalar> QueryIndex<'w, S> {
    fn new(world: &'w World<S>) -> Self {
        let limit = S::from_int(SAFE_COORDINATE);
        let mut entries = Vec::with_capacity(world.slots.len());
        let mut extent = S::ZERO;
        let mut indexed = true;
        for (id, body) in world.bodies() {
            let (lo, hi) = leaf_bounds(&body.shape, body.position);
            for v in [lo.x, lo.y, hi.x, hi.y] {
                let magnitude = v.abs();
                // Written so that NaN (float references only) fails too.
                if !matches!(
                    magnitude.partial_cmp(&limit),
                    Some(Ordering::Less | Ordering::Equal)
                ) {
                    indexed = false;
                }
                extent = extent.max(magnitude);
            }
            entries.push(Entry {
                lo,
                hi,
                id,
                kind: body.kind,
                shape: body.shape,
                position: body.position,
            });
        }
        // Node and entry indices are `u32`; a world too large for that (not
        // reachable in practice: slot indices are `u32` themselves) is simply
        // not indexed.
        if !u32::try_from(entries.len()).is_ok_and(|n| n <= u32::MAX / 4) {
            indexed = false;
        }
        let mut nodes = Vec::new();
        if indexed {
            let mut items: Vec<Item<S>> = entries
                .iter()
                .zip(0u32..)
                .map(|(e, entry)| Item {
                    key: Vec2::new(e.lo.x.add(e.hi.x), e.lo.y.add(e.hi.y)),
                    entry,
                })
                .collect();
            nodes.reserve(entries.len() / 2 + 1);
            if !items.is_empty() {
                build(&entries, &mut items, 0, &mut nodes);
            }
            // Entries in tree order: each leaf's are contiguous.
            entries = items
                .iter()
                .filter_map(|item| entries.get(item.entry as usize).copied())
                .collect();
        } else {
            entries = Vec::new();
        }
        QueryIndex {
            world,
            entries,
            nodes,
            extent,
            indexed,
        }
    }

    /// The world this index describes.
    ///
    /// ```
    /// use clockwork2d::geometry::*;
    /// use clockwork2d::prelude::*;
    /// let world = World::new(WorldSettings::default());
    /// let index = world.query_index();
    /// assert_eq!(index.world().body_count(), 0);
    /// ```
    #[must_use]
    pub fn world(&self) -> &'w World<S> {
        self.world
    }

    /// `true` if `p` is within the range where the tree's tests are exact.
    fn in_range(&self, p: Vec2<S>) -> bool {
        let limit = S::from_int(SAFE_COORDINATE);
        self.indexed && p.x.abs() <= limit && p.y.abs() <= limit
    }

    /// The margin for a query at `p` (see [`MARGIN_FACTOR`]):
    /// `64·ε·(1 + max(|p.x|, |p.y|, extent))`. For `Fx` and the bench's
    /// coordinates (~300) it is about 5e-6 units.
    fn margin(&self, p: Vec2<S>) -> S {
        let scale = p.x.abs().max(p.y.abs()).max(self.extent);
        S::EPSILON
            .mul_int(MARGIN_FACTOR)
            .add(S::EPSILON.mul(scale).mul_int(MARGIN_FACTOR))
    }

    /// The entries of a leaf.
    fn leaf(&self, node: &Node<S>) -> &[Entry<S>] {
        let start = node.first as usize;
        let end = start.saturating_add(node.count as usize);
        self.entries.get(start..end).unwrap_or(&[])
    }

    /// Same as [`World::raycast`]: the closest body hit by the ray from
    /// `origin` along `direction` within `max_distance`; ties go to the
    /// smaller id; `None` for a miss, a zero direction or a negative
    /// distance.
    ///
    /// ```
    /// use clockwork2d::geometry::*;
    /// use clockwork2d::prelude::*;
    /// let mut world = World::new(WorldSettings::default());
    /// let wall = world.add_body(BodyDef::fixed(Shape::aabb(Vec2::new(fx(0.5), fx(5.0))))
    ///     .position(Vec2::new(fx(10.0), fx(0.0)))).unwrap();
    /// let index = world.query_index();
    /// let hit = index.raycast(Vec2::ZERO, Vec2::new(fx(1.0), fx(0.0)), fx(100.0)).unwrap();
    /// assert_eq!(hit.body, wall);
    /// assert_eq!(hit.hit.distance, fx(9.5));
    /// ```
    #[must_use]
    pub fn raycast(
        &self,
        origin: Vec2<S>,
        direction: Vec2<S>,
        max_distance: S,
    ) -> Option<BodyRayHit<S>> {
        self.raycast_filtered(origin, direction, max_distance, &QueryFilter::default())
    }

    /// Same as [`World::raycast_filtered`]: [`raycast`](Self::raycast)
    /// restricted by a filter.
    ///
    /// ```
    /// use clockwork2d::geometry::*;
    /// use clockwork2d::prelude::*;
    /// let mut world = World::new(WorldSettings::default());
    /// let shape = Shape::aabb(Vec2::new(fx(0.5), fx(0.5)));
    /// let near = world.add_body(BodyDef::fixed(shape).position(Vec2::new(fx(2.0), fx(0.0)))).unwrap();
    /// let far = world.add_body(BodyDef::dynamic(shape).position(Vec2::new(fx(4.0), fx(0.0)))).unwrap();
    /// let index = world.query_index();
    /// let skip_near = QueryFilter { exclude: Some(near), ..QueryFilter::default() };
    /// let hit = index.raycast_filtered(Vec2::ZERO, Vec2::X, fx(10.0), &skip_near).unwrap();
    /// assert_eq!(hit.body, far);
    /// ```
    #[must_use]
    pub fn raycast_filtered(
        &self,
        origin: Vec2<S>,
        direction: Vec2<S>,
        max_distance: S,
        filter: &QueryFilter,
    ) -> Option<BodyRayHit<S>> {
        let ray = Ray::new(origin, direction, max_distance)?;
        if !self.in_range(ray.origin) {
            return self
                .world
                .raycast_filtered(origin, direction, max_distance, filter);
        }
        let setup = RaySetup::new(&ray, self.margin(ray.origin));
        let mask = kind_mask(filter);
        let mut reach = setup.reach(ray.max_distance);
        let mut best: Option<BodyRayHit<S>> = None;
        // Depth ≤ ⌈log₂ n⌉ ≤ 32, and the stack holds at most one pending
        // sibling per level plus the node being expanded.
        let mut stack: Vec<u32> = Vec::with_capacity(40);
        if !self.nodes.is_empty() {
            stack.push(0);
        }
        while let Some(index) = stack.pop() {
            let Some(node) = self.nodes.get(index as usize) else {
                continue;
            };
            // Re-tested here, when taken off the stack, with the best hit
            // found so far: this is where the search shrinks.
            if node.kinds & mask == 0 || !setup.may_hit(node.lo, node.hi, &reach) {
                continue;
            }
            if node.count == 0 {
                let (first, second) = (index.saturating_add(1), node.first);
                // Push the farther child first, so the nearer is opened first.
                if setup.second_child_first(node.split_y) {
                    stack.push(first);
                    stack.push(second);
                } else {
                    stack.push(second);
                    stack.push(first);
                }
                continue;
            }
            for entry in self.leaf(node) {
                if !filter.accepts_id_kind(entry.id, entry.kind)
                    || !setup.may_hit(entry.lo, entry.hi, &reach)
                {
                    continue;
                }
                let Some(hit) = ray_shape(&ray, &entry.shape, entry.position) else {
                    continue;
                };
                // The world keeps the first (smallest id) of the nearest;
                // bodies come in tree order here, so the tie rule is spelled
                // out.
                let better = best.is_none_or(|b| {
                    hit.distance < b.hit.distance
                        || (hit.distance == b.hit.distance && entry.id < b.body)
                });
                if better {
                    best = Some(BodyRayHit {
                        body: entry.id,
                        hit,
                    });
                    reach = setup.reach(hit.distance);
                }
            }
        }
        best
    }

    /// Same as [`World::raycast_all`]: every body hit by the ray, sorted by
    /// distance then id.
    ///
    /// ```
    /// use clockwork2d::geometry::*;
    /// use clockwork2d::prelude::*;
    /// let mut world = World::new(WorldSettings::default());
    /// let shape = Shape::circle(fx(0.5));
    /// let b = world.add_body(BodyDef::fixed(shape).position(Vec2::new(fx(4.0), fx(0.0)))).unwrap();
    /// let a = world.add_body(BodyDef::fixed(shape).position(Vec2::new(fx(2.0), fx(0.0)))).unwrap();
    /// let index = world.query_index();
    /// let hits = index.raycast_all(Vec2::ZERO, Vec2::X, fx(10.0), &QueryFilter::default());
    /// let order: Vec<BodyId> = hits.iter().map(|h| h.body).collect();
    /// assert_eq!(order, vec![a, b]);
    /// ```
    #[must_use]
    pub fn raycast_all(
        &self,
        origin: Vec2<S>,
        direction: Vec2<S>,
        max_distance: S,
        filter: &QueryFilter,
    ) -> Vec<BodyRayHit<S>> {
        let Some(ray) = Ray::new(origin, direction, max_distance) else {
            return Vec::new();
        };
        if !self.in_range(ray.origin) {
            return self
                .world
                .raycast_all(origin, direction, max_distance, filter);
        }
        let setup = RaySetup::new(&ray, self.margin(ray.origin));
        let mask = kind_mask(filter);
        let reach = setup.reach(ray.max_distance);
        let mut hits = Vec::new();
        self.walk(
            |node| node.kinds & mask != 0 && setup.may_hit(node.lo, node.hi, &reach),
            |entry| {
                if filter.accepts_id_kind(entry.id, entry.kind)
                    && setup.may_hit(entry.lo, entry.hi, &reach)
                    && let Some(hit) = ray_shape(&ray, &entry.shape, entry.position)
                {
                    hits.push(BodyRayHit {
                        body: entry.id,
                        hit,
                    });
                }
            },
        );
        // Id order first, then the world's own (stable) sort: the same input
        // order and the same comparator give the same output, even where the
        // comparator has ties (NaN distances of the float references).
        hits.sort_unstable_by_key(|h| h.body);
        sort_hits(&mut hits);
        hits
    }

    /// Same as [`World::query_aabb`]: bodies whose bounding box overlaps
    /// `area` (touching counts), in id order.
    ///
    /// ```
    /// use clockwork2d::geometry::*;
    /// use clockwork2d::prelude::*;
    /// let mut world = World::new(WorldSettings::default());
    /// let shape = Shape::circle(fx(0.5));
    /// let a = world.add_body(BodyDef::fixed(shape).position(Vec2::new(fx(0.0), fx(0.0)))).unwrap();
    /// let _b = world.add_body(BodyDef::fixed(shape).position(Vec2::new(fx(9.0), fx(0.0)))).unwrap();
    /// let index = world.query_index();
    /// let area = Aabb::new(Vec2::new(fx(1.0), fx(0.0)), Vec2::new(fx(0.5), fx(0.5)));
    /// assert_eq!(index.query_aabb(&area, &QueryFilter::default()), vec![a]);
    /// ```
    #[must_use]
    pub fn query_aabb(&self, area: &Aabb<S>, filter: &QueryFilter) -> Vec<BodyId> {
        if !self.indexed {
            return self.world.query_aabb(area, filter);
        }
        // The body test is `a0 ≤ b1 && b0 ≤ a1` per axis on the body's
        // corners a0, a1 and these corners b0, b1; every node box encloses
        // a0 and a1, so its own comparisons pass whenever a body's does. No
        // arithmetic, hence no margin and no range check.
        let (b0, b1) = (area.min(), area.max());
        let mask = kind_mask(filter);
        let mut ids = Vec::new();
        self.walk(
            |node| {
                node.kinds & mask != 0
                    && node.lo.x <= b1.x
                    && b0.x <= node.hi.x
                    && node.lo.y <= b1.y
                    && b0.y <= node.hi.y
            },
            |entry| {
                if filter.accepts_id_kind(entry.id, entry.kind)
                    && entry.shape.bounding_aabb_at(entry.position).overlaps(area)
                {
                    ids.push(entry.id);
                }
            },
        );
        ids.sort_unstable();
        ids
    }

    /// Same as [`World::query_point`]: bodies whose shape contains `point`
    /// (boundary included), in id order.
    ///
    /// ```
    /// use clockwork2d::geometry::*;
    /// use clockwork2d::prelude::*;
    /// let mut world = World::new(WorldSettings::default());
    /// let ball = world.add_body(BodyDef::dynamic(Shape::circle(fx(1.0)))).unwrap();
    /// let index = world.query_index();
    /// assert_eq!(index.query_point(Vec2::new(fx(1.0), fx(0.0)), &QueryFilter::default()), vec![ball]);
    /// assert!(index.query_point(Vec2::new(fx(0.8), fx(0.8)), &QueryFilter::default()).is_empty());
    /// ```
    #[must_use]
    pub fn query_point(&self, point: Vec2<S>, filter: &QueryFilter) -> Vec<BodyId> {
        if !self.in_range(point) {
            return self.world.query_point(point, filter);
        }
        // A contained point is within `center ± |size|` exactly (fixed
        // point, no saturation in range); the margin covers the float
        // references' rounding of `point − center`.
        let m = self.margin(point);
        let plus = Vec2::new(point.x.add(m), point.y.add(m));
        let minus = Vec2::new(point.x.sub(m), point.y.sub(m));
        let inside = |lo: Vec2<S>, hi: Vec2<S>| {
            lo.x <= plus.x && minus.x <= hi.x && lo.y <= plus.y && minus.y <= hi.y
        };
        let mask = kind_mask(filter);
        let mut ids = Vec::new();
        self.walk(
            |node| node.kinds & mask != 0 && inside(node.lo, node.hi),
            |entry| {
                if filter.accepts_id_kind(entry.id, entry.kind)
                    && inside(entry.lo, entry.hi)
                    && shape_contains_point(&entry.shape, entry.position, point)
                {
                    ids.push(entry.id);
                }
            },
        );
        ids.sort_unstable();
        ids
    }

    /// Depth-first walk over every node `enter` accepts, calling `visit` on
    /// each entry of the accepted leaves (in tree order).
    fn walk(&self, mut enter: impl FnMut(&Node<S>) -> bool, mut visit: impl FnMut(&Entry<S>)) {
        let mut stack: Vec<u32> = Vec::with_capacity(40);
        if !self.nodes.is_empty() {
            stack.push(0);
        }
        while let Some(index) = stack.pop() {
            let Some(node) = self.nodes.get(index as usize) else {
                continue;
            };
            if !enter(node) {
                continue;
            }
            if node.count == 0 {
                stack.push(node.first);
                stack.push(index.saturating_add(1));
            } else {
                self.leaf(node).iter().for_each(&mut visit);
            }
        }
    }
}
