//! The pixel trace in the viewer: **Trace** under the probe opens the course's computation behind
//! the pinned pixel of the frame on screen ([`crate::explore::trace`], the text `-trace X Y`
//! prints), with their pixel beside it while their image is compared.

use egui::RichText;

use super::ViewerApp;
use super::status::Status;
use crate::explore::trace::trace_pixel;

/// The trace window's title.
pub(crate) const TRACE_TITLE: &str = "Pixel trace";

impl ViewerApp {
    /// Traces the pinned pixel of the frame on screen into the trace window.
    pub(crate) fn open_trace(&mut self) {
        let (Some(shown), Some(px)) = (self.frames.shown.as_ref(), self.pinned_px()) else {
            self.status = Some(Status::error(
                "trace: pin a pixel first (click it on an image)",
            ));
            return;
        };
        let view = shown.view;
        let (x_px, y_up_px) = (px.x.floor() as u32, px.y.floor() as u32);
        match trace_pixel(
            &self.scene.loaded.scene,
            &view,
            x_px,
            y_up_px,
            Some(view.depth_range),
        ) {
            Ok(traced) => {
                let mut text = traced.text();
                if let Some(theirs) = self.compare.their_pixel(&traced) {
                    text.push_str(&theirs);
                }
                self.panels.trace = Some(text);
            }
            Err(error) => self.status = Some(Status::error(format!("trace: {error}"))),
        }
    }

    /// The trace window, while a trace is open: the text, scrolled both ways, and Copy.
    pub(crate) fn trace_ui(&mut self, ctx: &egui::Context) {
        let Some(text) = &self.panels.trace else {
            return;
        };
        let mut open = true;
        egui::Window::new(TRACE_TITLE)
            .open(&mut open)
            .default_width(620.0)
            .show(ctx, |ui| {
                if ui
                    .small_button("Copy")
                    .on_hover_text("copy the trace as text, to set beside your program's")
                    .clicked()
                {
                    ctx.copy_text(text.clone());
                }
                egui::ScrollArea::both().max_height(360.0).show(ui, |ui| {
                    ui.add(egui::Label::new(RichText::new(text).monospace().size(11.0)).extend());
                });
            });
        if !open {
            self.panels.trace = None;
        }
    }
}
