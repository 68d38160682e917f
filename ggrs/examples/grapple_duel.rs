//! The example game headless: two players with grapple ropes in an arena
//! with a stack, balls and a spring, under GGRS.
//!
//! ```text
//! cargo run --release -p clockwork2d-ggrs --example grapple_duel -- synctest
//! cargo run --release -p clockwork2d-ggrs --example grapple_duel -- synctest --nondeterministic
//! cargo run --release -p clockwork2d-ggrs --example grapple_duel -- p2p
//! cargo run --release -p clockwork2d-ggrs --example grapple_duel -- p2p --lockstep
//! cargo run --release -p clockwork2d-ggrs --example grapple_duel -- p2p --inject-desync 500 --out /tmp/duel
//! ```
//!
//! `p2p` runs both peers as threads on 127.0.0.1 over UDP through a link
//! that drops 20 %, duplicates, reorders and delays datagrams; each peer
//! prints its final hash and writes the confirmed inputs as a replay
//! (`peer0.replay`, `peer1.replay` in `--out`) for `clockwork2d verify`.
//! With `--inject-desync FRAME` peer 0 pushes a ball at FRAME; both peers
//! write the snapshot of the frame the desync report names
//! (`desync-frameF-peerN.snap`) for `clockwork2d diff`.

use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Duration;

use clap::{Parser, Subcommand};
use clockwork2d_ggrs::demo::{
    DuelRules, NondeterministicRules, PeerOptions, arena, run_pair, run_synctest,
};
use clockwork2d_ggrs::net::LinkConditions;

#[derive(Parser)]
#[command(about = "The clockwork2d grapple duel under GGRS, headless")]
struct Args {
    #[command(subcommand)]
    mode: Mode,
}

#[derive(Subcommand)]
enum Mode {
    /// A GGRS SyncTestSession: roll back and re-simulate every frame.
    Synctest {
        /// Frames to run.
        #[arg(long, default_value_t = 10_000)]
        frames: i32,
        /// Rollback distance checked every frame.
        #[arg(long, default_value_t = 7)]
        check_distance: usize,
        /// Seed of the random inputs.
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// Negative control: a step that differs on re-simulation.
        #[arg(long)]
        nondeterministic: bool,
    },
    /// Two peers on 127.0.0.1 over a lossy UDP link.
    P2p {
        /// Frames to play.
        #[arg(long, default_value_t = 3000)]
        frames: i32,
        /// GGRS lockstep mode (max_prediction = 0).
        #[arg(long)]
        lockstep: bool,
        /// Peer 0 perturbs a ball at this frame.
        #[arg(long)]
        inject_desync: Option<i32>,
        /// A perfect link instead of the lossy one.
        #[arg(long)]
        perfect_link: bool,
        /// Local input delay (default: 2 in rollback, 6 in lockstep).
        #[arg(long)]
        input_delay: Option<usize>,
        /// Desync-detection interval in frames.
        #[arg(long, default_value_t = 10)]
        desync_interval: u32,
        /// Where to write replays and forensic snapshots.
        #[arg(long, default_value = ".")]
        out: PathBuf,
        /// Seed of the inputs and of the link.
        #[arg(long, default_value_t = 1)]
        seed: u64,
    },
}

fn main() -> ExitCode {
    match Args::parse().mode {
        Mode::Synctest {
            frames,
            check_distance,
            seed,
            nondeterministic,
        } => synctest(frames, check_distance, seed, nondeterministic),
        Mode::P2p {
            frames,
            lockstep,
            inject_desync,
            perfect_link,
            input_delay,
            desync_interval,
            out,
            seed,
        } => {
            let mut options = PeerOptions::new(0, std::net::SocketAddr::from(([127, 0, 0, 1], 0)));
            options.frames = frames;
            options.lockstep = lockstep;
            options.inject_desync = inject_desync;
            options.input_delay = input_delay.unwrap_or(if lockstep { 6 } else { 2 });
            options.desync_interval = desync_interval;
            options.forensic_dir = Some(out.clone());
            options.seed = seed;
            let link = if perfect_link {
                LinkConditions::perfect()
            } else {
                LinkConditions::lossy(seed)
            };
            p2p(options, link, &out)
        }
    }
}

