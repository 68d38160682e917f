//! [`run_pair`]: both peers of a session, as two threads on 127.0.0.1.

use std::net::SocketAddr;
use std::sync::Arc;
use std::sync::atomic::AtomicUsize;

use super::{PeerError, PeerOptions, PeerOutcome, run_peer};
use crate::net::{LinkConditions, UdpTransport};

/// Runs two peers on 127.0.0.1 (ports chosen by the system), each through
/// its own link conditioner (`link` with seeds `link.seed` and
/// `link.seed + 1`). `configure(handle, options)` adjusts each peer's
/// options (`handle`, `remote`, `seed` and `finished_peers` are set before
/// it is called). Returns the outcomes by handle.
///
/// # Errors
/// The first peer's [`PeerError`]; a socket that cannot be bound or a
/// panicking peer thread are [`PeerError::Io`].
pub fn run_pair(
    base: &PeerOptions,
    link: LinkConditions,
    configure: impl Fn(usize, &mut PeerOptions),
) -> Result<[PeerOutcome; 2], PeerError> {
    let any: SocketAddr = SocketAddr::from(([127, 0, 0, 1], 0));
    let io = |e: std::io::Error| PeerError::Io(format!("UDP on 127.0.0.1: {e}"));
    let transports = [
        UdpTransport::bind(any, link).map_err(io)?,
        UdpTransport::bind(
            any,
            LinkConditions {
                seed: link.seed.wrapping_add(1),
                ..link
            },
        )
        .map_err(io)?,
    ];
    let addrs = [
        transports[0].local_addr().map_err(io)?,
        transports[1].local_addr().map_err(io)?,
    ];
    let done = Arc::new(AtomicUsize::new(0));
    let mut threads = Vec::new();
    for (handle, transport) in transports.into_iter().enumerate() {
        let mut options = base.clone();
        options.handle = handle;
        options.remote = addrs[1 - handle];
        options.seed = base.seed.wrapping_mul(31).wrapping_add(handle as u64);
        options.finished_peers = Some(Arc::clone(&done));
        configure(handle, &mut options);
        threads.push(std::thread::spawn(move || run_peer(&options, transport)));
    }
    let mut outcomes = Vec::new();
    for thread in threads {
        let outcome = thread
            .join()
            .map_err(|_| PeerError::Io("a peer thread panicked".to_owned()))??;
        outcomes.push(outcome);
    }
    let [a, b]: [PeerOutcome; 2] = outcomes
        .try_into()
        .map_err(|_| PeerError::Io("two peers expected".to_owned()))?;
    Ok([a, b])
}
