//! Opening the viewer's window: eframe's native options, the renderer that paints it, and the
//! one-line reason when no window can be opened here.
//!
//! The window is painted with OpenGL (glow) unless `RAYTRACER_RENDERER=wgpu` asks for wgpu. Where
//! there is no GPU, both paint on the CPU with Mesa, on the cores the render worker needs, and
//! OpenGL's painter (llvmpipe) costs about a fifth of the CPU per UI frame that Vulkan's
//! (lavapipe, under wgpu) does: `cargo xtask report window-frame-times` measures both
//! (`docs/window-frame-times.md`, `docs/window-frame-times-wgpu.md`).
//! If OpenGL cannot be started and no renderer was asked for, wgpu is tried (and standard error
//! says why).

use eframe::Renderer;

use crate::app::viewer::ViewerApp;
use crate::cli::ViewerRequest;

/// The environment variable that chooses the renderer: `glow` (OpenGL, the default) or `wgpu`.
pub(crate) const RENDERER_VARIABLE: &str = "RAYTRACER_RENDERER";

/// The renderer `value` (of [`RENDERER_VARIABLE`]) asks for: `None` when unset or empty (the
/// default, with wgpu tried when OpenGL cannot start), an error naming the choices when it is
/// neither `glow` nor `wgpu`.
pub(crate) fn renderer_asked(value: Option<&std::ffi::OsStr>) -> Result<Option<Renderer>, String> {
    match value.map(|value| (value.to_str(), value)) {
        None | Some((Some(""), _)) => Ok(None),
        Some((Some("glow"), _)) => Ok(Some(Renderer::Glow)),
        Some((Some("wgpu"), _)) => Ok(Some(Renderer::Wgpu)),
        Some((_, value)) => Err(format!(
            "{RENDERER_VARIABLE} is {:?}: it must be glow (OpenGL) or wgpu",
            value.to_string_lossy()
        )),
    }
}

/// Why the environment's choice of renderer for the window ([`RENDERER_VARIABLE`]) cannot be
/// followed, if it cannot: one line for the user, naming what may be chosen (checked before
/// anything else of the viewer starts).
pub fn environment_problem() -> Option<String> {
    renderer_of_environment().err()
}

/// [`renderer_asked`] by this process's [`RENDERER_VARIABLE`].
fn renderer_of_environment() -> Result<Option<Renderer>, String> {
    renderer_asked(std::env::var_os(RENDERER_VARIABLE).as_deref())
}

/// Opens the viewer window and runs it until closed. When OpenGL cannot start and no renderer
/// was asked for, says why on standard error and paints with wgpu; when both fail, the error
/// names both.
pub fn run(request: ViewerRequest) -> eframe::Result {
    let asked =
        renderer_of_environment().map_err(|reason| eframe::Error::AppCreation(reason.into()))?;
    let first = asked.unwrap_or(Renderer::Glow);
    let opened = std::cell::Cell::new(false);
    let outcome = run_with(first, request.clone(), &opened);
    // Another renderer only when OpenGL was not asked for, never came up (so no window was
    // shown or closed) and no termination signal has come meanwhile.
    let retry =
        asked.is_none() && !opened.get() && crate::platform::process::stop_requested().is_none();
    match outcome {
        Err(opengl_error) if retry => {
            crate::platform::console::print_err(&format!(
                "raytracer: OpenGL could not start ({opengl_error}); painting with wgpu\n"
            ));
            run_with(Renderer::Wgpu, request, &opened).map_err(|wgpu_error| {
                eframe::Error::AppCreation(
                    format!("OpenGL: {opengl_error}; wgpu: {wgpu_error}").into(),
                )
            })
        }
        outcome => outcome,
    }
}

/// Runs the viewer painted by `renderer`; `opened` is set once the app is created.
fn run_with(
    renderer: Renderer,
    request: ViewerRequest,
    opened: &std::cell::Cell<bool>,
) -> eframe::Result {
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_title("raytracer")
            .with_inner_size([1280.0, 720.0])
            .with_min_inner_size([320.0, 240.0])
            .with_drag_and_drop(true),
        renderer,
        ..Default::default()
    };
    eframe::run_native(
        "raytracer",
        options,
        Box::new(|cc| {
            opened.set(true);
            // A termination signal wakes the window, which then closes.
            let ctx = cc.egui_ctx.clone();
            crate::platform::process::set_wake(move || ctx.request_repaint());
            Ok(Box::new(ViewerApp::new(cc, request)))
        }),
    )
}

/// Why the viewer cannot open a window here (no display server to talk to), if it cannot: one
/// line for the user, with what to do instead.
pub fn no_display_reason() -> Option<&'static str> {
    if !crate::platform::display::display_server_missing() {
        None
    } else {
        Some(
            "no display to open the viewer on (DISPLAY and WAYLAND_DISPLAY are not set); \
             render to files instead: raytracer -input FILE -output FILE.png \
             [-depth DMIN DMAX FILE.png]",
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::ffi::OsStr;

    #[test]
    fn the_renderer_variable_chooses_opengl_or_wgpu_and_names_the_choices_otherwise() {
        assert_eq!(renderer_asked(None), Ok(None));
        assert_eq!(renderer_asked(Some(OsStr::new(""))), Ok(None));
        assert_eq!(
            renderer_asked(Some(OsStr::new("glow"))),
            Ok(Some(Renderer::Glow))
        );
        assert_eq!(
            renderer_asked(Some(OsStr::new("wgpu"))),
            Ok(Some(Renderer::Wgpu))
        );
        let error = renderer_asked(Some(OsStr::new("vulkan"))).unwrap_err();
        assert!(
            error.contains("\"vulkan\"") && error.contains("glow") && error.contains("wgpu"),
            "{error}"
        );
    }
}
