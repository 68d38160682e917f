//! The determinism panel's run: a built-in scene driven by the seeded
//! scripted input, the same input `clockwork2d record SCENE --ticks N
//! --seed S` records natively. `web/build.sh` runs that command and puts
//! its final hash in the page; the panel runs this function in the browser
//! and shows both.

use clockwork2d::prelude::World;
use clockwork2d_scene::{SceneError, builtin, scripted_commands};
use wasm_bindgen::prelude::wasm_bindgen;

use crate::PlaygroundError;

/// The state hash, as `0x` and 16 hex digits (the CLI's format), after
/// `ticks` ticks of the built-in scene `scene` with the scripted input of
/// seed `seed` applied before each tick.
///
/// # Errors
/// [`PlaygroundError::UnknownScene`] for a name that is not built in.
#[wasm_bindgen(js_name = determinismHash)]
pub fn determinism_hash(scene: &str, seed: u32, ticks: u32) -> Result<String, PlaygroundError> {
    let scene = builtin(scene).map_err(|e| match e {
        SceneError::Unknown(name) => PlaygroundError::UnknownScene(name),
        other => PlaygroundError::Scene(other),
    })?;
    let mut world: World = scene.build()?;
    for _ in 0..ticks {
        let commands = scripted_commands(&world, u64::from(seed));
        world.step_with(&commands);
    }
    Ok(hash_text(world.state_hash()))
}

/// A state hash as the CLI prints it.
pub(crate) fn hash_text(hash: u64) -> String {
    format!("0x{hash:016x}")
}
