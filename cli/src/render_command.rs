//! `clockwork2d render SCENE --ticks N -o OUT.gif|OUT.png`: a scene as
//! pictures, with a progress bar.

use std::fmt;
use std::io::IsTerminal;
use std::path::Path;
use std::process::ExitCode;

use clockwork2d::prelude::World;
use clockwork2d_render::{RenderError, RenderOptions, render_run};
use clockwork2d_scene::SceneError;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

/// Why `render` failed: the scene, or the picture.
#[derive(Debug)]
pub(crate) enum RenderCommandError {
    /// The scene could not be loaded or built.
    Scene(SceneError),
    /// The picture could not be made or written.
    Render(RenderError),
}

impl fmt::Display for RenderCommandError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            RenderCommandError::Scene(e) => write!(f, "{e}"),
            RenderCommandError::Render(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for RenderCommandError {}

/// Loads `scene`, simulates it for `options.ticks` ticks and writes
/// `output` (a GIF with a frame every `options.every` ticks, or a PNG of
/// the last tick). The format and the picture size are checked before the
/// scene is loaded and before anything is simulated or written.
pub(crate) fn render(scene: &str, options: &RenderOptions, output: &Path) -> ExitCode {
    match render_scene(scene, options, output) {
        Ok(line) => {
            println!("{line}");
            ExitCode::SUCCESS
        }
        Err(e) => crate::fail(e),
    }
}

fn render_scene(
    scene: &str,
    options: &RenderOptions,
    output: &Path,
) -> Result<String, RenderCommandError> {
    // Cheap checks first, so a typo costs no simulation.
    clockwork2d_render::OutputFormat::from_path(output).map_err(RenderCommandError::Render)?;
    let mut world: World = crate::load(scene)
        .and_then(|s| s.build())
        .map_err(RenderCommandError::Scene)?;
    let bar = ProgressBar::with_draw_target(Some(options.ticks), ProgressDrawTarget::hidden());
    if std::io::stderr().is_terminal() {
        bar.set_draw_target(ProgressDrawTarget::stderr());
    }
    if let Ok(style) =
        ProgressStyle::with_template("rendering {bar:40} {pos}/{len} ticks ({per_sec}, eta {eta})")
    {
        bar.set_style(style);
    }
    let result = render_run(&mut world, options, output, |done| {
        if done % 16 == 0 || done == options.ticks {
            bar.set_position(done);
        }
    });
    bar.finish_and_clear();
    let summary = result.map_err(RenderCommandError::Render)?;
    Ok(format!(
        "wrote {} ({}x{}, {} frame{}, tick {})",
        output.display(),
        options.width,
        options.height,
        summary.frames,
        if summary.frames == 1 { "" } else { "s" },
        summary.final_tick
    ))
}
