//! The bounding-volume tree of a [`QueryIndex`](super::QueryIndex): leaf
//! boxes, building the tree (median splits, in depth-first order), and the
//! exact node tests of the ray walk. The exactness argument is in the
//! module docs of [`query_index`](super) and, for the ray tests, of `rays.rs`.

use core::cmp::Ordering;

use super::super::queries::QueryFilter;
use crate::dynamics::{BodyId, BodyKind};
use crate::geometry::{Ray, Shape};
use crate::math::{Scalar, Vec2, WideScalar};

/// Most bodies in one leaf. Small leaves let the per-body leaf-box test (a
/// few narrow subtractions and wide products) reject most bodies before the
/// shape test; a tree of 2- to 4-body leaves measured fastest on the
/// `raycasts` benchmark.
const LEAF_SIZE: usize = 4;

/// Coordinates (of leaf boxes, ray origins, query points) up to this
/// magnitude keep every quantity of the node tests and of the shape casts
/// far from the scalar's range (for `Fx`, coordinate differences stay below
/// 2¹⁹, far inside ±2³¹, and every wide product is exact in `I64F64`), so
/// nothing saturates and the exactness argument holds. Validated worlds are
/// within ±(2¹⁵ + 4096).
pub(super) const SAFE_COORDINATE: i32 = 1 << 17;

/// The margin, in units of `Scalar::EPSILON · (1 + scale)`, by which leaf and
/// node boxes are grown for ray and point tests. For fixed point one
/// `EPSILON` is an ulp and circle hits are within about 7 ulps of the circle
/// (see the module docs of `rays.rs`), so 64 is a wide safety factor; the `scale` term
/// (the largest coordinate involved) makes the same margin cover the float
/// reference types, whose rounding is relative. Too large a margin only
/// costs a few extra node visits, never a wrong answer.
pub(super) const MARGIN_FACTOR: i32 = 64;

/// Bit of each body kind in a node's kind set.
fn kind_bit(kind: BodyKind) -> u8 {
    match kind {
        BodyKind::Fixed => 1,
        BodyKind::Kinematic => 2,
        BodyKind::Dynamic => 4,
    }
}

/// The kinds a filter accepts, as a kind set.
pub(super) fn kind_mask(filter: &QueryFilter) -> u8 {
    [BodyKind::Fixed, BodyKind::Kinematic, BodyKind::Dynamic]
        .into_iter()
        .filter(|&kind| filter.accepts_kind(kind))
        .fold(0, |mask, kind| mask | kind_bit(kind))
}

/// One live body, copied out of the world so the traversal reads one
/// compact array in tree order instead of chasing slots.
#[derive(Clone, Copy, Debug)]
pub(super) struct Entry<S: Scalar> {
    /// Leaf box, lower corner (see [`leaf_bounds`]).
    pub(super) lo: Vec2<S>,
    /// Leaf box, upper corner.
    pub(super) hi: Vec2<S>,
    pub(super) id: BodyId,
    pub(super) kind: BodyKind,
    pub(super) shape: Shape<S>,
    pub(super) position: Vec2<S>,
}

/// A node of the tree: a box enclosing its bodies' leaf boxes.
#[derive(Clone, Copy, Debug)]
pub(super) struct Node<S: Scalar> {
    pub(super) lo: Vec2<S>,
    pub(super) hi: Vec2<S>,
    /// Leaf: index of its first entry. Inner node: index of its second
    /// child (the first child is the next node: nodes are in depth-first
    /// order).
    pub(super) first: u32,
    /// Leaf: number of entries (at least one). Inner node: zero.
    pub(super) count: u32,
    /// The kinds of the bodies below ([`kind_bit`]s).
    pub(super) kinds: u8,
    /// Inner node: `true` if the children were split on y (else x). The
    /// first child holds the smaller coordinates.
    pub(super) split_y: bool,
}

