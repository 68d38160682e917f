//! Two peers on 127.0.0.1 over UDP through a lossy link: rollback and
//! lockstep sessions agree, the confirmed inputs make a replay that
//! verifies and ends where the session did, garbage datagrams and a
//! disconnecting peer are events.

use std::net::{SocketAddr, UdpSocket};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

use clockwork2d::replay::Replay;
use clockwork2d_ggrs::SeededRng;
use clockwork2d_ggrs::demo::{PeerError, PeerOptions, PeerOutcome, run_pair, run_peer};
use clockwork2d_ggrs::net::{LinkConditions, UdpTransport};

/// The bad link (20 % drop, duplicates, reordering) with shorter
/// delays so that a debug test run stays short.
fn bad_link(seed: u64) -> LinkConditions {
    LinkConditions {
        latency: Duration::from_millis(4),
        jitter: Duration::from_millis(4),
        reorder_delay: Duration::from_millis(8),
        ..LinkConditions::lossy(seed)
    }
}

fn options(frames: i32) -> PeerOptions {
    let mut o = PeerOptions::new(0, SocketAddr::from(([127, 0, 0, 1], 0)));
    o.frames = frames;
    o.timeout = Duration::from_secs(60);
    o
}

/// What every clean session must show: equal final hashes, no desync, and
/// each peer's replay of the confirmed inputs verifies, ends on the
/// session's final state, and is the same file on both peers.
fn assert_agree(outcomes: &[PeerOutcome; 2]) {
    let [a, b] = outcomes;
    assert_eq!(
        a.final_hash, b.final_hash,
        "peers disagree at the last frame"
    );
    assert!(a.desyncs.is_empty() && b.desyncs.is_empty());
    for o in outcomes {
        assert_eq!(o.replay.ticks(), u64::try_from(o.frames).unwrap());
        assert_eq!(
            o.replay_final_hash, o.final_hash,
            "the replay ends elsewhere than the session"
        );
        let bytes = o.replay.to_bytes();
        let read: Replay = Replay::from_bytes(&bytes).unwrap();
        let report = read.verify().unwrap();
        assert_eq!(report.ticks, o.replay.ticks());
        assert!(o.disconnected.is_empty());
    }
    assert_eq!(a.replay.to_bytes(), b.replay.to_bytes());
}

#[test]
fn rollback_over_a_lossy_link_agrees() {
    let outcomes = run_pair(&options(600), bad_link(7), |_, _| {}).unwrap();
    assert_agree(&outcomes);
    for o in &outcomes {
        // The link did its job: packets were dropped and duplicated, and
        // the lost inputs cost re-simulations.
        assert!(o.wire.dropped > 0 && o.wire.duplicated > 0 && o.wire.reordered > 0);
        assert!(o.simulated > u64::try_from(o.frames).unwrap());
    }
}

#[test]
fn lockstep_over_a_lossy_link_agrees() {
    let mut base = options(300);
    base.lockstep = true;
    base.input_delay = 4;
    let outcomes = run_pair(&base, bad_link(11), |_, _| {}).unwrap();
    assert_agree(&outcomes);
    for o in &outcomes {
        // Lockstep never predicts: no rollback, each frame simulated once.
        assert_eq!(o.rollbacks, 0);
        assert!(o.wire.dropped > 0);
    }
}

