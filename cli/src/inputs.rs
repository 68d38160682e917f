//! Input files for `clockwork2d record --inputs FILE`: a RON list of
//! `(tick, [commands])` with decimal numbers, converted once to the scalar
//! (like scene files).
//!
//! ```text
//! [
//!     (0, [Spawn((kind: Dynamic, shape: Circle(radius: 0.5), position: (0.0, 8.0)))]),
//!     (30, [Impulse(body: (1, 0), impulse: (2.0, 0.0)), Wake((0, 0))]),
//!     (60, [Velocity(body: (1, 0), velocity: (0.0, 3.0)), Despawn((1, 0))]),
//! ]
//! ```

use core::fmt;

use serde::{Deserialize, Serialize};

use clockwork2d::dynamics::{BodyDef, BodyId};
use clockwork2d::geometry::Shape;
use clockwork2d::math::{Scalar, Vec2};
use clockwork2d::world::Command;
use clockwork2d_scene::{SceneBody, SceneKind, SceneShape};

/// Most entries an input file may have (bounds memory for untrusted files).
const MAX_INPUT_COMMANDS: usize = 1 << 20;

/// Parsed inputs: `(tick, commands of that tick)`, sorted by tick.
pub type TickInputs<S> = Vec<(u64, Vec<Command<S>>)>;

/// One command of an input file. Body ids are `(index, generation)`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum InputCommand {
    /// [`Command::Spawn`] of a body described as in scene files.
    Spawn(SceneBody),
    /// [`Command::Despawn`].
    Despawn((u32, u32)),
    /// [`Command::ApplyImpulse`].
    Impulse {
        /// The body.
        body: (u32, u32),
        /// The impulse (x, y).
        impulse: (f64, f64),
    },
    /// [`Command::SetVelocity`].
    Velocity {
        /// The body.
        body: (u32, u32),
        /// The velocity (x, y).
        velocity: (f64, f64),
    },
    /// [`Command::SetPosition`].
    Position {
        /// The body.
        body: (u32, u32),
        /// The position (x, y).
        position: (f64, f64),
    },
    /// [`Command::Wake`].
    Wake((u32, u32)),
}

/// Why an input file was refused.
#[derive(Clone, Debug, PartialEq)]
pub enum InputError {
    /// Not valid RON for a list of `(tick, [commands])`.
    Parse(String),
    /// A NaN or infinite number.
    NotFinite {
        /// The index of the offending entry.
        entry: usize,
    },
    /// More than 2²⁰ commands.
    TooMany,
}

impl fmt::Display for InputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            InputError::Parse(e) => write!(f, "not a valid input list: {e}"),
            InputError::NotFinite { entry } => {
                write!(f, "entry {entry} has a number that is NaN or infinite")
            }
            InputError::TooMany => write!(f, "more than {MAX_INPUT_COMMANDS} commands"),
        }
    }
}

impl std::error::Error for InputError {}

fn num<S: Scalar>(v: f64, entry: usize) -> Result<S, InputError> {
    if v.is_finite() {
        Ok(S::from_f64(v))
    } else {
        Err(InputError::NotFinite { entry })
    }
}

fn pair<S: Scalar>(v: (f64, f64), entry: usize) -> Result<Vec2<S>, InputError> {
    Ok(Vec2::new(num(v.0, entry)?, num(v.1, entry)?))
}

fn id((index, generation): (u32, u32)) -> BodyId {
    BodyId::from_parts(index, generation)
}

impl InputCommand {
    /// The engine command (numbers converted to the scalar, rounding to
    /// nearest). `entry` is only used in error messages.
    ///
    /// # Errors
    /// [`InputError::NotFinite`] for NaN or infinite numbers.
    pub fn to_command<S: Scalar>(&self, entry: usize) -> Result<Command<S>, InputError> {
        Ok(match self {
            InputCommand::Spawn(b) => {
                let shape = match b.shape {
                    SceneShape::Circle { radius } => Shape::circle(num(radius, entry)?),
                    SceneShape::Box { half } => Shape::aabb(pair(half, entry)?),
                };
                let def = match b.kind {
                    SceneKind::Fixed => BodyDef::fixed(shape),
                    SceneKind::Kinematic => BodyDef::kinematic(shape),
                    SceneKind::Dynamic => BodyDef::dynamic(shape),
                };
                let m = &b.material;
                Command::Spawn(
                    def.position(pair(b.position, entry)?)
                        .velocity(pair(b.velocity, entry)?)
                        .density(num(m.density, entry)?)
                        .restitution(num(m.restitution, entry)?)
                        .friction(num(m.friction, entry)?)
                        .gravity_scale(num(m.gravity_scale, entry)?)
                        .bullet(m.bullet),
                )
            }
            InputCommand::Despawn(body) => Command::Despawn(id(*body)),
            InputCommand::Impulse { body, impulse } => Command::ApplyImpulse {
                body: id(*body),
                impulse: pair(*impulse, entry)?,
            },
            InputCommand::Velocity { body, velocity } => Command::SetVelocity {
                body: id(*body),
                velocity: pair(*velocity, entry)?,
            },
            InputCommand::Position { body, position } => Command::SetPosition {
                body: id(*body),
                position: pair(*position, entry)?,
            },
            InputCommand::Wake(body) => Command::Wake(id(*body)),
        })
    }
}

/// Parses an input file: a RON list of `(tick, [commands])`, where `tick`
/// counts from the start of the recording. Entries may come in any order;
/// they are sorted by tick (stably, so commands of one tick keep their
/// order).
///
/// # Errors
/// An [`InputError`].
pub fn parse_inputs<S: Scalar>(text: &str) -> Result<TickInputs<S>, InputError> {
    let raw: Vec<(u64, Vec<InputCommand>)> = ron::Options::default()
        .from_str(text)
        .map_err(|e| InputError::Parse(e.to_string()))?;
    let total: usize = raw.iter().map(|(_, c)| c.len()).sum();
    if total > MAX_INPUT_COMMANDS {
        return Err(InputError::TooMany);
    }
    let mut out = Vec::with_capacity(raw.len());
    for (entry, (tick, commands)) in raw.iter().enumerate() {
        let converted = commands
            .iter()
            .map(|c| c.to_command(entry))
            .collect::<Result<Vec<_>, _>>()?;
        out.push((*tick, converted));
    }
    out.sort_by_key(|(tick, _)| *tick);
    Ok(out)
}

#[cfg(test)]
mod tests {
    use clockwork2d::prelude::Fx;

    use super::parse_inputs;

    #[test]
    fn the_module_example_parses() {
        let inputs = parse_inputs::<Fx>(
            r#"[
            (0, [Spawn((kind: Dynamic, shape: Circle(radius: 0.5), position: (0.0, 8.0)))]),
            (30, [Impulse(body: (1, 0), impulse: (2.0, 0.0)), Wake((0, 0))]),
            (60, [Velocity(body: (1, 0), velocity: (0.0, 3.0)), Despawn((1, 0))]),
        ]"#,
        )
        .unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(inputs.len(), 3);
        assert_eq!(inputs[1].0, 30);
        assert_eq!(inputs[1].1.len(), 2);
    }
}