/// A box that contains everything any query can report for the body: the
/// closed box the ray casts use (`center ± |half|`, with `|r|` for a
/// circle, computed with the same saturating operations as `ray_aabb`) and
/// the corners `query_aabb` compares (`Body::aabb`, whose half extents are
/// taken as given). For a validated body (positive sizes) all of these are
/// the same box.
pub(super) fn leaf_bounds<S: Scalar>(shape: &Shape<S>, position: Vec2<S>) -> (Vec2<S>, Vec2<S>) {
    let half = shape.half_extents().abs();
    let aabb = shape.bounding_aabb_at(position);
    let (a, b) = (aabb.min(), aabb.max());
    let lo = (position - half).min(a).min(b);
    let hi = (position + half).max(a).max(b);
    (lo, hi)
}

/// A total order on scalars for the median splits: the natural order, with
/// NaN (only possible for the float reference types, and excluded by the
/// range check before any tree is built) after everything. A total order
/// keeps `select_nth_unstable_by` well defined whatever the input.
fn total_cmp<S: Scalar>(a: S, b: S) -> Ordering {
    a.partial_cmp(&b).unwrap_or_else(|| {
        let a_nan = a.partial_cmp(&a).is_none();
        let b_nan = b.partial_cmp(&b).is_none();
        a_nan.cmp(&b_nan)
    })
}

/// What the median splits move around: twice the centre of an entry's leaf
/// box (the sum needs no halving, so no rounding; within the safe range it
/// cannot saturate) and the entry's position in the id-ordered list. About a
/// quarter of an entry's size, so the selections move little memory.
#[derive(Clone, Copy)]
pub(super) struct Item<S: Scalar> {
    pub(super) key: Vec2<S>,
    pub(super) entry: u32,
}

/// Builds the subtree over `items` (which start at `offset` in the whole
/// item array), appending its nodes in depth-first order, and returns its
/// box and kind set. The recursion depth is at most ⌈log₂ n⌉ (each split
/// halves the count). Boxes are computed bottom-up (a node's is the union
/// of its children's), so each level costs one selection and one pass over
/// the keys.
pub(super) fn build<S: Scalar>(
    entries: &[Entry<S>],
    items: &mut [Item<S>],
    offset: u32,
    nodes: &mut Vec<Node<S>>,
) -> (Vec2<S>, Vec2<S>, u8) {
    let index = nodes.len();
    let count = items.len();
    if count <= LEAF_SIZE {
        // Id order inside a leaf (entries are listed in id order), so the
        // tree is a function of the world state alone, not of the selection
        // algorithm's internal order.
        items.sort_unstable_by_key(|item| item.entry);
        let mut bounds: Option<(Vec2<S>, Vec2<S>)> = None;
        let mut kinds = 0;
        for e in items
            .iter()
            .filter_map(|item| entries.get(item.entry as usize))
        {
            bounds = Some(bounds.map_or((e.lo, e.hi), |(lo, hi)| (lo.min(e.lo), hi.max(e.hi))));
            kinds |= kind_bit(e.kind);
        }
        let (lo, hi) = bounds.unwrap_or((Vec2::ZERO, Vec2::ZERO));
        nodes.push(Node {
            lo,
            hi,
            first: offset,
            count: u32::try_from(count).unwrap_or(0),
            kinds,
            split_y: false,
        });
        return (lo, hi, kinds);
    }
    // Split where the centres spread most: it keeps the children's boxes
    // apart, which is what lets a ray skip one of them.
    let (mut key_lo, mut key_hi) = (Vec2::new(S::MAX, S::MAX), Vec2::new(S::MIN, S::MIN));
    for item in items.iter() {
        key_lo = key_lo.min(item.key);
        key_hi = key_hi.max(item.key);
    }
    let spread = key_hi - key_lo;
    let split_y = spread.y > spread.x;
    let mid = count / 2;
    // Median by (centre, id): a total order, so the two halves are
    // determined by the state. O(count) per node, O(n log n) in all.
    items.select_nth_unstable_by(mid, |a, b| {
        let (ka, kb) = if split_y {
            (a.key.y, b.key.y)
        } else {
            (a.key.x, b.key.x)
        };
        total_cmp(ka, kb).then(a.entry.cmp(&b.entry))
    });
    nodes.push(Node {
        lo: Vec2::ZERO,
        hi: Vec2::ZERO,
        first: 0,
        count: 0,
        kinds: 0,
        split_y,
    });
    let (left, right) = items.split_at_mut(mid);
    let (lo_a, hi_a, kinds_a) = build(entries, left, offset, nodes);
    let second = u32::try_from(nodes.len()).unwrap_or(u32::MAX);
    let right_offset = offset.saturating_add(u32::try_from(mid).unwrap_or(u32::MAX));
    let (lo_b, hi_b, kinds_b) = build(entries, right, right_offset, nodes);
    let (lo, hi, kinds) = (lo_a.min(lo_b), hi_a.max(hi_b), kinds_a | kinds_b);
    if let Some(node) = nodes.get_mut(index) {
        node.lo = lo;
        node.hi = hi;
        node.first = second;
        node.kinds = kinds;
    }
    (lo, hi, kinds)
}

