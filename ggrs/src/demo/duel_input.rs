//! [`DuelInput`]: what a player sends each frame (two bytes), and
//! [`InputScript`]: seeded random play.

use serde::{Deserialize, Serialize};

use crate::SeededRng;

/// One player's input for one frame. Every value is valid (a remote peer
/// can send any bytes): unknown button bits are ignored and the aim is
/// taken modulo the number of directions.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct DuelInput {
    /// Button bits: [`DuelInput::LEFT`], [`DuelInput::RIGHT`],
    /// [`DuelInput::JUMP`], [`DuelInput::GRAPPLE`].
    pub buttons: u8,
    /// Aim of the grapple: an index into [`AIM_DIRECTIONS`] (modulo its
    /// length).
    pub aim: u8,
}

impl DuelInput {
    /// Push left.
    pub const LEFT: u8 = 1;
    /// Push right.
    pub const RIGHT: u8 = 2;
    /// Jump (an upward impulse).
    pub const JUMP: u8 = 4;
    /// Grapple held: fire the rope if none is attached; releasing the
    /// button releases the rope.
    pub const GRAPPLE: u8 = 8;

    /// Whether `button` is held.
    #[must_use]
    pub fn holds(self, button: u8) -> bool {
        self.buttons & button != 0
    }
}

/// Aim directions of the grapple, as small integer vectors (the ray cast
/// normalises them): eight directions across the upper half-plane, from
/// nearly horizontal left to nearly horizontal right.
pub const AIM_DIRECTIONS: [(i32, i32); 8] = [
    (-4, 1),
    (-3, 2),
    (-2, 3),
    (-1, 4),
    (1, 4),
    (2, 3),
    (3, 2),
    (4, 1),
];

/// Seeded random play: a player who holds a choice of buttons and aim for
/// a while (each frame, a 1-in-12 chance of a new choice), so the grapple
/// is fired, held for a swing, and released.
#[derive(Clone, Debug)]
pub struct InputScript {
    rng: SeededRng,
    current: DuelInput,
}

impl InputScript {
    /// A script fixed by `seed`.
    #[must_use]
    pub fn new(seed: u64) -> Self {
        InputScript {
            rng: SeededRng::new(seed),
            current: DuelInput::default(),
        }
    }

    /// The input of the next frame.
    pub fn next_input(&mut self) -> DuelInput {
        if self.rng.below(12) == 0 {
            let bits = self.rng.next_u64();
            self.current = DuelInput {
                buttons: (bits & 0x0f) as u8,
                aim: ((bits >> 8) & 0xff) as u8,
            };
        }
        self.current
    }
}
