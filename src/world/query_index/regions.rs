//! The region queries of a [`QueryIndex`]: [`query_aabb`](QueryIndex::query_aabb)
//! (bodies whose bounding box overlaps an area) and
//! [`query_point`](QueryIndex::query_point) (bodies whose shape contains a
//! point), each the [`World`](super::World) method's answer bit for bit, in
//! id order.
//!
//! Box queries need no margin at all: a body passes `query_aabb` on
//! comparisons of its box corners with the area's, and its leaf box (and so
//! every ancestor) encloses those corners, so the node comparisons pass by
//! transitivity.
//!
//! A point query grows the boxes by the margin (`QueryIndex::margin`) only for
//! the float reference scalars' rounding of `point − center`; in fixed point
//! a contained point is within `center ± |size|` exactly.

use super::QueryIndex;
use super::tree::kind_mask;
use crate::dynamics::BodyId;
use crate::geometry::Aabb;
use crate::math::{Scalar, Vec2};
use crate::world::queries::{QueryFilter, shape_contains_point};

impl<S: Scalar> QueryIndex<'_, S> {
    /// Same as [`World::query_aabb`](crate::world::World::query_aabb): bodies whose bounding box overlaps
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

    /// Same as [`World::query_point`](crate::world::World::query_point): bodies whose shape contains `point`
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
}
