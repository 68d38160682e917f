//! Arbitrary scalars biased towards the values where fixed-point code
//! breaks: zero, one ulp, the documented limits and one ulp past them, the
//! extremes of the type, and small "physical" values.

use arbitrary::{Arbitrary, Unstructured};
use clockwork2d::prelude::{Fx, Vec2};

/// Raw bits of one `Fx` ulp (2⁻³²).
const ULP: i64 = 1;
/// Raw bits of 1.0.
const ONE: i64 = 1 << 32;

/// Edge values, as raw `I32F32` bits.
const EDGES: &[i64] = &[
    0,
    ULP,
    -ULP,
    ONE,
    -ONE,
    ONE / 2,
    ONE / 60,
    ONE / 10_000,
    // The world limit 2^15 and one ulp either side.
    ONE << 15,
    (ONE << 15) + ULP,
    (ONE << 15) - ULP,
    -(ONE << 15),
    -(ONE << 15) - ULP,
    // Largest shape size 4096 and just past it.
    ONE << 12,
    (ONE << 12) + ULP,
    // Largest max_speed 65536 and just past it.
    ONE << 16,
    (ONE << 16) + ULP,
    // Mass range ends (1e-6 and 1e9, approximately).
    4295,
    4294,
    ONE * 1_000_000_000,
    ONE * 1_000_000_001,
    i64::MAX,
    i64::MIN,
    i64::MAX - 1,
    i64::MIN + 1,
];

/// A scalar chosen by the fuzzer: mostly small physical values, often edge
/// values, sometimes any bits.
#[derive(Clone, Copy, Debug)]
pub struct FuzzFx(pub Fx);

impl<'a> Arbitrary<'a> for FuzzFx {
    fn arbitrary(u: &mut Unstructured<'a>) -> arbitrary::Result<Self> {
        let tag: u8 = u.arbitrary()?;
        let value = match tag % 8 {
            // Multiples of 1/256 within ±128: exact, physical.
            0..=4 => Fx::from_bits(i64::from(u.arbitrary::<i16>()?) << 24),
            // Edge values.
            5 | 6 => Fx::from_bits(*u.choose(EDGES)?),
            // Any bits.
            _ => Fx::from_bits(u.arbitrary()?),
        };
        Ok(FuzzFx(value))
    }

    fn size_hint(_depth: usize) -> (usize, Option<usize>) {
        (1, Some(9))
    }
}

/// A scalar in a physical range only: multiples of 1/256 within ±128.
#[derive(Clone, Copy, Debug)]
pub struct SmallFx(pub Fx);

impl<'a> Arbitrary<'a> for SmallFx {
    fn arbitrary(u: &mut Unstructured<'a>) -> arbitrary::Result<Self> {
        Ok(SmallFx(Fx::from_bits(
            i64::from(u.arbitrary::<i16>()?) << 24,
        )))
    }

    fn size_hint(_depth: usize) -> (usize, Option<usize>) {
        (2, Some(2))
    }
}

/// A vector of [`FuzzFx`] components.
#[derive(Clone, Copy, Debug, Arbitrary)]
pub struct FuzzVec(pub FuzzFx, pub FuzzFx);

impl FuzzVec {
    /// As an engine vector.
    #[must_use]
    pub fn get(self) -> Vec2<Fx> {
        Vec2::new(self.0.0, self.1.0)
    }
}

/// A vector of [`SmallFx`] components.
#[derive(Clone, Copy, Debug, Arbitrary)]
pub struct SmallVec(pub SmallFx, pub SmallFx);

impl SmallVec {
    /// As an engine vector.
    #[must_use]
    pub fn get(self) -> Vec2<Fx> {
        Vec2::new(self.0.0, self.1.0)
    }
}
