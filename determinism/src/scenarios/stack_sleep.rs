//! The `stack_sleep` scenario: 10-box stack settles and sleeps; a dropped
//! ball and a wake command wake it.

use super::*;

struct StackSleep {
    boxes: Vec<BodyId>,
}

impl Script for StackSleep {
    fn commands(&mut self, world: &World, observer: &mut Observer<'_>) -> Vec<Command> {
        let tick = world.tick();
        if tick % 60 == 0 {
            // Which boxes are awake is in the state; the probe records what
            // a point query at the stack's top answers.
            let top = world.body(nth(&self.boxes, 9)).map(|b| b.position());
            if let Some(p) = top {
                observer
                    .probe
                    .ids(&world.query_point(p, &QueryFilter::default()));
            }
        }
        match tick {
            // The stack is asleep by now: a ball dropped on it wakes it.
            360 => vec![Command::Spawn(
                BodyDef::dynamic(Shape::circle(r(3, 10)))
                    .position(vf(r(1, 5), n(14)))
                    .restitution(r(1, 5)),
            )],
            // And a command wakes it again after it has settled.
            540 => vec![Command::Wake(nth(&self.boxes, 0))],
            _ => Vec::new(),
        }
    }
}

pub(crate) fn stack_sleep() -> Built {
    let world: World = builtin("stack")?.build()?;
    let boxes = ids_of(&world, BodyKind::Dynamic);
    Ok((world, Box::new(StackSleep { boxes })))
}
