//! [`LinkConditions`]: how bad a simulated network link is.

use std::time::Duration;

/// What the link does to each datagram sent through a
/// [`UdpTransport`](super::UdpTransport). Probabilities are in per mille so
/// they are exact integers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct LinkConditions {
    /// Chance that a datagram is never sent.
    pub drop_permille: u32,
    /// Chance that a datagram that is sent is sent twice (the copy with its
    /// own delay).
    pub duplicate_permille: u32,
    /// Chance that a datagram is held back by an extra `reorder_delay`, so
    /// that datagrams sent after it overtake it.
    pub reorder_permille: u32,
    /// Base one-way delay added to every datagram.
    pub latency: Duration,
    /// Uniform random extra delay in `[0, jitter]`.
    pub jitter: Duration,
    /// Extra delay of a reordered datagram.
    pub reorder_delay: Duration,
    /// Seed of the link's random choices.
    pub seed: u64,
}

impl LinkConditions {
    /// A perfect link: nothing dropped, duplicated, reordered or delayed.
    #[must_use]
    pub fn perfect() -> Self {
        LinkConditions {
            drop_permille: 0,
            duplicate_permille: 0,
            reorder_permille: 0,
            latency: Duration::ZERO,
            jitter: Duration::ZERO,
            reorder_delay: Duration::ZERO,
            seed: 0,
        }
    }

    /// The bad link: 20 % dropped, 5 % duplicated, 10 % reordered
    /// (held back 30 ms), 20 ms latency with 10 ms jitter.
    #[must_use]
    pub fn lossy(seed: u64) -> Self {
        LinkConditions {
            drop_permille: 200,
            duplicate_permille: 50,
            reorder_permille: 100,
            latency: Duration::from_millis(20),
            jitter: Duration::from_millis(10),
            reorder_delay: Duration::from_millis(30),
            seed,
        }
    }
}
