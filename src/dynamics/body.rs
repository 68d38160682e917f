//! Bodies: their kinds, the [`BodyDef`] builder and the simulated [`Body`].

use serde::{Deserialize, Serialize};

use crate::geometry::{Aabb, Shape};
use crate::math::Fx;
use crate::math::{Scalar, Vec2};

/// The island key of a body that is not asleep.
pub(crate) const NO_ISLAND: u32 = u32::MAX;

/// How a body takes part in the simulation.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub enum BodyKind {
    /// Never moves; infinite mass (ground, walls).
    Fixed,
    /// Moves with the velocity it is given; infinite mass, unaffected by
    /// gravity and contacts (moving platforms, shaking walls).
    Kinematic,
    /// Moved by gravity, contacts and constraints.
    Dynamic,
}

/// How the mass of a dynamic body is given.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub enum MassSpec<S: Scalar = Fx> {
    /// Mass = density × area.
    Density(S),
    /// The mass itself.
    Mass(S),
}

/// The description of a body to add: a builder with sensible defaults.
///
/// ```
/// use clockwork2d::prelude::*;
/// let def = BodyDef::dynamic(Shape::circle(fx(0.25)))
///     .position(Vec2::new(fx(0.0), fx(4.0)))
///     .restitution(fx(0.5))
///     .friction(fx(0.2));
/// assert_eq!(def.kind, BodyKind::Dynamic);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct BodyDef<S: Scalar = Fx> {
    /// Fixed, kinematic or dynamic.
    pub kind: BodyKind,
    /// The collision shape, centred on `position`.
    pub shape: Shape<S>,
    /// Initial position of the shape's centre.
    pub position: Vec2<S>,
    /// Initial velocity (units per second).
    pub velocity: Vec2<S>,
    /// Density or mass (dynamic bodies only). Default: density 1.
    pub mass: MassSpec<S>,
    /// Coefficient of restitution in [0, 1] (default 0). A pair uses the
    /// larger of its two coefficients.
    pub restitution: S,
    /// Coulomb friction coefficient ≥ 0 (default 0.6). A pair uses the
    /// geometric mean of its two coefficients.
    pub friction: S,
    /// Multiplier on the world's gravity (default 1).
    pub gravity_scale: S,
    /// Continuous collision by exact time of impact against everything the
    /// body can hit (for small fast bodies).
    pub bullet: bool,
}

impl<S: Scalar> BodyDef<S> {
    fn with_kind(kind: BodyKind, shape: Shape<S>) -> Self {
        BodyDef {
            kind,
            shape,
            position: Vec2::ZERO,
            velocity: Vec2::ZERO,
            mass: MassSpec::Density(S::ONE),
            restitution: S::ZERO,
            friction: S::from_ratio(3, 5),
            gravity_scale: S::ONE,
            bullet: false,
        }
    }

    /// A fixed (static) body.
    #[must_use]
    pub fn fixed(shape: Shape<S>) -> Self {
        Self::with_kind(BodyKind::Fixed, shape)
    }

    /// A kinematic body.
    #[must_use]
    pub fn kinematic(shape: Shape<S>) -> Self {
        Self::with_kind(BodyKind::Kinematic, shape)
    }

    /// A dynamic body.
    #[must_use]
    pub fn dynamic(shape: Shape<S>) -> Self {
        Self::with_kind(BodyKind::Dynamic, shape)
    }

    /// Sets the initial position.
    #[must_use]
    pub fn position(mut self, position: Vec2<S>) -> Self {
        self.position = position;
        self
    }

    /// Sets the initial velocity.
    #[must_use]
    pub fn velocity(mut self, velocity: Vec2<S>) -> Self {
        self.velocity = velocity;
        self
    }

    /// Sets the density (mass = density × area).
    #[must_use]
    pub fn density(mut self, density: S) -> Self {
        self.mass = MassSpec::Density(density);
        self
    }

    /// Sets the mass directly.
    #[must_use]
    pub fn mass(mut self, mass: S) -> Self {
        self.mass = MassSpec::Mass(mass);
        self
    }

