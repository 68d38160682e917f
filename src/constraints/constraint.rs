//! [`Constraint`]: the three constraint classes and their builders.

use serde::{Deserialize, Serialize};

use super::Anchor;
use crate::math::Fx;
use crate::math::{Scalar, Vec2};

/// A constraint between two anchors.
///
/// ```
/// use clockwork2d::prelude::*;
/// let mut world = World::new(WorldSettings::default());
/// let ball = world.add_body(BodyDef::dynamic(Shape::circle(fx(0.25)))
///     .position(Vec2::new(fx(0.0), fx(4.0)))).unwrap();
/// let rope = world.add_constraint(Constraint::rope(
///     Anchor::Point(Vec2::new(fx(0.0), fx(6.0))), Anchor::Body(ball), fx(2.0))).unwrap();
/// let spring = world.add_constraint(Constraint::bendy_spring(
///     Anchor::Point(Vec2::new(fx(0.0), fx(4.0))), Anchor::Body(ball),
///     Vec2::new(fx(50.0), fx(50.0)), fx(1.0))).unwrap();
/// assert_ne!(rope, spring);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub enum Constraint<S: Scalar = Fx> {
    /// Two independent springs, one per axis, pulling `b` toward
    /// `a + rest_offset` (Hooke's law per axis: F = -k·x - c·v).
    BendySpring {
        /// The anchor the spring pulls toward.
        a: Anchor<S>,
        /// The pulled anchor.
        b: Anchor<S>,
        /// Where `b` rests relative to `a`.
        rest_offset: Vec2<S>,
        /// Stiffness per axis (force per unit length), ≥ 0.
        stiffness: Vec2<S>,
        /// Damping (force per unit speed) on both axes, ≥ 0.
        damping: S,
    },
    /// The "rotational" spring: a pole on a pivot with a spring along it.
    /// Force only along the pivot→body line; the body swings freely around
    /// the pivot.
    RadialSpring {
        /// The pivot.
        pivot: Anchor<S>,
        /// The body end.
        body: Anchor<S>,
        /// Length at rest, ≥ 0.
        rest_length: S,
        /// Stiffness along the pole, ≥ 0.
        stiffness: S,
        /// Damping along the pole, ≥ 0.
        damping: S,
    },
    /// An ideal rope: slack below `max_length`, taut at it. At full length
    /// the velocity along the rope is removed (`restitution` 0) or reflected
    /// (`restitution` 1); the tangential velocity is kept.
    Rope {
        /// One end.
        a: Anchor<S>,
        /// The other end.
        b: Anchor<S>,
        /// Length of the rope, > 0.
        max_length: S,
        /// 0 = a real rope, 1 = the mirror rule.
        restitution: S,
    },
}

impl<S: Scalar> Constraint<S> {
    /// A bendy spring pulling `b` toward `a` (rest offset zero; see
    /// [`with_rest_offset`](Self::with_rest_offset)).
    #[must_use]
    pub fn bendy_spring(a: Anchor<S>, b: Anchor<S>, stiffness: Vec2<S>, damping: S) -> Self {
        Constraint::BendySpring {
            a,
            b,
            rest_offset: Vec2::ZERO,
            stiffness,
            damping,
        }
    }

    /// A radial ("rotational") spring from `pivot` to `body`.
    #[must_use]
    pub fn radial_spring(
        pivot: Anchor<S>,
        body: Anchor<S>,
        rest_length: S,
        stiffness: S,
        damping: S,
    ) -> Self {
        Constraint::RadialSpring {
            pivot,
            body,
            rest_length,
            stiffness,
            damping,
        }
    }

    /// A rope of length `max_length` with restitution 0.
    #[must_use]
    pub fn rope(a: Anchor<S>, b: Anchor<S>, max_length: S) -> Self {
        Constraint::Rope {
            a,
            b,
            max_length,
            restitution: S::ZERO,
        }
    }

    /// Sets a bendy spring's rest offset (no effect on other kinds).
    #[must_use]
    pub fn with_rest_offset(mut self, offset: Vec2<S>) -> Self {
        if let Constraint::BendySpring { rest_offset, .. } = &mut self {
            *rest_offset = offset;
        }
        self
    }

    /// Sets a rope's restitution (no effect on other kinds).
    #[must_use]
    pub fn with_restitution(mut self, value: S) -> Self {
        if let Constraint::Rope { restitution, .. } = &mut self {
            *restitution = value;
        }
        self
    }

    /// The two anchors, in order.
    #[must_use]
    pub fn anchors(&self) -> (Anchor<S>, Anchor<S>) {
        match *self {
            Constraint::BendySpring { a, b, .. } | Constraint::Rope { a, b, .. } => (a, b),
            Constraint::RadialSpring { pivot, body, .. } => (pivot, body),
        }
    }
}