/// Peer 0 pushes ball 0 at frame 95. On a perfect link every checksum
/// report arrives, so both peers report the first checksum frame after
/// the push (100: the state after frame 95's step differs from frame 96 on,
/// and checksums are sent for multiples of the interval), both write its
/// snapshot, and the diff of the two names the ball and a field.
#[test]
fn an_injected_desync_is_reported_and_the_snapshots_name_the_body() {
    let dir = std::env::temp_dir().join(format!("cw2d-ggrs-desync-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let mut base = options(200);
    base.desync_interval = 10;
    base.inject_desync = Some(95);
    base.forensic_dir = Some(dir.clone());
    let outcomes = run_pair(&base, LinkConditions::perfect(), |handle, o| {
        if handle == 1 {
            o.inject_desync = None;
        }
    })
    .unwrap();
    for o in &outcomes {
        let first = o.desyncs.first().expect("the desync is reported");
        assert_eq!(first.frame, 100);
        assert_ne!(first.local_checksum, first.remote_checksum);
        // Reported within a few checksum intervals of the frame.
        assert!(first.detected_at - first.frame <= 3 * 10 + 8, "{first:?}");
        // Before the push the peers agreed.
        assert!(o.desyncs.iter().all(|d| d.frame > 95));
    }
    let a = std::fs::read(dir.join("desync-frame100-peer0.snap")).unwrap();
    let b = std::fs::read(dir.join("desync-frame100-peer1.snap")).unwrap();
    let differences = clockwork2d::diff::diff_snapshots(&a, &b).unwrap();
    let scene = clockwork2d_ggrs::demo::arena().unwrap();
    let ball = scene.balls[0];
    let name = format!("body {} (gen {})", ball.index(), ball.generation());
    assert!(
        differences
            .iter()
            .any(|d| d.description.starts_with(&name) && d.description.contains("position.x")),
        "{differences:?}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A third socket sprays random datagrams at peer 0 during the session:
/// they are counted as undecodable and change nothing.
#[test]
fn garbage_datagrams_are_counted_and_ignored() {
    let stop = Arc::new(AtomicBool::new(false));
    let target = Arc::new(std::sync::Mutex::new(None::<SocketAddr>));
    let outcomes = std::thread::scope(|scope| {
        let (stop2, target2) = (Arc::clone(&stop), Arc::clone(&target));
        scope.spawn(move || {
            let socket = UdpSocket::bind(SocketAddr::from(([127, 0, 0, 1], 0))).unwrap();
            let mut rng = SeededRng::new(99);
            while !stop2.load(Ordering::SeqCst) {
                if let Some(addr) = *target2.lock().unwrap() {
                    let len = 1 + rng.below(200) as usize;
                    let bytes: Vec<u8> = (0..len).map(|_| rng.next_u64() as u8).collect();
                    let _ = socket.send_to(&bytes, addr);
                }
                std::thread::sleep(Duration::from_millis(1));
            }
        });
        let result = run_pair(&options(300), bad_link(3), |handle, o| {
            if handle == 1 {
                *target.lock().unwrap() = Some(o.remote);
            }
        });
        stop.store(true, Ordering::SeqCst);
        result
    })
    .unwrap();
    assert_agree(&outcomes);
    assert!(outcomes[0].wire.undecodable > 0);
}

/// Peer 1 leaves at frame 60; peer 0 gets a disconnect event after the
/// timeout and finishes the session alone (the missing player's inputs are
/// GGRS's "disconnected" default input) without a panic.
#[test]
fn a_disconnecting_peer_is_an_event() {
    let mut base = options(240);
    base.disconnect_timeout = Duration::from_millis(300);
    let any = SocketAddr::from(([127, 0, 0, 1], 0));
    let t0 = UdpTransport::bind(any, LinkConditions::perfect()).unwrap();
    let t1 = UdpTransport::bind(any, LinkConditions::perfect()).unwrap();
    let (a0, a1) = (t0.local_addr().unwrap(), t1.local_addr().unwrap());
    let mut o0 = base.clone();
    o0.remote = a1;
    let mut o1 = base;
    o1.handle = 1;
    o1.remote = a0;
    o1.quit_at = Some(60);
    let quitter = std::thread::spawn(move || run_peer(&o1, t1));
    let stayer = run_peer(&o0, t0).unwrap();
    let quit = quitter.join().unwrap();
    assert!(matches!(quit, Err(PeerError::Quit { frame }) if frame >= 60));
    assert_eq!(stayer.disconnected, vec![a1]);
    assert_eq!(stayer.replay.ticks(), 240);
    assert_eq!(stayer.replay_final_hash, stayer.final_hash);
}