/// One axis of the ray's slab test against a (grown) box.
#[derive(Clone, Copy)]
pub(super) enum Slab<S: Scalar> {
    /// The ray can never be within the slab on this axis.
    Miss,
    /// The ray is parallel to this axis and within the slab: no limit.
    Free,
    /// Within the slab for `t ∈ [enter / speed, exit / speed]`, with
    /// `exit ≥ 0` (so not entirely behind the origin).
    Span { enter: S, exit: S },
}

/// Per-ray constants of the node test.
pub(super) struct RaySetup<S: Scalar> {
    /// `origin + m` per axis (`m` the margin): folding the margin into the
    /// origin costs nothing per node.
    pub(super) plus: Vec2<S>,
    /// `origin − m` per axis.
    pub(super) minus: Vec2<S>,
    /// `|direction|` per axis.
    pub(super) speed: Vec2<S>,
    /// Sign of the direction per axis: `Some(true)` negative,
    /// `Some(false)` positive, `None` zero.
    pub(super) negative_x: Option<bool>,
    pub(super) negative_y: Option<bool>,
}

/// `(bound + ulp)·speed` per axis, the exclusive limit on a node's entry
/// numerator (see [`RaySetup::may_hit`]); recomputed when the bound shrinks.
#[derive(Clone, Copy)]
pub(super) struct Reach<W> {
    pub(super) x: W,
    pub(super) y: W,
}

fn sign_of<S: Scalar>(d: S) -> Option<bool> {
    if d.is_negative() {
        Some(true)
    } else if d.is_positive() {
        Some(false)
    } else {
        None
    }
}

impl<S: Scalar> RaySetup<S> {
    pub(super) fn new(ray: &Ray<S>, margin: S) -> Self {
        let o = ray.origin;
        let d = ray.direction;
        RaySetup {
            plus: Vec2::new(o.x.add(margin), o.y.add(margin)),
            minus: Vec2::new(o.x.sub(margin), o.y.sub(margin)),
            speed: d.abs(),
            negative_x: sign_of(d.x),
            negative_y: sign_of(d.y),
        }
    }

    /// The limit for hits at distances `≤ bound` (bound ≥ 0). Formed as a sum
    /// of exact wide products, so `bound + ulp` cannot saturate.
    pub(super) fn reach(&self, bound: S) -> Reach<S::Wide> {
        Reach {
            x: bound
                .wide_mul(self.speed.x)
                .add(S::EPSILON.wide_mul(self.speed.x)),
            y: bound
                .wide_mul(self.speed.y)
                .add(S::EPSILON.wide_mul(self.speed.y)),
        }
    }

