//! [`UdpTransport`]: GGRS messages over a non-blocking UDP socket, through
//! a link conditioner.

use std::io::ErrorKind;
use std::net::{SocketAddr, UdpSocket};
use std::sync::Arc;
use std::time::{Duration, Instant};

use ggrs::{Message, NonBlockingSocket};

use super::{LinkConditions, WireCounters};
use crate::seeded_rng::SeededRng;

/// Largest datagram read or decoded. GGRS messages are a few dozen bytes
/// (its own socket warns above 508); a longer datagram is garbage.
pub const MAX_DATAGRAM: usize = 4096;

/// A datagram waiting for its delivery time.
#[derive(Debug)]
struct Delayed {
    due: Instant,
    /// Order of sending, to break ties in `due` deterministically.
    sequence: u64,
    to: SocketAddr,
    bytes: Vec<u8>,
}

/// A GGRS transport on a UDP socket. Messages are encoded with bincode 2
/// (serde, standard configuration); received datagrams are decoded with a
/// size limit, and anything that does not decode is counted as garbage
/// ([`WireTotals::undecodable`](super::WireTotals::undecodable)) and
/// dropped: a peer sending garbage cannot make the session panic or
/// allocate without bound. Outgoing datagrams pass through
/// [`LinkConditions`] (drop, duplicate, reorder, delay).
#[derive(Debug)]
pub struct UdpTransport {
    socket: UdpSocket,
    conditions: LinkConditions,
    rng: SeededRng,
    queue: Vec<Delayed>,
    sequence: u64,
    counters: Arc<WireCounters>,
    buffer: Vec<u8>,
}

impl UdpTransport {
    /// Binds a non-blocking socket to `addr` (use port 0 for any free port).
    ///
    /// # Errors
    /// The operating system's error binding or configuring the socket.
    pub fn bind(addr: SocketAddr, conditions: LinkConditions) -> std::io::Result<Self> {
        let socket = UdpSocket::bind(addr)?;
        socket.set_nonblocking(true)?;
        Ok(UdpTransport {
            socket,
            rng: SeededRng::new(conditions.seed),
            conditions,
            queue: Vec::new(),
            sequence: 0,
            counters: WireCounters::new(),
            buffer: vec![0; MAX_DATAGRAM + 1],
        })
    }

    /// The address the socket is bound to.
    ///
    /// # Errors
    /// The operating system's error.
    pub fn local_addr(&self) -> std::io::Result<SocketAddr> {
        self.socket.local_addr()
    }

    /// The transport's counters (shared: they keep counting after the
    /// transport is handed to a session).
    #[must_use]
    pub fn counters(&self) -> Arc<WireCounters> {
        Arc::clone(&self.counters)
    }

    fn delay(&mut self) -> Duration {
        let jitter_us = u32::try_from(self.conditions.jitter.as_micros()).unwrap_or(u32::MAX);
        let extra = Duration::from_micros(u64::from(self.rng.below(jitter_us.saturating_add(1))));
        self.conditions.latency + extra
    }

    fn enqueue(&mut self, to: SocketAddr, bytes: Vec<u8>, delay: Duration) {
        self.sequence += 1;
        self.queue.push(Delayed {
            due: Instant::now() + delay,
            sequence: self.sequence,
            to,
            bytes,
        });
    }

    /// Sends every delayed datagram whose time has come, oldest first.
    fn flush(&mut self) {
        if self.queue.is_empty() {
            return;
        }
        let now = Instant::now();
        self.queue.sort_by_key(|d| (d.due, d.sequence));
        let ready = self.queue.partition_point(|d| d.due <= now);
        for d in self.queue.drain(..ready) {
            // A failed send is a lost datagram, which GGRS recovers from.
            if self.socket.send_to(&d.bytes, d.to).is_ok() {
                self.counters.sent(d.bytes.len());
            }
        }
    }
}

impl NonBlockingSocket<SocketAddr> for UdpTransport {
    fn send_to(&mut self, msg: &Message, addr: &SocketAddr) {
        let Ok(bytes) = bincode::serde::encode_to_vec(msg, bincode::config::standard()) else {
            return;
        };
        if self.rng.chance(self.conditions.drop_permille) {
            self.counters.dropped();
        } else {
            let mut delay = self.delay();
            if self.rng.chance(self.conditions.reorder_permille) {
                self.counters.reordered();
                delay += self.conditions.reorder_delay;
            }
            if self.rng.chance(self.conditions.duplicate_permille) {
                self.counters.duplicated();
                let again = self.delay();
                self.enqueue(*addr, bytes.clone(), again);
            }
            self.enqueue(*addr, bytes, delay);
        }
        self.flush();
    }

    fn receive_all_messages(&mut self) -> Vec<(SocketAddr, Message)> {
        self.flush();
        let mut messages = Vec::new();
        loop {
            match self.socket.recv_from(&mut self.buffer) {
                Ok((len, from)) => {
                    let decoded = (len <= MAX_DATAGRAM)
                        .then(|| {
                            bincode::serde::decode_from_slice::<Message, _>(
                                &self.buffer[..len],
                                bincode::config::standard().with_limit::<MAX_DATAGRAM>(),
                            )
                            .ok()
                        })
                        .flatten()
                        // Trailing bytes: not a message we sent.
                        .filter(|(_, used)| *used == len);
                    self.counters.received(len, decoded.is_some());
                    if let Some((msg, _)) = decoded {
                        messages.push((from, msg));
                    }
                }
                Err(e) if e.kind() == ErrorKind::WouldBlock => break,
                // ICMP port unreachable from a peer that has gone: it will be
                // reported by GGRS as a disconnect after its timeout.
                Err(e) if e.kind() == ErrorKind::ConnectionReset => {}
                Err(_) => break,
            }
        }
        messages
    }
}