    /// Sets the restitution.
    #[must_use]
    pub fn restitution(mut self, restitution: S) -> Self {
        self.restitution = restitution;
        self
    }

    /// Sets the friction coefficient.
    #[must_use]
    pub fn friction(mut self, friction: S) -> Self {
        self.friction = friction;
        self
    }

    /// Sets the gravity scale.
    #[must_use]
    pub fn gravity_scale(mut self, gravity_scale: S) -> Self {
        self.gravity_scale = gravity_scale;
        self
    }

    /// Marks the body as a bullet (continuous collision).
    #[must_use]
    pub fn bullet(mut self, bullet: bool) -> Self {
        self.bullet = bullet;
        self
    }
}

/// A body in the world. Read it with [`crate::world::World::body`]; change it with
/// [`crate::world::Command`]s.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "")]
pub struct Body<S: Scalar = Fx> {
    pub(crate) kind: BodyKind,
    pub(crate) shape: Shape<S>,
    pub(crate) position: Vec2<S>,
    pub(crate) velocity: Vec2<S>,
    /// Mass (zero for fixed and kinematic bodies).
    pub(crate) mass: S,
    /// 1 / mass, precomputed so the solver never divides (zero for fixed and
    /// kinematic bodies: infinite mass).
    pub(crate) inverse_mass: S,
    pub(crate) restitution: S,
    pub(crate) friction: S,
    pub(crate) gravity_scale: S,
    pub(crate) bullet: bool,
    /// `false` while asleep.
    pub(crate) awake: bool,
    /// Left the world bounds: held in place and ignored by the solver.
    pub(crate) frozen: bool,
    /// Seconds the body has been slower than the sleep threshold.
    pub(crate) sleep_time: S,
    /// Key of the sleeping island the body belongs to ([`NO_ISLAND`] while
    /// awake).
    pub(crate) island: u32,
}

impl<S: Scalar> Body<S> {
    /// Fixed, kinematic or dynamic.
    #[must_use]
    pub fn kind(&self) -> BodyKind {
        self.kind
    }
    /// The collision shape.
    #[must_use]
    pub fn shape(&self) -> Shape<S> {
        self.shape
    }
    /// Position of the shape's centre.
    #[must_use]
    pub fn position(&self) -> Vec2<S> {
        self.position
    }
    /// Velocity in units per second.
    #[must_use]
    pub fn velocity(&self) -> Vec2<S> {
        self.velocity
    }
    /// Mass (zero for fixed and kinematic bodies, which have infinite mass).
    #[must_use]
    pub fn mass(&self) -> S {
        self.mass
    }
    /// Restitution coefficient.
    #[must_use]
    pub fn restitution(&self) -> S {
        self.restitution
    }
    /// Friction coefficient.
    #[must_use]
    pub fn friction(&self) -> S {
        self.friction
    }
    /// Gravity scale.
    #[must_use]
    pub fn gravity_scale(&self) -> S {
        self.gravity_scale
    }
    /// `true` for bullets.
    #[must_use]
    pub fn is_bullet(&self) -> bool {
        self.bullet
    }
    /// `true` unless the body sleeps. Fixed bodies report `false`.
    #[must_use]
    pub fn is_awake(&self) -> bool {
        self.awake
    }
    /// `true` once the body has left the world bounds (it is then held
    /// still and takes no further part in the simulation).
    #[must_use]
    pub fn is_frozen(&self) -> bool {
        self.frozen
    }
    /// The body's bounding box at its current position.
    #[must_use]
    pub fn aabb(&self) -> Aabb<S> {
        self.shape.bounding_aabb_at(self.position)
    }
    /// `true` for a dynamic body that is awake and not frozen.
    #[inline]
    pub(crate) fn is_simulated_dynamic(&self) -> bool {
        self.kind == BodyKind::Dynamic && self.awake && !self.frozen
    }
    /// `true` if the body can move this step (awake dynamic or kinematic).
    #[inline]
    pub(crate) fn is_moving(&self) -> bool {
        self.kind != BodyKind::Fixed && self.awake && !self.frozen
    }
}
