//! The pixel trace in the viewer: **Trace** under the probe opens the course's computation behind
//! the pinned pixel of the frame on screen ([`crate::explore::trace`], the text `-trace X Y`
//! prints), with their pixel beside it while their image is compared.

use egui::RichText;

use glam::DVec2;

use super::compare::CompareState;
use super::status::Status;
use crate::explore::trace::trace_pixel;
use crate::render::View;
use crate::scene::Scene;

/// The trace window's title.
pub(crate) const TRACE_TITLE: &str = "Pixel trace";

/// The trace of pixel `px` (x, y up) of a frame of `scene` through `view`, with their pixel
/// beside it while their image is compared; or the status saying why there is none.
fn trace_text(
    scene: &Scene,
    view: Option<&View>,
    px: Option<DVec2>,
    compare: &CompareState,
) -> Result<String, Status> {
    let (Some(view), Some(px)) = (view, px) else {
        return Err(Status::error(
            "trace: pin a pixel first (click it on an image)",
        ));
    };
    let (x_px, y_up_px) = (px.x.floor() as u32, px.y.floor() as u32);
    let traced = trace_pixel(scene, view, x_px, y_up_px, Some(view.depth_range))
        .map_err(|error| Status::error(format!("trace: {error}")))?;
    let mut text = traced.text();
    if let Some(theirs) = compare.their_pixel(scene, &traced) {
        text.push_str(&theirs);
    }
    Ok(text)
}

/// Opens the trace window on pixel `px` of the frame of `scene` through `view` (see
/// [`trace_text`]): its text into `trace`, or the status saying why there is none.
pub(crate) fn open(
    trace: &mut Option<String>,
    scene: &Scene,
    view: Option<&View>,
    px: Option<DVec2>,
    compare: &CompareState,
) -> Option<Status> {
    let text = trace_text(scene, view, px, compare);
    text.map(|text| *trace = Some(text)).err()
}

/// The trace window, while a trace is open (`trace`): the text, scrolled both ways, and Copy;
/// closing it empties `trace`.
pub(crate) fn trace_ui(ctx: &egui::Context, trace: &mut Option<String>) {
    let Some(text) = trace.as_ref() else {
        return;
    };
    let mut open = true;
    // Sized to its lines at the body text size, within the window's room; resizable.
    let font = egui::FontId::monospace(egui::TextStyle::Body.resolve(&ctx.global_style()).size);
    let char_width = ctx.fonts_mut(|fonts| fonts.glyph_width(&font, '0'));
    let longest = text
        .lines()
        .map(|line| line.chars().count())
        .max()
        .unwrap_or(0) as f32;
    let lines = text.lines().count() as f32;
    let room = ctx.content_rect().size() - egui::vec2(40.0, 80.0);
    let size = egui::vec2(
        (longest * char_width + 30.0).clamp(300.0_f32.min(room.x), room.x.max(1.0)),
        (lines * font.size * 1.25 + 50.0).clamp(120.0_f32.min(room.y), room.y.max(1.0)),
    );
    egui::Window::new(TRACE_TITLE)
        .open(&mut open)
        .default_size(size)
        .resizable(true)
        .show(ctx, |ui| {
            if ui
                .small_button("Copy")
                .on_hover_text("copy the trace as text, to set beside your program's")
                .clicked()
            {
                ctx.copy_text(text.clone());
            }
            // A line longer than the window's room wraps (Copy gives it whole).
            egui::ScrollArea::vertical()
                .auto_shrink([false, false])
                .show(ui, |ui| {
                    ui.add(egui::Label::new(RichText::new(text).font(font.clone())).wrap());
                });
        });
    if !open {
        *trace = None;
    }
}
