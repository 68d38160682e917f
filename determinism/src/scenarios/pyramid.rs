//! The `pyramid` scenario: the 20-row pyramid (210 boxes) settles and sleeps;
//! a ball knocks its top.

use super::*;

struct Pyramid;

impl Script for Pyramid {
    fn commands(&mut self, world: &World, _observer: &mut Observer<'_>) -> Vec<Command> {
        if world.tick() == 420 {
            // A ball dropped on the apex (row 20, top at y = 20).
            vec![Command::Spawn(
                BodyDef::dynamic(Shape::circle(r(2, 5)))
                    .position(vf(r(3, 10), n(26)))
                    .density(n(2)),
            )]
        } else {
            Vec::new()
        }
    }
}

pub(crate) fn pyramid() -> Built {
    let world: World = builtin("pyramid")?.build()?;
    Ok((world, Box::new(Pyramid)))
}
