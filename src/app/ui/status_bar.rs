//! The status bar (the last message first, then render time, size, what is on screen,
//! the magnification, the scene, load progress) on one line whatever the window's width: the
//! message and the scene's name are shortened with "…" and shown whole on hover. And the error of
//! a scene that failed to load, floating over the images so that it moves nothing.

use egui::{Label, RichText, Ui};

use crate::app::status::Status;

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
    /// What is on screen: "preview" or the refined quality.
    pub(crate) stage: Option<String>,
    /// The magnifier's zoom (1: not magnified).
    pub(crate) magnification: f64,
    /// A render is in flight.
    pub(crate) busy: bool,
    /// A scene load that has run long enough to show its progress: its name and share done.
    pub(crate) loading: Option<(String, f32)>,
    /// Message of the last action (export result, view problem), while it is current.
    pub(crate) message: Option<&'a Status>,
}

/// The status bar.
pub(crate) fn status_bar_ui(ui: &mut Ui, status: &StatusLine<'_>) {
    ui.horizontal(|ui| {
        if status.busy {
            ui.spinner();
        }
        if let Some((name, fraction)) = &status.loading {
            ui.add(
                egui::ProgressBar::new(*fraction)
                    .desired_width(120.0)
                    .show_percentage(),
            )
            .on_hover_text(format!("loading {name}"));
        }
        match status.render_ms {
            Some(ms) => ui.label(format!("{ms:.1} ms")),
            None => ui.label("—"),
        }
        .on_hover_text("time to render the frame on screen and prepare its textures");
        if let Some([w, h]) = status.size_px {
            ui.label(format!("{w}×{h}"));
        }
        if let Some(stage) = &status.stage {
            ui.label(stage);
        }
        if status.magnification > 1.0 {
            ui.label(format!("magnified {:.1}×", status.magnification))
                .on_hover_text("the images enlarged without a new render (1 or Ctrl+0: fit)");
        }
        let plural = if status.sphere_count == 1 { "" } else { "s" };
        ui.label(format!("{} sphere{plural}", status.sphere_count));
        ui.separator();
        if let Some(message) = status.message {
            let colour = if message.is_error() {
                ui.visuals().error_fg_color
            } else {
                ui.visuals().text_color()
            };
            ui.add(Label::new(RichText::new(&message.text).color(colour)).truncate());
        } else {
            ui.add(Label::new(RichText::new(&status.scene_name).weak()).truncate());
        }
    });
}

/// A scene's error floating over the top of the images, `top` points down the window (below
/// their captions), with a "Dismiss" button: it moves nothing else. Returns true when dismissed.
pub(crate) fn error_overlay_ui(ctx: &egui::Context, message: &str, top: f32) -> bool {
    let mut dismissed = false;
    egui::Area::new(egui::Id::unique("scene error"))
        .anchor(egui::Align2::CENTER_TOP, egui::vec2(0.0, top))
        .order(egui::Order::Foreground)
        .show(ctx, |ui| {
            egui::Frame::popup(ui.style()).show(ui, |ui| {
                let width = (ctx.content_rect().width() - 60.0).max(100.0);
                ui.set_max_width(width);
                ui.horizontal(|ui| {
                    if ui.button("Dismiss").clicked() {
                        dismissed = true;
                    }
                    ui.add(
                        Label::new(
                            RichText::new(message)
                                .color(ui.visuals().error_fg_color)
                                .monospace(),
                        )
                        .wrap(),
                    );
                });
            });
        });
    dismissed
}
