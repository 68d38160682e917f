//! A small deterministic generator for the tests' random scenes
//! (SplitMix64): the same seed gives the same scene on every machine.

/// SplitMix64; the state is the seed.
pub struct SplitMix(pub u64);

impl SplitMix {
    /// The next value, uniform in `[0, 1)` with 53 random bits.
    pub fn unit(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    }

    /// The next value, uniform in `[low, high)`.
    pub fn range(&mut self, low: f64, high: f64) -> f64 {
        low + (high - low) * self.unit()
    }
}
