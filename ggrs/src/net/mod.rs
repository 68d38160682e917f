//! Transport for GGRS sessions over UDP: a socket with bounded decoding
//! ([`UdpTransport`]) and a link conditioner that drops, duplicates,
//! reorders and delays datagrams ([`LinkConditions`]), with counters of what
//! went over the wire ([`WireCounters`]).

mod link_conditions;
mod udp_transport;
mod wire_counters;

pub use link_conditions::LinkConditions;
pub use udp_transport::{MAX_DATAGRAM, UdpTransport};
pub use wire_counters::{WireCounters, WireTotals};
