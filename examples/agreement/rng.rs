//! A tiny deterministic generator (SplitMix64) so the report is repeatable.

/// SplitMix64 state.
pub struct Rng(pub u64);

impl Rng {
    /// Next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A value uniform in `[lo, hi)`, quantised to 1/1024 so that it is
    /// exactly representable in every scalar (the error then comes only from
    /// the query, not from converting its input).
    #[allow(clippy::cast_precision_loss)]
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        let unit = (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
        ((lo + unit * (hi - lo)) * 1024.0).round() / 1024.0
    }
}
