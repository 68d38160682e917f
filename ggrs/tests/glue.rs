//! The glue against GGRS requests: order checks, the refusing command
//! path, both saved-state forms, and a rolled-back session against a plain
//! run of the same inputs.

use clockwork2d::prelude::*;
use clockwork2d_ggrs::demo::{DuelConfig, DuelInput, DuelRules, InputScript, arena};
use clockwork2d_ggrs::{InputCommands, SessionError, SessionWorld, SnapshotState};
use ggrs::{Config, GameStateCell, GgrsRequest, InputStatus, PlayerHandle, SessionBuilder};

fn duel() -> SessionWorld<DuelRules> {
    let scene = arena().unwrap();
    SessionWorld::new(scene.world, DuelRules::new(scene.players))
}

#[test]
fn a_save_for_another_frame_is_refused_and_changes_nothing() {
    let mut game = duel();
    let before = game.world().state_hash128();
    let cell = GameStateCell::default();
    let err = game
        .handle_requests::<DuelConfig>(vec![GgrsRequest::SaveGameState { cell, frame: 3 }])
        .unwrap_err();
    assert_eq!(
        err,
        SessionError::FrameMismatch {
            request: "save",
            requested: 3,
            actual: 0
        }
    );
    assert!(err.to_string().contains("in the order given"));
    assert_eq!(game.world().state_hash128(), before);
}

#[test]
fn a_load_from_an_empty_cell_is_refused_and_changes_nothing() {
    let mut game = duel();
    let before = game.world().state_hash128();
    let cell = GameStateCell::default();
    let err = game
        .handle_requests::<DuelConfig>(vec![GgrsRequest::LoadGameState { cell, frame: 0 }])
        .unwrap_err();
    assert_eq!(err, SessionError::EmptyCell { frame: 0 });
    assert_eq!(game.world().state_hash128(), before);
}

/// Save at frame 0, advance twice, load frame 0: the world is back, the
/// frame is 0, and the checksum given to GGRS is `state_hash128`.
#[test]
fn save_advance_load_returns_to_the_saved_state() {
    let mut game = duel();
    let start = game.world().state_hash128();
    let cell = GameStateCell::default();
    let push = DuelInput {
        buttons: DuelInput::RIGHT | DuelInput::JUMP,
        aim: 0,
    };
    let advance = || GgrsRequest::AdvanceFrame {
        inputs: vec![(push, InputStatus::Confirmed); 2],
    };
    let report = game
        .handle_requests::<DuelConfig>(vec![
            GgrsRequest::SaveGameState {
                cell: cell.clone(),
                frame: 0,
            },
            advance(),
            advance(),
        ])
        .unwrap();
    assert_eq!((report.saves, report.advances), (1, 2));
    assert_eq!(game.frame(), 2);
    assert_ne!(game.world().state_hash128(), start);
    let after_two = game.world().state_hash128();
    assert_eq!(game.frame_hash(2), Some(after_two));
    game.handle_requests::<DuelConfig>(vec![GgrsRequest::LoadGameState {
        cell: cell.clone(),
        frame: 0,
    }])
    .unwrap();
    assert_eq!(game.frame(), 0);
    assert_eq!(game.world().state_hash128(), start);
    assert_eq!(game.checksum(), start);
}

/// Remote inputs can name anything. This mapping turns the input byte into
/// a despawn of body `input` and an impulse on it: for ids that do not
/// exist (or fixed bodies, for the impulse) the world refuses, the refusal
/// is reported with the player, and the world is as if the command had not
/// been given.
struct HostileInput;

impl InputCommands for HostileInput {
    type Input = u8;
    fn commands(
        &self,
        _: &World,
        _: PlayerHandle,
        input: &u8,
        _: InputStatus,
        out: &mut Vec<Command>,
    ) {
        let id = BodyId::from_parts(u32::from(*input), 7);
        out.push(Command::ApplyImpulse {
            body: id,
            impulse: Vec2::new(fx(1.0), fx(0.0)),
        });
        out.push(Command::Despawn(id));
    }
}

struct ByteConfig;
impl Config for ByteConfig {
    type Input = u8;
    type InputPredictor = ggrs::PredictRepeatLast;
    type State = World;
    type Address = std::net::SocketAddr;
}

#[test]
fn commands_from_hostile_inputs_are_refused_and_change_nothing() {
    let scene = arena().unwrap();
    let mut plain = scene.world.clone();
    let mut game = SessionWorld::new(scene.world, HostileInput);
    for input in [0u8, 3, 200, 255] {
        let report = game
            .handle_requests::<ByteConfig>(vec![GgrsRequest::AdvanceFrame {
                inputs: vec![
                    (input, InputStatus::Confirmed),
                    (input, InputStatus::Predicted),
                ],
            }])
            .unwrap();
        // Generation 7 matches no body of the arena: all four refused.
        assert_eq!(report.refused.len(), 4);
        assert_eq!(report.refused[0].player, 0);
        assert_eq!(report.refused[3].player, 1);
        plain.step();
        assert_eq!(game.world().state_hash128(), plain.state_hash128());
    }
}

/// The same rolled-back session with the world saved as snapshot bytes.
struct SnapshotConfig;
impl Config for SnapshotConfig {
    type Input = DuelInput;
    type InputPredictor = ggrs::PredictRepeatLast;
    type State = SnapshotState;
    type Address = std::net::SocketAddr;
}

/// A sync test (rollback of 7 frames every frame) with both saved-state
/// forms ends on the same state as a plain run of the same inputs without
/// any rollback: rollback changes nothing.
#[test]
fn rolled_back_sessions_end_where_a_plain_run_ends() {
    const FRAMES: usize = 400;
    let scene = arena().unwrap();
    let rules = DuelRules::new(scene.players);
    let mut scripts = [InputScript::new(5), InputScript::new(6)];
    let inputs: Vec<[DuelInput; 2]> = (0..FRAMES)
        .map(|_| [scripts[0].next_input(), scripts[1].next_input()])
        .collect();

    let mut plain = scene.world.clone();
    let mut commands = Vec::new();
    for frame in &inputs {
        commands.clear();
        for (player, input) in frame.iter().enumerate() {
            rules.commands(&plain, player, input, InputStatus::Confirmed, &mut commands);
        }
        plain.step_with(&commands);
    }

    let mut as_world: SessionWorld<DuelRules> =
        SessionWorld::new(scene.world.clone(), rules.clone());
    let mut as_bytes: SessionWorld<DuelRules, Fx, SnapshotState> =
        SessionWorld::new(scene.world.clone(), rules.clone());
    let mut s1 = SessionBuilder::<DuelConfig>::new()
        .with_check_distance(7)
        .start_synctest_session()
        .unwrap();
    let mut s2 = SessionBuilder::<SnapshotConfig>::new()
        .with_check_distance(7)
        .start_synctest_session()
        .unwrap();
    let mut loads = 0;
    for frame in &inputs {
        for (player, input) in frame.iter().enumerate() {
            s1.add_local_input(player, *input).unwrap();
            s2.add_local_input(player, *input).unwrap();
        }
        loads += as_world
            .handle_requests(s1.advance_frame().unwrap())
            .unwrap()
            .loads;
        as_bytes
            .handle_requests(s2.advance_frame().unwrap())
            .unwrap();
    }
    assert!(loads > 300);
    assert_eq!(as_world.world().state_hash128(), plain.state_hash128());
    assert_eq!(as_bytes.world().state_hash128(), plain.state_hash128());
    assert_eq!(as_world.frame(), 400);
}
