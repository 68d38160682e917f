//! The ray casts of a [`QueryIndex`]: [`raycast`](QueryIndex::raycast),
//! [`raycast_filtered`](QueryIndex::raycast_filtered) and
//! [`raycast_all`](QueryIndex::raycast_all), each the [`World`](super::World)
//! method's answer bit for bit. The shared part of the argument (leaf boxes,
//! no saturation) is in the [module notes](super); what rays add:
//!
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
//!
//! Closest-hit traversal goes depth first, nearer child first (the child on
//! the side the ray comes from along the split axis), and re-tests each
//! node against the best distance found so far when it is taken off the
//! stack, so once a near hit is found most of the tree is never opened.

use super::QueryIndex;
use super::tree::{RaySetup, kind_mask};
use crate::geometry::Ray;
use crate::math::{Scalar, Vec2};
use crate::world::queries::{BodyRayHit, QueryFilter, ray_shape, sort_hits};

impl<S: Scalar> QueryIndex<'_, S> {
    /// Same as [`World::raycast`](crate::world::World::raycast): the closest body hit by the ray from
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

    /// Same as [`World::raycast_filtered`](crate::world::World::raycast_filtered): [`raycast`](Self::raycast)
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

    /// Same as [`World::raycast_all`](crate::world::World::raycast_all): every body hit by the ray, sorted by
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
}
