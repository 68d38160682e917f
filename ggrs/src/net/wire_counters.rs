//! [`WireCounters`]: what a transport sent and received, readable while the
//! session owns the transport.

use std::sync::Arc;
use std::sync::atomic::{AtomicU64, Ordering};

/// Shared counters of one [`UdpTransport`](super::UdpTransport) (clone the
/// `Arc` before handing the transport to GGRS).
#[derive(Debug, Default)]
pub struct WireCounters {
    datagrams_sent: AtomicU64,
    bytes_sent: AtomicU64,
    dropped: AtomicU64,
    duplicated: AtomicU64,
    reordered: AtomicU64,
    datagrams_received: AtomicU64,
    bytes_received: AtomicU64,
    undecodable: AtomicU64,
}

/// A reading of [`WireCounters`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct WireTotals {
    /// Datagrams handed to the operating system (duplicates included).
    pub datagrams_sent: u64,
    /// Their bytes (UDP payload).
    pub bytes_sent: u64,
    /// Datagrams the link conditioner dropped.
    pub dropped: u64,
    /// Extra copies the link conditioner sent.
    pub duplicated: u64,
    /// Datagrams held back to be overtaken.
    pub reordered: u64,
    /// Datagrams received and decoded.
    pub datagrams_received: u64,
    /// Bytes of all datagrams received (decodable or not).
    pub bytes_received: u64,
    /// Datagrams received that are not a GGRS message (garbage): dropped,
    /// counted, never a panic.
    pub undecodable: u64,
}

impl WireCounters {
    /// New zeroed counters.
    #[must_use]
    pub fn new() -> Arc<Self> {
        Arc::new(WireCounters::default())
    }

    /// The current totals.
    #[must_use]
    pub fn totals(&self) -> WireTotals {
        let get = |c: &AtomicU64| c.load(Ordering::Relaxed);
        WireTotals {
            datagrams_sent: get(&self.datagrams_sent),
            bytes_sent: get(&self.bytes_sent),
            dropped: get(&self.dropped),
            duplicated: get(&self.duplicated),
            reordered: get(&self.reordered),
            datagrams_received: get(&self.datagrams_received),
            bytes_received: get(&self.bytes_received),
            undecodable: get(&self.undecodable),
        }
    }

    pub(super) fn sent(&self, bytes: usize) {
        self.datagrams_sent.fetch_add(1, Ordering::Relaxed);
        self.bytes_sent.fetch_add(bytes as u64, Ordering::Relaxed);
    }

    pub(super) fn dropped(&self) {
        self.dropped.fetch_add(1, Ordering::Relaxed);
    }

    pub(super) fn duplicated(&self) {
        self.duplicated.fetch_add(1, Ordering::Relaxed);
    }

    pub(super) fn reordered(&self) {
        self.reordered.fetch_add(1, Ordering::Relaxed);
    }

    pub(super) fn received(&self, bytes: usize, decoded: bool) {
        self.bytes_received
            .fetch_add(bytes as u64, Ordering::Relaxed);
        if decoded {
            self.datagrams_received.fetch_add(1, Ordering::Relaxed);
        } else {
            self.undecodable.fetch_add(1, Ordering::Relaxed);
        }
    }
}
