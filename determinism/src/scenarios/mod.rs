//! The suite's scenarios: a world and a script each.
//!
//! Every number here is an integer or a ratio of integers converted by the
//! scalar (`from_int`, `from_ratio`): no float appears, so the inputs are
//! the same bits on every target by construction. Built-in scenes are
//! loaded from their RON text, whose decimal literals the scene loader
//! converts with correct rounding.

mod bounds_extreme;
mod bullets_toi;
mod commands_churn;
mod grapple_rays;
mod pyramid;
mod ropes_chain;
mod springs;
mod stack_sleep;

pub(crate) use bounds_extreme::bounds_extreme;
pub(crate) use bullets_toi::bullets_toi;
pub(crate) use commands_churn::commands_churn;
pub(crate) use grapple_rays::grapple_rays;
pub(crate) use pyramid::pyramid;
pub(crate) use ropes_chain::ropes_chain;
pub(crate) use springs::springs;
pub(crate) use stack_sleep::stack_sleep;

use super::{Built, Observer, Script};
use clockwork2d::constraints::{Anchor, Constraint, ConstraintId};
use clockwork2d::dynamics::{BodyDef, BodyId, BodyKind};
use clockwork2d::geometry::{Aabb, Shape};
use clockwork2d::math::{Fx, Scalar, Vec2};
use clockwork2d::world::{Command, CommandOutcome, QueryFilter, World, WorldError, WorldSettings};
use clockwork2d_scene::builtin;
use clockwork2d_scene::scripted_commands;

/// An integer as a scalar.
fn n(value: i32) -> Fx {
    <Fx as Scalar>::from_int(value)
}

/// `numerator / denominator` as a scalar.
fn r(numerator: i32, denominator: i32) -> Fx {
    <Fx as Scalar>::from_ratio(numerator, denominator)
}

/// A vector of two integers.
fn vi(x: i32, y: i32) -> Vec2<Fx> {
    Vec2::new(n(x), n(y))
}

/// A vector of two scalars.
fn vf(x: Fx, y: Fx) -> Vec2<Fx> {
    Vec2::new(x, y)
}

/// The ids of the world's bodies of one kind, in id order.
fn ids_of(world: &World, kind: BodyKind) -> Vec<BodyId> {
    world
        .bodies()
        .filter(|(_, b)| b.kind() == kind)
        .map(|(id, _)| id)
        .collect()
}

/// The `i`-th element of `ids`, or a never-issued id (commands naming it
/// are refused, never a panic).
fn nth(ids: &[BodyId], i: usize) -> BodyId {
    ids.get(i)
        .copied()
        .unwrap_or(BodyId::from_parts(u32::MAX, u32::MAX))
}

/// Ids spawned and constraints added by a tick's commands, in order.
fn outcomes(results: &[Result<CommandOutcome, WorldError>]) -> (Vec<BodyId>, Vec<ConstraintId>) {
    let mut bodies = Vec::new();
    let mut constraints = Vec::new();
    for result in results {
        match result {
            Ok(CommandOutcome::Spawned(id)) => bodies.push(*id),
            Ok(CommandOutcome::ConstraintAdded(id)) => constraints.push(*id),
            _ => {}
        }
    }
    (bodies, constraints)
}

/// The impulse that changes a body's velocity by `dv` (`dv · mass`).
fn impulse_for(world: &World, body: BodyId, dv: Vec2<Fx>) -> Command {
    let mass = world.body(body).map_or(<Fx as Scalar>::ONE, |b| b.mass());
    Command::ApplyImpulse {
        body,
        impulse: dv.scale(mass),
    }
}
