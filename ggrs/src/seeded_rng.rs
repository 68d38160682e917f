//! [`SeededRng`]: a small deterministic generator for test inputs and for
//! the link conditioner (never for the simulation).

/// SplitMix64 (Steele, Lea and Flood, 2014): a 64-bit counter passed
/// through a bijective mixer. Every seed gives a full-period stream; the
/// same seed gives the same stream on every machine.
#[derive(Clone, Debug)]
pub struct SeededRng {
    state: u64,
}

impl SeededRng {
    /// A generator whose stream is fixed by `seed`.
    #[must_use]
    pub fn new(seed: u64) -> Self {
        SeededRng { state: seed }
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.state = self.state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A value in `0..bound` (0 when `bound` is 0), by the multiply-shift
    /// reduction (bias below 2⁻³² for the small bounds used here).
    pub fn below(&mut self, bound: u32) -> u32 {
        let hi = self.next_u64() >> 32;
        u32::try_from((hi * u64::from(bound)) >> 32).unwrap_or(0)
    }

    /// True with probability `permille / 1000`.
    pub fn chance(&mut self, permille: u32) -> bool {
        self.below(1000) < permille
    }
}