fn synctest(frames: i32, check_distance: usize, seed: u64, nondeterministic: bool) -> ExitCode {
    let scene = match arena() {
        Ok(a) => a,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    let rules = DuelRules::new(scene.players);
    let result = if nondeterministic {
        run_synctest(
            scene.world,
            NondeterministicRules::new(rules, scene.balls[0]),
            frames,
            check_distance,
            seed,
        )
    } else {
        run_synctest(scene.world, rules, frames, check_distance, seed)
    };
    let outcome = match result {
        Ok(o) => o,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    println!(
        "synctest: {} frames, check distance {check_distance}, {} frames simulated, {} refused \
         commands, {:.2} s",
        outcome.frames,
        outcome.simulated,
        outcome.refused,
        outcome.elapsed.as_secs_f64()
    );
    match outcome.mismatch {
        None => {
            println!("no mismatch; final hash {:032x}", outcome.final_hash);
            ExitCode::SUCCESS
        }
        Some((frame, frames)) => {
            println!("MISMATCH at frame {frame}: checksums of frames {frames:?} differ");
            ExitCode::from(1)
        }
    }
}

fn p2p(options: PeerOptions, link: LinkConditions, out: &std::path::Path) -> ExitCode {
    if let Err(e) = std::fs::create_dir_all(out) {
        eprintln!("error: cannot create {}: {e}", out.display());
        return ExitCode::from(2);
    }
    let mut options = options;
    options.timeout = Duration::from_secs(600);
    let outcomes = match run_pair(&options, link, |handle, o| {
        if handle == 1 {
            o.inject_desync = None;
        }
    }) {
        Ok(o) => o,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    let mode = if options.lockstep {
        "lockstep"
    } else {
        "rollback"
    };
    for o in &outcomes {
        let path = out.join(format!("peer{}.replay", o.handle));
        if let Err(e) = std::fs::write(&path, o.replay.to_bytes()) {
            eprintln!("error: cannot write {}: {e}", path.display());
            return ExitCode::from(2);
        }
        let secs = o.elapsed.as_secs_f64() - o.sync_time.as_secs_f64();
        println!(
            "peer {} ({mode}): {} frames confirmed in {:.2} s after {:.2} s sync ({:.0} frames/s); \
             final hash {:032x}",
            o.handle,
            o.frames,
            secs,
            o.sync_time.as_secs_f64(),
            f64::from(o.frames) / secs,
            o.final_hash
        );
        println!(
            "  wire: {} datagrams, {} bytes sent ({:.1} bytes/frame over {} frames advanced), \
             {} dropped, {} duplicated, {} reordered, {} undecodable received",
            o.wire.datagrams_sent,
            o.wire.bytes_sent,
            o.wire.bytes_sent as f64 / f64::from(o.frames_at_finish.max(1)),
            o.frames_at_finish,
            o.wire.dropped,
            o.wire.duplicated,
            o.wire.reordered,
            o.wire.undecodable
        );
        println!(
            "  {} rollbacks, {} frames simulated, {} refused commands, {} interruptions; replay {} \
             ({} ticks, final hash {:016x})",
            o.rollbacks,
            o.simulated,
            o.refused,
            o.interruptions,
            path.display(),
            o.replay.ticks(),
            o.replay.final_hash()
        );
        for d in &o.desyncs {
            println!(
                "  DESYNC at frame {} reported at frame {} (local {:032x}, remote {:032x}); \
                 snapshot {}",
                d.frame,
                d.detected_at,
                d.local_checksum,
                d.remote_checksum,
                d.snapshot
                    .as_ref()
                    .map_or("not kept".to_owned(), |p| p.display().to_string())
            );
        }
    }
    let equal = outcomes[0].final_hash == outcomes[1].final_hash;
    let desynced = outcomes.iter().any(|o| !o.desyncs.is_empty());
    println!(
        "final hashes {}; {}",
        if equal { "equal" } else { "DIFFER" },
        if desynced {
            "desync reported"
        } else {
            "no desync event"
        }
    );
    if options.inject_desync.is_some() {
        if desynced {
            ExitCode::SUCCESS
        } else {
            ExitCode::from(1)
        }
    } else if equal && !desynced {
        ExitCode::SUCCESS
    } else {
        ExitCode::from(1)
    }
}
