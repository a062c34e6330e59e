//! The status bar (render time, size, precision, what is on screen, the scene, load progress,
//! the last message) and the error banner of a scene that failed to load.

use egui::{RichText, Ui};

use crate::app::status::Status;
use crate::render::Precision;

/// What the status bar shows.
pub(crate) struct StatusLine<'a> {
    /// Render time of the frame on screen, milliseconds.
    pub(crate) render_ms: Option<f64>,
    /// Size of the frame on screen.
    pub(crate) size_px: Option<[u32; 2]>,
    /// Spheres in the scene.
    pub(crate) sphere_count: usize,
    /// The scene's path or name.
    pub(crate) scene_name: String,
    /// Precision the frame on screen was rendered in.
    pub(crate) precision: Option<Precision>,
    /// What is on screen: "preview" or the refined quality.
    pub(crate) stage: Option<String>,
    /// A render is in flight.
    pub(crate) busy: bool,
    /// A scene load that has run long enough to show its progress: its name and share done.
    pub(crate) loading: Option<(String, f32)>,
    /// Message of the last action (export result, view problem).
    pub(crate) message: Option<&'a Status>,
}

/// The status bar: render time, image size, sphere count, scene path, last message.
pub(crate) fn status_bar_ui(ui: &mut Ui, status: &StatusLine<'_>) {
    ui.horizontal(|ui| {
        match status.render_ms {
            Some(ms) => ui.label(format!("render {ms:.1} ms")),
            None => ui.label("render —"),
        };
        ui.separator();
        if let Some([w, h]) = status.size_px {
            ui.label(format!("{w}×{h} px"));
            ui.separator();
        }
        if let Some(precision) = status.precision {
            ui.label(precision.name());
            ui.separator();
        }
        if let Some(stage) = &status.stage {
            ui.label(stage);
            ui.separator();
        }
        let plural = if status.sphere_count == 1 { "" } else { "s" };
        ui.label(format!("{} sphere{plural}", status.sphere_count));
        ui.separator();
        ui.label(&status.scene_name);
        if status.busy {
            ui.separator();
            ui.spinner();
        }
        if let Some((name, fraction)) = &status.loading {
            ui.separator();
            ui.add(
                egui::ProgressBar::new(*fraction)
                    .desired_width(160.0)
                    .show_percentage(),
            );
            ui.label(format!("loading {name}"));
        }
        if let Some(message) = status.message {
            ui.separator();
            let colour = if message.is_error() {
                ui.visuals().error_fg_color
            } else {
                ui.visuals().text_color()
            };
            ui.label(RichText::new(&message.text).color(colour));
        }
    });
}

/// A red banner with an error (e.g. a scene that failed to parse) and a dismiss button.
/// Returns true when dismissed.
pub(crate) fn error_banner_ui(ui: &mut Ui, message: &str) -> bool {
    let mut dismissed = false;
    ui.horizontal(|ui| {
        ui.label(
            RichText::new(message)
                .color(ui.visuals().error_fg_color)
                .monospace(),
        );
        if ui.button("Dismiss").clicked() {
            dismissed = true;
        }
    });
    dismissed
}
