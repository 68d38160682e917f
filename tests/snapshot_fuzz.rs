//! No bytes can make `World::restore` panic: random bytes, every
//! truncation, every bit flip (with and without a repaired checksum, so the
//! decoder and validator see the damage), and random mutations. A world
//! that is accepted must step and snapshot without panicking.

use clockwork2d::prelude::*;
use clockwork2d_scene::builtin;
use clockwork2d_scene::scripted_commands;
use proptest::prelude::*;

mod common;
use common::file_checksum::fix_checksum;

/// A small world with contacts, sleepers, a free slot and a constraint.
fn sample_bytes() -> Vec<u8> {
    let mut w: World = builtin("stack").unwrap().build().unwrap();
    for _ in 0..130 {
        let commands = scripted_commands(&w, 3);
        w.step_with(&commands);
    }
    let anchor = w
        .bodies()
        .find(|(_, b)| b.kind() == BodyKind::Dynamic)
        .unwrap()
        .0;
    w.add_constraint(Constraint::rope(
        Anchor::Point(Vec2::new(fx(0.0), fx(20.0))),
        Anchor::Body(anchor),
        fx(30.0),
    ))
    .unwrap();
    for _ in 0..5 {
        w.step();
    }
    w.snapshot()
}

/// Restores; if accepted, the world must be usable.
fn exercise(bytes: &[u8]) -> bool {
    match World::<Fx>::restore(bytes) {
        Ok(mut w) => {
            for _ in 0..3 {
                w.step();
            }
            // A valid world must step into a valid world (this is how the
            // duplicate-contact-after-freezing bug was found).
            let again: World = World::restore(&w.snapshot())
                .unwrap_or_else(|e| panic!("an accepted world stepped into an invalid state: {e}"));
            assert_eq!(again.state_hash(), w.state_hash());
            true
        }
        Err(e) => {
            assert!(!e.to_string().is_empty());
            false
        }
    }
}

#[test]
fn every_bit_flip_is_caught_by_the_checksum_or_header_checks() {
    let bytes = sample_bytes();
    for i in 0..bytes.len() {
        for bit in 0..8 {
            let mut b = bytes.clone();
            b[i] ^= 1 << bit;
            assert!(
                World::<Fx>::restore(&b).is_err(),
                "flip at {i}.{bit} accepted"
            );
        }
    }
}

#[test]
fn every_bit_flip_with_a_repaired_checksum_is_an_error_or_a_valid_world() {
    let bytes = sample_bytes();
    let mut accepted = 0;
    for i in 0..bytes.len() - 8 {
        for bit in 0..8 {
            let mut b = bytes.clone();
            b[i] ^= 1 << bit;
            fix_checksum(&mut b);
            accepted += usize::from(exercise(&b));
        }
    }
    // Many flips change a position or an impulse: still a valid world.
    assert!(accepted > 0);
}

#[test]
fn every_truncation_and_extension_is_refused() {
    let bytes = sample_bytes();
    for n in 0..bytes.len() {
        assert!(World::<Fx>::restore(&bytes[..n]).is_err());
        let mut fixed = bytes[..n].to_vec();
        fix_checksum(&mut fixed);
        assert!(World::<Fx>::restore(&fixed).is_err());
    }
    let mut longer = bytes.clone();
    longer.push(0);
    assert!(World::<Fx>::restore(&longer).is_err());
}

/// A busier world: the mixed scene (bullet, stack, pyramid, balls) plus a
/// moving kinematic platform and a spring, after scripted commands.
fn busy_bytes() -> Vec<u8> {
    let mut w: World = builtin("mixed").unwrap().build().unwrap();
    w.add_body(
        BodyDef::kinematic(Shape::aabb(vec2(1.0, 0.2)))
            .position(vec2(0.0, 6.0))
            .velocity(vec2(0.5, 0.0)),
    )
    .unwrap();
    let bob = w
        .add_body(BodyDef::dynamic(Shape::circle(fx(0.3))).position(vec2(12.0, 9.0)))
        .unwrap();
    w.add_constraint(Constraint::radial_spring(
        Anchor::Point(vec2(12.0, 11.0)),
        Anchor::Body(bob),
        fx(1.5),
        fx(40.0),
        fx(0.5),
    ))
    .unwrap();
    for _ in 0..100 {
        let commands = scripted_commands(&w, 5);
        w.step_with(&commands);
    }
    w.snapshot()
}

#[test]
fn bit_flips_of_a_busy_world_are_an_error_or_a_valid_world() {
    let bytes = busy_bytes();
    // Every 5th byte, all bits (the record layouts repeat, so this reaches
    // every field of every kind of record).
    for i in (0..bytes.len() - 8).step_by(5) {
        for bit in 0..8 {
            let mut b = bytes.clone();
            b[i] ^= 1 << bit;
            fix_checksum(&mut b);
            exercise(&b);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(512))]

    #[test]
    fn random_bytes_never_panic(bytes in proptest::collection::vec(any::<u8>(), 0..4096)) {
        exercise(&bytes);
    }

    #[test]
    fn random_payloads_in_a_valid_frame_never_panic(
        payload in proptest::collection::vec(any::<u8>(), 0..2048)
    ) {
        let good = sample_bytes();
        // Keep the header up to the length field, then the random payload.
        let v = usize::from(good[10]);
        let name = usize::from(good[11 + v + 1]);
        let at = 11 + v + 2 + name;
        let mut b = good[..at].to_vec();
        b.extend_from_slice(&(payload.len() as u64).to_le_bytes());
        b.extend_from_slice(&payload);
        b.extend_from_slice(&[0; 8]);
        fix_checksum(&mut b);
        exercise(&b);
    }

    #[test]
    fn random_mutations_never_panic(
        edits in proptest::collection::vec((any::<prop::sample::Index>(), any::<u8>()), 1..8),
        repair in any::<bool>(),
    ) {
        let mut b = sample_bytes();
        for (index, value) in edits {
            let i = index.index(b.len());
            b[i] = value;
        }
        if repair {
            fix_checksum(&mut b);
        }
        exercise(&b);
    }
}