    /// The slab of `[lo − m, hi + m]` on one axis. With `o` the origin:
    /// moving up, `enter = (lo − m) − o = lo − plus`, `exit = (hi + m) − o =
    /// hi − minus`; moving down, `enter = o − (hi + m) = minus − hi`,
    /// `exit = o − (lo − m) = plus − lo`; not moving, the origin must lie in
    /// the grown slab: `lo ≤ plus` and `minus ≤ hi`. All exact (no
    /// saturation in the safe range).
    #[inline]
    pub(super) fn slab(negative: Option<bool>, plus: S, minus: S, lo: S, hi: S) -> Slab<S> {
        match negative {
            Some(false) => {
                let exit = hi.sub(minus);
                if exit.is_negative() {
                    Slab::Miss
                } else {
                    Slab::Span {
                        enter: lo.sub(plus),
                        exit,
                    }
                }
            }
            Some(true) => {
                let exit = plus.sub(lo);
                if exit.is_negative() {
                    Slab::Miss
                } else {
                    Slab::Span {
                        enter: minus.sub(hi),
                        exit,
                    }
                }
            }
            None => {
                if lo <= plus && minus <= hi {
                    Slab::Free
                } else {
                    Slab::Miss
                }
            }
        }
    }

    /// `false` only if no point of the ray at an exact parameter
    /// `t ∈ [0, ∞)` with `floor(t) ≤ bound` (`reach` built from `bound`) lies
    /// in the box `[lo − m, hi + m]`. Exact for fixed point: the entry
    /// parameter `t_in = max(0, enter_x / v_x, enter_y / v_y)` and the exit
    /// `t_out = min(exit_x / v_x, exit_y / v_y)` are compared by
    /// cross-multiplication in the wide type (exact products), and
    /// `floor(t_in) ≤ bound ⇔ t_in < bound + ulp ⇔ enter_i < (bound +
    /// ulp)·v_i` on each moving axis. No division, however small a
    /// direction component.
    #[inline]
    pub(super) fn may_hit(&self, lo: Vec2<S>, hi: Vec2<S>, reach: &Reach<S::Wide>) -> bool {
        let sx = Self::slab(self.negative_x, self.plus.x, self.minus.x, lo.x, hi.x);
        if let Slab::Miss = sx {
            return false;
        }
        let sy = Self::slab(self.negative_y, self.plus.y, self.minus.y, lo.y, hi.y);
        match (sx, sy) {
            (Slab::Miss, _) | (_, Slab::Miss) => false,
            // Only for a zero direction, which `Ray::new` never produces;
            // the origin is in the box then, so `t_in = 0`.
            (Slab::Free, Slab::Free) => true,
            (Slab::Span { enter, .. }, Slab::Free) => S::Wide::from_narrow(enter) < reach.x,
            (Slab::Free, Slab::Span { enter, .. }) => S::Wide::from_narrow(enter) < reach.y,
            (
                Slab::Span {
                    enter: ex,
                    exit: xx,
                },
                Slab::Span {
                    enter: ey,
                    exit: xy,
                },
            ) => {
                let (vx, vy) = (self.speed.x, self.speed.y);
                // Both exits are ≥ 0 (checked in `slab`), and enter ≤ exit
                // on each axis (lo ≤ hi), so t_in ≤ t_out reduces to the two
                // cross terms: enter_x / v_x ≤ exit_y / v_y and
                // enter_y / v_y ≤ exit_x / v_x.
                S::Wide::from_narrow(ex) < reach.x
                    && S::Wide::from_narrow(ey) < reach.y
                    && ex.wide_mul(vy) <= xy.wide_mul(vx)
                    && ey.wide_mul(vx) <= xx.wide_mul(vy)
            }
        }
    }

    /// `true` if the ray runs towards smaller coordinates along the split
    /// axis, so the second child (larger coordinates) is the nearer one.
    pub(super) fn second_child_first(&self, split_y: bool) -> bool {
        let negative = if split_y {
            self.negative_y
        } else {
            self.negative_x
        };
        negative == Some(true)
    }
}
