//! A segment cast against a solid axis-aligned box: the exact slab test
//! (see the [module notes](super) for the segment's parametrisation and the
//! error conventions).

use super::Cast;
use crate::math::{Scalar, Vec2, WideScalar};

/// One axis of the slab test.
#[derive(Clone, Copy)]
enum Slab<S: Scalar> {
    /// `dir` has no component on this axis and the origin is within the
    /// slab: the axis imposes no limit.
    Free,
    /// The segment crosses the slab's planes at `s = enter / speed` and
    /// `s = exit / speed`, `enter ≤ exit`, `speed > 0`.
    Span {
        /// Signed distance to the entry plane along the motion.
        enter: S,
        /// Signed distance to the exit plane along the motion.
        exit: S,
        /// `|dir|` on this axis, positive.
        speed: S,
        /// The entry plane's coordinate.
        face: S,
        /// `true` if moving towards −∞ on this axis (entering through the
        /// max face, whose outward normal is +axis).
        negative: bool,
    },
}

/// The slab `[lo, hi]` of one axis for a segment starting at `o` with
/// component `d`; `None` if the segment can never be inside the slab.
fn slab<S: Scalar>(o: S, d: S, lo: S, hi: S) -> Option<Slab<S>> {
    if d.is_positive() {
        Some(Slab::Span {
            enter: lo.sub(o),
            exit: hi.sub(o),
            speed: d,
            face: lo,
            negative: false,
        })
    } else if d.is_negative() {
        Some(Slab::Span {
            enter: o.sub(hi),
            exit: o.sub(lo),
            speed: d.neg(),
            face: hi,
            negative: true,
        })
    } else if lo <= o && o <= hi {
        Some(Slab::Free)
    } else {
        None
    }
}

/// Casts the segment against the solid box (`|half|` is used).
///
/// # Method: exact slab test without division
///
/// On an axis with `dir_i ≠ 0` the segment is between the box's two planes
/// for `s ∈ [enter_i / speed_i, exit_i / speed_i]` (`speed_i = |dir_i|`,
/// `enter_i`, `exit_i` the signed distances to the entry and exit planes
/// along the motion). On an axis with `dir_i = 0` there is no division at
/// all: if the origin's coordinate is within the slab, the axis imposes no
/// limit, otherwise the segment misses.
///
/// The segment enters the box at the larger entry parameter and leaves it at
/// the smaller exit parameter. These fractions are compared by cross
/// multiplication in the wide type (`enter_x·speed_y` vs `enter_y·speed_x`,
/// products of narrow values, exact for `Fx` and `I48F16`), and the reach
/// test `enter_k ≤ s_max·speed_k` likewise, so every decision (hit or miss,
/// which face) is exact. Only the reported `s = enter_k / speed_k` is
/// divided, once, after the reach test has proved it at most `s_max`: the
/// quotient cannot overflow however small `speed_k` is, and it is truncated
/// by less than one ulp.
///
/// Ties: when the entry parameters of both axes are exactly equal (the
/// segment enters exactly through a corner), the **y** face is reported,
/// the rule of the rest of the geometry module.
///
/// The returned `point` lies exactly on the entered face: its coordinate on
/// the entry axis is the face's, and the other one is
/// `origin + s·dir` (one rounding) clamped to the face's extent.
#[must_use]
pub(crate) fn cast_box<S: Scalar>(
    origin: Vec2<S>,
    dir: Vec2<S>,
    s_max: S,
    center: Vec2<S>,
    half: Vec2<S>,
) -> Cast<S> {
    let half = half.abs();
    let lo = center - half;
    let hi = center + half;
    if lo.x <= origin.x && origin.x <= hi.x && lo.y <= origin.y && origin.y <= hi.y {
        return Cast::Inside;
    }
    let (Some(sx), Some(sy)) = (
        slab(origin.x, dir.x, lo.x, hi.x),
        slab(origin.y, dir.y, lo.y, hi.y),
    ) else {
        return Cast::Miss;
    };
    // The entering axis (`true` = x) and its slab, and the other slab.
    let (x_enters, enter_slab, other) = match (sx, sy) {
        // Both free means the origin is in both slabs, i.e. inside (handled
        // above); kept as a defined answer.
        (Slab::Free, Slab::Free) => return Cast::Miss,
        (Slab::Span { .. }, Slab::Free) => (true, sx, sy),
        (Slab::Free, Slab::Span { .. }) => (false, sy, sx),
        (
            Slab::Span {
                enter: ex,
                speed: vx,
                ..
            },
            Slab::Span {
                enter: ey,
                speed: vy,
                ..
            },
        ) => {
            // enter_x / vx > enter_y / vy  ⇔  enter_x·vy > enter_y·vx (both
            // speeds positive). Ties go to y.
            if ex.wide_mul(vy) > ey.wide_mul(vx) {
                (true, sx, sy)
            } else {
                (false, sy, sx)
            }
        }
    };
    let Slab::Span {
        enter,
        exit,
        speed,
        face,
        negative,
    } = enter_slab
    else {
        return Cast::Miss;
    };
    // The box must not be behind the origin on the entering axis...
    if exit.is_negative() {
        return Cast::Miss;
    }
    // ...nor on the other one, and the entry must come before the other
    // axis's exit: enter / speed ≤ exit_o / speed_o.
    if let Slab::Span {
        exit: exit_o,
        speed: speed_o,
        ..
    } = other
        && (exit_o.is_negative() || enter.wide_mul(speed_o) > exit_o.wide_mul(speed))
    {
        return Cast::Miss;
    }
    // Reach: enter / speed ≤ s_max. A negative `enter` cannot happen for an
    // origin outside the box (the axis on which it is outside has a
    // positive entry distance, or a negative exit distance and was
    // rejected), but is clamped to zero all the same.
    let enter = enter.max(S::ZERO);
    if S::Wide::from_narrow(enter) > s_max.wide_mul(speed) {
        return Cast::Miss;
    }
    // 0 ≤ enter ≤ s_max·speed, so the quotient is in [0, s_max]: no
    // overflow. (`min` only matters for the float references, whose
    // division rounds to nearest.)
    let s = enter.div(speed).min(s_max);
    let sign = if negative { S::ONE } else { S::ONE.neg() };
    let (point, normal) = if x_enters {
        let y = origin.y.add(dir.y.mul(s)).clamp(lo.y, hi.y);
        (Vec2::new(face, y), Vec2::new(sign, S::ZERO))
    } else {
        let x = origin.x.add(dir.x.mul(s)).clamp(lo.x, hi.x);
        (Vec2::new(x, face), Vec2::new(S::ZERO, sign))
    };
    Cast::Hit { s, point, normal }
}
