//! [`WorldError`]: why the world refused a request.

use core::fmt;

use crate::constraints::ConstraintId;
use crate::dynamics::BodyId;

/// Why the world refused an operation. On any error the world is unchanged.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum WorldError {
    /// A circle radius or box half extent that is zero or negative.
    NonPositiveSize,
    /// A shape larger than the world allows (radius or half extent above
    /// 4096 units).
    ShapeTooLarge,
    /// A density or mass that is zero or negative.
    NonPositiveMass,
    /// A dynamic body's mass (density × area, or the mass given) outside
    /// [2⁻¹⁰, 2²⁰] = [1/1024, 1 048 576]: below, its inverse keeps too few
    /// bits; above, mass × speed leaves the number range.
    MassOutOfRange,
    /// Restitution outside [0, 1], friction or gravity scale outside their
    /// ranges.
    MaterialOutOfRange {
        /// The field.
        field: &'static str,
    },
    /// A position outside the world bounds.
    OutOfBounds,
    /// A velocity (given, or resulting from an impulse) with a component
    /// above `max_speed` in magnitude (the check is per axis).
    SpeedTooLarge,
    /// An id that names no live body (never issued, or removed since).
    UnknownBody(BodyId),
    /// The operation needs a dynamic body (e.g. an impulse on a fixed body).
    NotDynamic(BodyId),
    /// The operation is not possible on a fixed body.
    FixedBody(BodyId),
    /// The world holds the maximum number of bodies (2³¹).
    TooManyBodies,
    /// An id that names no live constraint.
    UnknownConstraint(ConstraintId),
    /// A constraint whose parameters are out of range.
    InvalidConstraint {
        /// What is wrong and what the range is.
        reason: &'static str,
    },
    /// The world holds the maximum number of constraints (2³¹).
    TooManyConstraints,
    /// A settings field outside its documented range.
    InvalidSettings {
        /// The field.
        field: &'static str,
        /// What the range is.
        reason: &'static str,
    },
}

impl fmt::Display for WorldError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            WorldError::NonPositiveSize => {
                write!(f, "shape size must be positive (radius / half extents > 0)")
            }
            WorldError::ShapeTooLarge => {
                write!(
                    f,
                    "shape too large: radius and half extents must be at most 4096"
                )
            }
            WorldError::NonPositiveMass => write!(f, "density and mass must be positive"),
            WorldError::MassOutOfRange => write!(
                f,
                "mass out of range: a dynamic body's mass (density × area, or the mass given) must be between 1/1024 (2^-10, about 0.000977) and 1048576 (2^20)"
            ),
            WorldError::MaterialOutOfRange { field } => write!(
                f,
                "{field} out of range (restitution in [0, 1], friction in [0, 1000], gravity scale in [-1000, 1000])"
            ),
            WorldError::OutOfBounds => write!(f, "position outside the world bounds"),
            WorldError::SpeedTooLarge => {
                write!(
                    f,
                    "velocity too large: each component (|vx|, |vy|) must be at most the world's max_speed setting"
                )
            }
            WorldError::UnknownBody(id) => {
                write!(f, "{id} does not exist (never created, or removed)")
            }
            WorldError::NotDynamic(id) => write!(f, "{id} is not a dynamic body"),
            WorldError::FixedBody(id) => write!(f, "{id} is a fixed body and cannot move"),
            WorldError::TooManyBodies => write!(f, "the world is full (2^31 bodies)"),
            WorldError::UnknownConstraint(id) => {
                write!(f, "{id} does not exist (never created, or removed)")
            }
            WorldError::InvalidConstraint { reason } => write!(f, "invalid constraint: {reason}"),
            WorldError::TooManyConstraints => {
                write!(f, "the world is full (2^31 constraints)")
            }
            WorldError::InvalidSettings { field, reason } => {
                write!(f, "invalid world setting {field}: {reason}")
            }
        }
    }
}

impl std::error::Error for WorldError {}
