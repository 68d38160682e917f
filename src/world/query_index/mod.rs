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
//! `I48F16`; see [`QueryIndex`] for the float reference types). Its shared
//! part is here; what is particular to rays (the grown node boxes, pruning
//! by the best hit) is in `rays.rs`, to box and point queries in
//! `regions.rs`.
//!
//! * **Leaf boxes** contain every point a body's query can report: for a box
//!   body the closed box `center ± |half|` computed exactly as `ray_aabb`
//!   computes it, for a circle `center ± |r|`; both also contain the body's
//!   [`aabb`](crate::dynamics::Body::aabb) as `query_aabb` compares it. Node boxes
//!   are unions of their children's.
//! * **No saturation**: the argument needs exact arithmetic, so the index is
//!   used only when every leaf box and the query's origin or point lie within
//!   ±2¹⁷ (validated worlds are within ±(2¹⁵ + 4096)). Anything else (a ray
//!   from far outside the world, a world with out-of-range coordinates) is
//!   answered by the [`World`] method itself: slower, still identical.
//!
//! # Where the parts are
//!
//! * `mod.rs` (here): the index itself, building it over a world, the
//!   range and margin rules, the depth-first walk shared by the queries
//!   that collect every match.
//! * `tree.rs`: the tree: leaf boxes, the median-split build, the node
//!   tests of the ray walk.
//! * `rays.rs`: the ray casts (closest hit, filtered, all hits).
//! * `regions.rs`: the box and point queries.
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

use core::cmp::Ordering;

mod rays;
mod regions;
mod tree;

use super::World;
use crate::math::Fx;
use crate::math::{Scalar, Vec2};
use tree::{Entry, Item, MARGIN_FACTOR, Node, SAFE_COORDINATE, build, leaf_bounds};

/// A spatial index over a borrowed [`World`], answering the world's queries
/// ([`raycast`](Self::raycast), [`raycast_filtered`](Self::raycast_filtered),
/// [`raycast_all`](Self::raycast_all), [`query_aabb`](Self::query_aabb),
/// [`query_point`](Self::query_point)) with identical results, bit for bit,
/// in about O(log n) each instead of O(n).
///
/// Build it with [`World::query_index`] (O(n log n)) when a tick needs many
/// queries; for one or two, the [`World`] methods are cheaper (no build).
/// It borrows the world, so the world cannot change while it lives: it can
/// never be out of date. See the module notes in `src/world/query_index/` for
/// the design and the argument that it never misses a body.
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
