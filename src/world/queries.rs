//! Read-only queries: ray casts, box and point queries. None of them mutates
//! the world, and all of them return results in a deterministic order.
//!
//! These methods test every body: O(n) per query, no set-up cost. That is the
//! right choice for a few queries per tick. For many (AI sight lines, bullet
//! sprays, a query per body), build a
//! [`QueryIndex`](super::QueryIndex) once with
//! [`World::query_index`] (O(n log n)) and ask it instead: it gives
//! identical answers, bit for bit, in about O(log n) per query.

use super::World;
use crate::dynamics::{Body, BodyId, BodyKind};
use crate::geometry::{Aabb, Circle, Ray, RayHit, Shape, ray_aabb, ray_circle};
use crate::math::{Scalar, Vec2};

/// Which bodies a query considers. `Default` accepts every body.
///
/// ```
/// use clockwork2d::prelude::*;
/// let only_dynamic = QueryFilter { fixed: false, kinematic: false, ..QueryFilter::default() };
/// assert!(only_dynamic.dynamic);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct QueryFilter {
    /// Include fixed bodies.
    pub fixed: bool,
    /// Include kinematic bodies.
    pub kinematic: bool,
    /// Include dynamic bodies.
    pub dynamic: bool,
    /// Skip this one body (e.g. the caster itself).
    pub exclude: Option<BodyId>,
}

impl Default for QueryFilter {
    fn default() -> Self {
        QueryFilter {
            fixed: true,
            kinematic: true,
            dynamic: true,
            exclude: None,
        }
    }
}

impl QueryFilter {
    fn accepts<S: Scalar>(&self, id: BodyId, body: &Body<S>) -> bool {
        self.accepts_id_kind(id, body.kind())
    }

    /// The kind part of the filter alone (the query index uses it to skip
    /// whole subtrees holding no accepted kind).
    pub(super) fn accepts_kind(&self, kind: BodyKind) -> bool {
        match kind {
            BodyKind::Fixed => self.fixed,
            BodyKind::Kinematic => self.kinematic,
            BodyKind::Dynamic => self.dynamic,
        }
    }

    /// The whole filter, from a body's id and kind: the one definition shared
    /// by the world's queries and the query index.
    pub(super) fn accepts_id_kind(&self, id: BodyId, kind: BodyKind) -> bool {
        self.accepts_kind(kind) && self.exclude != Some(id)
    }
}

/// A ray hit on a body.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BodyRayHit<S: Scalar> {
    /// The body hit.
    pub body: BodyId,
    /// Where and how.
    pub hit: RayHit<S>,
}

/// The ray against one body's shape. Shared with the query index, so both
/// compute every hit with the same calls and get the same bits.
pub(super) fn ray_shape<S: Scalar>(
    ray: &Ray<S>,
    shape: &Shape<S>,
    position: Vec2<S>,
) -> Option<RayHit<S>> {
    match *shape {
        Shape::Circle { radius } => ray_circle(ray, &Circle::new(position, radius)),
        Shape::Aabb { half_extents } => ray_aabb(ray, &Aabb::new(position, half_extents)),
    }
}

/// `true` if the body's shape contains `point` (boundary included). Shared
/// with the query index.
pub(super) fn shape_contains_point<S: Scalar>(
    shape: &Shape<S>,
    position: Vec2<S>,
    point: Vec2<S>,
) -> bool {
    match *shape {
        Shape::Circle { radius } => Circle::new(position, radius).contains_point(point),
        Shape::Aabb { half_extents } => Aabb::new(position, half_extents).contains_point(point),
    }
}

/// Sorts hits by distance then id: the order of
/// [`raycast_all`](World::raycast_all). The sort is stable, so for the float
/// reference types (where a NaN distance compares equal to everything) the
/// result also depends on the input order; callers pass hits in id order.
pub(super) fn sort_hits<S: Scalar>(hits: &mut [BodyRayHit<S>]) {
    hits.sort_by(|x, y| {
        x.hit
            .distance
            .partial_cmp(&y.hit.distance)
            .unwrap_or(core::cmp::Ordering::Equal)
            .then(x.body.cmp(&y.body))
    });
}

impl<S: Scalar> World<S> {
    /// The closest body hit by the ray from `origin` along `direction` (any
    /// non-zero length) within `max_distance`. `None` for a miss, a zero
    /// direction or a negative distance. Ties go to the smaller id.
    ///
    /// ```
    /// use clockwork2d::prelude::*;
    /// let mut world = World::new(WorldSettings::default());
    /// let wall = world.add_body(BodyDef::fixed(Shape::aabb(Vec2::new(fx(0.5), fx(5.0))))
    ///     .position(Vec2::new(fx(10.0), fx(0.0)))).unwrap();
    /// let hit = world.raycast(Vec2::ZERO, Vec2::new(fx(1.0), fx(0.0)), fx(100.0)).unwrap();
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

    /// [`raycast`](Self::raycast) restricted by a filter.
    #[must_use]
    pub fn raycast_filtered(
        &self,
        origin: Vec2<S>,
        direction: Vec2<S>,
        max_distance: S,
        filter: &QueryFilter,
    ) -> Option<BodyRayHit<S>> {
        let ray = Ray::new(origin, direction, max_distance)?;
        let mut best: Option<BodyRayHit<S>> = None;
        for (id, body) in self.bodies() {
            if !filter.accepts(id, body) {
                continue;
            }
            if let Some(hit) = ray_shape(&ray, &body.shape, body.position) {
                // Bodies come in id order, so a strict comparison keeps the
                // smaller id on ties.
                if best.is_none_or(|b| hit.distance < b.hit.distance) {
                    best = Some(BodyRayHit { body: id, hit });
                }
            }
        }
        best
    }

    /// Every body hit by the ray, sorted by distance then id.
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
        let mut hits: Vec<BodyRayHit<S>> = self
            .bodies()
            .filter(|(id, body)| filter.accepts(*id, body))
            .filter_map(|(id, body)| {
                ray_shape(&ray, &body.shape, body.position).map(|hit| BodyRayHit { body: id, hit })
            })
            .collect();
        sort_hits(&mut hits);
        hits
    }

    /// Bodies whose bounding box overlaps `area`, in id order.
    #[must_use]
    pub fn query_aabb(&self, area: &Aabb<S>, filter: &QueryFilter) -> Vec<BodyId> {
        self.bodies()
            .filter(|(id, body)| filter.accepts(*id, body) && body.aabb().overlaps(area))
            .map(|(id, _)| id)
            .collect()
    }

    /// Bodies whose shape contains `point` (boundary included), in id order.
    #[must_use]
    pub fn query_point(&self, point: Vec2<S>, filter: &QueryFilter) -> Vec<BodyId> {
        self.bodies()
            .filter(|(id, body)| {
                filter.accepts(*id, body) && shape_contains_point(&body.shape, body.position, point)
            })
            .map(|(id, _)| id)
            .collect()
    }
}
