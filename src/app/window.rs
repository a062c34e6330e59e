//! Opening the viewer's window: eframe's native options, and the one-line reason when no window
//! can be opened here.

use super::ViewerApp;
use crate::cli::ViewerRequest;

/// Opens the viewer window and runs it until closed.
pub fn run(request: ViewerRequest) -> eframe::Result {
    let options = eframe::NativeOptions {
        viewport: egui::ViewportBuilder::default()
            .with_title("raytracer")
            .with_inner_size([1280.0, 720.0])
            .with_min_inner_size([320.0, 240.0])
            .with_drag_and_drop(true),
        ..Default::default()
    };
    eframe::run_native(
        "raytracer",
        options,
        Box::new(|cc| Ok(Box::new(ViewerApp::new(cc, request)))),
    )
}

/// Why the viewer cannot open a window here (no display server to talk to), if it cannot: one
/// line for the user, with what to do instead.
pub fn no_display_reason() -> Option<&'static str> {
    let set = |name| std::env::var_os(name).is_some_and(|value| !value.is_empty());
    if set("DISPLAY") || set("WAYLAND_DISPLAY") || set("WAYLAND_SOCKET") {
        None
    } else {
        Some(
            "no display to open the viewer on (DISPLAY and WAYLAND_DISPLAY are not set); \
             render to files instead: raytracer -input FILE -output FILE.png \
             [-depth DMIN DMAX FILE.png]",
        )
    }
}
